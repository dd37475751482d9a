//! `shadowcheck repro` on the WebGL 2.0 backends: the harness runs a test on a `webgl:*` instance,
//! then `repro` writes the plain WebGL 2.0 page (repro.html) and build.sh, which runs it in
//! headless Chromium with the instance's flags and environment; the page, with no shadowcheck code,
//! must print the very RGBA the harness observed and exit 1 for a Fail (0 for a pass). Expected
//! values are the oracle's (inside the page); the observation is compared with this run's.
//!
//! Without Chromium (or the instance's driver) the test is skipped with a loud message, except
//! under CI=true, where it fails (`.ci/run` installs them).

mod common;
use common::*;
use shadowcheck_runner::records::Outcome;
use std::path::PathBuf;
use std::process::Command;

fn installed_or_skip(backend: &str) -> bool {
    let key = backend.trim_start_matches("webgl:");
    let why = match shadowcheck_webgl::instance::instance(key).and_then(|i| i.installed()) {
        Ok(()) => return true,
        Err(e) => e.to_string(),
    };
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {backend} is not installed: {why}");
    }
    eprintln!("\n*** SKIPPED the {backend} repro test: {why} ***\n");
    false
}

fn fixture_file(id: &str) -> PathBuf {
    grid_fixture_file(id)
}

/// Runs `test` on `backend` in the harness, writes its page with `repro`, runs build.sh on its own
/// and checks the page printed the harness's RGBA and exited as the harness's verdict says.
fn check(backend: &str, test: &str, want: Outcome) -> Option<PathBuf> {
    if !installed_or_skip(backend) {
        return None;
    }
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let fixtures = fixture_file(&id);
    // One directory per (backend, test): the tests run in parallel, some on the same backend.
    let slug: String = format!("{backend}-{test}")
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    let out = tmpdir(&format!("webgl-repro-{slug}"));
    let (rec, rc, dir) = harness_then_repro(backend, test, &fixtures, &out);
    assert_eq!(rec.outcome, want, "{test} on {backend}: {:?}", rec.reason);
    let harness = rec.observed.as_ref().expect("harness observed nothing").0;
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    assert_eq!(dir.join("REPORT.md").is_file(), want == Outcome::Fail);
    let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
    assert!(
        !page.contains("shadowcheck."),
        "the page calls no shadowcheck code"
    );
    let own = Command::new("sh")
        .arg("build.sh")
        .current_dir(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&own.stdout).into_owned();
    let code = if want == Outcome::Fail { 1 } else { 0 };
    assert_eq!(own.status.code(), Some(code), "{stdout}");
    let observed = repro_observed(&stdout);
    assert!(
        harness
            .iter()
            .zip(observed)
            .all(|(a, b)| (*a as f32) == (b as f32)),
        "{test}: page {observed:?}, harness {harness:?}"
    );
    Some(dir)
}

/// ANGLE's Vulkan back end on SwiftShader: an EQUAL comparison against a reference below 0 that the
/// spec clamps to 0 first (the WebGL report's reference-clamp class).
#[test]
fn a_webgl_fail_reproduces_on_chromium() {
    let Some(dir) = check(
        "webgl:chromium",
        "gles32/2d/d24/nearest/equal/clamp/dt=0/ref=-0.1@es300",
        Outcome::Fail,
    ) else {
        return;
    };
    let out = std::fs::read_to_string(dir.join("output.txt")).unwrap();
    assert!(out.contains("WEBGL_RENDERER: ANGLE"), "{out}");
    let report = std::fs::read_to_string(dir.join("REPORT.md")).unwrap();
    assert!(
        report.contains("**Fail**") && report.contains("WEBGL_RENDERER: `"),
        "{report}"
    );
}

/// A pass on ANGLE's OpenGL ES back end over llvmpipe (the instance's environment in build.sh);
/// with an accepted set no result lies in, the same page exits 1.
#[test]
fn a_webgl_pass_reproduces_on_chromium_gles_and_a_wrong_set_fails() {
    let Some(dir) = check(
        "webgl:chromium-gles",
        "gles32/2d/d24/nearest/equal/clamp/dt=0/ref=-0.1@es300",
        Outcome::Pass,
    ) else {
        return;
    };
    let sh = std::fs::read_to_string(dir.join("build.sh")).unwrap();
    assert!(
        sh.contains("env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe"),
        "{sh}"
    );
    let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
    let tampered = page.replace("const ACCEPTED = [", "const ACCEPTED = [[-9, -8]] || [");
    std::fs::write(dir.join("repro.html"), tampered).unwrap();
    let o = Command::new("sh")
        .arg(dir.join("build.sh"))
        .output()
        .unwrap();
    let s = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{s}");
    assert!(s.contains("verdict:   FAIL"), "{s}");
}

