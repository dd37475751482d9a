//! The bench as a whole: which measurements run, in which order, with which targets.

use super::cold;
use super::floor::{self, FloorResult};
use super::suite::{self, nearest_2d_fixtures};
use super::{
    cpu, ids, machine::Machine, targets, targets17, BenchReport, Goal, Measurement, Target,
    Unavailable, SCHEMA_VERSION,
};
use shadowcheck_gl::names::{BackendName, Driver};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// What to measure.
#[derive(Debug, Clone)]
pub struct BenchOptions {
    /// Seconds instead of minutes: fewer cases, shorter timings, only `egl:llvmpipe:core` unless
    /// backends are named, the suite rows over the 2D NEAREST fixtures only.
    pub quick: bool,
    /// The GL, Vulkan and WebGPU backends to measure, named as in `run --backend`
    /// (`egl:zink:core`, `vk:lavapipe`, `webgpu:chromium`); empty = all.
    pub backends: Vec<String>,
    /// The fixtures (directories or files; `--fixtures` repeated).
    pub fixtures: Vec<PathBuf>,
    /// The `shadowcheck` executable (suite children).
    pub exe: PathBuf,
}

/// GL backends to measure, before asking the drivers (names that can never work are left out).
pub fn candidates(o: &BenchOptions) -> Vec<String> {
    BackendName::all()
        .into_iter()
        .filter(|b| b.static_unavailability().is_none() && Driver::MESA.contains(&b.driver))
        .map(|b| b.to_string())
        .filter(|n| {
            if o.backends.is_empty() {
                !o.quick || n == "egl:llvmpipe:core"
            } else {
                o.backends.iter().any(|b| b == n)
            }
        })
        .collect()
}

fn floor_size(quick: bool) -> i32 {
    if quick {
        256
    } else {
        1024
    }
}

fn floor_row(id: &str, backend: &str, f: &FloorResult, extra: &str) -> Measurement {
    Measurement::new(
        id,
        Some(backend),
        f.per_s(),
        "lookups/s",
        format!(
            "{} draws of {} fragments in {:.2} s{extra}; {}",
            f.draws,
            f.lookups / f.draws.max(1) as u64,
            f.seconds,
            f.renderer
        ),
    )
}

/// What the bench has found so far: the rows measured and what could not be measured.
#[derive(Default)]
struct Found {
    rows: Vec<Measurement>,
    unavailable: Vec<Unavailable>,
}

impl Found {
    fn missing(&mut self, what: &str, backend: Option<&str>, reason: String) {
        self.unavailable.push(Unavailable {
            what: what.into(),
            backend: backend.map(str::to_string),
            reason,
        });
    }
}

/// Runs every measurement. `progress` gets a line before each step (the library never prints).
pub fn run(o: &BenchOptions, progress: &mut dyn FnMut(&str)) -> BenchReport {
    let mut found = Found::default();
    let load_avg = Machine::describe(None).load_average;

    progress("oracle: loading the default fixtures");
    let set = crate::run::load_cases(&o.fixtures);
    found.rows.extend(cold::density_rows(&set));
    cpu_rows(o, &set, &mut found, progress);

    let e2e_fixtures = e2e_fixtures(o);
    let (available, gl_version) = gl_rows(o, &e2e_fixtures, &mut found, progress);
    llvmpipe_one_thread_rows(o, &available, &mut found, progress);
    let (grid_rows, grid_missing) = super::api_grids::rows(o, progress);
    found.rows.extend(grid_rows);
    found.unavailable.extend(grid_missing);

    let costs = cold::compile_rows(
        o,
        &set,
        &available,
        &mut found.rows,
        &mut found.unavailable,
        progress,
    );
    suite_rows(
        o,
        &set,
        &available,
        &e2e_fixtures,
        &costs,
        &mut found,
        progress,
    );

    let mut machine = Machine::describe(gl_version.as_deref());
    machine.load_average = load_avg;
    BenchReport {
        schema: SCHEMA_VERSION,
        quick: o.quick,
        machine,
        rows: found.rows,
        unavailable: found.unavailable,
    }
}

