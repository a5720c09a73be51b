//! The test files themselves, read as text: what they must do that no build would catch.

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for entry in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                todo.push(path);
            } else if path.extension().is_some_and(|x| x == "rs") {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// Every test runs phong through `tests/support/` (`support::phong()`, `support::phong_std()`,
/// `support::phong_path()` under `support::sh()`), which clears `LC_ALL`, `LC_MESSAGES` and
/// `LANG`: phong's `--lang` defaults to the locale, so a test that builds its own command from
/// the binary's path passes in English and fails under `LANG=pt_BR.UTF-8`. No file outside
/// `tests/support/` names the binary: neither assert_cmd's function for it nor the variable
/// Cargo sets to its path (the two names below).
#[test]
fn only_the_support_module_names_the_phong_binary() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tests = root.join("tests");
    let support = tests.join("support");
    // Split so that this file does not name them itself.
    let names = [concat!("cargo", "_bin"), concat!("CARGO_BIN", "_EXE_")];
    let files = rust_files(&tests);
    assert!(files.len() > 40, "the test files: {files:?}");
    let mut found = Vec::new();
    for file in files.iter().filter(|f| !f.starts_with(&support)) {
        let text = std::fs::read_to_string(file).unwrap();
        for (i, line) in text.lines().enumerate() {
            if names.iter().any(|n| line.contains(n)) {
                let at = file.strip_prefix(root).unwrap().display();
                found.push(format!("{at}:{}: {}", i + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "{} places run phong without clearing the locale; use support::phong() (assert_cmd), \
         support::phong_std() (std::process::Command) or support::phong_path() under \
         support::sh():\n{}",
        found.len(),
        found.join("\n")
    );
}
