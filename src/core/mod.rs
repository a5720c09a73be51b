//! The shading core: Phong's illumination model of Chapter 4, pure and free of I/O.
//!
//! Symbols, as the chapter names them (docs/conventions.md fixes the signs):
//!
//! | symbol | meaning | eq. |
//! |---|---|---|
//! | `p` | P, the point being shaded | |
//! | `n` | N, the unit surface normal at P | |
//! | `l` | L = (P − P_l)/‖P − P_l‖, from the light TO the point (D_l for a directional light) | 4.1 |
//! | `d` | ‖P − P_l‖ | |
//! | `falloff` | f ∈ {0, 1, 2}; I_l = C_l / d^f | 4.2, 4.3 |
//! | `cos_psi`, `cos_gamma`, `e` | spot cone: I_l = C_l / d^f · cos(ψ)^e, zero for ψ > γ | 4.4 |
//! | `o_a`, `i_a` | ambient: O_a I_a (O_a already k_a·O_a) | 4.5, 4.6 |
//! | `o_d`, `cos_theta` | diffuse: O_d I_l cos θ, cos θ = −N·L | 4.7, 4.8 |
//! | `o_s`, `n_s`, `r`, `v`, `cos_phi` | specular: O_s I_l (cos φ)^n_s, R = L − 2(N·L)N, V from the eye TO P, cos φ = −R·V | 4.9–4.15 |
//! | | total: the sum over the lights | 4.16 |
//! | `o_r` | reflectivity; the reflection ray R_V = V − 2(N·V)N adds O_r C_r | 4.17 |
//!
//! Everything is generic over [`Real`] (f32 or f64) from one source.

pub(crate) mod color;
pub(crate) mod lanes;
pub(crate) mod light;
pub(crate) mod material;
pub mod real;
pub(crate) mod rounding;
pub mod secondary;
pub(crate) mod shade;
pub(crate) mod vector;

pub use lanes::{LaneVec, Lanes, Mask, Wide};
pub use light::{Arrival, Cone, ConeTest, Falloff, Light, LightKind, LightSet, Reach};
pub use material::{Material, Transmission};
pub use real::{Precision, Real, Vector, V3};
pub use shade::{
    shade, AllVisible, LightStatus, LightTerm, NoRecord, Recorder, Shade, ShadingPoint,
    SpecularStatus, SpecularTerm, Visibility,
};
pub(crate) use shade::{shade_with, Chapter, Formulas, Slipped};
pub use vector::{between, Normalized};
