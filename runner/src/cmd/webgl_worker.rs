//! `shadowcheck webgl-worker --backend webgl:chromium-gles`: headless Chromium with a WebGL 2.0
//! page on the instance's ANGLE back end and driver, speaking runner/PROTOCOL.md on stdin/stdout
//! (the `webgl:*` backends' child; `backend::webgl::worker_command`).
use shadowcheck_plan::serve::serve;
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
        let (ok, line) = probe_line(inst);
        println!("{line}");
        return Ok(if ok {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let mut w = WebglWorker::start(inst)?;
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    serve(
        &mut w,
        std::io::BufReader::with_capacity(1 << 16, stdin),
        std::io::BufWriter::new(stdout.lock()),
    )?;
    Ok(ExitCode::SUCCESS)
}
