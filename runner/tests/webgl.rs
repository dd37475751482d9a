//! Must show: the `webgl:chromium` backend runs real fixture cases in headless Chromium (WebGL 2.0
//! on ANGLE / SwiftShader) and the oracle judges them. The committed GLES 3.2 fixtures of the 2D,
//! cube and 2D-array D16 and D32F textures pass on this path (reports/webgl-chromium-*/ lists no
//! failure among them); what WebGL 2.0 lacks is Skip with the reason, never sent: cube-map arrays,
//! DEPTH32F_STENCIL8 uploads, border colours.
//!
//! Without Chromium the test is skipped with a loud message, except under CI=true, where it fails
//! (`.ci/run` installs the package).

mod common;
use common::*;
use std::collections::BTreeMap;
use std::path::PathBuf;

fn chromium_or_skip(test: &str) -> bool {
    match shadowcheck_webgl::browser::chromium_exe() {
        Ok(_) => true,
        Err(e) if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("CI=true but {e}: .ci/run must `apt-get install -y chromium`")
        }
        Err(e) => {
            eprintln!("\n*** SKIPPED {test}: {e} ***\n");
            false
        }
    }
}

fn fixtures() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .join("cases/fixtures")
}

/// (status, reason) of every test in `dir/results.jsonl`, by test name, as the one results.jsonl
/// reader gives them (the last record wins; compact `passed` lines expand to their tests).
fn results(dir: &std::path::Path) -> BTreeMap<String, (String, Option<String>)> {
    shadowcheck_runner::records::read_results(&dir.join("results.jsonl"))
        .unwrap()
        .results
        .into_iter()
        .map(|r| (r.test, (r.status.to_string(), r.reason)))
        .collect()
}

