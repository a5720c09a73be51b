//! The rules of Section 4.4 that decide a secondary ray, shared by the solver (which shows a
//! ray problem's R_V and T) and the tracer (which traces them): why a ray spawns no child
//! ([`Stop`]), what a ray of the tree is ([`RayKind`]), and Snell's law at a hit
//! ([`Refraction`]; docs/conventions.md, "Transmission"). They sit here, below both, so that
//! the solver and the tracer take one rule and neither imports the other's.

use super::vector::normalize;
use super::{Real, Vector, V3};

/// Why a ray spawns no reflection ray, or no transmission ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The ray hit nothing: its colour is the background.
    Miss,
    /// The surface has no reflectivity (O_r absent or zero): no reflection ray.
    NotReflective,
    /// The child's level would exceed the maximum level.
    MaxLevel,
    /// The child's weight (w_p·max(O_r), or w_p·max(O_t)) would not exceed the minimum weight.
    MinWeight,
    /// The surface's transmissivity O_t is zero: no transmission ray.
    NotTransmissive,
    /// Snell's law has no solution (k < 0, the ray meets the surface beyond the critical angle
    /// from the denser side): total internal reflection, no transmission ray.
    TotalInternalReflection,
}

/// What a ray of the tree is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RayKind {
    /// A pixel's ray, level 1.
    Primary,
    /// A reflection ray, Eq. 4.17.
    Reflection,
    /// A transmission ray, by Snell's law.
    Transmission,
}

/// Snell's law at a hit, as the explanation shows it (docs/conventions.md, "Transmission"): the
/// two media, the angle, and the transmitted direction T = η_r V + (η_r cos θ_i − √k) N, with
/// N facing the ray, cos θ_i = −N·V, η_r = η_i/η_t and k = 1 − η_r²(1 − cos²θ_i).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refraction<R: Real> {
    /// Whether the ray enters the material (it arrives against the surface's own normal).
    pub entering: bool,
    /// η_i, the index of the medium the ray travels in.
    pub eta_i: R,
    /// η_t, the index of the medium beyond the surface.
    pub eta_t: R,
    /// cos θ_i = −N·V, with N facing the ray.
    pub cos_i: R,
    /// k = 1 − η_r²(1 − cos²θ_i) = cos²θ_t; negative beyond the critical angle.
    pub k: R,
    /// T, unit; `None` under total internal reflection (k < 0).
    pub direction: Option<V3<R>>,
}

impl<R: Real> Refraction<R> {
    /// Snell's law for a ray along `v` (unit) meeting a surface whose own normal is `normal`,
    /// `n` being that normal turned to face the ray, with the material's `eta` inside.
    #[inline]
    pub fn at(v: V3<R>, normal: V3<R>, n: V3<R>, eta: R) -> Self {
        // Against the surface's own normal: from the outside (index 1) into the material.
        let entering = normal.dot(v) < R::ZERO;
        let (eta_i, eta_t) = if entering {
            (R::ONE, eta)
        } else {
            (eta, R::ONE)
        };
        let eta_r = eta_i / eta_t;
        let cos_i = -n.dot(v);
        // 1 − cos²θ_i, kept ≥ 0 against rounding.
        let sin2_i = (R::ONE - cos_i * cos_i).max(R::ZERO);
        let k = R::ONE - eta_r * eta_r * sin2_i;
        let direction = if k < R::ZERO {
            None
        } else {
            let t = v * eta_r + n * (eta_r * cos_i - k.sqrt());
            normalize::<R>(t).map(|t| t.unit)
        };
        Refraction {
            entering,
            eta_i,
            eta_t,
            cos_i,
            k,
            direction,
        }
    }
}
