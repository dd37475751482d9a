//! What `merge`, `report` and a baseline say instead of staying silent: missing shards and
//! unrelated runs are refused (exit 96), `report out/* -o out/html` works a second time, and
//! baseline entries that excuse nothing are warned about (stderr and report.md).

mod common;
use common::*;
use std::path::Path;

fn shadowcheck(args: &[&str]) -> Run {
    Run::of(bin().args(args).output().unwrap())
}

fn s(p: &Path) -> String {
    p.display().to_string()
}

#[test]
fn merge_refuses_missing_shards_and_unrelated_runs() {
    let (dir, fx) = cases_dir("merge-check", 12);
    let shard = |k: &str, extra: &[&str]| {
        let out = dir.join(format!("s{}{}", k.replace('/', "of"), extra.len()));
        let mut args = vec!["-b", "mock:", "--fixtures", &fx, "--shard", k];
        args.extend(extra);
        let o = s(&out);
        args.extend(["--out", &o]);
        let r = run(&args);
        assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
        out
    };
    let (a, b, c) = (shard("1/3", &[]), shard("2/3", &[]), shard("3/3", &[]));
    let merged = dir.join("merged");
    let r = shadowcheck(&["merge", "-o", &s(&merged), &s(&a), &s(&b)]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("shard(s) 3/3 missing"), "{}", r.stderr);
    assert!(!merged.join("results.csv").exists());

    let r = shadowcheck(&["merge", "-o", &s(&merged), &s(&a), &s(&b), &s(&c)]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert_eq!(results(&merged).len(), 12);

    // Another selection (--cases) is another run.
    let other = shard("3/3", &["--cases", "n=000"]);
    let r = shadowcheck(&[
        "merge",
        "-o",
        &s(&dir.join("m2")),
        &s(&a),
        &s(&b),
        &s(&other),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(r.stderr.contains("unrelated runs"), "{}", r.stderr);
}

#[test]
fn report_over_out_star_works_a_second_time() {
    let (dir, fx) = cases_dir("report-twice", 4);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        &s(&out.join("r1")),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let html = out.join("html");
    for round in 0..2 {
        // What the shell makes of `out/*`: r1, and html from the second round on.
        let mut inputs: Vec<String> = std::fs::read_dir(&out)
            .unwrap()
            .map(|e| s(&e.unwrap().path()))
            .collect();
        inputs.sort();
        let mut args = vec!["report".to_string()];
        args.extend(inputs);
        args.extend(["-o".into(), s(&html), "--fixtures".into(), fx.clone()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let r = shadowcheck(&args);
        assert_eq!(r.code, 0, "round {round}: {}{}", r.stdout, r.stderr);
        assert_eq!(
            r.stderr.contains("skipping input"),
            round == 1,
            "{}",
            r.stderr
        );
    }
}

#[test]
fn baseline_entries_that_excuse_nothing_are_reported() {
    let (dir, fx) = cases_dir("baseline-notes", 8);
    let base = dir.join("baseline.csv");
    std::fs::write(
        &base,
        "gl46/2d/d16/nearest/gequal/ref=0.5/texel=0_0/n=0001@core,Fail\n\
         gl46/2d/d16/nearest/lequal/ref=0.5/texel=0_0/n=0000@core,Pass\n\
         gl46/no/such/test@core,Fail\n",
    )
    .unwrap();
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:fail=n=0001",
        "--fixtures",
        &fx,
        "--baseline",
        &s(&base),
        "--out",
        &s(&out),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let pass = "`gl46/2d/d16/nearest/lequal/ref=0.5/texel=0_0/n=0000@core,Pass` has no effect";
    let gone = "`gl46/no/such/test@core` matches no test of this run";
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    for text in [pass, gone] {
        assert!(r.stderr.contains(text), "{text}: {}", r.stderr);
        assert!(md.contains(text), "{text}: {md}");
    }
    assert!(!r.stderr.contains("n=0001@core` matches"), "{}", r.stderr);
}
