//! Rules the oracle once encoded wrong: one test per rule, each quoting the sentence it encodes
//! (GL 4.6 / ES 3.2 §8.5.1 quoted from the specifications' PDF editions).

mod common;
use common::*;
use shadowcheck_model::*;

fn strict(c: &Case) -> Acceptance {
    eval(c).expect.accept[&Profile::Strict].clone()
}

/// GL 4.6 Table 8.23 (ES 3.2 Table 8.22): "ALWAYS r = 1.0", "NEVER r = 0.0", whatever Dt is, also
/// when the texel's value is left open (an out-of-range border on a fixed-point format: GL 4.6 §8.14.2
/// "the result is undefined"; a zero cube direction).
#[test]
fn always_and_never_are_exact_over_undefined_texels() {
    for (func, want) in [(CompareFunc::Always, 1.0), (CompareFunc::Never, 0.0)] {
        // An out-of-range border of a D24 texture: Dt undefined.
        let mut c = one(Spec::Gl46, Format::D24, func, 0.5, 0.5);
        c.sampler.wrap_s = Wrap::ClampToBorder;
        c.sampler.border = [1.5, 0.0, 0.0, 0.0];
        c.lookup.coord = [-0.5, 0.5, 0.0, 1.0];
        assert_eq!(strict(&c).0, vec![Interval::point(want)], "{func} border");
        // The same lookup with LEQUAL stays open.
        let mut l = c.clone();
        l.sampler.compare_func = CompareFunc::Lequal;
        let acc = strict(&l);
        assert!(acc.contains(0.0) && acc.contains(1.0));
        // A zero cube direction: the texel selection is undefined, the table is not.
        let mut z = one(Spec::Gles32, Format::D16, func, 0.5, 0.5);
        z.texture.target = Target::Cube;
        z.texture.levels[0].layers = 6;
        z.texture.levels[0].depth = texels(Format::D16, &[0.5; 6]);
        z.lookup.coord = [0.0, 0.0, 0.0, 1.0];
        assert_eq!(
            strict(&z).0,
            vec![Interval::point(want)],
            "{func} zero direction"
        );
    }
}

/// A 2D array of `layers` one-texel layers holding `vals`, looked up at layer coordinate `r`.
fn array(filter: Filter, vals: &[f64], r: f64) -> Case {
    let mut c = one(Spec::Gl46, Format::D16, CompareFunc::Lequal, 0.5, 0.0);
    c.sampler = Sampler::new(CompareMode::Compare, CompareFunc::Lequal, filter);
    c.texture.target = Target::T2dArray;
    c.texture.levels[0].layers = vals.len() as u32;
    c.texture.levels[0].depth = texels(Format::D16, vals);
    c.lookup.coord = [0.5, 0.5, r, 1.0];
    c
}

/// GL 4.6 §8.14.2, LINEAR: "For two-dimensional array textures, all texels are obtained from layer
/// l, where l = clamp(⌊r + 1/2⌋, 0, d_s − 1)". The RNE of the NEAREST formula and its footnote 4
/// ("Implementations may instead round the texture layer using the nearly equivalent computation
/// ⌊value + 1/2⌋") belong to NEAREST only.
#[test]
fn linear_array_layer_is_floor_r_plus_half() {
    // Layer 0 fails, layer 1 passes (Dref 0.5 LEQUAL).
    let lin = array(Filter::Linear, &[0.0, 1.0, 0.0], 0.5);
    assert_eq!(value(&lin), 1.0);
    assert_eq!(strict(&lin).0, vec![Interval::point(1.0)]);
    // NEAREST at the same tie: RNE(0.5) = 0 is the spec value, ⌊0.5 + 1/2⌋ = 1 accepted.
    let near = array(Filter::Nearest, &[0.0, 1.0, 0.0], 0.5);
    assert_eq!(value(&near), 0.0);
    let acc = strict(&near);
    assert!(acc.contains(0.0) && acc.contains(1.0));
    // 1D arrays: "l = clamp(⌊t + 1/2⌋, 0, h_s − 1)".
    let mut one_d = lin.clone();
    one_d.texture.target = Target::T1dArray;
    one_d.lookup.coord = [0.5, 0.5, 0.0, 1.0];
    assert_eq!(value(&one_d), 1.0);
}