#[test]
fn webgl2_in_headless_chromium_passes_the_d16_and_d32f_fixtures_and_skips_what_it_lacks() {
    if !chromium_or_skip("the webgl:chromium backend test") {
        return;
    }
    let tmp = tmpdir("webgl");
    let out = bin()
        .args(["run", "-v", "--backend", "webgl:chromium", "--fixtures"])
        .arg(fixtures())
        .args([
            "--cases",
            "^gles32/(2d|cube|2darray|cubearray)/(d16|d32f|d32fs8)/",
        ])
        .arg("--out")
        .arg(&tmp)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    // The hello names the WebGL implementation (ANGLE's renderer string, the browser version).
    assert!(
        stderr.contains("implementation: webgl:chromium (WebGL 2.0"),
        "{stderr}"
    );
    // The run's meta line records the renderer.
    let jsonl = std::fs::read_to_string(tmp.join("results.jsonl")).unwrap();
    let meta: serde_json::Value = serde_json::from_str(jsonl.lines().next().unwrap()).unwrap();
    let implementation = meta["implementations"]["webgl:chromium"]
        .as_str()
        .unwrap_or("");
    assert!(
        implementation.starts_with("webgl:chromium (WebGL 2.0") && implementation.contains("ANGLE"),
        "{meta}"
    );
    let r = results(&tmp);
    let count = |s: &str| r.values().filter(|(st, _)| st == s).count();
    assert_eq!(count("Fail") + count("Crash") + count("Timeout"), 0);
    assert!(count("Pass") >= 1000, "{} passed", count("Pass"));
    for (test, (status, reason)) in &r {
        let reason = reason.as_deref().unwrap_or("");
        let want = if test.starts_with("gles32/cubearray/") {
            Some("target `cubearray` not supported")
        } else if test.contains("/d32fs8/") {
            Some("format `d32fs8` not supported")
        } else if test.contains("/stage=compute/") && !test.contains("/gather/") {
            // WebGL 2.0 is ES 3.0: no compute shader (ES 3.1); a compute gather is refused for
            // the gather first (below).
            Some("a compute-stage lookup needs")
        } else if test.contains("/gather/") && !test.contains("wrap=border") {
            // WebGL 2.0 (GLSL ES 3.00) has no textureGather; a gather with CLAMP_TO_BORDER is
            // refused for the border first.
            Some("feature `gather`")
        } else if test.contains("wrap=border") || test.contains("border=") {
            Some("feature `border_clamp`")
        } else {
            None
        };
        match want {
            Some(w) => assert!(
                status == "Skip" && reason.contains(w),
                "{test}: {status} {reason}"
            ),
            // SwiftShader's offset between two mip levels (reports/README.md, WG2): a Warn.
            None if test.contains("/offset/between/") => {
                assert!(status == "Warn", "{test}: {status} {reason}")
            }
            None => assert!(status == "Pass", "{test}: {status} {reason}"),
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

/// `shadowcheck run -b webgl:chromium --cases PATTERN` on the committed fixtures: asserts exit 0
/// and returns the results with the output directory (removed by the caller).
fn run_webgl(dir: &str, pattern: &str) -> (BTreeMap<String, (String, Option<String>)>, PathBuf) {
    let tmp = tmpdir(dir);
    let out = bin()
        .args(["run", "--backend", "webgl:chromium", "--fixtures"])
        .arg(fixtures())
        .args(["--cases", pattern, "--out"])
        .arg(&tmp)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (results(&tmp), tmp)
}

#[test]
fn webgl2_binds_sampler_objects_and_their_state_is_the_one_used() {
    // The `sampler_object` family sets texture and sampler object state to different values, so
    // that sampling with the texture's state gives another r (soft's `sampler-object-ignored`
    // mutant dies on it). WebGL 2.0 has sampler objects; it lacks the swizzle and the border colour.
    if !chromium_or_skip("the webgl:chromium sampler-object test") {
        return;
    }
    let (r, tmp) = run_webgl("webgl-sampler", "^gles32/.*/sampler_object/");
    let mut passed = 0;
    for (test, (status, reason)) in &r {
        let reason = reason.as_deref().unwrap_or("");
        if test.contains("/so_border/") {
            assert!(
                status == "Skip" && reason.contains("feature `border_clamp`"),
                "{test}: {status} {reason}"
            );
        } else if test.contains("/so_swizzle/") {
            assert!(
                status == "Skip" && reason.contains("feature `swizzle`"),
                "{test}: {status} {reason}"
            );
        } else {
            assert!(status == "Pass", "{test}: {status} {reason}");
            passed += 1;
        }
    }
    assert!(passed >= 8, "{passed} sampler-object tests passed: {r:?}");
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn webgl2_answers_the_texparameter_state_cases() {
    // State cases (cases/fixtures/state/gles32.json): the page makes the TexParameter /
    // GetTexParameter call and reports glGetError and the value; the runner judges against the
    // oracle's tables (ES 3.2 §8.10), illegal values included. WebGL 2.0 has no cube-map arrays.
    if !chromium_or_skip("the webgl:chromium state-case test") {
        return;
    }
    let (r, tmp) = run_webgl("webgl-state", "^state/gles32/");
    assert!(r.len() >= 80, "{} state tests", r.len());
    let mut illegal = 0;
    for (test, (status, reason)) in &r {
        let reason = reason.as_deref().unwrap_or("");
        if test.contains("/cubearray/") {
            assert!(
                status == "Skip" && reason.contains("cubearray"),
                "{test}: {status} {reason}"
            );
        } else {
            assert!(status == "Pass", "{test}: {status} {reason}");
        }
        illegal += usize::from(test.contains("/set=") && status == "Pass");
    }
    assert!(illegal > 10, "{illegal} TexParameter calls judged");
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn the_default_run_includes_webgl_chromium_when_installed_and_announces_it_when_absent() {
    // No worker starts (GL or WebGL): the run shows which backends it tried; --skip-missing keeps
    // it going with `soft`.
    let (dir, fx) = cases_dir("webgl-default", 4);
    let out = dir.join("out");
    let default_run = |chromium: Option<&str>| default_run_without_workers(&fx, &out, chromium);
    // Absent: a note with the install command, not an error; the run is all good.
    let r = default_run(Some("/nonexistent/chromium"));
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("note: optional backend `webgl:chromium` is not installed here")
            && r.stderr.contains("apt-get install -y chromium"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("backend `webgl:chromium` cannot start"));
    // Installed: part of the default run (here it cannot start, its worker being nowhere).
    if !chromium_or_skip("the default-run half of the webgl:chromium default test") {
        return;
    }
    let r = default_run(None);
    assert!(
        r.stderr
            .contains("left out (--skip-missing): backend `webgl:chromium` cannot start here"),
        "{}",
        r.stderr
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_browser_that_dies_at_start_is_a_backend_that_cannot_start_with_the_reason() {
    // /bin/false as the browser: it exits at once, closing the DevTools pipe before any answer.
    let (dir, fx) = cases_dir("webgl-dead", 2);
    let r = Run::of(
        bin()
            .args([
                "run",
                "--backend",
                "webgl:chromium",
                "--fixtures",
                &fx,
                "--out",
            ])
            .arg(dir.join("out"))
            .env(shadowcheck_webgl::browser::CHROMIUM_ENV, "/bin/false")
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("backend `webgl:chromium` cannot start here")
            && r.stderr.contains("DevTools pipe"),
        "{}",
        r.stderr
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_rejected_tex_parameter_is_an_error_answer_naming_the_call() {
    if !chromium_or_skip("the webgl:chromium TexParameter error test") {
        return;
    }
    // A GLES 3.2 case from the fixtures, drawn as is and with MIRROR_CLAMP_TO_EDGE on s: WebGL
    // accepts an extension's enums only once the page has enabled it with getExtension (the WebGL
    // specification's extension rules; INVALID_ENUM otherwise), and the page does not enable
    // EXT_texture_mirror_clamp_to_edge.
    let file = fixtures().join("gles32/2d/nearest.json");
    let fixture: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let mut case = fixture["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["texture"]["format"] == "d16" && c["sampler"]["wrap_s"] == "edge")
        .unwrap()
        .clone();
    case.as_object_mut().unwrap().remove("expect");
    let mut bad = case.clone();
    bad["id"] = serde_json::json!(format!("{}-mirror", case["id"].as_str().unwrap()));
    bad["sampler"]["wrap_s"] = serde_json::json!("mirror_edge");
    let input: Vec<String> = [
        serde_json::json!({"type": "hello", "protocol": 1}),
        serde_json::json!({"type": "case", "case": case}),
        serde_json::json!({"type": "case", "case": bad}),
        serde_json::json!({"type": "flush"}),
        serde_json::json!({"type": "bye"}),
    ]
    .iter()
    .map(|m| m.to_string())
    .collect();
    let mut child = bin()
        .arg("webgl-worker")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    {
        use std::io::Write;
        let mut stdin = child.stdin.take().unwrap();
        stdin
            .write_all((input.join("\n") + "\n").as_bytes())
            .unwrap();
    }
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success());
    let lines: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 3, "{lines:?}");
    assert_eq!(lines[1]["type"], "observation", "{}", lines[1]);
    assert_eq!(lines[2]["type"], "error", "{}", lines[2]);
    assert_eq!(
        lines[2]["message"],
        "glTexParameteri(TEXTURE_WRAP_S) raised GL_INVALID_ENUM"
    );
}

/// A browser for `SHADOWCHECK_CHROMIUM` in `dir`: `webgl/tests/fake_chromium.py MODE` (a
/// DevTools pipe speaker standing in for Chromium).
fn fake_chromium(dir: &std::path::Path, mode: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let py = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .join("webgl/tests/fake_chromium.py");
    let p = dir.join(format!("chromium-{mode}"));
    std::fs::write(
        &p,
        format!("#!/bin/sh\nexec python3 {} {mode} \"$@\"\n", py.display()),
    )
    .unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o755)).unwrap();
    p
}

/// One lookup (r = 1: a context lost before the read-back reads (0,0,0,0), a Fail) and one state
/// case of the committed GLES 3.2 fixtures.
const ONE_LOOKUP: &str =
    "^gles32/2d/d16/nearest/notequal/texel1/ref=0\\.5/dt=0\\.2_0\\.4_0\\.6_0\\.8$";
const ONE_STATE: &str = "^state/gles32/es/2d/compare_mode/initial$";

/// `run -b webgl:chromium` on the two committed fixture files of [`ONE_LOOKUP`] and
/// [`ONE_STATE`] with the worker's test fault `fault`.
fn run_with_fault(dir: &str, pattern: &str, fault: &str, extra: &[&str]) -> (Run, PathBuf) {
    let tmp = tmpdir(dir);
    let r = Run::of(
        bin()
            .args(["run", "-v", "--backend", "webgl:chromium", "--fixtures"])
            .arg(fixtures().join("gles32/2d/nearest.json"))
            .arg("--fixtures")
            .arg(fixtures().join("state/gles32.json"))
            .args(["--cases", pattern])
            .args(extra)
            .arg("--out")
            .arg(&tmp)
            .env(shadowcheck_webgl::worker::TEST_FAULT_ENV, fault)
            .output()
            .unwrap(),
    );
    (r, tmp)
}

#[test]
fn a_lost_webgl_context_is_a_crash_of_the_cases_in_flight_never_a_verdict() {
    // WEBGL_lose_context's loseContext() in the real page, in every worker: once the lookup's
    // texture group is drawn (before the read-back), and before the state case's call. What the
    // page would read then ((0,0,0,0); CONTEXT_LOST_WEBGL from getError) is never an answer.
    if !chromium_or_skip("the webgl:chromium lost-context test") {
        return;
    }
    let pattern = format!("{ONE_LOOKUP}|{ONE_STATE}");
    let (r, tmp) = run_with_fault("webgl-lost", &pattern, "lose-context", &[]);
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let res = results(&tmp);
    assert_eq!(res.len(), 2, "{res:?}");
    for (test, (status, reason)) in &res {
        let reason = reason.as_deref().unwrap_or("");
        assert_eq!(status, "Crash", "{test}: {status} {reason}");
        assert!(
            reason.contains("the WebGL context was lost (")
                && reason.contains("the cases in flight are not answered"),
            "{test}: {reason}"
        );
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn a_dead_renderer_is_a_crash_with_the_reason_not_a_timeout() {
    // Page.crash before each job: the page's renderer process dies and Chromium never answers
    // the job's Runtime.evaluate (it sends Inspector.targetCrashed). --timeout 60: waiting for
    // the answer would be a Timeout a minute later.
    if !chromium_or_skip("the webgl:chromium dead-renderer test") {
        return;
    }
    let (r, tmp) = run_with_fault(
        "webgl-renderer",
        ONE_LOOKUP,
        "crash-renderer",
        &["--timeout", "60"],
    );
    assert_eq!(r.code, 100, "{}{}", r.stdout, r.stderr);
    let res = results(&tmp);
    assert_eq!(res.len(), 1, "{res:?}");
    for (test, (status, reason)) in &res {
        let reason = reason.as_deref().unwrap_or("");
        assert_eq!(status, "Crash", "{test}: {status} {reason}");
        assert!(
            reason.contains("the page's renderer process died"),
            "{test}: {reason}"
        );
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn a_browser_that_cannot_start_says_why_not_no_hello_within_30_s() {
    // The browser exits at once with a message, but a child of its keeps the DevTools pipe open
    // (no end of file): the reason is its exit status and stderr, given at once.
    use std::os::unix::fs::PermissionsExt;
    let (dir, fx) = cases_dir("webgl-nostart", 2);
    let exe = dir.join("chromium");
    std::fs::write(
        &exe,
        "#!/bin/sh\necho 'fake-chromium: error while loading shared libraries: libfoo.so' >&2\nsleep 40 &\nexit 127\n",
    )
    .unwrap();
    std::fs::set_permissions(&exe, std::fs::Permissions::from_mode(0o755)).unwrap();
    let t0 = std::time::Instant::now();
    let r = Run::of(
        bin()
            .args(["run", "-b", "webgl:chromium", "--fixtures", &fx, "--out"])
            .arg(dir.join("out"))
            .env(shadowcheck_webgl::browser::CHROMIUM_ENV, &exe)
            .output()
            .unwrap(),
    );
    assert_eq!(r.code, 96, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("backend `webgl:chromium` cannot start here")
            && r.stderr.contains("exit status: 127")
            && r.stderr
                .contains("error while loading shared libraries: libfoo.so"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("no hello within"), "{}", r.stderr);
    assert!(t0.elapsed().as_secs() < 25, "{:?}", t0.elapsed());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_killed_workers_profile_folder_is_removed_by_the_next_worker() {
    // SIGKILL leaves the worker no exit path: its browser dies with it (PR_SET_PDEATHSIG), its
    // profile folder stays, named by its pid; the next worker's start removes it. A worker that
    // ends by itself removes its own, also when its page cannot start.
    let (dir, _) = cases_dir("webgl-profile", 1);
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).unwrap();
    let profiles = || -> Vec<String> {
        std::fs::read_dir(&tmp)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().to_string())
            .filter(|n| n.starts_with(shadowcheck_webgl::browser::PROFILE_PREFIX))
            .collect()
    };
    let worker = |mode: &str| {
        let mut c = bin();
        c.arg("webgl-worker")
            .env("TMPDIR", &tmp)
            .env(
                shadowcheck_webgl::browser::CHROMIUM_ENV,
                fake_chromium(&dir, mode),
            )
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped());
        c
    };
    let mut w = worker("page").spawn().unwrap();
    {
        use std::io::{BufRead, Write};
        let mut stdin = w.stdin.take().unwrap();
        stdin
            .write_all(b"{\"type\":\"hello\",\"protocol\":2}\n")
            .unwrap();
        let mut line = String::new();
        std::io::BufReader::new(w.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        assert!(line.contains("\"hello\""), "{line}");
        // The worker runs, with its browser and page: kill it.
        let pid = w.id();
        assert_eq!(
            profiles()
                .iter()
                .filter(|n| n.contains(&format!("-{pid}-")))
                .count(),
            1,
            "{:?}",
            profiles()
        );
        w.kill().unwrap();
        w.wait().unwrap();
        drop(stdin);
    }
    assert_eq!(profiles().len(), 1, "{:?}", profiles());
    // The next worker (here one whose page has no context: it exits at start) removes it, and
    // its own.
    let out = worker("ok").output().unwrap();
    assert!(!out.status.success());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("fake: no WebGL 2.0 context"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(profiles(), Vec::<String>::new());
    let _ = std::fs::remove_dir_all(&dir);
}
