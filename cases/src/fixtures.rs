//! The fixture file format (version [`SCHEMA_VERSION`]), its writer and its loaders.
//!
//! A fixture file is one JSON object:
//! `{"schema_version":1,"generator":"shadowcheck-cases 0.1.0","grid":"default","seed":0,"cases":[...]}`
//! where each element of `cases` is a [`Case`] as the model serializes it, with `expect` filled by
//! the oracle. The writer puts the header on the first line and one case per line, so files are
//! compact and `git diff` shows changed cases one line each. cases/README.md documents the format and
//! cases/schema/fixture.schema.json is its JSON Schema.
//!
//! Loading never panics on bad input: every error names the file, the case (index and id, when the
//! case got far enough to have one) and the field (a path such as `texture.levels[0].width`).

pub use crate::fixture_error::{CaseRef, FixtureError};
use shadowcheck_model::state::validate_state;
use shadowcheck_model::{validate::validate, Case, ModelError, StateCase, SCHEMA_VERSION};
use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One fixture file.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FixtureFile {
    /// Format version; this crate reads and writes [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// `shadowcheck-cases <version>` of the generator that wrote the file.
    pub generator: String,
    /// The grid the cases come from (`smoke`, `default`, `exhaustive`, or a user's name).
    pub grid: String,
    /// The seed the grid was generated with.
    pub seed: u64,
    pub cases: Vec<Case>,
    /// TexParameter / GetTexParameter state cases (a file of the `state/` folder holds only these,
    /// after an empty `cases`); absent from lookup files.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub state_cases: Vec<StateCase>,
}

/// The header plus the still-unparsed cases (each case's JSON text, checked for syntax only), so
/// that one bad case can be reported on its own and each case is deserialized from its text once,
/// with no intermediate `serde_json::Value` tree.
#[derive(serde::Deserialize)]
struct RawFile {
    schema_version: u32,
    generator: String,
    grid: String,
    seed: u64,
    cases: Vec<Box<serde_json::value::RawValue>>,
    /// Present in state files only (after an empty `cases`).
    #[serde(default)]
    state_cases: Vec<Box<serde_json::value::RawValue>>,
}

/// Only a case's id, read from its text when the case itself does not deserialize.
#[derive(serde::Deserialize)]
struct IdOnly {
    id: String,
}

/// Serializes a fixture file: the header on the first line, then one case per line.
/// Deterministic: the same value always gives the same bytes (serde_json's float formatting is the
/// shortest round-trip representation, and every map in the model is a `BTreeMap`).
pub fn to_string(file: &FixtureFile) -> Result<String, serde_json::Error> {
    let mut out = String::new();
    // Written by hand so the header keys keep this order whatever serde_json features are enabled.
    let _ = write!(
        out,
        "{{\"schema_version\":{},\"generator\":{},\"grid\":{},\"seed\":{}",
        file.schema_version,
        serde_json::to_string(&file.generator)?,
        serde_json::to_string(&file.grid)?,
        file.seed
    );
    out.push_str(",\"cases\":[");
    for (i, case) in file.cases.iter().enumerate() {
        out.push_str(if i == 0 { "\n" } else { ",\n" });
        out.push_str(&serde_json::to_string(case)?);
    }
    if file.state_cases.is_empty() {
        out.push_str("\n]}\n");
        return Ok(out);
    }
    out.push_str(if file.cases.is_empty() { "]" } else { "\n]" });
    out.push_str(",\"state_cases\":[");
    for (i, case) in file.state_cases.iter().enumerate() {
        out.push_str(if i == 0 { "\n" } else { ",\n" });
        out.push_str(&serde_json::to_string(case)?);
    }
    out.push_str("\n]}\n");
    Ok(out)
}

/// Parses fixture text. `file` is only used in error messages. Strict: the first error aborts.
pub fn parse_str(file: &Path, text: &str) -> Result<FixtureFile, FixtureError> {
    let (f, errors) = parse_inner(file, text, true)?;
    match errors.into_iter().next() {
        Some(e) => Err(e),
        None => Ok(f),
    }
}

/// Parses fixture text, dropping bad cases and returning their errors.
///
/// A file that is not valid JSON as a whole (truncated, one corrupted line) is still read when it
/// has the writer's layout (header line, one case per line): each line that parses is kept, the
/// others are reported with their case index and, where readable, id.
pub fn parse_str_lenient(
    file: &Path,
    text: &str,
) -> Result<(FixtureFile, Vec<FixtureError>), FixtureError> {
    match parse_inner(file, text, false) {
        Err(e @ FixtureError::Syntax { .. }) => parse_by_line(file, text).ok_or(e),
        other => other,
    }
}

