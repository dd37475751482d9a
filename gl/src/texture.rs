//! Texture creation with exact texel control, sampler state, and read-back of what was stored.
//!
//! Unorm formats are uploaded as integers at (or above) the format's bit depth so the stored value
//! is the case's integer whatever rounding the driver does for floats (DESIGN.md: FLOAT uploads to
//! DEPTH_COMPONENT24 truncate on Mesa). Desktop GL reads level 0 back with glGetTexImage so the
//! verdict can use what was really stored.

use super::paths::GlInfo;
use super::GlError;
use glow::HasContext;
use shadowcheck_model::{Case, Format, Level, Spec, Target, Texels};

const GL_DEPTH_TEXTURE_MODE: u32 = 0x884B;
const GL_DEPTH_STENCIL_TEXTURE_MODE: u32 = 0x90EA;
const GL_TEXTURE_COMPARE_FAIL_VALUE_ARB: u32 = 0x80BF;

/// The transfer of a case's texture: the legacy specs (SGIX_shadow, ARB_shadow, EXT_shadow_funcs)
/// know the colour texture as LUMINANCE8 (GL 2.1 Table 3.20), GL 3.0+ and ES as R8.
pub fn transfer_for(case: &Case) -> (i32, u32, u32, usize) {
    let legacy = matches!(
        case.spec,
        Spec::Sgix | Spec::SgixAmbient | Spec::Arb | Spec::ArbAmbient | Spec::ExtFuncs
    );
    if case.texture.format == Format::R8 && legacy {
        const LUMINANCE8: i32 = 0x8040;
        const LUMINANCE: u32 = 0x1909;
        return (LUMINANCE8, LUMINANCE, glow::UNSIGNED_BYTE, 1);
    }
    transfer(case.texture.format)
}

/// Pixel transfer format/type for a texture format: (internal format, format, type, bytes/texel).
pub fn transfer(format: Format) -> (i32, u32, u32, usize) {
    match format {
        Format::D16 => (
            glow::DEPTH_COMPONENT16 as i32,
            glow::DEPTH_COMPONENT,
            glow::UNSIGNED_SHORT,
            2,
        ),
        Format::DepthUnsized => (
            glow::DEPTH_COMPONENT as i32,
            glow::DEPTH_COMPONENT,
            glow::UNSIGNED_SHORT,
            2,
        ),
        Format::D24 => (
            glow::DEPTH_COMPONENT24 as i32,
            glow::DEPTH_COMPONENT,
            glow::UNSIGNED_INT,
            4,
        ),
        Format::D32 => (
            glow::DEPTH_COMPONENT32 as i32,
            glow::DEPTH_COMPONENT,
            glow::UNSIGNED_INT,
            4,
        ),
        Format::D32f => (
            glow::DEPTH_COMPONENT32F as i32,
            glow::DEPTH_COMPONENT,
            glow::FLOAT,
            4,
        ),
        Format::D24S8 => (
            glow::DEPTH24_STENCIL8 as i32,
            glow::DEPTH_STENCIL,
            glow::UNSIGNED_INT_24_8,
            4,
        ),
        Format::D32fS8 => (
            glow::DEPTH32F_STENCIL8 as i32,
            glow::DEPTH_STENCIL,
            glow::FLOAT_32_UNSIGNED_INT_24_8_REV,
            8,
        ),
        Format::R8 => (glow::R8 as i32, glow::RED, glow::UNSIGNED_BYTE, 1),
    }
}

/// A 24-bit unorm integer as a 32-bit unorm integer that converts to it under every conversion a
/// driver may use (GL 4.6 §2.3.5 allows either neighbour): the 32-bit value is c + 1/4 steps of
/// 2^24-1 (c * (2^32-1)/(2^24-1) + (2^32-1)/(2^24-1)/4, rounded), so rounding and truncation both give c
/// (Mesa truncates: plain bit replication stored 1..65535 as one less), and the low byte is
/// clamped so that dropping it also gives c.
fn widen24(c: u32) -> u32 {
    const R: f64 = 4294967295.0 / 16777215.0;
    let low = ((c as f64 + 0.25) * R - 256.0 * c as f64)
        .round()
        .clamp(0.0, 255.0) as u32;
    (c << 8) | low
}

