//! A flat scene (planes and at most [`FLAT`] spheres, no triangles: the size at which
//! [`Aggregate`] itself loops instead of using its BVH) in lanes, for the wide tracer: every
//! sphere and plane tested against several rays at once (a packet: [`FlatScene::nearest`]), or
//! a packet of shadow rays, in the lanes the wide tracer builds them in, against each shape,
//! stopping once every ray is blocked ([`FlatScene::occluded_lanes`]), with no dispatch on the
//! shape's kind. Each shape's constants are splatted once ([`FlatScene::new`]), and a shape that
//! every ray of a packet misses by the cheap test (a sphere's line passing farther than r from
//! its centre, a plane met outside (0, t_max)) costs only that test.
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

/// The surfaces of a flat scene by kind, each with its index in the scene's order and its
/// constants already in lanes.
#[derive(Clone, Debug)]
pub struct FlatScene<R: Real> {
    planes: Vec<FlatPlane<R>>,
    spheres: Vec<FlatSphere<R>>,
}

/// A plane of a [`FlatScene`]: the plane, its tag (from its index in the scene), and N and Q
/// in every lane (splatted once, in [`FlatScene::new`], not once per packet).
#[derive(Clone, Debug)]
struct FlatPlane<R: Real> {
    plane: Plane<R>,
    normal: W3<W<R>>,
    point: W3<W<R>>,
    /// index + 1 in every lane: the mark [`FlatScene::nearest`] keeps of the best shape.
    tag: W<R>,
}

/// A sphere of a [`FlatScene`]: the sphere, its tag, and C and r² in every lane.
#[derive(Clone, Debug)]
struct FlatSphere<R: Real> {
    sphere: Sphere<R>,
    center: W3<W<R>>,
    r2: W<R>,
    /// index + 1 in every lane, as [`FlatPlane::tag`].
    tag: W<R>,
}

/// The lanes where `x` is 0 or a square the fast formula may use ([`Sphere::intersect_line`]).
#[inline(always)]
fn safe_square<L: Wide>(x: L) -> L {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let lo = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MIN);
    let hi = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MAX);
    x.eq(zero).or(x.gt(lo).and(x.lt(hi)))
}

/// No lane hit and none left to the scalar code: what a shape's test gives a packet that misses
/// it everywhere.
#[inline(always)]
fn no_hit<L: Wide>() -> (L, L, L) {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    (zero.gt(zero), zero, zero.gt(zero))
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
    sphere_hit_t_in(o, d, center, r2, t_max, u32::MAX).unwrap_or_else(no_hit)
}

/// [`sphere_hit_t`] for the lanes set in `live` (the others' answers are not read); `None`
/// (no hit, nothing undecided) when every live lane is a miss by the cheap test, so that the
/// caller goes on to the next shape at once.
#[inline(always)]
pub(crate) fn sphere_hit_t_in<L: Wide>(
    o: W3<L>,
    d: W3<L>,
    center: W3<L>,
    r2: L,
    t_max: L,
    live: u32,
) -> Option<(L, L, L)> {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let lo = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MIN);
    let hi = L::splat(<L::Scalar as Real>::SAFE_SQUARED_MAX);
    let f = o - center;
    let b = d.dot(f);
    let ff = f.dot(f);
    // Outside the sphere and moving away: both roots are behind the origin.
    let away = b.gt(zero).and(ff.gt(r2));
    let q = f - d.scale(b);
    let perp2 = q.dot(q);
    // Most lanes miss most spheres: the line passes farther than r from C (r² < ‖q‖², so
    // disc = r² − ‖q‖² < 0), with every square inside the fast formula's range (lo < r² <
    // ‖q‖² < hi, lo < f·f < hi). Such a lane, and an `away` one, is a miss the full test
    // below would decide as well; where every live lane is one, skip the rest.
    let passes = perp2
        .gt(r2)
        .and(perp2.lt(hi))
        .and(r2.gt(lo))
        .and(ff.gt(lo))
        .and(ff.lt(hi));
    if away.or(passes).not().bits() & live == 0 {
        return None;
    }
    let safe = safe_square(perp2).and(safe_square(r2)).and(safe_square(ff));
    let disc = r2 - perp2;
    let meets = disc.lt(zero).not();
    let decided = safe.or(away);
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
    Some((hit, in_lo.select(lo, hi), decided.not()))
}

