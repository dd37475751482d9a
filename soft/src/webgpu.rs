//! What a `wgsl` lookup (WebGPU) may ask for, and how a case's layer coordinate reaches WGSL's
//! integer `array_index`. The WebGPU sampler rules sit beside the other specs' in `compare`
//! (GPUCompareFunction, no reference clamp), `sampler` (address modes, formats, comparison
//! sampler, no LOD bias, no incomplete views) and `unitstate` (seamless cube views); this module
//! holds the WGSL built-ins' own rules (WGSL Texture Built-in Functions).
//!
//! The built-ins are textureSampleCompare (WGSL; derivatives give λ as in GL),
//! textureSampleCompareLevel (WGSL: "always samples texels from mip level 0", i.e. the
//! view's base level, used by the harness only where λ selects that level) and
//! textureGatherCompare (WGSL).

use crate::SoftError;
use shadowcheck_model::{Case, Spec, Target};

/// The integer array index a WGSL lookup receives for layer coordinate `x`.
///
/// WGSL textureSampleCompare: "`array_index`: The 0-based texture array index to
/// sample." — a parameter of type A, "A is i32, or u32", so only integers reach the texture
/// unit; the clamp ("This value will be clamped to the range [0, textureNumLayers(t) - 1]") is
/// applied where the layer is read (`filter`, as for the other specs). A case's layer coordinate
/// is a float; for an integer (every layer a WebGPU grid asks for) this is the identity. A
/// fractional one has no WGSL counterpart; the unit then takes the nearest integer, halves to
/// even, as WGSL's `round` would give it to the built-in (WGSL round: "the result is k when
/// k is even, and k + 1 when k is odd").
#[inline]
pub fn array_index(x: f32) -> f32 {
    x.round_ties_even()
}

/// The layer coordinate `x` of a lookup on `target` under `spec`, as the unit reads it.
#[inline]
pub(crate) fn layer_coordinate(spec: Spec, target: Target, x: f32) -> f32 {
    if spec == Spec::WebGpu && target.is_array() {
        array_index(x)
    } else {
        x
    }
}

fn undefined(spec: Spec, what: &'static str) -> Result<(), SoftError> {
    Err(SoftError::Undefined { spec, what })
}

/// Refuses what no WGSL depth-comparison built-in can express (called for the `wgsl` path).
pub(crate) fn check_lookup(spec: Spec, case: &Case) -> Result<(), SoftError> {
    let l = &case.lookup;
    if l.projective {
        // WGSL lists no projective texture built-in (no textureSampleCompareProj).
        return undefined(
            spec,
            "a projective lookup (WGSL has no projective texture built-in)",
        );
    }
    if l.bias != 0.0 {
        // WGSL textureSampleCompare takes (t, s, coords, [array_index,] depth_ref
        // [, offset]): no bias; textureSampleBias takes a `sampler`, not a `sampler_comparison`.
        return undefined(spec, "a bias argument to a WGSL depth-comparison built-in");
    }
    if l.offset != [0; 3] && !matches!(case.texture.target, Target::T2d | Target::T2dArray) {
        // WGSL: the `offset: vec2<i32>` overloads exist for texture_depth_2d and
        // texture_depth_2d_array only.
        return undefined(spec, "a texel offset on a WGSL cube depth texture");
    }
    if l.offset[2] != 0 || l.offset.iter().any(|o| !(-8..=7).contains(o)) {
        // WGSL: "Each `offset` component must be at least -8 and at most 7. Values
        // outside of this range will result in a shader-creation error."
        return undefined(
            spec,
            "a WGSL texel offset outside [-8, 7] (shader-creation error)",
        );
    }
    Ok(())
}

/// Refuses a gather WGSL cannot express: textureGatherCompare (WGSL) takes one optional
/// `offset: vec2<i32>` (2D and 2D array only), so there is no per-texel offsets form.
pub(crate) fn check_gather(spec: Spec, case: &Case) -> Result<(), SoftError> {
    if case
        .lookup
        .gather
        .as_ref()
        .is_some_and(|g| g.offsets.is_some())
    {
        return undefined(
            spec,
            "per-texel gather offsets (WGSL has no textureGatherOffsets)",
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_indices_pass_through_and_halves_go_to_even() {
        for x in [-1.0, 0.0, 1.0, 2.0, 7.0] {
            assert_eq!(array_index(x), x);
        }
        assert_eq!(array_index(0.5), 0.0);
        assert_eq!(array_index(1.5), 2.0);
        assert_eq!(array_index(2.5), 2.0);
        assert_eq!(array_index(1.4999), 1.0);
        assert_eq!(layer_coordinate(Spec::Gl46, Target::T2dArray, 0.5), 0.5);
        assert_eq!(layer_coordinate(Spec::WebGpu, Target::T2d, 0.5), 0.5);
    }
}
