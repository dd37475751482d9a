//! From an implementation's answer line ([`Reply`]) to the [`CaseAnswer`] of the case it answers
//! (PROTOCOL.md "Answers"): every API path of the case gets exactly one result or skip; a path
//! left out, given two results, or not in the case makes the case the implementation's error.

use super::{ApiAnswer, CaseAnswer};
use shadowcheck_model::{ApiPath, Case, StateCase};
use shadowcheck_protocol::{PathResult, PathSkip, Reply, StateResult};

/// The [`CaseAnswer`] for `case`, sent with API paths `api`, from its answer.
pub fn to_answer(case: &Case, api: &[ApiPath], a: Reply) -> CaseAnswer {
    match a {
        Reply::Observation { results, .. }
            if results.iter().any(|r| r.sweep.len() != case.sweep.len()) =>
        {
            let r = results.iter().find(|r| r.sweep.len() != case.sweep.len());
            CaseAnswer::Error(format!(
                "{} sweep results for API path `{}`; the case has {} points",
                r.map_or(0, |r| r.sweep.len()),
                r.map_or("", |r| r.api.as_str()),
                case.sweep.len()
            ))
        }
        Reply::Observation {
            results, skipped, ..
        } => collect(
            api,
            results
                .into_iter()
                .map(
                    |PathResult {
                         api,
                         rgba,
                         stored,
                         sweep,
                         ..
                     }| {
                        let outcome = ApiAnswer::Rgba {
                            rgba: rgba.0,
                            stored,
                            sweep: sweep.into_iter().map(|p| p.0).collect(),
                        };
                        (api, outcome)
                    },
                )
                .collect(),
            skipped,
        ),
        Reply::StateObservation { .. } => {
            CaseAnswer::Error("a state observation answering a lookup case".into())
        }
        other => common(other),
    }
}

/// The [`CaseAnswer`] for a state case from its reply (`state_observation`), by the same rules.
pub fn to_state_answer(case: &StateCase, a: Reply) -> CaseAnswer {
    match a {
        Reply::StateObservation {
            results, skipped, ..
        } => collect(
            &case.api,
            results
                .into_iter()
                .map(|StateResult { api, observed }| (api, ApiAnswer::State(observed)))
                .collect(),
            skipped,
        ),
        Reply::Observation { .. } => {
            CaseAnswer::Error("a lookup observation answering a state case".into())
        }
        other => common(other),
    }
}

/// Answers that mean the same for both kinds of case.
fn common(a: Reply) -> CaseAnswer {
    match a {
        Reply::Skip { reason, .. } => CaseAnswer::Skip(reason),
        Reply::Error { message, .. } => CaseAnswer::Error(message),
        // parse_answer never returns a hello.
        _ => CaseAnswer::Error("a hello where an answer was expected".into()),
    }
}

