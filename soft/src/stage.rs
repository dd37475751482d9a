//! The shader stage of a lookup (GLSL 4.60 / GLSL ES 3.20 §8.9; GLSL 1.20 / 1.30 §8.7, GLSL ES
//! 3.00 §8.8), read from the sentences: "Texture lookup functions are available in all shading
//! stages. However, level-of-detail is implicitly computed only for fragment shaders. Other
//! shaders operate as though the base level-of-detail were computed as zero."
//!
//! This unit takes that sentence literally: outside the fragment stage λ_base is 0 and the rest
//! of the level-of-detail pipeline (TEXTURE_LOD_BIAS, MIN_LOD / MAX_LOD, the magnification /
//! minification switch, §8.14.1 and §8.14.3) runs as for any λ. The bias argument does not exist
//! there ("The bias parameter is not accepted in any other shader stage"), so none is added.

use crate::faults::{Fault, Faults};
use crate::SoftError;
use shadowcheck_model::{ApiPath, Lookup, Spec, Stage};

/// λ_base of the lookup: the case's `lod` in the fragment stage, 0 in any other.
pub(crate) fn lambda_base(l: &Lookup, f: Faults) -> f32 {
    match l.stage {
        Stage::Fragment => l.lod as f32,
        // The seeded fault: the λ the fragment shader would have computed from derivatives.
        Stage::Vertex if f.has(Fault::VertexLodFromDerivatives) => l.lod as f32,
        Stage::Compute if f.has(Fault::ComputeLodFromDerivatives) => l.lod as f32,
        Stage::Vertex | Stage::Compute => 0.0,
    }
}

/// A vertex-stage lookup exists on the GLSL paths whose language has the lookup functions in
/// the vertex shader (GLSL 1.20 §8.7 "available to both vertex and fragment shaders", GLSL 1.30+,
/// GLSL ES 3.00+), a compute-stage one where the language has compute shaders (GLSL 4.30, GLSL
/// ES 3.10); neither with a bias argument.
pub(crate) fn check(spec: Spec, api: ApiPath, l: &Lookup) -> Result<(), SoftError> {
    if l.stage == Stage::Fragment {
        return Ok(());
    }
    let has_stage = match l.stage {
        // GLSL 4.30 §2.6 "Compute Processor", GLSL ES 3.10: no compute shader before them;
        // Vulkan's GLCompute execution model; WGSL's compute shader stage.
        Stage::Compute => matches!(
            api,
            ApiPath::GlslCore | ApiPath::Es300 | ApiPath::Vulkan | ApiPath::Wgsl
        ),
        _ => matches!(
            api,
            ApiPath::Glsl120 | ApiPath::Glsl130 | ApiPath::GlslCore | ApiPath::Es300
        ),
    };
    if !has_stage {
        return Err(SoftError::Undefined {
            spec,
            what: "a lookup in a shader stage the path's shading language does not have",
        });
    }
    if l.bias != 0.0 {
        return Err(SoftError::Undefined {
            spec,
            what: "a bias argument outside the fragment stage",
        });
    }
    Ok(())
}
