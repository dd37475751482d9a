//! Backends: implementations of depth-comparison lookups that the runner tests.
//!
//! Each backend declares its [`Capabilities`] (the runner turns anything outside them into Skip
//! with the reason before sending) and runs a batch of cases, answering one [`CaseAnswer`] per
//! case in order. The names (`--backend`) and everything else the runner knows about each kind of
//! backend (how it opens, its default instances, its worker subcommand, its help) are one table,
//! [`kinds::KINDS`]; each kind with code of its own has a module here (`soft`, `exec`, `gl`,
//! `webgl`, `vk`, `webgpu`, `mock`).

mod answer;
pub mod command;
pub mod exec;
pub mod gl;
pub mod kinds;
pub mod mock;
mod process;
pub mod soft;
pub mod sweep;
pub mod vk;
pub mod webgl;
pub mod webgpu;

use shadowcheck_model::{ApiPath, Case, StateCase, StateObserved, Texels};
pub use shadowcheck_protocol::{Capabilities, Support};
use shadowcheck_protocol::{Reply, Request};
use std::time::Duration;

/// What a backend returned for one API path of a case.
#[derive(Debug, Clone, PartialEq)]
pub enum ApiAnswer {
    Rgba {
        rgba: [f64; 4],
        stored: Option<Texels>,
        /// A sweep case's points, in order (empty for a case without a sweep).
        sweep: Vec<[f64; 4]>,
    },
    /// What a state case observed (its error and the value read back).
    State(StateObserved),
    Skip(String),
}

/// What the runner sends an implementation: a lookup case or a state case.
pub trait Sendable: Sync {
    fn id(&self) -> &str;
    /// Appends the request line (without the newline).
    fn write(&self, buf: &mut Vec<u8>, with_expect: bool);
    /// The answer an answer line gives this case.
    fn answer(&self, reply: Reply) -> CaseAnswer;
}

/// A lookup case as a backend is sent it: the fixture's case and the API paths it is a test of
/// on that backend (those the backend implements, less any skipped by name), so that narrowing
/// the paths copies nothing.
#[derive(Debug, Clone, Copy)]
pub struct Sent<'a> {
    pub case: &'a Case,
    pub api: &'a [ApiPath],
}

impl Sendable for Sent<'_> {
    fn id(&self) -> &str {
        &self.case.id
    }
    fn write(&self, buf: &mut Vec<u8>, with_expect: bool) {
        Request::write_case_on(buf, self.case, self.api, with_expect)
    }
    fn answer(&self, reply: Reply) -> CaseAnswer {
        answer::to_answer(self.case, self.api, reply)
    }
}

impl Sendable for StateCase {
    fn id(&self) -> &str {
        &self.id
    }
    fn write(&self, buf: &mut Vec<u8>, with_expect: bool) {
        Request::write_state(buf, self, with_expect)
    }
    fn answer(&self, reply: Reply) -> CaseAnswer {
        answer::to_state_answer(self, reply)
    }
}

/// The answer for one case.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseAnswer {
    /// Per API path; paths of the case that are missing here are Skip.
    Observed(Vec<(ApiPath, ApiAnswer)>),
    Skip(String),
    /// The implementation reported an error for this case (Fail with the message).
    Error(String),
    Crash(String),
    Timeout(String),
}

#[derive(Debug, thiserror::Error)]
pub enum BackendError {
    #[error("unknown backend `{0}` (expected {patterns})", patterns = kinds::patterns())]
    Unknown(String),
    #[error("backend `{backend}`: {msg}")]
    Setup { backend: String, msg: String },
}

