//! The run's contract with CI under faults (runner/README.md, "What a run guarantees"): each test injects one fault through the
//! `mock:` implementation or the file system and checks the statuses, the exit code and the files
//! left in `--out`.

mod common;
use common::*;
use std::path::Path;

fn report(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap()
}

/// (status, reason) of the one test whose name contains `needle`, from results.jsonl (every test;
/// report.json holds only the tests that did not pass), read by the one results.jsonl reader (the
/// last record of a test is its final one; compact `passed` lines expand to their tests).
fn result_of(out: &Path, needle: &str) -> (String, String) {
    let read = shadowcheck_runner::records::read_results(&out.join("results.jsonl")).unwrap();
    let found: Vec<_> = read
        .results
        .iter()
        .filter(|r| r.test.contains(needle))
        .collect();
    assert_eq!(found.len(), 1, "{needle}: {found:?}");
    (
        found[0].status.to_string(),
        found[0].reason.clone().unwrap_or_default(),
    )
}

fn counts(out: &Path) -> serde_json::Value {
    report(out)["summary"]["counts"].clone()
}

#[test]
fn an_extra_answer_line_blames_the_case_that_answered_twice() {
    let (dir, fx) = cases_dir("extra", 12);
    let out = dir.join("out");
    // n=0002 answers twice in the middle of a group; n=0003 twice at the end of its group (the
    // stray line is read when the next group starts).
    let r = run(&[
        "-b",
        "mock:extra=n=000[23]$",
        "--group",
        "4",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    for bad in ["n=0002@", "n=0003@"] {
        let (status, reason) = result_of(&out, bad);
        assert_eq!(status, "Crash", "{bad}: {reason}");
        assert!(reason.contains("answered this case twice"), "{reason}");
    }
    // The case whose answer was expected when the stray line came is not blamed.
    for good in ["n=0004@", "n=0001@"] {
        assert_eq!(result_of(&out, good).0, "Pass", "{good}");
    }
    let c = counts(&out);
    assert_eq!(
        (c["crash"].as_u64(), c["flake"].as_u64()),
        (Some(2), Some(0))
    );
    assert_eq!(c["pass"], 10);
}

#[test]
fn two_results_for_one_path_and_empty_results_are_failures_not_skips() {
    let (dir, fx) = cases_dir("dup", 8);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:dup=n=0002$,empty=n=0005$",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let (status, reason) = result_of(&out, "n=0002@");
    assert_eq!(status, "Fail");
    assert!(
        reason.contains("two results for API path `core`"),
        "{reason}"
    );
    let (status, reason) = result_of(&out, "n=0005@");
    assert_eq!(status, "Fail");
    assert!(
        reason.contains("neither a result nor a skip for API path `core`"),
        "{reason}"
    );
    assert_eq!(counts(&out)["skip"], 0);
}

#[test]
fn a_crash_that_recurs_on_the_rerun_is_crash_not_flake() {
    // The implementation dies on every 2nd case it reads, whichever it is (the count survives its
    // restarts): the re-run of the crashed cases crashes again, though not always on the same case.
    let (dir, fx) = cases_dir("crashevery", 30);
    let out = dir.join("out");
    let o = bin()
        .args([
            "run",
            "-b",
            "mock:buffer,crashevery=2",
            "--fixtures",
            &fx,
            "--out",
            out.to_str().unwrap(),
        ])
        .env("SHADOWCHECK_MOCK_COUNTER", dir.join("count"))
        .output()
        .unwrap();
    let r = Run::of(o);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let c = counts(&out);
    assert!(c["crash"].as_u64().unwrap() > 0, "{c}");
    assert_eq!(c["flake"], 0, "{c}");
    let rep = report(&out);
    // Crashes whose own re-run passed (a Flake under "any different outcome") stay Crash, saying why.
    let passed_alone: Vec<_> = rep["results"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["status"] == "Crash" && r["rerun"] == "Pass")
        .collect();
    assert!(!passed_alone.is_empty(), "{rep}");
    assert!(passed_alone.iter().all(|r| r["reason"]
        .as_str()
        .unwrap()
        .contains("crashed or hung again")));
}

#[test]
fn an_implementation_that_hangs_on_everything_is_given_up_after_k_timeouts() {
    let (dir, fx) = cases_dir("hang", 40);
    let out = dir.join("out");
    let t0 = std::time::Instant::now();
    let r = run(&[
        "-b",
        "mock:hang",
        "--timeout",
        "0.3",
        "--group",
        "8",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    let took = t0.elapsed().as_secs_f64();
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let c = counts(&out);
    assert_eq!(c["timeout"], 40, "{c}");
    let rep = report(&out);
    let not_sent = rep["results"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| {
            r["reason"]
                .as_str()
                .unwrap()
                .contains("not sent: the implementation gave no answer to 3 cases in a row")
        })
        .count();
    assert_eq!(not_sent, 37);
    // 7 stalls of 0.3 s (8, 4, 2, 1, 1, 2, 1 cases), not 5 per case.
    assert!(took < 20.0, "{took} s");
}

#[test]
fn a_backend_that_skips_everything_and_a_skips_list_of_everything_exit_4() {
    let (dir, fx) = cases_dir("skipall", 6);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:skip",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 4, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stdout.contains("backend `mock:skip` ran no test"),
        "{}",
        r.stdout
    );
    assert!(
        r.stdout.contains("exit code 4 (no test ran)"),
        "{}",
        r.stdout
    );
    let skips = dir.join("skips.txt");
    std::fs::write(&skips, ".*\n").unwrap();
    let r = run(&[
        "-b",
        "mock:",
        "-b",
        "soft",
        "--skips",
        skips.to_str().unwrap(),
        "--fixtures",
        &fx,
        "--out",
        dir.join("out2").to_str().unwrap(),
    ]);
    assert_eq!(r.code, 4, "{}{}", r.stdout, r.stderr);
    // One backend that ran nothing beside one that passes is not "all good" either.
    let r = run(&[
        "-b",
        "mock:skip",
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        dir.join("out3").to_str().unwrap(),
    ]);
    assert_eq!(r.code, 4, "{}{}", r.stdout, r.stderr);
}

#[test]
fn a_requested_backend_that_cannot_start_is_named_and_the_run_exits_96_unless_skip_missing() {
    let (dir, fx) = cases_dir("missing", 4);
    let args = |out: &str, extra: &[&str]| {
        let mut a = vec![
            "-b",
            "mock:",
            "-b",
            "exec:/nonexistent/implementation",
            "--fixtures",
            &fx,
        ];
        a.extend_from_slice(extra);
        let out = dir.join(out);
        let mut a: Vec<String> = a.iter().map(|s| s.to_string()).collect();
        a.extend(["--out".to_string(), out.display().to_string()]);
        run(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let r = args("o1", &[]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("error: backend `exec:/nonexistent/implementation` cannot start here"),
        "{}",
        r.stderr
    );
    assert_eq!(results(&dir.join("o1")).len(), 4);
    let r = args("o2", &["--skip-missing"]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
}

#[test]
fn a_second_run_into_a_locked_out_directory_exits_96_naming_the_holder() {
    let (dir, fx) = cases_dir("lock", 4);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let lock = shadowcheck_runner::outdir::OutLock::acquire(&out).unwrap();
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    let holder = format!(
        "in use by another shadowcheck run (pid {})",
        std::process::id()
    );
    assert!(r.stderr.contains(&holder), "{}", r.stderr);
    // Nothing of the holder's was touched.
    assert!(!out.join("results.jsonl").exists());
    drop(lock);
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
}

/// Files in `dir` that are empty or temporaries.
fn empty_or_temporary(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let meta = e.metadata().unwrap();
            name.contains(".tmp.") || (meta.is_file() && meta.len() == 0 && !name.starts_with('.'))
        })
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect()
}

#[test]
fn a_report_that_cannot_be_written_is_said_with_the_regressions_and_leaves_no_partial_file() {
    let (dir, fx) = cases_dir("writefail", 6);
    let out = dir.join("out");
    // report.json cannot be written: a non-empty directory stands where it goes.
    std::fs::create_dir_all(out.join("report.json/blocker")).unwrap();
    let r = run(&[
        "-b",
        "mock:fail=n=0001$",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    // Regressions win (100); the write error is said beside them, in the line that gives the code.
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let last = r.stdout.lines().last().unwrap_or_default();
    assert!(
        last.contains("exit code 100 (regressions; also 96: writing ")
            && last.contains("report.json"),
        "{last}"
    );
    assert!(
        empty_or_temporary(&out).is_empty(),
        "{:?}",
        empty_or_temporary(&out)
    );
    for f in ["results.csv", "junit.xml", "report.md", "failures.csv"] {
        assert!(std::fs::metadata(out.join(f)).unwrap().len() > 0, "{f}");
    }
    // Without regressions the write error decides: 96, as printed.
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stdout
            .lines()
            .last()
            .unwrap_or_default()
            .contains("exit code 96 (writing "),
        "{}",
        r.stdout
    );
}

#[test]
fn results_jsonl_on_a_full_device_is_an_error_before_any_test_runs() {
    let (dir, fx) = cases_dir("devfull", 4);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::os::unix::fs::symlink("/dev/full", out.join("results.jsonl")).unwrap();
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("No space left on device"), "{}", r.stderr);
}

#[test]
fn an_interrupted_run_writes_its_reports_says_how_to_resume_and_exits_130() {
    let (dir, fx) = cases_dir("sigint", 60);
    let out = dir.join("out");
    let args = [
        "run",
        "-b",
        "mock:fail=n=0003$",
        "--group",
        "8",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ];
    // The worker sends SIGINT to the runner when case 30 arrives (as a CI job's SIGTERM would).
    let r = Run::of(
        bin()
            .args(args)
            .env("SHADOWCHECK_MOCK_INTERRUPT_RUNNER", "n=0030$")
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 130, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("Resume with:"), "{}", r.stderr);
    assert!(r.stderr.contains("--resume"), "{}", r.stderr);
    assert!(
        r.stdout
            .contains("exit code 130 (interrupted; also 100: regressions)"),
        "{}",
        r.stdout
    );
    // Every answer that came back before the signal is kept, and nothing after it: the first k
    // cases in order, none blamed for the interruption. Case 30 is in the fourth group of 8,
    // written ahead once the second group is answered, so 16 <= k; k <= 32, as no group is
    // written once the signal has been handled.
    let kept = results(&out);
    assert!((16..=32).contains(&kept.len()), "{kept:?}");
    let mut sent: Vec<usize> = kept
        .iter()
        .map(|(test, status, _)| {
            assert!(status == "Pass" || status == "Fail", "{kept:?}");
            let n = test.split("/n=").nth(1).and_then(|t| t.split('@').next());
            n.and_then(|n| n.parse().ok()).unwrap_or(usize::MAX)
        })
        .collect();
    sent.sort_unstable();
    assert_eq!(sent, (0..kept.len()).collect::<Vec<_>>(), "{kept:?}");
    assert!(empty_or_temporary(&out).is_empty());
    let resumed = run(&[&args[1..], &["--resume"]].concat());
    assert_eq!(resumed.code, 100, "{}{}", resumed.stdout, resumed.stderr);
    assert_eq!(results(&out).len(), 60);
}

#[test]
fn ctrl_c_on_the_whole_process_group_keeps_no_crash_of_the_signalled_worker() {
    // As from a terminal: SIGINT reaches the runner and its implementation process at once. The
    // worker's death is the interruption, not a Crash of the case it was on.
    use std::os::unix::process::CommandExt;
    let (dir, fx) = cases_dir("ctrlc", 400);
    let out = dir.join("out");
    let args = [
        "run",
        "-b",
        "mock:slow=5",
        "--group",
        "16",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ];
    let child = bin()
        .args(args)
        .process_group(0)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let pid = child.id() as i32;
    // Wait for a few batches on disk, then Ctrl-C the group.
    let t0 = std::time::Instant::now();
    while std::fs::read_to_string(out.join("results.jsonl"))
        .map(|s| s.lines().count())
        .unwrap_or(0)
        < 40
    {
        assert!(t0.elapsed().as_secs() < 60, "the run did not start");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    // SAFETY: kill(2) on the process group this test created; no memory is involved.
    assert_eq!(unsafe { libc::kill(-pid, libc::SIGINT) }, 0);
    let r = Run::of(child.wait_with_output().unwrap());
    assert_eq!(r.code, 130, "{}{}", r.stdout, r.stderr);
    let kept = results(&out);
    assert!(!kept.is_empty() && kept.len() < 400, "{}", kept.len());
    assert!(kept.iter().all(|r| r.1 == "Pass"), "{kept:?}");
    let resumed = run(&[&args[1..], &["--resume"]].concat());
    assert_eq!(resumed.code, 0, "{}{}", resumed.stdout, resumed.stderr);
    assert_eq!(results(&out).len(), 400);
}

#[test]
fn an_extra_answer_for_a_sweep_point_blames_its_case() {
    // The mock runs no sweeps, so each point is sent as a case of its own
    // (`<id>/sweep=<k>`); point 3 answers twice.
    let dir = tmpdir("extra-point");
    let out = dir.join("out");
    let fx = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures/gl46/2d/nearest.json");
    let id = "gl46/2d/d16/nearest/never/texel1/ref=0.3/dt=0.2_0.4_0.6_0.8";
    let r = run(&[
        "-b",
        "mock:extra=/sweep=3$",
        "--fixtures",
        fx.to_str().unwrap(),
        "--cases",
        &format!("^{}$", regex::escape(id)),
        "--no-rerun",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let (status, reason) = result_of(&out, &format!("{id}@core"));
    assert_eq!(status, "Crash", "{reason}");
    assert!(
        reason.contains("answered sweep point 3 of this case twice"),
        "{reason}"
    );
}
