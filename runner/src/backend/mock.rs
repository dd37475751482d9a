//! `mock:<script>`: a scripted implementation for testing the runner itself (in the spirit of
//! deqp-runner's mock suite). It runs as a child process (`shadowcheck mock-worker SCRIPT`) speaking
//! PROTOCOL.md, so crashes and hangs are real.
//!
//! The script is a comma-separated list of `action=REGEX` (REGEX on the case id; `action` alone
//! means every case); the first matching action wins, the default is `pass`:
//! - `pass`: answers a value inside the strict acceptance set, laid out per API path;
//! - `warn`: a value inside quality but outside strict (Fail-level value when there is none; a
//!   sweep point with none answers its strict value);
//! - `fail`: r = -1 (outside every acceptance set);
//! - `skip`: answers skip; `error`: answers an error message;
//! - `crash`: exits with status 3 on reading the case; `hang`: stops answering;
//! - `garbage`: answers a line that is not JSON;
//! - `flaky`: fails the first time it sees the case in this process, passes afterwards;
//! - `extra`: answers the case (as `pass`) twice;
//! - `dup`: one observation with two results for each API path;
//! - `empty`: an observation with `results: []` (and nothing skipped);
//! - `previous`: answers (as `pass`) under the id of the case read before it in this process
//!   (as `pass` when it is the first);
//! - `late`: answers the case (as `pass`), and again just before its answer to the next case it
//!   reads (a second answer that arrives late, e.g. while the state cases are read);
//! - `notutf8`: answers a line that is not UTF-8;
//! - `spew`: writes a 4 MiB line to stderr, then exits as `crash` does.
//!
//! State cases are answered with their expectation; `crash`, `hang`, `garbage`, `extra`,
//! `late`, `previous`, `notutf8` and `spew` act on them as on lookups.
//!
//! Options (same list): `buffer` answers only at `flush` (like a GPU implementation; default is to
//! answer each case as it is read); `slow=MS` sleeps MS milliseconds per case; `crashevery=N`
//! exits on every N-th case it reads, counting across the worker's restarts when
//! `SHADOWCHECK_MOCK_COUNTER=FILE` names a file to keep the count in (else per process);
//! `once` makes `extra`, `late`, `previous`, `garbage` and `notutf8` act only the first time a case
//! arrives (answering as `pass` afterwards), remembered across restarts when
//! `SHADOWCHECK_MOCK_SEEN=FILE` names a file to keep the ids in (else per process): a one-off
//! protocol violation.
//! Environment: `SHADOWCHECK_MOCK_KILL_RUNNER=REGEX` makes the worker SIGKILL its parent (the
//! runner) on the first case whose id matches, to test that a killed run can be resumed;
//! `SHADOWCHECK_MOCK_INTERRUPT_RUNNER=REGEX` sends it SIGINT instead (each time a matching case
//! arrives), as Ctrl-C or a CI job's SIGTERM would.

use regex::Regex;
use shadowcheck_model::{Case, Channel, Profile, StateCase};
use shadowcheck_protocol::{
    Capabilities, Hello, PathResult, Reply, Request, Rgba, PROTOCOL_VERSION,
};
use std::collections::HashSet;
use std::io::{BufRead, Write};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Pass,
    Warn,
    Fail,
    Skip,
    Error,
    Crash,
    Hang,
    Garbage,
    Flaky,
    Extra,
    Dup,
    Empty,
    Previous,
    Late,
    NotUtf8,
    Spew,
}

/// A parsed mock script.
#[derive(Debug, Clone)]
pub struct Script {
    rules: Vec<(Action, Option<Regex>)>,
    pub buffer: bool,
    pub slow_ms: u64,
    /// Exit on every N-th case read (0: never).
    pub crash_every: u64,
    /// Protocol violations only the first time a case arrives.
    pub once: bool,
}

