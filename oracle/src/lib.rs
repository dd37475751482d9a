//! shadowcheck's oracle: the depth-comparison specifications encoded literally.
//!
//! INTERFACE (fixed; other crates build against it):
//! - [`evaluate`]: a case in, the [`Evaluation`] out (the expectation stored in fixtures, the
//!   footprint for failure dumps and the derivation steps with citations for `explain`).
//! - [`OracleError`]: the case is not something the spec defines (e.g. LESS under ARB_shadow,
//!   which is an INVALID_ENUM), or is malformed.

use shadowcheck_model::{Case, Expectation, Footprint};

/// One derivation step, for `shadowcheck explain`.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Step {
    /// What was computed, e.g. "Dref clamped to [0,1]: 1.5 -> 1".
    pub what: String,
    /// The section it comes from, e.g. "GL 4.6 §8.23.1".
    pub cite: String,
}

/// Everything the oracle says about one case.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Evaluation {
    pub expect: Expectation,
    pub footprint: Footprint,
    pub steps: Vec<Step>,
}

#[derive(Debug, thiserror::Error)]
pub enum OracleError {
    /// The state is illegal under the spec: setting it raises a GL error, so no lookup happens.
    #[error("case `{case}`: {spec} rejects this state with {error}: {why}")]
    GlError { case: String, spec: String, error: &'static str, why: String },
    /// The case is malformed (see shadowcheck_model::validate).
    #[error(transparent)]
    Model(#[from] shadowcheck_model::ModelError),
}

/// Evaluates a case under its own spec variant.
pub fn evaluate(case: &Case) -> Result<Evaluation, OracleError> {
    shadowcheck_model::validate::validate(case)?;
    todo!("oracle evaluate")
}
