//! Mutation testing of the harness: the default fixtures against seeded faults of the soft unit
//! (`shadowcheck mutants`). Being built.
