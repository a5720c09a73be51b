//! Phong's model at one point, Eq. 4.16, gated as docs/conventions.md ("Gating") reads the
//! chapter, recording every intermediate per light for callers that want it and nothing for
//! callers that do not.
//!
//! The caller passes a [`Recorder`]: [`NoRecord`] (the tracer's hot path: no allocation, no
//! literal values) or a `Vec<LightTerm>` (the solver's explanation). Shadowing is the caller's
//! business, asked through a [`Visibility`]; the core itself does no I/O and knows no scene.

use super::lanes::{LaneVec, Lanes, Mask};
use super::light::{Arrival, LaneArrival, Light, LightSet};
use super::material::Material;
use super::real::{powi_by_squaring, Real, Vector, V3};
use super::rounding::gamma;

/// The point being shaded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingPoint<R: Real> {
    /// P.
    pub p: V3<R>,
    /// N, unit length.
    pub n: V3<R>,
    /// V, unit, from the eye TO the point; `None` when the problem has no viewer.
    pub v: Option<V3<R>>,
}

/// Why a light does or does not add diffuse and specular light.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LightStatus {
    /// cos θ > 0 (beyond its rounding error, `tangent_tolerance`) and the light arrives: it
    /// adds diffuse (and specular where cos φ > 0).
    Lit,
    /// cos θ < 0 (beyond its rounding error): the light is on the back side of the surface.
    BehindSurface,
    /// cos θ = 0 to within its rounding error: the light lies in the tangent plane.
    InTangentPlane,
    /// A spot light and P is outside its cone.
    OutsideCone,
    /// P coincides with the light's position.
    AtLight,
    /// Something blocks the way from P to the light (decided by the caller).
    InShadow,
}

impl LightStatus {
    /// Every status, in the order of the enum (for tests that must meet each one, and for
    /// tables of their wording).
    pub const ALL: [LightStatus; 6] = [
        LightStatus::Lit,
        LightStatus::BehindSurface,
        LightStatus::InTangentPlane,
        LightStatus::OutsideCone,
        LightStatus::AtLight,
        LightStatus::InShadow,
    ];
}

/// Why the specular term is what it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SpecularStatus {
    /// cos φ > 0 and the light is lit: O_s I_l (cos φ)^n_s.
    Lit,
    /// cos φ ≤ 0: the reflection R points away from the viewer.
    AwayFromViewer,
    /// The light does not light the front of the surface (see the light's status).
    LightNotLit,
    /// No viewer: V, and so cos φ, cannot be computed.
    NoViewer,
    /// The material has no specular colour O_s.
    NoSpecularColor,
}

/// The specular part of one light's contribution, Eq. 4.9–4.15.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpecularTerm<R: Real> {
    /// Why the term is what it is (lit, R away from the viewer, no viewer, …).
    pub status: SpecularStatus,
    /// R = L − 2(N·L)N, Eq. 4.15 (computed only where needed).
    pub r: Option<V3<R>>,
    /// cos φ = −R·V, Eq. 4.10.
    pub cos_phi: Option<R>,
    /// (cos φ)^n_s where it was used (status `Lit`).
    pub cos_phi_pow: Option<R>,
    /// The gated term (zero unless `Lit`).
    pub term: V3<R>,
    /// O_s I_l (−R·V)^n_s without gating; `None` when not recorded, or undefined (a negative
    /// cos φ raised to a non-integer n_s).
    pub literal: Option<V3<R>>,
}

impl<R: Real> SpecularTerm<R> {
    /// A specular term that was not computed, for the reason `status` gives.
    fn skipped(status: SpecularStatus) -> Self {
        SpecularTerm {
            status,
            r: None,
            cos_phi: None,
            cos_phi_pow: None,
            term: V3::<R>::ZERO,
            literal: None,
        }
    }
}

/// Everything one light contributes at P.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightTerm<R: Real> {
    /// The light's position in the scene's list, from 0.
    pub index: usize,
    /// L, d, the falloff factor, the cone test and I_l (Eq. 4.1–4.4).
    pub arrival: Arrival<R>,
    /// N·L.
    pub n_dot_l: R,
    /// cos θ = −N·L, Eq. 4.7.
    pub cos_theta: R,
    /// Whether the light adds diffuse and specular light at P, and if not why.
    pub status: LightStatus,
    /// The gated diffuse term O_d I_l cos θ, Eq. 4.8; `None` when the material has no O_d.
    pub diffuse: Option<V3<R>>,
    /// O_d I_l cos θ without gating (recorded only when the recorder asks for detail).
    pub diffuse_literal: Option<V3<R>>,
    /// The specular term, Eq. 4.9–4.15.
    pub specular: SpecularTerm<R>,
}

/// The result of shading a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shade<R: Real> {
    /// O_a I_a, Eq. 4.6; `None` when there is no ambient light or no O_a.
    pub ambient: Option<V3<R>>,
    /// Σ diffuse terms.
    pub diffuse: V3<R>,
    /// Σ specular terms.
    pub specular: V3<R>,
    /// The total, Eq. 4.16 with gating, unclamped.
    pub color: V3<R>,
    /// Eq. 4.16 taken literally (no gating); `None` when not recorded or undefined.
    pub literal: Option<V3<R>>,
}

/// Receives each light's record. `DETAIL` also asks the core for the literal (ungated) values
/// and for R and cos φ of lights that do not light the point.
pub trait Recorder<R: Real> {
    /// Whether the core computes the literal values and the R and cos φ of unlit lights for
    /// this recorder (`false` costs nothing on the hot path).
    const DETAIL: bool;
    /// Receives one light's record, in the order of the light set.
    fn light(&mut self, term: &LightTerm<R>);
}

/// Records nothing: the tracer's hot path.
pub struct NoRecord;

impl<R: Real> Recorder<R> for NoRecord {
    const DETAIL: bool = false;
    #[inline(always)]
    fn light(&mut self, _: &LightTerm<R>) {}
}

impl<R: Real> Recorder<R> for Vec<LightTerm<R>> {
    const DETAIL: bool = true;
    fn light(&mut self, term: &LightTerm<R>) {
        self.push(*term);
    }
}

/// Decides whether a light that faces the point actually reaches it (shadow rays).
pub trait Visibility<R: Real> {
    /// Whether `light`, which lights P from the front and arrives as `arrival` says, reaches P
    /// unblocked.
    fn visible(&mut self, p: V3<R>, light: &Light<R>, arrival: &Arrival<R>) -> bool;
}

