//! Sweep cases in a worker: each point of a case's sweep is run as a lookup of its own, right
//! after the case's own lookup, so the renderer sees one group of lookups sharing texture and
//! sampler state (one texture, one batched draw where the path allows); the answers are then
//! folded back into one answer per case, the points' RGBA in the `sweep` of each path's result.

use crate::Answer;
use shadowcheck_model::{Case, Lookup};

/// One lookup to draw: a case's own, or one point of its sweep. A point is the case's lookup with
/// the point's coordinates and reference ([`Case::point_lookup`]) on the case's texture, sampler
/// and API paths, so a case and its points form one group (one texture, one batched draw).
#[derive(Debug, Clone)]
pub struct Job<'a> {
    pub case: &'a Case,
    pub lookup: Lookup,
    /// A sweep point: its answer keeps only the RGBA of each path (no stored texels, no note).
    pub point: bool,
}

impl<'a> Job<'a> {
    /// The case's own lookup.
    pub fn own(case: &'a Case) -> Job<'a> {
        Job {
            case,
            lookup: case.lookup.clone(),
            point: false,
        }
    }

    /// Do `self` and `other` draw on equal textures with equal sampler state?
    pub fn same_texture(&self, other: &Job) -> bool {
        std::ptr::eq(self.case, other.case)
            || (self.case.texture == other.case.texture && self.case.sampler == other.case.sampler)
    }
}

/// The lookups to draw for `cases`: each case's own, then each point of its sweep (borrowing the
/// case: a point is only its lookup).
pub fn jobs(cases: &[Case]) -> Vec<Job<'_>> {
    let mut out = Vec::with_capacity(cases.iter().map(Case::lookup_count).sum());
    for c in cases {
        out.push(Job::own(c));
        out.extend(c.sweep.iter().map(|p| Job {
            case: c,
            lookup: c.point_lookup(p),
            point: true,
        }));
    }
    out
}

/// `cases` with their sweeps expanded into cases of their own ([`Case::point_case`]), each case
/// followed by its points: for a worker that is sent whole cases (the WebGL page).
pub fn expand(cases: Vec<Case>) -> Vec<Case> {
    let mut flat = Vec::with_capacity(cases.iter().map(Case::lookup_count).sum());
    for mut c in cases {
        let points: Vec<Case> = (0..c.sweep.len()).filter_map(|k| c.point_case(k)).collect();
        c.sweep.clear();
        flat.push(c);
        flat.extend(points);
    }
    flat
}

/// Folds the answers of a case's points into the answer for its own lookup. A point that was not
/// observed on a path the case was observed on makes the case an error naming the point: the
/// points share the case's state, so they run where it runs.
pub fn merge(main: Answer, points: impl IntoIterator<Item = Answer>) -> Answer {
    let Answer::Observation(mut results, skipped) = main else {
        return main;
    };
    for (k, a) in points.into_iter().enumerate() {
        let observed = match a {
            Answer::Observation(r, _) => r,
            Answer::Skip(why) => return Answer::Error(format!("sweep point {k} skipped: {why}")),
            Answer::Error(e) => return Answer::Error(format!("sweep point {k}: {e}")),
        };
        for r in results.iter_mut() {
            match observed.iter().find(|p| p.api == r.api) {
                Some(p) => r.sweep.push(p.rgba),
                None => {
                    return Answer::Error(format!(
                        "sweep point {k}: no result on API path `{}`",
                        r.api
                    ))
                }
            }
        }
    }
    Answer::Observation(results, skipped)
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::{SweepPoint, Target};
    use shadowcheck_protocol::{PathResult, Rgba};

    fn result(v: f64) -> PathResult {
        PathResult {
            api: "core".into(),
            rgba: Rgba([v, 0.0, 0.0, 1.0]),
            stored: None,
            note: None,
            sweep: vec![],
        }
    }

    #[test]
    fn points_run_after_their_case_and_fold_back_in_order() {
        let mut c = crate::test_case::case(Target::T2d, 2, 1, 1);
        c.sweep = (0..3)
            .map(|k| SweepPoint {
                coord: [0.25, 0.5, 0.0, 1.0],
                dref: k as f64 / 4.0,
                expect: None,
            })
            .collect();
        let plain = crate::test_case::case(Target::T2d, 2, 1, 1);
        let both = vec![plain, c];
        let j = jobs(&both);
        assert_eq!(j.len(), 5);
        assert!(j[0].case.sweep.is_empty() && !j[0].point);
        assert!(std::ptr::eq(j[3].case, &both[1]) && j[3].point);
        assert_eq!(j[1].lookup, both[1].lookup);
        assert_eq!(j[3].lookup.dref, 0.25);
        let flat = expand(both.clone());
        assert_eq!(flat.len(), 5);
        assert_eq!(flat[3].id, "t/sweep=1");
        assert_eq!(flat[3].lookup, j[3].lookup);
        assert!(flat.iter().all(|c| c.sweep.is_empty()));

        let obs = |v| Answer::Observation(vec![result(v)], vec![]);
        let merged = merge(obs(1.0), [obs(0.0), obs(0.5), obs(1.0)]);
        let Answer::Observation(r, _) = merged else {
            panic!("{merged:?}")
        };
        let got: Vec<f64> = r[0].sweep.iter().map(|p| p.0[0]).collect();
        assert_eq!(got, vec![0.0, 0.5, 1.0]);
        // A point that failed to run makes its case an error that names it.
        let merged = merge(
            obs(1.0),
            [obs(0.0), Answer::Error("GL_OUT_OF_MEMORY".into())],
        );
        assert_eq!(
            merged,
            Answer::Error("sweep point 1: GL_OUT_OF_MEMORY".into())
        );
    }
}
