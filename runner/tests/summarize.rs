//! `shadowcheck summarize` on two small synthetic run directories. The expected files are what
//! reports/mesa-22.3.6/summarize.py (which the command replaced) wrote for the same inputs.

mod common;
use common::*;
use std::path::Path;

/// One results.jsonl record; `reason` None leaves the field out.
fn rec(backend: &str, test: &str, status: &str, reason: Option<&str>, func: &str) -> String {
    let (case_id, api) = test.split_once('@').unwrap();
    let mut v = serde_json::json!({
        "kind": "result", "backend": backend, "test": test, "case_id": case_id, "api": api,
        "status": status, "outcome": "Pass", "duration": 0.0,
        "tags": {"spec": "gl46", "target": "2d", "format": "d16", "func": func, "filter": "nearest/nearest"},
    });
    if let Some(r) = reason {
        v["reason"] = r.into();
    }
    v.to_string()
}

fn write_run(dir: &Path, backend: &str, records: &[String], report: &str) {
    std::fs::create_dir_all(dir).unwrap();
    let meta = format!(
        r#"{{"kind":"meta","schema_version":1,"backends":["{backend}"],"fixtures":["cases/fixtures"]}}"#
    );
    let error = r#"{"kind":"load_error","file":"f.json","message":"bad"}"#;
    let mut text = format!("{meta}\n{error}\n");
    let mut tests = std::collections::BTreeSet::new();
    for r in records {
        text += r;
        text += "\n";
        let v: serde_json::Value = serde_json::from_str(r).unwrap();
        tests.insert(v["test"].to_string());
    }
    // A finished run ends with its closing record (tests per backend).
    text += &format!(
        "{}\n",
        serde_json::json!({"kind": "end", "tests": {backend: tests.len()}})
    );
    std::fs::write(dir.join("results.jsonl"), text).unwrap();
    std::fs::write(
        dir.join("failures.csv"),
        format!("x@core,Fail\r\n{backend}\r\n"),
    )
    .unwrap();
    std::fs::write(dir.join("report.md"), report).unwrap();
}

