//! Virtual lights (Section 4.2) and what each one delivers at a point P: the incidence vector
//! L, the distance d, the falloff factor 1/d^f, the spot cone test and the colour I_l
//! (Eq. 4.1–4.4). Ambient light has no direction and is kept apart, as a sum I_a.

use super::real::{Real, Vector, V3};
use super::vector::between;

/// The falloff exponent f of Eq. 4.3.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Falloff {
    /// f = 0: I_l = C_l.
    None,
    /// f = 1: I_l = C_l / d.
    Linear,
    /// f = 2: I_l = C_l / d².
    Quadratic,
}

impl Falloff {
    /// The falloff from its exponent f ∈ {0, 1, 2}.
    pub(crate) fn from_exponent(f: u8) -> Option<Falloff> {
        match f {
            0 => Some(Falloff::None),
            1 => Some(Falloff::Linear),
            2 => Some(Falloff::Quadratic),
            _ => None,
        }
    }

    /// The exponent f.
    pub(crate) fn exponent(self) -> u8 {
        match self {
            Falloff::None => 0,
            Falloff::Linear => 1,
            Falloff::Quadratic => 2,
        }
    }

    /// The factor 1/d^f, for the record, computed as repeated division so that d² is never
    /// formed: d = 1e160 gives 1e-320 in f64 rather than overflowing d² to infinity.
    #[inline]
    pub(crate) fn factor<R: Real>(self, d: R) -> R {
        match self {
            Falloff::None => R::ONE,
            Falloff::Linear => R::ONE / d,
            Falloff::Quadratic => R::ONE / d / d,
        }
    }

    /// C_l / d^f, Eq. 4.2, dividing the colour itself so that neither d^f nor 1/d^f is formed:
    /// a tiny colour close to the light, or a huge one far from it, stays representable.
    #[inline]
    pub(crate) fn attenuate<R: Real, V: Vector<R>>(self, color: V, d: R) -> V {
        match self {
            Falloff::None => color,
            Falloff::Linear => color / d,
            Falloff::Quadratic => color / d / d,
        }
    }
}

/// The cone of a spot light (Eq. 4.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone<R: Real> {
    /// D_l: the unit axis, pointing away from the apex.
    pub axis: V3<R>,
    /// γ_l in degrees, 0 ≤ γ ≤ 90: the angle between the axis and the cone's side.
    pub angle_deg: R,
    /// γ_l in radians, precomputed.
    pub gamma: R,
    /// cos γ_l, precomputed (for the record).
    pub cos_gamma: R,
    /// e_l: the exponent of cos ψ.
    pub exponent: R,
}

impl<R: Real> Cone<R> {
    /// The cone with unit axis D_l, angle γ_l in degrees and exponent e_l, its γ_l in radians
    /// and cos γ_l computed once.
    pub fn new(axis: V3<R>, angle_deg: R, exponent: R) -> Self {
        Cone {
            axis,
            angle_deg,
            gamma: angle_deg.to_radians(),
            cos_gamma: angle_deg.cos_deg(),
            exponent,
        }
    }

    /// The bound (radians) on the rounding error of the computed ψ − γ for an exact P: a point
    /// with |ψ − γ| within it is on the edge to within rounding (see `CONE_EDGE_ULPS`).
    #[inline]
    pub(crate) fn edge_tolerance(&self) -> R {
        R::from_f64(CONE_EDGE_ULPS) * R::EPSILON * (R::ONE + self.gamma)
    }
}

/// Where the light is and how its colour decays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind<R: Real> {
    /// A point light at P_l.
    Point {
        /// P_l, the light's position.
        position: V3<R>,
        /// f, how its colour falls off with the distance d (Eq. 4.2–4.3).
        falloff: Falloff,
    },
    /// A directional light travelling along the unit vector D_l.
    Directional {
        /// D_l, unit: the direction the light travels in (L = D_l at every point).
        direction: V3<R>,
    },
    /// A spot light: a point light whose flux is restricted to a cone.
    Spot {
        /// P_l, the light's position (the cone's apex).
        position: V3<R>,
        /// f, how its colour falls off with the distance d (Eq. 4.2–4.3).
        falloff: Falloff,
        /// The cone: D_l, γ_l and e_l (Eq. 4.4).
        cone: Cone<R>,
    },
}

