//! The image: every pixel's samples traced and averaged, rows in parallel (rayon). Each row is
//! computed by itself and the rows are gathered by index, so the bytes never depend on the
//! number of threads or on which thread did what.

use rayon::prelude::*;

use super::camera::CameraRays;
use super::sampler::sample;
use super::trace::{Counts, Scene, Tracer};
use super::wide::{self, Engine};
use crate::core::color::{clamp01, rgb8};
use crate::core::real::to_f64_array;
use crate::core::{Real, V3};
use crate::problem::{Camera, Problem};

/// An 8-bit RGB image, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Its width in pixels.
    pub width: u32,
    /// Its height in pixels.
    pub height: u32,
    /// width × height × 3 bytes.
    pub rgb: Vec<u8>,
}

/// A pixel's value: the mean of its samples, each clamped to [0, 1] (what the chapter would
/// display for that ray), then round(255·c), as the solver's 8-bit colour.
#[inline]
pub(crate) fn to_rgb8(sum: [f64; 3], samples: u32) -> [u8; 3] {
    rgb8(mean(sum, samples))
}

/// The mean of `samples` summed values.
#[inline]
pub(crate) fn mean(sum: [f64; 3], samples: u32) -> [f64; 3] {
    sum.map(|c| c / f64::from(samples))
}

/// A colour clamped to [0, 1] and widened, to be summed over samples.
#[inline]
pub(crate) fn clamped<R: Real>(c: V3<R>) -> [f64; 3] {
    to_f64_array::<R>(clamp01::<R>(c))
}

/// The mean of pixel (x, y)'s samples, each clamped to [0, 1] (before rounding to 8 bits).
#[inline]
pub(crate) fn pixel_mean<R: Real>(
    tracer: &Tracer<R>,
    camera: &CameraRays<R>,
    x: u32,
    y: u32,
    counts: &mut Counts,
) -> [f64; 3] {
    let n = tracer.problem.render.samples;
    let mut sum = [0.0f64; 3];
    for i in 0..n {
        let (sx, sy) = sample(i, n);
        let c = clamped::<R>(tracer.trace(camera.ray(x, y, sx, sy), counts, &mut ()));
        for k in 0..3 {
            sum[k] += c[k];
        }
    }
    mean(sum, n)
}

/// An image of pixel means in [0, 1] (before rounding to 8 bits), rows top to bottom: what
/// `phong tradeoff` compares.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LinearImage {
    pub width: u32,
    pub height: u32,
    /// width × height × 3 values.
    pub rgb: Vec<f64>,
}

/// Every pixel mapped by `each` from its mean, rows in parallel and gathered by index; the
/// rows traced by `engine` (the same means either way).
fn render_rows<R: Real, T: Copy + Send>(
    engine: Engine,
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    progress: &(dyn Fn() + Sync),
    each: impl Fn([f64; 3]) -> [T; 3] + Sync,
) -> (Vec<T>, Counts) {
    let rays = CameraRays::new(camera);
    let tracer = Tracer { scene, problem };
    let width = camera.width;
    let plan = match engine {
        Engine::Scalar => None,
        Engine::Wide => Some(wide::Plan::new(scene, problem)),
    };
    let rows: Vec<(Vec<T>, Counts)> = (0..camera.height)
        .into_par_iter()
        .map(|y| {
            let mut counts = Counts::default();
            let mut row = Vec::with_capacity(width as usize * 3);
            match &plan {
                None => {
                    for x in 0..width {
                        row.extend_from_slice(&each(pixel_mean(&tracer, &rays, x, y, &mut counts)));
                    }
                }
                Some(plan) => wide::row(&tracer, plan, &rays, y, &mut counts, &each, &mut row),
            }
            progress();
            (row, counts)
        })
        .collect();
    let mut counts = Counts::default();
    let mut all = Vec::with_capacity(width as usize * camera.height as usize * 3);
    for (row, c) in rows {
        all.extend_from_slice(&row);
        counts += c;
    }
    (all, counts)
}

/// Renders the image with the problem's render settings and the default [`Engine`]. `progress`
/// is called once per finished row (from any thread).
pub fn render<R: Real>(
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    progress: &(dyn Fn() + Sync),
) -> (Image, Counts) {
    render_with(Engine::default(), problem, camera, scene, progress)
}

/// [`render`] by the given engine (the same image by either).
pub fn render_with<R: Real>(
    engine: Engine,
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    progress: &(dyn Fn() + Sync),
) -> (Image, Counts) {
    let (rgb, counts) = render_rows(engine, problem, camera, scene, progress, rgb8);
    let image = Image {
        width: camera.width,
        height: camera.height,
        rgb,
    };
    (image, counts)
}

/// Renders the pixel means, before rounding to 8 bits (`render` is this, rounded), by the given
/// engine (the same means by either).
pub(crate) fn render_linear_with<R: Real>(
    engine: Engine,
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    progress: &(dyn Fn() + Sync),
) -> (LinearImage, Counts) {
    let (rgb, counts) = render_rows(engine, problem, camera, scene, progress, |m| m);
    let image = LinearImage {
        width: camera.width,
        height: camera.height,
        rgb,
    };
    (image, counts)
}
