//! shadowcheck's shared vocabulary: the types that cross crate boundaries and go to disk.
//!
//! - [`enums`]: specification variants, API paths, GL state values (with their GL tokens);
//! - [`case`]: a test case (texture, sampler, lookup);
//! - [`sweep`]: more lookups of a case on the same texture and sampling state;
//! - [`state`]: a TexParameter / GetTexParameter state case, its expectation and observation;
//! - [`expect`]: the oracle's expectation, acceptance sets, observations and footprints;
//! - [`validate`]: checks that reject malformed cases with errors naming the field.
//!
//! No spec logic lives here: the oracle (`shadowcheck-oracle`) and the project's own texture unit
//! (`shadowcheck-soft`) both build on these types and check each other.

pub mod case;
pub mod enums;
pub mod expect;
pub mod keymap;
pub mod real;
pub mod state;
pub mod sweep;
pub mod validate;

pub use case::*;
pub use enums::*;
pub use expect::*;
pub use keymap::{KeyMap, Keyed};
pub use state::{
    AppliedExpect, ExtensionExpect, GlErrorCode, StateCall, StateCase, StateExpect, StateObserved,
    StatePname, StateType, StateValue,
};
pub use sweep::{split_point_id, PointExpectation, SweepPoint, MAX_SWEEP_POINTS, SWEEP_ID_TAG};

/// Version of the on-disk formats (fixtures, observations, results). Bumped on breaking change.
pub const SCHEMA_VERSION: u32 = 1;

/// Errors from parsing or validating model values.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    #[error("unknown {kind} `{key}` (expected one of: {expected})")]
    UnknownKey {
        kind: &'static str,
        key: String,
        expected: String,
    },
    #[error("case `{case}`: field `{field}`: {msg}")]
    Invalid {
        case: String,
        field: String,
        msg: String,
    },
}
