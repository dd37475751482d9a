//! The run: cases in, events out.
//!
//! For each backend: API paths (or whole cases) whose spec or path the backend does not implement
//! are no tests of it (not applicable: counted apart, no record); cases already finished in a
//! resumed run are replayed; the skips list and the backend's capabilities turn the rest into Skip
//! (with the reason) or a case to send; cases go to the backend in batches (the next one sent
//! ahead, [`Backend::send_ahead`]), each answer is judged ([`judge`], beside the next batch),
//! given its final status by the lists ([`crate::baseline`]) and sent as a `CaseFinished` event
//! (results.jsonl is written by a reporter, written per batch). Regressions are then re-run once:
//! a different outcome is a Flake, unless a Crash or Timeout recurred during the re-run. Faults a
//! backend finds later (a second answer for a case) make that case Crash, re-sent as a new record.
//! Once the run is interrupted ([`crate::interrupt`]) no batch is sent, of the batch in flight
//! only the cases answered whole are kept, and no re-run is made.

use crate::backend::{Backend, CaseAnswer, Sent, Support};
use crate::baseline::Lists;
use crate::events::{Event, Fanout, Sink, Timing};
use crate::interrupt;
use crate::records::{Counts, LoadError, Outcome, Results, Status, Summary, Tags, TestResult};
use crate::shard::Shard;
use judge::{finish_judged, judge_batch, judge_outcome, sent, Judged, ToSend};
use shadowcheck_model::{ApiPath, Case, StateCase};
use shadowcheck_protocol::Capabilities;
use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Instant;
use to_send::{cases_to_send, in_program_order};

/// A case and the fixture file it came from.
#[derive(Debug, Clone)]
pub struct Loaded {
    pub case: Case,
    pub file: usize,
}

/// A state case and the fixture file it came from.
#[derive(Debug, Clone)]
pub struct LoadedState {
    pub case: StateCase,
    pub file: usize,
}

/// The cases of a run and what went wrong loading them.
#[derive(Debug, Default)]
pub struct CaseSet {
    pub files: Vec<String>,
    pub cases: Vec<Loaded>,
    /// TexParameter state cases (`state_cases` of the fixture files).
    pub states: Vec<LoadedState>,
    pub errors: Vec<LoadError>,
}

/// Loads every fixture under `paths`. Bad files and bad cases become [`LoadError`]s naming file and
/// case; everything else loads. A case id seen twice keeps its first occurrence.
pub fn load_cases(paths: &[PathBuf]) -> CaseSet {
    let mut set = CaseSet::default();
    let mut seen: HashMap<String, usize> = HashMap::new();
    for root in paths {
        let files = match shadowcheck_cases::fixtures::fixture_paths(root) {
            Ok(f) => f,
            Err(e) => {
                set.errors.push(LoadError {
                    file: root.display().to_string(),
                    case: None,
                    message: e.to_string(),
                });
                continue;
            }
        };
        for path in files {
            let file = path.display().to_string();
            match shadowcheck_cases::fixtures::load_file_lenient(&path) {
                Ok((ff, errs)) => {
                    for e in errs {
                        let case = e.case_id().map(str::to_string);
                        set.errors.push(LoadError {
                            file: file.clone(),
                            case,
                            message: e.to_string(),
                        });
                    }
                    let idx = set.files.len();
                    set.files.push(file.clone());
                    for case in ff.cases {
                        if let Some(&first) = seen.get(&case.id) {
                            set.errors.push(LoadError {
                                file: file.clone(),
                                case: Some(case.id.clone()),
                                message: format!(
                                    "duplicate case id (first in {})",
                                    set.files[first]
                                ),
                            });
                            continue;
                        }
                        seen.insert(case.id.clone(), idx);
                        set.cases.push(Loaded { case, file: idx });
                    }
                    for case in ff.state_cases {
                        if let Some(&first) = seen.get(&case.id) {
                            set.errors.push(LoadError {
                                file: file.clone(),
                                case: Some(case.id.clone()),
                                message: format!(
                                    "duplicate case id (first in {})",
                                    set.files[first]
                                ),
                            });
                            continue;
                        }
                        seen.insert(case.id.clone(), idx);
                        set.states.push(LoadedState { case, file: idx });
                    }
                }
                Err(e) => set.errors.push(LoadError {
                    file,
                    case: None,
                    message: e.to_string(),
                }),
            }
        }
    }
    set
}