/// The bytes to upload for one level.
pub fn level_bytes(format: Format, level: &Level) -> Result<Vec<u8>, GlError> {
    let n = level.texel_count();
    let stencil = |i: usize| {
        level
            .stencil
            .as_ref()
            .and_then(|s| s.get(i))
            .copied()
            .unwrap_or(0) as u32
    };
    let mut out = Vec::with_capacity(n * transfer(format).3);
    match (&level.depth, format) {
        (Texels::Unorm(v), Format::D16 | Format::DepthUnsized) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&(c as u16).to_ne_bytes())),
        (Texels::Unorm(v), Format::D24) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&widen24(c).to_ne_bytes())),
        (Texels::Unorm(v), Format::D32) => v
            .iter()
            .for_each(|&c| out.extend_from_slice(&c.to_ne_bytes())),
        (Texels::Unorm(v), Format::D24S8) => v
            .iter()
            .enumerate()
            .for_each(|(i, &c)| out.extend_from_slice(&((c << 8) | stencil(i)).to_ne_bytes())),
        (Texels::Unorm(v), Format::R8) => v.iter().for_each(|&c| out.push(c as u8)),
        (Texels::Float(v), Format::D32f) => v
            .iter()
            .for_each(|&f| out.extend_from_slice(&f.to_ne_bytes())),
        (Texels::Float(v), Format::D32fS8) => v.iter().enumerate().for_each(|(i, &f)| {
            out.extend_from_slice(&f.to_ne_bytes());
            out.extend_from_slice(&stencil(i).to_ne_bytes());
        }),
        _ => {
            return Err(GlError::Gl(format!(
                "texel encoding does not match format {format}"
            )))
        }
    }
    Ok(out)
}

/// Decodes read-back bytes into the fixture's encoding.
pub fn decode_stored(format: Format, bytes: &[u8]) -> Texels {
    let u32s = |step: usize| {
        bytes
            .chunks_exact(step)
            .map(|c| u32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
    };
    match format {
        Format::D16 | Format::DepthUnsized => Texels::Unorm(
            bytes
                .chunks_exact(2)
                .map(|c| u16::from_ne_bytes([c[0], c[1]]) as u32)
                .collect(),
        ),
        // UNSIGNED_INT from a 24-bit store: c * (2^32-1)/(2^24-1) rounded; the top 24 bits are c.
        Format::D24 | Format::D24S8 => Texels::Unorm(u32s(4).map(|u| u >> 8).collect()),
        Format::D32 => Texels::Unorm(u32s(4).collect()),
        Format::D32f => Texels::Float(u32s(4).map(f32::from_bits).collect()),
        Format::D32fS8 => Texels::Float(u32s(8).map(f32::from_bits).collect()),
        Format::R8 => Texels::Unorm(bytes.iter().map(|&b| b as u32).collect()),
    }
}

fn face_targets(target: Target) -> Vec<u32> {
    if target == Target::Cube {
        (0..6)
            .map(|f| glow::TEXTURE_CUBE_MAP_POSITIVE_X + f)
            .collect()
    } else {
        vec![target.gl()]
    }
}

/// Creates the texture of `case`, uploads every level and sets the sampler state on the texture
/// object. Leaves it bound to unit 0. Returns GL errors raised on the way as `GlError::Gl`.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn create(
    gl: &glow::Context,
    info: &GlInfo,
    case: &Case,
) -> Result<glow::Texture, GlError> {
    let t = &case.texture;
    let target = t.target.gl();
    let (ifmt, fmt, ty, bpt) = transfer_for(case);
    let tex = gl.create_texture().map_err(GlError::Gl)?;
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(target, Some(tex));
    for (i, lvl) in t.levels.iter().enumerate() {
        let level = (t.base_level as usize + i) as i32;
        let bytes = level_bytes(t.format, lvl)?;
        let (w, h, l) = (lvl.width as i32, lvl.height as i32, lvl.layers as i32);
        let data = glow::PixelUnpackData::Slice(Some(&bytes));
        match t.target {
            Target::T1d => gl.tex_image_1d(target, level, ifmt, w, 0, fmt, ty, data),
            Target::T2d | Target::Rect => {
                gl.tex_image_2d(target, level, ifmt, w, h, 0, fmt, ty, data)
            }
            Target::T1dArray => gl.tex_image_2d(target, level, ifmt, w, l, 0, fmt, ty, data),
            Target::T2dArray | Target::CubeArray => {
                gl.tex_image_3d(target, level, ifmt, w, h, l, 0, fmt, ty, data)
            }
            Target::Cube => {
                let face = (w * h) as usize * bpt;
                for (f, ft) in face_targets(Target::Cube).into_iter().enumerate() {
                    let part = bytes
                        .get(f * face..(f + 1) * face)
                        .ok_or_else(|| GlError::Gl("cube level has fewer than 6 faces".into()))?;
                    gl.tex_image_2d(
                        ft,
                        level,
                        ifmt,
                        w,
                        h,
                        0,
                        fmt,
                        ty,
                        glow::PixelUnpackData::Slice(Some(part)),
                    );
                }
            }
        }
    }
    check(gl, "texture upload (glTexImage*)")?;
    set_state(gl, info, case)?;
    Ok(tex)
}

