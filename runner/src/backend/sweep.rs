//! Sweep cases on a backend that runs none (its hello has no `sweeps`, PROTOCOL.md §2): the case
//! is sent without its sweep, each point after it as a case of its own (`<id>/sweep=<k>`), and
//! the outcomes are folded back into one outcome per case, the points' RGBA in each path's
//! `sweep`. A point that does not come back observed on every path its case was observed on
//! decides the case's outcome, naming the point.

use super::{ApiOutcome, CaseOutcome, Sent};
use shadowcheck_model::Case;

/// Runs `cases` through `run`, sweeps expanded, and folds the outcomes back (one per case, in
/// order).
pub fn run_expanded(
    cases: &[Sent<'_>],
    run: impl FnOnce(&[Sent<'_>]) -> Vec<CaseOutcome>,
) -> Vec<CaseOutcome> {
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
            .unwrap_or_else(|| CaseOutcome::Error("internal: missing outcome".into()))
    };
    let mut folded = Vec::with_capacity(cases.len());
    for c in cases {
        let n = 1 + c.case.sweep.len();
        if answered < n && crate::interrupt::requested() {
            // An interrupted run gets the cases answered whole, a prefix (`Backend::run_batch`).
            break;
        }
        answered = answered.saturating_sub(n);
        let main = next();
        let points: Vec<CaseOutcome> = (0..c.case.sweep.len()).map(|_| next()).collect();
        folded.push(merge(main, points));
    }
    folded
}

/// Folds the outcomes of a case's points into the outcome of its own lookup.
pub fn merge(main: CaseOutcome, points: Vec<CaseOutcome>) -> CaseOutcome {
    let CaseOutcome::Observed(mut paths) = main else {
        return main;
    };
    for (k, point) in points.into_iter().enumerate() {
        let observed = match point {
            CaseOutcome::Observed(v) => v,
            CaseOutcome::Skip(why) => {
                return CaseOutcome::Error(format!("sweep point {k} skipped: {why}"))
            }
            CaseOutcome::Error(e) => return CaseOutcome::Error(format!("sweep point {k}: {e}")),
            CaseOutcome::Crash(e) => return CaseOutcome::Crash(format!("sweep point {k}: {e}")),
            CaseOutcome::Timeout(e) => {
                return CaseOutcome::Timeout(format!("sweep point {k}: {e}"))
            }
        };
        for (api, out) in paths.iter_mut() {
            let ApiOutcome::Rgba { sweep, .. } = out else {
                continue;
            };
            match observed.iter().find(|(a, _)| a == api) {
                Some((_, ApiOutcome::Rgba { rgba, .. })) => sweep.push(*rgba),
                _ => {
                    return CaseOutcome::Error(format!(
                        "sweep point {k}: not observed on API path `{}`",
                        api.key()
                    ))
                }
            }
        }
    }
    CaseOutcome::Observed(paths)
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::ApiPath;

    fn observed(v: f64) -> CaseOutcome {
        CaseOutcome::Observed(vec![(
            ApiPath::GlslCore,
            ApiOutcome::Rgba {
                rgba: [v, 0.0, 0.0, 1.0],
                stored: None,
                sweep: vec![],
            },
        )])
    }

    #[test]
    fn points_fold_into_their_case_and_a_lost_point_names_itself() {
        let CaseOutcome::Observed(paths) = merge(observed(1.0), vec![observed(0.0), observed(0.5)])
        else {
            panic!("not observed")
        };
        let ApiOutcome::Rgba { rgba, sweep, .. } = &paths[0].1 else {
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
                vec![observed(0.0), CaseOutcome::Crash("SIGSEGV".into())]
            ),
            CaseOutcome::Crash("sweep point 1: SIGSEGV".into())
        );
        assert_eq!(
            merge(observed(1.0), vec![CaseOutcome::Observed(vec![])]),
            CaseOutcome::Error("sweep point 0: not observed on API path `core`".into())
        );
    }
}
