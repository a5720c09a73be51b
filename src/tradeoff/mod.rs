//! `phong tradeoff`: what each setting of the tracer costs in time and buys in accuracy.
//!
//! A reference image is rendered once (f64, a deep maximum level, minimum weight 0, many samples
//! per pixel). Then every combination of the swept settings (precision, maximum level, minimum
//! weight, samples per pixel) is rendered `runs` times, round-robin, so that every setting sees
//! the same machine load; each gets the median of its times, its rays by kind, and its error
//! against the reference. The images are deterministic, so the errors and ray counts are the same
//! on every run; only the times vary.
//!
//! - [`Sweep`]: the settings to measure, checked ([`Sweep::new`]), and the reference's.
//! - [`errors`]: max absolute error, RMSE, PSNR and the share of 8-bit pixels that differ,
//!   computed on the pixel means before rounding to 8 bits ([`crate::tracer::LinearImage`]).
//! - [`pareto_front`]: the settings no other setting beats in both time and error.
//! - [`fastest_within`]: the answer to "what is the fastest setting within this error budget".
//! - [`report`]: the table (text), JSON and CSV; [`plot`]: error against time as SVG; the
//!   table's and the plot's words in English and Portuguese in [`messages`].

pub(crate) mod messages;
pub(crate) mod plot;
pub(crate) mod report;
pub(crate) mod sweep;

use std::time::Instant;

use serde::Serialize;

use crate::core::{Precision, Real};
use crate::problem::{Camera, Problem};
use crate::tracer::{render_linear_with, Counts, Engine, LinearImage, Scene};

pub use sweep::{ReferenceSettings, Setting, Sweep, MAX_RUNS, MAX_SWEEP_RAYS};

/// An image's error against the reference, over every channel of every pixel.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Errors {
    /// The largest |c − c_ref| of any channel, on the 0–1 scale.
    pub max_abs: f64,
    /// √(mean of (c − c_ref)²) over every channel.
    pub rmse: f64,
    /// 20·log10(1/RMSE) in dB (peak 1); `None` when the images are equal (infinite PSNR).
    pub psnr_db: Option<f64>,
    /// The share (0–1) of pixels whose 8-bit colour differs from the reference's in any channel.
    pub pixels_differ: f64,
}

impl Errors {
    /// The value of one metric (PSNR is not a metric to budget: larger is better).
    pub fn get(&self, metric: Metric) -> f64 {
        match metric {
            Metric::MaxAbs => self.max_abs,
            Metric::Rmse => self.rmse,
            Metric::PixelsDiffer => self.pixels_differ,
        }
    }
}

/// The error a budget and the Pareto front are judged by (`--metric`), each computed by
/// [`errors`].
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    MaxAbs,
    Rmse,
    PixelsDiffer,
}

impl Metric {
    /// Its name in the table's sentences and the plot, in either language.
    pub fn name(self) -> messages::MetricName {
        match self {
            Metric::MaxAbs => messages::MetricName::MaxAbs,
            Metric::Rmse => messages::MetricName::Rmse,
            Metric::PixelsDiffer => messages::MetricName::PixelsDiffer,
        }
    }
}

/// The errors of `image` against `reference` (same size).
pub fn errors(image: &LinearImage, reference: &LinearImage) -> Errors {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "images of one scene"
    );
    let mut max_abs = 0.0f64;
    let mut sum_sq = 0.0f64;
    let mut differ = 0usize;
    for (a, r) in image.rgb.chunks_exact(3).zip(reference.rgb.chunks_exact(3)) {
        let mut pixel_differs = false;
        for k in 0..3 {
            let e = (a[k] - r[k]).abs();
            max_abs = max_abs.max(e);
            sum_sq += e * e;
            pixel_differs |= (a[k] * 255.0).round() != (r[k] * 255.0).round();
        }
        differ += usize::from(pixel_differs);
    }
    let pixels = reference.rgb.len() / 3;
    let rmse = (sum_sq / reference.rgb.len().max(1) as f64).sqrt();
    Errors {
        max_abs,
        rmse,
        psnr_db: (rmse > 0.0).then(|| -20.0 * rmse.log10()),
        pixels_differ: differ as f64 / pixels.max(1) as f64,
    }
}

/// One measured setting.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Measured {
    pub setting: Setting,
    /// Every run's trace time in seconds, in run order.
    pub times_s: Vec<f64>,
    /// Their median.
    pub median_s: f64,
    /// Rays traced by one render.
    pub rays: Counts,
    pub errors: Errors,
    /// For an f32 setting, when f64 is swept too: its error against the f64 image of the same
    /// level, weight and samples, which is the error of the precision alone.
    pub vs_f64: Option<Errors>,
}

/// The reference render.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ReferenceRun {
    pub setting: Setting,
    pub time_s: f64,
    pub rays: Counts,
}

/// Everything `phong tradeoff` measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    pub width: u32,
    pub height: u32,
    pub threads: usize,
    pub runs: u32,
    pub reference: ReferenceRun,
    /// The scene's build time (BVH) per precision swept, in seconds.
    pub build_s: Vec<(Precision, f64)>,
    /// In the sweep's order.
    pub rows: Vec<Measured>,
}

