//! The messages of runner/PROTOCOL.md (version [`PROTOCOL_VERSION`]), the one definition used by
//! the runner's `exec:` backend, the `mock:` worker and the GL worker.
//!
//! One type per direction: [`Request`] (runner → implementation) and [`Reply`] (implementation →
//! runner). [`Capabilities`] is what an implementation declares in its hello, and
//! [`Capabilities::support`] is the one place that decides whether a case runs on it (and the Skip
//! reason when not).

mod capabilities;

pub use capabilities::{Capabilities, Feature, Support, FEATURES, TEX_PARAMETER};

use serde::{Deserialize, Serialize};
use shadowcheck_model::{
    ApiPath, Case, Expectation, Lookup, PointExpectation, Sampler, Spec, StateCase, StateObserved,
    SweepPoint, Texels, Texture,
};

/// The protocol version both sides speak.
/// 2: TexParameter state cases (`state` requests, `state_observation` answers).
pub const PROTOCOL_VERSION: u32 = 2;

/// Four channels that may be non-finite (written as "nan", "inf", "-inf").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Rgba(#[serde(with = "shadowcheck_model::real::array4")] pub [f64; 4]);

// ---------------------------------------------------------------------------------------------
// Runner → implementation.

/// A message from the runner.
#[derive(Debug)]
pub enum Request {
    Hello {
        protocol: u32,
    },
    Case {
        case: Box<Case>,
    },
    /// A TexParameter / GetTexParameter state case (sent only to implementations whose
    /// capabilities list the `tex_parameter` feature, or declare no feature list).
    State {
        case: Box<StateCase>,
    },
    Flush,
    Bye,
}

/// A request as read off the wire: a flat struct rather than an internally tagged enum, which
/// serde would buffer whole before deserializing the case (a third of the GL worker's time on
/// small cases).
#[derive(Debug, Deserialize)]
struct RequestWire {
    #[serde(rename = "type")]
    ty: String,
    #[serde(default)]
    protocol: u32,
    #[serde(default)]
    case: Option<Box<Case>>,
    #[serde(default)]
    state: Option<Box<StateCase>>,
}

impl Request {
    /// Parses one line.
    pub fn parse(line: &str) -> Result<Request, String> {
        let w: RequestWire = serde_json::from_str(line).map_err(|e| e.to_string())?;
        if w.ty == "state" {
            return match w.state {
                Some(case) => Ok(Request::State { case }),
                None => Err("state message without `state`".into()),
            };
        }
        match (w.ty.as_str(), w.case) {
            ("hello", _) => Ok(Request::Hello {
                protocol: w.protocol,
            }),
            ("case", Some(case)) => Ok(Request::Case { case }),
            ("case", None) => Err("case message without `case`".into()),
            ("flush", _) => Ok(Request::Flush),
            ("bye", _) => Ok(Request::Bye),
            (other, _) => Err(format!("unknown message type `{other}`")),
        }
    }

    /// The runner's greeting line (without the newline).
    pub fn hello_line() -> String {
        format!(r#"{{"type":"hello","protocol":{PROTOCOL_VERSION}}}"#)
    }

    /// The `flush` line, newline included.
    pub const FLUSH_LINE: &'static [u8] = b"{\"type\":\"flush\"}\n";
    /// The `bye` line, newline included.
    pub const BYE_LINE: &'static [u8] = b"{\"type\":\"bye\"}\n";

    /// Appends the `case` message for `c` (without the newline) to `buf`: the fixture's case
    /// without `expect` (unless the implementation asked for it with `wants_expect`).
    pub fn write_case(buf: &mut Vec<u8>, c: &Case, with_expect: bool) {
        Request::write_case_on(buf, c, &c.api, with_expect)
    }

    /// [`Request::write_case`] with `api` in place of the case's API paths (the ones it is a
    /// test of on the implementation it is sent to).
    pub fn write_case_on(buf: &mut Vec<u8>, c: &Case, api: &[ApiPath], with_expect: bool) {
        let msg = CaseMsg {
            kind: "case",
            case: CaseOut {
                id: &c.id,
                spec: c.spec,
                api,
                texture: &c.texture,
                sampler: &c.sampler,
                lookup: &c.lookup,
                expect: if with_expect { c.expect.as_ref() } else { None },
                sweep: Points {
                    points: &c.sweep,
                    with_expect,
                },
            },
        };
        // Serializing plain data into a Vec cannot fail (no maps with non-string keys here).
        let _ = serde_json::to_writer(&mut *buf, &msg);
    }
}

impl Request {
    /// Appends the `state` message for `c` (without the newline) to `buf`, without `expect`
    /// unless `with_expect`.
    pub fn write_state(buf: &mut Vec<u8>, c: &StateCase, with_expect: bool) {
        #[derive(Serialize)]
        struct StateMsg<'a> {
            #[serde(rename = "type")]
            kind: &'static str,
            state: &'a StateCase,
        }
        let stripped;
        let state = if with_expect || c.expect.is_none() {
            c
        } else {
            stripped = StateCase {
                expect: None,
                ..c.clone()
            };
            &stripped
        };
        let _ = serde_json::to_writer(
            &mut *buf,
            &StateMsg {
                kind: "state",
                state,
            },
        );
    }
}

