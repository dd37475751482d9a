//! Must show: the Vulkan backends (`vk:lavapipe`, `vk:swiftshader`) run real cases through their
//! `vk-worker` child, under VK_LAYER_KHRONOS_validation (`SHADOWCHECK_VK_VALIDATION=1`), and the
//! oracle judges them: every 2D case passes (or is inside the quality tier), what the device lacks
//! is Skip with the reason (SwiftShader has no D24 format at all), and the validation layer says
//! nothing (a message would make the case an Error).
//!
//! The cases are `cases/fixtures/vulkan/2d/` when present, else the GL 4.6 core 2D fixtures
//! recast as Vulkan cases (spec `vulkan`, API path `vk`, no stored expectation: the oracle
//! evaluates them). A driver, glslangValidator or the validation layer that is not installed
//! skips the test with a loud message, except under CI=true, where it fails (`.ci/run` installs
//! mesa-vulkan-drivers, chromium, glslang-tools and vulkan-validationlayers).

mod common;
use common::*;
use shadowcheck_model::{ApiPath, Spec};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// Whether everything `backend` needs is installed; otherwise skips loudly (fails under CI).
fn installed_or_skip(backend: &str, icd: &str, install: &str) -> bool {
    let missing = [
        (Path::new(icd).is_file(), format!("{icd} ({install})")),
        (
            std::process::Command::new("glslangValidator")
                .arg("--version")
                .output()
                .is_ok(),
            "glslangValidator (apt-get install -y glslang-tools)".to_string(),
        ),
        (
            Path::new("/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json")
                .is_file(),
            "the validation layer (apt-get install -y vulkan-validationlayers)".to_string(),
        ),
    ];
    let missing: Vec<&String> = missing.iter().filter(|m| !m.0).map(|m| &m.1).collect();
    if missing.is_empty() {
        return true;
    }
    let what = format!("{backend} needs {:?}", missing);
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {what}: .ci/run must install it");
    }
    eprintln!("\n*** SKIPPED the {backend} test: {what} ***\n");
    false
}

/// The fixtures of the test: the committed Vulkan 2D fixtures, else the GL 4.6 core 2D ones as
/// Vulkan cases, written under `dir`.
fn fixtures(dir: &Path) -> PathBuf {
    let committed = repo().join("cases/fixtures/vulkan/2d");
    if committed.is_dir() {
        return committed;
    }
    let mut cases = vec![];
    for (_, f) in shadowcheck_cases::fixtures::load_path(&repo().join("cases/fixtures/gl46/2d"))
        .expect("gl46 2d fixtures")
    {
        for mut c in f.cases {
            if !c.api.contains(&ApiPath::GlslCore) {
                continue;
            }
            c.spec = Spec::Vulkan;
            c.api = vec![ApiPath::Vulkan];
            c.id = format!("vulkan/{}", c.id.split_once('/').map_or("", |p| p.1));
            c.expect = None;
            for p in &mut c.sweep {
                p.expect = None;
            }
            cases.push(c);
        }
    }
    assert!(cases.len() > 100, "too few 2D core cases: {}", cases.len());
    let path = dir.join("fixtures/vulkan/2d.json");
    write_fixture(&path, cases);
    path
}

/// (status, reason) of every test of `dir/results.jsonl`.
fn results(dir: &Path) -> BTreeMap<String, (String, Option<String>)> {
    shadowcheck_runner::records::read_results(&dir.join("results.jsonl"))
        .unwrap()
        .results
        .into_iter()
        .map(|r| (r.test, (r.status.to_string(), r.reason)))
        .collect()
}

