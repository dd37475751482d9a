//! The runner's event stream and the records that go to disk.
//!
//! As in cargo-nextest, the runner core never prints: it emits [`Event`]s, and reporters
//! ([`Reporter`]) subscribe to them (terminal, results.jsonl, CSV, JUnit, JSON, Markdown).
//! [`TestResult`] is the stable serde record of one test; `results.jsonl` holds one per line
//! (see [`Line`]), which is what `--resume` and `shadowcheck merge` read back.

use crate::verdict::{ExpectedSummary, Outcome, Status};
use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Footprint, SCHEMA_VERSION};

/// The case's coordinates in the grid, for summary tables.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Tags {
    pub spec: String,
    pub target: String,
    pub format: String,
    pub func: String,
    /// `min/mag` filters, e.g. `linear/linear`.
    pub filter: String,
}

impl Tags {
    pub fn of(case: &Case) -> Tags {
        let s = &case.sampler;
        Tags {
            spec: case.spec.key().to_string(),
            target: case.texture.target.key().to_string(),
            format: case.texture.format.key().to_string(),
            func: if s.compare_mode == shadowcheck_model::CompareMode::None {
                "none".to_string()
            } else {
                s.compare_func.key().to_string()
            },
            filter: format!("{}/{}", s.min_filter.key(), s.mag_filter.key()),
        }
    }
}

/// Four channels that may be non-finite (written as "nan", "inf", "-inf"); the wire type of the
/// protocol, recorded as observed.
pub use shadowcheck_protocol::Rgba;

/// The result of one test (`<case id>@<api>`) on one backend.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TestResult {
    pub backend: String,
    /// `<case id>@<api key>`: the name used in baselines, skips and flakes lists.
    pub test: String,
    pub case_id: String,
    pub api: ApiPath,
    /// Final status (after baseline, flakes list and re-run).
    pub status: Status,
    /// Raw outcome of the (first) run.
    pub outcome: Outcome,
    /// Why: skip reason, crash message, failure summary.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Wall time of the case's share of its batch, in seconds.
    pub duration: f64,
    pub tags: Tags,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub observed: Option<Rgba>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expected: Option<ExpectedSummary>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub footprint: Option<Footprint>,
    /// Outcome of the flake re-run of a regression, when one was made.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rerun: Option<Outcome>,
    /// The fixture path the case came from (for the re-run command).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixtures: Option<String>,
}

impl TestResult {
    pub fn name(case_id: &str, api: ApiPath) -> String {
        format!("{case_id}@{}", api.key())
    }
    /// The one-line command that re-runs this case alone.
    pub fn rerun_command(&self) -> String {
        let fixtures = match &self.fixtures {
            Some(f) => format!(" --fixtures {}", shell_quote(f)),
            None => String::new(),
        };
        format!(
            "shadowcheck run --backend {}{fixtures} --cases {}",
            shell_quote(&self.backend),
            shell_quote(&format!("^{}$", regex::escape(&self.case_id)))
        )
    }
}

/// Quotes for a POSIX shell when needed.
pub fn shell_quote(s: &str) -> String {
    if !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./:=,@%+".contains(c))
    {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// A fixture file or case that could not be loaded; the run goes on without it.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub struct LoadError {
    pub file: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
    pub message: String,
}

/// What the run was asked to do; the first line of results.jsonl. `--resume` refuses to continue
/// a run whose selection differs.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct RunMeta {
    pub schema_version: u32,
    pub backends: Vec<String>,
    pub fixtures: Vec<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cases: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub baseline: Option<String>,
}

impl RunMeta {
    pub fn new() -> RunMeta {
        RunMeta {
            schema_version: SCHEMA_VERSION,
            backends: vec![],
            fixtures: vec![],
            cases: None,
            shard: None,
            baseline: None,
        }
    }
}

impl Default for RunMeta {
    fn default() -> Self {
        Self::new()
    }
}

/// One line of results.jsonl.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Line {
    Meta(RunMeta),
    LoadError(LoadError),
    Result(Box<TestResult>),
}

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

