//! Results the texts leave open, state outside a text, incomplete non-shadow reads. One test per rule, each quoting the sentence it encodes.

mod common;
use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};

/// GL 4.6 §11.1.3.5: "the results of a texture lookup are undefined if ... The sampler used in a
/// texture lookup function is not one of the shadow sampler types, the texture object's base internal
/// format is DEPTH_COMPONENT or DEPTH_STENCIL, and the TEXTURE_COMPARE_MODE is not NONE." A stencil
/// read goes through an unsigned integer sampler: any index, labelled.
#[test]
fn a_stencil_read_with_the_comparison_on_is_undefined() {
    let mut c = one(Spec::Gl46, Format::D24S8, CompareFunc::Lequal, 0.5, 0.5);
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c.texture.levels[0].stencil = Some(vec![42]);
    let e = eval(&c);
    let strict = &e.expect.accept[&Profile::Strict];
    assert!(strict.contains(0.0) && strict.contains(42.0) && strict.contains(255.0));
    assert_eq!(e.expect.spec_value, None);
    assert!(e
        .expect
        .implementation_defined
        .unwrap_or_default()
        .contains("§11.1.3.5"));
    // With the comparison off, r = St exactly (§8.23.1).
    c.sampler.compare_mode = CompareMode::None;
    assert_eq!(
        eval(&c).expect.accept[&Profile::Strict].0,
        vec![Interval::point(42.0)]
    );
}

/// SGIX_shadow, Notes: "These operators are defined only for textures with internal format
/// DEPTH_COMPONENT or DEPTH_COMPONENTS*_SGI." On a colour texture the result is open.
#[test]
fn sgix_operators_on_a_colour_texture_are_open() {
    let c = one(Spec::Sgix, Format::R8, CompareFunc::LequalRSgix, 0.5, 0.4);
    let e = eval(&c);
    let strict = &e.expect.accept[&Profile::Strict];
    assert!(strict.contains(0.0) && strict.contains(102.0 / 255.0) && strict.contains(1.0));
    assert!(e
        .expect
        .implementation_defined
        .unwrap_or_default()
        .contains("defined only for textures with internal format DEPTH_COMPONENT"));
}

/// SGIX_shadow's Table 3.8: "TEXTURE_WRAP_S integer CLAMP, REPEAT" (T and R_EXT alike), and no
/// TEXTURE_LOD_BIAS row. Other wraps and a bias are outside the text: not applicable.
#[test]
fn sgix_table_3_8_lists_only_clamp_and_repeat_and_no_lod_bias() {
    for spec in [Spec::Sgix, Spec::SgixAmbient] {
        let base = one(spec, Format::D16, CompareFunc::LequalRSgix, 0.5, 0.4);
        assert!(evaluate(&base).is_ok(), "{spec} CLAMP");
        let mut r = base.clone();
        r.sampler.wrap_t = Wrap::Repeat;
        assert!(evaluate(&r).is_ok(), "{spec} REPEAT");
        for w in [Wrap::ClampToEdge, Wrap::ClampToBorder, Wrap::MirroredRepeat] {
            let mut c = base.clone();
            c.sampler.wrap_s = w;
            assert!(
                matches!(evaluate(&c), Err(OracleError::NotApplicable { .. })),
                "{spec} {w}"
            );
        }
        let mut b = base.clone();
        b.sampler.lod_bias = 0.5;
        assert!(
            matches!(evaluate(&b), Err(OracleError::NotApplicable { .. })),
            "{spec} lod bias"
        );
    }
}

/// GL 4.6 §11.1.3.5: "If a sampler is used in a shader and the sampler's associated texture is not
/// complete, as defined in section 8.17, (0.0, 0.0, 0.0, 1.0), in floating-point, will be returned for
/// a non-shadow sampler and 0 for a shadow sampler." G, B and A are checked too.
#[test]
fn an_incomplete_non_shadow_read_returns_0001() {
    // A mipmapping filter with only level 0 of a 2x2 texture: incomplete (§8.17).
    for format in [Format::D16, Format::R8] {
        let mut c = case2d(
            Spec::Gl46,
            format,
            CompareFunc::Lequal,
            Filter::LinearMipmapLinear,
            2,
            2,
            &[0.5; 4],
            (0.5, 0.5),
            0.5,
        );
        c.sampler.compare_mode = CompareMode::None;
        c.id = format!("incomplete/{format}");
        let e = eval(&c).expect;
        assert_eq!(e.spec_value, Some(0.0), "{format}");
        let api = ApiPath::GlslCore;
        assert_eq!(
            e.judge(api, [0.0, 0.0, 0.0, 1.0]),
            Some(Judgement::Strictest),
            "{format}"
        );
        for wrong in [
            [0.0, 0.5, 0.0, 1.0],
            [0.0, 0.0, 0.5, 1.0],
            [0.0, 0.0, 0.0, 0.0],
        ] {
            assert_eq!(
                e.judge(api, wrong),
                Some(Judgement::Outside),
                "{format} {wrong:?}"
            );
        }
    }
}

