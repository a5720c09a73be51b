//! How far the two gates of the core can be trusted in the precision used: bounds on the
//! rounding error of cos θ (Eq. 4.7: lit only where cos θ > 0) and of the spot cone's ψ − γ
//! (Eq. 4.4), and an exact test of cos θ = 0 for given numbers. The solver reports a gate whose
//! computed value lies within its bound (`gate_undecidable`, `light_on_cone_edge`,
//! `cone_edge_undecidable`); the core itself decides as it always does, so the tracer's hot
//! path pays nothing for this.
//!
//! Notation: u = ε/2 is the unit roundoff of the precision, γ_k = ku/(1 − ku) bounds k
//! successive roundings (Higham), and "exact" means exact arithmetic on the numbers as the core
//! receives them (the problem's inputs rounded to the precision; a ray's hit point as computed,
//! whose own error bound is added separately).
//!
//! **cos θ = −N·L.** For given points the difference P − P_l is correctly rounded, so each
//! component of it is off by u *relative to itself*, however large the coordinates are; the
//! normalisation then adds γ₇, so L̂_i = L_i(1 + θ_i), |θ_i| ≤ γ₈ (a directional light's D_l,
//! normalised or used as given when its length is 1 to within 8ε: 16u). The normal likewise:
//! N̂_i = N_i(1 + θ_i), |θ_i| ≤ 16u. The dot product adds γ₃ per term. So
//! |ĉ − c| ≤ γ₃₅·Σ|N_i L_i| ≤ γ₄₀·Σ|N̂_i L̂_i| (the computed sum, the second-order terms inside
//! the margin), plus an absolute few·MIN_POSITIVE for components that underflow while being
//! normalised. Note Σ|N_i L_i|, not 1: with N along an axis the error of cos θ shrinks with
//! cos θ itself, and such a grazing light is decided correctly in any precision.
//!
//! A **computed** hit point P̂ with error bound e = ‖p_error‖ (each component's bound, taken as
//! a vector) moves P − P_l by at most e, so L by at most e/(d − e) ≤ 2e/d (for e ≤ d/2), and a
//! sphere's normal, (P − C)/r, by at most 2e/r: both add to the bound. This is the term that
//! grows with the size of the coordinates (p_error ≈ γ·(|O| + |P| + …)), the shape
//! few·ε·(1 + (|P| + |P_l|)/d) of a rough estimate. A triangle's or a plane's normal does not
//! depend on P; a triangle's is taken as computed from its corners (its rounding, a few ε for
//! a triangle that is not a sliver, is inside the margin of γ₄₀).
//!
//! **ψ − γ** is bounded by the core (`Cone::edge_tolerance`, the derivation in
//! `core/light.rs`); a computed hit point adds 2e/d to ψ as to L.

use std::cmp::Ordering;

use crate::core::shade::tangent_tolerance;
use crate::core::{Real, Vector, V3};

/// The smallest positive normal number of precision `R`.
fn min_positive<R: Real>() -> f64 {
    if R::NAME == "f32" {
        f64::from(f32::MIN_POSITIVE)
    } else {
        f64::MIN_POSITIVE
    }
}

/// What a computed (not given) hit point adds to the bounds: the bound e on its error, and the
/// radius of the sphere whose normal was computed from it.
#[derive(Clone, Copy, Debug)]
pub(super) struct HitError {
    pub e: f64,
    pub sphere_radius: Option<f64>,
}