fn check_err(gl: &glow::Context) -> Option<u32> {
    // SAFETY: a context is current (callers are unsafe fns that require it).
    let e = unsafe { gl.get_error() };
    (e != glow::NO_ERROR).then_some(e)
}

/// Name of a GL error code.
pub fn error_name(e: u32) -> String {
    match e {
        glow::INVALID_ENUM => "GL_INVALID_ENUM".into(),
        glow::INVALID_VALUE => "GL_INVALID_VALUE".into(),
        glow::INVALID_OPERATION => "GL_INVALID_OPERATION".into(),
        glow::OUT_OF_MEMORY => "GL_OUT_OF_MEMORY".into(),
        glow::INVALID_FRAMEBUFFER_OPERATION => "GL_INVALID_FRAMEBUFFER_OPERATION".into(),
        other => format!("GL error 0x{other:04X}"),
    }
}

/// Turns a pending GL error into `GlError::Gl` naming `what`.
/// A `w`×`h` RGBA32F texture with NEAREST filtering, bound to TEXTURE_2D of the active unit: the
/// result framebuffer's colour buffer.
///
/// # Safety
/// `gl` must be current on this thread.
pub unsafe fn rgba32f(gl: &glow::Context, w: i32, h: i32) -> Result<glow::Texture, String> {
    let t = gl.create_texture()?;
    gl.bind_texture(glow::TEXTURE_2D, Some(t));
    gl.tex_image_2d(
        glow::TEXTURE_2D,
        0,
        glow::RGBA32F as i32,
        w,
        h,
        0,
        glow::RGBA,
        glow::FLOAT,
        glow::PixelUnpackData::Slice(None),
    );
    for pname in [glow::TEXTURE_MIN_FILTER, glow::TEXTURE_MAG_FILTER] {
        gl.tex_parameter_i32(glow::TEXTURE_2D, pname, glow::NEAREST as i32);
    }
    Ok(t)
}

