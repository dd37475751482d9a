//! What the oracle expects (carried in fixtures) and what a backend observed.

use crate::enums::*;
use crate::keymap::KeyMap;
use serde::{Deserialize, Serialize};

/// A closed interval [lo, hi] of acceptable values of r.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Interval {
    pub lo: f64,
    pub hi: f64,
}

impl Interval {
    pub fn point(v: f64) -> Interval {
        Interval { lo: v, hi: v }
    }
    pub fn new(lo: f64, hi: f64) -> Interval {
        Interval { lo, hi }
    }
    pub fn contains(&self, v: f64) -> bool {
        v >= self.lo && v <= self.hi
    }
}

/// A union of closed intervals. Empty means nothing is acceptable.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Acceptance(pub Vec<Interval>);

impl Acceptance {
    pub fn contains(&self, v: f64) -> bool {
        self.0.iter().any(|i| i.contains(v))
    }
    /// Every interval of `self` lies inside some interval of `other` (other accepts at least as much).
    pub fn is_subset_of(&self, other: &Acceptance) -> bool {
        self.0
            .iter()
            .all(|i| other.0.iter().any(|o| o.lo <= i.lo && i.hi <= o.hi))
    }
    pub fn min(&self) -> Option<f64> {
        self.0.iter().map(|i| i.lo).reduce(f64::min)
    }
    pub fn max(&self) -> Option<f64> {
        self.0.iter().map(|i| i.hi).reduce(f64::max)
    }
}

impl std::fmt::Display for Acceptance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0.is_empty() {
            return f.write_str("{}");
        }
        let parts: Vec<String> = self
            .0
            .iter()
            .map(|i| {
                if i.lo == i.hi {
                    format!("{{{}}}", i.lo)
                } else {
                    format!("[{}, {}]", i.lo, i.hi)
                }
            })
            .collect();
        f.write_str(&parts.join(" ∪ "))
    }
}

/// The oracle's expectation for one case, as stored in fixtures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Expectation {
    /// r computed by the specification's pseudocode with exact arithmetic. `None` where the spec
    /// gives no single value (e.g. a NaN reference).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spec_value: Option<f64>,
    /// Acceptable values of r under each precision profile.
    pub accept: KeyMap<Profile, Acceptance>,
    /// How r appears in the observed RGBA, per API path the case applies to.
    pub layout: KeyMap<ApiPath, [Channel; 4]>,
    /// Where the texts give a path's result two readings that place r differently (e.g. the
    /// swizzled and the unswizzled shadow gather), the other readings, each named: an observation
    /// that any of them accepts is accepted as `layout` would accept it. Empty for most cases.
    #[serde(default, skip_serializing_if = "KeyMap::is_empty")]
    pub other_layouts: KeyMap<ApiPath, Vec<OtherLayout>>,
    /// Shadow textureGather: the acceptable values of the four result components (τi0j1, τi1j1,
    /// τi1j0, τi0j0) per profile, read by the layout's `g0`..`g3` channels; `accept` and
    /// `spec_value` then describe component 0. `None` for every other lookup.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gather: Option<[KeyMap<Profile, Acceptance>; 4]>,
    /// Set when the specs leave the result open; says why.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub implementation_defined: Option<String>,
    /// The sections the result rests on, e.g. "GL 4.6 §8.23.1 Table 8.23".
    pub citations: Vec<String>,
}

/// Another reading of where r appears on one API path ([`Expectation::other_layouts`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OtherLayout {
    /// The name of the reading (a contradiction key of the oracle, shown by `shadowcheck explain`).
    pub reading: String,
    pub layout: [Channel; 4],
}

/// The outcome of checking one observation against an expectation: the strictest profile (in
/// [`Profile::ALL`] order) whose acceptance set holds it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Judgement {
    /// Inside the strictest profile's acceptance set (a pass).
    Strictest,
    /// Inside this looser profile's set, outside every stricter one's (a warning).
    Looser(Profile),
    /// Outside every profile's set.
    Outside,
}

impl Expectation {
    /// Does `rgba`, observed through `api`, lie in the acceptance set of `profile`?
    /// Channels marked `Unused` are ignored; `Zero`/`One` must be exact.
    /// Returns `None` when the expectation has no layout for that API path.
    pub fn accepts(&self, profile: Profile, api: ApiPath, rgba: [f64; 4]) -> Option<bool> {
        let main = self.accepts_through(profile, self.layout.get(&api)?, rgba)?;
        Some(main || self.other_accepts(profile, api, rgba))
    }

    /// Does one of the other readings of `api`'s layout accept `rgba` under `profile`?
    fn other_accepts(&self, profile: Profile, api: ApiPath, rgba: [f64; 4]) -> bool {
        self.other_layouts
            .get(&api)
            .into_iter()
            .flatten()
            .any(|o| self.accepts_through(profile, &o.layout, rgba) == Some(true))
    }

    /// [`Expectation::accepts`] with the layout already looked up: r's set is fetched once, not
    /// once per channel (the per-observation hot path of a run goes through here).
    fn accepts_through(
        &self,
        profile: Profile,
        layout: &[Channel; 4],
        rgba: [f64; 4],
    ) -> Option<bool> {
        let r = self.accept.get(&profile)?;
        Some(layout.iter().zip(rgba).all(|(ch, v)| {
            let acc = match ch.gather_index() {
                Some(i) => self.gather.as_ref().and_then(|g| g[i].get(&profile)),
                None => Some(r),
            };
            channel_ok(*ch, acc, v)
        }))
    }

