//! The named grids (`smoke`, `default`, `exhaustive`) and the generator that turns them into
//! fixture files with the oracle's expectations filled in.

pub mod cells;
pub mod delivery;
pub mod draft;
pub mod exhaustive;
pub mod families;
pub mod gather;
pub mod interact;
pub mod offset;
pub mod random;
pub mod specs;
pub mod stage;
pub mod sweep;
pub mod tex_params;

use crate::dsl;
use crate::fixtures::{self, FixtureFile};
use draft::Draft;
use shadowcheck_model::{Case, CompareMode, Spec, SCHEMA_VERSION};
use shadowcheck_oracle::OracleError;
use std::collections::{BTreeMap, BTreeSet, HashSet};

/// `shadowcheck-cases <version>`: written into every fixture file.
pub const GENERATOR: &str = concat!("shadowcheck-cases ", env!("CARGO_PKG_VERSION"));

/// Errors from building a grid.
#[derive(Debug, thiserror::Error)]
pub enum GridError {
    #[error("unknown grid `{name}` (known: {})", names().join(", "))]
    UnknownGrid { name: String },
    #[error("grid `{grid}`: duplicate case id `{id}`")]
    DuplicateId { grid: String, id: String },
    #[error("grid `{grid}`: case `{id}`: no API path applies to it")]
    NoApi { grid: String, id: String },
    /// The oracle rejected a generated case: the grid is missing a filter for an illegal
    /// combination, or the case is malformed. Either way the grid must be fixed, not the fixture.
    #[error("grid `{grid}`: the oracle rejects a generated case (the grid needs a filter for it): {source}")]
    Oracle { grid: String, source: OracleError },
    /// The oracle cannot state a generated state case's expectation.
    #[error("grid `{grid}`: state case `{id}`: {msg}")]
    State {
        grid: String,
        id: String,
        msg: String,
    },
    #[error(transparent)]
    Fixture(#[from] fixtures::FixtureError),
}

/// The grids `shadowcheck gen --grid` knows.
pub fn names() -> &'static [&'static str] {
    &["smoke", "default", "exhaustive"]
}

/// The seed the committed `default` fixtures are generated with.
pub const DEFAULT_SEED: u64 = 0;
/// Cases in the seeded random family of `default`, per spec.
const RANDOM_PER_SPEC: usize = 30;

/// The cases of a grid before the oracle has seen them (not for `exhaustive`, which is streamed).
pub fn drafts(name: &str, seed: u64) -> Result<Vec<Draft>, GridError> {
    match name {
        "default" => Ok(default_drafts(seed)),
        "smoke" => Ok(smoke_drafts(seed)),
        _ => Err(GridError::UnknownGrid {
            name: name.to_string(),
        }),
    }
}

fn default_drafts(seed: u64) -> Vec<Draft> {
    specs::all()
        .iter()
        .flat_map(|d| spec_grid(d, seed).into_items())
        .collect()
}

/// TEXTURE_MIN_LOD, TEXTURE_MAX_LOD, TEXTURE_BASE_LEVEL or TEXTURE_MAX_LEVEL differ from the default.
fn uses_lod_state(x: &Draft) -> bool {
    x.sampler.min_lod != -1000.0
        || x.sampler.max_lod != 1000.0
        || x.sampler.max_level.is_some()
        || x.texture.base_level != 0
}

