//! The classic slips of a hand calculation, each reproduced by the SAME solver and core with one
//! thing changed, never by a second copy of a formula:
//!
//! - most slips are a change of the validated [`Problem`] (the falloff exponent, the ambient
//!   light removed, n_s = 1, the viewer or the lights mirrored through P, the normal reversed or
//!   left unnormalised, a spot made a point light, the ray reversed);
//! - two live inside a formula and are switched in the core ([`Slipped`]: |cos θ|, Blinn's
//!   half-vector), at no cost to the chapter's path; a third switch lets an unnormalised
//!   normal's "cos φ" exceed 1, as it does by hand;
//! - "no clamping" reads the literal Eq. 4.16 that the core records anyway;
//! - intermediates rounded to two decimals is a third formula switch (`round_to`): the core
//!   rounds each value it writes down before the next step uses it;
//! - the final colour truncated instead of rounded (to two decimals, or to 8 bits) is the
//!   colour of the problem as written, or of another slip, cut down: [`truncate`].
//!
//! A slip is offered only where it applies to the problem, and kept only where it changes the
//! result. Pairs of slips are tried too, for an answer that no single slip explains.

use crate::core::vector::is_unit_length;
use crate::core::{Falloff, Light, LightKind, Slipped, Vector};
use crate::problem::{GivenVector, NamedMaterial, Problem, Target as Shaded};
use crate::solve::{mirror_lights, solve_with, Solution};

use super::Target;

/// A classic slip. The order is the order of application in a pair: the ray first (it decides
/// P), the literal value last (it reads whatever the others computed).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Slip {
    /// The ray's intersection taken behind its origin (t < 0): the ray reversed.
    HitBehindOrigin,
    /// L taken from the point to the light, the opposite of Eq. 4.1: the lights mirrored through P.
    LightReversed,
    /// V taken from the point to the eye, the opposite of Eq. 4.10: the viewer mirrored through P.
    ViewerReversed,
    /// The normal reversed.
    NormalReversed,
    /// cos θ taken as |N·L| (Eq. 4.7).
    AbsCosTheta,
    /// The normal used with the length it was given.
    NormalNotNormalized,
    /// The falloff forgotten: I_l = C_l (Eq. 4.2).
    FalloffForgotten,
    /// Linear falloff where the problem says quadratic.
    FalloffLinearNotQuadratic,
    /// Quadratic falloff where the problem says linear.
    FalloffQuadraticNotLinear,
    /// The ambient term O_a I_a forgotten (Eq. 4.6).
    AmbientForgotten,
    /// An ambient term the problem does not give: a white ambient light I_a = (1, 1, 1) assumed,
    /// with the material's own O_a (Eq. 4.6).
    AmbientAssumed,
    /// cos φ from Blinn's half-vector, N·H, instead of −R·V (Eq. 4.10).
    HalfVector,
    /// cos φ not raised to n_s (n_s taken as 1).
    CosPhiNotRaised,
    /// The spot light's cone ignored: the spot taken as a point light (Eq. 4.4).
    SpotConeIgnored,
    /// R_V with the sign of its N·V term flipped: V + 2(N·V)N for V − 2(N·V)N (Eq. 4.17).
    ReflectionSignFlipped,
    /// Snell's law with η_i/η_t inverted (η_r = η_t/η_i): the material's η taken as 1/η.
    EtaInverted,
    /// Every intermediate (N, V, L, d, 1/d^f, I_l, N·L, R, cos φ, each term) rounded to two
    /// decimals before the next step uses it.
    IntermediatesRounded,
    /// Negative cosines kept: Eq. 4.16 taken literally, without clamping cos θ and cos φ at 0.
    NoClamping,
    /// The final colour truncated to two decimals instead of rounded (0.29 for 0.2992).
    TruncatedDecimals,
    /// The 8-bit colour truncated, ⌊255·c⌋, instead of rounded, round(255·c).
    TruncatedRgb8,
}

