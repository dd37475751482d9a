//! Textures on the GL context: created with the bytes and TexParameter calls of the plan
//! (`shadowcheck_plan::texels`, `shadowcheck_plan::unit`), and level 0 read back (desktop GL, with
//! glGetTexImage) so the verdict can use what was really stored.

use super::WorkerError;
use glow::HasContext;
use shadowcheck_model::{Case, Target, Texels};
use shadowcheck_plan::texels::{decode_stored, level_bytes, transfer_for};
use shadowcheck_plan::unit::{tex_params, ParamValue};
use shadowcheck_plan::GlInfo;

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
/// object. Leaves it bound to unit 0. Returns GL errors raised on the way as `WorkerError::Gl`.
///
/// # Safety
/// `gl` must be current.
pub unsafe fn create(
    gl: &glow::Context,
    info: &GlInfo,
    case: &Case,
) -> Result<glow::Texture, WorkerError> {
    let t = &case.texture;
    let target = t.target.gl();
    let (ifmt, fmt, ty, bpt) = transfer_for(case);
    let tex = gl.create_texture().map_err(WorkerError::Gl)?;
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(target, Some(tex));
    for (i, lvl) in t.levels.iter().enumerate() {
        let level = (t.base_level as usize + i) as i32;
        let bytes = level_bytes(t.format, lvl).map_err(|e| WorkerError::Gl(e.to_string()))?;
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
                    let part = bytes.get(f * face..(f + 1) * face).ok_or_else(|| {
                        WorkerError::Gl("cube level has fewer than 6 faces".into())
                    })?;
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

/// The result framebuffer: an `size`x`size` RGBA32F colour texture ([`rgba32f`]) attached to a
/// new framebuffer object, left bound to FRAMEBUFFER; an error if it is not complete. `storage`:
/// the texture is made by TexStorage2D (immutable), which a compute shader's image store needs on
/// ES (ES 3.2, "Texture Image Loads and Stores", BindImageTexture: "An INVALID_OPERATION error is
/// generated if texture is not the name of an immutable texture object"); every context with
/// compute shaders has TexStorage2D (GL 4.2, ES 3.0).
///
/// # Safety
/// `gl` must be current on this thread.
pub unsafe fn rgba32f_framebuffer(
    gl: &glow::Context,
    size: i32,
    storage: bool,
) -> Result<(glow::Framebuffer, glow::Texture), String> {
    let color = if storage {
        let t = gl.create_texture()?;
        gl.bind_texture(glow::TEXTURE_2D, Some(t));
        gl.tex_storage_2d(glow::TEXTURE_2D, 1, glow::RGBA32F, size, size);
        for pname in [glow::TEXTURE_MIN_FILTER, glow::TEXTURE_MAG_FILTER] {
            gl.tex_parameter_i32(glow::TEXTURE_2D, pname, glow::NEAREST as i32);
        }
        t
    } else {
        rgba32f(gl, size, size)?
    };
    let fbo = gl.create_framebuffer()?;
    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
    gl.framebuffer_texture_2d(
        glow::FRAMEBUFFER,
        glow::COLOR_ATTACHMENT0,
        glow::TEXTURE_2D,
        Some(color),
        0,
    );
    let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
    if status != glow::FRAMEBUFFER_COMPLETE {
        return Err(format!(
            "RGBA32F framebuffer incomplete (status 0x{status:04X})"
        ));
    }
    Ok((fbo, color))
}

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

/// Turns a pending GL error into `WorkerError::Gl` naming `what`.
pub fn check(gl: &glow::Context, what: &str) -> Result<(), WorkerError> {
    match check_err(gl) {
        None => Ok(()),
        Some(e) => {
            while check_err(gl).is_some() {}
            Err(WorkerError::Gl(format!("{what} raised {}", error_name(e))))
        }
    }
}

unsafe fn set_state(gl: &glow::Context, info: &GlInfo, case: &Case) -> Result<(), WorkerError> {
    let target = case.texture.target.gl();
    for p in tex_params(info.compat, case) {
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
) -> Result<Texels, WorkerError> {
    let t = &case.texture;
    gl.active_texture(glow::TEXTURE0);
    gl.bind_texture(t.target.gl(), Some(tex));
    let lvl = t
        .levels
        .first()
        .ok_or_else(|| WorkerError::Gl("no levels".into()))?;
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
    use shadowcheck_plan::gl;

    /// The plan names GL enums by number (it has no GL binding); each must be the registry's,
    /// which glow's constants are.
    #[test]
    fn plan_enums_match_glow() {
        let pairs = [
            (gl::UNSIGNED_BYTE, glow::UNSIGNED_BYTE),
            (gl::UNSIGNED_SHORT, glow::UNSIGNED_SHORT),
            (gl::UNSIGNED_INT, glow::UNSIGNED_INT),
            (gl::FLOAT, glow::FLOAT),
            (gl::DEPTH_COMPONENT, glow::DEPTH_COMPONENT),
            (gl::RED, glow::RED),
            (gl::DEPTH_COMPONENT16, glow::DEPTH_COMPONENT16),
            (gl::DEPTH_COMPONENT24, glow::DEPTH_COMPONENT24),
            (gl::DEPTH_COMPONENT32, glow::DEPTH_COMPONENT32),
            (gl::DEPTH_COMPONENT32F, glow::DEPTH_COMPONENT32F),
            (gl::DEPTH_STENCIL, glow::DEPTH_STENCIL),
            (gl::UNSIGNED_INT_24_8, glow::UNSIGNED_INT_24_8),
            (gl::DEPTH24_STENCIL8, glow::DEPTH24_STENCIL8),
            (gl::DEPTH32F_STENCIL8, glow::DEPTH32F_STENCIL8),
            (
                gl::FLOAT_32_UNSIGNED_INT_24_8_REV,
                glow::FLOAT_32_UNSIGNED_INT_24_8_REV,
            ),
            (gl::R8, glow::R8),
            (gl::TEXTURE_BORDER_COLOR, glow::TEXTURE_BORDER_COLOR),
            (gl::TEXTURE_MAG_FILTER, glow::TEXTURE_MAG_FILTER),
            (gl::TEXTURE_MIN_FILTER, glow::TEXTURE_MIN_FILTER),
            (gl::TEXTURE_WRAP_S, glow::TEXTURE_WRAP_S),
            (gl::TEXTURE_WRAP_T, glow::TEXTURE_WRAP_T),
            (gl::TEXTURE_WRAP_R, glow::TEXTURE_WRAP_R),
            (gl::TEXTURE_MIN_LOD, glow::TEXTURE_MIN_LOD),
            (gl::TEXTURE_MAX_LOD, glow::TEXTURE_MAX_LOD),
            (gl::TEXTURE_BASE_LEVEL, glow::TEXTURE_BASE_LEVEL),
            (gl::TEXTURE_MAX_LEVEL, glow::TEXTURE_MAX_LEVEL),
            (gl::TEXTURE_LOD_BIAS, glow::TEXTURE_LOD_BIAS),
            (gl::TEXTURE_COMPARE_MODE, glow::TEXTURE_COMPARE_MODE),
            (gl::TEXTURE_COMPARE_FUNC, glow::TEXTURE_COMPARE_FUNC),
            (gl::TEXTURE_SWIZZLE_R, glow::TEXTURE_SWIZZLE_R),
            (gl::TEXTURE_SWIZZLE_G, glow::TEXTURE_SWIZZLE_G),
            (gl::TEXTURE_SWIZZLE_B, glow::TEXTURE_SWIZZLE_B),
            (gl::TEXTURE_SWIZZLE_A, glow::TEXTURE_SWIZZLE_A),
            (
                gl::DEPTH_STENCIL_TEXTURE_MODE,
                glow::DEPTH_STENCIL_TEXTURE_MODE,
            ),
        ];
        for (i, (plan, glow)) in pairs.into_iter().enumerate() {
            assert_eq!(plan, glow, "pair {i}");
        }
        // glow has no constants for the compatibility and extension pnames; their registry values:
        assert_eq!(gl::DEPTH_TEXTURE_MODE, 0x884B);
        assert_eq!(gl::TEXTURE_COMPARE_FAIL_VALUE_ARB, 0x80BF);
    }
}
