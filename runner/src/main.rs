//! `shadowcheck`: the command-line edge. Each subcommand lives in `cmd/`; the library crate
//! (`shadowcheck_runner`) does the work and never prints.

// A closed stdout (`shadowcheck repro ... | head -1`) must not panic: print with `cmd::outln!`.
#![deny(clippy::print_stdout)]
// Nor a stderr whose reader has gone (`... 2>&1 | head -1`): write to it with `errln!`.
#![deny(clippy::print_stderr)]

use clap::{Parser, Subcommand};

mod cmd;

#[derive(Parser)]
#[command(
    name = "shadowcheck",
    version,
    about = "Conformance harness and spec-derived oracle for depth-texture comparison (shadow sampling) in OpenGL and OpenGL ES"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
#[allow(clippy::large_enum_variant)] // parsed once; boxing buys nothing
enum Command {
    /// Show what the specifications say about one case: spec value, acceptance per profile, derivation.
    Explain(cmd::explain::Args),
    /// Generate fixtures from a named grid.
    Gen(cmd::gen::Args),
    /// Run fixtures against backends and report verdicts.
    Run(cmd::run::Args),
    /// googletest's interface for one backend (`--gtest_list_tests`, `--gtest_filter=A:B`), so a
    /// gtest runner such as deqp-runner's `[[gtest]]` suite block runs shadowcheck.
    ///
    /// The backend comes from -b or SHADOWCHECK_BACKEND, the fixtures from --fixtures or
    /// SHADOWCHECK_FIXTURES. Test names map reversibly to gtest names (`.` and other characters a
    /// gtest runner reads are written %XX); Warn prints OK with a note, Crash and Timeout end the
    /// output after the test's RUN line (a crash to the runner). Exit 0 all passed or skipped, 1
    /// a test failed or crashed, 96 setup error or bad input.
    Gtest(cmd::gtest::Args),
    /// Merge result files of shards into one.
    Merge(cmd::merge::Args),
    /// Measure throughput: oracle, soft implementation, GL backends end to end against the bare-draw floor.
    Bench(cmd::bench::Args),
    /// Measure the suite's power: run the fixtures against seeded faults of the soft implementation.
    Mutants(cmd::mutants::Args),
    /// Write a self-contained HTML report (matrix, heatmaps, plots) from result files.
    Report(cmd::report::Args),
    /// Condense `shadowcheck run --out` directories into reference-results files (as reports/mesa-22.3.6/).
    ///
    /// Each RUN_DIR holds one finished run of one backend (by convention r-<backend with ':' as
    /// '-'>; the backend and its implementation's name come from the run's meta line, not from the
    /// folder's name). Writes, per run, OUTROOT/<backend with ':' as '-'>/: failures.csv (copied:
    /// the baseline), warnings.csv (`test,Warn`), summary.md (status counts per API path, skip
    /// reasons, non-pass groups with an example test) and report.md (the run's, capped at 150000
    /// characters); and OUTROOT/SUMMARY.md, one table over every backend x API path. Reads
    /// results.jsonl (the last record of a test wins), failures.csv and report.md of each run.
    /// Exit 0 when written, 96 on bad input (a run that did not finish included).
    Summarize(cmd::summarize::Args),
    /// Write a standalone C reproducer (repro.c, build.sh) and a bug report (REPORT.md) for a test
    /// that fails on a GL backend, or one per failure class of a results directory.
    ///
    /// `--backend B --case '<case id>@<api>'`: repro.c creates the worker's context, texture,
    /// sampler state and lookup, draws once, prints expected (from the oracle) and observed, and
    /// exits 1 when the observation is outside the accepted set. The command builds and runs it
    /// here (gcc and the GL dev packages needed), and writes REPORT.md only for a Fail. Exit 0
    /// written, 1 the test is not a Fail here (no report; --allow-pass: 0), 96 bad input or setup.
    /// `--all-failures RESULTS_DIR`: 0 when a reproducer was written, 4 when the results hold no
    /// Fail to reproduce, 96 when no class's reproducer could be written.
    Repro(cmd::repro::Args),
    /// The oracle's review queue: tests where at least three independent texture units return the
    /// same answer and the oracle rejects it (Fail).
    ///
    /// Reads RUN_DIR/results.jsonl of each run (several backends per run are fine); backends that
    /// share texture-unit code (llvmpipe, lavapipe under zink; SwiftShader's GLES, its Vulkan
    /// under zink, ANGLE on it) count as one unit. Only results with an observed value (Fail,
    /// Warn) are compared. Markdown on stdout (or JSON with --json); exit 0 when it ran, queue
    /// empty or not; 96 on bad input.
    Consensus(cmd::consensus::Args),
    /// Which layer broke each failure of a layered backend (zink on lavapipe or SwiftShader,
    /// WebGL on ANGLE's Vulkan back end on SwiftShader).
    ///
    /// For each Fail or Warn of such a backend in the runs, the same lookup as a Vulkan case (where
    /// Vulkan 1.3 defines it) is looked up in the Vulkan driver's results of the same runs: upper
    /// layer (the driver passes it, or the lookup has no Vulkan equivalent and the layer emulates
    /// it), lower (the driver fails it with the same r), both (it fails differently), or no
    /// equivalent (no answer of the driver in the runs). Markdown on stdout (or JSON with
    /// --json); exit 0 when it ran; 96 on bad input.
    Attribute(cmd::attribute::Args),
    /// The backend kinds' worker children (hidden; `backend::kinds::KINDS` names them).
    #[command(flatten)]
    Worker(cmd::workers::WorkerCommand),
}

