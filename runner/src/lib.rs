//! shadowcheck-runner library: backends, verdicts, baselines, reporters. The binary is src/main.rs.
//!
//! Data flows one way: fixtures → [`run`] (cases to a [`backend::Backend`]) → [`verdict`] (oracle
//! expectation and acceptance) → [`baseline`] (final status) → [`events`] → [`report`]ers.
//! The library never prints; reporters own every byte of output. What a run leaves on disk (the
//! result records, statuses, exit codes) and the one reader of results.jsonl are in [`records`].

pub mod backend;
pub mod baseline;
pub mod bench;
pub mod consensus;
pub mod events;
pub mod interrupt;
pub mod mutants;
pub mod outdir;
pub mod records;
pub mod report;
pub mod repro;
pub mod run;
pub mod schedule;
pub mod shard;
pub mod state_verdict;
pub mod verdict;
