//! The integration tests, one test binary with a module per file (issue 31: 40 binaries, each
//! linked against the whole crate, took most of CI's time). A file that needs a process of its
//! own stays a binary of its own: `tests/no_allocation.rs` and `tests/read_allocations.rs`
//! (each installs a counting `#[global_allocator]`), `tests/serve_load.rs` and
//! `tests/serve_one_client.rs` (load tests whose pass depends on the time the server gets),
//! `tests/fuzz.rs` (CI runs it again with 40 rounds) and `tests/errors_pt/`.
//!
//! A test that needs a program from outside Rust (pdflatex, chromium, chromedriver, povray,
//! xmllint, qemu-x86_64) is `#[ignore = "needs …"]`: `cargo test` lists it as ignored, and
//! `cargo test --test integration -- --ignored` (`.ci/run`) runs those tests.

#[path = "../support/mod.rs"]
#[allow(dead_code)]
mod support;

mod bad_input;
mod browser;
mod check;
mod check_fixsteps;
mod ci_script;
// QEMU's user mode and the build for the machine's CPU (.cargo/config.toml) are x86-64 Linux's.
#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
mod cpu;
mod diagnosis;
mod edge_cases;
mod explanations;
mod generate;
mod grade;
mod grade_csv;
mod grade_platforms;
mod hand_calculations;
mod help;
mod latex_compiles;
mod limits;
mod moodle;
mod names;
mod out_of_memory;
mod packets;
mod portuguese;
mod pov_crosscheck;
mod precision;
mod secondary_rays;
mod serve_api;
mod serve_browser;
mod serve_hostile;
mod serve_pages;
mod snapshots;
mod source;
mod stability;
mod test_sources;
mod tracer;
mod tradeoff;
mod transmission;
mod trusted_numbers;
mod vocabulary;
mod xml;
