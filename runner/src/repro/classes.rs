//! Failure classes for `repro --all-failures`: the Fails of a results directory grouped so that one
//! reproducer stands for one cause, not one per case.
//!
//! The class key is built from what every record carries:
//! - the backend (driver, context kind, lookup form) and the API path: where it happens;
//! - whether the lookup compares (compare mode NONE vs a compare function): the state that
//!   changes the code path in a driver;
//! - the rule that was broken: the expectation's citations (the sections the oracle's result rests
//!   on; a target with rules of its own, such as cube-map face selection, cites them) and which
//!   channels missed (the channel letters of the verdict's reason, e.g. `r` or `g,b,a`), so a
//!   wrong value and a wrong layout are different classes.
//!
//! Target, format, filter, wrap, reference and coordinates are not in the key: the same rule failing
//! on a 2D and an array texture, on D16 and D24, or at several references, is one class (the index
//! lists the targets of each class). Flaky failures (Flake, KnownFlake) are left
//! out: a reproducer of a flake may not reproduce. The representative of a class is its test with the
//! shortest id (then the first by name): usually the plainest case.

use crate::records::{Outcome, Status, TestResult};
use std::collections::BTreeMap;

/// One failure class.
#[derive(Debug, Clone)]
pub struct Class {
    pub key: String,
    /// The parts of the key, for the index: backend, API path, compare or not, channels missed.
    pub parts: [String; 4],
    /// The citations of the broken rule.
    pub rule: String,
    /// The targets of the class's tests.
    pub targets: Vec<String>,
    /// The test whose reproducer stands for the class.
    pub representative: TestResult,
    /// Every test of the class, sorted.
    pub tests: Vec<String>,
}

/// The channel letters named in a verdict reason (`g = 0.4 (expected 0), a = ...` gives `g,a`).
fn missed_channels(reason: Option<&str>) -> String {
    let Some(r) = reason else {
        return String::new();
    };
    let after = r.split_once(": ").map_or(r, |(_, rest)| rest);
    let mut out = Vec::new();
    for part in after.split(", ") {
        if let Some((ch, _)) = part.split_once(" = ") {
            let ch = ch.trim();
            if ["r", "g", "b", "a"].contains(&ch) && !out.contains(&ch) {
                out.push(ch);
            }
        }
    }
    out.join(",")
}

fn parts(r: &TestResult) -> ([String; 4], String) {
    let compare = if r.tags.func == "none" {
        "compare mode NONE"
    } else {
        "compare"
    };
    let rule = r
        .expected
        .as_ref()
        .map(|e| e.citations.join("; "))
        .unwrap_or_default();
    (
        [
            r.backend.clone(),
            r.api.key().to_string(),
            compare.to_string(),
            missed_channels(r.reason.as_deref()),
        ],
        rule,
    )
}

/// The class key of a Fail record (see the module docs).
pub fn key(r: &TestResult) -> String {
    let (p, rule) = parts(r);
    format!("{} | {} | {} | missed {} | {rule}", p[0], p[1], p[2], p[3])
}

/// Is this record a failure that gets a reproducer (a Fail that is not a flake)?
pub fn is_reproducible_fail(r: &TestResult) -> bool {
    r.outcome == Outcome::Fail && !matches!(r.status, Status::Flake | Status::KnownFlake)
}

/// The classes of the Fails among `results`, in key order.
pub fn classes(results: &[TestResult]) -> Vec<Class> {
    let mut by: BTreeMap<String, Vec<&TestResult>> = BTreeMap::new();
    for r in results.iter().filter(|r| is_reproducible_fail(r)) {
        by.entry(key(r)).or_default().push(r);
    }
    by.into_iter()
        .filter_map(|(key, mut rs)| {
            rs.sort_by(|a, b| (a.test.len(), &a.test).cmp(&(b.test.len(), &b.test)));
            let representative = (*rs.first()?).clone();
            let mut tests: Vec<String> = rs.iter().map(|r| r.test.clone()).collect();
            tests.sort();
            let mut targets: Vec<String> = rs.iter().map(|r| r.tags.target.clone()).collect();
            targets.sort();
            targets.dedup();
            let (parts, rule) = parts(&representative);
            Some(Class {
                key,
                parts,
                rule,
                targets,
                representative,
                tests,
            })
        })
        .collect()
}

/// A directory name for a class: its index, the backend, API path and the representative's target.
pub fn slug(i: usize, c: &Class) -> String {
    let r = &c.representative;
    let raw = format!(
        "{:02}-{}-{}-{}",
        i + 1,
        r.backend,
        r.api.key(),
        r.tags.target
    );
    raw.chars()
        .map(|ch| {
            if ch.is_ascii_alphanumeric() || ch == '-' {
                ch
            } else {
                '-'
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::records::ExpectedSummary;
    use shadowcheck_model::Profile;

    fn fail(test: &str, reason: &str, cites: &[&str]) -> TestResult {
        let mut r = TestResult::sample(test, Status::ExpectedFail);
        r.outcome = Outcome::Fail;
        r.reason = Some(reason.into());
        r.expected = Some(ExpectedSummary {
            spec_value: Some(0.0),
            strict: "{0}".into(),
            quality: "{0}".into(),
            layout: "r,-,-,-".into(),
            profile: Profile::loosest(),
            citations: cites.iter().map(|c| c.to_string()).collect(),
        });
        r
    }

    #[test]
    fn same_rule_and_channels_is_one_class_another_rule_or_layout_is_another() {
        let a = fail(
            "gl46/x/d16/long/id@core",
            "outside the quality acceptance set: r = 1 (expected r in {0})",
            &["§8.17"],
        );
        let b = fail(
            "gl46/x/d24@core",
            "outside the quality acceptance set: r = 0.5 (expected r in {0})",
            &["§8.17"],
        );
        let c = fail(
            "gl46/y@core",
            "outside the quality acceptance set: r = 1 (expected r in {0})",
            &["§8.14.2"],
        );
        let d = fail(
            "gl46/z@core",
            "outside the quality acceptance set: a = 0 (expected 1)",
            &["§8.17"],
        );
        let mut flake = fail(
            "gl46/w@core",
            "outside the quality acceptance set: r = 1 (expected r in {0})",
            &["§8.17"],
        );
        flake.status = Status::KnownFlake;
        let mut pass = TestResult::sample("gl46/v@core", Status::Plain(Outcome::Pass));
        pass.outcome = Outcome::Pass;
        let cs = classes(&[a, b, c, d, flake, pass]);
        assert_eq!(cs.len(), 3, "{cs:#?}");
        let first = cs.iter().find(|c| c.tests.len() == 2).unwrap();
        assert_eq!(first.representative.test, "gl46/x/d24@core");
        assert_eq!(first.targets, ["2d"]);
        assert_eq!(first.parts[3], "r");
        assert!(cs.iter().any(|c| c.key.contains("missed a |")));
        assert_eq!(slug(0, first), "01-b-core-2d");
    }

    #[test]
    fn missed_channels_reads_the_verdict_reason() {
        assert_eq!(
            missed_channels(Some("outside the quality acceptance set: g = 0.4 (expected 0), a = 0.4 (expected r in {0.4})")),
            "g,a"
        );
        assert_eq!(missed_channels(None), "");
    }
}
