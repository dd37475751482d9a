//! Legacy (compatibility-profile) entry points that glow 0.18 does not wrap: immediate mode,
//! TexEnv, and ARB_fragment_program. Loaded through the same loader as glow.

use super::WorkerError;
use std::ffi::c_void;

type FnBegin = unsafe extern "system" fn(u32);
type FnEnd = unsafe extern "system" fn();
type FnVertex2f = unsafe extern "system" fn(f32, f32);
type FnTexCoord4f = unsafe extern "system" fn(f32, f32, f32, f32);
type FnColor4f = unsafe extern "system" fn(f32, f32, f32, f32);
type FnTexEnvi = unsafe extern "system" fn(u32, u32, i32);
type FnTexEnvf = unsafe extern "system" fn(u32, u32, f32);
type FnGenPrograms = unsafe extern "system" fn(i32, *mut u32);
type FnBindProgram = unsafe extern "system" fn(u32, u32);
type FnProgramString = unsafe extern "system" fn(u32, u32, i32, *const c_void);
type FnProgramLocal4f = unsafe extern "system" fn(u32, u32, f32, f32, f32, f32);

pub const GL_TRIANGLES: u32 = 0x0004;
pub const GL_TEXTURE_ENV: u32 = 0x2300;
pub const GL_TEXTURE_ENV_MODE: u32 = 0x2200;
pub const GL_REPLACE: u32 = 0x1E01;
/// TexEnv COMBINE (GL 1.3, ARB_texture_env_combine) and the state that makes it pass the source
/// colour through: COMBINE_RGB = COMBINE_ALPHA = REPLACE (Arg0), SOURCE0 = TEXTURE, OPERAND0 =
/// SRC_COLOR / SRC_ALPHA.
pub const GL_COMBINE: u32 = 0x8570;
pub const GL_COMBINE_RGB: u32 = 0x8571;
pub const GL_COMBINE_ALPHA: u32 = 0x8572;
pub const GL_SOURCE0_RGB: u32 = 0x8580;
pub const GL_SOURCE0_ALPHA: u32 = 0x8588;
pub const GL_OPERAND0_RGB: u32 = 0x8590;
pub const GL_OPERAND0_ALPHA: u32 = 0x8598;
pub const GL_TEXTURE: u32 = 0x1702;
pub const GL_SRC_COLOR: u32 = 0x0300;
pub const GL_SRC_ALPHA: u32 = 0x0302;
pub const GL_TEXTURE_FILTER_CONTROL: u32 = 0x8500;
pub const GL_TEXTURE_LOD_BIAS: u32 = 0x8501;
pub const GL_FRAGMENT_PROGRAM_ARB: u32 = 0x8804;
pub const GL_PROGRAM_FORMAT_ASCII_ARB: u32 = 0x8875;
pub const GL_PROGRAM_ERROR_POSITION_ARB: u32 = 0x864B;
pub const GL_PROGRAM_ERROR_STRING_ARB: u32 = 0x8874;

/// The legacy entry points of a compatibility context.
pub struct Legacy {
    begin: FnBegin,
    end: FnEnd,
    vertex2f: FnVertex2f,
    tex_coord4f: FnTexCoord4f,
    color4f: FnColor4f,
    tex_envi: FnTexEnvi,
    tex_envf: FnTexEnvf,
    /// ARB_fragment_program (None where not exposed).
    arbfp: Option<ArbFp>,
}

struct ArbFp {
    gen: FnGenPrograms,
    bind: FnBindProgram,
    string: FnProgramString,
    local4f: FnProgramLocal4f,
}

fn load<T: Copy>(loader: &dyn Fn(&str) -> *const c_void, name: &str) -> Result<T, WorkerError> {
    let p = loader(name);
    if p.is_null() {
        return Err(WorkerError::MissingEntryPoint(name.to_string()));
    }
    debug_assert_eq!(
        std::mem::size_of::<T>(),
        std::mem::size_of::<*const c_void>()
    );
    // SAFETY: T is an `extern "system" fn` type matching the GL declaration of `name`.
    Ok(unsafe { std::mem::transmute_copy::<*const c_void, T>(&p) })
}

