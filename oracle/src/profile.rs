//! Precision profiles: how much a conforming implementation may deviate from the exact pseudocode.
//!
//! The spec value is exact; the acceptance set of a profile widens it by the tolerances below.
//! Every tolerance of `lenient` is at least that of `strict`, and `lenient` additionally takes the
//! hull of filtered results, so a looser profile never accepts less (checked by property tests).

use shadowcheck_model::Profile;

/// The tolerances that define one profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileSpec {
    pub profile: Profile,
    /// Reference precision in bits: a texel whose |Dref − Dt| <= 2^-bits may compare either way.
    /// `None`: only f32 rounding of Dref (projective divide) and of Dt (unorm → float) can flip a texel.
    pub ref_bits: Option<u32>,
    /// Each bilinear weight (α, β) and the mip blend weight frac(λ) may be off by this much.
    pub weight_tol: f64,
    /// λ may be off by this much (level selection and the mag/min switch).
    pub lod_tol: f64,
    /// Texture coordinates may be off by this many texels (texel selection at a NEAREST boundary).
    pub coord_tol: f64,
    /// Filtered results (more than one texel) are accepted anywhere between the smallest and largest
    /// possible value (the hull), including the unweighted pass fraction k/n.
    pub hull_filtered: bool,
}

/// `strict`: exact conversion c/(2^b−1); a texel is a tie only when f32 rounding of Dref/Dt could flip
/// it; bilinear PCF weights within 2^-8 (COMMON.md).
pub const STRICT: ProfileSpec = ProfileSpec {
    profile: Profile::Strict,
    ref_bits: None,
    weight_tol: 1.0 / 256.0,
    lod_tol: 0.0,
    coord_tol: 0.0,
    hull_filtered: false,
};

/// `lenient`: dEQP-like. Reference precision 16 bits; a filtered result anywhere between the minimum
/// and maximum pass fraction; weights within 2^-6; λ within 2^-6; coordinates within 2^-8 texel.
pub const LENIENT: ProfileSpec = ProfileSpec {
    profile: Profile::Lenient,
    ref_bits: Some(16),
    weight_tol: 1.0 / 64.0,
    lod_tol: 1.0 / 64.0,
    coord_tol: 1.0 / 256.0,
    hull_filtered: true,
};

/// Every profile, strictest first.
pub const PROFILES: [ProfileSpec; 2] = [STRICT, LENIENT];

/// The data of a named profile.
pub fn spec_of(p: Profile) -> ProfileSpec {
    match p {
        Profile::Strict => STRICT,
        Profile::Lenient => LENIENT,
    }
}

impl ProfileSpec {
    /// One line describing the profile, for `explain`.
    pub fn describe(&self) -> String {
        format!(
            "{}: reference precision {}, weights ±{}, λ ±{}, coordinates ±{} texel{}",
            self.profile.key(),
            match self.ref_bits {
                None => "f32 rounding only".to_string(),
                Some(b) => format!("2^-{b}"),
            },
            self.weight_tol,
            self.lod_tol,
            self.coord_tol,
            if self.hull_filtered {
                ", filtered results: hull incl. pass fraction"
            } else {
                ""
            }
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lenient_is_looser_in_every_tolerance() {
        let [s, l] = std::hint::black_box(PROFILES);
        assert!(l.weight_tol >= s.weight_tol);
        assert!(l.lod_tol >= s.lod_tol);
        assert!(l.coord_tol >= s.coord_tol);
        assert!(s.ref_bits.is_none() && l.ref_bits.is_some());
        assert!(l.hull_filtered && !s.hull_filtered);
        assert_eq!(spec_of(Profile::Lenient), LENIENT);
    }
}
