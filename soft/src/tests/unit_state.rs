//! The texture swizzle on a shadow gather and on the compatibility paths, and a sampler object's
//! rectangle-illegal state. Expected values by hand from GL 4.6 §8.14.2, §15.2.1, §16.1 (Table
//! 16.1, compatibility), §11.1.3.5, §8.2 and §8.10.

use super::*;

const RED: Swizzle = Swizzle::Red;
const GREEN: Swizzle = Swizzle::Green;
const BLUE: Swizzle = Swizzle::Blue;
const ALPHA: Swizzle = Swizzle::Alpha;
const ZERO: Swizzle = Swizzle::Zero;
const ONE: Swizzle = Swizzle::One;

fn rgba(c: &Case, api: ApiPath) -> [f32; 4] {
    SoftUnit::new(c.spec).sample(c, api).unwrap()
}

fn faulty(c: &Case, api: ApiPath, f: Fault) -> [f32; 4] {
    SoftUnit::new(c.spec).with_fault(f).sample(c, api).unwrap()
}

/// A shadow gather on the 2x2 D16 image rows j0 = [0, ¼], j1 = [¾, 1], at the centre, LEQUAL with
/// Dref ½: u = v = 1, i0 = j0 = 0, i1 = j1 = 1, so (τi0j1, τi1j1, τi1j0, τi0j0) = (¾, 1, ¼, 0)
/// and the comparisons (Dref ≤ Dt) are (1, 1, 0, 0): a mixed footprint.
fn gather(spec: Spec, swizzle_r: Swizzle) -> Case {
    let mut c = case2d(
        spec,
        Format::D16,
        2,
        2,
        vec![0, d16(0.25), d16(0.75), 65535],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.lookup.gather = Some(Gather { offsets: None });
    c.sampler.swizzle = Some([swizzle_r, GREEN, BLUE, ALPHA]);
    c
}

#[test]
fn shadow_gather_takes_the_post_swizzle_r_of_each_texel() {
    // §8.14.2: each texel's source colour Cb = (Rt, 0, 0, 1) (§11.1.3.5) is swizzled, then its R
    // is gathered: TEXTURE_SWIZZLE_R picks Rt, 0 (GREEN, BLUE, ZERO) or 1 (ALPHA, ONE).
    for (spec, api) in [
        (Spec::Gl46, ApiPath::GlslCore),
        (Spec::Gles32, ApiPath::Es300),
    ] {
        let g = |sw| rgba(&gather(spec, sw), api);
        assert_eq!(g(RED), [1.0, 1.0, 0.0, 0.0]);
        assert_eq!(g(GREEN), [0.0; 4]);
        assert_eq!(g(BLUE), [0.0; 4]);
        assert_eq!(g(ZERO), [0.0; 4]);
        assert_eq!(g(ALPHA), [1.0; 4]);
        assert_eq!(g(ONE), [1.0; 4]);
    }
    // Only TEXTURE_SWIZZLE_R matters (no comp argument: component R).
    let mut c = gather(Spec::Gl46, RED);
    c.sampler.swizzle = Some([RED, ZERO, ONE, ZERO]);
    assert_eq!(rgba(&c, ApiPath::GlslCore), [1.0, 1.0, 0.0, 0.0]);
    // The faults: the unswizzled comparisons.
    let c = gather(Spec::Gl46, ALPHA);
    for f in [Fault::GatherIgnoresSwizzle, Fault::SwizzleIgnored] {
        assert_eq!(faulty(&c, ApiPath::GlslCore, f), [1.0, 1.0, 0.0, 0.0]);
    }
    // The compatibility-path fault does not reach the core gather.
    assert_eq!(
        faulty(&c, ApiPath::GlslCore, Fault::CompatSwizzleDropped),
        [1.0; 4]
    );
}

#[test]
fn incomplete_gather_is_zero_whatever_the_swizzle() {
    // §8.14.2: "Incomplete textures ... are considered to return a texture source color of
    // (0.0, 0.0, 0.0, 1.0)" — a source colour, i.e. after the swizzle: R = 0 for every texel.
    let mut c = gather(Spec::Gl46, ONE);
    c.sampler.min_filter = Filter::LinearMipmapLinear; // one level of three: incomplete (§8.17)
    assert_eq!(rgba(&c, ApiPath::GlslCore), [0.0; 4]);
}

/// gl46, 2x1 D16 [Dt 0, Dt 1], LINEAR at s = ½ (u = 1, α = ½), LEQUAL Dref ½: PCF gives
/// r = ½·0 + ½·1 = ½. DEPTH_TEXTURE_MODE `mode`, swizzle `sw`, on `api`.
fn compat(api: ApiPath, mode: Option<DepthTextureMode>, sw: [Swizzle; 4]) -> Case {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![0, 65535],
        CompareFunc::Lequal,
        Filter::Linear,
    );
    c.api = vec![api];
    c.sampler.depth_texture_mode = mode;
    c.sampler.swizzle = Some(sw);
    c
}