fn run_backend(backend: &str, device: &str, icd: &str, install: &str, lacks: &[&str]) {
    if !installed_or_skip(backend, icd, install) {
        return;
    }
    let tmp = tmpdir(&backend.replace(':', "-"));
    let fx = fixtures(&tmp);
    let out = bin()
        .env("SHADOWCHECK_VK_VALIDATION", "1")
        .args(["run", "-v", "--backend", backend, "--fixtures"])
        .arg(&fx)
        .args(["--cases", "^vulkan/2d/", "--out"])
        .arg(tmp.join("out"))
        .output()
        .unwrap();
    let run = Run::of(out);
    assert!(
        run.code == 0,
        "exit {}: {}\n{}",
        run.code,
        run.stdout,
        run.stderr
    );
    // The worker answered, named its device and ran under the validation layer.
    let meta = std::fs::read_to_string(tmp.join("out/results.jsonl")).unwrap();
    let first = meta.lines().next().unwrap_or("");
    assert!(
        first.contains(device) && first.contains("validation"),
        "{first}"
    );
    assert!(!run.stderr.contains("vulkan validation"), "{}", run.stderr);
    let rs = results(&tmp.join("out"));
    let count = |s: &str| rs.values().filter(|r| r.0 == s).count();
    assert!(
        count("Pass") > 100,
        "{} passes of {}",
        count("Pass"),
        rs.len()
    );
    for (test, (status, reason)) in &rs {
        let reason = reason.clone().unwrap_or_default();
        assert!(!reason.contains("validation layer"), "{test}: {reason}");
        match status.as_str() {
            "Pass" => {}
            // Inside the quality tier: a filtered comparison that is not the exact weights.
            "Warn" => assert!(
                reason.contains("quality acceptance set"),
                "{test}: {reason}"
            ),
            // What the device or Vulkan lacks, or what the oracle does not define for Vulkan
            // (a lookup without comparison), never a draw.
            "Skip" => assert!(!reason.is_empty(), "{test}: a skip without a reason"),
            other => panic!("{test}: {other}: {reason}"),
        }
        for f in lacks {
            if test.contains(&format!("/{f}/")) {
                assert_eq!(status, "Skip", "{test}: {reason}");
            }
        }
    }
}

