//! The accuracy of phong's f32 and f64 against an independent 256-bit evaluation of the chapter's
//! model, on a generated suite of point problems (issue 5). Shared by `tests/precision.rs`, which
//! asserts bounds, and `examples/precision.rs`, which prints the table in README.md.

// Each user takes what it needs: the test does not time the core, the example asserts nothing.
#![allow(dead_code)]

pub mod measure;
pub mod reference;
pub mod report;
pub mod suite;
