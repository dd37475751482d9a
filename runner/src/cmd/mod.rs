//! One module per subcommand. Each has `Args` (clap) and `main(Args) -> anyhow::Result<ExitCode>`.
pub mod attribute;
pub mod bench;
pub mod consensus;
pub mod explain;
pub mod gen;
// The workers' stdout is their protocol pipe to the runner (a closed one means the runner is gone).
#[allow(clippy::print_stdout)]
pub mod gl_worker;
pub mod gtest;
pub mod merge;
pub mod mock_worker;
pub mod mutants;
pub mod report;
pub mod repro;
pub mod run;
pub mod summarize;
#[allow(clippy::print_stdout)]
pub mod vk_worker;
#[allow(clippy::print_stdout)]
pub mod webgl_worker;
#[allow(clippy::print_stdout)]
pub mod webgpu_worker;
pub mod workers;

/// Writes `text` to stdout. A reader that went away (`shadowcheck explain ... | head`) is not an
/// error: the output was for it, and nothing else depends on it. Other write errors are.
///
/// Every subcommand prints through it ([`outln!`]): `println!` panics on a closed stdout (exit
/// 101), so `main.rs` denies `clippy::print_stdout` outside the workers.
pub fn print_out(text: &str) -> std::io::Result<()> {
    use std::io::Write as _;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        r => r,
    }
}

/// `println!` that does not panic: [`print_out`] of the formatted line (a closed stdout is not an
/// error; another write error is returned).
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cmd::print_out(&format!("{}\n", format_args!($($arg)*)))
    };
}
pub(crate) use outln;
