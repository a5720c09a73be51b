//! One pixel's derivation: the same path the image traced, recorded ray by ray, and each ray's
//! hit solved by the solver ([`crate::solve::solve_ray`]) exactly as `phong solve` solves a ray
//! problem, so a student reads a pixel the way they read an exercise.

use super::camera::CameraRays;
use super::render::{clamped, to_rgb8};
use super::sampler::sample;
use super::trace::{Counts, RayRecord, Scene, Tracer};
use crate::core::{Real, V3};
use crate::problem::{Camera, GivenVector, Invalid, Problem};
use crate::solve::{solve_ray, Solution};

/// The derivation of one pixel.
#[derive(Clone, Debug)]
pub struct PixelExplanation<R: Real> {
    /// The pixel's column, from 0 at the left.
    pub x: u32,
    /// The pixel's row, from 0 at the top.
    pub y: u32,
    /// Each sample of the pixel, with its path.
    pub samples: Vec<SampleExplanation<R>>,
    /// The pixel's 8-bit colour, as in the image.
    pub rgb8: [u8; 3],
    /// How many rays of each kind the pixel's samples traced.
    pub counts: Counts,
}

/// One sample of the pixel: its position in the pixel and its path.
#[derive(Clone, Debug)]
pub struct SampleExplanation<R: Real> {
    /// (sx, sy) in [0, 1)², from the pixel's top-left corner.
    pub position: (f64, f64),
    /// The path's rays, primary first.
    pub rays: Vec<RayExplanation<R>>,
    /// The path's colour, unclamped: Σ factor·local.
    pub color: V3<R>,
}

/// One ray of a path and the solver's solution at its hit.
#[derive(Clone, Debug)]
pub struct RayExplanation<R: Real> {
    /// The ray as the tracer traced it.
    pub record: RayRecord<R>,
    /// The equivalent ray problem solved by the solver (`None` for a miss).
    pub solution: Option<Solution<R>>,
}

/// Explains pixel (x, y) of the problem's image, with the problem's render settings.
pub fn explain_pixel<R: Real>(
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    x: u32,
    y: u32,
) -> Result<PixelExplanation<R>, Invalid> {
    let rays = CameraRays::new(camera);
    let tracer = Tracer { scene, problem };
    let n = problem.render.samples;
    let mut counts = Counts::default();
    let mut samples = Vec::with_capacity(n as usize);
    let mut sum = [0.0f64; 3];
    for i in 0..n {
        let position = sample(i, n);
        let mut records: Vec<RayRecord<R>> = Vec::new();
        let color = tracer.trace(
            rays.ray(x, y, position.0, position.1),
            &mut counts,
            &mut records,
        );
        let c = clamped::<R>(color);
        for k in 0..3 {
            sum[k] += c[k];
        }
        let mut explained = Vec::with_capacity(records.len());
        for record in records {
            let solution = match record.hit {
                None => None,
                Some(_) => {
                    let d = record.ray.direction;
                    let direction = GivenVector {
                        given: d,
                        length: R::ONE,
                        unit: d,
                    };
                    Some(solve_ray(
                        problem,
                        None,
                        &record.ray,
                        &direction,
                        &scene.aggregate,
                    )?)
                }
            };
            explained.push(RayExplanation { record, solution });
        }
        samples.push(SampleExplanation {
            position,
            rays: explained,
            color,
        });
    }
    Ok(PixelExplanation {
        x,
        y,
        samples,
        rgb8: to_rgb8(sum, n),
        counts,
    })
}
