//! Tests of the shader and ARB program text.

use super::*;

/// A context of `api` with `version` and GLSL `glsl` (x100), no extensions.
fn info(api: crate::ContextApi, version: (u32, u32), glsl: u32) -> GlInfo {
    GlInfo {
        api,
        es: api == crate::ContextApi::Es3,
        compat: api == crate::ContextApi::Compat,
        version,
        glsl,
        renderer: String::new(),
        version_string: String::new(),
        extensions: Default::default(),
        version_override: false,
        form: Default::default(),
    }
}

/// A plain 2D shadow lookup on `path` with `form` (no projection, offset, depth mode or gather).
fn shadow_2d(path: ApiPath, form: LodForm) -> ShaderKey {
    ShaderKey {
        path,
        target: Target::T2d,
        kind: SamplerKind::Shadow,
        form,
        proj: false,
        mode: None,
        offset: [0, 0],
        gather: None,
        delivery: shadowcheck_model::Delivery::Literal,
        stage: shadowcheck_model::Stage::Fragment,
    }
}

#[test]
fn core_lookup_calls_put_dref_in_p_and_compare_separately_for_cube_arrays() {
    let k = shadow_2d(ApiPath::GlslCore, LodForm::Lod);
    assert_eq!(modern_call(&k, "u_tex"), "textureLod(u_tex, p.xyz, u_x)");
    let k = ShaderKey {
        target: Target::CubeArray,
        form: LodForm::Implicit(false),
        ..k
    };
    assert_eq!(modern_call(&k, "u_tex"), "texture(u_tex, p, u_x)");
    let k = ShaderKey {
        target: Target::Rect,
        form: LodForm::Grad,
        proj: true,
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureProjGrad(u_tex, p, u_dx.xy, u_dy.xy)"
    );
    // *Offset forms: the offset after P / LOD / gradients, before the bias.
    let k = ShaderKey {
        target: Target::T2d,
        offset: [-8, 7],
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureProjGradOffset(u_tex, p, u_dx.xy, u_dy.xy, ivec2(-8, 7))"
    );
    let k = ShaderKey {
        form: LodForm::Lod,
        proj: false,
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureLodOffset(u_tex, p.xyz, u_x, ivec2(-8, 7))"
    );
    let k = ShaderKey {
        form: LodForm::Implicit(true),
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureOffset(u_tex, p.xyz, ivec2(-8, 7), u_x)"
    );
}

#[test]
fn shadow_lod_overloads_enable_the_extension() {
    let k = ShaderKey {
        path: ApiPath::Es300,
        target: Target::CubeArray,
        kind: SamplerKind::Shadow,
        form: LodForm::Lod,
        proj: false,
        mode: None,
        offset: [0, 0],
        gather: None,
        delivery: shadowcheck_model::Delivery::Literal,
        stage: shadowcheck_model::Stage::Fragment,
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureLod(u_tex, p, u_x, u_dx.x)"
    );
    let info = info(crate::ContextApi::Es3, (3, 2), 320);
    let (_, fs) = glsl(&info, &k, None, 1);
    assert!(
        fs.starts_with("#version 320 es\n#extension GL_EXT_texture_shadow_lod : require\n"),
        "{fs}"
    );
    let k = ShaderKey {
        target: Target::T2d,
        ..k
    };
    assert!(!glsl(&info, &k, None, 1).1.contains("#extension"));
}

