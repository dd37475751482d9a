//! A fixture's `expect` is re-derived with the linked oracle when it loads (`cases/src/recheck.rs`): a
//! tampered expectation stops that case with an error naming the file, the case, the field and the
//! command that regenerates, and the run exits with the setup code 96.

mod common;
use common::*;
use shadowcheck_model::*;

#[test]
fn a_tampered_expectation_stops_the_case_with_the_regenerate_command() {
    let dir = tmpdir("stale-fixture");
    let good = nearest_case(CompareFunc::Lequal, 1, 1, 0.5);
    // Dref 0.5 <= Dt 1: r = 1 (GL 4.6 Table 8.23). The edit claims 0 under strict.
    let mut bad = nearest_case(CompareFunc::Lequal, 0, 0, 0.5);
    bad.id = format!("{}/tampered", bad.id);
    if let Some(e) = bad.expect.as_mut() {
        e.accept
            .insert(Profile::Strict, Acceptance(vec![Interval::point(1.0)]));
    }
    let fixture = dir.join("f.json");
    write_fixture(&fixture, vec![good.clone(), bad.clone()]);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "soft",
        "--fixtures",
        fixture.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    let all = format!("{}{}", r.stdout, r.stderr);
    for needle in [
        fixture.display().to_string(),
        format!("`{}`", bad.id),
        "field `expect.accept.strict`".to_string(),
        "the fixture is stale or was edited".to_string(),
        "shadowcheck gen --grid test".to_string(),
    ] {
        assert!(all.contains(&needle), "missing {needle:?} in:\n{all}");
    }
    // The untouched case still runs and passes; the tampered one is not judged at all.
    let rows = results(&out);
    assert!(rows
        .iter()
        .any(|(t, s, _)| t.starts_with(&good.id) && s == "Pass"));
    assert!(!rows.iter().any(|(t, _, _)| t.starts_with(&bad.id)));
}
