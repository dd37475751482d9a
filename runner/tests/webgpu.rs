//! Must show: the `webgpu:chromium` backend runs real `webgpu/` fixture cases in headless Chromium
//! (WebGPU on Dawn / SwiftShader, WGSL) and the oracle judges them: a few dozen cases across the
//! four targets and five formats, level-0 (`textureSampleCompareLevel`) and implicit-derivative
//! (`textureSampleCompare`) lookups, gathers (`textureGatherCompare`, one with an offset) and
//! offsets. A case the oracle gives a unique answer to (every strict interval one point) passes;
//! the others pass or warn; none fails or crashes. What WebGPU or WGSL cannot express is Skip with
//! its reason (a border colour; a layer coordinate that is no integer). A validation error is a
//! harness bug that fails every test of its batch, quoting the message; a lost device ends the
//! worker and its cases are Crash, never judged on what it read.
//!
//! Without Chromium or a WebGPU adapter the tests are skipped with a loud message, except under
//! CI=true, where they fail (`.ci/run` installs the package).

mod common;
use common::*;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Whether the backend can start here (the browser and an adapter): skipped loudly when not,
/// failed under CI=true.
fn webgpu_or_skip(test: &str) -> bool {
    let why = match shadowcheck_webgl::browser::chromium_exe() {
        Err(e) => e.to_string(),
        Ok(_) => {
            let out = bin()
                .args(["webgpu-worker", "--backend", "webgpu:chromium", "--probe"])
                .output()
                .unwrap();
            let line = String::from_utf8_lossy(&out.stdout).trim().to_string();
            if out.status.success() && line.starts_with("ok ") {
                return true;
            }
            format!("no WebGPU adapter: {line}")
        }
    };
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but {why}: .ci/run must `apt-get install -y chromium`");
    }
    eprintln!("\n*** SKIPPED {test}: {why} ***\n");
    false
}

fn fixtures() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .join("cases/fixtures/webgpu")
}

/// Every case of the committed webgpu fixtures, as JSON.
fn all_cases() -> Vec<Value> {
    let mut out = vec![];
    let mut files: Vec<PathBuf> = std::fs::read_dir(fixtures())
        .unwrap()
        .flat_map(|d| std::fs::read_dir(d.unwrap().path()).unwrap())
        .map(|f| f.unwrap().path())
        .collect();
    files.sort();
    for f in files {
        let v: Value = serde_json::from_str(&std::fs::read_to_string(&f).unwrap()).unwrap();
        out.extend(v["cases"].as_array().unwrap().iter().cloned());
    }
    out
}

/// What the test expects of a selected case.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Want {
    /// Pass where the oracle's answer is unique, else Pass or Warn.
    Drawn,
}

