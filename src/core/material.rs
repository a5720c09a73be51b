//! Surface materials (Section 4.3): the colours O_a, O_d, O_s (each already the product k·O),
//! the shininess n_s and the reflectivity O_r of Section 4.4.

use super::real::{Real, V3};

/// A material as the core uses it. A colour that is `None` was not given; the term that needs
/// it is not computed (the problem layer decides whether that is an error).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material<R: Real> {
    /// O_a = k_a·O_a, Eq. 4.5–4.6.
    pub o_a: Option<V3<R>>,
    /// O_d = k_d·O_d, Eq. 4.7–4.8.
    pub o_d: Option<V3<R>>,
    /// O_s = k_s·O_s, Eq. 4.9–4.10.
    pub o_s: Option<V3<R>>,
    /// n_s ≥ 0, the specular exponent.
    pub n_s: R,
    /// O_r, the reflectivity of Section 4.4 (explicit, or equal to O_s).
    pub o_r: Option<V3<R>>,
    /// O_t and η, the transmission of Section 4.4 ("idem para a transmissão ou refração, se
    /// considerada"); `None` for an opaque material.
    pub transmission: Option<Transmission<R>>,
}

/// A material's transmission (docs/conventions.md, "Transmission"): the transmissivity O_t,
/// which scales the colour C_t a transmitted ray brings back as O_r scales C_r, and the index
/// of refraction η of the material's inside (the side its surface's normal points away from),
/// the outside's being 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transmission<R: Real> {
    /// O_t: an RGB colour, each component ≥ 0 (zero: no transmission ray, as with O_r).
    pub o_t: V3<R>,
    /// η, the inside's index of refraction: 0.001 to 1000 once validated, so that Snell's law
    /// cannot overflow (`problem::validate::MAX_IOR`).
    pub eta: R,
}
