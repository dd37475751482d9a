//! The cold-run measurements: checks per compiled state, the compile time of one shader
//! variant, the default suite over every Mesa backend in one run (cold, cached, `--fast-compile`)
//! and the floor of the compilations a cold run cannot avoid.

use super::run::BenchOptions;
use super::suite;
use super::{ids, machine::Machine, targets, targets17, Goal, Measurement, Target, Unavailable};
use crate::run::CaseSet;
use shadowcheck_gl::names::{BackendName, Driver};
use std::path::{Path, PathBuf};

/// Checks per compiled sampler state on each API path of the fixtures (cases/README.md prints the
/// same table): tests over distinct states, against [`targets17::CHECKS_PER_STATE`].
pub fn density_rows(set: &CaseSet) -> Vec<Measurement> {
    let cov = shadowcheck_cases::coverage::Coverage::of(set.cases.iter().map(|l| &l.case));
    cov.per_path
        .iter()
        .map(|(api, d)| {
            let states = d.states.len().max(1);
            Measurement::new(
                ids::CHECKS_PER_STATE,
                Some(api.key()),
                d.checks as f64 / states as f64,
                "checks/state",
                format!(
                    "{} checks ({} tests with their sweeps) over {} distinct (target, format, compare mode/func, filters, wraps, depth modes)",
                    d.checks,
                    d.tests,
                    d.states.len()
                ),
            )
            .with_target(Target::new(
                Goal::AtLeast,
                targets17::CHECKS_PER_STATE,
                "cold-run goal",
            ))
        })
        .collect()
}

/// Measures the compile time of one variant on each compiling driver's `egl:<driver>:core`
/// backend that is available; returns the per-variant seconds per driver.
pub fn compile_rows(
    o: &BenchOptions,
    set: &CaseSet,
    available: &[String],
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) -> Vec<(Driver, f64)> {
    let mut per_variant: Vec<(Driver, f64)> = Vec::new();
    for d in [Driver::Llvmpipe, Driver::Zink] {
        let name = format!("egl:{}:core", d.key());
        if !available.contains(&name) {
            continue;
        }
        let stride = if o.quick { 64 } else { 8 };
        progress(&format!(
            "{name}: compile time per variant (every {stride}th state, empty shader cache)"
        ));
        match suite::compile_cost(&name, set, stride) {
            Ok(c) => {
                per_variant.push((d, c.per_variant_s()));
                let detail = format!(
                    "one case per compiled state, {} states (every {stride}th of the fixtures): cold {:.2} s, same cases warm {:.2} s; (cold - warm) / states",
                    c.states, c.cold_s, c.warm_s
                );
                rows.push(Measurement::new(
                    ids::COMPILE_PER_VARIANT,
                    Some(&name),
                    c.per_variant_s() * 1e3,
                    "ms",
                    detail,
                ));
            }
            Err(e) => unavailable.push(Unavailable {
                what: "compile time per variant".into(),
                backend: Some(name),
                reason: e,
            }),
        }
    }
    per_variant
}

/// The Mesa backends of a suite measurement and where its runs go.
pub struct Mesa<'a> {
    pub backends: &'a [String],
    pub fixtures: &'a [PathBuf],
    /// "default fixtures" or the quick subset, for the rows' details.
    pub what: &'a str,
    pub out_root: &'a Path,
}

/// Every Mesa backend in one `shadowcheck run`: cold, with the cache it filled, cold with
/// `--fast-compile`; then the floor (compiled states or cache entries x compile time) and the
/// cold run over it.
pub fn suite_rows(
    o: &BenchOptions,
    set: &CaseSet,
    m: &Mesa<'_>,
    per_variant: &[(Driver, f64)],
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) {
    if m.backends.is_empty() {
        return;
    }
    let cold = mesa_suite_runs(o, m, rows, unavailable, progress);
    // The floor: every backend's compiled states x its driver's compile time, over the cores.
    if per_variant.is_empty() {
        return;
    }
    let cores = Machine::describe(None).nproc.max(1) as f64;
    let heavy = states_floor_row(o, set, m, per_variant, cores, rows);
    cache_floor_rows(per_variant, cores, heavy, &cold, rows);
}

