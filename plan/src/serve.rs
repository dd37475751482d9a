//! The protocol loop of a worker process (runner/PROTOCOL.md): requests read and parsed on a
//! thread of their own, a group at a time; cases batched until `flush` and run by the worker
//! behind the loop ([`Serve`]: the GL worker, or the WebGL one), which answers each lookup, sweep
//! points included; the points' answers folded into their case's ([`crate::sweep::merge`]); one
//! answer per case, in order.

use crate::Answer;
use shadowcheck_model::StateObserved;
use shadowcheck_model::{Case, StateCase};
use shadowcheck_protocol::{
    Capabilities, Hello, PathSkip, Reply, Request, StateResult, Support, PROTOCOL_VERSION,
};
use std::io::{BufRead, Write};

fn answer_message(case_id: String, a: Answer) -> Reply {
    match a {
        Answer::Observation(results, skipped) => Reply::Observation {
            case_id,
            results,
            skipped,
        },
        Answer::Skip(reason) => Reply::Skip { case_id, reason },
        Answer::Error(message) => Reply::Error { case_id, message },
    }
}

/// An entry of the batch: a parsed case, or a line that should have been one (unparsable, or
/// a case that is not valid), which still gets its one answer (an error), in order.
enum Entry {
    Case(Box<Case>),
    State(Box<StateCase>),
    Bad { id: String, message: String },
}

fn write_line(out: &mut impl Write, msg: &Reply) -> std::io::Result<()> {
    serde_json::to_writer(&mut *out, msg).map_err(std::io::Error::other)?;
    out.write_all(b"\n")
}

/// Where each answer of a batch comes from, in order.
enum Slot {
    Lookup(String),
    State(Box<StateCase>),
    Bad(String, String),
}

fn flush_batch(
    worker: &mut impl Serve,
    batch: &mut Vec<Entry>,
    out: &mut impl Write,
) -> std::io::Result<()> {
    // Move the cases out; keep where each answer goes (a case id, or a parse error).
    let mut cases: Vec<Case> = Vec::new();
    let mut slots: Vec<Slot> = Vec::new();
    for e in batch.drain(..) {
        match e {
            Entry::Case(c) => {
                slots.push(Slot::Lookup(c.id.clone()));
                cases.push(*c);
            }
            Entry::State(c) => slots.push(Slot::State(c)),
            Entry::Bad { id, message } => slots.push(Slot::Bad(id, message)),
        }
    }
    let mut points = cases
        .iter()
        .map(|c| c.sweep.len())
        .collect::<Vec<_>>()
        .into_iter();
    // A batch with no lookup (state cases only, or the empty one at `bye`) draws nothing.
    let answers = if cases.is_empty() {
        vec![]
    } else {
        worker.draw_batch(cases)?
    };
    let mut answers = answers.into_iter();
    let mut next = || {
        answers
            .next()
            .unwrap_or(Answer::Error("internal: missing answer".into()))
    };
    for slot in slots {
        let msg = match slot {
            Slot::State(c) => worker.answer_state(&c)?,
            Slot::Lookup(id) => {
                let main = next();
                let n = points.next().unwrap_or(0);
                let swept: Vec<Answer> = (0..n).map(|_| next()).collect();
                answer_message(id, crate::sweep::merge(main, swept))
            }
            Slot::Bad(id, message) => Reply::Error {
                case_id: id,
                message,
            },
        };
        write_line(out, &msg)?;
    }
    out.flush()
}

/// A worker behind the protocol loop: its hello, and the answers for a batch (in order). An `Err`
/// ends the loop without answering (the process exits and the runner's crash handling takes over:
/// the implementation itself is gone, e.g. a browser that died).
pub trait Serve {
    fn hello(&self) -> Hello;
    /// One answer per lookup, in order: each case's own, then each point of its sweep
    /// ([`crate::sweep::jobs`], or [`crate::sweep::expand`] for a worker sent whole cases).
    fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>>;
    /// The answer to a state case. An implementation that does not declare the `tex_parameter`
    /// feature is never sent one; if it is, it answers Skip.
    fn run_state(&mut self, case: &StateCase) -> Reply {
        Reply::Skip {
            case_id: case.id.clone(),
            reason: "this implementation runs no state cases".into(),
        }
    }
    /// What the loop answers to a state case: [`Serve::run_state`]'s reply. A worker that can
    /// lose its implementation during a state case (the WebGL worker's lost context) overrides
    /// this one: an `Err` ends the loop without answering, as from [`Serve::draw_batch`].
    fn answer_state(&mut self, case: &StateCase) -> std::io::Result<Reply> {
        Ok(self.run_state(case))
    }
}

