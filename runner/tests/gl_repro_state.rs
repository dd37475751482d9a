//! `shadowcheck repro` of TexParameter state cases on GL backends: the harness judges the case's
//! call and read-back, then the reproducer (repro.c: the same call on a fresh texture in the
//! worker's context, the oracle's expectation as constants) runs on its own and must print the
//! observation the harness judged, exiting 1 for a Fail and 0 for a Pass.
//!
//! Needs gcc, the GL dev packages and the drivers: missing ones are a loud skip, a failure under
//! CI=true (see gl_support).
mod common;
mod gl_support;

use shadowcheck_runner::records::Outcome;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A TexParameter state case: the harness's verdict, then the reproducer on its own, which must
/// print the observation the harness judged and exit 1 for a Fail, 0 for a Pass.
fn check_state(backend: &str, test: &str, want: Outcome) -> Option<PathBuf> {
    if let Err(e) = shadowcheck_runner::backend::gl::worker_command(backend) {
        gl_support::unavailable(backend, &e.to_string());
        return None;
    }
    if !gl_support::can_build(backend) {
        return None;
    }
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let spec = id.split('/').nth(1).unwrap();
    let fixtures =
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../cases/fixtures/state/{spec}.json"));
    let out = common::tmpdir(&format!("repro-state-{}", backend.replace(':', "-")));
    let (rec, rc, dir) = common::harness_then_repro(backend, test, &fixtures, &out);
    assert_eq!(rec.outcome, want, "{test} on {backend}: {:?}", rec.reason);
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    assert_eq!(dir.join("REPORT.md").is_file(), want == Outcome::Fail);
    let own = Command::new("sh")
        .arg("build.sh")
        .current_dir(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&own.stdout).into_owned();
    let code = if want == Outcome::Fail { 1 } else { 0 };
    assert_eq!(own.status.code(), Some(code), "{stdout}");
    let observed = stdout
        .lines()
        .find_map(|l| l.strip_prefix("observed:"))
        .map(str::trim)
        .unwrap_or_else(|| panic!("no observed line: {stdout}"));
    match &rec.reason {
        // The harness's reason says what it got: the very observation of the program.
        Some(why) if want == Outcome::Fail => {
            assert!(
                why.contains(&format!("got {observed};")),
                "{why} / {observed}"
            )
        }
        _ => assert!(
            stdout.contains(&format!("expected:  {observed}\n")),
            "{stdout}"
        ),
    }
    Some(dir)
}

/// TEXTURE_COMPARE_FUNC set to a value that is no compare function: INVALID_ENUM and the state
/// unchanged (ES 3.2 §8.10). llvmpipe does so; the program passes, and with the expected error made
/// INVALID_VALUE it exits 1.
#[test]
fn a_state_case_passes_on_llvmpipe_and_a_wrong_expectation_fails() {
    let Some(dir) = check_state(
        "egl:llvmpipe:es3",
        "state/gles32/es/2d/compare_func/set=0x1234@es300",
        Outcome::Pass,
    ) else {
        return;
    };
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    assert!(c.contains("glTexParameteri(TARGET, PNAME, 0x1234);"), "{c}");
    assert!(c.contains("{NULL, 0x0500, 1, 0x0203, 0.0f,"), "{c}");
    let wrong = c.replace(
        "{NULL, 0x0500, 1, 0x0203, 0.0f,",
        "{NULL, 0x0501, 1, 0x0203, 0.0f,",
    );
    std::fs::write(dir.join("repro.c"), wrong).unwrap();
    let own = Command::new("sh")
        .arg("build.sh")
        .current_dir(&dir)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&own.stdout);
    assert_eq!(own.status.code(), Some(1), "{out}");
    assert!(out.contains("verdict:   FAIL"), "{out}");
}

/// SwiftShader's GLES raises INVALID_VALUE where ES 3.2 §8.10 requires INVALID_ENUM (the committed
/// swiftshader-4.0.0.3 report): the state reproducer, through its EGL 1.4 pbuffer, says the same.
#[test]
fn a_state_case_fails_on_swiftshader_gles() {
    let _ = check_state(
        "egl:swiftshader:es3",
        "state/gles32/es/2d/compare_func/set=0x1234@es300",
        Outcome::Fail,
    );
}