/// All `default` cases of one spec: the main product expanded into its lookups, the focused
/// families, then the filters that drop state the spec does not have.
pub fn spec_grid(d: &specs::SpecDims, seed: u64) -> dsl::Grid<Draft> {
    let mut g = cells::cells(d)
        .flat_map(cells::drafts)
        .extend(families::clamp(d))
        .extend(families::exact(d))
        .extend(families::pcf(d));
    // The *_ambient variants differ from their base spec only in the fail value: they get the
    // main product, the value families, wrap and `ambient`, not the sampling-geometry families again.
    if !d.fail_value {
        g = g
            .extend(families::mip(d))
            .extend(families::cube(d))
            .extend(families::cube_wraps(d))
            .extend(families::cube_mip(d))
            .extend(families::layer(d))
            .extend(families::mixfilter(d))
            .extend(families::incomplete(d))
            .extend(families::proj(d))
            .extend(families::swizzle(d))
            .extend(families::seamless(d))
            .extend(families::sampler_object(d))
            .extend(offset::offset(d))
            .extend(gather::gather(d))
            .extend(delivery::delivery(d))
            .extend(stage::stage(d));
    }
    g.extend(families::wrap(d))
        .extend(families::dtm(d))
        .extend(families::stencil(d))
        .extend(families::formats(d))
        .extend(families::ambient(d))
        .extend(interact::interact(d))
        .extend(random::random(d, seed, RANDOM_PER_SPEC))
        .filter(
            "ES 2.0 has no TEXTURE_MIN_LOD / MAX_LOD / BASE_LEVEL / MAX_LEVEL (added by GL 1.2 and ES 3.0; INVALID_ENUM)",
            |x| d.lod_state || !uses_lod_state(x),
        )
        .filter(
            "TEXTURE_LOD_BIAS does not exist in ES or SGIX-era GL (ES 3.2 §8.14.1; INVALID_ENUM), nor in WebGPU's GPUSamplerDescriptor",
            |x| d.lod_bias || (x.sampler.lod_bias == 0.0 && x.sampler.in_effect().lod_bias == 0.0),
        )
        .filter(
            "no shader bias argument on this spec's shadow lookups (shadow2DEXT, fixed function)",
            |x| d.shader_bias || x.lookup.bias == 0.0,
        )
        .filter(
            "Vulkan, WebGPU: a depth comparison needs a depth image and a comparison sampler (Vulkan 1.3 §16 Depth Compare Operation: compareEnable; WGSL texture built-in functions: a sampler_comparison); a depth read without comparison is no depth comparison",
            |x| {
                specs::compare_none(d.spec)
                    || (x.sampler.in_effect().compare_mode == CompareMode::Compare
                        && x.texture.format.is_depth())
            },
        )
        .filter(
            "Vulkan: the depth border Br is that of a VkBorderColor value, 0 (FLOAT_TRANSPARENT_BLACK) or 1 (FLOAT_OPAQUE_WHITE) (Vulkan 1.3 §16 Texel Replacement: \"Depth aspect D = Br\")",
            |x| d.spec != Spec::Vulkan || [0.0, 1.0].contains(&x.sampler.in_effect().border[0]),
        )
        .filter(
            "Vulkan, WebGPU: no incomplete textures (an image view has levelCount levels, Vulkan 1.3 §12.5; a GPUTextureView mipLevelCount, WebGPU createView), no texture swizzle on a depth-compare lookup, no GL sampler objects or seamless enable",
            |x| {
                !specs::sampler_create(d.spec)
                    || (shadowcheck_oracle::lod::incomplete(
                        &shadowcheck_oracle::rules::rules_for(d.spec),
                        &x.texture,
                        &x.sampler.in_effect(),
                        false,
                    )
                    .is_none()
                        && x.sampler.swizzle.is_none()
                        && x.sampler.sampler_object.is_none()
                        && x.sampler.seamless.is_none())
            },
        )
        .filter(
            "Vulkan: D32_SFLOAT texels outside [0,1] are undefined without VK_EXT_depth_range_unrestricted (a copy stores them as given; GL's upload clamps them)",
            |x| d.spec != Spec::Vulkan || floats_in_unit_range(&x.texture),
        )
        .filter(
            "WebGPU: depth texels are written by a render pass's frag_depth, which \"is clamped to the current [[viewport]] depth range\" (WebGPU, Output Merging); texel copies into depth formats are not allowed (WebGPU, Copying Depth/Stencil Textures)",
            |x| d.spec != Spec::WebGpu || floats_in_unit_range(&x.texture),
        )
        .filter(
            "WebGPU: the array index of a depth-compare built-in is an i32 or u32 (WGSL textureSampleCompare: \"array_index: The 0-based texture array index\"), so the layer coordinate is an integer",
            |x| d.spec != Spec::WebGpu || array_layer(&x.lookup, x.texture.target).is_none_or(|a| a.fract() == 0.0),
        )
        .filter(
            "WebGPU: GPUSamplerDescriptor has no border colour and GPUAddressMode no clamp-to-border (WebGPU, Samplers)",
            |x| d.spec != Spec::WebGpu || x.sampler.in_effect().border == [0.0; 4],
        )
        .filter(
            "WebGPU: WGSL has no projective texture built-in (WGSL texture built-in functions)",
            |x| d.spec != Spec::WebGpu || !x.lookup.projective,
        )
}

