//! The documented exit codes of `shadowcheck run`, `merge` and `summarize`, and of every
//! subcommand's setup error (runner/README.md#exit-codes). [`Summary::new`](super::Summary::new)
//! picks one for a run, in the order of precedence REGRESSIONS, SETUP, IMPROVEMENTS, NOTHING,
//! SUCCESS.
//!
//! `explain`, `gen --check` and `mutants` also use small codes of their own (1, 2) for answers
//! that are not errors; those are named and documented in their `cmd/` modules.

/// All good: every test passed, warned, was skipped, was an expected failure or a (known) flake.
pub const SUCCESS: u8 = 0;
/// Nothing selected: empty fixtures, `--cases` matched nothing, an empty shard.
pub const NOTHING: u8 = 4;
/// Setup error or bad input: unknown backend, an implementation that cannot start, unreadable
/// fixtures, baseline, skips or flakes file, `--resume` with another selection, reports that could
/// not be written; also a run that completed but met bad fixture files or bad cases. Every
/// subcommand exits with it on an error.
pub const SETUP: u8 = 96;
/// At least one regression: Fail, Crash or Timeout not excused by the baseline.
pub const REGRESSIONS: u8 = 100;
/// No regression, but tests listed in the baseline now pass (or are skipped): update the baseline.
pub const IMPROVEMENTS: u8 = 101;
