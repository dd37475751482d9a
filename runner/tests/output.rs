//! What a run writes for passing tests: report.json and junit.xml keep only what did not pass
//! unless `--full-report` (results.csv and results.jsonl list every test either way).

mod common;
use common::*;

fn junit_cases(out: &std::path::Path) -> usize {
    std::fs::read_to_string(out.join("junit.xml"))
        .unwrap()
        .matches("<testcase ")
        .count()
}

fn report(out: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap()
}

#[test]
fn passing_tests_get_details_only_on_request() {
    let dir = tmpdir("output-detail");
    let fx = dir.join("fixtures/cases.json");
    write_fixture(&fx, many_cases(30));
    let fx = fx.display().to_string();
    let run_into = |name: &str, extra: &[&str]| {
        let out = dir.join(name);
        let mut args = vec!["-b", "mock:fail=n=0007", "--fixtures", &fx];
        let o = out.display().to_string();
        args.extend(["--out", &o]);
        args.extend(extra);
        let r = run(&args);
        assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
        out
    };
    let slim = run_into("slim", &[]);
    let doc = report(&slim);
    assert_eq!(doc["summary"]["counts"]["pass"], 29);
    assert_eq!(doc["full"], false);
    let kept = doc["results"].as_array().unwrap();
    assert_eq!(kept.len(), 1, "only the failure: {kept:?}");
    assert_eq!(kept[0]["status"], "Fail");
    assert_eq!(junit_cases(&slim), 1);
    assert_eq!(results(&slim).len(), 30, "results.csv lists every test");

    let full = run_into("full", &["--full-report"]);
    let doc = report(&full);
    assert_eq!(doc["full"], true);
    assert_eq!(doc["results"].as_array().unwrap().len(), 30);
    assert_eq!(junit_cases(&full), 30);
}
