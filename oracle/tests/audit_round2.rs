//! More rules the oracle once encoded wrong (after those of `audit.rs`), each derived by hand from
//! the sentence it quotes: the swizzle of a
//! shadow gather, the swizzle on the compatibility fixed-function and GLSL 1.20 paths, the two
//! readings of a compatibility GLSL 1.30 depth read, a sampler object holding state a rectangle
//! texture refuses, and the gather footprint tolerance under `strict`.

mod common;

use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};
use Channel::{One, Unused, Zero, R};
use Swizzle as S;

/// A 4x4 D32F texture whose texel (x, y) holds (4y + x) / 16, gathered at (0.3125, 0.5625): the
/// footprint (0,2) = 8/16, (1,2) = 9/16, (1,1) = 5/16, (0,1) = 4/16. With Dref = 6.5/16 and LEQUAL
/// the comparisons are (1, 1, 0, 0) in the order τi0j1, τi1j1, τi1j0, τi0j0.
fn gather(sw: Option<[Swizzle; 4]>) -> Case {
    let vals: Vec<f64> = (0..16).map(|i| i as f64 / 16.0).collect();
    let mut c = case2d(
        Spec::Gl46,
        Format::D32f,
        CompareFunc::Lequal,
        Filter::Linear,
        4,
        4,
        &vals,
        (0.3125, 0.5625),
        6.5 / 16.0,
    );
    c.lookup.gather = Some(Gather { offsets: None });
    c.sampler.swizzle = sw;
    c
}

/// Every layout of `api`: the spec's reading first, then the others with their names.
fn readings(c: &Case, api: ApiPath) -> Vec<([Channel; 4], Option<String>)> {
    let e = eval(c).expect;
    let mut v = vec![(*e.layout.get(&api).expect("a layout"), None)];
    for o in e.other_layouts.get(&api).into_iter().flatten() {
        v.push((o.layout, Some(o.reading.clone())));
    }
    v
}

fn judge(c: &Case, api: ApiPath, rgba: [f64; 4]) -> Judgement {
    eval(c).expect.judge(api, rgba).expect("a judgement")
}

#[test]
fn class1_shadow_gather_takes_the_post_swizzle_r_component() {
    // GL 4.6 §8.14.2: "Each texel is then converted to a texture source color (Rs,Gs,Bs,As)
    // according to table 15.1 and then swizzled as described in section 15.2.1"; Figure 8.4: "each
    // component is taken from the post-swizzle R component of the corresponding texel". A
    // comparison result Rt is Cb = (Rt, 0, 0, 1) (§11.1.3.5).
    let core = ApiPath::GlslCore;
    // RED: the comparisons themselves, one reading.
    let c = gather(Some([S::Red, S::Zero, S::Zero, S::Zero]));
    assert_eq!(readings(&c, core), vec![(Channel::GATHER, None)]);
    assert_eq!(judge(&c, core, [1.0, 1.0, 0.0, 0.0]), Judgement::Strictest);
    // ZERO / GREEN / BLUE: Cs[0] = 0 for every texel; ALPHA / ONE: 1.
    for (sw, v) in [
        (S::Zero, Zero),
        (S::Green, Zero),
        (S::Blue, Zero),
        (S::Alpha, One),
        (S::One, One),
    ] {
        let c = gather(Some([sw, S::Green, S::Blue, S::Alpha]));
        let r = readings(&c, core);
        assert_eq!(r[0], ([v; 4], None), "TEXTURE_SWIZZLE_R {sw}");
        // GLSL 4.60 §8.9.4's "returns the result of that comparison in the appropriate component
        // of the result vector", read without the swizzle, is the named other reading.
        assert_eq!(r[1], (Channel::GATHER, Some("gather-swizzle".to_string())));
        let k = if v == One { 1.0 } else { 0.0 };
        assert_eq!(judge(&c, core, [k; 4]), Judgement::Strictest, "{sw}");
        assert_eq!(
            judge(&c, core, [1.0, 1.0, 0.0, 0.0]),
            Judgement::Strictest,
            "the unswizzled reading, {sw}"
        );
        // Neither reading: the comparisons rotated.
        assert_eq!(judge(&c, core, [0.0, 1.0, 1.0, 0.0]), Judgement::Outside);
        assert!(eval(&c)
            .expect
            .implementation_defined
            .is_some_and(|n| n.contains("gather-swizzle")));
    }
    // An incomplete texture: "a texture source color of (0.0, 0.0, 0.0, 1.0)" (already the source
    // colour), so R is 0 whatever the swizzle.
    let mut c = gather(Some([S::One, S::Green, S::Blue, S::Alpha]));
    c.sampler.min_filter = Filter::LinearMipmapLinear;
    assert_eq!(readings(&c, core), vec![(Channel::GATHER, None)]);
    assert_eq!(judge(&c, core, [0.0; 4]), Judgement::Strictest);
    assert_eq!(judge(&c, core, [1.0; 4]), Judgement::Outside);
}

