//! A ray's hit on a surface, with the error bound of the computed point, and what a shading step
//! does with it, as pbrt-v4's `Interaction` does: the normal turned to face the incoming ray
//! (`FaceForward`), and the rays spawned from it (`SpawnRay`, `OffsetRayOrigin`): offset along
//! the geometric normal by the error bound, so a secondary or shadow ray never re-hits the
//! surface it leaves, at any scale, without a global epsilon. The tracer and the solver's ray
//! problems both take these from the hit, so a pixel's ray and the same ray as a ray problem
//! are shaded with the same normal and the same shadow rays by construction.

use super::aggregate::Aggregate;
use super::shadow::ShadowRays;
use super::{Ray, Shape};
use crate::core::lanes::{LaneVec, Lanes};
use crate::core::rounding::gamma;
use crate::core::{Real, Vector, V3};

/// Where a ray meets a surface (t > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit<R: Real> {
    /// The ray parameter.
    pub t: R,
    /// The hit point, computed the surface's most accurate way (re-projected onto a sphere,
    /// interpolated from a triangle's corners).
    pub p: V3<R>,
    /// A bound on the absolute error of each component of `p`.
    pub p_error: V3<R>,
    /// The surface's own unit normal at `p` (a plane's as given, a sphere's outward, a
    /// triangle's (v1 − v0) × (v2 − v0)): the geometric normal, which decides which side of
    /// the surface a ray is on (`SurfaceHit::facing`) and where spawned rays leave from.
    pub normal: V3<R>,
    /// The unit normal to shade with, on the same side of the surface as `normal`: `normal`
    /// itself, except on a smooth triangle (a mesh with vertex normals), where it is the
    /// barycentric interpolation of the three vertex normals, normalised (or `normal` where
    /// that interpolation does not lie on `normal`'s side; docs/conventions.md, "Smooth
    /// meshes"). `SurfaceHit::facing` turns it to the ray with `normal`'s turn.
    pub shading: V3<R>,
}

/// The normal used at a hit: the shading normal, turned to face the incoming ray by the test
/// on the surface's own (geometric) normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facing<R: Real> {
    /// The shading normal on the side the ray comes from: N_g·D ≤ 0 for the geometric normal
    /// N_g so turned (and N·D ≤ 0 too wherever N is N_g: every surface but a smooth triangle).
    pub normal: V3<R>,
    /// Whether the surface's own normal was reversed to get it.
    pub reversed: bool,
}

impl<R: Real> SurfaceHit<R> {
    /// The point where the ray's *line* meets `shape` at a t behind the origin (t < 0): what
    /// the solver shades as the line's reading of a ray that meets its surface only behind
    /// (docs/conventions.md, "Ray hits"). `None` when the precision cannot resolve the normal
    /// there (see [`super::Sphere::normal_at`]).
    pub(crate) fn behind_origin(shape: &Shape<R>, ray: &Ray<R>, t: R) -> Option<Self> {
        // The point's error bound, for any shape: O, P and tD each a few roundings off.
        let p = shape.point_at(ray, t);
        let normal = shape.normal_at(p)?;
        Some(SurfaceHit {
            t,
            p,
            p_error: (ray.origin.abs() + p.abs() + (ray.direction * t).abs()) * gamma::<R>(8),
            normal,
            shading: shape.shading_at(p, normal),
        })
    }

    /// The normal to shade with, turned to face a ray arriving along `incoming` (pbrt-v4's
    /// `FaceForward`; docs/conventions.md, "Orientation", "Smooth meshes"): the shading normal,
    /// reversed when the geometric normal has N_g·D > 0, so that a primary ray sees the side it
    /// comes from. This is the one place the tracer (both engines' shading and the reflection
    /// direction, Eq. 4.17) and the solver take the normal from.
    #[inline]
    pub(crate) fn facing(&self, incoming: V3<R>) -> Facing<R> {
        let reversed = self.normal.dot(incoming) > R::ZERO;
        Facing {
            normal: if reversed {
                -self.shading
            } else {
                self.shading
            },
            reversed,
        }
    }

    /// The origin of a ray leaving the hit in direction `w` ([`offset_origin`] of the point,
    /// its error bound and the surface's own normal).
    #[inline]
    pub(crate) fn spawn_origin(&self, w: V3<R>) -> V3<R> {
        offset_origin::<R>(self.p, self.p_error, self.normal, w)
    }

