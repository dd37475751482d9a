//! `shadowcheck webgl-worker`: headless Chromium with a WebGL 2.0 page, speaking runner/PROTOCOL.md
//! on stdin/stdout (the `webgl:chromium` backend's child; `backend::webgl::worker_command`).
use shadowcheck_plan::serve::serve;
use shadowcheck_webgl::worker::{probe_line, WebglWorker};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Only start the browser and the page and print `ok <name>` or `unavailable: <reason>`.
    #[arg(long)]
    probe: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    if args.probe {
        let (ok, line) = probe_line();
        println!("{line}");
        return Ok(if ok {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
    }
    let mut w = WebglWorker::start()?;
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    serve(
        &mut w,
        std::io::BufReader::with_capacity(1 << 16, stdin),
        std::io::BufWriter::new(stdout.lock()),
    )?;
    Ok(ExitCode::SUCCESS)
}
