//! Scheduling the backends of a run: one after another, or several at once (`shadowcheck run
//! --jobs N`), each on its own thread, its events travelling over a channel to the calling thread,
//! which alone owns the reporters. Results are the
//! same as a sequential run (the final report is sorted; results.jsonl is keyed by backend and
//! test, so the interleaving of its lines does not matter).

use crate::backend::Backend;
use crate::events::{Event, Fanout, Sink, Timing};
use crate::records::Summary;
use crate::records::{Counts, Results, TestResult};
use crate::run::{finish, run_backend, CaseSet, Settings};
use std::collections::VecDeque;
use std::path::Path;
use std::sync::mpsc::{self, Sender};
use std::sync::Mutex;

/// Runs every backend over `set` (up to `jobs` backends at once, each in its own thread; the
/// reporters stay on this thread) and finishes the run (sorted results, summary, `RunFinished`).
pub fn run_all(
    backends: &mut [Box<dyn Backend>],
    set: &CaseSet,
    prior: &Results,
    settings: &Settings,
    fanout: &mut Fanout,
    out_dir: &Path,
    jobs: usize,
) -> (Vec<TestResult>, Summary, Vec<Timing>) {
    let names: Vec<String> = backends.iter().map(|b| b.name().to_string()).collect();
    // Not-applicable tests are outside the test count and the progress bar.
    let (tests, not_applicable) = backends
        .iter()
        .map(|b| set.tests_on(b.capabilities()))
        .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    fanout.emit(&Event::RunStarted {
        backends: &names,
        tests,
        out_dir,
    });
    for e in &set.errors {
        fanout.emit(&Event::LoadError(e));
    }
    let per_backend = if jobs <= 1 || backends.len() <= 1 {
        backends
            .iter_mut()
            .map(|b| run_backend(b.as_mut(), set, prior, settings, fanout))
            .collect()
    } else {
        run_backends(backends, set, prior, settings, fanout, jobs)
    };
    let mut all = Vec::new();
    let mut timings = Vec::new();
    for (r, t) in per_backend {
        all.extend(r);
        timings.push(t);
    }
    let summary = finish(names, &mut all, &set.errors, not_applicable, fanout);
    (all, summary, timings)
}

/// An event with owned data, as sent between threads (the events a backend run emits).
enum Owned {
    BackendStarted {
        backend: String,
        tests: usize,
        not_applicable: usize,
    },
    Diagnostic {
        backend: String,
        message: String,
    },
    CaseFinished {
        result: Box<TestResult>,
        replayed: bool,
    },
    BatchFinished {
        backend: String,
    },
    BackendFinished {
        backend: String,
        counts: Counts,
        timing: Timing,
    },
}

struct ChannelSink(Sender<Owned>);

impl Sink for ChannelSink {
    fn emit(&mut self, ev: &Event<'_>) {
        let owned = match ev {
            Event::BackendStarted {
                backend,
                tests,
                not_applicable,
            } => Owned::BackendStarted {
                backend: backend.to_string(),
                tests: *tests,
                not_applicable: *not_applicable,
            },
            Event::Diagnostic { backend, message } => Owned::Diagnostic {
                backend: backend.to_string(),
                message: message.to_string(),
            },
            Event::CaseFinished { result, replayed } => Owned::CaseFinished {
                result: Box::new((*result).clone()),
                replayed: *replayed,
            },
            Event::BatchFinished { backend } => Owned::BatchFinished {
                backend: backend.to_string(),
            },
            Event::BackendFinished {
                backend,
                counts,
                timing,
            } => Owned::BackendFinished {
                backend: backend.to_string(),
                counts: (*counts).clone(),
                timing: (*timing).clone(),
            },
            // Run-level events are emitted by the calling thread only.
            Event::RunStarted { .. } | Event::LoadError(_) | Event::RunFinished { .. } => return,
        };
        // The receiver lives until every backend thread has ended.
        let _ = self.0.send(owned);
    }
}

fn forward(fanout: &mut Fanout, m: &Owned) {
    match m {
        Owned::BackendStarted {
            backend,
            tests,
            not_applicable,
        } => fanout.emit(&Event::BackendStarted {
            backend,
            tests: *tests,
            not_applicable: *not_applicable,
        }),
        Owned::Diagnostic { backend, message } => {
            fanout.emit(&Event::Diagnostic { backend, message })
        }
        Owned::CaseFinished { result, replayed } => fanout.emit(&Event::CaseFinished {
            result,
            replayed: *replayed,
        }),
        Owned::BatchFinished { backend } => fanout.emit(&Event::BatchFinished { backend }),
        Owned::BackendFinished {
            backend,
            counts,
            timing,
        } => fanout.emit(&Event::BackendFinished {
            backend,
            counts,
            timing,
        }),
    }
}