/// [`Shape::hit_t`] of a plane (N and Q in every lane) in the lanes of a packet set in `live`:
/// the hit mask, t, and the lanes left to the scalar code (Q − O overflowing); `None` (no hit,
/// nothing undecided) when every live lane is a miss by the cheap test.
#[inline(always)]
pub(crate) fn plane_hit_t<L: Wide>(
    o: W3<L>,
    d: W3<L>,
    n: W3<L>,
    point: W3<L>,
    t_max: L,
    live: u32,
) -> Option<(L, L, L)> {
    let zero = L::splat(<L::Scalar as Real>::ZERO);
    let denom = n.dot(d);
    let diff = point - o;
    let along = n.dot(diff);
    let t = along / denom;
    let in_range = t.gt(zero).and(t.lt(t_max));
    // Where t is not in (0, t_max) the lane misses, unless Q − O overflowed (the scalar code
    // then works on the halves); N is finite, so a Q − O that is not makes N·(Q − O) not
    // finite either: a finite N·(Q − O) out of range is a miss the full test would decide.
    if in_range.or(along.finite().not()).bits() & live == 0 {
        return None;
    }
    let fast = diff.finite();
    let at = o + d.scale(t);
    let hit = denom
        .eq(zero)
        .not()
        .and(fast)
        .and(t.finite())
        .and(at.finite())
        .and(in_range);
    Some((hit, t, fast.not()))
}

/// The lanes of `lanes` whose ray (lane k of `o`, `d`) meets `shape` with 0 < t < lane k of
/// `t_max`, by the scalar [`Shape::hit_t`]: the lanes the fast formula left undecided.
#[cold]
#[inline(never)]
fn scalar_blocked<R: Real>(
    shape: Shape<R>,
    o: W3<W<R>>,
    d: W3<W<R>>,
    t_max: W<R>,
    lanes: u32,
) -> u32 {
    let tm = t_max.to_array();
    let mut blocked = 0;
    for k in lanes_of(lanes) {
        let ray = Ray {
            origin: o.at(k),
            direction: d.at(k),
        };
        if shape.hit_t(&ray, tm.as_ref()[k]).is_some() {
            blocked |= 1 << k;
        }
    }
    blocked
}

