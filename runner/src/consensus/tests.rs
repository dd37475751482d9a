//! Synthetic runs written with the project's own record types, read back through the one reader.

use super::*;
use crate::records::{Line, RunMeta, Status};

/// A fresh directory for one test.
fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "shadowcheck-consensus-unit-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

const TEST: &str = "gl46/2d/d16/linear/lequal/ref=0.5/dt=0.25_1";
const CITE: &str = "GL 4.6 §8.23.1 Table 8.23";

/// A record of `TEST@core` on `backend` with `outcome` and `observed`; the expected summary as
/// the verdict writes it for a non-pass (layout `r,0,0,1` unless changed).
fn rec(backend: &str, outcome: Outcome, observed: [f64; 4]) -> TestResult {
    let mut r = TestResult::sample(&format!("{TEST}@core"), Status::Plain(outcome));
    r.case_id = TEST.into();
    r.backend = backend.into();
    r.outcome = outcome;
    r.observed = Some(Rgba(observed));
    r.expected = Some(ExpectedSummary {
        spec_value: Some(1.0),
        strict: "{1}".into(),
        quality: "{1}".into(),
        layout: "r,0,0,1".into(),
        profile: shadowcheck_model::Profile::Quality,
        citations: vec![CITE.into()],
    });
    r
}

/// Writes one run directory (meta line, then the records) and returns it.
fn write_run(root: &Path, name: &str, rs: &[TestResult]) -> PathBuf {
    let dir = root.join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let mut meta = RunMeta::new();
    meta.backends = rs.iter().map(|r| r.backend.clone()).collect();
    let mut text = serde_json::to_string(&Line::Meta(meta)).unwrap() + "\n";
    for r in rs {
        text += &(serde_json::to_string(&Line::Result(Box::new(r.clone()))).unwrap() + "\n");
    }
    std::fs::write(dir.join(records::RESULTS_FILE), text).unwrap();
    dir
}

fn opts(min_units: usize) -> Options {
    Options {
        min_units,
        default_fixtures: PathBuf::from("no-such-fixtures"),
    }
}

/// The queue of `runs` (each a list of records, one directory each).
fn queue_of(name: &str, runs: &[Vec<TestResult>], min_units: usize) -> Queue {
    let root = tmpdir(name);
    let runs: Vec<Run> = runs
        .iter()
        .enumerate()
        .map(|(i, rs)| read_run(&write_run(&root, &format!("r{i}"), rs)).unwrap())
        .collect();
    let q = queue(&runs, &opts(min_units));
    std::fs::remove_dir_all(&root).unwrap();
    q
}

fn units(e: &Entry) -> Vec<&str> {
    e.units.iter().map(|u| u.unit.as_str()).collect()
}

const ZERO: [f64; 4] = [0.0, 0.0, 0.0, 1.0];

#[test]
fn three_units_agreeing_on_a_rejected_answer_are_listed_with_the_oracles_sentences() {
    let q = queue_of(
        "three",
        &[
            vec![rec("soft", Outcome::Fail, ZERO)],
            // One run holding two backends of different units.
            vec![
                rec("egl:llvmpipe:core", Outcome::Fail, ZERO),
                rec("egl:softpipe:core", Outcome::Fail, ZERO),
            ],
            // A backend that answered something else does not join.
            vec![rec(
                "egl:swiftshader:es3",
                Outcome::Fail,
                [0.5, 0.0, 0.0, 1.0],
            )],
        ],
        DEFAULT_MIN_UNITS,
    );
    assert_eq!(q.len(), 1, "{q:#?}");
    assert_eq!(q.tests_compared, 1);
    let c = &q.classes[0];
    assert_eq!(c.family, "gl46/2d/d16/linear/lequal/ref=*/dt=*");
    assert_eq!(c.citations, vec![CITE.to_string()]);
    let e = &c.tests[0];
    assert_eq!(e.test, format!("{TEST}@core"));
    assert_eq!(units(e), ["gallivm", "soft", "softpipe"]);
    assert_eq!(e.answer.0, ZERO);
    assert_eq!(e.citations_from, CitationSource::Record);
    assert_eq!(e.expected.as_ref().map(|x| x.quality.as_str()), Some("{1}"));
    assert_eq!(q.backends["egl:swiftshader:es3"], "swiftshader");
    let md = markdown(&q);
    assert!(md.contains(&format!("`{TEST}@core`")), "{md}");
    assert!(md.contains(&format!("- {CITE}")), "{md}");
    assert!(md.contains("quality {1}"), "{md}");
    assert!(
        md.contains("Fail and Warn"),
        "the header says what is compared:\n{md}"
    );
    let json = serde_json::to_value(&q).unwrap();
    assert_eq!(
        json["classes"][0]["tests"][0]["units"][0]["unit"],
        "gallivm"
    );
}

