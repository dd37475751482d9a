//! `shadowcheck webgpu-worker --backend webgpu:chromium`: headless Chromium with a WebGPU page,
//! speaking runner/PROTOCOL.md on stdin/stdout (the `webgpu:*` backends' child;
//! `backend::webgpu::worker_command`).
use shadowcheck_webgpu::launch::parse_backend;
use shadowcheck_webgpu::worker::{probe_line, WebgpuWorker};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Backend name: webgpu:chromium or webgpu:chromium-compat.
    #[arg(long, default_value = "webgpu:chromium")]
    backend: String,
    /// Only start the browser, the page and the device and print `ok <name>` or
    /// `unavailable: <reason>`.
    #[arg(long)]
    probe: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    let variant = parse_backend(&args.backend).ok_or_else(|| {
        anyhow::anyhow!(
            "unknown WebGPU backend `{}` (expected webgpu:chromium or webgpu:chromium-compat)",
            args.backend
        )
    })?;
    if args.probe {
        return Ok(super::workers::probe_exit(probe_line(variant)));
    }
    let mut w = WebgpuWorker::start(variant)?;
    super::workers::serve_stdio(&mut w)?;
    // The last stderr line: what was drawn (the runner shows it with `-v`).
    shadowcheck_runner::errln!("{}", w.stats());
    Ok(ExitCode::SUCCESS)
}
