//! `soft` and `soft:<spec>`: the project's own texture unit (shadowcheck-soft), in process.
//!
//! `soft:<spec>` runs one specification variant; cases written for another spec are not
//! applicable to it (its capabilities list that one spec);
//! `soft` runs each case under its own spec's variant. In-process and allocation-light: one
//! `SoftUnit` per spec, built once; each lookup returns four f32 channels.

use super::{ApiAnswer, Backend, BackendError, Capabilities, CaseAnswer, Sent};
use shadowcheck_model::{Spec, StateCase};
use shadowcheck_soft::SoftUnit;

pub struct SoftBackend {
    name: String,
    /// `Some(spec)` for `soft:<spec>`.
    only: Option<Spec>,
    /// One unit per spec, indexed like `Spec::ALL`, built on first use.
    units: Vec<Option<SoftUnit>>,
    caps: Capabilities,
}

impl SoftBackend {
    /// `variant`: empty for `soft`, a spec key for `soft:<spec>`.
    pub fn new(name: &str, variant: &str) -> Result<SoftBackend, BackendError> {
        let only = if variant.is_empty() {
            None
        } else {
            Some(Spec::from_key(variant).ok_or_else(|| BackendError::Setup {
                backend: name.to_string(),
                msg: format!(
                    "unknown soft variant `{variant}` (expected one of: {})",
                    Spec::ALL.iter().map(|s| s.key()).collect::<Vec<_>>().join(", ")
                ),
            })?)
        };
        Ok(SoftBackend {
            name: name.to_string(),
            only,
            units: Spec::ALL.iter().map(|_| None).collect(),
            caps: Capabilities {
                specs: only.map(|s| vec![s.key().to_string()]),
                ..Capabilities::all()
            },
        })
    }

    fn unit(&mut self, spec: Spec) -> &SoftUnit {
        let i = Spec::ALL.iter().position(|s| *s == spec).unwrap_or(0);
        self.units[i].get_or_insert_with(|| SoftUnit::new(spec))
    }

    fn run_one(&mut self, sent: Sent<'_>) -> CaseAnswer {
        let case = sent.case;
        if let Some(only) = self.only {
            if case.spec != only {
                return CaseAnswer::Skip(format!("case is for spec {}", case.spec));
            }
        }
        let unit = self.unit(case.spec);
        let results = sent
            .api
            .iter()
            .map(|&api| {
                let sampled = if case.sweep.is_empty() {
                    unit.sample(case, api).map(|v| vec![v])
                } else {
                    unit.sample_sweep(case, api)
                };
                let out = match sampled {
                    Ok(v) => ApiAnswer::Rgba {
                        rgba: v.first().map_or([f64::NAN; 4], |v| v.map(f64::from)),
                        stored: None,
                        sweep: v.iter().skip(1).map(|v| v.map(f64::from)).collect(),
                    },
                    Err(e) => ApiAnswer::Skip(e.to_string()),
                };
                (api, out)
            })
            .collect();
        CaseAnswer::Observed(results)
    }
}

impl Backend for SoftBackend {
    fn compiles_per_state(&self) -> bool {
        false
    }
    fn name(&self) -> &str {
        &self.name
    }
    fn capabilities(&self) -> &Capabilities {
        &self.caps
    }
    fn batch_size(&self) -> usize {
        1024
    }
    fn answer_batch(&mut self, cases: &[Sent<'_>]) -> Vec<CaseAnswer> {
        cases.iter().map(|c| self.run_one(*c)).collect()
    }
    /// The soft unit's own TexParameter state (`shadowcheck_soft::tex_param`).
    fn answer_state_batch(&mut self, cases: &[&StateCase]) -> Vec<CaseAnswer> {
        cases
            .iter()
            .map(|c| match self.only {
                Some(only) if c.spec != only => {
                    CaseAnswer::Skip(format!("case is for spec {}", c.spec))
                }
                _ => {
                    let unit = SoftUnit::new(c.spec);
                    CaseAnswer::Observed(
                        c.api
                            .iter()
                            .map(|&a| (a, ApiAnswer::State(unit.tex_parameter(c, a))))
                            .collect(),
                    )
                }
            })
            .collect()
    }
}
