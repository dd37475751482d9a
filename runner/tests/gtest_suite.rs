//! `shadowcheck gtest` under the real `deqp-runner suite` (0.24, the version of the dev-dependency;
//! `.ci/run` installs the binary with `cargo install deqp-runner --version '=0.24.0' --locked`):
//! one suite TOML with two `[[gtest]]` blocks (`soft:gl46`, named with `-b`, and a `mock:` backend
//! that fails, warns, skips and crashes on chosen cases, named through SHADOWCHECK_BACKEND and
//! SHADOWCHECK_FIXTURES), each
//! with a baseline, a skips and a flakes file. Checked: deqp-runner's results.csv, every status in
//! it, and its exit code, with a baseline that lists the failures (exit 0) and one that does not
//! (a regression: exit 1). Without the deqp-runner binary the test is skipped with a message, and
//! fails under CI=true.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The mock implementation: case n=0001 fails, n=0003 is skipped by the implementation, n=0004
/// crashes its process, n=0005 fails (the flakes file lists it), [`WARN_CASE`] warns.
const MOCK: &str = "mock:fail=n=0001,warn=/between/,skip=n=0003,crash=n=0004,fail=n=0005";

/// A committed fixture case whose `quality` acceptance is wider than `strict` (a LINEAR compare
/// whose footprint has passes and fails: GL 4.6 §8.23.1 leaves the filtered value open), so the
/// mock can answer a Warn.
const WARN_CASE: &str = "gl46/2d/d24/linear/lequal/proj/q=2/between/ref=0.5";
const WARN_GTEST: &str = "gl46.2d/d24/linear/lequal/proj/q=2/between/ref=0%2E5";

/// Writes `dir/warn.json` holding [`WARN_CASE`] as committed (the oracle's expectation) and
/// returns its API path keys.
fn write_warn_case(dir: &Path) -> Vec<String> {
    let committed =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures/gl46/2d/linear.json");
    let mut file: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(committed).unwrap()).unwrap();
    let case = file["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == WARN_CASE)
        .cloned()
        .unwrap_or_else(|| {
            panic!("{WARN_CASE} is no longer in cases/fixtures/gl46/2d/linear.json")
        });
    let apis = case["api"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a.as_str().unwrap().to_string())
        .collect();
    file["cases"] = serde_json::json!([case]);
    if file.get("state_cases").is_some() {
        file["state_cases"] = serde_json::json!([]);
    }
    std::fs::write(dir.join("warn.json"), file.to_string()).unwrap();
    apis
}

/// `deqp-runner` on PATH, in `$CARGO_HOME/bin` or in `~/.cargo/bin`.
fn deqp_runner() -> Option<PathBuf> {
    let mut dirs: Vec<PathBuf> = std::env::var_os("PATH")
        .map(|p| std::env::split_paths(&p).collect())
        .unwrap_or_default();
    if let Some(h) = std::env::var_os("CARGO_HOME") {
        dirs.push(Path::new(&h).join("bin"));
    }
    if let Some(h) = std::env::var_os("HOME") {
        dirs.push(Path::new(&h).join(".cargo/bin"));
    }
    dirs.into_iter()
        .map(|d| d.join("deqp-runner"))
        .find(|p| p.is_file())
}

/// The gtest name of test `n=<i>@core` of [`many_cases`]: its case id with the `.` of `ref=0.5`
/// written `%2E` and the part before the first `/` as the suite (runner/README.md, "The name
/// mapping").
fn gtest_name(i: usize) -> String {
    let funcs = ["lequal", "gequal", "less", "greater"];
    format!(
        "gl46.2d/d16/nearest/{}/ref=0%2E5/texel={}_{}/n={i:04}@core",
        funcs[i % 4],
        i / 4 % 2,
        i / 8 % 2
    )
}

fn script(dir: &Path, name: &str, body: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let p = dir.join(name);
    std::fs::write(&p, format!("#!/bin/sh\n{body}\n")).unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o755)).unwrap();
    p
}

