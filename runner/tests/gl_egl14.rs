//! EGL 1.4: the pbuffer fallback (forced on Mesa, where surfaceless contexts exist, and the only
//! path of SwiftShader's own GLES), a library directory named in the backend (`egl@<dir>:`), and
//! ES 3.0 gating on SwiftShader's GLES 3.0 context. Expected values come from the compare table
//! (LEQUAL of a constant texture: GL 4.6 / ES 3.2 Table 8.23), never from a driver.
mod gl_support;
use gl_support::*;
use shadowcheck_model::*;

/// D16 texel 32768: LEQUAL with Dref 0.1 passes (1), with 0.9 fails (0).
fn pass_fail(spec: Spec, path: ApiPath, target: Target) -> [Case; 2] {
    [
        d16_case("pass", spec, &[path], target, 32768, 0.1),
        d16_case("fail", spec, &[path], target, 32768, 0.9),
    ]
}

fn check_pass_fail(s: &mut Session, spec: Spec, path: ApiPath) {
    let answers = s.run(&pass_fail(spec, path, Target::T2d));
    assert_eq!(Session::rgba(&answers[0], path)[0], 1.0, "{}", s.backend);
    assert_eq!(Session::rgba(&answers[1], path)[0], 0.0, "{}", s.backend);
}

fn name(s: &Session) -> String {
    s.hello["name"].as_str().unwrap_or("").to_string()
}

#[test]
fn the_pbuffer_fallback_runs_cases_on_mesa() {
    for (backend, spec, path) in [
        ("egl:llvmpipe:es3", Spec::Gles32, ApiPath::Es300),
        ("egl:llvmpipe:compat", Spec::Gl46, ApiPath::Glsl120),
        ("egl:llvmpipe:core", Spec::Gl46, ApiPath::GlslCore),
    ] {
        let Some(mut s) = Session::start_with_env(backend, &[("SHADOWCHECK_EGL_PBUFFER", "1")])
        else {
            continue;
        };
        assert!(name(&s).ends_with("; EGL pbuffer)"), "{}", name(&s));
        check_pass_fail(&mut s, spec, path);
        // Without the switch Mesa's surfaceless, config-less context is used.
        let Some(plain) = Session::start(backend) else {
            continue;
        };
        assert!(!name(&plain).contains("pbuffer"), "{}", name(&plain));
    }
}

#[test]
fn a_library_directory_in_the_name_loads_that_libegl() {
    let dir = ["/usr/lib/x86_64-linux-gnu", "/usr/lib64", "/usr/lib"]
        .into_iter()
        .find(|d| std::path::Path::new(d).join("libEGL.so.1").is_file());
    let Some(dir) = dir else {
        unavailable(
            "egl@<dir>:llvmpipe:es3",
            "no libEGL.so.1 in the usual directories",
        );
        return;
    };
    let backend = format!("egl@{dir}:llvmpipe:es3");
    let wc = shadowcheck_runner::backend::gl::worker_command(&backend).unwrap();
    assert_eq!(wc.args, ["gl-worker", "--backend", "egl:llvmpipe:es3"]);
    assert!(wc
        .env
        .contains(&("SHADOWCHECK_LIBEGL".into(), format!("{dir}/libEGL.so.1"))));
    if let Some(mut s) = Session::start(&backend) {
        check_pass_fail(&mut s, Spec::Gles32, ApiPath::Es300);
    }
    let e = shadowcheck_runner::backend::gl::worker_command("egl@/no/such/dir:native:es3")
        .unwrap_err()
        .to_string();
    assert!(e.contains("/no/such/dir/libEGL.so"), "{e}");
}

#[test]
fn swiftshader_gles_3_0_runs_on_a_pbuffer_and_skips_es_3_1_and_3_2_state() {
    let Some(mut s) = Session::start("egl:swiftshader:es3") else {
        return;
    };
    let n = name(&s);
    assert!(n.contains("OpenGL ES 3.0 SwiftShader"), "{n}");
    assert!(n.ends_with("; EGL pbuffer)"), "{n}");
    assert!(!s.caps("targets").contains(&"cubearray".to_string()));
    let features = s.caps("features");
    assert!(!features
        .iter()
        .any(|f| f == "border_clamp" || f == "stencil_texturing"));
    check_pass_fail(&mut s, Spec::Gles32, ApiPath::Es300);
    // A case the runner would never send (Skip by Capabilities::support) is refused by the worker
    // with the same reason, not drawn into a GL error.
    let mut border = d16_case(
        "border",
        Spec::Gles32,
        &[ApiPath::Es300],
        Target::T2d,
        32768,
        0.1,
    );
    border.sampler.wrap_s = Wrap::ClampToBorder;
    let a = s.run(&[border]);
    assert_eq!(a[0]["type"], "skip", "{}", a[0]);
    assert!(
        a[0]["reason"]
            .as_str()
            .unwrap_or("")
            .contains("border_clamp"),
        "{}",
        a[0]
    );
}
