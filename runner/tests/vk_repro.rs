//! `shadowcheck repro` on the Vulkan backends: the harness runs a case on `vk:lavapipe` (and on
//! `vk:swiftshader`), then the reproducer is written (repro.c, vert.glsl, frag.glsl, build.sh),
//! built with glslangValidator and gcc against libvulkan-dev and run on its own; it must exit 0
//! and print the very RGBA the harness observed. No Vulkan case is a Fail on these drivers, so the
//! exit-1 path is checked with a deliberately wrong expectation: the accepted set in the generated
//! repro.c is replaced by one no result lies in (the driver is not made to fail). Nothing here is
//! a driver value written down: the expectation is the oracle's and the observation is compared
//! with the harness's of this run.
//!
//! Needs the driver's ICD (mesa-vulkan-drivers; chromium for SwiftShader), glslang-tools, gcc and
//! libvulkan-dev: a missing one skips the test loudly, and fails it under CI=true (.ci/run
//! installs them).
mod common;
use common::{grid_fixture_file, repro_observed};

use shadowcheck_runner::records::Outcome;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Whether `driver`'s ICD and the reproducer's toolchain are installed; otherwise a loud skip (a
/// failure under CI=true).
fn installed_or_skip(driver: &str) -> bool {
    let (icd, install) = match driver {
        "lavapipe" => (
            "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json",
            "mesa-vulkan-drivers",
        ),
        _ => ("/usr/lib/chromium/vk_swiftshader_icd.json", "chromium"),
    };
    let runs = |cmd: &str| {
        Command::new(cmd)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let missing: Vec<String> = [
        (Path::new(icd).is_file(), format!("{icd} ({install})")),
        (
            runs("glslangValidator"),
            "glslangValidator (glslang-tools)".into(),
        ),
        (runs("gcc"), "gcc".into()),
        (
            Path::new("/usr/include/vulkan/vulkan.h").is_file(),
            "vulkan/vulkan.h (libvulkan-dev)".into(),
        ),
    ]
    .into_iter()
    .filter(|m| !m.0)
    .map(|m| m.1)
    .collect();
    if missing.is_empty() {
        return true;
    }
    let what = format!(
        "the vk:{driver} reproducer needs {}: apt-get install -y {install} glslang-tools gcc libvulkan-dev",
        missing.join(", ")
    );
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {what}: .ci/run must install it");
    }
    use std::io::Write as _;
    let _ = writeln!(
        std::io::stderr(),
        "\n*** SKIPPED (not a pass): {what} ***\n"
    );
    false
}

fn same_rgba(a: [f64; 4], b: [f64; 4]) -> bool {
    a.iter().zip(b).all(|(x, y)| (*x as f32) == (y as f32))
}

/// The shaders a reproducer of `test` has beside repro.c, and those it must not have: a
/// compute-stage lookup's comp.glsl, a fragment-stage one's vert.glsl and frag.glsl.
fn shader_files(test: &str) -> (&'static [&'static str], &'static [&'static str]) {
    if test.contains("/stage=compute/") {
        (&["comp.glsl"], &["vert.glsl", "frag.glsl"])
    } else {
        (&["vert.glsl", "frag.glsl"], &["comp.glsl"])
    }
}

