//! Unit tests of the per-path plans: lookup forms, P layout, gradients, fixed-function coordinates.
use super::*;
use crate::test_case::case;

#[test]
fn glsl_function_availability_follows_the_language_tables() {
    use LodForm::*;
    // GLSL 4.60 §8.9.2: textureLod exists for 1D/2D/1DArray shadow only; no textureGrad on cube array shadow.
    assert!(available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::T2d,
        Lod,
        true
    ));
    assert!(!available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::Cube,
        Lod,
        false
    ));
    assert!(available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::Cube,
        Grad,
        false
    ));
    assert!(!available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::CubeArray,
        Grad,
        false
    ));
    assert!(!available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::T2dArray,
        Implicit(true),
        false
    ));
    // GLSL ES 3.00 has no 1D or rectangle samplers.
    assert!(!available(
        ApiPath::Es300,
        SamplerKind::Shadow,
        Target::T1d,
        Implicit(false),
        false
    ));
    // Projective forms exist for 1D, 2D and rect only.
    assert!(!available(
        ApiPath::GlslCore,
        SamplerKind::Shadow,
        Target::Cube,
        Grad,
        true
    ));
    // Fixed-function shadow: 1D, 2D, rect.
    assert!(available(
        ApiPath::FixedFunction,
        SamplerKind::Shadow,
        Target::Rect,
        Constant,
        false
    ));
    assert!(!available(
        ApiPath::FixedFunction,
        SamplerKind::Shadow,
        Target::Cube,
        Constant,
        false
    ));
}

#[test]
fn plan_prefers_explicit_lod_and_puts_dref_where_the_language_wants_it() {
    let c = case(Target::T2d, 4, 4, 1);
    let p = plan(ApiPath::GlslCore, &c).unwrap();
    assert_eq!(p.key.form, LodForm::Lod);
    assert_eq!(p.p, [0.5, 0.5, 0.5, 1.0]);
    let mut ca = case(Target::CubeArray, 4, 4, 12);
    ca.lookup.layer = 1.0;
    ca.lookup.dref = 0.25;
    let p = plan(ApiPath::GlslCore, &ca).unwrap();
    assert_eq!(p.key.form, LodForm::Implicit(false));
    assert_eq!((p.p[3], p.x), (1.0, 0.25));
    let mut b = case(Target::T2dArray, 4, 4, 2);
    b.lookup.bias = 1.0;
    let p = plan(ApiPath::GlslCore, &b).unwrap();
    assert_eq!(p.key.form, LodForm::Grad, "bias folded into gradients");
}

#[test]
fn a_preferred_lookup_form_goes_first_where_it_exists() {
    let c = case(Target::T2d, 4, 4, 1);
    let form = |p| plan_with(ApiPath::GlslCore, &c, p).unwrap().key.form;
    assert_eq!(form(LookupForm::Auto), LodForm::Lod);
    assert_eq!(form(LookupForm::Grad), LodForm::Grad);
    assert_eq!(form(LookupForm::Implicit), LodForm::Implicit(false));
    // GLSL 1.20 has only the implicit form: the preference cannot change it.
    assert_eq!(
        plan_with(ApiPath::Glsl120, &c, LookupForm::Grad)
            .unwrap()
            .key
            .form,
        LodForm::Implicit(false)
    );
    // A shader bias: the bias form by default, the folded LOD when textureLod is preferred.
    let mut b = c.clone();
    b.lookup.bias = 1.0;
    assert_eq!(
        plan_with(ApiPath::GlslCore, &b, LookupForm::Auto)
            .unwrap()
            .key
            .form,
        LodForm::Implicit(true)
    );
    assert_eq!(
        plan_with(ApiPath::GlslCore, &b, LookupForm::Lod)
            .unwrap()
            .key
            .form,
        LodForm::Lod
    );
}

#[test]
fn gradients_give_rho_two_to_the_lod() {
    let c = case(Target::T2d, 8, 4, 1);
    let (dx, dy) = gradients(&c, &c.lookup, 1.0);
    assert_eq!((dx[0] * 8.0, dy[1] * 4.0), (2.0, 2.0));
    let mut cube = case(Target::Cube, 4, 4, 6);
    cube.lookup.coord = [0.1, -0.2, -2.0, 1.0];
    let (dx, dy) = gradients(&cube, &cube.lookup, 0.0);
    // major axis r (|ma| = 2): one texel of a 4-wide face is 2*|ma|/4 in direction units.
    assert_eq!((dx[0], dy[1], dx[2], dy[2]), (1.0, 1.0, 0.0, 0.0));
}

#[test]
fn fixed_function_keeps_exact_coordinates_unless_lambda_matters() {
    let mut c = case(Target::T2d, 4, 4, 1);
    c.api = vec![ApiPath::FixedFunction];
    assert_eq!(
        plan(ApiPath::FixedFunction, &c).unwrap().key.form,
        LodForm::Constant
    );
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    c.lookup.lod = 1.0;
    c.lookup.bias = 0.5;
    let p = plan(ApiPath::FixedFunction, &c).unwrap();
    // lambda_base = 1 from gradients of 2 texels per pixel; the bias goes to the texture unit.
    assert_eq!(
        (p.key.form, p.x, p.dx[0] * 4.0),
        (LodForm::Implicit(true), 0.5, 2.0)
    );
    c.texture.target = Target::Cube;
    assert!(plan(ApiPath::FixedFunction, &c)
        .unwrap_err()
        .contains("cube"));
}