/// The subset: per target and format a level-0 case and an implicit-derivative one, gathers
/// (one with an offset, one on a cube), offsets on 2D and 2D arrays.
fn subset(cases: &[Value]) -> BTreeMap<String, (Want, Value)> {
    let mut out = BTreeMap::new();
    let id = |c: &Value| c["id"].as_str().unwrap().to_string();
    let lod = |c: &Value| c["lookup"]["lod"].as_f64().unwrap_or(0.0);
    let has = |c: &Value, k: &str| c["lookup"].get(k).is_some();
    let border = |c: &Value| c["sampler"]["border"] != serde_json::json!([0.0, 0.0, 0.0, 0.0]);
    let layer_ok = |c: &Value| {
        c["texture"]["target"] != "2darray"
            || c["lookup"]["coord"][2].as_f64().unwrap().fract() == 0.0
    };
    let plain = |c: &Value| !has(c, "gather") && !has(c, "offset") && !border(c) && layer_ok(c);
    let mut pick = |want: Want, f: &dyn Fn(&Value) -> bool| {
        if let Some(c) = cases.iter().find(|c| f(c) && !out.contains_key(&id(c))) {
            out.insert(id(c), (want, c.clone()));
        } else {
            panic!("no fixture case for one of the picks");
        }
    };
    for t in ["2d", "2darray", "cube", "cubearray"] {
        for f in ["d16", "d24", "d24s8", "d32f", "d32fs8"] {
            let of = |c: &Value| c["texture"]["target"] == t && c["texture"]["format"] == f;
            pick(Want::Drawn, &|c| of(c) && plain(c) && lod(c) == 0.0);
            pick(Want::Drawn, &|c| of(c) && plain(c) && lod(c) != 0.0);
        }
    }
    pick(Want::Drawn, &|c| has(c, "gather") && has(c, "offset"));
    pick(Want::Drawn, &|c| {
        has(c, "gather") && c["texture"]["target"] == "cube"
    });
    pick(Want::Drawn, &|c| {
        !has(c, "gather") && has(c, "offset") && c["texture"]["target"] == "2d"
    });
    pick(Want::Drawn, &|c| {
        !has(c, "gather") && has(c, "offset") && c["texture"]["target"] == "2darray" && layer_ok(c)
    });
    // The grid sends WebGPU no border colour and no fractional layer (cases/README.md's
    // filters); the worker's refusals of both are unit tests (plan/src/shaders/wgsl,
    // webgpu/src/job) and the runner's capability checks.
    out
}

/// Is every strict interval of the case (and of each sweep point) a single point?
fn unique(c: &Value) -> bool {
    let one = |e: &Value| {
        let s = e["accept"]["strict"].as_array().unwrap();
        s.len() == 1 && s[0]["lo"] == s[0]["hi"]
    };
    one(&c["expect"])
        && c["sweep"]
            .as_array()
            .is_none_or(|p| p.iter().all(|p| one(&p["expect"])))
}

/// `^(id|id|...)$` for the case ids.
fn pattern<'a>(ids: impl Iterator<Item = &'a String>) -> String {
    let alts: Vec<String> = ids.map(|i| regex::escape(i)).collect();
    format!("^({})$", alts.join("|"))
}

/// (status, reason) by test name.
type Results = BTreeMap<String, (String, Option<String>)>;

/// (status, reason) of every test in `dir/results.jsonl`, by test name.
fn results(dir: &std::path::Path) -> Results {
    shadowcheck_runner::records::read_results(&dir.join("results.jsonl"))
        .unwrap()
        .results
        .into_iter()
        .map(|r| (r.test, (r.status.to_string(), r.reason)))
        .collect()
}

fn run_webgpu(
    dir: &str,
    pattern: &str,
    env: &[(&str, &str)],
) -> (std::process::Output, Results, PathBuf) {
    let tmp = tmpdir(dir);
    let out = bin()
        .args([
            "run",
            "-v",
            "--backend",
            "webgpu:chromium",
            "--no-rerun",
            "--fixtures",
        ])
        .arg(fixtures())
        .args(["--cases", pattern, "--out"])
        .arg(&tmp)
        .envs(env.iter().copied())
        .output()
        .unwrap();
    let r = results(&tmp);
    (out, r, tmp)
}

