//! Backend names: `egl:<driver>:<api>[:<form>]` and `osmesa:<driver>:<api>[:<form>]`.
//!
//! The optional `<form>` (`lod`, `grad`, `implicit`) says which GLSL lookup function realizes the
//! level of detail where several exist (`textureLod`, `textureGrad`, `texture` with derivatives);
//! without it the worker prefers `textureLod` (exact λ), then gradients, then derivatives.
//!
//! A name says which window-system layer creates the context (EGL surfaceless or OSMesa), which Mesa
//! Gallium driver runs it, and which kind of context is asked for. The driver is chosen by
//! environment variables that must be set before Mesa loads, which is why every backend runs in its
//! own worker process (see shadowcheck-runner's `backend::gl::worker_command`).

use super::libdir::{
    lib_dir_env, missing_lib, swiftshader_dir, SWIFTSHADER_FETCH, SWIFTSHADER_LIBS,
};
use super::WorkerError;
pub use shadowcheck_plan::{ContextApi, LookupForm};

/// The layer that creates the context.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Platform {
    /// EGL on `EGL_PLATFORM_SURFACELESS_MESA`, rendering into an FBO.
    Egl,
    /// OSMesa (`libOSMesa.so.8`), desktop GL only.
    Osmesa,
}

/// The driver behind the context: a Mesa Gallium driver, or a preset naming another
/// implementation's texture unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Driver {
    Llvmpipe,
    Softpipe,
    /// GL on Vulkan, over lavapipe on these machines.
    Zink,
    /// zink on SwiftShader's Vulkan driver (`libvk_swiftshader.so` from Debian's chromium-common,
    /// chosen with `VK_ICD_FILENAMES`): Mesa's GL front end, SwiftShader's sampling, comparison,
    /// filtering and mip selection. Its native contexts are GL 2.1 and ES 2.0; see
    /// [`BackendName::env`] for the version overrides and why they are honest.
    ZinkSwiftshader,
    /// SwiftShader's own OpenGL ES 3.0 (front end, shader compiler and sampler its own): the
    /// `libEGL.so` / `libGLESv2.so` of the cefpython3 66.0 wheel, fetched by
    /// `gl/fetch-swiftshader.sh` into [`swiftshader_dir`]; EGL 1.4 only (pbuffer contexts).
    Swiftshader,
    /// Whatever the system's (or `egl@<dir>:`'s) libEGL gives, with none of Mesa's driver
    /// variables: a vendor's EGL driver. Never probed by the default run (on a Mesa machine it is
    /// one of Mesa's drivers again); named explicitly.
    Native,
}

/// A parsed backend name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BackendName {
    pub platform: Platform,
    pub driver: Driver,
    pub api: ContextApi,
    /// The preferred lookup function (a fourth name part; `Auto` when absent).
    pub form: LookupForm,
}

impl Platform {
    pub fn key(self) -> &'static str {
        match self {
            Platform::Egl => "egl",
            Platform::Osmesa => "osmesa",
        }
    }
}

impl Driver {
    /// Every driver a backend name may give.
    pub const ALL: [Driver; 6] = [
        Driver::Llvmpipe,
        Driver::Softpipe,
        Driver::Zink,
        Driver::ZinkSwiftshader,
        Driver::Swiftshader,
        Driver::Native,
    ];
    /// Mesa's own Gallium drivers (on lavapipe for zink): one GL front end and state tracker.
    pub const MESA: [Driver; 3] = [Driver::Llvmpipe, Driver::Softpipe, Driver::Zink];
    pub fn key(self) -> &'static str {
        match self {
            Driver::Llvmpipe => "llvmpipe",
            Driver::Softpipe => "softpipe",
            Driver::Zink => "zink",
            Driver::ZinkSwiftshader => "zink+swiftshader",
            Driver::Swiftshader => "swiftshader",
            Driver::Native => "native",
        }
    }
    /// Whether Mesa's driver-selection variables (LIBGL_ALWAYS_SOFTWARE, GALLIUM_DRIVER,
    /// EGL_PLATFORM) apply: the Gallium drivers.
    fn is_gallium(self) -> bool {
        matches!(
            self,
            Driver::Llvmpipe | Driver::Softpipe | Driver::Zink | Driver::ZinkSwiftshader
        )
    }
    /// Whether GL_RENDERER names this driver (`zink (SwiftShader Device (Subzero))` for
    /// zink+swiftshader, `zink (Lavapipe ...)` for zink): a worker refuses to run on another one.
    pub fn renderer_matches(self, renderer: &str) -> bool {
        let r = renderer.to_lowercase();
        match self {
            Driver::Llvmpipe | Driver::Softpipe => r.contains(self.key()),
            Driver::Zink => r.contains("zink") && !r.contains("swiftshader"),
            Driver::ZinkSwiftshader => r.contains("zink") && r.contains("swiftshader"),
            // "Google SwiftShader" (SwiftShader 4.0's own GLES).
            Driver::Swiftshader => r.contains("swiftshader") && !r.contains("zink"),
            Driver::Native => true,
        }
    }
}

