//! Every clamping, conversion and completeness rule of the oracle is exercised by the committed
//! fixtures on every format it applies to (GL 4.6 and ES 3.2), and cases/README.md's table
//! ("Rules by format") says so.

use shadowcheck_cases::format_audit::{self, RULES};
use shadowcheck_cases::grids::specs;
use shadowcheck_cases::{fixtures, markers};
use shadowcheck_model::{Case, Format};
use std::path::PathBuf;

const BEGIN: &str = "<!-- format-audit:begin -->";
const END: &str = "<!-- format-audit:end -->";

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn committed() -> Vec<Case> {
    let dir = crate_dir().join("fixtures");
    let mut out = Vec::new();
    for p in fixtures::fixture_paths(&dir).unwrap() {
        let rel = p.strip_prefix(&dir).unwrap().to_string_lossy().to_string();
        if format_audit::SPECS
            .iter()
            .any(|s| rel.starts_with(&format!("{s}/")))
        {
            out.extend(fixtures::load_file(&p).unwrap().cases);
        }
    }
    out
}

fn formats(spec: shadowcheck_model::Spec) -> Vec<Format> {
    format_audit::spec_formats(spec, specs::dims(spec).formats)
}

#[test]
fn every_rule_is_exercised_on_every_format_it_applies_to() {
    let cases = committed();
    assert!(cases.len() > 1000, "{} cases", cases.len());
    let have = format_audit::exercised(&cases);
    let missing = format_audit::missing(&have, formats);
    assert!(
        missing.is_empty(),
        "the committed fixtures miss {} (rule, format) pairs (add them to cases/src/grids/families/formats.rs):\n{}",
        missing.len(),
        missing.join("\n")
    );
}

#[test]
fn the_audit_finds_a_missing_pair() {
    // Without the incomplete STENCIL_INDEX reads the audit names both DEPTH_STENCIL formats.
    let cases: Vec<Case> = committed()
        .into_iter()
        .filter(|c| !(c.id.contains("dsm=stencil") || c.id.contains("/stencil/")))
        .collect();
    let missing = format_audit::missing(&format_audit::exercised(&cases), formats);
    for f in ["d24s8", "d32fs8"] {
        let want = format!("gl46: rule `incomplete-stencil` on format `{f}`");
        assert!(missing.contains(&want), "{want} not in {missing:?}");
    }
    assert!(RULES.len() >= 10);
}

#[test]
fn readme_table_matches_the_fixtures() {
    let path = crate_dir().join("README.md");
    let doc = std::fs::read_to_string(&path).unwrap();
    let table = format_audit::table(&format_audit::exercised(&committed()));
    if std::env::var_os("SHADOWCHECK_WRITE_AUDIT").is_some() {
        let new = markers::replace(&doc, BEGIN, END, &table).expect("markers in cases/README.md");
        std::fs::write(&path, new).unwrap();
        return;
    }
    let have = markers::section(&doc, BEGIN, END).expect("markers in cases/README.md");
    assert_eq!(
        have.trim(),
        table.trim(),
        "cases/README.md's \"Rules by format\" table is out of date: run `SHADOWCHECK_WRITE_AUDIT=1 cargo test --release -p shadowcheck-cases --test format_audit`"
    );
}
