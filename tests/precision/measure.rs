//! Runs phong on a case the way a user does (problem text → `problem::parse_str` →
//! `validate::<R>` → `solve::solve`), and measures its colour and intermediates against the
//! reference.
//!
//! Errors are measured three ways:
//! - **ulps**: |x − ref| / ulp(ref) in the precision of x, where ulp(ref) is the spacing of that
//!   precision at ref (subnormal spacing below the normal range, so a value that underflows is
//!   measured against the spacing it could have had). What a user sees.
//! - **scaled**: |x − ref| / (ε·W), where W is a first-order bound on how much the colour moves
//!   when each intermediate (L, N, V, d, the cosines, the powers) is perturbed by a few ε (see
//!   [`weight`]). It divides out the problem's own conditioning (1/cos θ, n_s/cos φ, e/cos ψ):
//!   an implementation that rounds each step well stays below a small constant however badly
//!   conditioned the problem is. What the arithmetic is worth.
//! - **gates**: each light's lit / behind / in the tangent plane / outside the cone / at the
//!   light, and whether its specular term is on, against the exact decision.

use std::path::Path;

use astro_float_num::BigFloat;
use phong::core::{
    between, shade, AllVisible, LightSet, LightStatus, Material, NoRecord, Real, ShadingPoint,
    SpecularStatus, Vector,
};
use phong::problem::{self, validate, Target};

use super::reference::{big, ldexp, to_f64, Reference, ShadeRef, Status, PREC};
use super::suite::{Case, LightIn};

/// One light as phong shaded it.
#[derive(Clone, Debug)]
pub struct LightOut {
    pub status: LightStatus,
    pub specular_lit: bool,
    pub cos_theta: f64,
    pub cos_phi: Option<f64>,
    /// The cone test put the point on the edge, within its tolerance.
    pub on_edge: bool,
    pub i_l: [f64; 3],
    pub d: Option<f64>,
}

/// What phong computed for a case.
#[derive(Clone, Debug)]
pub struct Out {
    pub lights: Vec<LightOut>,
    pub color: [f64; 3],
}

fn widen<R: Real>(v: <R as Real>::Vec3) -> [f64; 3] {
    v.to_array().map(|x| x.to_f64())
}

fn load<R: Real>(case: &Case) -> Result<problem::Problem<R>, String> {
    let file = problem::parse_str(Path::new("case.json"), &case.to_json())
        .map_err(|e| format!("{}: {e}", case.name))?;
    validate::validate::<R>(&file).map_err(|e| format!("{}: {}", e.field, e.message()))
}

/// Solves the case in precision R; `Err` carries phong's message when it refuses the problem.
pub fn solve<R: Real>(case: &Case) -> Result<Out, String> {
    let problem = load::<R>(case)?;
    let solution =
        phong::solve::solve(&problem).map_err(|e| format!("{}: {}", e.field, e.message()))?;
    let eval = solution.evaluation.ok_or("no evaluation")?;
    let lights = eval
        .lights
        .iter()
        .map(|t| LightOut {
            status: t.status,
            specular_lit: t.specular.status == SpecularStatus::Lit,
            cos_theta: t.cos_theta.to_f64(),
            cos_phi: t.specular.cos_phi.map(|c| c.to_f64()),
            on_edge: t.arrival.cone.is_some_and(|c| c.on_edge),
            i_l: widen::<R>(t.arrival.i_l),
            d: t.arrival.distance.map(|d| d.to_f64()),
        })
        .collect();
    Ok(Out {
        lights,
        color: widen::<R>(eval.shade.color),
    })
}

/// The core's inputs for a case, validated as the solver validates them: for timing the core.
pub struct Prepared<R: Real> {
    pub at: ShadingPoint<R>,
    pub material: Material<R>,
    pub lights: LightSet<R>,
}

pub fn prepare<R: Real>(case: &Case) -> Result<Prepared<R>, String> {
    let problem = load::<R>(case)?;
    let Target::Point {
        position: Some(p),
        normal: Some(n),
        material,
    } = &problem.target
    else {
        return Err("not a point problem with P and N".into());
    };
    let v = match problem.viewer {
        Some(e) => Some(between::<R>(e, *p).ok_or("the viewer is at P")?.unit),
        None => None,
    };
    Ok(Prepared {
        at: ShadingPoint {
            p: *p,
            n: n.unit,
            v,
        },
        material: *material.material,
        lights: problem.lights.clone(),
    })
}

/// The colour from the core alone (`core::shade`, the tracer's path), without the solver's
/// checks: for the cases the solver refuses.
pub fn core_color<R: Real>(case: &Case) -> Result<[f64; 3], String> {
    let p = prepare::<R>(case)?;
    let s = shade(
        &p.at,
        &p.material,
        &p.lights,
        &mut AllVisible,
        &mut NoRecord,
    );
    Ok(widen::<R>(s.color))
}

