//! Shared helpers for the runner's integration tests: hand-built fixture files (expectations from
//! the GL 4.6 compare table, written here from the spec text, not from any implementation) and a
//! way to run the `shadowcheck` binary.
#![allow(dead_code)]

use shadowcheck_cases::fixtures::{to_string, FixtureFile};
use shadowcheck_model::KeyMap;
use shadowcheck_model::*;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_shadowcheck"))
}

const TMP_PREFIX: &str = "shadowcheck-runner-test-";

/// A fresh, empty directory for one test. The directories of test processes that have ended are
/// removed first (once per process), so repeated runs on one machine do not fill its disk.
pub fn tmpdir(name: &str) -> PathBuf {
    static SWEEP: std::sync::Once = std::sync::Once::new();
    SWEEP.call_once(sweep_dead_tmpdirs);
    let d = std::env::temp_dir().join(format!("{TMP_PREFIX}{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Removes `<temp>/shadowcheck-runner-test-<pid>-*` of every pid that no longer runs (Linux: no
/// `/proc/<pid>`); directories of running test processes, and anything else, are left alone.
fn sweep_dead_tmpdirs() {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(std::env::temp_dir()) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(pid) = name
            .strip_prefix(TMP_PREFIX)
            .and_then(|rest| rest.split('-').next())
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        if !Path::new(&format!("/proc/{pid}")).exists() {
            let _ = std::fs::remove_dir_all(e.path());
        }
    }
}

/// The 2x2 D16 texture used by the hand-built cases: stored integers 0, 21845, 43690, 65535, i.e.
/// Dt = 0, 1/3, 2/3, 1 (GL 4.6 §2.3.5.1: unorm c / (2^16 - 1)), x fastest then y.
pub const TEXELS: [u32; 4] = [0, 21845, 43690, 65535];

/// GL 4.6 Table 8.23 with exact arithmetic.
pub fn compare(func: CompareFunc, dref: f64, dt: f64) -> f64 {
    let pass = match func {
        CompareFunc::Lequal => dref <= dt,
        CompareFunc::Gequal => dref >= dt,
        CompareFunc::Less => dref < dt,
        CompareFunc::Greater => dref > dt,
        CompareFunc::Equal => dref == dt,
        CompareFunc::Notequal => dref != dt,
        CompareFunc::Always => true,
        _ => false,
    };
    if pass {
        1.0
    } else {
        0.0
    }
}

/// A GL 4.6 core NEAREST lookup at the centre of texel `(x, y)` of the 2x2 texture with reference
/// `dref`. Its expectation: r = compare(func, dref, Dt(x,y)) exactly, in channel 0 of the float
/// GLSL result (the other channels unused), under every profile (no texel is near a tie).
pub fn nearest_case(func: CompareFunc, x: u32, y: u32, dref: f64) -> Case {
    let dt = TEXELS[(y * 2 + x) as usize] as f64 / 65535.0;
    let r = compare(func, dref, dt);
    let mut accept = KeyMap::new();
    for &p in Profile::ALL {
        accept.insert(p, Acceptance(vec![Interval::point(r)]));
    }
    let mut layout = KeyMap::new();
    layout.insert(
        ApiPath::GlslCore,
        [
            Channel::R,
            Channel::Unused,
            Channel::Unused,
            Channel::Unused,
        ],
    );
    Case {
        sweep: vec![],
        id: format!(
            "gl46/2d/d16/nearest/{}/ref={dref}/texel={x}_{y}",
            func.key()
        ),
        spec: Spec::Gl46,
        api: vec![ApiPath::GlslCore],
        texture: Texture {
            target: Target::T2d,
            format: Format::D16,
            base_level: 0,
            levels: vec![Level {
                width: 2,
                height: 2,
                layers: 1,
                depth: Texels::Unorm(TEXELS.to_vec()),
                stencil: None,
            }],
        },
        sampler: Sampler::new(CompareMode::Compare, func, Filter::Nearest),
        lookup: Lookup {
            coord: [(x as f64 + 0.5) / 2.0, (y as f64 + 0.5) / 2.0, 0.0, 1.0],
            layer: 0.0,
            dref,
            projective: false,
            lod: 0.0,
            bias: 0.0,
            offset: [0; 3],
            gather: None,
            delivery: Default::default(),
            stage: Default::default(),
        },
        expect: Some(Expectation {
            spec_value: Some(r),
            accept,
            layout,
            other_layouts: Default::default(),
            gather: None,
            implementation_defined: None,
            citations: vec!["GL 4.6 §8.23.1 Table 8.23".into()],
        }),
    }
}

/// `n` distinct cases cycling through funcs, texels and references.
pub fn many_cases(n: usize) -> Vec<Case> {
    let funcs = [
        CompareFunc::Lequal,
        CompareFunc::Gequal,
        CompareFunc::Less,
        CompareFunc::Greater,
    ];
    (0..n)
        .map(|i| {
            let mut c = nearest_case(funcs[i % 4], (i / 4 % 2) as u32, (i / 8 % 2) as u32, 0.5);
            c.id = format!("{}/n={i:04}", c.id);
            c
        })
        .collect()
}

pub fn write_fixture(path: &Path, cases: Vec<Case>) {
    let f = FixtureFile {
        schema_version: SCHEMA_VERSION,
        generator: "runner tests".into(),
        grid: "test".into(),
        seed: 0,
        cases,
        state_cases: vec![],
    };
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, to_string(&f).unwrap()).unwrap();
}

pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

impl Run {
    pub fn of(o: Output) -> Run {
        Run {
            code: o.status.code().unwrap_or(-1),
            stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
            stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
        }
    }
}

/// A default run (no `--backend`, `--skip-missing`) of the fixtures `fx` into `out` in which no
/// worker can start (`SHADOWCHECK_EXE` points nowhere), so it is quick and shows which backends it
/// tried; with `chromium` as the browser where given.
pub fn default_run_without_workers(fx: &str, out: &Path, chromium: Option<&str>) -> Run {
    let mut c = bin();
    c.args(["run", "--skip-missing", "--fixtures", fx, "--out"])
        .arg(out)
        .env("SHADOWCHECK_EXE", "/nonexistent/shadowcheck");
    if let Some(p) = chromium {
        c.env(shadowcheck_webgl::browser::CHROMIUM_ENV, p);
    }
    Run::of(c.output().unwrap())
}

/// `shadowcheck run ARGS` and its outcome.
pub fn run(args: &[&str]) -> Run {
    Run::of(bin().arg("run").args(args).output().unwrap())
}

/// Splits one CSV line (RFC 4180 quoting).
pub fn csv_fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                chars.next();
                out.last_mut().unwrap().push('"');
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// results.csv as (test, status, backend), durations dropped.
pub fn results(dir: &Path) -> Vec<(String, String, String)> {
    std::fs::read_to_string(dir.join("results.csv"))
        .unwrap()
        .lines()
        .map(|l| {
            let f = csv_fields(l);
            assert_eq!(f.len(), 4, "{l}");
            (f[0].clone(), f[1].clone(), f[3].clone())
        })
        .collect()
}

/// report.json without the durations (which differ from run to run).
pub fn report_without_durations(dir: &Path) -> serde_json::Value {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    for r in v["results"].as_array_mut().unwrap() {
        r.as_object_mut().unwrap().remove("duration");
    }
    v
}

pub fn status_of<'a>(rows: &'a [(String, String, String)], test_contains: &str) -> Vec<&'a str> {
    rows.iter()
        .filter(|r| r.0.contains(test_contains))
        .map(|r| r.1.as_str())
        .collect()
}

