//! The texture unit's state beside the texture and its compare mode: texture swizzle (GL 4.6 §15.2.1, §11.1.3.5), the
//! TEXTURE_CUBE_MAP_SEAMLESS enable (§8.13.1) and bound sampler objects (§8.17.1, §8.2).

mod common;
use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::{evaluate, OracleError};
use Channel::{One, Unused, Zero, R};
use Swizzle as S;

fn layout(c: &Case, api: ApiPath) -> [Channel; 4] {
    let e = eval(c).expect;
    *e.layout
        .get(&api)
        .unwrap_or_else(|| panic!("no layout on {api}"))
}

fn not_applicable(c: &Case) -> bool {
    matches!(evaluate(c), Err(OracleError::NotApplicable { .. }))
}

#[test]
fn swizzle_follows_the_comparison() {
    // §11.1.3.5: "expanding the resulting value Rt to a color Cb = (Rt, 0, 0, 1). In either case,
    // swizzling of Cb is then performed as described above, but only the first component Cs[0] is
    // returned to the shader." Dt 0.8, Dref 0.5, LEQUAL: Rt = 1.
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.sampler.swizzle = Some([S::Zero, S::Green, S::Blue, S::Alpha]);
    assert_eq!(
        layout(&c, ApiPath::GlslCore),
        [Zero, Unused, Unused, Unused]
    );
    c.sampler.swizzle = Some([S::Alpha, S::Red, S::Red, S::Red]);
    assert_eq!(layout(&c, ApiPath::GlslCore), [One, Unused, Unused, Unused]);
    c.sampler.swizzle = Some([S::Red, S::Zero, S::Zero, S::Zero]);
    assert_eq!(layout(&c, ApiPath::GlslCore), [R, Unused, Unused, Unused]);
    // r is still the comparison's: the swizzle is applied after it, not to Dt.
    assert_eq!(value(&c), 1.0);
    let mut es = c.clone();
    (es.spec, es.api) = (Spec::Gles32, vec![ApiPath::Es300]);
    es.sampler.swizzle = Some([S::One, S::Red, S::Red, S::Red]);
    assert_eq!(layout(&es, ApiPath::Es300), [One, Unused, Unused, Unused]);
}

#[test]
fn swizzle_of_non_shadow_reads_and_depth_texture_mode() {
    // §15.2.1: Cs[i] from Cb = (Dt, 0, 0, 1) by TEXTURE_SWIZZLE_R/G/B/A.
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.sampler.compare_mode = CompareMode::None;
    c.sampler.swizzle = Some([S::Green, S::Red, S::Alpha, S::Blue]);
    assert_eq!(layout(&c, ApiPath::GlslCore), [Zero, R, One, Zero]);
    // Compatibility GLSL 1.30: Cb by DEPTH_TEXTURE_MODE (INTENSITY: (r,r,r,r)), then the swizzle.
    c.api = vec![ApiPath::Glsl130];
    c.sampler.depth_texture_mode = Some(DepthTextureMode::Intensity);
    c.sampler.swizzle = Some([S::Alpha, S::Zero, S::One, S::Red]);
    assert_eq!(layout(&c, ApiPath::Glsl130), [R, Zero, One, R]);
}

#[test]
fn swizzle_only_where_it_exists() {
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.sampler.swizzle = Some([S::One, S::Green, S::Blue, S::Alpha]);
    // ARB fragment programs: their texture-access text is outside the pack.
    c.api = vec![ApiPath::ArbFp];
    assert!(not_applicable(&c), "ARB fp is not a modelled swizzle path");
    // Fixed function (compatibility §16.1) and GLSL 1.30 shadow lookups are modelled (their
    // readings: oracle/tests/audit_round2.rs).
    for api in [ApiPath::FixedFunction, ApiPath::Glsl120, ApiPath::Glsl130] {
        c.api = vec![api];
        assert!(!not_applicable(&c), "{api} has a swizzle");
    }
    let mut e = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 0.8);
    e.sampler.swizzle = Some([S::One, S::Green, S::Blue, S::Alpha]);
    assert!(not_applicable(&e), "ES 2.0 has no swizzle");
    let mut a = one(Spec::Arb, Format::D16, CompareFunc::Lequal, 0.5, 0.8);
    a.sampler.swizzle = Some([S::One, S::Green, S::Blue, S::Alpha]);
    a.api = vec![ApiPath::FixedFunction];
    assert!(not_applicable(&a), "ARB_shadow (GL 1.4) has no swizzle");
}

