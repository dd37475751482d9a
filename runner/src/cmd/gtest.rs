//! `shadowcheck gtest`: googletest's command-line interface for one backend, so that a gtest
//! runner (deqp-runner's `[[gtest]]` suite block, `gtest-runner`) runs shadowcheck as it runs any
//! googletest binary: `--gtest_list_tests` lists the backend's tests (a line `Suite.`, then the
//! test names indented), `--gtest_filter=A:B:C` runs those tests through the run core and prints
//! `[ RUN      ]` / `[       OK ]` / `[  FAILED  ]` / `[  SKIPPED ]` lines.
//!
//! Names: deqp-runner's list parser takes any `.` in a line for the suite separator, and a gtest
//! filter gives `:`, `-`, `*` and `?` meanings, so a test name (`<case id>@<api>`) is mapped
//! reversibly ([`to_gtest`], [`from_gtest`]): the part before its first `/` is the suite, the rest
//! the test, and in each every byte other than ASCII letters, digits and `/ = _ + ^ @` is written
//! `%XX` (upper-case hex), `%` included: `gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25@core` is
//! `gl46.2d/d16/nearest/lequal/ref=0%2E5/dt=0%2E25@core`. A name without `/` gets the suite `%2F`.
//!
//! Statuses (the raw outcome: deqp-runner applies its own baseline, skips and flakes, and detects
//! flakes by running a group again, so this command applies no list and re-runs nothing): Pass →
//! OK; Warn → OK after a note line (a pass with a note, as dEQP's QualityWarning is for
//! deqp-runner); Fail → FAILED; Skip → SKIPPED. Crash and Timeout have no googletest status:
//! their `[ RUN      ]` line is followed by a note and nothing else, and the process exits 1,
//! which deqp-runner's parser reads as a Crash of that test (a test without its end line); it
//! then runs the rest of the group in a new process. Exit code as googletest's: 0 when every
//! test printed passed or was skipped, 1 when one failed or the output ended on a crash; 96 on a
//! setup error or bad input (no backend, unreadable fixtures).

use anyhow::{bail, Context};
use shadowcheck_runner::backend::{self, Backend, BackendError, Capabilities};
use shadowcheck_runner::records::Results;
use shadowcheck_runner::run::{self, CaseSet, Settings};
use std::collections::{HashMap, HashSet};
use std::path::PathBuf;
use std::process::ExitCode;

mod names;
mod printer;
use names::{from_gtest, to_gtest, Filter};
use printer::{print_end, Printer};
#[cfg(test)]
use printer::{test_lines, NOTE_MAX};

/// The environment variable that names the backend when `-b` is not given.
pub const BACKEND_ENV: &str = "SHADOWCHECK_BACKEND";
/// The environment variable that names the fixtures (`:`-separated) when `--fixtures` is not given.
pub const FIXTURES_ENV: &str = "SHADOWCHECK_FIXTURES";

#[derive(clap::Args)]
pub struct Args {
    /// The one backend to run, named as for `run -b`; default: SHADOWCHECK_BACKEND.
    #[arg(long = "backend", short = 'b', value_name = "B", help = backend_help())]
    backend: Option<String>,
    /// Fixture file or directory (repeatable), as for `run`. Default: SHADOWCHECK_FIXTURES
    /// (`:`-separated), else cases/fixtures.
    #[arg(long, value_name = "PATH")]
    fixtures: Vec<PathBuf>,
    /// Only cases whose id matches this regular expression (as for `run`).
    #[arg(long, value_name = "PATTERN")]
    cases: Option<String>,
    #[command(flatten)]
    exchange: super::run::Exchange,
    /// googletest: list the tests (`Suite.` lines, then the test names indented) and exit.
    #[arg(long = "gtest_list_tests")]
    gtest_list_tests: bool,
    /// googletest: run only the tests matching `POSITIVE[-NEGATIVE]`, each a `:`-separated list
    /// of gtest names with `*` and `?` wildcards.
    #[arg(long = "gtest_filter", value_name = "PATTERNS")]
    gtest_filter: Option<String>,
}

/// The `-b` help: one backend, the patterns of `run -b`.
fn backend_help() -> String {
    format!(
        "The one backend to run ({}), named as for `run -b`. Default: the environment variable {BACKEND_ENV}.",
        backend::kinds::patterns()
    )
}

/// The suite part of a gtest name.
fn suite_of(gtest: &str) -> &str {
    gtest.split_once('.').map_or(gtest, |(s, _)| s)
}

/// One test of the backend: its gtest name, its shadowcheck name (`<case id>@<api>`) and its case id.
type Test = (String, String, String);