#[test]
fn two_units_are_not_enough_by_default_but_are_with_min_units_2() {
    let runs = [
        vec![rec("soft", Outcome::Fail, ZERO)],
        vec![rec("egl:softpipe:core", Outcome::Fail, ZERO)],
        // A third unit that passed: it agrees with the oracle and supports nothing.
        vec![rec(
            "egl:llvmpipe:core",
            Outcome::Pass,
            [1.0, 0.0, 0.0, 1.0],
        )],
    ];
    let q = queue_of("two", &runs, DEFAULT_MIN_UNITS);
    assert!(q.is_empty(), "{q:#?}");
    assert!(markdown(&q).contains("No test on the queue."));
    let q = queue_of("two-min2", &runs, 2);
    assert_eq!(q.len(), 1);
    assert_eq!(units(&q.classes[0].tests[0]), ["soft", "softpipe"]);
}

#[test]
fn llvmpipe_zink_and_osmesa_llvmpipe_are_one_unit() {
    let gallivm = vec![
        rec("egl:llvmpipe:core", Outcome::Fail, ZERO),
        rec("egl:zink:core", Outcome::Fail, ZERO),
        rec("osmesa:llvmpipe:compat", Outcome::Fail, ZERO),
    ];
    let q = queue_of("gallivm", std::slice::from_ref(&gallivm), DEFAULT_MIN_UNITS);
    assert!(q.is_empty(), "three backends, one unit: {q:#?}");
    // With two more units the test is listed, gallivm counted once with its three backends.
    let q = queue_of(
        "gallivm-plus",
        &[
            gallivm,
            vec![
                rec("soft", Outcome::Fail, ZERO),
                rec("webgl:chromium", Outcome::Fail, ZERO),
            ],
        ],
        DEFAULT_MIN_UNITS,
    );
    assert_eq!(q.len(), 1);
    let e = &q.classes[0].tests[0];
    assert_eq!(units(e), ["gallivm", "soft", "swiftshader"]);
    assert_eq!(e.units[0].backends.len(), 3);
}

#[test]
fn answers_further_apart_than_2_to_the_minus_16_are_not_grouped() {
    let at = |d: f64| [0.5 + d, 0.0, 0.0, 1.0];
    let step = 2.0 * TOLERANCE;
    let q = queue_of(
        "apart",
        &[vec![
            rec("soft", Outcome::Fail, at(0.0)),
            rec("egl:llvmpipe:core", Outcome::Fail, at(step)),
            rec("egl:softpipe:core", Outcome::Fail, at(2.0 * step)),
        ]],
        DEFAULT_MIN_UNITS,
    );
    assert!(q.is_empty(), "{q:#?}");
    // Within 2^-16 of the answer: one group.
    let q = queue_of(
        "close",
        &[vec![
            rec("soft", Outcome::Fail, at(0.0)),
            rec("egl:llvmpipe:core", Outcome::Fail, at(TOLERANCE / 2.0)),
            rec("egl:softpipe:core", Outcome::Fail, at(TOLERANCE)),
        ]],
        DEFAULT_MIN_UNITS,
    );
    assert_eq!(q.len(), 1);
    assert_eq!(q.classes[0].tests[0].compared, "rgba");
}

#[test]
fn channels_the_layout_marks_unused_do_not_matter() {
    let mut rs = vec![
        rec("soft", Outcome::Fail, [0.0, 0.0, 0.0, 1.0]),
        rec("egl:llvmpipe:core", Outcome::Fail, [0.0, 0.7, 0.2, 0.0]),
        rec(
            "egl:softpipe:core",
            Outcome::Fail,
            [0.0, f64::NAN, 1.0, 1.0],
        ),
    ];
    let q = queue_of("used", std::slice::from_ref(&rs), DEFAULT_MIN_UNITS);
    assert!(q.is_empty(), "layout r,0,0,1: g, b, a are compared");
    for r in &mut rs {
        if let Some(e) = r.expected.as_mut() {
            e.layout = "r,-,-,-".into();
        }
    }
    let q = queue_of("unused", &[rs], DEFAULT_MIN_UNITS);
    assert_eq!(q.len(), 1);
    assert_eq!(q.classes[0].tests[0].compared, "r");
    assert!(markdown(&q).contains("(0, -, -, -)"));
}

#[test]
fn agreement_accepted_by_the_oracle_is_not_on_the_queue() {
    let q = queue_of(
        "warn",
        &[vec![
            rec("soft", Outcome::Warn, ZERO),
            rec("egl:llvmpipe:core", Outcome::Warn, ZERO),
            rec("egl:softpipe:core", Outcome::Warn, ZERO),
        ]],
        DEFAULT_MIN_UNITS,
    );
    assert!(q.is_empty(), "Warn is inside an acceptance set: {q:#?}");
    assert_eq!(q.tests_compared, 1);
}