/// The validation messenger is live: a submission that breaks a valid-usage rule (the worker's
/// test fault) turns its answers into Errors quoting the layer, so every test is a Fail and the
/// run exits 100; without the validation layer the same fault goes unseen.
#[test]
fn a_validation_message_fails_the_tests_of_its_submission() {
    let (backend, icd) = ("vk:lavapipe", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
    if !installed_or_skip(backend, icd, "apt-get install -y mesa-vulkan-drivers") {
        return;
    }
    let tmp = tmpdir("vk-validation-fault");
    let fx = fixtures(&tmp);
    let run_with = |validation: &str, out: &str| {
        let o = bin()
            .env("SHADOWCHECK_VK_VALIDATION", validation)
            .env("SHADOWCHECK_VK_TEST_FAULT", "invalid-sampler")
            .args(["run", "--backend", backend, "--fixtures"])
            .arg(&fx)
            .args(["--cases", "^vulkan/2d/d16/nearest/lequal/", "--out"])
            .arg(tmp.join(out))
            .output()
            .unwrap();
        (Run::of(o), results(&tmp.join(out)))
    };
    let (run, rs) = run_with("1", "on");
    assert_eq!(run.code, 100, "{}\n{}", run.stdout, run.stderr);
    assert!(!rs.is_empty());
    for (test, (status, reason)) in &rs {
        let reason = reason.clone().unwrap_or_default();
        assert_eq!(status, "Fail", "{test}: {reason}");
        assert!(
            reason.contains("validation layer") && reason.contains("anisotropyEnable"),
            "{test}: {reason}"
        );
    }
    let (run, rs) = run_with("0", "off");
    assert_eq!(run.code, 0, "{}\n{}", run.stdout, run.stderr);
    assert!(rs.values().all(|r| r.0 == "Pass"), "{rs:?}");
}

#[test]
fn lavapipe_runs_the_2d_cases_under_validation() {
    run_backend(
        "vk:lavapipe",
        "llvmpipe",
        "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json",
        "apt-get install -y mesa-vulkan-drivers",
        &[],
    );
}

#[test]
fn swiftshader_runs_the_2d_cases_under_validation_and_skips_d24() {
    run_backend(
        "vk:swiftshader",
        "SwiftShader",
        "/usr/lib/chromium/vk_swiftshader_icd.json",
        "apt-get install -y chromium",
        &["d24", "d24s8"],
    );
}

/// A run holding zink and the Vulkan driver under it attributes zink's failures in report.md:
/// the LINEAR array-layer tie (GL: ⌊a + ½⌋; Vulkan: RNE or ⌊a + ½⌋) is the upper layer's, since
/// lavapipe answers the Vulkan lookup as Vulkan allows and zink does not emulate GL's rule.
#[test]
fn a_run_with_zink_and_lavapipe_attributes_the_layer_tie_to_zink() {
    let icd = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";
    if !installed_or_skip("vk:lavapipe", icd, "apt-get install -y mesa-vulkan-drivers") {
        return;
    }
    let tmp = tmpdir("vk-attribute");
    let out = bin()
        .args([
            "run",
            "-b",
            "egl:zink:core",
            "-b",
            "vk:lavapipe",
            "--fixtures",
        ])
        .arg(repo().join("cases/fixtures"))
        .arg("--cases")
        .arg("^(gl46|vulkan)/2darray/d24/linear/lequal/layer/")
        .arg("--out")
        .arg(tmp.join("out"))
        .output()
        .unwrap();
    let run = Run::of(out);
    // zink fails the ties (exit 100); lavapipe passes them.
    assert_eq!(run.code, 100, "{}\n{}", run.stdout, run.stderr);
    let md = std::fs::read_to_string(tmp.join("out/report.md")).unwrap();
    let section = md
        .split("## Layer attribution")
        .nth(1)
        .unwrap_or_else(|| panic!("no attribution in report.md:\n{md}"));
    assert!(
        section.contains("| egl:zink:core | upper |")
            && section.contains("the layer must emulate GL's rule"),
        "{section}"
    );
    let rs = results(&tmp.join("out"));
    assert!(rs
        .iter()
        .filter(|(t, _)| t.ends_with("@vk"))
        .all(|(_, r)| r.0 == "Pass"));
    // The HTML report of the same run has the section too.
    let o = bin()
        .args(["report"])
        .arg(tmp.join("out"))
        .arg("--fixtures")
        .arg(repo().join("cases/fixtures"))
        .arg("-o")
        .arg(tmp.join("html"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let page = std::fs::read_to_string(tmp.join("html/index.html")).unwrap();
    let layers = page
        .split("id=\"s-layers\"")
        .nth(1)
        .unwrap_or_else(|| panic!("no layer section in the HTML report"));
    assert!(layers.contains("<td>upper</td>") && layers.contains("must emulate GL"));
}

/// The compute-stage cases of the committed Vulkan fixtures (cube face edges, corners and
/// gathers at level 0, `stage=compute/`): each one dispatch of a compute pipeline storing into
/// the result image, under the validation layer, which says nothing. lavapipe answers every one
/// as the oracle accepts strictly or by quality, the gathers among them.
#[test]
fn lavapipe_runs_the_compute_stage_cases_under_validation() {
    let (backend, icd) = ("vk:lavapipe", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
    if !installed_or_skip(backend, icd, "apt-get install -y mesa-vulkan-drivers") {
        return;
    }
    let tmp = tmpdir("vk-compute");
    let out = bin()
        .env("SHADOWCHECK_VK_VALIDATION", "1")
        .args([
            "run",
            "-v",
            "--full-report",
            "--backend",
            backend,
            "--fixtures",
        ])
        .arg(repo().join("cases/fixtures/vulkan"))
        .args(["--cases", "/stage=compute/", "--out"])
        .arg(tmp.join("out"))
        .output()
        .unwrap();
    let run = Run::of(out);
    assert_eq!(run.code, 0, "{}\n{}", run.stdout, run.stderr);
    assert!(!run.stderr.contains("vulkan validation"), "{}", run.stderr);
    let rs = results(&tmp.join("out"));
    assert!(rs.len() >= 40, "{} compute tests", rs.len());
    for (test, (status, reason)) in &rs {
        assert!(test.contains("/stage=compute/"), "{test}");
        assert!(
            status == "Pass"
                || (status == "Warn" && reason.clone().unwrap_or_default().contains("quality")),
            "{test}: {status}: {reason:?}"
        );
    }
    assert!(
        rs.keys().any(|t| t.contains("/gather/")),
        "no compute gather among {} tests",
        rs.len()
    );
}
