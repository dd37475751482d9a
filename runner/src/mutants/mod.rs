//! Mutation testing of the suite (`shadowcheck mutants`): how many seeded faults of the project's
//! own texture unit (`shadowcheck-soft`, [`Fault`]) the fixtures catch.
//!
//! Each mutant is the soft unit with exactly one fault switched on (a switchable variant, not an
//! edit of the source). Every case of the fixtures is sampled in process on every API path of the
//! case and judged against the case's stored expectation, exactly as `shadowcheck run --backend
//! soft` judges it ([`crate::verdict`]):
//!
//! - a test is **Fail** when the observation is outside the `quality` acceptance set, or when the
//!   mutant refuses (errors on) a lookup the correct unit answers (the soft backend claims every
//!   capability, and an error on a supported lookup is a Fail, see [`crate::records::Outcome`]);
//! - **Warn** when it is inside `quality` but outside `strict`.
//!
//! A mutant is **killed** when at least one test is Fail; **warn-only** when none fails but at least
//! one is Warn (a weaker kill: a CI gating on Fail would not notice); otherwise it **survived**.
//! The mutation score is killed / mutants. Before the mutants, the correct unit (the *unmutated* unit)
//! must have no Fail at all: otherwise the suite or the unit is wrong and the score means nothing.
//!
//! The **minimal killing case** of a mutant is, among its killing cases, the one with the smallest
//! [`Complexity`]: fewest texels over all levels and layers, then fewest mip levels, then fewest API
//! paths, then the shortest id, then the id in byte order (total, so the choice is deterministic).
//! The **first killing case** is the first in fixture order (files in path order, cases in file
//! order).
//!
//! For every mutant that is not killed, the soft crate's witness for the fault
//! ([`shadowcheck_soft::witness::witness`], a small case on which the fault changes the result) is
//! judged by the oracle: a witness that Fails is an observable fault and a grid change to make
//! (the witness case, or its family, belongs in the grid); a witness inside the acceptance set means
//! the fault is not observable through the API on that case either.
//!
//! Speed: each mutant samples every test once; observations bit-identical to the unmutated unit's are not
//! judged again (they have the unmutated unit's verdict, Pass or Skip). Mutants run in parallel.

pub mod catalog;
pub mod render;
mod results;
mod state;

pub use state::StateSuite;

pub use catalog::{about, grid_change, unobservable, witness};
pub use results::{
    Complexity, Kill, KillStatus, MutantResult, MutantsReport, UnmutatedResult, WitnessCheck,
};

use crate::records::Outcome;
use crate::verdict;
use shadowcheck_model::{ApiPath, Case, Judgement, Spec};
use shadowcheck_soft::{BatchResult, Fault, SoftError, SoftUnit};
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// Version of the JSON written by `shadowcheck mutants --json`.
pub const SCHEMA_VERSION: u32 = 1;

/// Errors of a mutation run.
#[derive(Debug, thiserror::Error)]
pub enum MutantsError {
    #[error("no cases to run")]
    NoCases,
    #[error("unknown mutant `{0}` (known: {known})", known = Fault::ALL.iter().map(|f| f.key()).collect::<Vec<_>>().join(", "))]
    UnknownMutant(String),
    #[error("case `{id}` has no expectation and the oracle gives none: {msg}")]
    NoExpectation { id: String, msg: String },
}

/// Parses mutant keys (`Fault::key`); an empty list means every fault.
pub fn select(keys: &[String]) -> Result<Vec<Fault>, MutantsError> {
    if keys.is_empty() {
        return Ok(Fault::ALL.to_vec());
    }
    keys.iter()
        .map(|k| Fault::from_key(k).ok_or_else(|| MutantsError::UnknownMutant(k.clone())))
        .collect()
}

/// The cases, grouped by spec (one soft unit per spec samples a contiguous run of cases), and the
/// correct unit's observations.
pub struct Suite {
    /// Cases sorted by spec (stable).
    cases: Vec<Case>,
    /// Position of each case in fixture order.
    order: Vec<usize>,
    /// Contiguous runs of one spec.
    spans: Vec<(Spec, Range<usize>)>,
    /// Case index of each test, in sampling order.
    test_case: Vec<usize>,
    /// Correct observations, in sampling order.
    unmutated: Vec<BatchResult>,
    complexity: Vec<Complexity>,
    /// TexParameter state cases (empty unless [`Suite::with_states`]).
    states: StateSuite,
}

