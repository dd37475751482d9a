//! Must show: WebGL 2.0 on ANGLE's other back ends runs as backends of their own, each on its own
//! driver: `webgl:chromium-gles` (ANGLE's OpenGL ES back end on Mesa's llvmpipe) and
//! `webgl:chromium-lavapipe` (ANGLE's Vulkan back end on Mesa's lavapipe). Thirteen committed
//! GLES 3.2 cases on each, judged by the fixtures' expectations: depth comparisons of D16 / D32F
//! on 2D, cube and 2D-array textures and the D24 Dref clamp (ES 3.2 §8.20.1) pass; the LINEAR
//! array-layer tie (ES 3.2 §8.14.2) fails on both; the R8 colour texture with a compare mode
//! (ES 3.2 §8.20: no comparison for a colour format) fails under ANGLE's Vulkan back end only and
//! is a one-ulp Warn under its OpenGL ES back end; cube-map arrays are Skip. The run uses the
//! committed baseline of reports/webgl-chromium-*/ and must exit 0. The renderer string in the
//! run's meta line names the driver.
//!
//! Without Chromium or the driver the test is skipped with a loud message, except under CI=true,
//! where it fails (`.ci/run` installs chromium, libegl-mesa0, libgl1-mesa-dri and
//! mesa-vulkan-drivers).

mod common;
use common::*;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Whether `webgl:<key>` can run here: the browser and the driver's files are installed.
fn installed_or_skip(backend: &str) -> bool {
    let why = match shadowcheck_webgl::instance::of_backend(backend).map(|i| i.installed()) {
        Ok(Ok(())) => return true,
        Ok(Err(e)) | Err(e) => e,
    };
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {backend} cannot run: {why} (.ci/run must install it)");
    }
    eprintln!("\n*** SKIPPED the {backend} backend test: {why} ***\n");
    false
}

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// The cases: 13 tests of the default fixtures.
const CASES: &str = "^gles32/((2d|cube|2darray)/(d16|d32f)/nearest/less/texel1/ref=0\\.3/\
    |2d/d24/nearest/less/clamp/dt=0/ref=-0\\.1$|2d/d24/nearest/greater/clamp/dt=1/ref=1\\.1$\
    |2darray/d24/linear/lequal/layer/layer=0\\.5/|2d/r8/nearest/(less|none)/texel1/\
    |cubearray/d16/nearest/less/texel1/ref=0\\.3/)";

/// What the oracle's judgement of each test is on both backends, but the R8 compare case's.
fn common_outcome(test: &str) -> &'static str {
    if test.starts_with("gles32/cubearray/") {
        "Skip"
    } else if test.contains("/layer=0.5/") {
        // ES 3.2 §8.14.2: LINEAR takes layer ⌊0.5 + 1/2⌋ = 1; both give layer 0.
        "Fail"
    } else if test.contains("/r8/nearest/none/") {
        // The R8 texel 102 read as 0.40000004: inside `quality` (the 2^-16 of §2.3.4.1).
        "Warn"
    } else {
        "Pass"
    }
}

/// Runs the cases on `backend` with its committed baseline; returns the raw outcome of each test.
fn run_on(backend: &str) -> BTreeMap<String, String> {
    let slug = backend.replace(':', "-");
    let tmp = tmpdir(&slug);
    let baseline = std::fs::read_dir(repo().join("reports"))
        .unwrap()
        .flatten()
        .map(|e| e.path().join(&slug).join("failures.csv"))
        .find(|p| {
            p.is_file()
                && p.parent()
                    .and_then(|d| d.parent())
                    .and_then(|d| d.file_name())
                    .is_some_and(|n| n.to_string_lossy().starts_with("webgl-chromium-"))
        })
        .unwrap_or_else(|| panic!("no committed baseline reports/webgl-chromium-*/{slug}/"));
    let t0 = std::time::Instant::now();
    let out = bin()
        .args(["run", "-v", "--backend", backend, "--fixtures"])
        .arg(repo().join("cases/fixtures"))
        .args(["--cases", CASES, "--baseline"])
        .arg(&baseline)
        .arg("--out")
        .arg(&tmp)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(t0.elapsed().as_secs() < 60, "{backend}: {:?}", t0.elapsed());
    let jsonl = std::fs::read_to_string(tmp.join("results.jsonl")).unwrap();
    let meta: serde_json::Value = serde_json::from_str(jsonl.lines().next().unwrap()).unwrap();
    let implementation = meta["implementations"][backend].as_str().unwrap_or("");
    assert!(
        implementation.starts_with(&format!("{backend} (WebGL 2.0")),
        "{meta}"
    );
    let words: &[&str] = if backend.ends_with("-gles") {
        &["ANGLE", "llvmpipe", "OpenGL ES"]
    } else {
        &["ANGLE", "llvmpipe", "Vulkan"]
    };
    for w in words {
        assert!(implementation.contains(w), "{w}: {implementation}");
    }
    let r: BTreeMap<String, String> =
        shadowcheck_runner::records::read_results(&tmp.join("results.jsonl"))
            .unwrap()
            .results
            .into_iter()
            .map(|r| (r.test, r.outcome.as_str().to_string()))
            .collect();
    assert_eq!(r.len(), 13, "{r:?}");
    let _ = std::fs::remove_dir_all(&tmp);
    r
}

const R8_COMPARE: &str = "gles32/2d/r8/nearest/less/texel1/ref=0.3/dt=0.2_0.4_0.6_0.8@es300";

#[test]
fn angles_opengl_es_back_end_on_llvmpipe_runs_as_webgl_chromium_gles() {
    let backend = "webgl:chromium-gles";
    if !installed_or_skip(backend) {
        return;
    }
    for (test, outcome) in run_on(backend) {
        // The comparison is bypassed for the colour texture, as ES 3.2 §8.20 says; the texel
        // reads one ulp off (a Warn), as llvmpipe's own.
        let want = if test == R8_COMPARE {
            "Warn"
        } else {
            common_outcome(&test)
        };
        assert_eq!(outcome, want, "{test}");
    }
}

#[test]
fn angles_vulkan_back_end_on_lavapipe_runs_as_webgl_chromium_lavapipe() {
    let backend = "webgl:chromium-lavapipe";
    if !installed_or_skip(backend) {
        return;
    }
    for (test, outcome) in run_on(backend) {
        // ANGLE's Vulkan back end compares the R8 texel (0.3 < 0.4: r = 1) where ES 3.2 §8.20
        // returns the texel: a Fail, as on SwiftShader.
        let want = if test == R8_COMPARE {
            "Fail"
        } else {
            common_outcome(&test)
        };
        assert_eq!(outcome, want, "{test}");
    }
}