#[test]
fn webgpu_in_headless_chromium_passes_a_subset_of_the_webgpu_fixtures() {
    if !webgpu_or_skip("the webgpu:chromium backend test") {
        return;
    }
    let picked = subset(&all_cases());
    assert!(picked.len() >= 44, "{} cases picked", picked.len());
    let t0 = std::time::Instant::now();
    let (out, r, tmp) = run_webgpu("webgpu", &pattern(picked.keys()), &[]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    // The hello names the adapter (Dawn's SwiftShader adapter here) and the browser.
    let jsonl = std::fs::read_to_string(tmp.join("results.jsonl")).unwrap();
    let meta: Value = serde_json::from_str(jsonl.lines().next().unwrap()).unwrap();
    let implementation = meta["implementations"]["webgpu:chromium"]
        .as_str()
        .unwrap_or("");
    assert!(
        implementation.starts_with("webgpu:chromium (")
            && implementation.contains("maxTextureDimension2D"),
        "{meta}"
    );
    assert_eq!(r.len(), picked.len(), "{r:?}");
    let mut unique_passes = 0;
    for (id, (want, case)) in &picked {
        let test = format!("{id}@wgsl");
        let (status, reason) = r
            .get(&test)
            .unwrap_or_else(|| panic!("no result for {test}"));
        let reason = reason.as_deref().unwrap_or("");
        match want {
            Want::Drawn if unique(case) => {
                assert_eq!(status, "Pass", "{test}: {reason}");
                unique_passes += 1;
            }
            Want::Drawn => assert!(
                status == "Pass" || status == "Warn",
                "{test}: {status} {reason}"
            ),
        }
    }
    assert!(unique_passes >= 30, "{unique_passes} unique answers passed");
    eprintln!("{} webgpu tests in {:?}", r.len(), t0.elapsed());
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn a_validation_error_fails_its_batch_and_a_lost_device_is_a_crash() {
    if !webgpu_or_skip("the webgpu:chromium fault test") {
        return;
    }
    let cases = all_cases();
    let two: Vec<String> = cases
        .iter()
        .filter(|c| c["texture"]["target"] == "2d" && c.get("sweep").is_none())
        .take(2)
        .map(|c| c["id"].as_str().unwrap().to_string())
        .collect();
    let env = shadowcheck_webgpu::worker::TEST_FAULT_ENV;
    // A sampler with lodMinClamp -1 (WebGPU createSampler: a validation error): every
    // test of the batch fails, quoting the validation message, never a pass on what was drawn.
    let (out, r, tmp) = run_webgpu(
        "webgpu-invalid",
        &pattern(two.iter()),
        &[(env, "invalid-sampler")],
    );
    assert_eq!(
        out.status.code(),
        Some(100),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(r.len(), 2);
    for (test, (status, reason)) in &r {
        let reason = reason.as_deref().unwrap_or("");
        assert!(
            status == "Fail"
                && reason.contains("validation error")
                && reason.contains("harness bug"),
            "{test}: {status} {reason}"
        );
    }
    let _ = std::fs::remove_dir_all(&tmp);
    // GPUDevice.destroy() after the submission: the device is lost, the worker ends without
    // answering, the runner re-runs the cases in fresh browsers and each is a Crash naming why.
    let (out, r, tmp) = run_webgpu(
        "webgpu-lost",
        &pattern(two.iter()),
        &[(env, "destroy-device")],
    );
    assert_eq!(
        out.status.code(),
        Some(100),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for (test, (status, reason)) in &r {
        let reason = reason.as_deref().unwrap_or("");
        assert!(
            status == "Crash" && reason.contains("the WebGPU device is gone"),
            "{test}: {status} {reason}"
        );
    }
    let _ = std::fs::remove_dir_all(&tmp);
}

#[test]
fn the_default_run_includes_webgpu_chromium_when_installed_and_announces_it_when_absent() {
    // No worker starts: the run shows which backends it tried; --skip-missing keeps it going
    // with `soft`.
    let (dir, fx) = cases_dir("webgpu-default", 4);
    let out = dir.join("out");
    let default_run = |chromium: Option<&str>| default_run_without_workers(&fx, &out, chromium);
    // Absent: a note with the install command, not an error; the compat variant is never in it.
    let r = default_run(Some("/nonexistent/chromium"));
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stderr
            .contains("note: optional backend `webgpu:chromium` is not installed here")
            && r.stderr.contains("apt-get install -y chromium"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("webgpu:chromium-compat"), "{}", r.stderr);
    if shadowcheck_webgl::browser::chromium_exe().is_err() {
        eprintln!(
            "\n*** SKIPPED the installed half of the webgpu default-run test: no Chromium ***\n"
        );
        return;
    }
    // Installed: part of the default run (here it cannot start, its worker being nowhere).
    let r = default_run(None);
    assert!(
        r.stderr
            .contains("left out (--skip-missing): backend `webgpu:chromium` cannot start here"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("webgpu:chromium-compat"), "{}", r.stderr);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The observed RGBA of `test` in a `run --full-report` of its case.
fn harness_observed(dir: &str, test: &str) -> [f64; 4] {
    let id = test.rsplit_once('@').unwrap().0;
    let tmp = tmpdir(dir);
    let out = bin()
        .args([
            "run",
            "--backend",
            "webgpu:chromium",
            "--full-report",
            "--fixtures",
        ])
        .arg(fixtures())
        .args(["--cases", &format!("^{}$", regex::escape(id)), "--out"])
        .arg(&tmp)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r = shadowcheck_runner::records::read_results(&tmp.join("results.jsonl")).unwrap();
    let rec = r.results.into_iter().find(|r| r.test == test).unwrap();
    let _ = std::fs::remove_dir_all(&tmp);
    rec.observed
        .unwrap_or_else(|| panic!("{test}: no observed value"))
        .0
}

#[test]
fn the_standalone_page_reproduces_the_harness_observation() {
    if !webgpu_or_skip("the webgpu:chromium repro test") {
        return;
    }
    let same = |a: [f64; 4], b: [f64; 4]| a.iter().zip(b).all(|(x, y)| (*x as f32) == (y as f32));
    // A pass (an offset on a 2D array, the level-0 form), a gather, and a Warn (WG1: a cube lookup
    // with implicit derivatives, r = 0.5625 on SwiftShader): the page, with no shadowcheck code,
    // prints the very RGBA the harness observed.
    for (test, pass) in [
        (
            "webgpu/2darray/d24/nearest/lequal/offset/wrap=edge/texel=1_2/offset=2_-1/ref=0.5@wgsl",
            true,
        ),
        (
            "webgpu/2d/d24/linear/lequal/gather/uv=1.75_2.25/ref=0.5@wgsl",
            true,
        ),
        (
            "webgpu/cube/d16/lml/less/lod=1/ref=0.5/levels=0.2_0.8_0.4@wgsl",
            false,
        ),
    ] {
        let dir = tmpdir("webgpu-repro");
        let mut c = bin();
        c.args([
            "repro",
            "-b",
            "webgpu:chromium",
            "--case",
            test,
            "--fixtures",
        ])
        .arg(fixtures())
        .arg("-o")
        .arg(&dir);
        if pass {
            c.arg("--allow-pass");
        }
        let out = c.output().unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        let stderr = String::from_utf8_lossy(&out.stderr);
        // Not a Fail: exit 0 with --allow-pass; without it 1 ("not a Fail here"), no REPORT.md.
        assert_eq!(
            out.status.code(),
            Some(if pass { 0 } else { 1 }),
            "{stdout}{stderr}"
        );
        assert!(dir.join("repro.html").is_file() && !dir.join("REPORT.md").exists());
        let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
        assert!(
            !page.contains("shadowcheck."),
            "the page calls no shadowcheck code"
        );
        let text = std::fs::read_to_string(dir.join("output.txt")).unwrap();
        let observed = repro_observed(&text);
        let harness = harness_observed("webgpu-repro-run", test);
        assert!(
            same(observed, harness),
            "{test}: page {observed:?}, harness {harness:?}"
        );
        assert!(
            text.contains(if pass {
                "verdict:   pass"
            } else {
                "verdict:   warn"
            }),
            "{text}"
        );
        if pass {
            // The exit-1 path: the same page with an accepted set no result lies in.
            let tampered = page
                .replace("const ACCEPTED = [", "const ACCEPTED = [[-9, -8]] || [")
                .replace(
                    "const GATHER_ACCEPTED = [",
                    "const GATHER_ACCEPTED = [[], [], [], []] || [",
                );
            std::fs::write(dir.join("repro.html"), tampered).unwrap();
            let o = std::process::Command::new("sh")
                .arg(dir.join("build.sh"))
                .output()
                .unwrap();
            let s = String::from_utf8_lossy(&o.stdout);
            assert_eq!(o.status.code(), Some(1), "{s}");
            assert!(s.contains("verdict:   FAIL"), "{s}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The compute-stage cube-edge case (reports/README.md "V1": SwiftShader's compute shaders have
/// no cube map edge handling until a draw has sampled the image; a Flake in full runs, order
/// dependent, deterministic alone): run alone in the harness, then `repro`. The generated page
/// dispatches the worker's compute module (no draw of the lookup before the dispatch), prints the
/// RGBA the harness observed bit for bit and gives the harness's verdict: a Fail (REPORT.md,
/// build.sh exit 1), or a pass where the harness passed it in this run. Without Chromium:
/// skipped loudly, failed under CI=true.
#[test]
fn the_compute_stage_page_reproduces_the_harness_observation() {
    if !webgpu_or_skip("the webgpu:chromium compute-stage repro test") {
        return;
    }
    use shadowcheck_runner::records::Outcome;
    let test = "webgpu/cube/d24/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/x0=0.9/edge_s/ref=0.5@wgsl";
    let out = tmpdir("webgpu-repro-compute");
    let (rec, rc, dir) = harness_then_repro("webgpu:chromium", test, &fixtures(), &out);
    assert_eq!(rc.code, 0, "{}{}", rc.stdout, rc.stderr);
    let page = std::fs::read_to_string(dir.join("repro.html")).unwrap();
    assert!(
        !page.contains("shadowcheck."),
        "the page calls no shadowcheck code"
    );
    assert!(
        page.contains("@compute @workgroup_size(1)")
            && page.contains("const COMPUTE_BINDINGS = [[")
    );
    let harness = rec.observed.as_ref().expect("harness observed nothing").0;
    let text = std::fs::read_to_string(dir.join("output.txt")).unwrap();
    let observed = repro_observed(&text);
    assert!(
        harness
            .iter()
            .zip(observed)
            .all(|(h, o)| (*h as f32).to_bits() == (o as f32).to_bits()),
        "harness observed {harness:?}, page {observed:?}\n{text}"
    );
    let (verdict, code) = match rec.outcome {
        Outcome::Fail => ("verdict:   FAIL", 1),
        Outcome::Pass => ("verdict:   pass", 0),
        o => panic!("{test}: the harness says {o:?} ({:?})", rec.reason),
    };
    assert!(text.contains(verdict), "{text}");
    assert_eq!(dir.join("REPORT.md").is_file(), code == 1);
    // On its own, as a driver developer runs it: the same verdict as exit status.
    let o = std::process::Command::new("sh")
        .arg(dir.join("build.sh"))
        .output()
        .unwrap();
    let s = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(code), "{s}");
    assert!(s.contains(verdict), "{s}");
    let _ = std::fs::remove_dir_all(&out);
}

/// The observed RGBA of every result in a `--full-report` run's results.jsonl, by test name.
fn observed(dir: &std::path::Path) -> BTreeMap<String, Vec<f64>> {
    std::fs::read_to_string(dir.join("results.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str::<Value>(l).unwrap())
        .filter(|v| v["kind"] == "result")
        .map(|v| {
            let rgba = v["observed"].as_array().unwrap().iter();
            let rgba = rgba.map(|x| x.as_f64().unwrap()).collect();
            (v["test"].as_str().unwrap().to_string(), rgba)
        })
        .collect()
}

/// Compute-stage lookups on webgpu:chromium (one workgroup per lookup, the result copied into
/// its slot): a face-centre lookup (`inside`, every texel of the footprint on one face: 1 at ref
/// 0.5, 0 at ref 0.7), a face-edge lookup whose value the fragment stage gives too (face 2 of the
/// `cube` family: 0.7 x 0.5 of the face's texels pass, the neighbour face's fail: 0.35) and a
/// cube gather give the oracle's values, as the fixtures' `expect` states them. Without
/// Chromium: skipped loudly, failed under CI=true (`webgpu_or_skip`); an explicit run of the
/// compute cases with no browser fails and says why.
#[test]
fn compute_stage_lookups_on_webgpu_chromium_give_the_oracles_values() {
    let centre = "webgpu/cube/d24/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/lod=0/inside/ref=0.5";
    let centre_fail = "webgpu/cube/d24/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/lod=0/inside/ref=0.7";
    let edge = "webgpu/cube/d32f/linear/lequal/cube/stage=compute/face=2/edge/ref=0.39";
    let gather = "webgpu/cube/d32f/nearest/lequal/gather/stage=compute/uv=1.75_2.25/ref=0.75";
    let cases: BTreeMap<String, Value> = all_cases()
        .into_iter()
        .map(|c| (c["id"].as_str().unwrap().to_string(), c))
        .collect();
    // The values the oracle gives, from the fixtures (and by hand, for the scalar ones).
    let want: Vec<(&str, Vec<f64>)> = vec![
        (centre, vec![1.0]),
        (centre_fail, vec![0.0]),
        (edge, vec![0.35]),
        (gather, vec![1.0, 1.0, 0.0, 0.0]),
    ];
    for (id, w) in &want {
        let e = &cases.get(*id).unwrap_or_else(|| panic!("no fixture {id}"))["expect"];
        assert_eq!(
            e["accept"]["strict"].as_array().map(Vec::len),
            Some(1),
            "{id}: {e}"
        );
        if w.len() == 1 {
            let s = &e["accept"]["strict"][0];
            let (lo, hi) = (s["lo"].as_f64().unwrap(), s["hi"].as_f64().unwrap());
            assert!(lo <= w[0] + 1e-6 && w[0] - 1e-6 <= hi, "{id}: {e}");
        }
    }
    let ids: Vec<String> = want.iter().map(|(i, _)| i.to_string()).collect();
    // No browser: an explicit run of these cases is an error that names the install, not a pass.
    let tmp = tmpdir("webgpu-compute-nobrowser");
    let out = bin()
        .args(["run", "--backend", "webgpu:chromium", "--fixtures"])
        .arg(fixtures())
        .args(["--cases", &pattern(ids.iter()), "--out"])
        .arg(&tmp)
        .env(
            shadowcheck_webgl::browser::CHROMIUM_ENV,
            "/nonexistent/chromium",
        )
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{stderr}");
    assert!(stderr.contains("/nonexistent/chromium"), "{stderr}");
    let _ = std::fs::remove_dir_all(&tmp);
    if !webgpu_or_skip("the webgpu:chromium compute-stage test") {
        return;
    }
    let tmp = tmpdir("webgpu-compute");
    let out = bin()
        .args([
            "run",
            "--full-report",
            "--no-rerun",
            "--backend",
            "webgpu:chromium",
            "--fixtures",
        ])
        .arg(fixtures())
        .args(["--cases", &pattern(ids.iter()), "--out"])
        .arg(&tmp)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let r = results(&tmp);
    let seen = observed(&tmp);
    for (id, w) in &want {
        let test = format!("{id}@wgsl");
        let (status, reason) = r
            .get(&test)
            .unwrap_or_else(|| panic!("no result for {test}"));
        assert_eq!(status, "Pass", "{test}: {reason:?}");
        let got = seen
            .get(&test)
            .unwrap_or_else(|| panic!("no observation of {test}"));
        for (i, w) in w.iter().enumerate() {
            assert!(
                (got[i] - w).abs() < 1e-6,
                "{test}: observed {got:?}, want {w} in channel {i}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
}
