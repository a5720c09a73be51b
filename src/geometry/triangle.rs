//! A triangle, intersected with pbrt-v4's watertight algorithm (Woop, Benthin and Wald 2013;
//! pbrt-v4 §6.5.3): a ray through an edge shared by two triangles hits at least one of them.
//!
//! The ray becomes the +z axis of a sheared frame in which the triangle's projection is tested
//! with three edge functions; the two triangles on a shared edge compute that edge's function
//! from the same transformed corners, so their signs agree exactly (the products are formed in
//! the same order and Rust never fuses them into FMAs). The hit's t is then checked against a
//! conservative error bound so that a hit too close to the origin to be told from t = 0 is
//! rejected (§6.8.4), and the interpolated hit point carries the bound of its rounding error
//! (§6.8.5), from which a spawned ray's origin is offset.

use super::bounds::Aabb;
use super::hit::SurfaceHit;
use super::ray::Ray;
use crate::core::rounding::gamma;
use crate::core::vector::normalize;
use crate::core::{Real, Vector, V3};

/// The triangle with corners p₀, p₁, p₂.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle<R: Real> {
    /// The corners p₀, p₁, p₂; the normal is (p₁ − p₀) × (p₂ − p₀), normalised.
    pub p: [V3<R>; 3],
    /// The unit vertex normals N₀, N₁, N₂ at the corners (an OBJ file's `vn`) of a smooth
    /// triangle, shaded with their barycentric interpolation ([`Triangle::smooth`]); `None` for
    /// a flat triangle, shaded with its geometric normal.
    pub normals: Option<std::sync::Arc<[V3<R>; 3]>>,
}

/// How a smooth triangle's shading normal came about at a point: the interpolation of its
/// vertex normals (docs/conventions.md, "Smooth meshes"), for the hit and the explanation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothNormal<R: Real> {
    /// The barycentric weights b₀, b₁, b₂ of the point.
    pub b: [R; 3],
    /// The unit vertex normals N₀, N₁, N₂.
    pub vertex: [V3<R>; 3],
    /// b₀N₀ + b₁N₁ + b₂N₂ normalised; `None` where that sum is zero (opposite vertex normals).
    pub interpolated: Option<V3<R>>,
    /// The shading normal: `interpolated`, or the geometric normal where `interpolated` is
    /// `None` or not on the geometric normal's side (N·N_g ≤ 0).
    pub used: V3<R>,
    /// Whether `used` is the geometric normal in place of the interpolation.
    pub clamped: bool,
}

/// A ray's hit on a triangle, 0 < t < t_max.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TriangleHit<R: Real> {
    /// The ray parameter.
    pub t: R,
    /// Barycentric coordinates b₀, b₁, b₂ (non-negative, summing to 1 up to rounding).
    pub b: [R; 3],
    /// The hit point b₀p₀ + b₁p₁ + b₂p₂ (on the triangle's plane, unlike O + tD).
    pub p: V3<R>,
    /// A bound on the absolute error of each component of `p`: γ₇·Σ|b_i p_i|.
    pub p_error: V3<R>,
}

/// The triangle in the ray's frame: corners translated to the ray origin, axes permuted so
/// that the ray direction's largest component is z, then sheared so that the ray is +z.
struct RaySpace<R: Real> {
    /// Edge functions; e_i is twice the signed area opposite corner i in the projection.
    e: [R; 3],
    /// e₀ + e₁ + e₂.
    det: R,
    /// t·det, with t the hit's ray parameter.
    t_scaled: R,
    /// The sheared corners' x and y, and z scaled by 1/d_z.
    x: [R; 3],
    y: [R; 3],
    z: [R; 3],
}

/// max |v_i|.
#[inline]
fn max_abs<R: Real>(v: [R; 3]) -> R {
    v[0].abs().max(v[1].abs()).max(v[2].abs())
}

/// The ray in the triangle test's sheared frame (`Triangle::ray_space`, and the wide BVH's triangle leaves): the
/// permutation putting D's largest component last, and the shear.
#[derive(Clone, Copy)]
pub(crate) struct Shear<R: Real> {
    /// The axes (x, y, z) of the sheared frame: D's largest component is `k[2]`.
    pub(crate) k: [usize; 3],
    /// −D_x/D_z, −D_y/D_z and 1/D_z in that frame.
    pub(crate) sx: R,
    /// See `sx`.
    pub(crate) sy: R,
    /// See `sx`.
    pub(crate) sz: R,
}