/// `None` sees every light (shadows off); `Some(v)` asks `v`.
impl<R: Real, V: Visibility<R>> Visibility<R> for Option<V> {
    #[inline(always)]
    fn visible(&mut self, p: V3<R>, light: &Light<R>, arrival: &Arrival<R>) -> bool {
        match self {
            Some(v) => v.visible(p, light, arrival),
            None => true,
        }
    }
}

/// Every light reaches the point: the solver's single-point problems have no occluders.
pub struct AllVisible;

impl<R: Real> Visibility<R> for AllVisible {
    #[inline(always)]
    fn visible(&mut self, _: V3<R>, _: &Light<R>, _: &Arrival<R>) -> bool {
        true
    }
}

/// (cos φ)^n_s for 0 < cos φ, cos φ = −R·V with unit R and V (Eq. 4.9, 4.10), clamped to at
/// most 1 (cos φ may round a hair above 1, which a huge n_s must not turn into infinity).
///
/// Near cos φ = 1 the rounding of cos φ itself (a few ε, absolute) is what limits the power:
/// (cos φ)^n = exp(n·ln cos φ) moves by a factor exp(±n·few ε). Where n ≫ 1/ε that turns a true
/// exp(−n(1 − cos φ)) ≈ 0 into a spurious 1 (1 − 10⁻¹⁰ is 1 in f32; 1 − 10⁻¹⁷ is 1 in f64). So
/// where `pow` would use `powf` anyway (n_s not a whole number up to 1024, see [`Real::pow`])
/// and cos φ > 1/2, the power is formed from 1 − cos φ = ‖R + V‖²/2, which for unit R and V has
/// no cancellation (R + V is small and exact where R ≈ −V, and the lengths' own rounding
/// enters relatively), as exp(n·ln_1p(−(1 − cos φ))). A whole n_s up to 1024 keeps the
/// repeated squaring: its result moves by at most a factor 1 ± 1024·few ε, never to a spurious
/// 1, and the tracer's usual shininess stays on its fast path.
#[inline]
fn cos_phi_pow<R: Real>(cos_phi: R, r: V3<R>, v: V3<R>, n_s: R) -> R {
    let c = cos_phi.min(R::ONE);
    let by_squaring = n_s.trunc() == n_s && n_s <= R::from_f64(1024.0);
    if by_squaring || c <= R::ONE / R::TWO {
        return c.pow(n_s);
    }
    let s = r + v;
    let one_minus_cos = s.dot(s) / R::TWO;
    (n_s * (-one_minus_cos).ln_1p()).exp()
}

/// `e` as the exponent [`Real::pow`] raises by repeated squaring (a whole number up to 1024 in
/// magnitude), or `None` where it takes `powf`.
#[inline]
pub(crate) fn whole_exponent<R: Real>(e: R) -> Option<i32> {
    (e.trunc() == e && e.abs() <= R::from_f64(1024.0)).then(|| e.to_f64() as i32)
}

/// x^n_s where it is defined: a negative base has a real power only for an integer exponent.
/// x is a cosine: it is clamped to [−1, 1] first, so that a value rounded a hair beyond ±1
/// cannot grow without bound under a huge n_s. `unit` carries R and V where x is −R·V of unit
/// vectors (the chapter's formulas), so that a positive cos φ is raised exactly as the gated
/// term is ([`cos_phi_pow`]) and the literal total equals the colour where nothing is gated.
#[inline]
fn literal_pow<R: Real>(x: R, n_s: R, clamp: bool, unit: Option<(V3<R>, V3<R>)>) -> Option<R> {
    if x < R::ZERO && n_s.trunc() != n_s {
        None
    } else if !clamp {
        Some(x.pow(n_s))
    } else if let (Some((r, v)), true) = (unit, x > R::ZERO) {
        Some(cos_phi_pow(x, r, v, n_s))
    } else {
        Some(x.max(-R::ONE).min(R::ONE).pow(n_s))
    }
}

/// The two places where a classic slip lives *inside* a formula of the core, so that `phong
/// check` can reproduce it with the same code (every other slip is a change of the input).
/// [`Chapter`] answers `false` to both as a constant, so the chapter's path compiles to exactly
/// the code it would be without these switches; [`Slipped`] answers at run time.
pub(crate) trait Formulas: Copy {
    /// cos θ taken as |N·L| instead of −N·L (Eq. 4.7): a light behind the surface lights it.
    fn abs_cos_theta(self) -> bool;
    /// cos φ taken as N·H with Blinn's half-vector H = (−L − V)/‖−L − V‖ instead of −R·V
    /// (Eq. 4.10, 4.15).
    fn half_vector(self) -> bool;
    /// N is used as given, not of unit length: cos φ is then not a cosine and is not clamped to
    /// [−1, 1] (the clamp guards unit vectors against rounding only).
    fn raw_normal(self) -> bool;
    /// An intermediate as a hand calculation writes it down: [`Chapter`] keeps every digit;
    /// [`Slipped`] with `round_to: Some(k)` rounds N, V, L, d, 1/d^f, I_l, N·L, R, cos φ,
    /// (cos φ)^n_s and each term to k decimals before the next step uses it.
    fn round<L: Lanes>(self, x: L) -> L;
    /// Whether [`Formulas::round`] rounds (then (cos φ)^n_s is the plain power of the rounded
    /// cos φ, as by hand, not the accurate form near the highlight).
    fn rounds(self) -> bool;
}

/// Every component of `v` as [`Formulas::round`] writes it down.
#[inline(always)]
fn round_v<L: Lanes, F: Formulas>(f: F, v: L::V) -> L::V {
    let (x, y, z) = v.parts();
    L::V::from_parts(f.round(x), f.round(y), f.round(z))
}

/// The chapter's formulas, unchanged: the tracer's and the solver's.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Chapter;

impl Formulas for Chapter {
    #[inline(always)]
    fn abs_cos_theta(self) -> bool {
        false
    }
    #[inline(always)]
    fn half_vector(self) -> bool {
        false
    }
    #[inline(always)]
    fn raw_normal(self) -> bool {
        false
    }
    #[inline(always)]
    fn round<L: Lanes>(self, x: L) -> L {
        x
    }
    #[inline(always)]
    fn rounds(self) -> bool {
        false
    }
}

/// Formula switches chosen at run time (the mistake diagnosis of `phong check`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Slipped {
    pub abs_cos_theta: bool,
    pub half_vector: bool,
    pub raw_normal: bool,
    /// Round every intermediate to this many decimals (a hand calculation's slip).
    pub round_to: Option<u8>,
}