/// One API path's (context kind's) result of a state case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StateResult {
    pub api: String,
    #[serde(flatten)]
    pub observed: StateObserved,
}

/// A case as sent (borrowed, so the runner serializes without cloning).
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
    #[serde(skip_serializing_if = "Points::is_empty")]
    sweep: Points<'a>,
}

/// A case's sweep points on the wire: coordinates and reference, the expectations only for an
/// implementation that asked for them.
struct Points<'a> {
    points: &'a [SweepPoint],
    with_expect: bool,
}

impl Points<'_> {
    fn is_empty(&self) -> bool {
        self.points.is_empty()
    }
}

impl Serialize for Points<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        #[derive(Serialize)]
        struct Bare<'a> {
            #[serde(with = "shadowcheck_model::real::array4")]
            coord: [f64; 4],
            #[serde(with = "shadowcheck_model::real")]
            dref: f64,
            #[serde(skip_serializing_if = "Option::is_none")]
            expect: Option<&'a PointExpectation>,
        }
        let mut seq = s.serialize_seq(Some(self.points.len()))?;
        for p in self.points {
            seq.serialize_element(&Bare {
                coord: p.coord,
                dref: p.dref,
                expect: if self.with_expect {
                    p.expect.as_ref()
                } else {
                    None
                },
            })?;
        }
        seq.end()
    }
}

#[derive(Serialize)]
struct CaseMsg<'a> {
    #[serde(rename = "type")]
    kind: &'static str,
    case: CaseOut<'a>,
}

// ---------------------------------------------------------------------------------------------
// Implementation → runner.

/// The implementation's greeting (the body of [`Reply::Hello`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Hello {
    pub protocol: u32,
    #[serde(default)]
    pub name: Option<String>,
    #[serde(default)]
    pub capabilities: Capabilities,
    /// Test doubles only (the mock): ask the runner to send each case with its `expect`.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub wants_expect: bool,
    /// The implementation runs sweep cases (PROTOCOL.md §2): it is sent a case with its `sweep`
    /// and answers each path with one `sweep` RGBA per point. Without it the runner sends each
    /// point as a case of its own.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub sweeps: bool,
}

/// One API path's result in an observation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathResult {
    /// The API path's fixture key (kept as text so that a path the runner does not know is
    /// reported against the case rather than failing the parse).
    pub api: String,
    pub rgba: Rgba,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stored: Option<Texels>,
    /// How the implementation realized this path (GLSL function, LOD method); informative only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// A sweep case's points, in order: the RGBA of each (PROTOCOL.md §2). Empty otherwise.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sweep: Vec<Rgba>,
}

/// An API path of a case that the implementation did not run, and why.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathSkip {
    pub api: String,
    pub reason: String,
}

/// A message from the implementation: its hello, then one answer per case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Reply {
    Hello(Hello),
    Observation {
        case_id: String,
        results: Vec<PathResult>,
        /// API paths not run, each Skip with its reason (optional; a path with neither a result
        /// nor an entry here is Skip without a reason).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        skipped: Vec<PathSkip>,
    },
    /// The answer to a `state` request: what each API path's context observed.
    StateObservation {
        case_id: String,
        results: Vec<StateResult>,
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

/// Just the `type` of a message.
#[derive(Deserialize)]
struct Tag {
    #[serde(rename = "type")]
    ty: String,
}

impl Reply {
    /// The case an answer is for (`None` for a hello).
    pub fn case_id(&self) -> Option<&str> {
        match self {
            Reply::Hello(_) => None,
            Reply::Observation { case_id, .. }
            | Reply::StateObservation { case_id, .. }
            | Reply::Skip { case_id, .. }
            | Reply::Error { case_id, .. } => Some(case_id),
        }
    }

    /// Parses the implementation's greeting and checks its protocol version.
    pub fn parse_hello(line: &str) -> Result<Hello, String> {
        let h: Hello = serde_json::from_str(line).map_err(|e| e.to_string())?;
        let tag: Tag = serde_json::from_str(line).map_err(|e| e.to_string())?;
        if tag.ty != "hello" {
            return Err(format!("expected a hello message, got type `{}`", tag.ty));
        }
        let mut h = h;
        match h.protocol {
            PROTOCOL_VERSION => {}
            // Version 1 had no state cases: such an implementation is never sent one (its
            // features lose `tex_parameter`; no list meant every version-1 feature).
            1 => {
                let all = || FEATURES.iter().map(|f| f.key.to_string()).collect();
                let mut features: Vec<String> = h.capabilities.features.take().unwrap_or_else(all);
                features.retain(|f| f != TEX_PARAMETER);
                h.capabilities.features = Some(features);
            }
            other => {
                return Err(format!(
                    "protocol {other} (this runner speaks {PROTOCOL_VERSION}, and 1 without state cases)"
                ))
            }
        }
        Ok(h)
    }

    /// Parses an answer to a case (a hello here is an error).
    pub fn parse_answer(line: &str) -> Result<Reply, String> {
        match serde_json::from_str(line).map_err(|e| e.to_string())? {
            Reply::Hello(_) => Err("a hello where an answer to a case was expected".into()),
            a => Ok(a),
        }
    }
}

#[cfg(test)]
mod tests;
