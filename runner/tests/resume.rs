//! A run killed with SIGKILL midway keeps what it finished in results.jsonl, and `--resume`
//! completes it with the same final report as an uninterrupted run.
//!
//! The kill is deterministic: the mock worker reads SHADOWCHECK_MOCK_KILL_RUNNER (a regex on case
//! ids) and sends SIGKILL to its parent, the runner, when the first matching case arrives.

mod common;
use common::*;

#[test]
fn sigkill_then_resume_gives_the_uninterrupted_report() {
    let dir = tmpdir("resume");
    let fx = dir.join("fixtures/cases.json");
    write_fixture(&fx, many_cases(300));
    let fx = fx.to_str().unwrap();
    let script = "mock:fail=n=00[0-4]7,crash=n=0123";

    let whole = dir.join("whole");
    let r = run(&[
        "-b",
        script,
        "--fixtures",
        fx,
        "--out",
        whole.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);

    let killed = dir.join("killed");
    let o = bin()
        .args([
            "run",
            "-b",
            script,
            "--fixtures",
            fx,
            "--out",
            killed.to_str().unwrap(),
        ])
        .env("SHADOWCHECK_MOCK_KILL_RUNNER", "n=0250")
        .output()
        .unwrap();
    {
        use std::os::unix::process::ExitStatusExt;
        assert_eq!(
            o.status.signal(),
            Some(9),
            "the runner should have been killed: {o:?}"
        );
    }
    let done = shadowcheck_runner::records::read_results(&killed.join("results.jsonl"))
        .unwrap()
        .results
        .len();
    // Case 250 is in the fourth batch of 64, which is sent ahead once the second batch has come
    // back; by then the first batch is surely on disk (the second is being judged).
    assert!(
        (64..300).contains(&done),
        "{done} results on disk after the kill"
    );
    assert!(
        !killed.join("report.json").exists(),
        "no final report from a killed run"
    );

    let r = run(&[
        "-b",
        script,
        "--fixtures",
        fx,
        "--out",
        killed.to_str().unwrap(),
        "--resume",
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    assert_eq!(results(&killed), results(&whole));
    assert_eq!(
        report_without_durations(&killed),
        report_without_durations(&whole)
    );
    let read = |d: &std::path::Path| std::fs::read_to_string(d.join("failures.csv")).unwrap();
    assert_eq!(read(&killed), read(&whole));

    // Resuming with another selection is refused (bad input).
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        fx,
        "--out",
        killed.to_str().unwrap(),
        "--resume",
    ]);
    assert_eq!(r.code, 96, "{}", r.stderr);
}
