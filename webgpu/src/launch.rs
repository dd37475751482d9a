//! How the browser is started for each WebGPU backend, and which adapter the page asks for.
//!
//! Measured with Chromium 156 headless (no GPU on the machine): `navigator.gpu` exists only with
//! `--enable-unsafe-webgpu` and only in a secure context (WebGPU "navigator.gpu" is
//! `[SecureContext]`; about:blank is not one, so the worker loads a file:// page, see
//! `worker.rs`). Every flag set tried then gives Dawn's Vulkan backend on SwiftShader (adapter
//! info vendor `google`, architecture `swiftshader`, isFallbackAdapter true), with or without
//! `--use-angle=swiftshader` / `--enable-unsafe-swiftshader` / `--disable-gpu`;
//! `--use-webgpu-adapter=swiftshader` names it explicitly, so that a machine with a GPU still
//! tests SwiftShader, and `--disable-gpu` keeps a host GPU out as for WebGL.
//! `--enable-webgpu-developer-features` unmasks the adapter's `device` and `description`
//! (otherwise empty strings), which the hello reports.
//!
//! `--use-webgpu-adapter=opengles` with `requestAdapter({featureLevel: "compatibility"})` gives
//! a second adapter: Dawn's OpenGL ES backend on ANGLE (ANGLE's Vulkan back end on SwiftShader,
//! description `ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) ...))`), in WebGPU's
//! compatibility mode (no "core-features-and-limits": no cube-map-array views, no
//! depth32float-stencil8). Its core-mode request still answers with the SwiftShader adapter.

use shadowcheck_webgl::browser::Launch;

/// The WebGPU backends: the name after `webgpu:`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// `webgpu:chromium`: Dawn's Vulkan backend on SwiftShader, core WebGPU.
    Core,
    /// `webgpu:chromium-compat`: Dawn's OpenGL ES backend on ANGLE on SwiftShader, in
    /// compatibility mode.
    Compat,
}

impl Variant {
    pub const ALL: [Variant; 2] = [Variant::Core, Variant::Compat];

    /// The part of the backend name after `webgpu:`.
    pub fn key(self) -> &'static str {
        match self {
            Variant::Core => "chromium",
            Variant::Compat => "chromium-compat",
        }
    }

    pub fn from_key(s: &str) -> Option<Variant> {
        Variant::ALL.into_iter().find(|v| v.key() == s)
    }

    /// The backend's full name.
    pub fn name(self) -> String {
        format!("webgpu:{}", self.key())
    }

    /// The browser flags (after the common ones of `shadowcheck_webgl::browser::COMMON_FLAGS`).
    pub fn launch(self) -> Launch {
        let flags: &[&str] = match self {
            Variant::Core => &[
                "--enable-unsafe-webgpu",
                "--use-webgpu-adapter=swiftshader",
                "--enable-webgpu-developer-features",
                "--disable-gpu",
            ],
            Variant::Compat => &[
                "--enable-unsafe-webgpu",
                "--use-webgpu-adapter=opengles",
                "--enable-webgpu-developer-features",
                "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader",
            ],
        };
        Launch {
            flags: flags.iter().map(|f| f.to_string()).collect(),
            env: vec![],
        }
    }

    /// The `GPURequestAdapterOptions.featureLevel` the page asks for (WebGPU).
    pub fn feature_level(self) -> &'static str {
        match self {
            Variant::Core => "core",
            Variant::Compat => "compatibility",
        }
    }
}

/// `webgpu:<variant>` as a variant.
pub fn parse_backend(name: &str) -> Option<Variant> {
    name.strip_prefix("webgpu:").and_then(Variant::from_key)
}
