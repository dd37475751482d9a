//! The bench as a whole: which measurements run, in which order, with which targets.

use super::floor::{self, FloorResult};
use super::suite::{self, nearest_2d_fixtures};
use super::{
    cpu, ids, machine::Machine, targets, targets17, BenchReport, Goal, Measurement, Target,
    Unavailable, SCHEMA_VERSION,
};
use shadowcheck_gl::names::{BackendName, Driver};
use std::path::PathBuf;
use std::time::Duration;

/// What to measure.
#[derive(Debug, Clone)]
pub struct BenchOptions {
    /// Seconds instead of minutes: fewer cases, shorter timings, only `egl:llvmpipe:core` unless
    /// backends are named, the suite rows over the 2D NEAREST fixtures only.
    pub quick: bool,
    /// The GL backends to measure, named as in `run --backend` (`egl:zink:core`); empty = all.
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

/// Runs every measurement. `progress` gets a line before each step (the library never prints).
pub fn run(o: &BenchOptions, progress: &mut dyn FnMut(&str)) -> BenchReport {
    let min = if o.quick {
        Duration::from_millis(150)
    } else {
        Duration::from_secs(2)
    };
    let mut rows = Vec::new();
    let mut unavailable = Vec::new();
    let mut gl_version = None;
    let load_avg = Machine::describe(None).load_average;

    progress("oracle: loading the default fixtures");
    let set = crate::run::load_cases(&o.fixtures);
    rows.extend(density_rows(&set));
    let mut cases: Vec<_> = set.cases.iter().map(|l| l.case.clone()).collect();
    if o.quick {
        cases = cases.into_iter().step_by(10).collect();
    }
    if cases.is_empty() {
        unavailable.push(Unavailable {
            what: "oracle".into(),
            backend: None,
            reason: format!("no case loaded from {}", display_paths(&o.fixtures)),
        });
    } else {
        progress(&format!("oracle: {} cases, one thread", cases.len()));
        rows.extend(cpu::oracle_rows(&cases, min));
    }
    drop(cases);

    progress("soft: raw lookups, one thread");
    match cpu::soft_rows(if o.quick { 1 << 16 } else { 1 << 20 }, min) {
        Ok(r) => rows.extend(r),
        Err(e) => unavailable.push(Unavailable {
            what: "soft".into(),
            backend: None,
            reason: e,
        }),
    }

    let floor_min = if o.quick {
        Duration::from_millis(100)
    } else {
        Duration::from_secs(1)
    };
    let all_2d: Vec<PathBuf> = o
        .fixtures
        .iter()
        .flat_map(|f| nearest_2d_fixtures(f))
        .collect();
    let e2e_fixtures = match o
        .fixtures
        .iter()
        .map(|f| f.join("gl46/2d/nearest.json"))
        .find(|p| p.is_file())
    {
        Some(one) if o.quick => vec![one],
        _ => all_2d,
    };
    let mut available: Vec<String> = Vec::new();
    for name in candidates(o) {
        progress(&format!("{name}: bare-draw floor"));
        let f = floor::run_child(&name, floor_size(o.quick), floor_min, &[]);
        if !f.ok {
            unavailable.push(Unavailable {
                what: "gl".into(),
                backend: Some(name.clone()),
                reason: f.error.unwrap_or_default(),
            });
            continue;
        }
        gl_version.get_or_insert_with(|| f.version.clone());
        available.push(name.clone());
        let floor_per_s = f.per_s();
        rows.push(floor_row(ids::GL_FLOOR, &name, &f, ""));
        progress(&format!("{name}: end to end over the 2D NEAREST fixtures"));
        match suite::e2e(&name, &e2e_fixtures) {
            Ok(e) => {
                let detail = format!(
                    "{} verified tests ({} skipped) of {} cases in {:.2} s: load {:.2} s, worker start {:.2} s, run {:.2} s (backend {:.2} s, verdicts {:.2} s)",
                    e.verified, e.skipped, e.cases_loaded, e.total_s(), e.load_s, e.open_s, e.run_s, e.backend_s, e.verdict_s
                );
                let mut r =
                    Measurement::new(ids::GL_E2E, Some(&name), e.per_s(), "cases/s", detail);
                if name.contains(":llvmpipe:") {
                    r = r.with_target(Target::new(
                        Goal::AtLeast,
                        targets::LLVMPIPE_E2E_PER_S,
                        "issue 6 (llvmpipe, 2D NEAREST)",
                    ));
                }
                rows.push(r);
                rows.push(Measurement::new(
                    ids::GL_E2E_STEADY,
                    Some(&name),
                    e.steady_per_s(),
                    "cases/s",
                    "verified tests / run time (no fixture load, no worker start)".into(),
                ));
                rows.push(Measurement::new(
                    ids::GL_E2E_WARM,
                    Some(&name),
                    e.warm_per_s(),
                    "cases/s",
                    format!("the same cases again on the same worker ({:.2} s): shader variants already compiled", e.warm_run_s),
                ));
                let per_check = Measurement::new(
                    ids::HARNESS_PER_CHECK,
                    Some(&name),
                    e.warm_run_s / e.verified as f64 * 1e6,
                    "us/check",
                    format!("the warm pass ({:.3} s for {} checks): worker I/O, texture upload, draw, read-back and verdict once the variants exist", e.warm_run_s, e.verified),
                );
                rows.push(if name.contains(":llvmpipe:") {
                    per_check.with_target(Target::new(
                        Goal::AtMost,
                        targets17::HARNESS_US_PER_CHECK,
                        "issue 17 (llvmpipe)",
                    ))
                } else {
                    per_check
                });
                rows.push(Measurement::new(
                    ids::GL_E2E_CACHED,
                    Some(&name),
                    e.cached_per_s(),
                    "cases/s",
                    format!("a new worker with the on-disk shader cache the cold pass filled ({:.2} s incl. worker start; the cold pass starts from an empty cache)", e.cached_s),
                ));
                rows.push(
                    Measurement::new(
                        ids::GL_RATIO,
                        Some(&name),
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
                        "issue 6",
                    )),
                );
            }
            Err(e) => unavailable.push(Unavailable {
                what: "gl end to end".into(),
                backend: Some(name.clone()),
                reason: e,
            }),
        }
    }

