//! The runner tested through the `mock:` backend (a scripted implementation in a child process):
//! verdicts, exit codes, baselines, skips/flakes lists, crash and hang bisection, sharding + merge,
//! and bad fixtures that do not stop the run.

mod common;
use common::*;

#[test]
fn all_pass_writes_every_report_and_exits_0() {
    let (dir, fx) = cases_dir("pass", 40);
    let out = dir.join("out");
    let r = run(&[
        "--backend",
        "mock:",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let rows = results(&out);
    assert_eq!(rows.len(), 40);
    assert!(
        rows.iter()
            .all(|r| r.1 == "Pass" && r.2 == "mock:" && r.0.ends_with("@core")),
        "{rows:?}"
    );
    // Test names need no CSV quoting (ids hold no commas).
    assert!(std::fs::read_to_string(out.join("results.csv"))
        .unwrap()
        .starts_with("gl46/2d/d16/nearest/gequal/ref=0.5/texel=0_0/n=0001@core,Pass,"));
    for f in [
        "results.jsonl",
        "results.csv",
        "failures.csv",
        "junit.xml",
        "report.json",
        "report.md",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    assert_eq!(
        std::fs::read_to_string(out.join("failures.csv")).unwrap(),
        ""
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(report["schema_version"], 1);
    assert_eq!(report["summary"]["counts"]["pass"], 40);
    // Summary table by spec / func / filter / format on stdout.
    for dim in ["spec", "func", "filter", "format"] {
        assert!(r.stdout.contains(dim), "{}", r.stdout);
    }
    assert!(
        r.stdout.contains("lequal")
            && r.stdout.contains("nearest/nearest")
            && r.stdout.contains("d16")
    );
}

#[test]
fn failures_baseline_and_improvement_give_the_documented_exit_codes() {
    let (dir, fx) = cases_dir("baseline", 24);
    let out1 = dir.join("o1");
    let r = run(&[
        "-b",
        "mock:fail=/lequal/",
        "--fixtures",
        &fx,
        "--out",
        out1.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let rows = results(&out1);
    assert!(status_of(&rows, "/lequal/").iter().all(|s| *s == "Fail"));
    assert!(status_of(&rows, "/gequal/").iter().all(|s| *s == "Pass"));
    // The dump names the case, expected, observed and the re-run command.
    assert!(
        r.stdout.contains("observed:  rgba (-1, 0, 0, 0)"),
        "{}",
        r.stdout
    );
    assert!(r.stdout.contains("expected:  spec value"), "{}", r.stdout);
    assert!(
        r.stdout
            .contains("re-run:    shadowcheck run --backend mock:fail=/lequal/ --fixtures"),
        "{}",
        r.stdout
    );
    let failures = std::fs::read_to_string(out1.join("failures.csv")).unwrap();
    assert_eq!(failures.lines().count(), 6, "{failures}");
    assert!(
        failures
            .lines()
            .all(|l| l.contains("/lequal/") && l.ends_with("@core,Fail")),
        "{failures}"
    );

    // The failures as a baseline: all expected, exit 0.
    let base = dir.join("baseline.csv");
    std::fs::write(&base, format!("# known failures\n{failures}")).unwrap();
    let out2 = dir.join("o2");
    let r = run(&[
        "-b",
        "mock:fail=/lequal/",
        "--fixtures",
        &fx,
        "--baseline",
        base.to_str().unwrap(),
        "--out",
        out2.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(status_of(&results(&out2), "/lequal/")
        .iter()
        .all(|s| *s == "ExpectedFail"));
    // failures.csv still lists them (usable as the next baseline).
    assert_eq!(
        std::fs::read_to_string(out2.join("failures.csv")).unwrap(),
        failures
    );

    // Fixed implementation: the listed tests now pass.
    let out3 = dir.join("o3");
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--baseline",
        base.to_str().unwrap(),
        "--out",
        out3.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 101, "{}{}", r.stdout, r.stderr);
    assert!(status_of(&results(&out3), "/lequal/")
        .iter()
        .all(|s| *s == "UnexpectedImprovement(Pass)"));

    // A baseline listing a test twice is bad input.
    std::fs::write(&base, format!("{failures}{failures}")).unwrap();
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--baseline",
        base.to_str().unwrap(),
        "--out",
        out3.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}", r.stderr);
    assert!(r.stderr.contains("twice"), "{}", r.stderr);
}

#[test]
fn crash_hang_and_garbage_are_found_by_bisection_and_the_run_goes_on() {
    let (dir, fx) = cases_dir("bisect", 100);
    for (mode, label, group) in [("", "streaming", "64"), (",buffer", "buffered", "16")] {
        let out = dir.join(format!("out-{label}"));
        let script = format!("mock:crash=n=0013,hang=n=0042,garbage=n=0077{mode}");
        let r = run(&[
            "-b",
            &script,
            "--fixtures",
            &fx,
            "--timeout",
            "1",
            "--group",
            group,
            "--no-rerun",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(r.code, 100, "{label}: {}{}", r.stdout, r.stderr);
        let rows = results(&out);
        assert_eq!(rows.len(), 100);
        for (t, status, _) in &rows {
            let want = if t.contains("n=0013") {
                "Crash"
            } else if t.contains("n=0042") {
                "Timeout"
            } else if t.contains("n=0077") {
                "Crash"
            } else {
                "Pass"
            };
            assert_eq!(status, want, "{label}: {t}");
        }
    }
}

#[test]
fn flakes_known_flakes_skips_and_errors() {
    let (dir, fx) = cases_dir("flaky", 16);
    let out = dir.join("out");
    let skips = dir.join("skips.txt");
    std::fs::write(&skips, "# not on this driver\n/greater/\n").unwrap();
    let flakes = dir.join("flakes.txt");
    std::fs::write(&flakes, "n=0001\n").unwrap();
    let r = run(&[
        "-b",
        "mock:flaky=n=0000,fail=n=0001,skip=n=0002,error=n=0006",
        "--fixtures",
        &fx,
        "--skips",
        skips.to_str().unwrap(),
        "--flakes",
        flakes.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let rows = results(&out);
    assert_eq!(status_of(&rows, "n=0000"), ["Flake"]);
    assert_eq!(status_of(&rows, "n=0001"), ["KnownFlake"]);
    assert_eq!(status_of(&rows, "n=0002"), ["Skip"]);
    assert_eq!(status_of(&rows, "n=0006"), ["Fail"]);
    assert!(status_of(&rows, "/greater/").iter().all(|s| *s == "Skip"));
    // The error message of the implementation is the reason; a Fail is a regression.
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let report = std::fs::read_to_string(out.join("report.json")).unwrap();
    assert!(report.contains("implementation error: mock: scripted error"));
    assert!(report.contains("skips list: `/greater/`"));
    assert!(report.contains("mock: scripted skip"));
}

#[test]
fn shards_merge_into_the_unsharded_report() {
    let (dir, fx) = cases_dir("shard", 60);
    let full = dir.join("full");
    let r = run(&[
        "-b",
        "mock:fail=/less/",
        "--fixtures",
        &fx,
        "--out",
        full.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100);
    let mut parts = vec![];
    let mut total = 0;
    for k in 1..=3 {
        let out = dir.join(format!("shard{k}"));
        run(&[
            "-b",
            "mock:fail=/less/",
            "--fixtures",
            &fx,
            "--shard",
            &format!("{k}/3"),
            "--out",
            out.to_str().unwrap(),
        ]);
        total += results(&out).len();
        parts.push(out);
    }
    assert_eq!(total, 60, "each case in exactly one shard");
    let merged = dir.join("merged");
    let mut cmd = bin();
    cmd.arg("merge").arg("-o").arg(&merged).args(&parts);
    let m = Run::of(cmd.output().unwrap());
    assert_eq!(m.code, 100, "{}", m.stderr);
    assert_eq!(results(&merged), results(&full));
    assert_eq!(
        report_without_durations(&merged),
        report_without_durations(&full)
    );
    assert_eq!(
        std::fs::read_to_string(merged.join("failures.csv")).unwrap(),
        std::fs::read_to_string(full.join("failures.csv")).unwrap()
    );
}

#[test]
fn nothing_selected_exits_4_and_bad_input_96() {
    let (dir, fx) = cases_dir("empty", 4);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        &fx,
        "--cases",
        "^matches-nothing$",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 4, "{}{}", r.stdout, r.stderr);
    let r = run(&[
        "-b",
        "nonsense:x",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96);
    assert!(r.stderr.contains("unknown backend"), "{}", r.stderr);
    let r = run(&[
        "-b",
        "soft:gl99",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96);
    // An implementation that cannot start, or does not greet properly, is a setup error.
    let r = run(&[
        "-b",
        "exec:/nonexistent/implementation",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96);
    assert!(r.stderr.contains("cannot start"), "{}", r.stderr);
    let r = run(&[
        "-b",
        "exec:echo not-a-hello",
        "--fixtures",
        &fx,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96);
    assert!(r.stderr.contains("bad hello"), "{}", r.stderr);
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        dir.join("missing").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}", r.stderr);
}

#[test]
fn a_bad_case_is_reported_by_file_and_id_and_the_rest_runs() {
    let dir = tmpdir("badcase");
    let fx = dir.join("fixtures/cases.json");
    let mut cases = many_cases(5);
    cases[2].texture.levels[0].width = 3; // 4 texels for a 3x2 level: invalid
    let bad_id = cases[2].id.clone();
    // Write by hand (the writer would not check), then break a second file completely.
    let f = shadowcheck_cases::fixtures::FixtureFile {
        schema_version: 1,
        generator: "t".into(),
        grid: "t".into(),
        seed: 0,
        cases,
        state_cases: vec![],
    };
    std::fs::create_dir_all(fx.parent().unwrap()).unwrap();
    std::fs::write(&fx, shadowcheck_cases::fixtures::to_string(&f).unwrap()).unwrap();
    std::fs::write(dir.join("fixtures/broken.json"), "{ not json").unwrap();
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:",
        "--fixtures",
        dir.join("fixtures").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr.contains("cases.json") && r.stderr.contains(&bad_id),
        "{}",
        r.stderr
    );
    assert!(r.stderr.contains("broken.json"), "{}", r.stderr);
    assert_eq!(results(&out).len(), 4);
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(report["summary"]["load_errors"], 2);
}

#[test]
fn an_implementation_that_stops_reading_cannot_block_the_runner() {
    // 30 cases with 128x128 textures (~100 KB of JSON each): a group is far larger than a pipe
    // buffer, and the worker hangs on the second case without reading further. The runner's
    // writer thread blocks, the answer deadline still fires, and bisection finds the case.
    let dir = tmpdir("bigpipe");
    let fx = dir.join("fixtures/big.json");
    let cases: Vec<_> = many_cases(30)
        .into_iter()
        .map(|mut c| {
            let l = &mut c.texture.levels[0];
            l.width = 128;
            l.height = 128;
            l.depth = shadowcheck_model::Texels::Unorm(
                (0..128 * 128).map(|i| (i * 4) as u32 % 65536).collect(),
            );
            c
        })
        .collect();
    write_fixture(&fx, cases);
    let out = dir.join("out");
    let r = run(&[
        "-b",
        "mock:hang=n=0001",
        "--fixtures",
        fx.to_str().unwrap(),
        "--timeout",
        "1",
        "--no-rerun",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let rows = results(&out);
    assert_eq!(status_of(&rows, "n=0001"), ["Timeout"]);
    assert_eq!(rows.iter().filter(|r| r.1 == "Pass").count(), 29);
}

#[test]
fn parallel_backends_give_the_sequential_report() {
    let (dir, fx) = cases_dir("jobs", 40);
    let args = |out: &std::path::Path, jobs: &str| {
        run(&[
            "-b",
            "mock:",
            "-b",
            "mock:fail=/less/",
            "-b",
            "mock:crash=n=0005,buffer",
            "--fixtures",
            &fx,
            "--jobs",
            jobs,
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let (seq, par) = (dir.join("seq"), dir.join("par"));
    let r1 = args(&seq, "1");
    let r2 = args(&par, "3");
    assert_eq!(r1.code, 100, "{}", r1.stderr);
    assert_eq!(r2.code, 100, "{}", r2.stderr);
    assert_eq!(results(&seq).len(), 120);
    assert_eq!(results(&par), results(&seq));
    assert_eq!(
        report_without_durations(&par),
        report_without_durations(&seq)
    );
    // One JUnit suite per backend.
    let xml = std::fs::read_to_string(par.join("junit.xml")).unwrap();
    assert_eq!(xml.matches("<testsuite ").count(), 3);
}

#[test]
fn without_gl_drivers_the_default_run_says_how_to_install_them_runs_soft_and_exits_96() {
    // SHADOWCHECK_EXE pointing nowhere makes every GL probe fail, as on a machine without Mesa.
    let (dir, fx) = cases_dir("nogl", 16);
    let out = dir.join("out");
    let default_run = |extra: &[&str]| {
        Run::of(
            bin()
                .args(["run", "--fixtures", &fx, "--out", out.to_str().unwrap()])
                .args(extra)
                .env("SHADOWCHECK_EXE", "/nonexistent/shadowcheck")
                .output()
                .unwrap(),
        )
    };
    let r = default_run(&[]);
    // The missing backends are named, and the run is not "all good".
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("error: backend `egl:llvmpipe:core` cannot start here"),
        "{}",
        r.stderr
    );
    assert!(
        r.stdout
            .contains("exit code 96 (backends that could not start: egl:llvmpipe:core"),
        "{}",
        r.stdout
    );
    let r = default_run(&["--skip-missing"]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("warning: left out (--skip-missing): backend `egl:llvmpipe:core`"),
        "{}",
        r.stderr
    );
    assert!(
        r.stderr.contains(
            "apt-get install -y libegl-mesa0 libgl1-mesa-dri libosmesa6 mesa-vulkan-drivers"
        ),
        "{}",
        r.stderr
    );
    let rows = results(&out);
    assert_eq!(rows.len(), 16);
    assert!(
        rows.iter().all(|r| r.1 == "Pass" && r.2 == "soft"),
        "{rows:?}"
    );
}