/// Projective lookups divide "s, t, r and Dref" by q (GLSL textureProj; GL 4.6 §8.14.1). The
/// quotient is an f32 computation: Dref/q already had its f32 neighbours accepted; s/q and t/q get
/// the same allowance. At s/q = 1/3 on a 3-texel row the exact u = 1 selects texel 1, the f32
/// neighbour below (u = 0.99999994) texel 0.
#[test]
fn projective_s_and_t_over_q_may_be_either_f32_neighbour() {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Lequal,
        Filter::Nearest,
        3,
        1,
        &[0.2, 0.8, 0.8],
        (1.0, 1.5),
        1.5,
    );
    c.lookup.projective = true;
    c.lookup.coord[3] = 3.0;
    let e = eval(&c);
    // Dref = 1.5/3 = 0.5: texel 1 (0.8) passes, texel 0 (0.2) fails.
    assert_eq!(e.expect.spec_value, Some(1.0));
    let strict = &e.expect.accept[&Profile::Strict];
    assert!(strict.contains(1.0) && strict.contains(0.0), "{strict}");
    assert!(e
        .expect
        .implementation_defined
        .unwrap_or_default()
        .contains("s/q and t/q are computed in f32"));
    // Not projective (s = 1/3 passed as an f32 rounds up: u > 1): texel 1 only.
    let mut p = c.clone();
    p.lookup.projective = false;
    p.lookup.coord = [1.0 / 3.0, 0.5, 0.0, 1.0];
    p.lookup.dref = 0.5;
    assert_eq!(
        eval(&p).expect.accept[&Profile::Strict].0,
        vec![Interval::point(1.0)]
    );
}

/// A GLSL 1.30 shadow lookup in a compatibility context with DEPTH_TEXTURE_MODE ALPHA: compatibility
/// §11.1.3.5 expands "the resulting value Rt to a color Cb = (Rt, 0, 0, 1)" and returns Cs[0] (r),
/// while §8.23.1 ("The resulting r is assigned to Rt, Lt, It, or At if the value of
/// DEPTH_TEXTURE_MODE is respectively RED, LUMINANCE, INTENSITY, or ALPHA") with Table 16.1 gives
/// Cb = (0, 0, 0, At), so Cs[0] = 0. Both readings are accepted and labelled.
#[test]
fn glsl130_alpha_mode_shadow_lookup_accepts_both_readings() {
    let mut c = one(Spec::Gl46, Format::D16, CompareFunc::Lequal, 0.25, 0.5);
    c.api = vec![ApiPath::Glsl130];
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Alpha);
    let e = eval(&c).expect;
    assert_eq!(e.spec_value, Some(1.0));
    let api = ApiPath::Glsl130;
    assert_eq!(
        e.layout[&api],
        [
            Channel::ROrZero,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused
        ]
    );
    assert_eq!(
        e.judge(api, [1.0, 0.0, 0.0, 1.0]),
        Some(Judgement::Strictest)
    );
    assert_eq!(
        e.judge(api, [0.0, 0.0, 0.0, 1.0]),
        Some(Judgement::Strictest)
    );
    assert_eq!(e.judge(api, [0.5, 0.0, 0.0, 1.0]), Some(Judgement::Outside));
    assert!(e
        .implementation_defined
        .unwrap_or_default()
        .contains("compat-float-alpha"));
    // LUMINANCE: one reading, r.
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Luminance);
    let e = eval(&c).expect;
    assert_eq!(e.judge(api, [0.0, 0.0, 0.0, 1.0]), Some(Judgement::Outside));
}
