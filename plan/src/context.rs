//! The context a plan is made for: its kind ([`ContextApi`]), what it exposes ([`GlInfo`]: version,
//! GLSL version, extensions) and the preferred lookup function ([`LookupForm`]).

use shadowcheck_model::{ApiPath, Target};
use std::collections::HashSet;

/// The kind of context.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContextApi {
    /// Desktop GL core profile.
    Core,
    /// Desktop GL compatibility profile.
    Compat,
    /// OpenGL ES 3.x.
    Es3,
    /// OpenGL ES 2.0 (Mesa hands out an ES 3.x context; only ES 2.0 paths are run on it).
    Es2,
}

/// Which GLSL lookup function realizes λ when the target has several (GLSL >= 1.30 / ES 3.00
/// paths only; the legacy paths have one form each).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum LookupForm {
    /// textureLod, else textureGrad, else texture() with derivatives (the default).
    #[default]
    Auto,
    /// textureLod first.
    Lod,
    /// textureGrad first (λ from explicit gradients).
    Grad,
    /// texture() first (λ from the derivatives of the coordinates across the pixel quad).
    Implicit,
}

impl LookupForm {
    pub const NAMED: [LookupForm; 3] = [LookupForm::Lod, LookupForm::Grad, LookupForm::Implicit];
    pub fn key(self) -> &'static str {
        match self {
            LookupForm::Auto => "auto",
            LookupForm::Lod => "lod",
            LookupForm::Grad => "grad",
            LookupForm::Implicit => "implicit",
        }
    }
}

impl ContextApi {
    pub const ALL: [ContextApi; 4] = [
        ContextApi::Core,
        ContextApi::Compat,
        ContextApi::Es3,
        ContextApi::Es2,
    ];
    pub fn key(self) -> &'static str {
        match self {
            ContextApi::Core => "core",
            ContextApi::Compat => "compat",
            ContextApi::Es3 => "es3",
            ContextApi::Es2 => "es2",
        }
    }
    /// OpenGL ES (rather than desktop GL).
    pub fn is_es(self) -> bool {
        matches!(self, ContextApi::Es3 | ContextApi::Es2)
    }
    /// The API paths a context of this kind can run (before asking the driver what it exposes).
    pub fn paths(self) -> &'static [ApiPath] {
        match self {
            ContextApi::Core => &[ApiPath::GlslCore],
            ContextApi::Compat => &[
                ApiPath::FixedFunction,
                ApiPath::Glsl120,
                ApiPath::Glsl130,
                ApiPath::ArbFp,
            ],
            ContextApi::Es3 => &[ApiPath::Es300],
            ContextApi::Es2 => &[ApiPath::Es100Ext],
        }
    }
}

/// What the current context is and exposes.
#[derive(Debug, Clone)]
pub struct GlInfo {
    pub api: ContextApi,
    pub es: bool,
    pub compat: bool,
    /// (major, minor) from GL_VERSION.
    pub version: (u32, u32),
    /// GLSL version * 100 (e.g. 450, 320 for ES 3.20).
    pub glsl: u32,
    pub renderer: String,
    pub version_string: String,
    pub extensions: HashSet<String>,
    /// The preferred lookup function (from the backend name).
    pub form: LookupForm,
    /// The version is raised by MESA_GL_VERSION_OVERRIDE / MESA_GLES_VERSION_OVERRIDE above what
    /// the driver claims (`egl:zink+swiftshader:core|es3`, `gl/src/names.rs`): a feature of the
    /// raised version that the driver does not claim by extension is not used ([`Self::compute`]).
    pub version_override: bool,
}

