//! shadowcheck-webgpu: the `webgpu:chromium` worker. WebGPU in headless Chromium (Dawn on
//! SwiftShader's Vulkan driver), driven over the Chrome DevTools Protocol pipe of the WebGL
//! crate's [`shadowcheck_webgl::browser`], drawing the `wgsl` path of the lookup plan
//! (shadowcheck-plan: the lookup form, the WGSL of `shaders::wgsl`, the batch layout):
//!
//! - [`launch`]: the browser flags and which adapter is asked for;
//! - [`texture`]: a case's texture, view and `GPUSamplerDescriptor`, or why WebGPU cannot
//!   express it; the texel values the page writes with `frag_depth`;
//! - [`job`]: a batch of lookups as one job for the page script (`page.js`) and its answer as
//!   protocol answers;
//! - [`worker`]: the hello and the batches ([`shadowcheck_plan::serve::Serve`]).

pub mod job;
pub mod launch;
pub mod texture;
pub mod worker;

/// What goes wrong in the WebGPU worker.
#[derive(Debug, thiserror::Error)]
pub enum WebgpuError {
    /// The browser is missing, died, or its DevTools pipe failed.
    #[error(transparent)]
    Browser(#[from] shadowcheck_webgl::WebglError),
    /// The page has no WebGPU adapter or device (the page says why).
    #[error("WebGPU: {0}")]
    Adapter(String),
    /// The page script threw or answered something else than expected.
    #[error("page: {0}")]
    Page(String),
    /// The device was lost, or the page stopped answering, while a batch ran: nothing it read is
    /// an observation.
    #[error("the WebGPU device is gone ({0})")]
    DeviceLost(String),
}
