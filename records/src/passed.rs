//! The compact form results.jsonl keeps passing tests in (deqp-runner's habit: a line for everything,
//! details only for what did not pass). One [`Passed`] line holds consecutive plain passes of one
//! backend whose cases share their [`Tags`] (and fixture file): the tags once, then per case its id
//! and, per test, its API path and duration; about 50 bytes a test instead of the 400 of a full
//! [`TestResult`]. Only a plain Pass is kept so ([`Passed::admits`]); its observed value is a
//! detail and is not kept (`--full-report` writes full records, observed values included, for
//! every test).
//!
//! The reader expands a `Passed` line back into the [`TestResult`]s it stands for
//! ([`Passed::results`]): a passing record carries no expected summary, footprint, reason or
//! re-run, so only its observed value and its duration's digits beyond the third are not kept.

use super::{Outcome, Status, Tags, TestResult};
use serde::{Deserialize, Serialize};
use shadowcheck_model::ApiPath;

/// Plain passes of one backend, their cases sharing tags and fixture file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Passed {
    pub backend: String,
    /// The [`Tags`] as one string: `spec target format func min/mag`.
    pub tags: String,
    /// The fixture path the cases came from (as [`TestResult::fixtures`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixtures: Option<String>,
    pub cases: Vec<PassedCase>,
}

/// One case of a [`Passed`] line, written as a JSON array: `[case id, [[api, duration], ...]]`
/// (duration in seconds, three significant digits).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PassedCase(pub String, pub Vec<(ApiPath, f64)>);

/// Why a `Passed` line does not expand.
#[derive(Debug, thiserror::Error)]
#[error("a passed line's tags {0:?} are not `spec target format func filter`")]
pub struct BadTags(String);

impl Passed {
    /// Whether `r` can be kept in the compact form: a plain Pass with no reason, expected summary,
    /// footprint or re-run, named `<case id>@<api>`, with tags that hold no space.
    pub fn admits(r: &TestResult) -> bool {
        let t = &r.tags;
        r.status == Status::Plain(Outcome::Pass)
            && r.outcome == Outcome::Pass
            && r.reason.is_none()
            && r.expected.is_none()
            && r.footprint.is_none()
            && r.rerun.is_none()
            && r.test == TestResult::name(&r.case_id, r.api)
            && [&t.spec, &t.target, &t.format, &t.func, &t.filter]
                .iter()
                .all(|s| !s.is_empty() && !s.contains(' '))
    }

    /// A line holding `r` alone (which [`Passed::admits`]).
    pub fn first(r: &TestResult) -> Passed {
        let mut p = Passed {
            backend: r.backend.clone(),
            tags: tags_text(&r.tags),
            fixtures: r.fixtures.clone(),
            cases: vec![],
        };
        p.push(r);
        p
    }

    /// Whether `r` belongs on this line (same backend, tags and fixture file).
    pub fn holds(&self, r: &TestResult) -> bool {
        self.backend == r.backend && self.fixtures == r.fixtures && self.tags == tags_text(&r.tags)
    }

    /// Adds `r` (which [`Passed::admits`] and this line [`Passed::holds`]): to the last case when
    /// it is `r`'s, otherwise as a new case.
    pub fn push(&mut self, r: &TestResult) {
        let test = (r.api, three_digits(r.duration));
        match self.cases.last_mut() {
            Some(PassedCase(id, tests)) if *id == r.case_id => tests.push(test),
            _ => self.cases.push(PassedCase(r.case_id.clone(), vec![test])),
        }
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
        let mut out = vec![];
        for PassedCase(case_id, tests) in self.cases {
            for (api, duration) in tests {
                out.push(TestResult {
                    backend: self.backend.clone(),
                    test: TestResult::name(&case_id, api),
                    case_id: case_id.clone(),
                    api,
                    status: Status::Plain(Outcome::Pass),
                    outcome: Outcome::Pass,
                    reason: None,
                    duration,
                    tags: tags.clone(),
                    observed: None,
                    expected: None,
                    footprint: None,
                    rerun: None,
                    fixtures: self.fixtures.clone(),
                });
            }
        }
        Ok(out)
    }
}

