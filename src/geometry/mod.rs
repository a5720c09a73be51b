//! Geometry: rays and the surfaces a ray problem (and later the tracer) can hit.
//!
//! Intersections return the parameter t along the *line* of the ray, of either sign: whether a
//! hit behind the origin (t ≤ 0) counts is the caller's decision (DESIGN.md: a hit needs t > 0,
//! and the solver reports what the line would give when it meets a surface only behind).

pub mod plane;
pub mod ray;
pub mod sphere;

pub use plane::Plane;
pub use ray::Ray;
pub use sphere::Sphere;

use crate::core::{Real, V3};

/// A surface of a ray problem or scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape<R: Real> {
    Plane(Plane<R>),
    Sphere(Sphere<R>),
}

/// Where the line of a ray meets a surface: up to two parameters, nearest first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineHits<R: Real> {
    pub t: [Option<R>; 2],
}

impl<R: Real> LineHits<R> {
    pub const NONE: Self = LineHits { t: [None, None] };

    /// The nearest hit in front of the origin (t > 0).
    pub fn nearest_in_front(&self) -> Option<R> {
        self.t.iter().flatten().copied().find(|&t| t > R::ZERO)
    }

    /// The hit behind the origin (t < 0) nearest to it.
    pub fn nearest_behind(&self) -> Option<R> {
        self.t
            .iter()
            .rev()
            .flatten()
            .copied()
            .find(|&t| t < R::ZERO)
    }

    /// Whether the line meets the surface exactly at the origin (t = 0).
    pub fn at_origin(&self) -> bool {
        self.t.iter().flatten().any(|&t| t == R::ZERO)
    }
}

impl<R: Real> Shape<R> {
    /// The parameters where the ray's line meets the surface.
    pub fn line_hits(&self, ray: &Ray<R>) -> LineHits<R> {
        match self {
            Shape::Plane(p) => LineHits {
                t: [p.intersect_line(ray), None],
            },
            Shape::Sphere(s) => s.intersect_line(ray),
        }
    }

    /// The point at t, re-projected onto the surface where that reduces rounding error.
    pub fn point_at(&self, ray: &Ray<R>, t: R) -> V3<R> {
        match self {
            Shape::Plane(_) => ray.at(t),
            Shape::Sphere(s) => s.project(ray.at(t)),
        }
    }

    /// The surface's own unit normal at a point on it (the plane's as given, the sphere's
    /// outward); turning it to face a ray is the caller's choice. `None` when the precision
    /// cannot resolve it (see [`Sphere::normal_at`]).
    pub fn normal_at(&self, p: V3<R>) -> Option<V3<R>> {
        match self {
            Shape::Plane(pl) => Some(pl.normal),
            Shape::Sphere(s) => s.normal_at(p),
        }
    }

    /// "plane" or "sphere".
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Plane(_) => "plane",
            Shape::Sphere(_) => "sphere",
        }
    }
}
