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

/// The largest magnitude B a coordinate of a point the intersection tests take may have in
/// precision `R`, and a sphere's radius: 1e100 in f64, 1e12 in f32. Validation holds to it
/// every point a ray starts from or is tested against, in a problem file and in an OBJ mesh: a
/// ray problem's origin, the camera's eye and look-at point, a sphere's centre and radius, a
/// plane's point, a triangle's corners. Past it a product in a test can overflow to infinity
/// (or NaN) and a ray miss a surface without a word. Each test's need, with every coordinate
/// (and r) within ±B, so that a difference of two points is within ±2B per coordinate and
/// ‖O − X‖ ≤ 2√3·B:
///
/// - a triangle ([`Triangle`], watertight): it multiplies up to three coordinates taken
///   relative to the ray's origin: the sheared coordinates are within ±4B, the edge functions
///   within ±32B² and the scaled distance t·det within ±333B³ (the direction's largest
///   component is at least 1/√3). Finite while 333B³ ≤ MAX: B ≤ (MAX/333)^(1/3), 8.1e101 in
///   f64 and 1.0e12 in f32 (a triangle at ±1e300 was missed by a ray through its middle; at
///   ±1e308 its edges overflowed and it was taken for one whose corners lie on one line).
/// - a sphere ([`Sphere::intersect_line`], and the wide engine's `soa::sphere_hit_t`): with
///   f = O − C (‖f‖ ≤ 2√3·B) and q = f − (D·f)D, the part of f across the ray (‖q‖ ≤ ‖f‖), the
///   largest product is the discriminant (r − ‖q‖)(r + ‖q‖), or r² − ‖q‖² and f·f where the
///   squares are in range, each at most (r + ‖f‖)² ≤ (1 + 2√3)²B² ≈ 20B²; q = −(D·f ± √disc)
///   is then at most 8B. Finite while 20B² ≤ MAX: B ≤ √(MAX/20), 3.0e153 in f64 and 4.1e18
///   in f32 (a sphere of radius 1e199 at 1e200 was missed by the ray through its centre: the
///   discriminant was infinite).
/// - a plane ([`Plane`]): N·(Q − O) over N·D multiplies no two coordinates (and halves Q and
///   O where Q − O overflows), but its hit is the origin of the rays spawned from it, which the
///   other tests take within the bound (a hit far along a ray that grazes the plane may still
///   lie beyond it: the bound is on what the file gives).
/// - the camera: look_at − eye, within ±2B.
///
/// The triangle's bound is the tightest, and it is the one bound for all, rounded down to a
/// power of ten: one rule to state ("coordinates within ±1e100"), which keeps every test
/// finite. It bounds overflow, not resolution: a sphere of radius 1 at 1e20 is within it, and
/// still too small for f64 to resolve its normal there (the solver says so).
pub(crate) fn max_coordinate<R: Real>() -> f64 {
    if R::EPSILON.to_f64() > f64::EPSILON {
        1e12
    } else {
        1e100
    }
}

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