pub fn main(a: Args) -> anyhow::Result<ExitCode> {
    let name = backend_name(&a)?;
    let pattern = a
        .cases
        .as_deref()
        .map(regex::Regex::new)
        .transpose()
        .context("--cases")?;
    let opts = a.exchange.options()?;
    let mut set = load_fixtures(&a, pattern.as_ref())?;
    let mut backend = open_backend(&name, &opts)?;
    let tests = tests_of(&set, backend.capabilities());
    if a.gtest_list_tests {
        return list_tests(&tests);
    }
    let chosen = choose(&tests, a.gtest_filter.as_deref(), &name);
    keep_chosen(&mut set, &chosen);

    let suites: HashSet<&str> = chosen.iter().map(|t| suite_of(&t.0)).collect();
    let mut printer = Printer::new(
        chosen.iter().map(|t| t.1.clone()).collect(),
        chosen.iter().map(|t| t.0.clone()).collect(),
        a.exchange.verbose,
    );
    printer.out(&[format!(
        "[==========] Running {} tests from {} test suites ({}).",
        chosen.len(),
        suites.len(),
        name
    )]);
    let settings = Settings {
        rerun_regressions: false,
        explicit_fixtures: !a.fixtures.is_empty(),
        ..Settings::default()
    };
    let t0 = std::time::Instant::now();
    let results = if chosen.is_empty() {
        vec![]
    } else {
        run::run_backend(
            backend.as_mut(),
            &set,
            &Results::default(),
            &settings,
            &mut printer,
        )
        .0
    };
    drop(backend);
    printer.finish(&results);
    Ok(print_end(&mut printer, chosen.len(), suites.len(), t0))
}

/// The backend named by `-b`, else by the environment.
fn backend_name(a: &Args) -> anyhow::Result<String> {
    let env_backend = std::env::var(BACKEND_ENV).ok().filter(|s| !s.is_empty());
    let Some(name) = a.backend.clone().or(env_backend) else {
        bail!("gtest: no backend: give -b B or set {BACKEND_ENV}");
    };
    Ok(name)
}

/// The fixtures named by `--fixtures`, else by the environment, else the default.
fn fixture_paths(a: &Args) -> Vec<PathBuf> {
    if !a.fixtures.is_empty() {
        a.fixtures.clone()
    } else if let Some(env) = std::env::var_os(FIXTURES_ENV).filter(|v| !v.is_empty()) {
        std::env::split_paths(&env).collect()
    } else {
        vec![PathBuf::from(crate::cmd::run::DEFAULT_FIXTURES)]
    }
}

/// Loads the fixtures and selects the cases matching `pattern`; bad files and cases are said on
/// stderr, and are an error when nothing loaded or when listing.
fn load_fixtures(a: &Args, pattern: Option<&regex::Regex>) -> anyhow::Result<CaseSet> {
    let fixtures = fixture_paths(a);
    let shown: Vec<String> = fixtures.iter().map(|p| p.display().to_string()).collect();

    let mut set = run::load_cases(&fixtures);
    let loaded_any = !set.files.is_empty();
    set.select(pattern, None);
    for e in &set.errors {
        let case = e
            .case
            .as_deref()
            .map_or(String::new(), |c| format!(" ({c})"));
        shadowcheck_runner::errln!("shadowcheck: error: {}{case}: {}", e.file, e.message);
    }
    if !loaded_any && set.cases.is_empty() && set.states.is_empty() {
        bail!("no fixture could be loaded from {}", shown.join(", "));
    }
    // A listing is what the gtest runner plans from: a bad fixture stops it, loudly, rather than
    // leaving tests out of every later run without a word.
    if a.gtest_list_tests && !set.errors.is_empty() {
        bail!(
            "{} bad fixture file(s) or case(s) in {} (listed above)",
            set.errors.len(),
            shown.join(", ")
        );
    }
    Ok(set)
}

fn open_backend(name: &str, opts: &backend::Options) -> anyhow::Result<Box<dyn Backend>> {
    match backend::open(name, opts) {
        Ok(b) => Ok(b),
        Err(e @ BackendError::Unknown(_)) => Err(e.into()),
        Err(BackendError::Setup { msg, .. }) => {
            bail!("backend `{name}` cannot start here: {msg}")
        }
    }
}

/// Every test of this backend, sorted by gtest name.
fn tests_of(set: &CaseSet, caps: &Capabilities) -> Vec<Test> {
    let mut tests: Vec<Test> = set
        .test_names_on(caps)
        .into_iter()
        .map(|(case, test)| (to_gtest(&test), test, case.to_string()))
        .collect();
    tests.sort();
    tests
}

/// `--gtest_list_tests`: a line `Suite.` for each suite, then its test names indented.
fn list_tests(tests: &[Test]) -> anyhow::Result<ExitCode> {
    let mut lines = Vec::with_capacity(tests.len() * 2);
    let mut suite = None;
    for (g, _, _) in tests {
        let (s, t) = g.split_once('.').unwrap_or((g.as_str(), ""));
        if suite != Some(s) {
            lines.push(format!("{s}."));
            suite = Some(s);
        }
        lines.push(format!("  {t}"));
    }
    let mut text = lines.join("\n");
    if !text.is_empty() {
        text.push('\n');
    }
    crate::cmd::print_out(&text).context("writing the test list")?;
    Ok(ExitCode::SUCCESS)
}

