//! From a backend's answers to test results: each API path of each case sent is judged
//! ([`crate::verdict`]) and given its final status by the lists ([`crate::baseline`]); a batch is
//! judged on a thread of its own while the backend runs the next one, and finished in order.

use super::{base_result, Ctx};
use crate::backend::{ApiAnswer, CaseAnswer, Sent};
use crate::baseline::Lists;
use crate::events::{Event, Timing};
use crate::records::{Outcome, TestResult};
use crate::verdict;
use shadowcheck_model::{ApiPath, Case};
use shadowcheck_protocol::Rgba;
use std::borrow::Cow;
use std::time::Instant;

/// The raw outcome of each API path of `sent` from the backend's answer.
pub(super) fn judge_outcome(
    backend: &str,
    sent: Sent<'_>,
    outcome: &CaseAnswer,
    duration: f64,
    fixtures: Option<&str>,
) -> Vec<TestResult> {
    let case = sent.case;
    sent.api
        .iter()
        .map(|&api| {
            let mut r = base_result(backend, case, api, fixtures);
            r.duration = duration;
            let (o, reason) = match path_answer(outcome, api) {
                Err(settled) => settled,
                Ok(ApiAnswer::Skip(m)) => (Outcome::Skip, Some(m.clone())),
                Ok(ApiAnswer::State(_)) => (
                    Outcome::Fail,
                    Some("the backend answered a lookup case with a state result".into()),
                ),
                Ok(ApiAnswer::Rgba {
                    rgba,
                    stored,
                    sweep,
                }) => {
                    let (j, shown) = verdict::judge_sweep(case, api, *rgba, stored.as_ref(), sweep);
                    r.observed = Some(Rgba(shown));
                    r.expected = j.expected;
                    r.footprint = j.footprint;
                    (j.outcome, j.reason)
                }
            };
            r.outcome = o;
            r.reason = reason;
            r
        })
        .collect()
}

/// What the backend answered for `api`, or the outcome and reason the case's answer already
/// settles: Skip, an implementation error (Fail), Crash, Timeout, or no result for the path
/// (Fail). Lookup and state cases share it.
pub(super) fn path_answer(
    outcome: &CaseAnswer,
    api: ApiPath,
) -> Result<&ApiAnswer, (Outcome, Option<String>)> {
    match outcome {
        CaseAnswer::Skip(m) => Err((Outcome::Skip, Some(m.clone()))),
        CaseAnswer::Error(m) => Err((Outcome::Fail, Some(format!("implementation error: {m}")))),
        CaseAnswer::Crash(m) => Err((Outcome::Crash, Some(m.clone()))),
        CaseAnswer::Timeout(m) => Err((Outcome::Timeout, Some(m.clone()))),
        CaseAnswer::Observed(v) => match v.iter().find(|(a, _)| *a == api).map(|(_, o)| o) {
            None => Err((
                Outcome::Fail,
                Some("the backend returned no result for this API path".to_string()),
            )),
            Some(o) => Ok(o),
        },
    }
}

/// A case to send, the API paths it is a test of on the backend (borrowed when all of its own),
/// and its fixture file when named on the command line.
pub(super) type ToSend<'a> = (&'a Case, Cow<'a, [ApiPath]>, Option<&'a str>);

/// What a backend is sent for `chunk`.
pub(super) fn sent<'a>(chunk: &'a [ToSend<'a>]) -> Vec<Sent<'a>> {
    chunk
        .iter()
        .map(|(case, api, _)| Sent { case, api })
        .collect()
}

/// A batch's results as judged on the judging thread, and the seconds that took.
pub(super) type Judged = (Vec<TestResult>, f64);

/// Judges a batch: every test of every case sent, with its final status from the lists.
pub(super) fn judge_batch(
    name: &str,
    lists: &Lists,
    refs: &[Sent<'_>],
    chunk: &[ToSend<'_>],
    outcomes: &[CaseAnswer],
    per_case: f64,
) -> Judged {
    let t = Instant::now();
    let missing = CaseAnswer::Crash("the backend gave no answer".into());
    let mut out = Vec::with_capacity(refs.len() * 2);
    for ((sent, (_, _, fixtures)), outcome) in refs
        .iter()
        .zip(chunk)
        .zip(outcomes.iter().chain(std::iter::repeat(&missing)))
    {
        for mut r in judge_outcome(name, *sent, outcome, per_case, *fixtures) {
            let (status, note) = lists.status(name, &r.test, r.outcome);
            r.status = status;
            if let Some(n) = note {
                r.reason = Some(match r.reason.take() {
                    Some(old) => format!("{old}; {n}"),
                    None => n,
                });
            }
            out.push(r);
        }
    }
    (out, t.elapsed().as_secs_f64())
}

/// Finishes a judged batch in order (events, results), once its judging thread is done.
pub(super) fn finish_judged(
    ctx: &mut Ctx<'_>,
    name: &str,
    judging: Option<std::thread::ScopedJoinHandle<'_, Judged>>,
    timing: &mut Timing,
) {
    let Some(h) = judging else { return };
    let t = Instant::now();
    let (results, judge_s) = match h.join() {
        Ok(j) => j,
        // A panic while judging is a bug: it propagates as it would have on this thread.
        Err(p) => std::panic::resume_unwind(p),
    };
    for r in results {
        ctx.finish(r, false);
    }
    ctx.fanout.emit(&Event::BatchFinished { backend: name });
    timing.verdict_s += judge_s + t.elapsed().as_secs_f64();
}
