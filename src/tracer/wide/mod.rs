//! The wide tracer: the same paths as [`Tracer::trace`], traced a packet at a time.
//!
//! A row's samples are taken in blocks of [`BLOCK`] (a strip of neighbouring pixels, so the
//! primary rays of a packet are coherent). Each block keeps a queue of live paths per bounce
//! (a wavefront): the queue's rays are intersected [`Wide::LANES`] at a time against a
//! [`FlatScene`] (8 rays per instruction in f32, 4 in f64), each hit is stepped by the scalar
//! tracer's own [`Tracer::bounce`] (the core's [`crate::core::shade`] with the shadow rays, the
//! stop rules, the reflection ray), and the rays it spawns form the next bounce's queue. A hit
//! may push more than one child (refraction is planned): each queue entry carries the sample
//! it adds to and its own factor, so a ray tree fits the same queues.
//!
//! The shares of a sample are added in bounce order, as [`Tracer::trace`] adds them, and a
//! pixel's samples in sample order, as [`super::render::pixel_mean`] does; the packet
//! intersection is the aggregate's to the bit ([`FlatScene`]). So the image is the scalar
//! tracer's, byte for byte, in both precisions (src/tracer/wide/tests.rs). Scenes the packets do not cover
//! (more than a handful of spheres, which the aggregate puts in a BVH, or triangles) take the
//! same queues with the aggregate's scalar intersection.

use super::camera::CameraRays;
use super::render::{clamped, mean};
use super::sampler::sample;
use super::trace::{CountedVisibility, Counts, PathState, Tracer};
use crate::core::lanes::Wide;
use crate::core::{Arrival, Light, Real, Vector, Visibility, V3};
use crate::geometry::shadow::ShadowRays;
use crate::geometry::soa::FlatScene;
use crate::geometry::{AggregateHit, SurfaceHit};

/// Samples traced together: a strip of a row (one sample per pixel: 64 pixels).
pub const BLOCK: usize = 64;

/// Which tracer renders an image: the same image either way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Engine {
    /// One ray at a time ([`Tracer::trace`]).
    Scalar,
    /// Packets of rays in lanes, queues per bounce (this module); the default.
    #[default]
    Wide,
}

impl Engine {
    /// "scalar" or "wide", as `--engine` writes it.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Scalar => "scalar",
            Engine::Wide => "wide",
        }
    }
}

/// A live path in a bounce's queue: the sample it adds to and where it stands.
#[derive(Clone, Copy, Debug)]
struct Entry<R: Real> {
    /// The sample's place in its block.
    slot: u32,
    path: PathState<R>,
}

/// Shadow rays from a hit as [`ShadowRays`] makes them, each tested against the flat scene's
/// spheres in lanes ([`FlatScene::occluded`]: the aggregate's answer).
pub(crate) struct FlatShadowRays<'a, R: Real> {
    rays: ShadowRays<'a, R>,
    flat: &'a FlatScene<R>,
}

impl<R: Real> Visibility<R> for FlatShadowRays<'_, R> {
    #[inline]
    fn visible(&mut self, p: V3<R>, light: &Light<R>, arrival: &Arrival<R>) -> bool {
        debug_assert!(p == self.rays.from.p);
        self.rays.traced += 1;
        match self.rays.ray(light, arrival.l) {
            Some(s) => !self.flat.occluded(&s.ray, s.t_max),
            None => true,
        }
    }
}

impl<R: Real> CountedVisibility<R> for FlatShadowRays<'_, R> {
    #[inline]
    fn traced(&self) -> u64 {
        self.rays.traced
    }
}

/// The queues and buffers of one row, allocated once per row and reused by its blocks.
struct Buffers<R: Real> {
    queue: Vec<Entry<R>>,
    next: Vec<Entry<R>>,
    colors: Vec<V3<R>>,
    hits: Vec<Option<AggregateHit<R>>>,
    rays: Vec<crate::geometry::Ray<R>>,
}

/// Pixel means of row `y`, each mapped by `each` and appended to `out`: the row
/// [`super::render::pixel_mean`] gives pixel by pixel, traced in packets.
pub(crate) fn row<R: Real, T: Copy>(
    tracer: &Tracer<R>,
    flat: Option<&FlatScene<R>>,
    camera: &CameraRays<R>,
    y: u32,
    counts: &mut Counts,
    each: &impl Fn([f64; 3]) -> [T; 3],
    out: &mut Vec<T>,
) {
    let lanes = <R::Wide as Wide>::LANES;
    let n = tracer.problem.render.samples;
    let width = camera.width;
    let total = width as usize * n as usize;
    let mut b = Buffers {
        queue: Vec::with_capacity(BLOCK),
        next: Vec::with_capacity(BLOCK),
        colors: vec![V3::<R>::ZERO; BLOCK],
        hits: vec![None; lanes],
        rays: Vec::with_capacity(lanes),
    };
    let aggregate = &tracer.scene.aggregate;
    let mut sum = [0.0f64; 3];
    for start in (0..total).step_by(BLOCK) {
        let end = (start + BLOCK).min(total);
        // Primary rays, pixel by pixel and sample by sample, as pixel_mean takes them.
        b.queue.clear();
        for s in start..end {
            let (x, i) = ((s / n as usize) as u32, (s % n as usize) as u32);
            let (sx, sy) = sample(i, n);
            b.queue.push(Entry {
                slot: (s - start) as u32,
                path: PathState::primary(camera.ray(x, y, sx, sy)),
            });
            b.colors[s - start] = V3::<R>::ZERO;
        }
        counts.primary += (end - start) as u64;
        // One bounce per pass: the queue's nearest hits a packet at a time, then each hit
        // shaded and its children queued for the next pass.
        while !b.queue.is_empty() {
            b.next.clear();
            for packet in b.queue.chunks(lanes) {
                match flat {
                    Some(flat) => {
                        b.rays.clear();
                        b.rays.extend(packet.iter().map(|e| e.path.ray));
                        flat.nearest(aggregate, &b.rays, &mut b.hits);
                    }
                    None => {
                        b.rays.clear();
                        b.rays.extend(packet.iter().map(|e| e.path.ray));
                        aggregate.nearest_packet(&b.rays, &mut b.hits);
                    }
                }
                for (k, e) in packet.iter().enumerate() {
                    let mut path = e.path;
                    let found = b.hits[k];
                    let (share, more) = match flat {
                        Some(flat) => tracer.bounce(
                            &mut path,
                            found,
                            |h: &SurfaceHit<R>| FlatShadowRays {
                                rays: h.shadow_rays(aggregate),
                                flat,
                            },
                            counts,
                            &mut (),
                        ),
                        None => tracer.bounce(
                            &mut path,
                            found,
                            |h: &SurfaceHit<R>| h.shadow_rays(aggregate),
                            counts,
                            &mut (),
                        ),
                    };
                    b.colors[e.slot as usize] += share;
                    if more {
                        b.next.push(Entry { slot: e.slot, path });
                    }
                }
            }
            std::mem::swap(&mut b.queue, &mut b.next);
        }
        // The samples in order: each pixel's sum, then its mean, as pixel_mean forms them.
        for s in start..end {
            let c = clamped::<R>(b.colors[s - start]);
            for k in 0..3 {
                sum[k] += c[k];
            }
            if (s + 1) % n as usize == 0 {
                out.extend_from_slice(&each(mean(sum, n)));
                sum = [0.0; 3];
            }
        }
    }
}

#[cfg(test)]
mod tests;