/// Runs `deqp-runner suite` over two `[[gtest]]` blocks with `baseline` (the lines of the mock
/// block's baseline) and returns its exit code and results.csv as (test, status).
fn suite(
    deqp: &Path,
    dir: &Path,
    fx: &str,
    tag: &str,
    baseline: &[String],
) -> (i32, Vec<(String, String)>) {
    let bin = env!("CARGO_BIN_EXE_shadowcheck");
    // deqp-runner 0.24 runs a gtest binary with no arguments of its own and does not pass
    // [gtest.env] on, so each block's binary is a script naming the backend.
    let soft = script(
        dir,
        "soft.sh",
        &format!("exec '{bin}' gtest -b soft:gl46 --fixtures '{fx}' \"$@\""),
    );
    let mock = script(
        dir,
        "mock.sh",
        &format!(
            "SHADOWCHECK_BACKEND='{MOCK}' SHADOWCHECK_FIXTURES='{fx}' exec '{bin}' gtest \"$@\""
        ),
    );
    let write = |name: &str, lines: &[String]| {
        let p = dir.join(format!("{tag}-{name}"));
        std::fs::write(&p, lines.join("\n") + "\n").unwrap();
        p.display().to_string()
    };
    let mock_baseline = write("mock-baseline.csv", baseline);
    let soft_baseline = write("soft-baseline.csv", &["# nothing fails".to_string()]);
    let skips = write("skips.txt", &["mock/.*/n=0006@core$".to_string()]);
    let flakes = write("flakes.txt", &["mock/.*/n=0005@core$".to_string()]);
    let toml = format!(
        r#"
[[gtest]]
bin = "{soft}"
prefix = "soft/"
baseline = "{soft_baseline}"
skips = ["{skips}"]
flakes = ["{flakes}"]

[[gtest]]
bin = "{mock}"
prefix = "mock/"
baseline = "{mock_baseline}"
skips = ["{skips}"]
flakes = ["{flakes}"]
"#,
        soft = soft.display(),
        mock = mock.display(),
    );
    let suite = dir.join(format!("{tag}-suite.toml"));
    std::fs::write(&suite, toml).unwrap();
    let out = dir.join(format!("{tag}-out"));
    let o = Command::new(deqp)
        .args(["suite", "--jobs", "2", "--suite"])
        .arg(&suite)
        .arg("--output")
        .arg(&out)
        .output()
        .unwrap();
    let code = o.status.code().unwrap_or(-1);
    let csv = std::fs::read_to_string(out.join("results.csv")).unwrap_or_else(|e| {
        panic!(
            "no results.csv ({e}); deqp-runner exit {code}\n{}\n{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        )
    });
    let mut rows: Vec<(String, String)> = csv
        .lines()
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            assert_eq!(f.len(), 3, "{l}");
            (f[0].to_string(), f[1].to_string())
        })
        .collect();
    rows.sort();
    (code, rows)
}

#[test]
fn deqp_runner_suite_runs_two_backends_through_the_gtest_interface() {
    let Some(deqp) = deqp_runner() else {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("CI=true and no deqp-runner binary (PATH, $CARGO_HOME/bin, ~/.cargo/bin): .ci/run installs it with cargo install deqp-runner --version '=0.24.0' --locked");
        }
        eprintln!("SKIPPED gtest_suite: no deqp-runner binary on PATH, in $CARGO_HOME/bin or ~/.cargo/bin; install it with: cargo install deqp-runner --version '=0.24.0' --locked");
        return;
    };
    let (dir, fx) = cases_dir("gtest-suite", 12);
    let fx_dir = Path::new(&fx).parent().unwrap();
    let warn_apis = write_warn_case(fx_dir);
    let fx = fx_dir.display().to_string();

    // What each test is, from the mock script and the lists (deqp-runner's status names).
    let expected = |fail_listed: bool| -> Vec<(String, String)> {
        let mut rows = vec![];
        for i in 0..12 {
            rows.push((format!("soft/{}", gtest_name(i)), "Pass".to_string()));
            let mock = match i {
                1 if fail_listed => "ExpectedFail",
                1 => "Fail",
                2 => "Pass",         // a Warn is a pass with a note
                3 => "Skip",         // the implementation skipped it
                4 => "ExpectedFail", // a Crash, listed as one
                5 => "KnownFlake",
                6 => "Skip", // the skips file
                _ => "Pass",
            };
            rows.push((format!("mock/{}", gtest_name(i)), mock.to_string()));
        }
        for api in &warn_apis {
            rows.push((format!("soft/{WARN_GTEST}@{api}"), "Pass".to_string()));
            // A Warn is a pass with a note.
            rows.push((format!("mock/{WARN_GTEST}@{api}"), "Pass".to_string()));
        }
        rows.sort();
        rows
    };
    let listed = |with_fail: bool| {
        let mut b = vec![format!("mock/{},Crash", gtest_name(4))];
        if with_fail {
            b.push(format!("mock/{},Fail", gtest_name(1)));
        }
        b
    };

    let (code, rows) = suite(&deqp, &dir, &fx, "clean", &listed(true));
    assert_eq!(rows, expected(true));
    assert_eq!(code, 0, "every failure is in the baseline");

    let (code, rows) = suite(&deqp, &dir, &fx, "regression", &listed(false));
    assert_eq!(rows, expected(false));
    assert_eq!(code, 1, "n=0001 fails and the baseline does not list it");
}

fn gtest(args: &[&str], env: &[(&str, &str)]) -> Run {
    let mut c = bin();
    c.arg("gtest").args(args).env_remove("SHADOWCHECK_BACKEND");
    c.env_remove("SHADOWCHECK_FIXTURES");
    for (k, v) in env {
        c.env(k, v);
    }
    Run::of(c.output().unwrap())
}

