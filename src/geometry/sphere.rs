//! A sphere, intersected with the numerically stable quadratic (pbrt-v4).

use super::ray::Ray;
use crate::core::vector::normalize;
use crate::core::{Real, Vector, V3};

/// The sphere ‖X − C‖ = r.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<R: Real> {
    pub center: V3<R>,
    /// r > 0.
    pub radius: R,
}

impl<R: Real> Sphere<R> {
    /// The two parameters where the ray's line meets the sphere, t0 ≤ t1, of either sign.
    ///
    /// With f = O − C and unit D: b' = D·f, and the discriminant is formed as
    /// r² − ‖f − b'D‖² (the distance of the line from C), which does not cancel the way
    /// b'² − (f·f − r²) does for a small sphere far away. Then q = −(b' + sign(b')·√disc),
    /// t0 = q, t1 = c/q (no cancellation in either root).
    #[inline]
    pub fn intersect_line(&self, ray: &Ray<R>) -> Option<(R, R)> {
        let f = ray.origin - self.center;
        let b = ray.direction.dot(f);
        let perp = f - ray.direction * b;
        let disc = (self.radius - perp.naive_length()) * (self.radius + perp.naive_length());
        if disc < R::ZERO {
            return None;
        }
        let root = disc.sqrt();
        let q = if b < R::ZERO { -b + root } else { -b - root };
        let c = (f.naive_length() - self.radius) * (f.naive_length() + self.radius);
        let (mut t0, mut t1) = if q == R::ZERO {
            (R::ZERO, R::ZERO)
        } else {
            (q, c / q)
        };
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        (t0.is_finite() && t1.is_finite()).then_some((t0, t1))
    }

    /// The outward unit normal at a point on the sphere.
    #[inline]
    pub fn normal_at(&self, p: V3<R>) -> V3<R> {
        normalize::<R>(p - self.center).map_or(V3::<R>::ZERO, |n| n.unit)
    }

    /// Moves a point computed as O + tD back onto the sphere's surface.
    #[inline]
    pub fn project(&self, p: V3<R>) -> V3<R> {
        match normalize::<R>(p - self.center) {
            Some(n) => self.center + n.unit * self.radius,
            None => p,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn ray_through_centre_meets_sphere_at_both_sides() {
        let s = Sphere::<f64> {
            center: DVec3::new(0.0, 0.0, -5.0),
            radius: 1.0,
        };
        let ray = Ray::<f64> {
            origin: DVec3::ZERO,
            direction: DVec3::new(0.0, 0.0, -1.0),
        };
        assert_eq!(s.intersect_line(&ray), Some((4.0, 6.0)));
    }

    #[test]
    fn ray_from_inside_has_one_root_behind_and_one_in_front() {
        let s = Sphere::<f64> {
            center: DVec3::ZERO,
            radius: 2.0,
        };
        let ray = Ray::<f64> {
            origin: DVec3::ZERO,
            direction: DVec3::X,
        };
        assert_eq!(s.intersect_line(&ray), Some((-2.0, 2.0)));
    }

    #[test]
    fn small_far_sphere_is_hit_accurately() {
        // A sphere of radius 1 at distance 1e7: the naive discriminant loses every digit.
        let s = Sphere::<f64> {
            center: DVec3::new(0.0, 0.0, -1e7),
            radius: 1.0,
        };
        let ray = Ray::<f64> {
            origin: DVec3::new(0.5, 0.0, 0.0),
            direction: DVec3::new(0.0, 0.0, -1.0),
        };
        let (t0, _) = s.intersect_line(&ray).unwrap();
        let expected = 1e7 - (1.0f64 - 0.25).sqrt();
        assert!((t0 - expected).abs() < 1e-8, "{t0} vs {expected}");
    }

    #[test]
    fn line_that_passes_by_misses() {
        let s = Sphere::<f64> {
            center: DVec3::new(0.0, 3.0, -5.0),
            radius: 1.0,
        };
        let ray = Ray::<f64> {
            origin: DVec3::ZERO,
            direction: DVec3::new(0.0, 0.0, -1.0),
        };
        assert_eq!(s.intersect_line(&ray), None);
    }
}