impl Formulas for Slipped {
    #[inline]
    fn abs_cos_theta(self) -> bool {
        self.abs_cos_theta
    }
    #[inline]
    fn half_vector(self) -> bool {
        self.half_vector
    }
    #[inline]
    fn raw_normal(self) -> bool {
        self.raw_normal
    }
    #[inline]
    fn round<L: Lanes>(self, x: L) -> L {
        match self.round_to {
            Some(k) => {
                let scale = 10f64.powi(i32::from(k));
                x.map_lanes(L::all_lanes(), |_, x| {
                    <L::Scalar as Real>::from_f64((x.to_f64() * scale).round() / scale)
                })
            }
            None => x,
        }
    }
    #[inline]
    fn rounds(self) -> bool {
        self.round_to.is_some()
    }
}

/// The bound on the rounding error of the computed cos θ = −N·L for a given point: γ₄₀·Σ|N_i L_i|
/// ([`gamma`]: u = ε/2, γ_k = ku/(1 − ku); the derivation is in `solve/rounding.rs`, which adds
/// what a computed hit point's own error adds). A |cos θ| within it cannot be told from 0 in this
/// precision, so it is counted as 0 (the light in the tangent plane): an exact 0 is then decided
/// as exactly 0 (a light in the tangent plane does not switch the specular term on by a
/// rounding error), and a tiny non-zero value, which may lie on either side, is reported by the
/// solver (`gate_undecidable`). Σ|N_i L_i|, not 1: with N along an axis the error of cos θ
/// shrinks with cos θ itself, and such a grazing light is decided as the exact value says in
/// any precision.
#[inline(always)]
pub(crate) fn tangent_tolerance<L: Lanes>(n: L::V, l: L::V) -> L {
    let ((nx, ny, nz), (lx, ly, lz)) = (n.parts(), l.parts());
    let sum = (nx * lx).absolute() + (ny * ly).absolute() + (nz * lz).absolute();
    L::broadcast(gamma::<L::Scalar>(40)) * sum
}

/// Shades P with Phong's model, Eq. 4.16, gated as docs/conventions.md ("Gating") reads the
/// chapter: a light adds diffuse and specular only where cos θ > 0, and specular only where also
/// cos φ > 0.
#[inline]
pub fn shade<R: Real, Rec: Recorder<R>, Vis: Visibility<R>>(
    at: &ShadingPoint<R>,
    m: &Material<R>,
    lights: &LightSet<R>,
    visibility: &mut Vis,
    rec: &mut Rec,
) -> Shade<R> {
    shade_with(Chapter, at, m, lights, visibility, rec)
}

/// The points of some [`Lanes`] being shaded (one point, or one per lane): P, a unit N, and V
/// from the eye to P where there is a viewer (for every lane or none).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LanePoint<L: Lanes> {
    /// P.
    pub p: L::V,
    /// N, unit length.
    pub n: L::V,
    /// V, unit, from the eye to the point.
    pub v: Option<L::V>,
}

/// The specular part of one light in lanes, where it was formed (Eq. 4.9–4.15).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneSpecular<L: Lanes> {
    /// R = L − 2(N·L)N.
    pub r: L::V,
    /// cos φ = −R·V.
    pub cos_phi: L,
    /// The lanes where the light is lit and cos φ > 0: the term is added there.
    pub lit: L::Mask,
    /// (cos φ)^n_s in the `lit` lanes.
    pub pow: L,
    /// (cos φ)^n_s in the `lit` lanes before [`Formulas::round`]: the literal term's power
    /// there (the same formula, so the record need not raise cos φ a second time).
    pub raw_pow: L,
    /// O_s I_l (cos φ)^n_s in the `lit` lanes.
    pub term: L::V,
}

/// One light at the points of some [`Lanes`], as [`shade_lanes`] formed it: for a [`LaneSide`]
/// to record (the scalar core builds its [`LightTerm`] from it).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneTerm<L: Lanes> {
    /// L, d, 1/d^f, the cone and I_l, as the formulas wrote them down.
    pub arrival: LaneArrival<L>,
    /// N·L.
    pub n_dot_l: L,
    /// cos θ = −N·L (or |N·L| under that slip).
    pub cos_theta: L,
    /// cos θ beyond its rounding error above 0.
    pub front: L::Mask,
    /// cos θ beyond its rounding error below 0.
    pub behind: L::Mask,
    /// Where the light would be lit but a shadow ray was blocked.
    pub shadowed: L::Mask,
    /// Where the light lights the point (arrives, in front, not shadowed).
    pub lit: L::Mask,
    /// O_d I_l cos θ before gating where formed (zero where not); `None` without O_d.
    pub diffuse: Option<L::V>,
    /// The specular part; `None` without O_s or viewer, or where no lane needed it.
    pub specular: Option<LaneSpecular<L>>,
}

/// The caller's side of [`shade_lanes`]: the shadow rays, and what is recorded per light.
pub(crate) trait LaneSide<L: Lanes> {
    /// Whether the terms of lanes the light does not light are formed too, for the record
    /// (as [`Recorder::DETAIL`]).
    const DETAIL: bool;
    /// Of the lanes `need` (lit from the front by a light that could add something), those
    /// the light reaches unblocked.
    fn visible(
        &mut self,
        need: L::Mask,
        p: L::V,
        light: &Light<L::Scalar>,
        arrival: &LaneArrival<L>,
    ) -> L::Mask;
    /// One light's terms, in the order of the light set.
    fn light(
        &mut self,
        index: usize,
        light: &Light<L::Scalar>,
        at: &LanePoint<L>,
        term: LaneTerm<L>,
    );
}

/// The result of [`shade_lanes`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct LaneShade<L: Lanes> {
    /// O_a I_a, the same in every lane; `None` without ambient light or O_a.
    pub ambient: Option<V3<L::Scalar>>,
    /// Σ diffuse terms.
    pub diffuse: L::V,
    /// Σ specular terms.
    pub specular: L::V,
    /// The total, Eq. 4.16 with gating, unclamped.
    pub color: L::V,
}

