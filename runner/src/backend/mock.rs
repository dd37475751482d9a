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
//! - `empty`: an observation with `results: []` (and nothing skipped).
//!
//! Options (same list): `buffer` answers only at `flush` (like a GPU implementation; default is to
//! answer each case as it is read); `slow=MS` sleeps MS milliseconds per case; `crashevery=N`
//! exits on every N-th case it reads, counting across the worker's restarts when
//! `SHADOWCHECK_MOCK_COUNTER=FILE` names a file to keep the count in (else per process).
//! Environment: `SHADOWCHECK_MOCK_KILL_RUNNER=REGEX` makes the worker SIGKILL its parent (the
//! runner) on the first case whose id matches, to test that a killed run can be resumed;
//! `SHADOWCHECK_MOCK_INTERRUPT_RUNNER=REGEX` sends it SIGINT instead (each time a matching case
//! arrives), as Ctrl-C or a CI job's SIGTERM would.

use regex::Regex;
use shadowcheck_model::{Case, Channel, Profile};
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
}

/// A parsed mock script.
#[derive(Debug, Clone)]
pub struct Script {
    rules: Vec<(Action, Option<Regex>)>,
    pub buffer: bool,
    pub slow_ms: u64,
    /// Exit on every N-th case read (0: never).
    pub crash_every: u64,
}

impl Script {
    pub fn parse(s: &str) -> Result<Script, String> {
        let mut script = Script {
            rules: vec![],
            buffer: false,
            slow_ms: 0,
            crash_every: 0,
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

/// The worker loop: reads requests from `input`, answers on `output`. Returns the exit status.
pub fn serve(script: &Script, input: impl BufRead, mut output: impl Write) -> std::io::Result<i32> {
    let env_regex = |name| std::env::var(name).ok().and_then(|r| Regex::new(&r).ok());
    let kill_runner = env_regex("SHADOWCHECK_MOCK_KILL_RUNNER");
    let interrupt_runner = env_regex("SHADOWCHECK_MOCK_INTERRUPT_RUNNER");
    let mut seen = HashSet::new();
    let mut pending: Vec<String> = vec![];
    let counter = std::env::var_os("SHADOWCHECK_MOCK_COUNTER").map(std::path::PathBuf::from);
    let mut read: u64 = 0;
    for line in input.lines() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let req = match Request::parse(&line) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("mock: cannot read `{line}`: {e}");
                return Ok(2);
            }
        };
        match req {
            Request::Hello { .. } => {
                let hello = Reply::Hello(Hello {
                    sweeps: false,
                    protocol: PROTOCOL_VERSION,
                    name: Some("shadowcheck mock".into()),
                    capabilities: Capabilities::all(),
                    wants_expect: true,
                });
                serde_json::to_writer(&mut output, &hello)?;
                output.write_all(b"\n")?;
                output.flush()?;
            }
            Request::State { case } => {
                // The mock answers what the expectation says (it asked for it in its hello).
                let observed = shadowcheck_model::StateObserved {
                    error: case.expect.as_ref().and_then(|e| e.error),
                    other_error: None,
                    value: case.expect.as_ref().and_then(|e| e.value),
                };
                let reply = Reply::StateObservation {
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
                };
                pending.push(serde_json::to_string(&reply)?);
                if !script.buffer {
                    for l in pending.drain(..) {
                        writeln!(output, "{l}")?;
                    }
                    output.flush()?;
                }
            }
            Request::Case { case } => {
                if kill_runner.as_ref().is_some_and(|r| r.is_match(&case.id)) {
                    signal_parent("KILL");
                }
                if interrupt_runner
                    .as_ref()
                    .is_some_and(|r| r.is_match(&case.id))
                {
                    signal_parent("INT");
                    // The runner sees SIGINT on its handler thread; no answer is written until
                    // it has surely done so, so that what it keeps does not depend on scheduling.
                    std::thread::sleep(std::time::Duration::from_millis(500));
                }
                if script.slow_ms > 0 {
                    std::thread::sleep(std::time::Duration::from_millis(script.slow_ms));
                }
                read = match &counter {
                    Some(f) => {
                        let n = std::fs::read_to_string(f)
                            .ok()
                            .and_then(|s| s.trim().parse::<u64>().ok())
                            .unwrap_or(0)
                            + 1;
                        std::fs::write(f, n.to_string())?;
                        n
                    }
                    None => read + 1,
                };
                if script.crash_every > 0 && read.is_multiple_of(script.crash_every) {
                    eprintln!("mock: crashing on case number {read} ({})", case.id);
                    return Ok(3);
                }
                let action = script.action(&case.id);
                match action {
                    Action::Crash => {
                        eprintln!("mock: crashing on {}", case.id);
                        return Ok(3);
                    }
                    Action::Hang => loop {
                        std::thread::sleep(std::time::Duration::from_secs(3600));
                    },
                    Action::Garbage => pending.push("this is not json".to_string()),
                    Action::Extra => {
                        let line = serde_json::to_string(&answer(&case, action, &mut seen))?;
                        pending.push(line.clone());
                        pending.push(line);
                    }
                    _ => pending.push(serde_json::to_string(&answer(&case, action, &mut seen))?),
                }
                if !script.buffer {
                    for l in pending.drain(..) {
                        writeln!(output, "{l}")?;
                    }
                    output.flush()?;
                }
            }
            Request::Flush => {
                for l in pending.drain(..) {
                    writeln!(output, "{l}")?;
                }
                output.flush()?;
            }
            Request::Bye => break,
        }
    }
    Ok(0)
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