    // llvmpipe's single-thread lookup rate: the bar for `soft`.
    if available.iter().any(|n| n == "egl:llvmpipe:core") {
        progress("egl:llvmpipe:core: bare-draw floor with LP_NUM_THREADS=1");
        let f = floor::run_child(
            "egl:llvmpipe:core",
            floor_size(o.quick),
            floor_min,
            &[("LP_NUM_THREADS", "1")],
        );
        if f.ok {
            let one = f.per_s();
            rows.push(floor_row(
                ids::GL_FLOOR_1T,
                "egl:llvmpipe:core",
                &f,
                ", LP_NUM_THREADS=1",
            ));
            if let Some(s) = rows.iter_mut().find(|r| r.id == ids::SOFT_LOOKUPS) {
                *s = s.clone().with_target(Target::new(
                    Goal::AtLeast,
                    one,
                    "llvmpipe floor, LP_NUM_THREADS=1",
                ));
            }
        } else {
            unavailable.push(Unavailable {
                what: "gl floor, 1 thread".into(),
                backend: Some("egl:llvmpipe:core".into()),
                reason: f.error.unwrap_or_default(),
            });
        }
    } else {
        unavailable.push(Unavailable {
            what: "soft target".into(),
            backend: None,
            reason: "egl:llvmpipe:core is not available (or filtered out): no single-thread llvmpipe rate to compare with".into(),
        });
    }