#[test]
fn gather_calls_split_p_and_ref_z() {
    let k = ShaderKey {
        path: ApiPath::GlslCore,
        target: Target::T2d,
        kind: SamplerKind::Shadow,
        form: LodForm::Gather(false),
        proj: false,
        mode: None,
        offset: [0, 0],
        gather: Some(GatherCall::Single),
        delivery: shadowcheck_model::Delivery::Literal,
        stage: shadowcheck_model::Stage::Fragment,
    };
    assert_eq!(modern_call(&k, "u_tex"), "textureGather(u_tex, p.xy, p.z)");
    let k = ShaderKey {
        offset: [-8, 7],
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureGatherOffset(u_tex, p.xy, p.z, ivec2(-8, 7))"
    );
    let k = ShaderKey {
        target: Target::T2dArray,
        offset: [0, 0],
        gather: Some(GatherCall::Offsets([[0, 1], [1, 1], [1, 0], [0, 0]])),
        ..k
    };
    assert_eq!(
        modern_call(&k, "u_tex"),
        "textureGatherOffsets(u_tex, p.xyz, p.w, ivec2[4](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0)))"
    );
    let k = ShaderKey {
        target: Target::CubeArray,
        gather: Some(GatherCall::Single),
        ..k
    };
    assert_eq!(modern_call(&k, "u_tex"), "textureGather(u_tex, p, u_x)");
}

#[test]
fn batched_programs_draw_each_case_as_its_own_quad_and_vary_p_across_it_when_implicit() {
    let info = info(crate::ContextApi::Core, (4, 5), 450);
    let k = shadow_2d(ApiPath::GlslCore, LodForm::Implicit(false));
    assert!(batchable(&k));
    let (vs, fs) = glsl(&info, &k, Some(256), 1);
    // Case k draws the quad of slot u_base + k: 128 quads a row, NDC = pixel / 128 - 1.
    assert!(
        vs.contains("int s = u_base + int(a_x.y);\n  ivec2 corner = 2 * ivec2(s % 128, s / 128) + 2 * ivec2(a_pos);\n  gl_Position = vec4(vec2(corner) / 128.0 - 1.0, 0.0, 1.0);"),
        "{vs}"
    );
    // Every attribute is declared with its size (a one-unit program reads (x, k) of `a_x`).
    for (_, name, size, _) in PARAM_ATTRIBS {
        let size = if name == "a_x" { 2 } else { size };
        let ty = format!("vec{size}");
        assert!(vs.contains(&format!("in {ty} {name};")), "{vs}");
    }
    assert!(
        fs.contains("flat in vec4 v_p;") && fs.contains("vec4 p = v_p;"),
        "{fs}"
    );
    assert!(fs.contains("ivec2 q = ivec2(gl_FragCoord.xy) / 2;\n  vec2 c = vec2(q * 2) + 0.5;\n  p = p + (gl_FragCoord.x - c.x) * u_dx + (gl_FragCoord.y - c.y) * u_dy;"), "{fs}");
    assert!(fs.contains("if (u_base < 0) discard;"), "{fs}");
    // An explicit LOD reads P as stored: no variation across the quad.
    let lod = ShaderKey {
        form: LodForm::Lod,
        ..k
    };
    assert!(batchable(&lod));
    assert!(!glsl(&info, &lod, Some(256), 1).1.contains("vec2 c ="));
    // The compatibility paths and ES 1.00 draw one pixel per case.
    assert!(!batchable(&ShaderKey {
        path: ApiPath::Glsl120,
        ..k
    }));
    assert!(!batchable(&ShaderKey {
        path: ApiPath::Glsl130,
        ..k
    }));
    assert!(!batchable(&ShaderKey {
        path: ApiPath::Es100Ext,
        ..k
    }));
}

#[test]
fn single_case_programs_can_discard_but_only_where_the_pixel_centre_is_negative() {
    let k = shadow_2d(ApiPath::Glsl120, LodForm::Implicit(false));
    let compat = info(crate::ContextApi::Compat, (4, 5), 450);
    for key in [
        k,
        ShaderKey {
            form: LodForm::Lod,
            path: ApiPath::Glsl130,
            ..k
        },
    ] {
        let (_, fs) = glsl(&compat, &key, None, 1);
        // Before P is formed, on a uniform (control flow stays uniform).
        let at = fs.find("if (u_c.x < 0.0) discard;").expect(&fs);
        assert!(at < fs.find("vec4 p =").expect(&fs), "{fs}");
        assert!(fs.contains("uniform vec2 u_c;"), "{fs}");
    }
    let arb = arbfp(
        &ShaderKey {
            path: ApiPath::ArbFp,
            ..k
        },
        1,
    );
    assert!(
        arb.contains("PARAM c = program.local[3];") && arb.contains("KIL c;"),
        "{arb}"
    );
}

