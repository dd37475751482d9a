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
///
/// Each field is one allowance; oracle/README.md ("Verdicts by normative force") names the sentence
/// that makes it a "shall" (strict) or a "should" (quality).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileSpec {
    pub profile: Profile,
    /// Reference precision in bits: a texel whose |Dref − Dt| <= 2^-bits may compare either way.
    /// `None`: only f32 rounding of Dref (projective divide) and of Dt (unorm → float) can flip a texel.
    pub ref_bits: Option<u32>,
    /// Each bilinear weight (α, β) and the mip blend weight frac(λ) may be off by this much. A
    /// shadow gather's 2x2 block (i0 = ⌊u′ − ½⌋, from the same u′ − ½ as α) may therefore be the
    /// neighbouring block within this many texels of a block boundary (`engine::gather`;
    /// oracle/README.md's tier table).
    pub weight_tol: f64,
    /// λ may be off by this much (level selection, the mag/min switch and frac(λ)).
    pub lod_tol: f64,
    /// Texture coordinates may be off by this many texels (texel selection at a NEAREST boundary;
    /// a gather block takes the larger of this and `weight_tol`).
    pub coord_tol: f64,
    /// A filtered comparison whose footprint holds both a texel that may pass and one that may fail
    /// returns any value between the fail value and 1, where the spec leaves filtering
    /// "implementation-dependent" and only says r "should be ... proportional to the number of
    /// comparison passes or failures" (GL 4.6 §8.23.1, ES 3.2 §8.20.1, ARB_shadow,
    /// EXT_shadow_samplers). A footprint with no pass stays exactly the fail value and one with no
    /// fail exactly 1: any proportion of zero passes (failures) is zero.
    pub mixed_footprint_any: bool,
}

/// `strict`: what the "shall" sentences fix. Exact conversion c/(2^b−1); a texel is a tie only when
/// f32 rounding of Dref/Dt could flip it; bilinear PCF weights within 2^-8 (COMMON.md); exact λ.
pub const STRICT: ProfileSpec = ProfileSpec {
    profile: Profile::Strict,
    ref_bits: None,
    weight_tol: 1.0 / 256.0,
    lod_tol: 0.0,
    coord_tol: 0.0,
    mixed_footprint_any: false,
};

/// `quality`: also what the "should" sentences leave open (a result only here is a Warn, as dEQP's
/// QualityWarning), at least where dEQP's low-quality fallback does (es3fTextureShadowTests: pcfBits
/// 0, lodBits 4): a footprint with both passes and fails may return any value in [fail value, 1]; λ
/// within 2^-4 of the exact value. Plus the arithmetic slack of GL 4.6 / ES 3.2 §2.3.4.1 ("individual
/// results of floating-point operations are accurate to about 1 part in 10^5"): Dref, Dt and a
/// returned value within 2^-16 (dEQP's referenceBits 16). Nothing a sentence fixes exactly is
/// widened: a footprint with no pass (no fail) is exactly the fail value (1), NEVER/ALWAYS exact,
/// exact ties at 0 and 1 stay exact.
pub const QUALITY: ProfileSpec = ProfileSpec {
    profile: Profile::Quality,
    ref_bits: Some(16),
    weight_tol: 1.0 / 256.0,
    lod_tol: 1.0 / 16.0,
    coord_tol: 0.0,
    mixed_footprint_any: true,
};

/// Every profile, strictest first (the declaration order of [`Profile`]).
pub const PROFILES: &[ProfileSpec] = &[STRICT, QUALITY];

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
            if self.mixed_footprint_any {
                ", filtered compare with both passes and fails: any value in [fail, 1]"
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
        assert!(PROFILES[0].ref_bits.is_none() && !PROFILES[0].mixed_footprint_any);
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
            assert!(
                l.mixed_footprint_any || !s.mixed_footprint_any,
                "{}",
                l.profile
            );
        }
    }
}