impl HitError {
    pub(crate) fn new<R: Real>(p_error: V3<R>, sphere_radius: Option<R>) -> Self {
        let a = p_error.to_array().map(|x| x.to_f64());
        HitError {
            e: (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt(),
            sphere_radius: sphere_radius.map(|r| r.to_f64()),
        }
    }
}

/// 2e/x, the most an error e in a point moves a direction from a point at distance x (for
/// e ≤ x/2); 2, which bounds any change of a cosine, beyond that.
fn moved(e: f64, x: f64) -> f64 {
    if 2.0 * e <= x {
        2.0 * e / x
    } else {
        2.0
    }
}

/// A bound on |ĉ − c| for the computed cos θ = −N̂·L̂ (see the module doc). `distance` is d for
/// a point or spot light (`None` for a directional one).
pub(super) fn cos_theta_bound<R: Real>(
    n: V3<R>,
    l: V3<R>,
    distance: Option<R>,
    hit: Option<HitError>,
) -> f64 {
    // γ₄₀·Σ|N_i L_i|: the very tolerance within which the core counts cos θ as 0.
    let mut bound = tangent_tolerance::<R>(n, l).to_f64() + 8.0 * min_positive::<R>();
    if let Some(h) = hit {
        if let Some(d) = distance {
            bound += moved(h.e, d.to_f64());
        }
        if let Some(r) = h.sphere_radius {
            bound += moved(h.e, r);
        }
    }
    bound.min(2.0)
}

/// A bound on the error of the computed ψ − γ (radians): the core's edge tolerance, plus what
/// a computed hit point adds.
pub(super) fn cone_bound<R: Real>(edge_tolerance: R, distance: R, hit: Option<HitError>) -> f64 {
    let extra = hit.map_or(0.0, |h| moved(h.e, distance.to_f64()));
    (edge_tolerance.to_f64() + extra).min(std::f64::consts::PI)
}

/// Whether N·(P − P_l) (for a directional light, N·D_l) is exactly zero for the given numbers,
/// decided exactly: with error-free transformations in f64 (every number of either precision is
/// an f64), each difference is an exact pair, each product of N with a part of it an exact
/// pair (by fused multiply-add), and the exact sum of those twelve numbers is formed as a
/// non-overlapping expansion. `None` where a step overflows or a product underflows (then it
/// cannot be told this way).
pub(super) fn exactly_zero<R: Real>(n: V3<R>, p: V3<R>, from: Option<V3<R>>) -> Option<bool> {
    let n = n.to_array().map(|x| x.to_f64());
    let p = p.to_array().map(|x| x.to_f64());
    let q = from.map_or([0.0; 3], |q| q.to_array().map(|x| x.to_f64()));
    let mut terms = Vec::with_capacity(12);
    for i in 0..3 {
        let (s, e) = two_sum(p[i], -q[i]);
        for part in [s, e] {
            let (h, l) = two_product(n[i], part)?;
            terms.extend([h, l]);
        }
    }
    exact_sign(&terms).map(|o| o == Ordering::Equal)
}

/// a + b as the rounded sum and its exact error (Knuth's TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a·b as the rounded product and its exact error (by fused multiply-add); `None` where the
/// error is not exact: the product overflows, or its error has bits below the subnormal range.
fn two_product(a: f64, b: f64) -> Option<(f64, f64)> {
    let h = a * b;
    if !h.is_finite() {
        return None;
    }
    if a == 0.0 || b == 0.0 {
        return Some((h, 0.0));
    }
    // a·b − h is a multiple of lsb(a)·lsb(b) (each number's lowest set bit) smaller than an ulp
    // of h: representable exactly when that multiple is not below 2^-1074.
    if lowest_bit_exponent(a) + lowest_bit_exponent(b) < -1074 {
        return None;
    }
    Some((h, a.mul_add(b, -h)))
}

/// The exponent k of the lowest set bit 2^k of a finite non-zero x.
fn lowest_bit_exponent(x: f64) -> i32 {
    let bits = x.to_bits() & !(1u64 << 63);
    let field = (bits >> 52) as i32;
    let mantissa = bits & ((1u64 << 52) - 1);
    if field == 0 {
        -1074 + mantissa.trailing_zeros() as i32
    } else {
        field - 1075 + (mantissa | (1u64 << 52)).trailing_zeros() as i32
    }
}

/// The sign of the exact sum of `terms`: Shewchuk's grow-expansion keeps the sum as
/// non-overlapping components, the largest last, whose sign is the sum's. `None` on overflow.
fn exact_sign(terms: &[f64]) -> Option<Ordering> {
    let mut e: Vec<f64> = Vec::with_capacity(terms.len());
    for &t in terms {
        let mut q = t;
        let mut next = Vec::with_capacity(e.len() + 1);
        for &c in &e {
            let (s, err) = two_sum(q, c);
            if err != 0.0 {
                next.push(err);
            }
            q = s;
        }
        if !q.is_finite() {
            return None;
        }
        next.push(q);
        e = next;
    }
    let top = e.iter().rev().find(|&&x| x != 0.0).copied().unwrap_or(0.0);
    top.partial_cmp(&0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn an_exact_zero_is_told_from_a_tiny_value_that_rounding_hides() {
        // N = (1, 1, 0), P − P_l = (1, −1, 0): exactly 0.
        let n = DVec3::new(1.0, 1.0, 0.0);
        let p = DVec3::new(3.0, 1.0, 7.0);
        assert_eq!(
            exactly_zero::<f64>(n, p, Some(DVec3::new(2.0, 2.0, 7.0))),
            Some(true)
        );
        // P_l moved by one ulp of 2 in y: N·(P − P_l) = −2^-51 ≠ 0.
        let q = DVec3::new(2.0, 2f64.next_up(), 7.0);
        assert_eq!(exactly_zero::<f64>(n, p, Some(q)), Some(false));
        // Large coordinates: 1e16 + 2 and 1e16 − 2 are exact, the products cancel exactly.
        let n = DVec3::new(3.0, 3.0, 0.0);
        let p = DVec3::new(1e16 + 2.0, -1e16 + 2.0, 0.0);
        let q = DVec3::new(0.0, 4.0, 1.0);
        assert_eq!(exactly_zero::<f64>(n, p, Some(q)), Some(true));
        // A directional light: N·D_l.
        let d = DVec3::new(1e-300, 0.0, 5.0);
        assert_eq!(exactly_zero::<f64>(DVec3::X, d, None), Some(false));
        assert_eq!(exactly_zero::<f64>(DVec3::Y, d, None), Some(true));
    }

    #[test]
    fn products_whose_error_would_underflow_are_not_decided() {
        let x = DVec3::new(0.1e-200, 0.0, 0.0);
        assert_eq!(exactly_zero::<f64>(x, x, None), None);
        // A power of two times anything is exact, however small.
        let two = DVec3::new(2f64.powi(-100), 0.0, 0.0);
        assert_eq!(exactly_zero::<f64>(two, x, None), Some(false));
        assert_eq!(lowest_bit_exponent(1.0), 0);
        assert_eq!(lowest_bit_exponent(0.75), -2);
        assert_eq!(lowest_bit_exponent(f64::from_bits(1)), -1074);
        assert_eq!(lowest_bit_exponent(-6.0), 1);
    }

    #[test]
    fn the_cos_theta_bound_is_a_few_epsilon_for_given_points_and_grows_with_a_hit_s_error() {
        let n = DVec3::new(0.0, 0.6, 0.8);
        let l = DVec3::new(0.0, 0.8, -0.6);
        // Σ|N_i L_i| = 0.48 + 0.48 = 0.96: γ₄₀·0.96 ≈ 4.3e-15 (plus 8·MIN_POSITIVE).
        let b = cos_theta_bound::<f64>(n, l, Some(5.0), None);
        let g40 = 40.0 * f64::EPSILON / 2.0;
        assert!((b / (g40 * 0.96) - 1.0).abs() < 1e-10, "{b}");
        // A hit point known to 1e-6 at d = 5 adds 2e-6/5; on a sphere of radius 2, 2e-6/2.
        let hit = HitError::new::<f64>(DVec3::new(1e-6, 0.0, 0.0), Some(2.0));
        let b = cos_theta_bound::<f64>(n, l, Some(5.0), Some(hit));
        assert!((b - (g40 * 0.96 + 4e-7 + 1e-6)).abs() < 1e-18, "{b}");
        // An error beyond half the distance says nothing: the bound is 2.
        let hit = HitError::new::<f64>(DVec3::new(3.0, 0.0, 0.0), None);
        assert_eq!(cos_theta_bound::<f64>(n, l, Some(5.0), Some(hit)), 2.0);
    }
}
