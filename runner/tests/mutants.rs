//! `shadowcheck mutants` on the smoke grid: the correct soft unit has no kill (every test Pass or
//! Skip), a seeded LEQUAL/GEQUAL swap is killed, the minimal killing case really kills it (checked
//! again here through the verdict module), a fault the cases cannot see survives and its witness
//! shows it is observable, and the command prints and writes the matrix.

mod common;
use common::*;
use shadowcheck_model::{Case, CompareFunc, Spec, Wrap};
use shadowcheck_runner::mutants::{self, render, Complexity, KillStatus, Suite};
use shadowcheck_runner::records::Outcome;
use shadowcheck_runner::verdict;
use shadowcheck_soft::{Fault, SoftUnit};

fn smoke() -> Vec<Case> {
    shadowcheck_cases::grids::generate("smoke", 0)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect()
}

#[test]
fn correct_unit_has_no_kill_and_the_lequal_gequal_swap_is_killed() {
    let cases = smoke();
    let suite = Suite::new(cases.clone()).unwrap();
    let base = suite.unmutated();
    assert_eq!(base.fail, 0, "the correct unit fails: {:?}", base.failures);
    assert_eq!(base.warn, 0);
    assert!(base.pass > 0);
    assert_eq!(base.pass + base.skip, suite.tests());

    let m = suite.mutant(Fault::LequalGequalSwapped);
    assert_eq!(m.status, KillStatus::Killed);
    assert!(m.killing_cases > 0 && m.failing_tests >= m.killing_cases);
    assert!(m.witness.is_none());

    // The minimal killing case: a LEQUAL or GEQUAL case on which the swapped unit gives a value
    // the case's expectation rejects (judged again here, independently of the mutants module).
    let min = m.minimal.clone().unwrap();
    assert_eq!(min.outcome, Outcome::Fail);
    let case = cases.iter().find(|c| c.id == min.case).unwrap();
    assert!(
        matches!(
            case.sampler.compare_func,
            CompareFunc::Lequal | CompareFunc::Gequal
        ),
        "{}",
        case.id
    );
    let bad = SoftUnit::new(case.spec)
        .with_fault(Fault::LequalGequalSwapped)
        .sample(case, min.api)
        .unwrap();
    let good = SoftUnit::new(case.spec).sample(case, min.api).unwrap();
    assert_eq!(
        verdict::judge(case, min.api, bad.map(f64::from), None).outcome,
        Outcome::Fail
    );
    assert_eq!(
        verdict::judge(case, min.api, good.map(f64::from), None).outcome,
        Outcome::Pass
    );
    assert_eq!(min.rgba, Some(bad));
    assert_eq!(min.correct, Some(good));

    // Minimal means no killing case is smaller; check against the first killing case and every
    // case of the same compare function that the mutant fails.
    let first = m.first.clone().unwrap();
    assert!((&min.complexity, &min.case) <= (&first.complexity, &first.case));
    for c in &cases {
        let unit = SoftUnit::new(c.spec).with_fault(Fault::LequalGequalSwapped);
        let fails = c.api.iter().any(|&api| match unit.sample(c, api) {
            Ok(v) => verdict::judge(c, api, v.map(f64::from), None).outcome == Outcome::Fail,
            Err(_) => false,
        });
        if fails {
            assert!(
                (&min.complexity, &min.case) <= (&Complexity::of(c), &c.id),
                "{} is smaller than {}",
                c.id,
                min.case
            );
        }
    }
}

