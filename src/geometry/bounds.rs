//! Axis-aligned bounding boxes (pbrt-v4 `Bounds3`, §3.7), made conservative with the
//! rounding-error bound γ_n of [`crate::core::rounding::gamma`] (§6.8.1).
//!
//! The slab test [`Aabb::hit`] never rejects a box the ray really meets before `t_max`: the far
//! distances are scaled by 1 + 2γ₃ (pbrt §6.8.2), and a ray lying exactly in a slab's plane
//! (0·∞ = NaN) is taken to be inside that slab rather than outside it.

use crate::core::rounding::gamma;
use crate::core::{Real, Vector, V3};

/// Positive infinity of precision `R`.
#[inline]
pub(crate) fn infinity<R: Real>() -> R {
    R::from_f64(f64::INFINITY)
}

/// The box [min, max]; empty when min > max on some axis (`Aabb::empty` is +∞/−∞).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb<R: Real> {
    /// The corner of smallest coordinates.
    pub min: V3<R>,
    /// The corner of largest coordinates.
    pub max: V3<R>,
}

/// Applies `f` component-wise, through arrays so that only the `Vector` trait's existing
/// operations are needed.
#[inline]
fn zip<R: Real>(a: V3<R>, b: V3<R>, f: impl Fn(R, R) -> R) -> V3<R> {
    let (a, b) = (a.to_array(), b.to_array());
    V3::<R>::new(f(a[0], b[0]), f(a[1], b[1]), f(a[2], b[2]))
}

/// min and max by a single comparison (one instruction, where `f32::min`'s NaN rules cost
/// several): boxes are built from finite, validated coordinates, and the build's time goes
/// mostly into unions.
#[inline]
pub(super) fn lesser<R: Real>(a: R, b: R) -> R {
    if b < a {
        b
    } else {
        a
    }
}

#[inline]
pub(super) fn greater<R: Real>(a: R, b: R) -> R {
    if b > a {
        b
    } else {
        a
    }
}

impl<R: Real> Aabb<R> {
    /// The empty box: the identity of [`Aabb::union`].
    #[inline]
    pub(crate) fn empty() -> Self {
        let inf = infinity::<R>();
        Aabb {
            min: V3::<R>::splat(inf),
            max: V3::<R>::splat(-inf),
        }
    }

    /// The box of a single point.
    #[inline]
    pub(crate) fn of_point(p: V3<R>) -> Self {
        Aabb { min: p, max: p }
    }

    /// The box of a sphere, widened on each side by γ₂·(|c| + r), more than the rounding of
    /// c ± r and of the widening itself, so that it contains the exact sphere.
    #[inline]
    pub fn of_sphere(center: V3<R>, radius: R) -> Self {
        // Pad each side by the rounding error of c ± r.
        let r = V3::<R>::splat(radius);
        let pad = (center.abs() + r) * gamma::<R>(2);
        Aabb {
            min: center - r - pad,
            max: center + r + pad,
        }
    }

    /// Whether the box holds no point.
    #[inline]
    #[cfg(test)]
    pub(crate) fn is_empty(&self) -> bool {
        let (lo, hi) = (self.min.to_array(), self.max.to_array());
        !(0..3).all(|a| lo[a] <= hi[a])
    }

    /// The smallest box holding both.
    #[inline]
    pub(crate) fn union(self, o: Self) -> Self {
        Aabb {
            min: zip::<R>(self.min, o.min, lesser),
            max: zip::<R>(self.max, o.max, greater),
        }
    }

    /// The smallest box holding this box and the point `p`.
    #[inline]
    pub(crate) fn union_point(self, p: V3<R>) -> Self {
        Aabb {
            min: zip::<R>(self.min, p, lesser),
            max: zip::<R>(self.max, p, greater),
        }
    }

    /// Whether `o` lies inside this box (boundary included).
    #[inline]
    #[cfg(test)]
    pub(crate) fn contains(&self, o: &Self) -> bool {
        let (a0, a1, b0, b1) = (
            self.min.to_array(),
            self.max.to_array(),
            o.min.to_array(),
            o.max.to_array(),
        );
        (0..3).all(|a| a0[a] <= b0[a] && b1[a] <= a1[a])
    }

    /// The centre, as ½min + ½max so that it cannot overflow.
    #[inline]
    pub(crate) fn centroid(&self) -> V3<R> {
        let half = R::ONE / R::TWO;
        self.min * half + self.max * half
    }

    /// The extent max − min (negative on some axis for an empty box).
    #[inline]
    pub(crate) fn diagonal(&self) -> V3<R> {
        self.max - self.min
    }

