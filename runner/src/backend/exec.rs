//! `exec:` backends: an implementation in a child process speaking runner/PROTOCOL.md.
//!
//! Pipelined: a group of cases is written, then `flush`, then the answers are read (the process
//! and its pipe threads: `process.rs`); the runner's next group is written before the answers of
//! the one before are read ([`Backend::send_ahead`]: two in flight).
//! A process that dies, stalls or answers garbage is killed; the unanswered part of the group is
//! bisected in fresh processes until the case that does it is alone (Crash or Timeout), and the
//! run goes on. When the process was answering case by case, the first unanswered case is tried
//! alone first (one restart instead of log2(group) when it is the culprit). The GL backends and the mock use the same machinery.
//!
//! Misbehaviour is blamed on the case that misbehaved: a second answer for a case answered before
//! makes that case Crash ([`Backend::take_faults`]) and the case whose answer was expected is sent
//! again; after `--give-up-after` K cases in a row end in Timeout the rest are Timeout unsent; an
//! interrupted run stops waiting within [`POLL`]. Answers become outcomes in `answer.rs`.

pub use super::command::{split_command, ProcessCommand};
use super::process::Proc;
use super::{Backend, BackendError, Capabilities, CaseAnswer, Options, Sendable, Sent};
use shadowcheck_model::StateCase;
use shadowcheck_protocol::{Hello, Reply, Request};
use std::collections::{HashSet, VecDeque};
use std::sync::mpsc::RecvTimeoutError;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How the reason of a Crash for a protocol violation starts (an unreadable answer line, an
/// answer for another case, a second answer): the run never re-runs these as possible flakes.
pub const PROTOCOL_ERROR: &str = "protocol error";

/// How often a wait for answers checks whether the run was interrupted.
const POLL: Duration = Duration::from_millis(200);

/// Time allowed for the hello, at least (a GL worker creates its context first; zink starts a
/// Vulkan device).
const HANDSHAKE_MIN: Duration = Duration::from_secs(30);

enum Failure {
    /// Unparsable or out-of-order answer: the case it should have answered is Crash.
    Protocol(String),
    /// A second answer for a case answered before (named): that case is to blame, not the one
    /// whose answer was expected, which is sent again to a fresh process.
    Extra(String),
    /// The process exited or closed stdout.
    Died,
    /// No answer before the deadline.
    Stalled,
}

/// A backend speaking PROTOCOL.md through a child process.
pub struct ExecBackend {
    name: String,
    cmd: ProcessCommand,
    timeout: Duration,
    group: usize,
    caps: Capabilities,
    wants_expect: bool,
    /// The hello's `sweeps`: the implementation is sent sweep cases whole.
    sweeps: bool,
    proc: Option<Proc>,
    diags: Arc<Mutex<Vec<String>>>,
    /// How many processes were started (the first one included).
    pub spawns: usize,
    /// Give up after this many Timeouts in a row (0: never).
    give_up: usize,
    /// Cases that ended in Timeout since the last answer or crash; a case counts once, however
    /// many parts (its lookup, its sweep points sent as cases of their own) timed out.
    timeouts_in_a_row: usize,
    /// The case (id without a sweep point's suffix) whose lookup or sweep point timed out last in
    /// this batch: its other parts are Timeout without being sent, as the case's outcome is
    /// that Timeout whatever they answer (`sweep::merge`).
    timed_out_case: Option<String>,
    /// Ids the current process has answered, by [`id_key`] (to recognize a second answer for
    /// one of them without keeping a copy of every id of the run).
    answered: HashSet<u64>,
    /// Groups written ahead ([`Backend::send_ahead`]) and not yet read: their [`group_key`] and
    /// the process they went to (by [`ExecBackend::spawns`]).
    ahead: VecDeque<(u64, usize)>,
    /// Answered cases found misbehaving later (see [`Backend::take_faults`]).
    faults: Vec<(String, String)>,
    /// The hello's `name`.
    implementation: Option<String>,
    /// See [`Backend::compiles_per_state`]; set by the opener that knows the driver.
    compiles_per_state: bool,
}

impl ExecBackend {
    /// Declares whether the implementation compiles code per sampler state (the scheduler's
    /// weight; see [`Backend::compiles_per_state`]).
    pub fn with_compiles_per_state(mut self, yes: bool) -> ExecBackend {
        self.compiles_per_state = yes;
        self
    }

    /// Starts the process and reads its capabilities.
    pub fn start(
        name: &str,
        cmd: ProcessCommand,
        opts: &Options,
    ) -> Result<ExecBackend, BackendError> {
        let mut b = ExecBackend {
            name: name.to_string(),
            cmd,
            timeout: opts.timeout,
            group: opts.group.max(1),
            caps: Capabilities::default(),
            wants_expect: false,
            sweeps: false,
            proc: None,
            diags: Arc::new(Mutex::new(vec![])),
            spawns: 0,
            give_up: opts.give_up,
            timeouts_in_a_row: 0,
            timed_out_case: None,
            answered: HashSet::new(),
            ahead: VecDeque::new(),
            faults: vec![],
            implementation: None,
            compiles_per_state: true,
        };
        let hello = b.ensure().map_err(|msg| BackendError::Setup {
            backend: name.to_string(),
            msg,
        })?;
        if let Some(h) = hello {
            b.caps = h.capabilities;
            b.wants_expect = h.wants_expect;
            b.sweeps = h.sweeps;
            if let Some(n) = h.name {
                b.push_diag(format!("implementation: {n}"));
                b.implementation = Some(n);
            }
        }
        Ok(b)
    }

    fn push_diag(&self, msg: String) {
        if let Ok(mut d) = self.diags.lock() {
            d.push(msg);
        }
    }

    /// Makes sure a greeted process is running; returns its hello when it had to start one.
    fn ensure(&mut self) -> Result<Option<Hello>, String> {
        if let Some(p) = self.proc.as_mut() {
            // A process that exited between groups (after answering everything) is replaced before
            // any case is sent, so its exit is not blamed on the next group.
            match p.child.try_wait() {
                Ok(None) => return Ok(None),
                _ => {
                    let how = self.kill_proc();
                    self.push_diag(format!(
                        "{}: the implementation exited between groups ({how}); restarting",
                        self.name
                    ));
                }
            }
        }
        let mut p = Proc::spawn(&self.cmd, &self.diags)?;
        self.spawns += 1;
        let hello = Request::hello_line();
        if let Err(e) = p.send(format!("{hello}\n").into_bytes()) {
            let how = p.kill();
            return Err(format!("handshake failed: {e} ({how})"));
        }
        let line = match p.lines.recv_timeout(self.timeout.max(HANDSHAKE_MIN)) {
            Ok(l) => l,
            Err(RecvTimeoutError::Timeout) => {
                let how = p.kill();
                return Err(format!(
                    "no hello within {:?} ({how})",
                    self.timeout.max(HANDSHAKE_MIN)
                ));
            }
            Err(RecvTimeoutError::Disconnected) => {
                let how = p.kill();
                return Err(format!("exited before its hello ({how})"));
            }
        };
        let parsed = line.and_then(|l| Reply::parse_hello(&l));
        match parsed {
            Ok(h) => {
                self.proc = Some(p);
                Ok(Some(h))
            }
            Err(e) => {
                let how = p.kill();
                Err(format!("bad hello: {e} ({how})"))
            }
        }
    }

    /// One attempt at a group in the current process: the answers received, and why it stopped
    /// early if it did.
    fn attempt<T: Sendable + ?Sized>(
        &mut self,
        group: &[&T],
    ) -> (Vec<CaseAnswer>, Option<Failure>) {
        // A group written ahead (`send_ahead`) to this process is only read here.
        let written = self.take_ahead(group);
        if !written {
            self.check_stray_lines();
        }
        let Some(p) = self.proc.as_mut() else {
            return (vec![], Some(Failure::Died));
        };
        if !written {
            // A failed hand-over means the process is gone: reading says so (Died).
            let _ = p.send(group_frame(group, self.wants_expect));
        }
        let deadline = Instant::now() + self.timeout;
        let mut out = Vec::with_capacity(group.len());
        for (i, c) in group.iter().enumerate() {
            let line = loop {
                let left = deadline.saturating_duration_since(Instant::now());
                // Waits in slices, so that an interrupted run stops waiting.
                match p.lines.recv_timeout(left.min(POLL)) {
                    Ok(Ok(l)) if l.trim().is_empty() => continue,
                    Ok(Ok(l)) => break l,
                    // A line the protocol cannot read (not UTF-8, too long) is the parse error
                    // it is, on the case whose answer was expected.
                    Ok(Err(why)) => {
                        return (
                            out,
                            Some(Failure::Protocol(format!("bad answer line: {why}"))),
                        )
                    }
                    Err(RecvTimeoutError::Timeout) if crate::interrupt::requested() => {
                        return (out, Some(Failure::Died))
                    }
                    Err(RecvTimeoutError::Timeout) if left > POLL => continue,
                    Err(RecvTimeoutError::Timeout) => return (out, Some(Failure::Stalled)),
                    Err(RecvTimeoutError::Disconnected) => return (out, Some(Failure::Died)),
                }
            };
            match Reply::parse_answer(&line) {
                Ok(a) if a.case_id() == Some(c.id()) => out.push(c.answer(a)),
                Ok(a)
                    if a.case_id().is_some_and(|id| {
                        group[..i].iter().any(|g| g.id() == id)
                            || self.answered.contains(&id_key(id))
                    }) =>
                {
                    let id = a.case_id().unwrap_or_default().to_string();
                    return (out, Some(Failure::Extra(id)));
                }
                Ok(a) => {
                    let msg = format!(
                        "answer for `{}` where `{}` was expected",
                        a.case_id().unwrap_or_default(),
                        c.id()
                    );
                    return (out, Some(Failure::Protocol(msg)));
                }
                Err(e) => {
                    return (
                        out,
                        Some(Failure::Protocol(format!(
                            "bad answer line: {e}: {}",
                            clip(&line)
                        ))),
                    )
                }
            }
        }
        self.answered.extend(group.iter().map(|c| id_key(c.id())));
        self.check_stray_lines();
        (out, None)
    }

    /// Reads, without waiting, lines the process wrote after its last expected answer: a second
    /// answer for a case it answered is a fault of that case; anything else is a diagnostic.
    /// Not while a group written ahead is in flight: its answers are not stray.
    fn check_stray_lines(&mut self) {
        if !self.ahead.is_empty() {
            return;
        }
        let Some(p) = self.proc.as_mut() else { return };
        let mut stray = vec![];
        while let Ok(l) = p.lines.try_recv() {
            match l {
                Ok(l) if l.trim().is_empty() => {}
                Ok(l) => stray.push(l),
                Err(why) => stray.push(why),
            }
        }
        for l in stray {
            match Reply::parse_answer(&l)
                .ok()
                .and_then(|a| a.case_id().map(str::to_string))
            {
                Some(id) if self.answered.contains(&id_key(&id)) => self.fault(id),
                _ => self.push_diag(format!(
                    "{}: ignored a line nobody asked for: {}",
                    self.name,
                    clip(&l)
                )),
            }
        }
    }

    /// Records a second answer for `id`, a case answered before.
    /// A sweep point sent as a case of its own (`<case id>/sweep=<k>`, `sweep.rs`) is a fault of
    /// its case, whose verdict it is part of.
    fn fault(&mut self, id: String) {
        self.push_diag(format!(
            "{}: protocol error: a second answer for `{id}`",
            self.name
        ));
        let (case, what) = match shadowcheck_model::split_point_id(&id) {
            Some((case, k)) => (case.to_string(), format!("sweep point {k} of this case")),
            None => (id, "this case".to_string()),
        };
        self.faults.push((
            case,
            format!(
                "{PROTOCOL_ERROR}: the implementation answered {what} twice (an extra answer line)"
            ),
        ));
    }

    /// Whether `cases` go to the implementation as they are: it runs sweeps, or none has one
    /// (otherwise each sweep point is sent as a case of its own, `sweep.rs`).
    fn sent_whole(&self, cases: &[Sent<'_>]) -> bool {
        self.sweeps || cases.iter().all(|c| c.case.sweep.is_empty())
    }

    /// Whether `group` is the next group written ahead to the current process (taking it). A
    /// written group that is not the one run next would have its answers taken for another
    /// group's: the process is restarted instead.
    fn take_ahead<T: Sendable + ?Sized>(&mut self, group: &[&T]) -> bool {
        let Some(&(key, spawn)) = self.ahead.front() else {
            return false;
        };
        if key == group_key(group) && spawn == self.spawns && self.proc.is_some() {
            self.ahead.pop_front();
            return true;
        }
        let how = self.kill_proc();
        self.push_diag(format!(
            "{}: a group written ahead was not the next one run; restarting ({how})",
            self.name
        ));
        let _ = self.ensure();
        false
    }

    fn kill_proc(&mut self) -> String {
        self.answered.clear();
        self.ahead.clear();
        self.proc
            .take()
            .map(|p| p.kill())
            .unwrap_or_else(|| "not running".to_string())
    }

    /// Runs a group, bisecting whatever a dying or stalling process leaves unanswered.
    fn run_group<T: Sendable + ?Sized>(&mut self, cases: &[&T]) -> Vec<CaseAnswer> {
        let mut results = Vec::with_capacity(cases.len());
        while results.len() < cases.len() {
            let rest = &cases[results.len()..];
            if crate::interrupt::requested() {
                // Only the answered prefix comes back; `--resume` sends the rest again.
                break;
            }
            if self.timed_out_case.as_deref() == Some(case_of(rest[0].id())) {
                results.push(CaseAnswer::Timeout(
                    "not sent: another part of this case (its lookup or a sweep point) gave no answer".into(),
                ));
                continue;
            }
            if self.give_up > 0 && self.timeouts_in_a_row >= self.give_up {
                let msg = format!(
                    "not sent: the implementation gave no answer to {} cases in a row, so it was given up (--give-up-after {})",
                    self.timeouts_in_a_row, self.give_up
                );
                results.extend(rest.iter().map(|_| CaseAnswer::Timeout(msg.clone())));
                break;
            }
            if let Err(msg) = self.ensure() {
                // The implementation cannot even start again: nothing more can run.
                let msg = format!("cannot restart the implementation: {msg}");
                results.extend(rest.iter().map(|_| CaseAnswer::Crash(msg.clone())));
                break;
            }
            let (answers, failure) = self.attempt(rest);
            let streamed = !answers.is_empty();
            if streamed {
                self.timeouts_in_a_row = 0;
                self.timed_out_case = None;
            }
            results.extend(answers);
            let Some(failure) = failure else { break };
            if crate::interrupt::requested() {
                // Whatever stopped the answers (often the same signal), the rest is not blamed
                // on a case: it is left unanswered.
                self.kill_proc();
                break;
            }
            let rest = &cases[results.len()..];
            match failure {
                Failure::Extra(id) => {
                    let how = self.kill_proc();
                    self.push_diag(format!(
                        "{}: answer for `{}` expected; restarting ({how})",
                        self.name,
                        rest[0].id()
                    ));
                    self.fault(id);
                }
                Failure::Protocol(msg) => {
                    let how = self.kill_proc();
                    self.push_diag(format!(
                        "{}: protocol error on `{}`: {msg}; restarting ({how})",
                        self.name,
                        rest[0].id()
                    ));
                    results.push(CaseAnswer::Crash(format!("{PROTOCOL_ERROR}: {msg}")));
                }
                Failure::Died | Failure::Stalled => {
                    let stalled = matches!(failure, Failure::Stalled);
                    let how = self.kill_proc();
                    if rest.len() == 1 {
                        let what = if stalled {
                            let case = case_of(rest[0].id());
                            if self.timed_out_case.as_deref() != Some(case) {
                                self.timeouts_in_a_row += 1;
                                self.timed_out_case = Some(case.to_string());
                            }
                            CaseAnswer::Timeout(format!("no answer within {:?}", self.timeout))
                        } else {
                            self.timeouts_in_a_row = 0;
                            self.timed_out_case = None;
                            CaseAnswer::Crash(format!("the process died on this case: {how}"))
                        };
                        self.push_diag(format!(
                            "{}: `{}`: {}",
                            self.name,
                            rest[0].id(),
                            if stalled { "timeout" } else { "crash" }
                        ));
                        results.push(what);
                    } else if streamed {
                        // It answered case by case up to here: the first unanswered case is the
                        // likely culprit. Try it alone, then go on with the rest.
                        let first = [rest[0]];
                        results.extend(self.run_group(&first));
                    } else {
                        let mid = rest.len() / 2;
                        let (a, b) = rest.split_at(mid);
                        let (a, b) = (a.to_vec(), b.to_vec());
                        results.extend(self.run_group(&a));
                        results.extend(self.run_group(&b));
                    }
                }
            }
        }
        results
    }
}

/// The case a sent id belongs to: a sweep point sent as a case of its own (`<case id>/sweep=<k>`,
/// `sweep.rs`) belongs to its case; any other id is its case's.
fn case_of(id: &str) -> &str {
    shadowcheck_model::split_point_id(id).map_or(id, |(case, _)| case)
}

/// A group's request lines followed by `flush`, in one buffer (one hand-over to the writer thread).
fn group_frame<T: Sendable + ?Sized>(group: &[&T], with_expect: bool) -> Vec<u8> {
    let mut buf = Vec::with_capacity(group.len() * 1024);
    for c in group {
        c.write(&mut buf, with_expect);
        buf.push(b'\n');
    }
    buf.extend_from_slice(Request::FLUSH_LINE);
    buf
}

/// A 64-bit hash of ids in order: the key of a group in [`ExecBackend::ahead`] (its ids) and of
/// a case in [`ExecBackend::answered`] (one id). Two of a run's keys are equal with odds of about
/// 2^-64 per pair.
fn ids_key<'a>(ids: impl IntoIterator<Item = &'a str>) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for id in ids {
        id.hash(&mut h);
    }
    h.finish()
}