pub fn check(gl: &glow::Context, what: &str) -> Result<(), GlError> {
    match check_err(gl) {
        None => Ok(()),
        Some(e) => {
            while check_err(gl).is_some() {}
            Err(GlError::Gl(format!("{what} raised {}", error_name(e))))
        }
    }
}

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
/// they are made (state left at its default is not set). The GL worker makes them with glow; the
/// WebGL page makes the same list (`shadowcheck-webgl`).
pub fn tex_params(info: &GlInfo, case: &Case) -> Vec<TexParam> {
    let s = &case.sampler;
    let t = &case.texture;
    let mut v = Vec::new();
    let mut push =
        |pname: u32, name: &'static str, value: ParamValue| v.push(TexParam { pname, name, value });
    use ParamValue::{Float, Floats, Int};
    if t.base_level != 0 {
        push(
            glow::TEXTURE_BASE_LEVEL,
            "TEXTURE_BASE_LEVEL",
            Int(t.base_level),
        );
    }
    if let Some(m) = s.max_level {
        push(glow::TEXTURE_MAX_LEVEL, "TEXTURE_MAX_LEVEL", Int(m));
    }
    push(
        glow::TEXTURE_MIN_FILTER,
        "TEXTURE_MIN_FILTER",
        Int(s.min_filter.gl()),
    );
    push(
        glow::TEXTURE_MAG_FILTER,
        "TEXTURE_MAG_FILTER",
        Int(s.mag_filter.gl()),
    );
    // Only the wraps of coordinates the target uses: a rectangle texture rejects REPEAT even for
    // a coordinate it never wraps.
    push(glow::TEXTURE_WRAP_S, "TEXTURE_WRAP_S", Int(s.wrap_s.gl()));
    if t.target.dims() == 2 {
        push(glow::TEXTURE_WRAP_T, "TEXTURE_WRAP_T", Int(s.wrap_t.gl()));
    }
    if t.target.is_cube() {
        push(glow::TEXTURE_WRAP_R, "TEXTURE_WRAP_R", Int(s.wrap_r.gl()));
    }
    if s.border != [0.0; 4] {
        push(
            glow::TEXTURE_BORDER_COLOR,
            "TEXTURE_BORDER_COLOR",
            Floats(s.border),
        );
    }
    if s.min_lod != -1000.0 {
        push(glow::TEXTURE_MIN_LOD, "TEXTURE_MIN_LOD", Float(s.min_lod));
    }
    if s.max_lod != 1000.0 {
        push(glow::TEXTURE_MAX_LOD, "TEXTURE_MAX_LOD", Float(s.max_lod));
    }
    if s.lod_bias != 0.0 {
        push(
            glow::TEXTURE_LOD_BIAS,
            "TEXTURE_LOD_BIAS",
            Float(s.lod_bias),
        );
    }
    push(
        glow::TEXTURE_COMPARE_MODE,
        "TEXTURE_COMPARE_MODE",
        Int(s.compare_mode.gl()),
    );
    push(
        glow::TEXTURE_COMPARE_FUNC,
        "TEXTURE_COMPARE_FUNC",
        Int(s.compare_func.gl()),
    );
    if let (Some(m), true) = (s.depth_texture_mode, info.compat) {
        push(GL_DEPTH_TEXTURE_MODE, "DEPTH_TEXTURE_MODE", Int(m.gl()));
    }
    if let Some(m) = s.depth_stencil_mode {
        push(
            GL_DEPTH_STENCIL_TEXTURE_MODE,
            "DEPTH_STENCIL_TEXTURE_MODE",
            Int(m.gl()),
        );
    }
    if let Some(f) = s.fail_value {
        push(
            GL_TEXTURE_COMPARE_FAIL_VALUE_ARB,
            "TEXTURE_COMPARE_FAIL_VALUE_ARB",
            Float(f),
        );
    }
    if let Some(sw) = s.swizzle {
        // One call per component (the same state as TEXTURE_SWIZZLE_RGBA, GL 4.6 §8.10).
        let names = [
            (glow::TEXTURE_SWIZZLE_R, "TEXTURE_SWIZZLE_R"),
            (glow::TEXTURE_SWIZZLE_G, "TEXTURE_SWIZZLE_G"),
            (glow::TEXTURE_SWIZZLE_B, "TEXTURE_SWIZZLE_B"),
            (glow::TEXTURE_SWIZZLE_A, "TEXTURE_SWIZZLE_A"),
        ];
        for ((pname, name), c) in names.into_iter().zip(sw) {
            push(pname, name, Int(c.gl()));
        }
    }
    v
}

