//! An infinite plane through a point with a unit normal.

use super::hit::SurfaceHit;
use super::ray::Ray;
use crate::core::rounding::gamma;
use crate::core::{Real, Vector, V3};

/// The plane N·(X − Q) = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<R: Real> {
    /// Q, a point on the plane.
    pub point: V3<R>,
    /// N, unit length, as given (not turned towards anything).
    pub normal: V3<R>,
}

impl<R: Real> Plane<R> {
    /// t where the ray's line meets the plane, of either sign: t = N·(Q − O) / (N·D).
    /// `None` when the line is parallel to the plane (or lies in it), and when the meeting point
    /// O + tD lies beyond the range of `R`: a point that cannot be represented is no meeting
    /// point (docs/conventions.md, "Hits beyond the floating-point range"), so neither the tracer
    /// nor the solver shades, prints or spawns a ray from an infinite point.
    #[inline]
    pub(crate) fn intersect_line(&self, ray: &Ray<R>) -> Option<R> {
        let denom = self.normal.dot(ray.direction);
        if denom == R::ZERO {
            return None;
        }
        // Q − O may overflow although both are finite: then work on the halves.
        let diff = self.point - ray.origin;
        let along = if diff.is_finite() {
            self.normal.dot(diff)
        } else {
            let half = R::ONE / R::TWO;
            self.normal.dot(self.point * half - ray.origin * half) * R::TWO
        };
        let t = along / denom;
        (t.is_finite() && ray.at(t).is_finite()).then_some(t)
    }

    /// Whether the ray's line lies in the plane as computed: N·D = 0 and N·(Q − O) = 0. Such a
    /// line meets the plane at every point, so [`Plane::intersect_line`] has no single t for it
    /// (docs/conventions.md, "Ray hits"); the solver says so rather than "no hit".
    pub(crate) fn contains_line(&self, ray: &Ray<R>) -> bool {
        self.normal.dot(ray.direction) == R::ZERO
            && self.normal.dot(self.point - ray.origin) == R::ZERO
    }

    /// The hit at a t found by [`Plane::intersect_line`]: O + tD, bounded in error, with the
    /// plane's normal as given.
    #[inline]
    pub(crate) fn hit_at(&self, ray: &Ray<R>, t: R) -> SurfaceHit<R> {
        // The point's error bound: t carries the rounding of N·(Q − O)/(N·D); O + tD adds two
        // more. (Each term is scaled by γ before the sum, which could overflow near the range's
        // end.)
        let p = ray.at(t);
        let g = gamma::<R>(7);
        let p_error = ray.origin.abs() * g + self.point.abs() * g + (ray.direction * t).abs() * g;
        SurfaceHit {
            t,
            p,
            p_error,
            normal: self.normal,
            shading: self.normal,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn line_meets_plane_behind_the_origin_with_negative_t() {
        // Exercise 4.3: 18 + 0.2·t/... = 0 along D = (0.8, 0, −0.6) from (8, 4, 6).
        let n = DVec3::ONE / 3f64.sqrt();
        let plane = Plane::<f64> {
            point: DVec3::ZERO,
            normal: n,
        };
        let ray = Ray::<f64> {
            origin: DVec3::new(8.0, 4.0, 6.0),
            direction: DVec3::new(0.8, 0.0, -0.6),
        };
        let t = plane.intersect_line(&ray).unwrap();
        assert!((t + 90.0).abs() < 1e-12, "t = {t}");
    }

    #[test]
    fn a_meeting_point_beyond_the_range_is_no_meeting_point() {
        // From (1e308, 1e308, 0) along (−0.8, −0.6, 0), the floor y = 0 is met at t = 1e308/0.6
        // and x = 1e308 − 0.8·t = −1e308/3: representable. From (0, 1e308, 0) with the ray
        // nearly level (D_y ≈ −1e-10) it is met at x ≈ −1e318: beyond f64, so not met.
        let plane = Plane::<f64> {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        let steep = Ray::<f64> {
            origin: DVec3::new(1e308, 1e308, 0.0),
            direction: DVec3::new(-0.8, -0.6, 0.0),
        };
        let t = plane
            .intersect_line(&steep)
            .expect("met at x = −(1/3)·1e308");
        assert!(
            (steep.at(t).x + 1e308 / 3.0).abs() < 1e293,
            "{:?}",
            steep.at(t)
        );
        let level = Ray::<f64> {
            origin: DVec3::new(0.0, 1e308, 0.0),
            direction: DVec3::new(-1.0, -1e-10, 0.0).normalize(),
        };
        assert_eq!(plane.intersect_line(&level), None);
    }

    #[test]
    fn parallel_line_misses_plane() {
        let plane = Plane::<f64> {
            point: DVec3::ZERO,
            normal: DVec3::Z,
        };
        let ray = Ray::<f64> {
            origin: DVec3::new(0.0, 0.0, 1.0),
            direction: DVec3::X,
        };
        assert_eq!(plane.intersect_line(&ray), None);
    }
}
