//! The unit and sampler state of a case, as the calls that set it in the order they are made:
//! TexParameter calls on the texture object (GL 4.6 §8.10), then, when the case binds one, the
//! SamplerParameter calls of its sampler object (§8.2). The TEXTURE_CUBE_MAP_SEAMLESS enable
//! (§8.13.1) is the case's `sampler.seamless`, set by each backend.

use crate::gl;
use shadowcheck_model::Case;

/// The value of one TexParameter call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamValue {
    /// glTexParameteri.
    Int(u32),
    /// glTexParameterf.
    Float(f32),
    /// glTexParameterfv.
    Floats([f32; 4]),
}

/// One TexParameter call of a case's sampler state: the parameter, its name (for error messages)
/// and the value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexParam {
    pub pname: u32,
    pub name: &'static str,
    pub value: ParamValue,
}

impl TexParam {
    /// The call as an error message names it, e.g. `glTexParameteri(TEXTURE_COMPARE_MODE)`.
    pub fn call(&self) -> String {
        let f = match self.value {
            ParamValue::Int(_) => "glTexParameteri",
            ParamValue::Float(_) => "glTexParameterf",
            ParamValue::Floats(_) => "glTexParameterfv",
        };
        format!("{f}({})", self.name)
    }
}

/// The TexParameter calls that set `case`'s sampler state on its texture object, in the order
/// they are made (state left at its default is not set). The GL worker makes them with glow, the
/// WebGL page and the C reproducer make the same list.
pub fn tex_params(compat: bool, case: &Case) -> Vec<TexParam> {
    let s = &case.sampler;
    let t = &case.texture;
    let mut v = Vec::new();
    let mut push =
        |pname: u32, name: &'static str, value: ParamValue| v.push(TexParam { pname, name, value });
    use ParamValue::{Float, Floats, Int};
    if t.base_level != 0 {
        push(
            gl::TEXTURE_BASE_LEVEL,
            "TEXTURE_BASE_LEVEL",
            Int(t.base_level),
        );
    }
    if let Some(m) = s.max_level {
        push(gl::TEXTURE_MAX_LEVEL, "TEXTURE_MAX_LEVEL", Int(m));
    }
    push(
        gl::TEXTURE_MIN_FILTER,
        "TEXTURE_MIN_FILTER",
        Int(s.min_filter.gl()),
    );
    push(
        gl::TEXTURE_MAG_FILTER,
        "TEXTURE_MAG_FILTER",
        Int(s.mag_filter.gl()),
    );
    // Only the wraps of coordinates the target uses: a rectangle texture rejects REPEAT even for
    // a coordinate it never wraps.
    push(gl::TEXTURE_WRAP_S, "TEXTURE_WRAP_S", Int(s.wrap_s.gl()));
    if t.target.dims() == 2 {
        push(gl::TEXTURE_WRAP_T, "TEXTURE_WRAP_T", Int(s.wrap_t.gl()));
    }
    if t.target.is_cube() {
        push(gl::TEXTURE_WRAP_R, "TEXTURE_WRAP_R", Int(s.wrap_r.gl()));
    }
    if s.border != [0.0; 4] {
        push(
            gl::TEXTURE_BORDER_COLOR,
            "TEXTURE_BORDER_COLOR",
            Floats(s.border),
        );
    }
    if s.min_lod != -1000.0 {
        push(gl::TEXTURE_MIN_LOD, "TEXTURE_MIN_LOD", Float(s.min_lod));
    }
    if s.max_lod != 1000.0 {
        push(gl::TEXTURE_MAX_LOD, "TEXTURE_MAX_LOD", Float(s.max_lod));
    }
    if s.lod_bias != 0.0 {
        push(gl::TEXTURE_LOD_BIAS, "TEXTURE_LOD_BIAS", Float(s.lod_bias));
    }
    push(
        gl::TEXTURE_COMPARE_MODE,
        "TEXTURE_COMPARE_MODE",
        Int(s.compare_mode.gl()),
    );
    push(
        gl::TEXTURE_COMPARE_FUNC,
        "TEXTURE_COMPARE_FUNC",
        Int(s.compare_func.gl()),
    );
    if let (Some(m), true) = (s.depth_texture_mode, compat) {
        push(gl::DEPTH_TEXTURE_MODE, "DEPTH_TEXTURE_MODE", Int(m.gl()));
    }
    if let Some(m) = s.depth_stencil_mode {
        push(
            gl::DEPTH_STENCIL_TEXTURE_MODE,
            "DEPTH_STENCIL_TEXTURE_MODE",
            Int(m.gl()),
        );
    }
    if let Some(f) = s.fail_value {
        push(
            gl::TEXTURE_COMPARE_FAIL_VALUE_ARB,
            "TEXTURE_COMPARE_FAIL_VALUE_ARB",
            Float(f),
        );
    }
    if let Some(sw) = s.swizzle {
        // One call per component (the same state as TEXTURE_SWIZZLE_RGBA, GL 4.6 §8.10).
        let names = [
            (gl::TEXTURE_SWIZZLE_R, "TEXTURE_SWIZZLE_R"),
            (gl::TEXTURE_SWIZZLE_G, "TEXTURE_SWIZZLE_G"),
            (gl::TEXTURE_SWIZZLE_B, "TEXTURE_SWIZZLE_B"),
            (gl::TEXTURE_SWIZZLE_A, "TEXTURE_SWIZZLE_A"),
        ];
        for ((pname, name), c) in names.into_iter().zip(sw) {
            push(pname, name, Int(c.gl()));
        }
    }
    v
}

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
        gl::TEXTURE_MIN_FILTER,
        "TEXTURE_MIN_FILTER",
        Int(o.min_filter.gl()),
    );
    push(
        gl::TEXTURE_MAG_FILTER,
        "TEXTURE_MAG_FILTER",
        Int(o.mag_filter.gl()),
    );
    push(gl::TEXTURE_WRAP_S, "TEXTURE_WRAP_S", Int(o.wrap_s.gl()));
    if t.dims() == 2 {
        push(gl::TEXTURE_WRAP_T, "TEXTURE_WRAP_T", Int(o.wrap_t.gl()));
    }
    if t.is_cube() {
        push(gl::TEXTURE_WRAP_R, "TEXTURE_WRAP_R", Int(o.wrap_r.gl()));
    }
    if o.border != [0.0; 4] {
        push(
            gl::TEXTURE_BORDER_COLOR,
            "TEXTURE_BORDER_COLOR",
            Floats(o.border),
        );
    }
    push(gl::TEXTURE_MIN_LOD, "TEXTURE_MIN_LOD", Float(o.min_lod));
    push(gl::TEXTURE_MAX_LOD, "TEXTURE_MAX_LOD", Float(o.max_lod));
    if o.lod_bias != 0.0 {
        push(gl::TEXTURE_LOD_BIAS, "TEXTURE_LOD_BIAS", Float(o.lod_bias));
    }
    push(
        gl::TEXTURE_COMPARE_MODE,
        "TEXTURE_COMPARE_MODE",
        Int(o.compare_mode.gl()),
    );
    push(
        gl::TEXTURE_COMPARE_FUNC,
        "TEXTURE_COMPARE_FUNC",
        Int(o.compare_func.gl()),
    );
    v
}