fn group_key<T: Sendable + ?Sized>(group: &[&T]) -> u64 {
    ids_key(group.iter().map(|c| c.id()))
}

fn id_key(id: &str) -> u64 {
    ids_key([id])
}

pub(super) fn clip(s: &str) -> String {
    if s.len() > 200 {
        let mut end = 200;
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        format!("{}...", &s[..end])
    } else {
        s.to_string()
    }
}

impl Backend for ExecBackend {
    fn compiles_per_state(&self) -> bool {
        self.compiles_per_state
    }
    fn name(&self) -> &str {
        &self.name
    }
    fn capabilities(&self) -> &Capabilities {
        &self.caps
    }
    fn batch_size(&self) -> usize {
        self.group
    }
    fn send_ahead(&mut self, current: &[Sent<'_>], next: &[Sent<'_>]) {
        // Only batches sent as they are (not expanded into one case per sweep point), one group
        // each, to a running process.
        let whole = |b: &[Sent<'_>]| !b.is_empty() && b.len() <= self.group && self.sent_whole(b);
        if !whole(current) || !whole(next) || crate::interrupt::requested() {
            return;
        }
        let current: Vec<&Sent<'_>> = current.iter().collect();
        let next: Vec<&Sent<'_>> = next.iter().collect();
        let spawns = self.spawns;
        let Some(p) = self.proc.as_mut() else { return };
        // In order: the current batch first, unless it is already the next one written.
        match self.ahead.front() {
            Some(&(key, s)) if key == group_key(&current) && s == spawns => {}
            Some(_) => return,
            None => {
                if p.send(group_frame(&current, self.wants_expect)).is_err() {
                    return;
                }
                self.ahead.push_back((group_key(&current), spawns));
            }
        }
        if self.ahead.len() == 1 && p.send(group_frame(&next, self.wants_expect)).is_ok() {
            self.ahead.push_back((group_key(&next), spawns));
        }
    }
    fn answer_batch(&mut self, cases: &[Sent<'_>]) -> Vec<CaseAnswer> {
        // A case sent again (a flake re-run) is sent whole again.
        self.timed_out_case = None;
        if self.sent_whole(cases) {
            self.run_group(&cases.iter().collect::<Vec<_>>())
        } else {
            super::sweep::run_expanded(cases, |flat| {
                self.run_group(&flat.iter().collect::<Vec<_>>())
            })
        }
    }
    fn answer_state_batch(&mut self, cases: &[&StateCase]) -> Vec<CaseAnswer> {
        self.timed_out_case = None;
        self.run_group(cases)
    }
    fn implementation(&self) -> Option<String> {
        self.implementation.clone()
    }

    fn take_diagnostics(&mut self) -> Vec<String> {
        self.diags
            .lock()
            .map(|mut d| std::mem::take(&mut *d))
            .unwrap_or_default()
    }
    fn take_faults(&mut self) -> Vec<(String, String)> {
        self.check_stray_lines();
        std::mem::take(&mut self.faults)
    }
    fn close(&mut self) -> Vec<String> {
        self.close_process()
    }
}

impl ExecBackend {
    /// Ends the implementation's process (see [`Backend::close`]).
    fn close_process(&mut self) -> Vec<String> {
        if let Some(p) = self.proc.take() {
            p.finish();
        }
        self.take_diagnostics()
    }
}

impl Drop for ExecBackend {
    fn drop(&mut self) {
        if let Some(p) = self.proc.take() {
            p.finish();
        }
    }
}