/// A shape's (hit, t) in lanes with the lanes of `slow` replaced by the scalar
/// [`Shape::hit_t`] of `rays[k]` below `best_t`: the lanes the fast formula left undecided.
#[cold]
#[inline(never)]
fn scalar_nearest<R: Real>(
    shape: Shape<R>,
    rays: &[Ray<R>],
    (hit, t): (W<R>, W<R>),
    best_t: W<R>,
    slow: u32,
) -> (W<R>, W<R>) {
    let zero = W::<R>::splat(R::ZERO);
    let (mut t, mut h) = (
        t.to_array(),
        hit.select(W::<R>::splat(R::ONE), zero).to_array(),
    );
    let bests = best_t.to_array();
    for k in lanes_of(slow) {
        let found = shape.hit_t(&rays[k], bests.as_ref()[k]);
        h.as_mut()[k] = if found.is_some() { R::ONE } else { R::ZERO };
        t.as_mut()[k] = found.unwrap_or(R::ZERO);
    }
    (W::<R>::from_array(h).gt(zero), W::<R>::from_array(t))
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
            let index = u32::try_from(i).ok()?;
            // The best shape's index + 1 (0: none yet), exact in either precision below 2^24
            // shapes.
            let tag = W::<R>::splat(R::from_f64(f64::from(index) + 1.0));
            match s {
                Shape::Plane(p) => planes.push(FlatPlane {
                    plane: *p,
                    normal: W3::splat(p.normal),
                    point: W3::splat(p.point),
                    tag,
                }),
                Shape::Sphere(_) if spheres.len() == FLAT => return None,
                Shape::Sphere(sp) => spheres.push(FlatSphere {
                    sphere: *sp,
                    center: W3::splat(sp.center),
                    // r², as Sphere::intersect_line forms it.
                    r2: W::<R>::splat(sp.radius * sp.radius),
                    tag,
                }),
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
        // The best shape's tag (index + 1) in each lane (0: none yet).
        let mut best_i = zero;
        let live = (1u32 << rays.len()) - 1;
        // Planes first, then spheres, each in the scene's order, as the aggregate takes them;
        // each lane's hit kept where it is nearer than its best so far (the strict rule), the
        // lanes the fast formula could not decide tested by the scalar code.
        for p in &self.planes {
            let Some((hit, t, slow)) = plane_hit_t(o, d, p.normal, p.point, best_t, live) else {
                continue;
            };
            let slow = slow.bits() & live;
            let (hit, t) = if slow == 0 {
                (hit, t)
            } else {
                scalar_nearest(Shape::Plane(p.plane), rays, (hit, t), best_t, slow)
            };
            if hit.bits() != 0 {
                best_t = hit.select(t, best_t);
                best_i = hit.select(p.tag, best_i);
            }
        }
        for s in &self.spheres {
            let Some((hit, t, slow)) = sphere_hit_t_in(o, d, s.center, s.r2, best_t, live) else {
                continue;
            };
            let slow = slow.bits() & live;
            let (hit, t) = if slow == 0 {
                (hit, t)
            } else {
                scalar_nearest(Shape::Sphere(s.sphere), rays, (hit, t), best_t, slow)
            };
            if hit.bits() != 0 {
                best_t = hit.select(t, best_t);
                best_i = hit.select(s.tag, best_i);
            }
        }
        let (best_t, best_i) = (best_t.to_array(), best_i.to_array());
        for (k, ray) in rays.iter().enumerate() {
            // Only the nearest hit gets its point, error bound and normal, as in the aggregate.
            let i = best_i.as_ref()[k].to_f64();
            out[k] = if i == 0.0 {
                None
            } else {
                // The tag is a small whole number (FlatScene::new): the u32 conversion is exact.
                let index = (i as u32 - 1) as usize;
                let t = best_t.as_ref()[k];
                // Shape::hit_at, each kind's own called here so that it is inlined and its hit
                // written in place.
                let hit = match &aggregate.shapes()[index] {
                    Shape::Plane(p) => Some(p.hit_at(ray, t)),
                    Shape::Sphere(s) => s.hit_at(ray, t),
                    shape => shape.hit_at(ray, t),
                };
                hit.map(|hit| AggregateHit { index, hit })
            };
        }
    }

    /// The shadow rays of a packet, any hit: bit k of the result is set where lane k of `want`
    /// is and some surface meets `rays[k]` with 0 < t < `t_max[k]` ([`Aggregate::occluded`] of
    /// that ray, to the bit). `rays` and `t_max` hold [`Wide::LANES`] entries; the lanes not
    /// wanted may hold any ray. The rays are gathered into lanes for
    /// [`FlatScene::occluded_lanes`].
    #[cfg(test)]
    pub(crate) fn occluded_packet(&self, rays: &[Ray<R>], t_max: &[R], want: u32) -> u32 {
        let lanes = W::<R>::LANES;
        debug_assert!(rays.len() == lanes && t_max.len() == lanes);
        let o = W3::<W<R>>::gather(rays.iter().map(|r| r.origin), rays[0].origin);
        let d = W3::<W<R>>::gather(rays.iter().map(|r| r.direction), rays[0].direction);
        let mut tm = <W<R> as Wide>::Array::default();
        tm.as_mut().copy_from_slice(t_max);
        self.occluded_lanes(o, d, W::<R>::from_array(tm), want)
    }

    /// The shadow rays of a packet in lanes (origins `o`, directions `d`, lengths `t_max`), as
    /// the wide tracer builds them, any hit: bit k is set where bit k of `want` is and some
    /// surface meets lane k's ray with 0 < t < lane k of `t_max` ([`Aggregate::occluded`] of
    /// that ray, to the bit). The lanes not wanted may hold anything (they are never read).
    /// Every shape is tested against the lanes not yet blocked at once, and the test stops as
    /// soon as every wanted lane is blocked (any hit: the order of the shapes changes the
    /// cost, never the answer).
    pub(crate) fn occluded_lanes(&self, o: W3<W<R>>, d: W3<W<R>>, t_max: W<R>, want: u32) -> u32 {
        let mut blocked = 0u32;
        for p in &self.planes {
            let open = want & !blocked;
            let Some((hit, _, slow)) = plane_hit_t(o, d, p.normal, p.point, t_max, open) else {
                continue;
            };
            blocked |= hit.bits() & open;
            let slow = slow.bits() & want & !blocked;
            if slow != 0 {
                blocked |= scalar_blocked(Shape::Plane(p.plane), o, d, t_max, slow);
            }
            if blocked == want {
                return want;
            }
        }
        for s in &self.spheres {
            let open = want & !blocked;
            let Some((hit, _, slow)) = sphere_hit_t_in(o, d, s.center, s.r2, t_max, open) else {
                continue;
            };
            blocked |= hit.bits() & open;
            let slow = slow.bits() & want & !blocked;
            if slow != 0 {
                blocked |= scalar_blocked(Shape::Sphere(s.sphere), o, d, t_max, slow);
            }
            if blocked == want {
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
    use crate::core::V3;

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
                // In lanes, the lanes not wanted holding NaN: the same answer.
                let nan = v3::<R>([f64::NAN; 3]);
                let pick = |k: usize, v: V3<R>| if want & (1 << k) != 0 { v } else { nan };
                let o =
                    W3::<W<R>>::gather(rs.iter().enumerate().map(|(k, r)| pick(k, r.origin)), nan);
                let d = W3::<W<R>>::gather(
                    rs.iter().enumerate().map(|(k, r)| pick(k, r.direction)),
                    nan,
                );
                let mut tm = <W<R> as Wide>::Array::default();
                tm.as_mut().copy_from_slice(&t_max);
                assert_eq!(flat.occluded_lanes(o, d, W::<R>::from_array(tm), want), got);
            }
        }
    }

    #[test]
    fn packets_and_shadow_rays_meet_what_the_aggregate_meets_in_both_precisions() {
        packets_and_shadow_rays_are_the_aggregates::<f32>();
        packets_and_shadow_rays_are_the_aggregates::<f64>();
    }
}
