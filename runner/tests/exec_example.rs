//! The example external implementation (runner/examples/nearest_2d.py) through `exec:`:
//! with LEQUAL and GEQUAL swapped it fails exactly the LEQUAL/GEQUAL cases, with a footprint dump
//! and exit code 100; a baseline of those failures gives 0; the fixed script then reports
//! UnexpectedImprovement (101). Needs `python3` (installed by .ci/run).

mod common;
use common::*;
use shadowcheck_model::CompareFunc;

fn example() -> String {
    format!("{}/examples/nearest_2d.py", env!("CARGO_MANIFEST_DIR"))
}

/// 4 funcs x 4 texels, reference 0.5, plus a case outside the example's capabilities (a cube map).
fn fixture(dir: &std::path::Path) -> String {
    let mut cases = vec![];
    for f in [
        CompareFunc::Lequal,
        CompareFunc::Gequal,
        CompareFunc::Less,
        CompareFunc::Greater,
    ] {
        for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            cases.push(nearest_case(f, x, y, 0.5));
        }
    }
    let mut other = nearest_case(CompareFunc::Lequal, 0, 0, 0.5);
    other.id = "gl46/2d/d16/nearest/lequal/ref=0.5/as-es300".into();
    other.api = vec![shadowcheck_model::ApiPath::Es300];
    other.spec = shadowcheck_model::Spec::Gles32;
    // Its layout on its own API path (ES 3.2 §11.1.3.5: the shadow lookup returns a float, as core).
    if let Some(e) = other.expect.as_mut() {
        if let Some(l) = e.layout.remove(&shadowcheck_model::ApiPath::GlslCore) {
            e.layout.insert(shadowcheck_model::ApiPath::Es300, l);
        }
    }
    cases.push(other);
    let p = dir.join("fixtures/example.json");
    write_fixture(&p, cases);
    p.display().to_string()
}