/// Phong's model at the points of some [`Lanes`]: the one source of the arithmetic of Eq.
/// 4.5–4.16 and of the gating (docs/conventions.md, "Gating", "Tangent tolerance"), for the
/// scalar core ([`shade_with`], L = the precision itself, masks `bool`) and the wide tracer (L a
/// register of lanes sharing one material). Written in select form: a gate is a mask, a term is
/// formed where any lane needs it (for one number: where it is needed, as a branch) and added
/// where its mask is set, so each lane computes the scalar bits in the scalar order. A whole
/// n_s or spot exponent (up to 1024) is raised by repeated squaring in every lane at once (the
/// scalar's own `powi`); the steps the lanes cannot compute to the bit (powf, the ln_1p form of
/// `cos_phi_pow`, a spot's atan2, the robust branch of a length) run lane by lane with the
/// scalar code, on the lanes that need them. `active`:
/// the lanes holding a point (no shadow ray is asked for the others).
#[inline(always)]
pub(crate) fn shade_lanes<L: Lanes, F: Formulas, S: LaneSide<L>>(
    formulas: F,
    at: &LanePoint<L>,
    active: L::Mask,
    m: &Material<L::Scalar>,
    lights: &LightSet<L::Scalar>,
    side: &mut S,
) -> LaneShade<L> {
    type Scalar<L> = <L as Lanes>::Scalar;
    let zero = L::broadcast(<Scalar<L> as Real>::ZERO);
    let zero_v = L::V::broadcast(V3::<Scalar<L>>::ZERO);
    // N and V as the formulas write them down (the chapter: exactly as given).
    let at = &LanePoint::<L> {
        p: at.p,
        n: round_v::<L, F>(formulas, at.n),
        v: at.v.map(|v| round_v::<L, F>(formulas, v)),
    };
    // Ambient light, Eq. 4.6.
    let ambient = match (m.o_a, lights.ambient) {
        (Some(o_a), Some(i_a)) => Some(round_v::<Scalar<L>, F>(formulas, o_a * i_a)),
        _ => None,
    };
    let mut diffuse = zero_v;
    let mut specular = zero_v;
    let contributes = m.o_d.is_some() || (m.o_s.is_some() && at.v.is_some());
    // n_s as the exponent of the repeated squaring where `Real::pow` takes it (and then so does
    // `cos_phi_pow`, whose own rule, a whole n_s up to 1024, includes every such n_s ≥ 0).
    let whole_n_s = whole_exponent(m.n_s);

    for (index, light) in lights.lights.iter().enumerate() {
        let mut arrival = light.arrive_lanes::<L>(at.p, S::DETAIL);
        arrival.l = round_v::<L, F>(formulas, arrival.l);
        arrival.d = formulas.round(arrival.d);
        arrival.falloff_factor = formulas.round(arrival.falloff_factor);
        arrival.i_l = round_v::<L, F>(formulas, arrival.i_l);
        // Diffuse reflection, cos θ = −N·L, Eq. 4.7–4.8.
        let n_dot_l = formulas.round::<L>(at.n.dot3(arrival.l));
        let cos_theta = if formulas.abs_cos_theta() {
            n_dot_l.absolute()
        } else {
            n_dot_l.negated()
        };
        // Within its own rounding error of 0, cos θ counts as 0: the light is in the tangent
        // plane, as a point within rounding of a spot's edge is on the edge.
        let tolerance = tangent_tolerance::<L>(at.n, arrival.l);
        let front = cos_theta.greater(tolerance);
        let behind = cos_theta.less(tolerance.negated());
        let lit_front = arrival.arrives.both(front).both(active);
        // Ask for a shadow ray only where the light could add something.
        let mut shadowed = L::all_lanes().invert();
        if contributes {
            let need = lit_front.both(arrival.i_l.zero_mask().invert());
            if need.any() {
                let visible = side.visible(need, at.p, light, &arrival);
                shadowed = need.both(visible.invert());
            }
        }
        let lit = lit_front.both(shadowed.invert());

        // O_d I_l cos θ, formed once: added where the light is lit, recorded on request.
        let diffuse_term = m.o_d.map(|o_d| {
            let want = if S::DETAIL { arrival.arrives } else { lit };
            if !want.any() {
                return zero_v;
            }
            let value = round_v::<L, F>(
                formulas,
                L::V::broadcast(o_d).times(arrival.i_l).scaled(cos_theta),
            );
            let value = if S::DETAIL {
                L::V::pick3(want, value, zero_v)
            } else {
                value
            };
            diffuse = diffuse.plus(L::V::pick3(lit, value, zero_v));
            value
        });

        // Specular reflection, R = L − 2(N·L)N and cos φ = −R·V, Eq. 4.10 and 4.15.
        let spec = match (m.o_s, at.v) {
            (Some(o_s), Some(v)) if S::DETAIL || lit.any() => {
                let two = L::broadcast(<Scalar<L> as Real>::TWO);
                let r = round_v::<L, F>(formulas, arrival.l.minus(at.n.scaled(two * n_dot_l)));
                let cos_phi = if formulas.half_vector() {
                    // Blinn: H halfway between the directions to the light and to the eye.
                    zero.map_lanes(L::all_lanes(), |k, _| {
                        let (l, v) = (arrival.l.lane(k), v.lane(k));
                        crate::core::vector::normalize::<Scalar<L>>(-l - v)
                            .map_or(<Scalar<L> as Real>::ZERO, |h| at.n.lane(k).dot(h.unit))
                    })
                } else {
                    formulas.round(r.dot3(v).negated())
                };
                let spec_lit = lit.both(cos_phi.greater(zero));
                let (mut pow, mut raw_pow, mut term) = (zero, zero, zero_v);
                if spec_lit.any() {
                    // cos φ can round a hair above 1; a huge n_s must not turn that into inf,
                    // nor a cos φ that rounds to 1 into a spurious 1 (see `cos_phi_pow`).
                    raw_pow = match whole_n_s {
                        // A whole n_s up to 1024: every branch of `cos_phi_pow` and
                        // `Real::pow` is the repeated squaring of min(cos φ, 1) (of cos φ
                        // itself with N used raw), the same multiplications in every lane.
                        Some(n) => {
                            let base = if formulas.raw_normal() {
                                cos_phi
                            } else {
                                cos_phi.minimum(L::broadcast(<Scalar<L> as Real>::ONE))
                            };
                            let one = L::broadcast(<Scalar<L> as Real>::ONE);
                            L::pick(spec_lit, powi_by_squaring(base, one, n), zero)
                        }
                        // Otherwise powf or the ln_1p form, lane by lane: no lane pow gives
                        // the scalar's bits.
                        None => cos_phi.map_lanes(spec_lit, |k, c| {
                            if formulas.raw_normal() {
                                c.pow(m.n_s)
                            } else if formulas.half_vector() || formulas.rounds() {
                                c.min(<Scalar<L> as Real>::ONE).pow(m.n_s)
                            } else {
                                cos_phi_pow(c, r.lane(k), v.lane(k), m.n_s)
                            }
                        }),
                    };
                    pow = formulas.round(raw_pow);
                    term = round_v::<L, F>(
                        formulas,
                        L::V::broadcast(o_s).times(arrival.i_l).scaled(pow),
                    );
                    specular = specular.plus(L::V::pick3(spec_lit, term, zero_v));
                }
                Some(LaneSpecular {
                    r,
                    cos_phi,
                    lit: spec_lit,
                    pow,
                    raw_pow,
                    term,
                })
            }
            _ => None,
        };

        side.light(
            index,
            light,
            at,
            LaneTerm {
                arrival,
                n_dot_l,
                cos_theta,
                front,
                behind,
                shadowed,
                lit,
                diffuse: diffuse_term,
                specular: spec,
            },
        );
    }

    // The total, Eq. 4.16.
    let a = L::V::broadcast(ambient.unwrap_or(V3::<Scalar<L>>::ZERO));
    LaneShade {
        ambient,
        diffuse,
        specular,
        color: a.plus(diffuse).plus(specular),
    }
}