    // What one shader variant costs each compiling driver to build (issue 17's floor).
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
        match suite::compile_cost(&name, &set, stride) {
            Ok(c) => {
                per_variant.push((d, c.per_variant_s()));
                rows.push(Measurement::new(
                    ids::COMPILE_PER_VARIANT,
                    Some(&name),
                    c.per_variant_s() * 1e3,
                    "ms",
                    format!("one case per compiled state, {} states (every {stride}th of the fixtures): cold {:.2} s, same cases warm {:.2} s; (cold - warm) / states", c.states, c.cold_s, c.warm_s),
                ));
            }
            Err(e) => unavailable.push(Unavailable {
                what: "compile time per variant".into(),
                backend: Some(name),
                reason: e,
            }),
        }
    }

    // The default suite (quick: the 2D NEAREST fixtures): soft alone, then every Mesa backend in
    // one run, cold, with the cache it filled, and cold again with --fast-compile.
    let suite_fixtures = if o.quick {
        e2e_fixtures.clone()
    } else {
        o.fixtures.clone()
    };
    let what = if o.quick {
        "2D NEAREST fixtures (quick)"
    } else {
        "default fixtures"
    };
    let out_root = std::env::temp_dir().join(format!("shadowcheck-bench-{}", std::process::id()));
    progress("suite: soft, twice");
    let soft = ["soft".to_string()];
    match (
        suite::suite(&o.exe, &soft, &suite_fixtures, &out_root.join("soft"), &[]),
        suite::suite(
            &o.exe,
            &soft,
            &suite_fixtures,
            &out_root.join("soft-2"),
            &[],
        ),
    ) {
        (Ok(s), Ok(c)) => {
            let detail = format!(
                "`shadowcheck run` over the {what}, backend soft, exit {}",
                s.exit_code
            );
            rows.push(Measurement::new(
                ids::SUITE_WALL,
                Some("soft"),
                s.wall_s,
                "s",
                detail.clone(),
            ));
            rows.push(Measurement::new(
                ids::SUITE_WALL_CACHED,
                Some("soft"),
                c.wall_s,
                "s",
                format!("{detail}; a second run"),
            ));
            rows.push(
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
                    "issue 6",
                )),
            );
        }
        (Err(e), _) | (_, Err(e)) => unavailable.push(Unavailable {
            what: "suite".into(),
            backend: Some("soft".into()),
            reason: e,
        }),
    }
    let mesa: Vec<String> = available.clone();
    let drivers: Vec<Driver> = Driver::MESA
        .iter()
        .copied()
        .filter(|d| mesa.iter().any(|n| n.split(':').nth(1) == Some(d.key())))
        .collect();
    if !mesa.is_empty() {
        let every = drivers.len() == Driver::MESA.len() && !o.quick;
        let label = "mesa";
        let mut cold_s = None;
        let mut cold_entries = 0;
        // Cold then cached share one cache; the --fast-compile cold run gets a fresh one.
        let mut cache = None;
        for (id, extra, cached) in [
            (ids::MESA_COLD, &[][..], false),
            (ids::MESA_CACHED, &[][..], true),
            (ids::MESA_FAST_COMPILE, &["--fast-compile"][..], false),
        ] {
            progress(&format!(
                "suite: {} ({}){}",
                mesa.join(", "),
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
            ));
            if !cached {
                drop(cache.take());
                match suite::ShaderCache::fresh(&format!("{label}-{id}")) {
                    Ok(c) => cache = Some(c),
                    Err(e) => {
                        unavailable.push(Unavailable {
                            what: "suite".into(),
                            backend: Some(label.into()),
                            reason: e,
                        });
                        continue;
                    }
                }
            }
            match suite::suite(&o.exe, &mesa, &suite_fixtures, &out_root.join(id), extra) {
                Ok(run) => {
                    if id == ids::MESA_COLD {
                        cold_entries = cache.as_ref().map_or(0, |c| c.entries());
                    }
                    let per: Vec<String> = run
                        .backend_s
                        .iter()
                        .map(|(b, t)| format!("{b} {t:.1}"))
                        .collect();
                    let mut m = Measurement::new(
                        id,
                        None,
                        run.wall_s,
                        "s",
                        format!(
                            "`shadowcheck run` over the {what}, {} backends, {} at once (-j default), exit {}, peak RSS {:.0} MiB; seconds in each backend: {}",
                            mesa.len(),
                            Machine::describe(None).nproc,
                            run.exit_code,
                            run.peak_rss_mib,
                            per.join(", ")
                        ),
                    );
                    if id == ids::MESA_COLD {
                        cold_s = Some(run.wall_s);
                        if every {
                            m = m.with_target(Target::new(
                                Goal::AtMost,
                                targets17::MESA_COLD_S,
                                "issue 17 (2 cores)",
                            ));
                        }
                        rows.push(
                            Measurement::new(
                                ids::SUITE_RSS,
                                Some(label),
                                run.peak_rss_mib,
                                "MiB",
                                "largest process of the cold run, wait4 ru_maxrss".into(),
                            )
                            .with_target(Target::new(
                                Goal::AtMost,
                                targets::PEAK_RSS_MIB,
                                "issue 6",
                            )),
                        );
                    }
                    rows.push(m);
                }
                Err(e) => unavailable.push(Unavailable {
                    what: "suite".into(),
                    backend: Some(label.into()),
                    reason: e,
                }),
            }
        }
        drop(cache);
        // The floor: every backend's compiled states x its driver's compile time, over the cores.
        if !per_variant.is_empty() {
            let quick_set;
            let suite_set = if o.quick {
                quick_set = crate::run::load_cases(&suite_fixtures);
                &quick_set
            } else {
                &set
            };
            let cores = Machine::describe(None).nproc.max(1) as f64;
            let mut floor = 0.0;
            // One backend is one worker thread: the floor is never below its own compile time.
            let mut longest: f64 = 0.0;
            // Backends that compile anything: more cores than these cannot be used.
            let mut heavy = 0usize;
            let mut parts = Vec::new();
            let mut complete = true;
            for n in &mesa {
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
            // The same floor with the driver's own count: the entries the cold run wrote to its
            // empty shader cache (distinct states in the driver's terms: formats it stores alike
            // share a variant).
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
            if let Some(c) = cold_s.filter(|_| floor > 0.0) {
                rows.push(
                    Measurement::new(
                        ids::COLD_OVER_FLOOR,
                        None,
                        c / floor,
                        "x",
                        format!("cold suite {c:.1} s over the floor of the variants it compiled, {floor:.1} s"),
                    )
                    .with_target(Target::new(
                        Goal::AtMost,
                        targets17::COLD_OVER_FLOOR,
                        "issue 17",
                    )),
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&out_root);

    let mut machine = Machine::describe(gl_version.as_deref());
    machine.load_average = load_avg;
    BenchReport {
        schema: SCHEMA_VERSION,
        quick: o.quick,
        machine,
        rows,
        unavailable,
    }
}

/// `a, b` for messages naming several fixture paths.
fn display_paths(paths: &[PathBuf]) -> String {
    let v: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    v.join(", ")
}

/// Checks per compiled sampler state on each API path of the fixtures (cases/README.md prints the
/// same table): tests over distinct states, against issue 17's goal.
fn density_rows(set: &crate::run::CaseSet) -> Vec<Measurement> {
    let cov = shadowcheck_cases::coverage::Coverage::of(set.cases.iter().map(|l| &l.case));
    cov.per_path
        .iter()
        .map(|(api, d)| {
            let states = d.states.len().max(1);
            Measurement::new(
                ids::CHECKS_PER_STATE,
                Some(api.key()),
                d.tests as f64 / states as f64,
                "checks/state",
                format!(
                    "{} tests over {} distinct (target, format, compare mode/func, filters, wraps, depth modes)",
                    d.tests,
                    d.states.len()
                ),
            )
            .with_target(Target::new(
                Goal::AtLeast,
                targets17::CHECKS_PER_STATE,
                "issue 17",
            ))
        })
        .collect()
}
