//! shadowcheck-runner library: backends, verdicts, baselines, reporters. The binary is src/main.rs.
//!
//! Data flows one way: fixtures → [`run`] (cases to a [`backend::Backend`]) → [`verdict`] (oracle
//! expectation and acceptance) → [`baseline`] (final status) → [`events`] → [`report`]ers.
//! The library never prints; reporters own every byte of output.

pub mod backend;
pub mod baseline;
pub mod bench;
pub mod events;
pub mod mutants;
pub mod parallel;
pub mod report;
pub mod resume;
pub mod run;
pub mod shard;
pub mod verdict;