/// Seconds a compilation of one shader variant takes on llvmpipe / lavapipe (reports/BENCH.md,
/// `compile_ms_per_variant`: 24-27 ms on these machines); only the ratio to [`PER_TEST_S`] matters.
const COMPILE_S: f64 = 25e-3;
/// Seconds of harness and driver work per test once its variant exists (reports/BENCH.md: about
/// 30 us per check on llvmpipe, `gl_warm_us_per_check`).
const PER_TEST_S: f64 = 30e-6;

/// Estimated seconds of a cold run of `b` over `set`: a compilation per distinct (API path, sampler
/// state) on a backend that compiles per state, plus the per-test cost. Orders the queue only.
fn estimated_cost(b: &dyn Backend, set: &CaseSet) -> f64 {
    let caps = b.capabilities();
    let (tests, _) = set.tests_on(caps);
    let compile = if b.compiles_per_state() {
        set.compiled_states_on(caps) as f64 * COMPILE_S
    } else {
        0.0
    };
    compile + tests as f64 * PER_TEST_S
}

/// Runs `backends` on up to `jobs` threads; returns each backend's results, in `backends` order.
pub fn run_backends(
    backends: &mut [Box<dyn Backend>],
    set: &CaseSet,
    prior: &Results,
    settings: &Settings,
    fanout: &mut Fanout,
    jobs: usize,
) -> Vec<(Vec<TestResult>, Timing)> {
    let n = backends.len();
    // Longest first (LPT): a cold run's time is mostly compilation, so a compile-heavy backend
    // started last would leave the other threads idle while it finishes alone.
    let mut order: Vec<(usize, f64)> = backends
        .iter()
        .map(|b| estimated_cost(b.as_ref(), set))
        .enumerate()
        .collect();
    order.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut slots: Vec<Option<&mut Box<dyn Backend>>> = backends.iter_mut().map(Some).collect();
    let queue: Mutex<VecDeque<(usize, &mut Box<dyn Backend>)>> = Mutex::new(
        order
            .iter()
            .filter_map(|&(i, _)| slots[i].take().map(|b| (i, b)))
            .collect(),
    );
    type Finished = Option<(Vec<TestResult>, Timing)>;
    let done: Mutex<Vec<Finished>> = Mutex::new((0..n).map(|_| None).collect());
    let (tx, rx) = mpsc::channel();
    std::thread::scope(|s| {
        for _ in 0..jobs.min(n) {
            let mut sink = ChannelSink(tx.clone());
            let (queue, done) = (&queue, &done);
            s.spawn(move || loop {
                let next = queue.lock().ok().and_then(|mut q| q.pop_front());
                let Some((i, b)) = next else { break };
                let r = run_backend(b.as_mut(), set, prior, settings, &mut sink);
                if let Ok(mut d) = done.lock() {
                    d[i] = Some(r);
                }
            });
        }
        drop(tx);
        for m in rx {
            forward(fanout, &m);
        }
    });
    done.into_inner()
        .unwrap_or_default()
        .into_iter()
        .map(|r| r.unwrap_or_default())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::backend::CaseAnswer;
    use crate::backend::Sent;
    use shadowcheck_protocol::Capabilities;

    struct Idle {
        caps: Capabilities,
        compiles: bool,
    }

    impl Backend for Idle {
        fn name(&self) -> &str {
            "idle"
        }
        fn capabilities(&self) -> &Capabilities {
            &self.caps
        }
        fn answer_batch(&mut self, cases: &[Sent<'_>]) -> Vec<CaseAnswer> {
            cases
                .iter()
                .map(|_| CaseAnswer::Skip("idle".into()))
                .collect()
        }
        fn compiles_per_state(&self) -> bool {
            self.compiles
        }
    }

    #[test]
    fn a_backend_compiling_per_state_is_estimated_by_its_distinct_states() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures");
        let set = crate::run::load_cases(&[root.join("gl46/2d/nearest.json")]);
        assert!(set.errors.is_empty(), "{:?}", set.errors);
        let caps = Capabilities::default();
        let (tests, _) = set.tests_on(&caps);
        // Distinct (path, state) pairs, counted independently of the runner's helper.
        let mut pairs = std::collections::BTreeSet::new();
        for l in &set.cases {
            for a in &l.case.api {
                pairs.insert((*a, shadowcheck_cases::coverage::state_key(&l.case)));
            }
        }
        let states = set.compiled_states_on(&caps);
        assert_eq!(states, pairs.len());
        assert!(
            states > 0 && states < tests,
            "{states} states, {tests} tests"
        );
        let heavy = Idle {
            caps: caps.clone(),
            compiles: true,
        };
        let light = Idle {
            caps,
            compiles: false,
        };
        let (h, l) = (estimated_cost(&heavy, &set), estimated_cost(&light, &set));
        assert!(
            (h - l - states as f64 * COMPILE_S).abs() < 1e-9,
            "{h} vs {l}"
        );
        assert!((l - tests as f64 * PER_TEST_S).abs() < 1e-9);
    }
}