/// Every path of `case_api` gets exactly one result or skip.
fn collect(
    case_api: &[ApiPath],
    results: Vec<(String, ApiAnswer)>,
    skipped: Vec<PathSkip>,
) -> CaseAnswer {
    let mut v = Vec::with_capacity(results.len() + skipped.len());
    for (api, outcome) in results {
        match ApiPath::from_key(&api) {
            Some(a) if v.iter().any(|(p, _)| *p == a) => {
                return CaseAnswer::Error(format!("two results for API path `{api}`"))
            }
            Some(a) if case_api.contains(&a) => v.push((a, outcome)),
            _ => {
                return CaseAnswer::Error(format!(
                    "result for API path `{api}`, which the case does not have"
                ))
            }
        }
    }
    // A path both answered and listed as skipped keeps its result (judged, never hidden).
    for PathSkip { api, reason } in skipped {
        match ApiPath::from_key(&api) {
            Some(a) if case_api.contains(&a) => {
                if !v.iter().any(|(p, _)| *p == a) {
                    v.push((a, ApiAnswer::Skip(reason)));
                }
            }
            _ => {
                return CaseAnswer::Error(format!(
                    "skipped API path `{api}`, which the case does not have"
                ))
            }
        }
    }
    // Every path sent is answered or skipped: a path left out is the implementation's error
    // (never a silent Skip).
    if let Some(a) = case_api.iter().find(|a| !v.iter().any(|(p, _)| p == *a)) {
        return CaseAnswer::Error(format!(
            "neither a result nor a skip for API path `{}`",
            a.key()
        ));
    }
    CaseAnswer::Observed(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A case with the compat paths (ff, glsl120) of a GL 4.6 2D lookup; only `api` matters here.
    fn compat_case() -> Case {
        let json = r#"{"id":"x","spec":"gl46","api":["ff","glsl120"],"texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]},"lookup":{"coord":[0.5,0.5,0,1],"dref":0.5}}"#;
        serde_json::from_str(json).unwrap()
    }

    #[test]
    fn skipped_paths_become_skip_with_the_implementations_reason() {
        let case = compat_case();
        let line = r#"{"type":"observation","case_id":"x","results":[{"api":"glsl120","rgba":[1,1,1,1],"note":"shadow2D"}],"skipped":[{"api":"ff","reason":"fixed-function has no cube arrays"}]}"#;
        let out = to_answer(&case, &case.api, Reply::parse_answer(line).unwrap());
        let CaseAnswer::Observed(v) = out else {
            panic!("{out:?}")
        };
        assert!(matches!(
            v.iter().find(|(a, _)| *a == ApiPath::Glsl120),
            Some((_, ApiAnswer::Rgba { .. }))
        ));
        match v.iter().find(|(a, _)| *a == ApiPath::FixedFunction) {
            Some((_, ApiAnswer::Skip(m))) => assert_eq!(m, "fixed-function has no cube arrays"),
            other => panic!("{other:?}"),
        }
        // A skipped path the case does not have is the implementation's error, as a stray result is.
        let bad = r#"{"type":"observation","case_id":"x","results":[],"skipped":[{"api":"core","reason":"no"}]}"#;
        assert!(matches!(
            to_answer(&case, &case.api, Reply::parse_answer(bad).unwrap()),
            CaseAnswer::Error(_)
        ));
        // An answered path that is also listed keeps its result.
        let both = r#"{"type":"observation","case_id":"x","results":[{"api":"ff","rgba":[0,0,0,1]}],"skipped":[{"api":"ff","reason":"no"},{"api":"glsl120","reason":"no"}]}"#;
        let CaseAnswer::Observed(v) =
            to_answer(&case, &case.api, Reply::parse_answer(both).unwrap())
        else {
            panic!()
        };
        assert_eq!(v.len(), 2);
        assert!(matches!(v[0].1, ApiAnswer::Rgba { .. }));
    }

    #[test]
    fn two_results_for_one_path_and_paths_left_out_are_the_implementations_error() {
        let case = compat_case();
        let error =
            |line: &str| match to_answer(&case, &case.api, Reply::parse_answer(line).unwrap()) {
                CaseAnswer::Error(m) => m,
                other => panic!("{other:?}"),
            };
        let dup = r#"{"type":"observation","case_id":"x","results":[{"api":"ff","rgba":[0,0,0,1]},{"api":"glsl120","rgba":[0,0,0,1]},{"api":"ff","rgba":[1,1,1,1]}]}"#;
        assert_eq!(error(dup), "two results for API path `ff`");
        let empty = r#"{"type":"observation","case_id":"x","results":[]}"#;
        assert_eq!(
            error(empty),
            "neither a result nor a skip for API path `ff`"
        );
        let partial =
            r#"{"type":"observation","case_id":"x","results":[{"api":"ff","rgba":[0,0,0,1]}]}"#;
        assert_eq!(
            error(partial),
            "neither a result nor a skip for API path `glsl120`"
        );
    }
}
