//! The cold-run measurements: checks per compiled state, the compile time of one shader
//! variant, the default suite over every Mesa backend in one run (cold, cached, `--fast-compile`)
//! and the floor of the compilations a cold run cannot avoid.

use super::run::BenchOptions;
use super::{grouping, suite};
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

/// What compiling costs one driver: seconds per variant of one state (one state per program),
/// and, from the same cases drawn with many states per program, per variant of a set and the
/// units such a set had on average.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriverCost {
    pub driver: Driver,
    pub per_variant_s: f64,
    pub per_set_s: Option<f64>,
    pub units_per_set: Option<f64>,
}

impl DriverCost {
    /// The cost of a variant as a fixed part and a part per unit (state) it samples, (fixed,
    /// per unit) in seconds: the line through the one-state variant (1 unit) and the sets'
    /// mean; without sets of more than one unit on average, all of it per unit.
    pub fn fixed_and_per_unit_s(&self) -> (f64, f64) {
        let one = self.per_variant_s;
        match (self.per_set_s, self.units_per_set) {
            (Some(set), Some(u)) if u > 1.5 => {
                let per_unit = (set - one) / (u - 1.0);
                let fixed = one - per_unit;
                if per_unit > 0.0 && fixed >= 0.0 {
                    (fixed, per_unit)
                } else {
                    (0.0, set / u)
                }
            }
            _ => (0.0, one),
        }
    }
}

/// Measures the compile time on each compiling driver's `egl:<driver>:core` backend that is
/// available, once with one state per program and once with the default states per program.
pub fn compile_rows(
    o: &BenchOptions,
    set: &CaseSet,
    available: &[String],
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) -> Vec<DriverCost> {
    let mut costs: Vec<DriverCost> = Vec::new();
    for d in [Driver::Llvmpipe, Driver::Zink] {
        let name = format!("egl:{}:core", d.key());
        if !available.contains(&name) {
            continue;
        }
        let stride = if o.quick { 64 } else { 8 };
        progress(&format!(
            "{name}: compile time per variant (every {stride}th state, empty shader cache)"
        ));
        let one = match suite::compile_cost(&name, set, stride, 1) {
            Ok(c) => c,
            Err(e) => {
                unavailable.push(Unavailable {
                    what: "compile time per variant".into(),
                    backend: Some(name),
                    reason: e,
                });
                continue;
            }
        };
        rows.push(Measurement::new(
            ids::COMPILE_PER_VARIANT,
            Some(&name),
            one.per_variant_s() * 1e3,
            "ms",
            format!(
                "one state per program (`--states-per-program 1`); one case per compiled state, {} states (every {stride}th of the fixtures): cold {:.2} s, same cases warm {:.2} s; (cold - warm) / states",
                one.states, one.cold_s, one.warm_s
            ),
        ));
        let k = shadowcheck_plan::units::DEFAULT_STATES_PER_PROGRAM;
        progress(&format!(
            "{name}: compile time per state, {k} states per program"
        ));
        let many = suite::compile_cost(&name, set, stride, k);
        let mut cost = DriverCost {
            driver: d,
            per_variant_s: one.per_variant_s(),
            per_set_s: None,
            units_per_set: None,
        };
        match &many {
            Ok(c) => {
                if let (Some(st), Some(set_s), Some(p)) =
                    (c.per_state_s(), c.per_set_s(), c.per_pass)
                {
                    let units = p.units as f64 / p.sets.max(1) as f64;
                    cost.per_set_s = Some(set_s);
                    cost.units_per_set = Some(units);
                    let (fixed, per_unit) = cost.fixed_and_per_unit_s();
                    rows.push(Measurement::new(
                        ids::COMPILE_PER_STATE,
                        Some(&name),
                        st * 1e3,
                        "ms",
                        format!(
                            "the same cases, up to {} states per program: {} distinct sets of {} units in all over {} programs; cold {:.2} s, warm {:.2} s; (cold - warm) / units",
                            p.states_per_program, p.sets, p.units, p.programs, c.cold_s, c.warm_s
                        ),
                    ));
                    rows.push(Measurement::new(
                        ids::COMPILE_PER_SET,
                        Some(&name),
                        set_s * 1e3,
                        "ms",
                        format!(
                            "(cold - warm) / sets: one variant sampling {units:.1} states on average; with the one-state variant, a variant costs {:.1} ms + {:.1} ms per state it samples",
                            fixed * 1e3,
                            per_unit * 1e3
                        ),
                    ));
                }
            }
            Err(e) => unavailable.push(Unavailable {
                what: "compile time per state".into(),
                backend: Some(name.clone()),
                reason: e.clone(),
            }),
        }
        costs.push(cost);
    }
    costs
}

