//! A backend's answer for one case, before it becomes a protocol reply
//! ([`crate::serve`] adds the case id).

use shadowcheck_protocol::{PathResult, PathSkip};

/// The answer for one case.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    /// The paths that ran, and why the others did not.
    Observation(Vec<PathResult>, Vec<PathSkip>),
    Skip(String),
    Error(String),
}