/// A fresh directory for one test holding `fixtures/cases.json` with [`many_cases`]`(n)`; returns
/// the directory and the fixture path as a `--fixtures` argument.
pub fn cases_dir(name: &str, n: usize) -> (PathBuf, String) {
    let dir = tmpdir(name);
    let fx = dir.join("fixtures/cases.json");
    write_fixture(&fx, many_cases(n));
    (dir.clone(), fx.display().to_string())
}

/// The fixture file of a default-grid case (`cases/fixtures/<spec>/<target>/<min filter>.json`, the
/// first, second and fourth parts of its id), so that neither a run nor `repro` loads them all.
pub fn grid_fixture_file(id: &str) -> PathBuf {
    let parts: Vec<&str> = id.split('/').collect();
    let f = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../cases/fixtures")
        .join(parts[0])
        .join(parts[1])
        .join(format!("{}.json", parts[3]));
    assert!(f.is_file(), "{} missing", f.display());
    f
}

/// The RGBA of a reproducer's `observed: (r, g, b, a)` line.
pub fn repro_observed(stdout: &str) -> [f64; 4] {
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("observed:"))
        .unwrap_or_else(|| panic!("no observed line in\n{stdout}"));
    let v: Vec<f64> = line
        .trim()
        .trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect();
    v.try_into().unwrap()
}

/// Runs `test` (`<case id>@<api>`) alone on `backend` in the harness (no re-run, full records) into
/// `out/run`: the harness's record of the test. Panics, naming the test, when the harness has no
/// record of it.
pub fn harness_record(
    backend: &str,
    test: &str,
    fixtures: &Path,
    out: &Path,
) -> shadowcheck_runner::records::TestResult {
    let (id, _) = shadowcheck_runner::repro::parse_test_id(test).unwrap();
    let run_dir = out.join("run");
    let r = run(&[
        "--backend",
        backend,
        "--fixtures",
        fixtures.to_str().unwrap(),
        "--cases",
        &format!("^{}$", regex::escape(&id)),
        "--no-rerun",
        "--full-report",
        "--out",
        run_dir.to_str().unwrap(),
    ]);
    let results = shadowcheck_runner::records::read_results(
        &run_dir.join(shadowcheck_runner::records::RESULTS_FILE),
    )
    .unwrap();
    results
        .get(backend, test)
        .unwrap_or_else(|| panic!("{test} not in the run's results: {}", r.stderr))
        .clone()
}

/// [`harness_record`], then `shadowcheck repro --allow-pass` for the test into `out/repro`: the
/// harness's record of the test, `repro`'s own run, and the reproducer's directory.
pub fn harness_then_repro(
    backend: &str,
    test: &str,
    fixtures: &Path,
    out: &Path,
) -> (shadowcheck_runner::records::TestResult, Run, PathBuf) {
    let rec = harness_record(backend, test, fixtures, out);
    let dir = out.join("repro");
    let rc = Run::of(
        bin()
            .args([
                "repro",
                "-b",
                backend,
                "--case",
                test,
                "--allow-pass",
                "--fixtures",
            ])
            .arg(fixtures)
            .arg("-o")
            .arg(&dir)
            .output()
            .unwrap(),
    );
    (rec, rc, dir)
}
