//! The documented exit codes of `shadowcheck run`, `merge` and `summarize`, and of every
//! subcommand's setup error (runner/README.md#exit-codes). [`Summary::new`](super::Summary::new)
//! picks one from a run's results; [`Ending`] adds what happened around them (backends that could
//! not start, reports that could not be written, an interruption) and is the one place the code a
//! run returns is decided, in the order of [`PRECEDENCE`].
//!
//! `explain`, `gen --check` and `mutants` also use small codes of their own (1, 2) for answers
//! that are not errors; those are named and documented in their `cmd/` modules.

/// All good: every test passed, warned, was skipped, was an expected failure or a (known) flake,
/// and every backend ran at least one test.
pub const SUCCESS: u8 = 0;
/// Nothing ran: no test selected (empty fixtures, `--cases` matched nothing, an empty shard), or a
/// backend on which every test was skipped (a skips list `.*`, an implementation that skips
/// everything). nextest exits 4 when no test ran, too.
pub const NOTHING: u8 = 4;
/// Setup error or bad input: unknown backend, an implementation that cannot start, unreadable
/// fixtures, baseline, skips or flakes file, `--resume` with another selection, an output directory
/// in use by another run, reports that could not be written; also a run that completed but met bad
/// fixture files or bad cases. Every subcommand exits with it on an error.
pub const SETUP: u8 = 96;
/// At least one regression: Fail, Crash or Timeout not excused by the baseline.
pub const REGRESSIONS: u8 = 100;
/// No regression, but tests listed in the baseline now pass (or are skipped): update the baseline.
pub const IMPROVEMENTS: u8 = 101;
/// The run was interrupted (Ctrl-C, SIGTERM): 128 + SIGINT, as shells report it.
pub const INTERRUPTED: u8 = 130;

/// Exit codes, the one that wins first.
pub const PRECEDENCE: [u8; 6] = [
    INTERRUPTED,
    REGRESSIONS,
    SETUP,
    IMPROVEMENTS,
    NOTHING,
    SUCCESS,
];

fn rank(code: u8) -> usize {
    PRECEDENCE
        .iter()
        .position(|&c| c == code)
        .unwrap_or(PRECEDENCE.len())
}

/// Of two codes, the one that takes precedence.
pub fn worst(a: u8, b: u8) -> u8 {
    if rank(b) < rank(a) {
        b
    } else {
        a
    }
}

/// What each code says, for the summary line.
pub fn meaning(code: u8) -> &'static str {
    match code {
        SUCCESS => "all good",
        NOTHING => "no test ran",
        SETUP => "setup error or bad input",
        REGRESSIONS => "regressions",
        IMPROVEMENTS => "unexpected improvements: update the baseline",
        INTERRUPTED => "interrupted",
        _ => "?",
    }
}

/// The exit code of a run, decided once: the code of its results plus every other reason, each
/// kept so that the summary line says all of them (a regression is never hidden by a later write
/// error, nor the write error by the regression).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ending {
    pub code: u8,
    /// Every reason, with its own code, in the order they were added.
    pub reasons: Vec<(u8, String)>,
}

impl Ending {
    /// Starts from the code the results give.
    pub fn new(results_code: u8) -> Ending {
        Ending {
            code: results_code,
            reasons: vec![(results_code, meaning(results_code).to_string())],
        }
    }

    /// Adds a reason with its code; the run's code becomes the one that takes precedence.
    pub fn add(&mut self, code: u8, why: impl Into<String>) {
        self.code = worst(self.code, code);
        self.reasons.push((code, why.into()));
    }

    /// `exit code 100 (regressions; also 96: writing reports failed: ...)`.
    pub fn describe(&self) -> String {
        let mut main = vec![];
        let mut also = vec![];
        for (c, why) in &self.reasons {
            if *c == self.code {
                main.push(why.clone());
            } else if *c != SUCCESS {
                also.push(format!("{c}: {why}"));
            }
        }
        let mut s = format!("exit code {} ({}", self.code, main.join("; "));
        if !also.is_empty() {
            s.push_str("; also ");
            s.push_str(&also.join("; "));
        }
        s.push(')');
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_write_error_does_not_hide_regressions_and_both_are_said() {
        let mut e = Ending::new(REGRESSIONS);
        e.add(SETUP, "writing out/report.json: No space left on device");
        assert_eq!(e.code, REGRESSIONS);
        assert_eq!(
            e.describe(),
            "exit code 100 (regressions; also 96: writing out/report.json: No space left on device)"
        );
        let mut ok = Ending::new(SUCCESS);
        ok.add(SETUP, "backend `egl:zink:core` could not start");
        assert_eq!(ok.code, SETUP);
        assert_eq!(
            ok.describe(),
            "exit code 96 (backend `egl:zink:core` could not start)"
        );
        let mut i = Ending::new(IMPROVEMENTS);
        i.add(INTERRUPTED, "interrupted");
        assert_eq!(i.code, INTERRUPTED);
        assert_eq!(worst(NOTHING, IMPROVEMENTS), IMPROVEMENTS);
        assert_eq!(worst(SETUP, REGRESSIONS), REGRESSIONS);
    }
}
