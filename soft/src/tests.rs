//! End-to-end tests of the unit (case in, RGBA out); expected values hand-computed from the specs.