#[test]
fn a_missing_run_directory_is_an_error_naming_it() {
    let root = tmpdir("missing");
    let missing = root.join("no-such-run");
    let e = read_run(&missing).unwrap_err().to_string();
    assert!(e.contains("no-such-run"), "{e}");
    assert!(matches!(read_run(&missing), Err(ReadError::Io { .. })));
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn citations_missing_from_the_records_come_from_the_named_fixture_file() {
    let fixtures = "../cases/fixtures/gl46/2d/nearest.json";
    let file = shadowcheck_cases::fixtures::load_file(Path::new(fixtures)).unwrap();
    let case = &file.cases[0];
    let want = case.expect.as_ref().unwrap().citations.clone();
    assert!(!want.is_empty());
    let rs: Vec<TestResult> = ["soft", "egl:llvmpipe:core", "egl:softpipe:core"]
        .iter()
        .map(|b| {
            let mut r = rec(b, Outcome::Fail, ZERO);
            r.case_id = case.id.clone();
            r.test = format!("{}@core", case.id);
            r.fixtures = Some(fixtures.into());
            if let Some(e) = r.expected.as_mut() {
                e.citations.clear();
            }
            r
        })
        .collect();
    let q = queue_of("cite", &[rs], DEFAULT_MIN_UNITS);
    let e = &q.classes[0].tests[0];
    assert_eq!(e.citations, want);
    assert_eq!(e.citations_from, CitationSource::Fixtures(fixtures.into()));
}

#[test]
fn lineage_maps_shared_samplers_to_one_unit_and_the_rest_to_themselves() {
    for (b, u) in [
        ("soft", "soft"),
        ("soft:gl46", "soft"),
        ("egl:llvmpipe:core:grad", "gallivm"),
        ("osmesa:llvmpipe:compat", "gallivm"),
        ("egl:zink:es3", "gallivm"),
        ("egl@/opt/mesa/lib:llvmpipe:core", "gallivm"),
        ("vk:lavapipe", "gallivm"),
        ("egl:softpipe:compat", "softpipe"),
        ("osmesa:softpipe:core", "softpipe"),
        ("egl:swiftshader:es3", "swiftshader"),
        ("egl:zink+swiftshader:compat", "swiftshader"),
        ("webgl:chromium", "swiftshader"),
        ("webgl:chromium-gles", "gallivm"),
        ("webgl:chromium-lavapipe", "gallivm"),
        // Dawn on SwiftShader's Vulkan driver (or on ANGLE over it) samples with SwiftShader.
        ("webgpu:chromium", "swiftshader"),
        ("webgpu:chromium-compat", "swiftshader"),
        (
            "egl@/opt/vendor/lib:native:es3",
            "egl@/opt/vendor/lib:native:es3",
        ),
        ("exec:python3 x.py", "exec:python3 x.py"),
        ("mock:fail", "mock:fail"),
        ("webgpu:dawn", "webgpu:dawn"),
    ] {
        assert_eq!(unit_of(b), u, "{b}");
    }
    assert_eq!(
        family("arb/rect/d32/linear/gequal/rand/seed=0/6"),
        "arb/rect/d32/linear/gequal/rand/seed=*/*"
    );
}

#[test]
fn front_ends_say_which_units_share_the_gl_front_end() {
    for (b, f) in [
        ("egl:llvmpipe:core", "mesa"),
        ("osmesa:softpipe:compat", "mesa"),
        ("egl:zink:es3", "mesa"),
        ("egl:zink+swiftshader:compat", "mesa"),
        ("egl:swiftshader:es3", "swiftshader-gles"),
        ("webgl:chromium", "angle"),
        ("webgl:chromium-gles", "angle"),
        ("webgl:chromium-lavapipe", "angle"),
        ("webgpu:chromium", "dawn"),
        ("webgpu:chromium-compat", "dawn-angle"),
        ("soft", "soft"),
        // A Vulkan driver driven directly has no GL front end: its own name stands for it.
        ("vk:lavapipe", "vk:lavapipe"),
        ("exec:python3 x.py", "exec:python3 x.py"),
    ] {
        assert_eq!(front_end_of(b), f, "{b}");
    }
}

#[test]
fn an_entry_names_the_front_ends_its_answer_came_through() {
    let wrong = [1.0, 0.0, 0.0, 1.0];
    // Three units, one GL front end (Mesa's): the entry says so.
    let mesa = vec![
        rec("egl:llvmpipe:core", Outcome::Fail, wrong),
        rec("egl:softpipe:core", Outcome::Fail, wrong),
        rec("egl:zink+swiftshader:core", Outcome::Fail, wrong),
    ];
    let q = queue_of("front-mesa", std::slice::from_ref(&mesa), DEFAULT_MIN_UNITS);
    assert_eq!(q.classes[0].tests[0].front_ends, vec!["mesa".to_string()]);
    assert!(markdown(&q).contains("| mesa |"));
    // SwiftShader's own GLES joins: two front ends.
    let mut two = mesa;
    two.push(rec("egl:swiftshader:es3", Outcome::Fail, wrong));
    let q = queue_of("front-two", &[two], DEFAULT_MIN_UNITS);
    assert_eq!(
        q.classes[0].tests[0].front_ends,
        vec!["mesa".to_string(), "swiftshader-gles".to_string()]
    );
}