/// Without deqp-runner: the listing, the backend from the environment, a filter, a hang that
/// ends the output on its RUN line (a crash to a gtest runner) and stops the run, bad fixtures.
#[test]
fn gtest_lists_filters_and_ends_on_a_hang() {
    let (dir, fx) = cases_dir("gtest-direct", 12);
    let list = gtest(
        &["-b", "mock:pass", "--fixtures", &fx, "--gtest_list_tests"],
        &[],
    );
    assert_eq!(list.code, 0, "{}", list.stderr);
    let mut want: Vec<String> = (0..12).map(gtest_name).collect();
    want.sort();
    let mut expect = String::from("gl46.\n");
    for n in &want {
        expect.push_str(&format!("  {}\n", n.trim_start_matches("gl46.")));
    }
    assert_eq!(list.stdout, expect);
    let env = gtest(
        &["--gtest_list_tests"],
        &[
            ("SHADOWCHECK_BACKEND", "mock:pass"),
            ("SHADOWCHECK_FIXTURES", &fx),
        ],
    );
    assert_eq!((env.code, env.stdout), (0, expect));

    // Exact names, a wildcard and a negative pattern (n=0000 is lequal), as googletest reads a
    // filter; the tests run in listing order.
    let filter = format!(
        "{}:{}:{}:gl46.*/n=0003@core-*lequal*",
        gtest_name(7),
        gtest_name(1),
        gtest_name(0)
    );
    let two = gtest(
        &[
            "-b",
            "mock:fail=n=0001",
            "--fixtures",
            &fx,
            "--gtest_filter",
            &filter,
        ],
        &[],
    );
    let runs: Vec<&str> = two
        .stdout
        .lines()
        .filter(|l| l.starts_with("[ RUN"))
        .collect();
    assert_eq!(
        runs,
        vec![
            format!("[ RUN      ] {}", gtest_name(1)),
            format!("[ RUN      ] {}", gtest_name(3)),
            format!("[ RUN      ] {}", gtest_name(7)),
        ]
    );
    assert!(
        two.stdout
            .contains(&format!("[  FAILED  ] {} (", gtest_name(1))),
        "{}",
        two.stdout
    );
    assert_eq!(two.code, 1, "a test failed: googletest's exit code");

    // n=0002 hangs: the output ends on its RUN line and a note; what sorts before it passed.
    let t0 = std::time::Instant::now();
    let hang = gtest(
        &[
            "-b",
            "mock:hang=n=0002",
            "--fixtures",
            &fx,
            "--timeout",
            "0.5",
            "--group",
            "1",
        ],
        &[],
    );
    let status_lines: Vec<&str> = hang.stdout.lines().filter(|l| l.starts_with('[')).collect();
    let at = want.iter().position(|n| *n == gtest_name(2)).unwrap();
    assert_eq!(status_lines.len(), 1 + 2 * at + 1, "{}", hang.stdout);
    assert_eq!(
        status_lines.last().copied(),
        Some(format!("[ RUN      ] {}", gtest_name(2)).as_str())
    );
    let last = hang.stdout.lines().last().unwrap_or("");
    assert!(last.starts_with("shadowcheck: Timeout"), "{last}");
    assert_eq!(hang.code, 1);
    // One timeout, then the run stops: the gtest runner runs the rest in a new process.
    assert!(t0.elapsed().as_secs_f64() < 20.0);

    // n=0002 answered twice, one case per group: the extra line is read with the next group,
    // after n=0002 was judged a Pass; its result is held back until then, so it is printed as the
    // Crash it is, never OK first.
    let extra = gtest(
        &["-b", "mock:extra=n=0002", "--fixtures", &fx, "--group", "1"],
        &[],
    );
    let mut lines = extra.stdout.lines().filter(|l| l.starts_with('['));
    assert!(
        !extra
            .stdout
            .contains(&format!("[       OK ] {}", gtest_name(2))),
        "{}",
        extra.stdout
    );
    assert_eq!(
        lines.next_back(),
        Some(format!("[ RUN      ] {}", gtest_name(2)).as_str())
    );
    assert!(
        extra.stdout.contains("answered this case twice"),
        "{}",
        extra.stdout
    );
    assert_eq!(extra.code, 1);

    // A bad fixture file: the listing refuses it, naming it (exit 96).
    std::fs::write(dir.join("fixtures/bad.json"), "{").unwrap();
    let dir_fx = dir.join("fixtures").display().to_string();
    let bad = gtest(
        &[
            "-b",
            "mock:pass",
            "--fixtures",
            &dir_fx,
            "--gtest_list_tests",
        ],
        &[],
    );
    assert_eq!(bad.code, 96, "{}", bad.stderr);
    assert!(bad.stderr.contains("bad.json"), "{}", bad.stderr);
    let none = gtest(&["--fixtures", &fx, "--gtest_list_tests"], &[]);
    assert_eq!(none.code, 96);
    assert!(
        none.stderr.contains("SHADOWCHECK_BACKEND"),
        "{}",
        none.stderr
    );
}
