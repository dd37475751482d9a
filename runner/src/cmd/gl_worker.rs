//! `shadowcheck gl_worker` (being built).
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {}

pub fn main(_args: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`gl_worker` is not built yet")
}
