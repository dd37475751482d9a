//! The worker's side of runner/PROTOCOL.md (version 1): the messages it reads and writes.

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Texels};

pub const PROTOCOL_VERSION: u32 = 1;

/// A message from the runner.
#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Incoming {
    Hello {
        #[serde(default)]
        protocol: u32,
    },
    Case {
        case: Box<Case>,
    },
    Flush,
    Bye,
}

/// What the worker can check (fixture keys).
#[derive(Debug, Clone, Default, Serialize, Deserialize, PartialEq)]
pub struct Capabilities {
    pub specs: Vec<String>,
    pub api: Vec<String>,
    pub targets: Vec<String>,
    pub formats: Vec<String>,
    pub extensions: Vec<String>,
}

/// One API path's result.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct PathResult {
    pub api: ApiPath,
    #[serde(with = "shadowcheck_model::real::array4")]
    pub rgba: [f64; 4],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stored: Option<Texels>,
    /// How the path realized the case (GLSL function, LOD method); informative only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// A message to the runner.
#[derive(Debug, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Outgoing {
    Hello {
        protocol: u32,
        name: String,
        capabilities: Capabilities,
    },
    Observation {
        case_id: String,
        results: Vec<PathResult>,
    },
    Skip {
        case_id: String,
        reason: String,
    },
    Error {
        case_id: String,
        message: String,
    },
}
