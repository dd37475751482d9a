//! `shadowcheck vk-worker --backend vk:lavapipe`: one Vulkan device speaking runner/PROTOCOL.md on
//! stdin/stdout. Started by the runner with the loader's `VK_ICD_FILENAMES` already set
//! (`backend::vk::worker_command`).
use shadowcheck_vk::worker::{probe_line, VkWorker};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Backend name: vk:lavapipe, vk:swiftshader or vk:native.
    #[arg(long)]
    backend: String,
    /// Only open the device and print `ok <name>` or `unavailable: <reason>`, then exit.
    #[arg(long)]
    probe: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    let driver = shadowcheck_vk::parse_backend(&args.backend)?;
    if args.probe {
        return Ok(super::workers::probe_exit(probe_line(driver)));
    }
    let mut w = VkWorker::start(driver)?;
    super::workers::serve_stdio(&mut w)?;
    // The last stderr line: what was compiled and drawn (the runner shows it with `-v`).
    shadowcheck_runner::errln!("{}", w.stats());
    Ok(ExitCode::SUCCESS)
}