/// `sh build.sh` in `dir`: (exit status, stdout, stderr).
fn build_sh(dir: &Path) -> (i32, String, String) {
    let o = Command::new("sh")
        .arg("build.sh")
        .current_dir(dir)
        .output()
        .unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Runs `test` (a case without a sweep: the harness's observation is its own lookup's) on
/// `vk:<driver>`, writes its reproducer with `repro`, runs it on its own and checks that it passes
/// with the harness's RGBA; then a wrong accepted set makes the same program exit 1. Returns the
/// reproducer's directory, or `None` when skipped.
fn check(driver: &str, test: &str) -> Option<PathBuf> {
    if !installed_or_skip(driver) {
        return None;
    }
    let backend = format!("vk:{driver}");
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let fixtures = grid_fixture_file(&id);
    // One directory per test: the lavapipe tests run in parallel.
    let tag = test
        .bytes()
        .fold(0u32, |h, b| h.wrapping_mul(31).wrapping_add(b as u32));
    let out = common::tmpdir(&format!("vk-repro-{driver}-{tag:08x}"));
    let rec = common::harness_record(&backend, test, &fixtures, &out);
    assert!(
        matches!(rec.outcome, Outcome::Pass | Outcome::Warn),
        "{test} on {backend}: {:?} {:?}",
        rec.outcome,
        rec.reason
    );
    let harness = rec.observed.as_ref().expect("harness observed nothing").0;

    // Not a Fail: `repro` refuses without --allow-pass (exit 1) and writes no REPORT.md.
    let dir = out.join("repro");
    let repro = |extra: &[&str]| {
        common::Run::of(
            common::bin()
                .args(["repro", "--backend", &backend, "--case", test, "--fixtures"])
                .arg(&fixtures)
                .arg("--out")
                .arg(&dir)
                .args(extra)
                .output()
                .unwrap(),
        )
    };
    let rc = repro(&[]);
    assert_eq!(rc.code, 1, "{}{}", rc.stdout, rc.stderr);
    let rc = repro(&["--allow-pass"]);
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    let (shaders, not_written) = shader_files(test);
    for f in ["repro.c", "build.sh", "output.txt"].iter().chain(shaders) {
        assert!(dir.join(f).is_file(), "no {f}: {}{}", rc.stdout, rc.stderr);
    }
    for f in not_written {
        assert!(!dir.join(f).exists(), "{f} written for {test}");
    }
    assert!(!dir.join("REPORT.md").exists());

    // The reproducer on its own, as a driver developer runs it.
    let (code, stdout, stderr) = build_sh(&dir);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("VK_DEVICE: "), "{stdout}");
    let observed = repro_observed(&stdout);
    assert!(
        same_rgba(harness, observed),
        "harness observed {harness:?}, reproducer {observed:?}"
    );

    // A deliberately wrong expectation: nothing lies in [2, 3], so the same observation is
    // outside the accepted set and the program exits 1.
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    let accepted = regex::Regex::new(r"static const double ACCEPTED\[\]\[2\] = \{.*\};").unwrap();
    assert!(accepted.is_match(&c), "no ACCEPTED constant in repro.c");
    let wrong = accepted.replace(&c, "static const double ACCEPTED[][2] = {{2.0, 3.0}};");
    // A gather's first value is judged by its own set (GATHER_ACCEPTED_0): the same wrong set.
    let gather0 =
        regex::Regex::new(r"static const double GATHER_ACCEPTED_0\[\]\[2\] = \{.*\};").unwrap();
    let wrong = gather0.replace(
        &wrong,
        "static const double GATHER_ACCEPTED_0[][2] = {{2.0, 3.0}};",
    );
    std::fs::write(dir.join("repro.c"), wrong.as_ref()).unwrap();
    let (code, stdout, stderr) = build_sh(&dir);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(stdout.contains("verdict:   FAIL"), "{stdout}");
    assert!(same_rgba(observed, repro_observed(&stdout)));
    Some(dir)
}

/// A mipmapped LINEAR cube-array lookup (imageCubeArray, the view's levels, explicit LOD) on
/// lavapipe.
#[test]
fn a_passing_case_reproduces_on_lavapipe() {
    let Some(dir) = check(
        "lavapipe",
        "vulkan/cubearray/d16/lml/lequal/lod=1/ref=0.5/levels=0.2_0.8_0.4@vk",
    ) else {
        return;
    };
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    for want in [
        ".viewType = 6 /* VK_IMAGE_VIEW_TYPE_CUBE_ARRAY */,",
        "#define NEED_IMAGE_CUBE_ARRAY 1",
        "VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json ./repro",
    ] {
        assert!(c.contains(want), "missing `{want}`");
    }
}

/// A shadow textureGatherOffsets (OpImageDrefGather with four constant offsets, which needs
/// shaderImageGatherExtended) on lavapipe: the four comparisons, each judged by its own set.
#[test]
fn a_gather_reproduces_on_lavapipe() {
    let Some(dir) = check(
        "lavapipe",
        "vulkan/2d/d24/nearest/lequal/gather/offsets=1/wrap=repeat/ref=0.5@vk",
    ) else {
        return;
    };
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    for want in [
        "#define NEED_GATHER_EXTENDED 1",
        "#define IS_GATHER 1",
        "static const char LAYOUT[4] = {'A', 'B', 'C', 'D'};",
    ] {
        assert!(c.contains(want), "missing `{want}`");
    }
    let frag = std::fs::read_to_string(dir.join("frag.glsl")).unwrap();
    assert!(frag.contains("textureGatherOffsets("), "{frag}");
}

