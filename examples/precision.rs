//! Prints README's "Accuracy of f32 and f64" tables: the error of phong's f32 and f64 against an
//! independent 256-bit evaluation of the chapter's model (tests/precision/), on the generated
//! suite of ordinary problems and every extreme of issue 5, and the time the core takes per
//! shaded point in each precision, side by side in the same run.
//!
//! Run with `cargo run --release --example precision` (about 20 s).

#[path = "../tests/precision/mod.rs"]
mod precision;

use std::hint::black_box;
use std::time::{Duration, Instant};

use phong::core::{shade, AllVisible, NoRecord, Real, Vector};
use precision::measure::{measure, prepare, Prepared};
use precision::reference::Reference;
use precision::report::{accuracy_table, details, intermediates_table, summarize};
use precision::suite::{suite, Case, GROUPS};

/// Shades every point once; the colours are summed so that nothing is optimised away.
fn pass<R: Real>(points: &[Prepared<R>]) -> f64 {
    let mut sum = 0.0;
    for p in points {
        let s = shade(
            black_box(&p.at),
            &p.material,
            &p.lights,
            &mut AllVisible,
            &mut NoRecord,
        );
        sum += s.color.to_array()[0].to_f64();
    }
    sum
}

/// One sample: `iters` passes, in nanoseconds per shaded point.
fn sample<R: Real>(points: &[Prepared<R>], iters: u32) -> f64 {
    let t = Instant::now();
    for _ in 0..iters {
        black_box(pass(points));
    }
    t.elapsed().as_nanos() as f64 / (iters as f64 * points.len() as f64)
}

/// Passes per sample so that one sample lasts about 5 ms.
fn iterations<R: Real>(points: &[Prepared<R>]) -> u32 {
    let t = Instant::now();
    let mut n = 0u32;
    while t.elapsed() < Duration::from_millis(5) {
        black_box(pass(points));
        n += 1;
    }
    n.max(1)
}

/// The fastest of 41 samples, taken alternately for f64 and f32, in ns per shade, on the points
/// both accept (so that both shade the same points); f64 alone where f32 refuses them all. The
/// fastest sample is the one least disturbed by other work on the machine; a median moves with
/// the machine's load.
fn fastest(xs: &[f64]) -> f64 {
    xs.iter().copied().fold(f64::INFINITY, f64::min)
}

struct Timing {
    points: usize,
    lights_per_point: f64,
    f64: f64,
    f32: Option<f64>,
}

fn time(cases: &[&Case]) -> Option<Timing> {
    let both: Vec<(Prepared<f64>, Prepared<f32>)> = cases
        .iter()
        .filter_map(|c| Some((prepare::<f64>(c).ok()?, prepare::<f32>(c).ok()?)))
        .collect();
    let lights = |p: &[Prepared<f64>]| {
        p.iter().map(|q| q.lights.lights.len()).sum::<usize>() as f64 / p.len() as f64
    };
    if both.is_empty() {
        let p64: Vec<_> = cases
            .iter()
            .filter_map(|c| prepare::<f64>(c).ok())
            .collect();
        if p64.is_empty() {
            return None;
        }
        let i = iterations(&p64);
        let t: Vec<f64> = (0..41).map(|_| sample(&p64, i)).collect();
        return Some(Timing {
            points: p64.len(),
            lights_per_point: lights(&p64),
            f64: fastest(&t),
            f32: None,
        });
    }
    let (p64, p32): (Vec<_>, Vec<_>) = both.into_iter().unzip();
    let (i64_, i32_) = (iterations(&p64), iterations(&p32));
    let (mut s64, mut s32) = (Vec::new(), Vec::new());
    for _ in 0..41 {
        s64.push(sample(&p64, i64_));
        s32.push(sample(&p32, i32_));
    }
    Some(Timing {
        points: p64.len(),
        lights_per_point: lights(&p64),
        f64: fastest(&s64),
        f32: Some(fastest(&s32)),
    })
}

fn main() {
    let cases = suite();
    let t = Instant::now();
    let mut reference = Reference::default();
    let results: Vec<_> = cases.iter().map(|c| measure(c, &mut reference)).collect();
    let measured = t.elapsed();
    let groups = summarize(&results);

    println!("## Error against the 256-bit reference\n");
    println!("{}", accuracy_table(&groups));
    println!("## Intermediates (max over each group, where the gates agree)\n");
    println!("{}", intermediates_table(&groups));
    println!("## Gates decided unlike the exact decision, and refusals\n");
    println!("{}", details(&groups));

    println!("## Time per shaded point in the core (core::shade, no record), fastest of 41 samples of 5 ms\n");
    println!("| case group | points | lights per point | f64 ns | f32 ns | f32/f64 |");
    println!("|---|---:|---:|---:|---:|---:|");
    let row = |title: &str, members: Vec<&Case>| match time(&members) {
        Some(t) => println!(
            "| {title} | {} | {:.1} | {:.1} | {} | {} |",
            t.points,
            t.lights_per_point,
            t.f64,
            t.f32.map_or("refused".into(), |x| format!("{x:.1}")),
            t.f32.map_or("–".into(), |x| format!("{:.2}", x / t.f64)),
        ),
        None => println!("| {title} | 0 | – | – | – | – |"),
    };
    for (key, title) in GROUPS {
        row(title, cases.iter().filter(|c| c.group == *key).collect());
    }
    row("**whole suite**", cases.iter().collect());
    println!(
        "\n{} cases measured against the reference in {:.1} s. Times: {} on this machine \
         ({} logical CPUs); noisy where other work runs.",
        cases.len(),
        measured.as_secs_f64(),
        std::env::consts::ARCH,
        std::thread::available_parallelism().map_or(0, |n| n.get())
    );
}
