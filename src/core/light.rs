//! Virtual lights (Section 4.2) and what each one delivers at a point P: the incidence vector
//! L, the distance d, the falloff factor 1/d^f, the spot cone test and the colour I_l
//! (Eq. 4.1–4.4). Ambient light has no direction and is kept apart, as a sum I_a.

use super::lanes::{LaneVec, Lanes, Mask};
use super::real::{powi_by_squaring, Real, Vector, V3};
use super::vector::between_lanes;

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
    #[inline(always)]
    pub(crate) fn factor<L: Lanes>(self, d: L) -> L {
        let one = L::broadcast(<L::Scalar as Real>::ONE);
        match self {
            Falloff::None => one,
            Falloff::Linear => one / d,
            Falloff::Quadratic => one / d / d,
        }
    }

    /// C_l / d^f, Eq. 4.2, dividing the colour itself so that neither d^f nor 1/d^f is formed:
    /// a tiny colour close to the light, or a huge one far from it, stays representable.
    #[inline(always)]
    pub(crate) fn attenuate<L: Lanes>(self, color: L::V, d: L) -> L::V {
        match self {
            Falloff::None => color,
            Falloff::Linear => color.divided(d),
            Falloff::Quadratic => color.divided(d).divided(d),
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
    /// loses half the digits near 0°. Left at 0 by `Light::arrive_lanes` without detail where
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
/// with room to spare (tests/integration/stability.rs checks it against exactly constructed edges).
/// The size of the coordinates does not enter: the difference of two binary numbers is rounded
/// relative to itself. (A *computed* P, a ray's hit, carries its own error; the solver adds it
/// when it reports how reliable the test is, `solve::findings`.)
const CONE_EDGE_ULPS: f64 = 20.0;
/// Away from the edge by more than this many ε in cos ψ − cos γ, the cheap cosine comparison
/// and the angle comparison agree: within the edge tolerance, |cos ψ − cos γ| ≤ sin γ·20ε(1 + γ)
/// ≤ 52ε, and cos ψ = D_l·L and cos γ are each rounded by a few ε more.
const CONE_COS_MARGIN_ULPS: f64 = 128.0;

/// What a light delivers at the points of some [`Lanes`] (one point, or one per lane), as the
/// core's arithmetic computes it once for both: [`Light::arrival_of`] turns one lane of it into
/// an [`Arrival`], the wide tracer shades with it directly.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneArrival<L: Lanes> {
    /// L (zero where P is at the light).
    pub l: L::V,
    /// d (0 for a directional light, and where P is at the light).
    pub d: L,
    /// 1/d^f (1 for a directional light, 0 where P is at the light).
    pub falloff_factor: L,
    /// I_l.
    pub i_l: L::V,
    /// The lanes where P coincides with the light.
    pub at_light: L::Mask,
    /// The lanes where the light's flux arrives (not at the light, inside the cone).
    pub arrives: L::Mask,
    /// A spot's cone test; `None` for other lights.
    pub cone: Option<LaneCone<L>>,
}

/// A spot's cone test in lanes (see [`ConeTest`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneCone<L: Lanes> {
    /// cos ψ = D_l · L.
    pub cos_psi: L,
    /// ψ in radians where it was formed (0 where cos ψ alone decided).
    pub psi: L,
    /// ψ ≤ γ.
    pub inside: L::Mask,
    /// |ψ − γ| within rounding.
    pub on_edge: L::Mask,
    /// (cos ψ)^e inside the cone, 0 outside.
    pub factor: L,
}

impl<R: Real> Light<R> {
    /// What this light delivers at P (Eq. 4.1–4.4), with every intermediate.
    #[inline]
    #[cfg(test)]
    pub(crate) fn arrive(&self, p: V3<R>) -> Arrival<R> {
        self.arrival_of(&self.arrive_lanes::<R>(p, true))
    }

    /// One lane's [`LaneArrival`] as the record shows it (the scalar instantiation is one lane).
    #[inline(always)]
    pub(crate) fn arrival_of(&self, a: &LaneArrival<R>) -> Arrival<R> {
        let (distance, falloff, cone_of) = match self.kind {
            LightKind::Directional { .. } => (None, None, None),
            LightKind::Point { falloff, .. } => (Some(a.d), Some(falloff), None),
            LightKind::Spot { falloff, cone, .. } => (Some(a.d), Some(falloff), Some(cone)),
        };
        let reach = if a.at_light {
            Reach::AtLight
        } else if a.arrives {
            Reach::Arrives
        } else {
            Reach::OutsideCone
        };
        let cone = match (cone_of, a.cone) {
            (Some(c), Some(t)) if !a.at_light => Some(ConeTest {
                cos_psi: t.cos_psi,
                psi_deg: t.psi.to_degrees(),
                cos_gamma: c.cos_gamma,
                inside: t.inside,
                on_edge: t.on_edge,
                factor: t.factor,
            }),
            _ => None,
        };
        Arrival {
            l: a.l,
            distance,
            falloff,
            falloff_factor: a.falloff_factor,
            cone,
            i_l: a.i_l,
            reach,
        }
    }