#[test]
fn legacy_calls_use_the_glsl_120_names() {
    let k = ShaderKey {
        path: ApiPath::Glsl120,
        target: Target::Rect,
        kind: SamplerKind::Shadow,
        form: LodForm::Implicit(false),
        proj: true,
        mode: None,
        offset: [0, 0],
        gather: None,
        delivery: shadowcheck_model::Delivery::Literal,
        stage: shadowcheck_model::Stage::Fragment,
    };
    assert_eq!(legacy_call(&k, "u_tex"), "shadow2DRectProj(u_tex, p)");
    let k = ShaderKey {
        path: ApiPath::Es100Ext,
        target: Target::T2d,
        ..k
    };
    assert_eq!(legacy_call(&k, "u_tex"), "shadow2DProjEXT(u_tex, p)");
}

#[test]
fn arb_program_uses_the_shadow_target_and_txb_for_bias() {
    let k = shadow_2d(ApiPath::ArbFp, LodForm::Implicit(true));
    let s = arbfp(&k, 1);
    assert!(
        s.contains("OPTION ARB_fragment_program_shadow;")
            && s.contains("TXB result.color, q, texture[0], SHADOW2D;"),
        "{s}"
    );
}

#[test]
fn several_units_are_sampled_by_one_program_and_the_case_picks_its_own() {
    let info = info(crate::ContextApi::Core, (4, 5), 450);
    let k = shadow_2d(ApiPath::GlslCore, LodForm::Lod);
    // One unit: the program of one state, no selection.
    let (vs1, fs1) = glsl(&info, &k, Some(256), 1);
    assert!(fs1.contains("uniform sampler2DShadow u_tex;") && !fs1.contains("v_unit"));
    assert!(vs1.contains("in vec2 a_x;") && !vs1.contains("v_unit"));
    // Three units, batched: the unit arrives flat from the third component of a_x, and each
    // branch samples its own unit's sampler.
    let (vs, fs) = glsl(&info, &k, Some(256), 3);
    assert!(
        vs.contains("in vec3 a_x;") && vs.contains("v_unit = int(a_x.z);"),
        "{vs}"
    );
    for u in 0..3 {
        assert!(
            fs.contains(&format!("uniform sampler2DShadow u_tex{u};")),
            "{fs}"
        );
        assert!(
            fs.contains(&format!("textureLod(u_tex{u}, p.xyz, u_x)")),
            "{fs}"
        );
    }
    assert!(
        fs.contains("if (v_unit == 0)")
            && fs.contains("else if (v_unit == 1)")
            && fs.contains("else o ="),
        "{fs}"
    );
    assert!(!fs.contains("u_tex;"), "{fs}");
    // Single-case programs take the unit as an attribute's current value, passed on flat.
    let (vs, fs) = glsl(&info, &k, None, 2);
    assert!(
        vs.contains("in float a_unit;") && vs.contains("v_unit = a_unit;"),
        "{vs}"
    );
    assert!(
        fs.contains("flat in float v_unit;")
            && fs.contains("int unit = int(v_unit + 0.5);")
            && fs.contains("if (unit == 0)"),
        "{fs}"
    );
    // ARB programs sample every unit and weight the results; the case's unit weighs 1.
    let k = shadow_2d(ApiPath::ArbFp, LodForm::Implicit(false));
    let s = arbfp(&k, 6);
    for u in 0..6 {
        assert!(
            s.contains(&format!("TEX t, q, texture[{u}], SHADOW2D;")),
            "{s}"
        );
    }
    assert!(
        s.contains("PARAM w0 = program.local[4];") && s.contains("PARAM w1 = program.local[5];"),
        "{s}"
    );
    assert!(
        s.contains("MUL r, t, w0.x;")
            && s.contains("MAD r, t, w1.y, r;")
            && s.contains("MOV result.color, r;"),
        "{s}"
    );
    assert_eq!(
        arbfp_unit_weights(5, 6),
        vec![[0.0; 4], [0.0, 1.0, 0.0, 0.0]]
    );
    assert_eq!(arbfp_unit_weights(0, 3), vec![[1.0, 0.0, 0.0, 0.0]]);
}