#[test]
fn swapped_lequal_gequal_fails_with_a_footprint_then_baseline_then_improvement() {
    let dir = tmpdir("exec-example");
    let fx = fixture(&dir);
    let swapped = format!("exec:python3 {} --swap-lequal-gequal", example());
    let fixed = format!("exec:python3 {}", example());

    let out1 = dir.join("swapped");
    let r = run(&[
        "-b",
        &swapped,
        "--fixtures",
        &fx,
        "--out",
        out1.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let rows = results(&out1);
    // The gles32 case is no test of this gl46-only implementation (not applicable): 16 tests.
    assert_eq!(rows.len(), 16);
    assert!(r.stderr.contains("1 not applicable"), "{}", r.stderr);
    // LEQUAL with Dref 0.5 passes where Dt >= 0.5 (texels 2/3 and 1), GEQUAL where Dt <= 0.5; the
    // swapped script answers the other way round on every one of those 8 cases.
    for (t, st, _) in &rows {
        assert!(!t.contains("as-es300"), "{t}");
        let want = if t.contains("/lequal/") || t.contains("/gequal/") {
            "Fail"
        } else {
            "Pass"
        };
        assert_eq!(st, want, "{t}");
    }
    // The dump of texel (1,1): stored 65535, Dt 1, Dref 0.5, expected 1, observed 0.
    let md = std::fs::read_to_string(out1.join("report.md")).unwrap();
    let dump = md
        .split("```text")
        .find(|d| d.contains("/lequal/ref=0.5/texel=1_1@core"))
        .expect("dump of texel 1,1");
    assert!(
        dump.contains("expected:  spec value 1; strict {1}; quality {1}"),
        "{dump}"
    );
    assert!(dump.contains("observed:  rgba (0, 0, 0, 1)"), "{dump}");
    assert!(dump.contains("footprint: Dref 0.5 (1 texels)"), "{dump}");
    let texel_line = dump
        .lines()
        .find(|l| l.trim_start().starts_with("0     1,1,0"))
        .expect("footprint texel line");
    let cols: Vec<&str> = texel_line.split_whitespace().collect();
    assert_eq!(
        cols,
        ["0", "1,1,0", "65535", "1", "pass", "1"],
        "{texel_line}"
    );
    assert!(
        dump.contains("re-run:    shadowcheck run --backend 'exec:python3 "),
        "{dump}"
    );
    assert!(
        dump.contains("--cases '^gl46/2d/d16/nearest/lequal/ref=0\\.5/texel=1_1$'"),
        "{dump}"
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out1.join("report.json")).unwrap()).unwrap();
    assert_eq!(report["summary"]["counts"]["not_applicable"], 1);

    // results.jsonl: the 8 passing tests in the compact form, the 8 failures in full; merging the
    // run keeps all 16 tests and its not-applicable count.
    let jsonl = std::fs::read_to_string(out1.join("results.jsonl")).unwrap();
    let failed: std::collections::BTreeSet<String> = jsonl
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|v| v["kind"] == "result")
        .map(|v| v["test"].to_string())
        .collect();
    let passed_tests: usize = jsonl
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|v| v["kind"] == "passed")
        .flat_map(|v| v["cases"].as_array().unwrap().clone())
        .map(|c| c[1].as_array().unwrap().len())
        .sum();
    assert_eq!(passed_tests, 8, "{jsonl}");
    // (each failure twice: its first record, then the flake re-run's final one)
    assert_eq!(failed.len(), 8, "{jsonl}");
    let merged = dir.join("merged");
    let r = Run::of(
        bin()
            .args([
                "merge",
                "-o",
                merged.to_str().unwrap(),
                out1.to_str().unwrap(),
            ])
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    assert_eq!(results(&merged), rows);
    // The merged results.jsonl holds every test (it is what the next merge or report reads).
    let again = shadowcheck_runner::records::read_results(&merged.join("results.jsonl")).unwrap();
    assert_eq!(again.results.len(), 16);
    assert_eq!(again.not_applicable.values().sum::<usize>(), 1);
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(merged.join("report.json")).unwrap())
            .unwrap();
    assert_eq!(report["summary"]["counts"]["not_applicable"], 1);
    let said = format!("{}{}", r.stdout, r.stderr);
    assert!(said.contains("1 not applicable"), "{said}");

    // Those failures as the baseline: exit 0.
    let base = out1.join("failures.csv");
    assert_eq!(std::fs::read_to_string(&base).unwrap().lines().count(), 8);
    let out2 = dir.join("baselined");
    let r = run(&[
        "-b",
        &swapped,
        "--fixtures",
        &fx,
        "--baseline",
        base.to_str().unwrap(),
        "--out",
        out2.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert_eq!(
        results(&out2)
            .iter()
            .filter(|r| r.1 == "ExpectedFail")
            .count(),
        8
    );

    // The fixed script: the 8 listed tests are unexpected improvements.
    let out3 = dir.join("fixed");
    let r = run(&[
        "-b",
        &fixed,
        "--fixtures",
        &fx,
        "--baseline",
        base.to_str().unwrap(),
        "--out",
        out3.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 101, "{}{}", r.stdout, r.stderr);
    assert_eq!(
        results(&out3)
            .iter()
            .filter(|r| r.1 == "UnexpectedImprovement(Pass)")
            .count(),
        8
    );
    // And without the baseline everything it supports passes.
    let out4 = dir.join("fixed-plain");
    let r = run(&[
        "-b",
        &fixed,
        "--fixtures",
        &fx,
        "--out",
        out4.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
}

#[test]
fn the_example_passes_every_default_fixture_it_claims() {
    // Over the committed fixtures (cases/fixtures), the correct script passes every gl46 2D case
    // it runs and skips the rest with a reason; swapped, it fails LEQUAL/GEQUAL cases only.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap();
    assert!(
        root.join("cases/fixtures").is_dir(),
        "cases/fixtures is missing"
    );
    let dir = tmpdir("exec-example-default");
    let out = dir.join("fixed");
    let r = Run::of(
        bin()
            .current_dir(root)
            .args([
                "run",
                "-b",
                &format!("exec:python3 {}", example()),
                "--cases",
                "^gl46/2d/",
                "--out",
                out.to_str().unwrap(),
            ])
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let rows = results(&out);
    let passed = rows.iter().filter(|r| r.1 == "Pass").count();
    assert!(passed > 100, "only {passed} passes");
    assert!(rows.iter().all(|r| r.1 == "Pass" || r.1 == "Skip"));

    let out = dir.join("swapped");
    let r = Run::of(
        bin()
            .current_dir(root)
            .args([
                "run",
                "-b",
                &format!("exec:python3 {} --swap-lequal-gequal", example()),
                "--cases",
                "^gl46/2d/",
            ])
            .args(["--no-rerun", "--out", out.to_str().unwrap()])
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 100);
    let rows = results(&out);
    let failed: Vec<_> = rows
        .iter()
        .filter(|r| r.1 == "Fail" || r.1 == "Warn")
        .collect();
    assert!(!failed.is_empty());
    assert!(
        failed
            .iter()
            .all(|r| r.0.contains("/lequal/") || r.0.contains("/gequal/")),
        "{failed:?}"
    );
}

#[test]
fn an_implementation_lying_about_stored_texels_fails() {
    // `--lie-stored` answers r = 1 and claims every texel holds 65535: re-judged with those texels
    // the LEQUAL/GEQUAL cases would pass; outside the upload allowance they are Fails of their own.
    let dir = tmpdir("exec-lie-stored");
    let fx = fixture(&dir);
    let liar = format!("exec:python3 {} --lie-stored", example());
    let out = dir.join("liar");
    let r = run(&[
        "-b",
        &liar,
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let rows = results(&out);
    let fails = rows.iter().filter(|r| r.1 == "Fail").count();
    assert_eq!(fails, 16, "{rows:?}");
    let report = std::fs::read_to_string(out.join("report.json")).unwrap();
    assert!(
        report.contains(
            "stored texel outside the upload allowance: texel 0: fixture 0, stored 65535"
        ),
        "reason with both values missing"
    );
}