#[test]
fn compat_paths_swizzle_the_depth_texture_mode_colour() {
    // Table 16.1 with r = ½: LUMINANCE (½, ½, ½, 1), INTENSITY (½, ½, ½, ½), ALPHA (0, 0, 0, ½),
    // RED (½, 0, 0, 1); then §15.2.1 with (ALPHA, ONE, RED, ZERO): (Ab, 1, Cb[0], 0).
    use DepthTextureMode as M;
    let sw = [ALPHA, ONE, RED, ZERO];
    for api in [ApiPath::FixedFunction, ApiPath::Glsl120] {
        let s = |mode| rgba(&compat(api, mode, sw), api);
        assert_eq!(s(None), [1.0, 1.0, 0.5, 0.0]); // default LUMINANCE
        assert_eq!(s(Some(M::Luminance)), [1.0, 1.0, 0.5, 0.0]);
        assert_eq!(s(Some(M::Intensity)), [0.5, 1.0, 0.5, 0.0]);
        assert_eq!(s(Some(M::Alpha)), [0.5, 1.0, 0.0, 0.0]);
        assert_eq!(s(Some(M::Red)), [1.0, 1.0, 0.5, 0.0]);
        // (GREEN, BLUE, ALPHA, RED) on ALPHA (0, 0, 0, ½): (0, 0, ½, 0).
        let c = compat(api, Some(M::Alpha), [GREEN, BLUE, ALPHA, RED]);
        assert_eq!(rgba(&c, api), [0.0, 0.0, 0.5, 0.0]);
        // The fault returns the Table 16.1 colour unswizzled.
        let c = compat(api, Some(M::Luminance), sw);
        assert_eq!(
            faulty(&c, api, Fault::CompatSwizzleDropped),
            [0.5, 0.5, 0.5, 1.0]
        );
    }
}