unsafe fn set_state(gl: &glow::Context, info: &GlInfo, case: &Case) -> Result<(), GlError> {
    let target = case.texture.target.gl();
    for p in tex_params(info, case) {
        match p.value {
            ParamValue::Int(v) => gl.tex_parameter_i32(target, p.pname, v as i32),
            ParamValue::Float(v) => gl.tex_parameter_f32(target, p.pname, v),
            ParamValue::Floats(v) => gl.tex_parameter_f32_slice(target, p.pname, &v),
        }
        check(gl, &p.call())?;
    }
    Ok(())
}

/// Reads level `base_level` of `tex` (the texture of `case`) back (desktop GL only), in the
/// fixture's encoding.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn read_back(
    gl: &glow::Context,
    tex: glow::Texture,
    case: &Case,
) -> Result<Texels, GlError> {
    let t = &case.texture;
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(t.target.gl(), Some(tex));
    let lvl = t
        .levels
        .first()
        .ok_or_else(|| GlError::Gl("no levels".into()))?;
    let (_, fmt, ty, bpt) = transfer_for(case);
    let mut all = Vec::with_capacity(lvl.texel_count() * bpt);
    let targets = face_targets(t.target);
    let per = lvl.texel_count() * bpt / targets.len();
    for ft in targets {
        let mut buf = vec![0u8; per];
        gl.get_tex_image(
            ft,
            t.base_level as i32,
            fmt,
            ty,
            glow::PixelPackData::Slice(Some(&mut buf)),
        );
        all.extend_from_slice(&buf);
    }
    check(gl, "glGetTexImage")?;
    Ok(decode_stored(t.format, &all))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn d24_widening_is_exact_under_rounding_truncation_and_shift() {
        // GL 4.6 §2.3.5: f = c / (2^b - 1); a driver may round or truncate c32 * (2^24-1)/(2^32-1),
        // or drop the low byte. Every 24-bit value must survive all three (exact integer arithmetic).
        let (m24, m32) = ((1u64 << 24) - 1, (1u64 << 32) - 1);
        for c in (0..=m24 as u32)
            .step_by(97)
            .chain([1, 2, 65535, 0xFFFFFE, 0xFFFFFF])
        {
            let u = widen24(c) as u64;
            assert_eq!(u * m24 / m32, c as u64, "truncating {c}");
            assert!(2 * u * m24 < (2 * c as u64 + 1) * m32, "rounding {c}");
            assert_eq!(u >> 8, c as u64, "dropping the low byte {c}");
        }
    }

    #[test]
    fn level_bytes_pack_stencil_and_floats() {
        let lvl = Level {
            width: 2,
            height: 1,
            layers: 1,
            depth: Texels::Unorm(vec![1, 0xFFFFFF]),
            stencil: Some(vec![7, 9]),
        };
        let b = level_bytes(Format::D24S8, &lvl).unwrap();
        assert_eq!(u32::from_ne_bytes([b[0], b[1], b[2], b[3]]), (1 << 8) | 7);
        assert_eq!(
            decode_stored(Format::D24S8, &b),
            Texels::Unorm(vec![1, 0xFFFFFF])
        );
        let f = Level {
            width: 1,
            height: 1,
            layers: 1,
            depth: Texels::Float(vec![0.25]),
            stencil: None,
        };
        let b = level_bytes(Format::D32fS8, &f).unwrap();
        assert_eq!(b.len(), 8);
        assert_eq!(decode_stored(Format::D32fS8, &b), Texels::Float(vec![0.25]));
    }
}