#[test]
fn a_fault_the_cases_cannot_see_survives_and_its_witness_kills_it() {
    // The smoke cases without CLAMP_TO_BORDER or CLAMP (whose LINEAR footprint reaches the border
    // too; a bound sampler object's wraps are the ones in effect): ignoring the border cannot
    // change any of them.
    let cases: Vec<Case> = smoke()
        .into_iter()
        .filter(|c| {
            // Seamless cube filtering wraps with CLAMP_TO_BORDER too (§8.13.1) before taking
            // the neighbouring face's texel (ES, Vulkan and WebGPU cubes are always seamless).
            let seamless = c.texture.target.is_cube()
                && (matches!(c.spec, Spec::Gles32 | Spec::Vulkan | Spec::WebGpu)
                    || c.sampler.seamless == Some(true));
            let s = c.sampler.in_effect();
            let w = [s.wrap_s, s.wrap_t, s.wrap_r];
            !seamless && !w.contains(&Wrap::ClampToBorder) && !w.contains(&Wrap::Clamp)
        })
        .collect();
    assert!(!cases.is_empty());
    let suite = Suite::new(cases).unwrap();
    let m = suite.mutant(Fault::BorderIgnored);
    assert_eq!(m.status, KillStatus::Survived);
    assert_eq!((m.killing_cases, m.warn_cases, m.changed_tests), (0, 0, 0));
    assert!(m.minimal.is_none() && m.first.is_none());
    // The witness (border depth 1 next to Dt 0, LEQUAL with Dref 0.5 just past the edge) is judged
    // by the oracle: r = 1 from the border (§8.14.2), so the correct unit passes and the mutant
    // (edge texel, r = 0) fails: the fault is observable and the witness is a grid change that
    // kills it.
    let w = m.witness.unwrap();
    assert_eq!((w.correct, w.mutant), (Outcome::Pass, Outcome::Fail));
    assert_eq!(w.case.sampler.wrap_s, Wrap::ClampToBorder);
    assert!(w.reason.unwrap().contains("r = 0"));
}

#[test]
fn unobservable_faults_are_told_apart_from_grid_gaps() {
    // Only the smoke cases of GL 4.6 with LEQUAL: neither fault below changes any of them.
    let cases: Vec<Case> = smoke()
        .into_iter()
        .filter(|c| c.sampler.compare_func == CompareFunc::Lequal)
        .collect();
    let suite = Suite::new(cases).unwrap();
    // NaN references: every comparison table orders Dref and Dt, so the oracle accepts 0 and 1;
    // an ordered NOTEQUAL cannot be told from IEEE != through the API.
    let nan = suite.mutant(Fault::NanOrderedNotequal);
    assert_eq!(nan.status, KillStatus::Survived);
    assert!(nan.unobservable.as_deref().unwrap().contains("NaN"));
    assert!(nan.grid_change.is_none());
    assert_ne!(nan.witness.unwrap().mutant, Outcome::Fail);
    // Dt not clamped for fixed-point formats: undefined in GL 4.6 (out-of-range border), but
    // ARB_shadow puts Dt in [0,1]: border 1.5 reads as 1, so GEQUAL with R = 1 gives 1, the
    // mutant 0. Observable: a grid change, with a witness that the oracle rejects.
    let dt = suite.mutant(Fault::DtNotClamped);
    assert!(dt.unobservable.is_none());
    assert!(dt.grid_change.as_deref().unwrap().contains("border 1.5"));
    let w = dt.witness.unwrap();
    assert_eq!(
        (w.case.spec, w.correct, w.mutant),
        (shadowcheck_model::Spec::Arb, Outcome::Pass, Outcome::Fail)
    );
    assert!(w.reason.unwrap().contains("r = 0 (expected r in {1})"));
}

#[test]
fn run_reports_score_matrix_and_markdown() {
    let suite = Suite::new(smoke()).unwrap();
    let faults = [
        Fault::LequalGequalSwapped,
        Fault::LessAsLequal,
        Fault::AlwaysNeverSwapped,
    ];
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let r = mutants::run(&suite, "grid smoke", &faults, 2, |_, _| {
        calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    });
    assert_eq!(calls.into_inner(), 3);
    assert_eq!(
        r.mutants.iter().map(|m| m.key.as_str()).collect::<Vec<_>>(),
        [
            "lequal-gequal-swapped",
            "less-as-lequal",
            "always-never-swapped"
        ]
    );
    assert_eq!(r.killed + r.warn_only + r.survived, 3);
    assert_eq!(r.score, 100.0 * r.killed as f64 / 3.0);
    assert!(r.unmutated.ok());
    let md = render::markdown(&r, "shadowcheck mutants --grid smoke");
    assert!(md.contains("| 1 | `lequal-gequal-swapped` |"), "{md}");
    let min = r.mutants[0].minimal.as_ref().unwrap();
    assert!(md.contains(&format!("`{}`", min.case)));
    assert!(render::table(&r).contains("lequal-gequal-swapped"));
    // The README section: same rows, no timings (it must not change from run to run).
    let sec = render::readme_section(&r);
    assert!(
        sec.contains(&format!(
            "| 1 | `lequal-gequal-swapped` | {} | killed | `{}` |",
            mutants::about(faults[0]),
            min.case
        )),
        "{sec}"
    );
    assert!(!sec.contains(" s ") && !sec.contains("threads"), "{sec}");
}

