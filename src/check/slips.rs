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
use crate::text::{Lang, Message};

/// Declares the slips, one row each: its doc, variant, JSON code, the chapter's equation (or
/// section) it is about, optionally its `group` (slips that exclude each other) and the factor it
/// `truncate`s the final colour by, and its name in English and in Portuguese. The enum, its
/// `ALL`, `code`, `name`, `group`, `reference` and `truncation` are generated from the rows; how a
/// slip changes the problem is its arm of [`Variant::with`]'s `match`.
macro_rules! slips {
    ($(
        $(#[doc = $doc:literal])*
        $variant:ident = $code:literal, $reference:literal
            $(group $group:literal)? $(truncate $factor:literal)? =>
            $en:literal, $pt:literal;
    )*) => {
        /// A classic slip. The order is the order of application in a pair: the ray first (it
        /// decides P), the literal value last (it reads whatever the others computed).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[cfg_attr(test, derive(strum::EnumIter))]
        pub enum Slip {
            $($(#[doc = $doc])* $variant,)*
        }

        impl Slip {
            /// Every slip, in the order of application.
            pub const ALL: [Slip; [$(stringify!($variant)),*].len()] = [$(Slip::$variant),*];

            /// The stable code (as in the JSON output).
            pub fn code(self) -> &'static str {
                match self {
                    $(Slip::$variant => $code,)*
                }
            }

            /// What the slip is, in a few words, in `lang`.
            pub fn name(self, lang: Lang) -> &'static str {
                match (self, lang) {
                    $(
                        (Slip::$variant, Lang::En) => $en,
                        (Slip::$variant, Lang::Pt) => $pt,
                    )*
                }
            }

            /// The chapter's equation (or section) the slip is about: `Eq. 4.7`, `Sec. 4.4`.
            pub fn reference(self) -> &'static str {
                match self {
                    $(Slip::$variant => $reference,)*
                }
            }

            /// Slips that exclude each other (one falloff exponent at a time) share a group.
            fn group(self) -> Option<u8> {
                match self {
                    $(Slip::$variant => None $(.or(Some($group)))?,)*
                }
            }

            /// A truncation of the final colour's last step: ⌊k·c⌋/k, by this `k`.
            fn truncation(self) -> Option<f64> {
                match self {
                    $(Slip::$variant => None $(.or(Some($factor)))?,)*
                }
            }
        }
    };
}

