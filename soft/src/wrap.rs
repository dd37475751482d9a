//! Coordinate wrapping and texel selection (GL 4.6 §8.14.2, Table 8.20; ES 3.2 Table 8.21).
//!
//! Wrapping works on integer texel locations: NEAREST uses i = wrap(⌊u′⌋); LINEAR uses
//! i0 = wrap(⌊u′ − ½⌋), i1 = wrap(⌊u′ − ½⌋ + 1), α = frac(u′ − ½). A wrapped location outside
//! [0, size) (only CLAMP_TO_BORDER and legacy CLAMP produce one) selects the border texel.

use crate::faults::{Fault, Faults};
use shadowcheck_model::Wrap;

/// Float → integer texel location: ⌊x⌋ saturated into i64 (NaN → 0, ±inf → the i64 limits), so
/// that absurd coordinates stay deterministic.
///
/// Computed from the truncating conversion rather than `f32::floor`, which is a libm call on
/// the baseline x86-64 target (no SSE4.1 `roundss`) and dominated the lookup profile.
#[inline(always)]
pub fn floor_i64(x: f32) -> i64 {
    let i = x as i64; // truncates toward zero; saturates; NaN -> 0
                      // A negative non-integer truncated upward. (|x| >= 2^23 is already an integer, so the
                      // conversion back is exact whenever this comparison matters.)
    if (i as f32) > x {
        i.saturating_sub(1)
    } else {
        i
    }
}

/// (⌊x⌋, frac(x)) with frac in [0, 1); frac is 0 for non-finite or out-of-i64-range x.
#[inline(always)]
pub fn floor_frac(x: f32) -> (i64, f32) {
    let i = floor_i64(x);
    let f = x - i as f32;
    (i, if (0.0..1.0).contains(&f) { f } else { 0.0 })
}

/// mirror(a) of Table 8.20: a if a ≥ 0, −(1 + a) otherwise.
#[inline(always)]
pub fn mirror(a: i64) -> i64 {
    if a >= 0 {
        a
    } else {
        -(1 + a)
    }
}

/// wrap(coord) of Table 8.20 for an integer texel location. `linear` tells legacy CLAMP which
/// row applies (compatibility profile: clamp(coord, 0, size−1) for NEAREST, clamp(coord, −1, size)
/// for LINEAR). The result is in [0, size) or, for border modes, −1 / size (a border texel).
#[inline]
pub fn wrap(mode: Wrap, coord: i64, size: i64, linear: bool, faults: Faults) -> i64 {
    match mode {
        Wrap::ClampToEdge => coord.clamp(0, size - 1),
        Wrap::ClampToBorder => {
            if faults.has(Fault::BorderIgnored) {
                coord.clamp(0, size - 1)
            } else {
                coord.clamp(-1, size)
            }
        }
        Wrap::Clamp => {
            if linear && !faults.has(Fault::BorderIgnored) {
                coord.clamp(-1, size)
            } else {
                coord.clamp(0, size - 1)
            }
        }
        Wrap::Repeat => {
            if size & (size - 1) == 0 {
                // Power of two: two's-complement masking is the Euclidean remainder, without a division.
                coord & (size - 1)
            } else {
                coord.rem_euclid(size)
            }
        }
        Wrap::MirroredRepeat => {
            // ES 3.2 Table 8.21 (the GL 4.6 row is misprinted): (size−1) − mirror(fmod(coord, 2·size) − size).
            let m = coord.rem_euclid(2 * size) - size;
            if faults.has(Fault::MirroredRepeatOffByOne) {
                ((size - 1) - m.abs()).clamp(0, size - 1)
            } else {
                (size - 1) - mirror(m)
            }
        }
        Wrap::MirrorClampToEdge => mirror(coord).clamp(0, size - 1),
    }
}

/// Legacy CLAMP clamps the coordinate itself to [0, size] before texel selection (compatibility
/// profile §8.14.2: u′ = clamp(u, 0, w_s) when the wrap mode is CLAMP); other modes leave u′ = u.
#[inline(always)]
pub fn pre_clamp(mode: Wrap, u: f32, size: f32) -> f32 {
    if mode == Wrap::Clamp {
        u.max(0.0).min(size)
    } else {
        u
    }
}

/// NEAREST texel location along one axis: wrap(⌊u′⌋).
#[inline(always)]
pub fn nearest(mode: Wrap, u: f32, size: u32, faults: Faults) -> i64 {
    let u = pre_clamp(mode, u, size as f32);
    wrap(mode, floor_i64(u), size as i64, false, faults)
}