/// Exit codes of `shadowcheck run` and `merge` (documented in runner/README.md).
pub mod exit {
    /// Every test passed, warned, was skipped, was an expected failure or a (known) flake.
    pub const OK: u8 = 0;
    /// No test was selected (empty fixtures, `--cases` matched nothing, empty shard).
    pub const NO_TESTS: u8 = 4;
    /// Setup error or bad input (unknown backend, unreadable fixtures or baseline, bad cases).
    pub const SETUP: u8 = 96;
    /// At least one regression: Fail, Crash or Timeout not excused by the baseline.
    pub const REGRESSION: u8 = 100;
    /// No regression, but tests listed in the baseline now pass: update the baseline.
    pub const IMPROVEMENT: u8 = 101;
}

/// The end of a run: totals and the exit code they give.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    pub schema_version: u32,
    pub backends: Vec<String>,
    pub counts: Counts,
    pub load_errors: usize,
    pub exit_code: u8,
}

impl Summary {
    /// Regressions (100) first, then bad input (96), improvements (101), nothing selected (4).
    pub fn new(backends: Vec<String>, results: &[TestResult], load_errors: usize) -> Summary {
        let mut counts = Counts::default();
        for r in results {
            counts.add(r.status);
        }
        let exit_code = if counts.regressions() > 0 {
            exit::REGRESSION
        } else if load_errors > 0 {
            exit::SETUP
        } else if counts.unexpected_improvement > 0 {
            exit::IMPROVEMENT
        } else if counts.total() == 0 {
            exit::NO_TESTS
        } else {
            exit::OK
        };
        Summary {
            schema_version: SCHEMA_VERSION,
            backends,
            counts,
            load_errors,
            exit_code,
        }
    }
}

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
/// the thread that owns the reporters ([`crate::parallel`]).
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

/// Wall time spent per backend, for `--profile`.
#[derive(Debug, Clone, Default)]
pub struct Timing {
    pub cases_sent: usize,
    /// Seconds inside the backend's `run_batch` (lookups, process I/O).
    pub backend_s: f64,
    /// Seconds judging answers and sending events (verdicts, reporters).
    pub verdict_s: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn result(test: &str, status: Status) -> TestResult {
        TestResult {
            backend: "b".into(),
            test: test.into(),
            case_id: test.into(),
            api: ApiPath::GlslCore,
            status,
            outcome: Outcome::Pass,
            reason: None,
            duration: 0.0,
            tags: Tags {
                spec: "gl46".into(),
                target: "2d".into(),
                format: "d16".into(),
                func: "lequal".into(),
                filter: "nearest/nearest".into(),
            },
            observed: None,
            expected: None,
            footprint: None,
            rerun: None,
            fixtures: None,
        }
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
            exit::REGRESSION
        );
        assert_eq!(code(&[pass.clone(), better.clone()], 1), exit::SETUP);
        assert_eq!(code(&[pass.clone(), better.clone()], 0), exit::IMPROVEMENT);
        assert_eq!(code(&[], 0), exit::NO_TESTS);
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
            exit::OK
        );
    }

    #[test]
    fn records_round_trip_and_rerun_commands_quote() {
        let mut r = result(
            "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25,1@core",
            Status::Plain(Outcome::Fail),
        );
        r.case_id = "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25,1".into();
        r.observed = Some(Rgba([f64::NAN, 0.0, f64::INFINITY, 1.0]));
        let line = serde_json::to_string(&Line::Result(Box::new(r.clone()))).unwrap();
        let back: Line = serde_json::from_str(&line).unwrap();
        let Line::Result(back) = back else {
            panic!("{line}")
        };
        assert!(back.observed.unwrap().0[0].is_nan());
        assert_eq!(back.status, r.status);
        assert_eq!(r.rerun_command(), "shadowcheck run --backend b --cases '^gl46/2d/d16/nearest/lequal/ref=0\\.5/dt=0\\.25,1$'");
        r.backend = "exec:python3 it's.py".into();
        assert!(r
            .rerun_command()
            .starts_with("shadowcheck run --backend 'exec:python3 it'\\''s.py' "));
    }
}