/// The scalar core's side of [`shade_lanes`] (one lane): the caller's [`Visibility`] and
/// [`Recorder`], each light's [`LightTerm`] built from the lane's masks and values, and the
/// literal (ungated) sums of Eq. 4.16 for a recorder that asks for detail.
struct ScalarSide<'a, R: Real, Vis, Rec, F> {
    visibility: &'a mut Vis,
    rec: &'a mut Rec,
    formulas: F,
    m: &'a Material<R>,
    /// The literal sums, formed in the same order as the gated ones, so that where nothing
    /// was gated the two totals agree to the last bit.
    literal_diffuse: V3<R>,
    literal_specular: V3<R>,
    literal_defined: bool,
    /// Σ of the literal terms' sizes (|term| per channel) and their number: the scale of the
    /// literal total's rounding error ([`zero_within_rounding`]).
    literal_size: V3<R>,
    literal_terms: u32,
}

/// The literal total of Eq. 4.16 with each channel that is zero within its rounding error
/// made 0. Its terms have both signs (an ungated diffuse or specular term is negative), so
/// where they cancel, as in (0.1 + 0.56 + 0.2 − 0.7 − 0.16) = 0, the computed sum is noise
/// (−2.8·10⁻¹⁷ in f64) that a report would print as a value. A sum of n terms is off by at
/// most γ_{n−1}·Σ|tᵢ| (Higham, *Accuracy and Stability of Numerical Algorithms*, §4.2), and
/// each term carries the rounding of its own few products and of the vectors it came from:
/// 16 + n units of roundoff of Σ|tᵢ| bounds both for the products of Eq. 4.1–4.10. A channel
/// within that of zero has no digit the report could show; where nothing is gated every term
/// is ≥ 0, Σ|tᵢ| is the total itself, and no channel changes (the two totals stay equal). An
/// infinite term leaves its channel as computed (the solver refuses it).
fn zero_within_rounding<R: Real>(total: V3<R>, size: V3<R>, terms: u32) -> V3<R> {
    let units = R::from_f64(16.0 + f64::from(terms)) * R::EPSILON;
    let [t, s] = [total.to_array(), size.to_array()];
    let channel = |i: usize| {
        if s[i].is_finite() && t[i].abs() <= units * s[i] {
            R::ZERO
        } else {
            t[i]
        }
    };
    V3::<R>::new(channel(0), channel(1), channel(2))
}

impl<R: Real, Vis: Visibility<R>, Rec: Recorder<R>, F: Formulas> LaneSide<R>
    for ScalarSide<'_, R, Vis, Rec, F>
{
    const DETAIL: bool = Rec::DETAIL;

    #[inline(always)]
    fn visible(&mut self, _: bool, p: V3<R>, light: &Light<R>, arrival: &LaneArrival<R>) -> bool {
        self.visibility
            .visible(p, light, &light.arrival_of(arrival))
    }

    #[inline(always)]
    fn light(&mut self, index: usize, light: &Light<R>, at: &LanePoint<R>, t: LaneTerm<R>) {
        let arrival = light.arrival_of(&t.arrival);
        let status = if t.arrival.at_light {
            LightStatus::AtLight
        } else if !t.arrival.arrives {
            LightStatus::OutsideCone
        } else if t.shadowed {
            LightStatus::InShadow
        } else if t.front {
            LightStatus::Lit
        } else if t.behind {
            LightStatus::BehindSurface
        } else {
            LightStatus::InTangentPlane
        };
        let lit = t.lit;
        let (diffuse, diffuse_literal) = match t.diffuse {
            None => (None, None),
            Some(value) => (
                Some(if lit { value } else { V3::<R>::ZERO }),
                Rec::DETAIL.then_some(value),
            ),
        };
        if let Some(d) = diffuse_literal {
            self.literal_diffuse += d;
            self.literal_size += d.abs();
            self.literal_terms += 1;
        }
        let f = self.formulas;
        let specular = match (self.m.o_s, at.v, t.specular) {
            (None, _, _) => SpecularTerm::skipped(SpecularStatus::NoSpecularColor),
            (Some(_), None, _) => SpecularTerm::skipped(SpecularStatus::NoViewer),
            (Some(o_s), Some(v), Some(s)) => {
                let status = if !lit {
                    SpecularStatus::LightNotLit
                } else if s.lit {
                    SpecularStatus::Lit
                } else {
                    SpecularStatus::AwayFromViewer
                };
                let literal = if !Rec::DETAIL {
                    None
                } else if !t.arrival.arrives {
                    Some(V3::<R>::ZERO)
                } else if s.lit {
                    // cos φ > 0: `literal_pow` would raise it exactly as the gated term did
                    // (clamped, or raw with N raw), so its power before rounding is reused.
                    Some(o_s * arrival.i_l * s.raw_pow)
                } else {
                    let clamp = !f.raw_normal();
                    let unit = (clamp && !f.half_vector() && !f.rounds()).then_some((s.r, v));
                    literal_pow(s.cos_phi, self.m.n_s, clamp, unit).map(|p| o_s * arrival.i_l * p)
                };
                SpecularTerm {
                    status,
                    r: Some(s.r),
                    cos_phi: Some(s.cos_phi),
                    cos_phi_pow: s.lit.then_some(s.pow),
                    term: if s.lit { s.term } else { V3::<R>::ZERO },
                    literal,
                }
            }
            (Some(_), Some(_), None) => SpecularTerm::skipped(SpecularStatus::LightNotLit),
        };
        if Rec::DETAIL && self.m.o_s.is_some() && at.v.is_some() {
            match specular.literal {
                Some(t) => {
                    self.literal_specular += t;
                    self.literal_size += t.abs();
                    self.literal_terms += 1;
                }
                None => self.literal_defined = false,
            }
        }
        self.rec.light(&LightTerm {
            index,
            arrival,
            n_dot_l: t.n_dot_l,
            cos_theta: t.cos_theta,
            status,
            diffuse,
            diffuse_literal,
            specular,
        });
    }
}

