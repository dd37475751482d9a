//! Shadow textureGather (GL 4.6 / ES 3.2 §8.14.2, GLSL 4.60 §8.9.4): "The rules for the LINEAR
//! minification filter are applied to identify the four selected texels ... in the order τi0j1,
//! τi1j1, τi1j0, and τi0j0"; "each of the four texel lookups perform a depth comparison against the
//! depth reference value passed in (refZ)".

mod common;

use common::*;
use shadowcheck_model::*;
use shadowcheck_oracle::evaluate;

/// A 4x4 D32F texture whose texel (x, y) holds (4y + x) / 16, gathered at (s, t) with `dref`.
fn gather_case(st: (f64, f64), dref: f64, filter: Filter) -> Case {
    let vals: Vec<f64> = (0..16).map(|i| i as f64 / 16.0).collect();
    let mut c = case2d(
        Spec::Gl46,
        Format::D32f,
        CompareFunc::Lequal,
        filter,
        4,
        4,
        &vals,
        st,
        dref,
    );
    c.lookup.gather = Some(Gather { offsets: None });
    c
}

/// The strict points of the four components.
fn strict(c: &Case) -> [Vec<Interval>; 4] {
    let e = eval(c).expect;
    let g = e.gather.expect("a gather expectation");
    g.map(|m| m.get(&Profile::Strict).expect("strict").0.clone())
}

fn points(v: [f64; 4]) -> [Vec<Interval>; 4] {
    v.map(|x| vec![Interval::point(x)])
}

#[test]
fn four_comparisons_in_the_order_i0j1_i1j1_i1j0_i0j0() {
    // u = 4·0.3125 = 1.25 → i0 = ⌊0.75⌋ = 0, i1 = 1; v = 4·0.5625 = 2.25 → j0 = 1, j1 = 2.
    // Texels: (0,2) = 8/16, (1,2) = 9/16, (1,1) = 5/16, (0,1) = 4/16. LEQUAL passes when
    // Dref <= Dt: with Dref = 6/16 + 1/32 only the j1 row passes.
    let c = gather_case((0.3125, 0.5625), 6.5 / 16.0, Filter::Nearest);
    assert_eq!(strict(&c), points([1.0, 1.0, 0.0, 0.0]));
    let e = eval(&c).expect;
    assert_eq!(
        e.layout.get(&ApiPath::GlslCore),
        Some(&Channel::GATHER),
        "gather results fill all four channels"
    );
    // With Dref between τi0j0 (4/16) and τi1j0 (5/16): R, G, B pass, A fails.
    let c = gather_case((0.3125, 0.5625), 4.5 / 16.0, Filter::Nearest);
    assert_eq!(strict(&c), points([1.0, 1.0, 1.0, 0.0]));
}

#[test]
fn filters_and_level_of_detail_are_ignored() {
    // "the minification and magnification filters are ignored": NEAREST and LINEAR sampler
    // state give the same four comparisons, and a λ that would pick level 1 still gathers level base.
    let a = gather_case((0.3125, 0.5625), 4.5 / 16.0, Filter::Nearest);
    let mut b = gather_case((0.3125, 0.5625), 4.5 / 16.0, Filter::LinearMipmapLinear);
    b.texture.levels.push(Level {
        width: 2,
        height: 2,
        layers: 1,
        depth: Texels::Float(vec![0.0; 4]),
        stencil: None,
    });
    b.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: Texels::Float(vec![0.0]),
        stencil: None,
    });
    b.lookup.lod = 1.0;
    assert_eq!(strict(&a), strict(&b));
}

