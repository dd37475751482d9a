//! `shadowcheck mock-worker SCRIPT` (internal): the `mock:` backend's process. See
//! shadowcheck_runner::backend::mock for the script language.

use anyhow::anyhow;
use shadowcheck_runner::backend::mock::{serve, Script};
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// The script, e.g. `fail=lequal,crash=/cube/`.
    #[arg(default_value = "")]
    script: String,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let script = Script::parse(&a.script).map_err(|e| anyhow!(e))?;
    let code = serve(&script, std::io::stdin().lock(), std::io::stdout().lock())?;
    Ok(ExitCode::from(u8::try_from(code).unwrap_or(1)))
}