impl CaseSet {
    /// Keeps the cases whose id matches `pattern` and that belong to `shard`.
    pub fn select(&mut self, pattern: Option<&regex::Regex>, shard: Option<Shard>) {
        let keep = |id: &str| {
            pattern.is_none_or(|p| p.is_match(id)) && shard.is_none_or(|s| s.contains(id))
        };
        self.cases.retain(|l| keep(&l.case.id));
        self.states.retain(|l| keep(&l.case.id));
    }
    pub fn tests(&self) -> usize {
        self.cases.iter().map(|l| l.case.api.len()).sum::<usize>()
            + self.states.iter().map(|l| l.case.api.len()).sum::<usize>()
    }
    /// The tests of this set on a backend with `caps`: `(tests, not applicable)`. A case's API
    /// paths, or the whole case, whose spec or path the backend does not implement are no tests
    /// of it ([`Support::NotApplicable`]); they are counted apart, outside the test count and the
    /// progress bar.
    pub fn tests_on(&self, caps: &Capabilities) -> (usize, usize) {
        let mut n = (0, 0);
        for l in &self.cases {
            let applicable = applicable_apis(caps, &l.case).map_or(0, |(a, _)| a.len());
            n.0 += applicable;
            n.1 += l.case.api.len() - applicable;
        }
        for l in &self.states {
            let applicable = state::applicable(caps, &l.case).map_or(0, |(a, _)| a.len());
            n.0 += applicable;
            n.1 += l.case.api.len() - applicable;
        }
        n
    }
    /// The names (`<case id>@<api>`) of the tests of this set on a backend with `caps`, with the
    /// id of their case, in set order: the tests [`CaseSet::tests_on`] counts (Skips by
    /// capabilities included), the not-applicable ones left out.
    pub fn test_names_on(&self, caps: &Capabilities) -> Vec<(&str, String)> {
        let mut out = Vec::new();
        for l in &self.cases {
            if let Some((apis, _)) = applicable_apis(caps, &l.case) {
                out.extend(
                    apis.iter()
                        .map(|&a| (l.case.id.as_str(), TestResult::name(&l.case.id, a))),
                );
            }
        }
        for l in &self.states {
            if let Some((apis, _)) = state::applicable(caps, &l.case) {
                out.extend(
                    apis.iter()
                        .map(|&a| (l.case.id.as_str(), TestResult::name(&l.case.id, a))),
                );
            }
        }
        out
    }
}

impl CaseSet {
    /// Distinct (API path, compiled sampler state) pairs among the cases a backend with `caps`
    /// runs: how many shader variants a driver that bakes the sampler state into its code
    /// (llvmpipe, lavapipe) compiles for this set ([`shadowcheck_cases::coverage::state_key`]).
    pub fn compiled_states_on(&self, caps: &Capabilities) -> usize {
        let mut seen = std::collections::HashSet::new();
        for l in &self.cases {
            if let Some((apis, None)) = applicable_apis(caps, &l.case) {
                let key = shadowcheck_cases::coverage::state_key(&l.case);
                for a in apis {
                    seen.insert((a, key.clone()));
                }
            }
        }
        seen.len()
    }
}

/// The API paths of `case` that are tests of a backend with `caps`, and the reason to Skip them
/// all when the backend lacks the case's target or format; `None` when none is applicable.
fn applicable_apis(caps: &Capabilities, case: &Case) -> Option<(Vec<ApiPath>, Option<String>)> {
    match caps.support(case) {
        Support::NotApplicable(_) => None,
        Support::Skip(reason) => {
            let apis = case.api.iter().copied().filter(|a| caps.implements_api(*a));
            Some((apis.collect(), Some(reason)))
        }
        Support::Run { apis, .. } => Some((apis, None)),
    }
}