impl Suite {
    /// Groups `cases` (in fixture order) by spec, fills missing expectations from the oracle and
    /// samples them with the correct unit.
    pub fn new(cases: Vec<Case>) -> Result<Suite, MutantsError> {
        if cases.is_empty() {
            return Err(MutantsError::NoCases);
        }
        let mut indexed: Vec<(usize, Case)> = cases.into_iter().enumerate().collect();
        indexed.sort_by_key(|(i, c)| (Spec::ALL.iter().position(|s| *s == c.spec), *i));
        let mut order = Vec::with_capacity(indexed.len());
        let mut cases = Vec::with_capacity(indexed.len());
        for (i, mut c) in indexed {
            if c.expect.is_none() {
                let ev =
                    verdict::oracle_evaluate(&c).map_err(|msg| MutantsError::NoExpectation {
                        id: c.id.clone(),
                        msg,
                    })?;
                c.expect = Some(ev.expect);
            }
            order.push(i);
            cases.push(c);
        }
        let mut spans: Vec<(Spec, Range<usize>)> = vec![];
        for (i, c) in cases.iter().enumerate() {
            match spans.last_mut() {
                Some((s, r)) if *s == c.spec => r.end = i + 1,
                _ => spans.push((c.spec, i..i + 1)),
            }
        }
        let complexity = cases.iter().map(Complexity::of).collect();
        let mut suite = Suite {
            cases,
            order,
            spans,
            test_case: vec![],
            unmutated: vec![],
            complexity,
            states: StateSuite::default(),
        };
        let unmutated = suite.sample(None);
        suite.test_case = unmutated.iter().map(|b| b.case).collect();
        suite.unmutated = unmutated;
        Ok(suite)
    }

    /// The same suite with the state cases `states` as well (sampled by each mutant's own
    /// TexParameter state, judged like `shadowcheck run --backend soft`).
    pub fn with_states(mut self, states: Vec<shadowcheck_model::StateCase>) -> Suite {
        self.states = StateSuite::new(states);
        self
    }

    pub fn cases(&self) -> usize {
        self.cases.len()
    }
    pub fn tests(&self) -> usize {
        self.unmutated.len() + self.states.tests()
    }

    /// Every test sampled by the unit with `fault` (or the correct unit), in sampling order, with
    /// `case` indices into `self.cases`.
    fn sample(&self, fault: Option<Fault>) -> Vec<BatchResult> {
        let mut out = Vec::with_capacity(self.unmutated.len().max(self.cases.len()));
        for (spec, range) in &self.spans {
            let mut unit = SoftUnit::new(*spec);
            if let Some(f) = fault {
                unit = unit.with_fault(f);
            }
            let start = out.len();
            unit.sample_batch(&self.cases[range.clone()], &mut out);
            for b in &mut out[start..] {
                b.case += range.start;
            }
        }
        out
    }

    /// Judges one observation (see the module docs for errors).
    fn judge(
        &self,
        case: &Case,
        api: ApiPath,
        rgba: &Result<[f32; 4], SoftError>,
        correct: &Result<[f32; 4], SoftError>,
    ) -> Outcome {
        match rgba {
            Ok(v) => match case
                .expect
                .as_ref()
                .and_then(|e| e.judge(api, v.map(f64::from)))
            {
                Some(Judgement::Strictest) => Outcome::Pass,
                Some(Judgement::Looser(_)) => Outcome::Warn,
                Some(Judgement::Outside) => Outcome::Fail,
                None => Outcome::Skip,
            },
            Err(_) if correct.is_ok() => Outcome::Fail,
            Err(_) => Outcome::Skip,
        }
    }

    /// A [`Kill`] record for test `t` of `results`, with the verdict's reason.
    fn kill(&self, results: &[BatchResult], t: usize, outcome: Outcome) -> Kill {
        let b = &results[t];
        let case = &self.cases[b.case];
        let correct = self
            .unmutated
            .get(t)
            .and_then(|c| c.rgba.as_ref().ok().copied());
        let reason = match &b.rgba {
            Ok(v) => verdict::judge(case, b.api, v.map(f64::from), None).reason,
            Err(e) => Some(format!("refused a lookup the correct unit answers: {e}")),
        };
        Kill {
            case: case.id.clone(),
            api: b.api,
            outcome,
            rgba: b.rgba.as_ref().ok().copied(),
            correct,
            reason,
            complexity: self.complexity[b.case].clone(),
        }
    }

