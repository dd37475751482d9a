//! The compact form results.jsonl keeps passing tests in (deqp-runner's habit: a line for everything,
//! details only for what did not pass): one [`Passed`] line per (backend, case) holds the case id and
//! tags once and, per test, its API path, duration and observed value, about 100 bytes a test
//! instead of the 400 of a full [`TestResult`]. Only a plain Pass with nothing else to say is kept
//! so ([`Passed::admits`]); `--full-report` writes full records for every test.
//!
//! The reader expands a `Passed` line back into the [`TestResult`]s it stands for
//! ([`Passed::results`]): nothing a passing record carried is lost (a passing record carries no
//! expected summary, footprint, reason or re-run) but its duration's digits beyond the third.

use super::{Outcome, Status, Tags, TestResult};
use serde::{Deserialize, Serialize};
use shadowcheck_model::ApiPath;
use shadowcheck_protocol::Rgba;

/// Passing tests of one case on one backend.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Passed {
    pub backend: String,
    pub case_id: String,
    /// The [`Tags`] as one string: `spec target format func min/mag`.
    pub tags: String,
    /// The fixture path the case came from (as [`TestResult::fixtures`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixtures: Option<String>,
    pub tests: Vec<PassedTest>,
}

/// One passing test of a [`Passed`] line, written as a JSON array:
/// `[api, duration in seconds (three significant digits), observed]` (observed as f32, which
/// read-back values are).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PassedTest(
    pub ApiPath,
    pub f64,
    #[serde(default, skip_serializing_if = "Option::is_none")] pub Option<[f32; 4]>,
);

/// Why a `Passed` line does not expand.
#[derive(Debug, thiserror::Error)]
#[error("a passed line's tags {0:?} are not `spec target format func filter`")]
pub struct BadTags(String);

impl Passed {
    /// Whether `r` can be kept in the compact form without losing anything: a plain Pass with no
    /// reason, expected summary, footprint or re-run, and an observed value that is finite and
    /// exact in f32.
    pub fn admits(r: &TestResult) -> bool {
        r.status == Status::Plain(Outcome::Pass)
            && r.outcome == Outcome::Pass
            && r.reason.is_none()
            && r.expected.is_none()
            && r.footprint.is_none()
            && r.rerun.is_none()
            && r.test == TestResult::name(&r.case_id, r.api)
            && r.observed
                .as_ref()
                .is_none_or(|o| observed_f32(o).is_some())
            && !r.tags.spec.contains(' ')
            && [&r.tags.target, &r.tags.format, &r.tags.func, &r.tags.filter]
                .iter()
                .all(|t| !t.is_empty() && !t.contains(' '))
    }

    /// A line holding `r` alone (which [`Passed::admits`]).
    pub fn first(r: &TestResult) -> Passed {
        let t = &r.tags;
        let mut p = Passed {
            backend: r.backend.clone(),
            case_id: r.case_id.clone(),
            tags: format!(
                "{} {} {} {} {}",
                t.spec, t.target, t.format, t.func, t.filter
            ),
            fixtures: r.fixtures.clone(),
            tests: vec![],
        };
        p.push(r);
        p
    }

    /// Whether `r` belongs on this line (same backend and case).
    pub fn holds(&self, r: &TestResult) -> bool {
        self.backend == r.backend && self.case_id == r.case_id && self.fixtures == r.fixtures
    }

    /// Adds `r` (which [`Passed::admits`] and this line [`Passed::holds`]).
    pub fn push(&mut self, r: &TestResult) {
        self.tests.push(PassedTest(
            r.api,
            three_digits(r.duration),
            r.observed.as_ref().and_then(observed_f32),
        ));
    }

