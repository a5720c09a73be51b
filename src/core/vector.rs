//! Robust vector operations: lengths and unit vectors that neither underflow nor overflow.
//!
//! `x*x + y*y + z*z` underflows to zero for a vector of length 1e-300 and overflows for 1e300 in
//! f64 (1e-30 and 1e30 in f32). Scaling by the largest component first keeps every square in
//! [0, 1], so [`normalize`] works for any finite non-zero vector.

use super::lanes::{LaneVec, Lanes, Mask};
use super::real::{Real, Vector, V3};

/// A unit vector together with the length of the vector it came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Normalized<R: Real> {
    /// v/‖v‖, of length 1 within rounding.
    pub unit: V3<R>,
    /// ‖v‖; may be +inf when the true length exceeds the precision's range (|v| near MAX).
    pub length: R,
}

/// Normalises `v` without needless underflow or overflow. `None` for a zero or non-finite vector.
#[inline]
pub(crate) fn normalize<R: Real>(v: V3<R>) -> Option<Normalized<R>> {
    // The common case: v·v neither overflows nor underflows, so ‖v‖ = √(v·v).
    let sq = v.dot(v);
    if sq > R::SAFE_SQUARED_MIN && sq < R::SAFE_SQUARED_MAX {
        let length = sq.sqrt();
        return Some(Normalized {
            unit: v * (R::ONE / length),
            length,
        });
    }
    if !v.is_finite() {
        return None;
    }
    // Scale by the largest magnitude so that the squares stay in [0, 1].
    let m = v.abs().max_element();
    if m == R::ZERO {
        return None;
    }
    let w = v / m;
    let l = w.naive_length(); // in [1, √3]
    Some(Normalized {
        unit: w / l,
        length: m * l,
    })
}

/// The unit vector from `a` to `b` and the distance between them, robust where `b − a`
/// overflows although both points are finite (it then works on the halves; the distance may
/// still be +inf, which the caller must treat as out of range). `None` only when `a == b` or a
/// point is not finite.
#[inline]
pub fn between<R: Real>(a: V3<R>, b: V3<R>) -> Option<Normalized<R>> {
    let d = b - a;
    if d.is_finite() {
        return normalize(d);
    }
    if !(a.is_finite() && b.is_finite()) {
        return None;
    }
    let half = R::ONE / R::TWO;
    normalize::<R>(b * half - a * half).map(|n| Normalized {
        unit: n.unit,
        length: n.length * R::TWO,
    })
}

/// [`between`] in [`Lanes`]: the unit vectors from `a` to `b` and the distances, `found` where
/// [`between`] gives `Some` (elsewhere a zero vector and length 0).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneNormalized<L: Lanes> {
    /// (b − a)/‖b − a‖.
    pub unit: L::V,
    /// ‖b − a‖.
    pub length: L,
    /// The lanes with a direction.
    pub found: L::Mask,
}

/// [`between`] in every lane: the common case (b − a finite, its squared length in the safe
/// range) in lanes with [`normalize`]'s own operations, every other lane by [`between`] itself.
#[inline(always)]
pub(crate) fn between_lanes<L: Lanes>(a: L::V, b: L::V) -> LaneNormalized<L> {
    let one = L::broadcast(<L::Scalar as Real>::ONE);
    let d = b.minus(a);
    let sq = d.dot3(d);
    let fast = sq
        .greater(L::broadcast(<L::Scalar as Real>::SAFE_SQUARED_MIN))
        .both(sq.less(L::broadcast(<L::Scalar as Real>::SAFE_SQUARED_MAX)));
    let length = sq.root();
    let unit = d.scaled(one / length);
    let slow = fast.invert();
    if !slow.any() {
        return LaneNormalized {
            unit,
            length,
            found: fast,
        };
    }
    let mut robust: [Option<Normalized<L::Scalar>>; 8] = [None; 8];
    let zero = <L::Scalar as Real>::ZERO;
    let mut found = L::pick(fast, one, L::broadcast(zero));
    found = found.map_lanes(slow, |k, _| {
        robust[k] = between::<L::Scalar>(a.lane(k), b.lane(k));
        if robust[k].is_some() {
            <L::Scalar as Real>::ONE
        } else {
            zero
        }
    });
    LaneNormalized {
        unit: unit.map_lanes(slow, |k, _| {
            robust[k].map_or(V3::<L::Scalar>::ZERO, |n| n.unit)
        }),
        length: length.map_lanes(slow, |k, _| robust[k].map_or(zero, |n| n.length)),
        found: found.greater(L::broadcast(zero)),
    }
}

/// The robust Euclidean length ‖v‖ (0 for the zero vector).
#[inline]
pub(crate) fn length<R: Real>(v: V3<R>) -> R {
    let sq = v.dot(v);
    if sq > R::SAFE_SQUARED_MIN && sq < R::SAFE_SQUARED_MAX {
        return sq.sqrt();
    }
    normalize(v).map_or(R::ZERO, |n| n.length)
}

/// Whether `v` (a unit-normalised input) differed in length from 1 by more than rounding.
#[inline]
pub(crate) fn is_unit_length<R: Real>(length: R) -> bool {
    (length - R::ONE).abs() <= R::from_f64(8.0) * R::EPSILON
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3A};

    fn check_f64(scale: f64) {
        let n = normalize::<f64>(DVec3::new(3.0, 0.0, 4.0) * scale).unwrap();
        assert!((n.unit - DVec3::new(0.6, 0.0, 0.8)).abs().max_element() < 1e-15);
        assert!((n.length / (5.0 * scale) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn normalize_survives_tiny_and_huge_vectors_in_f64() {
        for s in [1e-300, 1e-6, 1.0, 1e6, 1e300] {
            check_f64(s);
        }
    }

    #[test]
    fn normalize_survives_tiny_and_huge_vectors_in_f32() {
        for s in [1e-30f32, 1e-6, 1.0, 1e6, 1e30] {
            let n = normalize::<f32>(Vec3A::new(3.0, 0.0, 4.0) * s).unwrap();
            assert!((n.unit - Vec3A::new(0.6, 0.0, 0.8)).abs().max_element() < 1e-6);
        }
    }

    #[test]
    fn direction_between_far_apart_points_survives_overflow_of_the_difference() {
        let a = DVec3::new(-1e308, 0.0, 0.0);
        let b = DVec3::new(1e308, 0.0, 0.0);
        let n = between::<f64>(a, b).unwrap();
        assert_eq!(n.unit, DVec3::X);
        assert!(n.length.is_infinite(), "2e308 is beyond f64");
        assert!(between::<f64>(b, b).is_none());
    }

    #[test]
    fn zero_and_non_finite_vectors_have_no_direction() {
        assert!(normalize::<f64>(DVec3::ZERO).is_none());
        assert!(normalize::<f64>(DVec3::new(f64::NAN, 0.0, 1.0)).is_none());
        assert!(normalize::<f64>(DVec3::new(f64::INFINITY, 0.0, 1.0)).is_none());
    }
}
