//! Sweep cases: one texture and sampler state, many lookups.
//!
//! A case's `sweep` lists more lookups on the case's own texture and sampling state: each point
//! replaces the lookup's coordinates and reference (everything else of [`Lookup`] is the case's)
//! and carries its own acceptance sets. The drivers that compile one shader variant per sampling
//! state then check many values per compilation, and a sweep travels as one message and one
//! record: the test `<case id>@<api>` passes only if the case's lookup and every point pass.
//!
//! Fixture form (cases/README.md): `"sweep":[{"coord":[s,t,r,q],"dref":R,"expect":{...}}, ...]`,
//! where `expect` holds `spec_value`, `accept` and `implementation_defined` as in the case's
//! [`Expectation`]; the layout and citations are the case's.

use crate::case::{Case, Lookup};
use crate::enums::{Channel, Profile};
use crate::expect::{Acceptance, Expectation};
use crate::keymap::KeyMap;
use serde::{Deserialize, Serialize};

/// What a sweep point's id adds to its case's id, before the point's index ([`Case::point_id`]).
pub const SWEEP_ID_TAG: &str = "/sweep=";

/// The case id and point index of a [`Case::point_id`], or `None` for any other id.
pub fn split_point_id(id: &str) -> Option<(&str, usize)> {
    let (case, k) = id.rsplit_once(SWEEP_ID_TAG)?;
    if k.is_empty() || !k.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((case, k.parse().ok()?))
}

/// Most points a case may carry (a bound on absurd input, far above what the grid writes).
pub const MAX_SWEEP_POINTS: usize = 4096;

/// One more lookup of a sweep: the case's lookup with these coordinates and this reference.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepPoint {
    /// (s, t, r, q) as passed, meaning as in [`Lookup::coord`].
    #[serde(with = "crate::real::array4")]
    pub coord: [f64; 4],
    /// The reference as passed, as in [`Lookup::dref`].
    #[serde(with = "crate::real")]
    pub dref: f64,
    /// The oracle's expectation for this point (present in fixtures, left out on the wire).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expect: Option<PointExpectation>,
}

/// The part of an [`Expectation`] that differs from point to point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PointExpectation {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spec_value: Option<f64>,
    pub accept: KeyMap<Profile, Acceptance>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub implementation_defined: Option<String>,
}

impl PointExpectation {
    /// Does `rgba`, read through `layout`, lie in this point's strictest acceptance set (a pass)?
    /// The verdict's fast path; anything else is judged on [`Case::point_case`].
    pub fn passes(&self, layout: &[Channel; 4], rgba: [f64; 4]) -> bool {
        let acc = self.accept.get(&Profile::strictest());
        layout.iter().zip(rgba).all(|(ch, v)| {
            let acc = if ch.gather_index().is_some() {
                None
            } else {
                acc
            };
            crate::expect::channel_ok(*ch, acc, v)
        })
    }

    /// The point's part of a full expectation (`None` for a gather expectation: sweeps hold
    /// filtered lookups only).
    pub fn of(e: &Expectation) -> Option<PointExpectation> {
        if e.gather.is_some() {
            return None;
        }
        Some(PointExpectation {
            spec_value: e.spec_value,
            accept: e.accept.clone(),
            implementation_defined: e.implementation_defined.clone(),
        })
    }
}

impl Case {
    /// How many lookups the case checks: its own and its sweep's.
    pub fn lookup_count(&self) -> usize {
        1 + self.sweep.len()
    }

    /// The lookup of sweep point `p`: the case's lookup with the point's coordinates and reference.
    pub fn point_lookup(&self, p: &SweepPoint) -> Lookup {
        Lookup {
            coord: p.coord,
            dref: p.dref,
            ..self.lookup.clone()
        }
    }

    /// The id of sweep point `k` when it is shown or run as a case of its own.
    pub fn point_id(&self, k: usize) -> String {
        format!("{}{SWEEP_ID_TAG}{k}", self.id)
    }

    /// Sweep point `k` as a case of its own (id [`Case::point_id`], no sweep): what a backend that
    /// runs no sweeps is sent, and what a verdict on the point is about. Its expectation is the
    /// point's, with the case's layout and citations; `None` if either side has none.
    pub fn point_case(&self, k: usize) -> Option<Case> {
        let p = self.sweep.get(k)?;
        let expect = match (&self.expect, &p.expect) {
            (Some(e), Some(pe)) => Some(Expectation {
                spec_value: pe.spec_value,
                accept: pe.accept.clone(),
                layout: e.layout.clone(),
                other_layouts: e.other_layouts.clone(),
                gather: None,
                implementation_defined: pe.implementation_defined.clone(),
                citations: e.citations.clone(),
            }),
            _ => None,
        };
        Some(Case {
            id: self.point_id(k),
            spec: self.spec,
            api: self.api.clone(),
            texture: self.texture.clone(),
            sampler: self.sampler.clone(),
            lookup: self.point_lookup(p),
            expect,
            sweep: vec![],
        })
    }

    /// The case without its sweep (what a backend that runs no sweeps is sent for the case's own
    /// lookup).
    pub fn without_sweep(&self) -> Case {
        Case {
            sweep: vec![],
            ..self.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::split_point_id;

    #[test]
    fn a_point_id_splits_into_its_case_id_and_index_and_nothing_else_does() {
        assert_eq!(
            split_point_id("gl46/2d/d16/nearest/never/sweep=12"),
            Some(("gl46/2d/d16/nearest/never", 12))
        );
        assert_eq!(split_point_id("a/sweep=3/sweep=4"), Some(("a/sweep=3", 4)));
        for plain in ["gl46/2d/d16", "a/sweep=", "a/sweep=x1", "a/sweep=-1"] {
            assert_eq!(split_point_id(plain), None, "{plain}");
        }
    }
}
