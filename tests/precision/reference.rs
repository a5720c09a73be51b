//! An independent evaluation of the chapter's model at a point, in 256-bit binary floating point
//! (astro-float), written from the table and the gating rules of docs/conventions.md, not from
//! phong's core:
//!
//! - L = (P − P_l)/‖P − P_l‖ (D_l/‖D_l‖ for a directional light), d = ‖P − P_l‖, I_l = C_l/d^f;
//! - a spot: cos ψ = D̂_l·L, I_l·(cos ψ)^e inside the cone ψ ≤ γ (the edge is lit), 0 outside;
//! - cos θ = −N̂·L; a light adds diffuse O_d I_l cos θ only where cos θ > 0;
//! - R = L − 2(N̂·L)N̂, V = (P − E)/‖P − E‖, cos φ = −R·V; specular O_s I_l (cos φ)^n_s only where
//!   the light is lit and cos φ > 0;
//! - ambient O_a I_a with I_a the sum of the ambient lights; the colour is the sum of the terms.
//!
//! Every value is rounded to 256 bits (a relative error below 2⁻²⁵⁵, far beneath f64's 2⁻⁵³).
//! Every *decision* (the signs of cos θ and cos φ, inside or outside the cone) is made exactly
//! on the inputs, with no rounding at all: each is the sign of a polynomial in the inputs,
//! evaluated in astro-float's exact (full-precision) arithmetic. The cone's cos²γ is exact for
//! γ = 0°, 30°, 45°, 60° and 90° (1, 3/4, 1/2, 1/4, 0); for other angles it is the 256-bit
//! value, which cannot tie with a point given in binary.

use std::cmp::Ordering;

use astro_float_num::{BigFloat, Consts, RoundingMode};

use super::suite::{Case, LightIn};

/// The working precision in bits (the issue asks for at least 100).
pub const PREC: usize = 256;
const RM: RoundingMode = RoundingMode::ToEven;

pub type V3 = [BigFloat; 3];

/// An input number, exactly. (astro-float-num 0.3.7's `from_f64` halves a subnormal, so one is
/// scaled into the normal range first and back by an exact power of two.)
pub fn big(x: f64) -> BigFloat {
    if x != 0.0 && x.abs() < f64::MIN_POSITIVE {
        let mut y = BigFloat::from_f64(x * 2f64.powi(64), PREC);
        let e = y.exponent().expect("finite");
        y.set_exponent(e - 64);
        return y;
    }
    BigFloat::from_f64(x, PREC)
}

fn vec3(a: [f64; 3]) -> V3 {
    a.map(big)
}

fn add(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.add(b, PREC, RM)
}

fn sub(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.sub(b, PREC, RM)
}

fn mul(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.mul(b, PREC, RM)
}

fn div(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.div(b, PREC, RM)
}

fn dot(a: &V3, b: &V3) -> BigFloat {
    add(
        &add(&mul(&a[0], &b[0]), &mul(&a[1], &b[1])),
        &mul(&a[2], &b[2]),
    )
}

fn scale(a: &V3, s: &BigFloat) -> V3 {
    [mul(&a[0], s), mul(&a[1], s), mul(&a[2], s)]
}

fn hadamard(a: &V3, b: &V3) -> V3 {
    [mul(&a[0], &b[0]), mul(&a[1], &b[1]), mul(&a[2], &b[2])]
}

fn vsub(a: &V3, b: &V3) -> V3 {
    [sub(&a[0], &b[0]), sub(&a[1], &b[1]), sub(&a[2], &b[2])]
}

fn vadd(a: &V3, b: &V3) -> V3 {
    [add(&a[0], &b[0]), add(&a[1], &b[1]), add(&a[2], &b[2])]
}

fn zero3() -> V3 {
    [big(0.0), big(0.0), big(0.0)]
}

/// ‖a‖ and a/‖a‖.
fn unit(a: &V3) -> (BigFloat, V3) {
    let len = dot(a, a).sqrt(PREC, RM);
    let inv = BigFloat::from_f64(1.0, PREC).div(&len, PREC, RM);
    (len.clone(), scale(a, &inv))
}

