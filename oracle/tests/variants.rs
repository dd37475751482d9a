//! Where the variants differ: clamping, border, completeness, layouts, filtering, stencil.

mod common;
use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};

#[test]
fn ref_clamp_differs_by_spec_and_format() {
    // GL 4.6 §8.23.1: Dref clamped only for fixed-point depth. Ref 1.5 vs Dt 1.0, LEQUAL.
    assert_eq!(
        value(&one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 1.5, 1.0)),
        1.0
    );
    assert_eq!(
        value(&one(
            Spec::Gl46,
            Format::D32f,
            CompareFunc::Lequal,
            1.5,
            1.0
        )),
        0.0
    );
    assert_eq!(
        value(&one(
            Spec::Gles32,
            Format::D16,
            CompareFunc::Lequal,
            1.5,
            1.0
        )),
        1.0
    );
    assert_eq!(
        value(&one(
            Spec::Gles32,
            Format::D32f,
            CompareFunc::Lequal,
            1.5,
            1.0
        )),
        0.0
    );
    // ARB_shadow: "R ... clamped to the range [0, 1]"; EXT_shadow_samplers: always clamped.
    assert_eq!(
        value(&one(Spec::Arb, Format::D24, CompareFunc::Lequal, 1.5, 1.0)),
        1.0
    );
    assert_eq!(
        value(&one(
            Spec::Es2Ext,
            Format::D24,
            CompareFunc::Lequal,
            1.5,
            1.0
        )),
        1.0
    );
    // Below zero: GEQUAL with Dref −0.5 against Dt 0.
    assert_eq!(
        value(&one(
            Spec::Gl46,
            Format::D16,
            CompareFunc::Gequal,
            -0.5,
            0.0
        )),
        1.0
    );
    assert_eq!(
        value(&one(
            Spec::Gl46,
            Format::D32fS8,
            CompareFunc::Gequal,
            -0.5,
            0.0
        )),
        0.0
    );
}

#[test]
fn sgix_r_clamp_is_unstated_so_both_readings_are_accepted() {
    // texel 0 <= R = −0.5 fails unclamped (the literal spec value) but passes with NVIDIA's clamp.
    let e = eval(&one(
        Spec::Sgix,
        Format::D16,
        CompareFunc::LequalRSgix,
        -0.5,
        0.0,
    ));
    assert_eq!(e.expect.spec_value, Some(0.0));
    for &p in Profile::ALL {
        assert!(e.expect.accept[&p].contains(0.0) && e.expect.accept[&p].contains(1.0));
    }
    assert!(e
        .expect
        .implementation_defined
        .unwrap()
        .contains("unstated"));
}

#[test]
fn float_depth_upload_is_clamped_but_dt_is_not() {
    // §8.5: uploads clamp to [0,1] even for D32F: a stored 1.5 becomes 1.0; Dref 1.2 > 1.0.
    assert_eq!(
        value(&one(
            Spec::Gl46,
            Format::D32f,
            CompareFunc::Lequal,
            1.2,
            1.5
        )),
        0.0
    );
    // A D32F border is not clamped by GL 4.6 (in range for a float format): Dt = 1.5 ≥ Dref 1.2.
    let mut c = one(Spec::Gl46, Format::D32f, CompareFunc::Lequal, 1.2, 0.0);
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.5, 0.0, 0.0, 0.0];
    c.lookup.coord = [-0.5, 0.5, 0.0, 1.0];
    assert_eq!(value(&c), 1.0);
    // A unorm border out of [0,1] is undefined in GL 4.6, clamped in ES 3.2.
    let mut d = c.clone();
    d.texture = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.0, 0.0).texture;
    d.lookup.dref = 0.9;
    d.sampler.border = [-2.0, 0.0, 0.0, 0.0];
    let e = eval(&d);
    assert!(e.expect.implementation_defined.is_some());
    assert!(
        e.expect.accept[&Profile::Strict].contains(0.0)
            && e.expect.accept[&Profile::Strict].contains(1.0)
    );
    d.spec = Spec::Gles32;
    d.api = vec![ApiPath::Es300];
    let e = eval(&d);
    assert_eq!(e.expect.spec_value, Some(0.0));
    assert!(!e.expect.accept[&Profile::Strict].contains(1.0));
}

#[test]
fn incomplete_texture_result_per_era() {
    let mut c = one(Spec::Gl46, Format::D16, CompareFunc::Always, 0.5, 0.5);
    c.sampler.min_filter = Filter::LinearMipmapLinear; // one level of a 1x1 texture is complete...
    assert_eq!(value(&c), 1.0);
    c.texture.levels[0].width = 2; // ...a 2x1 base without level 1 is not.
    c.texture.levels[0].depth = Texels::Unorm(vec![0, 0]);
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.0));
    assert_eq!(
        e.expect.layout[&ApiPath::GlslCore],
        [
            Channel::R,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ]
    );
    // Legacy: (0,0,0,1) through GLSL 1.20.
    c.spec = Spec::ExtFuncs;
    c.api = vec![ApiPath::Glsl120];
    let e = eval(&c);
    assert_eq!(
        e.expect.layout[&ApiPath::Glsl120],
        [Channel::R, Channel::Zero, Channel::Zero, Channel::One]
    );
    assert_eq!(e.expect.spec_value, Some(0.0));
}

