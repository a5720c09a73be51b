//! Geometry: rays, the surfaces a ray problem or the tracer can hit, and what a hit hands on to
//! shading (the normal facing the ray, the rays spawned from it).
//!
//! Intersections return the parameter t along the *line* of the ray, of either sign: whether a
//! hit behind the origin (t ≤ 0) counts is the caller's decision (docs/conventions.md, "Ray
//! hits": a hit needs t > 0, and the solver reports what the line would give when it meets a
//! surface only behind). Each shape bounds the error of its own hit point (`Shape::hit_at`
//! only dispatches).

pub(crate) mod aggregate;
pub(crate) mod bounds;
pub(crate) mod bvh;
pub(crate) mod hit;
pub(crate) mod plane;
pub(crate) mod ray;
pub(crate) mod shadow;
pub(crate) mod soa;
pub(crate) mod sphere;
pub(crate) mod triangle;
pub(crate) mod wbvh;

pub use aggregate::{Aggregate, AggregateHit};
pub use bounds::Aabb;
pub use bvh::{Bvh, BvhHit};
pub use hit::{offset_origin, SurfaceHit};
pub use plane::Plane;
pub use ray::Ray;
pub use sphere::Sphere;
pub use triangle::{SmoothNormal, Triangle};

use crate::core::{Real, Vector, V3};

/// A surface of a ray problem or scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape<R: Real> {
    /// An infinite plane.
    Plane(Plane<R>),
    /// A sphere.
    Sphere(Sphere<R>),
    /// A triangle (a mesh is stored as its triangles).
    Triangle(Triangle<R>),
}

/// Where the line of a ray meets a surface: up to two parameters, nearest first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineHits<R: Real> {
    /// The parameters t of the meetings along the line (of either sign), nearest first;
    /// `None` where there are fewer than two.
    pub t: [Option<R>; 2],
}

impl<R: Real> LineHits<R> {
    pub(crate) const NONE: Self = LineHits { t: [None, None] };

    /// The nearest hit in front of the origin (t > 0).
    pub fn nearest_in_front(&self) -> Option<R> {
        self.t.iter().flatten().copied().find(|&t| t > R::ZERO)
    }

    /// The hit behind the origin (t < 0) nearest to it.
    pub(crate) fn nearest_behind(&self) -> Option<R> {
        self.t
            .iter()
            .rev()
            .flatten()
            .copied()
            .find(|&t| t < R::ZERO)
    }

    /// Whether the line meets the surface exactly at the origin (t = 0).
    pub(crate) fn at_origin(&self) -> bool {
        self.t.iter().flatten().any(|&t| t == R::ZERO)
    }
}

impl<R: Real> Shape<R> {
    /// The box around the surface; `None` for a plane, which has none.
    pub(crate) fn bounds(&self) -> Option<Aabb<R>> {
        match self {
            Shape::Plane(_) => None,
            Shape::Sphere(s) => Some(Aabb::of_sphere(s.center, s.radius)),
            Shape::Triangle(t) => Some(t.bounds()),
        }
    }

    /// The parameters where the ray's line meets the surface.
    pub(crate) fn line_hits(&self, ray: &Ray<R>) -> LineHits<R> {
        match self {
            Shape::Plane(p) => LineHits {
                t: [p.intersect_line(ray), None],
            },
            Shape::Sphere(s) => s.intersect_line(ray),
            Shape::Triangle(t) => LineHits {
                t: [t.line_t(ray), None],
            },
        }
    }

    /// The nearest t with 0 < t < `t_max` where the ray meets the surface: the cheap test the
    /// BVH asks of every candidate; `Shape::hit_at` then completes the winner.
    #[inline]
    pub fn hit_t(&self, ray: &Ray<R>, t_max: R) -> Option<R> {
        let inside = |t: &R| *t > R::ZERO && *t < t_max;
        match self {
            Shape::Plane(pl) => pl.intersect_line(ray).filter(inside),
            Shape::Sphere(s) => {
                // Outside the sphere and moving away: both roots are behind the origin.
                let f = ray.origin - s.center;
                if ray.direction.dot(f) > R::ZERO && f.dot(f) > s.radius * s.radius {
                    return None;
                }
                s.intersect_line(ray).t.into_iter().flatten().find(inside)
            }
            Shape::Triangle(tri) => tri.intersect(ray, t_max).map(|h| h.t),
        }
    }

    /// The nearest hit with 0 < t < `t_max`, its point computed the accurate way for the shape
    /// and bounded in error (for `SurfaceHit::spawn_ray`). This is the one intersection
    /// routine of the tracer and of the solver's ray problems.
    #[inline]
    pub fn hit(&self, ray: &Ray<R>, t_max: R) -> Option<SurfaceHit<R>> {
        match self {
            Shape::Triangle(tri) => tri.hit(ray, t_max),
            _ => self.hit_at(ray, self.hit_t(ray, t_max)?),
        }
    }

    /// The hit at a t found by [`Shape::hit_t`], each shape's point and error bound its own.
    #[inline]
    pub(crate) fn hit_at(&self, ray: &Ray<R>, t: R) -> Option<SurfaceHit<R>> {
        match self {
            Shape::Plane(pl) => Some(pl.hit_at(ray, t)),
            Shape::Sphere(s) => s.hit_at(ray, t),
            // The same t again, with the barycentric point and its error bound.
            Shape::Triangle(tri) => tri.hit(ray, t.next_up()),
        }
    }

    /// Whether the ray's whole line lies on the surface (a plane it lies in,
    /// [`Plane::contains_line`]); a sphere or a triangle never holds a whole line.
    pub(crate) fn contains_line(&self, ray: &Ray<R>) -> bool {
        match self {
            Shape::Plane(p) => p.contains_line(ray),
            Shape::Sphere(_) | Shape::Triangle(_) => false,
        }
    }

    /// The point at t, re-projected onto the surface where that reduces rounding error.
    pub(crate) fn point_at(&self, ray: &Ray<R>, t: R) -> V3<R> {
        match self {
            Shape::Plane(_) | Shape::Triangle(_) => ray.at(t),
            Shape::Sphere(s) => s.project(ray.at(t)),
        }
    }

    /// The surface's own unit normal at a point on it (the plane's as given, the sphere's
    /// outward); turning it to face a ray is the caller's choice. `None` when the precision
    /// cannot resolve it (see [`Sphere::normal_at`]).
    pub(crate) fn normal_at(&self, p: V3<R>) -> Option<V3<R>> {
        match self {
            Shape::Plane(pl) => Some(pl.normal),
            Shape::Sphere(s) => s.normal_at(p),
            Shape::Triangle(t) => t.normal(),
        }
    }

    /// The unit normal to shade with at a point `p` on the surface whose own normal there is
    /// `normal`: `normal`, except on a smooth triangle ([`Triangle::shading_at`]).
    pub(crate) fn shading_at(&self, p: V3<R>, normal: V3<R>) -> V3<R> {
        match self {
            Shape::Triangle(t) => t.shading_at(p, normal),
            _ => normal,
        }
    }

    /// "plane", "sphere" or "triangle".
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            Shape::Plane(_) => "plane",
            Shape::Sphere(_) => "sphere",
            Shape::Triangle(_) => "triangle",
        }
    }
}