/// The median of some times (the mean of the middle two for an even count).
pub fn median(times: &[f64]) -> f64 {
    let mut t = times.to_vec();
    t.sort_by(f64::total_cmp);
    let n = t.len();
    match n {
        0 => 0.0,
        _ if n % 2 == 1 => t[n / 2],
        _ => (t[n / 2 - 1] + t[n / 2]) / 2.0,
    }
}

/// The scene in one precision, ready to render under any setting.
struct Prepared<R: Real> {
    problem: Problem<R>,
    camera: Camera<R>,
    scene: Scene<R>,
}

impl<R: Real> Prepared<R> {
    fn new(problem: Problem<R>, camera: Camera<R>) -> (Self, f64) {
        let t = Instant::now();
        let scene = Scene::new(&problem);
        let built = t.elapsed().as_secs_f64();
        let prepared = Prepared {
            problem,
            camera,
            scene,
        };
        (prepared, built)
    }

    /// Renders under `setting` (its precision is this one's) by `engine`: the image, the rays,
    /// the seconds.
    fn render(&mut self, engine: Engine, setting: &Setting) -> (LinearImage, Counts, f64) {
        let r = &mut self.problem.render;
        r.max_level = setting.max_level;
        r.min_weight = R::from_f64(setting.min_weight);
        r.samples = setting.samples;
        let t = Instant::now();
        let (p, c, s) = (&self.problem, &self.camera, &self.scene);
        let (image, counts) = render_linear_with(engine, p, c, s, &|| {});
        (image, counts, t.elapsed().as_secs_f64())
    }
}

/// The scene in the precisions a sweep needs (the reference always needs f64).
pub struct Scenes {
    f32: Option<(Problem<f32>, Camera<f32>)>,
    f64: (Problem<f64>, Camera<f64>),
}

impl Scenes {
    /// `f32` is needed only when the sweep has f32.
    pub fn new(f64: (Problem<f64>, Camera<f64>), f32: Option<(Problem<f32>, Camera<f32>)>) -> Self {
        Scenes { f32, f64 }
    }
}

/// Renders the reference, then every setting `sweep.runs` times round-robin, on the current
/// rayon pool (its thread count is reported), every render (the reference too) by `engine`: the
/// engines give the same images and rays, so only the times differ. `progress` is told each
/// render as it starts.
pub fn measure(
    engine: Engine,
    scenes: Scenes,
    sweep: &Sweep,
    progress: &dyn Fn(&Setting),
) -> Outcome {
    let (problem, camera) = scenes.f64;
    let (width, height) = (camera.width, camera.height);
    let (mut p64, built64) = Prepared::new(problem, camera);
    let mut build_s = Vec::new();
    let mut p32 = scenes.f32.map(|(problem, camera)| {
        let (p, built) = Prepared::new(problem, camera);
        build_s.push((Precision::F32, built));
        p
    });
    build_s.push((Precision::F64, built64));

    let ref_setting = sweep.reference.setting();
    progress(&ref_setting);
    let (ref_image, ref_rays, ref_time) = p64.render(engine, &ref_setting);

    let settings = sweep.settings();
    // Renders go twin by twin: the f64 setting, then the f32 one with the same level, weight
    // and samples, which is compared with the f64 image while it is still at hand.
    let mut order: Vec<usize> = (0..settings.len()).collect();
    order.sort_by(|&a, &b| {
        let (sa, sb) = (&settings[a], &settings[b]);
        (sa.max_level, sa.samples)
            .cmp(&(sb.max_level, sb.samples))
            .then(sa.min_weight.total_cmp(&sb.min_weight))
            .then((sa.precision == Precision::F32).cmp(&(sb.precision == Precision::F32)))
    });
    let mut times = vec![Vec::with_capacity(sweep.runs as usize); settings.len()];
    let mut first: Vec<Option<(Counts, Errors, Option<Errors>)>> = vec![None; settings.len()];
    for _ in 0..sweep.runs.max(1) {
        let mut twin: Option<(Setting, LinearImage)> = None;
        for &i in &order {
            let setting = &settings[i];
            progress(setting);
            let (image, rays, secs) = match setting.precision {
                Precision::F64 => p64.render(engine, setting),
                Precision::F32 => p32
                    .as_mut()
                    .expect("the f32 scene is loaded when the sweep has f32")
                    .render(engine, setting),
            };
            times[i].push(secs);
            if first[i].is_some() {
                continue;
            }
            let vs_f64 = match &twin {
                Some((t, f64_image))
                    if setting.precision == Precision::F32
                        && (t.max_level, t.min_weight, t.samples)
                            == (setting.max_level, setting.min_weight, setting.samples) =>
                {
                    Some(errors(&image, f64_image))
                }
                _ => None,
            };
            first[i] = Some((rays, errors(&image, &ref_image), vs_f64));
            if setting.precision == Precision::F64 {
                twin = Some((*setting, image));
            }
        }
    }
    let rows = settings
        .into_iter()
        .zip(times)
        .zip(first)
        .map(|((setting, times_s), first)| {
            let (rays, errors, vs_f64) = first.expect("every setting ran at least once");
            Measured {
                setting,
                median_s: median(&times_s),
                times_s,
                rays,
                errors,
                vs_f64,
            }
        })
        .collect();
    Outcome {
        width,
        height,
        threads: rayon::current_num_threads(),
        runs: sweep.runs.max(1),
        reference: ReferenceRun {
            setting: ref_setting,
            time_s: ref_time,
            rays: ref_rays,
        },
        build_s,
        rows,
    }
}

