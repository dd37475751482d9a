//! State cases in `shadowcheck mutants`: each mutant's own TexParameter state
//! ([`SoftUnit::tex_parameter`]) judged against the state cases' expectations exactly as `shadowcheck
//! run --backend soft` judges them ([`crate::state_verdict`]). A state test the mutant answers
//! differently from the correct unit and Fails (where the correct unit passes) kills the mutant.
//!
//! A case whose expectation depends on an extension (`StateExpect::with_extension`) is also run on
//! the unit as a context exposing the extensions it implements
//! ([`shadowcheck_soft::tex_param::STATE_EXTENSIONS`]) and judged with that extension string, so the
//! extension's expectation is checked (and a fault in it seen) as well as the base one.

use super::{Complexity, Kill, UnmutatedResult};
use crate::records::Outcome;
use crate::state_verdict::{judge_state, observed_text};
use shadowcheck_model::{ApiPath, StateCase, StateObserved};
use shadowcheck_soft::tex_param::STATE_EXTENSIONS;
use shadowcheck_soft::{Fault, SoftUnit};

/// The extension string of the unit as a context: none (the soft backend's hello), or the
/// extensions it implements.
fn extensions(exposing: bool) -> &'static [&'static str] {
    if exposing {
        STATE_EXTENSIONS
    } else {
        &[]
    }
}

/// One state test: a case, its API path, whether the unit exposes its extensions, and the correct
/// unit's observation.
type Test = (usize, ApiPath, bool, StateObserved);

/// The state cases and the correct unit's observations (one per case and API path, and one more
/// exposing the extensions where the expectation depends on them).
#[derive(Default)]
pub struct StateSuite {
    cases: Vec<StateCase>,
    correct: Vec<Test>,
}

/// What a mutant did to the state tests.
#[derive(Default)]
pub(super) struct StateKills {
    pub killing_cases: usize,
    pub failing_tests: usize,
    pub changed_tests: usize,
    /// The first failing test (fixture order).
    pub first: Option<Kill>,
}

fn observe(case: &StateCase, api: ApiPath, exposing: bool, fault: Option<Fault>) -> StateObserved {
    let mut unit = SoftUnit::new(case.spec);
    if let Some(f) = fault {
        unit = unit.with_fault(f);
    }
    unit.tex_parameter_exposing(case, api, extensions(exposing))
}

fn kill(case: &StateCase, api: ApiPath, o: &StateObserved, reason: Option<String>) -> Kill {
    Kill {
        case: case.id.clone(),
        api,
        outcome: Outcome::Fail,
        rgba: None,
        correct: None,
        reason: Some(format!(
            "{} (observed {})",
            reason.unwrap_or_default(),
            observed_text(o)
        )),
        complexity: Complexity {
            texels: 0,
            levels: 0,
            paths: case.api.len(),
            id_len: case.id.len(),
        },
    }
}

impl StateSuite {
    pub fn new(cases: Vec<StateCase>) -> StateSuite {
        let correct = cases
            .iter()
            .enumerate()
            .flat_map(|(i, c)| {
                let ext = c
                    .expect
                    .as_ref()
                    .is_some_and(|e| !e.with_extension.is_empty());
                c.api.iter().flat_map(move |&a| {
                    [false, true]
                        .into_iter()
                        .filter(move |&x| !x || ext)
                        .map(move |x| (i, a, x, observe(c, a, x, None)))
                })
            })
            .collect();
        StateSuite { cases, correct }
    }

    pub fn tests(&self) -> usize {
        self.correct.len()
    }

    /// Adds the correct unit's verdicts to `r`.
    pub(super) fn unmutated(&self, r: &mut UnmutatedResult) {
        for (i, api, x, o) in &self.correct {
            let case = &self.cases[*i];
            match judge_state(case, o, extensions(*x)) {
                (Outcome::Pass, _) => r.pass += 1,
                (_, reason) => {
                    r.fail += 1;
                    if r.failures.len() < 20 {
                        r.failures.push(kill(case, *api, o, reason));
                    }
                }
            }
        }
    }

    pub(super) fn mutant(&self, fault: Fault) -> StateKills {
        let mut k = StateKills::default();
        let mut killed_case = None;
        for (i, api, x, correct) in &self.correct {
            let case = &self.cases[*i];
            let o = observe(case, *api, *x, Some(fault));
            if o == *correct {
                continue;
            }
            k.changed_tests += 1;
            let exts = extensions(*x);
            let (outcome, reason) = judge_state(case, &o, exts);
            if outcome != Outcome::Fail || judge_state(case, correct, exts).0 == Outcome::Fail {
                continue;
            }
            k.failing_tests += 1;
            if killed_case != Some(*i) {
                k.killing_cases += 1;
                killed_case = Some(*i);
            }
            if k.first.is_none() {
                k.first = Some(kill(case, *api, &o, reason));
            }
        }
        k
    }
}
