//! `shadowcheck repro` end to end on Mesa: for one known failing test of each Mesa cause in
//! reports/README.md that is a "shall" violation (a Fail), the harness runs the test, then the
//! reproducer is written, built with the system C compiler and run on its own; it must exit 1 and
//! print the very RGBA the harness observed. A test that passes on its backend gives a reproducer
//! that exits 0 (and no REPORT.md). Nothing here is a driver value written down: the expectation is
//! the oracle's (inside repro.c) and the observation is compared with the harness's of this run.
//!
//! Needs gcc, the GL dev packages (libegl-dev libgles-dev libgl-dev libosmesa6-dev) and the Mesa
//! drivers: missing ones are a loud skip, a failure under CI=true (see gl_support).
mod common;
use common::{grid_fixture_file, repro_observed};
mod gl_support;

use shadowcheck_runner::records::{read_results, Outcome, RESULTS_FILE};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// What the harness and the reproducer said about one test.
struct Both {
    harness: Outcome,
    harness_rgba: [f64; 4],
    repro_exit: i32,
    repro_rgba: [f64; 4],
    repro_cmd_exit: i32,
    dir: PathBuf,
}

/// Runs `test` on `backend` in the harness, then `shadowcheck repro` for it, then the reproducer's
/// build.sh on its own. `None` when the backend or the toolchain is missing (reported).
fn both(backend: &str, test: &str, name: &str, extra: &[&str]) -> Option<Both> {
    if let Err(e) = shadowcheck_runner::backend::gl::worker_command(backend) {
        gl_support::unavailable(backend, &e.to_string());
        return None;
    }
    if !gl_support::can_build(backend) {
        return None;
    }
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let fixtures = grid_fixture_file(&id);
    let out = common::tmpdir(name);
    let pattern = format!("^{}$", regex::escape(&id));
    let run_dir = out.join("run");
    let r = common::run(&[
        "--backend",
        backend,
        "--fixtures",
        fixtures.to_str().unwrap(),
        "--cases",
        &pattern,
        "--no-rerun",
        // Full records for passes too: the observed value of a pass is a detail.
        "--full-report",
        "--out",
        run_dir.to_str().unwrap(),
    ]);
    if r.code == 96 && r.stderr.contains("cannot start") {
        gl_support::unavailable(backend, r.stderr.trim());
        return None;
    }
    let results = read_results(&run_dir.join(RESULTS_FILE)).unwrap();
    let rec = results
        .get(backend, test)
        .unwrap_or_else(|| panic!("{test} not in the run's results: {}", r.stderr));
    let harness_rgba = rec.observed.as_ref().expect("harness observed nothing").0;
    let dir = out.join("repro");
    let mut cmd = common::bin();
    cmd.args(["repro", "--backend", backend, "--case", test, "--fixtures"])
        .arg(&fixtures)
        .arg("--out")
        .arg(&dir)
        .args(extra);
    let rc = common::Run::of(cmd.output().unwrap());
    assert!(
        dir.join("repro.c").is_file(),
        "no repro.c: {}{}",
        rc.stdout,
        rc.stderr
    );
    // The reproducer on its own, as a driver developer runs it.
    let own = Command::new("sh")
        .arg("build.sh")
        .current_dir(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&own.stdout).into_owned();
    assert!(
        matches!(own.status.code(), Some(0 | 1)),
        "reproducer setup failed:\n{stdout}{}",
        String::from_utf8_lossy(&own.stderr)
    );
    Some(Both {
        harness: rec.outcome,
        harness_rgba,
        repro_exit: own.status.code().unwrap_or(-1),
        repro_rgba: repro_observed(&stdout),
        repro_cmd_exit: rc.code,
        dir,
    })
}

/// The harness's observation is f32 read back as f64; the reproducer prints f32 with 9 digits.
fn same_rgba(a: [f64; 4], b: [f64; 4]) -> bool {
    a.iter().zip(b).all(|(x, y)| (*x as f32) == (y as f32))
}

