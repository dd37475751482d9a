//! Precision profiles (tiers): how much a conforming implementation may deviate from the exact
//! pseudocode, as data.
//!
//! The spec value is exact; the acceptance set of a profile widens it by the tolerances of its entry
//! in [`PROFILES`]. Everything in the oracle iterates that table; nothing assumes how many tiers there
//! are. The table lists the profiles strictest first, in the declaration order of
//! [`shadowcheck_model::Profile`], which is also what an observation earns
//! ([`shadowcheck_model::Expectation::judge`]): inside the first tier's set a Pass, inside a later
//! one's only a Warn, outside every set a Fail.
//!
//! Every tolerance of a tier is at least that of the tier before it, and each tier's set is finally
//! united with the one before (`accept::finalize`), so a looser profile never accepts less (checked
//! below and by property tests).
//!
//! Adding a tier: a variant of `shadowcheck_model::Profile` (its key is the fixtures' key, its
//! position its strictness) and its entry here, at the same position, with its tolerances.

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

/// Every profile, strictest first (the declaration order of [`Profile`]).
pub const PROFILES: &[ProfileSpec] = &[STRICT, LENIENT];

/// The data of a named profile (`None` only if the table missed a variant, which a test rules out).
pub fn spec_of(p: Profile) -> Option<&'static ProfileSpec> {
    PROFILES.iter().find(|s| s.profile == p)
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
    fn the_table_lists_every_profile_strictest_first() {
        let names: Vec<Profile> = PROFILES.iter().map(|p| p.profile).collect();
        assert_eq!(names, Profile::ALL);
        for p in Profile::ALL {
            assert_eq!(spec_of(*p).map(|s| s.profile), Some(*p));
        }
        assert!(PROFILES[0].ref_bits.is_none() && !PROFILES[0].hull_filtered);
    }

    #[test]
    fn each_tier_is_at_least_as_loose_as_the_one_before() {
        for w in std::hint::black_box(PROFILES).windows(2) {
            let (s, l) = (&w[0], &w[1]);
            assert!(l.weight_tol >= s.weight_tol, "{}", l.profile);
            assert!(l.lod_tol >= s.lod_tol, "{}", l.profile);
            assert!(l.coord_tol >= s.coord_tol, "{}", l.profile);
            // A reference precision of 2^-b: fewer bits are looser; `None` (f32 rounding only) is the
            // tightest.
            match (s.ref_bits, l.ref_bits) {
                (Some(sb), Some(lb)) => assert!(lb <= sb, "{}", l.profile),
                (Some(_), None) => {
                    panic!("{} drops {}'s reference precision", l.profile, s.profile)
                }
                (None, _) => {}
            }
            assert!(l.hull_filtered || !s.hull_filtered, "{}", l.profile);
        }
    }
}