/// A light other than ambient: its colour C_l and its kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light<R: Real> {
    /// C_l, the light's colour (I_l = C_l / d^f, Eq. 4.2).
    pub color: V3<R>,
    /// Where it is and how its colour decays: point, directional or spot.
    pub kind: LightKind<R>,
}

/// Whether a light's flux arrives at the point at all.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Reach {
    /// The light arrives (it may still be behind the surface).
    Arrives,
    /// A spot light and the point lies outside its cone (ψ > γ): I_l = 0.
    OutsideCone,
    /// The point coincides with the light's position: L is undefined.
    AtLight,
}

/// The result of the spot cone test, ψ against γ (Eq. 4.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConeTest<R: Real> {
    /// cos ψ = D_l · L.
    pub cos_psi: R,
    /// ψ in degrees, from atan2(‖D_l × L‖, D_l · L): accurate at every angle, where acos(cos ψ)
    /// loses half the digits near 0°. Left at 0 by `Light::arrive_with` without detail where
    /// cos ψ alone decided the test.
    pub psi_deg: R,
    /// cos γ_l, the cosine of the cone's angle.
    pub cos_gamma: R,
    /// ψ ≤ γ (a point on the edge counts as inside).
    pub inside: bool,
    /// |ψ − γ| within rounding: the point sits on the cone's edge.
    pub on_edge: bool,
    /// (cos ψ)^e inside the cone, 0 outside.
    pub factor: R,
}

/// What one light delivers at P (Eq. 4.1–4.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arrival<R: Real> {
    /// L: the unit vector from the light to P (the direction of travel for a directional light).
    pub l: V3<R>,
    /// d = ‖P − P_l‖; `None` for a directional light.
    pub distance: Option<R>,
    /// The falloff f; `None` for a directional light.
    pub falloff: Option<Falloff>,
    /// 1/d^f (1 for a directional light).
    pub falloff_factor: R,
    /// The spot cone test; `None` for other lights.
    pub cone: Option<ConeTest<R>>,
    /// I_l: the light's colour at P.
    pub i_l: V3<R>,
    /// Whether the light's flux arrives at P at all (inside the cone, P not at the light).
    pub reach: Reach,
}

/// Tolerance of the cone-edge test in units of machine epsilon ε (radians, times 1 + γ): a
/// point whose computed ψ lies within this of the computed γ is on the edge to within rounding,
/// and the edge is lit (docs/conventions.md, "Spot cone"). It bounds the error of ψ − γ for
/// exact (binary) P, P_l, D_l and angle, with u = ε/2 and γ_k = ku/(1 − ku):
/// - D_l as used is the given axis normalised (γ₆ per component: its direction is off by at
///   most γ₆ rad) or, when its length is 1 to within 8ε, the given vector itself (the same
///   direction; the angle from atan2 does not depend on the length);
/// - L = (P − P_l)/d: the difference is correctly rounded (u, relative, whatever the size of the
///   coordinates), then normalised (γ₇): off by at most γ₈ rad;
/// - atan2(‖D_l × L‖, D_l·L) of the rounded vectors: each cross component a_j b_k − a_k b_j is
///   off by γ₂(|a_j b_k| + |a_k b_j|), √2·γ₂ in all, its length by γ₃, the dot by γ₃; moving
///   (sin ψ, cos ψ) by that moves the angle by at most γ₈; atan2 itself is within 2 ulp (4u·ψ);
/// - γ in radians is γ°·(π/180) with π/180 rounded: 3u·γ.
///
/// In all about γ₂₂ + 4u·ψ + 3u·γ ≈ 11ε + 3.5ε·γ near the edge, plus second-order terms and
/// the underflow of a cross product below √(MIN_POSITIVE), far below ε; 20ε·(1 + γ) covers it
/// with room to spare (tests/stability.rs checks it against exactly constructed edges).
/// The size of the coordinates does not enter: the difference of two binary numbers is rounded
/// relative to itself. (A *computed* P, a ray's hit, carries its own error; the solver adds it
/// when it reports how reliable the test is, `solve::findings`.)
const CONE_EDGE_ULPS: f64 = 20.0;
/// Away from the edge by more than this many ε in cos ψ − cos γ, the cheap cosine comparison
/// and the angle comparison agree: within the edge tolerance, |cos ψ − cos γ| ≤ sin γ·20ε(1 + γ)
/// ≤ 52ε, and cos ψ = D_l·L and cos γ are each rounded by a few ε more.
const CONE_COS_MARGIN_ULPS: f64 = 128.0;

