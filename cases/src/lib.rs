//! shadowcheck-cases: the grids that enumerate depth-comparison cases, the generator that writes
//! them as JSON fixtures with the oracle's expectations, and the fixture loader.
//!
//! - [`dsl`]: a small typed grid DSL (cartesian product, filters that say why, derived values);
//! - [`build`]: stored texel values per format, textures per target, lookups at known positions;
//! - [`grids`]: the named grids (`smoke`, `default`, `exhaustive`) and [`grids::generate`];
//! - [`fixtures`]: the versioned fixture file format, its writer and loaders (which re-derive every
//!   case's `expect` with the linked oracle, `recheck`);
//! - [`coverage`]: cases per spec x target x format x filter x func, checks per compiled state;
//! - [`features`]: cases per feature (mixed filters, per-coordinate wraps, ...) and spec;
//! - [`pairs`]: pairwise coverage of the unit-state interactions (the `interact` covering array);
//! - [`markers`]: generated sections of hand-written Markdown (README tables).
//!
//! The format is documented in cases/README.md; its JSON Schema is cases/schema/fixture.schema.json.

pub mod build;
pub mod coverage;
pub mod dsl;
pub mod features;
mod fixture_error;
pub mod fixtures;
pub mod format_audit;
pub mod grids;
pub mod markers;
pub mod pairs;
mod recheck;

pub use grids::GridError;
