//! What WGSL's depth-comparison built-ins ("Texture Built-in Functions" of WGSL) can express
//! of a case, beyond the per-dialect table of `forms.rs`:
//! - `textureSampleCompareLevel` "always samples texels from mip level 0", so it realizes the
//!   case only where the case's own level of detail is that one: lod = 0, no shader bias, and a
//!   sampler whose min_lod is at most 0 (then λ clamps to 0 under WebGPU's lodMinClamp, which the
//!   worker sets to max(min_lod, 0): level base, magnification filter, as the case's λ ≤ 0 gives);
//! - no built-in takes a bias;
//! - `array_index` is an integer (i32 or u32), so a layer coordinate that is not one has no WGSL
//!   lookup (the conversion would be the shader's, not the texture unit's);
//! - an offset is a const-expression `vec2<i32>` whose components "must be at least -8 and at
//!   most 7" (WGSL textureSampleCompare, textureGatherCompare: "offset"), else the shader
//!   does not compile.

use super::LodForm;
use shadowcheck_model::{Case, Lookup, Target};

/// How a form realizes the case on the `wgsl` path (the result's note).
pub fn note(form: LodForm) -> &'static str {
    match form {
        LodForm::Lod => "textureSampleCompareLevel (level 0: the case's lod is 0 and min_lod <= 0)",
        LodForm::Implicit(_) => "textureSampleCompare, implicit derivatives (P varying across the quad by the case's gradients)",
        LodForm::Gather(_) => "textureGatherCompare",
        LodForm::Grad | LodForm::Constant => "no WGSL form",
    }
}

/// WGSL texture built-in functions: the offset components' range.
pub const OFFSET_RANGE: (i32, i32) = (-8, 7);

/// May `textureSampleCompareLevel` (level 0) realize lookup `l` of `case`?
pub fn level_zero_equivalent(case: &Case, l: &Lookup) -> bool {
    l.lod == 0.0 && l.bias == 0.0 && case.sampler.in_effect().min_lod <= 0.0
}

/// Why WGSL has no lookup for `l` of `case` (a bias, a layer that is not an integer), if so.
pub fn unexpressible(case: &Case, l: &Lookup) -> Option<String> {
    if l.bias != 0.0 {
        return Some(format!(
            "WGSL has no compare lookup with a bias (WGSL texture built-in functions: textureSampleCompare, textureSampleCompareLevel and textureGatherCompare take none); the case's bias is {}",
            l.bias
        ));
    }
    if l.projective {
        return Some(
            "WGSL has no projective compare lookup (WGSL texture built-in functions)".into(),
        );
    }
    let layer = match case.texture.target {
        Target::T2dArray => Some(l.coord[2]),
        Target::CubeArray => Some(l.layer),
        _ => None,
    };
    match layer {
        Some(v) if v.fract() != 0.0 || v.abs() > i32::MAX as f64 => Some(format!(
            "WGSL's array_index is an integer (WGSL textureSampleCompare: \"array_index: The 0-based texture array index to sample\", an i32 or u32); the case's layer coordinate {v} is not one, and converting it would be the shader's rounding, not the texture unit's"
        )),
        _ => None,
    }
}

/// The offset as WGSL writes it, or why it cannot.
pub fn offset(o: [i32; 3]) -> Result<[i8; 2], String> {
    let (lo, hi) = OFFSET_RANGE;
    let ok = |v: i32| (lo..=hi).contains(&v);
    if o[2] != 0 {
        return Err(format!(
            "WGSL offsets are vec2<i32>: offset {o:?} has a third component"
        ));
    }
    match (ok(o[0]) && ok(o[1]), i8::try_from(o[0]), i8::try_from(o[1])) {
        (true, Ok(a), Ok(b)) => Ok([a, b]),
        _ => Err(format!(
            "WGSL offset components must be in [{lo}, {hi}] (WGSL \"offset\"); the case's offset is {o:?}"
        )),
    }
}