// Exact arithmetic (no rounding: the result holds every bit) for the decisions. astro-float-num
// 0.3.7's full-precision operations return an empty mantissa (which reads as 0) when an operand
// is zero (0 − 3 gives 0), so zero operands are handled here.

pub fn xadd(a: &BigFloat, b: &BigFloat) -> BigFloat {
    if a.is_zero() {
        b.clone()
    } else if b.is_zero() {
        a.clone()
    } else {
        a.add_full_prec(b)
    }
}

pub fn xsub(a: &BigFloat, b: &BigFloat) -> BigFloat {
    xadd(a, &b.neg())
}

pub fn xmul(a: &BigFloat, b: &BigFloat) -> BigFloat {
    if a.is_zero() || b.is_zero() {
        big(0.0)
    } else {
        a.mul_full_prec(b)
    }
}

pub fn xdot(a: &V3, b: &V3) -> BigFloat {
    xadd(
        &xadd(&xmul(&a[0], &b[0]), &xmul(&a[1], &b[1])),
        &xmul(&a[2], &b[2]),
    )
}

fn xvsub(a: &V3, b: &V3) -> V3 {
    [xsub(&a[0], &b[0]), xsub(&a[1], &b[1]), xsub(&a[2], &b[2])]
}

pub fn sign(x: &BigFloat) -> Ordering {
    assert!(!x.is_nan(), "a decision of the reference is NaN");
    if x.is_zero() {
        Ordering::Equal
    } else if x.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// Approximately as an f64 (within an ulp; ±inf beyond f64's range): for reports and weights.
pub fn to_f64(x: &BigFloat) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x.is_inf_pos() {
        return f64::INFINITY;
    }
    if x.is_inf_neg() {
        return f64::NEG_INFINITY;
    }
    if x.is_zero() {
        return 0.0;
    }
    let (m, _, _, e, _) = x.as_raw_parts().expect("a finite number");
    // The value is 0.m × 2^e, the top word's highest bit set.
    let top = *m.last().expect("a mantissa") as f64;
    let v = ldexp(top, e as i64 - 64);
    if x.is_negative() {
        -v
    } else {
        v
    }
}

/// x·2^k, by exact steps of powers of two.
pub fn ldexp(mut x: f64, mut k: i64) -> f64 {
    while k > 1000 {
        x *= 2f64.powi(1000);
        k -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while k < -1000 {
        x *= 2f64.powi(-1000);
        k += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * 2f64.powi(k as i32)
}

/// Whether a light lights the point, decided exactly (docs/conventions.md, "Gating").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Lit,
    BehindSurface,
    InTangentPlane,
    OutsideCone,
    AtLight,
}

impl Status {
    /// The name phong's JSON and `LightStatus` use.
    pub fn name(self) -> &'static str {
        match self {
            Status::Lit => "lit",
            Status::BehindSurface => "behind_surface",
            Status::InTangentPlane => "in_tangent_plane",
            Status::OutsideCone => "outside_cone",
            Status::AtLight => "at_light",
        }
    }
}

/// One light's values at P.
#[derive(Clone, Debug)]
pub struct LightRef {
    pub status: Status,
    /// d (point and spot lights that do not sit at P).
    pub d: Option<BigFloat>,
    /// I_l (zero outside the cone and at the light).
    pub i_l: V3,
    /// cos θ = −N̂·L (`None` at the light, where L is undefined).
    pub cos_theta: Option<BigFloat>,
    /// cos ψ of a spot.
    pub cos_psi: Option<BigFloat>,
    /// cos φ = −R·V, where there is a viewer and L is defined.
    pub cos_phi: Option<BigFloat>,
    /// cos φ > 0, decided exactly (`None` without a viewer or L).
    pub cos_phi_positive: Option<bool>,
    /// The gated diffuse and specular terms.
    pub diffuse: V3,
    pub specular: V3,
    /// Whether the specular term was added (lit and cos φ > 0 and O_s and a viewer).
    pub specular_lit: bool,
}

/// The point's values.
#[derive(Clone, Debug)]
pub struct ShadeRef {
    pub ambient: V3,
    pub lights: Vec<LightRef>,
    /// Eq. 4.16, gated, unclamped.
    pub color: V3,
}

/// The 256-bit evaluator (holds astro-float's cache of constants such as π).
pub struct Reference {
    cc: Consts,
}