/// How the run behaves.
#[derive(Debug, Default)]
pub struct Settings {
    pub lists: Lists,
    /// Re-run regressions once to detect flakes (deqp-runner does; on by default).
    pub rerun_regressions: bool,
    /// Fixtures were named on the command line: the re-run command of a test names its file.
    pub explicit_fixtures: bool,
    /// Close each backend when its run is done ([`Backend::close`]), its last stderr lines (a
    /// GL worker's stats) emitted as diagnostics: `shadowcheck run` does; a caller that runs
    /// the same backend again (the bench's warm passes) does not.
    pub close_backends: bool,
}

struct Ctx<'a> {
    settings: &'a Settings,
    fanout: &'a mut dyn Sink,
    results: Vec<TestResult>,
}

impl Ctx<'_> {
    fn finish(&mut self, r: TestResult, replayed: bool) {
        self.fanout.emit(&Event::CaseFinished {
            result: &r,
            replayed,
        });
        self.results.push(r);
    }
}

fn base_result(backend: &str, case: &Case, api: ApiPath, fixtures: Option<&str>) -> TestResult {
    TestResult {
        backend: backend.to_string(),
        test: TestResult::name(&case.id, api),
        case_id: case.id.clone(),
        api,
        status: Status::Plain(Outcome::Skip),
        outcome: Outcome::Skip,
        reason: None,
        duration: 0.0,
        tags: Tags::of(case),
        observed: None,
        expected: None,
        footprint: None,
        rerun: None,
        fixtures: fixtures.map(str::to_string),
    }
}

/// Runs the selected cases on one backend. `prior`: results of a resumed run (replayed, not re-run).
pub fn run_backend(
    backend: &mut dyn Backend,
    set: &CaseSet,
    prior: &Results,
    settings: &Settings,
    fanout: &mut dyn Sink,
) -> (Vec<TestResult>, Timing) {
    let name = backend.name().to_string();
    let mut ctx = Ctx {
        settings,
        fanout,
        results: Vec::with_capacity(set.tests()),
    };
    let mut timing = Timing::default();
    let (tests, not_applicable) = set.tests_on(backend.capabilities());
    ctx.fanout.emit(&Event::BackendStarted {
        backend: &name,
        tests,
        not_applicable,
    });
    let mut to_send = cases_to_send(backend.capabilities(), &name, set, prior, &mut ctx);
    if backend.compiles_per_state() {
        to_send = in_program_order(to_send);
    }
    send_and_judge(
        backend,
        &name,
        &to_send,
        &settings.lists,
        &mut ctx,
        &mut timing,
    );
    state::run_states(backend, set, prior, &mut ctx, &mut timing);
    // A fault found after the last batch (an extra answer line read since) is a Crash before the
    // re-run, so it is not re-run as a flake; one found during the re-run, after it.
    collect_late_faults(backend, &mut ctx);
    if settings.rerun_regressions && !interrupt::requested() {
        rerun_regressions(backend, set, &mut ctx);
        collect_late_faults(backend, &mut ctx);
    }
    if settings.close_backends {
        for d in backend.close() {
            ctx.fanout.emit(&Event::Diagnostic {
                backend: &name,
                message: &d,
            });
        }
    }
    let mut counts = Counts::default();
    for r in &ctx.results {
        counts.add(r.status);
    }
    counts.not_applicable = not_applicable;
    ctx.fanout.emit(&Event::BackendFinished {
        backend: &name,
        counts: &counts,
        timing: &timing,
    });
    (ctx.results, timing)
}