fn tags_text(t: &Tags) -> String {
    format!(
        "{} {} {} {} {}",
        t.spec, t.target, t.format, t.func, t.filter
    )
}

/// `d` to three significant digits (a duration; results.csv keeps microseconds).
fn three_digits(d: f64) -> f64 {
    format!("{d:.2e}").parse().unwrap_or(d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Line;
    use shadowcheck_protocol::Rgba;

    fn pass(case_id: &str, api: ApiPath) -> TestResult {
        let mut r = TestResult::sample("x", Status::Plain(Outcome::Pass));
        r.case_id = case_id.into();
        r.api = api;
        r.test = TestResult::name(&r.case_id, api);
        r.duration = 1.25e-6;
        r
    }

    #[test]
    fn a_passed_line_expands_to_the_records_it_stands_for() {
        let c1 = "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25_1";
        let c2 = "gl46/2d/d16/nearest/lequal/ref=0.75/dt=0.25_1";
        let a = pass(c1, ApiPath::GlslCore);
        let b = pass(c1, ApiPath::Es300);
        let c = pass(c2, ApiPath::GlslCore);
        assert!([&a, &b, &c].iter().all(|r| Passed::admits(r)));
        let mut p = Passed::first(&a);
        for r in [&b, &c] {
            assert!(p.holds(r));
            p.push(r);
        }
        let line = serde_json::to_string(&Line::Passed(p)).unwrap();
        assert_eq!(
            line,
            format!(
                r#"{{"kind":"passed","backend":"b","tags":"gl46 2d d16 lequal nearest/nearest","cases":[["{c1}",[["core",1.25e-6],["es300",1.25e-6]]],["{c2}",[["core",1.25e-6]]]]}}"#
            )
        );
        let Line::Passed(back) = serde_json::from_str(&line).unwrap() else {
            panic!("{line}")
        };
        assert_eq!(back.results().unwrap(), vec![a, b, c]);
    }

    #[test]
    fn another_backend_tag_or_fixture_file_is_another_line() {
        let a = pass("c", ApiPath::GlslCore);
        let p = Passed::first(&a);
        let mut b = a.clone();
        b.fixtures = Some("f.json".into());
        assert!(!p.holds(&b));
        let mut b = a.clone();
        b.backend = "other".into();
        assert!(!p.holds(&b));
        let mut b = a.clone();
        b.tags.func = "gequal".into();
        assert!(!p.holds(&b));
    }

    #[test]
    fn what_a_compact_line_cannot_hold_stays_a_full_record() {
        let mut r = pass("c", ApiPath::GlslCore);
        // The observed value of a pass is a detail: admitted, not kept.
        r.observed = Some(Rgba([0.1, 0.0, 0.0, 1.0]));
        assert!(Passed::admits(&r));
        r.reason = Some("why".into());
        assert!(!Passed::admits(&r));
        r.reason = None;
        r.status = Status::Plain(Outcome::Warn);
        assert!(!Passed::admits(&r));
        let mut r = pass("c", ApiPath::GlslCore);
        r.rerun = Some(Outcome::Pass);
        assert!(!Passed::admits(&r));
        let mut r = pass("c", ApiPath::GlslCore);
        r.tags.func = "two words".into();
        assert!(!Passed::admits(&r));
    }

    #[test]
    fn malformed_tags_are_an_error_not_a_panic() {
        let p = Passed {
            backend: "b".into(),
            tags: "only three parts".into(),
            fixtures: None,
            cases: vec![PassedCase("c".into(), vec![(ApiPath::FixedFunction, 0.0)])],
        };
        assert!(p.results().is_err());
    }
}
