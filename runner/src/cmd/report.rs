//! `shadowcheck report RESULTS... -o DIR`: a self-contained HTML report (DIR/index.html) from the
//! result files (results.jsonl, report.json) or `shadowcheck run --out` directories of one or
//! more runs, merged. Exit 0 when written, 96 on bad input (as every subcommand).

use anyhow::Context;
use shadowcheck_runner::report::html::{
    self, geometry::Geometry, load, matrix::DetailCaps, PageOptions,
};
use std::path::PathBuf;
use std::process::ExitCode;

/// The fixtures used for the heatmaps when neither --fixtures nor the runs name any that exist.
const DEFAULT_FIXTURES: &str = "cases/fixtures";

#[derive(clap::Args)]
pub struct Args {
    /// Result files (results.jsonl or report.json) or `shadowcheck run --out` directories; merged,
    /// a later input's record of the same (backend, test) replacing an earlier one.
    #[arg(required = true, value_name = "RESULTS")]
    inputs: Vec<PathBuf>,
    /// Output directory; the report is DIR/index.html.
    #[arg(short = 'o', long, value_name = "DIR")]
    out: PathBuf,
    /// Fixture file or directory the runs used (repeatable), to place every test on the heatmaps.
    /// Default: the fixtures the runs name, else cases/fixtures.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Dumps shown per matrix cell (the rest are counted).
    #[arg(long, value_name = "N", default_value_t = 50)]
    max_details: usize,
    /// Dumps shown in the whole report (shared out among the cells, at least 3 each).
    #[arg(long, value_name = "N", default_value_t = 600)]
    max_details_total: usize,
    /// Tests drawn per acceptance plot (warnings and failures first).
    #[arg(long, value_name = "N", default_value_t = 48)]
    max_plot_points: usize,
    /// Title of the page. Default: made from what the inputs hold (the backends by kind, the Mesa
    /// versions their implementations name).
    #[arg(long)]
    title: Option<String>,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    // `report out/* -o out/html` a second time: out/html is among the inputs; it is skipped.
    let out = std::fs::canonicalize(&a.out).ok();
    let inputs: Vec<PathBuf> = a
        .inputs
        .iter()
        .filter(|p| {
            let same = out.is_some() && std::fs::canonicalize(p).ok() == out;
            if same {
                shadowcheck_runner::errln!(
                    "shadowcheck report: skipping input {}: it is the output directory",
                    p.display()
                );
            }
            !same
        })
        .cloned()
        .collect();
    if inputs.is_empty() {
        anyhow::bail!("no inputs left once the output directory is left out");
    }
    let input = load::read_inputs(&inputs)?;
    for why in &input.unfinished {
        shadowcheck_runner::errln!(
            "shadowcheck report: warning: a partial run: {why}; the page shows the tests it holds"
        );
    }
    let fixtures: Vec<PathBuf> = if !a.fixtures.is_empty() {
        a.fixtures.clone()
    } else {
        let named: Vec<PathBuf> = input
            .fixtures
            .iter()
            .map(PathBuf::from)
            .filter(|p| p.exists())
            .collect();
        if named.is_empty() {
            vec![PathBuf::from(DEFAULT_FIXTURES)]
        } else {
            named
        }
    };
    let geo = Geometry::from_fixtures(&fixtures, &input.results);
    let opts = PageOptions {
        title: a.title.clone(),
        details: DetailCaps {
            per_cell: a.max_details,
            total: a.max_details_total,
        },
        plot_points: a.max_plot_points.max(1),
    };
    let page = html::render(&input, &geo, &opts);
    std::fs::create_dir_all(&a.out).with_context(|| format!("creating {}", a.out.display()))?;
    let path = a.out.join(html::INDEX);
    shadowcheck_runner::report::atomic::write(&path, page.as_bytes())
        .with_context(|| format!("writing {}", path.display()))?;
    super::outln!(
        "wrote {} ({} KiB): {} tests on {} backends ({}) from {} input(s); heatmap geometry from {}",
        path.display(),
        page.len().div_ceil(1024),
        input.results.len(),
        input.backends.len(),
        input.backends.join(", "),
        input.sources.len(),
        if geo.fixtures.is_empty() { "the records' footprints only (no fixtures found)".to_string() } else { geo.fixtures.join(", ") }
    )?;
    Ok(ExitCode::SUCCESS)
}
