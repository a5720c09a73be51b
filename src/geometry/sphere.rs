//! A sphere, intersected with the numerically stable quadratic (pbrt-v4).

use super::hit::SurfaceHit;
use super::ray::Ray;
use super::LineHits;
use crate::core::rounding::gamma;
use crate::core::vector::{length, normalize};
use crate::core::{Real, Vector, V3};

/// The sphere ‖X − C‖ = r.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<R: Real> {
    /// C, the centre.
    pub center: V3<R>,
    /// r > 0.
    pub radius: R,
}

impl<R: Real> Sphere<R> {
    /// The parameters t0 ≤ t1 where the ray's line meets the sphere, of either sign.
    ///
    /// With f = O − C and unit D: b' = D·f, and the discriminant is formed as
    /// (r − ‖f − b'D‖)(r + ‖f − b'D‖), from the distance of the line to C, which does not cancel
    /// the way b'² − (f·f − r²) does for a small sphere far away. Then q = −(b' + sign(b')·√disc),
    /// t0 = q, t1 = c/q with c = (‖f‖ − r)(‖f‖ + r): no cancellation in either root. Where the
    /// squares are representable they are used directly (r² − ‖f − b'D‖², f·f − r²); otherwise
    /// the lengths are the robust ones, so nothing is squared that could overflow.
    #[inline]
    pub fn intersect_line(&self, ray: &Ray<R>) -> LineHits<R> {
        let f = ray.origin - self.center;
        let b = ray.direction.dot(f);
        let q = f - ray.direction * b;
        let (perp2, r2, ff) = (q.dot(q), self.radius * self.radius, f.dot(f));
        let safe = |x: R| x == R::ZERO || (x > R::SAFE_SQUARED_MIN && x < R::SAFE_SQUARED_MAX);
        let (mut t0, mut t1) = if safe(perp2) && safe(r2) && safe(ff) {
            // The squares are representable: disc = r² − ‖f − b'D‖² and c = f·f − r², each as
            // accurate as the products of lengths below, with one square root.
            let disc = r2 - perp2;
            if disc < R::ZERO {
                return LineHits::NONE;
            }
            let root = disc.sqrt();
            let q = if b < R::ZERO { -b + root } else { -b - root };
            if q == R::ZERO {
                (R::ZERO, R::ZERO)
            } else {
                (q, (ff - r2) / q)
            }
        } else {
            // Huge or tiny: the same with robust lengths, nothing squared that could overflow.
            let perp = length::<R>(q);
            let disc = (self.radius - perp) * (self.radius + perp);
            // A negative (or NaN) discriminant: the line misses.
            if disc.partial_cmp(&R::ZERO).is_none_or(|o| o.is_lt()) {
                return LineHits::NONE;
            }
            let root = disc.sqrt();
            let q = if b < R::ZERO { -b + root } else { -b - root };
            let dist = length::<R>(f);
            // t1 = c/q, with c = (‖f‖ − r)(‖f‖ + r) divided before it is multiplied out, so that
            // c itself (the square of a large distance) is never formed.
            if q == R::ZERO {
                (R::ZERO, R::ZERO)
            } else {
                (q, (dist - self.radius) * ((dist + self.radius) / q))
            }
        };
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        if t0.is_finite() && t1.is_finite() {
            LineHits {
                t: [Some(t0), Some(t1)],
            }
        } else {
            LineHits::NONE
        }
    }

    /// The hit at a t found by [`Sphere::intersect_line`]: O + tD re-projected onto the sphere,
    /// bounded in error, with the outward normal; `None` when the precision cannot resolve the
    /// normal (see [`Sphere::normal_at`]).
    #[inline]
    pub(crate) fn hit_at(&self, ray: &Ray<R>, t: R) -> Option<SurfaceHit<R>> {
        // The point's error bound: C + r·(P − C)/‖P − C‖ is a few roundings of |C| and |P|
        // (pbrt re-projects in object space; here C is not at the origin).
        let p = self.project(ray.at(t));
        let normal = self.normal_at(p)?;
        Some(SurfaceHit {
            t,
            p,
            p_error: self.center.abs() * gamma::<R>(6) + p.abs() * gamma::<R>(6),
            normal,
            shading: normal,
        })
    }

    /// The outward unit normal at a point on the sphere; `None` when the point cannot be told
    /// from the centre in this precision (a radius below the rounding of the coordinates).
    #[inline]
    pub(crate) fn normal_at(&self, p: V3<R>) -> Option<V3<R>> {
        normalize::<R>(p - self.center).map(|n| n.unit)
    }

    /// Moves a point computed as O + tD back onto the sphere's surface.
    #[inline]
    pub(crate) fn project(&self, p: V3<R>) -> V3<R> {
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
        assert_eq!(s.intersect_line(&ray).t, [Some(4.0), Some(6.0)]);
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
        assert_eq!(s.intersect_line(&ray).t, [Some(-2.0), Some(2.0)]);
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
        let t0 = s.intersect_line(&ray).t[0].unwrap();
        let expected = 1e7 - (1.0f64 - 0.25).sqrt();
        assert!((t0 - expected).abs() < 1e-8, "{t0} vs {expected}");
    }

    #[test]
    fn huge_sphere_far_away_is_hit_without_overflow() {
        // Radius 1e150 at the origin, ray from z = 1e160 downwards: squares would overflow.
        let s = Sphere::<f64> {
            center: DVec3::ZERO,
            radius: 1e150,
        };
        let ray = Ray::<f64> {
            origin: DVec3::new(0.0, 0.0, 1e160),
            direction: DVec3::new(0.0, 0.0, -1.0),
        };
        let t = s.intersect_line(&ray).t;
        assert_eq!(t, [Some(1e160 - 1e150), Some(1e160 + 1e150)]);
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
        assert_eq!(s.intersect_line(&ray), LineHits::NONE);
    }
}
