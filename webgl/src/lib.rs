//! shadowcheck-webgl: the `webgl:*` worker. WebGL 2.0 in headless Chromium on one of ANGLE's back
//! ends ([`instance`]: Vulkan on SwiftShader, OpenGL ES on Mesa's llvmpipe, Vulkan on Mesa's
//! lavapipe), driven over the Chrome DevTools Protocol pipe ([`browser`]), running the `es300`
//! path of the lookup plan: the same plans, shader text, texture bytes and TexParameter calls as
//! the GL worker (shadowcheck-plan), made by a small page script (`page.js`) in batches ([`job`]). The [`worker`] answers runner/PROTOCOL.md through
//! the plan's serve loop; the runner starts it as `shadowcheck webgl-worker`.

pub mod browser;
pub mod instance;
pub mod job;
pub mod state;
pub mod worker;

#[derive(Debug, thiserror::Error)]
pub enum WebglError {
    /// The browser is not installed or cannot be started.
    #[error("{0}")]
    NoBrowser(String),
    /// The browser or its DevTools pipe failed.
    #[error("browser: {0}")]
    Browser(String),
    /// The page script threw.
    #[error("page: {0}")]
    Page(String),
    /// The page has no usable WebGL 2.0 context.
    #[error("WebGL: {0}")]
    Context(String),
    /// The page's WebGL context was lost while it ran (the page says why): nothing it read
    /// is an observation.
    #[error("the WebGL context was lost ({0})")]
    ContextLost(String),
}
