//! Throughput measurements behind `shadowcheck bench` (the goals in [`targets`] and [`targets17`]).
//!
//! Each measurement yields [`Measurement`]s: the oracle's verdicts per second on one core, the `soft`
//! implementation's raw lookups per second on one core, and per GL backend the bare-draw floor
//! (full-screen draws of shadow lookups with parameters computed in the shader), the verified cases
//! per second end to end, their ratio, and the wall time and peak RSS of the default suite per
//! driver. A row carries its target (a goal of the benchmark, never a test assertion) and whether
//! this run met it. Nothing here prints: `cmd/bench.rs` renders the [`BenchReport`].

pub mod api_grids;
pub mod cold;
pub mod cpu;
pub mod floor;
pub mod grouping;
pub mod machine;
pub mod markdown;
pub mod run;
pub mod suite;

use serde::{Deserialize, Serialize};

/// Version of the JSON written by `shadowcheck bench --json`.
pub const SCHEMA_VERSION: u32 = 1;

/// The comparison a row's value is held to.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Goal {
    /// value >= bound
    AtLeast,
    /// value < bound
    Below,
    /// value <= bound
    AtMost,
}

/// A target for a row: `value <goal> bound`, with where the bound comes from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Target {
    pub goal: Goal,
    pub bound: f64,
    /// e.g. "throughput goal" or "llvmpipe LP_NUM_THREADS=1 floor".
    pub source: String,
}

impl Target {
    pub fn new(goal: Goal, bound: f64, source: &str) -> Target {
        Target {
            goal,
            bound,
            source: source.to_string(),
        }
    }
    pub fn met(&self, value: f64) -> bool {
        match self.goal {
            Goal::AtLeast => value >= self.bound,
            Goal::Below => value < self.bound,
            Goal::AtMost => value <= self.bound,
        }
    }
    /// e.g. ">= 5.00e7".
    pub fn describe(&self, unit: &str) -> String {
        let op = match self.goal {
            Goal::AtLeast => ">=",
            Goal::Below => "<",
            Goal::AtMost => "<=",
        };
        format!("{op} {} {unit}", fmt_num(self.bound))
    }
}

/// One measured figure.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    /// Stable key, e.g. `oracle_verdicts_per_s`, `gl_floor_lookups_per_s`.
    pub id: String,
    /// The backend (GL rows, suite rows), or `None`.
    pub backend: Option<String>,
    pub value: f64,
    pub unit: String,
    pub target: Option<Target>,
    /// `Some(met)` when the row has a target.
    pub met: Option<bool>,
    /// How it was measured (counts, seconds, workload).
    pub detail: String,
}

impl Measurement {
    pub fn new(
        id: &str,
        backend: Option<&str>,
        value: f64,
        unit: &str,
        detail: String,
    ) -> Measurement {
        Measurement {
            id: id.to_string(),
            backend: backend.map(str::to_string),
            value,
            unit: unit.to_string(),
            target: None,
            met: None,
            detail,
        }
    }
    pub fn with_target(mut self, t: Target) -> Measurement {
        self.met = Some(t.met(self.value));
        self.target = Some(t);
        self
    }
}

/// A measurement that could not be taken, with the reason (shown in the report, never silent).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Unavailable {
    pub what: String,
    pub backend: Option<String>,
    pub reason: String,
}

/// Everything one `shadowcheck bench` run measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BenchReport {
    pub schema: u32,
    pub quick: bool,
    pub machine: machine::Machine,
    pub rows: Vec<Measurement>,
    pub unavailable: Vec<Unavailable>,
}

impl BenchReport {
    pub fn row(&self, id: &str, backend: Option<&str>) -> Option<&Measurement> {
        self.rows
            .iter()
            .find(|r| r.id == id && r.backend.as_deref() == backend)
    }
}