/// A Mesa "shall" failure: the harness says Fail, `repro` writes REPORT.md (exit 0), the program
/// exits 1 and prints what the harness observed.
fn check_fail(cause: &str, backend: &str, test: &str) -> Option<PathBuf> {
    let name = format!("repro-{}", cause.replace(' ', "-"));
    let b = both(backend, test, &name, &[])?;
    assert_eq!(
        b.harness,
        Outcome::Fail,
        "{cause}: the harness no longer fails {test} on {backend} (driver fixed? update reports/README.md)"
    );
    assert_eq!(b.repro_cmd_exit, 0, "{cause}: shadowcheck repro exit");
    assert_eq!(b.repro_exit, 1, "{cause}: the reproducer must exit 1");
    assert!(
        same_rgba(b.harness_rgba, b.repro_rgba),
        "{cause}: harness observed {:?}, reproducer {:?}",
        b.harness_rgba,
        b.repro_rgba
    );
    let report = std::fs::read_to_string(b.dir.join("REPORT.md")).unwrap();
    assert!(
        report.contains(test) && report.contains("GL_RENDERER: `") && report.contains("**Fail**"),
        "{report}"
    );
    Some(b.dir)
}

#[test]
fn cause2_es_sized_depth_completeness() {
    let _ = check_fail(
        "cause 2",
        "egl:llvmpipe:es3",
        "gles32/2d/d24/linear/none/a=0.25_0.5/read/dt=0.2_0.4_0.6_0.8@es300",
    );
}

#[test]
fn cause3_softpipe_compare_after_filtering() {
    let _ = check_fail(
        "cause 3",
        "egl:softpipe:core",
        "gl46/2d/d24/linear/equal/pcf/a=0.5_0.5/ref=0.5/dt=0.2_0.4_0.6_0.8@core",
    );
}

#[test]
fn cause5_fixed_function_1d_compares_against_t() {
    let _ = check_fail(
        "cause 5",
        "egl:llvmpipe:compat",
        "arb/1d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@ff",
    );
}

#[test]
fn cause5_on_osmesa() {
    let _ = check_fail(
        "cause 5 osmesa",
        "osmesa:llvmpipe:compat",
        "arb/1d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@ff",
    );
}

#[test]
fn cause6_zink_depth_texture_mode_layout() {
    let _ = check_fail(
        "cause 6",
        "egl:zink:compat",
        "arb/2d/d24/linear/lequal/wrap/wrap=clamp/st=-0.25_0.25/border=1/ref=0.5@glsl120",
    );
}

#[test]
fn cause7_glsl130_alpha_becomes_intensity() {
    let _ = check_fail(
        "cause 7",
        "egl:llvmpipe:compat",
        "gl46/2d/d24/nearest/none/dtm/dtm=alpha/texel1/ref=0.3@glsl130",
    );
}

#[test]
fn cause8_softpipe_texture_grad_drops_lod_bias() {
    let _ = check_fail(
        "cause 8",
        "egl:softpipe:core:grad",
        "gl46/2d/d24/nmn/lequal/mip/lod_bias=1/lod=0/ref=0.5/levels=0.2_0.8_0.4@core",
    );
}

#[test]
fn cause9_linear_array_layer_tie() {
    let _ = check_fail(
        "cause 9",
        "egl:llvmpipe:core",
        "gl46/2darray/d24/linear/lequal/layer/layer=0.5/ref=0.6/layers=0.2_0.8_0.4@core",
    );
}

/// A shadow textureGather whose four comparisons softpipe gets wrong on a cube-map array (the
/// hand-written reproducer reports/mesa-22.3.6/repro/gather-softpipe-cube-array/ found it): the
/// generated program judges each gather value by its own accepted set and prints all four.
#[test]
fn gather_softpipe_cube_array() {
    let Some(dir) = check_fail(
        "gather",
        "egl:softpipe:es3",
        "gles32/cubearray/d24/linear/lequal/gather/uv=1.75_2.25/ref=0.8645833333333334@es300",
    ) else {
        return;
    };
    let c = std::fs::read_to_string(dir.join("repro.c")).unwrap();
    assert!(c.contains("textureGather(u_tex"), "no textureGather call");
    assert!(c.contains("static const char LAYOUT[4] = {'A', 'B', 'C', 'D'};"));
}

