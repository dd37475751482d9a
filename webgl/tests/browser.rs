//! The worker's handling of a browser that misbehaves, with stand-ins for Chromium (shell scripts
//! and `fake_chromium.py`, a DevTools pipe speaker): a browser that exits without answering, one
//! that never answers, a page whose renderer dies, one that ignores `Browser.close`, and the
//! profile folders of killed workers. No real browser is needed.

use shadowcheck_webgl::browser::{remove_stale_profiles, Browser, Launch, PROFILE_PREFIX};
use shadowcheck_webgl::WebglError;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "shadowcheck-webgl-test-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An executable shell script `name` in `dir`.
fn script(dir: &Path, name: &str, body: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let p = dir.join(name);
    std::fs::write(&p, format!("#!/bin/sh\n{body}\n")).unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o755)).unwrap();
    p
}

/// A browser that runs `fake_chromium.py MODE`.
fn fake(dir: &Path, mode: &str) -> PathBuf {
    let py = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fake_chromium.py");
    script(
        dir,
        &format!("fake-{mode}"),
        &format!("exec python3 {} {mode} \"$@\"", py.display()),
    )
}

/// Runs `f` on a thread of its own; its value, or None when it takes longer than `limit` (a
/// wait without end fails the test instead of hanging it).
fn within<T: Send + 'static>(limit: Duration, f: impl FnOnce() -> T + Send + 'static) -> Option<T> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(limit).ok()
}

fn start_error(exe: PathBuf, start_timeout: Duration, limit: Duration) -> String {
    let t0 = Instant::now();
    let r = within(limit, move || {
        Browser::start_with(&exe, start_timeout, &Launch::default()).map(|_| ())
    });
    match r {
        None => panic!("the start still waited after {limit:?}"),
        Some(Ok(())) => panic!("the start succeeded"),
        Some(Err(e)) => format!("{e} (after {:?})", t0.elapsed()),
    }
}

#[test]
fn a_browser_that_exits_while_a_child_keeps_the_pipe_is_an_error_with_its_status_and_stderr() {
    // The browser's own process exits at once; a child of its keeps the DevTools pipe open for
    // 20 s, so no end of file comes: the wait must watch the process.
    let dir = scratch("exits");
    let exe = script(
        &dir,
        "chromium",
        "echo 'fake-chromium: cannot open the GPU' >&2\nsleep 20 &\nexit 7",
    );
    let e = start_error(exe, Duration::from_secs(15), Duration::from_secs(10));
    assert!(
        e.contains("exited without answering") && e.contains("exit status: 7"),
        "{e}"
    );
    assert!(e.contains("fake-chromium: cannot open the GPU"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_browser_that_never_answers_is_an_error_after_the_start_timeout_with_its_stderr() {
    let dir = scratch("silent");
    let exe = script(
        &dir,
        "chromium",
        "echo 'fake-chromium: waiting' >&2\nexec sleep 60",
    );
    let e = start_error(exe, Duration::from_secs(1), Duration::from_secs(10));
    assert!(
        e.contains("did not start")
            && e.contains("no answer within")
            && e.contains("still running"),
        "{e}"
    );
    assert!(e.contains("fake-chromium: waiting"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_page_whose_renderer_crashed_is_an_error_at_once_not_an_answer_awaited_forever() {
    // Chromium answers no command sent to a page whose renderer process died; it sends the
    // page's Inspector.targetCrashed event (Runtime.evaluate would wait forever).
    let dir = scratch("renderer");
    let exe = fake(&dir, "renderer-crash");
    let r = within(Duration::from_secs(20), move || {
        let mut b = Browser::start_with(&exe, Duration::from_secs(15), &Launch::default())?;
        let first = b.evaluate("shadowcheck.run({})");
        // Every later command to the page fails at once too.
        let second = b.evaluate("1 + 1");
        Ok::<_, WebglError>((first, second))
    });
    let (first, second) = r.expect("the evaluation still waited after 20 s").unwrap();
    for e in [first, second] {
        match e {
            Err(WebglError::Browser(m)) => assert!(
                m.contains("the page's renderer process died (Inspector.targetCrashed)"),
                "{m}"
            ),
            other => panic!("{other:?}"),
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_browser_that_ignores_close_is_killed_after_the_grace_period_and_its_profile_removed() {
    let dir = scratch("close");
    let exe = fake(&dir, "hang-close");
    let b = Browser::start_with(&exe, Duration::from_secs(15), &Launch::default()).unwrap();
    let pid = b.pid();
    let profile = b.profile().to_path_buf();
    assert!(profile.is_dir());
    let name = profile.file_name().unwrap().to_string_lossy().to_string();
    assert!(
        name.starts_with(&format!("{PROFILE_PREFIX}{}-", std::process::id())),
        "{name}"
    );
    let t0 = Instant::now();
    assert!(
        within(Duration::from_secs(10), move || drop(b)).is_some(),
        "dropping the browser still waited after 10 s"
    );
    assert!(t0.elapsed() < Duration::from_secs(5), "{:?}", t0.elapsed());
    // The browser is gone (killed and reaped) and so is its profile.
    let alive = nix::sys::signal::kill(nix::unistd::Pid::from_raw(pid as i32), None).is_ok();
    assert!(!alive, "the browser {pid} still runs");
    assert!(!profile.exists(), "{}", profile.display());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn profile_folders_of_workers_that_no_longer_run_are_removed_and_no_other() {
    let dir = scratch("stale");
    let mut gone = std::process::Command::new("true").spawn().unwrap();
    let dead = gone.id();
    gone.wait().unwrap();
    let stale = dir.join(format!("{PROFILE_PREFIX}{dead}-abc123"));
    let live = dir.join(format!("{PROFILE_PREFIX}{}-def456", std::process::id()));
    let unnamed = dir.join(format!("{PROFILE_PREFIX}ghi789"));
    let other = dir.join("something-else");
    for d in [&stale, &live, &unnamed, &other] {
        std::fs::create_dir_all(d.join("Default")).unwrap();
        std::fs::write(d.join("Default/Preferences"), "{}").unwrap();
    }
    assert_eq!(remove_stale_profiles(&dir), 1);
    assert!(!stale.exists());
    for d in [&live, &unnamed, &other] {
        assert!(d.exists(), "{}", d.display());
    }
    let _ = std::fs::remove_dir_all(&dir);
}