/// Sends `to_send` to the backend in batches and finishes each case's tests from its answer, in
/// order. Each batch's answers are judged on a second thread while the backend runs the next batch
/// (its process works meanwhile, with the batch after that already sent), then finished here in
/// order: results and events come out as they would one batch at a time. Once the run is
/// interrupted, the batch in flight keeps the answers that came back and nothing more is sent.
fn send_and_judge(
    backend: &mut dyn Backend,
    name: &str,
    to_send: &[ToSend<'_>],
    lists: &Lists,
    ctx: &mut Ctx<'_>,
    timing: &mut Timing,
) {
    let batch = backend.batch_size().max(1);
    std::thread::scope(|scope| {
        let mut judging: Option<std::thread::ScopedJoinHandle<'_, Judged>> = None;
        let chunks: Vec<&[ToSend<'_>]> = to_send.chunks(batch).collect();
        for (k, chunk) in chunks.iter().copied().enumerate() {
            if interrupt::requested() {
                break;
            }
            let mut refs = sent(chunk);
            // The batch after this one is announced before this one runs (two in flight).
            if let Some(next) = chunks.get(k + 1) {
                backend.send_ahead(&refs, &sent(next));
            }
            let t0 = Instant::now();
            let mut answers = backend.answer_batch(&refs);
            let interrupted = interrupt::requested();
            let mut chunk = chunk;
            if interrupted {
                // Only the answers that came back are kept (once interrupted, a backend answers
                // a prefix: its processes may have been signalled too); `--resume` sends the rest.
                answers.truncate(refs.len());
                refs.truncate(answers.len());
                chunk = &chunk[..refs.len()];
            }
            let dt = t0.elapsed().as_secs_f64();
            timing.backend_s += dt;
            timing.cases_sent += refs.len();
            if refs.is_empty() {
                break;
            }
            // The batch before this one, judged meanwhile, is finished before any fault of this
            // batch can name one of its cases.
            finish_judged(ctx, name, judging.take(), timing);
            let faults = backend.take_faults();
            let ids: Vec<&str> = refs.iter().map(|c| c.case.id.as_str()).collect();
            blame_in_batch(&ids, &mut answers, &faults);
            blame_earlier(ctx, name, &ids, &faults);
            for d in backend.take_diagnostics() {
                ctx.fanout.emit(&Event::Diagnostic {
                    backend: name,
                    message: &d,
                });
            }
            let per_case = dt / refs.len() as f64;
            judging = Some(
                scope.spawn(move || judge_batch(name, lists, &refs, chunk, &answers, per_case)),
            );
            if interrupted {
                break;
            }
        }
        finish_judged(ctx, name, judging.take(), timing);
    });
}

/// Re-runs the cases of regressions not yet re-run; a test whose outcome changes is a Flake
/// (deqp-runner's and nextest's rule). A Crash or Timeout is not a flake when the implementation
/// crashed or hung again during the re-run, on any case: the failure recurred.
fn rerun_regressions(backend: &mut dyn Backend, set: &CaseSet, ctx: &mut Ctx<'_>) {
    let name = backend.name().to_string();
    let mut by_case: HashMap<&str, Vec<usize>> = HashMap::new();
    for (i, r) in ctx.results.iter().enumerate() {
        // A protocol violation is never a flake: it happened, whatever a re-run answers.
        let violation = r.outcome == Outcome::Crash && is_protocol_violation(r.reason.as_deref());
        if r.status.is_regression() && r.rerun.is_none() && !violation {
            by_case.entry(r.case_id.as_str()).or_default().push(i);
        }
    }
    if by_case.is_empty() {
        return;
    }
    // The same narrowing as the first run: only the API paths that regressed.
    let cases: Vec<_> = set
        .cases
        .iter()
        .filter_map(|l| {
            let idx = by_case.get(l.case.id.as_str())?;
            let apis: Vec<ApiPath> = idx.iter().map(|&i| ctx.results[i].api).collect();
            let file = ctx
                .settings
                .explicit_fixtures
                .then(|| set.files[l.file].as_str());
            Some((&l.case, apis, idx.clone(), file))
        })
        .collect();
    let refs: Vec<Sent<'_>> = cases
        .iter()
        .map(|(case, api, _, _)| Sent { case, api })
        .collect();
    let (answers, earlier) = answer_again(backend, &refs);
    if interrupt::requested() {
        return;
    }
    let recurred = refs.iter().zip(&answers).find_map(|(c, o)| {
        matches!(o, CaseAnswer::Crash(_) | CaseAnswer::Timeout(_)).then_some(c.case.id.as_str())
    });
    for d in backend.take_diagnostics() {
        ctx.fanout.emit(&Event::Diagnostic {
            backend: &name,
            message: &d,
        });
    }
    for ((sent, (_, _, idx, file)), answer) in refs.iter().zip(&cases).zip(answers.iter()) {
        let again = judge_outcome(&name, *sent, answer, 0.0, *file);
        for (&i, second) in idx.iter().zip(again) {
            mark_rerun(&mut ctx.results[i], second.outcome, recurred);
            let r = ctx.results[i].clone();
            ctx.fanout.emit(&Event::CaseFinished {
                result: &r,
                replayed: false,
            });
        }
    }
    // Faults the re-run found on cases it did not send (their extra answers came late).
    blame_earlier(ctx, &name, &[], &earlier);
    ctx.fanout.emit(&Event::BatchFinished { backend: &name });
}

/// Sends `refs` to the backend again, in batches: the answers, with the faults found on each batch
/// blamed on its cases, and the faults that name cases of earlier batches (extra answers that came
/// late).
fn answer_again(
    backend: &mut dyn Backend,
    refs: &[Sent<'_>],
) -> (Vec<CaseAnswer>, Vec<(String, String)>) {
    let mut answers = Vec::with_capacity(refs.len());
    let mut earlier = Vec::new();
    for chunk in refs.chunks(backend.batch_size().max(1)) {
        let mut got = backend.answer_batch(chunk);
        let ids: Vec<&str> = chunk.iter().map(|c| c.case.id.as_str()).collect();
        let faults = backend.take_faults();
        blame_in_batch(&ids, &mut got, &faults);
        earlier.extend(
            faults
                .into_iter()
                .filter(|(id, _)| !ids.contains(&id.as_str())),
        );
        answers.extend(got);
    }
    (answers, earlier)
}

/// Records the re-run's outcome `second` on the regression `r`: a changed outcome makes it a Flake,
/// except a Crash or Timeout while the implementation crashed or hung again in the re-run (on the
/// case `recurred`), which stays, with the reason saying so.
fn mark_rerun(r: &mut TestResult, second: Outcome, recurred: Option<&str>) {
    r.rerun = Some(second);
    let died = matches!(r.outcome, Outcome::Crash | Outcome::Timeout);
    if let (true, Some(on)) = (died && second != r.outcome, recurred) {
        r.reason = Some(format!(
            "{}; re-run gave {}, but the implementation crashed or hung again in the re-run (on `{on}`): not a flake",
            r.reason.clone().unwrap_or_default(),
            second
        ));
    } else if second != r.outcome {
        r.status = Status::Flake;
        r.reason = Some(format!(
            "{}; re-run gave {}",
            r.reason.clone().unwrap_or_default(),
            second
        ));
    }
}

/// Results in report order: by backend, then by test name.
pub fn sort_results(results: &mut [TestResult]) {
    results.sort_by(|a, b| {
        (a.backend.as_str(), a.test.as_str()).cmp(&(b.backend.as_str(), b.test.as_str()))
    });
}

/// Sorts, totals and announces the end of a run (shared with `merge`). `not_applicable`: the
/// count of not-applicable tests ([`CaseSet::tests_on`]; `merge` adds up its inputs' counts).
pub fn finish(
    backends: Vec<String>,
    results: &mut [TestResult],
    errors: &[LoadError],
    not_applicable: usize,
    fanout: &mut Fanout,
) -> Summary {
    sort_results(results);
    let mut summary = Summary::new(backends, results, errors.len());
    summary.counts.not_applicable = not_applicable;
    fanout.emit(&Event::RunFinished {
        results,
        load_errors: errors,
        summary: &summary,
    });
    summary
}

mod faults;
mod judge;
mod state;
mod to_send;

use faults::{blame_earlier, blame_in_batch, collect_late_faults, is_protocol_violation};
pub use state::tags as state_tags;

#[cfg(test)]
mod tests;