impl Slip {
    /// Every slip, in the order of application.
    pub const ALL: [Slip; 20] = [
        Slip::HitBehindOrigin,
        Slip::LightReversed,
        Slip::ViewerReversed,
        Slip::NormalReversed,
        Slip::AbsCosTheta,
        Slip::NormalNotNormalized,
        Slip::FalloffForgotten,
        Slip::FalloffLinearNotQuadratic,
        Slip::FalloffQuadraticNotLinear,
        Slip::AmbientForgotten,
        Slip::AmbientAssumed,
        Slip::HalfVector,
        Slip::CosPhiNotRaised,
        Slip::SpotConeIgnored,
        Slip::ReflectionSignFlipped,
        Slip::EtaInverted,
        Slip::IntermediatesRounded,
        Slip::NoClamping,
        Slip::TruncatedDecimals,
        Slip::TruncatedRgb8,
    ];

    /// The stable code (as in the JSON output).
    pub fn code(self) -> &'static str {
        match self {
            Slip::HitBehindOrigin => "hit_behind_origin",
            Slip::LightReversed => "light_reversed",
            Slip::ViewerReversed => "viewer_reversed",
            Slip::NormalReversed => "normal_reversed",
            Slip::AbsCosTheta => "abs_cos_theta",
            Slip::NormalNotNormalized => "normal_not_normalized",
            Slip::FalloffForgotten => "falloff_forgotten",
            Slip::FalloffLinearNotQuadratic => "falloff_linear_not_quadratic",
            Slip::FalloffQuadraticNotLinear => "falloff_quadratic_not_linear",
            Slip::AmbientForgotten => "ambient_forgotten",
            Slip::AmbientAssumed => "ambient_assumed",
            Slip::HalfVector => "half_vector",
            Slip::CosPhiNotRaised => "cos_phi_not_raised",
            Slip::SpotConeIgnored => "spot_cone_ignored",
            Slip::ReflectionSignFlipped => "reflection_sign_flipped",
            Slip::EtaInverted => "eta_inverted",
            Slip::IntermediatesRounded => "intermediates_rounded",
            Slip::NoClamping => "no_clamping",
            Slip::TruncatedDecimals => "truncated_decimals",
            Slip::TruncatedRgb8 => "truncated_rgb8",
        }
    }

    /// Slips that exclude each other (one falloff exponent at a time) share a group.
    fn group(self) -> Option<u8> {
        match self {
            Slip::FalloffForgotten
            | Slip::FalloffLinearNotQuadratic
            | Slip::FalloffQuadraticNotLinear => Some(0),
            Slip::TruncatedDecimals | Slip::TruncatedRgb8 => Some(1),
            _ => None,
        }
    }

    /// A slip of the final colour's last step (truncation), made on top of another outcome
    /// rather than as a change of the problem.
    pub fn is_truncation(self) -> bool {
        matches!(self, Slip::TruncatedDecimals | Slip::TruncatedRgb8)
    }
}

/// A problem as a slip changed it: the input, the core's formula switches, and whether the
/// literal (unclamped-cosine) value is read.
#[derive(Clone, Debug)]
pub(crate) struct Variant {
    pub problem: Problem<f64>,
    pub formulas: Slipped,
    pub literal: bool,
    /// R_V taken as V + 2(N·V)N: the secondary rays' slip, made on the solution's R_V (the
    /// local colour does not depend on it).
    pub reflection_sign_flipped: bool,
}

impl Variant {
    pub fn of(problem: &Problem<f64>) -> Self {
        Variant {
            problem: problem.clone(),
            formulas: Slipped::default(),
            literal: false,
            reflection_sign_flipped: false,
        }
    }

    /// Solves the variant with the same solver and core; with `reflection_sign_flipped`, the
    /// reflection ray's direction is then the slip's V + 2(N·V)N, normalised as R_V is.
    pub fn solve(&self) -> Option<Solution<f64>> {
        let mut s = solve_with(&self.problem, self.formulas).ok()?;
        if self.reflection_sign_flipped {
            if let Some(x) = &mut s.secondary {
                if let Some(r) = &mut x.reflection {
                    let slipped = x.v + x.n * (2.0 * x.n.dot(x.v));
                    r.direction = crate::core::vector::normalize::<f64>(slipped).map(|u| u.unit);
                }
            }
        }
        Some(s)
    }