impl GlInfo {
    pub fn has_ext(&self, e: &str) -> bool {
        self.extensions.contains(e)
    }
    pub fn at_least(&self, major: u32, minor: u32) -> bool {
        self.version >= (major, minor)
    }
    pub fn cube_array(&self) -> bool {
        if self.es {
            self.at_least(3, 2)
                || self.has_ext("GL_OES_texture_cube_map_array")
                || self.has_ext("GL_EXT_texture_cube_map_array")
        } else {
            self.at_least(4, 0) || self.has_ext("GL_ARB_texture_cube_map_array")
        }
    }
    /// CLAMP_TO_BORDER and TEXTURE_BORDER_COLOR: desktop GL 1.3 on; ES 3.2 or
    /// OES/EXT_texture_border_clamp.
    pub fn border_clamp(&self) -> bool {
        !self.es
            || self.at_least(3, 2)
            || self.has_ext("GL_OES_texture_border_clamp")
            || self.has_ext("GL_EXT_texture_border_clamp")
    }
    /// EXT_texture_shadow_lod: its textureLod/texture overloads for array and cube shadow samplers
    /// come from the extension alone (GLSL 4.60 §8.9.2 lists none of them).
    pub fn shadow_lod(&self) -> bool {
        self.has_ext("GL_EXT_texture_shadow_lod")
    }
    /// Shadow textureGather / textureGatherOffset(s): GLSL 4.00 on desktop GL (ARB_texture_gather
    /// has no shadow forms), GLSL ES 3.10 on ES (textureGatherOffsets only from GLSL ES 3.20:
    /// [`plan_for`] skips it below).
    pub fn gather(&self) -> bool {
        if self.es {
            self.at_least(3, 1) && self.glsl >= 310
        } else {
            self.glsl >= 400
        }
    }
    /// Compute shaders (GLSL 4.30 §2.6 "Compute Processor", GLSL ES 3.10) with image stores of
    /// an RGBA32F image: GL 4.3, ES 3.1 (ARB_compute_shader alone does not give GLSL 4.30's
    /// `#version`, which the compute-stage program is written in). Under a version override only
    /// where the driver claims ARB_compute_shader (ES has no such extension): zink on SwiftShader
    /// (native GL 2.1 / ES 2.0) does not, and its overridden GL 4.6 core context refuses
    /// glCreateShader(GL_COMPUTE_SHADER).
    pub fn compute(&self) -> bool {
        if self.version_override && (self.es || !self.has_ext("GL_ARB_compute_shader")) {
            return false;
        }
        if self.es {
            self.at_least(3, 1) && self.glsl >= 310
        } else {
            self.at_least(4, 3) && self.glsl >= 430
        }
    }
    /// DEPTH_STENCIL_TEXTURE_MODE: GL 4.3 or ARB_stencil_texturing; ES 3.1.
    pub fn stencil_texturing(&self) -> bool {
        if self.es {
            self.at_least(3, 1)
        } else {
            self.at_least(4, 3) || self.has_ext("GL_ARB_stencil_texturing")
        }
    }
    /// TEXTURE_SWIZZLE_*: GL 3.3 or ARB/EXT_texture_swizzle; ES 3.0.
    pub fn swizzle(&self) -> bool {
        if self.es {
            self.at_least(3, 0)
        } else {
            self.at_least(3, 3)
                || self.has_ext("GL_ARB_texture_swizzle")
                || self.has_ext("GL_EXT_texture_swizzle")
        }
    }
    /// Enable / Disable(TEXTURE_CUBE_MAP_SEAMLESS): GL 3.2 or ARB_seamless_cube_map; ES has
    /// no such enable (always seamless).
    pub fn seamless_toggle(&self) -> bool {
        !self.es && (self.at_least(3, 2) || self.has_ext("GL_ARB_seamless_cube_map"))
    }
    /// Sampler objects: GL 3.3 or ARB_sampler_objects; ES 3.0.
    pub fn sampler_objects(&self) -> bool {
        if self.es {
            self.at_least(3, 0)
        } else {
            self.at_least(3, 3) || self.has_ext("GL_ARB_sampler_objects")
        }
    }
    /// 1D and 2D array textures on desktop GL: 3.0 or EXT_texture_array.
    fn texture_array(&self) -> bool {
        self.at_least(3, 0) || self.has_ext("GL_EXT_texture_array")
    }
    /// Rectangle textures on desktop GL: 3.1 or ARB/NV/EXT_texture_rectangle.
    fn texture_rectangle(&self) -> bool {
        self.at_least(3, 1)
            || [
                "GL_ARB_texture_rectangle",
                "GL_NV_texture_rectangle",
                "GL_EXT_texture_rectangle",
            ]
            .iter()
            .any(|e| self.has_ext(e))
    }
    pub fn arbfp_shadow(&self) -> bool {
        self.compat
            && self.has_ext("GL_ARB_fragment_program")
            && self.has_ext("GL_ARB_fragment_program_shadow")
    }
    pub fn shadow_samplers_es2(&self) -> bool {
        self.has_ext("GL_EXT_shadow_samplers")
    }
    /// The paths of this context that can run here.
    pub fn paths(&self) -> Vec<ApiPath> {
        self.api
            .paths()
            .iter()
            .copied()
            .filter(|p| match p {
                ApiPath::ArbFp => self.arbfp_shadow(),
                ApiPath::Glsl130 => self.glsl >= 130,
                ApiPath::Es100Ext => self.shadow_samplers_es2(),
                _ => true,
            })
            .collect()
    }
    /// Targets a case may use on this context.
    pub fn targets(&self) -> Vec<Target> {
        let mut v = if self.es || self.api == ContextApi::Es2 {
            vec![Target::T2d, Target::Cube, Target::T2dArray]
        } else {
            let mut v = vec![Target::T1d, Target::T2d];
            if self.texture_rectangle() {
                v.push(Target::Rect);
            }
            v.push(Target::Cube);
            if self.texture_array() {
                v.extend([Target::T1dArray, Target::T2dArray]);
            }
            v
        };
        if self.api == ContextApi::Es2 {
            v = vec![Target::T2d];
        } else if self.cube_array() {
            v.push(Target::CubeArray);
        }
        v
    }
}
