//! Backends: implementations of depth-comparison lookups that the runner tests.
//!
//! Each backend declares its [`Capabilities`] (the runner turns anything outside them into Skip
//! with the reason before sending) and runs a batch of cases, answering one [`CaseOutcome`] per
//! case in order. Names (`--backend`):
//! - `soft` / `soft:<spec>`: the project's own texture unit (shadowcheck-soft);
//! - `exec:<command line>`: an external process speaking runner/PROTOCOL.md;
//! - `egl:*`, `osmesa:*`: GL drivers, each in a `shadowcheck gl-worker` child speaking the protocol;
//! - `mock:<script>`: a scripted implementation for testing the runner itself.

pub mod exec;
pub mod mock;
pub mod protocol;
pub mod soft;

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Texels};
use std::time::Duration;

/// What an implementation can run. `None` for a list means "no restriction declared".
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Capabilities {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specs: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub api: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub targets: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub formats: Option<Vec<String>>,
    /// Extensions the implementation exposes (informational: reports show them).
    #[serde(default)]
    pub extensions: Vec<String>,
}

fn listed(list: &Option<Vec<String>>, key: &str) -> bool {
    list.as_ref().is_none_or(|l| l.iter().any(|k| k == key))
}

/// Which API paths of a case a backend will run, or why it runs none.
pub enum Support {
    /// Run these paths (a subset of the case's); the others are Skip with the reason.
    Run {
        apis: Vec<ApiPath>,
        others: Option<String>,
    },
    Skip(String),
}

impl Capabilities {
    /// Everything allowed.
    pub fn all() -> Capabilities {
        Capabilities::default()
    }

    pub fn support(&self, case: &Case) -> Support {
        if !listed(&self.specs, case.spec.key()) {
            return Support::Skip(format!(
                "spec `{}` not supported by this backend",
                case.spec
            ));
        }
        if !listed(&self.targets, case.texture.target.key()) {
            return Support::Skip(format!(
                "target `{}` not supported by this backend",
                case.texture.target
            ));
        }
        if !listed(&self.formats, case.texture.format.key()) {
            return Support::Skip(format!(
                "format `{}` not supported by this backend",
                case.texture.format
            ));
        }
        let apis: Vec<ApiPath> = case
            .api
            .iter()
            .copied()
            .filter(|a| listed(&self.api, a.key()))
            .collect();
        if apis.is_empty() {
            return Support::Skip(
                "none of the case's API paths is supported by this backend".to_string(),
            );
        }
        let others = (apis.len() < case.api.len())
            .then(|| "API path not supported by this backend".to_string());
        Support::Run { apis, others }
    }
}

/// What a backend returned for one API path of a case.
#[derive(Debug, Clone, PartialEq)]
pub enum ApiOutcome {
    Rgba {
        rgba: [f64; 4],
        stored: Option<Texels>,
    },
    Skip(String),
}

/// The answer for one case.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseOutcome {
    /// Per API path; paths of the case that are missing here are Skip.
    Observed(Vec<(ApiPath, ApiOutcome)>),
    Skip(String),
    /// The implementation reported an error for this case (Fail with the message).
    Error(String),
    Crash(String),
    Timeout(String),
}

#[derive(Debug, thiserror::Error)]
pub enum BackendError {
    #[error("unknown backend `{0}` (expected soft, soft:<spec>, exec:<command>, egl:*, osmesa:*, mock:<script>)")]
    Unknown(String),
    #[error("backend `{backend}`: {msg}")]
    Setup { backend: String, msg: String },
}

/// A backend. `run_batch` answers `cases.len()` outcomes in order; the cases it receives are
/// already inside its capabilities (the runner filtered them) and carry only supported API paths.
/// `Send`: backends may run in parallel threads (`--jobs`).
pub trait Backend: Send {
    fn name(&self) -> &str;
    fn capabilities(&self) -> &Capabilities;
    fn run_batch(&mut self, cases: &[&Case]) -> Vec<CaseOutcome>;
    /// How many cases the runner hands over at once (streaming granularity of results.jsonl).
    fn batch_size(&self) -> usize {
        256
    }
    /// Lines an implementation printed on stderr, restarts and the like since the last call.
    fn take_diagnostics(&mut self) -> Vec<String> {
        vec![]
    }
}

/// Options shared by the backends that run child processes.
#[derive(Debug, Clone)]
pub struct Options {
    /// Time allowed for one group of cases before the process is killed.
    pub timeout: Duration,
    /// Cases written to a process before each `flush` (PROTOCOL.md §2).
    pub group: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            timeout: Duration::from_secs(10),
            group: 64,
        }
    }
}

/// The GL backends this machine offers (`egl:...`, `osmesa:...`), from the GL helper's probe.
pub fn gl_backends() -> Vec<String> {
    crate::gl::probe()
}

/// Backends run when none is named: `soft` plus every GL driver found.
pub fn default_backends() -> Vec<String> {
    let mut v = vec!["soft".to_string()];
    v.extend(gl_backends());
    v
}

/// Opens the backend called `name` (starting and greeting its process, if any).
pub fn open(name: &str, opts: &Options) -> Result<Box<dyn Backend>, BackendError> {
    let (kind, rest) = name.split_once(':').unwrap_or((name, ""));
    match kind {
        "soft" => Ok(Box::new(soft::SoftBackend::new(name, rest)?)),
        "exec" => {
            let argv = exec::split_command(rest).map_err(|msg| BackendError::Setup {
                backend: name.into(),
                msg,
            })?;
            let Some((program, args)) = argv.split_first() else {
                return Err(BackendError::Setup {
                    backend: name.into(),
                    msg: "empty command".into(),
                });
            };
            let cmd = exec::ProcessCommand {
                program: program.into(),
                args: args.to_vec(),
                env: vec![],
            };
            Ok(Box::new(exec::ExecBackend::start(name, cmd, opts)?))
        }
        "egl" | "osmesa" => {
            let wc = crate::gl::worker_command(name).map_err(|e| BackendError::Setup {
                backend: name.into(),
                msg: e.to_string(),
            })?;
            let cmd = exec::ProcessCommand {
                program: wc.program,
                args: wc.args,
                env: wc.env,
            };
            Ok(Box::new(exec::ExecBackend::start(name, cmd, opts)?))
        }
        "mock" => {
            let exe = std::env::current_exe().map_err(|e| BackendError::Setup {
                backend: name.into(),
                msg: e.to_string(),
            })?;
            mock::Script::parse(rest).map_err(|msg| BackendError::Setup {
                backend: name.into(),
                msg,
            })?;
            let cmd = exec::ProcessCommand {
                program: exe,
                args: vec!["mock-worker".into(), rest.to_string()],
                env: vec![],
            };
            Ok(Box::new(exec::ExecBackend::start(name, cmd, opts)?))
        }
        _ => Err(BackendError::Unknown(name.to_string())),
    }
}