#[test]
fn summarize_writes_what_summarize_py_wrote() {
    let dir = tmpdir("summarize");
    let b = "soft:gl46";
    write_run(
        &dir.join("r-soft-gl46"),
        b,
        &[
            rec(
                b,
                "gl46/a/ref=0.5/dt=0.25_1@core",
                "Fail",
                Some("out"),
                "lequal",
            ),
            rec(b, "gl46/b,2@core", "Warn", None, "lequal"),
            rec(b, "gl46/a0@core", "Warn", None, "gequal"),
            rec(b, "gl46/c@core", "Skip", Some("no cube"), "lequal"),
            rec(b, "gl46/d@ff", "Skip", None, "lequal"),
            rec(b, "gl46/e@ff", "Skip", Some(""), "lequal"),
            rec(b, "gl46/f@ff", "Skip", Some("no ff"), "lequal"),
            rec(b, "gl46/g@ff", "Skip", Some("no ff"), "lequal"),
            rec(b, "gl46/h@core", "Pass", None, "lequal"),
            rec(
                b,
                "gl46/i@core",
                "UnexpectedImprovement(Pass)",
                None,
                "less",
            ),
            rec(b, "gl46/j@core", "Fail", None, "less"),
            rec(b, "gl46/k@core", "Fail", None, "less"),
            rec(b, "gl46/l@core", "Fail", None, "lequal"),
            // The flake re-run's record of the first test: the last record wins.
            rec(
                b,
                "gl46/a/ref=0.5/dt=0.25_1@core",
                "Flake",
                Some("out"),
                "lequal",
            ),
        ],
        "# report\n\nλ ≤ 1\n",
    );
    let e = "egl:llvmpipe:es3";
    let long_line = format!("{}\n", "λ".repeat(99));
    write_run(
        &dir.join("r-egl-llvmpipe-es3"),
        e,
        &[
            rec(e, "es/x@es300", "Pass", None, "lequal"),
            rec(e, "es/y@es300", "ExpectedFail", None, "never"),
            rec(
                e,
                "es/z@core",
                "Skip",
                Some("spec `gl46` not supported"),
                "lequal",
            ),
        ],
        &long_line.repeat(1600),
    );
    let out = dir.join("out");
    let o = bin()
        .args(["summarize", "-o", out.to_str().unwrap()])
        .arg(dir.join("r-soft-gl46"))
        .arg(dir.join("r-egl-llvmpipe-es3"))
        .args(["--platform", "Mesa 22.3.6"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    let read = |p: &str| std::fs::read_to_string(out.join(p)).unwrap();

    assert_eq!(read("SUMMARY.md"), SUMMARY);
    assert_eq!(read("soft-gl46/summary.md"), SOFT_SUMMARY);
    assert_eq!(
        read("soft-gl46/warnings.csv"),
        "gl46/a0@core,Warn\r\n\"gl46/b,2@core\",Warn\r\n"
    );
    assert_eq!(
        read("soft-gl46/failures.csv"),
        "x@core,Fail\r\nsoft:gl46\r\n"
    );
    assert_eq!(read("soft-gl46/report.md"), "# report\n\nλ ≤ 1\n");
    assert_eq!(read("egl-llvmpipe-es3/summary.md"), ES_SUMMARY);
    assert_eq!(read("egl-llvmpipe-es3/warnings.csv"), "");
    assert_eq!(
        read("egl-llvmpipe-es3/report.md"),
        format!(
            "{}\n\n... report.md capped at 150000 bytes of 160000; re-run with run.sh for the full file.\n",
            long_line.repeat(1500).trim_end_matches('\n')
        )
    );

    // A run directory without results is bad input: 96.
    let o = bin()
        .args(["summarize", "-o", out.to_str().unwrap()])
        .arg(dir.join("missing"))
        .args(["--platform", "x"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(96), "{o:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

const SUMMARY: &str = r#"# Mesa 22.3.6 reference results (default fixtures)

One row per backend x API path; a test is one case on one API path. See ../README.md for the causes.

| backend | API path | Pass | Warn | Fail | Skip | Crash | Timeout | Flake | KnownFlake | ExpectedFail | UnexpectedImprovement(Pass) |
|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| soft-gl46 | core | 1 | 2 | 3 | 1 | 0 | 0 | 1 | 0 | 0 | 1 |
| egl-llvmpipe-es3 | es300 | 1 | 0 | 0 | 0 | 0 | 0 | 0 | 0 | 1 | 0 |
"#;
const SOFT_SUMMARY: &str = r#"# soft-gl46 on Mesa 22.3.6

Status per API path (tests = case x API path):

| API path | Pass | Warn | Fail | Skip | Crash | Timeout | Flake | KnownFlake | ExpectedFail | UnexpectedImprovement(Pass) | total |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| core | 1 | 2 | 3 | 1 | 0 | 0 | 1 | 0 | 0 | 1 | 9 |
| ff | 0 | 0 | 0 | 4 | 0 | 0 | 0 | 0 | 0 | 0 | 4 |

## Skip reasons

- `core` 1: no cube
- `ff` 2: (no reason)
- `ff` 2: no ff

## Non-pass groups (spec/target/format/filter/func), with one example test

| API path | status | group | tests | example |
|---|---|---|---:|---|
| core | Fail | `gl46/2d/d16/nearest/nearest/less` | 2 | `gl46/j@core` |
| core | Fail | `gl46/2d/d16/nearest/nearest/lequal` | 1 | `gl46/l@core` |
| core | Flake | `gl46/2d/d16/nearest/nearest/lequal` | 1 | `gl46/a/ref=0.5/dt=0.25_1@core` |
| core | UnexpectedImprovement(Pass) | `gl46/2d/d16/nearest/nearest/less` | 1 | `gl46/i@core` |
| core | Warn | `gl46/2d/d16/nearest/nearest/gequal` | 1 | `gl46/a0@core` |
| core | Warn | `gl46/2d/d16/nearest/nearest/lequal` | 1 | `gl46/b,2@core` |
"#;
const ES_SUMMARY: &str = r#"# egl-llvmpipe-es3 on Mesa 22.3.6

Status per API path (tests = case x API path):

| API path | Pass | Warn | Fail | Skip | Crash | Timeout | Flake | KnownFlake | ExpectedFail | total |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| core | 0 | 0 | 0 | 1 | 0 | 0 | 0 | 0 | 0 | 1 |
| es300 | 1 | 0 | 0 | 0 | 0 | 0 | 0 | 0 | 1 | 2 |

## Skip reasons

- `core` 1: spec `gl46` not supported

## Non-pass groups (spec/target/format/filter/func), with one example test

| API path | status | group | tests | example |
|---|---|---|---:|---|
| es300 | ExpectedFail | `gl46/2d/d16/nearest/nearest/never` | 1 | `es/y@es300` |
"#;
