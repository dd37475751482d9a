//! `shadowcheck webgl-worker --backend webgl:chromium-gles`: headless Chromium with a WebGL 2.0
//! page on the instance's ANGLE back end and driver, speaking runner/PROTOCOL.md on stdin/stdout
//! (the `webgl:*` backends' child; `backend::webgl::worker_command`).
use shadowcheck_webgl::instance;
use shadowcheck_webgl::worker::{probe_line, WebglWorker};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Backend name: webgl:chromium (ANGLE Vulkan on SwiftShader), webgl:chromium-gles (ANGLE
    /// OpenGL ES on Mesa's llvmpipe) or webgl:chromium-lavapipe (ANGLE Vulkan on Mesa's lavapipe).
    #[arg(long, default_value = "webgl:chromium")]
    backend: String,
    /// Only start the browser and the page and print `ok <name>` or `unavailable: <reason>`.
    #[arg(long)]
    probe: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    let inst = instance::of_backend(&args.backend)?;
    if args.probe {
        return Ok(super::workers::probe_exit(probe_line(inst)));
    }
    let mut w = WebglWorker::start(inst)?;
    super::workers::serve_stdio(&mut w)?;
    Ok(ExitCode::SUCCESS)
}
