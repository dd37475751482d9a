//! `shadowcheck gl-worker --backend egl:llvmpipe:core`: one GL context speaking runner/PROTOCOL.md on
//! stdin/stdout. Started by the runner with the driver env vars already set (`backend::gl::worker_command`).
use shadowcheck_gl::{worker, BackendName};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// Backend name: egl|osmesa : llvmpipe|softpipe|zink : core|compat|es3|es2.
    #[arg(long)]
    backend: String,
    /// Only create the context and print `ok <name>`, `nothing: <reason>` (it starts but exposes
    /// none of its specs) or `unavailable: <reason>`, then exit.
    #[arg(long)]
    probe: bool,
}

pub fn main(args: Args) -> anyhow::Result<ExitCode> {
    let name: BackendName = args.backend.parse()?;
    if args.probe {
        return Ok(super::workers::probe_exit(worker::probe_line(name)));
    }
    let mut w = worker::Worker::start(name)?;
    super::workers::serve_stdio(&mut w)?;
    // The last stderr line: what was compiled and drawn (the runner shows it with `-v`; the
    // bench reads it).
    shadowcheck_runner::errln!("{}", w.stats());
    Ok(ExitCode::SUCCESS)
}