impl Script {
    pub fn parse(s: &str) -> Result<Script, String> {
        let mut script = Script {
            rules: vec![],
            buffer: false,
            slow_ms: 0,
            crash_every: 0,
            once: false,
        };
        for item in s.split(',').map(str::trim).filter(|i| !i.is_empty()) {
            let (key, val) = match item.split_once('=') {
                Some((k, v)) => (k, Some(v)),
                None => (item, None),
            };
            let action = match key {
                "buffer" => {
                    script.buffer = true;
                    continue;
                }
                "once" => {
                    script.once = true;
                    continue;
                }
                "slow" => {
                    script.slow_ms = val
                        .and_then(|v| v.parse().ok())
                        .ok_or("slow=MS needs a number of milliseconds")?;
                    continue;
                }
                "crashevery" => {
                    script.crash_every = val
                        .and_then(|v| v.parse().ok())
                        .filter(|&n| n > 0)
                        .ok_or("crashevery=N needs a positive number of cases")?;
                    continue;
                }
                "pass" => Action::Pass,
                "warn" => Action::Warn,
                "fail" => Action::Fail,
                "skip" => Action::Skip,
                "error" => Action::Error,
                "crash" => Action::Crash,
                "hang" => Action::Hang,
                "garbage" => Action::Garbage,
                "flaky" => Action::Flaky,
                "extra" => Action::Extra,
                "dup" => Action::Dup,
                "empty" => Action::Empty,
                "previous" => Action::Previous,
                "late" => Action::Late,
                "notutf8" => Action::NotUtf8,
                "spew" => Action::Spew,
                other => return Err(format!("unknown mock action `{other}`")),
            };
            let re = val
                .map(|v| Regex::new(v).map_err(|e| format!("mock `{item}`: {e}")))
                .transpose()?;
            script.rules.push((action, re));
        }
        Ok(script)
    }

    pub fn action(&self, id: &str) -> Action {
        self.rules
            .iter()
            .find(|(_, re)| re.as_ref().is_none_or(|r| r.is_match(id)))
            .map(|(a, _)| *a)
            .unwrap_or(Action::Pass)
    }
}

/// The RGBA a path shows for r, per the expectation's layout (unused channels 0).
fn laid_out(case: &Case, api: shadowcheck_model::ApiPath, r: f64) -> [f64; 4] {
    let layout = case
        .expect
        .as_ref()
        .and_then(|e| e.layout.get(&api))
        .copied()
        .unwrap_or([Channel::R; 4]);
    let pass = strict_value(case) == Some(r);
    layout.map(|c| match c {
        Channel::R | Channel::ROrZero => r,
        Channel::One => 1.0,
        Channel::Zero | Channel::Unused => 0.0,
        // A gather component: its own strict value when answering the expectation, else r.
        Channel::G0 | Channel::G1 | Channel::G2 | Channel::G3 => c
            .gather_index()
            .filter(|_| pass)
            .and_then(|k| gather_strict(case, k))
            .unwrap_or(r),
    })
}

/// Gather component `k`'s strict value (its spec value where the strict set holds it).
fn gather_strict(case: &Case, k: usize) -> Option<f64> {
    let e = case.expect.as_ref()?;
    let acc = e.gather.as_ref()?[k].get(&Profile::strictest())?;
    acc.0.first().map(|i| i.lo)
}

fn strict_value(case: &Case) -> Option<f64> {
    let e = case.expect.as_ref()?;
    let acc = e.accept.get(&Profile::strictest())?;
    match e.spec_value {
        Some(v) if acc.contains(v) => Some(v),
        _ => acc.0.first().map(|i| i.lo),
    }
}

fn warn_value(case: &Case) -> Option<f64> {
    let e = case.expect.as_ref()?;
    let (strict, quality) = (
        e.accept.get(&Profile::strictest())?,
        e.accept.get(&Profile::loosest())?,
    );
    quality
        .0
        .iter()
        .flat_map(|i| [i.lo, i.hi, (i.lo + i.hi) / 2.0])
        .find(|v| !strict.contains(*v))
}