    /// 2(dx·dy + dy·dz + dz·dx); 0 for an empty box.
    #[inline]
    #[cfg(test)]
    pub(crate) fn surface_area(&self) -> R {
        if self.is_empty() {
            return R::ZERO;
        }
        let d = self.diagonal().to_array();
        R::TWO * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0])
    }

    /// The axis (0 = x, 1 = y, 2 = z) along which the box is longest; the first on a tie.
    #[inline]
    pub(crate) fn longest_axis(&self) -> usize {
        let d = self.diagonal().to_array();
        if d[0] >= d[1] && d[0] >= d[2] {
            0
        } else if d[1] >= d[2] {
            1
        } else {
            2
        }
    }

    /// Whether the ray O + tD meets the box for some t in [0, `t_max`], given 1/D
    /// component-wise (`inv_dir`, ±∞ where D has a ±0 component). Conservative: a box the ray
    /// really meets is never rejected (pbrt-v4 `Bounds3::IntersectP`, §6.1.2 and §6.8.2).
    #[inline]
    pub(crate) fn hit(&self, origin: V3<R>, inv_dir: V3<R>, t_max: R) -> bool {
        let (lo, hi) = (self.min.to_array(), self.max.to_array());
        let (o, inv) = (origin.to_array(), inv_dir.to_array());
        // Widen the far distances by the rounding of (b − o)·inv, pbrt's 1 + 2γ₃.
        let widen = R::ONE + R::TWO * gamma::<R>(3);
        let (mut t0, mut t1) = (R::ZERO, t_max);
        for a in 0..3 {
            // Near and far slab planes along this axis; the sign of 1/D, not of D, so that
            // D = −0 (1/D = −∞) picks the planes in the right order.
            let (near, far) = if inv[a] < R::ZERO {
                (hi[a], lo[a])
            } else {
                (lo[a], hi[a])
            };
            let t_near = (near - o[a]) * inv[a];
            let t_far = (far - o[a]) * inv[a] * widen;
            // Shrink [t0, t1]; a NaN (origin on the plane of a parallel slab: 0·∞) leaves it
            // unchanged, because every comparison with NaN is false.
            if t_near > t0 {
                t0 = t_near;
            }
            if t_far < t1 {
                t1 = t_far;
            }
        }
        t0 <= t1
    }
}

/// 1/D component-wise (±∞ for a ±0 component), for [`Aabb::hit`].
#[inline]
pub(crate) fn inverse<R: Real>(d: V3<R>) -> V3<R> {
    let d = d.to_array();
    V3::<R>::new(R::ONE / d[0], R::ONE / d[1], R::ONE / d[2])
}

/// A tiny deterministic random source for the geometry tests (SplitMix64, Steele et al. 2014):
/// seeded, so every run tests the same cases, and no dependency.
#[cfg(test)]
pub(crate) mod test_rng {
    pub(crate) struct Rng(u64);

