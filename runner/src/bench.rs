//! Throughput measurement behind `shadowcheck bench` (being built).
