//! shadowcheck-runner library: backends, verdicts, baselines, reporters. The binary is src/main.rs.

pub mod gl;
