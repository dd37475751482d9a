//! deqp-runner compatibility, checked with deqp-runner's own code (the `deqp-runner` crate, 0.24):
//! its CSV reader (`RunnerResults::from_csv`, which splits on every comma and refuses a name
//! listed twice) reads shadowcheck's results.csv and failures.csv of single- and multi-backend
//! runs, and its baseline logic (`read_baseline`, `RunnerStatus::with_baseline`) applied to a
//! failures.csv excuses exactly what shadowcheck's `--baseline` excuses, per backend.

mod common;
use common::*;
use deqp_runner::{read_baseline, RunnerResults, RunnerStatus};
use std::path::Path;

fn deqp_read(path: &Path) -> RunnerResults {
    let mut f = std::fs::File::open(path).unwrap();
    match RunnerResults::from_csv(&mut f) {
        Ok(r) => r,
        Err(e) => panic!("deqp-runner cannot read {}: {e:#}", path.display()),
    }
}

fn run_ok(args: &[&str], want: i32) -> Run {
    let r = run(args);
    assert_eq!(r.code, want, "{}{}", r.stdout, r.stderr);
    r
}

const ONE: &str = "mock:fail=n=0001";
// A comma in a backend name: the prefix writes it as `_` (names need no CSV quoting).
const TWO: &str = "mock:fail=n=0002,crash=n=0003";

#[test]
fn deqp_runner_reads_single_backend_results_and_failures() {
    let (dir, fx) = cases_dir("deqp-single", 8);
    let out = dir.join("out");
    run_ok(
        &["-b", ONE, "--fixtures", &fx, "--out", out.to_str().unwrap()],
        100,
    );
    let results = deqp_read(&out.join("results.csv"));
    assert_eq!(results.result_counts.total, 8);
    assert_eq!(results.result_counts.fail, 1);
    assert_eq!(results.result_counts.pass, 7);
    let failures = deqp_read(&out.join("failures.csv"));
    assert_eq!(failures.result_counts.total, 1);
    let name = "gl46/2d/d16/nearest/gequal/ref=0.5/texel=0_0/n=0001@core";
    assert_eq!(
        failures.get(name).map(|r| r.status),
        Some(RunnerStatus::Fail)
    );
}

#[test]
fn multi_backend_files_name_each_test_once_keep_the_backend_and_baseline_per_backend() {
    let (dir, fx) = cases_dir("deqp-multi", 8);
    let out = dir.join("out");
    run_ok(
        &[
            "-b",
            ONE,
            "-b",
            TWO,
            "--fixtures",
            &fx,
            "--out",
            out.to_str().unwrap(),
        ],
        100,
    );
    // One result per test name: the backend is the name's prefix.
    let results = deqp_read(&out.join("results.csv"));
    assert_eq!(results.result_counts.total, 16);
    let failures = deqp_read(&out.join("failures.csv"));
    assert_eq!(
        failures.result_counts.total, 3,
        "one per failing test per backend"
    );
    let two = "mock:fail=n=0002_crash=n=0003";
    let listed: Vec<(String, RunnerStatus)> = failures
        .sorted_results()
        .iter()
        .map(|r| (r.test.clone(), r.status))
        .collect();
    for (prefix, n, want) in [
        (ONE, 1, RunnerStatus::Fail),
        (two, 2, RunnerStatus::Fail),
        (two, 3, RunnerStatus::Crash),
    ] {
        let tail = format!("/n={n:04}@core");
        assert!(
            listed
                .iter()
                .any(|(t, s)| t.starts_with(&format!("{prefix}/gl46/"))
                    && t.ends_with(&tail)
                    && *s == want),
            "{prefix} {tail} {want:?} not in {listed:?}"
        );
    }

    // deqp-runner applying failures.csv as the baseline of the same results: every failure is an
    // ExpectedFail, n=0001 on the second backend (which passes there) stays a Pass.
    let baseline = read_baseline(Some(&out.join("failures.csv"))).unwrap();
    for r in results.sorted_results() {
        let listed = baseline.get(&r.test).map(|b| b.status);
        let now = r.status.with_baseline(listed);
        assert!(now.is_success(), "{} {:?} -> {now:?}", r.test, r.status);
        assert!(
            !matches!(now, RunnerStatus::UnexpectedImprovement(_)),
            "{}",
            r.test
        );
    }

    // shadowcheck with the same baseline: exit 0, the same verdicts.
    let again = dir.join("again");
    run_ok(
        &[
            "-b",
            ONE,
            "-b",
            TWO,
            "--fixtures",
            &fx,
            "--baseline",
            out.join("failures.csv").to_str().unwrap(),
            "--out",
            again.to_str().unwrap(),
        ],
        0,
    );
    let rows = results_named(&again);
    let status = |prefix: &str, n: u32| {
        let tail = format!("/n={n:04}@core");
        rows.iter()
            .find(|r| r.0.starts_with(&format!("{prefix}/gl46/")) && r.0.ends_with(&tail))
            .map(|r| r.1.clone())
            .unwrap_or_else(|| panic!("{prefix} {tail} not in results.csv"))
    };
    assert_eq!(status(ONE, 1), "ExpectedFail");
    assert_eq!(status(two, 1), "Pass");
    assert_eq!(status(two, 2), "ExpectedFail");
    assert_eq!(status(two, 3), "ExpectedFail");
    // And deqp-runner reads the second run's results.csv too.
    assert_eq!(
        deqp_read(&again.join("results.csv"))
            .result_counts
            .expected_fail,
        3
    );
}

/// results.csv as (test, status), read by the test's own CSV splitter.
fn results_named(dir: &Path) -> Vec<(String, String)> {
    results(dir).into_iter().map(|(t, s, _)| (t, s)).collect()
}