/// The tests `--gtest_filter` selects (all without one); an exact name that is no test of
/// `backend` is said on stderr (googletest is silent).
fn choose<'t>(tests: &'t [Test], filter: Option<&str>, backend: &str) -> Vec<&'t Test> {
    let filter = Filter::parse(filter.unwrap_or("*"));
    let names: Vec<String> = tests.iter().map(|t| t.0.clone()).collect();
    let chosen = filter.select(&names);
    let known: HashSet<&str> = names.iter().map(String::as_str).collect();
    for p in &filter.positive {
        if !p.contains(['*', '?']) && !known.contains(p.as_str()) {
            let what = match from_gtest(p) {
                Some(t) => format!("test `{t}`"),
                None => "a name this command never lists".into(),
            };
            shadowcheck_runner::errln!(
                "shadowcheck: warning: --gtest_filter names `{p}` ({what}), which is no test of `{backend}` with these fixtures"
            );
        }
    }
    chosen.iter().map(|&i| &tests[i]).collect()
}

/// Keeps only the chosen cases in `set`, in the order their tests are printed.
fn keep_chosen(set: &mut CaseSet, chosen: &[&Test]) {
    let mut first: HashMap<&str, usize> = HashMap::new();
    for (k, t) in chosen.iter().enumerate() {
        first.entry(t.2.as_str()).or_insert(k);
    }
    set.cases.retain(|l| first.contains_key(l.case.id.as_str()));
    set.states
        .retain(|l| first.contains_key(l.case.id.as_str()));
    let pos = |id: &str| first.get(id).copied().unwrap_or(usize::MAX);
    set.cases.sort_by_key(|l| pos(&l.case.id));
    set.states.sort_by_key(|l| pos(&l.case.id));
}

#[cfg(test)]
mod tests {
    use super::*;
    use shadowcheck_runner::records::{Outcome, Status, Tags, TestResult};

    fn result(outcome: Outcome, reason: &str) -> TestResult {
        TestResult {
            backend: "mock:pass".into(),
            test: "gl46/x/ref=0.5@core".into(),
            case_id: "gl46/x/ref=0.5".into(),
            api: shadowcheck_model::ApiPath::GlslCore,
            status: Status::Plain(outcome),
            outcome,
            reason: Some(reason.into()),
            duration: 0.002,
            tags: Tags {
                spec: "gl46".into(),
                target: "2d".into(),
                format: "d16".into(),
                func: "lequal".into(),
                filter: "nearest".into(),
            },
            observed: None,
            expected: None,
            footprint: None,
            rerun: None,
            fixtures: None,
        }
    }

    /// deqp-runner 0.24's gtest result parser (src/gtest_command.rs): once a test has begun, any
    /// line matching this is its status line.
    fn deqp_status_line(line: &str) -> Option<String> {
        let re = regex::Regex::new(r"\[\s*(\S*)\s*\]\s(\S*)").unwrap();
        re.captures(line).map(|c| c[1].to_string())
    }

    #[test]
    fn every_outcome_prints_what_a_gtest_parser_expects() {
        let g = "gl46.x/ref=0%2E5@core";
        let tricky = "observed [0.5] outside {1}\nsecond line [ OK ] x";
        for (o, end, stops) in [
            (Outcome::Pass, Some("OK"), false),
            (Outcome::Warn, Some("OK"), false),
            (Outcome::Fail, Some("FAILED"), false),
            (Outcome::Skip, Some("SKIPPED"), false),
            (Outcome::Crash, None, true),
            (Outcome::Timeout, None, true),
        ] {
            let (lines, stop) = test_lines(g, &result(o, tricky));
            assert_eq!(stop, stops, "{o}");
            assert_eq!(lines[0], format!("[ RUN      ] {g}"));
            // Between the RUN line and the end, nothing reads as a status line.
            let body = &lines[1..lines.len() - usize::from(end.is_some())];
            for l in body {
                assert_eq!(deqp_status_line(l), None, "{o}: {l}");
            }
            if let Some(end) = end {
                let last = lines.last().unwrap();
                assert_eq!(deqp_status_line(last).as_deref(), Some(end), "{o}");
                assert!(last.contains(&format!(" {g} ")), "{last}");
            } else {
                assert!(!body.is_empty(), "a crash says why");
            }
            if o != Outcome::Pass {
                assert!(body.iter().any(|l| l.contains("observed (0.5)")), "{o}");
            }
        }
    }

    #[test]
    fn a_long_reason_is_cut() {
        let (lines, _) = test_lines("a.b", &result(Outcome::Crash, &"x".repeat(3_000_000)));
        assert!(lines.iter().map(String::len).sum::<usize>() < 3 * NOTE_MAX);
    }
}