/// A backend. `answer_batch` gives `cases.len()` answers in order (once the run is interrupted
/// ([`crate::interrupt`]), possibly only those of a prefix: the cases it got answers for); the cases it receives are
/// already inside its capabilities (the runner filtered them) and name only supported API paths
/// ([`Sent::api`]; the case's own list may name more).
/// `Send`: backends may run in parallel threads (`--jobs`).
pub trait Backend: Send {
    fn name(&self) -> &str;
    fn capabilities(&self) -> &Capabilities;
    fn answer_batch(&mut self, cases: &[Sent<'_>]) -> Vec<CaseAnswer>;
    /// Before `answer_batch(current)`, the batch the runner will run after it: a backend whose
    /// implementation works apart from the runner (a process) may send both now, `current`
    /// first, so that the implementation never waits for the runner between batches. They are
    /// then run by the next two `answer_batch` calls, with exactly these cases; nothing is owed if
    /// those calls never come.
    fn send_ahead(&mut self, _current: &[Sent<'_>], _next: &[Sent<'_>]) {}
    /// Runs TexParameter state cases (only sent when the capabilities list the `tex_parameter`
    /// feature, or declare no feature list). A backend without them answers Skip.
    fn answer_state_batch(&mut self, cases: &[&StateCase]) -> Vec<CaseAnswer> {
        cases
            .iter()
            .map(|_| CaseAnswer::Skip("this backend runs no state cases".into()))
            .collect()
    }
    /// How many cases the runner hands over at once (streaming granularity of results.jsonl).
    fn batch_size(&self) -> usize {
        256
    }
    /// What the implementation called itself (the protocol hello's `name`: version, renderer),
    /// for the run's meta line; `None` when it said nothing.
    fn implementation(&self) -> Option<String> {
        None
    }
    /// Lines an implementation printed on stderr, restarts and the like since the last call.
    fn take_diagnostics(&mut self) -> Vec<String> {
        vec![]
    }
    /// Cases already answered whose implementation misbehaved afterwards (an extra answer line for
    /// the case, read after its answer was taken), with what happened, since the last call. The
    /// runner makes those cases Crash, also when they were answered in an earlier batch.
    fn take_faults(&mut self) -> Vec<(String, String)> {
        vec![]
    }
    /// Whether the implementation compiles code per sampler state (llvmpipe and lavapipe bake
    /// filter, wrap, compare function and format into each shader variant): a cold run of such a
    /// backend costs a compilation per distinct state, which the scheduler weighs (longest first).
    /// An unknown implementation is assumed to.
    fn compiles_per_state(&self) -> bool {
        true
    }
    /// The run is done with the backend: its process (if any) is asked to end, and what it wrote
    /// on stderr since the last [`Backend::take_diagnostics`] is returned (a GL worker's last line
    /// says what it compiled and drew: `shadowcheck_gl::stats::WorkerStats`). A closed backend
    /// that is sent more work starts again.
    fn close(&mut self) -> Vec<String> {
        self.take_diagnostics()
    }
}

/// Options shared by the backends that run child processes.
#[derive(Debug, Clone)]
pub struct Options {
    /// Time allowed for one group of cases before the process is killed.
    pub timeout: Duration,
    /// Cases written to a process before each `flush` (PROTOCOL.md §2).
    pub group: usize,
    /// After this many cases in a row ended in Timeout, the rest of the implementation's cases are
    /// Timeout without being sent (0: never give up).
    pub give_up: usize,
    /// `run --fast-compile`: GL workers run with `GALLIVM_PERF=nopt` (llvmpipe and lavapipe skip
    /// LLVM's optimisation passes). Opt-in only: it changes the driver's code generation.
    pub fast_compile: bool,
    /// `run --states-per-program`: the most sampler states one program of a GL worker samples
    /// (`shadowcheck_plan::units`).
    pub states_per_program: usize,
}

/// Consecutive timeouts after which an implementation is given up (`run --give-up-after`).
pub const GIVE_UP_AFTER: usize = 3;

impl Default for Options {
    fn default() -> Self {
        Options {
            timeout: Duration::from_secs(10),
            group: 64,
            give_up: GIVE_UP_AFTER,
            fast_compile: false,
            states_per_program: shadowcheck_plan::units::DEFAULT_STATES_PER_PROGRAM,
        }
    }
}

/// A backend name and why it does not run here.
pub type Unavailable = (String, String);

/// The backends of a run that names none, and those left out of it, each list with the reason.
#[derive(Debug, Default)]
pub struct Defaults {
    /// Run: `soft`, every GL backend a machine with Mesa offers, the Vulkan drivers found,
    /// `webgl:chromium` when Chromium is installed and its `-gles` / `-lavapipe` siblings when
    /// Mesa's llvmpipe / lavapipe are too, and `webgpu:chromium` when Chromium is installed (each
    /// kind's [`kinds::DefaultInstances`]).
    pub run: Vec<String>,
    /// Cannot start here (a driver not installed or hidden): the run goes on without them and exits
    /// 96 unless `--skip-missing`. Combinations that can never work (OSMesa with ES, OSMesa with
    /// zink) are in no list.
    pub missing: Vec<Unavailable>,
    /// The optional implementations beyond Mesa whose files are not installed (SwiftShader's
    /// Vulkan ICD, SwiftShader's GLES, Chromium), each with the command that installs it:
    /// announced, not an error.
    pub absent: Vec<Unavailable>,
    /// Start here but can run no case (the context exposes none of the specs its kind implements,
    /// e.g. an ES 2.0 context without GL_EXT_shadow_samplers): not applicable, said once in the
    /// run's summary. Named with `-b`, such a backend runs, every test a Skip (exit 4).
    pub not_applicable: Vec<Unavailable>,
}

/// Backends run when none is named, and those left out with the reason ([`Defaults`]): each kind's
/// default instances ([`kinds::BackendKind::defaults`]), in table order.
pub fn default_backends() -> Defaults {
    sort_defaults(kinds::probe_defaults())
}

/// Each default instance into its list by what its probe found (an impossible one into none).
fn sort_defaults(found: Vec<(String, kinds::Found)>) -> Defaults {
    let mut d = Defaults::default();
    for (name, found) in found {
        match found {
            kinds::Found::Runs => d.run.push(name),
            kinds::Found::RunsNothing(why) => d.not_applicable.push((name, why)),
            kinds::Found::Missing(why) => d.missing.push((name, why)),
            kinds::Found::Absent(how) => d.absent.push((name, how)),
            kinds::Found::Impossible => {}
        }
    }
    d
}

/// Opens the backend called `name` (starting and greeting its process, if any); the kind comes
/// from [`kinds::KINDS`].
pub fn open(name: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let kind = kinds::kind_of(name).ok_or_else(|| BackendError::Unknown(name.to_string()))?;
    let rest = name.split_once(':').map_or("", |(_, r)| r);
    (kind.open)(name, rest, opts)
}

#[cfg(test)]
mod tests {
    use super::kinds::Found;
    use super::*;

    #[test]
    fn each_default_instance_goes_to_the_list_of_what_was_found() {
        let d = sort_defaults(vec![
            ("soft".into(), Found::Runs),
            (
                "egl:llvmpipe:es2".into(),
                Found::RunsNothing("no shadow".into()),
            ),
            ("egl:zink:core".into(), Found::Missing("no device".into())),
            ("osmesa:llvmpipe:es3".into(), Found::Impossible),
            ("egl:llvmpipe:core".into(), Found::Runs),
            ("webgl:chromium".into(), Found::Absent("apt".into())),
        ]);
        assert_eq!(d.run, ["soft", "egl:llvmpipe:core"]);
        let pair = |n: &str, w: &str| (n.to_string(), w.to_string());
        assert_eq!(d.not_applicable, [pair("egl:llvmpipe:es2", "no shadow")]);
        assert_eq!(d.missing, [pair("egl:zink:core", "no device")]);
        assert_eq!(d.absent, [pair("webgl:chromium", "apt")]);
    }
}
