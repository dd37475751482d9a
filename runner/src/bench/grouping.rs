//! Many sampler states per compiled program (`shadowcheck_plan::units`), measured: the cold
//! suite against the one-state code (`run --states-per-program 1`) run right before it in the
//! same bench, whether the two gave the same verdicts, how many states each backend's programs
//! sampled (the GL workers' stats lines), and the compile floor recomputed from the drawn
//! (program, state) pairs and the per-state compile time.

use super::suite::SuiteRun;
use super::{cold::DriverCost, ids, Goal, Measurement, Target};
use shadowcheck_gl::names::{BackendName, Driver};
use std::collections::BTreeMap;
use std::path::Path;

/// The goals of the states-per-program work (their rows name them "cold-run goal (states per
/// program)").
pub mod targets {
    /// Cold default suite over the same suite with one state per program, one bench.
    pub const COLD_OVER_ONE_STATE: f64 = 0.45;
    /// Tests whose status differs between the two cold runs (known flaky ones aside).
    pub const VERDICTS_DIFFERING: f64 = 0.0;
    /// Distinct (API path, state) pairs per entry of the empty shader cache after a cold
    /// `egl:llvmpipe:core` run over the gl46 fixtures.
    pub const STATES_PER_CACHE_ENTRY: f64 = 8.0;
}

const GOAL: &str = "cold-run goal (states per program)";

/// The A/B rows: the one-state cold run's wall time, the default cold run over it, and the tests
/// whose status differs between the two (`results.csv` under `one_out` and `cold_out`), the
/// tests of the committed flake lists aside.
pub fn ab_rows(
    one: &SuiteRun,
    cold: &SuiteRun,
    one_out: &Path,
    cold_out: &Path,
    goals: bool,
) -> Vec<Measurement> {
    let mut ratio = Measurement::new(
        ids::MESA_COLD_OVER_ONE_STATE,
        None,
        cold.wall_s / one.wall_s,
        "x",
        format!(
            "cold suite {:.1} s (up to {} states per program) over {:.1} s with one state per program, run right before it; user+sys CPU of the two: see their rows",
            cold.wall_s,
            shadowcheck_plan::units::DEFAULT_STATES_PER_PROGRAM,
            one.wall_s
        ),
    );
    if goals {
        ratio = ratio.with_target(Target::new(
            Goal::AtMost,
            targets::COLD_OVER_ONE_STATE,
            GOAL,
        ));
    }
    let mut rows = vec![ratio];
    match (statuses(one_out), statuses(cold_out)) {
        (Ok(a), Ok(b)) => {
            let flaky = known_flaky();
            let mut differ: Vec<String> = Vec::new();
            let mut excused = 0usize;
            for (test, sa) in &a {
                let sb = b.get(test).map_or("(absent)", String::as_str);
                if sb == sa {
                    continue;
                }
                if flaky.iter().any(|re| re.is_match(&test.1)) {
                    excused += 1;
                } else {
                    differ.push(format!("{} {}: {sa} / {sb}", test.0, test.1));
                }
            }
            differ.extend(
                b.keys()
                    .filter(|t| !a.contains_key(*t))
                    .map(|t| format!("{} {}: (absent) / {}", t.0, t.1, b[t])),
            );
            let shown: Vec<&str> = differ.iter().take(10).map(String::as_str).collect();
            rows.push(
                Measurement::new(
                    ids::MESA_VERDICTS_DIFFERING,
                    None,
                    differ.len() as f64,
                    "tests",
                    format!(
                        "{} tests in each run; statuses that differ between one and many states per program{}; {excused} more differ in tests of the committed flake lists (reports/mesa-22.3.6/*/flakes.txt)",
                        a.len(),
                        if shown.is_empty() {
                            String::new()
                        } else {
                            format!(": {}", shown.join("; "))
                        }
                    ),
                )
                .with_target(Target::new(
                    Goal::AtMost,
                    targets::VERDICTS_DIFFERING,
                    GOAL,
                )),
            );
        }
        (Err(e), _) | (_, Err(e)) => rows.push(Measurement::new(
            ids::MESA_VERDICTS_DIFFERING,
            None,
            f64::NAN,
            "tests",
            format!("not compared: {e}"),
        )),
    }
    rows
}

/// (backend, test) -> status of a run's results.csv (deqp-runner's `test,status,...` with the
/// backend last).
fn statuses(out: &Path) -> Result<BTreeMap<(String, String), String>, String> {
    let path = out.join("results.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(text
        .lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let (test, status, backend) = (f.first()?, f.get(1)?, f.last()?);
            Some((
                (backend.to_string(), test.trim_matches('"').to_string()),
                status.to_string(),
            ))
        })
        .collect())
}