    /// The full records this line stands for.
    pub fn results(self) -> Result<Vec<TestResult>, BadTags> {
        let parts: Vec<&str> = self.tags.split(' ').collect();
        let [spec, target, format, func, filter] = parts[..] else {
            return Err(BadTags(self.tags));
        };
        let tags = Tags {
            spec: spec.into(),
            target: target.into(),
            format: format.into(),
            func: func.into(),
            filter: filter.into(),
        };
        Ok(self
            .tests
            .into_iter()
            .map(|PassedTest(api, duration, observed)| TestResult {
                backend: self.backend.clone(),
                test: TestResult::name(&self.case_id, api),
                case_id: self.case_id.clone(),
                api,
                status: Status::Plain(Outcome::Pass),
                outcome: Outcome::Pass,
                reason: None,
                duration,
                tags: tags.clone(),
                observed: observed.map(|o| Rgba(o.map(f64::from))),
                expected: None,
                footprint: None,
                rerun: None,
                fixtures: self.fixtures.clone(),
            })
            .collect())
    }
}

/// `d` to three significant digits (a duration; results.csv keeps microseconds).
fn three_digits(d: f64) -> f64 {
    format!("{d:.2e}").parse().unwrap_or(d)
}

/// `o` as f32, when every channel is finite and exactly an f32 (as RGBA32F read-back is).
fn observed_f32(o: &Rgba) -> Option<[f32; 4]> {
    let mut out = [0f32; 4];
    for (v, slot) in o.0.iter().zip(out.iter_mut()) {
        let f = *v as f32;
        if !v.is_finite() || f64::from(f) != *v {
            return None;
        }
        *slot = f;
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::records::Line;

    fn pass(api: ApiPath, observed: Option<[f64; 4]>) -> TestResult {
        let mut r = TestResult::sample("x", Status::Plain(Outcome::Pass));
        r.case_id = "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25_1".into();
        r.api = api;
        r.test = TestResult::name(&r.case_id, api);
        r.duration = 1.25e-6;
        r.observed = observed.map(Rgba);
        r
    }

    #[test]
    fn a_passed_line_expands_to_the_records_it_stands_for() {
        let a = pass(ApiPath::GlslCore, Some([0.45f32 as f64, 0.0, 0.0, 1.0]));
        let mut b = pass(ApiPath::Es300, None);
        b.fixtures = Some("f.json".into());
        assert!(
            !Passed::first(&a).holds(&b),
            "another fixture file is another line"
        );
        b.fixtures = None;
        assert!(Passed::admits(&a) && Passed::admits(&b));
        let mut p = Passed::first(&a);
        assert!(p.holds(&b));
        p.push(&b);
        let line = serde_json::to_string(&Line::Passed(p)).unwrap();
        // The observed f32 0.45 is written as 0.45, not 0.45000001788139343.
        assert!(line.contains("[0.45,0.0,0.0,1.0]"), "{line}");
        let Line::Passed(back) = serde_json::from_str(&line).unwrap() else {
            panic!("{line}")
        };
        assert_eq!(back.results().unwrap(), vec![a, b]);
    }

    #[test]
    fn what_a_compact_line_cannot_hold_stays_a_full_record() {
        let mut r = pass(ApiPath::GlslCore, Some([0.1, 0.0, 0.0, 1.0]));
        assert!(!Passed::admits(&r), "0.1 is not an f32");
        r.observed = Some(Rgba([f64::NAN, 0.0, 0.0, 1.0]));
        assert!(!Passed::admits(&r));
        r.observed = None;
        assert!(Passed::admits(&r));
        r.reason = Some("why".into());
        assert!(!Passed::admits(&r));
        r.reason = None;
        r.status = Status::Plain(Outcome::Warn);
        assert!(!Passed::admits(&r));
        let mut r = pass(ApiPath::GlslCore, None);
        r.rerun = Some(Outcome::Pass);
        assert!(!Passed::admits(&r));
    }

    #[test]
    fn malformed_tags_are_an_error_not_a_panic() {
        let p = Passed {
            backend: "b".into(),
            case_id: "c".into(),
            tags: "only three parts".into(),
            fixtures: None,
            tests: vec![PassedTest(ApiPath::FixedFunction, 0.0, None)],
        };
        assert!(p.results().is_err());
    }
}