/// A TexParameter state case on `webgl:chromium`: the page makes the worker's call and read-back
/// and agrees with the harness (a Pass: INVALID_ENUM, the state unchanged, ES 3.2 §8.10); with the
/// expected error made INVALID_VALUE the same page exits 1.
#[test]
fn a_webgl_state_case_reproduces_and_a_wrong_expectation_fails() {
    let backend = "webgl:chromium";
    if !installed_or_skip(backend) {
        return;
    }
    let test = "state/gles32/es/2d/compare_func/set=0x1234@es300";
    let fixtures =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures/state/gles32.json");
    let (rec, rc, dir) = harness_then_repro(backend, test, &fixtures, &tmpdir("webgl-repro-state"));
    assert_eq!(rec.outcome, Outcome::Pass, "{:?}", rec.reason);
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    let sh = |dir: &std::path::Path| {
        let o = Command::new("sh")
            .arg(dir.join("build.sh"))
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stdout).into_owned(),
        )
    };
    let (code, text) = sh(&dir);
    assert_eq!(code, Some(0), "{text}");
    assert!(
        text.contains(
            "expected:  GL_INVALID_ENUM, value 0x0203\nobserved:  GL_INVALID_ENUM, value 0x0203\n"
        ),
        "{text}"
    );
    let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
    let base = "  { extension: null, error: 1280, value: 515,";
    assert!(page.contains(base), "{page}");
    std::fs::write(
        dir.join("repro.html"),
        page.replace(base, "  { extension: null, error: 1281, value: 515,"),
    )
    .unwrap();
    let (code, text) = sh(&dir);
    assert_eq!(code, Some(1), "{text}");
    assert!(text.contains("verdict:   FAIL"), "{text}");
}

/// A lookup whose values differ between the fragments of the pixel quad (`per_fragment` delivery)
/// and a colour texture of four components: the page draws the worker's 2x2 quad and uploads the
/// worker's texels, and prints the harness's RGBA.
#[test]
fn a_per_fragment_lookup_and_a_colour_texture_reproduce() {
    let Some(dir) = check(
        "webgl:chromium-gles",
        "gles32/2d/d24/lml/lequal/mip/delivery=per_fragment/lod=0.5/ref=0.3/levels=0.2_0.8_0.4@es300",
        Outcome::Pass,
    ) else {
        return;
    };
    let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
    assert!(page.contains("viewport: [0, 0, 2, 2]"), "{page}");
    check(
        "webgl:chromium",
        "gles32/2d/rgba8/linear/lequal/formats/bypass/a=0.25_0.5/ref=0.5/dt=0.2_0.4_0.6_0.8@es300",
        Outcome::Fail,
    );
}

/// A case the WebGL worker does not draw (a shadow gather: GLSL ES 3.00 has none) gets no page:
/// `repro` says why, as the worker's Skip does, and writes nothing that would not run.
#[test]
fn a_case_the_webgl_worker_skips_gets_no_page() {
    let backend = "webgl:chromium";
    if !installed_or_skip(backend) {
        return;
    }
    let id = "gles32/2d/d24/linear/lequal/gather/delivery=per_fragment/uv=1.75_2.25/ref=0.375";
    let out = tmpdir("webgl-repro-skip");
    let rc = Run::of(
        bin()
            .args(["repro", "-b", backend, "--case", &format!("{id}@es300")])
            .arg("--fixtures")
            .arg(fixture_file(id))
            .arg("-o")
            .arg(out.join("repro"))
            .output()
            .unwrap(),
    );
    assert_eq!(rc.code, 96, "{}{}", rc.stdout, rc.stderr);
    assert!(
        rc.stderr.contains("does not draw this case") && rc.stderr.contains("gather"),
        "{}",
        rc.stderr
    );
    assert!(!out.join("repro").join("repro.html").exists());
}