/// The array layer coordinate of a lookup on `target` (1D array: t; 2D array: r; cube array:
/// `layer`), `None` for a target without layers.
fn array_layer(l: &shadowcheck_model::Lookup, target: shadowcheck_model::Target) -> Option<f64> {
    use shadowcheck_model::Target;
    match target {
        Target::T1dArray => Some(l.coord[1]),
        Target::T2dArray => Some(l.coord[2]),
        Target::CubeArray => Some(l.layer),
        _ => None,
    }
}

/// Every stored float depth lies in [0, 1].
fn floats_in_unit_range(t: &shadowcheck_model::Texture) -> bool {
    t.levels.iter().all(|l| match &l.depth {
        shadowcheck_model::Texels::Float(v) => v.iter().all(|d| (0.0..=1.0).contains(d)),
        shadowcheck_model::Texels::Unorm(_) | shadowcheck_model::Texels::Colour(_) => true,
    })
}

/// One of everything: the first `default` case for each new (spec, value) of every dimension and
/// each family, so every target, format, filter, func, family, DEPTH_TEXTURE_MODE and wrap mode of
/// each spec appears at least once.
fn smoke_drafts(seed: u64) -> Vec<Draft> {
    let mut seen: HashSet<String> = HashSet::new();
    let mut out = Vec::new();
    for x in default_drafts(seed) {
        let c = &x.cell;
        let s = &x.sampler;
        let keys = [
            format!("target {}", c.target),
            format!("format {}", c.format),
            format!("filter {}", c.filter),
            format!("func {}", c.func_key()),
            format!("family {}", x.family),
            format!("dtm {:?}", c.dtm),
            format!("wrap {}", s.wrap_s),
            format!("dsm {:?}", s.depth_stencil_mode),
            format!("target-format {} {}", c.target, c.format),
        ];
        let mut new = false;
        for k in keys {
            new |= seen.insert(format!("{} {k}", c.spec));
        }
        if new {
            out.push(x);
        }
    }
    out
}

/// The combinations the `default` grid's filters removed, per reason, summed over the specs (what
/// `shadowcheck gen` reports as pruned).
pub fn pruned() -> Vec<(String, usize)> {
    let mut out: Vec<(String, usize)> = Vec::new();
    for d in specs::all() {
        for (why, n) in spec_grid(&d, DEFAULT_SEED).pruned() {
            match out.iter_mut().find(|(w, _)| w == why) {
                Some(slot) => slot.1 += n,
                None => out.push((why.clone(), *n)),
            }
        }
    }
    out
}

/// Turns drafts into cases and checks what the oracle cannot: unique ids, a non-empty API list.
fn to_cases(grid: &str, drafts: Vec<Draft>) -> Result<Vec<(String, Case)>, GridError> {
    let mut ids = HashSet::new();
    let mut out = Vec::with_capacity(drafts.len());
    for x in drafts {
        let file = x.file(grid);
        let case = x.into_case();
        if !ids.insert(case.id.clone()) {
            return Err(GridError::DuplicateId {
                grid: grid.into(),
                id: case.id,
            });
        }
        if case.api.is_empty() {
            return Err(GridError::NoApi {
                grid: grid.into(),
                id: case.id,
            });
        }
        out.push((file, case));
    }
    Ok(out)
}

