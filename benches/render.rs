//! The benchmarks that carry issue 17's targets, in one run (`cargo bench --bench render`, about
//! 5 minutes on 2 cores): the classic scene (`scenes/classic.json`) and 100,000 spheres
//! (`scenes/many_spheres.rs`, 100,001 surfaces with the floor), 640×480, maximum level 5, one
//! sample per pixel, f32 and f64. Groups (run one with `cargo bench --bench render -- read/`):
//!
//! - `read/<scene>/<precision>`: the file read, parsed and validated (`problem::load`, what
//!   `phong render --stats` reports as "read and validated"), in objects per second; and the
//!   floor under it, `read/100k-spheres/json-syntax` (serde_json skipping the whole text:
//!   its scanner alone, no numbers converted, nothing built) and `…/parse` (phong's parse
//!   alone, no validation);
//! - `build/<scene>/<precision>`: the BVH (`Scene::new`);
//! - `render/<scene>/<precision>-<engine>/<threads>`: the trace alone, scalar against wide, 1
//!   and 2 threads, in rays per second (primary + reflection + shadow);
//! - `whole/<scene>/<precision>-wide/<threads>`: read + build + trace + the PPM written, in
//!   the process (no start-up, no fsync: `benches/vs_povray.sh` times the real process).
//!
//! At the end the ratios the issue sets targets for are printed from this run's estimates
//! (medians), and written to `target/criterion/targets.md`: read time of 100k objects (≤ 0.08 s),
//! trace 100k / classic (≤ 1.5), whole 100k / classic (≤ 2), f32 / f64 speed (≥ 1.7), two
//! threads / one (≥ 1.9), wide / scalar.

use std::collections::BTreeMap;
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use criterion::{BenchmarkId, Criterion, Throughput};
use phong::core::Real;
use phong::problem::{self, Camera, Problem};
use phong::tracer::output::{encode, ImageFormat};
use phong::tracer::{render_with, Engine, Scene};

#[path = "../scenes/many_spheres.rs"]
mod many_spheres;

const CLASSIC: &str = "classic";
const MANY: &str = "100k-spheres";

/// A scene file: its name in the ids, and its path.
struct SceneFile {
    name: &'static str,
    path: PathBuf,
}

fn load<R: Real>(path: &Path) -> (Problem<R>, Camera<R>) {
    let (_, problem) = problem::load::<R>(path).expect("a valid scene");
    let camera = problem.camera.expect("a camera");
    (problem, camera)
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

fn bench_read(c: &mut Criterion, scenes: &[SceneFile]) {
    for scene in scenes {
        let (p, _) = load::<f64>(&scene.path);
        let mut group = c.benchmark_group(format!("read/{}", scene.name));
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(3));
        group.throughput(Throughput::Elements(p.surfaces().len() as u64));
        group.bench_function("f64", |b| b.iter(|| load::<f64>(black_box(&scene.path))));
        group.bench_function("f32", |b| b.iter(|| load::<f32>(black_box(&scene.path))));
        if scene.name == MANY {
            let text = std::fs::read_to_string(&scene.path).expect("the scene");
            group.bench_function("json-syntax", |b| {
                b.iter(|| serde_json::from_str::<serde::de::IgnoredAny>(black_box(&text)))
            });
            group.bench_function("parse", |b| {
                b.iter(|| problem::parse_str(&scene.path, black_box(&text)).expect("valid"))
            });
        }
        group.finish();
    }
}

fn bench_trace<R: Real>(c: &mut Criterion, scenes: &[SceneFile]) {
    for scene in scenes {
        let (problem, camera) = load::<R>(&scene.path);
        let mut group = c.benchmark_group(format!("build/{}", scene.name));
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(3));
        group.bench_function(R::NAME, |b| b.iter(|| Scene::new(black_box(&problem))));
        group.finish();

        let scene_r = Scene::new(&problem);
        let (_, counts) = render_with(Engine::Scalar, &problem, &camera, &scene_r, &|| {});
        let mut group = c.benchmark_group(format!("render/{}", scene.name));
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(4));
        group.throughput(Throughput::Elements(counts.total()));
        for threads in [1usize, 2] {
            let pool = pool(threads);
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
                            pool.install(|| {
                                render_with(engine, &problem, &camera, &scene_r, &|| {})
                            })
                        })
                    },
                );
            }
        }
        group.finish();
    }
}

/// Read + build + trace + write, as `phong render` does in its process.
fn whole<R: Real>(path: &Path, out: &Path, pool: &rayon::ThreadPool) -> usize {
    let (problem, camera) = load::<R>(path);
    let scene = pool.install(|| Scene::new(&problem));
    let (image, _) = pool.install(|| render_with(Engine::Wide, &problem, &camera, &scene, &|| {}));
    let bytes = encode(&image, ImageFormat::Ppm);
    std::fs::write(out, &bytes).expect("the image is written");
    bytes.len()
}

fn bench_whole<R: Real>(c: &mut Criterion, scenes: &[SceneFile], dir: &Path) {
    for scene in scenes {
        let mut group = c.benchmark_group(format!("whole/{}", scene.name));
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.measurement_time(Duration::from_secs(5));
        let out = dir.join(format!("{}.ppm", scene.name));
        for threads in [1usize, 2] {
            let pool = pool(threads);
            group.bench_with_input(
                BenchmarkId::new(format!("{}-wide", R::NAME), format!("{threads} thread(s)")),
                &threads,
                |b, _| b.iter(|| whole::<R>(&scene.path, &out, &pool)),
            );
        }
        group.finish();
    }
}

