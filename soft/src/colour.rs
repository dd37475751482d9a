//! Colour textures of several components (RG8, RGB8, RGBA8, RGBA4), read from the sentences:
//!
//! - GL 4.6 §8.23.1 (ES 3.2 §8.20.1; ARB_shadow, GL 2.1 §3.8.14 for RGB/RGBA): TEXTURE_COMPARE_MODE
//!   and TEXTURE_COMPARE_FUNC act only on a DEPTH_COMPONENT or DEPTH_STENCIL texture; for any other
//!   "the texture unit operates in the normal manner and texture comparison is bypassed". So the
//!   compare state is ignored and each component is filtered like any colour value.
//! - §8.4.4 / eq. (2.1): a component of b bits holding c is c / (2^b − 1) (b = 8, or 4 for RGBA4).
//! - A border texel takes the matching component of TEXTURE_BORDER_COLOR (§8.14.2).
//! - Table 15.1 (Table 3.20 and compatibility Table 16.1 give the same rows): the base colour is
//!   RG (R, G, 0, 1), RGB (R, G, B, 1), RGBA (R, G, B, A); then the texture swizzle (§15.2.1). The
//!   lookup is a vec4 whatever the path, through a non-shadow sampler.
//! - An incomplete texture returns (0, 0, 0, 1) to a non-shadow sampler (§11.1.3.5).

use crate::faults::{Fault, Faults};
use crate::filter::Coords;
use crate::sampler::{Kind, SamplerState};
use crate::storage::{clamp01, PreparedTexture};
use crate::{layout, unitstate, SoftError};
use shadowcheck_model::{ApiPath, Case, Spec};

/// The RGBA of a lookup of a colour texture of several components.
pub(crate) fn sample(
    spec: Spec,
    case: &Case,
    api: ApiPath,
    tex: &PreparedTexture,
    st: &SamplerState,
    c: &Coords,
    faults: Faults,
) -> Result<[f32; 4], SoftError> {
    if !st.complete {
        return Ok(layout::INCOMPLETE);
    }
    let n = case.texture.format.components();
    let mut cb = [0.0, 0.0, 0.0, 1.0];
    if faults.has(Fault::ColourAlphaZero) && n < 4 {
        cb[3] = 0.0;
    }
    let read = if faults.has(Fault::ColourAsRed) { 1 } else { n };
    for (i, slot) in cb.iter_mut().enumerate().take(read) {
        let mut sti = st.clone();
        sti.border = border(spec, case, i);
        *slot = tex.component(i).lookup(&sti, c);
    }
    Ok(unitstate::swizzle(
        &case.sampler,
        api,
        Kind::Colour,
        cb,
        faults,
    ))
}

/// Component `i` of TEXTURE_BORDER_COLOR as the border texel holds it: ES 3.2 clamps border
/// values to the range of a fixed-point format (§8.14.2), desktop GL uses them as given (GL ≤ 2.1
/// clamped them when set).
fn border(spec: Spec, case: &Case, i: usize) -> f32 {
    let b = case.sampler.in_effect().border[i.min(3)];
    match spec {
        Spec::Gl46 => b,
        _ => clamp01(b),
    }
}