/// A request line as the reader thread hands it over.
enum Incoming {
    /// An entry of the batch: a case (validated here) or a line that should have been one.
    Entry(Entry),
    Hello {
        protocol: u32,
    },
    Flush,
    Bye,
    /// Any other line that does not parse.
    Unknown(String),
}

fn incoming(line: &str) -> Incoming {
    match Request::parse(line) {
        // A case is checked here, once with its sweep (not once per point after expansion).
        Ok(Request::Case { case }) => {
            Incoming::Entry(match shadowcheck_model::validate::validate(&case) {
                Ok(()) => Entry::Case(case),
                Err(e) => Entry::Bad {
                    id: case.id.clone(),
                    message: format!("invalid case: {e}"),
                },
            })
        }
        Ok(Request::State { case }) => Incoming::Entry(Entry::State(case)),
        Ok(Request::Hello { protocol }) => Incoming::Hello { protocol },
        Ok(Request::Flush) => Incoming::Flush,
        Ok(Request::Bye) => Incoming::Bye,
        Err(e) => {
            let v: Option<serde_json::Value> = serde_json::from_str(line).ok();
            let is_case = v
                .as_ref()
                .and_then(|v| v.get("type"))
                .and_then(|t| t.as_str())
                .filter(|t| *t == "case" || *t == "state");
            match is_case {
                Some(ty) => Incoming::Entry(Entry::Bad {
                    id: v
                        .as_ref()
                        .and_then(|v| v.pointer(&format!("/{ty}/id")))
                        .and_then(|i| i.as_str())
                        .unwrap_or("")
                        .to_string(),
                    message: format!("cannot parse case: {e}"),
                }),
                None => Incoming::Unknown(e),
            }
        }
    }
}

/// Groups parsed ahead of the loop that answers them, at most this many.
const READ_AHEAD: usize = 8;

/// Speaks the protocol on `input`/`output` until `bye` or end of input. Lines are read and parsed
/// on a thread of their own, so that the next group is parsed while this one is drawn.
pub fn serve(
    worker: &mut impl Serve,
    input: impl BufRead + Send + 'static,
    mut output: impl Write,
) -> std::io::Result<()> {
    // Handed over a group at a time (up to and including its `flush`): one wake-up per group.
    let (tx, rx) = std::sync::mpsc::sync_channel::<Vec<std::io::Result<Incoming>>>(READ_AHEAD);
    // Not joined: at `bye` the loop returns while the reader may still wait for end of input.
    std::thread::spawn(move || {
        let mut group = Vec::new();
        for line in input.lines() {
            let item = match line {
                Ok(l) if l.trim().is_empty() => continue,
                Ok(l) => Ok(incoming(&l)),
                Err(e) => Err(e),
            };
            // A group ends at anything but an entry (`flush`, mostly) or a read error.
            let stop = item.is_err();
            let end = !matches!(item, Ok(Incoming::Entry(_)));
            group.push(item);
            if end && (tx.send(std::mem::take(&mut group)).is_err() || stop) {
                return;
            }
        }
        let _ = tx.send(group);
    });
    let mut batch: Vec<Entry> = Vec::new();
    for item in rx.into_iter().flatten() {
        match item? {
            Incoming::Entry(e) => batch.push(e),
            Incoming::Hello { protocol } => {
                if protocol != 0 && protocol != PROTOCOL_VERSION {
                    eprintln!(
                        "worker: runner speaks protocol {protocol}, this worker {PROTOCOL_VERSION}"
                    );
                }
                // Every worker behind the loop runs sweeps (`Serve::draw_batch`).
                let hello = Reply::Hello(Hello {
                    sweeps: true,
                    ..worker.hello()
                });
                write_line(&mut output, &hello)?;
                output.flush()?;
            }
            Incoming::Flush => flush_batch(worker, &mut batch, &mut output)?,
            Incoming::Bye => break,
            Incoming::Unknown(e) => eprintln!("worker: ignoring unknown message: {e}"),
        }
    }
    flush_batch(worker, &mut batch, &mut output)
}