impl Default for Reference {
    fn default() -> Self {
        Reference {
            cc: Consts::new().expect("astro-float's constants"),
        }
    }
}

impl Reference {
    /// x^e for x ≥ 0, with 0^0 = 1 (as the chapter's n_s = 0 and e = 0 mean "no exponent").
    fn pow(&mut self, x: &BigFloat, e: f64) -> BigFloat {
        if e == 0.0 {
            return big(1.0);
        }
        if x.is_zero() {
            return big(0.0);
        }
        let one = big(1.0);
        if x.cmp(&one) == Some(0) {
            return one;
        }
        let r = x.pow(&big(e), PREC, RM, &mut self.cc);
        // astro-float's exponent reaches 2^±2^31 or so; (1 − 1e-16)^1e300 is far below it,
        // and far below every f64 too: 0 is then exact to every bit an f64 can show.
        if r.is_nan() || r.is_inf() {
            assert!(x.cmp(&one) == Some(-1), "x^e overflowed for x ≥ 1");
            return big(0.0);
        }
        r
    }

    /// cos²γ: exact for the angles whose square cosine is rational, 256-bit otherwise.
    fn cos2_deg(&mut self, gamma: f64) -> BigFloat {
        match gamma {
            0.0 => big(1.0),
            30.0 => big(0.75),
            45.0 => big(0.5),
            60.0 => big(0.25),
            90.0 => big(0.0),
            g => {
                let pi = self.cc.pi(PREC, RM);
                let rad = div(&mul(&big(g), &pi), &big(180.0));
                let c = rad.cos(PREC, RM, &mut self.cc);
                mul(&c, &c)
            }
        }
    }