/// The indices of the rows on the Pareto front of (median time, `metric`): no other row is at
/// least as fast and at least as accurate, and better in one of the two. In the rows' order.
pub fn pareto_front(rows: &[Measured], metric: Metric) -> Vec<usize> {
    let key = |m: &Measured| (m.median_s, m.errors.get(metric));
    (0..rows.len())
        .filter(|&i| {
            let (t, e) = key(&rows[i]);
            !rows.iter().any(|o| {
                let (to, eo) = key(o);
                to <= t && eo <= e && (to < t || eo < e)
            })
        })
        .collect()
}

/// The fastest row whose `metric` is within `budget`, if any.
pub fn fastest_within(rows: &[Measured], metric: Metric, budget: f64) -> Option<usize> {
    (0..rows.len())
        .filter(|&i| rows[i].errors.get(metric) <= budget)
        .min_by(|&a, &b| rows[a].median_s.total_cmp(&rows[b].median_s))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(values: &[f64]) -> LinearImage {
        LinearImage {
            width: (values.len() / 3) as u32,
            height: 1,
            rgb: values.to_vec(),
        }
    }

    #[test]
    fn errors_are_worked_out_by_hand() {
        // Two pixels. Differences: (0.1, 0, 0) and (0, 0, −0.2).
        // max = 0.2; RMSE = √((0.01 + 0.04)/6) = √(1/120) ≈ 0.0912871; PSNR = −20·log10 of it
        // = 10·log10(120) ≈ 20.7918 dB. 8-bit: 0.5 → 128 against 0.6 → 153 differs; 0.3 → 77
        // against 0.1 → 26 differs: both pixels.
        let r = image(&[0.5, 0.2, 0.2, 0.1, 0.1, 0.3]);
        let a = image(&[0.6, 0.2, 0.2, 0.1, 0.1, 0.1]);
        let e = errors(&a, &r);
        approx::assert_abs_diff_eq!(e.max_abs, 0.2, epsilon = 1e-15);
        approx::assert_abs_diff_eq!(e.rmse, (1.0f64 / 120.0).sqrt(), epsilon = 1e-15);
        approx::assert_abs_diff_eq!(e.psnr_db.unwrap(), 10.0 * 120f64.log10(), epsilon = 1e-12);
        assert_eq!(e.pixels_differ, 1.0);
    }

    #[test]
    fn equal_images_have_no_error_and_no_finite_psnr() {
        let r = image(&[0.5, 0.25, 1.0]);
        let e = errors(&r, &r);
        assert_eq!(
            (e.max_abs, e.rmse, e.psnr_db, e.pixels_differ),
            (0.0, 0.0, None, 0.0)
        );
    }

    #[test]
    fn a_difference_below_half_a_level_leaves_the_8_bit_pixel_alone() {
        // 0.5·255 = 127.5 rounds to 128; 0.501·255 = 127.755 also rounds to 128.
        let e = errors(&image(&[0.501, 0.0, 0.0]), &image(&[0.5, 0.0, 0.0]));
        assert_eq!(e.pixels_differ, 0.0);
        assert!(e.max_abs > 0.0);
    }

    fn row(time: f64, err: f64) -> Measured {
        Measured {
            setting: Setting {
                precision: Precision::F64,
                max_level: 1,
                min_weight: 0.0,
                samples: 1,
            },
            times_s: vec![time],
            median_s: time,
            rays: Counts::default(),
            errors: Errors {
                max_abs: err,
                rmse: err,
                psnr_db: None,
                pixels_differ: err,
            },
            vs_f64: None,
        }
    }

    #[test]
    fn the_front_keeps_only_rows_nothing_beats_in_both() {
        // (time, error): 0 (1, 0.5) front; 1 (2, 0.5) beaten by 0; 2 (2, 0.1) front;
        // 3 (3, 0.1) beaten by 2; 4 (4, 0) front; 5 (1, 0.5) ties 0 exactly: both stay.
        let rows = [
            row(1.0, 0.5),
            row(2.0, 0.5),
            row(2.0, 0.1),
            row(3.0, 0.1),
            row(4.0, 0.0),
            row(1.0, 0.5),
        ];
        assert_eq!(pareto_front(&rows, Metric::MaxAbs), vec![0, 2, 4, 5]);
        assert_eq!(fastest_within(&rows, Metric::MaxAbs, 0.1), Some(2));
        assert_eq!(fastest_within(&rows, Metric::Rmse, 0.0), Some(4));
        assert_eq!(fastest_within(&rows, Metric::Rmse, -1.0), None);
    }

    #[test]
    fn the_median_of_even_and_odd_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
    }
}
