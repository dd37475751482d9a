//! Exact values and the unorm <-> float conversions of GL 4.6 §2.3.5 (ES 3.2 §2.3.5 is the same text).
//!
//! A stored unorm depth is the rational c / (2^b - 1); it is kept as such ([`Exact::Q`]) so that a
//! comparison with the reference value is decided exactly, not after a rounding of our own.

use std::cmp::Ordering;

/// An exact real: a double that is exact as it stands (an f32, a clamped value, an f64 quotient that
/// we treat as the spec's real) or the rational c / m of a unorm texel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Exact {
    F(f64),
    Q { c: u64, m: u64 },
}

impl Exact {
    /// The nearest double (for display and for windows that are far wider than one ulp).
    pub fn approx(self) -> f64 {
        match self {
            Exact::F(v) => v,
            Exact::Q { c, m } => c as f64 / m as f64,
        }
    }

    /// Exact comparison of `x` with `self` (`x.partial_cmp(self)`); `None` when x is NaN.
    pub fn cmp_from(self, x: f64) -> Option<Ordering> {
        match self {
            Exact::F(v) => x.partial_cmp(&v),
            Exact::Q { c, m } => cmp_with_ratio(x, c, m),
        }
    }
}

/// Compares x with c/m exactly: the sign of x*m - c with x*m split into hi + lo (two-product).
fn cmp_with_ratio(x: f64, c: u64, m: u64) -> Option<Ordering> {
    if x.is_nan() {
        return None;
    }
    if x.is_infinite() {
        return Some(if x > 0.0 {
            Ordering::Greater
        } else {
            Ordering::Less
        });
    }
    let mf = m as f64; // m < 2^53: exact
    let hi = x * mf;
    let lo = x.mul_add(mf, -hi);
    // hi - c is exact when hi and c are close (Sterbenz); when they are not, its sign dominates lo.
    let d = (hi - c as f64) + lo;
    d.partial_cmp(&0.0)
}

/// Maximum of a b-bit unsigned normalized integer: 2^b - 1.
pub fn unorm_max(bits: u32) -> u64 {
    (1u64 << bits) - 1
}

/// §2.3.5.1 equation (2.1): "f = c / (2^b − 1)". Returned exactly.
pub fn unorm_to_float(c: u64, bits: u32) -> Exact {
    Exact::Q {
        c,
        m: unorm_max(bits),
    }
}

/// §2.3.5.2 equation (2.3): the float is first clamped to [0,1], then
/// "convert_float_uint(r,b) returns one of the two unsigned binary integer values with exactly b bits
/// which are closest to the floating-point value r (where rounding to nearest is preferred)".
/// Returns (preferred, other); equal when f × (2^b − 1) is an integer.
pub fn float_to_unorm(f: f64, bits: u32) -> (u64, u64) {
    let m = unorm_max(bits);
    let f = if f.is_nan() { 0.0 } else { f.clamp(0.0, 1.0) };
    let r = f * m as f64;
    let lo = r.floor();
    let hi = r.ceil();
    // Products are exact for bits <= 29 with an f32 input; above, the floor/ceil still bracket.
    let nearest = if r - lo <= hi - r { lo } else { hi };
    let other = if nearest == lo { hi } else { lo };
    ((nearest as u64).min(m), (other as u64).min(m))
}

/// The f32 values an implementation may hold for the real `v`: `v` itself when an f32 represents it,
/// otherwise the two f32 neighbours (round down, round up). A conversion by multiplication with a
/// reciprocal or by division may land on either one: GL 4.6 §2.3.5.1 defines f = c / (2^b - 1)
/// but not how the quotient is rounded to the float the unit holds.
pub fn f32_candidates(v: Exact) -> [f64; 2] {
    let a = v.approx();
    if !a.is_finite() {
        return [a, a];
    }
    let f = a as f32;
    let ff = f as f64;
    match v.cmp_from(ff) {
        Some(Ordering::Equal) => [ff, ff],
        Some(Ordering::Less) => [ff, f.next_up() as f64],
        Some(Ordering::Greater) => [f.next_down() as f64, ff],
        None => [ff, ff],
    }
}

/// Rounds an API float to f32 (the API passes floats; COMMON.md).
pub fn f32r(x: f64) -> f64 {
    x as f32 as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_ratio_comparison() {
        let half16 = unorm_to_float(32768, 16);
        assert_eq!(half16.cmp_from(0.5), Some(Ordering::Less)); // 32768/65535 > 0.5
        assert_eq!(
            unorm_to_float(65535, 16).cmp_from(1.0),
            Some(Ordering::Equal)
        );
        assert_eq!(unorm_to_float(0, 24).cmp_from(0.0), Some(Ordering::Equal));
        // 32-bit: 2^31 / (2^32-1) is a hair above 0.5.
        assert_eq!(
            unorm_to_float(1 << 31, 32).cmp_from(0.5),
            Some(Ordering::Less)
        );
        assert_eq!(
            unorm_to_float(u32::MAX as u64, 32).cmp_from(1.0),
            Some(Ordering::Equal)
        );
        assert_eq!(half16.cmp_from(f64::NAN), None);
        assert_eq!(half16.cmp_from(f64::INFINITY), Some(Ordering::Greater));
    }

    #[test]
    fn f32_neighbours_bracket_the_ratio() {
        for (c, b) in [
            (1u64, 16u32),
            (32768, 16),
            (12345, 24),
            (7, 32),
            (65535, 16),
        ] {
            let v = unorm_to_float(c, b);
            let [lo, hi] = f32_candidates(v);
            assert!(v.cmp_from(lo) != Some(Ordering::Greater), "{c}/{b}");
            assert!(v.cmp_from(hi) != Some(Ordering::Less), "{c}/{b}");
            assert!((lo as f32).next_up() as f64 >= hi);
        }
        assert_eq!(f32_candidates(Exact::F(0.5)), [0.5, 0.5]);
    }

    #[test]
    fn either_neighbour_on_upload() {
        // Pack note to (2.3): depth 0.5 into 16 bits gives 32767.5, so 32767 or 32768 may be stored.
        let (a, b) = float_to_unorm(0.5, 16);
        assert_eq!((a.min(b), a.max(b)), (32767, 32768));
        assert_eq!(float_to_unorm(1.0, 24), (16777215, 16777215));
        assert_eq!(float_to_unorm(-3.0, 16), (0, 0));
    }
}
