//! shadowcheck's oracle: the depth-comparison specifications encoded literally.
//!
//! INTERFACE (fixed; other crates build against it):
//! - [`evaluate`]: a case in, the [`Evaluation`] out (the expectation stored in fixtures, the
//!   footprint for failure dumps and the derivation steps with citations for `explain`).
//! - [`OracleError`]: the case is not something the spec defines (e.g. LESS under ARB_shadow,
//!   which is an INVALID_ENUM), or is malformed.
//!
//! Layout:
//! - one module per specification (`sgix`, `arb`, `ext_funcs`, `es2_ext`, `gl46`, `gles32`), each filling a
//!   [`rules::Rules`] beside the sentences it encodes: comparison table, clamps, border, filtering,
//!   completeness, targets, formats, API paths, its TexParameter table (`params`, served by `state`) and
//!   its readings of the documents' disagreements; [`rules::rules_for`] is the registry;
//! - shared machinery that asks the `Rules` and never matches on the spec: `check` (GL errors,
//!   not-applicable), `unorm`, `wrap`, `cube`, `lod`, `select`, `sample`, `accept`, `layout`, and `engine`,
//!   whose `run` is the list of phases (inputs, completeness and layout, geometry, levels and per-profile
//!   intervals, footprint, acceptance);
//! - precision profiles as data (`profile::PROFILES`, strictest first); TexParameter state (`state`); the
//!   documents' disagreements (`contradictions`); `explain`.
//!
//! Adding a spec rule: a rule of an existing spec is changed in its module only; a new kind of
//! difference is a `Rules` field (`rules.rs`) plus its value in each spec module. A new spec is one
//! module plus one line in `rules::rules_for` (and its `Spec` variant in the model).
//!
//! Adding a precision tier: a `shadowcheck_model::Profile` variant (in strictness order) and its entry in
//! `profile::PROFILES`; everything else iterates the table (see `profile`).

use shadowcheck_model::{Case, Expectation, Footprint};

pub mod accept;
pub mod arb;
pub mod check;
pub mod contradictions;
pub mod cube;
mod engine;
pub mod es2_ext;
pub mod explain;
pub mod ext_funcs;
pub mod gl46;
pub mod gles32;
pub mod layout;
pub mod lod;
pub mod profile;
pub mod rules;
pub mod sample;
mod select;
pub mod sgix;
pub mod state;
pub mod unorm;
pub mod vulkan;
pub mod webgpu;
pub mod wrap;

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
    GlError {
        case: String,
        spec: String,
        error: &'static str,
        why: String,
    },
    /// The spec defines no such lookup (an API path, target or format it does not have).
    #[error("case `{case}`: not defined by {spec}: {why}")]
    NotApplicable {
        case: String,
        spec: String,
        why: String,
    },
    /// The case is malformed (see shadowcheck_model::validate).
    #[error(transparent)]
    Model(#[from] shadowcheck_model::ModelError),
}

/// Evaluates a case under its own spec variant.
pub fn evaluate(case: &Case) -> Result<Evaluation, OracleError> {
    shadowcheck_model::validate::validate(case)?;
    engine::run(case, rules::rules_for(case.spec))
}

/// Evaluates a case under the other reading of a contradiction (see [`contradictions`]), for `explain`.
/// `None` when the contradiction has no alternative rule for this case's spec.
pub fn evaluate_reading(
    case: &Case,
    contradiction: &str,
) -> Option<Result<Evaluation, OracleError>> {
    if let Err(e) = shadowcheck_model::validate::validate(case) {
        return Some(Err(e.into()));
    }
    let r = contradictions::alternative_rules(case, contradiction)?;
    Some(engine::run(case, r))
}