/// Line-by-line recovery for [`parse_str_lenient`]; `None` if the text does not have the writer's
/// layout.
fn parse_by_line(file: &Path, text: &str) -> Option<(FixtureFile, Vec<FixtureError>)> {
    let mut lines = text.lines();
    let header = lines.next()?.strip_suffix("\"cases\":[")?;
    let (mut f, _) = parse_inner(file, &format!("{header}\"cases\":[]}}"), false).ok()?;
    let mut errors = Vec::new();
    let mut seen = std::collections::HashMap::new();
    for (index, line) in lines.enumerate() {
        let body = line.strip_suffix(',').unwrap_or(line);
        if body.starts_with(']') {
            break;
        }
        let value: Result<&serde_json::value::RawValue, _> = serde_json::from_str(body);
        let at = CaseRef {
            index: Some(index),
            id: None,
        };
        let result = match value {
            Ok(v) => case_from_text(file, index, &f.grid, v.get()).and_then(|c| {
                match seen.insert(c.id.clone(), index) {
                    Some(first) => Err(FixtureError::DuplicateId {
                        file: file.to_path_buf(),
                        at: CaseRef {
                            id: Some(c.id.clone()),
                            ..at
                        },
                        first,
                    }),
                    None => Ok(c),
                }
            }),
            Err(e) => Err(FixtureError::Syntax {
                file: file.to_path_buf(),
                at: CaseRef {
                    id: locate_case(&format!("{{\"cases\":[{body}"), 1, e.column() + 11).id,
                    ..at
                },
                line: index + 2,
                column: e.column(),
                msg: strip_position(&e.to_string()),
            }),
        };
        match result {
            Ok(c) => f.cases.push(c),
            Err(e) => errors.push(e),
        }
    }
    Some((f, errors))
}

fn parse_inner(
    file: &Path,
    text: &str,
    stop_at_first: bool,
) -> Result<(FixtureFile, Vec<FixtureError>), FixtureError> {
    let raw: RawFile = header_or_error(file, text)?;
    if raw.schema_version != SCHEMA_VERSION {
        return Err(FixtureError::Version {
            file: file.to_path_buf(),
            found: raw.schema_version,
            supported: SCHEMA_VERSION,
        });
    }
    let mut errors = Vec::new();
    let mut cases = Vec::with_capacity(raw.cases.len());
    let mut seen: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for (index, value) in raw.cases.iter().enumerate() {
        let result = case_from_text(file, index, &raw.grid, value.get()).and_then(|case| {
            if let Some(&first) = seen.get(&case.id) {
                return Err(FixtureError::DuplicateId {
                    file: file.to_path_buf(),
                    at: CaseRef {
                        index: Some(index),
                        id: Some(case.id.clone()),
                    },
                    first,
                });
            }
            seen.insert(case.id.clone(), index);
            Ok(case)
        });
        match result {
            Ok(case) => cases.push(case),
            Err(e) => {
                errors.push(e);
                if stop_at_first {
                    break;
                }
            }
        }
    }
    let mut state_cases = Vec::with_capacity(raw.state_cases.len());
    for (index, value) in raw.state_cases.iter().enumerate() {
        if stop_at_first && !errors.is_empty() {
            break;
        }
        let result = state_from_text(file, index, &raw.grid, value.get()).and_then(|case| {
            let at = CaseRef {
                index: Some(index),
                id: Some(case.id.clone()),
            };
            match seen.insert(case.id.clone(), index) {
                Some(first) => Err(FixtureError::DuplicateId {
                    file: file.to_path_buf(),
                    at,
                    first,
                }),
                None => Ok(case),
            }
        });
        match result {
            Ok(case) => state_cases.push(case),
            Err(e) => errors.push(e),
        }
    }
    let f = FixtureFile {
        schema_version: raw.schema_version,
        generator: raw.generator,
        grid: raw.grid,
        seed: raw.seed,
        cases,
        state_cases,
    };
    Ok((f, errors))
}

fn header_or_error(file: &Path, text: &str) -> Result<RawFile, FixtureError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let raw: RawFile = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        json_error(
            file,
            text,
            if path == "." {
                "(top level)".to_string()
            } else {
                path
            },
            e.into_inner(),
        )
    })?;
    de.end()
        .map_err(|e| json_error(file, text, "(after the top-level object)".into(), e))?;
    Ok(raw)
}

/// A serde_json error on the whole text: syntax errors name the case they fall in; type errors in
/// the header say the text is not a fixture file.
fn json_error(file: &Path, text: &str, field: String, inner: serde_json::Error) -> FixtureError {
    match inner.classify() {
        serde_json::error::Category::Syntax
        | serde_json::error::Category::Eof
        | serde_json::error::Category::Io => FixtureError::Syntax {
            file: file.to_path_buf(),
            at: locate_case(text, inner.line(), inner.column()),
            line: inner.line(),
            column: inner.column(),
            msg: strip_position(&inner.to_string()),
        },
        serde_json::error::Category::Data => FixtureError::NotFixture {
            file: file.to_path_buf(),
            field,
            msg: strip_position(&inner.to_string()),
        },
    }
}

