//! Grading speed: 100,000 CSV rows over the chapter's exercises (right answers, the 4.2 slip,
//! the intended readings, wrong answers with no slip, 8-bit answers and malformed rows), graded
//! and written as the CSV report, on one core. The goal is under 2 s; each exercise is solved
//! once (with its slips), so a row costs a parse and a few comparisons.
//!
//! Run: `cargo bench --bench grade`.

use std::path::PathBuf;

use criterion::{criterion_group, criterion_main, Criterion};
use phong::check::grade::{grade_bytes, rows_csv, Options};

/// `rows` submissions cycling through a mix of answers.
fn submissions(rows: usize) -> Vec<u8> {
    const ANSWERS: [(&str, &str); 10] = [
        ("4.1", "0.5 0.7 0.3"),
        ("4.2", "0.245 0.28 0.21"),
        ("4.2", "\"0.299, 0.361, 0.318\""),
        ("4.2", "0 0 0"),
        ("4.3", "(0.52 0.03 0)"),
        ("4.3", "0.9 0.9 0.9"),
        ("4.1", "#80B34D"),
        ("spot-inside", "0.79 0.95 0.85"),
        ("several-lights", "0.5 0.5 0.5"),
        ("4.1", "not an answer"),
    ];
    let mut csv = String::from("student,exercise,answer\n");
    for i in 0..rows {
        let (exercise, answer) = ANSWERS[i % ANSWERS.len()];
        csv.push_str(&format!("student{i},{exercise},{answer}\n"));
    }
    csv.into_bytes()
}

fn bench(c: &mut Criterion) {
    let csv = submissions(100_000);
    let options = Options {
        exercises: PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("exercises"),
        scale: None,
        delimiter: None,
        ..Options::default()
    };
    let mut group = c.benchmark_group("grade");
    group.sample_size(10);
    group.bench_function("100k rows, graded and written as CSV", |b| {
        b.iter(|| {
            let report = grade_bytes(&csv, &options);
            assert_eq!(report.rows.len(), 100_000);
            rows_csv(&report).len()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