/// SwiftShader's Vulkan ICD file as Debian's chromium-common installs it; `$SHADOWCHECK_VK_SWIFTSHADER_ICD`
/// names another.
pub const VK_SWIFTSHADER_ICD: &str = "/usr/lib/chromium/vk_swiftshader_icd.json";
pub const VK_SWIFTSHADER_ICD_ENV: &str = "SHADOWCHECK_VK_SWIFTSHADER_ICD";

/// The SwiftShader Vulkan ICD file this machine would use.
pub fn vk_swiftshader_icd() -> std::path::PathBuf {
    std::env::var_os(VK_SWIFTSHADER_ICD_ENV)
        .map_or_else(|| VK_SWIFTSHADER_ICD.into(), std::path::PathBuf::from)
}

impl BackendName {
    /// Every combination the default run probes, in a stable order (EGL first): every driver but
    /// `native`.
    pub fn all() -> Vec<BackendName> {
        let mut v = Vec::new();
        for platform in [Platform::Egl, Platform::Osmesa] {
            for driver in Driver::ALL.into_iter().filter(|d| *d != Driver::Native) {
                for api in ContextApi::ALL {
                    v.push(BackendName {
                        platform,
                        driver,
                        api,
                        form: LookupForm::Auto,
                    });
                }
            }
        }
        v
    }

    /// Why this combination can never work, independent of what is installed.
    pub fn static_unavailability(self) -> Option<String> {
        if self.platform == Platform::Osmesa && self.api.is_es() {
            return Some(
                "OSMesa creates desktop GL contexts only (no OpenGL ES); use egl:".to_string()
                    + self.driver.key()
                    + ":"
                    + self.api.key(),
            );
        }
        if self.driver == Driver::Swiftshader && !self.api.is_es() {
            return Some(format!(
                "SwiftShader's own GL is OpenGL ES only; use egl:swiftshader:es3 or egl:zink+swiftshader:{}",
                self.api.key()
            ));
        }
        if self.platform == Platform::Osmesa
            && matches!(self.driver, Driver::Swiftshader | Driver::Native)
        {
            return Some(format!(
                "{} is an EGL library; use egl:{}:{}",
                self.driver.key(),
                self.driver.key(),
                self.api.key()
            ));
        }
        if self.platform == Platform::Osmesa && self.driver == Driver::ZinkSwiftshader {
            return Some(format!(
                "OSMesa cannot run zink (see osmesa:zink); use egl:zink+swiftshader:{}",
                self.api.key()
            ));
        }
        if self.platform == Platform::Osmesa && self.driver == Driver::Zink {
            return Some(
                "OSMesa with GALLIUM_DRIVER=zink segfaults in Mesa 22.3 (zink needs a winsys OSMesa does not give it); use egl:zink:*"
                    .to_string(),
            );
        }
        None
    }

