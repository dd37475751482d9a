//! What an implementation declares it can run, and the one decision made from it: does a case run
//! (on which API paths), is it Skip and why, or is it no test of this implementation at all (a spec
//! or API path it does not implement: not applicable, as a dEQP caselist would not list it).

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case};

/// What an implementation can run (fixture keys). `None` for a list means "no restriction
/// declared".
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
#[derive(Debug, Clone, PartialEq)]
pub enum Support {
    /// Run these paths (a subset of the case's); the others are not applicable (API paths the
    /// implementation does not implement), with the reason.
    Run {
        apis: Vec<ApiPath>,
        others: Option<String>,
    },
    /// Applicable, but not run here (a target or format the implementation lacks): Skip, with
    /// the reason.
    Skip(String),
    /// No test of this implementation: its spec, or every one of its API paths, is one the
    /// implementation does not implement. Not counted as a test.
    NotApplicable(String),
}

impl Capabilities {
    /// Whether the implementation implements API path `api` (no list declared: every path).
    pub fn implements_api(&self, api: ApiPath) -> bool {
        listed(&self.api, api.key())
    }

    /// Everything allowed.
    pub fn all() -> Capabilities {
        Capabilities::default()
    }

    /// Whether `case` runs here: the runner calls this before sending a case (anything outside
    /// is never sent), and a worker may call it on what it receives. Not applicable (spec, API
    /// paths) is decided before Skip (target, format): a path the backend does not implement is
    /// no test of it, whatever the texture.
    pub fn support(&self, case: &Case) -> Support {
        if !listed(&self.specs, case.spec.key()) {
            return Support::NotApplicable(format!(
                "spec `{}` not supported by this backend",
                case.spec
            ));
        }
        let apis: Vec<ApiPath> = case
            .api
            .iter()
            .copied()
            .filter(|a| self.implements_api(*a))
            .collect();
        if apis.is_empty() {
            return Support::NotApplicable(
                "none of the case's API paths is supported by this backend".to_string(),
            );
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
        let others = (apis.len() < case.api.len())
            .then(|| "API path not supported by this backend".to_string());
        Support::Run { apis, others }
    }
}