    /// The colour the variant gives: the clamped and unclamped colour of the problem as written,
    /// or the literal Eq. 4.16.
    pub fn target(&self, solution: &Solution<f64>) -> Option<Target> {
        let e = solution.evaluation.as_ref()?;
        if self.literal {
            e.shade.literal.map(|l| Target {
                unclamped: l.to_array(),
                clamped: None,
            })
        } else {
            Some(Target::of(e))
        }
    }

    /// The variant with `slip` made too, where it applies; `solution` is this variant's own
    /// (for P, where a slip mirrors something through it).
    pub fn with(&self, slip: Slip, solution: Option<&Solution<f64>>) -> Option<Variant> {
        let mut v = self.clone();
        let p = solution
            .and_then(|s| s.evaluation.as_ref())
            .and_then(|e| e.point);
        let changed = match slip {
            Slip::HitBehindOrigin => reverse_ray(&mut v.problem),
            Slip::LightReversed => match p {
                Some(p) if !v.problem.lights.lights.is_empty() => {
                    v.problem.lights = mirror_lights(&v.problem.lights, p);
                    true
                }
                _ => false,
            },
            Slip::ViewerReversed => match (p, v.problem.viewer, &v.problem.target) {
                (Some(p), Some(e), _) => {
                    v.problem.viewer = Some(p * 2.0 - e);
                    true
                }
                // V = D, from the ray's origin: the eye mirrored through P is 2P − O.
                (Some(p), None, Shaded::Ray { ray, .. }) => {
                    v.problem.viewer = Some(p * 2.0 - ray.origin);
                    true
                }
                _ => false,
            },
            Slip::NormalReversed => match &mut v.problem.target {
                Shaded::Point {
                    normal: Some(n), ..
                } => {
                    n.unit = -n.unit;
                    true
                }
                _ => false,
            },
            Slip::AbsCosTheta => !std::mem::replace(&mut v.formulas.abs_cos_theta, true),
            Slip::HalfVector => !std::mem::replace(&mut v.formulas.half_vector, true),
            Slip::NoClamping => !std::mem::replace(&mut v.literal, true),
            Slip::NormalNotNormalized => {
                // cos φ is then no cosine: the core must not clamp it to 1.
                v.formulas.raw_normal = true;
                unnormalize(&mut v.problem)
            }
            Slip::FalloffForgotten => refall(&mut v.problem, |f| f != Falloff::None, Falloff::None),
            Slip::FalloffLinearNotQuadratic => {
                refall(&mut v.problem, |f| f == Falloff::Quadratic, Falloff::Linear)
            }
            Slip::FalloffQuadraticNotLinear => {
                refall(&mut v.problem, |f| f == Falloff::Linear, Falloff::Quadratic)
            }
            Slip::AmbientForgotten => v.problem.lights.ambient.take().is_some(),
            Slip::AmbientAssumed => {
                let has_o_a = materials(&mut v.problem)
                    .iter()
                    .any(|m| m.material.o_a.is_some());
                if v.problem.lights.ambient.is_none() && has_o_a {
                    v.problem.lights.ambient = Some(crate::core::V3::<f64>::new(1.0, 1.0, 1.0));
                    true
                } else {
                    false
                }
            }
            Slip::IntermediatesRounded => v.formulas.round_to.replace(2).is_none(),
            Slip::TruncatedDecimals | Slip::TruncatedRgb8 => false,
            Slip::CosPhiNotRaised => {
                let mut any = false;
                for m in materials(&mut v.problem) {
                    if m.material.o_s.is_some() && m.material.n_s != 1.0 {
                        m.material.n_s = 1.0;
                        any = true;
                    }
                }
                any
            }
            Slip::ReflectionSignFlipped => {
                let reflects = solution
                    .and_then(|s| s.secondary.as_ref())
                    .is_some_and(|x| x.reflection.is_some());
                reflects && !std::mem::replace(&mut v.reflection_sign_flipped, true)
            }
            Slip::EtaInverted => {
                let mut any = false;
                for m in materials(&mut v.problem) {
                    if let Some(t) = &mut m.material.transmission {
                        if t.eta != 1.0 {
                            t.eta = 1.0 / t.eta;
                            any = true;
                        }
                    }
                }
                any
            }
            Slip::SpotConeIgnored => {
                let mut any = false;
                for l in &mut v.problem.lights.lights {
                    if let LightKind::Spot {
                        position, falloff, ..
                    } = l.kind
                    {
                        *l = Light {
                            color: l.color,
                            kind: LightKind::Point { position, falloff },
                        };
                        any = true;
                    }
                }
                any
            }
        };
        changed.then_some(v)
    }
}

