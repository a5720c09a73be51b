//! Helpers shared by the tests that need an outside program (pdflatex, chromium).

use std::path::PathBuf;

/// The path of `program` on PATH, if it is installed.
pub fn find(program: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(program))
        .find(|p| p.is_file())
}

/// The program, or: under CI (`CI=true`) a failure, since CI must run the check; elsewhere
/// `None` after printing why the test is skipped.
pub fn require(program: &str, install: &str) -> Option<PathBuf> {
    if let Some(p) = find(program) {
        return Some(p);
    }
    let ci = std::env::var("CI").is_ok_and(|v| v == "true");
    assert!(
        !ci,
        "{program} is not installed, and CI=true requires this check. Fix: {install} \
         (.ci/run does)"
    );
    eprintln!(
        "SKIPPED: {program} is not installed, so this check did not run. To run it: {install}"
    );
    None
}