/// The CPU rows: the oracle's verdicts over the loaded cases, `soft`'s raw lookups.
fn cpu_rows(
    o: &BenchOptions,
    set: &crate::run::CaseSet,
    found: &mut Found,
    progress: &mut dyn FnMut(&str),
) {
    let min = if o.quick {
        Duration::from_millis(150)
    } else {
        Duration::from_secs(2)
    };
    let mut cases: Vec<_> = set.cases.iter().map(|l| l.case.clone()).collect();
    if o.quick {
        cases = cases.into_iter().step_by(10).collect();
    }
    if cases.is_empty() {
        found.missing(
            "oracle",
            None,
            format!("no case loaded from {}", display_paths(&o.fixtures)),
        );
    } else {
        progress(&format!("oracle: {} cases, one thread", cases.len()));
        found.rows.extend(cpu::oracle_rows(&cases, min));
    }
    drop(cases);

    progress("soft: raw lookups, one thread");
    match cpu::soft_rows(if o.quick { 1 << 16 } else { 1 << 20 }, min) {
        Ok(r) => found.rows.extend(r),
        Err(e) => found.missing("soft", None, e),
    }
}

fn floor_min(quick: bool) -> Duration {
    if quick {
        Duration::from_millis(100)
    } else {
        Duration::from_secs(1)
    }
}

/// The fixtures of the end-to-end rows: the 2D NEAREST ones (quick: gl46's alone, if present).
fn e2e_fixtures(o: &BenchOptions) -> Vec<PathBuf> {
    let all_2d: Vec<PathBuf> = o
        .fixtures
        .iter()
        .flat_map(|f| nearest_2d_fixtures(f))
        .collect();
    match o
        .fixtures
        .iter()
        .map(|f| f.join("gl46/2d/nearest.json"))
        .find(|p| p.is_file())
    {
        Some(one) if o.quick => vec![one],
        _ => all_2d,
    }
}

/// Per GL backend that starts: its bare-draw floor and the end-to-end rows. Returns the backends
/// that started and the first one's GL version.
fn gl_rows(
    o: &BenchOptions,
    e2e_fixtures: &[PathBuf],
    found: &mut Found,
    progress: &mut dyn FnMut(&str),
) -> (Vec<String>, Option<String>) {
    let mut available: Vec<String> = Vec::new();
    let mut gl_version = None;
    for name in candidates(o) {
        progress(&format!("{name}: bare-draw floor"));
        let f = floor::run_child(&name, floor_size(o.quick), floor_min(o.quick), &[]);
        if !f.ok {
            found.missing("gl", Some(&name), f.error.unwrap_or_default());
            continue;
        }
        gl_version.get_or_insert_with(|| f.version.clone());
        available.push(name.clone());
        let floor_per_s = f.per_s();
        found.rows.push(floor_row(ids::GL_FLOOR, &name, &f, ""));
        progress(&format!("{name}: end to end over the 2D NEAREST fixtures"));
        match suite::e2e(&name, e2e_fixtures) {
            Ok(e) => found.rows.extend(e2e_rows(&name, &e, floor_per_s)),
            Err(e) => found.missing("gl end to end", Some(&name), e),
        }
    }
    (available, gl_version)
}