/// The ray reversed, where its line meets a surface behind the origin: the hit behind becomes
/// the reversed ray's hit in front (and V = −D where no viewer is given).
fn reverse_ray(problem: &mut Problem<f64>) -> bool {
    let Shaded::Ray {
        ray,
        direction,
        surfaces,
    } = &mut problem.target
    else {
        return false;
    };
    let behind = surfaces
        .iter()
        .any(|s| s.shape.line_hits(ray).nearest_behind().is_some());
    if behind {
        ray.direction = -ray.direction;
        *direction = GivenVector {
            given: -direction.given,
            length: direction.length,
            unit: -direction.unit,
        };
    }
    behind
}

/// Every normal given with a length other than 1, used with that length.
fn unnormalize(problem: &mut Problem<f64>) -> bool {
    let mut any = false;
    match &mut problem.target {
        Shaded::Point {
            normal: Some(n), ..
        } if !is_unit_length(n.length) => {
            n.unit = n.given;
            any = true;
        }
        Shaded::Point { .. } => {}
        Shaded::Ray { surfaces, .. } | Shaded::Scene { surfaces } => {
            for s in surfaces {
                if let (crate::geometry::Shape::Plane(pl), Some(n)) = (&mut s.shape, &mut s.normal)
                {
                    if !is_unit_length(n.length) {
                        pl.normal = n.given;
                        n.unit = n.given;
                        any = true;
                    }
                }
            }
        }
    }
    any
}

/// Every point or spot light whose falloff `from` selects gets falloff `to`.
fn refall(problem: &mut Problem<f64>, from: impl Fn(Falloff) -> bool, to: Falloff) -> bool {
    let mut any = false;
    for l in &mut problem.lights.lights {
        if let LightKind::Point { falloff, .. } | LightKind::Spot { falloff, .. } = &mut l.kind {
            if from(*falloff) {
                *falloff = to;
                any = true;
            }
        }
    }
    any
}

fn materials(problem: &mut Problem<f64>) -> Vec<&mut NamedMaterial<f64>> {
    match &mut problem.target {
        Shaded::Point { material, .. } => vec![material],
        Shaded::Ray { surfaces, .. } | Shaded::Scene { surfaces } => {
            surfaces.iter_mut().map(|s| &mut s.material).collect()
        }
    }
}

/// A slip (or two) and the colour it gives.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    pub slips: Vec<Slip>,
    pub target: Target,
}

