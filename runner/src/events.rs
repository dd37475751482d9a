//! The runner's event stream.
//!
//! As in cargo-nextest, the runner core never prints: it emits [`Event`]s, and reporters
//! ([`Reporter`]) subscribe to them (terminal, results.jsonl, CSV, JUnit, JSON, Markdown). The
//! records the events carry, and that go to disk, are in [`crate::records`].

use crate::records::{Counts, LoadError, Summary, TestResult};

/// What the runner tells its reporters.
#[derive(Debug)]
pub enum Event<'a> {
    RunStarted {
        backends: &'a [String],
        tests: usize,
        out_dir: &'a std::path::Path,
    },
    LoadError(&'a LoadError),
    BackendStarted {
        backend: &'a str,
        tests: usize,
        /// Cases whose spec or API path the backend does not implement: not tests of it.
        not_applicable: usize,
    },
    /// Something an implementation or the runner wants a human to see (stderr lines, restarts).
    Diagnostic {
        backend: &'a str,
        message: &'a str,
    },
    /// One test finished. `replayed`: read back from results.jsonl by `--resume` / `merge`
    /// (already on disk). A flake re-run sends the same test again with its final status.
    CaseFinished {
        result: &'a TestResult,
        replayed: bool,
    },
    /// A batch of cases has been judged: a good moment to flush files (results.jsonl is flushed
    /// per batch, so a killed run loses at most the batch in flight, which `--resume` re-runs).
    BatchFinished {
        backend: &'a str,
    },
    BackendFinished {
        backend: &'a str,
        counts: &'a Counts,
        timing: &'a Timing,
    },
    /// The run is over: all results in report order (backend, then test name) and the totals.
    RunFinished {
        results: &'a [TestResult],
        load_errors: &'a [LoadError],
        summary: &'a Summary,
    },
}

/// A subscriber to the event stream.
pub trait Reporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()>;
}

/// Where events go: the reporters directly ([`Fanout`]) or, from a backend's thread, a channel to
/// the thread that owns the reporters ([`crate::schedule`]).
pub trait Sink {
    fn emit(&mut self, ev: &Event<'_>);
}

impl Sink for Fanout {
    fn emit(&mut self, ev: &Event<'_>) {
        Fanout::emit(self, ev)
    }
}

/// Sends every event to each reporter; the first I/O error is kept and returned at the end (a full
/// disk must not hide the rest of the run).
#[derive(Default)]
pub struct Fanout {
    pub reporters: Vec<Box<dyn Reporter>>,
    pub error: Option<(usize, std::io::Error)>,
}

impl Fanout {
    pub fn emit(&mut self, ev: &Event<'_>) {
        for (i, r) in self.reporters.iter_mut().enumerate() {
            if let Err(e) = r.event(ev) {
                if self.error.is_none() {
                    self.error = Some((i, e));
                }
            }
        }
    }
}

/// Wall time spent per backend, for `run --timings`.
#[derive(Debug, Clone, Default)]
pub struct Timing {
    pub cases_sent: usize,
    /// Seconds inside the backend's `answer_batch` (lookups, process I/O).
    pub backend_s: f64,
    /// Seconds judging answers and sending events (verdicts, reporters). Judging runs beside the
    /// backend's next batch, so `backend_s + verdict_s` may exceed the wall time.
    pub verdict_s: f64,
}