/// GL 4.6 §8.23.1 (ES 3.2 §8.20.1): "If the value of TEXTURE_MAG_FILTER is not NEAREST, or the value
/// of TEXTURE_MIN_FILTER is not NEAREST or NEAREST_MIPMAP_NEAREST, then r may be computed by comparing
/// more than one depth texture value to the texture reference value." The filter *state* decides, not
/// the filter a lookup ends up using.
#[test]
fn multi_texel_allowance_follows_the_filter_state() {
    // 2x1 texture (fail, pass) read at the boundary between the two texels, minified (λ = 1) with
    // min NEAREST, mag LINEAR: NEAREST picks texel 1 (pass); PCF may mix both.
    let mut c = case2d(
        Spec::Gles32,
        Format::D16,
        CompareFunc::Lequal,
        Filter::Nearest,
        2,
        1,
        &[0.0, 1.0],
        (0.5, 0.5),
        0.5,
    );
    c.sampler.mag_filter = Filter::Linear;
    c.lookup.lod = 1.0;
    assert_eq!(value(&c), 1.0);
    let acc = strict(&c);
    assert!(acc.contains(0.5), "PCF value accepted: {acc:?}");
    assert!(eval(&c)
        .expect
        .implementation_defined
        .is_some_and(|n| n.contains("more than one depth texture value")));
    // All NEAREST: one texel only.
    c.sampler.mag_filter = Filter::Nearest;
    assert_eq!(strict(&c).0, vec![Interval::point(1.0)]);
}

/// GL 4.6 §2.3.5.1 (2.1): "f = c / (2^b − 1)" is exact: a NEAREST read of an R8 texel is c/255, not
/// its neighbours.
#[test]
fn r8_results_are_exact() {
    let mut c = one(Spec::Gles32, Format::R8, CompareFunc::Lequal, 0.5, 0.4);
    c.sampler.compare_mode = CompareMode::None;
    c.texture.levels[0].depth = Texels::Unorm(vec![102]);
    let acc = strict(&c);
    let v = 102.0 / 255.0;
    assert!(acc.contains(v));
    assert!(
        !acc.contains(101.0 / 255.0) && !acc.contains(103.0 / 255.0),
        "{acc:?}"
    );
    // The c/256 conversion bug is outside.
    assert!(!acc.contains(102.0 / 256.0));
}

/// GL 4.6 §8.5.1 and ES 3.2 §8.5.1: "Requesting one of these sized internal formats for any texture
/// type will allocate at least the internal component sizes, and exactly the component types shown
/// for that format" (DEPTH_COMPONENT16 is ticked "Req. format"; ES 3.2 Table 8.11: "minimum component
/// resolutions"). A D16 may be stored with 24 bits: near a tie, the outcome of either storage passes.
#[test]
fn d16_may_be_stored_with_more_bits() {
    // c = 1: Dt = 1/65535 in 16 bits; a 24-bit store holds 256/16777215 or 257/16777215.
    let dt16 = 1.0 / 65535.0;
    let below = (dt16 as f32).next_down_f64();
    let mut c = one(Spec::Gles32, Format::D16, CompareFunc::Less, below, dt16);
    c.texture.levels[0].depth = Texels::Unorm(vec![1]);
    assert_eq!(value(&c), 1.0, "16-bit storage: Dref < Dt");
    let acc = strict(&c);
    // 256/16777215 < Dref: a 24-bit store fails LESS.
    assert!((256.0 / 16777215.0) < below);
    assert!(acc.contains(0.0) && acc.contains(1.0), "{acc:?}");
    // Far from a tie the storage does not matter.
    let mut far = c.clone();
    far.lookup.dref = 0.5 / 65535.0;
    assert_eq!(strict(&far).0, vec![Interval::point(1.0)]);
}

trait NextDown {
    fn next_down_f64(self) -> f64;
}
impl NextDown for f32 {
    /// The f32 one step below, as f64.
    fn next_down_f64(self) -> f64 {
        f32::from_bits(self.to_bits() - 1) as f64
    }
}

/// EXT_shadow_samplers Table 3.X: "GREATER r = { 1.0, if D_ref > Dt { 0.0, if D_ref < Dt": nothing
/// at D_ref = Dt, so the result is open: either value, labelled implementation-defined.
#[test]
fn ext_shadow_samplers_greater_at_equality_is_open() {
    let e = eval(&one(
        Spec::Es2Ext,
        Format::D16,
        CompareFunc::Greater,
        1.0,
        1.0,
    ));
    assert_eq!(e.expect.spec_value, None);
    let acc = &e.expect.accept[&Profile::Strict];
    assert!(acc.contains(0.0) && acc.contains(1.0));
    assert!(e.expect.implementation_defined.is_some());
}