/// What the cold suite run left for the floor rows.
struct ColdRun {
    /// Its wall time, when it ran.
    wall_s: Option<f64>,
    /// The entries it wrote to its empty shader cache.
    cache_entries: usize,
}

/// The label of the Mesa suite rows and of their shader caches.
const MESA: &str = "mesa";

/// The three runs of the suite over every Mesa backend: cold, cached (the cold run's cache),
/// cold with `--fast-compile` (a fresh cache).
fn mesa_suite_runs(
    o: &BenchOptions,
    m: &Mesa<'_>,
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) -> ColdRun {
    let drivers: Vec<Driver> = Driver::MESA
        .iter()
        .copied()
        .filter(|d| {
            m.backends
                .iter()
                .any(|n| n.split(':').nth(1) == Some(d.key()))
        })
        .collect();
    let every = drivers.len() == Driver::MESA.len() && !o.quick;
    let mut cold = ColdRun {
        wall_s: None,
        cache_entries: 0,
    };
    // Cold then cached share one cache; the --fast-compile cold run gets a fresh one.
    let mut cache = None;
    for (id, extra, cached) in [
        (ids::MESA_COLD, &[][..], false),
        (ids::MESA_CACHED, &[][..], true),
        (ids::MESA_FAST_COMPILE, &["--fast-compile"][..], false),
    ] {
        progress(&suite_progress(m, cached, extra));
        if !cached {
            drop(cache.take());
            match suite::ShaderCache::fresh(&format!("{MESA}-{id}")) {
                Ok(c) => cache = Some(c),
                Err(e) => {
                    unavailable.push(Unavailable {
                        what: "suite".into(),
                        backend: Some(MESA.into()),
                        reason: e,
                    });
                    continue;
                }
            }
        }
        match suite::suite(&o.exe, m.backends, m.fixtures, &m.out_root.join(id), extra) {
            Ok(run) => {
                let mut row = mesa_suite_row(id, &run, m);
                if id == ids::MESA_COLD {
                    cold.cache_entries = cache.as_ref().map_or(0, |c| c.entries());
                    cold.wall_s = Some(run.wall_s);
                    if every {
                        row = row.with_target(Target::new(
                            Goal::AtMost,
                            targets17::MESA_COLD_S,
                            "cold-run goal (2 cores)",
                        ));
                    }
                    rows.push(cold_rss_row(&run));
                }
                rows.push(row);
            }
            Err(e) => unavailable.push(Unavailable {
                what: "suite".into(),
                backend: Some(MESA.into()),
                reason: e,
            }),
        }
    }
    cold
}

/// The progress line of one Mesa suite run.
fn suite_progress(m: &Mesa<'_>, cached: bool, extra: &[&str]) -> String {
    format!(
        "suite: {} ({}){}",
        m.backends.join(", "),
        if cached {
            "shader cache filled"
        } else {
            "empty shader cache"
        },
        if extra.is_empty() {
            String::new()
        } else {
            format!(", {}", extra.join(" "))
        }
    )
}

/// The peak memory row of the cold Mesa suite run.
fn cold_rss_row(run: &suite::SuiteRun) -> Measurement {
    Measurement::new(
        ids::SUITE_RSS,
        Some(MESA),
        run.peak_rss_mib,
        "MiB",
        "largest process of the cold run, wait4 ru_maxrss".into(),
    )
    .with_target(Target::new(
        Goal::AtMost,
        targets::PEAK_RSS_MIB,
        "throughput goal",
    ))
}

/// The wall-time row of one Mesa suite run.
fn mesa_suite_row(id: &str, run: &suite::SuiteRun, m: &Mesa<'_>) -> Measurement {
    let per: Vec<String> = run
        .backend_s
        .iter()
        .map(|(b, t)| format!("{b} {t:.1}"))
        .collect();
    Measurement::new(
        id,
        None,
        run.wall_s,
        "s",
        format!(
            "`shadowcheck run` over the {}, {} backends, {} at once (-j default), exit {}, peak RSS {:.0} MiB; seconds in each backend: {}",
            m.what,
            m.backends.len(),
            Machine::describe(None).nproc,
            run.exit_code,
            run.peak_rss_mib,
            per.join(", ")
        ),
    )
}