/// The answer to a state case on a context with `caps`: Skip (with the reason) when the case does
/// not run here or its spec is not exposed (`unexposed`), else what `observe` saw, for each API path
/// that runs here.
pub fn state_reply(
    caps: &Capabilities,
    unexposed: Option<String>,
    case: &StateCase,
    observe: impl FnOnce(&StateCase) -> StateObserved,
) -> Reply {
    let case_id = case.id.clone();
    let (apis, others) = match caps.support_state(case) {
        Support::Skip(reason) | Support::NotApplicable(reason) => {
            return Reply::Skip { case_id, reason }
        }
        Support::Run { apis, others } => (apis, others),
    };
    if let Some(reason) = unexposed {
        return Reply::Skip { case_id, reason };
    }
    let observed = observe(case);
    let skipped = case
        .api
        .iter()
        .filter(|a| !apis.contains(a))
        .map(|a| PathSkip {
            api: a.key().to_string(),
            reason: others.clone().unwrap_or_default(),
        })
        .collect();
    Reply::StateObservation {
        case_id,
        results: apis
            .iter()
            .map(|a| StateResult {
                api: a.key().to_string(),
                observed: observed.clone(),
            })
            .collect(),
        skipped,
    }
}

/// A worker's batch as its capabilities admit it ([`Capabilities::support`], the runner's own
/// decision before sending): the cases it draws, their API paths cut to those it runs; per lookup
/// of the batch (a case's own, then its sweep points) a Skip answered at once or `None` (drawn);
/// per drawn case the paths it leaves out.
pub struct Admission {
    pub runnable: Vec<Case>,
    pub early: Vec<Option<Answer>>,
    pub left_out: Vec<Vec<PathSkip>>,
}

/// Admits `cases` by `caps` ([`Admission`]).
pub fn admit(caps: &Capabilities, cases: Vec<Case>) -> Admission {
    let mut a = Admission {
        runnable: Vec::new(),
        early: Vec::new(),
        left_out: Vec::new(),
    };
    for mut c in cases {
        match caps.support(&c) {
            Support::Skip(r) | Support::NotApplicable(r) => a
                .early
                .extend((0..c.lookup_count()).map(|_| Some(Answer::Skip(r.clone())))),
            Support::Run { apis, others } => {
                let skips = c
                    .api
                    .iter()
                    .filter(|x| !apis.contains(x))
                    .map(|x| PathSkip {
                        api: x.key().to_string(),
                        reason: others.clone().unwrap_or_default(),
                    })
                    .collect();
                c.api = apis;
                a.early.extend((0..c.lookup_count()).map(|_| None));
                a.left_out.push(skips);
                a.runnable.push(c);
            }
        }
    }
    a
}

