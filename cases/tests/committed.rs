//! The committed fixtures (cases/fixtures), the JSON Schema and the README's coverage table agree
//! with the generator.

use shadowcheck_cases::coverage::{self, Coverage};
use shadowcheck_cases::fixtures;
use shadowcheck_cases::grids::{self, specs};
use shadowcheck_model::*;
use std::path::{Path, PathBuf};

const FIX: &str = "cargo run --release -- gen --grid default -o cases/fixtures";

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}
fn fixtures_dir() -> PathBuf {
    crate_dir().join("fixtures")
}

fn schema() -> serde_json::Value {
    let text = std::fs::read_to_string(crate_dir().join("schema/fixture.schema.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn default_grid_regenerates_byte_for_byte() {
    let files = grids::generate("default", grids::DEFAULT_SEED).unwrap();
    let dir = fixtures_dir();
    let mut problems = Vec::new();
    for (rel, f) in &files {
        let want = fixtures::to_string(f).unwrap();
        match std::fs::read_to_string(dir.join(rel)) {
            Ok(have) if have == want => {}
            Ok(_) => problems.push(format!("{rel}: differs")),
            Err(e) => problems.push(format!("{rel}: {e}")),
        }
    }
    let wanted = grids::paths(&files);
    for p in fixtures::fixture_paths(&dir).unwrap_or_default() {
        let rel = p
            .strip_prefix(&dir)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        if !wanted.contains(rel.as_str()) {
            problems.push(format!("{rel}: not produced by the generator (stale)"));
        }
    }
    assert!(
        problems.is_empty(),
        "cases/fixtures is out of date; run `{FIX}`:\n{}",
        problems.join("\n")
    );
}

#[test]
fn every_committed_fixture_matches_the_schema_and_loads() {
    let validator = jsonschema::validator_for(&schema()).unwrap();
    let paths = fixtures::fixture_paths(&fixtures_dir()).unwrap();
    assert!(paths.len() > 50, "{} files", paths.len());
    let mut cases = 0;
    for p in &paths {
        let text = std::fs::read_to_string(p).unwrap();
        let value: serde_json::Value = serde_json::from_str(&text).unwrap();
        let errors: Vec<String> = validator
            .iter_errors(&value)
            .take(5)
            .map(|e| format!("{} at {}", e, e.instance_path()))
            .collect();
        assert!(errors.is_empty(), "{}: {}", p.display(), errors.join("\n"));
        let f = fixtures::load_file(p).unwrap();
        assert!(
            f.cases.iter().all(|c| c.expect.is_some()),
            "{}: a case without expectation",
            p.display()
        );
        cases += f.cases.len();
    }
    assert!((10_000..=40_000).contains(&cases), "{cases} cases");
}

#[test]
fn committed_size_is_within_budget() {
    let total: u64 = fixtures::fixture_paths(&fixtures_dir())
        .unwrap()
        .iter()
        .map(|p| std::fs::metadata(p).unwrap().len())
        .sum();
    // The sweeps (`sweep` in cases/README.md) take most of it: ~94,000 points of ~200 bytes each
    // (coordinates, reference and exact acceptance intervals). The Vulkan grid adds about 8 MiB,
    // the WebGPU grid about 6.5 MiB; the coverage round of interactions, deliveries, colour
    // formats and cube chains about 3.7 MiB.
    assert!(
        total <= 60 * 1024 * 1024,
        "{total} bytes committed (budget 60 MiB)"
    );
}

#[test]
fn schema_rejects_what_the_loader_rejects() {
    let validator = jsonschema::validator_for(&schema()).unwrap();
    let p = fixtures::fixture_paths(&fixtures_dir()).unwrap().remove(0);
    let good: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap();
    assert!(validator.is_valid(&good));
    type Edit = (&'static str, fn(&mut serde_json::Value));
    let edits: [Edit; 6] = [
        ("unknown enum", |v| {
            v["cases"][0]["sampler"]["compare_func"] = "lequalish".into()
        }),
        ("wrong type", |v| {
            v["cases"][0]["texture"]["levels"][0]["width"] = "4".into()
        }),
        ("absurd size", |v| {
            v["cases"][0]["texture"]["levels"][0]["width"] = 100000.into()
        }),
        ("nan where a number is required", |v| {
            v["cases"][0]["sampler"]["min_lod"] = "nan".into()
        }),
        ("unknown field", |v| {
            v["cases"][0]["lookup"]["extra"] = 1.into()
        }),
        ("wrong version", |v| v["schema_version"] = 2.into()),
    ];
    for (what, edit) in edits {
        let mut bad = good.clone();
        edit(&mut bad);
        assert!(!validator.is_valid(&bad), "schema accepts: {what}");
    }
    // Non-finite reals are written as strings where the model allows them.
    let mut ok = good.clone();
    ok["cases"][0]["lookup"]["dref"] = "-inf".into();
    assert!(validator.is_valid(&ok));
}

/// The schema's enum lists are the model's keys (the schema is hand-written; this keeps it honest).
#[test]
fn schema_enums_match_the_model() {
    let s = schema();
    let keys = |name: &str| -> Vec<String> {
        s["$defs"][name]["enum"]
            .as_array()
            .unwrap_or_else(|| panic!("no enum {name}"))
            .iter()
            .map(|v| v.as_str().unwrap().to_string())
            .collect()
    };
    fn all<T: Copy>(v: &[T], key: fn(T) -> &'static str) -> Vec<String> {
        v.iter().map(|x| key(*x).to_string()).collect()
    }
    assert_eq!(keys("spec"), all(Spec::ALL, Spec::key));
    assert_eq!(keys("swizzle"), all(Swizzle::ALL, Swizzle::key));
    assert_eq!(keys("api"), all(ApiPath::ALL, ApiPath::key));
    assert_eq!(
        keys("compare_func"),
        all(CompareFunc::ALL, CompareFunc::key)
    );
    assert_eq!(
        keys("compare_mode"),
        all(CompareMode::ALL, CompareMode::key)
    );
    assert_eq!(
        keys("depth_texture_mode"),
        all(DepthTextureMode::ALL, DepthTextureMode::key)
    );
    assert_eq!(
        keys("depth_stencil_mode"),
        all(DepthStencilMode::ALL, DepthStencilMode::key)
    );
    assert_eq!(keys("filter"), all(Filter::ALL, Filter::key));
    assert_eq!(keys("format"), all(Format::ALL, Format::key));
    assert_eq!(keys("target"), all(Target::ALL, Target::key));
    assert_eq!(keys("wrap"), all(Wrap::ALL, Wrap::key));
    assert_eq!(keys("profile"), all(Profile::ALL, Profile::key));
    assert_eq!(keys("channel"), all(Channel::ALL, Channel::key));
}

fn default_unfilled() -> Vec<Case> {
    grids::unfilled("default", grids::DEFAULT_SEED)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect()
}

/// For every spec, every target x format x filter x func (and compare NONE) the spec allows has
/// cases in `default`.
#[test]
fn default_covers_every_allowed_combination() {
    let cases = default_unfilled();
    let cov = Coverage::of(&cases);
    let missing = cov.missing();
    assert!(
        missing.is_empty(),
        "{} empty cells, e.g. {:?}",
        missing.len(),
        &missing[..missing.len().min(10)]
    );
    // Shadow gather: every function on every target and path that has it.
    let missing = cov.missing_gather();
    assert!(missing.is_empty(), "gather cells with no test: {missing:?}");
    // The unit-state dimensions (swizzle, seamless enable / ES rule, sampler objects) on every
    // API path that has them.
    assert_eq!(cov.unit_state_missing(), vec![]);
    // And nothing outside what the spec allows.
    for c in &cases {
        let d = specs::dims(c.spec);
        assert!(d.targets.contains(&c.texture.target), "{}", c.id);
        // The colour formats of several components come from the `formats` family only.
        assert!(
            d.formats.contains(&c.texture.format)
                || grids::families::multi_colour_formats(c.spec).contains(&c.texture.format),
            "{}",
            c.id
        );
        assert!(
            c.sampler.compare_mode == CompareMode::None
                || d.funcs.contains(&c.sampler.compare_func),
            "{}",
            c.id
        );
        assert!(
            d.wraps.contains(&c.sampler.wrap_s) || c.sampler.wrap_s == Wrap::ClampToEdge,
            "{}",
            c.id
        );
        assert!(
            specs::filter_allowed(c.texture.target, c.sampler.min_filter),
            "{}",
            c.id
        );
        assert!(d.lod_bias || c.sampler.lod_bias == 0.0, "{}", c.id);
        assert!(d.shader_bias || c.lookup.bias == 0.0, "{}", c.id);
        let lod_state = c.sampler.min_lod != -1000.0
            || c.sampler.max_lod != 1000.0
            || c.sampler.max_level.is_some()
            || c.texture.base_level != 0;
        assert!(d.lod_state || !lod_state, "{}", c.id);
        assert!(d.fail_value || c.sampler.fail_value.is_none(), "{}", c.id);
        assert!(
            c.sampler
                .depth_texture_mode
                .is_none_or(|m| d.dtms.contains(&m)),
            "{}",
            c.id
        );
        assert!(
            d.stencil_mode || c.sampler.depth_stencil_mode.is_none(),
            "{}",
            c.id
        );
    }
}

/// Checks per compiled state: a case counts once per API path it lists; cases that differ only in
/// values (Dref, texels) share a state, a different wrap is another state.
#[test]
fn density_counts_tests_and_distinct_states_per_path() {
    let cases = default_unfilled();
    let base = cases
        .iter()
        .find(|c| c.api.len() >= 2 && c.texture.target == Target::T2d)
        .expect("a 2D case on two API paths");
    let mut same_state = base.clone();
    same_state.id.push_str("/other-values");
    same_state.lookup.dref /= 2.0;
    let mut other_wrap = base.clone();
    other_wrap.id.push_str("/other-wrap");
    other_wrap.sampler.wrap_s = if base.sampler.wrap_s == Wrap::Repeat {
        Wrap::ClampToEdge
    } else {
        Wrap::Repeat
    };
    let cov = Coverage::of([base, &same_state, &other_wrap]);
    for api in &base.api {
        let d = &cov.per_path[api];
        assert_eq!((d.tests, d.states.len()), (3, 2), "{api}");
    }
    assert!(cov.density_markdown().contains("| 3 | 2 | 1.5 |"));
}

#[test]
fn every_feature_a_spec_defines_has_cases_and_the_predicates_tell_cases_apart() {
    let cases = default_unfilled();
    let cov = Coverage::of(&cases);
    assert_eq!(cov.features.missing(), Vec::<(&str, Spec)>::new());
    // Each predicate picks some cases and leaves others: no feature row counts everything.
    for (i, f) in shadowcheck_cases::features::FEATURES.iter().enumerate() {
        let n: usize = Spec::ALL.iter().map(|s| cov.features.count(i, *s)).sum();
        assert!(n > 0 && n < cases.len(), "{}: {n}", f.name);
    }
    // A hand-made case of each kind is recognised.
    let base = cases
        .iter()
        .find(|c| c.spec == Spec::Gl46 && c.texture.target == Target::T2d)
        .expect("a gl46 2D case");
    let mut mixed = base.clone();
    mixed.sampler.min_filter = Filter::Nearest;
    mixed.sampler.mag_filter = Filter::Linear;
    let mut pair = base.clone();
    pair.sampler.wrap_s = Wrap::Repeat;
    pair.sampler.wrap_t = Wrap::ClampToEdge;
    let hits = Coverage::of([&mixed, &pair]).features;
    assert_eq!(hits.count(0, Spec::Gl46), 1, "mixed filter classes");
    assert_eq!(hits.count(1, Spec::Gl46), 1, "wrap_s != wrap_t");
    assert!(cov.markdown().contains("#### Features"));
}

#[test]
fn readme_coverage_table_is_current() {
    let readme = std::fs::read_to_string(crate_dir().join("README.md")).unwrap();
    let have = coverage::section(&readme).expect("coverage markers in cases/README.md");
    let states: Vec<StateCase> = grids::unfilled("default", grids::DEFAULT_SEED)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.state_cases)
        .collect();
    // The committed fixtures, not the unfilled grid: the checks-per-state table counts the sweeps,
    // which need the oracle (default_grid_regenerates_byte_for_byte holds them to the generator).
    let committed: Vec<Case> = fixtures::load_path(&fixtures_dir())
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect();
    let want = Coverage::of(&committed).with_states(&states).markdown();
    assert!(
        have.trim() == want.trim(),
        "the coverage table in cases/README.md is out of date; run `cargo run --release -- gen --grid default -o cases/fixtures --update-readme cases/README.md`"
    );
}

#[test]
fn smoke_has_one_of_everything_in_under_1000_cases() {
    let smoke: Vec<Case> = grids::unfilled("smoke", 0)
        .unwrap()
        .into_iter()
        .flat_map(|(_, f)| f.cases)
        .collect();
    assert!(smoke.len() < 1000, "{}", smoke.len());
    for d in specs::all() {
        let of = |f: &dyn Fn(&Case) -> bool| smoke.iter().any(|c| c.spec == d.spec && f(c));
        for t in d.targets {
            assert!(of(&|c| c.texture.target == *t), "{} {t}", d.spec);
        }
        for fo in d.formats {
            assert!(of(&|c| c.texture.format == *fo), "{} {fo}", d.spec);
        }
        for fi in d.filters {
            assert!(of(&|c| c.sampler.min_filter == *fi), "{} {fi}", d.spec);
        }
        for fu in d.funcs {
            assert!(
                of(&|c| c.sampler.compare_mode == CompareMode::Compare
                    && c.sampler.compare_func == *fu),
                "{} {fu}",
                d.spec
            );
        }
        for w in d.wraps {
            assert!(of(&|c| c.sampler.wrap_s == *w), "{} {w}", d.spec);
        }
    }
}

#[test]
fn ids_are_readable_and_start_with_their_coordinates() {
    for c in default_unfilled() {
        let prefix = format!(
            "{}/{}/{}/{}/",
            c.spec, c.texture.target, c.texture.format, c.sampler.min_filter
        );
        assert!(c.id.starts_with(&prefix), "{}", c.id);
        assert!(c.id.is_ascii() && !c.id.contains(' '), "{}", c.id);
    }
}

#[test]
fn seed_changes_only_the_random_family() {
    let a = grids::unfilled("default", 0).unwrap();
    let b = grids::unfilled("default", 7).unwrap();
    let ids = |f: &[(String, fixtures::FixtureFile)]| -> Vec<String> {
        f.iter()
            .flat_map(|(_, f)| f.cases.iter().map(|c| c.id.clone()))
            .filter(|id| !id.contains("/rand/"))
            .collect()
    };
    assert!(
        ids(&a) == ids(&b),
        "seed changed ids outside the random family"
    );
    // Compare as text: NaN references make `==` on cases false.
    let text = |f: &[(String, fixtures::FixtureFile)]| -> Vec<String> {
        f.iter()
            .map(|(_, f)| fixtures::to_string(f).unwrap())
            .collect()
    };
    assert!(text(&a) != text(&b), "the seed changed nothing");
    assert!(
        text(&grids::unfilled("default", 7).unwrap()) == text(&b),
        "same seed, different output"
    );
}

#[test]
fn exhaustive_is_streamed_in_files_of_bounded_size() {
    let mut chunks = grids::exhaustive::chunks();
    let (rel, first) = chunks.next().unwrap();
    assert_eq!(rel, "gl46/d16/always/00000.json");
    assert_eq!(first.len(), grids::exhaustive::CHUNK as usize * 3);
    assert_eq!(1 + chunks.count(), grids::exhaustive::len() / first.len());
    let _ = Path::new(&rel);
}

#[test]
fn smoke_generates_with_expectations_that_match_the_schema() {
    let validator = jsonschema::validator_for(&schema()).unwrap();
    let files = grids::generate("smoke", 0).unwrap();
    assert!(!files.is_empty());
    for (rel, f) in &files {
        let value: serde_json::Value =
            serde_json::from_str(&fixtures::to_string(f).unwrap()).unwrap();
        let errors: Vec<String> = validator
            .iter_errors(&value)
            .take(5)
            .map(|e| format!("{} at {}", e, e.instance_path()))
            .collect();
        assert!(errors.is_empty(), "{rel}: {}", errors.join("\n"));
        assert!(f.cases.iter().all(|c| c.expect.is_some()));
    }
}

#[test]
fn unknown_grid_is_an_error() {
    let e = grids::generate("nope", 0).unwrap_err().to_string();
    assert!(e.contains("nope") && e.contains("default"), "{e}");
}

/// The first number in `text` after `marker` (digits with `,` separators, or a decimal).
fn figure_after(text: &str, marker: &str) -> f64 {
    let at = text
        .find(marker)
        .unwrap_or_else(|| panic!("`{marker}` not in cases/README.md"))
        + marker.len();
    let num: String = text[at..]
        .chars()
        .skip_while(|c| !c.is_ascii_digit())
        .take_while(|c| c.is_ascii_digit() || *c == ',' || *c == '.')
        .filter(|c| *c != ',')
        .collect();
    num.trim_end_matches('.')
        .parse()
        .unwrap_or_else(|_| panic!("no number after `{marker}`"))
}

#[test]
fn readme_hand_written_counts_are_current() {
    let readme = std::fs::read_to_string(crate_dir().join("README.md")).unwrap();
    let stale = "cases/README.md quotes stale figures; update them from `cargo run --release -- gen --grid default -o /tmp/x` and `gen --grid smoke`";
    let default = grids::unfilled("default", 0).unwrap();
    let cases: usize = default.iter().map(|(_, f)| f.cases.len()).sum();
    assert_eq!(
        figure_after(&readme, "holds the `default` grid: **"),
        cases as f64,
        "{stale}"
    );
    assert_eq!(
        figure_after(&readme, "cases in "),
        default.len() as f64,
        "{stale}"
    );
    let bytes: u64 = fixtures::fixture_paths(&fixtures_dir())
        .unwrap()
        .iter()
        .map(|p| std::fs::metadata(p).unwrap().len())
        .sum();
    let mib = figure_after(&readme, "files, about ");
    let have = bytes as f64 / (1024.0 * 1024.0);
    assert!(
        (mib - have).abs() <= 0.1 * have,
        "README says about {mib} MiB, the fixtures are {have:.1} MiB: {stale}"
    );
    let smoke: usize = grids::unfilled("smoke", 0)
        .unwrap()
        .iter()
        .map(|(_, f)| f.cases.len())
        .sum();
    assert_eq!(
        figure_after(&readme, "### `smoke`"),
        smoke as f64,
        "{stale}"
    );
}