    /// Environment variables that select the driver; set before the driver library loads.
    ///
    /// zink+swiftshader: `VK_ICD_FILENAMES` names SwiftShader's ICD. Its native contexts are GL 2.1
    /// and ES 2.0 (Mesa 22.3.6: no transform feedback, no geometry shaders), yet the GL 2.1
    /// context exposes, as extensions, every sampling feature the GLSL paths use
    /// (EXT_texture_array, EXT_gpu_shader4, ARB_shader_texture_lod, ARB_texture_cube_map_array,
    /// ARB_stencil_texturing, ARB_texture_float, ARB_color_buffer_float, ARB_texture_border_clamp)
    /// and the ES 2.0 one OES_texture_border_clamp. So the version overrides are honest for the
    /// paths that run (they claim only missing features no path uses):
    /// - `core`: MESA_GL_VERSION_OVERRIDE=4.6, MESA_GLSL_VERSION_OVERRIDE=460 (no core profile
    ///   below 3.2 exists);
    /// - `compat`: no override: the context runs at GL 2.1 / GLSL 1.20 (ff, ARB fp, GLSL 1.20);
    ///   the GLSL 1.30 path is Skip ("GLSL 1.30 not supported"), its lookups run on `core`;
    /// - `es3`, `es2`: MESA_GLES_VERSION_OVERRIDE=3.1 (ES 3.0 needs the RGBA32F render target
    ///   and GLSL ES 3.00, absent at 2.0; 3.1 adds DEPTH_STENCIL_TEXTURE_MODE, backed by
    ///   ARB_stencil_texturing). Not 3.2: Mesa's ES context refuses TEXTURE_CUBE_MAP_ARRAY without
    ///   OES_texture_cube_map_array, which this driver does not expose (it needs geometry
    ///   shaders), so at 3.2 every cube-map-array upload is a GL error; at 3.1 they are Skip.
    ///
    /// swiftshader: its libEGL from [`swiftshader_dir`], with LD_LIBRARY_PATH at that directory
    /// (otherwise it binds the system libGLESv2 and every pbuffer fails with EGL_BAD_ALLOC).
    /// native: nothing.
    pub fn env(self) -> Vec<(String, String)> {
        if self.driver == Driver::Swiftshader {
            return lib_dir_env(&swiftshader_dir());
        }
        if !self.driver.is_gallium() {
            return vec![];
        }
        let gallium = match self.driver {
            Driver::ZinkSwiftshader => "zink",
            d => d.key(),
        };
        let mut env = vec![
            ("LIBGL_ALWAYS_SOFTWARE".to_string(), "1".to_string()),
            ("GALLIUM_DRIVER".to_string(), gallium.to_string()),
            // Mesa's on-disk shader cache stays as the user has it: llvmpipe and zink JIT one
            // variant per sampler state, so a cold run of the ES fixtures takes ~40 s and a warm
            // one under 1 s. MESA_SHADER_CACHE_DISABLE=true in the environment gives cold runs.
        ];
        if self.platform == Platform::Egl {
            env.push(("EGL_PLATFORM".to_string(), "surfaceless".to_string()));
        }
        if self.driver == Driver::ZinkSwiftshader {
            let icd = vk_swiftshader_icd().to_string_lossy().into_owned();
            env.push(("VK_ICD_FILENAMES".to_string(), icd));
            let overrides: &[(&str, &str)] = match self.api {
                ContextApi::Core => &[
                    ("MESA_GL_VERSION_OVERRIDE", "4.6"),
                    ("MESA_GLSL_VERSION_OVERRIDE", "460"),
                ],
                ContextApi::Compat => &[],
                ContextApi::Es3 | ContextApi::Es2 => &[("MESA_GLES_VERSION_OVERRIDE", "3.1")],
            };
            env.extend(
                overrides
                    .iter()
                    .map(|(k, v)| (k.to_string(), v.to_string())),
            );
        }
        env
    }

    /// A file this backend needs that is missing here (SwiftShader's Vulkan ICD), with the
    /// command that installs it.
    pub fn missing_file(self) -> Option<(std::path::PathBuf, &'static str)> {
        match self.driver {
            Driver::ZinkSwiftshader => {
                let icd = vk_swiftshader_icd();
                (!icd.is_file()).then_some((
                    icd,
                    "apt-get install -y chromium-common mesa-vulkan-drivers",
                ))
            }
            Driver::Swiftshader => {
                missing_lib(&swiftshader_dir(), &SWIFTSHADER_LIBS).map(|p| (p, SWIFTSHADER_FETCH))
            }
            _ => None,
        }
    }
}