/// LINEAR footprint along one axis: (i0, i1, α). With [`Fault::PcfHalfTexelOff`] the −½ is
/// forgotten.
#[inline(always)]
pub fn linear(mode: Wrap, u: f32, size: u32, faults: Faults) -> (i64, i64, f32) {
    let u = pre_clamp(mode, u, size as f32);
    let a = if faults.has(Fault::PcfHalfTexelOff) {
        u
    } else {
        u - 0.5
    };
    let (i, alpha) = floor_frac(a);
    let s = size as i64;
    (
        wrap(mode, i, s, true, faults),
        wrap(mode, i.saturating_add(1), s, true, faults),
        alpha,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    const F: Faults = Faults::NONE;

    #[test]
    fn table_8_20_rows() {
        // size 4: CLAMP_TO_EDGE clamps to [0,3]; CLAMP_TO_BORDER to [-1,4]; REPEAT is mod 4.
        assert_eq!(wrap(Wrap::ClampToEdge, -3, 4, false, F), 0);
        assert_eq!(wrap(Wrap::ClampToEdge, 9, 4, false, F), 3);
        assert_eq!(wrap(Wrap::ClampToBorder, -3, 4, false, F), -1);
        assert_eq!(wrap(Wrap::ClampToBorder, 9, 4, false, F), 4);
        assert_eq!(wrap(Wrap::Repeat, -1, 4, false, F), 3);
        assert_eq!(wrap(Wrap::Repeat, 9, 4, false, F), 1);
        // MIRRORED_REPEAT over 2*size = 8: 0 1 2 3 3 2 1 0, and -1 -> 0, -2 -> 1.
        let m: Vec<i64> = (-2..10)
            .map(|c| wrap(Wrap::MirroredRepeat, c, 4, false, F))
            .collect();
        assert_eq!(m, vec![1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1]);
        // MIRROR_CLAMP_TO_EDGE: clamp(mirror(c), 0, 3): -1 -> 0, -3 -> 2, -9 -> 3.
        let m: Vec<i64> = [-9, -3, -1, 0, 2, 7]
            .iter()
            .map(|&c| wrap(Wrap::MirrorClampToEdge, c, 4, false, F))
            .collect();
        assert_eq!(m, vec![3, 2, 0, 0, 2, 3]);
    }

    #[test]
    fn legacy_clamp_depends_on_filter() {
        assert_eq!(wrap(Wrap::Clamp, -1, 4, false, F), 0);
        assert_eq!(wrap(Wrap::Clamp, -1, 4, true, F), -1);
        // s = 1.0 on a 4-wide texture: u = 4, NEAREST picks texel 3, LINEAR blends 3 and border.
        assert_eq!(nearest(Wrap::Clamp, 4.0, 4, F), 3);
        assert_eq!(linear(Wrap::Clamp, 4.0, 4, F), (3, 4, 0.5));
        // s = 2.0 is first clamped to 1.0.
        assert_eq!(linear(Wrap::Clamp, 8.0, 4, F), (3, 4, 0.5));
    }

    #[test]
    fn linear_footprint_uses_u_minus_half() {
        // u = 1.75: u - 1/2 = 1.25 -> i0 = 1, i1 = 2, alpha = 0.25.
        assert_eq!(linear(Wrap::ClampToEdge, 1.75, 4, F), (1, 2, 0.25));
        // u = 0.25 at the left edge: floor(-0.25) = -1 -> clamped to 0 (edge), alpha = 0.75.
        assert_eq!(linear(Wrap::ClampToEdge, 0.25, 4, F), (0, 0, 0.75));
        assert_eq!(linear(Wrap::ClampToBorder, 0.25, 4, F), (-1, 0, 0.75));
        assert_eq!(linear(Wrap::Repeat, 0.25, 4, F), (3, 0, 0.75));
        // Texel centre: weight 0 on the second texel.
        assert_eq!(linear(Wrap::ClampToEdge, 2.5, 4, F), (2, 3, 0.0));
    }

    #[test]
    fn nearest_floors() {
        assert_eq!(nearest(Wrap::ClampToEdge, 1.999, 4, F), 1);
        assert_eq!(nearest(Wrap::ClampToEdge, 4.0, 4, F), 3);
        assert_eq!(nearest(Wrap::ClampToBorder, 4.0, 4, F), 4);
        assert_eq!(nearest(Wrap::Repeat, -0.5, 4, F), 3);
    }

    #[test]
    fn absurd_coordinates_stay_in_range() {
        for mode in Wrap::ALL {
            for u in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30, -1e30] {
                let i = nearest(*mode, u, 4, F);
                assert!((-1..=4).contains(&i), "{mode:?} {u} -> {i}");
                let (a, b, al) = linear(*mode, u, 4, F);
                assert!(
                    (-1..=4).contains(&a) && (-1..=4).contains(&b) && (0.0..1.0).contains(&al),
                    "{mode:?} {u}"
                );
            }
        }
    }

    #[test]
    fn fast_floor_matches_floor() {
        for x in [
            0.0f32, -0.0, 0.5, -0.5, 1.0, -1.0, 2.75, -2.75, 8388607.5, -8388607.5, 16777216.0,
            -1e20, 1e20, 3.4e38, -3.4e38,
        ] {
            assert_eq!(floor_i64(x), x.floor() as i64, "{x}");
        }
        assert_eq!(floor_i64(f32::NAN), 0);
        assert_eq!(floor_frac(-2.75), (-3, 0.25));
        assert_eq!(floor_frac(1e30).1, 0.0);
    }

    #[test]
    fn faults_change_wrapping() {
        let bi = Faults::NONE.with(Fault::BorderIgnored);
        assert_eq!(wrap(Wrap::ClampToBorder, -1, 4, true, bi), 0);
        let h = Faults::NONE.with(Fault::PcfHalfTexelOff);
        assert_eq!(linear(Wrap::ClampToEdge, 1.75, 4, h), (1, 2, 0.75));
    }
}
