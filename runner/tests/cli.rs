//! The command line behaves the same in every subcommand: bad arguments are a setup error (96,
//! runner/README.md "Exit codes"), never clap's 2; --help and --version exit 0; a Markdown file
//! output is `--markdown FILE`, never `-o` (which names a directory wherever it exists).

mod common;
use common::bin;

fn code(args: &[&str]) -> (Option<i32>, String) {
    let o = bin().args(args).output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn bad_arguments_exit_with_the_setup_error_code() {
    for args in [
        &["run", "--no-such-flag"][..],
        &["gen", "--seed", "not-a-number"],
        &["explain", "--ref"],
        &["bench", "-o", "x.md"],
        &["mutants", "-o", "x.md"],
        &["no-such-subcommand"],
        &[],
    ] {
        let (c, err) = code(args);
        assert_eq!(c, Some(96), "shadowcheck {args:?}: {err}");
        assert!(
            !err.is_empty(),
            "shadowcheck {args:?} said nothing on stderr"
        );
    }
}

#[test]
fn help_and_version_exit_zero() {
    for args in [
        &["--help"][..],
        &["--version"],
        &["run", "--help"],
        &["bench", "--help"],
    ] {
        let o = bin().args(args).output().unwrap();
        assert_eq!(o.status.code(), Some(0), "shadowcheck {args:?}");
        assert!(!o.stdout.is_empty(), "shadowcheck {args:?} printed nothing");
    }
}

#[test]
fn markdown_outputs_have_their_own_flag() {
    for sub in ["bench", "mutants", "consensus"] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&o.stdout);
        assert!(help.contains("--markdown <FILE>"), "{sub} --help:\n{help}");
        assert!(!help.contains("-o,"), "{sub} --help still has -o:\n{help}");
    }
}

/// Runs `shadowcheck args` with stdout going to a pipe whose reader is closed before anything is
/// written, as `shadowcheck ... | head -0` does; returns the exit code and stderr.
fn with_closed_stdout(args: &[&str]) -> (Option<i32>, String) {
    use std::process::Stdio;
    let mut child = bin()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // the reader goes away
    let o = child.wait_with_output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn a_closed_stdout_is_not_a_crash_and_keeps_the_exit_code() {
    let (c, err) = with_closed_stdout(&["explain", "--func", "lequal"]);
    assert_eq!(c, Some(0), "explain | head: {err}");
    assert!(!err.contains("panicked"), "{err}");
    let (c, err) = with_closed_stdout(&["mutants", "--list"]);
    assert_eq!(c, Some(0), "mutants --list | head: {err}");
    // A run with a regression keeps its exit code (100) when nobody reads the summary table.
    let out = common::tmpdir("closed-stdout");
    let (c, err) = with_closed_stdout(&[
        "run",
        "-b",
        "mock:fail",
        "--fixtures",
        "../cases/fixtures/gl46/2d/nearest.json",
        "--cases",
        "^gl46/2d/d16/nearest/lequal/",
        "--no-rerun",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(c, Some(100), "run | head with regressions: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn absurd_timeouts_are_bad_input_not_a_panic() {
    for t in ["1e19", "1e20", "inf", "nan", "0", "-1"] {
        let (c, err) = code(&["run", "-b", "soft", "--timeout", t, "--cases", "^$"]);
        assert_eq!(c, Some(96), "--timeout {t}: {err}");
        assert!(err.contains("--timeout"), "--timeout {t}: {err}");
        assert!(!err.contains("panicked"), "--timeout {t}: {err}");
    }
}

#[test]
fn every_subcommand_that_writes_a_directory_takes_dash_o() {
    for sub in ["run", "gen", "report", "merge", "summarize"] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&o.stdout);
        assert!(
            help.contains("-o, --out <DIR>"),
            "{sub} --help has no `-o, --out <DIR>`:\n{help}"
        );
    }
    for sub in ["run", "bench"] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&o.stdout);
        assert!(help.contains("-b, --backend <B>"), "{sub}:\n{help}");
    }
    for sub in ["run", "bench", "mutants", "report"] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&o.stdout);
        assert!(
            help.contains("--fixtures <PATH>") && help.contains("(repeatable)"),
            "{sub}:\n{help}"
        );
    }
}

#[test]
fn bench_backends_are_named_as_in_run() {
    let (c, err) = code(&["bench", "--quick", "-b", "llvmpipe"]);
    assert_eq!(c, Some(96), "{err}");
    assert!(err.contains("named as in `run --backend`"), "{err}");
}

#[test]
fn every_flag_has_help() {
    // clap prints a flag without a doc comment as a bare `--name <VALUE>` line: every option
    // line must be followed by text on the same or the next line.
    for sub in [
        "run",
        "gen",
        "report",
        "merge",
        "summarize",
        "bench",
        "mutants",
        "explain",
        "consensus",
        "gtest",
        "repro",
    ] {
        let o = bin().args([sub, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&o.stdout);
        let lines: Vec<&str> = help.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let t = l.trim_start();
            if !t.starts_with('-') {
                continue;
            }
            let same_line = t.split("  ").skip(1).any(|s| !s.trim().is_empty());
            let next = lines.get(i + 1).map(|n| n.trim()).unwrap_or("");
            let next_is_text = !next.is_empty() && !next.starts_with('-');
            assert!(same_line || next_is_text, "{sub}: `{t}` has no help");
        }
    }
}

#[test]
fn a_missing_list_file_is_named_with_its_os_error_once() {
    let dir = common::tmpdir("missing-flakes");
    let missing = dir.join("no-such-flakes.txt");
    let out = dir.join("out");
    let (c, err) = code(&[
        "run",
        "-b",
        "soft",
        "--flakes",
        missing.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(c, Some(96), "{err}");
    assert!(err.contains("no-such-flakes.txt"), "{err}");
    assert_eq!(err.matches("No such file or directory").count(), 1, "{err}");
}

#[test]
fn consensus_of_a_missing_run_directory_is_a_setup_error() {
    let dir = common::tmpdir("consensus-missing");
    let missing = dir.join("no-such-run");
    let (c, err) = code(&["consensus", missing.to_str().unwrap()]);
    assert_eq!(c, Some(96), "{err}");
    assert!(err.contains("no-such-run"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