    /// Judges the correct unit over every test.
    pub fn unmutated(&self) -> UnmutatedResult {
        let t0 = Instant::now();
        let mut r = UnmutatedResult::default();
        for (t, b) in self.unmutated.iter().enumerate() {
            let o = self.judge(
                &self.cases[b.case],
                b.api,
                &b.rgba,
                &Err(SoftError::UndefinedResult("unmutated")),
            );
            match o {
                Outcome::Pass => r.pass += 1,
                Outcome::Warn => r.warn += 1,
                Outcome::Fail => {
                    r.fail += 1;
                    if r.failures.len() < 20 {
                        r.failures.push(self.kill(&self.unmutated, t, o));
                    }
                }
                _ => r.skip += 1,
            }
        }
        self.states.unmutated(&mut r);
        r.seconds = t0.elapsed().as_secs_f64();
        r
    }

    /// Runs one mutant over every test.
    pub fn mutant(&self, fault: Fault) -> MutantResult {
        let t0 = Instant::now();
        let results = self.sample(Some(fault));
        // Per case: worst outcome; per status: first (fixture order) and minimal test.
        let mut worst: Vec<Outcome> = vec![Outcome::Pass; self.cases.len()];
        let (mut failing_tests, mut changed_tests) = (0, 0);
        let mut first: [Option<(usize, usize)>; 2] = [None, None]; // (fixture position, test) for Fail, Warn
        let mut minimal: [Option<usize>; 2] = [None, None];
        for (t, (b, c)) in results.iter().zip(&self.unmutated).enumerate() {
            let same = match (&b.rgba, &c.rgba) {
                (Ok(x), Ok(y)) => x.map(f32::to_bits) == y.map(f32::to_bits),
                (Err(_), Err(_)) => true,
                _ => false,
            };
            if same || b.case != c.case || b.api != c.api {
                continue;
            }
            changed_tests += 1;
            let case = &self.cases[b.case];
            let o = self.judge(case, b.api, &b.rgba, &c.rgba);
            // A test the correct unit also misses is not evidence against the mutant.
            let base = self.judge(
                case,
                c.api,
                &c.rgba,
                &Err(SoftError::UndefinedResult("unmutated")),
            );
            let slot = match o {
                Outcome::Fail if base != Outcome::Fail => 0,
                Outcome::Warn if base == Outcome::Pass => 1,
                _ => continue,
            };
            if slot == 0 {
                failing_tests += 1;
            }
            if worst[b.case] != Outcome::Fail {
                worst[b.case] = o;
            }
            let pos = self.order[b.case];
            if first[slot].is_none_or(|(p, _)| pos < p) {
                first[slot] = Some((pos, t));
            }
            let better = |m: usize| {
                let (a, z) = (&self.complexity[b.case], &self.complexity[results[m].case]);
                (a, &case.id) < (z, &self.cases[results[m].case].id)
            };
            if minimal[slot].is_none_or(better) {
                minimal[slot] = Some(t);
            }
        }
        let states = self.states.mutant(fault);
        failing_tests += states.failing_tests;
        changed_tests += states.changed_tests;
        let killing_cases =
            worst.iter().filter(|o| **o == Outcome::Fail).count() + states.killing_cases;
        let warn_cases = worst.iter().filter(|o| **o == Outcome::Warn).count();
        let (status, slot) = if killing_cases > 0 {
            (KillStatus::Killed, 0)
        } else if warn_cases > 0 {
            (KillStatus::WarnOnly, 1)
        } else {
            (KillStatus::Survived, 1)
        };
        let outcome = if slot == 0 {
            Outcome::Fail
        } else {
            Outcome::Warn
        };
        MutantResult {
            key: fault.key().to_string(),
            about: about(fault).to_string(),
            status,
            killing_cases,
            failing_tests,
            warn_cases,
            changed_tests,
            first: first[slot]
                .map(|(_, t)| self.kill(&results, t, outcome))
                .or_else(|| (slot == 0).then(|| states.first.clone()).flatten()),
            minimal: minimal[slot]
                .map(|t| self.kill(&results, t, outcome))
                .or_else(|| (slot == 0).then_some(states.first).flatten()),
            witness: None,
            unobservable: None,
            grid_change: None,
            seconds: 0.0,
        }
        .explained(fault, t0)
    }
}

