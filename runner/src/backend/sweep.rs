//! Sweep cases on a backend that runs none (its hello has no `sweeps`, PROTOCOL.md §2): the case
//! is sent without its sweep, each point after it as a case of its own (`<id>/sweep=<k>`), and
//! the outcomes are folded back into one outcome per case, the points' RGBA in each path's
//! `sweep`. A point that does not come back observed on every path its case was observed on
//! decides the case's outcome, naming the point.

use super::{ApiAnswer, CaseAnswer, Sent};
use shadowcheck_model::Case;

/// Runs `cases` through `run`, sweeps expanded, and folds the outcomes back (one per case, in
/// order).
pub fn run_expanded(
    cases: &[Sent<'_>],
    run: impl FnOnce(&[Sent<'_>]) -> Vec<CaseAnswer>,
) -> Vec<CaseAnswer> {
    // Owned cases for every case with a sweep (itself without it, then its points).
    let owned: Vec<Vec<Case>> = cases
        .iter()
        .map(|c| {
            let c = c.case;
            if c.sweep.is_empty() {
                return vec![];
            }
            let mut v = Vec::with_capacity(c.lookup_count());
            v.push(c.without_sweep());
            v.extend((0..c.sweep.len()).filter_map(|k| c.point_case(k)));
            v
        })
        .collect();
    let flat: Vec<Sent<'_>> = cases
        .iter()
        .zip(&owned)
        .flat_map(|(c, o)| {
            if o.is_empty() {
                vec![*c]
            } else {
                o.iter().map(|case| Sent { case, api: c.api }).collect()
            }
        })
        .collect();
    let outcomes = run(&flat);
    let mut answered = outcomes.len();
    let mut outcomes = outcomes.into_iter();
    let mut next = || {
        outcomes
            .next()
            .unwrap_or_else(|| CaseAnswer::Error("internal: missing outcome".into()))
    };
    let mut folded = Vec::with_capacity(cases.len());
    for c in cases {
        let n = 1 + c.case.sweep.len();
        if answered < n && crate::interrupt::requested() {
            // An interrupted run gets the cases answered whole, a prefix (`Backend::answer_batch`).
            break;
        }
        answered = answered.saturating_sub(n);
        let main = next();
        let points: Vec<CaseAnswer> = (0..c.case.sweep.len()).map(|_| next()).collect();
        folded.push(merge(main, points));
    }
    folded
}

/// Folds the outcomes of a case's points into the outcome of its own lookup.
pub fn merge(main: CaseAnswer, points: Vec<CaseAnswer>) -> CaseAnswer {
    let CaseAnswer::Observed(mut paths) = main else {
        return main;
    };
    for (k, point) in points.into_iter().enumerate() {
        let observed = match point {
            CaseAnswer::Observed(v) => v,
            CaseAnswer::Skip(why) => {
                return CaseAnswer::Error(format!("sweep point {k} skipped: {why}"))
            }
            CaseAnswer::Error(e) => return CaseAnswer::Error(format!("sweep point {k}: {e}")),
            CaseAnswer::Crash(e) => return CaseAnswer::Crash(format!("sweep point {k}: {e}")),
            CaseAnswer::Timeout(e) => return CaseAnswer::Timeout(format!("sweep point {k}: {e}")),
        };
        for (api, out) in paths.iter_mut() {
            let ApiAnswer::Rgba { sweep, .. } = out else {
                continue;
            };
            match observed.iter().find(|(a, _)| a == api) {
                Some((_, ApiAnswer::Rgba { rgba, .. })) => sweep.push(*rgba),
                _ => {
                    return CaseAnswer::Error(format!(
                        "sweep point {k}: not observed on API path `{}`",
                        api.key()
                    ))
                }
            }
        }
    }
    CaseAnswer::Observed(paths)
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::ApiPath;

    fn observed(v: f64) -> CaseAnswer {
        CaseAnswer::Observed(vec![(
            ApiPath::GlslCore,
            ApiAnswer::Rgba {
                rgba: [v, 0.0, 0.0, 1.0],
                stored: None,
                sweep: vec![],
            },
        )])
    }

    #[test]
    fn points_fold_into_their_case_and_a_lost_point_names_itself() {
        let CaseAnswer::Observed(paths) = merge(observed(1.0), vec![observed(0.0), observed(0.5)])
        else {
            panic!("not observed")
        };
        let ApiAnswer::Rgba { rgba, sweep, .. } = &paths[0].1 else {
            panic!("not rgba")
        };
        assert_eq!(rgba[0], 1.0);
        assert_eq!(
            sweep.iter().map(|p| p[0]).collect::<Vec<_>>(),
            vec![0.0, 0.5]
        );
        assert_eq!(
            merge(
                observed(1.0),
                vec![observed(0.0), CaseAnswer::Crash("SIGSEGV".into())]
            ),
            CaseAnswer::Crash("sweep point 1: SIGSEGV".into())
        );
        assert_eq!(
            merge(observed(1.0), vec![CaseAnswer::Observed(vec![])]),
            CaseAnswer::Error("sweep point 0: not observed on API path `core`".into())
        );
    }
}