#[test]
fn class2_swizzle_on_fixed_function_and_glsl120() {
    // Compatibility §16.1: the source colour of Table 16.1 (by DEPTH_TEXTURE_MODE, §8.23.1: "The
    // resulting r is assigned to Rt, Lt, It, or At"), then the swizzle of §15.2.1 ("Cs[i] ... RED:
    // Cb[0], GREEN: Cb[1], BLUE: Cb[2], ALPHA: Ab, ZERO: 0, ONE: 1"). Dt 0.8, Dref 0.5, LEQUAL: r = 1.
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.sampler.swizzle = Some([S::Alpha, S::One, S::Red, S::Zero]);
    for api in [ApiPath::FixedFunction, ApiPath::Glsl120] {
        c.api = vec![api];
        // LUMINANCE (the initial mode): (r, r, r, 1) → (1, 1, r, 0).
        c.sampler.depth_texture_mode = None;
        assert_eq!(
            readings(&c, api),
            vec![([One, One, R, Zero], None)],
            "{api}"
        );
        assert_eq!(judge(&c, api, [1.0, 1.0, 1.0, 0.0]), Judgement::Strictest);
        // The unswizzled (r, r, r, 1) is a Fail: the swizzle is a "shall".
        assert_eq!(judge(&c, api, [1.0, 1.0, 1.0, 1.0]), Judgement::Outside);
        // ALPHA: (0, 0, 0, r) → (r, 1, 0, 0).
        c.sampler.depth_texture_mode = Some(DepthTextureMode::Alpha);
        assert_eq!(
            readings(&c, api),
            vec![([R, One, Zero, Zero], None)],
            "{api}"
        );
        // INTENSITY: (r, r, r, r) → (r, 1, r, 0).
        c.sampler.depth_texture_mode = Some(DepthTextureMode::Intensity);
        assert_eq!(readings(&c, api), vec![([R, One, R, Zero], None)], "{api}");
    }
    // A non-shadow read through fixed function: Table 16.1 on Dt the same way.
    c.api = vec![ApiPath::FixedFunction];
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Red);
    assert_eq!(
        readings(&c, ApiPath::FixedFunction),
        vec![([One, One, R, Zero], None)]
    );
    assert!((value(&c) - 0.8).abs() < 1e-6);
}

#[test]
fn class2_glsl130_shadow_swizzle_has_two_readings() {
    // §11.1.3.5: Cs[0] of the swizzled Cb = (Rt, 0, 0, 1); §8.23.1 + Table 16.1: Cb by
    // DEPTH_TEXTURE_MODE. Swizzle R = GREEN under LUMINANCE: Cb[1] = 0 by the first, r by the second.
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.api = vec![ApiPath::Glsl130];
    c.sampler.swizzle = Some([S::Green, S::Green, S::Blue, S::Alpha]);
    assert_eq!(
        readings(&c, ApiPath::Glsl130),
        vec![
            ([Zero, Unused, Unused, Unused], None),
            (
                [R, Unused, Unused, Unused],
                Some("compat-depth-cb".to_string())
            )
        ]
    );
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [0.0, 0.3, 0.3, 0.3]),
        Judgement::Strictest
    );
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [1.0, 0.0, 0.0, 1.0]),
        Judgement::Strictest
    );
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [0.5, 0.0, 0.0, 1.0]),
        Judgement::Outside
    );
    // Swizzle R = RED: both give r (ALPHA mode aside), one reading.
    c.sampler.swizzle = Some([S::Red, S::Green, S::Blue, S::Alpha]);
    assert_eq!(
        readings(&c, ApiPath::Glsl130),
        vec![([R, Unused, Unused, Unused], None)]
    );
}

#[test]
fn class3_compat_glsl130_non_shadow_depth_read_has_two_readings() {
    // A non-shadow texture(sampler2D) of a depth texture in a compatibility context. §11.1.3.5:
    // "Texture lookups involving textures with depth component data generate a texture base color
    // Cb either using depth data directly or by performing a comparison ... and expanding the
    // resulting value Rt to a color Cb = (Rt, 0, 0, 1)"; §8.23.1 / Table 16.1: by DEPTH_TEXTURE_MODE
    // (LUMINANCE initially: (r, r, r, 1)).
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.api = vec![ApiPath::Glsl130];
    c.sampler.compare_mode = CompareMode::None;
    assert_eq!(
        readings(&c, ApiPath::Glsl130),
        vec![
            ([R, R, R, One], None),
            ([R, Zero, Zero, One], Some("compat-depth-cb".to_string()))
        ]
    );
    let dt = (0.8f64 * 16777215.0).round() / 16777215.0;
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [dt, dt, dt, 1.0]),
        Judgement::Strictest
    );
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [dt, 0.0, 0.0, 1.0]),
        Judgement::Strictest
    );
    assert_eq!(
        judge(&c, ApiPath::Glsl130, [dt, dt, 0.0, 1.0]),
        Judgement::Outside
    );
    // RED: the two readings coincide.
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Red);
    assert_eq!(
        readings(&c, ApiPath::Glsl130),
        vec![([R, Zero, Zero, One], None)]
    );
}

