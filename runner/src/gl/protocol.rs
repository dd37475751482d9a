//! The worker's side of runner/PROTOCOL.md (version 1): the messages it reads and writes.

use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Texels};

pub const PROTOCOL_VERSION: u32 = 1;

/// A message from the runner, as read off the wire: a flat struct rather than an internally
/// tagged enum, which serde would buffer whole before deserializing the case (a third of the
/// worker's time on small cases).
#[derive(Debug, Deserialize)]
struct Wire {
    #[serde(rename = "type")]
    ty: String,
    #[serde(default)]
    protocol: u32,
    #[serde(default)]
    case: Option<Box<Case>>,
}

impl Incoming {
    /// Parses one line.
    pub fn parse(line: &str) -> Result<Incoming, String> {
        let w: Wire = serde_json::from_str(line).map_err(|e| e.to_string())?;
        match (w.ty.as_str(), w.case) {
            ("hello", _) => Ok(Incoming::Hello {
                protocol: w.protocol,
            }),
            ("case", Some(case)) => Ok(Incoming::Case { case }),
            ("case", None) => Err("case message without `case`".into()),
            ("flush", _) => Ok(Incoming::Flush),
            ("bye", _) => Ok(Incoming::Bye),
            (other, _) => Err(format!("unknown message type `{other}`")),
        }
    }
}

/// A message from the runner.
#[derive(Debug)]
pub enum Incoming {
    Hello { protocol: u32 },
    Case { case: Box<Case> },
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

/// An API path of a case that was not run, and why.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct PathSkip {
    pub api: ApiPath,
    pub reason: String,
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
        /// The case's API paths this worker did not run, with the reason (an extension of
        /// PROTOCOL.md; readers that do not know it ignore it).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        skipped: Vec<PathSkip>,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_runner_message_and_ignores_unknown_fields() {
        assert!(matches!(
            Incoming::parse(r#"{"type":"hello","protocol":1,"extra":true}"#),
            Ok(Incoming::Hello { protocol: 1 })
        ));
        assert!(matches!(
            Incoming::parse(r#"{"type":"flush"}"#),
            Ok(Incoming::Flush)
        ));
        assert!(matches!(
            Incoming::parse(r#"{"type":"bye"}"#),
            Ok(Incoming::Bye)
        ));
        let case = r#"{"type":"case","case":{"id":"x","spec":"gl46","api":["core"],"texture":{"target":"2d","format":"d16","levels":[{"width":1,"height":1,"layers":1,"depth":{"unorm":[7]}}]},"sampler":{"compare_mode":"compare","compare_func":"lequal","min_filter":"nearest","mag_filter":"nearest","wrap_s":"edge","wrap_t":"edge","wrap_r":"edge","border":[0,0,0,0]},"lookup":{"coord":[0.5,0.5,0,1],"dref":"nan"}}}"#;
        match Incoming::parse(case) {
            Ok(Incoming::Case { case }) => assert!(case.lookup.dref.is_nan() && case.id == "x"),
            other => panic!("{other:?}"),
        }
        assert!(Incoming::parse(r#"{"type":"case"}"#)
            .unwrap_err()
            .contains("without"));
        assert!(Incoming::parse(r#"{"type":"frobnicate"}"#)
            .unwrap_err()
            .contains("frobnicate"));
    }
}
