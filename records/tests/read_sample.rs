//! Reads the committed samples in `tests/data/` with the crate's public API alone, as an outside
//! tool would. Every expected value below is counted by hand from the sample files.

use shadowcheck_records::{exit, read_results, Counts, Outcome, Status, Summary};
use std::path::Path;

fn sample(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

#[test]
fn a_finished_run_is_counted_and_its_closing_record_seen() {
    let r = read_results(&sample("finished.jsonl")).expect("the sample reads");
    let meta = r.meta.as_ref().expect("a meta line");
    assert_eq!(meta.backends, ["soft", "exec:./my-impl"]);

    // 5 tests: the passed line stands for 2, the soft Fail is replaced by its later Flake record.
    assert_eq!(r.results.len(), 5);
    let flaky = r
        .get("soft", "gl46/2d/d16/nearest/greater/ref=0.5@core")
        .expect("the soft greater test");
    assert_eq!(flaky.status, Status::Flake);
    assert_eq!(flaky.rerun, Some(Outcome::Pass));
    let improved = r
        .get(
            "exec:./my-impl",
            "gl46/2d/d16/nearest/lequal/ref=0.5@glsl130",
        )
        .expect("the exec glsl130 test");
    assert_eq!(
        improved.status,
        Status::UnexpectedImprovement(Outcome::Pass)
    );

    let summary = Summary::new(meta.backends.clone(), &r.results, r.load_errors.len());
    let want = Counts {
        pass: 2,
        expected_fail: 1,
        unexpected_improvement: 1,
        flake: 1,
        ..Counts::default()
    };
    assert_eq!(summary.counts, want);
    assert_eq!(summary.counts.regressions(), 0);
    // No regression, but one bad fixture file: a setup error.
    assert_eq!(r.load_errors.len(), 1);
    assert_eq!(summary.exit_code, exit::SETUP);

    assert_eq!(r.not_applicable.get("exec:./my-impl"), Some(&1));
    let end = r.end.as_ref().expect("the closing record");
    assert_eq!(end.get("soft"), Some(&3));
    assert_eq!(end.get("exec:./my-impl"), Some(&2));
    assert!(!r.truncated);
    assert_eq!(r.unfinished(), None);
}

#[test]
fn a_killed_run_is_recognised_as_unfinished() {
    let r = read_results(&sample("unfinished.jsonl")).expect("a cut last line is not an error");
    assert!(r.truncated, "the cut last line is dropped and reported");
    assert_eq!(r.end, None);
    assert_eq!(r.results.len(), 2);
    assert!(r
        .results
        .iter()
        .all(|t| t.status == Status::Plain(Outcome::Pass)));
    let why = r.unfinished().expect("no closing record: unfinished");
    assert!(why.contains("cut off"), "{why}");
    assert!(why.contains("`soft`: 2 of 3 tests written"), "{why}");
    assert!(why.contains("`exec:./my-impl`: never started"), "{why}");
}

#[test]
fn a_file_that_is_not_there_is_an_error_naming_it() {
    let err = read_results(&sample("missing.jsonl")).expect_err("no such file");
    assert!(err.to_string().contains("missing.jsonl"), "{err}");
}
