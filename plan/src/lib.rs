//! shadowcheck-plan: what to draw for a case, for every backend that draws one. The GL worker
//! (shadowcheck-gl), the WebGL page (shadowcheck-webgl) and the standalone C reproducer
//! (`shadowcheck repro`) are its users; none of them decides any of this on its own.
//!
//! For a case and an API path:
//! - [`paths`]: the lookup: the sampler type and function that realize the case's level of detail,
//!   offsets and gathers, and the values the shader receives ([`Plan`], keyed by [`ShaderKey`]);
//! - [`shaders`]: the program text, one emitter per language (GLSL 1.10/1.20, GLSL 1.30+ and
//!   GLSL ES, ARB fragment programs);
//! - [`texels`]: the pixel transfer and the bytes of every level, layer and face;
//! - [`unit`]: the texture and sampler-object state, as the calls that set it, in order;
//! - [`layout`]: the quad of each (case, path) in the result image and the batched draws;
//! - [`units`]: texture states dealt into bundles, one texture unit each, so that one compiled
//!   program samples many sampler states;
//! - [`sweep`]: a case's sweep points as lookups of their own, and the fold of their answers back
//!   into one [`Answer`] per case;
//! - [`serve`]: the worker side of runner/PROTOCOL.md, running any [`serve::Serve`] drawer.
//!
//! Nothing here opens a library, a window system or a process: `cargo test -p shadowcheck-plan`
//! runs on a machine without GL.

pub mod answer;
pub mod context;
pub mod gl;
pub mod layout;
pub mod paths;
pub mod serve;
pub mod shaders;
pub mod sweep;
#[cfg(any(test, feature = "test-support"))]
pub mod test_case;
pub mod texels;
pub mod unit;
pub mod units;

pub use answer::Answer;
pub use context::{ContextApi, GlInfo, LookupForm};
pub use paths::{GatherCall, LodForm, Plan, SamplerKind, ShaderKey};
pub use sweep::Job;

/// A case the plan cannot describe.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    /// The case's texels are not in the encoding its format stores.
    #[error("texel encoding does not match format {0}")]
    Encoding(shadowcheck_model::Format),
}