/// Every lookup's answer in the batch's order: its early Skip, else the next of `drawn` (the
/// answers to `jobs`, [`crate::sweep::jobs`] of the admitted cases, in order; `None`: none came,
/// an internal error). The paths a case leaves out go with the answer to its own lookup.
pub fn assemble(
    early: Vec<Option<Answer>>,
    left_out: Vec<Vec<PathSkip>>,
    jobs: &[crate::sweep::Job<'_>],
    drawn: Vec<Option<Answer>>,
) -> Vec<Answer> {
    let missing = || Answer::Error("internal: missing answer".into());
    let mut skips = left_out.into_iter();
    let mut drawn =
        drawn
            .into_iter()
            .zip(jobs)
            .map(|(a, j)| match (a.unwrap_or_else(missing), j.point) {
                (Answer::Observation(r, mut s), false) => {
                    s.extend(skips.next().unwrap_or_default());
                    Answer::Observation(r, s)
                }
                (other, false) => {
                    skips.next();
                    other
                }
                (other, true) => other,
            });
    early
        .into_iter()
        .map(|a| a.or_else(|| drawn.next()).unwrap_or_else(missing))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_model::Target;
    use shadowcheck_protocol::Capabilities;

    /// Answers every case it is given with a skip naming it, and records the batches.
    struct Echo(Vec<usize>);

    impl Serve for Echo {
        fn hello(&self) -> Hello {
            Hello {
                protocol: PROTOCOL_VERSION,
                name: None,
                capabilities: Capabilities::default(),
                wants_expect: false,
                sweeps: false,
            }
        }
        fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
            self.0.push(cases.len());
            Ok(cases
                .iter()
                .flat_map(|c| (0..c.lookup_count()).map(|_| Answer::Skip(c.id.clone())))
                .collect())
        }
    }

    /// What the loop writes for `input`, a JSON value per line.
    fn answer_lines(worker: &mut impl Serve, input: Vec<u8>) -> Vec<serde_json::Value> {
        let mut out = Vec::new();
        serve(worker, std::io::Cursor::new(input), &mut out).unwrap();
        String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect()
    }

    /// Answers lookup k of its life with R = k on the `core` path.
    struct Numbered(f64);

    impl Serve for Numbered {
        fn hello(&self) -> Hello {
            Echo(vec![]).hello()
        }
        fn draw_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>> {
            let n: usize = cases.iter().map(Case::lookup_count).sum();
            Ok((0..n)
                .map(|_| {
                    self.0 += 1.0;
                    let r = shadowcheck_protocol::PathResult {
                        api: "core".into(),
                        rgba: shadowcheck_protocol::Rgba([self.0 - 1.0, 0.0, 0.0, 1.0]),
                        stored: None,
                        note: None,
                        sweep: vec![],
                    };
                    Answer::Observation(vec![r], vec![])
                })
                .collect())
        }
    }

    #[test]
    fn a_workers_answers_for_sweep_points_fold_into_their_case_and_the_next_case_keeps_its_own() {
        let mut swept = crate::test_case::case(Target::T2d, 2, 2, 1);
        swept.id = "swept".into();
        swept.sweep = (0..2)
            .map(|k| shadowcheck_model::SweepPoint {
                coord: [0.25, 0.5, 0.0, 1.0],
                dref: 0.25 * k as f64,
                expect: None,
            })
            .collect();
        let mut plain = crate::test_case::case(Target::T2d, 2, 2, 1);
        plain.id = "plain".into();
        let mut input = Request::hello_line().into_bytes();
        input.push(b'\n');
        for c in [&swept, &plain] {
            Request::write_case_on(&mut input, c, &c.api, false);
            input.push(b'\n');
        }
        input.extend_from_slice(Request::FLUSH_LINE);
        input.extend_from_slice(Request::BYE_LINE);
        let lines = answer_lines(&mut Numbered(0.0), input);
        assert_eq!(lines.len(), 3, "{lines:?}");
        // Lookups 0 (the case's own), 1 and 2 (its points) are the first case's; 3 the next's.
        let r = &lines[1]["results"][0];
        assert_eq!(
            (&lines[1]["case_id"], &r["rgba"][0]),
            (&"swept".into(), &0.0.into())
        );
        let sweep: Vec<f64> = r["sweep"]
            .as_array()
            .expect("sweep")
            .iter()
            .map(|p| p[0].as_f64().unwrap_or(-1.0))
            .collect();
        assert_eq!(sweep, vec![1.0, 2.0]);
        let r = &lines[2]["results"][0];
        assert_eq!(
            (&lines[2]["case_id"], &r["rgba"][0]),
            (&"plain".into(), &3.0.into())
        );
    }

    #[test]
    fn each_line_of_a_group_gets_one_answer_in_order_invalid_and_unparsable_cases_included() {
        let mut good = crate::test_case::case(Target::T2d, 2, 2, 1);
        good.id = "good".into();
        let mut invalid = good.clone();
        invalid.id = "invalid".into();
        invalid.api.clear();
        let mut input = Request::hello_line().into_bytes();
        input.push(b'\n');
        for c in [&good, &invalid] {
            Request::write_case_on(&mut input, c, &c.api, false);
            input.push(b'\n');
        }
        input.extend_from_slice(b"{\"type\":\"case\",\"case\":{\"id\":\"broken\"}}\n");
        input.extend_from_slice(b"{\"type\":\"no-such-message\"}\n");
        input.extend_from_slice(Request::FLUSH_LINE);
        input.extend_from_slice(Request::BYE_LINE);
        let mut worker = Echo(vec![]);
        let lines = answer_lines(&mut worker, input);
        // The hello, then one answer per case line, in order; the unknown line gets none.
        assert_eq!(lines.len(), 4, "{lines:?}");
        assert_eq!(lines[0]["type"], "hello");
        assert_eq!(lines[0]["sweeps"], true, "the loop answers sweeps");
        assert_eq!(
            (&lines[1]["type"], &lines[1]["case_id"]),
            (&"skip".into(), &"good".into())
        );
        assert_eq!(
            (&lines[2]["type"], &lines[2]["case_id"]),
            (&"error".into(), &"invalid".into())
        );
        assert!(lines[2]["message"]
            .as_str()
            .unwrap()
            .starts_with("invalid case:"));
        assert_eq!(
            (&lines[3]["type"], &lines[3]["case_id"]),
            (&"error".into(), &"broken".into())
        );
        assert!(lines[3]["message"]
            .as_str()
            .unwrap()
            .starts_with("cannot parse case:"));
        // Only the valid case reached the worker, in one batch.
        assert_eq!(worker.0, vec![1]);
    }
}
