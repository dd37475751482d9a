//! One module per subcommand. Each has `Args` (clap) and `main(Args) -> anyhow::Result<ExitCode>`.
pub mod bench;
pub mod explain;
pub mod gen;
pub mod gl_worker;
pub mod merge;
pub mod mock_worker;
pub mod mutants;
pub mod report;
pub mod run;
pub mod summarize;
