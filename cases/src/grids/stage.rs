//! The `stage` cut: lookups drawn again outside the fragment stage, where "the base
//! level-of-detail" is "computed as zero" (GLSL 4.60 / GLSL ES 3.20 §8.9).
//!
//! - Vertex shader ([`Stage::Vertex`], GL 4.6, ES 3.2 and ARB_shadow's GLSL 1.20 / 1.30 paths):
//!   mipmapped lookups of the `mip` and `cube_mip` families with the implicit-LOD function. The
//!   case's `lod` (0.5, 1, 2, and the LOD-state variants' 2) is the λ_base a fragment shader would
//!   compute, so a fragment λ used in the vertex stage selects another level of the chain's
//!   distinct levels (0.2, 0.8, 0.4). The MIN_LOD, MAX_LOD, BASE_LEVEL, MAX_LEVEL and
//!   TEXTURE_LOD_BIAS variants are where the two readings of the section differ (λ_base = 0
//!   through §8.14, or "the base texture is used": contradiction `non-fragment-base-texture`); the
//!   shader bias variant is left out ("The bias parameter is not accepted in any other shader
//!   stage"); the fragment-λ lookups again on a 2D array of two layers (layer 1) where the spec
//!   has 2D arrays.
//! - Compute shader ([`Stage::Compute`], GL 4.6 and ES 3.2: GLSL 4.30, GLSL ES 3.10): the same
//!   lookups, and the lookups at cube face edges and corners that a compute shader reaches by
//!   other code than a fragment shader's: the `seamless` family at level 0 (LINEAR, each edge, a
//!   corner and inside, seamless on and off), the `cube` family's LINEAR lookups near an edge
//!   (cube and cube array), and the `gather` family's cube and cube-array gathers. Vulkan and
//!   WebGPU get these cube lookups only (level 0, where every stage selects the same level: the
//!   WebGPU CTS's compute-only failures are there).
//!
//! Ids carry `stage=vertex/` or `stage=compute/` before the family's own tags.

use super::draft::{lookup, Draft};
use super::specs::SpecDims;
use super::{families, gather};
use crate::build::At;
use shadowcheck_model::{Filter, Spec, Stage, Target, Texels};

/// The fragment λ_base values of the `mip` family drawn in the vertex stage: each selects a level
/// other than level 0 under a mipmapped filter (0.5: level 0 or 1 by the rounding, blended by the
/// *_MIPMAP_LINEAR filters).
const LODS: [&str; 3] = ["lod=0.5/", "lod=1/", "lod=2/"];

/// The lookups of spec `d` that the cut draws in the vertex stage.
fn base(d: &SpecDims) -> Vec<Draft> {
    let mips = families::mip(d).into_iter().filter(|x| {
        x.lookup.bias == 0.0
            && (LODS.iter().any(|l| x.tags.starts_with(l))
                || (x.lookup.lod == 2.0 && !x.tags.starts_with("lod=")))
    });
    let cubes = families::cube_mip(d)
        .into_iter()
        .filter(|x| x.lookup.lod != 0.0);
    let arrays = arrays(d);
    mips.chain(cubes).chain(arrays).collect()
}

/// The `mip` lookups at the fragment λ of [`LODS`] on a 2D array texture of two layers (both the
/// same chain), looked up in layer 1, where the spec has 2D array textures.
fn arrays(d: &SpecDims) -> Vec<Draft> {
    if !d.targets.contains(&Target::T2dArray) {
        return Vec::new();
    }
    families::mip(d)
        .into_iter()
        .filter(|x| x.lookup.bias == 0.0 && LODS.iter().any(|l| x.tags.starts_with(l)))
        .map(|mut x| {
            x.cell.target = Target::T2dArray;
            x.texture.target = Target::T2dArray;
            for l in &mut x.texture.levels {
                l.layers = 2;
                l.depth = twice(&l.depth);
                l.stencil = l.stencil.take().map(|s| s.repeat(2));
            }
            let mut lk = lookup(
                Target::T2dArray,
                At {
                    layer: 1.0,
                    ..At::st(0.5, 0.5)
                },
                4,
                4,
                x.lookup.dref,
            );
            lk.lod = x.lookup.lod;
            x.lookup = lk;
            x.tags = format!("layer=1/{}", x.tags);
            x
        })
        .collect()
}

/// The cube lookups of spec `d` at face edges and corners that the cut draws in a compute shader
/// (module docs): level 0 only, so that the fragment and compute stages select the same level.
fn cube_edges(d: &SpecDims) -> Vec<Draft> {
    let seamless = families::seamless(d)
        .into_iter()
        .filter(|x| x.lookup.lod == 0.0 && x.sampler.min_filter == Filter::Linear);
    let cube = families::cube(d)
        .into_iter()
        .filter(|x| x.sampler.min_filter == Filter::Linear && x.tags.contains("/edge/"));
    let gathers = gather::gather(d)
        .into_iter()
        .filter(|x| x.texture.target.is_cube());
    seamless.chain(cube).chain(gathers).collect()
}

/// `x` drawn in `stage`, its id tagged.
fn in_stage(x: Draft, stage: Stage) -> Draft {
    let mut y = x;
    y.lookup.stage = stage;
    y.tags = format!("stage={stage}/{}", y.tags);
    y
}

/// The `stage` cut of spec `d`: the vertex stage on GL 4.6, ES 3.2 and ARB_shadow, the compute
/// stage on GL 4.6 and ES 3.2.
pub fn stage(d: &SpecDims) -> Vec<Draft> {
    match d.spec {
        Spec::Gl46 | Spec::Gles32 => {
            let vertex = base(d).into_iter().map(|x| in_stage(x, Stage::Vertex));
            let compute = base(d)
                .into_iter()
                .chain(cube_edges(d))
                .map(|x| in_stage(x, Stage::Compute));
            vertex.chain(compute).collect()
        }
        Spec::Arb => base(d)
            .into_iter()
            .map(|x| in_stage(x, Stage::Vertex))
            .collect(),
        // Level 0 only: a compute lookup there is `texture()` with an explicit LOD of 0 (SPIR-V
        // ExplicitLod, GLSL 4.60 §8.9) or textureSampleCompareLevel (WGSL), the same level the
        // fragment lookups of these cases select.
        Spec::Vulkan | Spec::WebGpu => cube_edges(d)
            .into_iter()
            .map(|x| in_stage(x, Stage::Compute))
            .collect(),
        _ => Vec::new(),
    }
}

/// The texels of one layer, then the same again (a second layer).
fn twice(t: &Texels) -> Texels {
    match t {
        Texels::Unorm(v) => Texels::Unorm(v.repeat(2)),
        Texels::Float(v) => Texels::Float(v.repeat(2)),
        Texels::Colour(v) => Texels::Colour(v.repeat(2)),
    }
}