/// textureGatherOffsets on llvmpipe passes: the program exits 0 with the harness's four values;
/// with one gather value's accepted set emptied it exits 1.
#[test]
fn gather_offsets_pass_and_a_wrong_component_set_fails() {
    let test = "gl46/2d/d24/nearest/lequal/gather/offsets=1/wrap=repeat/ref=0.5@core";
    let Some(b) = both(
        "egl:llvmpipe:core",
        test,
        "repro-gather-pass",
        &["--allow-pass"],
    ) else {
        return;
    };
    assert_eq!(b.harness, Outcome::Pass);
    assert_eq!((b.repro_cmd_exit, b.repro_exit), (0, 0));
    assert!(same_rgba(b.harness_rgba, b.repro_rgba));
    let c = std::fs::read_to_string(b.dir.join("repro.c")).unwrap();
    assert!(
        c.contains("textureGatherOffsets(u_tex"),
        "no textureGatherOffsets call"
    );
    // Gather value 2 (blue) accepted nowhere: the same observation is now outside.
    let set = regex::Regex::new(r"static const struct set GATHER_ACCEPTED\[4\] = \{\{GATHER_ACCEPTED_0, (\d)\}, \{GATHER_ACCEPTED_1, (\d)\}, \{GATHER_ACCEPTED_2, \d\}").unwrap();
    assert!(set.is_match(&c), "no GATHER_ACCEPTED table");
    let wrong = set.replace(&c, "static const struct set GATHER_ACCEPTED[4] = {{GATHER_ACCEPTED_0, $1}, {GATHER_ACCEPTED_1, $2}, {GATHER_ACCEPTED_2, 0}");
    std::fs::write(b.dir.join("repro.c"), wrong.as_ref()).unwrap();
    let own = Command::new("sh")
        .arg("build.sh")
        .current_dir(&b.dir)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&own.stdout);
    assert_eq!(own.status.code(), Some(1), "{out}");
    assert!(
        out.contains("b = ") && out.contains("outside what channel 'C' allows"),
        "{out}"
    );
}

/// Delivered values (`lookup.delivery`): a variable textureGatherOffset offset reaches the program
/// as the worker's uniform `u_o`, and values that differ between the fragments of the pixel quad
/// are drawn over the worker's 2x2 quad; both reproduce the harness's RGBA.
#[test]
fn delivered_gather_offset_and_per_fragment_values_reproduce() {
    let cases = [
        (
            "gl46/2d/d24/nearest/lequal/gather/delivery=uniform/offset=1_0/wrap=repeat/ref=0.5@core",
            "glUniform2i(glGetUniformLocation(p, \"u_o\"), 1, 0);",
        ),
        (
            "gl46/2d/d24/linear/lequal/gather/delivery=per_fragment/uv=1.75_2.25/ref=0.375@core",
            "glViewport(0, 0, 2, 2);",
        ),
    ];
    for (i, (test, call)) in cases.into_iter().enumerate() {
        let Some(b) = both(
            "egl:llvmpipe:core",
            test,
            &format!("repro-delivery-{i}"),
            &["--allow-pass"],
        ) else {
            return;
        };
        assert_eq!(b.harness, Outcome::Pass, "{test}");
        assert_eq!((b.repro_cmd_exit, b.repro_exit), (0, 0), "{test}");
        assert!(same_rgba(b.harness_rgba, b.repro_rgba), "{test}");
        let c = std::fs::read_to_string(b.dir.join("repro.c")).unwrap();
        assert!(c.contains(call), "{test}: no `{call}` in repro.c");
    }
}