#[test]
fn es_sized_depth_with_compare_none_and_linear_is_incomplete() {
    let mut c = case2d(
        Spec::Gles32,
        Format::D24,
        CompareFunc::Lequal,
        Filter::Linear,
        2,
        1,
        &[0.25, 0.75],
        (0.5, 0.5),
        0.5,
    );
    c.sampler.compare_mode = CompareMode::None;
    assert_eq!(value(&c), 0.0);
    // GL 4.6 has no such rule: r = Dt, filtered: (0.25 + 0.75) / 2.
    c.spec = Spec::Gl46;
    c.api = vec![ApiPath::GlslCore];
    let v = value(&c);
    assert!((v - 0.5).abs() < 1e-7, "{v}");
    // With comparison on, ES keeps it complete.
    c.spec = Spec::Gles32;
    c.api = vec![ApiPath::Es300];
    c.sampler.compare_mode = CompareMode::Compare;
    assert_eq!(value(&c), 0.5);
}

#[test]
fn stencil_mode_returns_st() {
    let mut c = one(Spec::Gl46, Format::D24S8, CompareFunc::Never, 0.5, 0.5);
    c.texture.levels[0].stencil = Some(vec![77]);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    // With the comparison off (with it on the read is undefined, §11.1.3.5: audit_open.rs).
    c.sampler.compare_mode = CompareMode::None;
    assert_eq!(value(&c), 77.0);
    // Not a pname before GL 4.3 / ES 3.1.
    c.spec = Spec::ExtFuncs;
    c.api = vec![ApiPath::FixedFunction];
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
}

#[test]
fn depth_texture_mode_layouts() {
    let base = one(Spec::Arb, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    let cases = [
        (None, [Channel::R, Channel::R, Channel::R, Channel::One]),
        (Some(DepthTextureMode::Intensity), [Channel::R; 4]),
        (
            Some(DepthTextureMode::Alpha),
            [Channel::Zero, Channel::Zero, Channel::Zero, Channel::R],
        ),
    ];
    for (m, want) in cases {
        let mut c = base.clone();
        c.api = vec![ApiPath::Glsl120, ApiPath::ArbFp];
        c.sampler.depth_texture_mode = m;
        let e = eval(&c);
        assert_eq!(e.expect.layout[&ApiPath::Glsl120], want, "{m:?}");
        assert_eq!(e.expect.layout[&ApiPath::ArbFp], want, "{m:?}");
    }
    // RED exists only in GL 3.0+ compatibility.
    let mut c = base.clone();
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Red);
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
    c.spec = Spec::Gl46;
    c.api = vec![ApiPath::Glsl120, ApiPath::Glsl130];
    let e = eval(&c);
    assert_eq!(
        e.expect.layout[&ApiPath::Glsl120],
        [Channel::R, Channel::Zero, Channel::Zero, Channel::One]
    );
    assert_eq!(
        e.expect.layout[&ApiPath::Glsl130],
        [
            Channel::R,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ]
    );
    // ... and not in a core context.
    c.api = vec![ApiPath::GlslCore];
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
}

#[test]
fn api_paths_that_do_not_apply_are_errors() {
    let mut c = one(Spec::Gles32, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.api = vec![ApiPath::GlslCore];
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::NotApplicable { .. })
    ));
    let mut c = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.texture.target = Target::T1d;
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::NotApplicable { .. })
    ));
}

#[test]
fn sgix_filters_before_comparing_and_gl_is_implementation_dependent() {
    // 2x2, lookup at the centre: weights 1/4; texels 0.2 0.4 0.6 0.8 against R = 0.5.
    let vals = [0.2, 0.4, 0.6, 0.8];
    let c = case2d(
        Spec::Sgix,
        Format::D16,
        CompareFunc::LequalRSgix,
        Filter::Linear,
        2,
        2,
        &vals,
        (0.5, 0.5),
        0.5,
    );
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(0.5)); // two texels <= R
    assert!(e.expect.implementation_defined.is_none());
    // Off-centre: α = 0.25, β = 0.75 → weights (0.1875, 0.0625, 0.5625, 0.1875); passes are texels 0, 1.
    let c = case2d(
        Spec::Sgix,
        Format::D16,
        CompareFunc::LequalRSgix,
        Filter::Linear,
        2,
        2,
        &vals,
        (0.375, 0.625),
        0.5,
    );
    assert_eq!(value(&c), 0.25);
    let g = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Gequal,
        Filter::Linear,
        2,
        2,
        &vals,
        (0.375, 0.625),
        0.5,
    );
    let e = eval(&g);
    assert_eq!(e.expect.spec_value, Some(0.25));
    assert!(e
        .expect
        .implementation_defined
        .unwrap()
        .contains("implementation-dependent"));
    // Quality also accepts the unweighted pass fraction 2/4 (any value in [0, 1] for a footprint
    // with both passes and fails: the proportion is a "should").
    assert!(e.expect.accept[&Profile::Quality].contains(0.5));
    assert!(!e.expect.accept[&Profile::Strict].contains(0.5));
}