#[test]
fn compat_paths_swizzle_colour_and_stencil_reads() {
    // R8 102 = 0.4 (eq. (2.1)), comparison bypassed: RED (0.4, 0, 0, 1); (ONE, RED, ZERO, RED)
    // gives (1, 0.4, 0, 0.4).
    let mut c = case2d(
        Spec::Gl46,
        Format::R8,
        1,
        1,
        vec![102],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.api = vec![ApiPath::FixedFunction];
    c.sampler.swizzle = Some([ONE, RED, ZERO, RED]);
    assert_eq!(rgba(&c, ApiPath::FixedFunction), [1.0, 0.4, 0.0, 0.4]);
    // STENCIL_INDEX read (St, 0, 0, 1) = (7, 0, 0, 1); (GREEN, RED, ONE, RED) gives (0, 7, 1, 7).
    let mut c = case2d(
        Spec::Gl46,
        Format::D24S8,
        1,
        1,
        vec![0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.api = vec![ApiPath::Glsl120];
    c.texture.levels[0].stencil = Some(vec![7]);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.depth_stencil_mode = Some(DepthStencilMode::StencilIndex);
    c.sampler.swizzle = Some([GREEN, RED, ONE, RED]);
    assert_eq!(rgba(&c, ApiPath::Glsl120), [0.0, 7.0, 1.0, 7.0]);
}

#[test]
fn compat_glsl130_shadow_swizzles_rt_0_0_1() {
    // §11.1.3.5: Cs[0] of the swizzled Cb = (Rt, 0, 0, 1), in a compatibility context too,
    // whatever DEPTH_TEXTURE_MODE says: RED ½, GREEN 0, ALPHA 1.
    use DepthTextureMode as M;
    let api = ApiPath::Glsl130;
    let s = |r| {
        rgba(
            &compat(api, Some(M::Luminance), [r, GREEN, BLUE, ALPHA]),
            api,
        )
    };
    assert_eq!(s(RED), [0.5, 0.0, 0.0, 1.0]);
    assert_eq!(s(GREEN), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(s(ALPHA), [1.0, 0.0, 0.0, 1.0]);
}

#[test]
fn compat_swizzle_limits() {
    let sw = [ALPHA, ONE, RED, ZERO];
    // The pre-3.3 specs have no swizzle state.
    let mut c = compat(ApiPath::FixedFunction, None, sw);
    c.spec = Spec::Arb;
    assert!(SoftUnit::new(Spec::Arb)
        .sample(&c, ApiPath::FixedFunction)
        .is_err());
    // ARB_fragment_program stays refused (its own text is outside the spec pack).
    let c = compat(ApiPath::ArbFp, None, sw);
    assert!(SoftUnit::new(Spec::Gl46)
        .sample(&c, ApiPath::ArbFp)
        .is_err());
    // An incomplete texture is not swizzled: (0, 0, 0, 1) as for the other incomplete textures.
    let mut c = compat(ApiPath::FixedFunction, None, [ONE, ONE, ONE, ZERO]);
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    assert_eq!(rgba(&c, ApiPath::FixedFunction), [0.0, 0.0, 0.0, 1.0]);
}

/// A 2x1 rectangle [Dt 1, Dt 0] (the texture's own wrap CLAMP_TO_EDGE), NEAREST, LEQUAL Dref ½,
/// at unnormalized s; a bound sampler object with the texture's state changed by `f`.
fn rect(s: f64, f: impl FnOnce(&mut SamplerObject)) -> Case {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        2,
        1,
        vec![65535, 0],
        CompareFunc::Lequal,
        Filter::Nearest,
    );
    c.texture.target = Target::Rect;
    c.lookup.coord = [s, 0.5, 0.0, 1.0];
    let mut o = SamplerObject::from_sampler(&c.sampler);
    f(&mut o);
    c.sampler.sampler_object = Some(o);
    c
}

#[test]
fn rect_illegal_sampler_object_state_makes_the_texture_incomplete() {
    // §8.2: state TexParameter would reject for the rectangle texture (§8.10) held by the bound
    // sampler object makes the texture incomplete: core returns 0 (§11.1.3.5), (0, 0, 0, 1).
    let core = ApiPath::GlslCore;
    let incomplete = [0.0, 0.0, 0.0, 1.0];
    let cases = [
        rect(2.5, |o| o.wrap_s = Wrap::Repeat),
        rect(0.5, |o| o.wrap_s = Wrap::Repeat),
        rect(0.5, |o| o.wrap_t = Wrap::MirroredRepeat),
        rect(0.5, |o| o.wrap_s = Wrap::MirrorClampToEdge),
        rect(0.5, |o| o.min_filter = Filter::LinearMipmapNearest),
        rect(0.5, |o| o.min_filter = Filter::NearestMipmapNearest),
    ];
    for c in &cases {
        assert_eq!(rgba(c, core), incomplete, "{:?}", c.sampler.sampler_object);
        // Fixed function and GLSL 1.30 (compatibility): the incomplete result (0, 0, 0, 1) too.
        assert_eq!(rgba(c, ApiPath::FixedFunction), incomplete);
        assert_eq!(rgba(c, ApiPath::Glsl130), incomplete);
    }
    // A shadow gather on it: four zeros (§8.14.2).
    let mut c = rect(1.0, |o| o.wrap_s = Wrap::Repeat);
    c.lookup.gather = Some(Gather { offsets: None });
    assert_eq!(rgba(&c, core), [0.0; 4]);
    // The fault samples with REPEAT: s = 2.5 reads texel ⌊2.5⌋ mod 2 = 0, Dt 1 passes.
    assert_eq!(
        faulty(&cases[0], core, Fault::SamplerObjectRectComplete),
        [1.0, 0.0, 0.0, 1.0]
    );
}

#[test]
fn rect_legal_sampler_object_state_samples_normally() {
    let core = ApiPath::GlslCore;
    // CLAMP_TO_EDGE: s = ½ reads texel 0 (Dt 1 passes); s = 2.5 clamps to texel 1 (Dt 0 fails).
    assert_eq!(
        rgba(&rect(0.5, |o| o.wrap_s = Wrap::ClampToEdge), core),
        [1.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(
        rgba(&rect(2.5, |o| o.wrap_s = Wrap::ClampToEdge), core),
        [0.0, 0.0, 0.0, 1.0]
    );
    // CLAMP_TO_BORDER with border depth 1: s = 2.5 reads the border, 0.5 ≤ 1 passes.
    let c = rect(2.5, |o| {
        o.wrap_s = Wrap::ClampToBorder;
        o.border = [1.0, 0.0, 0.0, 0.0];
    });
    assert_eq!(rgba(&c, core), [1.0, 0.0, 0.0, 1.0]);
    // TEXTURE_WRAP_R is not in §8.10's list for rectangles (and does not address them).
    assert_eq!(
        rgba(&rect(0.5, |o| o.wrap_r = Wrap::Repeat), core),
        [1.0, 0.0, 0.0, 1.0]
    );
    // The same REPEAT set on the texture itself is an INVALID_ENUM error (§8.10): refused.
    let mut c = rect(0.5, |_| {});
    c.sampler.sampler_object = None;
    c.sampler.wrap_s = Wrap::Repeat;
    assert_eq!(
        SoftUnit::new(Spec::Gl46).sample(&c, core),
        Err(SoftError::Wrap {
            spec: Spec::Gl46,
            wrap: Wrap::Repeat
        })
    );
}

/// GL 4.6 §8.17.1: with a sampler object bound, "the sampling state for that unit is taken from
/// the sampler object", for a gather too: its GEQUAL turns the LEQUAL pattern (1, 1, 0, 0) into
/// (0, 0, 1, 1). The fault `gather-ignores-sampler-object` gathers with the texture's LEQUAL,
/// and leaves a filtered lookup alone.
#[test]
fn a_gather_takes_the_bound_sampler_objects_compare_function() {
    let core = ApiPath::GlslCore;
    let mut c = gather(Spec::Gl46, RED);
    c.sampler.swizzle = None;
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Gequal;
    c.sampler.sampler_object = Some(o);
    assert_eq!(rgba(&c, core), [0.0, 0.0, 1.0, 1.0]);
    let f = Fault::GatherIgnoresSamplerObject;
    assert_eq!(faulty(&c, core, f), [1.0, 1.0, 0.0, 0.0]);
    c.lookup.gather = None;
    assert_eq!(faulty(&c, core, f), rgba(&c, core));
}