/// Fills `expect` from the oracle, on all cores; the order of `cases` is kept.
pub fn fill_expectations(grid: &str, cases: &mut [Case]) -> Result<(), GridError> {
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, 16);
    let chunk = cases.len().div_ceil(threads).max(1);
    let results: Vec<Result<(), OracleError>> = std::thread::scope(|s| {
        let handles: Vec<_> = cases
            .chunks_mut(chunk)
            .map(|part| {
                s.spawn(move || {
                    for c in part.iter_mut() {
                        c.expect = Some(shadowcheck_oracle::evaluate(c)?.expect);
                    }
                    Ok(())
                })
            })
            .collect();
        // A panicking oracle is a bug to report, not something to recover from: re-raise it.
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    });
    for r in results {
        r.map_err(|source| GridError::Oracle {
            grid: grid.into(),
            source,
        })?;
    }
    Ok(())
}

/// Groups cases into files (sorted by relative path; cases keep generation order inside a file).
fn into_files(grid: &str, seed: u64, cases: Vec<(String, Case)>) -> Vec<(String, FixtureFile)> {
    let mut files: BTreeMap<String, Vec<Case>> = BTreeMap::new();
    for (file, case) in cases {
        files.entry(file).or_default().push(case);
    }
    files
        .into_iter()
        .map(|(rel, cases)| {
            (
                rel,
                FixtureFile {
                    schema_version: SCHEMA_VERSION,
                    generator: GENERATOR.to_string(),
                    grid: grid.to_string(),
                    seed,
                    cases,
                    state_cases: vec![],
                },
            )
        })
        .collect()
}

/// Generates a grid with expectations filled in, as (relative path, file) pairs sorted by path.
/// For `exhaustive` this holds everything in memory; prefer [`for_each_file`] there.
pub fn generate(name: &str, seed: u64) -> Result<Vec<(String, FixtureFile)>, GridError> {
    let mut out = Vec::new();
    for_each_file(name, seed, |rel, file| {
        out.push((rel, file));
        Ok(())
    })?;
    Ok(out)
}

/// Generates a grid file by file, handing each to `sink` as soon as it is complete (so `exhaustive`
/// never needs to be in memory at once). Files arrive sorted by relative path.
pub fn for_each_file(
    name: &str,
    seed: u64,
    mut sink: impl FnMut(String, FixtureFile) -> Result<(), GridError>,
) -> Result<(), GridError> {
    if name == "exhaustive" {
        for (rel, drafts) in exhaustive::chunks() {
            // The chunk decides the file, not Draft::file.
            let mut cases: Vec<Case> = to_cases(name, drafts)?
                .into_iter()
                .map(|(_, c)| c)
                .collect();
            fill_expectations(name, &mut cases)?;
            sink(
                rel,
                FixtureFile {
                    schema_version: SCHEMA_VERSION,
                    generator: GENERATOR.to_string(),
                    grid: name.to_string(),
                    seed,
                    cases,
                    state_cases: vec![],
                },
            )?;
        }
        return Ok(());
    }
    let cases = to_cases(name, drafts(name, seed)?)?;
    let (files, mut cases): (Vec<String>, Vec<Case>) = cases.into_iter().unzip();
    fill_expectations(name, &mut cases)?;
    sweep::add_sweeps(&mut cases);
    for (rel, file) in into_files(name, seed, files.into_iter().zip(cases).collect()) {
        sink(rel, file)?;
    }
    // `state/` sorts after every spec folder, so files still arrive sorted by path.
    for (rel, file) in tex_params::files(name, seed)? {
        sink(rel, file)?;
    }
    Ok(())
}

/// The cases of a grid without expectations (ids, API lists and structure only): what the
/// generator would evaluate. Used by tests that must not depend on the oracle.
pub fn unfilled(name: &str, seed: u64) -> Result<Vec<(String, FixtureFile)>, GridError> {
    let cases = to_cases(name, drafts(name, seed)?)?;
    let mut files = into_files(name, seed, cases);
    files.extend(tex_params::unfilled_files(name, seed));
    Ok(files)
}

/// Distinct relative paths of a list of files (for reports).
pub fn paths(files: &[(String, FixtureFile)]) -> BTreeSet<&str> {
    files.iter().map(|(p, _)| p.as_str()).collect()
}