/// The Mesa backends of a suite measurement and where its runs go.
pub struct Mesa<'a> {
    pub backends: &'a [String],
    pub fixtures: &'a [PathBuf],
    /// "default fixtures" or the quick subset, for the rows' details.
    pub what: &'a str,
    pub out_root: &'a Path,
}

/// Every Mesa backend in one `shadowcheck run`: cold with one state per program, cold (the
/// default, many states per program), with the cache it filled, cold with `--fast-compile`; the
/// A/B rows of the two cold runs (`grouping.rs`); then the floors (compiled states x compile
/// time per variant; drawn (program, state) pairs x compile time per state) and the cold run over
/// the latter.
pub fn suite_rows(
    o: &BenchOptions,
    set: &CaseSet,
    m: &Mesa<'_>,
    costs: &[DriverCost],
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) {
    if m.backends.is_empty() {
        return;
    }
    let runs = mesa_suite_runs(o, m, rows, unavailable, progress);
    if let (Some(one), Some(cold)) = (&runs.one_state, &runs.cold) {
        rows.extend(grouping::ab_rows(
            one,
            cold,
            &m.out_root.join(ids::MESA_ONE_STATE),
            &m.out_root.join(ids::MESA_COLD),
            runs.every,
        ));
    }
    if let Some(cold) = &runs.cold {
        rows.extend(grouping::states_per_set_rows(cold));
    }
    if costs.is_empty() {
        return;
    }
    let cores = Machine::describe(None).nproc.max(1) as f64;
    let per_variant: Vec<(Driver, f64)> =
        costs.iter().map(|c| (c.driver, c.per_variant_s)).collect();
    states_floor_row(o, set, m, &per_variant, cores, rows);
    if let Some(cold) = &runs.cold {
        rows.extend(grouping::floor_rows(cold, costs, cores, runs.cache_entries));
    }
}

/// What the Mesa suite runs left for the rows after them.
struct MesaRuns {
    /// Every Mesa driver of the project ran, over the default fixtures: the goals apply.
    every: bool,
    /// The cold run (default states per program) and the entries it wrote to its empty cache.
    cold: Option<suite::SuiteRun>,
    cache_entries: usize,
    /// The cold run with one state per program.
    one_state: Option<suite::SuiteRun>,
}

/// The label of the Mesa suite rows and of their shader caches.
const MESA: &str = "mesa";

/// The four runs of the suite over every Mesa backend, in this order: cold with one state per
/// program and cold with the default (the A/B pair, one right after the other), cached (the
/// second run's cache), cold with `--fast-compile` (a fresh cache).
fn mesa_suite_runs(
    o: &BenchOptions,
    m: &Mesa<'_>,
    rows: &mut Vec<Measurement>,
    unavailable: &mut Vec<Unavailable>,
    progress: &mut dyn FnMut(&str),
) -> MesaRuns {
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
    let mut runs = MesaRuns {
        every,
        cold: None,
        cache_entries: 0,
        one_state: None,
    };
    // Cold then cached share one cache; every other cold run gets a fresh one.
    let mut cache = None;
    for (id, extra, cached) in [
        (
            ids::MESA_ONE_STATE,
            &["--states-per-program", "1"][..],
            false,
        ),
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
                    runs.cache_entries = cache.as_ref().map_or(0, |c| c.entries());
                    if every {
                        row = row.with_target(Target::new(
                            Goal::AtMost,
                            targets17::MESA_COLD_S,
                            "cold-run goal (2 cores)",
                        ));
                    }
                    rows.push(cold_rss_row(&run));
                    runs.cold = Some(run);
                } else if id == ids::MESA_ONE_STATE {
                    runs.one_state = Some(run);
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
    runs
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

/// The floor of one state per program, from compiled (API path, state) pairs: per backend its
/// compiled states x its driver's compile time per variant, over the cores (never below the
/// longest backend alone).
fn states_floor_row(
    o: &BenchOptions,
    set: &CaseSet,
    m: &Mesa<'_>,
    per_variant: &[(Driver, f64)],
    cores: f64,
    rows: &mut Vec<Measurement>,
) {
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
}