/// Deserializes case number `index` from its JSON text (syntax already checked), validates its
/// structure and re-derives its `expect` with the linked oracle (`recheck`).
fn case_from_text(file: &Path, index: usize, grid: &str, text: &str) -> Result<Case, FixtureError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let case: Case = serde_path_to_error::deserialize(&mut de).map_err(|e| FixtureError::Case {
        file: file.to_path_buf(),
        at: CaseRef {
            index: Some(index),
            // Where the case does not deserialize, its id (if it has a readable one) names it.
            id: serde_json::from_str::<IdOnly>(text).ok().map(|c| c.id),
        },
        field: if e.path().to_string() == "." {
            "(case)".to_string()
        } else {
            e.path().to_string()
        },
        msg: strip_position(&e.inner().to_string()),
    })?;
    let at = &CaseRef {
        index: Some(index),
        id: Some(case.id.clone()),
    };
    validate(&case).map_err(|e| match e {
        ModelError::Invalid { field, msg, .. } => FixtureError::Case {
            file: file.to_path_buf(),
            at: at.clone(),
            field,
            msg,
        },
        other => FixtureError::Case {
            file: file.to_path_buf(),
            at: at.clone(),
            field: "(case)".into(),
            msg: other.to_string(),
        },
    })?;
    crate::recheck::check(file, at, grid, &case)?;
    Ok(case)
}

/// Deserializes state case number `index` (of `state_cases`), validates it and re-derives its
/// `expect` with the linked oracle (`recheck::check_state`).
fn state_from_text(
    file: &Path,
    index: usize,
    grid: &str,
    text: &str,
) -> Result<StateCase, FixtureError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let case: StateCase =
        serde_path_to_error::deserialize(&mut de).map_err(|e| FixtureError::Case {
            file: file.to_path_buf(),
            at: CaseRef {
                index: Some(index),
                id: serde_json::from_str::<IdOnly>(text).ok().map(|c| c.id),
            },
            field: format!("state_cases.{}", e.path()),
            msg: strip_position(&e.inner().to_string()),
        })?;
    let at = CaseRef {
        index: Some(index),
        id: Some(case.id.clone()),
    };
    validate_state(&case).map_err(|e| FixtureError::Case {
        file: file.to_path_buf(),
        at: at.clone(),
        field: match &e {
            ModelError::Invalid { field, .. } => field.clone(),
            _ => "(case)".into(),
        },
        msg: match e {
            ModelError::Invalid { msg, .. } => msg,
            other => other.to_string(),
        },
    })?;
    crate::recheck::check_state(file, &at, grid, &case)?;
    Ok(case)
}

/// serde_json appends " at line L column C" to its messages; the fixture errors carry that apart.
fn strip_position(msg: &str) -> String {
    match msg.rfind(" at line ") {
        Some(i) => msg[..i].to_string(),
        None => msg.to_string(),
    }
}

