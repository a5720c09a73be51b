//! Helpers shared by the tests: `phong()`, the command every test runs phong by (and
//! `phong_std()`, `phong_path()` and `sh()` for the few that need a `std::process::Command`);
//! the outside programs (pdflatex, chromium, povray, xmllint) a test needs; and, as modules, the
//! HTTP client, the `phong serve` process and the screenshot reader. `tests/integration/`,
//! `tests/errors_pt/` and `tests/fuzz.rs` declare it once (`#[path = "../support/mod.rs"] mod
//! support;`, from fuzz.rs `"support/mod.rs"`); `tests/serve_load.rs` and
//! `tests/serve_one_client.rs` include the files they need.
//! No test file outside this folder names the binary (`tests/integration/test_sources.rs`).

pub mod http;
pub mod screenshot;
pub mod server;

use std::path::PathBuf;

use assert_cmd::Command;

/// The variables phong's `--lang` defaults from (`src/text/lang.rs`), cleared in every run.
const LOCALE: [&str; 3] = ["LC_ALL", "LC_MESSAGES", "LANG"];

/// `phong`, the binary this package builds, run from the package's root and with the locale
/// variables (`LC_ALL`, `LC_MESSAGES`, `LANG`) cleared, so that its language is English unless
/// a test gives `--lang` or sets one of them, whatever the caller's locale.
pub fn phong() -> Command {
    let mut c = Command::new(phong_path());
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    for var in LOCALE {
        c.env_remove(var);
    }
    c
}

/// [`phong()`] as a `std::process::Command`, for a test that spawns phong and holds the child
/// (a closed pipe, a signal) or runs it in a loop without assert_cmd.
pub fn phong_std() -> std::process::Command {
    without_locale(phong_path())
}

/// `sh`, from the package's root and with the locale variables cleared, for a test that runs
/// phong under a shell (a `ulimit`, a `umask`, a pipe): give it [`phong_path()`] as an argument
/// or a variable, and phong inherits the cleared locale.
pub fn sh() -> std::process::Command {
    without_locale("sh")
}

/// The path of the phong binary, only for running it through [`sh()`]: to run it directly, use
/// [`phong()`] or [`phong_std()`].
pub fn phong_path() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_phong"))
}

fn without_locale(program: impl AsRef<std::ffi::OsStr>) -> std::process::Command {
    let mut c = std::process::Command::new(program);
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    for var in LOCALE {
        c.env_remove(var);
    }
    c
}

/// The path of `program` on PATH, if it is installed.
pub fn find(program: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(program))
        .find(|p| p.is_file())
}

/// The program a test needs. Such a test is `#[ignore = "needs PROGRAM: …"]`, so it runs only
/// when asked for (`cargo test --test integration -- --ignored`, as `.ci/run` does): a missing
/// program is then a failure naming the fix, never a pass. (Always `Some`: the `Option` keeps
/// the call sites written when a missing program was a skip.)
pub fn require(program: &str, install: &str) -> Option<PathBuf> {
    let found = find(program);
    assert!(
        found.is_some(),
        "{program} is not installed, and this test needs it. Fix: {install} (.ci/run does), or \
         run `cargo test` without --ignored, which lists this test as ignored"
    );
    found
}

/// `xml` is well formed for roxmltree, a parser in Rust that applies XML 1.0's `Char` rule;
/// `what` names the document in a failure. `xml.rs` and `moodle.rs` check each document so, and
/// again with [`xmllint_well_formed`] in tests of their own.
pub fn roxmltree_well_formed(xml: &str, what: &str) {
    if let Err(e) = roxmltree::Document::parse(xml) {
        panic!("{what} is not well-formed XML: {e}");
    }
}

/// `xml` is valid against the XML Schema `xsd` for `xmllint --schema`; `what` names the
/// document in a failure. Only in a test `#[ignore = "needs xmllint: apt-get install
/// libxml2-utils"]`: a missing xmllint fails it.
pub fn xmllint_schema_valid(xml: &str, xsd: &std::path::Path, what: &str) {
    xmllint(xml, &["--schema".as_ref(), xsd.as_os_str()], what);
}

/// `xml` is well formed for xmllint (`xmllint --noout`), a second parser after
/// [`roxmltree_well_formed`]; `what` names the document in a failure. Only in a test
/// `#[ignore = "needs xmllint: apt-get install libxml2-utils"]`: a missing xmllint fails it.
pub fn xmllint_well_formed(xml: &str, what: &str) {
    xmllint(xml, &[], what);
}

/// `xmllint --noout ARGS FILE` accepts `xml` written to FILE.
fn xmllint(xml: &str, args: &[&std::ffi::OsStr], what: &str) {
    let Some(lint) = require("xmllint", "apt-get install libxml2-utils") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("doc.xml");
    std::fs::write(&path, xml).unwrap();
    let out = std::process::Command::new(lint)
        .arg("--noout")
        .args(args)
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "xmllint refuses {what}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}