/// The regular expressions of the committed flake lists of the Mesa reference results (tests
/// that flip between runs whatever the harness does).
fn known_flaky() -> Vec<regex::Regex> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../reports/mesa-22.3.6");
    let Ok(dirs) = std::fs::read_dir(&root) else {
        return Vec::new();
    };
    dirs.filter_map(|d| std::fs::read_to_string(d.ok()?.path().join("flakes.txt")).ok())
        .flat_map(|text| {
            text.lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .filter_map(|l| regex::Regex::new(l).ok())
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Per GL backend of the cold run: the states each distinct (program, states bound together)
/// set sampled on average, with the programs compiled and the distinct pairs and sets drawn.
pub fn states_per_set_rows(cold: &SuiteRun) -> Vec<Measurement> {
    cold.worker_stats
        .iter()
        .filter(|(_, s)| s.sets > 0)
        .map(|(b, s)| {
            Measurement::new(
                ids::STATES_PER_SET,
                Some(b),
                s.units as f64 / s.sets as f64,
                "states/set",
                format!(
                    "cold run: {} programs compiled; {} distinct (lookup, sampling state) pairs (the variants of one state per program) drawn in {} distinct sets of {} units in all, up to {} states per program (fixed function, one state a draw, not counted)",
                    s.programs, s.states, s.sets, s.units, s.states_per_program
                ),
            )
        })
        .collect()
}

/// The compile floor of the cold run as it compiled: per backend, the fixed part of a variant
/// for each distinct set its worker drew and the part per state for each distinct (lookup,
/// sampling state) pair ([`DriverCost::fixed_and_per_unit_s`]: a unit that repeats a sampling
/// state another set already had is not counted again), over the cores (never below the
/// longest backend alone); and the cold run over it.
pub fn floor_rows(
    cold: &SuiteRun,
    costs: &[DriverCost],
    cores: f64,
    cache_entries: usize,
) -> Vec<Measurement> {
    let mut floor = 0.0;
    let mut longest: f64 = 0.0;
    let mut parts = Vec::new();
    let mut complete = true;
    for (b, s) in &cold.worker_stats {
        let Ok(bn) = b.parse::<BackendName>() else {
            continue;
        };
        if bn.driver == Driver::Softpipe {
            continue;
        }
        let Some(cost) = costs.iter().find(|c| c.driver == bn.driver) else {
            complete = false;
            continue;
        };
        let (fixed, per_unit) = cost.fixed_and_per_unit_s();
        let t = s.sets as f64 * fixed + s.states as f64 * per_unit;
        floor += t;
        longest = longest.max(t);
        parts.push(format!("{b} {}/{}", s.sets, s.states));
    }
    let floor = (floor / cores).max(longest);
    let model: Vec<String> = costs
        .iter()
        .map(|c| {
            let (fixed, per_unit) = c.fixed_and_per_unit_s();
            format!(
                "{} {:.1} ms + {:.1} ms per state",
                c.driver.key(),
                fixed * 1e3,
                per_unit * 1e3
            )
        })
        .collect();
    let mut rows = vec![Measurement::new(
        ids::COLD_FLOOR,
        None,
        floor,
        "s",
        format!(
            "distinct sets / distinct (lookup, sampling state) pairs the cold run's workers drew (softpipe interprets: none): {}; a variant costs {} (each set its fixed part, each pair its part per state once); the sum / {cores} cores, or the longest backend alone if more; the run wrote {cache_entries} entries to its empty shader cache{}",
            parts.join(", "),
            model.join(", "),
            if complete { "" } else { "; some backend had no figure" }
        ),
    )];
    if floor > 0.0 {
        rows.push(
            Measurement::new(
                ids::COLD_OVER_FLOOR,
                None,
                cold.wall_s / floor,
                "x",
                format!(
                    "cold suite {:.1} s over the floor of what it compiled, {floor:.1} s",
                    cold.wall_s
                ),
            )
            .with_target(Target::new(
                Goal::AtMost,
                super::targets17::COLD_OVER_FLOOR,
                "cold-run goal",
            )),
        );
    }
    rows
}

/// Distinct (API path, state) pairs per entry of an empty shader cache after a cold
/// `egl:llvmpipe:core` run over the `gl46` fixtures under `fixtures_root` (the entries: one per
/// fragment variant, plus the programs' own).
pub fn cache_entry_row(
    exe: &Path,
    fixtures_root: &Path,
    out: &Path,
) -> Result<Measurement, String> {
    let backend = "egl:llvmpipe:core";
    let gl46 = fixtures_root.join("gl46");
    if !gl46.is_dir() {
        return Err(format!("{} is not a directory", gl46.display()));
    }
    let set = crate::run::load_cases(std::slice::from_ref(&gl46));
    let b = crate::backend::open(backend, &crate::backend::Options::default())
        .map_err(|e| e.to_string())?;
    let states = set.compiled_states_on(b.capabilities());
    drop(b);
    let cache = super::suite::ShaderCache::fresh("gl46-entries")?;
    let run = super::suite::suite(exe, &[backend.to_string()], &[gl46], out, &[])?;
    let entries = cache.entries();
    drop(cache);
    let stats = run
        .worker_stats
        .iter()
        .find(|(n, _)| n == backend)
        .map(|(_, s)| {
            format!(
                "; its worker compiled {} programs and drew {} (program, state) pairs in {} sets",
                s.programs, s.states, s.sets
            )
        })
        .unwrap_or_default();
    Ok(Measurement::new(
        ids::STATES_PER_CACHE_ENTRY,
        Some(backend),
        states as f64 / entries.max(1) as f64,
        "states/entry",
        format!(
            "cold run over the gl46 fixtures ({:.1} s): {states} distinct (API path, state) pairs, {entries} entries in the empty shader cache{stats}",
            run.wall_s
        ),
    )
    .with_target(Target::new(
        Goal::AtLeast,
        targets::STATES_PER_CACHE_ENTRY,
        GOAL,
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(wall_s: f64) -> SuiteRun {
        SuiteRun {
            wall_s,
            peak_rss_mib: 1.0,
            exit_code: 0,
            backend_s: vec![],
            worker_stats: vec![],
        }
    }

    #[test]
    fn the_ab_rows_compare_wall_times_and_count_differing_verdicts_but_known_flakes() {
        let dir = std::env::temp_dir().join(format!("sc-grouping-{}", std::process::id()));
        let (a, b) = (dir.join("a"), dir.join("b"));
        std::fs::create_dir_all(&a).expect("temp dir");
        std::fs::create_dir_all(&b).expect("temp dir");
        let head = "";
        std::fs::write(
            a.join("results.csv"),
            format!("{head}t1@core,Pass,0.1,egl:llvmpipe:core\nt2@core,Fail,0.1,egl:llvmpipe:core\narb/2d/d16/nearest/none/dtm/dtm=alpha/texel1/ref=0.3@arbfp,Pass,0.1,egl:llvmpipe:compat\n"),
        )
        .expect("write");
        std::fs::write(
            b.join("results.csv"),
            format!("{head}t1@core,Pass,0.2,egl:llvmpipe:core\nt2@core,Pass,0.1,egl:llvmpipe:core\narb/2d/d16/nearest/none/dtm/dtm=alpha/texel1/ref=0.3@arbfp,Warn,0.1,egl:llvmpipe:compat\n"),
        )
        .expect("write");
        let rows = ab_rows(&run(100.0), &run(40.0), &a, &b, true);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(rows[0].id, ids::MESA_COLD_OVER_ONE_STATE);
        assert!((rows[0].value - 0.4).abs() < 1e-12);
        assert_eq!(rows[1].id, ids::MESA_VERDICTS_DIFFERING);
        // t2 differs; the ARB fp ALPHA test is on a committed flake list.
        assert_eq!(rows[1].value, 1.0, "{}", rows[1].detail);
        assert!(
            rows[1].detail.contains("t2@core: Fail / Pass"),
            "{}",
            rows[1].detail
        );
        assert!(
            rows[1].detail.contains("1 more differ"),
            "{}",
            rows[1].detail
        );
    }

    #[test]
    fn the_floor_counts_each_set_and_each_pair_once_at_the_drivers_cost() {
        let mut cold = run(30.0);
        let stats = |states| shadowcheck_gl::stats::WorkerStats {
            states_per_program: 16,
            programs: 10,
            states,
            sets: states / 10,
            units: 2 * states,
        };
        cold.worker_stats = vec![
            ("egl:llvmpipe:core".into(), stats(1000)),
            ("egl:softpipe:core".into(), stats(1000)),
            ("egl:zink:core".into(), stats(500)),
        ];
        // llvmpipe: 12 ms for one state, 68 ms for a set of 15: 8 ms + 4 ms a state.
        let llvmpipe = DriverCost {
            driver: Driver::Llvmpipe,
            per_variant_s: 0.012,
            per_set_s: Some(0.068),
            units_per_set: Some(15.0),
        };
        let (fixed, per_unit) = llvmpipe.fixed_and_per_unit_s();
        assert!((fixed - 0.008).abs() < 1e-12 && (per_unit - 0.004).abs() < 1e-12);
        // zink: no sets measured: all of it per state.
        let zink = DriverCost {
            driver: Driver::Zink,
            per_variant_s: 0.02,
            per_set_s: None,
            units_per_set: None,
        };
        assert_eq!(zink.fixed_and_per_unit_s(), (0.0, 0.02));
        let rows = floor_rows(&cold, &[llvmpipe, zink], 2.0, 123);
        // llvmpipe 100 sets x 8 ms + 1000 pairs x 4 ms = 4.8 s; zink 500 pairs x 20 ms = 10 s;
        // softpipe compiles nothing. (4.8 + 10) / 2 cores = 7.4 s, below zink alone: 10 s.
        assert!((rows[0].value - 10.0).abs() < 1e-9, "{}", rows[0].value);
        assert!(rows[0].detail.contains("123 entries"), "{}", rows[0].detail);
        assert!((rows[1].value - 3.0).abs() < 1e-9);
    }
}
