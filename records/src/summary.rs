//! The totals of a run and the exit code they give (`report.json`'s `summary`, the terminal's
//! last line).

use super::exit;
use super::{Outcome, Status, TestResult};
use serde::{Deserialize, Serialize};
use shadowcheck_model::SCHEMA_VERSION;

/// Counts per final status.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Counts {
    pub pass: usize,
    pub warn: usize,
    pub fail: usize,
    pub skip: usize,
    pub crash: usize,
    pub timeout: usize,
    pub expected_fail: usize,
    pub unexpected_improvement: usize,
    pub flake: usize,
    pub known_flake: usize,
    /// Not tests: API paths (or cases) whose spec or path the backend does not implement, as a
    /// dEQP caselist would not list them. Outside [`Counts::total`]; no record in any file.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub not_applicable: usize,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Counts {
    pub fn add(&mut self, s: Status) {
        match s {
            Status::Plain(Outcome::Pass) => self.pass += 1,
            Status::Plain(Outcome::Warn) => self.warn += 1,
            Status::Plain(Outcome::Fail) => self.fail += 1,
            Status::Plain(Outcome::Skip) => self.skip += 1,
            Status::Plain(Outcome::Crash) => self.crash += 1,
            Status::Plain(Outcome::Timeout) => self.timeout += 1,
            Status::ExpectedFail => self.expected_fail += 1,
            Status::UnexpectedImprovement(_) => self.unexpected_improvement += 1,
            Status::Flake => self.flake += 1,
            Status::KnownFlake => self.known_flake += 1,
        }
    }
    pub fn total(&self) -> usize {
        self.pass
            + self.warn
            + self.fail
            + self.skip
            + self.crash
            + self.timeout
            + self.expected_fail
            + self.unexpected_improvement
            + self.flake
            + self.known_flake
    }
    pub fn regressions(&self) -> usize {
        self.fail + self.crash + self.timeout
    }
}

/// The end of a run: totals and the exit code they give.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub schema_version: u32,
    pub backends: Vec<String>,
    pub counts: Counts,
    pub load_errors: usize,
    /// Backends that had tests and skipped every one: the run exits 4 ([`exit::NOTHING`]) unless
    /// something weightier happened.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub idle_backends: Vec<String>,
    pub exit_code: u8,
}

impl Summary {
    /// Regressions (100) first, then bad input (96), improvements (101), nothing ran (4: no test
    /// selected, or a backend on which every test was skipped).
    pub fn new(backends: Vec<String>, results: &[TestResult], load_errors: usize) -> Summary {
        let mut counts = Counts::default();
        for r in results {
            counts.add(r.status);
        }
        // A backend that had tests and skipped every one of them (a skips list `.*`, an
        // implementation that skips everything) tested nothing.
        let idle_backends: Vec<String> = backends
            .iter()
            .filter(|b| {
                let mut own = results.iter().filter(|r| &r.backend == *b).peekable();
                own.peek().is_some() && own.all(|r| r.outcome == Outcome::Skip)
            })
            .cloned()
            .collect();
        let exit_code = if counts.regressions() > 0 {
            exit::REGRESSIONS
        } else if load_errors > 0 {
            exit::SETUP
        } else if counts.unexpected_improvement > 0 {
            exit::IMPROVEMENTS
        } else if counts.total() == 0 || !idle_backends.is_empty() {
            exit::NOTHING
        } else {
            exit::SUCCESS
        };
        Summary {
            schema_version: SCHEMA_VERSION,
            backends,
            counts,
            load_errors,
            idle_backends,
            exit_code,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn result(test: &str, status: Status) -> TestResult {
        TestResult::sample(test, status)
    }

    #[test]
    fn exit_code_precedence_is_regression_setup_improvement_empty_ok() {
        let pass = result("p", Status::Plain(Outcome::Pass));
        let fail = result("f", Status::Plain(Outcome::Crash));
        let better = result("i", Status::UnexpectedImprovement(Outcome::Pass));
        let flake = result("k", Status::Flake);
        let code = |rs: &[TestResult], errors| Summary::new(vec![], rs, errors).exit_code;
        assert_eq!(
            code(&[pass.clone(), fail.clone(), better.clone()], 1),
            exit::REGRESSIONS
        );
        assert_eq!(code(&[pass.clone(), better.clone()], 1), exit::SETUP);
        assert_eq!(code(&[pass.clone(), better.clone()], 0), exit::IMPROVEMENTS);
        assert_eq!(code(&[], 0), exit::NOTHING);
        // A backend that skipped everything did not test anything: not "all good".
        let skipped = result("s", Status::Plain(Outcome::Skip));
        let mut skipped = TestResult {
            outcome: Outcome::Skip,
            backend: "idle".into(),
            ..skipped
        };
        let both = |s: &TestResult| {
            Summary::new(
                vec!["b".into(), "idle".into()],
                &[pass.clone(), s.clone()],
                0,
            )
        };
        assert_eq!(both(&skipped).exit_code, exit::NOTHING);
        assert_eq!(both(&skipped).idle_backends, ["idle"]);
        skipped.outcome = Outcome::Pass;
        assert_eq!(both(&skipped).exit_code, exit::SUCCESS);
        assert_eq!(
            code(
                &[
                    pass,
                    flake,
                    result("e", Status::ExpectedFail),
                    result("w", Status::Plain(Outcome::Warn))
                ],
                0
            ),
            exit::SUCCESS
        );
    }
}