fn answer(case: &Case, action: Action, seen: &mut HashSet<String>) -> Reply {
    let id = case.id.clone();
    let value = match action {
        Action::Skip => {
            return Reply::Skip {
                case_id: id,
                reason: "mock: scripted skip".into(),
            }
        }
        Action::Error => {
            return Reply::Error {
                case_id: id,
                message: "mock: scripted error".into(),
            }
        }
        Action::Fail => Some(-1.0),
        // A sweep point (sent as a case of its own: the mock runs no sweeps) with no value
        // between strict and quality answers its strict value, so its test stays a Warn.
        Action::Warn if case.id.contains(shadowcheck_model::SWEEP_ID_TAG) => {
            warn_value(case).or(strict_value(case))
        }
        Action::Warn => warn_value(case).or(Some(-1.0)),
        Action::Flaky if seen.insert(case.id.clone()) => Some(-1.0),
        _ => strict_value(case),
    };
    let Some(r) = value else {
        return Reply::Skip {
            case_id: id,
            reason: "mock: the case carries no expectation to answer from".into(),
        };
    };
    let copies = match action {
        Action::Empty => 0,
        Action::Dup => 2,
        _ => 1,
    };
    let results = case
        .api
        .iter()
        .flat_map(|&a| std::iter::repeat_n(a, copies))
        .map(|a| PathResult {
            sweep: vec![],
            api: a.key().to_string(),
            rgba: Rgba(laid_out(case, a, r)),
            stored: None,
            note: None,
        })
        .collect();
    Reply::Observation {
        case_id: id,
        results,
        skipped: Vec::new(),
    }
}

fn signal_parent(signal: &str) {
    let ppid = std::os::unix::process::parent_id();
    // The shell's builtin `kill` (no procps needed).
    let _ = std::process::Command::new("sh")
        .args(["-c", &format!("kill -{signal} {ppid}")])
        .status();
}

/// A line that is not UTF-8 (0xFF never occurs in UTF-8), for `notutf8`.
const NOT_UTF8: &[u8] = b"{\"type\":\"skip\",\"case_id\":\"\xff\xfe\"}";

/// Whether a case arrives for the first time (for `once`): in the file `seen` names when set
/// (one id a line, kept across the worker's restarts), else in this process's `seen_here`.
fn first_time(
    id: &str,
    seen: Option<&std::path::Path>,
    seen_here: &mut HashSet<String>,
) -> std::io::Result<bool> {
    let Some(f) = seen else {
        return Ok(seen_here.insert(id.to_string()));
    };
    let known = std::fs::read_to_string(f).unwrap_or_default();
    if known.lines().any(|l| l == id) {
        return Ok(false);
    }
    let mut w = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(f)?;
    writeln!(w, "{id}")?;
    Ok(true)
}

/// What the worker does with a case (lookup or state) whose action is `action`, besides
/// answering: `Some(status)` when it exits with that status instead.
fn misbehave(
    action: Action,
    id: &str,
    answer: String,
    previous: Option<&str>,
    pending: &mut Vec<Vec<u8>>,
    deferred: &mut Option<Vec<u8>>,
) -> Option<i32> {
    // A late second answer of the case before goes out just before this case's answer.
    if let Some(late) = deferred.take() {
        pending.push(late);
    }
    match action {
        Action::Crash => {
            crate::errln!("mock: crashing on {id}");
            return Some(3);
        }
        Action::Spew => {
            let mut err = std::io::stderr().lock();
            let _ = err.write_all(&vec![b'x'; 4 << 20]);
            let _ = writeln!(err, " mock: spewed 4 MiB on {id}");
            return Some(3);
        }
        Action::Hang => loop {
            std::thread::sleep(std::time::Duration::from_secs(3600));
        },
        Action::Garbage => pending.push(b"this is not json".to_vec()),
        Action::NotUtf8 => pending.push(NOT_UTF8.to_vec()),
        Action::Extra => {
            pending.push(answer.clone().into_bytes());
            pending.push(answer.into_bytes());
        }
        Action::Late => {
            pending.push(answer.clone().into_bytes());
            *deferred = Some(answer.into_bytes());
        }
        Action::Previous => {
            let line = match previous {
                Some(p) => answer.replacen(
                    &serde_json::to_string(id).unwrap_or_default(),
                    &serde_json::to_string(p).unwrap_or_default(),
                    1,
                ),
                None => answer,
            };
            pending.push(line.into_bytes());
        }
        _ => pending.push(answer.into_bytes()),
    }
    None
}

