//! The messages of runner/PROTOCOL.md (version 1), for the runner side and for workers written in
//! Rust (the mock; the GL worker may use them too).

use super::Capabilities;
use crate::events::Rgba;
use serde::{Deserialize, Serialize};
use shadowcheck_model::{ApiPath, Case, Expectation, Lookup, Sampler, Spec, Texels, Texture};

pub const PROTOCOL_VERSION: u32 = 1;

/// The runner's greeting.
pub fn hello_line() -> String {
    format!(r#"{{"type":"hello","protocol":{PROTOCOL_VERSION}}}"#)
}

/// The implementation's greeting.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Hello {
    #[serde(rename = "type")]
    pub kind: String,
    pub protocol: u32,
    #[serde(default)]
    pub name: Option<String>,
    #[serde(default)]
    pub capabilities: Capabilities,
    /// Test doubles only (the mock): ask the runner to send each case with its `expect`.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub wants_expect: bool,
}

pub fn parse_hello(line: &str) -> Result<Hello, String> {
    let h: Hello = serde_json::from_str(line).map_err(|e| e.to_string())?;
    if h.kind != "hello" {
        return Err(format!("expected a hello message, got type `{}`", h.kind));
    }
    if h.protocol != PROTOCOL_VERSION {
        return Err(format!(
            "protocol {} (this runner speaks {PROTOCOL_VERSION})",
            h.protocol
        ));
    }
    Ok(h)
}

/// A case as sent: the fixture's case without `expect` (unless the implementation asked for it).
#[derive(Serialize)]
struct CaseOut<'a> {
    id: &'a str,
    spec: Spec,
    api: &'a [ApiPath],
    texture: &'a Texture,
    sampler: &'a Sampler,
    lookup: &'a Lookup,
    #[serde(skip_serializing_if = "Option::is_none")]
    expect: Option<&'a Expectation>,
}

#[derive(Serialize)]
struct CaseMsg<'a> {
    #[serde(rename = "type")]
    kind: &'static str,
    case: CaseOut<'a>,
}

/// Appends the `case` message for `c` (without the newline) to `buf`.
pub fn write_case(buf: &mut Vec<u8>, c: &Case, with_expect: bool) {
    let msg = CaseMsg {
        kind: "case",
        case: CaseOut {
            id: &c.id,
            spec: c.spec,
            api: &c.api,
            texture: &c.texture,
            sampler: &c.sampler,
            lookup: &c.lookup,
            expect: if with_expect { c.expect.as_ref() } else { None },
        },
    };
    // Serializing plain data into a Vec cannot fail (no maps with non-string keys here).
    let _ = serde_json::to_writer(&mut *buf, &msg);
}

/// One API path's result in an observation.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ApiResultMsg {
    pub api: String,
    pub rgba: Rgba,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stored: Option<Texels>,
    /// How the implementation realized this path (informative; not judged).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// An API path of a case that the implementation did not run, and why.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SkippedMsg {
    pub api: String,
    pub reason: String,
}

/// An implementation's answer to one case.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Answer {
    Observation {
        case_id: String,
        results: Vec<ApiResultMsg>,
        /// API paths not run, each Skip with its reason (optional; a path with neither a result
        /// nor an entry here is Skip without a reason).
        #[serde(default)]
        skipped: Vec<SkippedMsg>,
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

impl Answer {
    pub fn case_id(&self) -> &str {
        match self {
            Answer::Observation { case_id, .. }
            | Answer::Skip { case_id, .. }
            | Answer::Error { case_id, .. } => case_id,
        }
    }
}

pub fn parse_answer(line: &str) -> Result<Answer, String> {
    serde_json::from_str(line).map_err(|e| e.to_string())
}

/// What a worker reads.
#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Request {
    Hello {
        #[allow(dead_code)]
        protocol: u32,
    },
    Case {
        case: Box<Case>,
    },
    Flush,
    Bye,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_parse_with_non_finite_channels_and_unknown_fields() {
        let a =
            parse_answer(r#"{"type":"observation","case_id":"x","extra":1,"results":[{"api":"core","rgba":["nan",0,"inf",1]}]}"#).unwrap();
        match a {
            Answer::Observation {
                case_id, results, ..
            } => {
                assert_eq!(case_id, "x");
                assert!(results[0].rgba.0[0].is_nan());
                assert_eq!(results[0].rgba.0[2], f64::INFINITY);
            }
            other => panic!("{other:?}"),
        }
        assert!(parse_answer(r#"{"type":"bogus","case_id":"x"}"#).is_err());
        let h = parse_hello(r#"{"type":"hello","protocol":1,"capabilities":{"specs":["gl46"]}}"#)
            .unwrap();
        assert_eq!(h.capabilities.specs, Some(vec!["gl46".to_string()]));
        assert!(h.capabilities.formats.is_none());
        assert!(parse_hello(r#"{"type":"hello","protocol":2}"#).is_err());
    }
}