impl<R: Real> Shear<R> {
    #[inline]
    pub(crate) fn of(ray: &Ray<R>) -> Self {
        let d = ray.direction.to_array();
        let ad = [d[0].abs(), d[1].abs(), d[2].abs()];
        let kz = if ad[0] > ad[1] {
            if ad[0] > ad[2] {
                0
            } else {
                2
            }
        } else if ad[1] > ad[2] {
            1
        } else {
            2
        };
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        Shear {
            k: [kx, ky, kz],
            sx: -d[kx] / d[kz],
            sy: -d[ky] / d[kz],
            sz: R::ONE / d[kz],
        }
    }
}

impl<R: Real> Triangle<R> {
    /// The triangle with corners `p0`, `p1`, `p2`.
    #[inline]
    pub fn new(p0: V3<R>, p1: V3<R>, p2: V3<R>) -> Self {
        Triangle {
            p: [p0, p1, p2],
            normals: None,
        }
    }

    /// The shading normal of a smooth triangle at the barycentric point `b`, whose geometric
    /// normal is `ng` (docs/conventions.md, "Smooth meshes"): N = b₀N₀ + b₁N₁ + b₂N₂ normalised,
    /// kept only where it lies on `ng`'s side of the surface (N·N_g > 0; else N_g, as pbrt and
    /// Mitsuba keep a shading normal from crossing the geometric surface); `None` for a flat
    /// triangle.
    #[inline]
    pub fn smooth(&self, b: [R; 3], ng: V3<R>) -> Option<SmoothNormal<R>> {
        let vertex = self.normals.as_deref()?;
        let sum = vertex[0] * b[0] + vertex[1] * b[1] + vertex[2] * b[2];
        let interpolated = normalize::<R>(sum).map(|n| n.unit);
        let (used, clamped) = match interpolated {
            Some(n) if n.dot(ng) > R::ZERO => (n, false),
            _ => (ng, true),
        };
        Some(SmoothNormal {
            b,
            vertex: *vertex,
            interpolated,
            used,
            clamped,
        })
    }

    /// The barycentric weights of a point `p` on the triangle's plane whose geometric normal is
    /// `ng`: each b_i the signed area of the triangle p with the other two corners over the
    /// whole (for a point the watertight test did not give: the line's meeting behind a ray's
    /// origin).
    pub(crate) fn barycentric_at(&self, p: V3<R>, ng: V3<R>) -> [R; 3] {
        let [p0, p1, p2] = self.p;
        let area = |a: V3<R>, b: V3<R>, c: V3<R>| (b - a).cross(c - a).dot(ng);
        let whole = area(p0, p1, p2);
        [
            area(p, p1, p2) / whole,
            area(p0, p, p2) / whole,
            area(p0, p1, p) / whole,
        ]
    }

    /// The unit normal to shade with at a point `p` on the triangle whose geometric normal is
    /// `ng`: the smooth normal there ([`Triangle::smooth`] at [`Triangle::barycentric_at`]),
    /// or `ng` for a flat triangle.
    pub(crate) fn shading_at(&self, p: V3<R>, ng: V3<R>) -> V3<R> {
        if self.normals.is_none() {
            return ng;
        }
        self.smooth(self.barycentric_at(p, ng), ng)
            .map_or(ng, |s| s.used)
    }

    /// The box of the three corners (exact: no arithmetic).
    #[inline]
    pub(crate) fn bounds(&self) -> Aabb<R> {
        Aabb::of_point(self.p[0])
            .union_point(self.p[1])
            .union_point(self.p[2])
    }

    /// The unit geometric normal, (p₁ − p₀) × (p₂ − p₀) normalised; `None` for a degenerate
    /// triangle: two equal corners, or corners collinear in this precision (the cross product
    /// of the edges, each scaled to a largest component of 1, is within its rounding error
    /// 2γ₆ of zero; in f32 that rejects slivers whose angle is below about 7·10⁻⁷ rad).
    pub fn normal(&self) -> Option<V3<R>> {
        let [p0, p1, p2] = self.p;
        // Scale each edge to a largest component of 1, so that the cross product can neither
        // overflow nor underflow for a triangle that is not a sliver.
        let (u, v) = (p1 - p0, p2 - p0);
        let (su, sv) = (u.abs().max_element(), v.abs().max_element());
        if !(su > R::ZERO && sv > R::ZERO && su.is_finite() && sv.is_finite()) {
            return None;
        }
        let c = (u / su).cross(v / sv);
        // Reject a cross product that rounding alone could have produced.
        let resolved = c.abs().max_element() > R::TWO * gamma::<R>(6);
        if !resolved {
            return None;
        }
        normalize::<R>(c).map(|n| n.unit)
    }

