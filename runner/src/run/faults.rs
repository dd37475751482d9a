//! Faults of an implementation's answers (an extra answer line, an answer naming another case,
//! one that cannot be read): the cases they name become Crash, in the batch at hand or in earlier
//! ones, and a protocol violation is never taken for a flake.

use super::Ctx;
use crate::backend::{Backend, CaseAnswer};
use crate::events::Event;
use crate::records::Outcome;

/// Makes the cases of a batch (`ids`, in the order of `outcomes`) that a fault names Crash, with
/// the fault's message.
pub(super) fn blame_in_batch(
    ids: &[&str],
    outcomes: &mut [CaseAnswer],
    faults: &[(String, String)],
) {
    for (sent, outcome) in ids.iter().zip(outcomes.iter_mut()) {
        if let Some((_, msg)) = faults.iter().find(|(id, _)| id == sent) {
            *outcome = CaseAnswer::Crash(msg.clone());
        }
    }
}

/// Faults the backend found since its last batch (a stray line read after the answers it
/// expected): the tests they name, lookups or state cases, become Crash.
pub(super) fn collect_late_faults(backend: &mut dyn Backend, ctx: &mut Ctx<'_>) {
    let faults = backend.take_faults();
    if faults.is_empty() {
        return;
    }
    let name = backend.name().to_string();
    blame_earlier(ctx, &name, &[], &faults);
    for d in backend.take_diagnostics() {
        ctx.fanout.emit(&Event::Diagnostic {
            backend: &name,
            message: &d,
        });
    }
    ctx.fanout.emit(&Event::BatchFinished { backend: &name });
}

/// Whether a Crash's reason is a protocol violation of the implementation (an extra answer line,
/// an answer that cannot be read or answers another case; also of one sweep point of the case):
/// a fact about what it wrote, which a re-run that goes well does not undo.
pub(super) fn is_protocol_violation(reason: Option<&str>) -> bool {
    let Some(mut r) = reason else { return false };
    if let Some(rest) = r.strip_prefix("sweep point ") {
        r = rest.split_once(": ").map_or(rest, |(_, after)| after);
    }
    r.starts_with(crate::backend::exec::PROTOCOL_ERROR)
}

/// Makes the tests of earlier batches that a fault names Crash (a later answer line showed their
/// implementation misbehaving), and sends them again with that status (the last record of a test in
/// results.jsonl wins). `ids`: the cases of the current batch, blamed there instead.
pub(super) fn blame_earlier(
    ctx: &mut Ctx<'_>,
    backend: &str,
    ids: &[&str],
    faults: &[(String, String)],
) {
    for (id, msg) in faults {
        if ids.contains(&id.as_str()) {
            continue;
        }
        for i in 0..ctx.results.len() {
            let r = &mut ctx.results[i];
            if r.backend != backend || r.case_id != *id || r.outcome == Outcome::Crash {
                continue;
            }
            r.outcome = Outcome::Crash;
            r.status = ctx
                .settings
                .lists
                .status(&r.backend, &r.test, Outcome::Crash)
                .0;
            r.reason = Some(msg.clone());
            r.observed = None;
            r.expected = None;
            r.footprint = None;
            let r = r.clone();
            ctx.fanout.emit(&Event::CaseFinished {
                result: &r,
                replayed: false,
            });
        }
    }
}