    impl Rng {
        pub(crate) fn new(seed: u64) -> Self {
            Rng(seed)
        }
        pub(crate) fn next_u64(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }
        /// Uniform in [0, 1).
        pub(crate) fn unit(&mut self) -> f64 {
            (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
        }
        /// Uniform in [lo, hi).
        pub(crate) fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.unit()
        }
        /// A uniformly distributed unit vector (normalised Gaussian-free: rejection in the cube).
        pub(crate) fn direction(&mut self) -> [f64; 3] {
            loop {
                let v = [
                    self.range(-1.0, 1.0),
                    self.range(-1.0, 1.0),
                    self.range(-1.0, 1.0),
                ];
                let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
                if l2 > 1e-6 && l2 <= 1.0 {
                    let l = l2.sqrt();
                    return [v[0] / l, v[1] / l, v[2] / l];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::v3;

    fn unit_box<R: Real>() -> Aabb<R> {
        Aabb {
            min: v3::<R>([0.0, 0.0, 0.0]),
            max: v3::<R>([1.0, 1.0, 1.0]),
        }
    }

    /// [`Aabb::hit`] with the ray given in f64 arrays, for brevity.
    fn ray_hits<R: Real>(b: &Aabb<R>, o: [f64; 3], d: [f64; 3], t_max: f64) -> bool {
        b.hit(v3::<R>(o), inverse::<R>(v3::<R>(d)), R::from_f64(t_max))
    }

    fn box_basics<R: Real>() {
        let a = unit_box::<R>();
        let b = Aabb::of_point(v3::<R>([3.0, -1.0, 0.5]));
        let u = a.union(b);
        assert_eq!(u.min, v3::<R>([0.0, -1.0, 0.0]));
        assert_eq!(u.max, v3::<R>([3.0, 1.0, 1.0]));
        assert_eq!(u, a.union_point(v3::<R>([3.0, -1.0, 0.5])));
        assert_eq!(Aabb::<R>::empty().union(a), a);
        assert!(Aabb::<R>::empty().is_empty() && !a.is_empty());
        // 2(3·2 + 2·1 + 1·3) = 22.
        assert_eq!(u.surface_area(), R::from_f64(22.0));
        assert_eq!(Aabb::<R>::empty().surface_area(), R::ZERO);
        assert_eq!(u.longest_axis(), 0);
        assert_eq!(u.centroid(), v3::<R>([1.5, 0.0, 0.5]));
        assert!(u.contains(&a) && !a.contains(&u));
    }

    #[test]
    fn union_centroid_area_and_longest_axis_follow_the_definitions() {
        box_basics::<f32>();
        box_basics::<f64>();
    }

    fn sphere_box_contains_the_sphere<R: Real>() {
        for (c, r) in [([1e6, -1e6, 3.0], 1e-3), ([0.1, 0.2, 0.3], 0.7)] {
            let b = Aabb::<R>::of_sphere(v3::<R>(c), R::from_f64(r));
            let (lo, hi) = (b.min.to_array(), b.max.to_array());
            for a in 0..3 {
                // Compared in f64, where c ± r is (nearly) exact.
                let (cf, rf) = (R::from_f64(c[a]).to_f64(), R::from_f64(r).to_f64());
                assert!(lo[a].to_f64() <= cf - rf && hi[a].to_f64() >= cf + rf);
            }
        }
    }

    #[test]
    fn sphere_box_contains_the_exact_sphere_at_any_scale() {
        sphere_box_contains_the_sphere::<f32>();
        sphere_box_contains_the_sphere::<f64>();
    }

    fn slab_cases<R: Real>() {
        let b = unit_box::<R>();
        // Straight through, and the same ray stopped short of the box.
        assert!(ray_hits(&b, [0.5, 0.5, -1.0], [0.0, 0.0, 1.0], 10.0));
        assert!(!ray_hits(&b, [0.5, 0.5, -1.0], [0.0, 0.0, 1.0], 0.5));
        // Pointing away, and passing beside.
        assert!(!ray_hits(&b, [0.5, 0.5, -1.0], [0.0, 0.0, -1.0], 10.0));
        assert!(!ray_hits(&b, [1.5, 0.5, -1.0], [0.0, 0.0, 1.0], 10.0));
        // From inside, in any direction, with an infinite t_max.
        assert!(ray_hits(
            &b,
            [0.5, 0.5, 0.5],
            [0.6, -0.8, 0.0],
            f64::INFINITY
        ));
        // Parallel to two axes with D = −0 components (1/D = −∞): still hits.
        assert!(b.hit(
            v3::<R>([0.5, 0.5, -1.0]),
            inverse::<R>(V3::<R>::new(-R::ZERO, -R::ZERO, R::ONE)),
            R::from_f64(10.0)
        ));
        // Origin exactly on a slab plane, ray parallel to it: 0·∞ = NaN must not give a miss.
        assert!(ray_hits(&b, [0.0, 0.5, -1.0], [0.0, 0.0, 1.0], 10.0));
        assert!(ray_hits(&b, [1.0, 1.0, -1.0], [0.0, 0.0, 1.0], 10.0));
        assert!(b.hit(
            v3::<R>([1.0, 0.0, -1.0]),
            inverse::<R>(V3::<R>::new(-R::ZERO, R::ZERO, R::ONE)),
            R::from_f64(10.0)
        ));
        // Parallel and outside the slab: a miss.
        assert!(!ray_hits(
            &b,
            [1.0 + 1e-3, 0.5, -1.0],
            [0.0, 0.0, 1.0],
            10.0
        ));
        // The empty box is never hit.
        assert!(!Aabb::<R>::empty().hit(
            v3::<R>([0.0, 0.0, 0.0]),
            inverse::<R>(v3::<R>([1.0, 0.0, 0.0])),
            R::from_f64(f64::INFINITY)
        ));
        // Huge and tiny scales.
        for s in [1e-3, 1e6] {
            let big = Aabb::<R> {
                min: v3::<R>([s, s, s]),
                max: v3::<R>([2.0 * s, 2.0 * s, 2.0 * s]),
            };
            assert!(!ray_hits(&big, [0.0, 0.0, 0.0], [0.6, 0.0, 0.8], 1e9));
            let k = 1.0 / 3f64.sqrt();
            assert!(ray_hits(&big, [0.0, 0.0, 0.0], [k, k, k], 1e9));
        }
    }

    #[test]
    fn slab_test_handles_signed_zeros_infinite_inverses_and_origins_on_a_face() {
        slab_cases::<f32>();
        slab_cases::<f64>();
    }

    fn touching_ray_is_kept<R: Real>() {
        // A ray that only grazes an edge of the box (t0 = t1) counts as a hit.
        let b = unit_box::<R>();
        let k = 1.0 / 2f64.sqrt();
        assert!(ray_hits(&b, [-1.0, 0.0, 0.5], [k, k, 0.0], 10.0));
    }

    #[test]
    fn a_ray_grazing_an_edge_of_the_box_is_kept() {
        touching_ray_is_kept::<f32>();
        touching_ray_is_kept::<f64>();
    }
}