#[test]
fn offset_lookups_exist_per_glsl_4_60_8_9_2() {
    use SamplerKind::Shadow;
    // 2D: every form; rectangles: no LOD form, no bias; 2D-array shadow: gradients only; ES: no 1D.
    assert!(offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::T2d,
        LodForm::Implicit(true)
    ));
    assert!(offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::T1dArray,
        LodForm::Lod
    ));
    assert!(!offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::Rect,
        LodForm::Lod
    ));
    assert!(!offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::Rect,
        LodForm::Implicit(true)
    ));
    assert!(offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::Rect,
        LodForm::Grad
    ));
    assert!(!offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::T2dArray,
        LodForm::Implicit(false)
    ));
    assert!(offset_available(
        ApiPath::Es300,
        Shadow,
        Target::T2dArray,
        LodForm::Grad
    ));
    assert!(!offset_available(
        ApiPath::Es300,
        Shadow,
        Target::T1d,
        LodForm::Lod
    ));
    assert!(!offset_available(
        ApiPath::GlslCore,
        Shadow,
        Target::Cube,
        LodForm::Grad
    ));
    // The plan falls back to the form that has an offset variant.
    let mut c = case(Target::T2dArray, 4, 4, 2);
    c.lookup.offset = [1, 0, 0];
    assert_eq!(plan(ApiPath::GlslCore, &c).unwrap().key.form, LodForm::Grad);
    assert_eq!(
        plan_with(ApiPath::GlslCore, &c, LookupForm::Implicit)
            .unwrap()
            .key
            .form,
        LodForm::Grad
    );
}

#[test]
fn ext_texture_shadow_lod_overloads_are_used_when_the_form_asks_for_them() {
    // EXT_texture_shadow_lod §8.9.2: textureLod on samplerCubeShadow, sampler2DArrayShadow and
    // samplerCubeArrayShadow, texture(sampler2DArrayShadow, P, bias), textureOffset on
    // sampler2DArrayShadow.
    for (target, layers) in [
        (Target::Cube, 6),
        (Target::T2dArray, 2),
        (Target::CubeArray, 6),
    ] {
        let mut c = case(target, 4, 4, layers);
        c.lookup.lod = 1.0;
        let with = plan_in(ApiPath::GlslCore, &c, &c.lookup, LookupForm::Lod, true).unwrap();
        assert_eq!(with.key.form, LodForm::Lod, "{target}");
        assert!(uses_shadow_lod(&with.key));
        assert!(
            with.note.contains("EXT_texture_shadow_lod"),
            "{}",
            with.note
        );
        // Without the extension, or without asking for textureLod: the form of before.
        let without = plan_in(ApiPath::GlslCore, &c, &c.lookup, LookupForm::Lod, false).unwrap();
        assert_ne!(without.key.form, LodForm::Lod, "{target}");
        let auto = plan_in(ApiPath::GlslCore, &c, &c.lookup, LookupForm::Auto, true).unwrap();
        assert_eq!(auto.key.form, without.key.form, "{target}");
        if target == Target::CubeArray {
            // textureLod(samplerCubeArrayShadow, P, compare, lod): compare in x, lod in dx.x.
            assert_eq!((with.x, with.dx[0]), (c.lookup.dref as f32, 1.0));
        }
    }
    let mut b = case(Target::T2dArray, 4, 4, 2);
    b.lookup.bias = 1.0;
    let p = plan_in(ApiPath::Es300, &b, &b.lookup, LookupForm::Implicit, true).unwrap();
    assert_eq!(p.key.form, LodForm::Implicit(true));
    assert!(uses_shadow_lod(&p.key));
    let p = plan_in(ApiPath::Es300, &b, &b.lookup, LookupForm::Implicit, false).unwrap();
    assert_ne!(
        p.key.form,
        LodForm::Implicit(true),
        "no bias form without the extension"
    );
    b.lookup.offset = [1, 0, 0];
    let p = plan_in(ApiPath::GlslCore, &b, &b.lookup, LookupForm::Implicit, true).unwrap();
    assert_eq!(
        p.key.form,
        LodForm::Implicit(true),
        "textureOffset with bias"
    );
}

#[test]
fn the_vulkan_path_realizes_lookups_as_the_core_path_does() {
    for target in [
        Target::T2d,
        Target::Cube,
        Target::T2dArray,
        Target::CubeArray,
    ] {
        let layers = match target {
            Target::Cube => 6,
            Target::CubeArray => 12,
            Target::T2dArray => 3,
            _ => 1,
        };
        let mut c = case(target, 4, 4, layers);
        c.lookup.offset = if target.is_cube() { [0; 3] } else { [1, -2, 0] };
        let core = plan(ApiPath::GlslCore, &c).expect("core");
        let vk = plan(ApiPath::Vulkan, &c).expect("vk");
        assert_eq!(
            vk.key,
            ShaderKey {
                path: ApiPath::Vulkan,
                ..core.key
            },
            "{target}"
        );
        assert_eq!(
            (vk.p, vk.x, vk.dx, vk.dy),
            (core.p, core.x, core.dx, core.dy)
        );
        c.lookup.offset = [0; 3];
        c.lookup.gather = Some(shadowcheck_model::Gather { offsets: None });
        let g = plan(ApiPath::Vulkan, &c).expect("vk gather");
        assert_eq!(g.key.gather, Some(GatherCall::Single), "{target}");
    }
}
