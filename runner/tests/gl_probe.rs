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
            (Some(_), Ok(())) => panic!("{name} cannot work, yet probed available"),
            (Some(why), Err(e)) => assert_eq!(&why, e),
            (None, Ok(())) => {}
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
    assert!(available
        .iter()
        .all(|n| report.iter().any(|(m, r)| m == n && r.is_ok())));
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
