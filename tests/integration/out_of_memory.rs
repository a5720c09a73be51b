//! When the system refuses memory, `phong grade` ends with its clear error (exit 2, in the run's
//! language) and writes nothing half: the report it was to replace is left as it was and no
//! temporary file stays behind. Never Rust's abort ("memory allocation of N bytes failed", exit
//! 134). Issue 30, item 1's last point.
//!
//! Run under `sh -c 'ulimit -v KB; exec phong …'`. The memory a run needs depends on the build
//! (debug or release, the libraries mapped), so the limits are found, not assumed: the smallest
//! limit (in 2 MiB steps) under which a one-row file is graded is the program's own; then a
//! class of 300,000 rows is graded under that limit plus 2, 4, 6, … MiB until it succeeds.
//! Every run below that must end with exit 2 and the error (the rows and the report need more
//! than the one-row file: the text alone is 1.8 MB, each row's place 24 bytes), and at least
//! one must.

#![cfg(target_os = "linux")]

use crate::support;

use std::path::Path;

/// `phong grade INPUT --exercises exercises -o OUT ARGS…` under `ulimit -v` of `mib` MiB:
/// (exit code, standard error). `None` for the code when a signal ended it.
fn grade_under(mib: u64, input: &Path, out: &Path, args: &[&str]) -> (Option<i32>, String) {
    let output = support::sh()
        .arg("-c")
        .arg(format!("ulimit -v {}; exec \"$0\" \"$@\"", mib * 1024))
        .arg(support::phong_path())
        .arg("grade")
        .arg(input)
        .arg("--exercises")
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/exercises"))
        .arg("-o")
        .arg(out)
        .args(args)
        .output()
        .unwrap();
    (
        output.status.code(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn refused_memory_is_a_clear_error_and_nothing_half_written() {
    let dir = tempfile::tempdir().unwrap();
    let tiny = dir.path().join("tiny.csv");
    std::fs::write(&tiny, "student,exercise,answer\ns,x,1\n").unwrap();
    // The cheapest row to grade: an exercise the folder does not have.
    let class = dir.path().join("class.csv");
    let mut text = String::from("student,exercise,answer\n");
    text.push_str(&"s,x,1\n".repeat(300_000));
    std::fs::write(&class, text).unwrap();
    let out = dir.path().join("report.json");

    // The program's own need: the smallest limit under which one row is graded.
    let own = (8..=256)
        .map(|k| 2 * k)
        .find(|&mib| {
            std::fs::write(&out, "old").unwrap();
            grade_under(mib, &tiny, &out, &[]).0 == Some(0)
        })
        .expect("one row is graded within 512 MiB");

    let mut refused = 0;
    let mut step = 0;
    loop {
        step += 1;
        assert!(
            step <= 200,
            "300,000 rows were not graded within {own} + 400 MiB"
        );
        let mib = own + 2 * step;
        std::fs::write(&out, "old").unwrap();
        let lang = if step % 2 == 0 { "pt" } else { "en" };
        let (code, err) = grade_under(mib, &class, &out, &["--format", "json", "--lang", lang]);
        match code {
            Some(0) => break,
            Some(2) => {
                refused += 1;
                let said = match lang {
                    "en" => "error: out of memory: the system refused ",
                    _ => "erro: memória insuficiente: o sistema recusou mais ",
                };
                assert!(err.starts_with(said), "under {mib} MiB: {err}");
                assert!(err.contains("ulimit -v"), "under {mib} MiB: {err}");
                assert_eq!(err.lines().count(), 1, "under {mib} MiB: {err}");
                // Nothing half written: the old report is as it was, and no temporary file.
                assert_eq!(
                    std::fs::read_to_string(&out).unwrap(),
                    "old",
                    "under {mib} MiB"
                );
                assert_eq!(
                    names(dir.path()),
                    ["class.csv", "report.json", "tiny.csv"],
                    "under {mib} MiB"
                );
            }
            other => panic!("under {mib} MiB: exit {other:?} (a signal when None): {err}"),
        }
    }
    eprintln!(
        "out_of_memory: one row graded from {own} MiB; 300,000 rows refused with exit 2 under \
         {refused} limits, graded from {} MiB",
        own + 2 * step
    );
    assert!(refused > 0, "no limit refused memory");
}
