//! The tracer on whole images: the classic scene and 100,000 spheres, f32 and f64, the scalar
//! and the wide engine, 1 and 2 threads, 640×480, maximum level 5, one sample per pixel.
//! Criterion reports rays per second (primary + reflection + shadow rays), one id per
//! `render/<scene>/<precision>-<engine>/<threads>`. Run with `cargo bench --bench render`.
//!
//! The BVH build is measured apart (`build/…`), so `render/…` is the trace alone.

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong::core::Real;
use phong::problem::{self, validate, Problem};
use phong::tracer::{render_with, Engine, Scene};

#[path = "../scenes/many_spheres.rs"]
mod many_spheres;

fn load<R: Real>(name: &str, json: &str) -> Problem<R> {
    let file = problem::parse_str(Path::new(name), json).expect("a valid scene");
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    validate::validate_in::<R>(&file, Some(&base)).expect("a valid scene")
}

fn bench_precision<R: Real>(c: &mut Criterion, scenes: &[(&str, String)]) {
    for (name, json) in scenes {
        let problem = load::<R>(name, json);
        let camera = problem.camera.expect("a camera");
        let mut group = c.benchmark_group(format!("build/{name}"));
        group.sample_size(10);
        group.bench_function(R::NAME, |b| b.iter(|| Scene::new(black_box(&problem))));
        group.finish();

        let scene = Scene::new(&problem);
        let (_, counts) = render_with(Engine::Scalar, &problem, &camera, &scene, &|| {});
        let mut group = c.benchmark_group(format!("render/{name}"));
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(5));
        group.throughput(Throughput::Elements(counts.total()));
        for threads in [1usize, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            // The engines side by side, alternating, so a load on the machine hits both.
            for engine in [Engine::Scalar, Engine::Wide] {
                group.bench_with_input(
                    BenchmarkId::new(
                        format!("{}-{}", R::NAME, engine.name()),
                        format!("{threads} thread(s)"),
                    ),
                    &threads,
                    |b, _| {
                        b.iter(|| {
                            pool.install(|| render_with(engine, &problem, &camera, &scene, &|| {}))
                        })
                    },
                );
            }
        }
        group.finish();
    }
}

fn benches(c: &mut Criterion) {
    let classic =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/classic.json"))
            .expect("scenes/classic.json");
    let scenes = [
        ("classic", classic),
        ("100k-spheres", many_spheres::scene(100_000).to_string()),
    ];
    bench_precision::<f32>(c, &scenes);
    bench_precision::<f64>(c, &scenes);
}

criterion_group!(render_benches, benches);
criterion_main!(render_benches);