slips! {
    /// The ray's intersection taken behind its origin (t < 0): the ray reversed.
    HitBehindOrigin = "hit_behind_origin", "Eq. 4.17" =>
        "the intersection taken behind the ray's origin (t < 0)",
        "a interseção tomada atrás da origem do raio (t < 0)";
    /// L taken from the point to the light, the opposite of Eq. 4.1: the lights mirrored through P.
    LightReversed = "light_reversed", "Eq. 4.1" =>
        "L reversed: taken from the point to the light, the opposite of Eq. 4.1",
        "L invertido: tomado do ponto para a luz, o oposto da Eq. 4.1";
    /// V taken from the point to the eye, the opposite of Eq. 4.10: the viewer mirrored through P.
    ViewerReversed = "viewer_reversed", "Eq. 4.10" =>
        "V reversed: taken from the point to the eye, the opposite of Eq. 4.10",
        "V invertido: tomado do ponto para o observador, o oposto da Eq. 4.10";
    /// The normal reversed.
    NormalReversed = "normal_reversed", "Eq. 4.7" =>
        "the normal reversed",
        "a normal invertida";
    /// cos θ taken as |N·L| (Eq. 4.7).
    AbsCosTheta = "abs_cos_theta", "Eq. 4.7" =>
        "|cos θ| taken: cos θ = |N·L| instead of −N·L (Eq. 4.7)",
        "|cos θ| usado: cos θ = |N·L| em vez de −N·L (Eq. 4.7)";
    /// The normal used with the length it was given.
    NormalNotNormalized = "normal_not_normalized", "Eq. 4.7" =>
        "the normal not normalised (used with the length it was given)",
        "a normal não normalizada (usada com o comprimento dado)";
    /// The falloff forgotten: I_l = C_l (Eq. 4.2).
    FalloffForgotten = "falloff_forgotten", "Eq. 4.2" group 0 =>
        "the falloff forgotten (I_l = C_l instead of C_l/d^f, Eq. 4.2)",
        "o decaimento esquecido (I_l = C_l em vez de C_l/d^f, Eq. 4.2)";
    /// Linear falloff where the problem says quadratic.
    FalloffLinearNotQuadratic = "falloff_linear_not_quadratic", "Eq. 4.2" group 0 =>
        "linear falloff where the problem says quadratic (Eq. 4.3)",
        "decaimento linear onde o problema diz quadrático (Eq. 4.3)";
    /// Quadratic falloff where the problem says linear.
    FalloffQuadraticNotLinear = "falloff_quadratic_not_linear", "Eq. 4.2" group 0 =>
        "quadratic falloff where the problem says linear (Eq. 4.3)",
        "decaimento quadrático onde o problema diz linear (Eq. 4.3)";
    /// The ambient term O_a I_a forgotten (Eq. 4.6).
    AmbientForgotten = "ambient_forgotten", "Eq. 4.6" =>
        "the ambient term O_a I_a forgotten (Eq. 4.6)",
        "o termo de luz ambiente O_a I_a esquecido (Eq. 4.6)";
    /// An ambient term the problem does not give: a white ambient light I_a = (1, 1, 1) assumed,
    /// with the material's own O_a (Eq. 4.6).
    AmbientAssumed = "ambient_assumed", "Eq. 4.6" =>
        "an ambient term the problem does not give: a white ambient light I_a = (1, 1, 1) \
                 assumed, with the material's O_a (Eq. 4.6)",
        "um termo ambiente que o problema não dá: uma luz ambiente branca \
                 I_a = (1, 1, 1) suposta, com o O_a do material (Eq. 4.6)";
    /// cos φ from Blinn's half-vector, N·H, instead of −R·V (Eq. 4.10).
    HalfVector = "half_vector", "Eq. 4.10" =>
        "cos φ from Blinn's half-vector, N·H, instead of −R·V (Eq. 4.10)",
        "cos φ pelo vetor médio de Blinn, N·H, em vez de −R·V (Eq. 4.10)";
    /// cos φ not raised to n_s (n_s taken as 1).
    CosPhiNotRaised = "cos_phi_not_raised", "Eq. 4.10" =>
        "cos φ not raised to n_s (Eq. 4.10)",
        "cos φ não elevado a n_s (Eq. 4.10)";
    /// The spot light's cone ignored: the spot taken as a point light (Eq. 4.4).
    SpotConeIgnored = "spot_cone_ignored", "Eq. 4.4" =>
        "the spot light's cone ignored (taken as a point light, Eq. 4.4)",
        "o cone do spot ignorado (tomado como luz pontual, Eq. 4.4)";
    /// R_V with the sign of its N·V term flipped: V + 2(N·V)N for V − 2(N·V)N (Eq. 4.17).
    ReflectionSignFlipped = "reflection_sign_flipped", "Eq. 4.17" =>
        "R_V with the sign of its N·V term flipped: V + 2(N·V)N instead of V − 2(N·V)N \
                 (Eq. 4.17)",
        "R_V com o sinal do termo em N·V trocado: V + 2(N·V)N em vez de V − 2(N·V)N \
                 (Eq. 4.17)";
    /// Snell's law with η_i/η_t inverted (η_r = η_t/η_i): the material's η taken as 1/η.
    EtaInverted = "eta_inverted", "Sec. 4.4" =>
        "Snell's law with η_i/η_t inverted: η_r = η_t/η_i (from the medium beyond into \
                 the medium the ray travels in)",
        "a lei de Snell com η_i/η_t invertido: η_r = η_t/η_i (do meio além da superfície \
                 para o meio em que o raio viaja)";
    /// Every intermediate (N, V, L, d, 1/d^f, I_l, N·L, R, cos φ, each term) rounded to two
    /// decimals before the next step uses it.
    IntermediatesRounded = "intermediates_rounded", "Eq. 4.16" =>
        "intermediates rounded to 2 decimals (L, d, I_l, cos θ, R, V, cos φ, each term): \
                 keep 4 significant digits until the end",
        "valores intermediários arredondados a 2 casas decimais (L, d, I_l, cos θ, R, V, \
                 cos φ, cada termo): mantenha 4 algarismos significativos até o fim";
    /// Negative cosines kept: Eq. 4.16 taken literally, without clamping cos θ and cos φ at 0.
    NoClamping = "no_clamping", "Eq. 4.16" =>
        "negative cosines kept: Eq. 4.16 taken literally, cos θ and cos φ not clamped at 0",
        "cossenos negativos mantidos: a Eq. 4.16 ao pé da letra, cos θ e cos φ sem o \
                 limite em 0";
    /// The final colour truncated to two decimals instead of rounded (0.29 for 0.2992).
    TruncatedDecimals = "truncated_decimals", "Eq. 4.16" group 1 truncate 100.0 =>
        "the colour truncated to 2 decimals instead of rounded (0.299 is 0.30, not 0.29)",
        "a cor truncada a 2 casas decimais em vez de arredondada (0,299 é 0,30, não 0,29)";
    /// The 8-bit colour truncated, ⌊255·c⌋, instead of rounded, round(255·c).
    TruncatedRgb8 = "truncated_rgb8", "Eq. 4.16" group 1 truncate 255.0 =>
        "the 8-bit value truncated, ⌊255·c⌋, instead of rounded, round(255·c)",
        "o valor de 8 bits truncado, ⌊255·c⌋, em vez de arredondado, round(255·c)";
}

impl Slip {
    /// A slip of the final colour's last step (truncation), made on top of another outcome
    /// rather than as a change of the problem.
    pub fn is_truncation(self) -> bool {
        self.truncation().is_some()
    }
}

impl serde::Serialize for Slip {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.code())
    }
}

impl Message for Slip {
    fn text(&self, lang: Lang) -> String {
        self.name(lang).to_owned()
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
        for slip in Slip::ALL.into_iter().filter(|s| s.is_truncation()) {
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
    let k = slip.truncation()?;
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