/// The worker loop: reads requests from `input`, answers on `output`. Returns the exit status.
pub fn serve(script: &Script, input: impl BufRead, mut output: impl Write) -> std::io::Result<i32> {
    let mut worker = Worker::new(script);
    for line in input.lines() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let req = match Request::parse(&line) {
            Ok(r) => r,
            Err(e) => {
                crate::errln!("mock: cannot read `{line}`: {e}");
                return Ok(2);
            }
        };
        let status = match req {
            Request::Hello { .. } => {
                write_hello(&mut output)?;
                None
            }
            Request::State { case } => {
                let reply = state_reply(&case);
                let action = worker.action_of(&case.id)?;
                let answer = serde_json::to_string(&reply)?;
                worker.deliver(&case.id, action, answer, &mut output)?
            }
            Request::Case { case } => match worker.before_case(&case.id)? {
                Some(status) => Some(status),
                None => {
                    let action = worker.action_of(&case.id)?;
                    let answer = serde_json::to_string(&answer(&case, action, &mut worker.seen))?;
                    worker.deliver(&case.id, action, answer, &mut output)?
                }
            },
            Request::Flush => {
                write_pending(&mut output, &mut worker.pending)?;
                None
            }
            Request::Bye => break,
        };
        if let Some(status) = status {
            return Ok(status);
        }
    }
    Ok(0)
}

/// The worker's state across the requests of one process.
struct Worker<'s> {
    script: &'s Script,
    kill_runner: Option<Regex>,
    interrupt_runner: Option<Regex>,
    /// The cases seen (for `flaky`).
    seen: HashSet<String>,
    /// Answer lines not yet written.
    pending: Vec<Vec<u8>>,
    counter: Option<std::path::PathBuf>,
    seen_file: Option<std::path::PathBuf>,
    seen_once: HashSet<String>,
    /// The id of the case read before the current one (for `previous`).
    previous: Option<String>,
    /// The second answer of a `late` case, written before the next case's answer.
    deferred: Option<Vec<u8>>,
    /// Lookup cases read in this process (when no counter file is named).
    read: u64,
}

