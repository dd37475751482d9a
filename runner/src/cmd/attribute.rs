//! `shadowcheck attribute RUN_DIR...`: which layer broke each failure of a layered backend (zink,
//! WebGL on ANGLE), from the answers of the driver under it in the same runs: a Vulkan driver's to
//! the same lookups, or, under ANGLE's OpenGL ES back end, `egl:llvmpipe:es3`'s to the same tests
//! (the rules are `shadowcheck_runner::attribute`). Markdown on stdout, or JSON with `--json`;
//! `--markdown FILE` also writes the Markdown to FILE.
//!
//! Exit 0 when the attribution was made (with or without failures to attribute); 96 on bad input
//! (a run directory without a readable results.jsonl, fixtures that do not load, an output that
//! cannot be written).

use anyhow::Context;
use shadowcheck_runner::attribute;
use shadowcheck_runner::consensus;
use shadowcheck_runner::records::{exit, Results};
use std::collections::HashMap;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(clap::Args)]
pub struct Args {
    /// `shadowcheck run --out` directories (each holding results.jsonl), or results.jsonl files:
    /// together they must hold the layered backend's results and the lower driver's (e.g.
    /// `run -b egl:zink:core -b vk:lavapipe`, `run -b webgl:chromium-gles -b egl:llvmpipe:es3`);
    /// a later input's record of the same (backend, test) replaces an earlier.
    #[arg(required = true, value_name = "RUN_DIR")]
    runs: Vec<PathBuf>,
    /// The fixtures holding the runs' cases, GL and Vulkan (file or directory, repeatable).
    /// Default: cases/fixtures.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Also write the Vulkan counterparts the fixtures lack (the "no equivalent" failures whose
    /// lookup Vulkan defines) as a fixture file: run it on the Vulkan driver, then attribute
    /// again with `--fixtures cases/fixtures --fixtures FILE`.
    #[arg(long, value_name = "FILE")]
    counterparts: Option<PathBuf>,
    /// Print the attribution as JSON on stdout instead of the Markdown.
    #[arg(long)]
    json: bool,
    /// Also write the Markdown to FILE.
    #[arg(long, value_name = "FILE")]
    markdown: Option<PathBuf>,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let mut all = Results::default();
    for p in &a.runs {
        let run = consensus::read_run(p).with_context(|| format!("reading run {}", p.display()))?;
        if let Some(why) = run.results.unfinished() {
            shadowcheck_runner::errln!(
                "shadowcheck attribute: warning: {}: the run did not finish, so its missing tests are not attributed: {why}",
                run.path
            );
        }
        for r in run.results.results {
            all.insert(r);
        }
    }
    let mut cases = HashMap::new();
    let roots = if a.fixtures.is_empty() {
        vec![PathBuf::from(super::run::DEFAULT_FIXTURES)]
    } else {
        a.fixtures.clone()
    };
    for root in &roots {
        let files = shadowcheck_cases::fixtures::load_path(root)
            .with_context(|| format!("loading fixtures {}", root.display()))?;
        for (_, f) in files {
            for c in f.cases {
                cases.insert(c.id.clone(), c);
            }
        }
    }
    let rows = attribute::attribute(&all, &cases);
    if let Some(path) = &a.counterparts {
        let missing = attribute::counterparts_to_run(&all, &cases);
        let file = shadowcheck_cases::fixtures::FixtureFile {
            schema_version: shadowcheck_model::SCHEMA_VERSION,
            generator: shadowcheck_cases::grids::GENERATOR.to_string(),
            grid: "attribute-counterparts".into(),
            seed: 0,
            cases: missing,
            state_cases: vec![],
        };
        let text = shadowcheck_cases::fixtures::to_string(&file)
            .context("serializing the counterparts")?;
        shadowcheck_runner::report::atomic::write(path, text.as_bytes())
            .with_context(|| format!("writing {}", path.display()))?;
        shadowcheck_runner::errln!(
            "shadowcheck attribute: {} Vulkan counterparts the fixtures lack written to {}: run them on the Vulkan driver (`shadowcheck run -b vk:lavapipe --fixtures {}`), then attribute again with that file among --fixtures",
            file.cases.len(),
            path.display(),
            path.display()
        );
    }
    let md = attribute::markdown(&rows);
    if let Some(path) = &a.markdown {
        shadowcheck_runner::report::atomic::write(path, md.as_bytes())
            .with_context(|| format!("writing {}", path.display()))?;
    }
    let text = if a.json {
        serde_json::to_string_pretty(&rows).context("serializing the attribution")? + "\n"
    } else {
        md
    };
    super::print_out(&text).context("writing to stdout")?;
    Ok(ExitCode::from(exit::SUCCESS))
}