impl std::fmt::Display for BackendName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}:{}",
            self.platform.key(),
            self.driver.key(),
            self.api.key()
        )?;
        if self.form != LookupForm::Auto {
            write!(f, ":{}", self.form.key())?;
        }
        Ok(())
    }
}

impl std::str::FromStr for BackendName {
    type Err = WorkerError;
    fn from_str(s: &str) -> Result<Self, WorkerError> {
        let bad = |why: &str| WorkerError::BadName {
            name: s.to_string(),
            why: why.to_string(),
        };
        let parts: Vec<&str> = s.split(':').collect();
        if !(3..=4).contains(&parts.len()) {
            return Err(bad(
                "expected egl|osmesa:llvmpipe|softpipe|zink|zink+swiftshader|swiftshader|native:core|compat|es3|es2[:lod|grad|implicit] (egl@<lib-dir>: for another libEGL)",
            ));
        }
        let form = match parts.get(3) {
            None => LookupForm::Auto,
            Some(k) => LookupForm::NAMED
                .into_iter()
                .find(|f| f.key() == *k)
                .ok_or_else(|| {
                    bad("the lookup form (fourth part) must be lod, grad or implicit")
                })?,
        };
        let platform = match parts[0] {
            "egl" => Platform::Egl,
            "osmesa" => Platform::Osmesa,
            _ => return Err(bad("platform must be egl or osmesa")),
        };
        let driver = Driver::ALL
            .into_iter()
            .find(|d| d.key() == parts[1])
            .ok_or_else(|| bad("driver must be llvmpipe, softpipe, zink, zink+swiftshader, swiftshader or native"))?;
        let api = ContextApi::ALL
            .into_iter()
            .find(|a| a.key() == parts[2])
            .ok_or_else(|| bad("api must be core, compat, es3 or es2"))?;
        Ok(BackendName {
            platform,
            driver,
            api,
            form,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookup_form_is_an_optional_fourth_part() {
        let b: BackendName = "egl:llvmpipe:core:grad".parse().unwrap();
        assert_eq!((b.api, b.form), (ContextApi::Core, LookupForm::Grad));
        assert_eq!(b.to_string(), "egl:llvmpipe:core:grad");
        assert_eq!(
            "egl:llvmpipe:core".parse::<BackendName>().unwrap().form,
            LookupForm::Auto
        );
        let e = "egl:llvmpipe:core:fast"
            .parse::<BackendName>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("lod, grad or implicit"), "{e}");
        assert!("egl:llvmpipe:core:grad:x".parse::<BackendName>().is_err());
    }

    #[test]
    fn names_round_trip() {
        for b in BackendName::all() {
            let s = b.to_string();
            assert_eq!(s.parse::<BackendName>().unwrap(), b);
        }
        assert_eq!(BackendName::all().len(), 40);
    }

    #[test]
    fn bad_names_say_why() {
        let e = "egl:swrast:core"
            .parse::<BackendName>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("driver"), "{e}");
        assert!("egl:llvmpipe".parse::<BackendName>().is_err());
    }

    #[test]
    fn osmesa_zink_and_osmesa_es_are_unavailable_with_a_reason() {
        let z: BackendName = "osmesa:zink:core".parse().unwrap();
        assert!(z.static_unavailability().unwrap().contains("segfault"));
        let e: BackendName = "osmesa:llvmpipe:es3".parse().unwrap();
        assert!(e.static_unavailability().unwrap().contains("OpenGL ES"));
        let ok: BackendName = "egl:zink:es2".parse().unwrap();
        assert!(ok.static_unavailability().is_none());
        assert!(ok
            .env()
            .contains(&("GALLIUM_DRIVER".to_string(), "zink".to_string())));
    }
}