impl<R: Real> Light<R> {
    /// What this light delivers at P (Eq. 4.1–4.4), with every intermediate.
    #[inline]
    #[cfg(test)]
    pub(crate) fn arrive(&self, p: V3<R>) -> Arrival<R> {
        self.arrive_with(p, true)
    }

    /// [`Light::arrive`]; without `detail`, a spot's ψ (degrees) is left at 0 where cos ψ alone
    /// decides the cone test, to spare an atan2 on the tracer's hot path.
    #[inline]
    pub(crate) fn arrive_with(&self, p: V3<R>, detail: bool) -> Arrival<R> {
        match self.kind {
            LightKind::Directional { direction } => Arrival {
                l: direction,
                distance: None,
                falloff: None,
                falloff_factor: R::ONE,
                cone: None,
                i_l: self.color,
                reach: Reach::Arrives,
            },
            LightKind::Point { position, falloff } => {
                self.positional(p, position, falloff, None, detail)
            }
            LightKind::Spot {
                position,
                falloff,
                cone,
            } => self.positional(p, position, falloff, Some(cone), detail),
        }
    }

    fn positional(
        &self,
        p: V3<R>,
        position: V3<R>,
        falloff: Falloff,
        cone: Option<Cone<R>>,
        detail: bool,
    ) -> Arrival<R> {
        // Compute the incidence vector and the distance, Eq. 4.1.
        let Some(n) = between::<R>(position, p) else {
            return Arrival {
                l: V3::<R>::ZERO,
                distance: Some(R::ZERO),
                falloff: Some(falloff),
                falloff_factor: R::ZERO,
                cone: None,
                i_l: V3::<R>::ZERO,
                reach: Reach::AtLight,
            };
        };
        let (l, d) = (n.unit, n.length);
        // Attenuate by the falloff, Eq. 4.2 and 4.3.
        let falloff_factor = falloff.factor(d);
        let mut i_l = falloff.attenuate(self.color, d);
        let mut reach = Reach::Arrives;
        // Restrict to the cone and weight by cos(ψ)^e, Eq. 4.4. The test compares angles: ψ from
        // atan2 is accurate to a few ulps everywhere, so the decision is the same in f32 and
        // f64 except within rounding of the edge.
        let cone = cone.map(|c| {
            let cos_psi = c.axis.dot(l);
            // Far from the edge (by many times the rounding of either side), cos ψ against
            // cos γ decides the same way and costs no atan2; ψ itself is then only formed
            // for a caller that records it.
            let margin = R::from_f64(CONE_COS_MARGIN_ULPS) * R::EPSILON;
            let clear = (cos_psi - c.cos_gamma).abs() > margin;
            let (psi, inside, on_edge) = if clear && !detail {
                (R::ZERO, cos_psi > c.cos_gamma, false)
            } else {
                let psi = c.axis.cross(l).naive_length().atan2(cos_psi);
                let tol = c.edge_tolerance();
                (psi, psi <= c.gamma + tol, (psi - c.gamma).abs() <= tol)
            };
            // cos ψ may round a hair outside [0, 1] on the edge of a 90° cone or on the axis.
            let factor = if inside {
                cos_psi.max(R::ZERO).min(R::ONE).pow(c.exponent)
            } else {
                R::ZERO
            };
            ConeTest {
                cos_psi,
                psi_deg: psi.to_degrees(),
                cos_gamma: c.cos_gamma,
                inside,
                on_edge,
                factor,
            }
        });
        if let Some(t) = cone {
            i_l = i_l * t.factor;
            if !t.inside {
                reach = Reach::OutsideCone;
            }
        }
        Arrival {
            l,
            distance: Some(d),
            falloff: Some(falloff),
            falloff_factor,
            cone,
            i_l,
            reach,
        }
    }

    /// The light's position, for point and spot lights.
    pub(crate) fn position(&self) -> Option<V3<R>> {
        match self.kind {
            LightKind::Point { position, .. } | LightKind::Spot { position, .. } => Some(position),
            LightKind::Directional { .. } => None,
        }
    }
}

/// All the lights of a problem or scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LightSet<R: Real> {
    /// I_a: the sum of the ambient lights' colours; `None` when there is no ambient light.
    pub ambient: Option<V3<R>>,
    /// The point, directional and spot lights, in the order given.
    pub lights: Vec<Light<R>>,
}
