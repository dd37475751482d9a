//! End-to-end measurements: verified cases per second through a GL backend (in process: fixture
//! load, worker start, upload, draw, read-back, verdict), and the wall time and peak RSS of the
//! default suite per driver (a `shadowcheck run` child, reaped with `wait4` for its rusage).

use crate::backend::{self, Options};
use crate::events::{Fanout, Timing};
use crate::records::{exit, Outcome, Results, TestResult};
use crate::run::{self, CaseSet, Settings};
use shadowcheck_gl::stats::WorkerStats;
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::Instant;

/// A fresh, empty Mesa on-disk shader cache for the GL children started while it lives
/// (`MESA_SHADER_CACHE_DIR` set in this process's environment, which workers inherit;
/// `MESA_SHADER_CACHE_DISABLE` removed). llvmpipe and zink compile one shader variant per sampler
/// state, so cold and cached runs differ by an order of magnitude: the bench measures both.
/// Environment changes are process-wide: the bench is single-threaded while one exists.
pub struct ShaderCache {
    dir: PathBuf,
    old_dir: Option<std::ffi::OsString>,
    old_disable: Option<std::ffi::OsString>,
}

impl ShaderCache {
    pub fn fresh(label: &str) -> Result<ShaderCache, String> {
        let dir = std::env::temp_dir().join(format!(
            "shadowcheck-bench-cache-{}-{label}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
        let c = ShaderCache {
            dir,
            old_dir: std::env::var_os("MESA_SHADER_CACHE_DIR"),
            old_disable: std::env::var_os("MESA_SHADER_CACHE_DISABLE"),
        };
        std::env::set_var("MESA_SHADER_CACHE_DIR", &c.dir);
        std::env::remove_var("MESA_SHADER_CACHE_DISABLE");
        Ok(c)
    }
}

impl ShaderCache {
    /// Files in the cache: one per compiled shader variant (llvmpipe, lavapipe), plus a few for
    /// the GL front end's programs and zink's pipeline caches.
    pub fn entries(&self) -> usize {
        fn count(dir: &Path) -> usize {
            std::fs::read_dir(dir).map_or(0, |rd| {
                rd.filter_map(|e| e.ok())
                    .map(|e| match e.file_type() {
                        Ok(t) if t.is_dir() => count(&e.path()),
                        Ok(t) if t.is_file() => 1,
                        _ => 0,
                    })
                    .sum()
            })
        }
        count(&self.dir)
    }
}

impl Drop for ShaderCache {
    fn drop(&mut self) {
        match &self.old_dir {
            Some(v) => std::env::set_var("MESA_SHADER_CACHE_DIR", v),
            None => std::env::remove_var("MESA_SHADER_CACHE_DIR"),
        }
        if let Some(v) = &self.old_disable {
            std::env::set_var("MESA_SHADER_CACHE_DISABLE", v);
        }
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// One end-to-end run of a backend over a set of fixtures.
#[derive(Debug, Clone, PartialEq)]
pub struct E2e {
    pub cases_loaded: usize,
    /// Tests (case x path) with a verdict: Pass, Warn or Fail.
    pub verified: usize,
    /// Lookups those tests checked: each test's own and its case's sweep points.
    pub checks: usize,
    pub skipped: usize,
    pub load_s: f64,
    /// Starting the worker process and its handshake.
    pub open_s: f64,
    /// Sending, drawing, reading back and judging every case.
    pub run_s: f64,
    /// Of run_s: inside the backend (worker I/O, upload, draw, read-back).
    pub backend_s: f64,
    /// Of run_s: judging answers.
    pub verdict_s: f64,
    /// A pass over the same cases again on the same worker: the driver's shader variants and the
    /// worker's programs are compiled, the fixtures loaded (the median of `warm_passes` passes).
    pub warm_run_s: f64,
    pub warm_passes: usize,
    /// A third pass on a new worker whose on-disk shader cache the first pass filled (worker
    /// start included).
    pub cached_s: f64,
}

impl E2e {
    pub fn total_s(&self) -> f64 {
        self.load_s + self.open_s + self.run_s
    }
    pub fn per_s(&self) -> f64 {
        self.verified as f64 / self.total_s()
    }
    pub fn steady_per_s(&self) -> f64 {
        self.verified as f64 / self.run_s
    }
    pub fn warm_per_s(&self) -> f64 {
        self.verified as f64 / self.warm_run_s
    }
    pub fn cached_per_s(&self) -> f64 {
        self.verified as f64 / self.cached_s
    }
}

/// The 2D NEAREST fixture files under `root` (`<spec>/2d/nearest.json`), or `root` itself when it
/// is a file.
pub fn nearest_2d_fixtures(root: &Path) -> Vec<PathBuf> {
    if root.is_file() {
        return vec![root.to_path_buf()];
    }
    let mut v: Vec<PathBuf> = std::fs::read_dir(root)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.path().join("2d").join("nearest.json"))
                .filter(|p| p.is_file())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// One pass of `b` over `set` as a run makes it, with no reporters, no prior results and no flake
/// re-runs (what every end-to-end measurement times).
fn quiet_pass(b: &mut dyn backend::Backend, set: &CaseSet) -> (Vec<TestResult>, Timing) {
    run::run_backend(
        b,
        set,
        &Results::default(),
        &Settings::default(),
        &mut Fanout::default(),
    )
}

/// Runs `backend` over `fixtures` in this process with no reporters and no flake re-runs: cold
/// (empty shader cache), warm (same worker again), cached (new worker, filled cache).
pub fn e2e(backend_name: &str, fixtures: &[PathBuf]) -> Result<E2e, String> {
    let cache = ShaderCache::fresh("e2e")?;
    let t0 = Instant::now();
    let set = run::load_cases(fixtures);
    let load_s = t0.elapsed().as_secs_f64();
    if set.cases.is_empty() {
        return Err(format!("no case loaded from {fixtures:?}"));
    }
    let t1 = Instant::now();
    let mut b = backend::open(backend_name, &Options::default()).map_err(|e| e.to_string())?;
    let open_s = t1.elapsed().as_secs_f64();
    let t2 = Instant::now();
    let (results, timing) = quiet_pass(b.as_mut(), &set);
    let run_s = t2.elapsed().as_secs_f64();
    // Warm passes until about a second has gone by (at least 3, at most 50): a single pass over
    // the 2D NEAREST fixtures lasts a few hundredths of a second, too short to time alone.
    let mut warm = Vec::new();
    let t3 = Instant::now();
    while warm.len() < 3 || (warm.len() < 50 && t3.elapsed().as_secs_f64() < 1.0) {
        let t = Instant::now();
        let _ = quiet_pass(b.as_mut(), &set);
        warm.push(t.elapsed().as_secs_f64());
    }
    warm.sort_by(f64::total_cmp);
    let warm_run_s = warm[warm.len() / 2];
    let warm_passes = warm.len();
    drop(b);
    let t4 = Instant::now();
    let mut b = backend::open(backend_name, &Options::default()).map_err(|e| e.to_string())?;
    let _ = quiet_pass(b.as_mut(), &set);
    drop(b);
    let cached_s = t4.elapsed().as_secs_f64();
    drop(cache);
    let verified = results
        .iter()
        .filter(|r| matches!(r.outcome, Outcome::Pass | Outcome::Warn | Outcome::Fail))
        .count();
    let checks_of: std::collections::HashMap<&str, usize> = set
        .cases
        .iter()
        .map(|l| (l.case.id.as_str(), l.case.lookup_count()))
        .collect();
    let checks = results
        .iter()
        .filter(|r| matches!(r.outcome, Outcome::Pass | Outcome::Warn | Outcome::Fail))
        .map(|r| checks_of.get(r.case_id.as_str()).copied().unwrap_or(1))
        .sum();
    let skipped = results
        .iter()
        .filter(|r| r.outcome == Outcome::Skip)
        .count();
    if verified == 0 {
        return Err(format!(
            "{backend_name} verified no case of {} ({} skipped)",
            set.cases.len(),
            skipped
        ));
    }
    Ok(E2e {
        cases_loaded: set.cases.len(),
        verified,
        checks,
        skipped,
        load_s,
        open_s,
        run_s,
        backend_s: timing.backend_s,
        verdict_s: timing.verdict_s,
        warm_run_s,
        warm_passes,
        cached_s,
    })
}

/// Wall time and peak memory of one `shadowcheck run` child.
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteRun {
    pub wall_s: f64,
    /// Largest resident set of the run process or its workers (wait4's ru_maxrss), MiB.
    pub peak_rss_mib: f64,
    pub exit_code: i32,
    /// Seconds each backend spent in its implementation (`run --timings`), in the order printed.
    pub backend_s: Vec<(String, f64)>,
    /// What each GL worker compiled and drew (its last stderr line, shown by `run -v`).
    pub worker_stats: Vec<(String, WorkerStats)>,
}

/// Runs `shadowcheck run --backend B... --fixtures F... --out OUT --no-rerun --timings -v EXTRA...`
/// and reaps it with wait4. Exit codes 0 (all passed) and 100 (failures) are both a finished
/// suite. The child's stderr goes to `OUT.stderr` (read back for the per-backend timings and,
/// `-v` showing the workers' stderr, each GL worker's [`WorkerStats`]).
pub fn suite(
    exe: &Path,
    backends: &[String],
    fixtures: &[PathBuf],
    out: &Path,
    extra: &[&str],
) -> Result<SuiteRun, String> {
    let mut c = std::process::Command::new(exe);
    c.arg("run");
    for b in backends {
        c.args(["--backend", b]);
    }
    for f in fixtures {
        c.arg("--fixtures").arg(f);
    }
    c.arg("--out")
        .arg(out)
        .args(["--no-rerun", "--timings", "-v"]);
    c.args(extra);
    if let Some(parent) = out.parent() {
        std::fs::create_dir_all(parent)
            .map_err(|e| format!("creating {}: {e}", parent.display()))?;
    }
    let err_path = out.with_extension("stderr");
    let err_file = std::fs::File::create(&err_path)
        .map_err(|e| format!("creating {}: {e}", err_path.display()))?;
    c.stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::from(err_file));
    let t0 = Instant::now();
    let child = c
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", exe.display()))?;
    let pid = child.id() as libc::pid_t;
    let mut status: libc::c_int = 0;
    // SAFETY: rusage is plain old data, zero is a valid value.
    let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
    let r = loop {
        // SAFETY: pid is our child, not yet reaped (std's Child is not waited on); pointers are valid.
        let r = unsafe { libc::wait4(pid, &mut status, 0, &mut ru) };
        if r == -1 && std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
            continue;
        }
        break r;
    };
    let wall_s = t0.elapsed().as_secs_f64();
    if r != pid {
        return Err(format!("wait4: {}", std::io::Error::last_os_error()));
    }
    let exit_code = if libc::WIFEXITED(status) {
        libc::WEXITSTATUS(status)
    } else {
        -libc::WTERMSIG(status)
    };
    if exit_code != i32::from(exit::SUCCESS) && exit_code != i32::from(exit::REGRESSIONS) {
        return Err(format!(
            "`shadowcheck run` ended with {exit_code} (see {} and {})",
            out.display(),
            err_path.display()
        ));
    }
    let stderr = std::fs::read_to_string(&err_path).unwrap_or_default();
    // ru_maxrss is in KiB on Linux.
    Ok(SuiteRun {
        wall_s,
        peak_rss_mib: ru.ru_maxrss as f64 / 1024.0,
        exit_code,
        backend_s: parse_timings(&stderr),
        worker_stats: parse_worker_stats(&stderr),
    })
}

/// The `[<backend>] gl-worker stats: ...` lines of `run -v` (a GL worker's last line).
pub fn parse_worker_stats(stderr: &str) -> Vec<(String, WorkerStats)> {
    stderr
        .lines()
        .filter_map(|l| {
            let (name, rest) = l.strip_prefix('[')?.split_once("] ")?;
            Some((name.to_string(), WorkerStats::parse(rest)?))
        })
        .collect()
}

/// The `timings <backend>: N cases sent, X s in the backend ...` lines of `run --timings`.
fn parse_timings(stderr: &str) -> Vec<(String, f64)> {
    stderr
        .lines()
        .filter_map(|l| {
            let (name, rest) = l.strip_prefix("timings ")?.split_once(": ")?;
            let (_, after) = rest.split_once(" cases sent, ")?;
            let secs = after.split_once(" s in the backend")?.0.parse().ok()?;
            Some((name.to_string(), secs))
        })
        .collect()
}

/// What compiling one shader variant costs a backend: one case per distinct compiled state
/// (every `stride`-th state of the set, in order of first appearance) run on a worker with an
/// empty shader cache, then the same cases again on the same worker (variants in memory).
#[derive(Debug, Clone, PartialEq)]
pub struct CompileCost {
    /// Distinct (API path, state) pairs the sample compiled.
    pub states: usize,
    pub cold_s: f64,
    pub warm_s: f64,
    /// What the worker drew (its [`WorkerStats`]: distinct pairs and sets, the same in both
    /// passes), if it said.
    pub per_pass: Option<WorkerStats>,
}

impl CompileCost {
    /// Seconds per variant: what the cold pass spent beyond the warm pass, per state.
    pub fn per_variant_s(&self) -> f64 {
        self.excess_s() / self.states.max(1) as f64
    }

    /// What the cold pass spent beyond the warm pass.
    fn excess_s(&self) -> f64 {
        (self.cold_s - self.warm_s).max(0.0)
    }

    /// Seconds per unit of the sets drawn: the compile time of a state when states share
    /// programs, the sets' fixed cost spread over their units.
    pub fn per_state_s(&self) -> Option<f64> {
        let p = self.per_pass.filter(|p| p.units > 0)?;
        Some(self.excess_s() / p.units as f64)
    }

    /// Seconds per (program, states bound together) set: the compile time of one variant of a
    /// program sampling several states.
    pub fn per_set_s(&self) -> Option<f64> {
        let p = self.per_pass.filter(|p| p.sets > 0)?;
        Some(self.excess_s() / p.sets as f64)
    }
}

/// Measures [`CompileCost`] of `backend_name` over a sample of `set`'s compiled states, its
/// worker sampling at most `states_per_program` states with one program (`run
/// --states-per-program`).
pub fn compile_cost(
    backend_name: &str,
    set: &CaseSet,
    stride: usize,
    states_per_program: usize,
) -> Result<CompileCost, String> {
    let cache = ShaderCache::fresh("compile")?;
    let opts = Options {
        states_per_program,
        ..Options::default()
    };
    let mut b = backend::open(backend_name, &opts).map_err(|e| e.to_string())?;
    let mut seen = std::collections::HashSet::new();
    let mut sample = CaseSet::default();
    for l in &set.cases {
        if seen.insert(shadowcheck_cases::coverage::state_key(&l.case))
            && (seen.len() - 1) % stride.max(1) == 0
        {
            sample.cases.push(l.clone());
        }
    }
    let states = sample.compiled_states_on(b.capabilities());
    if states == 0 {
        return Err(format!("{backend_name} runs none of the sampled states"));
    }
    let pass = |b: &mut Box<dyn backend::Backend>| {
        let t = Instant::now();
        let _ = quiet_pass(b.as_mut(), &sample);
        let s = t.elapsed().as_secs_f64();
        // What the worker wrote so far is not read: dropped, so that its held lines (capped)
        // leave room for the stats line it writes at the end.
        let _ = b.take_diagnostics();
        s
    };
    let cold_s = pass(&mut b);
    let warm_s = pass(&mut b);
    let per_pass = b.close().iter().find_map(|l| WorkerStats::parse(l));
    drop(b);
    drop(cache);
    Ok(CompileCost {
        states,
        cold_s,
        warm_s,
        per_pass,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn run_timings_lines_are_read_per_backend() {
        let err = "egl:llvmpipe:core: 3 pass\ntimings egl:llvmpipe:core: 6425 cases sent, 59.285 s in the backend (108 cases/s), 0.059 s judging and reporting\ntimings soft: 1 cases sent, 0.5 s in the backend (2 cases/s), 0 s judging\nnoise";
        assert_eq!(
            parse_timings(err),
            vec![
                ("egl:llvmpipe:core".to_string(), 59.285),
                ("soft".to_string(), 0.5)
            ]
        );
    }

    #[test]
    fn compile_cost_is_the_cold_excess_per_state() {
        let c = CompileCost {
            states: 10,
            cold_s: 1.2,
            warm_s: 0.2,
            per_pass: Some(WorkerStats {
                states_per_program: 16,
                programs: 2,
                states: 20,
                sets: 4,
                units: 20,
            }),
        };
        assert!((c.per_variant_s() - 0.1).abs() < 1e-12);
        assert!((c.per_state_s().expect("stats") - 0.05).abs() < 1e-12);
        assert!((c.per_set_s().expect("stats") - 0.25).abs() < 1e-12);
        let none = CompileCost {
            states: 0,
            cold_s: 0.1,
            warm_s: 0.2,
            per_pass: None,
        };
        assert_eq!(none.per_variant_s(), 0.0);
        assert_eq!(none.per_state_s(), None);
    }

    #[test]
    fn worker_stats_are_read_from_the_verbose_run_output() {
        let err = "timings egl:llvmpipe:core: 10 cases sent, 1.5 s in the backend\n[egl:llvmpipe:core] XDG_RUNTIME_DIR is invalid\n[egl:llvmpipe:core] gl-worker stats: states_per_program=16 programs=3 states=40 sets=5 units=41\n[soft] something\n";
        let got = parse_worker_stats(err);
        assert_eq!(got.len(), 1);
        assert_eq!(got[0].0, "egl:llvmpipe:core");
        assert_eq!((got[0].1.states, got[0].1.sets), (40, 5));
    }

    #[test]
    fn nearest_2d_fixtures_are_found_per_spec() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures");
        let v = nearest_2d_fixtures(&root);
        assert!(
            v.iter().any(|p| p.ends_with("gl46/2d/nearest.json")),
            "{v:?}"
        );
        assert!(v.iter().all(|p| p.ends_with("2d/nearest.json")));
        let one = root.join("gl46/2d/nearest.json");
        assert_eq!(nearest_2d_fixtures(&one), vec![one]);
    }
}
