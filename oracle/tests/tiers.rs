//! The tiers by normative force (`oracle/src/profile.rs`), on worked examples: inside `strict` (what the
//! "shall" sentences fix) a Pass, inside `quality` only (what the "should" sentences leave open) a
//! Warn, outside both a Fail.

mod common;
use common::*;
use shadowcheck_model::*;

#[derive(Debug, PartialEq)]
enum Tier {
    Pass,
    Warn,
    Fail,
}

/// The tier an observed r earns: the first profile (strictest first) whose set holds it.
fn tier(c: &Case, r: f64) -> Tier {
    let e = eval(c);
    match Profile::ALL
        .iter()
        .position(|p| e.expect.accept[p].contains(r))
    {
        Some(0) => Tier::Pass,
        Some(_) => Tier::Warn,
        None => Tier::Fail,
    }
}

/// A 2x2 LINEAR (PCF) lookup at the centre: every texel weighs 1/4.
fn pcf(func: CompareFunc, vals: &[f64]) -> Case {
    case2d(
        Spec::Gl46,
        Format::D16,
        func,
        Filter::Linear,
        2,
        2,
        vals,
        (0.5, 0.5),
        0.5,
    )
}

/// GL 4.6 §8.23.1 (ES 3.2 §8.20.1): "The details of this are implementation-dependent, but r should be
/// a value in the range [0, 1] which is proportional to the number of comparison passes or
/// failures." The weights are a "should" (Warn when off); [0, 1] and a zero count are not.
#[test]
fn a_footprint_with_passes_and_fails_may_return_any_value_in_fail_to_one_as_a_warning() {
    // LEQUAL with Dref 0.5: the two texels at 0.8 pass, the two at 0.2 fail.
    let c = pcf(CompareFunc::Lequal, &[0.2, 0.8, 0.2, 0.8]);
    assert_eq!(value(&c), 0.5);
    assert_eq!(tier(&c, 0.5), Tier::Pass);
    // Inside [fail value, 1], outside the strict bilinear weights (±2^-8).
    assert_eq!(tier(&c, 0.3), Tier::Warn);
    // Compare-after-filter (Mesa softpipe, reports/README.md cause 3): one comparison of the
    // filtered Dt 0.5 with Dref 0.5 gives 1.
    assert_eq!(tier(&c, 1.0), Tier::Warn);
    assert_eq!(tier(&c, 0.0), Tier::Warn);
    // Outside [0, 1]: not "a value in the range [0, 1]".
    assert_eq!(tier(&c, 1.2), Tier::Fail);
    assert_eq!(tier(&c, -0.1), Tier::Fail);
}

/// Zero passes are zero whatever the proportion; zero failures likewise (the same sentence). Tables
/// 8.22/8.23 give "ALWAYS 1.0" and "NEVER 0.0" for every texel, so their footprints never mix.
#[test]
fn a_footprint_with_no_pass_or_no_fail_stays_exact_under_quality() {
    let none_pass = pcf(CompareFunc::Lequal, &[0.2, 0.2, 0.2, 0.2]);
    assert_eq!(tier(&none_pass, 0.0), Tier::Pass);
    assert_eq!(tier(&none_pass, 0.1), Tier::Fail);
    let none_fail = pcf(CompareFunc::Lequal, &[0.8, 0.8, 0.8, 0.8]);
    assert_eq!(tier(&none_fail, 1.0), Tier::Pass);
    assert_eq!(tier(&none_fail, 0.9), Tier::Fail);
    for (func, want) in [(CompareFunc::Never, 0.0), (CompareFunc::Always, 1.0)] {
        let c = pcf(func, &[0.2, 0.8, 0.2, 0.8]);
        assert_eq!(tier(&c, want), Tier::Pass, "{func}");
        assert_eq!(tier(&c, 0.5), Tier::Fail, "{func}");
    }
}

/// A 2x2 + 1x1 mipmapped GL 4.6 D16 texture with level 0 holding `l0` and level 1 `l1`, looked up
/// with λ_base = `lod` under `filter`.
fn mipmapped(mode: CompareMode, filter: Filter, l0: f64, l1: f64, lod: f64) -> Case {
    let mut c = case2d(
        Spec::Gl46,
        Format::D16,
        CompareFunc::Lequal,
        filter,
        2,
        2,
        &[l0; 4],
        (0.5, 0.5),
        0.5,
    );
    c.sampler = Sampler::new(mode, CompareFunc::Lequal, filter);
    c.texture.levels.push(Level {
        width: 1,
        height: 1,
        layers: 1,
        depth: texels(Format::D16, &[l1]),
        stencil: None,
    });
    c.lookup.lod = lod;
    c
}

/// GL 4.6 §8.14.1 gives λ with no tolerance for its log2 (only ρ "may" be approximated); dEQP's
/// low-quality tier allows lodBits 4. The quality tier takes λ within 2^-4 of the exact value: a
/// Warn; further off, a Fail.
#[test]
fn lambda_within_two_to_the_minus_four_is_a_warning_beyond_a_failure() {
    // Depth read (r = Dt) blending level 0 (0.0) and level 1 (1.0) with frac(λ): r = λ.
    let lod = 0.25;
    let c = mipmapped(
        CompareMode::None,
        Filter::NearestMipmapLinear,
        0.0,
        1.0,
        lod,
    );
    assert_eq!(value(&c), lod);
    assert_eq!(tier(&c, lod), Tier::Pass);
    assert_eq!(tier(&c, lod + 2f64.powi(-5)), Tier::Warn);
    assert_eq!(tier(&c, lod - 2f64.powi(-5)), Tier::Warn);
    assert_eq!(tier(&c, lod + 2f64.powi(-3)), Tier::Fail);
    // Level selection (NEAREST_MIPMAP_NEAREST, not a multi-texel filter state): level 0 passes,
    // level 1 fails; d = 0 while λ <= 1/2 (§8.14.3).
    let near = |off: f64| {
        mipmapped(
            CompareMode::Compare,
            Filter::NearestMipmapNearest,
            0.8,
            0.2,
            0.5 - off + 2f64.powi(-7),
        )
    };
    let c = near(2f64.powi(-5));
    assert_eq!(value(&c), 1.0);
    assert_eq!(tier(&c, 0.0), Tier::Warn, "level 1 with λ off by 2^-5");
    let c = near(2f64.powi(-3));
    assert_eq!(value(&c), 1.0);
    assert_eq!(tier(&c, 0.0), Tier::Fail, "level 1 with λ off by 2^-3");
}
