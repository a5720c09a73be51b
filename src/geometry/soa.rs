//! A flat scene (planes and at most [`FLAT`] spheres, no triangles: the size at which
//! [`Aggregate`] itself loops instead of using its BVH) in lanes, for the wide tracer: every
//! sphere and plane tested against several rays at once (a packet: [`FlatScene::nearest`]), or
//! a packet of shadow rays against each shape, stopping at the first occluder
//! ([`FlatScene::occluded_packet`]), with no dispatch
//! on the shape's kind.
//!
//! The lanes compute exactly what the scalar [`Shape::hit_t`] computes, operation for operation
//! (see [`crate::core::lanes`]), and shapes are taken in the aggregate's order with the same
//! strict "nearer than the best so far" rule, so the nearest (shape, t) of each lane is the
//! scalar one to the bit. A lane whose numbers need the scalar code's robust branch (squares
//! beyond the range of the fast formula, a plane's Q − O overflowing) is handed to that code.

use super::aggregate::{Aggregate, AggregateHit, FLAT};
use super::{Plane, Ray, Shape, Sphere};
use crate::core::lanes::{lanes_of, Wide, W, W3};
use crate::core::Real;

/// The surfaces of a flat scene by kind, each with its index in the scene's order.
#[derive(Clone, Debug)]
pub struct FlatScene<R: Real> {
    planes: Vec<(u32, Plane<R>)>,
    spheres: Vec<(u32, Sphere<R>)>,
}

/// The lanes where `x` is 0 or a square the fast formula may use ([`Sphere::intersect_line`]).
#[inline(always)]
fn safe_square<L: Wide>(x: L) -> L {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let lo = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MIN);
    let hi = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MAX);
    x.eq(zero).or(x.gt(lo).and(x.lt(hi)))
}

/// [`Shape::hit_t`] of a sphere in every lane (rays or spheres, either may be the same in all
/// lanes): the mask of lanes with a hit at 0 < t < `t_max`, that t, and the mask of lanes the
/// fast formula cannot decide (left to the scalar code).
#[inline(always)]
pub(crate) fn sphere_hit_t<L: Wide>(
    o: W3<L>,
    d: W3<L>,
    center: W3<L>,
    r2: L,
    t_max: L,
) -> (L, L, L) {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let f = o - center;
    let b = d.dot(f);
    let ff = f.dot(f);
    // Outside the sphere and moving away: both roots are behind the origin.
    let away = b.gt(zero).and(ff.gt(r2));
    let q = f - d.scale(b);
    let perp2 = q.dot(q);
    let safe = safe_square(perp2).and(safe_square(r2)).and(safe_square(ff));
    let disc = r2 - perp2;
    let meets = disc.lt(zero).not();
    let decided = safe.or(away);
    // Most lanes miss most spheres: where none can hit, skip the root and the division.
    if away.not().and(meets).or(decided.not()).bits() == 0 {
        return (zero.gt(zero), zero, zero.gt(zero));
    }
    let root = disc.sqrt();
    let nb = b.neg();
    let qq = b.lt(zero).select(nb + root, nb - root);
    let t1 = (ff - r2) / qq;
    let q_zero = qq.eq(zero);
    let t0 = q_zero.select(zero, qq);
    let t1 = q_zero.select(zero, t1);
    let swap = t0.gt(t1);
    let (lo, hi) = (swap.select(t1, t0), swap.select(t0, t1));
    let finite = lo.finite().and(hi.finite());
    let in_lo = lo.gt(zero).and(lo.lt(t_max));
    let in_hi = hi.gt(zero).and(hi.lt(t_max));
    let hit = away
        .not()
        .and(safe)
        .and(meets)
        .and(finite)
        .and(in_lo.or(in_hi));
    (hit, in_lo.select(lo, hi), decided.not())
}

/// [`Shape::hit_t`] of a plane in every lane of a packet: the hit mask, t, and the lanes left to
/// the scalar code (Q − O overflowing).
#[inline(always)]
fn plane_hit_t<L: Wide>(o: W3<L>, d: W3<L>, plane: &Plane<L::Scalar>, t_max: L) -> (L, L, L) {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let n = W3::<L>::splat(plane.normal);
    let denom = n.dot(d);
    let diff = W3::<L>::splat(plane.point) - o;
    let fast = diff.finite();
    let t = n.dot(diff) / denom;
    let at = o + d.scale(t);
    let hit = denom
        .eq(zero)
        .not()
        .and(fast)
        .and(t.finite())
        .and(at.finite())
        .and(t.gt(zero))
        .and(t.lt(t_max));
    (hit, t, fast.not())
}