/// Finds which case a syntax error at (line, column) falls in: counts the objects opened at depth 2
/// inside the top-level `cases` array before the error, and picks up the last `"id"` seen there.
/// Best effort on broken text: a string containing braces is skipped correctly, anything else may
/// leave the id unknown.
fn locate_case(text: &str, line: usize, column: usize) -> CaseRef {
    let offset = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum::<usize>()
        + column.saturating_sub(1);
    let upto = &text[..floor_char_boundary(text, offset.min(text.len()))];
    let Some(start) = upto.find("\"cases\"") else {
        return CaseRef::default();
    };
    let mut depth = 0usize;
    let mut in_str = false;
    let mut escaped = false;
    let mut index: Option<usize> = None;
    let mut case_start = 0usize;
    for (i, ch) in upto[start..].char_indices() {
        if in_str {
            match (escaped, ch) {
                (true, _) => escaped = false,
                (false, '\\') => escaped = true,
                (false, '"') => in_str = false,
                _ => {}
            }
            continue;
        }
        match ch {
            '"' => in_str = true,
            '[' | '{' => {
                depth += 1;
                if depth == 2 && ch == '{' {
                    index = Some(index.map_or(0, |n| n + 1));
                    case_start = start + i;
                }
            }
            ']' | '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    let Some(index) = index else {
        return CaseRef::default();
    };
    let id = upto[case_start..].find("\"id\":").and_then(|p| {
        let rest = upto[case_start + p + 5..].trim_start().strip_prefix('"')?;
        rest.find('"').map(|end| rest[..end].to_string())
    });
    CaseRef {
        index: Some(index),
        id,
    }
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// Loads one fixture file. Strict: the first error aborts.
pub fn load_file(path: &Path) -> Result<FixtureFile, FixtureError> {
    let text = std::fs::read_to_string(path).map_err(|source| FixtureError::Read {
        file: path.to_path_buf(),
        source,
    })?;
    parse_str(path, &text)
}

/// Loads one fixture file, dropping the cases that fail and reporting them. `Err` only when the
/// file itself cannot be read or is not a fixture file.
pub fn load_file_lenient(path: &Path) -> Result<(FixtureFile, Vec<FixtureError>), FixtureError> {
    let text = std::fs::read_to_string(path).map_err(|source| FixtureError::Read {
        file: path.to_path_buf(),
        source,
    })?;
    parse_str_lenient(path, &text)
}

/// The `*.json` files at `path`: the file itself, or a directory searched recursively, sorted.
pub fn fixture_paths(path: &Path) -> Result<Vec<PathBuf>, FixtureError> {
    let meta = std::fs::metadata(path).map_err(|source| FixtureError::Read {
        file: path.to_path_buf(),
        source,
    })?;
    if !meta.is_dir() {
        return Ok(vec![path.to_path_buf()]);
    }
    let mut out = Vec::new();
    let mut stack = vec![path.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let rd = std::fs::read_dir(&dir).map_err(|source| FixtureError::Read {
            file: dir.clone(),
            source,
        })?;
        for entry in rd {
            let entry = entry.map_err(|source| FixtureError::Read {
                file: dir.clone(),
                source,
            })?;
            let p = entry.path();
            let ft = entry.file_type().map_err(|source| FixtureError::Read {
                file: p.clone(),
                source,
            })?;
            if ft.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "json") {
                out.push(p);
            }
        }
    }
    out.sort();
    if out.is_empty() {
        return Err(FixtureError::NoFixtures {
            path: path.to_path_buf(),
        });
    }
    Ok(out)
}

/// Loads a file, or every `*.json` under a directory (recursively, sorted by path). Strict.
pub fn load_path(path: &Path) -> Result<Vec<(PathBuf, FixtureFile)>, FixtureError> {
    fixture_paths(path)?
        .into_iter()
        .map(|p| load_file(&p).map(|f| (p, f)))
        .collect()
}

/// Writes `files` (paths relative to `dir`, `/`-separated) under `dir`, creating folders. Fixture
/// files already under `dir` that are not in `files` are removed, so that regenerating a grid whose
/// layout changed leaves no stale file behind; other files are left alone.
pub fn write_dir(dir: &Path, files: &[(String, FixtureFile)]) -> Result<(), FixtureError> {
    let mut wanted = BTreeSet::new();
    for (rel, file) in files {
        wanted.insert(write_file(dir, rel, file)?);
    }
    remove_stale(dir, &wanted)
}

/// Writes one fixture file at `dir/rel` (creating folders) and returns its path. Nothing else in
/// `dir` is touched: for grids written file by file, call [`remove_stale`] at the end.
pub fn write_file(dir: &Path, rel: &str, file: &FixtureFile) -> Result<PathBuf, FixtureError> {
    if rel.is_empty() || rel.starts_with('/') || rel.split('/').any(|c| c == ".." || c.is_empty()) {
        return Err(FixtureError::BadRelativePath {
            dir: dir.to_path_buf(),
            rel: rel.to_string(),
        });
    }
    let path = dir.join(rel);
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|source| FixtureError::Write {
            file: parent.to_path_buf(),
            source,
        })?;
    }
    let text = to_string(file).map_err(|e| FixtureError::Write {
        file: path.clone(),
        source: std::io::Error::other(e),
    })?;
    std::fs::write(&path, text).map_err(|source| FixtureError::Write {
        file: path.clone(),
        source,
    })?;
    Ok(path)
}

/// Removes the fixture files under `dir` (recognised by their first bytes) whose paths are not in
/// `keep`; any other file is left alone.
pub fn remove_stale(dir: &Path, keep: &BTreeSet<PathBuf>) -> Result<(), FixtureError> {
    let Ok(existing) = fixture_paths(dir) else {
        return Ok(());
    };
    for p in existing {
        if keep.contains(&p) || !is_fixture_file(&p) {
            continue;
        }
        std::fs::remove_file(&p).map_err(|source| FixtureError::Write {
            file: p.clone(),
            source,
        })?;
    }
    Ok(())
}

fn is_fixture_file(p: &Path) -> bool {
    use std::io::Read;
    let prefix = b"{\"schema_version\":";
    let mut buf = [0u8; 18];
    std::fs::File::open(p)
        .and_then(|mut f| f.read_exact(&mut buf))
        .is_ok()
        && buf[..] == prefix[..]
}

/// A one-line summary of a set of errors (for lenient loading reports).
pub fn summarize(errors: &[FixtureError]) -> String {
    let mut s = String::new();
    for e in errors {
        let _ = writeln!(s, "{e}");
    }
    s
}