/// A LINEAR 2D lookup on SwiftShader's Vulkan driver.
#[test]
fn a_passing_case_reproduces_on_swiftshader() {
    check(
        "swiftshader",
        "vulkan/2d/d16/linear/lequal/a=0.25_0.5/ref=0.7/dt=0.2_0.4_0.6_0.8@vk",
    );
}

/// A format the device lacks (SwiftShader has no D24): the program says so and exits 2, and
/// `repro` exits 96 (the harness answers the test Skip there).
#[test]
fn a_format_the_device_lacks_is_a_setup_error_naming_it() {
    if !installed_or_skip("swiftshader") {
        return;
    }
    let test = "vulkan/2d/d24/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@vk";
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let dir = common::tmpdir("vk-repro-lacks");
    let r = common::Run::of(
        common::bin()
            .args([
                "repro",
                "-b",
                "vk:swiftshader",
                "--case",
                test,
                "--fixtures",
            ])
            .arg(grid_fixture_file(&id))
            .arg("-o")
            .arg(&dir)
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("the device lacks SAMPLED_IMAGE, TRANSFER_DST and TRANSFER_SRC on VK_FORMAT_X8_D24_UNORM_PACK32"),
        "{}",
        r.stderr
    );
}

/// A missing shader compiler is a build error naming its package, not a panic (PATH holds only
/// what build.sh needs before it: sh and dirname). `vk:native` needs no ICD manifest to write.
#[test]
fn a_missing_shader_compiler_names_its_package() {
    let dir = common::tmpdir("vk-repro-no-glslang");
    let bin = dir.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    for tool in ["sh", "dirname"] {
        let Some(path) = ["/bin", "/usr/bin"]
            .iter()
            .map(|d| Path::new(d).join(tool))
            .find(|p| p.is_file())
        else {
            panic!("no {tool}");
        };
        std::os::unix::fs::symlink(path, bin.join(tool)).unwrap();
    }
    let test = "vulkan/2d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@vk";
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let r = common::Run::of(
        common::bin()
            .env("PATH", &bin)
            .args(["repro", "-b", "vk:native", "--case", test, "--fixtures"])
            .arg(grid_fixture_file(&id))
            .arg("-o")
            .arg(dir.join("repro"))
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains("glslangValidator is not installed")
            && r.stderr.contains("apt-get install -y glslang-tools"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
}

/// Bad Vulkan arguments exit 96 with a message naming the problem (no device needed).
#[test]
fn bad_vulkan_arguments_exit_96() {
    let fixtures = root().join("cases/fixtures/vulkan/2d/nearest.json");
    for (args, says) in [
        (
            vec!["--backend", "vk:nosuch", "--case", "x@vk"],
            "unknown Vulkan backend",
        ),
        (
            vec![
                "--backend",
                "vk:native",
                "--case",
                "vulkan/2d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@core",
            ],
            "runs the API paths vk",
        ),
    ] {
        let r = common::Run::of(
            common::bin()
                .arg("repro")
                .args(&args)
                .arg("--fixtures")
                .arg(&fixtures)
                .output()
                .unwrap(),
        );
        assert_eq!(r.code, 96, "{args:?}: {}", r.stderr);
        assert!(r.stderr.contains(says), "{args:?}: {}", r.stderr);
    }
}

/// The Khronos validation layer's manifest, or a loud skip (a failure under CI=true).
fn validation_layer_or_skip() -> bool {
    let manifest = "/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json";
    if Path::new(manifest).is_file() {
        return true;
    }
    let what =
        format!("the validation run needs {manifest}: apt-get install -y vulkan-validationlayers");
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {what}: .ci/run must install it");
    }
    use std::io::Write as _;
    let _ = writeln!(
        std::io::stderr(),
        "\n*** SKIPPED (not a pass): {what} ***\n"
    );
    false
}

/// The compute-stage Fail of SwiftShader's Vulkan driver (V1: no cube map edge handling in a
/// compute shader, reports/vulkan/repro/compute-cube-edge).
const COMPUTE_CUBE_EDGE: &str = "vulkan/cube/d32f/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/x0=0.9/edge_s/ref=0.5@vk";

/// On vk:swiftshader the harness answers the compute-stage cube-edge case Fail; its reproducer
/// (comp.glsl, one dispatch) builds, exits 1 and prints the harness's RGBA bit for bit, and run
/// under the validation layer it says nothing and exits 1 with the same RGBA.
#[test]
fn a_compute_stage_fail_reproduces_on_swiftshader_under_the_validation_layer() {
    if !installed_or_skip("swiftshader") || !validation_layer_or_skip() {
        return;
    }
    let backend = "vk:swiftshader";
    let test = COMPUTE_CUBE_EDGE;
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let fixtures = grid_fixture_file(&id);
    let out = common::tmpdir("vk-repro-swiftshader-compute-fail");
    let rec = common::harness_record(backend, test, &fixtures, &out);
    assert_eq!(rec.outcome, Outcome::Fail, "{:?}", rec.reason);
    let harness = rec.observed.as_ref().expect("harness observed nothing").0;

    // A Fail: `repro` writes the reproducer and REPORT.md without --allow-pass.
    let dir = out.join("repro");
    let rc = common::Run::of(
        common::bin()
            .args(["repro", "--backend", backend, "--case", test, "--fixtures"])
            .arg(&fixtures)
            .arg("--out")
            .arg(&dir)
            .output()
            .unwrap(),
    );
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    for f in [
        "repro.c",
        "comp.glsl",
        "build.sh",
        "output.txt",
        "REPORT.md",
    ] {
        assert!(dir.join(f).is_file(), "no {f}: {}{}", rc.stdout, rc.stderr);
    }
    for f in ["vert.glsl", "frag.glsl"] {
        assert!(
            !dir.join(f).exists(),
            "{f} written for a compute-stage case"
        );
    }
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    for want in [
        "vkCmdDispatch(cmd, 1, 1, 1);",
        "shader_module(\"comp.spv\")",
    ] {
        assert!(c.contains(want), "missing `{want}`");
    }
    assert!(!c.contains("vkCmdDraw("));

    // On its own, as a driver developer runs it: exit 1, the harness's RGBA.
    let (code, stdout, stderr) = build_sh(&dir);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(stdout.contains("verdict:   FAIL"), "{stdout}");
    let observed = repro_observed(&stdout);
    assert!(
        same_rgba(harness, observed),
        "harness observed {harness:?}, reproducer {observed:?}"
    );

    // Under the validation layer: no message, the same exit status and RGBA.
    let o = Command::new("./repro")
        .current_dir(&dir)
        .env(
            "VK_ICD_FILENAMES",
            "/usr/lib/chromium/vk_swiftshader_icd.json",
        )
        .env("VK_INSTANCE_LAYERS", "VK_LAYER_KHRONOS_validation")
        .output()
        .unwrap();
    let (vout, verr) = (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    );
    assert_eq!(o.status.code(), Some(1), "{vout}{verr}");
    // The layer writes its messages to stdout, the loader its own to stderr: the run prints
    // exactly what the plain run printed, and nothing on stderr but the loader's note that
    // VK_INSTANCE_LAYERS added the layer.
    assert_eq!(vout, stdout, "the validation run printed more: {verr}");
    let messages: Vec<&str> = verr
        .lines()
        .filter(|l| !l.starts_with("(general message"))
        .collect();
    assert!(messages.is_empty(), "validation messages: {messages:#?}");
    assert!(same_rgba(observed, repro_observed(&vout)), "{vout}");
}

/// On vk:lavapipe, where every compute-stage case passes, the same case's reproducer passes with
/// the harness's RGBA (`repro --allow-pass`), and exits 1 with an accepted set nothing lies in.
#[test]
fn a_compute_stage_case_reproduces_as_a_pass_on_lavapipe() {
    let Some(dir) = check("lavapipe", COMPUTE_CUBE_EDGE) else {
        return;
    };
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    assert!(c.contains("vkCmdDispatch(cmd, 1, 1, 1);"));
    let comp = std::fs::read_to_string(dir.join("comp.glsl")).unwrap();
    assert!(comp.contains("imageStore(u_out, u_at, r)"), "{comp}");
}
