//! Unit state a case sets besides its texture object: a bound sampler object (GL 4.6 §8.2) and
//! the TEXTURE_CUBE_MAP_SEAMLESS enable (§8.13.1). The texture swizzle is texture state and is
//! set with the other TexParameter calls (`texture::tex_params`).

use super::texture::{check, ParamValue, TexParam};
use super::GlError;
use glow::HasContext;
use shadowcheck_model::Case;

/// The SamplerParameter calls that set a case's sampler object (the same pnames and values as
/// the texture's, GL 4.6 §8.2), in the order they are made.
pub fn sampler_params(case: &Case) -> Vec<TexParam> {
    let Some(o) = &case.sampler.sampler_object else {
        return Vec::new();
    };
    let t = case.texture.target;
    let mut v = Vec::new();
    let mut push =
        |pname: u32, name: &'static str, value: ParamValue| v.push(TexParam { pname, name, value });
    use ParamValue::{Float, Floats, Int};
    push(
        glow::TEXTURE_MIN_FILTER,
        "TEXTURE_MIN_FILTER",
        Int(o.min_filter.gl()),
    );
    push(
        glow::TEXTURE_MAG_FILTER,
        "TEXTURE_MAG_FILTER",
        Int(o.mag_filter.gl()),
    );
    push(glow::TEXTURE_WRAP_S, "TEXTURE_WRAP_S", Int(o.wrap_s.gl()));
    if t.dims() == 2 {
        push(glow::TEXTURE_WRAP_T, "TEXTURE_WRAP_T", Int(o.wrap_t.gl()));
    }
    if t.is_cube() {
        push(glow::TEXTURE_WRAP_R, "TEXTURE_WRAP_R", Int(o.wrap_r.gl()));
    }
    if o.border != [0.0; 4] {
        push(
            glow::TEXTURE_BORDER_COLOR,
            "TEXTURE_BORDER_COLOR",
            Floats(o.border),
        );
    }
    push(glow::TEXTURE_MIN_LOD, "TEXTURE_MIN_LOD", Float(o.min_lod));
    push(glow::TEXTURE_MAX_LOD, "TEXTURE_MAX_LOD", Float(o.max_lod));
    if o.lod_bias != 0.0 {
        push(
            glow::TEXTURE_LOD_BIAS,
            "TEXTURE_LOD_BIAS",
            Float(o.lod_bias),
        );
    }
    push(
        glow::TEXTURE_COMPARE_MODE,
        "TEXTURE_COMPARE_MODE",
        Int(o.compare_mode.gl()),
    );
    push(
        glow::TEXTURE_COMPARE_FUNC,
        "TEXTURE_COMPARE_FUNC",
        Int(o.compare_func.gl()),
    );
    v
}

/// Unit state a case sets besides its texture: a sampler object bound to unit 0 and the
/// TEXTURE_CUBE_MAP_SEAMLESS enable. Undo with [`unbind_unit_state`] after drawing.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn bind_unit_state(
    gl: &glow::Context,
    case: &Case,
) -> Result<Option<glow::Sampler>, GlError> {
    if let Some(on) = case.sampler.seamless {
        if on {
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        } else {
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        }
        check(gl, "glEnable/glDisable(TEXTURE_CUBE_MAP_SEAMLESS)")?;
    }
    if case.sampler.sampler_object.is_none() {
        return Ok(None);
    }
    let so = gl.create_sampler().map_err(GlError::Gl)?;
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
    gl.bind_sampler(0, Some(so));
    check(gl, "glBindSampler")?;
    Ok(Some(so))
}

/// Restores the defaults [`bind_unit_state`] changed: seamless filtering disabled (GL's initial
/// state, §8.13.1) and no sampler object on unit 0.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn unbind_unit_state(gl: &glow::Context, case: &Case, so: Option<glow::Sampler>) {
    if case.sampler.seamless == Some(true) {
        gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
    }
    if let Some(so) = so {
        gl.bind_sampler(0, None);
        gl.delete_sampler(so);
    }
}
