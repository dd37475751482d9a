//! What `shadowcheck mutants` reports (the serde types of `--json` and of reports/MUTANTS.md): per
//! mutant its kill status, the killing cases and, for a survivor, the witness check; the unmutated
//! unit's own result.

use crate::records::Outcome;
use serde::Serialize;
use shadowcheck_model::{ApiPath, Case};

/// How simple a case is, for choosing the minimal killing case (see the module docs). Ordered
/// field by field.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub struct Complexity {
    /// Texels over all levels and layers.
    pub texels: usize,
    /// Mip levels given.
    pub levels: usize,
    /// API paths of the case.
    pub paths: usize,
    /// Length of the id.
    pub id_len: usize,
}

impl Complexity {
    pub fn of(case: &Case) -> Complexity {
        Complexity {
            texels: case.texture.levels.iter().map(|l| l.texel_count()).sum(),
            levels: case.texture.levels.len(),
            paths: case.api.len(),
            id_len: case.id.len(),
        }
    }
}

/// One test (case on one API path) that a mutant fails or warns on.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Kill {
    /// Case id.
    pub case: String,
    pub api: ApiPath,
    /// Fail or Warn.
    pub outcome: Outcome,
    /// What the mutant returned (`None` when it refused the lookup).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rgba: Option<[f32; 4]>,
    /// What the correct unit returned.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub correct: Option<[f32; 4]>,
    /// The verdict's reason (which channel misses which acceptance set) or the mutant's error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    pub complexity: Complexity,
}

/// The result class of a mutant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum KillStatus {
    /// At least one test Fails.
    Killed,
    /// No test Fails, at least one Warns.
    WarnOnly,
    /// Every test Passes (or is skipped as for the correct unit).
    Survived,
}

impl KillStatus {
    pub fn as_str(self) -> &'static str {
        match self {
            KillStatus::Killed => "killed",
            KillStatus::WarnOnly => "warn-only",
            KillStatus::Survived => "SURVIVED",
        }
    }
}

/// The fault's witness (a small case on which it changes the result) judged by the oracle; filled
/// for mutants that are not killed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WitnessCheck {
    /// The witness case as JSON (its id is `witness`), ready to add to a grid.
    pub case: Case,
    pub api: ApiPath,
    /// Verdict on the correct unit's result (expected Pass).
    pub correct: Outcome,
    /// Verdict on the mutant's result: Fail means the fault is observable and this case kills it.
    pub mutant: Outcome,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// What one mutant did over the suite.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MutantResult {
    /// `Fault::key`.
    pub key: String,
    /// The real-world defect the fault is modelled on.
    pub about: String,
    pub status: KillStatus,
    /// Cases with at least one Fail test.
    pub killing_cases: usize,
    /// Tests (case × API path) that Fail.
    pub failing_tests: usize,
    /// Cases with a Warn test and no Fail test.
    pub warn_cases: usize,
    /// Tests whose observation differs from the correct unit's (bitwise), judged or not.
    pub changed_tests: usize,
    /// First killing case in fixture order (a Warn case for warn-only mutants).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first: Option<Kill>,
    /// Minimal killing case (a Warn case for warn-only mutants).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub minimal: Option<Kill>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<WitnessCheck>,
    /// For a mutant not killed: why the fault cannot be observed through the API ([`unobservable`]),
    /// when that is documented and the witness agrees (the oracle accepts the faulty result).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unobservable: Option<String>,
    /// For a mutant not killed and observable: the grid change that kills it ([`grid_change`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid_change: Option<String>,
    pub seconds: f64,
}

/// What the correct unit did over the suite.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct UnmutatedResult {
    pub pass: usize,
    pub warn: usize,
    pub fail: usize,
    /// Tests the unit does not answer (an API path or state the spec lacks): skipped for every
    /// mutant too, unless the mutant answers them (not judged).
    pub skip: usize,
    /// The first failing tests (at most 20), with reasons.
    pub failures: Vec<Kill>,
    pub seconds: f64,
}

impl UnmutatedResult {
    pub fn ok(&self) -> bool {
        self.fail == 0
    }
}

/// The whole run: `shadowcheck mutants --json` writes this.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MutantsReport {
    pub schema_version: u32,
    /// Where the cases came from (fixture path or grid name).
    pub fixtures: String,
    pub cases: usize,
    pub tests: usize,
    pub threads: usize,
    pub unmutated: UnmutatedResult,
    pub mutants: Vec<MutantResult>,
    pub killed: usize,
    pub warn_only: usize,
    pub survived: usize,
    /// Mutants not killed whose fault cannot be observed through the API (documented reason).
    pub unobservable: usize,
    /// killed / mutants, in percent.
    pub score: f64,
    /// (killed + warn-only) / mutants, in percent.
    pub score_with_warn: f64,
    /// killed / (mutants - unobservable), in percent: the score over the faults an application can see.
    pub score_observable: f64,
    /// Seconds for sampling and judging (unmutated unit + mutants).
    pub run_seconds: f64,
    /// Seconds for the whole command, loading included (set by the command).
    pub wall_seconds: f64,
}