/// The end-to-end rows of one GL backend: cold, steady, warm, per check, cached, over the floor.
fn e2e_rows(name: &str, e: &suite::E2e, floor_per_s: f64) -> Vec<Measurement> {
    let mut rows = Vec::new();
    let detail = format!(
        "{} verified tests ({} skipped) of {} cases in {:.2} s: load {:.2} s, worker start {:.2} s, run {:.2} s (backend {:.2} s, verdicts {:.2} s)",
        e.verified, e.skipped, e.cases_loaded, e.total_s(), e.load_s, e.open_s, e.run_s, e.backend_s, e.verdict_s
    );
    let mut r = Measurement::new(ids::GL_E2E, Some(name), e.per_s(), "cases/s", detail);
    if name.contains(":llvmpipe:") {
        r = r.with_target(Target::new(
            Goal::AtLeast,
            targets::LLVMPIPE_E2E_PER_S,
            "throughput goal (llvmpipe, 2D NEAREST)",
        ));
    }
    rows.push(r);
    rows.push(Measurement::new(
        ids::GL_E2E_STEADY,
        Some(name),
        e.steady_per_s(),
        "cases/s",
        "verified tests / run time (no fixture load, no worker start)".into(),
    ));
    rows.push(Measurement::new(
        ids::GL_E2E_WARM,
        Some(name),
        e.warm_per_s(),
        "cases/s",
        format!("the same cases again on the same worker ({:.3} s, the median of {} passes): shader variants already compiled", e.warm_run_s, e.warm_passes),
    ));
    let per_check = Measurement::new(
        ids::HARNESS_PER_CHECK,
        Some(name),
        e.warm_run_s / e.checks as f64 * 1e6,
        "us/check",
        format!("the warm pass ({:.3} s for {} checks: {} tests and their sweep points; the median of {} passes): worker I/O, texture upload, draw, read-back and verdict once the variants exist", e.warm_run_s, e.checks, e.verified, e.warm_passes),
    );
    rows.push(if name.contains(":llvmpipe:") {
        per_check.with_target(Target::new(
            Goal::AtMost,
            targets17::HARNESS_US_PER_CHECK,
            "cold-run goal (llvmpipe)",
        ))
    } else {
        per_check
    });
    rows.push(Measurement::new(
        ids::GL_E2E_CACHED,
        Some(name),
        e.cached_per_s(),
        "cases/s",
        format!("a new worker with the on-disk shader cache the cold pass filled ({:.2} s incl. worker start; the cold pass starts from an empty cache)", e.cached_s),
    ));
    rows.push(
        Measurement::new(
            ids::GL_RATIO,
            Some(name),
            e.per_s() / floor_per_s,
            "x",
            format!(
                "end to end {:.3e} cases/s over floor {:.3e} lookups/s",
                e.per_s(),
                floor_per_s
            ),
        )
        .with_target(Target::new(
            Goal::AtLeast,
            targets::E2E_OVER_FLOOR,
            "throughput goal",
        )),
    );
    rows
}

/// llvmpipe's single-thread lookup rate: the bar for `soft` (its target is set on soft's row).
fn llvmpipe_one_thread_rows(
    o: &BenchOptions,
    available: &[String],
    found: &mut Found,
    progress: &mut dyn FnMut(&str),
) {
    if !available.iter().any(|n| n == "egl:llvmpipe:core") {
        found.missing(
            "soft target",
            None,
            "egl:llvmpipe:core is not available (or filtered out): no single-thread llvmpipe rate to compare with".into(),
        );
        return;
    }
    progress("egl:llvmpipe:core: bare-draw floor with LP_NUM_THREADS=1");
    let f = floor::run_child(
        "egl:llvmpipe:core",
        floor_size(o.quick),
        floor_min(o.quick),
        &[("LP_NUM_THREADS", "1")],
    );
    if !f.ok {
        found.missing(
            "gl floor, 1 thread",
            Some("egl:llvmpipe:core"),
            f.error.unwrap_or_default(),
        );
        return;
    }
    let one = f.per_s();
    found.rows.push(floor_row(
        ids::GL_FLOOR_1T,
        "egl:llvmpipe:core",
        &f,
        ", LP_NUM_THREADS=1",
    ));
    if let Some(s) = found.rows.iter_mut().find(|r| r.id == ids::SOFT_LOOKUPS) {
        *s = s.clone().with_target(Target::new(
            Goal::AtLeast,
            one,
            "llvmpipe floor, LP_NUM_THREADS=1",
        ));
    }
}

