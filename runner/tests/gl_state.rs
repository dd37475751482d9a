//! TexParameter / GetTexParameter state cases (`cases/fixtures/state/`) through `shadowcheck run`
//! on every driver and context kind (EGL core, compat, es3; OSMesa core, compat): the GL worker
//! only observes, the runner judges against the oracle's expectations in the fixtures (re-derived
//! from the oracle's tables when they load), and every state test of the context passes.
mod common;
mod gl_support;
use gl_support::*;
use shadowcheck_model::ApiPath;
use std::path::{Path, PathBuf};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures")
}

/// The state tests of the committed fixtures that run in a context of kind `api` (their API path).
fn expected_tests(path: ApiPath) -> Vec<String> {
    let files = shadowcheck_cases::fixtures::load_path(&fixtures().join("state"))
        .unwrap_or_else(|e| panic!("{e}"));
    let mut v: Vec<String> = files
        .iter()
        .flat_map(|(_, f)| f.state_cases.iter())
        .filter(|c| c.api.contains(&path))
        .map(|c| format!("{}@{}", c.id, path.key()))
        .collect();
    v.sort();
    v
}

#[test]
fn state_cases_pass_on_every_mesa_context_through_run() {
    let mut names = Vec::new();
    for api in ["core", "compat", "es3"] {
        names.extend(backends(api, api != "es3"));
    }
    for b in names {
        if let Err(e) = shadowcheck_runner::backend::gl::worker_command(&b) {
            unavailable(&b, &e.to_string());
            continue;
        }
        let path = match b.rsplit(':').next() {
            Some("core") => ApiPath::GlslCore,
            Some("compat") => ApiPath::FixedFunction,
            _ => ApiPath::Es300,
        };
        let out = common::tmpdir(&format!("state-{}", b.replace(':', "-")));
        let fx = fixtures().display().to_string();
        let outs = out.display().to_string();
        let r = common::run(&[
            "--backend",
            &b,
            "--fixtures",
            &fx,
            "--cases",
            "^state/",
            "--out",
            &outs,
        ]);
        if r.code == 96 && r.stderr.contains("cannot start") {
            unavailable(&b, r.stderr.trim());
            continue;
        }
        assert_eq!(r.code, 0, "{b}: {}\n{}", r.stdout, r.stderr);
        let rows = common::results(&out);
        let mut tests: Vec<String> = rows.iter().map(|r| r.0.clone()).collect();
        tests.sort();
        // Every state test of this context kind ran (TEXTURE_COMPARE_MODE, _FUNC and the pnames
        // the context lacks at least), and nothing else.
        let want = expected_tests(path);
        assert!(want.len() >= 60, "{b}: only {} state tests", want.len());
        assert_eq!(tests, want, "{b}");
        let bad: Vec<String> = rows
            .iter()
            .filter(|r| r.1 != "Pass")
            .map(|r| format!("{} {}", r.0, r.1))
            .collect();
        assert!(bad.is_empty(), "{b}:\n{}", bad.join("\n"));
    }
}

/// `repro::subject` is for lookup cases: a state case is named as such, and `repro::reproducer`
/// gives its state reproducer (`runner/src/repro/state.rs`; built and run in tests/gl_repro.rs).
#[test]
fn repro_writes_a_state_case_through_its_own_reproducer() {
    let (backend, test) = (
        "egl:llvmpipe:core",
        "state/gl46/core/2d/compare_mode/initial@core",
    );
    let fixtures = [fixtures().join("state")];
    let e = shadowcheck_runner::repro::subject(backend, test, &fixtures)
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(e.contains("TexParameter state case"), "{e}");
    let r = shadowcheck_runner::repro::reproducer(backend, test, &fixtures);
    assert!(
        matches!(r, Ok(shadowcheck_runner::repro::Reproducer::State(_))),
        "{r:?}"
    );
}