impl<R: Real> FlatScene<R> {
    /// The aggregate's surfaces in lanes, when it is flat: no BVH (at most [`FLAT`] bounded
    /// shapes) and no triangles. `None` otherwise: the wide tracer then asks the aggregate.
    pub fn new(aggregate: &Aggregate<R>) -> Option<Self> {
        if aggregate.shapes().len() >= 1 << 24 {
            return None;
        }
        let mut planes = Vec::new();
        let mut spheres = Vec::new();
        for (i, s) in aggregate.shapes().iter().enumerate() {
            let i = u32::try_from(i).ok()?;
            match s {
                Shape::Plane(p) => planes.push((i, *p)),
                Shape::Sphere(_) if spheres.len() == FLAT => return None,
                Shape::Sphere(sp) => spheres.push((i, *sp)),
                Shape::Triangle(_) => return None,
            }
        }
        Some(FlatScene { planes, spheres })
    }

    /// The nearest hit of each ray of a packet (at most [`Wide::LANES`] rays), with
    /// 0 < t < ∞: what [`Aggregate::nearest`] gives each of them, to the bit.
    pub fn nearest(
        &self,
        aggregate: &Aggregate<R>,
        rays: &[Ray<R>],
        out: &mut [Option<AggregateHit<R>>],
    ) {
        let lanes = W::<R>::LANES;
        debug_assert!(rays.len() <= lanes && out.len() >= rays.len());
        let fill = rays[0];
        let o = W3::<W<R>>::gather(rays.iter().map(|r| r.origin), fill.origin);
        let d = W3::<W<R>>::gather(rays.iter().map(|r| r.direction), fill.direction);
        let infinity = R::from_f64(f64::INFINITY);
        let zero = W::<R>::splat(R::ZERO);
        let mut best_t = W::<R>::splat(infinity);
        // The best shape's index + 1 in each lane (0: none yet), exact in either precision
        // below 2^24 shapes (FlatScene::new).
        let mut best_i = zero;
        let live = (1u32 << rays.len()) - 1;
        // Keeps each lane's hit where it is nearer than its best so far: the lanes' own
        // test, with the lanes it could not decide tested by the scalar code.
        let mut take = |(hit, t, slow): (W<R>, W<R>, W<R>),
                        index: u32,
                        best_t: &mut W<R>,
                        scalar: &dyn Fn(&Ray<R>, R) -> Option<R>| {
            let slow = slow.bits() & live;
            let (hit, t) = if slow == 0 {
                (hit, t)
            } else {
                let (mut t, mut h) = (
                    t.to_array(),
                    hit.select(W::<R>::splat(R::ONE), zero).to_array(),
                );
                let bests = best_t.to_array();
                for k in lanes_of(slow) {
                    let found = scalar(&rays[k], bests.as_ref()[k]);
                    h.as_mut()[k] = if found.is_some() { R::ONE } else { R::ZERO };
                    t.as_mut()[k] = found.unwrap_or(R::ZERO);
                }
                (W::<R>::from_array(h).gt(zero), W::<R>::from_array(t))
            };
            *best_t = hit.select(t, *best_t);
            best_i = hit.select(W::<R>::splat(R::from_f64(f64::from(index) + 1.0)), best_i);
        };
        // Planes first, then spheres, each in the scene's order, as the aggregate takes them.
        for (index, plane) in &self.planes {
            let found = plane_hit_t(o, d, plane, best_t);
            take(found, *index, &mut best_t, &|ray, t_max| {
                Shape::Plane(*plane).hit_t(ray, t_max)
            });
        }
        for (index, sphere) in &self.spheres {
            let c = W3::<W<R>>::splat(sphere.center);
            let r2 = W::<R>::splat(sphere.radius * sphere.radius);
            let found = sphere_hit_t(o, d, c, r2, best_t);
            take(found, *index, &mut best_t, &|ray, t_max| {
                Shape::Sphere(*sphere).hit_t(ray, t_max)
            });
        }
        let (best_t, best_i) = (best_t.to_array(), best_i.to_array());
        for (k, ray) in rays.iter().enumerate() {
            // Only the nearest hit gets its point, error bound and normal, as in the aggregate.
            let i = best_i.as_ref()[k].to_f64();
            out[k] = if i == 0.0 {
                None
            } else {
                let index = i as usize - 1;
                aggregate.shapes()[index]
                    .hit_at(ray, best_t.as_ref()[k])
                    .map(|hit| AggregateHit { index, hit })
            };
        }
    }