/// A 2x2 cube: +X holds 0 (fails at Dref 0.5), +Z holds 1 (passes); LINEAR near their edge.
fn cube_edge(spec: Spec) -> Case {
    let mut c = one(spec, Format::D16, CompareFunc::Lequal, 0.5, 0.0);
    let mut vals = vec![0.0; 24];
    vals[16..20].fill(1.0);
    c.texture.target = Target::Cube;
    c.texture.levels[0] = Level {
        width: 2,
        height: 2,
        layers: 6,
        depth: texels(Format::D16, &vals),
        stencil: None,
    };
    c.sampler = Sampler::new(CompareMode::Compare, CompareFunc::Lequal, Filter::Linear);
    // +X at s = 0.05: u − ½ = −0.4, i0 = −1 (past the +Z edge), α = 0.6.
    c.lookup.coord = [1.0, 0.0, 0.9, 1.0];
    c
}

#[test]
fn seamless_enable_switches_the_cube_rule() {
    // §8.13.1: "When seamless cube map filtering is enabled ... If a texture sample location would
    // lie in the texture border in either u or v, instead select the corresponding texel from the
    // appropriate neighboring face." "Initially, it is disabled."
    let mut c = cube_edge(Spec::Gl46);
    assert_eq!(value(&c), 0.0);
    c.sampler.seamless = Some(false);
    assert_eq!(value(&c), 0.0);
    c.sampler.seamless = Some(true);
    assert!((value(&c) - 0.4).abs() < 1e-6, "{}", value(&c));
    // Wrap modes are ignored while seamless: REPEAT gives the same r.
    c.sampler.wrap_s = Wrap::Repeat;
    assert!((value(&c) - 0.4).abs() < 1e-6);
    // ES: always seamless, and there is no enable to set.
    let mut es = cube_edge(Spec::Gles32);
    es.api = vec![ApiPath::Es300];
    assert!((value(&es) - 0.4).abs() < 1e-6);
    es.sampler.seamless = Some(true);
    assert!(not_applicable(&es));
}

#[test]
fn a_bound_sampler_object_replaces_the_sampling_state() {
    // §8.17.1: "the sampling state for that unit is taken from the sampler object".
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    assert_eq!(value(&c), 1.0);
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Greater;
    c.sampler.sampler_object = Some(o.clone());
    assert_eq!(value(&c), 0.0);
    // Compare mode NONE on the sampler object: r = Dt (a non-shadow read).
    o.compare_mode = CompareMode::None;
    c.sampler.sampler_object = Some(o);
    let v = value(&c);
    assert!((v - 0.8).abs() < 1e-6, "{v}");
    assert_eq!(layout(&c, ApiPath::GlslCore), [R, Zero, Zero, One]);
}

#[test]
fn es_depth_completeness_reads_the_sampler_objects_compare_mode() {
    // ES 3.2 §8.17: a sized depth texture is incomplete if "the value of TEXTURE_COMPARE_MODE is
    // NONE" with non-NEAREST filtering; with a sampler object bound, that is the sampler's state.
    let mut c = one(Spec::Gles32, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    c.api = vec![ApiPath::Es300];
    c.sampler.compare_mode = CompareMode::None;
    (c.sampler.min_filter, c.sampler.mag_filter) = (Filter::Linear, Filter::Linear);
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_mode = CompareMode::Compare;
    c.sampler.sampler_object = Some(o.clone());
    assert_eq!(value(&c), 1.0, "complete: the sampler object compares");
    // The reverse: the texture compares, the sampler object does not: incomplete, (0,0,0,1).
    c.sampler.compare_mode = CompareMode::Compare;
    o.compare_mode = CompareMode::None;
    c.sampler.sampler_object = Some(o);
    assert_eq!(value(&c), 0.0);
    assert_eq!(layout(&c, ApiPath::Es300), [R, Zero, Zero, One]);
}

#[test]
fn texture_state_stays_on_the_texture() {
    // §8.2: state "not listed here and in the sampler state in table 23.18 is not part of the
    // sampler state, and remains in the texture object": the swizzle applies with a sampler bound.
    let mut c = one(Spec::Gl46, Format::D24, CompareFunc::Lequal, 0.5, 0.8);
    let mut o = SamplerObject::from_sampler(&c.sampler);
    o.compare_func = CompareFunc::Gequal;
    c.sampler.sampler_object = Some(o);
    c.sampler.swizzle = Some([S::One, S::Red, S::Zero, S::Red]);
    assert_eq!(layout(&c, ApiPath::GlslCore), [One, Unused, Unused, Unused]);
    assert_eq!(value(&c), 0.0);
    let mut es2 = one(Spec::Es2Ext, Format::D16, CompareFunc::Lequal, 0.5, 0.8);
    es2.sampler.sampler_object = Some(SamplerObject::from_sampler(&es2.sampler));
    assert!(not_applicable(&es2), "ES 2.0 has no sampler objects");
}
