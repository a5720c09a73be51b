//! The rounding-error bound γ_n of n successive roundings (Higham; pbrt-v4 §6.8.1, `gamma(n)`),
//! defined once: the core's tangent tolerance (γ₄₀), the geometry's error bounds of hit points,
//! boxes and triangle tests, and the shadow ray's stop short of a light all take it from here.

use super::real::Real;

/// γ_n = nu/(1 − nu), with u the unit roundoff (`EPSILON`/2): a bound on the relative error of
/// n successive roundings, |(1 ± u)ⁿ − 1| ≤ γ_n. (nu = (n/2)·`EPSILON` exactly, so γ₄₀ is
/// 20·`EPSILON`/(1 − 20·`EPSILON`) to the bit.)
#[inline]
pub fn gamma<R: Real>(n: u32) -> R {
    let nu = R::from_f64(f64::from(n)) * (R::EPSILON / R::TWO);
    nu / (R::ONE - nu)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gamma_is_the_bound_of_n_roundings<R: Real>() {
        // γ₁ = u/(1 − u) with u = EPSILON/2: just above half an ulp of 1.
        let u = R::EPSILON.to_f64() / 2.0;
        let g1 = gamma::<R>(1).to_f64();
        assert!((g1 - u / (1.0 - u)).abs() <= u * u * 4.0, "{g1}");
        let g3 = gamma::<R>(3).to_f64();
        assert!(
            (g3 - 3.0 * u / (1.0 - 3.0 * u)).abs() <= u * u * 16.0,
            "{g3}"
        );
        assert_eq!(gamma::<R>(0), R::ZERO);
    }

    #[test]
    fn gamma_is_n_epsilon_over_one_minus_n_epsilon() {
        gamma_is_the_bound_of_n_roundings::<f32>();
        gamma_is_the_bound_of_n_roundings::<f64>();
    }

    fn gamma_40_is_twenty_epsilon_to_the_bit<R: Real>() {
        // The tangent tolerance's γ₄₀ was once written 20ε/(1 − 20ε) with ε = EPSILON.
        let twenty = R::from_f64(20.0) * R::EPSILON;
        let spelled_out = twenty / (R::ONE - twenty);
        assert_eq!(
            gamma::<R>(40).to_f64().to_bits(),
            spelled_out.to_f64().to_bits()
        );
    }

    #[test]
    fn gamma_40_is_the_tangent_tolerance_s_old_expression() {
        gamma_40_is_twenty_epsilon_to_the_bit::<f32>();
        gamma_40_is_twenty_epsilon_to_the_bit::<f64>();
    }
}