    /// The ray leaving the hit in the unit direction `w`, from [`SurfaceHit::spawn_origin`].
    #[inline]
    pub(crate) fn spawn_ray(&self, w: V3<R>) -> Ray<R> {
        Ray {
            origin: self.spawn_origin(w),
            direction: w,
        }
    }

    /// The shadow rays from the hit through `aggregate`, as the core's `Visibility`.
    #[inline]
    pub(crate) fn shadow_rays<'a>(&self, aggregate: &'a Aggregate<R>) -> ShadowRays<'a, R> {
        ShadowRays {
            aggregate,
            from: *self,
            traced: 0,
        }
    }
}

/// The origin of a ray leaving `p` in direction `w`: `p` moved off the surface along `n`, to the
/// side `w` goes, by the distance |n|·p_error that the error box of `p` can reach along `n`, each
/// component then rounded one step further away.
#[inline]
pub fn offset_origin<R: Real>(p: V3<R>, p_error: V3<R>, n: V3<R>, w: V3<R>) -> V3<R> {
    offset_origin_lanes::<R>(p, p_error, n, w)
}

/// [`offset_origin`] in [`Lanes`]: one ray's origin (L a precision, the scalar code) or one per
/// lane (L a register: the wide tracer's shadow rays), the same operations in the same order.
#[inline(always)]
pub(crate) fn offset_origin_lanes<L: Lanes>(p: L::V, p_error: L::V, n: L::V, w: L::V) -> L::V {
    let zero = L::broadcast(<L::Scalar as Real>::ZERO);
    let d = n.absolute().dot3(p_error);
    let offset = n.scaled(d);
    let offset = L::V::pick3(w.dot3(n).less(zero), offset.negated(), offset);
    let po = p.plus(offset);
    // Round away from p so that the rounding of the sum cannot undo the offset.
    let ((ox, oy, oz), (qx, qy, qz)) = (offset.parts(), po.parts());
    L::V::from_parts(qx.next_away(ox), qy.next_away(oy), qz.next_away(oz))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::v3;
    use crate::geometry::Plane;

    fn floor_hit<R: Real>() -> (Shape<R>, Ray<R>, SurfaceHit<R>) {
        let floor = Shape::Plane(Plane {
            point: v3::<R>([0.0, 0.0, 0.0]),
            normal: v3::<R>([0.0, 1.0, 0.0]),
        });
        let ray = Ray {
            origin: v3::<R>([0.0, 2.0, 0.0]),
            direction: v3::<R>([0.6, -0.8, 0.0]),
        };
        let hit = floor.hit(&ray, R::from_f64(f64::INFINITY)).expect("a hit");
        (floor, ray, hit)
    }

    fn the_hit_faces_the_ray_and_spawns_off_its_surface<R: Real>() {
        let (floor, ray, hit) = floor_hit::<R>();
        let from_above = hit.facing(ray.direction);
        assert_eq!(
            (from_above.normal, from_above.reversed),
            (hit.normal, false)
        );
        let from_below = hit.facing(-ray.direction);
        assert_eq!(
            (from_below.normal, from_below.reversed),
            (-hit.normal, true)
        );
        let up = v3::<R>([0.6, 0.8, 0.0]);
        let spawned = hit.spawn_ray(up);
        assert_eq!(spawned.direction, up);
        assert_eq!(
            spawned.origin,
            offset_origin::<R>(hit.p, hit.p_error, hit.normal, up)
        );
        assert!(spawned.origin.y() > R::ZERO, "{:?}", spawned.origin);
        assert_eq!(floor.hit_t(&spawned, R::from_f64(f64::INFINITY)), None);
    }

    fn a_line_behind_the_origin_gives_a_hit_with_a_bound<R: Real>() {
        let (floor, ray, _) = floor_hit::<R>();
        let back = Ray {
            direction: -ray.direction,
            ..ray
        };
        let hit = SurfaceHit::behind_origin(&floor, &back, R::from_f64(-2.5)).expect("a normal");
        assert_eq!(hit.normal, v3::<R>([0.0, 1.0, 0.0]));
        assert!(hit.p.y().abs() <= hit.p_error.y(), "{hit:?}");
    }

    #[test]
    fn a_hit_faces_spawns_and_reads_the_line_behind_in_both_precisions() {
        the_hit_faces_the_ray_and_spawns_off_its_surface::<f32>();
        the_hit_faces_the_ray_and_spawns_off_its_surface::<f64>();
        a_line_behind_the_origin_gives_a_hit_with_a_bound::<f32>();
        a_line_behind_the_origin_gives_a_hit_with_a_bound::<f64>();
    }
}