impl MutantResult {
    /// Adds, for a mutant not killed, the witness check and the documented reason or grid change.
    fn explained(mut self, fault: Fault, t0: Instant) -> MutantResult {
        if self.status != KillStatus::Killed && fault.is_state() {
            // No lookup shows a TexParameter state fault: the state cases do.
            self.grid_change = Some(
                "run with the state cases (cases/fixtures/state/, `shadowcheck gen` writes them)"
                    .to_string(),
            );
        } else if self.status != KillStatus::Killed {
            let w = check_witness(fault);
            // A documented "unobservable" only stands while the oracle accepts the witness's faulty result.
            if w.mutant != Outcome::Fail {
                self.unobservable = unobservable(fault).map(str::to_string);
            }
            if self.unobservable.is_none() {
                self.grid_change =
                    Some(grid_change(fault).map(str::to_string).unwrap_or_else(|| {
                        "add the witness case below (or its family) to the grid".to_string()
                    }));
            }
            self.witness = Some(w);
        }
        self.seconds = t0.elapsed().as_secs_f64();
        self
    }
}

/// Judges the soft crate's witness of `fault` with the oracle (see the module docs).
pub fn check_witness(fault: Fault) -> WitnessCheck {
    let (mut case, api) = witness(fault);
    let unit = SoftUnit::new(case.spec);
    let judge = |r: Result<[f32; 4], SoftError>, case: &Case| match r {
        Ok(v) => {
            let j = verdict::judge(case, api, v.map(f64::from), None);
            (j.outcome, j.reason)
        }
        Err(e) => (Outcome::Skip, Some(e.to_string())),
    };
    if let Ok(ev) = verdict::oracle_evaluate(&case) {
        case.expect = Some(ev.expect);
    }
    let (correct, _) = judge(unit.sample(&case, api), &case);
    let (mutant, reason) = judge(unit.with_fault(fault).sample(&case, api), &case);
    WitnessCheck {
        case,
        api,
        correct,
        mutant,
        reason,
    }
}

/// Runs the unmutated unit and then `faults` over `suite` on `threads` threads, calling `progress` after
/// each mutant (from the worker threads, with the count done so far).
pub fn run(
    suite: &Suite,
    fixtures: &str,
    faults: &[Fault],
    threads: usize,
    progress: impl Fn(usize, &MutantResult) + Sync,
) -> MutantsReport {
    let t0 = Instant::now();
    let unmutated = suite.unmutated();
    let threads = threads.clamp(1, faults.len().max(1));
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let slots: Mutex<Vec<Option<MutantResult>>> = Mutex::new(vec![None; faults.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(&f) = faults.get(i) else { break };
                let r = suite.mutant(f);
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, &r);
                if let Ok(mut v) = slots.lock() {
                    v[i] = Some(r);
                }
            });
        }
    });
    let mutants: Vec<MutantResult> = slots
        .into_inner()
        .unwrap_or_default()
        .into_iter()
        .flatten()
        .collect();
    let count = |s: KillStatus| mutants.iter().filter(|m| m.status == s).count();
    let (killed, warn_only, survived) = (
        count(KillStatus::Killed),
        count(KillStatus::WarnOnly),
        count(KillStatus::Survived),
    );
    let unobservable = mutants.iter().filter(|m| m.unobservable.is_some()).count();
    let pct = |n: usize| {
        if mutants.is_empty() {
            0.0
        } else {
            100.0 * n as f64 / mutants.len() as f64
        }
    };
    MutantsReport {
        schema_version: SCHEMA_VERSION,
        fixtures: fixtures.to_string(),
        cases: suite.cases(),
        tests: suite.tests(),
        threads,
        unmutated,
        killed,
        warn_only,
        survived,
        unobservable,
        score_observable: if mutants.len() > unobservable {
            100.0 * killed as f64 / (mutants.len() - unobservable) as f64
        } else {
            100.0
        },
        score: pct(killed),
        score_with_warn: pct(killed + warn_only),
        mutants,
        run_seconds: t0.elapsed().as_secs_f64(),
        wall_seconds: 0.0,
    }
}

#[cfg(test)]
mod tests;
