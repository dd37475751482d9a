//! The `stage` cut: mipmapped lookups of the `mip` and `cube_mip` families drawn again in the
//! vertex shader ([`Stage::Vertex`]) with the implicit-LOD function. There "the base
//! level-of-detail" is "computed as zero" (GLSL 4.60 / GLSL ES 3.20 §8.9), while the case's `lod`
//! (0.5, 1, 2, and the LOD-state variants' 2) is the λ_base a fragment shader would compute, so a
//! fragment λ used in the vertex stage selects another level of the chain's distinct levels
//! (0.2, 0.8, 0.4). The MIN_LOD, MAX_LOD, BASE_LEVEL, MAX_LEVEL and TEXTURE_LOD_BIAS variants are
//! where the two readings of the section differ (λ_base = 0 through §8.14, or "the base texture
//! is used": contradiction `vertex-base-texture`); the shader bias variant is left out ("The bias
//! parameter is not accepted in any other shader stage"). GL 4.6, ES 3.2 and ARB_shadow (its
//! GLSL 1.20 / 1.30 paths); ids carry `stage=vertex/` before the family's own tags.

use super::draft::Draft;
use super::families;
use super::specs::SpecDims;
use shadowcheck_model::{Spec, Stage};

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
    mips.chain(cubes).collect()
}

/// The `stage` cut of spec `d` (GL 4.6, ES 3.2, ARB_shadow).
pub fn stage(d: &SpecDims) -> Vec<Draft> {
    if !matches!(d.spec, Spec::Gl46 | Spec::Gles32 | Spec::Arb) {
        return Vec::new();
    }
    base(d)
        .into_iter()
        .map(|x| {
            let mut y = x.clone();
            y.lookup.stage = Stage::Vertex;
            y.tags = format!("stage=vertex/{}", x.tags);
            y
        })
        .collect()
}
