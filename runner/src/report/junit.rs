//! junit.xml: one test suite per backend, one test case per test that did not pass (every test
//! with `run --full-report`; as deqp-runner's junit.xml, which lists failures) (quick-junit).
//!
//! Fail and UnexpectedImprovement are `<failure>` (both make the run exit non-zero), Crash and
//! Timeout are `<error>`, Skip is `<skipped>`; Pass, Warn, ExpectedFail, Flake and KnownFlake are
//! successes (with the status in system-out where it is not Pass).

use crate::events::{Event, Reporter};
use crate::records::{Outcome, Status, TestResult};
use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};
use std::path::{Path, PathBuf};
use std::time::Duration;

pub struct JunitReporter {
    dir: PathBuf,
    full: bool,
}

impl JunitReporter {
    pub fn new(dir: &Path, full: bool) -> JunitReporter {
        JunitReporter {
            dir: dir.to_path_buf(),
            full,
        }
    }
}

fn case(r: &TestResult) -> TestCase {
    let dump = super::dump(r, "");
    let message = r.reason.clone().unwrap_or_else(|| r.status.to_string());
    let status = match r.status {
        Status::Plain(Outcome::Fail) | Status::UnexpectedImprovement(_) => {
            let mut s = TestCaseStatus::non_success(NonSuccessKind::Failure);
            s.set_message(message)
                .set_type(r.status.to_string())
                .set_description(dump.clone());
            s
        }
        Status::Plain(Outcome::Crash | Outcome::Timeout) => {
            let mut s = TestCaseStatus::non_success(NonSuccessKind::Error);
            s.set_message(message)
                .set_type(r.status.to_string())
                .set_description(dump.clone());
            s
        }
        Status::Plain(Outcome::Skip) => {
            let mut s = TestCaseStatus::skipped();
            s.set_message(message);
            s
        }
        _ => TestCaseStatus::success(),
    };
    let mut tc = TestCase::new(r.test.clone(), status);
    tc.set_classname(format!("{}.{}", r.tags.spec, r.tags.target));
    tc.set_time(Duration::from_secs_f64(r.duration.max(0.0)));
    if !matches!(
        r.status,
        Status::Plain(
            Outcome::Pass | Outcome::Skip | Outcome::Fail | Outcome::Crash | Outcome::Timeout
        )
    ) && !r.status.is_improvement()
    {
        tc.set_system_out(format!("{}\n{dump}", r.status));
    }
    tc
}

/// The JUnit document for `results` (in report order, so one suite per backend, also for a
/// backend whose every test passed); passing tests are test cases only with `full`.
pub fn to_xml(results: &[TestResult], full: bool) -> Result<String, quick_junit::SerializeError> {
    let mut report = Report::new("shadowcheck");
    let mut suite: Option<TestSuite> = None;
    for r in results {
        if let Some(done) = suite.take_if(|s| s.name.as_str() != r.backend) {
            report.add_test_suite(done);
        }
        let s = suite.get_or_insert_with(|| TestSuite::new(r.backend.clone()));
        if super::in_detail(r, full) {
            s.add_test_case(case(r));
        }
    }
    if let Some(s) = suite {
        report.add_test_suite(s);
    }
    report.to_string()
}

impl Reporter for JunitReporter {
    fn event(&mut self, ev: &Event<'_>) -> std::io::Result<()> {
        if let Event::RunFinished { results, .. } = ev {
            let xml = to_xml(results, self.full).map_err(std::io::Error::other)?;
            super::atomic::write(&self.dir.join("junit.xml"), xml.as_bytes())?;
        }
        Ok(())
    }
}
