//! The fixture loader on good and malformed files: every error names the file, the case and the
//! field, and nothing panics.

use shadowcheck_cases::fixtures::{self, FixtureError, FixtureFile};
use shadowcheck_cases::grids;
use std::path::{Path, PathBuf};

fn sample() -> FixtureFile {
    // The smoke grid's structure, without expectations (this test must not depend on the oracle).
    let mut files = grids::unfilled("smoke", 0).unwrap();
    let (_, mut f) = files.remove(0);
    f.cases.truncate(5);
    f
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "shadowcheck-cases-test-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The text of the sample with one case line edited.
fn edited(case: usize, from: &str, to: &str) -> (String, String) {
    let f = sample();
    let id = f.cases[case].id.clone();
    let text = fixtures::to_string(&f).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let line = &mut lines[case + 1];
    assert!(line.contains(from), "{from} not in {line}");
    *line = line.replacen(from, to, 1);
    (lines.join("\n"), id)
}

fn err(text: &str) -> FixtureError {
    fixtures::parse_str(Path::new("dir/bad.json"), text).unwrap_err()
}

#[test]
fn round_trip_through_a_directory() {
    let d = tmpdir("roundtrip");
    let f = sample();
    fixtures::write_dir(
        &d,
        &[("b/x.json".into(), f.clone()), ("a.json".into(), f.clone())],
    )
    .unwrap();
    let loaded = fixtures::load_path(&d).unwrap();
    let names: Vec<_> = loaded
        .iter()
        .map(|(p, _)| p.strip_prefix(&d).unwrap().to_path_buf())
        .collect();
    assert_eq!(
        names,
        vec![PathBuf::from("a.json"), PathBuf::from("b/x.json")]
    );
    assert_eq!(loaded[0].1, f);
    assert_eq!(fixtures::load_file(&d.join("a.json")).unwrap(), f);
    // A file that is not in the set any more is removed on rewrite; other files are left alone.
    std::fs::write(d.join("notes.json"), "{}").unwrap();
    fixtures::write_dir(&d, &[("a.json".into(), f.clone())]).unwrap();
    assert!(!d.join("b/x.json").exists());
    assert!(d.join("notes.json").exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn layout_is_one_case_per_line_and_deterministic() {
    let f = sample();
    let a = fixtures::to_string(&f).unwrap();
    assert_eq!(a, fixtures::to_string(&f.clone()).unwrap());
    assert!(
        a.starts_with("{\"schema_version\":1,\"generator\":\"shadowcheck-cases "),
        "{}",
        &a[..80]
    );
    assert_eq!(a.lines().count(), f.cases.len() + 2);
    assert!(a.ends_with("\n]}\n"));
}

#[test]
fn truncated_file_names_the_case_it_stops_in() {
    let f = sample();
    let text = fixtures::to_string(&f).unwrap();
    let cut = text.find(&f.cases[2].id).unwrap() + f.cases[2].id.len() + 40;
    let e = err(&text[..cut]);
    let msg = e.to_string();
    assert!(matches!(e, FixtureError::Syntax { .. }), "{msg}");
    assert_eq!(e.case_id(), Some(f.cases[2].id.as_str()), "{msg}");
    assert!(
        msg.contains("dir/bad.json") && msg.contains("case #2"),
        "{msg}"
    );
}

#[test]
fn wrong_type_names_case_and_field() {
    let (text, id) = edited(1, "\"width\":", "\"width\":\"four\",\"w\":");
    let e = err(&text);
    let msg = e.to_string();
    assert_eq!(e.case_id(), Some(id.as_str()), "{msg}");
    assert_eq!(e.field(), Some("texture.levels[0].width"), "{msg}");
    assert!(msg.contains("dir/bad.json") && msg.contains(&id), "{msg}");
}

#[test]
fn unknown_enum_names_case_and_field() {
    let (text, id) = edited(0, "\"min_filter\":\"", "\"min_filter\":\"bogus_");
    let e = err(&text);
    let msg = e.to_string();
    assert_eq!(e.field(), Some("sampler.min_filter"), "{msg}");
    assert!(msg.contains(&id) && msg.contains("bogus_"), "{msg}");
}

#[test]
fn nan_literal_is_a_syntax_error_naming_the_case() {
    let (text, id) = edited(3, "\"min_lod\":-1000.0", "\"min_lod\":NaN");
    let e = err(&text);
    let msg = e.to_string();
    assert!(matches!(e, FixtureError::Syntax { .. }), "{msg}");
    assert_eq!(e.case_id(), Some(id.as_str()), "{msg}");
    assert!(msg.contains("line 5"), "{msg}");
}

#[test]
fn nan_string_where_a_number_is_required_names_the_field() {
    let (text, id) = edited(2, "\"min_lod\":-1000.0", "\"min_lod\":\"nan\"");
    let e = err(&text);
    assert_eq!(e.field(), Some("sampler.min_lod"), "{e}");
    assert_eq!(e.case_id(), Some(id.as_str()));
    // Non-finite values are allowed where the model allows them (the reference value).
    let (ok, _) = edited(2, "\"dref\":", "\"dref\":\"nan\",\"x\":");
    fixtures::parse_str(Path::new("ok.json"), &ok).unwrap();
}

#[test]
fn absurd_texture_sizes_are_errors_not_allocations() {
    let (text, id) = edited(1, "\"width\":", "\"width\":1000000000,\"w\":");
    let e = err(&text);
    assert!(
        e.field().unwrap().starts_with("texture.levels[0].width"),
        "{e}"
    );
    assert!(e.to_string().contains(&id));
    let (text, _) = edited(1, "\"width\":", "\"width\":1099511627776,\"w\":");
    assert_eq!(err(&text).field(), Some("texture.levels[0].width"));
    let (text, _) = edited(1, "\"layers\":", "\"layers\":-1,\"l\":");
    assert_eq!(err(&text).field(), Some("texture.levels[0].layers"));
}

#[test]
fn texel_count_mismatch_names_the_level() {
    let (text, id) = edited(0, "\"depth\":{\"unorm\":[", "\"depth\":{\"unorm\":[7,");
    let e = err(&text);
    assert_eq!(e.field(), Some("texture.levels[0].depth"), "{e}");
    assert_eq!(e.case_id(), Some(id.as_str()));
}

#[test]
fn lenient_loading_drops_and_reports_bad_cases() {
    let (text, id) = edited(1, "\"min_filter\":\"", "\"min_filter\":\"bogus_");
    let (f, errors) = fixtures::parse_str_lenient(Path::new("x.json"), &text).unwrap();
    assert_eq!(f.cases.len(), sample().cases.len() - 1);
    assert_eq!(errors.len(), 1);
    assert_eq!(errors[0].case_id(), Some(id.as_str()));
    // The file itself still has to be a fixture file.
    assert!(fixtures::parse_str_lenient(Path::new("x.json"), "[1,2]").is_err());
}

#[test]
fn header_errors() {
    let e = err("{\"schema_version\":1,\"generator\":\"g\",\"grid\":\"x\",\"seed\":0}");
    assert!(matches!(e, FixtureError::NotFixture { .. }), "{e}");
    assert!(e.to_string().contains("cases"), "{e}");
    let e =
        err("{\"schema_version\":99,\"generator\":\"g\",\"grid\":\"x\",\"seed\":0,\"cases\":[]}");
    assert!(matches!(e, FixtureError::Version { found: 99, .. }), "{e}");
    let e =
        err("{\"schema_version\":1,\"generator\":\"g\",\"grid\":\"x\",\"seed\":-3,\"cases\":[]}");
    assert_eq!(e.field(), Some("seed"), "{e}");
    let e = err("");
    assert!(matches!(e, FixtureError::Syntax { .. }), "{e}");
    let e = err("{\"schema_version\":1,\"generator\":\"g\",\"grid\":\"x\",\"seed\":0,\"cases\":[]} trailing");
    assert!(matches!(e, FixtureError::Syntax { .. }), "{e}");
}

#[test]
fn duplicate_ids_are_rejected() {
    let mut f = sample();
    f.cases[2].id = f.cases[0].id.clone();
    let e = err(&fixtures::to_string(&f).unwrap());
    assert!(
        matches!(e, FixtureError::DuplicateId { first: 0, .. }),
        "{e}"
    );
}

#[test]
fn missing_paths_and_empty_directories() {
    let e = fixtures::load_path(Path::new("/nonexistent/shadowcheck")).unwrap_err();
    assert!(e.to_string().contains("/nonexistent/shadowcheck"), "{e}");
    let d = tmpdir("empty");
    assert!(matches!(
        fixtures::load_path(&d),
        Err(FixtureError::NoFixtures { .. })
    ));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn write_dir_refuses_paths_outside_the_folder() {
    let d = tmpdir("escape");
    let e = fixtures::write_dir(&d, &[("../x.json".into(), sample())]).unwrap_err();
    assert!(matches!(e, FixtureError::BadRelativePath { .. }), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn files_written_one_by_one_survive_until_remove_stale() {
    let d = tmpdir("stream");
    let f = sample();
    let a = fixtures::write_file(&d, "x/a.json", &f).unwrap();
    let b = fixtures::write_file(&d, "x/b.json", &f).unwrap();
    fixtures::write_file(&d, "old.json", &f).unwrap();
    assert!(a.exists() && b.exists());
    fixtures::remove_stale(&d, &[a.clone(), b.clone()].into_iter().collect()).unwrap();
    assert!(a.exists() && b.exists() && !d.join("old.json").exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn lenient_loading_recovers_the_intact_cases_of_a_truncated_file() {
    let f = sample();
    let text = fixtures::to_string(&f).unwrap();
    let cut = text.find(&f.cases[3].id).unwrap() + f.cases[3].id.len() + 40;
    assert!(fixtures::parse_str(Path::new("t.json"), &text[..cut]).is_err());
    let (got, errors) = fixtures::parse_str_lenient(Path::new("t.json"), &text[..cut]).unwrap();
    assert_eq!(got.cases.len(), 3);
    assert_eq!(got.cases[..], f.cases[..3]);
    assert_eq!(errors.len(), 1);
    assert_eq!(
        errors[0].case_id(),
        Some(f.cases[3].id.as_str()),
        "{}",
        errors[0]
    );
    assert!(errors[0].to_string().contains("case #3"), "{}", errors[0]);
    // Text without the writer's layout still fails as a whole.
    assert!(fixtures::parse_str_lenient(Path::new("t.json"), "{\"schema_version\":1,").is_err());
}

#[test]
fn ids_needing_csv_quoting_are_rejected_naming_file_and_case() {
    for (bad, shown) in [
        ("/dt=0.2,0.4", "/dt=0.2,0.4`"),
        ("/q=\\\"x\\\"", "/q=\\\"x\\\"`"),
        ("/a b", "/a b`"),
        ("/a\\nb", "/a\\nb`"),
    ] {
        let f = sample();
        let id = f.cases[1].id.clone();
        let (text, _) = edited(
            1,
            &format!("\"id\":\"{id}\""),
            &format!("\"id\":\"{id}{bad}\""),
        );
        let e = err(&text);
        let msg = e.to_string();
        assert_eq!(e.field(), Some("id"), "{msg}");
        assert!(msg.contains("dir/bad.json"), "{msg}");
        assert!(msg.contains(&format!("case #1 `{id}{shown}")), "{msg}");
        assert!(!msg.contains('\n'), "the id is shown escaped: {msg}");
    }
}

#[test]
fn duplicate_api_paths_in_a_case_are_rejected() {
    let f = sample();
    let api = f.cases[0].api[0].key();
    let (text, id) = edited(0, "\"api\":[", &format!("\"api\":[\"{api}\","));
    let e = err(&text);
    let msg = e.to_string();
    assert_eq!(e.case_id(), Some(id.as_str()), "{msg}");
    assert!(
        msg.contains("dir/bad.json") && msg.contains("duplicate API path"),
        "{msg}"
    );
}

#[test]
fn generated_ids_need_no_csv_quoting() {
    for grid in ["smoke", "default"] {
        for (_, f) in grids::unfilled(grid, 0).unwrap() {
            for c in &f.cases {
                assert!(
                    c.id.chars().all(shadowcheck_model::validate::id_char_ok),
                    "{grid}: {}",
                    c.id
                );
            }
        }
    }
}

/// The loader re-derives `expect` with the linked oracle (`cases/src/recheck.rs`); an edited
/// expectation is an error naming the file, the case, the field and the regenerate command.
#[test]
fn an_edited_expectation_is_a_load_error_naming_file_case_and_field() {
    let (_, mut f) = grids::generate("smoke", 0).unwrap().remove(0);
    f.cases.truncate(3);
    let text = fixtures::to_string(&f).unwrap();
    assert!(fixtures::parse_str(Path::new("ok.json"), &text).is_ok());
    let e = f.cases[1].expect.as_mut().unwrap();
    e.spec_value = Some(e.spec_value.unwrap_or(0.0) + 0.5);
    let id = f.cases[1].id.clone();
    let text = fixtures::to_string(&f).unwrap();
    let err = fixtures::parse_str(Path::new("edited.json"), &text).unwrap_err();
    assert_eq!(err.case_id(), Some(id.as_str()));
    assert_eq!(err.field(), Some("expect.spec_value"));
    let msg = err.to_string();
    assert!(msg.starts_with("edited.json: case #1"), "{msg}");
    assert!(msg.contains("shadowcheck gen --grid smoke"), "{msg}");
}
