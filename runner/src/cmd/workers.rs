//! The hidden worker subcommands: the child processes of the backend kinds whose table entry
//! names a [`Worker`](shadowcheck_runner::backend::kinds::Worker) (`shadowcheck_runner::backend::kinds::KINDS`).
//! Each subcommand's name and description come from the table; the variant says which code runs.
use super::{gl_worker, mock_worker, vk_worker, webgl_worker, webgpu_worker};
use shadowcheck_runner::backend::kinds::{
    GL_WORKER, MOCK_WORKER, VK_WORKER, WEBGL_WORKER, WEBGPU_WORKER,
};
use std::process::ExitCode;

#[derive(clap::Subcommand)]
pub enum WorkerCommand {
    #[command(name = GL_WORKER.subcommand, about = GL_WORKER.about, hide = true)]
    Gl(gl_worker::Args),
    #[command(name = WEBGL_WORKER.subcommand, about = WEBGL_WORKER.about, hide = true)]
    Webgl(webgl_worker::Args),
    #[command(name = VK_WORKER.subcommand, about = VK_WORKER.about, hide = true)]
    Vk(vk_worker::Args),
    #[command(name = WEBGPU_WORKER.subcommand, about = WEBGPU_WORKER.about, hide = true)]
    Webgpu(webgpu_worker::Args),
    #[command(name = MOCK_WORKER.subcommand, about = MOCK_WORKER.about, hide = true)]
    Mock(mock_worker::Args),
}

impl WorkerCommand {
    pub fn main(self) -> anyhow::Result<ExitCode> {
        match self {
            WorkerCommand::Gl(a) => gl_worker::main(a),
            WorkerCommand::Webgl(a) => webgl_worker::main(a),
            WorkerCommand::Vk(a) => vk_worker::main(a),
            WorkerCommand::Webgpu(a) => webgpu_worker::main(a),
            WorkerCommand::Mock(a) => mock_worker::main(a),
        }
    }
}

/// A worker's `--probe` answer: its line on stdout, exit 0 when the implementation starts here,
/// else 1. (The workers' stdout is their protocol pipe to the runner, hence `println!`.)
#[allow(clippy::print_stdout)]
pub fn probe_exit((ok, line): (bool, String)) -> ExitCode {
    println!("{line}");
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// Serves runner/PROTOCOL.md with `w` on stdin/stdout until the runner closes stdin.
pub fn serve_stdio(w: &mut impl shadowcheck_plan::serve::Serve) -> std::io::Result<()> {
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    shadowcheck_plan::serve::serve(
        w,
        std::io::BufReader::with_capacity(1 << 16, stdin),
        std::io::BufWriter::new(stdout.lock()),
    )
}
