//! State cases in a run: the same path as lookups (not applicable / resumed / skips list / Skip by
//! capabilities / sent in batches / judged / given a status by the lists), judged by
//! [`crate::state_verdict`]. State calls are deterministic, so their regressions are not re-run.

use super::{CaseSet, Ctx, LoadedState};
use crate::backend::{ApiAnswer, Backend, CaseAnswer, Support};
use crate::events::{Event, Timing};
use crate::interrupt;
use crate::records::{Outcome, Results, Status, Tags, TestResult};
use shadowcheck_model::{ApiPath, StateCase};
use shadowcheck_protocol::Capabilities;
use std::time::Instant;

/// The API paths of `case` that are tests of a backend with `caps`, and the Skip reason for all
/// of them; `None` when none is applicable.
pub(super) fn applicable(
    caps: &Capabilities,
    case: &StateCase,
) -> Option<(Vec<ApiPath>, Option<String>)> {
    match caps.support_state(case) {
        Support::NotApplicable(_) => None,
        Support::Skip(reason) => {
            let apis = case.api.iter().copied().filter(|a| caps.implements_api(*a));
            Some((apis.collect(), Some(reason)))
        }
        Support::Run { apis, .. } => Some((apis, None)),
    }
}

/// The grid tags of a state case: spec and target; the lookup dimensions are `-`.
pub fn tags(case: &StateCase) -> Tags {
    Tags {
        spec: case.spec.key().to_string(),
        target: case.target.key().to_string(),
        format: "-".into(),
        func: "-".into(),
        filter: "-".into(),
    }
}

fn base(backend: &str, case: &StateCase, api: ApiPath, fixtures: Option<&str>) -> TestResult {
    TestResult {
        backend: backend.to_string(),
        test: TestResult::name(&case.id, api),
        case_id: case.id.clone(),
        api,
        status: Status::Plain(Outcome::Skip),
        outcome: Outcome::Skip,
        reason: None,
        duration: 0.0,
        tags: tags(case),
        observed: None,
        expected: None,
        footprint: None,
        rerun: None,
        fixtures: fixtures.map(str::to_string),
    }
}

/// The test results of `case`'s API paths, judged against the expectation that applies on a
/// backend exposing `extensions` (its hello's `capabilities.extensions`).
fn judge(
    backend: &str,
    extensions: &[String],
    case: &StateCase,
    outcome: &CaseAnswer,
    duration: f64,
    fixtures: Option<&str>,
) -> Vec<TestResult> {
    case.api
        .iter()
        .map(|&api| {
            let mut r = base(backend, case, api, fixtures);
            r.duration = duration;
            let (o, reason) = match super::judge::path_answer(outcome, api) {
                Err(settled) => settled,
                Ok(ApiAnswer::Skip(m)) => (Outcome::Skip, Some(m.clone())),
                Ok(ApiAnswer::State(obs)) => {
                    crate::state_verdict::judge_state(case, obs, extensions)
                }
                Ok(ApiAnswer::Rgba { .. }) => (
                    Outcome::Fail,
                    Some("the backend answered a state case with a lookup result".into()),
                ),
            };
            r.outcome = o;
            r.reason = reason;
            r
        })
        .collect()
}

/// Runs the selected state cases on one backend (after its lookups).
pub(super) fn run_states(
    backend: &mut dyn Backend,
    set: &CaseSet,
    prior: &Results,
    ctx: &mut Ctx<'_>,
    timing: &mut Timing,
) {
    let name = backend.name().to_string();
    // The extensions the backend reported: they decide which of a state case's expectations
    // applies (`StateExpect::with_extension`).
    let extensions = backend.capabilities().extensions.clone();
    let lists = &ctx.settings.lists;
    let file_of = |l: &LoadedState| {
        ctx.settings
            .explicit_fixtures
            .then(|| set.files[l.file].clone())
    };
    let mut to_send: Vec<(StateCase, Option<String>)> = Vec::new();
    let mut finished = Vec::new();
    for l in &set.states {
        let case = &l.case;
        let fixtures = file_of(l);
        let Some((apis, skip_reason)) = applicable(backend.capabilities(), case) else {
            continue;
        };
        let done: Vec<&TestResult> = apis
            .iter()
            .filter_map(|&a| prior.get(&name, &TestResult::name(&case.id, a)))
            .collect();
        if done.len() == apis.len() {
            finished.extend(done.into_iter().map(|r| (r.clone(), true)));
            continue;
        }
        let mut send = Vec::new();
        for &api in &apis {
            let test = TestResult::name(&case.id, api);
            let reason = match (lists.skips.matching_for(&name, &test), &skip_reason) {
                (Some(re), _) => Some(format!("skips list: `{re}`")),
                (None, Some(why)) => Some(why.clone()),
                (None, None) => None,
            };
            match reason {
                Some(why) => {
                    let mut r = base(&name, case, api, fixtures.as_deref());
                    r.reason = Some(why);
                    finished.push((r, false));
                }
                None => send.push(api),
            }
        }
        if !send.is_empty() {
            to_send.push((
                StateCase {
                    api: send,
                    ..case.clone()
                },
                fixtures,
            ));
        }
    }
    for (r, replayed) in finished {
        ctx.finish(r, replayed);
    }
    for chunk in to_send.chunks(backend.batch_size().max(1)) {
        if interrupt::requested() {
            break;
        }
        let refs: Vec<&StateCase> = chunk.iter().map(|(c, _)| c).collect();
        let t0 = Instant::now();
        let mut outcomes = backend.answer_state_batch(&refs);
        if interrupt::requested() {
            break;
        }
        // Faults found while this batch was read count as a lookup batch's do: a second answer
        // for a state case of this batch makes it Crash; one for a test finished earlier (a state
        // case, or a lookup whose extra answer came late) makes that test Crash again.
        let faults = backend.take_faults();
        let ids: Vec<&str> = refs.iter().map(|c| c.id.as_str()).collect();
        super::blame_in_batch(&ids, &mut outcomes, &faults);
        super::blame_earlier(ctx, &name, &ids, &faults);
        let dt = t0.elapsed().as_secs_f64();
        timing.backend_s += dt;
        timing.cases_sent += refs.len();
        let per_case = dt / refs.len() as f64;
        let missing = CaseAnswer::Crash("the backend gave no answer".into());
        for ((case, fixtures), outcome) in chunk
            .iter()
            .zip(outcomes.iter().chain(std::iter::repeat(&missing)))
        {
            for mut r in judge(
                &name,
                &extensions,
                case,
                outcome,
                per_case,
                fixtures.as_deref(),
            ) {
                let (status, note) = ctx.settings.lists.status(&name, &r.test, r.outcome);
                r.status = status;
                if let Some(n) = note {
                    r.reason = Some(match r.reason.take() {
                        Some(old) => format!("{old}; {n}"),
                        None => n,
                    });
                }
                ctx.finish(r, false);
            }
        }
        for d in backend.take_diagnostics() {
            ctx.fanout.emit(&Event::Diagnostic {
                backend: &name,
                message: &d,
            });
        }
        ctx.fanout.emit(&Event::BatchFinished { backend: &name });
    }
}
