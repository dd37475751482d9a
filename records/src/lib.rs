//! The records a run leaves on disk, as stable serde types (in the spirit of nextest-metadata):
//! what `results.jsonl` and `report.json` hold, and what every reader of them shares.
//!
//! - [`TestResult`]: the result of one test (`<case id>@<api>`) on one backend, with its
//!   [`Status`] and raw [`Outcome`] ([`status`]), its grid [`Tags`] and, for what did not pass, the
//!   [`ExpectedSummary`];
//! - [`Line`]: one line of `results.jsonl`: the run's [`RunMeta`] first, then one [`TestResult`]
//!   or [`LoadError`] per line, plain passes of a backend's cases with the same tags together on
//!   one [`Passed`] line ([`passed`]: the compact form, unless `--full-report`), and last, when
//!   the run finished, the closing [`Line::End`];
//! - [`Counts`] and [`Summary`]: the totals of a run and the exit code they give ([`exit`], the
//!   documented exit codes, runner/README.md#exit-codes in the repository);
//! - [`reader`]: the one reader of `results.jsonl` (for `--resume`, `merge`, `report`,
//!   `summarize` and `consensus`): a truncated last line is dropped, the last record of a (backend, test) wins,
//!   load errors are de-duplicated.
//!
//! Nothing here runs a test: the runner (`shadowcheck-runner`) makes these records and writes
//! them; an outside tool reads a run's results with this crate alone (see README.md).

pub mod exit;
pub mod passed;
pub mod reader;
pub mod status;
mod summary;

pub use passed::{Passed, PassedCase};
pub use reader::{read_results, truncate_partial_line, ReadError, Results, RESULTS_FILE};
pub use status::{Outcome, Status};
pub use summary::{Counts, Summary};

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Footprint, Profile, SCHEMA_VERSION};
use shadowcheck_protocol::Rgba;
use std::collections::BTreeMap;

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

/// A test's name in a file that holds the results of several backends (results.csv and
/// failures.csv of a multi-backend run, a baseline meant for one backend of such a run):
/// `<backend>/<test>`, the backend as a prefix as deqp-runner's per-suite `prefix` does, so that
/// each name appears once. Characters a test name may not hold (commas, quotes, whitespace: see
/// `shadowcheck_model::validate::id_char_ok`) become `_` in the backend part.
pub fn qualified_name(backend: &str, test: &str) -> String {
    let b: String = backend
        .chars()
        .map(|c| {
            if shadowcheck_model::validate::id_char_ok(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{b}/{test}")
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
    /// Per backend, what its implementation called itself in the protocol hello (for a GL or
    /// WebGL worker: the version and renderer strings, e.g. ANGLE's for `webgl:chromium`).
    /// Informational: `--resume` and `merge` do not compare it.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub implementations: BTreeMap<String, String>,
}

impl RunMeta {
    /// The meta without what `--resume` does not compare (the implementations' names).
    pub fn selection(&self) -> RunMeta {
        RunMeta {
            implementations: BTreeMap::new(),
            ..self.clone()
        }
    }

    pub fn new() -> RunMeta {
        RunMeta {
            schema_version: SCHEMA_VERSION,
            backends: vec![],
            fixtures: vec![],
            cases: None,
            shard: None,
            baseline: None,
            implementations: BTreeMap::new(),
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
    /// Plain passes of cases with the same tags, in the compact form ([`passed`]).
    Passed(Passed),
    /// A backend started: how many cases of the selection are not tests of it (spec or API path
    /// not implemented), so `merge` and `report` count them as the run did.
    NotApplicable {
        backend: String,
        cases: usize,
        /// The tests the backend has in this selection (absent in files of older builds): what a
        /// finished run holds a record of ([`reader::Results::unfinished`]).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        tests: Option<usize>,
    },
    /// The closing record: the run finished (not interrupted, not killed, results.jsonl written
    /// whole) with this many tests per backend. Written once every backend has a record of each
    /// of its tests; a file without it is a run that did not finish.
    End {
        tests: BTreeMap<String, usize>,
    },
}

/// What the verdict of one observation rests on, kept for the reports.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExpectedSummary {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spec_value: Option<f64>,
    /// Acceptance set under `strict`, as text (e.g. `{1}` or `[0.25, 0.5]`).
    pub strict: String,
    /// Acceptance set under `quality`.
    pub quality: String,
    /// Channel layout of the API path (`r`, `0`, `1`, `-`, `r|0`; `g0`..`g3` for a gather).
    pub layout: String,
    /// The profile that decided the verdict (`quality` for Warn and Fail: Warn is inside it, Fail
    /// outside; only non-passing tests carry an expected summary).
    pub profile: Profile,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub citations: Vec<String>,
}

#[cfg(any(test, feature = "test-support"))]
impl TestResult {
    /// A Pass-outcome record of `test` on backend `b` (gl46 2D D16 LEQUAL NEAREST), for unit tests
    /// (feature `test-support`).
    pub fn sample(test: &str, status: Status) -> TestResult {
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
}

#[cfg(test)]
mod tests {
    use super::*;

    fn result(test: &str, status: Status) -> TestResult {
        TestResult::sample(test, status)
    }

    #[test]
    fn records_round_trip_and_rerun_commands_quote() {
        let mut r = result(
            "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25_1@core",
            Status::Plain(Outcome::Fail),
        );
        r.case_id = "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25_1".into();
        r.observed = Some(Rgba([f64::NAN, 0.0, f64::INFINITY, 1.0]));
        let line = serde_json::to_string(&Line::Result(Box::new(r.clone()))).unwrap();
        let back: Line = serde_json::from_str(&line).unwrap();
        let Line::Result(back) = back else {
            panic!("{line}")
        };
        assert!(back.observed.unwrap().0[0].is_nan());
        assert_eq!(back.status, r.status);
        assert_eq!(r.rerun_command(), "shadowcheck run --backend b --cases '^gl46/2d/d16/nearest/lequal/ref=0\\.5/dt=0\\.25_1$'");
        r.backend = "exec:python3 it's.py".into();
        assert!(r
            .rerun_command()
            .starts_with("shadowcheck run --backend 'exec:python3 it'\\''s.py' "));
    }
}

/// The example of README.md, compiled as a doctest so it stays true to the API.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