fn main() -> std::process::ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // --help and --version are not errors: clap prints them and exits 0. Bad arguments exit
        // with the documented setup-error code (96), not clap's 2.
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            let _ = e.print();
            return std::process::ExitCode::from(96);
        }
    };
    let result = match cli.command {
        Command::Explain(a) => cmd::explain::main(a),
        Command::Gen(a) => cmd::gen::main(a),
        Command::Run(a) => cmd::run::main(a),
        Command::Merge(a) => cmd::merge::main(a),
        Command::Gtest(a) => cmd::gtest::main(a),
        Command::Bench(a) => cmd::bench::main(a),
        Command::Mutants(a) => cmd::mutants::main(a),
        Command::Report(a) => cmd::report::main(a),
        Command::Summarize(a) => cmd::summarize::main(a),
        Command::Repro(a) => cmd::repro::main(a),
        Command::Consensus(a) => cmd::consensus::main(a),
        Command::Attribute(a) => cmd::attribute::main(a),
        Command::Worker(w) => w.main(),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            shadowcheck_runner::errln!("shadowcheck: error: {}", message(&e));
            std::process::ExitCode::from(shadowcheck_runner::records::exit::SETUP)
        }
    }
}

/// The error and its causes, each cause once: a library error that already names its source in
/// its message (`"{file}: {source}"`) does not get it printed twice.
fn message(e: &anyhow::Error) -> String {
    let mut msg = e.to_string();
    for cause in e.chain().skip(1) {
        let c = cause.to_string();
        if !msg.contains(&c) {
            msg.push_str(": ");
            msg.push_str(&c);
        }
    }
    msg
}

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;
    use shadowcheck_runner::backend::kinds;

    /// The hidden subcommands are exactly the worker children the table of backend kinds names,
    /// each with the table's description: a kind whose worker is not wired here (or a worker no
    /// kind names) fails.
    #[test]
    fn the_worker_subcommands_are_those_of_the_kinds_table() {
        let cli = Cli::command();
        let hidden: Vec<(String, String)> = cli
            .get_subcommands()
            .filter(|c| c.is_hide_set())
            .map(|c| {
                let about = c.get_about().map(|a| a.to_string()).unwrap_or_default();
                (c.get_name().to_string(), about)
            })
            .collect();
        let table: Vec<(String, String)> = kinds::workers()
            .iter()
            .map(|w| (w.subcommand.to_string(), w.about.to_string()))
            .collect();
        assert_eq!(hidden, table);
        assert_eq!(
            table.iter().map(|(s, _)| s.as_str()).collect::<Vec<_>>(),
            [
                "gl-worker",
                "webgl-worker",
                "vk-worker",
                "webgpu-worker",
                "mock-worker"
            ]
        );
    }
}
