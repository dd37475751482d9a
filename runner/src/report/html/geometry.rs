//! What the pictures need beyond the result records: where each test sits on the heatmaps (the
//! stored texel value Dt and the reference Dref its lookup compared) and, for passing tests, the
//! expectation (result records carry the expected summary and the oracle's footprint only for
//! Warn and Fail, to keep results.jsonl small).
//!
//! Both come from the fixtures the runs used: the expectation stored with each case, and the
//! geometry from the oracle's evaluation of the case (the same spec rules the verdict used), whose
//! footprint gives Dref after projective divide and clamping and Dt after the spec's clamping. Only single-texel lookups (NEAREST, and mipmapped lookups
//! that touch one texel of one level) have one (Dt, Dref) point; filtered lookups are shown on the
//! acceptance plots instead. Without fixtures, the footprints in the records are used (so only
//! the Warn/Fail tests are placed, and the page says so).

use crate::records::TestResult;
use crate::run::load_cases;
use crate::verdict::oracle_evaluate;
use shadowcheck_model::{Expectation, Footprint, Spec};
use std::collections::{HashMap, HashSet};
use std::path::PathBuf;

/// (Dt, Dref) of the one texel a lookup used with a non-zero weight, if there is exactly one.
pub fn single_texel(fp: &Footprint) -> Option<(f64, f64)> {
    let mut used = fp.texels.iter().filter(|t| t.weight != 0.0);
    let t = used.next()?;
    if used.next().is_some() {
        return None;
    }
    Some((t.dt, fp.dref))
}

/// Per case id: (Dt, Dref) of single-texel lookups, and the expectation.
#[derive(Debug, Default)]
pub struct Geometry {
    points: HashMap<String, (f64, f64)>,
    expects: HashMap<String, Expectation>,
    /// The fixture paths the points came from (empty: none were found).
    pub fixtures: Vec<String>,
    /// Cases named by results that no fixture holds.
    pub missing: usize,
    /// The cases the layer attribution needs (`crate::attribute`): the failing ones of a layered
    /// backend whose Vulkan driver is in the results too, and the Vulkan ones; empty otherwise.
    pub cases: HashMap<String, shadowcheck_model::Case>,
}

impl Geometry {
    /// Loads the fixtures under `paths` (those that exist) and evaluates the cases that `results`
    /// name. Fixture files that do not load are skipped: the run itself reported them.
    pub fn from_fixtures(paths: &[PathBuf], results: &[TestResult]) -> Geometry {
        let paths: Vec<PathBuf> = paths.iter().filter(|p| p.exists()).cloned().collect();
        let mut g = Geometry {
            fixtures: paths.iter().map(|p| p.display().to_string()).collect(),
            ..Geometry::default()
        };
        if paths.is_empty() {
            return g;
        }
        let wanted: HashSet<&str> = results.iter().map(|r| r.case_id.as_str()).collect();
        let backends: HashSet<&str> = results.iter().map(|r| r.backend.as_str()).collect();
        let layered: HashSet<&str> = results
            .iter()
            .filter(|r| {
                matches!(
                    r.outcome,
                    crate::records::Outcome::Fail | crate::records::Outcome::Warn
                ) && crate::attribute::layering_of(&r.backend)
                    .is_some_and(|l| backends.contains(l.lower))
            })
            .map(|r| r.case_id.as_str())
            .collect();
        let set = load_cases(&paths);
        let mut found = 0usize;
        for l in &set.cases {
            if !wanted.contains(l.case.id.as_str()) {
                continue;
            }
            found += 1;
            if !layered.is_empty()
                && (layered.contains(l.case.id.as_str()) || l.case.spec == Spec::Vulkan)
            {
                g.cases.insert(l.case.id.clone(), l.case.clone());
            }
            if let Ok(ev) = oracle_evaluate(&l.case) {
                if let Some(p) = single_texel(&ev.footprint) {
                    g.points.insert(l.case.id.clone(), p);
                }
                // The fixture's stored expectation is what the run judged by; the oracle's when absent.
                g.expects.insert(
                    l.case.id.clone(),
                    l.case.expect.clone().unwrap_or(ev.expect),
                );
            } else if let Some(e) = &l.case.expect {
                g.expects.insert(l.case.id.clone(), e.clone());
            }
        }
        g.missing = wanted.len().saturating_sub(found);
        g
    }

    /// The (Dt, Dref) of `r`'s lookup: from the fixtures, else from the record's own footprint.
    pub fn point(&self, r: &TestResult) -> Option<(f64, f64)> {
        self.points
            .get(&r.case_id)
            .copied()
            .or_else(|| r.footprint.as_ref().and_then(single_texel))
    }

    /// The fixture's expectation of `r`'s case, if the fixtures hold it.
    pub fn expectation(&self, r: &TestResult) -> Option<&Expectation> {
        self.expects.get(&r.case_id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::FootprintTexel;

    fn texel(dt: f64, weight: f64) -> FootprintTexel {
        FootprintTexel {
            level: 0,
            xyz: Some([0, 0, 0]),
            stored: dt,
            dt,
            pass: Some(true),
            weight,
        }
    }

    #[test]
    fn only_lookups_with_one_weighted_texel_have_a_point() {
        let one = Footprint {
            dref: 0.5,
            texels: vec![texel(0.25, 1.0), texel(0.75, 0.0)],
        };
        assert_eq!(single_texel(&one), Some((0.25, 0.5)));
        let two = Footprint {
            dref: 0.5,
            texels: vec![texel(0.25, 0.5), texel(0.75, 0.5)],
        };
        assert_eq!(single_texel(&two), None);
        assert_eq!(single_texel(&Footprint::default()), None);
    }
}