#[test]
fn vulkan_programs_give_every_interface_variable_a_location_and_use_a_push_constant() {
    let key = shadow_2d(ApiPath::Vulkan, LodForm::Implicit(false));
    assert!(batchable(&key));
    let (vs, fs) = glsl(
        &info(crate::ContextApi::Core, (4, 6), 460),
        &key,
        Some(crate::layout::FB_SIZE),
        1,
    );
    for src in [&vs, &fs] {
        assert!(src.starts_with("#version 450\n"), "{src}");
        assert!(src.contains("layout(push_constant) uniform PC { int u_base; };"));
        assert!(!src.contains("uniform int u_base"), "{src}");
        // Every stage input and output (but the built-ins) has a location.
        for line in src.lines() {
            let io = line.contains(" in ") || line.contains(" out ");
            if io && !line.contains("gl_") {
                assert!(line.starts_with("layout(location = "), "{line}");
            }
        }
    }
    // The vertex inputs sit at PARAM_ATTRIBS' locations.
    for (loc, name, _, _) in PARAM_ATTRIBS {
        assert!(
            vs.contains(&format!("layout(location = {loc}) in ")) && vs.contains(name),
            "{name}: {vs}"
        );
    }
    assert!(fs.contains("layout(set = 0, binding = 0) uniform sampler2DShadow u_tex;"));
    assert!(fs.contains("layout(location = 0) out vec4 o;"));
    assert!(fs.contains("o = vec4(texture(u_tex, p.xyz), 0.0, 0.0, 1.0);"));
    // Implicit derivatives: P varies across the case's 2x2 quad, as on the core path.
    assert!(fs.contains("p = p + (gl_FragCoord.x - c.x) * u_dx + (gl_FragCoord.y - c.y) * u_dy;"));
    let (_, lod) = glsl(
        &info(crate::ContextApi::Core, (4, 6), 460),
        &shadow_2d(ApiPath::Vulkan, LodForm::Lod),
        Some(crate::layout::FB_SIZE),
        1,
    );
    assert!(lod.contains("textureLod(u_tex, p.xyz, u_x)") && !lod.contains("gl_FragCoord"));
}

#[test]
fn vulkan_gathers_and_offsets_are_the_glsl_450_calls() {
    let key = ShaderKey {
        target: Target::T2dArray,
        form: LodForm::Gather(false),
        gather: Some(GatherCall::Offsets([[0, 0], [1, 0], [0, 1], [-1, -1]])),
        ..shadow_2d(ApiPath::Vulkan, LodForm::Lod)
    };
    let (_, fs) = vulkan::glsl(&key, crate::layout::FB_SIZE);
    assert!(fs.contains("uniform sampler2DArrayShadow u_tex;"));
    assert!(fs.contains("o = vec4(textureGatherOffsets(u_tex, p.xyz, p.w, ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(-1, -1))));"), "{fs}");
    let key = ShaderKey {
        offset: [-8, 7],
        ..shadow_2d(ApiPath::Vulkan, LodForm::Grad)
    };
    let (_, fs) = vulkan::glsl(&key, crate::layout::FB_SIZE);
    assert!(fs.contains("textureGradOffset(u_tex, p.xyz, u_dx.xy, u_dy.xy, ivec2(-8, 7))"));
}