/// Compute-stage lookups (`lookup.stage`: compute; every one passes on llvmpipe): the program
/// compiles the worker's compute shader, stores the result into the framebuffer's colour texture
/// as image unit 0 and reads it back, printing the harness's RGBA: a cube gather's four values on
/// GL 4.5 core, a LINEAR seamless cube edge's fraction on ES 3.2.
#[test]
fn compute_stage_lookups_reproduce() {
    let cases = [
        (
            "egl:llvmpipe:core",
            "gl46/cube/d24/linear/lequal/gather/stage=compute/uv=1.75_2.25/ref=0.75@core",
            "#version 430 core",
        ),
        (
            "egl:llvmpipe:es3",
            "gles32/cube/d24/linear/lequal/seamless/stage=compute/seamless=es/wrap=edge/lod=0/edge_s/ref=0.5@es300",
            "#version 310 es",
        ),
    ];
    for (i, (backend, test, version)) in cases.into_iter().enumerate() {
        let name = format!("repro-compute-{i}");
        let Some(b) = both(backend, test, &name, &["--allow-pass"]) else {
            continue;
        };
        assert_eq!(b.harness, Outcome::Pass, "{test} on {backend}");
        assert_eq!((b.repro_cmd_exit, b.repro_exit), (0, 0), "{test}");
        assert!(
            same_rgba(b.harness_rgba, b.repro_rgba),
            "{test}: harness observed {:?}, reproducer {:?}",
            b.harness_rgba,
            b.repro_rgba
        );
        let c = std::fs::read_to_string(b.dir.join("repro.c")).unwrap();
        for call in [
            version,
            "imageStore(u_out, u_at, r);",
            "glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, 16, 16);",
            "glDispatchCompute(1, 1, 1);",
            "glMemoryBarrier(GL_ALL_BARRIER_BITS);",
        ] {
            assert!(c.contains(call), "{test}: no `{call}` in repro.c");
        }
    }
}

/// SwiftShader's own GLES (an EGL 1.4 library: pbuffer contexts only) clamps no reference before
/// an EQUAL comparison (reports/swiftshader-4.0.0.3): the program opens the library as the worker
/// does, through a pbuffer, and reproduces the harness's observation.
#[test]
fn swiftshader_gles_through_an_egl_1_4_pbuffer() {
    let Some(dir) = check_fail(
        "swiftshader pbuffer",
        "egl:swiftshader:es3",
        "gles32/2d/d24/nearest/equal/clamp/dt=0/ref=-0.1@es300",
    ) else {
        return;
    };
    let out = std::fs::read_to_string(dir.join("output.txt")).unwrap();
    assert!(out.contains("egl:       EGL 1.4, pbuffer"), "{out}");
    let sh = std::fs::read_to_string(dir.join("build.sh")).unwrap();
    assert!(sh.contains("-L\"$dir\" -Wl,-rpath,\"$dir\""), "{sh}");
    assert!(
        !sh.contains("/root") && !sh.contains("/home"),
        "a machine path in {sh}"
    );
}

/// A test that passes: without --allow-pass `repro` refuses (exit 1, no REPORT.md); with it, exit 0;
/// the program exits 0 and prints what the harness observed.
#[test]
fn passing_test_gives_exit_0_and_no_report() {
    let backend = "egl:llvmpipe:compat";
    let test = "arb/2d/d24/linear/lequal/wrap/wrap=clamp/st=-0.25_0.25/border=1/ref=0.5@glsl120";
    let Some(b) = both(backend, test, "repro-pass", &[]) else {
        return;
    };
    assert_eq!(b.harness, Outcome::Pass);
    assert_eq!(
        b.repro_cmd_exit, 1,
        "repro refuses a Pass without --allow-pass"
    );
    assert!(!b.dir.join("REPORT.md").exists());
    assert_eq!(b.repro_exit, 0);
    assert!(same_rgba(b.harness_rgba, b.repro_rgba));
    let Some(b) = both(backend, test, "repro-pass-allowed", &["--allow-pass"]) else {
        return;
    };
    assert_eq!(b.repro_cmd_exit, 0);
    assert!(!b.dir.join("REPORT.md").exists());
}

/// `repro ... | head -1`: a stdout whose reader has gone away ends the output quietly; it used to
/// panic (exit 101) on the second line.
#[test]
fn a_closed_stdout_is_not_a_panic() {
    let backend = "egl:llvmpipe:compat";
    let test = "arb/2d/d24/linear/lequal/wrap/wrap=clamp/st=-0.25_0.25/border=1/ref=0.5@glsl120";
    if let Err(e) = shadowcheck_runner::backend::gl::worker_command(backend) {
        gl_support::unavailable(backend, &e.to_string());
        return;
    }
    if !gl_support::can_build(backend) {
        return;
    }
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let out = common::tmpdir("repro-closed-stdout");
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let r = common::Run::of(
        common::bin()
            .args([
                "repro",
                "--backend",
                backend,
                "--case",
                test,
                "--allow-pass",
            ])
            .arg("--fixtures")
            .arg(grid_fixture_file(&id))
            .arg("--out")
            .arg(&out)
            .stdout(writer)
            .output()
            .unwrap(),
    );
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(out.join("repro.c").is_file());
}

