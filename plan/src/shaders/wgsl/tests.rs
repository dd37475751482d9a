//! Unit tests of the WGSL emitter: the built-in each form calls, its arguments per target, the
//! const offset, the quad's varying P, and what WGSL cannot express.
use super::*;
use crate::paths;
use crate::test_case::case;
use crate::SamplerKind;
use shadowcheck_model::{ApiPath, Filter, Gather};

fn key(target: Target, form: LodForm) -> ShaderKey {
    ShaderKey {
        path: ApiPath::Wgsl,
        target,
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

fn module_of(k: &ShaderKey) -> String {
    module(k, crate::layout::FB_SIZE).unwrap_or_else(|e| panic!("{k:?}: {e}"))
}

#[test]
fn each_form_calls_its_builtin_with_the_targets_arguments() {
    let m = module_of(&key(Target::T2d, LodForm::Lod));
    assert!(m.contains("var t: texture_depth_2d;"), "{m}");
    assert!(m.contains("var s: sampler_comparison;"), "{m}");
    assert!(
        m.contains("return vec4f(textureSampleCompareLevel(t, s, p.xy, p.z), 0.0, 0.0, 1.0);"),
        "{m}"
    );
    // The level form does not vary P: no derivatives are taken.
    assert!(!m.contains("v.dx"), "{m}");
    let m = module_of(&key(Target::T2dArray, LodForm::Implicit(false)));
    assert!(m.contains("texture_depth_2d_array"), "{m}");
    assert!(
        m.contains("textureSampleCompare(t, s, p.xy, i32(v.p.z), p.w)"),
        "{m}"
    );
    let m = module_of(&key(Target::Cube, LodForm::Implicit(false)));
    assert!(m.contains("textureSampleCompare(t, s, p.xyz, p.w)"), "{m}");
    let m = module_of(&key(Target::CubeArray, LodForm::Lod));
    assert!(m.contains("texture_depth_cube_array"), "{m}");
    assert!(
        m.contains("textureSampleCompareLevel(t, s, p.xyz, i32(v.p.w), v.x)"),
        "{m}"
    );
}

#[test]
fn implicit_derivatives_vary_p_across_the_quad_and_keep_it_at_the_written_pixel() {
    let m = module_of(&key(Target::T2d, LodForm::Implicit(false)));
    assert!(
        m.contains("let c = vec2f((vec2u(v.pos.xy) / 2u) * 2u) + 0.5;\n  p = p + (v.pos.x - c.x) * v.dx + (v.pos.y - c.y) * v.dy;"),
        "{m}"
    );
    // No branch anywhere: the implicit-derivative call is in uniform control flow.
    assert!(!m.contains("if ") && !m.contains("discard"), "{m}");
    // Every value reaches the fragment shader flat, with the sampling compatibility mode accepts.
    assert_eq!(m.matches("@interpolate(flat, either)").count(), 4, "{m}");
    // Slot s's quad: column 2*(s % 128), row 2*(s / 128), NDC y pointing up.
    assert!(m.contains("f32(slot % 128u), f32(slot / 128u)"), "{m}");
    assert!(m.contains("1.0 - corner.y / 128.0"), "{m}");
}

#[test]
fn offsets_are_const_vec2i_arguments_and_gathers_return_all_four() {
    let mut k = key(Target::T2dArray, LodForm::Lod);
    k.offset = [7, -8];
    let m = module_of(&k);
    assert!(
        m.contains("textureSampleCompareLevel(t, s, p.xy, i32(v.p.z), p.w, vec2i(7, -8))"),
        "{m}"
    );
    let mut g = key(Target::T2d, LodForm::Gather(false));
    g.gather = Some(GatherCall::Single);
    g.offset = [-1, -1];
    let m = module_of(&g);
    assert!(
        m.contains("return textureGatherCompare(t, s, p.xy, p.z, vec2i(-1, -1));"),
        "{m}"
    );
    g.target = Target::CubeArray;
    g.offset = [0, 0];
    let m = module_of(&g);
    assert!(
        m.contains("return textureGatherCompare(t, s, p.xyz, i32(v.p.w), v.x);"),
        "{m}"
    );
}

#[test]
fn what_wgsl_cannot_express_is_an_error_not_a_module() {
    let bad = |k: ShaderKey| module(&k, 256).is_err();
    assert!(bad(key(Target::Rect, LodForm::Lod)));
    assert!(bad(key(Target::T1dArray, LodForm::Lod)));
    assert!(bad(key(Target::T2d, LodForm::Grad)));
    assert!(bad(key(Target::T2d, LodForm::Implicit(true))));
    let mut k = key(Target::T2d, LodForm::Lod);
    k.proj = true;
    assert!(bad(k));
    let mut k = key(Target::T2d, LodForm::Lod);
    k.kind = SamplerKind::Float;
    assert!(bad(k));
    let mut k = key(Target::Cube, LodForm::Lod);
    k.offset = [1, 0];
    assert!(bad(k));
    let mut k = key(Target::T2d, LodForm::Gather(false));
    k.gather = Some(GatherCall::Offsets([[0, 0]; 4]));
    assert!(bad(k));
}

fn wgsl_case(target: Target, layers: u32) -> shadowcheck_model::Case {
    let mut c = case(target, 4, 4, layers);
    c.api = vec![ApiPath::Wgsl];
    c
}

#[test]
fn the_level_form_is_chosen_only_where_it_is_the_cases_level() {
    let c = wgsl_case(Target::T2d, 1);
    let p = paths::plan(ApiPath::Wgsl, &c).expect("plan");
    assert_eq!(p.key.form, LodForm::Lod);
    // A level of detail other than 0: implicit derivatives with the case's gradients.
    let mut l = c.clone();
    l.lookup.lod = 0.5;
    let p = paths::plan(ApiPath::Wgsl, &l).expect("plan");
    assert_eq!(p.key.form, LodForm::Implicit(false));
    assert!(p.dx[0] > 0.0 && p.dy[1] > 0.0);
    // lod 0 but min_lod 1: λ clamps to 1, which level 0 is not.
    let mut m = c.clone();
    m.sampler.min_lod = 1.0;
    m.sampler.min_filter = Filter::NearestMipmapNearest;
    let p = paths::plan(ApiPath::Wgsl, &m).expect("plan");
    assert_eq!(p.key.form, LodForm::Implicit(false));
    // A bias has no WGSL form at all.
    let mut b = c.clone();
    b.lookup.bias = 1.0;
    let why = paths::plan(ApiPath::Wgsl, &b).unwrap_err();
    assert!(why.contains("bias"), "{why}");
    // Cube maps: textureSampleCompareLevel exists for them in WGSL.
    let p = paths::plan(ApiPath::Wgsl, &wgsl_case(Target::Cube, 6)).expect("cube");
    assert_eq!(p.key.form, LodForm::Lod);
    let p = paths::plan(ApiPath::Wgsl, &wgsl_case(Target::CubeArray, 12)).expect("cube array");
    assert_eq!(p.key.form, LodForm::Lod);
}

#[test]
fn layers_must_be_integers_and_offsets_in_wgsls_range() {
    let mut c = wgsl_case(Target::T2dArray, 3);
    c.lookup.coord[2] = 1.0;
    c.lookup.offset = [-8, 7, 0];
    let p = paths::plan(ApiPath::Wgsl, &c).expect("plan");
    assert_eq!((p.key.offset, p.p[2]), ([-8, 7], 1.0));
    c.lookup.coord[2] = 0.5;
    let why = paths::plan(ApiPath::Wgsl, &c).unwrap_err();
    assert!(why.contains("array_index is an integer"), "{why}");
    c.lookup.coord[2] = 1.0;
    c.lookup.offset = [8, 0, 0];
    let why = paths::plan(ApiPath::Wgsl, &c).unwrap_err();
    assert!(why.contains("[-8, 7]"), "{why}");
    let mut a = wgsl_case(Target::CubeArray, 12);
    a.lookup.layer = 1.5;
    assert!(paths::plan(ApiPath::Wgsl, &a).is_err());
    // Gathers: one offset, never four.
    let mut g = wgsl_case(Target::T2d, 1);
    g.lookup.gather = Some(Gather { offsets: None });
    g.lookup.offset = [2, -1, 0];
    let p = paths::plan(ApiPath::Wgsl, &g).expect("gather");
    assert_eq!(
        (p.key.gather, p.key.offset),
        (Some(GatherCall::Single), [2, -1])
    );
    g.lookup.gather = Some(Gather {
        offsets: Some([[0, 0]; 4]),
    });
    assert!(paths::plan(ApiPath::Wgsl, &g).is_err());
}

#[test]
fn instance_values_and_texel_points_are_laid_out_as_declared() {
    let c = wgsl_case(Target::CubeArray, 12);
    let p = paths::plan(ApiPath::Wgsl, &c).expect("plan");
    let v = instance_values(&p);
    for (i, (_, format, at)) in INSTANCE_ATTRIBS.iter().enumerate() {
        let n = if *format == "float32x4" { 4 } else { 1 };
        let want: Vec<f32> = match i {
            0 => p.p.to_vec(),
            1 => p.dx.to_vec(),
            2 => p.dy.to_vec(),
            _ => vec![p.x],
        };
        assert_eq!(v[*at..at + n].to_vec(), want);
    }
    assert_eq!(texel_point(0, 0, 2, 2), [-0.5, 0.5]);
    assert_eq!(texel_point(1, 1, 2, 2), [0.5, -0.5]);
    assert_eq!(texel_point(0, 0, 1, 1), [0.0, 0.0]);
}

#[test]
fn a_compute_key_is_one_workgroup_per_lookup_reading_its_values_and_writing_its_slot() {
    let mut k = key(Target::Cube, LodForm::Lod);
    k.stage = shadowcheck_model::Stage::Compute;
    let m = module_of(&k);
    // Only the compute entry point: no vertex or fragment stage, no derivatives.
    assert!(
        m.contains("@compute @workgroup_size(1)\nfn cs(@builtin(workgroup_id) id: vec3u) {"),
        "{m}"
    );
    assert!(
        !m.contains("@vertex") && !m.contains("@fragment") && !m.contains("dx"),
        "{m}"
    );
    // The same call as the fragment module's, on the values read from the instance floats.
    let frag = module_of(&key(Target::Cube, LodForm::Lod));
    assert!(
        frag.contains("textureSampleCompareLevel(t, s, p.xyz, p.w)"),
        "{frag}"
    );
    assert!(
        m.contains(
            "results[slot] = vec4f(textureSampleCompareLevel(t, s, p.xyz, p.w), 0.0, 0.0, 1.0);"
        ),
        "{m}"
    );
    assert!(
        m.contains("let slot = first.x + id.x;\n  let i = 13u * slot;"),
        "{m}"
    );
    assert!(
        m.contains("let v = Lookup(vec4f(lookups[i], lookups[i + 1u], lookups[i + 2u], lookups[i + 3u]), lookups[i + 12u]);"),
        "{m}"
    );
    for (name, binding, _) in COMPUTE_BINDINGS {
        assert!(
            m.contains(&format!("@group(0) @binding({binding}) var")),
            "{m}"
        );
        assert!(m.contains(&format!("> {name}: ")), "{name}: {m}");
    }
    assert!(m.contains("var<storage, read> lookups: array<f32>;"), "{m}");
    assert!(
        m.contains("var<storage, read_write> results: array<vec4f>;"),
        "{m}"
    );
    // The layout the shader reads is the one instance_values writes: P at 0, x at 12.
    assert_eq!((INSTANCE_ATTRIBS[0].2, INSTANCE_ATTRIBS[3].2), (0, 12));
    assert_eq!(INSTANCE_FLOATS, 13);
    // A cube-array gather: all four comparisons, the layer and the reference from the values.
    let mut g = key(Target::CubeArray, LodForm::Gather(false));
    g.gather = Some(GatherCall::Single);
    g.stage = shadowcheck_model::Stage::Compute;
    let m = module_of(&g);
    assert!(
        m.contains("results[slot] = textureGatherCompare(t, s, p.xyz, i32(v.p.w), v.x);"),
        "{m}"
    );
    assert!(m.contains("var t: texture_depth_cube_array;"), "{m}");
    // Forms that need derivatives, and the vertex stage, are no compute module.
    let mut i = key(Target::Cube, LodForm::Implicit(false));
    i.stage = shadowcheck_model::Stage::Compute;
    assert!(module(&i, 256).unwrap_err().contains("derivatives"));
    let mut gi = g;
    gi.form = LodForm::Gather(true);
    assert!(module(&gi, 256).is_err());
    let mut v = key(Target::Cube, LodForm::Lod);
    v.stage = shadowcheck_model::Stage::Vertex;
    assert!(module(&v, 256).is_err());
}

#[test]
fn the_plan_of_a_compute_case_gives_a_compute_module_with_the_cases_values() {
    let mut c = wgsl_case(Target::Cube, 6);
    c.lookup.stage = shadowcheck_model::Stage::Compute;
    let p = paths::plan(ApiPath::Wgsl, &c).expect("plan");
    assert_eq!(
        (p.key.stage, p.key.form),
        (shadowcheck_model::Stage::Compute, LodForm::Lod)
    );
    let m = module_of(&p.key);
    assert!(m.contains("fn cs("), "{m}");
    // The instance floats are the plan's P and x, unchanged, for the shader to read bit for bit.
    let v = instance_values(&p);
    assert_eq!(v[0..4], p.p);
    assert_eq!(v[12].to_bits(), p.x.to_bits());
}