/// The default suite (quick: the 2D NEAREST fixtures): soft alone, then every Mesa backend in
/// one run, cold, with the cache it filled, and cold again with --fast-compile.
fn suite_rows(
    o: &BenchOptions,
    set: &crate::run::CaseSet,
    available: &[String],
    e2e_fixtures: &[PathBuf],
    costs: &[cold::DriverCost],
    found: &mut Found,
    progress: &mut dyn FnMut(&str),
) {
    let suite_fixtures = if o.quick {
        e2e_fixtures.to_vec()
    } else {
        o.fixtures.clone()
    };
    let what = if o.quick {
        "2D NEAREST fixtures (quick)"
    } else {
        "default fixtures"
    };
    let out_root = std::env::temp_dir().join(format!("shadowcheck-bench-{}", std::process::id()));
    soft_suite_rows(o, &suite_fixtures, what, &out_root, found, progress);
    let mesa = cold::Mesa {
        backends: available,
        fixtures: &suite_fixtures,
        what,
        out_root: &out_root,
    };
    cold::suite_rows(
        o,
        set,
        &mesa,
        costs,
        &mut found.rows,
        &mut found.unavailable,
        progress,
    );
    if !o.quick && available.iter().any(|b| b == "egl:llvmpipe:core") {
        progress("egl:llvmpipe:core: gl46 fixtures, empty shader cache (states per cache entry)");
        let root = o
            .fixtures
            .first()
            .map(PathBuf::as_path)
            .unwrap_or(Path::new("cases/fixtures"));
        match super::grouping::cache_entry_row(&o.exe, root, &out_root.join("gl46-entries")) {
            Ok(row) => found.rows.push(row),
            Err(e) => found.unavailable.push(Unavailable {
                what: "states per cache entry".into(),
                backend: Some("egl:llvmpipe:core".into()),
                reason: e,
            }),
        }
    }
    let _ = std::fs::remove_dir_all(&out_root);
}

/// The suite on `soft`, twice: wall time of each run and the larger peak RSS.
fn soft_suite_rows(
    o: &BenchOptions,
    suite_fixtures: &[PathBuf],
    what: &str,
    out_root: &Path,
    found: &mut Found,
    progress: &mut dyn FnMut(&str),
) {
    progress("suite: soft, twice");
    let soft = ["soft".to_string()];
    let (s, c) = match (
        suite::suite(&o.exe, &soft, suite_fixtures, &out_root.join("soft"), &[]),
        suite::suite(&o.exe, &soft, suite_fixtures, &out_root.join("soft-2"), &[]),
    ) {
        (Ok(s), Ok(c)) => (s, c),
        (Err(e), _) | (_, Err(e)) => return found.missing("suite", Some("soft"), e),
    };
    let detail = format!(
        "`shadowcheck run` over the {what}, backend soft, exit {}",
        s.exit_code
    );
    found.rows.push(Measurement::new(
        ids::SUITE_WALL,
        Some("soft"),
        s.wall_s,
        "s",
        detail.clone(),
    ));
    found.rows.push(Measurement::new(
        ids::SUITE_WALL_CACHED,
        Some("soft"),
        c.wall_s,
        "s",
        format!("{detail}; a second run"),
    ));
    found.rows.push(
        Measurement::new(
            ids::SUITE_RSS,
            Some("soft"),
            s.peak_rss_mib.max(c.peak_rss_mib),
            "MiB",
            format!("largest process of either run, wait4 ru_maxrss; {detail}"),
        )
        .with_target(Target::new(
            Goal::AtMost,
            targets::PEAK_RSS_MIB,
            "throughput goal",
        )),
    );
}

/// `a, b` for messages naming several fixture paths.
fn display_paths(paths: &[PathBuf]) -> String {
    let v: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    v.join(", ")
}
