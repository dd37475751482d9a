//! [`Reproducer`]: a lookup case's or a TexParameter state case's reproducer, what `shadowcheck
//! repro` writes, runs and judges for either; and which test a Fail record's reproducer is for
//! ([`failing_test`]: a sweep point's, where the verdict found the Fail there).

use super::{
    backend_packages, c_build_sh, csource, io, keys, report, run_build_sh, state, webgl, webgpu,
    write_sources, Backend, ReproError, RunOutput, Subject, BUILD_SH, REPRO_C,
};
use shadowcheck_model::ApiPath;
use std::path::{Path, PathBuf};

/// The subject of a state case: a GL backend, a path the case lists, the oracle's expectation.
pub(super) fn state_subject(
    name: Backend,
    l: &crate::run::LoadedState,
    file: &str,
    api: ApiPath,
    lib_dir: Option<PathBuf>,
) -> Result<state::StateSubject, ReproError> {
    let case = l.case.clone();
    if !matches!(name, Backend::Gl(_) | Backend::Webgl(_)) {
        return Err(ReproError::BadBackend(format!(
            "`{}` is a TexParameter state case: it runs on the GL and WebGL backends, not on {name}",
            case.id
        )));
    }
    let backend = name;
    if !case.api.contains(&api) {
        return Err(ReproError::NoPath {
            id: case.id,
            api: api.key().into(),
            listed: keys(&case.api),
        });
    }
    let expect =
        shadowcheck_oracle::state::expect_state(&case).map_err(ReproError::NoExpectation)?;
    Ok(state::StateSubject {
        backend,
        case,
        api,
        expect,
        fixture: PathBuf::from(file),
        lib_dir,
    })
}

/// A reproducer's subject: a lookup case or a TexParameter state case.
#[derive(Debug, Clone)]
pub enum Reproducer {
    Lookup(Box<Subject>),
    State(Box<state::StateSubject>),
}

/// The runner's verdict on what a reproducer printed.
#[derive(Debug, Clone)]
pub enum Judgement {
    Lookup(crate::verdict::Judged),
    State(crate::records::Outcome, Option<String>),
}

impl Judgement {
    pub fn outcome(&self) -> crate::records::Outcome {
        match self {
            Judgement::Lookup(j) => j.outcome,
            Judgement::State(o, _) => *o,
        }
    }
}

impl Reproducer {
    /// `<case id>@<api>`.
    pub fn test(&self) -> String {
        match self {
            Reproducer::Lookup(s) => s.test(),
            Reproducer::State(s) => s.test(),
        }
    }
    pub fn backend(&self) -> Backend {
        match self {
            Reproducer::Lookup(s) => s.backend,
            Reproducer::State(s) => s.backend,
        }
    }
    /// The program file: repro.c or repro.html.
    pub fn program_file(&self) -> &'static str {
        match self {
            Reproducer::Lookup(s) => super::program_file(s),
            Reproducer::State(s) if matches!(s.backend, Backend::Webgl(_)) => webgpu::REPRO_HTML,
            Reproducer::State(_) => REPRO_C,
        }
    }
    /// Writes the program and build.sh into `dir` (created).
    pub fn write_sources(&self, dir: &Path) -> Result<(), ReproError> {
        let s = match self {
            Reproducer::Lookup(s) => return write_sources(s, dir),
            Reproducer::State(s) => s,
        };
        std::fs::create_dir_all(dir).map_err(io(format!("creating {}", dir.display())))?;
        let b = match s.backend {
            Backend::Gl(b) => b,
            Backend::Webgl(k) => {
                let page = state::page(s, k).map_err(ReproError::NotPlanned)?;
                std::fs::write(dir.join(webgpu::REPRO_HTML), page)
                    .map_err(io("writing repro.html"))?;
                std::fs::write(dir.join(BUILD_SH), webgl::script(&s.test(), k))
                    .map_err(io("writing build.sh"))?;
                return Ok(());
            }
            Backend::Vk(_) | Backend::Webgpu(_) => {
                return Err(ReproError::BadBackend(format!(
                    "a state case does not run on {}",
                    s.backend
                )))
            }
        };
        std::fs::write(dir.join(REPRO_C), state::program(s, b)).map_err(io("writing repro.c"))?;
        let lib_dir = s.lib_dir.as_deref();
        let sh = c_build_sh(
            &s.test(),
            s.backend,
            lib_dir,
            &csource::build_line(b, lib_dir),
            &csource::env_words(b, lib_dir),
        );
        std::fs::write(dir.join(BUILD_SH), sh).map_err(io("writing build.sh"))?;
        Ok(())
    }
    /// Runs the reproducer written in `dir` and judges what it printed as the runner does.
    pub fn run(&self, dir: &Path) -> Result<(RunOutput, Judgement), ReproError> {
        let run = run_build_sh(self.backend(), dir)?;
        let unread = || ReproError::Setup {
            code: run.code,
            log: format!(
                "the reproducer printed no `observed:` line the verdict can read:\n{}{}",
                run.stdout, run.stderr
            ),
        };
        let judged = match self {
            Reproducer::Lookup(s) => {
                let observed = run.observed().ok_or_else(unread)?;
                Judgement::Lookup(crate::verdict::judge(&s.case, s.api, observed, None))
            }
            Reproducer::State(s) => {
                let (o, why) = state::judge(s, &run).ok_or_else(unread)?;
                Judgement::State(o, why)
            }
        };
        Ok((run, judged))
    }
    /// REPORT.md.
    pub fn report(&self, run: &RunOutput, j: &Judgement) -> String {
        match (self, j) {
            (Reproducer::Lookup(s), Judgement::Lookup(judged)) => {
                report::render(s, run, judged, &report::package_versions(s))
            }
            (Reproducer::State(s), Judgement::State(_, reason)) => state::report(
                s,
                run,
                reason.as_deref().unwrap_or("as required"),
                &report::versions_of(&backend_packages(s.backend)),
            ),
            // A judgement of the other kind is never made ([`Reproducer::run`]).
            (Reproducer::Lookup(_), Judgement::State(..))
            | (Reproducer::State(_), Judgement::Lookup(_)) => String::new(),
        }
    }
}

/// The test a reproducer of a Fail record is written for: the record's own, or, when the verdict
/// found the Fail at a sweep point (`sweep point <k> (...)`, `verdict::judge_sweep`), that point's
/// (`<case id>/sweep=<k>@<api>`), whose lookup gave the RGBA the record holds.
pub fn failing_test(r: &crate::records::TestResult) -> String {
    let k = r
        .reason
        .as_deref()
        .and_then(|why| why.strip_prefix("sweep point "))
        .and_then(|rest| rest.split_once(' '))
        .and_then(|(k, _)| k.parse::<usize>().ok());
    match k {
        Some(k) => format!(
            "{}{}{k}@{}",
            r.case_id,
            shadowcheck_model::sweep::SWEEP_ID_TAG,
            r.api.key()
        ),
        None => r.test.clone(),
    }
}