    /// The watertight test's common part: the triangle in the ray's frame, or `None` when the
    /// ray's line misses it (or the triangle is degenerate, or seen exactly edge-on).
    #[inline]
    fn ray_space(&self, ray: &Ray<R>) -> Option<RaySpace<R>> {
        let [p0, p1, p2] = self.p;
        // Return no intersection if the triangle is degenerate
        if (p2 - p0).cross(p1 - p0) == V3::<R>::ZERO {
            return None;
        }

        // Translate vertices based on ray origin
        let o = ray.origin;
        let q = [
            (p0 - o).to_array(),
            (p1 - o).to_array(),
            (p2 - o).to_array(),
        ];

        // Permute components of triangle vertices and ray direction (largest |d| to z), and
        // apply the shear transformation to translated vertex positions
        let Shear {
            k: [kx, ky, kz],
            sx,
            sy,
            sz,
        } = Shear::of(ray);
        let x = [0, 1, 2].map(|i| q[i][kx] + sx * q[i][kz]);
        let y = [0, 1, 2].map(|i| q[i][ky] + sy * q[i][kz]);

        // Compute edge function coefficients e0, e1, e2
        let mut e = [
            x[1] * y[2] - y[1] * x[2],
            x[2] * y[0] - y[2] * x[0],
            x[0] * y[1] - y[0] * x[1],
        ];

        // Fall back to double-precision test at triangle edges (f32 only: the products of two
        // f32 are exact in f64, so the sign of a zero edge function is then resolved)
        if R::EPSILON.to_f64() > f64::EPSILON && e.contains(&R::ZERO) {
            let dop = |a: R, b: R, c: R, d: R| {
                R::from_f64(a.to_f64() * b.to_f64() - c.to_f64() * d.to_f64())
            };
            e = [
                dop(x[1], y[2], y[1], x[2]),
                dop(x[2], y[0], y[2], x[0]),
                dop(x[0], y[1], y[0], x[1]),
            ];
        }

        // Perform triangle edge and determinant tests (an edge function of 0 counts as inside)
        let any_neg = e.iter().any(|&v| v < R::ZERO);
        let any_pos = e.iter().any(|&v| v > R::ZERO);
        if any_neg && any_pos {
            return None;
        }
        let det = e[0] + e[1] + e[2];
        if det == R::ZERO {
            return None;
        }

        // Compute scaled hit distance to triangle
        let z = [0, 1, 2].map(|i| q[i][kz] * sz);
        let t_scaled = e[0] * z[0] + e[1] * z[1] + e[2] * z[2];
        Some(RaySpace {
            e,
            det,
            t_scaled,
            x,
            y,
            z,
        })
    }