/// [`shade`] with a formula switched as `formulas` says (see [`Formulas`]); with [`Chapter`]
/// it is [`shade`] itself. The arithmetic is [`shade_lanes`] in one lane.
#[inline]
pub(crate) fn shade_with<R: Real, Rec: Recorder<R>, Vis: Visibility<R>, F: Formulas>(
    formulas: F,
    at: &ShadingPoint<R>,
    m: &Material<R>,
    lights: &LightSet<R>,
    visibility: &mut Vis,
    rec: &mut Rec,
) -> Shade<R> {
    let mut side = ScalarSide {
        visibility,
        rec,
        formulas,
        m,
        literal_diffuse: V3::<R>::ZERO,
        literal_specular: V3::<R>::ZERO,
        literal_defined: true,
        literal_size: V3::<R>::ZERO,
        literal_terms: 0,
    };
    let point = LanePoint::<R> {
        p: at.p,
        n: at.n,
        v: at.v,
    };
    let s = shade_lanes::<R, F, _>(formulas, &point, true, m, lights, &mut side);
    let a = s.ambient.unwrap_or(V3::<R>::ZERO);
    Shade {
        ambient: s.ambient,
        diffuse: s.diffuse,
        specular: s.specular,
        color: s.color,
        literal: (Rec::DETAIL && side.literal_defined).then(|| {
            zero_within_rounding::<R>(
                a + side.literal_diffuse + side.literal_specular,
                a.abs() + side.literal_size,
                side.literal_terms + 1,
            )
        }),
    }
}

#[cfg(test)]
mod tests {
    //! Each test is written once and instantiated for f32 and f64. Expected values are worked
    //! out by hand in the comments.
    use super::*;
    use crate::core::lanes::{lanes_of, mask_of, Wide, W, W3};
    use crate::core::light::{Cone, Falloff, LightKind, Reach};
    use crate::core::real::v3;

    fn matte_and_shiny<R: Real>() -> Material<R> {
        Material {
            o_a: Some(v3::<R>([0.5, 0.4, 0.6])),
            o_d: Some(v3::<R>([0.7, 0.8, 0.6])),
            o_s: Some(v3::<R>([0.2, 0.3, 0.4])),
            n_s: R::ONE,
            o_r: None,
            transmission: None,
        }
    }

    fn point_light<R: Real>(pos: [f64; 3], falloff: Falloff) -> Light<R> {
        Light {
            color: v3::<R>([1.0; 3]),
            kind: LightKind::Point {
                position: v3::<R>(pos),
                falloff,
            },
        }
    }

    fn at_origin<R: Real>(viewer_dir: Option<[f64; 3]>) -> ShadingPoint<R> {
        ShadingPoint {
            p: v3::<R>([0.0; 3]),
            n: v3::<R>([0.0, 0.0, 1.0]),
            v: viewer_dir.map(v3::<R>),
        }
    }