/// The floor from compiled (API path, state) pairs: per backend its compiled states x its
/// driver's compile time per variant, over the cores (never below the longest backend alone).
/// Returns how many backends compile anything.
fn states_floor_row(
    o: &BenchOptions,
    set: &CaseSet,
    m: &Mesa<'_>,
    per_variant: &[(Driver, f64)],
    cores: f64,
    rows: &mut Vec<Measurement>,
) -> usize {
    let quick_set;
    let suite_set = if o.quick {
        quick_set = crate::run::load_cases(m.fixtures);
        &quick_set
    } else {
        set
    };
    let mut floor = 0.0;
    // One backend is one worker thread: the floor is never below its own compile time.
    let mut longest: f64 = 0.0;
    // Backends that compile anything: more cores than these cannot be used.
    let mut heavy = 0usize;
    let mut parts = Vec::new();
    let mut complete = true;
    for n in m.backends {
        let Ok(bn) = n.parse::<BackendName>() else {
            continue;
        };
        let cost = match bn.driver {
            Driver::Softpipe => Some(0.0),
            // OSMesa's llvmpipe is the same compiler (its own cache: nothing is shared).
            d => per_variant.iter().find(|(k, _)| *k == d).map(|(_, c)| *c),
        };
        let Some(cost) = cost else {
            complete = false;
            continue;
        };
        if cost == 0.0 {
            continue;
        }
        match crate::backend::open(n, &crate::backend::Options::default()) {
            Ok(b) => {
                let states = suite_set.compiled_states_on(b.capabilities());
                floor += states as f64 * cost;
                longest = longest.max(states as f64 * cost);
                heavy += usize::from(states > 0);
                parts.push(format!("{n} {states}"));
            }
            Err(_) => complete = false,
        }
    }
    floor = (floor / cores).max(longest);
    rows.push(Measurement::new(
        ids::COLD_FLOOR_STATES,
        None,
        floor,
        "s",
        format!(
            "compiled (API path, state) pairs per backend: {}; x the measured compile time per variant of its driver (softpipe interprets: 0); the sum / {cores} cores, or the longest backend alone if more{}",
            parts.join(", "),
            if complete { "" } else { "; some backend had no figure" }
        ),
    ));
    heavy
}

/// The same floor with the driver's own count: the entries the cold run wrote to its empty shader
/// cache (distinct states in the driver's terms: formats it stores alike share a variant); and
/// the cold run over it.
fn cache_floor_rows(
    per_variant: &[(Driver, f64)],
    cores: f64,
    heavy: usize,
    cold: &ColdRun,
    rows: &mut Vec<Measurement>,
) {
    let cold_entries = cold.cache_entries;
    let mean = per_variant.iter().map(|(_, c)| c).sum::<f64>() / per_variant.len() as f64;
    let usable = cores.min(heavy.max(1) as f64);
    let floor = cold_entries as f64 * mean / usable;
    rows.push(Measurement::new(
        ids::COLD_FLOOR,
        None,
        floor,
        "s",
        format!(
            "{cold_entries} entries written to the empty shader cache by the cold run x {:.1} ms (mean measured compile time per variant) / {usable} cores (the cores, or the backends that compile if fewer)",
            mean * 1e3
        ),
    ));
    if let Some(c) = cold.wall_s.filter(|_| floor > 0.0) {
        rows.push(
            Measurement::new(
                ids::COLD_OVER_FLOOR,
                None,
                c / floor,
                "x",
                format!(
                    "cold suite {c:.1} s over the floor of the variants it compiled, {floor:.1} s"
                ),
            )
            .with_target(Target::new(
                Goal::AtMost,
                targets17::COLD_OVER_FLOOR,
                "cold-run goal",
            )),
        );
    }
}
