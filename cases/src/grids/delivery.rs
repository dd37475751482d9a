//! The `delivery` cut: lookups of existing families drawn again with their values delivered
//! otherwise than as literals ([`Delivery`]): from uniforms, from flat inputs, and per fragment
//! (values that differ between the fragments of the 2x2 pixel quad, the measured fragment getting
//! the case's). The expectation is the literal's (values are values, GLSL 4.60 / GLSL ES 3.20
//! §8.9.4); the cut exists because compilers take other code paths for non-constant operands.
//!
//! Taken from: every shadow gather with one offset or none (non-constant textureGatherOffset
//! offsets, GLSL 4.00+ / GLSL ES 3.20; not textureGatherOffsets, whose offsets "must be constant
//! integral expressions"), the mipmapped lookups at fractional LODs (the LOD delivered), the cube
//! map edges and corners, and the 2D array layers (the coordinates delivered); GL 4.6 and ES 3.2
//! only (the GLSL 1.30+ / GLSL ES 3.00 paths). Ids carry `delivery=<kind>/` before the family's
//! own tags.

use super::draft::Draft;
use super::families;
use super::gather;
use super::specs::SpecDims;
use shadowcheck_model::{Delivery, Spec, Target};

/// The delivered kinds (every one but the default).
pub const KINDS: [Delivery; 3] = [Delivery::Uniform, Delivery::Flat, Delivery::PerFragment];

/// The LODs of the `mip` family drawn with a delivered LOD: between levels, so that a LOD read
/// from another fragment or rounded shows.
const LODS: [&str; 2] = ["lod=0.5/", "lod=1.5/"];

/// The lookups of spec `d` that the cut delivers, before the delivery is set.
fn base(d: &SpecDims) -> Vec<Draft> {
    let gathers = gather::gather(d)
        .into_iter()
        .filter(|x| {
            x.lookup
                .gather
                .as_ref()
                .is_some_and(|g| g.offsets.is_none())
        })
        .filter(|x| x.sampler.swizzle.is_none());
    let mips = families::mip(d)
        .into_iter()
        .filter(|x| LODS.iter().any(|l| x.tags.starts_with(l)));
    let cubes = families::cube(d)
        .into_iter()
        .filter(|x| x.cell.format == families::fixed_fmt(d));
    // The layer ties (layer = 0.5) are left to the `layer` family: their one known failure
    // (round-half-to-even under LINEAR, reports/README.md cause 9) is the same with every delivery.
    let layers = families::layer(d)
        .into_iter()
        .filter(|x| x.cell.target == Target::T2dArray && !x.tags.contains("layer=0.5/"));
    gathers.chain(mips).chain(cubes).chain(layers).collect()
}

/// The `delivery` cut of spec `d` (GL 4.6, ES 3.2).
pub fn delivery(d: &SpecDims) -> Vec<Draft> {
    if !matches!(d.spec, Spec::Gl46 | Spec::Gles32) {
        return Vec::new();
    }
    let base = base(d);
    let mut out = Vec::with_capacity(base.len() * KINDS.len());
    for kind in KINDS {
        for x in &base {
            let mut y = x.clone();
            y.lookup.delivery = kind;
            y.tags = format!("delivery={kind}/{}", x.tags);
            out.push(y);
        }
    }
    out
}
