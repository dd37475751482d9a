//! Faults of the run pipeline found by the second fault campaign: each test injects one fault
//! through the `mock:` implementation (its misbehaving actions, PROTOCOL.md violations) and checks
//! the statuses, the reasons and the exit code.

mod common;
use common::*;
use shadowcheck_runner::records::{read_results, TestResult};
use std::path::{Path, PathBuf};

fn committed(rel: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../cases/fixtures")
        .join(rel)
        .display()
        .to_string()
}

/// Every final record of results.jsonl (the last record of a test wins).
fn records(out: &Path) -> Vec<TestResult> {
    read_results(&out.join("results.jsonl")).unwrap().results
}

fn of<'a>(recs: &'a [TestResult], needle: &str) -> Vec<&'a TestResult> {
    recs.iter().filter(|r| r.test.contains(needle)).collect()
}

fn out_dir(name: &str) -> PathBuf {
    tmpdir(name).join("out")
}

#[test]
fn faults_found_while_state_cases_are_read_are_crashes() {
    // One lookup (its second answer arrives only when the first state case is read), then the
    // state cases of TEXTURE_COMPARE_MODE: 0x0205 answered twice, 0x0207 answered under the id of
    // 0x0206 (the case before it), and the last one, 0x884E, answered twice after its group.
    let out = out_dir("state-faults");
    let lookup = "gl46/2d/d16/nearest/never/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8";
    let r = run(&[
        "-b",
        "mock:late=never/texel1/ref=0\\.5/,extra=set=0x0205$,previous=set=0x0207$,extra=set=0x884E$",
        "--fixtures",
        &committed("gl46/2d/nearest.json"),
        "--fixtures",
        &committed("state/gl46.json"),
        "--cases",
        &format!(
            "^{}$|^state/gl46/core/2d/compare_mode/",
            regex::escape(lookup)
        ),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let recs = records(&out);
    let twice = "answered this case twice";
    let lookups = of(&recs, lookup);
    assert_eq!(lookups.len(), 4, "{lookups:?}");
    for t in lookups {
        assert_eq!(t.status.to_string(), "Crash", "{t:?}");
        assert!(t.reason.as_deref().unwrap_or("").contains(twice), "{t:?}");
    }
    for bad in ["set=0x0205@", "set=0x0206@", "set=0x884E@"] {
        let t = of(&recs, bad);
        assert_eq!(t.len(), 1, "{bad}");
        assert_eq!(t[0].status.to_string(), "Crash", "{bad}: {:?}", t[0]);
        assert!(t[0].reason.as_deref().unwrap_or("").contains(twice));
    }
    // The case whose answer was expected when the wrong line came is sent again: not blamed.
    assert_eq!(of(&recs, "set=0x0207@")[0].status.to_string(), "Pass");
    let crashes = recs
        .iter()
        .filter(|t| t.status.to_string() == "Crash")
        .count();
    assert_eq!(crashes, 4 + 3, "{recs:?}");
    assert!(r.stdout.contains("7 crash"), "{}", r.stdout);
}

#[test]
fn a_one_off_protocol_violation_is_crash_not_flake() {
    // Case 3 is answered twice the first time it arrives only (the ids seen are kept in a file
    // across the worker's restarts): the re-run would answer it correctly. The violation happened.
    let (dir, fx) = cases_dir("once", 8);
    let out = dir.join("out");
    let r = Run::of(
        bin()
            .args([
                "run",
                "-b",
                "mock:once,extra=n=0003$",
                "--group",
                "4",
                "--fixtures",
                &fx,
                "--out",
                out.to_str().unwrap(),
            ])
            .env("SHADOWCHECK_MOCK_SEEN", dir.join("seen"))
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let recs = records(&out);
    let t = of(&recs, "n=0003@");
    assert_eq!(t[0].status.to_string(), "Crash", "{:?}", t[0]);
    assert!(t[0].rerun.is_none(), "a protocol violation is not re-run");
    assert_eq!(
        recs.iter()
            .filter(|t| t.status.to_string() == "Pass")
            .count(),
        7
    );
}

#[test]
fn a_hanging_case_with_28_sweep_points_counts_once_toward_give_up() {
    // The mock runs no sweeps, so the case is sent as its lookup and 28 points, each a case of its
    // own; all hang. With --give-up-after 3 the other 29 cases must still run.
    let out = out_dir("sweep-hang");
    let hung = "gl46/2d/d16/nearest/never/texel1/ref=0.3/dt=0.2_0.4_0.6_0.8";
    let t0 = std::time::Instant::now();
    let r = run(&[
        "-b",
        &format!("mock:hang=^{}", regex::escape(hung)),
        "--fixtures",
        &committed("gl46/2d/nearest.json"),
        "--cases",
        "^gl46/2d/d16/nearest/(never|less)/",
        "--timeout",
        "0.3",
        "--give-up-after",
        "3",
        "--no-rerun",
        "--out",
        out.to_str().unwrap(),
    ]);
    let took = t0.elapsed().as_secs_f64();
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let recs = records(&out);
    assert_eq!(recs.len(), 30 * 4);
    for t in &recs {
        let want = if t.case_id == hung { "Timeout" } else { "Pass" };
        assert_eq!(t.status.to_string(), want, "{t:?}");
    }
    // Its points are not sent once one part of the case gave no answer: a few stalls in all.
    assert!(took < 15.0, "{took} s");
}

#[test]
fn a_crash_after_megabytes_of_stderr_keeps_a_bounded_reason() {
    // Case 2 writes a 4 MiB stderr line, then exits.
    let (dir, fx) = cases_dir("spew", 4);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:spew=n=0002$",
        "--no-rerun",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let recs = records(&out);
    let t = of(&recs, "n=0002@");
    assert_eq!(t[0].status.to_string(), "Crash");
    let reason = t[0].reason.as_deref().unwrap_or("");
    assert!(reason.len() < 8 << 10, "{} bytes of reason", reason.len());
    assert!(reason.contains("bytes of this line not kept"), "{reason}");
    assert!(reason.contains("mock: spewed 4 MiB"), "{reason}");
    let mut total = 0;
    for e in std::fs::read_dir(&out).unwrap() {
        total += e.unwrap().metadata().unwrap().len();
    }
    assert!(total < 1 << 20, "{total} bytes of reports");
}

#[test]
fn an_answer_that_is_not_utf8_is_a_protocol_error_on_its_case() {
    let (dir, fx) = cases_dir("notutf8", 6);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:notutf8=n=0002$",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let recs = records(&out);
    let t = of(&recs, "n=0002@");
    assert_eq!(t[0].status.to_string(), "Crash");
    let reason = t[0].reason.as_deref().unwrap_or("");
    assert!(
        reason.starts_with("protocol error: bad answer line: not UTF-8"),
        "{reason}"
    );
    assert!(!reason.contains("SIGKILL"), "{reason}");
    assert_eq!(
        recs.iter()
            .filter(|t| t.status.to_string() == "Pass")
            .count(),
        5
    );
}

#[test]
fn the_interrupt_message_counts_only_the_tests_of_the_run() {
    // 60 GL 4.6 cases: tests of the mock, not applicable on soft:sgix (another spec). The run has
    // 60 tests, not 120.
    let (dir, fx) = cases_dir("sigint-count", 60);
    let out = dir.join("out");
    let r = Run::of(
        bin()
            .args([
                "run",
                "-b",
                "mock:",
                "-b",
                "soft:sgix",
                "--group",
                "8",
                "--fixtures",
                &fx,
                "--out",
                out.to_str().unwrap(),
            ])
            .env("SHADOWCHECK_MOCK_INTERRUPT_RUNNER", "n=0030$")
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 130, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains(" of 60 tests finished"), "{}", r.stderr);
}