/// Every slip and every pair of slips that applies to the problem and changes its result, with
/// the colour each gives: singles first, in [`Slip::ALL`] order, then pairs.
pub fn outcomes(problem: &Problem<f64>, base: Option<&Target>) -> Vec<Outcome> {
    let root = Variant::of(problem);
    let root_solution = root.solve();
    let differs = |t: &Target, from: Option<&Target>| from.is_none_or(|f| !t.same_as(f));
    // Singles: every slip that applies to the problem as written, in `Slip::ALL` order.
    let singles = Slip::ALL.map(|slip| root.with(slip, root_solution.as_ref()).map(Single::solve));
    let mut out: Vec<Outcome> = Slip::ALL
        .iter()
        .zip(&singles)
        .filter_map(|(slip, single)| {
            let t = single.as_ref()?.target.as_ref()?;
            differs(t, base).then(|| Outcome {
                slips: vec![*slip],
                target: *t,
            })
        })
        .collect();
    // Pairs: the first slip's variant, then the second on top of it (which may apply only
    // then: L reversed needs the P that the reversed ray finds).
    for (i, (a, single)) in Slip::ALL.iter().zip(&singles).enumerate() {
        let Some(sa) = single else {
            continue;
        };
        for (b, single_b) in Slip::ALL.iter().zip(&singles).skip(i + 1) {
            if a.group().is_some() && a.group() == b.group() {
                continue;
            }
            let Some(v) = sa.variant.with(*b, sa.solution.as_ref()) else {
                continue;
            };
            let Some(t) = v.solve().and_then(|s| v.target(&s)) else {
                continue;
            };
            let target_b = single_b.as_ref().and_then(|s| s.target.as_ref());
            if differs(&t, base) && differs(&t, sa.target.as_ref()) && differs(&t, target_b) {
                out.push(Outcome {
                    slips: vec![*a, *b],
                    target: t,
                });
            }
        }
    }
    // Truncation: the colour of the problem as written, and of each outcome so far, cut down.
    let mut cut = Vec::new();
    let base_or_slips = base
        .map(|t| (Vec::new(), *t))
        .into_iter()
        .chain(out.iter().map(|o| (o.slips.clone(), o.target)));
    for (slips, target) in base_or_slips {
        if slips.len() > 1 {
            continue;
        }
        for slip in [Slip::TruncatedDecimals, Slip::TruncatedRgb8] {
            let Some(t) = truncate(&target, slip) else {
                continue;
            };
            if differs(&t, base) && !t.same_as(&target) {
                let mut s = slips.clone();
                s.push(slip);
                cut.push(Outcome {
                    slips: s,
                    target: t,
                });
            }
        }
    }
    // Singles before pairs.
    let (singles_cut, pairs_cut): (Vec<_>, Vec<_>) =
        cut.into_iter().partition(|o| o.slips.len() == 1);
    let at = out.iter().take_while(|o| o.slips.len() == 1).count();
    out.splice(at..at, singles_cut);
    out.extend(pairs_cut);
    out
}

/// The colour `target` gives, truncated as `slip` says: to two decimals (⌊100·c⌋/100), or to
/// 8 bits (⌊255·c⌋/255, on the 0–1 scale), of the colour clamped to [0, 1]. `None` for a
/// literal value (no clamped colour) or a slip that is no truncation. A hair (1e-7) is added
/// before cutting, so that a colour that is exactly 0.29 is not cut to 0.28 by its binary form.
pub fn truncate(target: &Target, slip: Slip) -> Option<Target> {
    let k = match slip {
        Slip::TruncatedDecimals => 100.0,
        Slip::TruncatedRgb8 => 255.0,
        _ => return None,
    };
    let c = target.clamped?.map(|x| (x * k + 1e-7).floor() / k);
    Some(Target {
        unclamped: c,
        clamped: Some(c),
    })
}

/// Each slip that applies to the problem as written, made alone, and the solution it gives
/// (for step checking: which slip gives a student's intermediate value).
pub(crate) fn single_solutions(problem: &Problem<f64>) -> Vec<(Slip, Solution<f64>)> {
    let root = Variant::of(problem);
    let root_solution = root.solve();
    Slip::ALL
        .iter()
        .filter_map(|slip| {
            let v = root.with(*slip, root_solution.as_ref())?;
            Some((*slip, v.solve()?))
        })
        .collect()
}

/// One slip made on the problem as written: the variant, its solution and the colour it gives.
struct Single {
    variant: Variant,
    solution: Option<Solution<f64>>,
    target: Option<Target>,
}

impl Single {
    fn solve(variant: Variant) -> Self {
        let solution = variant.solve();
        let target = solution.as_ref().and_then(|s| variant.target(s));
        Single {
            variant,
            solution,
            target,
        }
    }
}

impl Target {
    /// The same colour (to 1e-9): a slip that gives it does not change the result.
    fn same_as(&self, o: &Target) -> bool {
        (0..3).all(|i| (self.unclamped[i] - o.unclamped[i]).abs() <= 1e-9)
    }
}