#[test]
fn mutant_keys_are_checked() {
    assert_eq!(mutants::select(&[]).unwrap().len(), Fault::ALL.len());
    assert_eq!(
        mutants::select(&["less-as-lequal".into()]).unwrap(),
        vec![Fault::LessAsLequal]
    );
    assert!(mutants::select(&["no-such-fault".into()])
        .unwrap_err()
        .to_string()
        .contains("less-as-lequal"));
    assert!(Fault::ALL.len() >= 30);
    for f in Fault::ALL {
        assert!(!mutants::about(*f).is_empty(), "{f} has no description");
    }
}

#[test]
fn cli_runs_one_mutant_on_the_smoke_grid_and_writes_markdown() {
    let tmp = tmpdir("mutants-cli");
    let md = tmp.join("MUTANTS.md");
    let o = bin()
        .args([
            "mutants",
            "--grid",
            "smoke",
            "--mutant",
            "lequal-gequal-swapped",
            "--json",
            "-q",
            "--markdown",
        ])
        .arg(&md)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["killed"], 1);
    assert_eq!(v["score"], 100.0);
    assert_eq!(v["unmutated"]["fail"], 0);
    assert_eq!(v["mutants"][0]["status"], "killed");
    assert!(v["mutants"][0]["minimal"]["case"].as_str().is_some());
    let text = std::fs::read_to_string(&md).unwrap();
    assert!(
        text.contains("**Mutation score: 100.0 % (1 of 1 mutants killed)**"),
        "{text}"
    );

    let o = bin()
        .args(["mutants", "--grid", "smoke", "--mutant", "no-such-fault"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(96));
    assert!(String::from_utf8_lossy(&o.stderr).contains("unknown mutant"));

    // --update-readme on a file without the markers: a setup error naming the file, file untouched.
    let plain = tmp.join("PLAIN.md");
    std::fs::write(&plain, "# no markers here\n").unwrap();
    let o = bin()
        .args([
            "mutants",
            "--grid",
            "smoke",
            "--mutant",
            "less-as-lequal",
            "-q",
            "--update-readme",
        ])
        .arg(&plain)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(96));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("PLAIN.md") && err.contains("no kill-matrix markers"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(&plain).unwrap(),
        "# no markers here\n"
    );
}

#[test]
fn the_committed_default_fixtures_kill_every_observable_mutant() {
    // Must show: over cases/fixtures every fault is killed (a Fail, not only a Warn), except the
    // ones documented as unobservable through the API, and the correct unit has no Fail.
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf();
    // The kill matrix in README.md is generated: regenerate it into a copy and compare.
    let readme = root.join("README.md");
    let copy = tmpdir("mutants-readme").join("README.md");
    std::fs::copy(&readme, &copy).unwrap();
    let o = bin()
        .current_dir(&root)
        .args(["mutants", "--json", "-q", "--update-readme"])
        .arg(&copy)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["unmutated"]["fail"], 0);
    assert_eq!(v["unmutated"]["warn"], 0);
    let ms = v["mutants"].as_array().unwrap();
    assert_eq!(ms.len(), Fault::ALL.len());
    for m in ms {
        assert!(
            m["status"] == "killed" || m["unobservable"].is_string(),
            "{} not killed: {m}",
            m["key"]
        );
        if m["status"] == "killed" {
            assert!(m["minimal"]["case"].is_string() && m["killing_cases"].as_u64().unwrap() > 0);
        }
    }
    assert_eq!(v["score_observable"], 100.0);
    assert!(
        std::fs::read_to_string(&copy).unwrap() == std::fs::read_to_string(&readme).unwrap(),
        "the kill matrix in README.md is stale: run `cargo run --release -- mutants --markdown reports/MUTANTS.md --update-readme README.md`"
    );
}

