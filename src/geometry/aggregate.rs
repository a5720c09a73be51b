//! All the surfaces of a scene behind one question, "what does this ray hit first?", and its
//! cheaper sibling, "does anything block this shadow ray?". Bounded shapes (spheres, triangles)
//! sit in a BVH, so the cost grows about logarithmically with their number; planes, which no box
//! bounds, are tested one by one. The BVH is built binary (binned SAH, leaves of up to
//! [`Wide::LANES`] shapes) and searched in its wide form ([`WideBvh`]: a node's children's
//! boxes in lanes, leaves' spheres and triangles in lanes), which gives the binary search's
//! answer to the bit.
//!
//! The tracer and the solver's ray problems both ask here, so a pixel and the equivalent ray
//! problem meet the same surface at the same point.

use super::bvh::Bvh;
use super::hit::SurfaceHit;
use super::ray::{lane_ray, RayLanes};
use super::soa::plane_hit_t;
use super::wbvh::WideBvh;
use super::{Plane, Ray, Shape};
use crate::core::lanes::{lanes_of, mask_of, Wide, W, W3};
use crate::core::Real;

/// Up to this many bounded shapes are tested in a plain loop rather than through the BVH.
pub(crate) const FLAT: usize = 8;

/// The surfaces of a scene, indexed in the order given.
#[derive(Clone, Debug)]
pub struct Aggregate<R: Real> {
    shapes: Vec<Shape<R>>,
    /// Indices of the shapes without a bounding box (planes).
    unbounded: Vec<u32>,
    /// Indices of the bounded shapes; the BVH's primitive `k` is `bounded[k]`.
    bounded: Vec<u32>,
    /// The binary tree over `bounded` (kept for the tests, which check the wide search
    /// against its own).
    #[cfg(test)]
    bvh: Bvh<R>,
    /// `bvh` collapsed into wide nodes with SoA leaves: what the searches use (empty for
    /// [`FLAT`] or fewer bounded shapes, which are looped over).
    wide: WideBvh<R>,
}

/// The nearest hit of a ray: which shape, and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AggregateHit<R: Real> {
    /// The shape's index in the order given.
    pub index: usize,
    /// Where the ray meets it: t, the point with its error bound, and the normal.
    pub hit: SurfaceHit<R>,
}

/// The origins and directions of a packet of rays (at most [`Wide::LANES`], at least one) in
/// lanes; lanes past its end repeat its first ray.
#[inline(always)]
fn origins_and_directions<R: Real>(rays: &[Ray<R>]) -> RayLanes<R> {
    (
        W3::gather(rays.iter().map(|r| r.origin), rays[0].origin),
        W3::gather(rays.iter().map(|r| r.direction), rays[0].direction),
    )
}

/// [`Shape::hit_t`] of a plane against the lanes set in `live` ([`plane_hit_t`], the flat
/// scene's test, with the plane splatted): the bits of the hits, their t, and the bits of the
/// lanes left to the scalar code (Q − O overflowing, which it computes on halves).
#[inline(always)]
fn plane_bits<R: Real>(
    o: W3<W<R>>,
    d: W3<W<R>>,
    plane: &Plane<R>,
    t_max: W<R>,
    live: u32,
) -> (u32, W<R>, u32) {
    let (n, q) = (W3::splat(plane.normal), W3::splat(plane.point));
    match plane_hit_t(o, d, n, q, t_max, live) {
        Some((hit, t, slow)) => (hit.bits(), t, slow.bits()),
        None => (0, t_max, 0),
    }
}

impl<R: Real> Aggregate<R> {
    /// Builds the BVH over the bounded shapes.
    pub fn new(shapes: Vec<Shape<R>>) -> Self {
        // (Room for every shape: pages never written are never resident.)
        let mut unbounded = Vec::new();
        let mut bounded = Vec::with_capacity(shapes.len());
        for (i, s) in shapes.iter().enumerate() {
            let i = u32::try_from(i).expect("fewer than 2^32 surfaces");
            match s {
                Shape::Plane(_) => unbounded.push(i),
                Shape::Sphere(_) | Shape::Triangle(_) => bounded.push(i),
            }
        }
        let boxes =
            (bounded.iter()).map(|&i| shapes[i as usize].bounds().expect("a bounded shape"));
        // One shape per lane in a leaf: a leaf is one test in lanes.
        let bvh = Bvh::build_with_leaves(boxes, W::<R>::LANES);
        let wide = if bounded.len() > FLAT {
            WideBvh::new(&bvh, &bounded, &shapes)
        } else {
            WideBvh::new(&Bvh::build(&[]), &[], &shapes)
        };
        Aggregate {
            #[cfg(test)]
            bvh,
            wide,
            shapes,
            unbounded,
            bounded,
        }
    }

