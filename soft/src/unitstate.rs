//! Unit state beyond the texture's own parameters: a bound sampler object, the context's
//! TEXTURE_CUBE_MAP_SEAMLESS enable and the texture swizzle. This unit resolves them on its own
//! (independent of the oracle):
//! - a bound sampler object supplies every sampling parameter (GL 4.6 §8.17.1 "the sampling state
//!   for that unit is taken from the sampler object"); DEPTH_TEXTURE_MODE,
//!   DEPTH_STENCIL_TEXTURE_MODE, the swizzle, TEXTURE_MAX_LEVEL and the fail value stay on the
//!   texture (§8.2: not sampler state);
//! - cube maps are seamless in ES 3.x; in GL when the case enables TEXTURE_CUBE_MAP_SEAMLESS;
//! - the swizzle picks each output channel from the base colour (§15.2.1); a shadow lookup on a
//!   float path returns Cs[0] of the swizzled (Rt, 0, 0, 1) (§11.1.3.5).

use crate::faults::{Fault, Faults};
use crate::layout;
use crate::sampler::Kind;
use crate::SoftError;
use shadowcheck_model::{ApiPath, Case, Sampler, Spec, Swizzle};
use std::borrow::Cow;

/// Specs with sampler objects and the texture swizzle (GL 3.3+, ES 3.0+).
fn has_gl33_state(spec: Spec) -> bool {
    matches!(spec, Spec::Gl46 | Spec::Gles32)
}

/// The sampling state the unit uses for `case` (see the module docs).
pub fn effective(spec: Spec, case: &Case, faults: Faults) -> Result<Cow<'_, Sampler>, SoftError> {
    let s = &case.sampler;
    if s.seamless.is_some() && spec != Spec::Gl46 {
        return Err(SoftError::Undefined {
            spec,
            what: "a TEXTURE_CUBE_MAP_SEAMLESS enable",
        });
    }
    if s.swizzle.is_some() && !has_gl33_state(spec) {
        return Err(SoftError::Undefined {
            spec,
            what: "TEXTURE_SWIZZLE_*",
        });
    }
    let Some(o) = &s.sampler_object else {
        return Ok(Cow::Borrowed(s));
    };
    if !has_gl33_state(spec) {
        return Err(SoftError::Undefined {
            spec,
            what: "sampler objects",
        });
    }
    if faults.has(Fault::SamplerObjectIgnored) {
        return Ok(Cow::Borrowed(s));
    }
    let mut eff = s.clone();
    eff.compare_mode = o.compare_mode;
    eff.compare_func = o.compare_func;
    eff.min_filter = o.min_filter;
    eff.mag_filter = o.mag_filter;
    eff.wrap_s = o.wrap_s;
    eff.wrap_t = o.wrap_t;
    eff.wrap_r = o.wrap_r;
    eff.border = o.border;
    eff.min_lod = o.min_lod;
    eff.max_lod = o.max_lod;
    eff.lod_bias = o.lod_bias;
    Ok(Cow::Owned(eff))
}

/// Whether cube lookups filter across faces.
pub fn seamless(spec: Spec, s: &Sampler, faults: Faults) -> bool {
    match spec {
        Spec::Gles32 => true,
        Spec::Gl46 if !faults.has(Fault::SeamlessIgnored) => s.seamless == Some(true),
        _ => false,
    }
}

/// The value a comparison sees for Dt when the swizzle is (wrongly) applied to the stored depth
/// before the comparison ([`Fault::SwizzleBeforeCompare`]): Cs[0] of (Dt, 0, 0, 1) for a
/// swizzle that does not read red; `None` when it reads red or no such fault is set.
pub fn pre_compare_dt(s: &Sampler, faults: Faults) -> Option<f32> {
    let sw = s.swizzle?;
    if !faults.has(Fault::SwizzleBeforeCompare) || sw[0] == Swizzle::Red {
        return None;
    }
    Some(sw[0].pick([f32::NAN, 0.0, 0.0, 1.0], 0.0, 1.0))
}

/// The swizzled result of a complete lookup: `rgba` is the layout's output for r on `api`.
pub fn swizzle(s: &Sampler, api: ApiPath, kind: Kind, rgba: [f32; 4], faults: Faults) -> [f32; 4] {
    let Some(sw) = s.swizzle else {
        return rgba;
    };
    if faults.has(Fault::SwizzleIgnored) {
        return rgba;
    }
    let shadow_float = kind == Kind::Compare && layout::is_float_path(api);
    if shadow_float {
        if faults.has(Fault::SwizzleBeforeCompare) {
            // Already applied to Dt before the comparison.
            return rgba;
        }
        let cs0 = sw[0].pick([rgba[0], 0.0, 0.0, 1.0], 0.0, 1.0);
        return [cs0, 0.0, 0.0, 1.0];
    }
    sw.map(|c| c.pick(rgba, 0.0, 1.0))
}