    /// The acceptance set a channel's value is checked against under `profile`: r's, or for a
    /// gather channel its component's. `None` for the constant channels or a missing profile.
    pub fn channel_acceptance(&self, profile: Profile, ch: Channel) -> Option<&Acceptance> {
        match ch.gather_index() {
            Some(i) => self.gather.as_ref()?[i].get(&profile),
            None if matches!(ch, Channel::R | Channel::ROrZero) => self.accept.get(&profile),
            None => None,
        }
    }

    /// Does one channel's value `v` satisfy `ch` under `profile`?
    pub fn channel_accepts(&self, profile: Profile, ch: Channel, v: f64) -> bool {
        channel_ok(ch, self.channel_acceptance(profile, ch), v)
    }

    /// The strictest profile accepting one observation, trying the profiles strictest first (a
    /// profile accepts when the path's layout or one of its other readings does).
    /// `None` when the layout or a profile tried is missing.
    pub fn judge(&self, api: ApiPath, rgba: [f64; 4]) -> Option<Judgement> {
        let layout = self.layout.get(&api)?;
        for &p in Profile::ALL {
            if self.accepts_through(p, layout, rgba)? || self.other_accepts(p, api, rgba) {
                return Some(if p == Profile::strictest() {
                    Judgement::Strictest
                } else {
                    Judgement::Looser(p)
                });
            }
        }
        Some(Judgement::Outside)
    }
}

/// Does one channel's value `v` satisfy `ch`, where `acc` is the acceptance set the channel reads
/// (r's or its gather component's; `None` for the constant channels)?
pub fn channel_ok(ch: Channel, acc: Option<&Acceptance>, v: f64) -> bool {
    match ch {
        Channel::Zero => v == 0.0,
        Channel::One => v == 1.0,
        Channel::Unused => true,
        Channel::ROrZero => v == 0.0 || acc.is_some_and(|a| a.contains(v)),
        Channel::R | Channel::G0 | Channel::G1 | Channel::G2 | Channel::G3 => {
            acc.is_some_and(|a| a.contains(v))
        }
    }
}

/// What a backend returned for one case on one API path.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Observation {
    pub case_id: String,
    pub api: ApiPath,
    /// The four channels as read back (from a float target where the backend can).
    #[serde(with = "crate::real::array4")]
    pub rgba: [f64; 4],
    /// What the backend read back of the stored level-0 depth texels, where the API allows; the
    /// verdict then uses these instead of the fixture's values.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stored: Option<crate::case::Texels>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// One texel of a lookup's footprint, for failure dumps.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FootprintTexel {
    /// Mip level (relative to level base).
    pub level: u32,
    /// Texel coordinates (x, y, layer); `None` for a border texel.
    pub xyz: Option<[u32; 3]>,
    /// The stored value as written in the fixture (integer for unorm) and as a real.
    #[serde(with = "crate::real")]
    pub stored: f64,
    /// Dt after the specification's clamping.
    #[serde(with = "crate::real")]
    pub dt: f64,
    /// Per-texel comparison: `Some(pass)`, or `None` when the texel is within reference precision
    /// (either outcome allowed).
    pub pass: Option<bool>,
    /// Filter weight of this texel in the spec value.
    #[serde(with = "crate::real")]
    pub weight: f64,
}

/// The texels a lookup touched.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Footprint {
    /// Dref after projective divide and clamping.
    #[serde(with = "crate::real")]
    pub dref: f64,
    pub texels: Vec<FootprintTexel>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(v: f64) -> KeyMap<Profile, Acceptance> {
        Profile::ALL
            .iter()
            .map(|&p| (p, Acceptance(vec![Interval::point(v)])))
            .collect()
    }

    #[test]
    fn gather_channels_read_their_own_component() {
        let e = Expectation {
            spec_value: Some(1.0),
            accept: set(1.0),
            layout: [(ApiPath::GlslCore, Channel::GATHER)].into_iter().collect(),
            other_layouts: Default::default(),
            gather: Some([set(1.0), set(1.0), set(0.0), set(0.0)]),
            implementation_defined: None,
            citations: vec![],
        };
        let judge = |rgba| e.judge(ApiPath::GlslCore, rgba);
        assert_eq!(judge([1.0, 1.0, 0.0, 0.0]), Some(Judgement::Strictest));
        // Rotated order, or r written to every channel: outside.
        assert_eq!(judge([0.0, 1.0, 1.0, 0.0]), Some(Judgement::Outside));
        assert_eq!(judge([1.0, 1.0, 1.0, 1.0]), Some(Judgement::Outside));
        // A gather channel with no gather sets accepts nothing.
        let no_gather = Expectation {
            gather: None,
            ..e.clone()
        };
        assert!(!no_gather.channel_accepts(Profile::Strict, Channel::G0, 1.0));
        assert_eq!(Channel::G2.gather_index(), Some(2));
        assert_eq!(Channel::R.gather_index(), None);
    }
}
