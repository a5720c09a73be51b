//! How well a ray problem's hit on a plane is determined by its data (docs/accuracy.md, "Hits
//! nearly parallel to a plane"). t = N·(Q − O)/(N·D) divides by N·D, the sine of the angle
//! between the ray and the plane: a ray that grazes the plane makes t, and the hit point
//! O + tD with it, sensitive to the last digits of the data, however exact the arithmetic that
//! follows. The solver reports such a hit (`hit_ill_conditioned`) with a bound on t and on P;
//! the tracer, which meets grazing floors at every horizon, pays nothing for it.
//!
//! Notation as in `solve::rounding`: u = ε/2, γ_k = ku/(1 − ku). "Exact" here means the
//! problem as written in the file, decimals included: each number of the file is read as
//! x(1 + δ), |δ| ≤ u (a correctly rounded decimal), so the bound covers the data's own
//! rounding and the computation's.
//!
//! **The bound.** t is unchanged when N is scaled, so only the relative error of each
//! component of N̂ matters, apart from a factor common to all three: `core::vector::normalize`
//! multiplies by one 1/‖N‖ (or divides twice, by the largest component and by a length), so
//! N̂_i = c·N_i(1 + θ_i) with |θ_i| ≤ 3u, the reading of N_i included; the same for D̂, whose
//! common factor (its computed length is 1 to within a few u) scales t by at most γ₄. Q − O is
//! formed from two read numbers and one subtraction: off by at most 2u(|Q_i| + |O_i|) per
//! component, first order. A product adds u and the two additions of a dot product 2u per term.
//! So the numerator a = N̂·(Q − O) is off by at most e_a = γ₉·Σ|N̂_i|(|Q_i| + |O_i|), the
//! denominator b = N̂·D̂ by at most e_b = γ₉·Σ|N̂_i D̂_i| (both with a spare u for a reading
//! through f64 into f32), and with â, b̂ as computed (|β| ≤ e_b < |b̂|),
//!
//! |t − t̂| ≤ (e_a + |t̂|·e_b)/(|b̂| − e_b) + γ₅|t̂|,
//!
//! from t − t̂ = (âβ − b̂α)/(b̂(b̂ − β)) with |α| ≤ e_a, |β| ≤ e_b (the γ₅: the division's
//! rounding and D̂'s common factor). The hit point P = O + tD̂ is then off by at most
//! |D̂_i|·Δt + γ₆(|O_i| + |t̂ D̂_i|) per component (O read, D̂_i's 3u, the product and the
//! sum). The bound is a worst case: every rounding of the same sign at once. When
//! e_b ≥ |b̂| not even the sign of N·D is known: whether the line meets the plane in front of
//! the origin or behind, or at all, depends on the last digits (`parallel_within_rounding`).
//!
//! **When it is reported.** When the bound on t exceeds 1e-6 of t (the reports print six
//! significant digits, so the last of them could be wrong) *and* the ray grazes the plane,
//! Σ|N̂_i D̂_i| ≥ 100·|N̂·D̂| (the loss comes from N·D, not from the constants of a worst-case
//! bound). In f64 that takes an angle below about 1e-9 rad; in f32 below about 0.01 rad.

use crate::core::rounding::gamma;
use crate::core::{Real, Vector, V3};
use crate::geometry::{Plane, Ray};

/// The relative bound on t above which a hit is reported: the reports' sixth digit.
const REPORTED_RELATIVE: f64 = 1e-6;

/// How much larger Σ|N̂_i D̂_i| must be than |N̂·D̂| for the ray to count as grazing the plane.
const GRAZING: f64 = 100.0;

/// What the data's last digits leave undetermined of a ray's hit on a plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum PlaneHit {
    /// The hit is determined well enough to print (nothing to report).
    WellConditioned,
    /// The hit is ill-conditioned: t and P are known only to within these bounds.
    Ill {
        /// N·D as computed (unit N and D).
        n_dot_d: f64,
        /// The bound on the error of N·D.
        n_dot_d_error: f64,
        /// The bound on |t − t̂|.
        t_error: f64,
        /// The bound on each component of |P − P̂|.
        p_error: [f64; 3],
    },
    /// N·D is within its own error bound of 0: the line may be parallel to the plane.
    Parallel {
        /// N·D as computed (unit N and D).
        n_dot_d: f64,
        /// The bound on the error of N·D.
        n_dot_d_error: f64,
        /// N·(Q − O) is within its error bound of 0 too: the ray may lie in the plane.
        may_lie_in_plane: bool,
    },
}

/// The conditioning of the hit at t̂ = `t` of `ray` on `plane` (see the module doc).
pub(super) fn plane_hit<R: Real>(plane: &Plane<R>, ray: &Ray<R>, t: R) -> PlaneHit {
    let f = |v: V3<R>| v.to_array().map(|x| x.to_f64());
    let (n, q, o, d) = (
        f(plane.normal),
        f(plane.point),
        f(ray.origin),
        f(ray.direction),
    );
    let g = |k: u32| gamma::<R>(k).to_f64();
    // N̂·(Q − O) and N̂·D̂ as the plane computes them, in the precision used.
    let a = plane.normal.dot(plane.point - ray.origin).to_f64();
    let b = plane.normal.dot(ray.direction).to_f64();
    let sa: f64 = (0..3).map(|i| n[i].abs() * (q[i].abs() + o[i].abs())).sum();
    let sb: f64 = (0..3).map(|i| (n[i] * d[i]).abs()).sum();
    let (e_a, e_b) = (g(9) * sa, g(9) * sb);
    if !(a.is_finite() && e_a.is_finite() && e_b.is_finite()) {
        return PlaneHit::WellConditioned;
    }
    if b.abs() <= e_b {
        return PlaneHit::Parallel {
            n_dot_d: b,
            n_dot_d_error: e_b,
            may_lie_in_plane: a.abs() <= e_a,
        };
    }
    let t = t.to_f64();
    let t_error = (e_a + t.abs() * e_b) / (b.abs() - e_b) + g(5) * t.abs();
    let grazing = sb >= GRAZING * b.abs();
    if !(grazing && t_error > REPORTED_RELATIVE * t.abs()) {
        return PlaneHit::WellConditioned;
    }
    let p_error: [f64; 3] =
        std::array::from_fn(|i| d[i].abs() * t_error + g(6) * (o[i].abs() + (t * d[i]).abs()));
    // Bounds beyond f64 (coordinates near the end of the range) are not printed: no finding.
    if !(t_error.is_finite() && p_error.iter().all(|x| x.is_finite())) {
        return PlaneHit::WellConditioned;
    }
    PlaneHit::Ill {
        n_dot_d: b,
        n_dot_d_error: e_b,
        t_error,
        p_error,
    }
}