impl<'s> Worker<'s> {
    fn new(script: &'s Script) -> Worker<'s> {
        let env_regex = |name| std::env::var(name).ok().and_then(|r| Regex::new(&r).ok());
        Worker {
            script,
            kill_runner: env_regex("SHADOWCHECK_MOCK_KILL_RUNNER"),
            interrupt_runner: env_regex("SHADOWCHECK_MOCK_INTERRUPT_RUNNER"),
            seen: HashSet::new(),
            pending: vec![],
            counter: std::env::var_os("SHADOWCHECK_MOCK_COUNTER").map(std::path::PathBuf::from),
            seen_file: std::env::var_os("SHADOWCHECK_MOCK_SEEN").map(std::path::PathBuf::from),
            seen_once: HashSet::new(),
            previous: None,
            deferred: None,
            read: 0,
        }
    }

    /// The action for a case: a protocol violation under `once` only the first time it arrives.
    fn action_of(&mut self, id: &str) -> std::io::Result<Action> {
        let a = self.script.action(id);
        let violation = matches!(
            a,
            Action::Extra | Action::Late | Action::Previous | Action::Garbage | Action::NotUtf8
        );
        if self.script.once
            && violation
            && !first_time(id, self.seen_file.as_deref(), &mut self.seen_once)?
        {
            return Ok(Action::Pass);
        }
        Ok(a)
    }

    /// What happens on reading a lookup case before it is answered: the signals to the runner,
    /// `slow`, and the count for `crashevery`. `Some(status)` when the worker exits instead.
    fn before_case(&mut self, id: &str) -> std::io::Result<Option<i32>> {
        if self.kill_runner.as_ref().is_some_and(|r| r.is_match(id)) {
            signal_parent("KILL");
        }
        if self
            .interrupt_runner
            .as_ref()
            .is_some_and(|r| r.is_match(id))
        {
            signal_parent("INT");
            // The runner sees SIGINT on its handler thread; no answer is written until
            // it has surely done so, so that what it keeps does not depend on scheduling.
            std::thread::sleep(std::time::Duration::from_millis(500));
        }
        if self.script.slow_ms > 0 {
            std::thread::sleep(std::time::Duration::from_millis(self.script.slow_ms));
        }
        self.read = self.count_read()?;
        if self.script.crash_every > 0 && self.read.is_multiple_of(self.script.crash_every) {
            crate::errln!("mock: crashing on case number {} ({id})", self.read);
            return Ok(Some(3));
        }
        Ok(None)
    }

    /// The number of this lookup case: counted in the counter file when one is named (across
    /// the worker's restarts), else in this process.
    fn count_read(&self) -> std::io::Result<u64> {
        Ok(match &self.counter {
            Some(f) => {
                let n = std::fs::read_to_string(f)
                    .ok()
                    .and_then(|s| s.trim().parse::<u64>().ok())
                    .unwrap_or(0)
                    + 1;
                std::fs::write(f, n.to_string())?;
                n
            }
            None => self.read + 1,
        })
    }

    /// Queues the answer to case `id` as `action` says (see [`misbehave`]) and writes it unless
    /// answers are buffered. `Some(status)` when the worker exits instead.
    fn deliver(
        &mut self,
        id: &str,
        action: Action,
        answer: String,
        output: &mut impl Write,
    ) -> std::io::Result<Option<i32>> {
        let prev = self.previous.replace(id.to_string());
        if let Some(status) = misbehave(
            action,
            id,
            answer,
            prev.as_deref(),
            &mut self.pending,
            &mut self.deferred,
        ) {
            return Ok(Some(status));
        }
        if !self.script.buffer {
            write_pending(output, &mut self.pending)?;
        }
        Ok(None)
    }
}

/// The worker's hello: every capability, no sweeps, and a request for the expectations.
fn write_hello(output: &mut impl Write) -> std::io::Result<()> {
    let hello = Reply::Hello(Hello {
        sweeps: false,
        protocol: PROTOCOL_VERSION,
        name: Some("shadowcheck mock".into()),
        capabilities: Capabilities::all(),
        wants_expect: true,
    });
    serde_json::to_writer(&mut *output, &hello)?;
    output.write_all(b"\n")?;
    output.flush()
}

/// The answer to a state case: what its expectation says (the mock asked for it in its hello).
fn state_reply(case: &StateCase) -> Reply {
    let observed = shadowcheck_model::StateObserved {
        error: case.expect.as_ref().and_then(|e| e.error),
        other_error: None,
        value: case.expect.as_ref().and_then(|e| e.value),
    };
    Reply::StateObservation {
        case_id: case.id.clone(),
        results: case
            .api
            .iter()
            .map(|a| shadowcheck_protocol::StateResult {
                api: a.key().to_string(),
                observed: observed.clone(),
            })
            .collect(),
        skipped: vec![],
    }
}

/// Writes the answer lines held back, each followed by a newline, and flushes.
fn write_pending(output: &mut impl Write, pending: &mut Vec<Vec<u8>>) -> std::io::Result<()> {
    for l in pending.drain(..) {
        output.write_all(&l)?;
        output.write_all(b"\n")?;
    }
    output.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn script_first_matching_rule_wins() {
        let s = Script::parse("crash=boom,fail=lequal,buffer,slow=5,crashevery=3").unwrap();
        assert_eq!(s.crash_every, 3);
        assert!(Script::parse("crashevery=0").is_err());
        assert_eq!(s.action("x/boom/lequal"), Action::Crash);
        assert_eq!(s.action("x/lequal"), Action::Fail);
        assert_eq!(s.action("x/gequal"), Action::Pass);
        assert!(s.buffer);
        assert_eq!(s.slow_ms, 5);
        assert!(Script::parse("explode").is_err());
        assert!(Script::parse("fail=(").is_err());
        assert_eq!(
            Script::parse("fail").unwrap().action("anything"),
            Action::Fail
        );
    }
}
