//! Must show: each `soft:<variant>` backend over the default fixtures (cases/fixtures, the cases
//! crate's committed output with the oracle's expectations) passes every case of its own spec
//! under the strict profile, and exits 0. Fails (never skips) when the fixtures are missing.

mod common;
use common::*;
use shadowcheck_model::Spec;
use std::path::PathBuf;

fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

#[test]
fn every_soft_variant_passes_its_own_specs_fixtures_under_strict() {
    let root = workspace();
    let fixtures = root.join("cases/fixtures");
    assert!(
        fixtures.is_dir(),
        "{} is missing: generate it with `shadowcheck gen` (the cases crate commits it)",
        fixtures.display()
    );
    let tmp = tmpdir("soft-fixtures");
    let mut covered = 0;
    for spec in Spec::ALL {
        let out = tmp.join(spec.key());
        // The generator writes one folder per spec; load only that one when it is there.
        let spec_dir = fixtures.join(spec.key());
        let from = if spec_dir.is_dir() {
            spec_dir
        } else {
            fixtures.clone()
        };
        let o = bin()
            .current_dir(&root)
            .args([
                "run",
                "--backend",
                &format!("soft:{}", spec.key()),
                "--cases",
                &format!("^{}/", spec.key()),
            ])
            .args(["--fixtures", from.to_str().unwrap()])
            .args(["--out", out.to_str().unwrap(), "--full-report"])
            .output()
            .unwrap();
        let r = Run::of(o);
        let report: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap())
                .unwrap();
        let results = report["results"].as_array().unwrap();
        let own: Vec<&serde_json::Value> = results
            .iter()
            .filter(|t| t["tags"]["spec"] == spec.key())
            .collect();
        assert!(!own.is_empty(), "no fixture case for spec {spec}");
        let not_pass: Vec<String> = own
            .iter()
            .filter(|t| t["status"] != "Pass")
            .take(5)
            .map(|t| format!("{} {} {}", t["test"], t["status"], t["reason"]))
            .collect();
        assert!(
            not_pass.is_empty(),
            "soft:{spec}: not Pass under strict:\n{}\n{}",
            not_pass.join("\n"),
            r.stdout
        );
        assert_eq!(r.code, 0, "soft:{spec}: {}{}", r.stdout, r.stderr);
        covered += own.len();
    }
    // The TexParameter state cases (cases/fixtures/state/), answered by soft's own state table.
    let out = tmp.join("state");
    let r = Run::of(
        bin()
            .current_dir(&root)
            .args(["run", "--backend", "soft", "--fixtures"])
            .arg(fixtures.join("state"))
            .args(["--out", out.to_str().unwrap(), "--full-report"])
            .output()
            .unwrap(),
    );
    assert_eq!(
        r.code, 0,
        "soft on the state cases: {}{}",
        r.stdout, r.stderr
    );
    let state = results(&out);
    assert!(state.len() >= 250, "{} state tests", state.len());
    assert!(state.iter().all(|t| t.1 == "Pass"), "{state:?}");
    covered += state.len();
    // The same cases through `soft` (each case under its own spec): everything passes at once.
    let out = tmp.join("all");
    let r = Run::of(
        bin()
            .current_dir(&root)
            .args(["run", "--backend", "soft", "--out", out.to_str().unwrap()])
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 0, "soft: {}{}", r.stdout, r.stderr);
    assert_eq!(
        results(&out).len(),
        covered,
        "every fixture case belongs to exactly one spec and was covered once"
    );
}
