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
        let (ok, line) = probe_line(driver);
        println!("{line}");
        return Ok(if ok {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let mut w = VkWorker::start(driver)?;
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    shadowcheck_plan::serve::serve(
        &mut w,
        std::io::BufReader::with_capacity(1 << 16, stdin),
        std::io::BufWriter::new(stdout.lock()),
    )?;
    // The last stderr line: what was compiled and drawn (the runner shows it with `-v`).
    shadowcheck_runner::errln!("{}", w.stats());
    Ok(ExitCode::SUCCESS)
}
