//! Unit state a case sets besides its texture object: a bound sampler object (GL 4.6 §8.2) and
//! the TEXTURE_CUBE_MAP_SEAMLESS enable (§8.13.1). The texture swizzle is texture state and is
//! set with the other TexParameter calls (`shadowcheck_plan::unit::tex_params`).

use super::texture::check;
use super::WorkerError;
use glow::HasContext;
use shadowcheck_model::Case;
use shadowcheck_plan::unit::{sampler_params, ParamValue};

/// The sampler object of `case` with its SamplerParameter calls made, or `None` when the case
/// binds none. Delete it with `glDeleteSamplers` once its draws are done.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn create_sampler_object(
    gl: &glow::Context,
    case: &Case,
) -> Result<Option<glow::Sampler>, WorkerError> {
    if case.sampler.sampler_object.is_none() {
        return Ok(None);
    }
    let so = gl.create_sampler().map_err(WorkerError::Gl)?;
    for p in sampler_params(case) {
        match p.value {
            ParamValue::Int(v) => gl.sampler_parameter_i32(so, p.pname, v as i32),
            ParamValue::Float(v) => gl.sampler_parameter_f32(so, p.pname, v),
            ParamValue::Floats(v) => gl.sampler_parameter_f32_slice(so, p.pname, &v),
        }
        if let Err(e) = check(
            gl,
            &p.call().replace("glTexParameter", "glSamplerParameter"),
        ) {
            gl.delete_sampler(so);
            return Err(e);
        }
    }
    Ok(Some(so))
}

/// Sets the unit state of `case` on texture unit `unit`: its sampler object `so` (from
/// [`create_sampler_object`]) bound there and the TEXTURE_CUBE_MAP_SEAMLESS enable. Undo with
/// [`unbind_unit_state`] after drawing.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn bind_unit_state(
    gl: &glow::Context,
    case: &Case,
    unit: u32,
    so: Option<glow::Sampler>,
) -> Result<(), WorkerError> {
    if let Some(on) = case.sampler.seamless {
        if on {
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        } else {
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        }
        check(gl, "glEnable/glDisable(TEXTURE_CUBE_MAP_SEAMLESS)")?;
    }
    if let Some(so) = so {
        gl.bind_sampler(unit, Some(so));
        check(gl, "glBindSampler")?;
    }
    Ok(())
}

/// Restores the defaults [`bind_unit_state`] changed: seamless filtering disabled (GL's initial
/// state, §8.13.1) and no sampler object on texture unit `unit`.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn unbind_unit_state(
    gl: &glow::Context,
    case: &Case,
    unit: u32,
    so: Option<glow::Sampler>,
) {
    if case.sampler.seamless == Some(true) {
        gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
    }
    if so.is_some() {
        gl.bind_sampler(unit, None);
    }
}