    /// The shapes, in the order given (the wide tracer's `FlatScene` lays them out in lanes).
    pub(crate) fn shapes(&self) -> &[Shape<R>] {
        &self.shapes
    }

    /// The nearest hit with 0 < t < `t_max`.
    pub fn nearest(&self, ray: &Ray<R>, t_max: R) -> Option<AggregateHit<R>> {
        let mut best: Option<(usize, R)> = None;
        let mut t_max = t_max;
        for &i in &self.unbounded {
            if let Some(t) = self.shapes[i as usize].hit_t(ray, t_max) {
                t_max = t;
                best = Some((i as usize, t));
            }
        }
        if self.bounded.len() <= FLAT {
            // A handful of shapes: a plain loop costs less than the boxes around them.
            for &i in &self.bounded {
                if let Some(t) = self.shapes[i as usize].hit_t(ray, t_max) {
                    t_max = t;
                    best = Some((i as usize, t));
                }
            }
        } else if let Some((i, t)) = self.wide.nearest(&self.shapes, ray, t_max) {
            // The search shrinks its t_max to each hit it accepts, so every accepted hit is
            // nearer.
            best = Some((i as usize, t));
        }
        // Only the nearest hit gets its point, error bound and normal.
        let (index, t) = best?;
        Some(AggregateHit {
            index,
            hit: self.shapes[index].hit_at(ray, t)?,
        })
    }

    /// Whether any surface meets the ray with 0 < t < `t_max` (stopping at the first it finds).
    pub fn occluded(&self, ray: &Ray<R>, t_max: R) -> bool {
        let blocks = |i: &u32| self.shapes[*i as usize].hit_t(ray, t_max).is_some();
        if self.unbounded.iter().any(blocks) {
            return true;
        }
        if self.bounded.len() <= FLAT {
            return self.bounded.iter().any(blocks);
        }
        self.wide.occluded(&self.shapes, ray, t_max)
    }

    /// The nearest hit with 0 < t < ∞ of each ray of a packet (`out[k]` for `rays[k]`):
    /// [`Aggregate::nearest`] of each, to the bit, for the wide tracer's queues of rays. Rays
    /// go through the wide BVH [`Wide::LANES`] at a time (`WideBvh::nearest_packet`).
    pub fn nearest_packet(&self, rays: &[Ray<R>], out: &mut [Option<AggregateHit<R>>]) {
        let infinity = [R::from_f64(f64::INFINITY); 8];
        let lanes = W::<R>::LANES;
        for (rays, out) in rays.chunks(lanes).zip(out.chunks_mut(lanes)) {
            self.nearest_packet_within(rays, &infinity[..rays.len()], out);
        }
    }

    /// [`Aggregate::nearest`] of each ray of a packet of at most [`Wide::LANES`] rays, ray k
    /// within `limit[k]`.
    pub(crate) fn nearest_packet_within(
        &self,
        rays: &[Ray<R>],
        limit: &[R],
        out: &mut [Option<AggregateHit<R>>],
    ) {
        debug_assert!(rays.len() <= W::<R>::LANES && limit.len() >= rays.len());
        if self.bounded.len() <= FLAT {
            for ((ray, hit), &t_max) in rays.iter().zip(out.iter_mut()).zip(limit) {
                *hit = self.nearest(ray, t_max);
            }
            return;
        }
        let mut t_max = [R::ZERO; 8];
        t_max[..rays.len()].copy_from_slice(&limit[..rays.len()]);
        let mut best: [Option<u32>; 8] = [None; 8];
        let n = rays.len();
        let live = (1u32 << n) - 1;
        // The rays in lanes, once for the planes and the tree.
        let (o, d) = origins_and_directions(rays);
        // Planes first, in their order, as `nearest` takes them: each plane against every
        // ray in lanes
        if !self.unbounded.is_empty() {
            let mut tm = <W<R> as Wide>::Array::default();
            tm.as_mut()[..n].copy_from_slice(&t_max[..n]);
            let mut tm = W::<R>::from_array(tm);
            for &i in &self.unbounded {
                let Shape::Plane(plane) = &self.shapes[i as usize] else {
                    unreachable!("only planes are unbounded")
                };
                let (hit, t, slow) = plane_bits(o, d, plane, tm, live);
                let (hit, slow) = (hit & live, slow & live);
                if hit != 0 {
                    tm = mask_of::<W<R>>(hit).select(t, tm);
                    for k in lanes_of(hit) {
                        best[k] = Some(i);
                    }
                }
                if slow != 0 {
                    let mut a = tm.to_array();
                    for k in lanes_of(slow) {
                        if let Some(t) = self.shapes[i as usize].hit_t(&rays[k], a.as_ref()[k]) {
                            a.as_mut()[k] = t;
                            best[k] = Some(i);
                        }
                    }
                    tm = W::<R>::from_array(a);
                }
            }
            t_max[..n].copy_from_slice(&tm.to_array().as_ref()[..n]);
        }
        self.wide.nearest_packet(
            &self.shapes,
            rays,
            (o, d),
            live,
            &mut t_max[..n],
            &mut best[..n],
        );
        for (k, (ray, hit)) in rays.iter().zip(out.iter_mut()).enumerate() {
            *hit = best[k].and_then(|i| {
                let index = i as usize;
                Some(AggregateHit {
                    index,
                    hit: self.shapes[index].hit_at(ray, t_max[k])?,
                })
            });
        }
    }