/// The two precisions, with what the measurement needs of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    F32,
    F64,
}

impl Precision {
    /// Machine epsilon.
    pub fn epsilon(self) -> f64 {
        match self {
            Precision::F32 => f32::EPSILON as f64,
            Precision::F64 => f64::EPSILON,
        }
    }
    /// Bits of the significand.
    fn bits(self) -> i64 {
        match self {
            Precision::F32 => 24,
            Precision::F64 => 53,
        }
    }
    /// The exponent of the smallest subnormal.
    fn min_exp(self) -> i64 {
        match self {
            Precision::F32 => -149,
            Precision::F64 => -1074,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

/// |a − b| as a 256-bit number (a is exact in it).
fn abs_diff(a: f64, b: &BigFloat) -> BigFloat {
    big(a)
        .sub(b, PREC, astro_float_num::RoundingMode::ToEven)
        .abs()
}

/// x·2^k exactly.
fn times_pow2(x: &BigFloat, k: i64) -> BigFloat {
    if x.is_zero() {
        return x.clone();
    }
    let mut y = x.clone();
    let e = y.exponent().expect("finite") as i64 + k;
    y.set_exponent(e as astro_float_num::Exponent);
    y
}

/// The exponent of the spacing of `prec` at `r`.
fn ulp_exp(r: &BigFloat, prec: Precision) -> i64 {
    if r.is_zero() {
        return prec.min_exp();
    }
    // r lies in [2^(e−1), 2^e): its spacing is 2^(e−bits).
    let e = r.exponent().expect("finite") as i64;
    (e - prec.bits()).max(prec.min_exp())
}

/// |x − r| in ulps of `prec` at r.
pub fn ulps(x: f64, r: &BigFloat, prec: Precision) -> f64 {
    to_f64(&times_pow2(&abs_diff(x, r), -ulp_exp(r, prec)))
}

/// |x − r| / max(ε·w, smallest subnormal of `prec`).
fn scaled(x: f64, r: &BigFloat, w: &BigFloat, prec: Precision) -> f64 {
    let rm = astro_float_num::RoundingMode::ToEven;
    let eps_w = w.mul(&big(prec.epsilon()), PREC, rm);
    let floor = big(ldexp(1.0, prec.min_exp()));
    let den = if eps_w > floor { eps_w } else { floor };
    to_f64(&abs_diff(x, r).div(&den, PREC, rm))
}

fn max_abs(a: [f64; 3]) -> f64 {
    a.iter().fold(0.0, |m, x| m.max(x.abs()))
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// W per channel, in units of ε: each term of the reference colour times how much it moves
/// when every intermediate is perturbed by a few ε (first order, except for (cos φ)^n_s):
///
/// - L, unit: δL = 2 + 2ρ, where ρ = (|P| + |P_l|)/d when the inputs themselves were rounded to
///   the precision (a position moved by ε|P| turns L by ε|P|/d), 0 otherwise;
/// - cos θ: δθ = δL + 2 (absolute), so the diffuse term moves by δθ/cos θ relative;
/// - I_l: 2 + f, and for a spot e(δL + 2)/cos ψ + 2 log₂(1 + e) + 2 (+ e|ln cos ψ| for a
///   rounded e);
/// - cos φ: δφ = 2δL + 6 + 2ρ_V (absolute). (cos φ)^n_s moves by up to
///   (min(1, cos φ + δφ ε))^n_s − (cos φ)^n_s, which is n_s·δφ ε/cos φ relative to first order
///   but stays right where n_s is so large that ε turns 0 into 1 (n_s = 1e300 near the mirror
///   direction); plus the rounding of powi/powf (2 log₂(1 + n_s) + 2) and, for a rounded n_s,
///   n_s|ln cos φ|;
/// - 3 more for the products and the sum; 2 + the number of ambient lights for O_a I_a.
pub fn weight(case: &Case, r: &ShadeRef, prec: Precision, input_rounding: bool) -> [BigFloat; 3] {
    let rm = astro_float_num::RoundingMode::ToEven;
    let eps = prec.epsilon();
    let k = |x: f64| big(x);
    let n_ambient = case
        .lights
        .iter()
        .filter(|l| matches!(l, LightIn::Ambient { .. }))
        .count() as f64;
    let mut w: [BigFloat; 3] =
        [0, 1, 2].map(|c| r.ambient[c].abs().mul(&k(2.0 + n_ambient), PREC, rm));
    let direct = case
        .lights
        .iter()
        .filter(|l| !matches!(l, LightIn::Ambient { .. }));
    let rho_v = match (input_rounding, case.viewer) {
        (true, Some(e)) => (max_abs(case.point) + max_abs(e)) / dist(case.point, e),
        _ => 0.0,
    };
    let n_s = case.material.shininess;
    for (l, lr) in direct.zip(&r.lights) {
        if lr.status != Status::Lit {
            continue;
        }
        let (position, falloff, exponent) = match *l {
            LightIn::Point {
                position, falloff, ..
            } => (Some(position), falloff, None),
            LightIn::Spot {
                position,
                falloff,
                exponent,
                ..
            } => (Some(position), falloff, Some(exponent)),
            _ => (None, 0, None),
        };
        let d = lr.d.as_ref().map_or(0.0, to_f64);
        let rho = match (input_rounding, position) {
            (true, Some(q)) if d > 0.0 => (max_abs(case.point) + max_abs(q)) / d,
            _ => 0.0,
        };
        let d_l = 2.0 + 2.0 * rho;
        let mut rel_i = 2.0 + falloff as f64;
        if let (Some(e), Some(c)) = (exponent, lr.cos_psi.as_ref().map(to_f64)) {
            if e > 0.0 {
                rel_i += e * (d_l + 2.0) / c + 2.0 * (1.0 + e).log2() + 2.0;
                if input_rounding {
                    rel_i += e * c.ln().abs();
                }
            }
        }
        let cos_theta = lr.cos_theta.as_ref().map_or(1.0, to_f64);
        let diffuse = 3.0 + rel_i + (d_l + 2.0) / cos_theta;
        // The specular term: its relative part, and how far (cos φ)^n_s itself can move.
        let (specular, pow_spread) = match (&lr.cos_phi, lr.specular_lit) {
            (Some(c), true) => {
                let c = to_f64(c);
                let mut rel = 3.0 + rel_i + 2.0 * (1.0 + n_s).log2() + 2.0;
                if input_rounding && n_s > 0.0 {
                    rel += n_s * c.ln().abs();
                }
                let h = (2.0 * d_l + 6.0 + 2.0 * rho_v) * eps;
                let spread = if n_s * h / c < 1.0 {
                    c.powf(n_s) * (n_s * (h / c).ln_1p()).exp_m1()
                } else {
                    (c + h).min(1.0).powf(n_s)
                };
                (rel, spread / eps)
            }
            _ => (0.0, 0.0),
        };
        for (c, wc) in w.iter_mut().enumerate() {
            let t = lr.diffuse[c].abs().mul(&k(diffuse), PREC, rm);
            let s = lr.specular[c].abs().mul(&k(specular), PREC, rm);
            let o_s_i_l = k(case.material.specular[c]).mul(&lr.i_l[c], PREC, rm);
            let spread = o_s_i_l.mul(&k(pow_spread), PREC, rm);
            *wc = wc
                .add(&t, PREC, rm)
                .add(&s, PREC, rm)
                .add(&spread, PREC, rm);
        }
    }
    w
}

/// A gate phong decided differently from the exact decision.
#[derive(Clone, Debug)]
pub struct Gate {
    pub light: usize,
    /// "light" (lit, behind, …) or "specular" (cos φ > 0).
    pub what: &'static str,
    pub reference: String,
    pub phong: String,
    /// phong's cone test put the point on the edge, within its stated tolerance, and lit it
    /// (docs/conventions.md, "Spot cone": the edge is lit).
    pub edge_tolerance: bool,
}

/// The errors of one precision on one case.
#[derive(Clone, Debug, Default)]
pub struct Measured {
    /// phong refused the problem (a validation error), with its message.
    pub refused: Option<String>,
    /// Where the solver refused: the core's own colour against the reference (max ulps), or
    /// why the core could not be run either.
    pub core_when_refused: Option<Result<f64, String>>,
    /// Some colour channel is NaN or infinite.
    pub non_finite: bool,
    pub gates: Vec<Gate>,
    /// Max over channels (only meaningful where no gate differs).
    pub color_ulps: f64,
    pub color_scaled: f64,
    pub color_abs: f64,
    /// Max over lights decided alike: |Δcos θ|/ε, |Δcos φ|/ε, I_l in ulps.
    pub cos_theta_eps: f64,
    pub cos_phi_eps: f64,
    pub i_l_ulps: f64,
}

fn status_name(s: LightStatus) -> &'static str {
    match s {
        LightStatus::Lit => "lit",
        LightStatus::BehindSurface => "behind_surface",
        LightStatus::InTangentPlane => "in_tangent_plane",
        LightStatus::OutsideCone => "outside_cone",
        LightStatus::AtLight => "at_light",
        LightStatus::InShadow => "in_shadow",
    }
}

/// Compares phong's output with the reference computed from `inputs` (the case as phong's
/// precision read it, or as given).
pub fn compare(
    inputs: &Case,
    r: &ShadeRef,
    out: &Result<Out, String>,
    prec: Precision,
    input_rounding: bool,
) -> Measured {
    let out = match out {
        Ok(o) => o,
        Err(e) => {
            return Measured {
                refused: Some(e.clone()),
                ..Measured::default()
            }
        }
    };
    let mut m = Measured {
        non_finite: out.color.iter().any(|x| !x.is_finite()),
        ..Measured::default()
    };
    assert_eq!(out.lights.len(), r.lights.len(), "{}", inputs.name);
    let eps = prec.epsilon();
    for (i, (o, lr)) in out.lights.iter().zip(&r.lights).enumerate() {
        let phong_status = status_name(o.status);
        if phong_status != lr.status.name() {
            m.gates.push(Gate {
                light: i,
                what: "light",
                reference: lr.status.name().into(),
                phong: phong_status.into(),
                edge_tolerance: o.on_edge
                    && lr.status == Status::OutsideCone
                    && o.status == LightStatus::Lit,
            });
            continue;
        }
        if lr.status == Status::Lit && o.specular_lit != lr.specular_lit {
            let on_off = |b: bool| if b { "on" } else { "off" };
            m.gates.push(Gate {
                light: i,
                what: "specular",
                reference: on_off(lr.specular_lit).into(),
                phong: on_off(o.specular_lit).into(),
                edge_tolerance: false,
            });
        }
        if lr.status == Status::AtLight {
            continue;
        }
        if let Some(c) = &lr.cos_theta {
            let d = to_f64(&abs_diff(o.cos_theta, c)) / eps;
            m.cos_theta_eps = m.cos_theta_eps.max(d);
        }
        if let (Some(c), Some(x)) = (&lr.cos_phi, o.cos_phi) {
            m.cos_phi_eps = m.cos_phi_eps.max(to_f64(&abs_diff(x, c)) / eps);
        }
        for c in 0..3 {
            m.i_l_ulps = m.i_l_ulps.max(ulps(o.i_l[c], &lr.i_l[c], prec));
        }
    }
    let w = weight(inputs, r, prec, input_rounding);
    for (c, wc) in w.iter().enumerate() {
        m.color_ulps = m.color_ulps.max(ulps(out.color[c], &r.color[c], prec));
        m.color_scaled = m
            .color_scaled
            .max(scaled(out.color[c], &r.color[c], wc, prec));
        m.color_abs = m
            .color_abs
            .max(to_f64(&abs_diff(out.color[c], &r.color[c])));
    }
    m
}

/// One case measured in both precisions.
#[derive(Clone, Debug)]
pub struct CaseResult {
    pub group: &'static str,
    pub name: String,
    /// f64 against the reference.
    pub f64: Measured,
    /// f32 against the reference of the inputs as given (what a user of f32 gets).
    pub f32: Measured,
    /// f32 against the reference of its own inputs, rounded to f32 (its arithmetic alone).
    pub f32_own: Measured,
}

/// Where the solver refused, measures the core's colour (max ulps over the channels).
fn core_when_refused<R: Real>(m: &mut Measured, case: &Case, r: &ShadeRef, prec: Precision) {
    if m.refused.is_none() {
        return;
    }
    m.core_when_refused = Some(core_color::<R>(case).and_then(|c| {
        if c.iter().all(|x| x.is_finite()) {
            Ok((0..3)
                .map(|i| ulps(c[i], &r.color[i], prec))
                .fold(0.0, f64::max))
        } else {
            Err(format!("the core's colour is not finite: {c:?}"))
        }
    }));
}

/// Runs phong in both precisions on a case and measures both against the reference.
pub fn measure(case: &Case, reference: &mut Reference) -> CaseResult {
    let exact = reference.shade(case);
    let out64 = solve::<f64>(case);
    let out32 = solve::<f32>(case);
    let rounded = case.rounded_to_f32();
    let mut f64 = compare(case, &exact, &out64, Precision::F64, false);
    core_when_refused::<f64>(&mut f64, case, &exact, Precision::F64);
    let mut f32 = compare(case, &exact, &out32, Precision::F32, true);
    core_when_refused::<f32>(&mut f32, case, &exact, Precision::F32);
    // The reference of the f32 inputs, where they are all finite in f32 (else phong refused).
    let f32_own = if prepare::<f32>(case).is_ok() {
        let exact32 = reference.shade(&rounded);
        let mut m = compare(&rounded, &exact32, &out32, Precision::F32, false);
        core_when_refused::<f32>(&mut m, case, &exact32, Precision::F32);
        m
    } else {
        f32.clone()
    };
    CaseResult {
        group: case.group,
        name: case.name.clone(),
        f64,
        f32,
        f32_own,
    }
}