/// Bad arguments exit 96 with a message naming the problem (no GL needed).
#[test]
fn bad_arguments_exit_96() {
    let fixtures = root().join("cases/fixtures");
    for (args, says) in [
        (
            vec!["--backend", "egl:llvmpipe:core", "--case", "no-api-path"],
            "bad test id",
        ),
        (
            vec!["--backend", "soft", "--case", "x@core"],
            "bad backend name",
        ),
        (
            vec!["--backend", "egl:llvmpipe:core", "--case", "gl46/none@core"],
            "not found",
        ),
        (
            vec![
                "--backend",
                "egl:llvmpipe:core",
                "--case",
                "arb/1d/d16/nearest/lequal/texel1/ref=0.5/dt=0.2_0.4_0.6_0.8@ff",
            ],
            "runs the API paths core",
        ),
        (vec!["--case", "x@core"], "--backend"),
    ] {
        let r = common::Run::of(
            common::bin()
                .arg("repro")
                .args(&args)
                .arg("--fixtures")
                .arg(&fixtures)
                .output()
                .unwrap(),
        );
        assert_eq!(r.code, 96, "{args:?}: {}", r.stderr);
        assert!(r.stderr.contains(says), "{args:?}: {}", r.stderr);
    }
}

/// `--all-failures`: the Fails of a run (ES 2D and cube fixtures on llvmpipe: the 84-case
/// completeness cause shows on both targets) become fewer classes than Fails, each with a
/// reproducer that fails alone, and index.md names every failing test once.
#[test]
fn all_failures_writes_one_reproducer_per_class() {
    let backend = "egl:llvmpipe:es3";
    if shadowcheck_runner::backend::gl::worker_command(backend).is_err()
        || !gl_support::can_build(backend)
    {
        gl_support::unavailable(backend, "driver or toolchain missing");
        return;
    }
    let out = common::tmpdir("repro-all");
    let run_dir = out.join("run");
    let fx = root().join("cases/fixtures/gles32");
    let r = common::run(&[
        "--backend",
        backend,
        "--fixtures",
        fx.join("2d").to_str().unwrap(),
        "--fixtures",
        fx.join("cube").to_str().unwrap(),
        "--no-rerun",
        "--out",
        run_dir.to_str().unwrap(),
    ]);
    assert_eq!(
        r.code, 100,
        "the ES completeness Fails make it a regression run: {}",
        r.stderr
    );
    let results = read_results(&run_dir.join(RESULTS_FILE)).unwrap();
    let fails: Vec<&str> = results
        .results
        .iter()
        .filter(|r| r.outcome == Outcome::Fail)
        .map(|r| r.test.as_str())
        .collect();
    assert!(fails.len() > 2, "{fails:?}");
    let a = common::Run::of(
        common::bin()
            .args(["repro", "--all-failures"])
            .arg(&run_dir)
            .output()
            .unwrap(),
    );
    assert_eq!(a.code, 0, "{}{}", a.stdout, a.stderr);
    let index = std::fs::read_to_string(run_dir.join("repro/index.md")).unwrap();
    let rows: Vec<&str> = index.lines().filter(|l| l.starts_with("| [")).collect();
    assert!(
        !rows.is_empty() && rows.len() < fails.len(),
        "{} classes for {} Fails",
        rows.len(),
        fails.len()
    );
    for row in &rows {
        assert!(row.contains("Fail reproduced"), "{row}");
    }
    for t in &fails {
        assert_eq!(
            index.matches(&format!("- `{t}`")).count(),
            1,
            "{t} in\n{index}"
        );
    }
    let reports = std::fs::read_dir(run_dir.join("repro"))
        .unwrap()
        .filter(|e| e.as_ref().unwrap().path().join("REPORT.md").is_file())
        .count();
    assert_eq!(reports, rows.len());
}
