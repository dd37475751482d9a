//! `shadowcheck bench`: throughput of the oracle, the soft implementation and each GL backend (end
//! to end against the bare-draw floor), and wall time / peak memory of the default suite per driver.
//! Targets are goals reported against, never assertions. See reports/BENCH.md.
use anyhow::Context;
use shadowcheck_gl::BackendName;
use shadowcheck_runner::bench::{self, markdown, run::BenchOptions};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

#[derive(clap::Args)]
pub struct Args {
    /// A few seconds instead of minutes (CI smoke): fewer cases, only egl:llvmpipe:core unless
    /// --backend is given, suite rows over the 2D NEAREST fixtures.
    #[arg(long)]
    quick: bool,
    /// Print the report as JSON on stdout instead of the table.
    #[arg(long)]
    json: bool,
    /// GL, Vulkan or WebGPU backend to measure (repeatable), named as in `run --backend`:
    /// `egl:llvmpipe:core`, `vk:lavapipe`, `webgpu:chromium`. Default: every GL backend found
    /// (with --quick: egl:llvmpipe:core) and vk:lavapipe, vk:swiftshader, webgpu:chromium where
    /// they start.
    #[arg(long = "backend", short = 'b', value_name = "B")]
    backends: Vec<String>,
    /// Fixture file or directory (repeatable). Default: cases/fixtures.
    #[arg(long, value_name = "PATH", default_value = super::run::DEFAULT_FIXTURES)]
    fixtures: Vec<PathBuf>,
    /// Also write the Markdown report (table + machine) to FILE, e.g. reports/BENCH.md; only the
    /// generated block of an existing file is replaced.
    #[arg(long, value_name = "FILE")]
    markdown: Option<PathBuf>,
    /// Render a report written earlier by `--json` (table, `--markdown`) instead of measuring.
    #[arg(long, value_name = "FILE")]
    from_json: Option<PathBuf>,
    /// (internal) Measure the bare-draw floor of this GL backend in this process and print JSON.
    #[arg(long, hide = true, value_name = "NAME")]
    floor_child: Option<String>,
    /// (internal) Side of the floor child's square target, in pixels.
    #[arg(long, hide = true, default_value_t = 1024)]
    floor_size: i32,
    /// (internal) Seconds the floor child measures for.
    #[arg(long, hide = true, default_value_t = 1.0)]
    floor_seconds: f64,
}

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    if let Some(name) = &a.floor_child {
        let name: BackendName = name.parse()?;
        let r = bench::floor::measure(
            name,
            a.floor_size.clamp(1, 4096),
            Duration::from_secs_f64(a.floor_seconds.clamp(0.0, 600.0)),
        );
        super::outln!("{}", serde_json::to_string(&r)?)?;
        return Ok(ExitCode::SUCCESS);
    }
    for b in &a.backends {
        if bench::api_grids::is_measured(b) {
            continue;
        }
        b.parse::<BackendName>().with_context(|| {
            format!(
                "--backend {b}: bench measures GL backends, named as in `run --backend` (egl:llvmpipe:core, osmesa:softpipe:compat, ...), and {}",
                bench::api_grids::names().join(", ")
            )
        })?;
    }
    let exe = std::env::current_exe().context("locating the shadowcheck executable")?;
    let opts = BenchOptions {
        quick: a.quick,
        backends: a.backends.clone(),
        fixtures: a.fixtures.clone(),
        exe,
    };
    let mut progress = |m: &str| shadowcheck_runner::errln!("bench: {m}");
    let report = match &a.from_json {
        Some(p) => {
            let text =
                std::fs::read_to_string(p).with_context(|| format!("reading {}", p.display()))?;
            serde_json::from_str(&text).with_context(|| {
                format!("{} is not a `shadowcheck bench --json` report", p.display())
            })?
        }
        None => bench::run::run(&opts, &mut progress),
    };
    if let Some(path) = &a.markdown {
        let old = std::fs::read_to_string(path).ok();
        shadowcheck_runner::report::atomic::write(
            path,
            markdown::document(&report, old.as_deref()).as_bytes(),
        )
        .with_context(|| format!("writing {}", path.display()))?;
        shadowcheck_runner::errln!("bench: wrote {}", path.display());
    }
    if a.json {
        super::print_out(&format!("{}\n", serde_json::to_string_pretty(&report)?))?;
    } else {
        super::print_out(&markdown::text(&report))?;
    }
    Ok(ExitCode::SUCCESS)
}