#[test]
fn wraps_apply_per_texel() {
    // s = 0.0625 → u = 0.25, i0 = wrap(−1): REPEAT gives 3, CLAMP_TO_EDGE gives 0.
    let mut c = gather_case((0.0625, 0.5625), 2.5 / 16.0, Filter::Nearest);
    c.sampler.wrap_s = Wrap::ClampToEdge;
    // i0 = i1 = 0 after clamping: j1 row texel (0,2) = 8/16 passes, j0 row (0,1) = 4/16 passes too.
    assert_eq!(strict(&c), points([1.0, 1.0, 1.0, 1.0]));
    c.sampler.wrap_s = Wrap::Repeat;
    // i0 = 3: (3,2) = 11/16, (0,2) = 8/16, (0,1) = 4/16, (3,1) = 7/16 all >= 2.5/16.
    let c2 = {
        let mut x = c.clone();
        x.lookup.dref = 7.5 / 16.0;
        x
    };
    // Dref 7.5/16: (3,2) 11 pass, (0,2) 8 pass, (0,1) 4 fail, (3,1) 7 fail.
    assert_eq!(strict(&c2), points([1.0, 1.0, 0.0, 0.0]));
    c.sampler.wrap_s = Wrap::ClampToBorder;
    c.sampler.border = [1.0, 0.0, 0.0, 0.0];
    // Border texel i0 = −1 has Dt = 1: passes; (0,2) passes, (0,1) = 4/16 with Dref 5/16 fails.
    c.lookup.dref = 5.0 / 16.0;
    assert_eq!(strict(&c), points([1.0, 1.0, 0.0, 1.0]));
}

#[test]
fn gather_offsets_take_i0j0_of_each_footprint() {
    // Offsets (0,1), (1,1), (1,0), (0,0) reproduce the plain gather's texels.
    let plain = gather_case((0.3125, 0.5625), 6.5 / 16.0, Filter::Nearest);
    let mut o = plain.clone();
    o.lookup.gather = Some(Gather {
        offsets: Some([[0, 1], [1, 1], [1, 0], [0, 0]]),
    });
    assert_eq!(strict(&plain), strict(&o));
    // All four offsets (0,1): every component is τ(0,2) = 8/16 → pass.
    o.lookup.gather = Some(Gather {
        offsets: Some([[0, 1]; 4]),
    });
    assert_eq!(strict(&o), points([1.0; 4]));
    // textureGatherOffset: the whole footprint moves by (δu, δv) = (2, 0).
    let mut one = plain.clone();
    one.lookup.offset = [2, 0, 0];
    // i0 = 2, i1 = 3, j0 = 1, j1 = 2: (2,2) = 10, (3,2) = 11, (3,1) = 7, (2,1) = 6; Dref 6.5 → 1,1,1,0.
    assert_eq!(strict(&one), points([1.0, 1.0, 1.0, 0.0]));
}

#[test]
fn near_ties_and_footprint_boundaries_accept_both() {
    // u − 1/2 exactly an integer: a footprint boundary; strict's weight tolerance lets either
    // block be gathered, so components that differ between the blocks accept both results.
    let c = gather_case((0.375, 0.625), 6.5 / 16.0, Filter::Nearest);
    let s = strict(&c);
    assert!(
        s.iter().any(|v| v.len() == 2),
        "a boundary leaves some component open: {s:?}"
    );
    assert!(eval(&c).expect.implementation_defined.is_some());
}

#[test]
fn gather_is_refused_where_no_shadow_gather_exists() {
    let mut c = gather_case((0.3125, 0.5625), 0.5, Filter::Nearest);
    c.api = vec![ApiPath::Glsl130];
    assert!(evaluate(&c).is_err(), "GLSL 1.30 has no textureGather");
    let mut c = gather_case((0.3125, 0.5625), 0.5, Filter::Nearest);
    c.sampler.compare_mode = CompareMode::None;
    assert!(
        evaluate(&c).is_err(),
        "non-shadow gather is outside the model"
    );
    let mut c = gather_case((0.3125, 0.5625), 0.5, Filter::Nearest);
    c.lookup.offset = [8, 0, 0];
    assert!(evaluate(&c).is_err(), "offset past the spec minimum range");
}
