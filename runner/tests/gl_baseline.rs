//! The committed Mesa 22.3.6 reference baselines (reports/mesa-22.3.6/<backend>/failures.csv) work
//! as deqp-runner baselines: a run of llvmpipe over a subset of the default fixtures with its
//! committed baseline (and flakes list) exits 0, the documented "all good" code (runner/README.md).
//! A missing driver is a loud skip here, a failure under CI=true (see gl_support).
mod common;
mod gl_support;

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Runs `backend` over `cases` (a --cases regex) of the default fixtures with the committed
/// baseline; `None` when the driver is not there (already reported by `unavailable`).
fn run_with_baseline(backend: &str, cases: &str, name: &str) -> Option<common::Run> {
    if let Err(e) = shadowcheck_runner::backend::gl::worker_command(backend) {
        gl_support::unavailable(backend, &e.to_string());
        return None;
    }
    let dir = root()
        .join("reports/mesa-22.3.6")
        .join(backend.replace(':', "-"));
    let baseline = dir.join("failures.csv");
    assert!(
        baseline.is_file(),
        "committed baseline missing: {}",
        baseline.display()
    );
    let out = common::tmpdir(name);
    let fixtures = root().join("cases/fixtures");
    let mut args: Vec<String> = vec![
        "--backend".into(),
        backend.into(),
        "--fixtures".into(),
        fixtures.display().to_string(),
        "--cases".into(),
        cases.into(),
        "--baseline".into(),
        baseline.display().to_string(),
        "--out".into(),
        out.display().to_string(),
    ];
    let flakes = dir.join("flakes.txt");
    if flakes.is_file() {
        args.extend(["--flakes".into(), flakes.display().to_string()]);
    }
    let argv: Vec<&str> = args.iter().map(String::as_str).collect();
    let r = common::run(&argv);
    if r.code == 96 && r.stderr.contains("cannot start") {
        gl_support::unavailable(backend, r.stderr.trim());
        return None;
    }
    Some(r)
}

#[test]
fn llvmpipe_core_subset_passes_with_its_committed_baseline() {
    let Some(r) = run_with_baseline("egl:llvmpipe:core", "^gl46/(2d|cube)/d24/", "baseline-core")
    else {
        return;
    };
    assert_eq!(
        r.code,
        0,
        "exit code {}\nstdout tail: {}\nstderr tail: {}",
        r.code,
        tail(&r.stdout),
        tail(&r.stderr)
    );
}

#[test]
fn llvmpipe_es3_known_failures_are_expected_fails_with_its_committed_baseline() {
    // The 2D ES cases include the sized-depth + COMPARE_MODE NONE + LINEAR cases that Mesa 22.3.6
    // samples although ES 3.2 §8.17 makes the texture incomplete: listed in the baseline.
    let Some(r) = run_with_baseline("egl:llvmpipe:es3", "^gles32/2d/", "baseline-es3") else {
        return;
    };
    assert_eq!(
        r.code,
        0,
        "exit code {}\nstdout tail: {}\nstderr tail: {}",
        r.code,
        tail(&r.stdout),
        tail(&r.stderr)
    );
    let summary = r
        .stderr
        .lines()
        .chain(r.stdout.lines())
        .find(|l| l.contains("expected fail"))
        .unwrap_or("")
        .to_string();
    assert!(
        !summary.contains(" 0 expected fail"),
        "the baseline excused nothing: {summary}"
    );
}

fn tail(s: &str) -> String {
    let lines: Vec<&str> = s.lines().collect();
    lines[lines.len().saturating_sub(15)..].join("\n")
}
