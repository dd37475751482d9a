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
    for sub in ["bench", "mutants"] {
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
