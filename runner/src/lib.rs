//! shadowcheck-runner library: backends, verdicts, baselines, reporters. The binary is src/main.rs.
//!
//! Data flows one way: fixtures → [`run`] (cases to a [`backend::Backend`]) → [`verdict`] (oracle
//! expectation and acceptance) → [`baseline`] (final status) → [`events`] → [`report`]ers.
//! The library never prints; reporters own every byte of output. What a run leaves on disk (the
//! result records, statuses, exit codes) and the one reader of results.jsonl are the crate
//! `shadowcheck-records`, re-exported here as [`records`] so the runner's modules name it as before.

// A stderr whose reader has gone (`shadowcheck run 2>&1 | head -1`) must not panic: write to it
// with `errln!`.
#![deny(clippy::print_stderr)]

/// `eprintln!` that does not panic: a stderr that cannot be written (its reader gone) loses the
/// line, and nothing else happens.
#[macro_export]
macro_rules! errln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

pub mod attribute;
pub mod backend;
pub mod baseline;
pub mod bench;
pub mod consensus;
pub mod events;
pub mod interrupt;
pub mod mutants;
pub mod outdir;
pub use shadowcheck_records as records;
pub mod report;
pub mod repro;
pub mod run;
pub mod schedule;
pub mod shard;
pub mod state_verdict;
pub mod verdict;