    /// The shadow rays of a packet, any hit: bit k of the result is set where lane k of `want`
    /// is and some surface meets `rays[k]` with 0 < t < `t_max[k]` ([`Aggregate::occluded`] of
    /// that ray, to the bit). Every shape is tested against all the lanes at once, and the test
    /// stops as soon as every wanted lane is blocked. `rays` and `t_max` hold [`Wide::LANES`]
    /// entries; the lanes not wanted may hold any ray.
    pub(crate) fn occluded_packet(&self, rays: &[Ray<R>], t_max: &[R], want: u32) -> u32 {
        let lanes = W::<R>::LANES;
        debug_assert!(rays.len() == lanes && t_max.len() == lanes);
        let o = W3::<W<R>>::gather(rays.iter().map(|r| r.origin), rays[0].origin);
        let d = W3::<W<R>>::gather(rays.iter().map(|r| r.direction), rays[0].direction);
        let mut tm = <W<R> as Wide>::Array::default();
        tm.as_mut().copy_from_slice(t_max);
        let tm = W::<R>::from_array(tm);
        let mut blocked = 0u32;
        // Each shape's lanes, then the lanes its fast formula could not decide, by the scalar
        // test; `true` once every wanted lane is blocked.
        let mut take = |(hit, _, slow): (W<R>, W<R>, W<R>), shape: Shape<R>| {
            blocked |= hit.bits() & want;
            for k in lanes_of(slow.bits() & want & !blocked) {
                if shape.hit_t(&rays[k], t_max[k]).is_some() {
                    blocked |= 1 << k;
                }
            }
            blocked == want
        };
        for (_, plane) in &self.planes {
            if take(plane_hit_t(o, d, plane, tm), Shape::Plane(*plane)) {
                return want;
            }
        }
        for (_, sphere) in &self.spheres {
            let c = W3::<W<R>>::splat(sphere.center);
            let r2 = W::<R>::splat(sphere.radius * sphere.radius);
            if take(sphere_hit_t(o, d, c, r2, tm), Shape::Sphere(*sphere)) {
                return want;
            }
        }
        blocked
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::v3;
    use crate::core::vector::normalize;

    fn scene<R: Real>() -> Aggregate<R> {
        let sphere = |c: [f64; 3], r: f64| {
            Shape::Sphere(Sphere {
                center: v3::<R>(c),
                radius: R::from_f64(r),
            })
        };
        Aggregate::new(vec![
            sphere([0.0, 1.0, 0.0], 1.0),
            Shape::Plane(Plane {
                point: v3::<R>([0.0, 0.0, 0.0]),
                normal: v3::<R>([0.0, 1.0, 0.0]),
            }),
            sphere([-2.0, 0.5, 1.0], 0.5),
            // Two equal spheres: the first in the scene's order wins the tie.
            sphere([2.0, 0.7, 1.0], 0.7),
            sphere([2.0, 0.7, 1.0], 0.7),
            // Tiny and huge: the scalar code's robust branch.
            sphere([0.0, 3.0, -4.0], 1e-25),
            sphere([0.0, 0.0, -1e30], 1e25),
        ])
    }

    fn packets_and_shadow_rays_are_the_aggregates<R: Real>() {
        let aggregate = scene::<R>();
        let flat = FlatScene::new(&aggregate).expect("flat");
        let eye = v3::<R>([0.0, 2.0, 8.0]);
        let mut rays = Vec::new();
        for i in 0..40 {
            for j in 0..30 {
                let target = v3::<R>([f64::from(i) / 5.0 - 4.0, f64::from(j) / 8.0 - 1.0, 0.0]);
                let d = normalize::<R>(target - eye).unwrap().unit;
                rays.push(Ray {
                    origin: eye,
                    direction: d,
                });
            }
        }
        // From inside a sphere and from the floor upwards.
        rays.push(Ray {
            origin: v3::<R>([0.0, 1.0, 0.0]),
            direction: v3::<R>([0.0, 0.0, 1.0]),
        });
        rays.push(Ray {
            origin: v3::<R>([0.0, 3.0, 8.0]),
            direction: v3::<R>([0.0, 0.0, -1.0]),
        });
        let mut out = vec![None; W::<R>::LANES];
        let infinity = R::from_f64(f64::INFINITY);
        for packet in rays.chunks(W::<R>::LANES) {
            flat.nearest(&aggregate, packet, &mut out);
            for (k, ray) in packet.iter().enumerate() {
                assert_eq!(out[k], aggregate.nearest(ray, infinity), "{ray:?}");
            }
            // The same rays as shadow packets, each lane its own t_max, every other lane wanted.
            let lanes = W::<R>::LANES;
            let mut rs = vec![packet[0]; lanes];
            rs[..packet.len()].copy_from_slice(packet);
            let t_max: Vec<R> = (0..lanes)
                .map(|k| [R::from_f64(3.0), R::from_f64(9.0), infinity][k % 3])
                .collect();
            for want in [
                (1u32 << packet.len()) - 1,
                0b0101_0101 & ((1 << packet.len()) - 1),
            ] {
                let got = flat.occluded_packet(&rs, &t_max, want);
                for k in 0..packet.len() {
                    let expected = want & (1 << k) != 0 && aggregate.occluded(&rs[k], t_max[k]);
                    assert_eq!(got & (1 << k) != 0, expected, "{:?} {}", rs[k], t_max[k]);
                }
            }
        }
    }

    #[test]
    fn packets_and_shadow_rays_meet_what_the_aggregate_meets_in_both_precisions() {
        packets_and_shadow_rays_are_the_aggregates::<f32>();
        packets_and_shadow_rays_are_the_aggregates::<f64>();
    }
}