/// Measurement ids (the JSON keys tests and scripts read).
pub mod ids {
    pub const ORACLE_VERDICTS: &str = "oracle_verdicts_per_s";
    pub const ORACLE_JUDGE: &str = "oracle_judge_only_per_s";
    pub const SOFT_LOOKUPS: &str = "soft_lookups_per_s";
    pub const SOFT_LOOKUPS_LINEAR: &str = "soft_lookups_per_s_linear";
    pub const GL_FLOOR: &str = "gl_floor_lookups_per_s";
    pub const GL_FLOOR_1T: &str = "gl_floor_lookups_per_s_1thread";
    pub const GL_E2E: &str = "gl_e2e_cases_per_s";
    pub const GL_E2E_STEADY: &str = "gl_e2e_steady_cases_per_s";
    pub const GL_E2E_WARM: &str = "gl_e2e_warm_cases_per_s";
    pub const GL_E2E_CACHED: &str = "gl_e2e_cached_cases_per_s";
    pub const GL_RATIO: &str = "gl_e2e_over_floor";
    /// The Vulkan backends over the `vulkan/` fixtures (`bench::api_grids`).
    pub const VK_E2E: &str = "vk_e2e_cases_per_s";
    pub const VK_E2E_WARM: &str = "vk_e2e_warm_cases_per_s";
    pub const VK_E2E_CACHED: &str = "vk_e2e_cached_cases_per_s";
    pub const VK_PER_CHECK: &str = "vk_warm_us_per_check";
    /// WebGPU in headless Chromium over the `webgpu/` fixtures (`bench::api_grids`).
    pub const WEBGPU_E2E: &str = "webgpu_e2e_cases_per_s";
    pub const WEBGPU_E2E_WARM: &str = "webgpu_e2e_warm_cases_per_s";
    pub const WEBGPU_E2E_CACHED: &str = "webgpu_e2e_cached_cases_per_s";
    pub const WEBGPU_PER_CHECK: &str = "webgpu_warm_us_per_check";
    pub const SUITE_WALL: &str = "suite_wall_s";
    pub const SUITE_RSS: &str = "suite_peak_rss_mib";
    pub const SUITE_WALL_CACHED: &str = "suite_wall_cached_s";
    /// Every Mesa backend of the machine in one `shadowcheck run` (both cores).
    pub const MESA_COLD: &str = "suite_mesa_cold_s";
    pub const MESA_CACHED: &str = "suite_mesa_cached_s";
    pub const MESA_FAST_COMPILE: &str = "suite_mesa_fast_compile_cold_s";
    /// The same cold suite with one sampler state per program (`run --states-per-program 1`).
    pub const MESA_ONE_STATE: &str = "suite_mesa_one_state_cold_s";
    /// The cold suite over the one-state cold suite, run one after the other.
    pub const MESA_COLD_OVER_ONE_STATE: &str = "suite_mesa_cold_over_one_state";
    /// Tests whose status differs between those two runs (known flaky ones aside).
    pub const MESA_VERDICTS_DIFFERING: &str = "suite_mesa_verdicts_differing";
    /// Per GL backend: (program, state) pairs drawn per (program, states) set in the cold run.
    pub const STATES_PER_SET: &str = "states_per_program_set";
    /// Distinct (API path, state) pairs per shader cache entry, cold egl:llvmpipe:core over gl46.
    pub const STATES_PER_CACHE_ENTRY: &str = "states_per_cache_entry";
    /// Tests per distinct compiled sampler state, per API path (backend column: the path).
    pub const CHECKS_PER_STATE: &str = "checks_per_compiled_state";
    /// Harness and driver cost per check after compilation (warm pass), microseconds.
    pub const HARNESS_PER_CHECK: &str = "gl_warm_us_per_check";
    /// Measured compile time of one shader variant of one state (one state per program; cold
    /// minus warm, per state), milliseconds.
    pub const COMPILE_PER_VARIANT: &str = "compile_ms_per_variant";
    /// The same cases with many states per program: cold minus warm per (program, state) pair.
    pub const COMPILE_PER_STATE: &str = "compile_ms_per_state";
    /// ... and per (program, states) set, one variant of a program sampling several states.
    pub const COMPILE_PER_SET: &str = "compile_ms_per_program_set";
    /// Compiled states of the Mesa backends ([`shadowcheck_cases::coverage::StateKey`] per API
    /// path) x their driver's compile time, over the cores.
    pub const COLD_FLOOR_STATES: &str = "cold_floor_states_s";
    /// (program, state) pairs the cold suite's workers drew x the compile time per state, over
    /// the cores.
    pub const COLD_FLOOR: &str = "cold_floor_s";
    pub const COLD_OVER_FLOOR: &str = "suite_mesa_cold_over_floor";
}

/// The throughput goals the project set itself (their rows name them "throughput goal").
pub mod targets {
    /// Oracle verdicts per second on one core.
    pub const ORACLE_VERDICTS_PER_S: f64 = 50e6;
    /// End-to-end verified cases per second on llvmpipe, 2D NEAREST.
    pub const LLVMPIPE_E2E_PER_S: f64 = 50e6;
    /// End to end over bare-draw floor.
    pub const E2E_OVER_FLOOR: f64 = 0.5;
    /// Peak resident set size, MiB.
    pub const PEAK_RSS_MIB: f64 = 1024.0;
}

/// The cold-run goals the project set itself (their rows name them "cold-run goal").
pub mod targets17 {
    /// Default suite, every Mesa backend, empty shader cache, 2 cores: seconds of wall time.
    pub const MESA_COLD_S: f64 = 60.0;
    /// Tests per compiled sampler state on every API path.
    pub const CHECKS_PER_STATE: f64 = 16.0;
    /// Harness cost per check after compilation on llvmpipe, microseconds.
    pub const HARNESS_US_PER_CHECK: f64 = 2.0;
    /// `judge` verdicts per second on one core.
    pub const JUDGE_PER_S: f64 = 50e6;
    /// Cold suite over its compile floor.
    pub const COLD_OVER_FLOOR: f64 = 1.2;
}

/// Compact number: 3 significant digits with SI suffix (k, M, G) for large values.
pub fn fmt_num(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if a != 0.0 && a < 1e-3 {
        return format!("{v:.1e}");
    }
    let (x, s) = if a >= 1e9 {
        (v / 1e9, "G")
    } else if a >= 1e6 {
        (v / 1e6, "M")
    } else if a >= 1e4 {
        (v / 1e3, "k")
    } else {
        (v, "")
    };
    let ax = x.abs();
    let digits = if ax >= 100.0 {
        0
    } else if ax >= 10.0 {
        1
    } else if ax >= 1.0 {
        2
    } else {
        3
    };
    format!("{x:.digits$}{s}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_compare_as_stated() {
        assert!(Target::new(Goal::AtLeast, 2.0, "x").met(2.0));
        assert!(!Target::new(Goal::Below, 2.0, "x").met(2.0));
        assert!(Target::new(Goal::AtMost, 2.0, "x").met(2.0));
        let r = Measurement::new("a", None, 1.0, "u", String::new()).with_target(Target::new(
            Goal::AtLeast,
            2.0,
            "x",
        ));
        assert_eq!(r.met, Some(false));
    }

    #[test]
    fn numbers_are_compact() {
        assert_eq!(fmt_num(50e6), "50.0M");
        assert_eq!(fmt_num(123_456.0), "123k");
        assert_eq!(fmt_num(0.5), "0.500");
        assert_eq!(fmt_num(2.5e9), "2.50G");
        assert_eq!(fmt_num(12.0), "12.0");
        assert_eq!(fmt_num(2.013e-6), "2.0e-6");
    }
}