    /// Which rays of a packet (at most [`Wide::LANES`]) something blocks, ray k of `want` to
    /// `t_max[k]`: the mask of the rays [`Aggregate::occluded`] says are blocked, to the bit.
    /// Rays go through the wide BVH together (`WideBvh::occluded_packet`).
    pub fn occluded_packet(&self, rays: &[Ray<R>], t_max: &[R], want: u32) -> u32 {
        debug_assert!(rays.len() <= W::<R>::LANES && t_max.len() >= rays.len());
        let mut tm = <W<R> as Wide>::Array::default();
        tm.as_mut()[..rays.len()].copy_from_slice(&t_max[..rays.len()]);
        self.occluded_packet_in(origins_and_directions(rays), &tm, want)
    }

    /// [`Aggregate::occluded_packet`] of rays in lanes (`lanes`: origins and directions, lane k
    /// being ray k for each k of `want`, the others anything; `t_max` a number per lane), as
    /// the wide tracer builds its shadow rays: never gathered, and made one by one only where
    /// the one-ray code needs them.
    pub(crate) fn occluded_packet_in(
        &self,
        (o, d): RayLanes<R>,
        lanes_t_max: &<W<R> as Wide>::Array,
        want: u32,
    ) -> u32 {
        let t_max = lanes_t_max.as_ref();
        let ray = |k: usize| lane_ray((o, d), k);
        if self.bounded.len() <= FLAT {
            return lanes_of(want)
                .filter(|&k| self.occluded(&ray(k), t_max[k]))
                .fold(0, |m, k| m | 1 << k);
        }
        // Planes first, each against every ray in lanes
        let mut blocked = 0;
        if !self.unbounded.is_empty() && want != 0 {
            let tm = W::<R>::from_array(*lanes_t_max);
            for &i in &self.unbounded {
                let Shape::Plane(plane) = &self.shapes[i as usize] else {
                    unreachable!("only planes are unbounded")
                };
                let (hit, _, slow) = plane_bits(o, d, plane, tm, want & !blocked);
                blocked |= hit & want;
                for k in lanes_of(slow & want & !blocked) {
                    if self.shapes[i as usize].hit_t(&ray(k), t_max[k]).is_some() {
                        blocked |= 1 << k;
                    }
                }
                if want & !blocked == 0 {
                    return blocked;
                }
            }
        }
        blocked
            | self
                .wide
                .occluded_packet(&self.shapes, (o, d), lanes_t_max, want & !blocked)
    }

    /// [`Aggregate::nearest`] through the binary tree's own search (the reference of the wide
    /// one): the shape's index and t.
    #[cfg(test)]
    pub(crate) fn nearest_binary(&self, ray: &Ray<R>, t_max: R) -> Option<(usize, R)> {
        let mut best: Option<(usize, R)> = None;
        let mut t_max = t_max;
        for &i in &self.unbounded {
            if let Some(t) = self.shapes[i as usize].hit_t(ray, t_max) {
                t_max = t;
                best = Some((i as usize, t));
            }
        }
        if let Some(h) = self.bvh.nearest(ray, t_max, |k, t_max| {
            self.shapes[self.bounded[k as usize] as usize].hit_t(ray, t_max)
        }) {
            best = Some((self.bounded[h.prim as usize] as usize, h.t));
        }
        best
    }

    /// [`Aggregate::occluded`] through the binary tree's own search.
    #[cfg(test)]
    pub(crate) fn occluded_binary(&self, ray: &Ray<R>, t_max: R) -> bool {
        let blocks = |i: &u32| self.shapes[*i as usize].hit_t(ray, t_max).is_some();
        self.unbounded.iter().any(blocks)
            || self.bvh.any(ray, t_max, |k, t_max| {
                self.shapes[self.bounded[k as usize] as usize]
                    .hit_t(ray, t_max)
                    .is_some()
            })
    }
}
