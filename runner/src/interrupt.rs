//! Stopping a run early (Ctrl-C, SIGTERM: `shadowcheck run` installs the handler in
//! `cmd/run.rs`). Once [`request`]ed, no more cases are sent, the batch in flight is dropped (its
//! implementation process got the terminal's SIGINT too, so its answers cannot be trusted;
//! `--resume` re-runs it), no flake re-run is made, and the reports are written for what is done.
//!
//! The flag is process-wide; the runner core and the process backends poll [`requested`].

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Whether the run was asked to stop.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::SeqCst)
}

/// Asks the run to stop; returns whether it had been asked already.
pub fn request() -> bool {
    REQUESTED.swap(true, Ordering::SeqCst)
}