/// A 4x4 rectangle D24 texture of 0.8 sampled at (5.5, 1.5) (outside, past the right edge) with
/// Dref 0.5 LEQUAL: every texel passes.
fn rect_with_object(object_wrap: Wrap, object_min: Filter) -> Case {
    let mut c = case2d(
        Spec::Gl46,
        Format::D24,
        CompareFunc::Lequal,
        Filter::Nearest,
        4,
        4,
        &[0.8; 16],
        (5.5, 1.5),
        0.5,
    );
    c.texture.target = Target::Rect;
    c.sampler.wrap_s = Wrap::ClampToEdge;
    c.sampler.wrap_t = Wrap::ClampToEdge;
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.wrap_s = object_wrap;
    o.min_filter = object_min;
    c.sampler.sampler_object = Some(o);
    c
}

#[test]
fn class4_sampler_object_state_a_rectangle_texture_refuses_makes_it_incomplete() {
    // GL 4.6 §8.2: "If state is present in a sampler object bound to a texture unit that would have
    // been rejected by a call to TexParameter* for the texture bound to that unit, the behavior of
    // the implementation is as if the texture were incomplete. For example, if TEXTURE_WRAP_S or
    // TEXTURE_WRAP_T is set to REPEAT, MIRRORED_REPEAT, or MIRROR_CLAMP_TO_EDGE on the sampler
    // object bound to a texture unit and the texture bound to that unit is a rectangle texture, the
    // texture will be considered incomplete." §11.1.3.5: 0 for a shadow sampler.
    for w in [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::MirrorClampToEdge] {
        let c = rect_with_object(w, Filter::Nearest);
        let ev = evaluate(&c).unwrap_or_else(|e| panic!("{w}: no GL error, but {e}"));
        assert_eq!(ev.expect.spec_value, Some(0.0), "{w}");
        assert!(
            ev.steps
                .iter()
                .any(|s| s.what.contains("§8.2") && s.what.contains("incomplete")),
            "{w}"
        );
    }
    // A mipmap minification filter on the sampler object (§8.10: "TEXTURE_MIN_FILTER is set to a
    // value other than NEAREST or LINEAR"): incomplete as well.
    let c = rect_with_object(Wrap::ClampToEdge, Filter::NearestMipmapNearest);
    assert_eq!(value(&c), 0.0);
    // Legal state on the sampler object: the lookup is made (CLAMP_TO_EDGE, texel 0.8 passes).
    let c = rect_with_object(Wrap::ClampToEdge, Filter::Nearest);
    assert_eq!(value(&c), 1.0);
    // The same REPEAT on the texture itself is TexParameter's INVALID_ENUM, not an incomplete lookup.
    let mut c = rect_with_object(Wrap::ClampToEdge, Filter::Nearest);
    c.sampler.sampler_object = None;
    c.sampler.wrap_s = Wrap::Repeat;
    assert!(matches!(
        evaluate(&c),
        Err(OracleError::GlError { error, .. }) if error == "INVALID_ENUM"
    ));
}

#[test]
fn class6_gather_footprint_tolerance_is_the_weight_precision() {
    // The strict tier's coordinates are exact for texel selection, but a gather's 2x2 block follows
    // the LINEAR rule's i0 = ⌊u − ½⌋ (§8.14.2), computed at the precision of its weights α, β:
    // within 2^-8 texel of a block boundary either block is accepted (oracle/README.md tier table).
    let vals: Vec<f64> = (0..16).map(|i| i as f64 / 16.0).collect();
    let at = |s: f64| {
        let mut c = case2d(
            Spec::Gl46,
            Format::D32f,
            CompareFunc::Lequal,
            Filter::Nearest,
            4,
            4,
            &vals,
            (s, 0.5625),
            0.3,
        );
        c.lookup.gather = Some(Gather { offsets: None });
        eval(&c).expect
    };
    // u = 4s; the boundary between blocks i0 = 0 and i0 = 1 is at u = 1.5 (s = 0.375).
    let near = at(0.375 + 0.5 / 256.0 / 4.0);
    let g = near.gather.as_ref().expect("gather sets");
    let strict0 = g[0].get(&Profile::Strict).expect("strict");
    // τi0j1 is (0,2) = 8/16 or (1,2) = 9/16 — both pass Dref 0.3; τi0j0 (0,1) = 4/16 fails, (1,1)
    // = 5/16 passes: the A component accepts both outcomes within 2^-8 texel of the boundary.
    assert!(strict0.contains(1.0));
    let a = g[3].get(&Profile::Strict).expect("strict");
    assert!(a.contains(0.0) && a.contains(1.0), "{a}");
    // Well inside a block (a quarter texel away): one block, one outcome.
    let inside = at(0.375 + 0.25 / 4.0);
    let a = inside.gather.as_ref().expect("gather sets")[3]
        .get(&Profile::Strict)
        .expect("strict")
        .clone();
    assert!(a.contains(1.0) && !a.contains(0.0), "{a}");
}
