//! The cost of one shaded point in the core: f32 against f64, with and without the record, for
//! 1, 2, 4 and 8 lights. Run with `cargo bench --bench shade` (about 50 s: 16 benchmarks of 1 s
//! warm-up and 2 s measurement each).

use std::hint::black_box;
use std::time::Duration;

use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion};
use phong::core::real::v3;
use phong::core::{
    shade, AllVisible, Cone, Falloff, Light, LightKind, LightSet, Material, NoRecord, Real,
    ShadingPoint, V3,
};

/// `n` lights, cycling through point (each falloff), directional and spot, all in front of the
/// surface so that every one is lit and shaded in full.
fn lights<R: Real>(n: usize) -> LightSet<R> {
    let lights = (0..n)
        .map(|i| {
            let x = i as f64 * 0.37 - 1.0;
            let kind = match i % 4 {
                0 => LightKind::Point {
                    position: v3::<R>([x, 1.0, 3.0]),
                    falloff: Falloff::Quadratic,
                },
                1 => LightKind::Directional {
                    direction: v3::<R>([0.0, -0.6, -0.8]),
                },
                2 => LightKind::Spot {
                    position: v3::<R>([x, 0.0, 4.0]),
                    falloff: Falloff::Linear,
                    cone: Cone::new(v3::<R>([0.0, 0.0, -1.0]), R::from_f64(60.0), R::TWO),
                },
                _ => LightKind::Point {
                    position: v3::<R>([-x, -1.0, 2.0]),
                    falloff: Falloff::None,
                },
            };
            Light {
                color: v3::<R>([0.5, 0.5, 0.5]),
                kind,
            }
        })
        .collect();
    LightSet {
        ambient: Some(v3::<R>([0.1, 0.1, 0.1])),
        lights,
    }
}

fn material<R: Real>() -> Material<R> {
    Material {
        o_a: Some(v3::<R>([0.5, 0.4, 0.6])),
        o_d: Some(v3::<R>([0.7, 0.8, 0.6])),
        o_s: Some(v3::<R>([0.2, 0.3, 0.4])),
        n_s: R::from_f64(16.0),
        o_r: None,
        transmission: None,
    }
}

fn point<R: Real>() -> ShadingPoint<R> {
    ShadingPoint {
        p: v3::<R>([0.1, 0.2, 0.0]),
        n: v3::<R>([0.0, 0.0, 1.0]),
        v: Some(v3::<R>([0.0, 0.6, -0.8])),
    }
}

/// One precision's two benchmarks (without and with the record) for `n` lights, in `group`.
fn bench_precision<R: Real>(group: &mut BenchmarkGroup<'_, WallTime>, n: usize) {
    let m = material::<R>();
    let at = point::<R>();
    let set = lights::<R>(n);
    group.bench_function(BenchmarkId::new(R::NAME, "no_record"), |b| {
        b.iter(|| -> V3<R> {
            shade(black_box(&at), &m, &set, &mut AllVisible, &mut NoRecord).color
        })
    });
    group.bench_function(BenchmarkId::new(R::NAME, "record"), |b| {
        let mut rec = Vec::with_capacity(n);
        b.iter(|| -> V3<R> {
            rec.clear();
            shade(black_box(&at), &m, &set, &mut AllVisible, &mut rec).color
        })
    });
}

/// For each number of lights, f32 and f64 one after the other, so that both see the same
/// machine (the load of a shared machine drifts over a minute).
fn benches(c: &mut Criterion) {
    for n in [1usize, 2, 4, 8] {
        let mut group = c.benchmark_group(format!("shade/{n} lights"));
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(2));
        bench_precision::<f32>(&mut group, n);
        bench_precision::<f64>(&mut group, n);
        group.finish();
    }
}

criterion_group!(shade_benches, benches);
criterion_main!(shade_benches);