impl Legacy {
    /// Loads the entry points; `with_arbfp` also loads ARB_fragment_program's.
    pub fn load(
        loader: &dyn Fn(&str) -> *const c_void,
        with_arbfp: bool,
    ) -> Result<Legacy, WorkerError> {
        let arbfp = if with_arbfp {
            Some(ArbFp {
                gen: load(loader, "glGenProgramsARB")?,
                bind: load(loader, "glBindProgramARB")?,
                string: load(loader, "glProgramStringARB")?,
                local4f: load(loader, "glProgramLocalParameter4fARB")?,
            })
        } else {
            None
        };
        Ok(Legacy {
            begin: load(loader, "glBegin")?,
            end: load(loader, "glEnd")?,
            vertex2f: load(loader, "glVertex2f")?,
            tex_coord4f: load(loader, "glTexCoord4f")?,
            color4f: load(loader, "glColor4f")?,
            tex_envi: load(loader, "glTexEnvi")?,
            tex_envf: load(loader, "glTexEnvf")?,
            arbfp,
        })
    }

    /// One triangle covering the whole viewport, with the current texture coordinate and colour.
    ///
    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn fullscreen_triangle(&self) {
        (self.begin)(GL_TRIANGLES);
        (self.vertex2f)(-1.0, -1.0);
        (self.vertex2f)(3.0, -1.0);
        (self.vertex2f)(-1.0, 3.0);
        (self.end)();
    }

    /// The full-viewport triangle with one texture coordinate per vertex (corners (-1,-1), (3,-1),
    /// (-1,3) in NDC).
    ///
    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn triangle_with_tex_coords(&self, tc: [[f32; 4]; 3]) {
        (self.begin)(GL_TRIANGLES);
        for (v, (x, y)) in tc.iter().zip([(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)]) {
            (self.tex_coord4f)(v[0], v[1], v[2], v[3]);
            (self.vertex2f)(x, y);
        }
        (self.end)();
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn tex_coord4f(&self, v: [f32; 4]) {
        (self.tex_coord4f)(v[0], v[1], v[2], v[3]);
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn color4f(&self, v: [f32; 4]) {
        (self.color4f)(v[0], v[1], v[2], v[3]);
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn tex_envi(&self, target: u32, pname: u32, v: i32) {
        (self.tex_envi)(target, pname, v);
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn tex_envf(&self, target: u32, pname: u32, v: f32) {
        (self.tex_envf)(target, pname, v);
    }

    pub fn has_arbfp(&self) -> bool {
        self.arbfp.is_some()
    }

    /// Compiles an ARB fragment program; returns its name or the driver's error string (the caller
    /// reads GL_PROGRAM_ERROR_STRING_ARB through glow).
    ///
    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn arbfp_program(&self, gl: &glow::Context, src: &str) -> Result<u32, WorkerError> {
        use glow::HasContext;
        let fp = self
            .arbfp
            .as_ref()
            .ok_or_else(|| WorkerError::MissingEntryPoint("glProgramStringARB".into()))?;
        while gl.get_error() != glow::NO_ERROR {}
        let mut id = 0u32;
        (fp.gen)(1, &mut id);
        (fp.bind)(GL_FRAGMENT_PROGRAM_ARB, id);
        (fp.string)(
            GL_FRAGMENT_PROGRAM_ARB,
            GL_PROGRAM_FORMAT_ASCII_ARB,
            src.len() as i32,
            src.as_ptr() as *const c_void,
        );
        let pos = gl.get_parameter_i32(GL_PROGRAM_ERROR_POSITION_ARB);
        let err = gl.get_error();
        if pos != -1 || err != glow::NO_ERROR {
            let msg = gl.get_parameter_string(GL_PROGRAM_ERROR_STRING_ARB);
            return Err(WorkerError::Gl(format!(
                "ARB fragment program rejected at {pos}: {msg}\n{src}"
            )));
        }
        Ok(id)
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn bind_arbfp(&self, id: u32) {
        if let Some(fp) = &self.arbfp {
            (fp.bind)(GL_FRAGMENT_PROGRAM_ARB, id);
        }
    }

    /// # Safety
    /// A compatibility context must be current.
    pub unsafe fn arbfp_local(&self, index: u32, v: [f32; 4]) {
        if let Some(fp) = &self.arbfp {
            (fp.local4f)(GL_FRAGMENT_PROGRAM_ARB, index, v[0], v[1], v[2], v[3]);
        }
    }
}
