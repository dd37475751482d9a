//! junit.xml is read back by an independent JUnit parser (junit-parser), with the counts the run
//! reported (passing tests are in junit.xml only with --full-report: tests/output.rs).

mod common;
use common::*;

#[test]
fn junit_output_parses_with_the_right_counts() {
    let dir = tmpdir("junit");
    let fx = dir.join("fixtures/cases.json");
    write_fixture(&fx, many_cases(20));
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:fail=n=000[0-2],crash=n=0005,skip=n=001",
        "--fixtures",
        fx.to_str().unwrap(),
        "--no-rerun",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let xml = std::fs::read(out.join("junit.xml")).unwrap();
    let suites = junit_parser::from_reader(std::io::Cursor::new(xml)).unwrap();
    assert_eq!(suites.suites.len(), 1);
    let s = &suites.suites[0];
    assert_eq!(s.name, "mock:fail=n=000[0-2],crash=n=0005,skip=n=001");
    // Passing tests are left out unless --full-report (20 tests: 3 fail, 1 crash, 10 skip, 6 pass).
    assert_eq!(s.cases.len(), 14);
    assert_eq!(s.failures, 3);
    assert_eq!(s.errors, 1);
    // quick-junit counts skipped cases in the `disabled` attribute; count the <skipped/> elements.
    assert_eq!(s.cases.iter().filter(|c| c.status.is_skipped()).count(), 10);
    let failed = s.cases.iter().find(|c| c.name.contains("n=0000")).unwrap();
    assert!(failed.status.is_failure());
    let f = failed.status.failure_as_ref();
    assert!(
        f.text.contains("observed:  rgba (-1, 0, 0, 0)"),
        "{}",
        f.text
    );
    assert!(f.text.contains("re-run:"), "{}", f.text);
    assert!(s
        .cases
        .iter()
        .find(|c| c.name.contains("n=0005"))
        .unwrap()
        .status
        .is_error());
}