    /// The chapter's model at the case's point, on its inputs exactly as given.
    pub fn shade(&mut self, case: &Case) -> ShadeRef {
        let p = vec3(case.point);
        let n_given = vec3(case.normal);
        let (_, n) = unit(&n_given);
        let m = &case.material;
        let (o_a, o_d, o_s) = (vec3(m.ambient), vec3(m.diffuse), vec3(m.specular));
        // V from the eye to the point, Eq. 4.10; v_raw = P − E exactly, for the decisions.
        let v_raw = case.viewer.map(|e| xvsub(&p, &vec3(e)));
        let v = v_raw.as_ref().map(|w| unit(w).1);

        // Ambient light, Eq. 4.5–4.6: O_a times the sum of the ambient lights.
        let mut i_a = zero3();
        let mut any_ambient = false;
        for l in &case.lights {
            if let LightIn::Ambient { color } = l {
                i_a = vadd(&i_a, &vec3(*color));
                any_ambient = true;
            }
        }
        let ambient = if any_ambient {
            hadamard(&o_a, &i_a)
        } else {
            zero3()
        };

        let mut color = ambient.clone();
        let mut lights = Vec::new();
        for l in &case.lights {
            // The incidence vector before normalising (exact), and the light's colour.
            let (w, c, falloff, spot) = match l {
                LightIn::Ambient { .. } => continue,
                LightIn::Directional { direction, color } => {
                    (vec3(*direction), vec3(*color), None, None)
                }
                LightIn::Point {
                    position,
                    color,
                    falloff,
                } => (
                    xvsub(&p, &vec3(*position)),
                    vec3(*color),
                    Some(*falloff),
                    None,
                ),
                LightIn::Spot {
                    position,
                    axis,
                    angle,
                    exponent,
                    color,
                    falloff,
                } => (
                    xvsub(&p, &vec3(*position)),
                    vec3(*color),
                    Some(*falloff),
                    Some((vec3(*axis), *angle, *exponent)),
                ),
            };
            if w.iter().all(|x| x.is_zero()) {
                // P is at the light: L is undefined and nothing arrives.
                lights.push(LightRef {
                    status: Status::AtLight,
                    d: Some(big(0.0)),
                    i_l: zero3(),
                    cos_theta: None,
                    cos_psi: None,
                    cos_phi: None,
                    cos_phi_positive: None,
                    diffuse: zero3(),
                    specular: zero3(),
                    specular_lit: false,
                });
                continue;
            }
            // L and d, Eq. 4.1; the falloff, Eq. 4.2–4.3 (rounded at 256 bits).
            let (len, l_unit) = unit(&w);
            let d = falloff.map(|_| len.clone());
            let mut i_l = c.clone();
            if let Some(f) = falloff {
                for _ in 0..f {
                    i_l = [div(&i_l[0], &len), div(&i_l[1], &len), div(&i_l[2], &len)];
                }
            }
            // The cone, Eq. 4.4: inside iff D·w ≥ 0 and (D·w)² ≥ cos²γ ‖D‖²‖w‖², exactly.
            let mut outside = false;
            let mut cos_psi = None;
            if let Some((axis, gamma, e)) = &spot {
                let s = xdot(axis, &w);
                let lhs = xmul(&s, &s);
                let rhs_exact = xmul(&xdot(axis, axis), &xdot(&w, &w));
                let cos2 = self.cos2_deg(*gamma);
                let rhs = if matches!(*gamma, 0.0 | 30.0 | 45.0 | 60.0 | 90.0) {
                    xmul(&cos2, &rhs_exact)
                } else {
                    mul(&cos2, &rhs_exact)
                };
                let inside =
                    sign(&s) != Ordering::Less && sign(&xsub(&lhs, &rhs)) != Ordering::Less;
                let c_psi = dot(&unit(axis).1, &l_unit);
                if inside {
                    // Clamped to [0, 1] against the last of 256 bits only.
                    let x = c_psi.clamp(&big(0.0), &big(1.0));
                    let factor = self.pow(&x, *e);
                    i_l = scale(&i_l, &factor);
                } else {
                    outside = true;
                    i_l = zero3();
                }
                cos_psi = Some(c_psi);
            }
            // cos θ = −N̂·L, Eq. 4.7; its sign exactly: that of −N·w.
            let cos_theta = dot(&n, &l_unit).neg();
            let facing = sign(&xdot(&n_given, &w).neg());
            let status = if outside {
                Status::OutsideCone
            } else {
                match facing {
                    Ordering::Greater => Status::Lit,
                    Ordering::Less => Status::BehindSurface,
                    Ordering::Equal => Status::InTangentPlane,
                }
            };
            let lit = status == Status::Lit;
            // Diffuse, Eq. 4.8.
            let diffuse = if lit {
                scale(&hadamard(&o_d, &i_l), &cos_theta)
            } else {
                zero3()
            };
            // Specular, Eq. 4.9–4.15: R = L − 2(N̂·L)N̂, cos φ = −R·V. Its sign exactly:
            // cos φ·‖w‖‖N‖²‖v‖ = 2(N·w)(N·v) − (w·v)‖N‖², a polynomial in the inputs.
            let (mut cos_phi, mut cos_phi_positive) = (None, None);
            let mut specular = zero3();
            let mut specular_lit = false;
            if let (Some(v), Some(v_raw)) = (&v, &v_raw) {
                let n_dot_l = dot(&n, &l_unit);
                let r = vsub(&l_unit, &scale(&n, &mul(&big(2.0), &n_dot_l)));
                let c_phi = dot(&r, v).neg();
                let two_nw_nv = xmul(
                    &xmul(&big(2.0), &xdot(&n_given, &w)),
                    &xdot(&n_given, v_raw),
                );
                let wv_nn = xmul(&xdot(&w, v_raw), &xdot(&n_given, &n_given));
                let positive = sign(&xsub(&two_nw_nv, &wv_nn)) == Ordering::Greater;
                if lit && positive {
                    let x = c_phi.clamp(&big(0.0), &big(1.0));
                    let pow = self.pow(&x, m.shininess);
                    specular = scale(&hadamard(&o_s, &i_l), &pow);
                    specular_lit = true;
                }
                cos_phi = Some(c_phi);
                cos_phi_positive = Some(positive);
            }
            color = vadd(&color, &vadd(&diffuse, &specular));
            lights.push(LightRef {
                status,
                d,
                i_l,
                cos_theta: Some(cos_theta),
                cos_psi,
                cos_phi,
                cos_phi_positive,
                diffuse,
                specular,
                specular_lit,
            });
        }
        ShadeRef {
            ambient,
            lights,
            color,
        }
    }
}
