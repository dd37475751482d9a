//! Unit tests of the C program text (no GL, no compiler).

use super::*;
use crate::repro::cexpect::cd;
use shadowcheck_model::*;

/// GL 4.6 core, 2x2 D16 (stored 0, 21845, 43690, 65535), NEAREST at the centre of texel (1,0)
/// (Dt = 1/3), LEQUAL, Dref 0.5: Table 8.23 gives r = 0 (0.5 <= 1/3 is false).
fn subject() -> Subject {
    let case = Case {
        sweep: vec![],
        id: "gl46/2d/d16/nearest/lequal/unit".into(),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: 2,
                height: 2,
                layers: 1,
                depth: Texels::Unorm(vec![0, 21845, 43690, 65535]),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Nearest),
        lookup: Lookup {
            coord: [0.75, 0.25, 0.0, 1.0],
            layer: 0.0,
            dref: 0.5,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: None,
    };
    let ev = shadowcheck_oracle::evaluate(&case).unwrap();
    Subject {
        backend: "egl:llvmpipe:core".parse().unwrap(),
        case,
        api: ApiPath::GlslCore,
        expect: ev.expect,
        steps: ev.steps,
        explain: String::new(),
        fixture: "unit.json".into(),
        lib_dir: None,
    }
}

fn gl(s: &Subject) -> BackendName {
    match s.backend {
        super::super::Backend::Gl(b) => b,
        super::super::Backend::Vk(_)
        | super::super::Backend::Webgpu(_)
        | super::super::Backend::Webgl(_) => {
            panic!("a GL subject")
        }
    }
}

#[test]
fn program_carries_the_stored_integers_the_state_the_lookup_and_the_oracle_set() {
    let s = subject();
    let c = program(&s, gl(&s)).unwrap();
    for want in [
        "static const GLushort LEVEL0[] = {\n    0, 21845, 43690, 65535\n};",
        "glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, LEVEL0);",
        "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);",
        "glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);",
        "textureLod(u_tex, p.xyz, u_x)",
        "glUniform4f(glGetUniformLocation(p, \"u_p\"), 0.75f, 0.25f, 0.5f, 1.0f);",
        "static const double ACCEPTED[][2] = {{0.0, 0.0}};",
        "static const char LAYOUT[4] = {'r', '-', '-', '-'};",
        "EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT",
        "#version 400 core",
        "#version 330 core",
    ] {
        assert!(c.contains(want), "missing `{want}` in\n{c}");
    }
    // Desktop-only tokens not used: no #ifndef block.
    assert!(!c.contains("#ifndef"), "{c}");
}

#[test]
fn float_literals_read_back_exactly() {
    for v in [0.1f32, 1.0 / 3.0, 1e-7, -0.0, 16777215.0, f32::MIN_POSITIVE] {
        let lit = cf(v);
        let back: f32 = lit.trim_end_matches('f').parse().unwrap();
        assert_eq!(back.to_bits(), v.to_bits(), "{lit}");
    }
    assert_eq!(cf(f32::INFINITY), "INFINITY");
    assert_eq!(cd(0.4000000059604645), "0.4000000059604645");
}

#[test]
fn every_reading_of_the_layout_goes_into_the_program() {
    let mut s = subject();
    let c = program(&s, gl(&s)).unwrap();
    assert!(
        c.contains("static const char LAYOUTS[][4] = {{'r', '-', '-', '-'}};"),
        "{c}"
    );
    assert!(c.contains("static const int N_LAYOUTS = 1;"), "{c}");
    // A second reading (as a compatibility GLSL 1.30 depth read has, `compat-depth-cb`): the
    // program accepts a result either reading accepts and names both.
    s.expect.other_layouts.insert(
        ApiPath::GlslCore,
        vec![OtherLayout {
            reading: "compat-depth-cb".into(),
            layout: [Channel::R, Channel::Zero, Channel::Zero, Channel::One],
        }],
    );
    let c = program(&s, gl(&s)).unwrap();
    for want in [
        "static const char LAYOUTS[][4] = {{'r', '-', '-', '-'}, {'r', '0', '0', '1'}};",
        "static const char *READINGS[] = {\"the spec value's\", \"compat-depth-cb\"};",
        "static const int N_LAYOUTS = 2;",
        "ok |= a;",
    ] {
        assert!(c.contains(want), "missing `{want}` in\n{c}");
    }
}

/// A compute-stage lookup: the program compiles the worker's compute shader (the very text of
/// `shaders::compute_glsl`) instead of a draw program, stores into the immutable colour texture
/// bound as image unit 0, and makes the store visible before the read-back.
#[test]
fn a_compute_stage_lookup_dispatches_the_workers_compute_shader() {
    for (backend, api, versions) in [
        ("egl:llvmpipe:core", ApiPath::GlslCore, &["{430,"][..]),
        ("egl:llvmpipe:es3", ApiPath::Es300, &["{320,", "{310,"][..]),
    ] {
        let mut s = subject();
        s.backend = backend.parse().unwrap();
        s.api = api;
        s.case.api = vec![api];
        s.case.lookup.stage = Stage::Compute;
        let c = program(&s, gl(&s)).unwrap();
        let plan = paths::plan_in(api, &s.case, &s.case.lookup, gl(&s).form, true).unwrap();
        for glsl in [310, 320, 430] {
            let cs = shaders::compute_glsl(&gl_info(gl(&s), glsl), &plan.key, 1).unwrap();
            assert!(
                c.contains(&cstr(&cs, "     ")),
                "{backend}: {cs} not in\n{c}"
            );
        }
        for want in versions.iter().copied().chain([
            "#define COMPUTE_STAGE 1",
            "glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, 16, 16);",
            "shader(GL_COMPUTE_SHADER, PROGRAMS[v].cs)",
            "glUniform2i(glGetUniformLocation(p, \"u_at\"), 0, 0);",
            "glBindImageTexture(0, (GLuint)color, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);",
            "glDispatchCompute(1, 1, 1);",
            "glMemoryBarrier(GL_ALL_BARRIER_BITS);",
            "imageStore(u_out, u_at, r);",
        ]) {
            assert!(c.contains(want), "{backend}: missing `{want}` in\n{c}");
        }
        assert!(
            !c.contains("#error") && !c.contains("GL_VERTEX_SHADER"),
            "{c}"
        );
    }
    // A fragment-stage lookup keeps the mutable colour texture and the draw.
    let c = program(&subject(), gl(&subject())).unwrap();
    assert!(
        !c.contains("#define COMPUTE_STAGE") && c.contains("glDrawArrays"),
        "{c}"
    );
}
