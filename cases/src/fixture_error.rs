//! The errors of the fixture loaders and writer ([`FixtureError`]) and where in a file they are
//! ([`CaseRef`]); re-exported by [`crate::fixtures`].

use std::path::PathBuf;

/// Where in a file an error is, as far as it is known.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct CaseRef {
    /// Index in the `cases` array.
    pub index: Option<usize>,
    /// The case's `id`, when it could be read.
    pub id: Option<String>,
}

impl std::fmt::Display for CaseRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match (&self.index, &self.id) {
            (Some(i), Some(id)) => write!(f, "case #{i} `{}`", id.escape_debug()),
            (None, Some(id)) => write!(f, "case `{}`", id.escape_debug()),
            (Some(i), None) => write!(f, "case #{i} (id unknown)"),
            (None, None) => f.write_str("file header"),
        }
    }
}

/// Errors from reading or writing fixture files.
#[derive(Debug, thiserror::Error)]
pub enum FixtureError {
    #[error("{}: cannot read: {source}", file.display())]
    Read {
        file: PathBuf,
        source: std::io::Error,
    },
    #[error("{}: cannot write: {source}", file.display())]
    Write {
        file: PathBuf,
        source: std::io::Error,
    },
    /// The text is not JSON (truncated file, `NaN` literal, stray comma...).
    #[error("{}: {at}: invalid JSON at line {line} column {column}: {msg}", file.display())]
    Syntax {
        file: PathBuf,
        at: CaseRef,
        line: usize,
        column: usize,
        msg: String,
    },
    /// The top-level object is not a fixture file (missing or mistyped header field).
    #[error("{}: not a shadowcheck fixture file: field `{field}`: {msg}", file.display())]
    NotFixture {
        file: PathBuf,
        field: String,
        msg: String,
    },
    #[error("{}: schema_version {found} is not supported (this shadowcheck reads {supported}; regenerate with `shadowcheck gen` or update shadowcheck)", file.display())]
    Version {
        file: PathBuf,
        found: u32,
        supported: u32,
    },
    /// One case does not deserialize or fails structural validation.
    #[error("{}: {at}: field `{field}`: {msg}", file.display())]
    Case {
        file: PathBuf,
        at: CaseRef,
        field: String,
        msg: String,
    },
    /// The written `expect` differs from what the linked oracle derives (a stale or edited fixture);
    /// `msg` gives both values and the command that regenerates.
    #[error("{}: {at}: field `{field}`: {msg}", file.display())]
    StaleExpect {
        file: PathBuf,
        at: CaseRef,
        field: String,
        msg: String,
    },
    #[error("{}: {at}: duplicate case id (first at case #{first})", file.display())]
    DuplicateId {
        file: PathBuf,
        at: CaseRef,
        first: usize,
    },
    #[error("{}: no fixture files (*.json) found", path.display())]
    NoFixtures { path: PathBuf },
    #[error("{}: refusing to write outside the output directory: `{rel}`", dir.display())]
    BadRelativePath { dir: PathBuf, rel: String },
}

impl FixtureError {
    /// The case this error is about, when known.
    pub fn case_id(&self) -> Option<&str> {
        match self {
            FixtureError::Syntax { at, .. }
            | FixtureError::Case { at, .. }
            | FixtureError::StaleExpect { at, .. }
            | FixtureError::DuplicateId { at, .. } => at.id.as_deref(),
            _ => None,
        }
    }
    /// The field this error is about, when known.
    pub fn field(&self) -> Option<&str> {
        match self {
            FixtureError::Case { field, .. }
            | FixtureError::StaleExpect { field, .. }
            | FixtureError::NotFixture { field, .. } => Some(field),
            _ => None,
        }
    }
}
