//! The protocol loop of a worker process (runner/PROTOCOL.md): requests read and parsed on a
//! thread of their own, a group at a time; cases batched until `flush`, their sweeps expanded
//! ([`super::sweep`]) and run by the worker behind the loop ([`Serve`]: the GL worker, or the
//! WebGL one); one answer per case, in order.

use super::draw::Answer;
use shadowcheck_model::{Case, StateCase};
use shadowcheck_protocol::{Hello, Reply, Request, PROTOCOL_VERSION};
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

/// An entry of the batch: a parsed case, or a line that should have been one.
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
    let (cases, points) = super::sweep::expand(cases);
    let mut points = points.into_iter();
    let mut answers = worker.run_batch(cases)?.into_iter();
    let mut next = || {
        answers
            .next()
            .unwrap_or(Answer::Error("internal: missing answer".into()))
    };
    for slot in slots {
        let msg = match slot {
            Slot::State(c) => worker.run_state(&c),
            Slot::Lookup(id) => {
                let main = next();
                let n = points.next().unwrap_or(0);
                let swept: Vec<Answer> = (0..n).map(|_| next()).collect();
                answer_message(id, super::sweep::merge(main, swept))
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
    fn run_batch(&mut self, cases: Vec<Case>) -> std::io::Result<Vec<Answer>>;
    /// The answer to a state case. An implementation that does not declare the `tex_parameter`
    /// feature is never sent one; if it is, it answers Skip.
    fn run_state(&mut self, case: &StateCase) -> Reply {
        Reply::Skip {
            case_id: case.id.clone(),
            reason: "this implementation runs no state cases".into(),
        }
    }
}

/// A request line as the reader thread hands it over: parsed, or why not.
enum Incoming {
    Request(Request),
    /// A case line that does not parse: it still gets its one answer, in order.
    Bad {
        id: String,
        message: String,
    },
    /// Any other line that does not parse.
    Unknown(String),
}

fn incoming(line: &str) -> Incoming {
    match Request::parse(line) {
        // A case is checked here, once with its sweep (not once per point after expansion).
        Ok(Request::Case { case }) => match shadowcheck_model::validate::validate(&case) {
            Ok(()) => Incoming::Request(Request::Case { case }),
            Err(e) => Incoming::Bad {
                id: case.id.clone(),
                message: format!("invalid case: {e}"),
            },
        },
        Ok(r) => Incoming::Request(r),
        Err(e) => {
            let v: Option<serde_json::Value> = serde_json::from_str(line).ok();
            let is_case = v
                .as_ref()
                .and_then(|v| v.get("type"))
                .and_then(|t| t.as_str())
                .filter(|t| *t == "case" || *t == "state");
            match is_case {
                Some(ty) => Incoming::Bad {
                    id: v
                        .as_ref()
                        .and_then(|v| v.pointer(&format!("/{ty}/id")))
                        .and_then(|i| i.as_str())
                        .unwrap_or("")
                        .to_string(),
                    message: format!("cannot parse case: {e}"),
                },
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
            let end = !matches!(item, Ok(Incoming::Request(Request::Case { .. })))
                && !matches!(item, Ok(Incoming::Request(Request::State { .. })));
            let stop = item.is_err();
            group.push(item);
            if end && tx.send(std::mem::take(&mut group)).is_err() || stop {
                return;
            }
        }
        let _ = tx.send(group);
    });
    let mut batch: Vec<Entry> = Vec::new();
    for item in rx.into_iter().flatten() {
        match item? {
            Incoming::Request(Request::Hello { protocol }) => {
                if protocol != 0 && protocol != PROTOCOL_VERSION {
                    eprintln!(
                        "worker: runner speaks protocol {protocol}, this worker {PROTOCOL_VERSION}"
                    );
                }
                // Sweeps are expanded here, whatever the worker behind the loop.
                let hello = Reply::Hello(Hello {
                    sweeps: true,
                    ..worker.hello()
                });
                write_line(&mut output, &hello)?;
                output.flush()?;
            }
            Incoming::Request(Request::Case { case }) => batch.push(Entry::Case(case)),
            Incoming::Request(Request::State { case }) => batch.push(Entry::State(case)),
            Incoming::Request(Request::Flush) => flush_batch(worker, &mut batch, &mut output)?,
            Incoming::Request(Request::Bye) => break,
            Incoming::Bad { id, message } => batch.push(Entry::Bad { id, message }),
            Incoming::Unknown(e) => eprintln!("worker: ignoring unknown message: {e}"),
        }
    }
    flush_batch(worker, &mut batch, &mut output)
}