fn main() {
    let started = SystemTime::now();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let many = dir.path().join("many_spheres.json");
    std::fs::write(&many, many_spheres::scene(100_000).to_string()).expect("the scene");
    let scenes = [
        SceneFile {
            name: CLASSIC,
            path: Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/classic.json"),
        },
        SceneFile {
            name: MANY,
            path: many,
        },
    ];
    let output = criterion_home();
    let mut c = Criterion::default()
        .output_directory(&output)
        .configure_from_args();
    bench_read(&mut c, &scenes);
    bench_trace::<f32>(&mut c, &scenes);
    bench_trace::<f64>(&mut c, &scenes);
    bench_whole::<f32>(&mut c, &scenes, dir.path());
    bench_whole::<f64>(&mut c, &scenes, dir.path());
    c.final_summary();
    targets::report(&output, started);
}

/// Where criterion writes its estimates (its own default, set explicitly so the summary knows).
fn criterion_home() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return home.into();
    }
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
        PathBuf::from,
    );
    target.join("criterion")
}

/// The ratios of issue 17's targets, from the estimates criterion wrote in this run.
mod targets {
    use super::*;

    /// Every benchmark's median (seconds) by its id, from the `new/` estimates written since
    /// `since`.
    fn medians(dir: &Path, since: SystemTime, out: &mut BTreeMap<String, f64>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if !path.is_dir() {
                continue;
            }
            let (bench, estimates) = (path.join("benchmark.json"), path.join("estimates.json"));
            let fresh = std::fs::metadata(&estimates)
                .and_then(|m| m.modified())
                .is_ok_and(|t| t >= since);
            if path.file_name().is_some_and(|n| n == "new") && fresh {
                let read = |p: &Path| -> Option<serde_json::Value> {
                    serde_json::from_str(&std::fs::read_to_string(p).ok()?).ok()
                };
                if let (Some(b), Some(e)) = (read(&bench), read(&estimates)) {
                    if let (Some(id), Some(ns)) = (
                        b["full_id"].as_str(),
                        e["median"]["point_estimate"].as_f64(),
                    ) {
                        out.insert(id.to_owned(), ns * 1e-9);
                    }
                }
            } else {
                medians(&path, since, out);
            }
        }
    }

    pub(super) fn report(dir: &Path, since: SystemTime) {
        let mut m = BTreeMap::new();
        medians(dir, since, &mut m);
        if m.is_empty() {
            return;
        }
        let mut lines = vec![
            "| target | measured | goal |".to_owned(),
            "|---|---:|---|".to_owned(),
        ];
        let mut row = |what: String, value: Option<f64>, unit: &str, goal: &str| {
            if let Some(v) = value {
                lines.push(format!("| {what} | {v:.3}{unit} | {goal} |"));
            }
        };
        let get = |id: String| m.get(&id).copied();
        let ratio = |a: Option<f64>, b: Option<f64>| Some(a? / b?);
        for p in ["f64", "f32"] {
            row(
                format!("read and validate 100,001 objects, {p}"),
                get(format!("read/{MANY}/{p}")),
                " s",
                "≤ 0.08 s",
            );
        }
        row(
            "… of which serde_json's scanner alone (the floor)".to_owned(),
            get(format!("read/{MANY}/json-syntax")),
            " s",
            "",
        );
        row(
            "… of which the parse alone".to_owned(),
            get(format!("read/{MANY}/parse")),
            " s",
            "",
        );
        let trace = |scene: &str, p: &str, e: &str, t: u32| {
            get(format!("render/{scene}/{p}-{e}/{t} thread(s)"))
        };
        for p in ["f64", "f32"] {
            for e in ["wide", "scalar"] {
                for t in [1, 2] {
                    row(
                        format!("trace 100k / classic, {p} {e}, {t} thread(s)"),
                        ratio(trace(MANY, p, e, t), trace(CLASSIC, p, e, t)),
                        "×",
                        "≤ 1.5×",
                    );
                }
            }
        }
        for p in ["f64", "f32"] {
            for t in [1, 2] {
                let whole = |scene: &str| get(format!("whole/{scene}/{p}-wide/{t} thread(s)"));
                row(
                    format!("whole 100k / classic, {p} wide, {t} thread(s)"),
                    ratio(whole(MANY), whole(CLASSIC)),
                    "×",
                    "≤ 2×",
                );
            }
        }
        for e in ["wide", "scalar"] {
            for t in [1, 2] {
                row(
                    format!("f32 speed / f64 speed, classic, {e}, {t} thread(s)"),
                    ratio(trace(CLASSIC, "f64", e, t), trace(CLASSIC, "f32", e, t)),
                    "×",
                    "≥ 1.7×",
                );
            }
        }
        for p in ["f64", "f32"] {
            for e in ["wide", "scalar"] {
                row(
                    format!("2 threads / 1 thread speed, classic, {p} {e}"),
                    ratio(trace(CLASSIC, p, e, 1), trace(CLASSIC, p, e, 2)),
                    "×",
                    "≥ 1.9×",
                );
            }
        }
        for scene in [CLASSIC, MANY] {
            for p in ["f64", "f32"] {
                row(
                    format!("wide speed / scalar speed, {scene}, {p}, 1 thread"),
                    ratio(trace(scene, p, "scalar", 1), trace(scene, p, "wide", 1)),
                    "×",
                    "",
                );
            }
        }
        let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
        let text = format!(
            "Issue 17's targets, from this run's medians (load average {}):\n\n{}\n",
            load.split_whitespace()
                .take(3)
                .collect::<Vec<_>>()
                .join(" "),
            lines.join("\n")
        );
        println!("\n{text}");
        let _ = std::fs::write(dir.join("targets.md"), text);
    }
}
