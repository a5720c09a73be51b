//! One pixel's derivation: the same path the image traced, recorded ray by ray, and each ray's
//! hit solved by the solver ([`crate::solve::solve_ray`]) exactly as `phong solve` solves a ray
//! problem, so a student reads a pixel the way they read an exercise.

use super::camera::CameraRays;
use super::faults::TracerFault;
use super::render::{clamped, mean, to_rgb8};
use super::sampler::sample;
use super::trace::{Counts, RayRecord, Scene, Tracer};
use crate::core::{Real, Vector, V3};
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
    /// The pixel's colour: the mean of its samples' colours, each clamped to [0, 1].
    pub color: [f64; 3],
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

/// Explains pixel (x, y) of the problem's image, with the problem's render settings: refused,
/// before anything is traced, where its samples could hold more than 2^13 rays in all
/// (`problem::validate::MAX_EXPLAINED_RAYS`).
pub fn explain_pixel<R: Real>(
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    x: u32,
    y: u32,
) -> Result<PixelExplanation<R>, Invalid> {
    crate::problem::validate::check_explanation(problem).map_err(|e| e.at("render"))?;
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
        // Each ray's own colour is finite here (the solver refuses one that overflows); their
        // sum along the path may still overflow.
        if !color.is_finite() {
            return Err(overflowed(problem, &explained));
        }
        let c = clamped::<R>(color);
        for k in 0..3 {
            sum[k] += c[k];
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
        color: mean(sum, n),
        rgb8: to_rgb8(sum, n),
        counts,
    })
}

/// Why a tree's colour Σ factor·local is not finite although each ray's own colour is: the
/// factor, the product of the O_r and O_t on the way to a ray (Eq. 4.17), or its product with
/// that ray's local colour, overflows. Names the surface the ray left from (its parent's hit),
/// as the solver names the light whose term overflows.
fn overflowed<R: Real>(problem: &Problem<R>, rays: &[RayExplanation<R>]) -> Invalid {
    let surfaces = problem.surfaces();
    // The first ray whose contribution factor·local is not finite, and the hit it left from.
    let k = rays
        .iter()
        .position(|r| !(r.record.factor * r.record.local).is_finite())
        .unwrap_or(rays.len().saturating_sub(1));
    let from = rays
        .get(k)
        .and_then(|r| r.record.parent)
        .and_then(|j| rays[j as usize].record.hit)
        .map(|h| &surfaces[h.index]);
    let (field, material) = match from {
        Some(s) => (
            format!("surfaces[{}]", s.source.index),
            s.material
                .name
                .as_deref()
                .map_or(String::new(), |m| format!(" (material \"{m}\")")),
        ),
        None => ("surfaces".to_owned(), String::new()),
    };
    let level = rays.get(k).map_or(1, |r| r.record.level);
    let transmitted = rays
        .get(k)
        .is_some_and(|r| r.record.kind == super::trace::RayKind::Transmission);
    let fault = if transmitted {
        TracerFault::TransmittedOverflows {
            level,
            precision: R::NAME,
            material,
        }
    } else {
        TracerFault::ReflectedOverflows {
            level,
            precision: R::NAME,
            material,
        }
    };
    Invalid::of(field, fault)
}