#[test]
fn state_faults_are_killed_by_the_state_cases_and_the_correct_state_passes() {
    let mut cases = Vec::new();
    let mut states = Vec::new();
    for (_, f) in shadowcheck_cases::grids::generate("smoke", 0).unwrap() {
        cases.extend(f.cases);
        states.extend(f.state_cases);
    }
    assert!(!states.is_empty());
    let suite = Suite::new(cases).unwrap().with_states(states.clone());
    let base = suite.unmutated();
    assert_eq!(base.fail, 0, "the correct unit fails: {:?}", base.failures);
    for f in [Fault::WrongInitialCompareFunc, Fault::IllegalValueStored] {
        let m = suite.mutant(f);
        assert_eq!(m.status, KillStatus::Killed, "{f}: {m:?}");
        let k = m.first.unwrap();
        assert!(k.case.starts_with("state/"), "{f}: {}", k.case);
        assert!(k.reason.unwrap_or_default().contains("expected"), "{f}");
    }
    // Without the state cases no lookup sees them: survived, pointing at the state cases.
    let lookups_only = Suite::new(smoke()).unwrap();
    let m = lookups_only.mutant(Fault::IllegalValueStored);
    assert_eq!(m.status, KillStatus::Survived);
    assert!(m.grid_change.unwrap_or_default().contains("state cases"));
}

/// The Vulkan fixtures alone kill the faults a Vulkan driver or a translation layer on Vulkan can
/// plausibly have: Dref clamped for D32_SFLOAT (Vulkan clamps only UNORM), texel and gather
/// offsets ignored (zink drops non-constant gather offsets without shaderImageGatherExtended),
/// the gather order, the depth border taken from another component than Br, and cube-map edge
/// handling done per face (GL's non-seamless default under Vulkan).
#[test]
fn the_vulkan_fixtures_alone_kill_the_vulkan_faults() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures/vulkan");
    let cases: Vec<Case> = shadowcheck_cases::fixtures::load_path(&root)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect();
    assert!(cases.iter().all(|c| c.spec == Spec::Vulkan) && cases.len() > 1000);
    let suite = Suite::new(cases).unwrap();
    let base = suite.unmutated();
    assert_eq!((base.fail, base.warn), (0, 0), "{:?}", base.failures);
    for f in [
        Fault::RefClampedForFloat,
        Fault::OffsetIgnored,
        Fault::GatherOrderRotated,
        Fault::BorderDepthFromAlpha,
        Fault::VkCubeEdgePerFace,
    ] {
        let m = suite.mutant(f);
        assert_eq!(m.status, KillStatus::Killed, "{f:?}");
        let min = m.minimal.unwrap();
        assert!(min.case.starts_with("vulkan/"), "{}", min.case);
    }
}

/// The WebGPU fixtures alone kill the faults a WebGPU implementation can plausibly have:
/// GPUCompareFunction applied as texel OP depth_ref, WGSL's array_index wrapped instead of
/// clamped, cube views filtered per face (a GL backend without TEXTURE_CUBE_MAP_SEAMLESS) and a
/// cube array's index counted in layers. The faults belong to the WebGPU variant only: a unit for
/// another spec ignores them, so no other fixture can kill them.
#[test]
fn the_webgpu_fixtures_alone_kill_the_webgpu_faults() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures/webgpu");
    let cases: Vec<Case> = shadowcheck_cases::fixtures::load_path(&root)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect();
    assert!(cases.iter().all(|c| c.spec == Spec::WebGpu) && cases.len() > 1000);
    let suite = Suite::new(cases).unwrap();
    let base = suite.unmutated();
    assert_eq!(
        (base.fail, base.warn, base.skip),
        (0, 0, 0),
        "{:?}",
        base.failures
    );
    let webgpu_only: Vec<Fault> = Fault::ALL
        .iter()
        .copied()
        .filter(|f| f.spec() == Some(Spec::WebGpu))
        .collect();
    assert_eq!(
        webgpu_only,
        [
            Fault::WgpuCompareOperandsSwapped,
            Fault::WgpuArrayIndexWrapped,
            Fault::WgpuCubePerFace,
            Fault::WgpuCubeArrayIndexAsLayer,
        ]
    );
    for f in webgpu_only {
        let m = suite.mutant(f);
        assert_eq!(m.status, KillStatus::Killed, "{f:?}");
        let min = m.minimal.unwrap();
        assert!(min.case.starts_with("webgpu/"), "{}", min.case);
        // A unit for another spec does not take the fault.
        assert!(SoftUnit::new(Spec::Gl46).with_fault(f).faults().is_empty());
    }
}
