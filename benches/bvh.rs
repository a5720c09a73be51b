//! The BVH: build time for 100,000 and 1,000,000 sphere boxes, and nearest-hit queries per
//! second on 100,000 spheres, in f32 and f64: the binary tree's own search (`Bvh::nearest`,
//! leaves of 4) against the aggregate's wide search (`Aggregate::nearest`, the binary tree
//! with leaves of one sphere per lane collapsed into nodes of 8 (f32) or 4 (f64) children),
//! and the aggregate's any-hit search (`Aggregate::occluded`, shadow rays to t = 50). Run with
//! `cargo bench --bench bvh`.
//!
//! The spheres (radii 0.5 to 2 for 100,000 of them) take up about 14 % of a cube of side 200;
//! query rays start anywhere in the cube and go in any direction, and 90 % of them hit a
//! sphere after passing many boxes.

use std::hint::black_box;
use std::time::Duration;

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use phong::core::real::v3;
use phong::core::Real;
use phong::geometry::{Aabb, Aggregate, Bvh, Ray, Shape, Sphere};

/// SplitMix64: a seeded, dependency-free source of the same scene on every run.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// `n` spheres in [−100, 100]³, radii scaled with n^(−1/3) so that the filled fraction of the
/// cube stays about 14 %.
fn spheres<R: Real>(n: usize) -> Vec<Sphere<R>> {
    let mut rng = Rng(7);
    let r_max = 2.0 * (100_000.0 / n as f64).cbrt();
    (0..n)
        .map(|_| Sphere {
            center: v3::<R>([0, 1, 2].map(|_| rng.range(-100.0, 100.0))),
            radius: R::from_f64(rng.range(0.25, 1.0) * r_max),
        })
        .collect()
}

fn boxes<R: Real>(s: &[Sphere<R>]) -> Vec<Aabb<R>> {
    s.iter()
        .map(|s| Aabb::of_sphere(s.center, s.radius))
        .collect()
}

fn rays<R: Real>(n: usize) -> Vec<Ray<R>> {
    let mut rng = Rng(11);
    (0..n)
        .map(|_| {
            let d = loop {
                let v = [0, 1, 2].map(|_| rng.range(-1.0, 1.0));
                let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                if l > 1e-3 && l <= 1.0 {
                    break v.map(|x| x / l);
                }
            };
            Ray {
                origin: v3::<R>([0, 1, 2].map(|_| rng.range(-100.0, 100.0))),
                direction: v3::<R>(d),
            }
        })
        .collect()
}

fn build<R: Real>(c: &mut Criterion) {
    let mut g = c.benchmark_group(format!("bvh_build_{}", R::NAME));
    g.sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(8));
    for n in [100_000, 1_000_000] {
        let b = boxes(&spheres::<R>(n));
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &b, |bench, b| {
            bench.iter(|| Bvh::build(black_box(b)))
        });
    }
    g.finish();
}

const QUERIES: usize = 10_000;

fn nearest<R: Real>(c: &mut Criterion) {
    let s = spheres::<R>(100_000);
    let bvh = Bvh::build(&boxes(&s));
    let rays = rays::<R>(QUERIES);
    let inf = R::from_f64(f64::INFINITY);
    let mut g = c.benchmark_group(format!("bvh_nearest_{}", R::NAME));
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .throughput(Throughput::Elements(QUERIES as u64));
    g.bench_function("100000_spheres", |bench| {
        bench.iter(|| {
            let mut hits = 0u32;
            for ray in &rays {
                let hit = bvh.nearest(ray, inf, |p, t_max| {
                    s[p as usize]
                        .intersect_line(ray)
                        .nearest_in_front()
                        .filter(|&t| t < t_max)
                });
                hits += u32::from(hit.is_some());
            }
            black_box(hits)
        })
    });
    let aggregate = Aggregate::new(s.iter().map(|&s| Shape::Sphere(s)).collect());
    g.bench_function("100000_spheres_wide", |bench| {
        bench.iter(|| {
            let hits = rays
                .iter()
                .filter(|ray| aggregate.nearest(ray, inf).is_some())
                .count();
            black_box(hits)
        })
    });
    let shadow = R::from_f64(50.0);
    g.bench_function("100000_spheres_occluded_wide", |bench| {
        bench.iter(|| {
            let hits = rays
                .iter()
                .filter(|ray| aggregate.occluded(ray, shadow))
                .count();
            black_box(hits)
        })
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    build::<f32>(c);
    build::<f64>(c);
    nearest::<f32>(c);
    nearest::<f64>(c);
}

criterion_group!(bvh, benches);
criterion_main!(bvh);