    /// What this light delivers at the points `p` of some [`Lanes`] (Eq. 4.1–4.4): the one
    /// source of the arrival for the scalar core and the wide tracer alike. Without `detail`, a
    /// spot's ψ is left at 0 where cos ψ alone decides the cone test, to spare an atan2 on the
    /// tracer's hot path.
    #[inline(always)]
    pub(crate) fn arrive_lanes<L: Lanes<Scalar = R>>(
        &self,
        p: L::V,
        detail: bool,
    ) -> LaneArrival<L> {
        match self.kind {
            LightKind::Directional { direction } => LaneArrival {
                l: L::V::broadcast(direction),
                d: L::broadcast(R::ZERO),
                falloff_factor: L::broadcast(R::ONE),
                i_l: L::V::broadcast(self.color),
                at_light: L::all_lanes().invert(),
                arrives: L::all_lanes(),
                cone: None,
            },
            LightKind::Point { position, falloff } => {
                self.positional::<L>(p, position, falloff, None, detail)
            }
            LightKind::Spot {
                position,
                falloff,
                cone,
            } => self.positional::<L>(p, position, falloff, Some(cone), detail),
        }
    }

    #[inline(always)]
    fn positional<L: Lanes<Scalar = R>>(
        &self,
        p: L::V,
        position: V3<R>,
        falloff: Falloff,
        cone: Option<Cone<R>>,
        detail: bool,
    ) -> LaneArrival<L> {
        let zero = L::broadcast(R::ZERO);
        // Compute the incidence vector and the distance, Eq. 4.1 (none where P is the light).
        let n = between_lanes::<L>(L::V::broadcast(position), p);
        let at_light = n.found.invert();
        let (l, d) = (n.unit, n.length);
        // Attenuate by the falloff, Eq. 4.2 and 4.3.
        let falloff_factor = L::pick(at_light, zero, falloff.factor(d));
        let mut i_l = L::V::pick3(
            at_light,
            L::V::broadcast(V3::<R>::ZERO),
            falloff.attenuate::<L>(L::V::broadcast(self.color), d),
        );
        let mut arrives = n.found;
        // Restrict to the cone and weight by cos(ψ)^e, Eq. 4.4. The test compares angles: ψ from
        // atan2 is accurate to a few ulps everywhere, so the decision is the same in f32 and
        // f64 except within rounding of the edge.
        let cone = cone.map(|c| {
            let cos_psi = L::V::broadcast(c.axis).dot3(l);
            // Far from the edge (by many times the rounding of either side), cos ψ against
            // cos γ decides the same way and costs no atan2; ψ itself is then only formed
            // for a caller that records it.
            let margin = L::broadcast(R::from_f64(CONE_COS_MARGIN_ULPS) * R::EPSILON);
            let cos_gamma = L::broadcast(c.cos_gamma);
            let clear = (cos_psi - cos_gamma).absolute().greater(margin);
            let cheap = if detail {
                L::all_lanes().invert()
            } else {
                clear
            };
            let near = cheap.invert().both(n.found);
            // Near the edge, ψ = atan2(‖D_l × L‖, D_l · L), lane by lane (no lane atan2 gives
            // the scalar's bits).
            let psi = zero.map_lanes(near, |k, _| {
                c.axis
                    .cross(l.lane(k))
                    .naive_length()
                    .atan2(cos_psi.lane(k))
            });
            let tol = L::broadcast(c.edge_tolerance());
            let gamma = L::broadcast(c.gamma);
            let by_angle = psi.at_most(gamma + tol);
            let inside = L::pick_mask(cheap, cos_psi.greater(cos_gamma), by_angle);
            let on_edge = cheap.invert().both((psi - gamma).absolute().at_most(tol));
            // cos ψ may round a hair outside [0, 1] on the edge of a 90° cone or on the axis.
            // A whole exponent (up to 1024) raises min(cos ψ, 1) by repeated squaring in the
            // lanes where cos ψ > 0 (there max(cos ψ, 0) is cos ψ itself); any other power,
            // and cos ψ ≤ 0 or NaN, lane by lane with the scalar's pow.
            let lit = inside.both(n.found);
            let (factor, by_hand) = match super::shade::whole_exponent(c.exponent) {
                Some(e) => {
                    let positive = lit.both(cos_psi.greater(zero));
                    let one = L::broadcast(R::ONE);
                    let base = cos_psi.minimum(one);
                    (
                        L::pick(positive, powi_by_squaring(base, one, e), zero),
                        lit.both(positive.invert()),
                    )
                }
                None => (zero, lit),
            };
            let factor = factor.map_lanes(by_hand, |k, _| {
                cos_psi.lane(k).max(R::ZERO).min(R::ONE).pow(c.exponent)
            });
            LaneCone {
                cos_psi,
                psi,
                inside,
                on_edge,
                factor,
            }
        });
        if let Some(t) = cone {
            i_l = i_l.scaled(t.factor);
            arrives = arrives.both(t.inside);
        }
        LaneArrival {
            l,
            d: L::pick(at_light, zero, d),
            falloff_factor,
            i_l,
            at_light,
            arrives,
            cone,
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
