//! Backend probing: every name is reported, the impossible combinations say why, and (under CI=true)
//! every other backend must be available.
use shadowcheck_gl::BackendName;
use shadowcheck_runner::backend::gl;

#[test]
fn probe_reports_every_backend_with_reasons() {
    std::env::set_var(gl::WORKER_EXE_ENV, env!("CARGO_BIN_EXE_shadowcheck"));
    let report = gl::probe_report();
    assert_eq!(report.len(), 40);
    let ci = std::env::var("CI").is_ok_and(|v| v == "true");
    for (name, res) in &report {
        let b: BackendName = name.parse().unwrap();
        match (b.static_unavailability(), res) {
            (Some(_), Ok(_)) => panic!("{name} cannot work, yet probed available"),
            (Some(why), Err(e)) => assert_eq!(&why, e),
            (None, Ok(_)) => {}
            (None, Err(e)) if ci => panic!("{name} unavailable under CI=true: {e}"),
            (None, Err(e)) => eprintln!("SKIPPED (not a pass): {name} unavailable: {e}"),
        }
    }
    let osmesa_zink = report
        .iter()
        .find(|(n, _)| n == "osmesa:zink:core")
        .unwrap();
    assert!(osmesa_zink.1.as_ref().unwrap_err().contains("segfault"));
    let available = gl::probe();
    assert!(available.iter().all(|n| report
        .iter()
        .any(|(m, r)| m == n && r == &Ok(gl::Probed::Runs))));
}

#[test]
fn worker_command_sets_the_driver_before_it_loads() {
    std::env::set_var(gl::WORKER_EXE_ENV, env!("CARGO_BIN_EXE_shadowcheck"));
    let wc = gl::worker_command("egl:zink:es3").unwrap();
    assert_eq!(wc.args, ["gl-worker", "--backend", "egl:zink:es3"]);
    assert!(wc.env.contains(&("GALLIUM_DRIVER".into(), "zink".into())));
    assert!(wc
        .env
        .contains(&("LIBGL_ALWAYS_SOFTWARE".into(), "1".into())));
    assert!(gl::worker_command("osmesa:zink:core").is_err());
    assert!(gl::worker_command("egl:nope:core")
        .unwrap_err()
        .to_string()
        .contains("driver"));
}

#[test]
fn a_missing_library_is_reported_with_the_install_command() {
    // What a machine without Mesa sees: the worker starts, cannot load the library, and says which
    // package to install (never a build or link failure).
    for (backend, env, pkg) in [
        (
            "osmesa:llvmpipe:core",
            "SHADOWCHECK_LIBOSMESA",
            "libosmesa6",
        ),
        ("egl:llvmpipe:core", "SHADOWCHECK_LIBEGL", "libegl1"),
    ] {
        let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_shadowcheck"));
        c.args(["gl-worker", "--backend", backend, "--probe"])
            .env(env, "/nonexistent/libmissing.so");
        let out = c.output().unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(!out.status.success(), "{backend}: {stdout}");
        assert!(stdout.starts_with("unavailable: "), "{backend}: {stdout}");
        assert!(
            stdout.contains("could not be loaded")
                && stdout.contains("apt-get install -y")
                && stdout.contains(pkg),
            "{backend}: {stdout}"
        );
    }
}

/// A backend the probe calls `RunsNothing` (it starts but exposes none of its specs: left out of
/// the default run as not applicable) really runs nothing: named with `-b`, every test of its spec
/// is a Skip with the probe's reason, and the run exits 4 as before.
#[test]
fn a_backend_that_runs_nothing_skips_every_case_when_named() {
    std::env::set_var(gl::WORKER_EXE_ENV, env!("CARGO_BIN_EXE_shadowcheck"));
    let nothing: Vec<(String, String)> = gl::probe_report()
        .into_iter()
        .filter_map(|(n, r)| match r {
            Ok(gl::Probed::RunsNothing(why)) => Some((n, why)),
            _ => None,
        })
        .collect();
    if nothing.is_empty() {
        eprintln!("SKIPPED (not a pass): no backend here starts without exposing a spec");
        return;
    }
    let (name, why) = &nothing[0];
    let b: BackendName = name.parse().unwrap();
    let spec = match b.api {
        shadowcheck_gl::ContextApi::Es2 => "es2_ext",
        _ => panic!("{name}: only an ES 2.0 context can expose none of its specs ({why})"),
    };
    let dir = std::env::temp_dir().join(format!("sc-runs-nothing-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
        .args(["run", "-b", name, "--cases", &format!("^{spec}/2d/")])
        .arg("--fixtures")
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/../cases/fixtures"))
        .arg("-o")
        .arg(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(4), "{stderr}");
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().filter(|l| !l.is_empty()).collect();
    assert!(!rows.is_empty(), "no test of {spec}/2d on {name}");
    assert!(rows.iter().all(|l| l.contains(",Skip,")), "{csv}");
    let jsonl = std::fs::read_to_string(dir.join("results.jsonl")).unwrap();
    assert!(
        jsonl.contains(why.as_str()),
        "the Skip reason is not the probe's: {why}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
