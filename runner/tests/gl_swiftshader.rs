//! zink on SwiftShader's Vulkan driver (`egl:zink+swiftshader:*`): the context each preset gets and
//! what runs on it by capability. The compat backend runs at GL 2.1, SwiftShader's native version,
//! with no override: the GLSL 1.30 path is Skip with its reason, the legacy paths return the spec's
//! values. Expectations come from the spec (LEQUAL of a constant texture), not from the driver.
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

#[test]
fn compat_runs_at_gl_2_1_and_skips_glsl_1_30_by_capability() {
    let Some(mut s) = Session::start("egl:zink+swiftshader:compat") else {
        return;
    };
    let name = s.hello["name"].as_str().unwrap_or("").to_string();
    assert!(name.contains("SwiftShader"), "{name}");
    assert!(name.contains("(2.1 Mesa"), "no override on compat: {name}");
    let paths = [
        ApiPath::FixedFunction,
        ApiPath::Glsl120,
        ApiPath::Glsl130,
        ApiPath::ArbFp,
    ];
    // Dt = 32768/65535: LEQUAL passes for 0.1 (r = 1), fails for 0.9 (r = 0); GL 2.1 Table 3.20
    // LUMINANCE layout (r, r, r, 1) on the legacy paths.
    let cases: Vec<Case> = [(0.1, 1.0), (0.9, 0.0)]
        .iter()
        .map(|(dref, _)| {
            d16_case(
                &format!("d{dref}"),
                Spec::Arb,
                &paths,
                Target::T2d,
                32768,
                *dref,
            )
        })
        .collect();
    let answers = s.run(&cases);
    for (a, r) in answers.iter().zip([1.0, 0.0]) {
        for p in [ApiPath::FixedFunction, ApiPath::Glsl120, ApiPath::ArbFp] {
            // Alpha is zink's known deviation (reports/README.md cause 6: (r, r, r, r) whatever
            // DEPTH_TEXTURE_MODE says, as in gl_compat.rs KNOWN; fixed function too, read through
            // the COMBINE environment), so only r, g, b are checked.
            let got = Session::rgba(a, p);
            assert_eq!(got[..3], [r, r, r], "{p}: {a}");
        }
        let skipped = a["skipped"].as_array().cloned().unwrap_or_default();
        assert!(
            skipped
                .iter()
                .any(|k| k["api"] == "glsl130" && k["reason"] == "GLSL 1.30 not supported"),
            "{a}"
        );
    }
}

#[test]
fn core_and_es3_run_under_the_documented_overrides() {
    for (backend, version) in [
        ("egl:zink+swiftshader:core", "4.6 (Core Profile)"),
        ("egl:zink+swiftshader:es3", "OpenGL ES 3.1"),
    ] {
        let Some(mut s) = Session::start(backend) else {
            continue;
        };
        let name = s.hello["name"].as_str().unwrap_or("").to_string();
        assert!(
            name.contains(version) && name.contains("SwiftShader"),
            "{name}"
        );
        let (spec, path) = if backend.ends_with("es3") {
            (Spec::Gles32, ApiPath::Es300)
        } else {
            (Spec::Gl46, ApiPath::GlslCore)
        };
        let cases = [
            d16_case("pass", spec, &[path], Target::T2dArray, 32768, 0.1),
            d16_case("fail", spec, &[path], Target::T2dArray, 32768, 0.9),
        ];
        let answers = s.run(&cases);
        assert_eq!(Session::rgba(&answers[0], path)[0], 1.0, "{backend}");
        assert_eq!(Session::rgba(&answers[1], path)[0], 0.0, "{backend}");
    }
}

#[test]
fn a_missing_swiftshader_icd_is_announced_with_the_install_command() {
    let dir = std::env::temp_dir().join(format!("shadowcheck-zss-missing-{}", std::process::id()));
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
        .args(["run", "-b", "egl:zink+swiftshader:es3", "--out"])
        .arg(dir.join("out"))
        .env(
            "SHADOWCHECK_VK_SWIFTSHADER_ICD",
            dir.join("no-such-icd.json"),
        )
        .output()
        .expect("run shadowcheck");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(96), "{err}");
    assert!(err.contains("no-such-icd.json"), "{err}");
    assert!(err.contains("apt-get install -y chromium-common"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