    fn close<R: Real>(a: V3<R>, b: [f64; 3], tol: f64) -> bool {
        let a = crate::core::real::to_f64_array::<R>(a);
        (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
    }

    fn light_behind_surface_adds_nothing<R: Real>() {
        let lights = LightSet {
            ambient: None,
            lights: vec![point_light::<R>([0.0, 0.0, -2.0], Falloff::None)],
        };
        let mut rec = Vec::new();
        let s = shade(
            &at_origin::<R>(Some([0.0, 0.0, -1.0])),
            &matte_and_shiny::<R>(),
            &lights,
            &mut AllVisible,
            &mut rec,
        );
        assert_eq!(rec[0].status, LightStatus::BehindSurface);
        assert!(close::<R>(s.color, [0.0; 3], 0.0));
        // Literally: L = (0,0,1), cos θ = −1, so diffuse O_d·(−1); R = L − 2(N·L)N = (0,0,−1)
        // and V = (0,0,−1), so cos φ = −R·V = −1 and specular O_s·(−1)¹.
        assert!(close::<R>(s.literal.unwrap(), [-0.9, -1.1, -1.0], 1e-6));
    }

    fn light_in_tangent_plane_adds_nothing<R: Real>() {
        let lights = LightSet {
            ambient: None,
            lights: vec![point_light::<R>([5.0, 0.0, 0.0], Falloff::None)],
        };
        let mut rec = Vec::new();
        let s = shade(
            &at_origin::<R>(None),
            &matte_and_shiny::<R>(),
            &lights,
            &mut AllVisible,
            &mut rec,
        );
        assert_eq!(rec[0].status, LightStatus::InTangentPlane);
        assert!(close::<R>(s.color, [0.0; 3], 0.0));
    }

    fn mirror_viewer_sees_full_highlight<R: Real>() {
        // Light at (3,0,4), d = 5, falloff 2 with C_l = 25: I_l = 1, cos θ = 0.8.
        // Viewer at the mirror position (−3,0,4): cos φ = 1, so specular = O_s.
        let mut l = point_light::<R>([3.0, 0.0, 4.0], Falloff::Quadratic);
        l.color = v3::<R>([25.0; 3]);
        let lights = LightSet {
            ambient: None,
            lights: vec![l],
        };
        let s = shade(
            &at_origin::<R>(Some([0.6, 0.0, -0.8])),
            &matte_and_shiny::<R>(),
            &lights,
            &mut AllVisible,
            &mut NoRecord,
        );
        assert!(close::<R>(s.diffuse, [0.56, 0.64, 0.48], 1e-6));
        assert!(close::<R>(s.specular, [0.2, 0.3, 0.4], 1e-6));
        assert_eq!(s.literal, None, "NoRecord computes no literal value");
    }

    fn recording_does_not_change_the_colour<R: Real>() {
        let lights = LightSet {
            ambient: Some(v3::<R>([0.1, 0.2, 0.3])),
            lights: vec![
                point_light::<R>([1.0, 2.0, 3.0], Falloff::Linear),
                point_light::<R>([-1.0, 0.5, 2.0], Falloff::Quadratic),
                point_light::<R>([0.0, 1.0, -3.0], Falloff::None),
            ],
        };
        let at = at_origin::<R>(Some([0.1, -0.2, -0.97]));
        let m = matte_and_shiny::<R>();
        let a = shade(&at, &m, &lights, &mut AllVisible, &mut NoRecord);
        let b = shade(&at, &m, &lights, &mut AllVisible, &mut Vec::new());
        assert_eq!(a.color, b.color);
    }

    fn spot_cone_edge_is_lit_and_outside_is_dark<R: Real>() {
        // Apex (0,0,4), axis (0,0,−1), γ = 45°: P = (4,0,0) is on the edge, (4.1,0,0) outside.
        let spot = Light {
            color: v3::<R>([1.0; 3]),
            kind: LightKind::Spot {
                position: v3::<R>([0.0, 0.0, 4.0]),
                falloff: Falloff::None,
                cone: Cone::new(v3::<R>([0.0, 0.0, -1.0]), R::from_f64(45.0), R::ONE),
            },
        };
        let on = spot.arrive(v3::<R>([4.0, 0.0, 0.0]));
        let cone = on.cone.unwrap();
        assert!(cone.inside && cone.on_edge);
        assert_eq!(on.reach, Reach::Arrives);
        let off = spot.arrive(v3::<R>([4.1, 0.0, 0.0]));
        assert_eq!(off.reach, Reach::OutsideCone);
        assert!(close::<R>(off.i_l, [0.0; 3], 0.0));
    }

    fn huge_shininess_with_cos_phi_rounded_above_one_stays_finite<R: Real>() {
        // The mirror configuration again, n_s = 1e30: cos φ may round to 1 + ε.
        let mut m = matte_and_shiny::<R>();
        m.n_s = R::from_f64(1e30);
        let lights = LightSet {
            ambient: None,
            lights: vec![point_light::<R>([3.0, 0.0, 4.0], Falloff::None)],
        };
        let s = shade(
            &at_origin::<R>(Some([0.6, 0.0, -0.8])),
            &m,
            &lights,
            &mut AllVisible,
            &mut Vec::new(),
        );
        assert!(s.color.is_finite());
        assert!(s.specular.max_element() <= R::from_f64(0.4));
    }

    fn huge_shininess_near_the_highlight_gives_no_spurious_one<R: Real>() {
        // Light straight above (L = (0,0,−1), so R = (0,0,1)); the eye at E = (x, 0, 1) sees P
        // at an angle φ from the mirror direction with cos φ = 1/√(1 + x²): 1 − cos φ ≈ x²/2,
        // 1e-10 in f32 (x ≈ 1.41e-5) and 1e-18 in f64 (x ≈ 1.41e-9), both of which round cos φ
        // to exactly 1. With n_s = 1/(1 − cos φ) the power is (cos φ)^n = exp(−(n/2)·ln(1 + x²))
        // ≈ e⁻¹, computed here in f64 from the input as rounded to R; a naive powf gives 1.
        let (x, n_s) = if R::NAME == "f32" {
            (1.414_213_5e-5, 1e10)
        } else {
            (1.414_213_562_373_095e-9, 1e18)
        };
        let x = R::from_f64(x);
        let xf = x.to_f64();
        let expected = (-(n_s / 2.0) * (xf * xf).ln_1p()).exp();
        assert!((expected - (-1f64).exp()).abs() < 1e-3, "{expected}");
        let m = Material {
            o_a: None,
            o_d: None,
            o_s: Some(v3::<R>([1.0; 3])),
            n_s: R::from_f64(n_s),
            o_r: None,
            transmission: None,
        };
        let lights = LightSet {
            ambient: None,
            lights: vec![point_light::<R>([0.0, 0.0, 1.0], Falloff::None)],
        };
        let e = V3::<R>::new(x, R::ZERO, R::ONE);
        let v = crate::core::vector::normalize::<R>(-e).unwrap().unit;
        let at = ShadingPoint {
            p: V3::<R>::ZERO,
            n: v3::<R>([0.0, 0.0, 1.0]),
            v: Some(v),
        };
        let mut rec = Vec::new();
        let s = shade(&at, &m, &lights, &mut AllVisible, &mut rec);
        assert_eq!(rec[0].specular.cos_phi, Some(R::ONE), "cos φ rounds to 1");
        // 1 − cos φ from ‖R + V‖²/2 is exact to a few ε relative here (R + V = (−x', 0, 0) up to
        // the rounding of V), so the power is within a relative 1e-4 of the expected value.
        let got = s.specular.x().to_f64();
        assert!((got / expected - 1.0).abs() < 1e-4, "{got} vs {expected}");
        assert_eq!(s.literal.map(|l| l.x()), Some(s.specular.x()));
    }

    /// Blocks the shadow rays of point lights (not spots) to points with x > 0.5: a rule both
    /// instantiations can ask.
    fn blocked<R: Real>(p: V3<R>, light: &Light<R>) -> bool {
        matches!(light.kind, LightKind::Point { .. }) && p.x() > R::from_f64(0.5)
    }

    struct Blocker(u64);

    impl<R: Real> Visibility<R> for Blocker {
        fn visible(&mut self, p: V3<R>, light: &Light<R>, _: &Arrival<R>) -> bool {
            self.0 += 1;
            !blocked(p, light)
        }
    }

    struct LaneBlocker<R>(u64, std::marker::PhantomData<R>);

    impl<R: Real> LaneSide<W<R>> for LaneBlocker<R> {
        const DETAIL: bool = false;
        fn visible(
            &mut self,
            need: W<R>,
            p: W3<W<R>>,
            light: &Light<R>,
            _: &LaneArrival<W<R>>,
        ) -> W<R> {
            let mut bits = 0;
            for k in lanes_of(need.bits()) {
                self.0 += 1;
                if blocked(p.at(k), light) {
                    bits |= 1 << k;
                }
            }
            need.and(mask_of::<W<R>>(bits).not())
        }
        fn light(&mut self, _: usize, _: &Light<R>, _: &LanePoint<W<R>>, _: LaneTerm<W<R>>) {}
    }

    /// Points, normals and viewers that reach every gate of the model with the lights below:
    /// lit, behind the surface, in the tangent plane, outside and on the edge of the spot's
    /// cone, at a light, in shadow, R away from the viewer, and a light so far away that its
    /// distance takes the robust branch of `between`.
    fn gated_points<R: Real>() -> Vec<ShadingPoint<R>> {
        let unit = |a: [f64; 3]| {
            crate::core::vector::normalize::<R>(v3::<R>(a))
                .unwrap()
                .unit
        };
        let mut points = Vec::new();
        for i in 0..7 {
            for j in 0..5 {
                let (x, y) = (f64::from(i) * 0.6 - 1.7, f64::from(j) * 0.7 - 1.3);
                points.push(ShadingPoint {
                    p: v3::<R>([x, y, 0.1 * x * y]),
                    n: unit([0.1 * y, -0.2 * x, 1.0]),
                    v: Some(unit([-x, -y + 0.3, -4.0])),
                });
            }
        }
        let up = v3::<R>([0.0, 0.0, 1.0]);
        // Behind: N away from the lights; the viewer along the light (R away from it).
        points.push(ShadingPoint {
            p: v3::<R>([0.2, 0.1, 0.0]),
            n: -up,
            v: Some(up),
        });
        points.push(ShadingPoint {
            p: v3::<R>([0.0; 3]),
            n: up,
            v: Some(unit([0.0, 0.0, 1.0])),
        });
        // At the point light; on the spot's edge (apex (0,0,4), axis −z, 45°: x = 4).
        points.push(ShadingPoint {
            p: v3::<R>([1.0, 2.0, 3.0]),
            n: up,
            v: Some(-up),
        });
        points.push(ShadingPoint {
            p: v3::<R>([4.0, 0.0, 0.0]),
            n: up,
            v: Some(-up),
        });
        points.push(ShadingPoint {
            p: v3::<R>([4.1, 0.0, 0.0]),
            n: up,
            v: Some(-up),
        });
        // The tangent plane of the light at (5, 0, 0): cos θ = 0 exactly.
        points.push(ShadingPoint {
            p: v3::<R>([0.0, 0.0, 0.0]),
            n: up,
            v: Some(unit([0.3, 0.0, -1.0])),
        });
        // The mirror direction of the light at (0, 0, 4), for the huge n_s.
        points.push(ShadingPoint {
            p: v3::<R>([0.0; 3]),
            n: up,
            v: Some(unit([1e-3, 0.0, -1.0])),
        });
        points
    }

    fn gated_lights<R: Real>() -> LightSet<R> {
        let far = if R::NAME == "f32" { 3e20 } else { 1e160 };
        let mut far_light = point_light::<R>([far, far, far], Falloff::Linear);
        far_light.color = v3::<R>([far; 3]);
        LightSet {
            ambient: Some(v3::<R>([0.1, 0.2, 0.3])),
            lights: vec![
                point_light::<R>([1.0, 2.0, 3.0], Falloff::Quadratic),
                point_light::<R>([0.0, 0.0, 4.0], Falloff::None),
                point_light::<R>([5.0, 0.0, 0.0], Falloff::Linear),
                Light {
                    color: v3::<R>([0.3, 0.4, 0.5]),
                    kind: LightKind::Directional {
                        direction: v3::<R>([0.0, 0.6, -0.8]),
                    },
                },
                Light {
                    color: v3::<R>([0.9, 0.8, 0.7]),
                    kind: LightKind::Spot {
                        position: v3::<R>([0.0, 0.0, 4.0]),
                        falloff: Falloff::Linear,
                        cone: Cone::new(
                            v3::<R>([0.0, 0.0, -1.0]),
                            R::from_f64(45.0),
                            R::from_f64(2.5),
                        ),
                    },
                },
                far_light,
            ],
        }
    }

    /// The lane instantiation of the core ([`shade_lanes`] over a register) gives every lane
    /// the scalar [`shade`]'s bits and asks the same shadow rays, through every gate, for
    /// whole and fractional n_s (repeated squaring, powf, and the huge n_s's ln_1p form).
    fn lanes_shade_as_the_scalar_core<R: Real>() {
        let lights = gated_lights::<R>();
        let points = gated_points::<R>();
        let lanes = W::<R>::LANES;
        let mut statuses = Vec::new();
        let mut speculars = Vec::new();
        for n_s in [20.0, 2.5, 1e6 + 0.5] {
            let mut m = matte_and_shiny::<R>();
            m.n_s = R::from_f64(n_s);
            let (mut scalar_rays, mut lane_rays) = (0, 0);
            for group in points.chunks(lanes) {
                let fill = group[0];
                let at = LanePoint::<W<R>> {
                    p: W3::gather(group.iter().map(|a| a.p), fill.p),
                    n: W3::gather(group.iter().map(|a| a.n), fill.n),
                    v: Some(W3::gather(
                        group.iter().map(|a| a.v.unwrap()),
                        fill.v.unwrap(),
                    )),
                };
                let active = mask_of::<W<R>>((1 << group.len()) - 1);
                let mut side = LaneBlocker::<R>(0, std::marker::PhantomData);
                let wide =
                    shade_lanes::<W<R>, Chapter, _>(Chapter, &at, active, &m, &lights, &mut side);
                lane_rays += side.0;
                for (k, a) in group.iter().enumerate() {
                    let mut blocker = Blocker(0);
                    let s = shade(a, &m, &lights, &mut blocker, &mut NoRecord);
                    scalar_rays += blocker.0;
                    let bits = |v: V3<R>| v.to_array().map(|c| c.to_f64().to_bits());
                    assert_eq!(bits(wide.color.at(k)), bits(s.color), "{a:?} n_s {n_s}");
                    assert_eq!(bits(wide.diffuse.at(k)), bits(s.diffuse), "{a:?}");
                    assert_eq!(bits(wide.specular.at(k)), bits(s.specular), "{a:?}");
                    let mut rec = Vec::new();
                    shade(a, &m, &lights, &mut Blocker(0), &mut rec);
                    statuses.extend(rec.iter().map(|t| t.status));
                    speculars.extend(rec.iter().map(|t| t.specular.status));
                }
            }
            assert_eq!(lane_rays, scalar_rays, "shadow rays asked");
        }
        for s in LightStatus::ALL {
            assert!(statuses.contains(&s), "no {s:?} among the cases");
        }
        for s in [SpecularStatus::Lit, SpecularStatus::AwayFromViewer] {
            assert!(speculars.contains(&s), "no specular {s:?} among the cases");
        }
    }

    macro_rules! for_both_precisions {
        ($($name:ident),* $(,)?) => {
            mod f32_tests { $( #[test] fn $name() { super::$name::<f32>() } )* }
            mod f64_tests { $( #[test] fn $name() { super::$name::<f64>() } )* }
        };
    }

    for_both_precisions!(
        light_behind_surface_adds_nothing,
        light_in_tangent_plane_adds_nothing,
        mirror_viewer_sees_full_highlight,
        recording_does_not_change_the_colour,
        spot_cone_edge_is_lit_and_outside_is_dark,
        huge_shininess_with_cos_phi_rounded_above_one_stays_finite,
        huge_shininess_near_the_highlight_gives_no_spurious_one,
        lanes_shade_as_the_scalar_core,
    );

    #[test]
    fn quadratic_falloff_far_away_neither_overflows_nor_flushes_to_zero() {
        // d = 1e160: d² would overflow f64, but 1/d/d = 1e-320 (subnormal) is representable.
        let f = Falloff::Quadratic.factor(1e160f64);
        assert!(f > 0.0 && f.is_finite());
        assert!((f / 1e-320 - 1.0).abs() < 1e-2);
    }
}