#[test]
fn ties_within_reference_precision_accept_either_outcome() {
    // EQUAL with Dref = f32(c/65535): not equal in exact arithmetic, but the f32 conversion of Dt may
    // land on Dref, so strict accepts both.
    let c = 12345u32;
    let mut k = one(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Equal,
        (c as f64 / 65535.0) as f32 as f64,
        0.0,
    );
    k.texture.levels[0].depth = Texels::Unorm(vec![c]);
    let e = eval(&k);
    assert!(
        e.expect.accept[&Profile::Strict].contains(0.0)
            && e.expect.accept[&Profile::Strict].contains(1.0)
    );
    assert_eq!(e.footprint.texels[0].pass, None);
    // Two 24-bit units away from Dref, strict is exact; quality (2^-16, the "about 1 part in 10^5"
    // of GL 4.6 §2.3.4.1) still accepts both.
    let c24 = 5_000_000u32;
    k.texture.format = Format::D24;
    k.lookup.dref = (c24 as f64 / 16777215.0) as f32 as f64;
    k.texture.levels[0].depth = Texels::Unorm(vec![c24 + 2]);
    let e = eval(&k);
    assert_eq!(
        e.expect.accept[&Profile::Strict].0,
        vec![Interval::point(0.0)]
    );
    assert!(e.expect.accept[&Profile::Quality].contains(1.0));
}

#[test]
fn nan_reference_is_implementation_defined() {
    let e = eval(&one(
        Spec::Gl46,
        Format::D32f,
        CompareFunc::Lequal,
        f64::NAN,
        0.5,
    ));
    assert_eq!(e.expect.spec_value, None);
    assert!(e.expect.implementation_defined.is_some());
    assert!(
        e.expect.accept[&Profile::Strict].contains(0.0)
            && e.expect.accept[&Profile::Strict].contains(1.0)
    );
    // ALWAYS does not look at Dref.
    assert_eq!(
        value(&one(
            Spec::Gl46,
            Format::D32f,
            CompareFunc::Always,
            f64::NAN,
            0.5
        )),
        1.0
    );
}

#[test]
fn es2_has_no_lod_state_and_no_bias_argument() {
    let mut c = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.sampler.max_level = Some(0);
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
    let mut c = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.sampler.min_lod = 0.0;
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError {
            error: "INVALID_ENUM",
            ..
        })
    ));
    let mut c = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.lookup.bias = 1.0;
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::NotApplicable { .. })
    ));
}

#[test]
fn compat_float_shadow_lookup_returns_r_or_under_alpha_also_0() {
    let mut c = one(Spec::Gl46, Format::D16, CompareFunc::Lequal, 0.5, 1.0);
    c.api = vec![ApiPath::Glsl130, ApiPath::Glsl120];
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Alpha);
    let e = eval(&c);
    // Both readings of contradiction `compat-float-alpha` (audit_open.rs).
    assert_eq!(
        e.expect.layout[&ApiPath::Glsl130],
        [
            Channel::ROrZero,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ]
    );
    assert_eq!(
        e.expect.layout[&ApiPath::Glsl120],
        [Channel::Zero, Channel::Zero, Channel::Zero, Channel::R]
    );
    assert!(shadowcheck_oracle::contradictions::touching(&c)
        .iter()
        .any(|x| x.id == "compat-float-alpha"));
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Luminance);
    assert_eq!(
        eval(&c).expect.layout[&ApiPath::Glsl130],
        [
            Channel::R,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ]
    );
}

#[test]
fn non_required_d32_may_be_stored_at_24_bits_and_denormals_may_flush() {
    // DEPTH_COMPONENT32 has only "desired" resolution (Table 8.13): c = 1 may read back as 0.
    let mut c = one(Spec::Gl46, Format::D32, CompareFunc::Lequal, 1e-12, 0.0);
    c.texture.levels[0].depth = Texels::Unorm(vec![1]);
    let e = eval(&c);
    assert_eq!(e.expect.spec_value, Some(1.0)); // 1e-12 ≤ 1/(2^32−1) ≈ 2.3e-10
    assert!(
        e.expect.accept[&Profile::Strict].contains(0.0)
            && e.expect.accept[&Profile::Strict].contains(1.0)
    );
    // A subnormal Dref may be flushed to 0: EQUAL against a D32F zero may pass.
    let tiny = f32::from_bits(1) as f64;
    let e = eval(&one(
        Spec::Gl46,
        Format::D32f,
        CompareFunc::Equal,
        -tiny,
        0.0,
    ));
    assert_eq!(e.expect.spec_value, Some(0.0));
    assert!(e.expect.accept[&Profile::Strict].contains(1.0));
}