    /// The ray's hit with 0 < t < `t_max`, or `None`. Hits whose t cannot be told from 0 given
    /// the rounding of the computation are rejected (pbrt's "t ≤ δt" test), which is what keeps
    /// a ray spawned from this triangle from hitting it again.
    #[inline]
    pub(crate) fn intersect(&self, ray: &Ray<R>, t_max: R) -> Option<TriangleHit<R>> {
        let RaySpace {
            e,
            det,
            t_scaled,
            x,
            y,
            z,
        } = self.ray_space(ray)?;

        // Test the scaled hit distance against the ray's t range (NaN fails both branches)
        let in_range = if det > R::ZERO {
            t_scaled > R::ZERO && t_scaled <= t_max * det
        } else {
            t_scaled < R::ZERO && t_scaled >= t_max * det
        };
        if !in_range {
            return None;
        }

        // Compute barycentric coordinates and t value for triangle intersection
        let inv_det = R::ONE / det;
        let b = e.map(|ei| ei * inv_det);
        let t = t_scaled * inv_det;
        let before_t_max = t < t_max;
        if !before_t_max {
            return None;
        }

        // Ensure that computed triangle t is conservatively greater than zero (§6.8.4):
        // δz, then δx and δy, then δe, then δt
        let max_zt = max_abs(z);
        let delta_z = gamma::<R>(3) * max_zt;
        let (max_xt, max_yt) = (max_abs(x), max_abs(y));
        let delta_x = gamma::<R>(5) * (max_xt + max_zt);
        let delta_y = gamma::<R>(5) * (max_yt + max_zt);
        let delta_e =
            R::TWO * (gamma::<R>(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        let max_e = max_abs(e);
        let delta_t = R::from_f64(3.0)
            * (gamma::<R>(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e)
            * inv_det.abs();
        let beyond_error = t > delta_t;
        if !beyond_error {
            return None;
        }

        // Interpolate the hit point from the corners and bound its error (§6.8.5)
        let [p0, p1, p2] = self.p;
        let (w0, w1, w2) = (p0 * b[0], p1 * b[1], p2 * b[2]);
        let p = w0 + w1 + w2;
        // (Scaled before the sum, which could overflow near the range's end.)
        let g = gamma::<R>(7);
        let p_error = w0.abs() * g + w1.abs() * g + w2.abs() * g;
        Some(TriangleHit { t, b, p, p_error })
    }

    /// The ray's hit with 0 < t < `t_max` as [`Triangle::intersect`] finds it, with the
    /// barycentric point, its error bound, the triangle's normal and the normal to shade with
    /// (the smooth normal at the hit's barycentric weights, [`Triangle::smooth`]; the
    /// triangle's normal for a flat one); `None` also for a triangle degenerate in this
    /// precision (see [`Triangle::normal`]).
    #[inline]
    pub(crate) fn hit(&self, ray: &Ray<R>, t_max: R) -> Option<SurfaceHit<R>> {
        let h = self.intersect(ray, t_max)?;
        let normal = self.normal()?;
        Some(SurfaceHit {
            t: h.t,
            p: h.p,
            p_error: h.p_error,
            normal,
            shading: self.smooth(h.b, normal).map_or(normal, |s| s.used),
        })
    }

    /// How the shading normal of the hit [`Triangle::hit`] gives for a ray whose hit is at `t`
    /// came about: its barycentric weights and the interpolation ([`Triangle::smooth`], the
    /// same arithmetic, so `used` is the hit's shading normal to the bit); `None` for a flat
    /// triangle or no hit. The solver's explanation reads it.
    pub(crate) fn smooth_hit(&self, ray: &Ray<R>, t: R) -> Option<SmoothNormal<R>> {
        self.normals.as_ref()?;
        let h = self.intersect(ray, t.next_up())?;
        self.smooth(h.b, self.normal()?)
    }

    /// t (of either sign, 0 included) where the ray's *line* meets the triangle, by the same
    /// watertight test; the solver uses it to report a hit behind the origin.
    #[inline]
    pub(crate) fn line_t(&self, ray: &Ray<R>) -> Option<R> {
        let rs = self.ray_space(ray)?;
        let t = rs.t_scaled / rs.det;
        t.is_finite().then_some(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::real::{to_f64_array, v3};
    use crate::geometry::bounds::test_rng::Rng;
    use crate::geometry::hit::offset_origin;

    fn tri<R: Real>(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Triangle<R> {
        Triangle::new(v3::<R>(a), v3::<R>(b), v3::<R>(c))
    }

    fn ray<R: Real>(o: [f64; 3], d: [f64; 3]) -> Ray<R> {
        Ray {
            origin: v3::<R>(o),
            direction: v3::<R>(d),
        }
    }

    fn inf<R: Real>() -> R {
        R::from_f64(f64::INFINITY)
    }

    /// |a − b| within `ulps` units of the precision, relative to max(|b|, 1).
    fn close<R: Real>(a: R, b: f64, ulps: f64) -> bool {
        (a.to_f64() - b).abs() <= ulps * R::EPSILON.to_f64() * b.abs().max(1.0)
    }

    fn check_hit<R: Real>(
        t: &Triangle<R>,
        r: &Ray<R>,
        want_t: f64,
        want_b: [f64; 3],
        want_p: [f64; 3],
    ) {
        let h = t.intersect(r, inf::<R>()).expect("a hit");
        assert!(close(h.t, want_t, 8.0), "t = {} for {want_t}", h.t);
        for i in 0..3 {
            assert!(close(h.b[i], want_b[i], 8.0), "b = {:?}", h.b);
            let (p, e) = (h.p.to_array()[i], h.p_error.to_array()[i]);
            assert!((p.to_f64() - want_p[i]).abs() <= e.to_f64().max(1e-30) * 4.0);
        }
        let line = t.line_t(r).expect("the line meets it too");
        assert!(close(line, want_t, 8.0));
    }

    fn known_hits<R: Real>() {
        let t = tri::<R>([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // Straight down onto (0.25, 0.25, 0): b₁ = x, b₂ = y, b₀ = 1 − x − y.
        check_hit(
            &t,
            &ray([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]),
            1.0,
            [0.5, 0.25, 0.25],
            [0.25, 0.25, 0.0],
        );
        // Along (0.6, 0, −0.8) from (−1, 0.25, 2): z = 0 at t = 2/0.8 = 2.5, x = −1 + 1.5 = 0.5.
        check_hit(
            &t,
            &ray([-1.0, 0.25, 2.0], [0.6, 0.0, -0.8]),
            2.5,
            [0.25, 0.5, 0.25],
            [0.5, 0.25, 0.0],
        );
        // A triangle in the plane x = 3, met along +x (the permutation puts x last): the point
        // (3, 0.5, 0.5) = ½p₀ + ¼p₁ + ¼p₂ since p₁ − p₀ = 2ŷ and p₂ − p₀ = 2ẑ.
        let side = tri::<R>([3.0, 0.0, 0.0], [3.0, 2.0, 0.0], [3.0, 0.0, 2.0]);
        check_hit(
            &side,
            &ray([0.0, 0.5, 0.5], [1.0, 0.0, 0.0]),
            3.0,
            [0.5, 0.25, 0.25],
            [3.0, 0.5, 0.5],
        );
        // The same from behind the triangle's back face (−x): still a hit.
        check_hit(
            &side,
            &ray([5.0, 0.5, 0.5], [-1.0, 0.0, 0.0]),
            2.0,
            [0.5, 0.25, 0.25],
            [3.0, 0.5, 0.5],
        );
    }

    #[test]
    fn hits_have_the_t_and_barycentrics_worked_out_by_hand() {
        known_hits::<f32>();
        known_hits::<f64>();
    }

    fn edges<R: Real>() {
        let t = tri::<R>([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let delta = 1e3 * R::EPSILON.to_f64();
        let dir = {
            let l = (0.3f64 * 0.3 + 0.2 * 0.2 + 1.0).sqrt();
            [0.3 / l, -0.2 / l, -1.0 / l]
        };
        // Each edge's midpoint moved by δ inwards and outwards (x + y = 1, y = 0, x = 0).
        let cases = [
            ([0.5 - delta, 0.5 - delta], [0.5 + delta, 0.5 + delta]),
            ([0.5, delta], [0.5, -delta]),
            ([delta, 0.5], [-delta, 0.5]),
        ];
        for (inside, outside) in cases {
            for (target, hits) in [(inside, true), (outside, false)] {
                // Start 2 units back along the direction from the target on z = 0.
                let o = [
                    target[0] - 2.0 * dir[0],
                    target[1] - 2.0 * dir[1],
                    -2.0 * dir[2],
                ];
                let r = ray::<R>(o, dir);
                assert_eq!(t.intersect(&r, inf::<R>()).is_some(), hits, "{target:?}");
                assert_eq!(t.line_t(&r).is_some(), hits, "{target:?}");
            }
        }
    }

    #[test]
    fn rays_just_outside_each_edge_miss_and_just_inside_hit() {
        edges::<f32>();
        edges::<f64>();
    }

    fn behind<R: Real>() {
        let t = tri::<R>([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // The triangle is 1 behind an origin at z = −1 looking down −z.
        let r = ray::<R>([0.25, 0.25, -1.0], [0.0, 0.0, -1.0]);
        assert!(t.intersect(&r, inf::<R>()).is_none());
        assert!(close(t.line_t(&r).unwrap(), -1.0, 4.0));
        // In front at t = 1: t_max = 1 excludes it, anything beyond includes it.
        let r = ray::<R>([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]);
        assert!(t.intersect(&r, R::ONE).is_none());
        assert!(t.intersect(&r, R::from_f64(1.001)).is_some());
        // A ray lying in the triangle's plane meets it edge-on: no hit, no line parameter.
        let r = ray::<R>([-1.0, 0.25, 0.0], [1.0, 0.0, 0.0]);
        assert!(t.intersect(&r, inf::<R>()).is_none() && t.line_t(&r).is_none());
    }

    #[test]
    fn hits_behind_the_origin_are_not_hits_but_the_line_still_reports_them() {
        behind::<f32>();
        behind::<f64>();
    }

    fn normals<R: Real>() {
        let z = tri::<R>([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(z.normal(), Some(v3::<R>([0.0, 0.0, 1.0])));
        let flipped = tri::<R>([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]);
        assert_eq!(flipped.normal(), Some(v3::<R>([0.0, 0.0, -1.0])));
        // (1,0,0)×(0,1,1)/√2 = (0,−1,1)/√2.
        let n = tri::<R>([1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 2.0])
            .normal()
            .unwrap();
        let k = 1.0 / 2f64.sqrt();
        for (a, b) in to_f64_array::<R>(n).into_iter().zip([0.0, -k, k]) {
            assert!((a - b).abs() <= 4.0 * R::EPSILON.to_f64());
        }
        // Extreme scales of the precision, where the naive cross product under- or overflows.
        let s = if R::EPSILON.to_f64() > f64::EPSILON {
            [1e-30, 1e30]
        } else {
            [1e-300, 1e300]
        };
        for s in s {
            let t = tri::<R>([0.0, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s, 0.0]);
            assert_eq!(t.normal(), Some(v3::<R>([0.0, 0.0, 1.0])), "scale {s}");
        }
        // Degenerate: a repeated corner, and collinear corners (exactly, and up to rounding).
        for t in [
            tri::<R>([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            tri::<R>([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]),
            tri::<R>([0.0, 0.0, 0.0], [0.1, 0.2, 0.3], [0.3, 0.6, 0.9]),
            tri::<R>(
                [1e6, 0.0, 0.0],
                [1e6 + 1.0, 2.0, 3.0],
                [1e6 + 3.0, 6.0, 9.0],
            ),
        ] {
            assert_eq!(t.normal(), None, "{t:?}");
        }
    }

    /// The triangle with corners (−B, −B, −B), (B, −B, −B), (−B, B, −B) and the ray from (B, B, B)
    /// to (−B/2, −B/2, −B): the edge functions are 2B², B² and B², the scaled distance
    /// 4B²·2.9155B = 11.66B³. Its hit at t = 2.9155B, or `None`.
    fn from_corner_to_corner<R: Real>(b: f64) -> Option<R> {
        let t = tri::<R>([-b, -b, -b], [b, -b, -b], [-b, b, -b]);
        let d = unit([-1.5, -1.5, -2.0]);
        t.intersect(&ray([b, b, b], d), inf::<R>()).map(|h| h.t)
    }

    fn largest_coordinates<R: Real>() {
        let b = crate::geometry::max_coordinate::<R>();
        let want = b * (1.5f64 * 1.5 + 1.5 * 1.5 + 4.0).sqrt();
        let t = from_corner_to_corner::<R>(b).expect("a hit at the bound");
        assert!(close(t, want, 16.0), "{} at {b:e}: t = {t}", R::NAME);
        // A thousand times past the bound, 11.66B³ overflows: the ray misses without a word,
        // which is what validation's bound keeps from happening.
        assert_eq!(from_corner_to_corner::<R>(b * 1e3), None, "{}", R::NAME);
    }

    #[test]
    fn a_triangle_at_the_largest_coordinates_is_hit_and_past_them_the_test_overflows() {
        largest_coordinates::<f32>();
        largest_coordinates::<f64>();
    }

    #[test]
    fn normal_is_unit_and_oriented_by_corner_order_and_none_for_degenerate_triangles() {
        normals::<f32>();
        normals::<f64>();
    }

    fn smooth_normals<R: Real>() {
        let mut t = tri::<R>([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // Flat: the shading normal is the geometric normal, bit for bit, and facing turns it
        // as before.
        let down = ray::<R>([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]);
        let flat = t.hit(&down, inf::<R>()).unwrap();
        assert_eq!(flat.shading, flat.normal);
        assert_eq!(flat.facing(down.direction).normal, flat.normal);
        assert!(t.smooth_hit(&down, flat.t).is_none());
        // N₀ = (0, 0, 1), N₁ = (0.6, 0, 0.8), N₂ = (0, 0.6, 0.8) and the hit at (0.25, 0.25, 0),
        // b = (0.5, 0.25, 0.25): ΣbN = (0.15, 0.15, 0.5 + 0.2 + 0.2) = (0.15, 0.15, 0.9), of
        // length √0.855 (by hand).
        t.normals = Some(std::sync::Arc::new([
            v3::<R>([0.0, 0.0, 1.0]),
            v3::<R>([0.6, 0.0, 0.8]),
            v3::<R>([0.0, 0.6, 0.8]),
        ]));
        let h = t.hit(&down, inf::<R>()).unwrap();
        let len = 0.855f64.sqrt();
        let want = [0.15 / len, 0.15 / len, 0.9 / len];
        let got = to_f64_array::<R>(h.shading);
        for i in 0..3 {
            assert!(close(R::from_f64(got[i]), want[i], 8.0), "{got:?} {want:?}");
        }
        // The geometric normal, the point and t are the flat triangle's.
        assert_eq!((h.normal, h.p, h.t), (flat.normal, flat.p, flat.t));
        let s = t.smooth_hit(&down, h.t).unwrap();
        assert_eq!((s.used, s.clamped), (h.shading, false));
        for (b, want) in s.b.iter().zip([0.5, 0.25, 0.25]) {
            assert!(close(*b, want, 8.0), "{:?}", s.b);
        }
        // From below, the shading normal turns with the geometric normal's test.
        let up = ray::<R>([0.25, 0.25, -1.0], [0.0, 0.0, 1.0]);
        let below = t.hit(&up, inf::<R>()).unwrap();
        let f = below.facing(up.direction);
        assert!(f.reversed);
        assert_eq!(f.normal, -below.shading);
        // The line's point behind an origin gets the same weights from its areas.
        let b = t.barycentric_at(h.p, h.normal);
        for (b, want) in b.iter().zip([0.5, 0.25, 0.25]) {
            assert!(close(*b, want, 8.0), "{b:?}");
        }
        // Vertex normals against the winding: the interpolation is on the other side of the
        // surface, so the geometric normal is used.
        t.normals = Some(std::sync::Arc::new([
            v3::<R>([0.0, 0.0, -1.0]),
            v3::<R>([0.6, 0.0, -0.8]),
            v3::<R>([0.0, 0.6, -0.8]),
        ]));
        let h = t.hit(&down, inf::<R>()).unwrap();
        assert_eq!(h.shading, h.normal);
        assert!(t.smooth_hit(&down, h.t).unwrap().clamped);
        // Opposite normals cancelling at the hit: no interpolation, the geometric normal.
        t.normals = Some(std::sync::Arc::new([
            v3::<R>([0.0, 0.0, 1.0]),
            v3::<R>([0.0, 0.0, -1.0]),
            v3::<R>([0.0, 0.0, -1.0]),
        ]));
        let h = t.hit(&down, inf::<R>()).unwrap();
        let s = t.smooth_hit(&down, h.t).unwrap();
        assert_eq!(
            (s.interpolated, s.clamped, h.shading),
            (None, true, h.normal)
        );
    }

    #[test]
    fn a_smooth_triangle_shades_with_its_interpolated_vertex_normals_worked_by_hand() {
        smooth_normals::<f32>();
        smooth_normals::<f64>();
    }

    #[test]
    fn bounds_are_the_box_of_the_corners() {
        let t = tri::<f64>([1.0, -2.0, 3.0], [0.0, 5.0, 3.5], [2.0, 0.0, -1.0]);
        let b = t.bounds();
        assert_eq!(b.min, v3::<f64>([0.0, -2.0, -1.0]));
        assert_eq!(b.max, v3::<f64>([2.0, 5.0, 3.5]));
    }

    /// A random point in [−1, 1]³ scaled by `s` and moved by `c`.
    fn point(rng: &mut Rng, c: [f64; 3], s: f64) -> [f64; 3] {
        [0, 1, 2].map(|i| c[i] + s * rng.range(-1.0, 1.0))
    }

    fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
    }

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }

    fn unit(a: [f64; 3]) -> [f64; 3] {
        let l = dot(a, a).sqrt();
        a.map(|x| x / l)
    }

    /// (scale, offset) pairs from 1e-3 to 1e6, near and far from the origin.
    const SCALES: [(f64, f64); 6] = [
        (1e-3, 0.0),
        (1e-3, 1.0),
        (1.0, 0.0),
        (1.0, 1e3),
        (1e3, 1e3),
        (1e6, 1e6),
    ];

    fn watertight<R: Real>(rays_per_scale: usize) -> usize {
        let mut rng = Rng::new(0x7A7E_4716);
        let mut both = 0;
        for (s, off) in SCALES {
            for _ in 0..rays_per_scale {
                // Two triangles sharing the edge p₁p₂ of a parallelogram, wound alike.
                let c = point(&mut rng, [0.0; 3], off);
                let (p0, p1, p2) = (
                    point(&mut rng, c, s),
                    point(&mut rng, c, s),
                    point(&mut rng, c, s),
                );
                let p3 = [0, 1, 2].map(|i| p1[i] + p2[i] - p0[i]);
                let a = tri::<R>(p0, p1, p2);
                let b = tri::<R>(p3, p2, p1);
                if a.normal().is_none() || b.normal().is_none() {
                    continue;
                }
                // A ray from a random origin through a random point of the shared edge, not
                // nearly parallel to the plane.
                let u = rng.range(0.1, 0.9);
                let target = [0, 1, 2].map(|i| p1[i] + u * (p2[i] - p1[i]));
                let o = point(&mut rng, target, 3.0 * s);
                let d = unit(sub(target, o));
                let n = unit(cross(sub(p1, p0), sub(p2, p0)));
                if dot(d, n).abs() < 0.05 {
                    continue;
                }
                let r = ray::<R>(o, d);
                let (ha, hb) = (
                    a.intersect(&r, inf::<R>()).is_some(),
                    b.intersect(&r, inf::<R>()).is_some(),
                );
                assert!(ha || hb, "both missed: {a:?} {b:?} {r:?}");
                both += usize::from(ha && hb);
            }
        }
        both
    }

    #[test]
    fn a_ray_through_a_shared_edge_never_misses_both_triangles() {
        watertight::<f32>(20_000);
        watertight::<f64>(20_000);
    }

    /// (spawned rays that found no self-hit, hits found) over random triangles and rays.
    fn no_self_hits<R: Real>(cases_per_scale: usize) -> (usize, usize) {
        let mut rng = Rng::new(0x05E1_F417);
        let (mut spawned, mut hits) = (0, 0);
        for (s, off) in SCALES {
            for _ in 0..cases_per_scale {
                let c = point(&mut rng, [0.0; 3], off);
                let t = tri::<R>(
                    point(&mut rng, c, s),
                    point(&mut rng, c, s),
                    point(&mut rng, c, s),
                );
                let Some(n) = t.normal() else { continue };
                // Aim at a random interior point from a random origin.
                let (b1, b2) = (rng.unit(), rng.unit());
                let (b1, b2) = if b1 + b2 > 1.0 {
                    (1.0 - b1, 1.0 - b2)
                } else {
                    (b1, b2)
                };
                let p = t.p.map(to_f64_array::<R>);
                let target =
                    [0, 1, 2].map(|i| (1.0 - b1 - b2) * p[0][i] + b1 * p[1][i] + b2 * p[2][i]);
                let o = point(&mut rng, target, 4.0 * s);
                let d = unit(sub(target, o));
                let r = ray::<R>(o, d);
                let Some(h) = t.intersect(&r, inf::<R>()) else {
                    continue;
                };
                hits += 1;
                // Leave by the mirror direction, by a random direction on either side, and
                // back the way the ray came.
                let dv = r.direction;
                let mirror = dv - n * (R::TWO * n.dot(dv));
                for w in [mirror, v3::<R>(rng.direction()), -dv] {
                    let spawned_ray = Ray {
                        origin: offset_origin::<R>(h.p, h.p_error, n, w),
                        direction: w,
                    };
                    assert!(
                        t.intersect(&spawned_ray, inf::<R>()).is_none(),
                        "self-hit: {t:?} {h:?} {spawned_ray:?}"
                    );
                    spawned += 1;
                }
            }
        }
        (spawned, hits)
    }

    #[test]
    fn a_ray_spawned_from_a_hit_with_the_offset_origin_never_hits_the_same_triangle() {
        let n = 20_000;
        let (spawned, hits) = no_self_hits::<f32>(n);
        // Nearly every aimed ray must hit, or the test would test nothing.
        assert!(hits > SCALES.len() * n * 9 / 10, "{hits}");
        assert_eq!(spawned, 3 * hits);
        let (_, hits) = no_self_hits::<f64>(n);
        assert!(hits > SCALES.len() * n * 9 / 10, "{hits}");
    }
}
