//! `shadowcheck consensus RUN_DIR...`: the oracle's review queue (the logic and its rules are
//! `shadowcheck_runner::consensus`). Markdown on stdout, or JSON with `--json`; `--markdown FILE`
//! also writes the Markdown to FILE (the flag name `bench` and `mutants` use: `-o` names a
//! directory wherever it exists).
//!
//! Exit 0 when the queue was built, empty or not (an entry is a question for the oracle's
//! authors, not a failure of any run); 96 on bad input (a run directory without a readable
//! results.jsonl, a line that does not parse, an output that cannot be written).

use anyhow::Context;
use shadowcheck_runner::consensus::{self, Options, DEFAULT_MIN_UNITS};
use shadowcheck_runner::records::exit;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// `shadowcheck run --out` directories (each holding results.jsonl, one or more backends), or
    /// results.jsonl files; a later input's record of the same (backend, test) replaces an earlier.
    #[arg(required = true, value_name = "RUN_DIR")]
    runs: Vec<PathBuf>,
    /// Independent texture units that must return the same rejected answer.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MIN_UNITS as u32,
          value_parser = clap::value_parser!(u32).range(1..))]
    min_units: u32,
    /// Print the queue as JSON on stdout instead of the Markdown.
    #[arg(long)]
    json: bool,
    /// Also write the Markdown queue to FILE.
    #[arg(long, value_name = "FILE")]
    markdown: Option<PathBuf>,
    /// Where to look up the citations of a test whose records carry none and name no fixture
    /// file.
    #[arg(long, value_name = "PATH", default_value = super::run::DEFAULT_FIXTURES)]
    fixtures: PathBuf,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let mut runs = vec![];
    for p in &a.runs {
        let run = consensus::read_run(p).with_context(|| format!("reading run {}", p.display()))?;
        // A partial run still has answers worth a look; its missing tests are not on the queue.
        if let Some(why) = run.results.unfinished() {
            shadowcheck_runner::errln!(
                "shadowcheck consensus: warning: {}: the run did not finish, so its missing tests are not on the queue: {why}",
                run.path
            );
        }
        runs.push(run);
    }
    let q = consensus::queue(
        &runs,
        &Options {
            min_units: a.min_units as usize,
            default_fixtures: a.fixtures.clone(),
        },
    );
    let md = consensus::markdown(&q);
    if let Some(path) = &a.markdown {
        shadowcheck_runner::report::atomic::write(path, md.as_bytes())
            .with_context(|| format!("writing {}", path.display()))?;
    }
    let text = if a.json {
        serde_json::to_string_pretty(&q).context("serializing the queue")? + "\n"
    } else {
        md
    };
    super::print_out(&text).context("writing to stdout")?;
    Ok(ExitCode::from(exit::SUCCESS))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_run_directory_is_an_error_so_the_exit_is_96() {
        let missing = std::env::temp_dir().join(format!(
            "shadowcheck-consensus-cmd-{}-no-such-run",
            std::process::id()
        ));
        let r = main(Args {
            runs: vec![missing],
            min_units: 3,
            json: false,
            markdown: None,
            fixtures: PathBuf::from("cases/fixtures"),
        });
        // main.rs turns every error of a subcommand into exit::SETUP (96).
        let e = r.err().map(|e| format!("{e:#}")).unwrap_or_default();
        assert!(
            e.contains("reading run") && e.contains("no-such-run"),
            "{e}"
        );
    }
}
