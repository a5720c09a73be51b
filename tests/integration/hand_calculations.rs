//! Checks the solver's JSON for the chapter's exercises 4.1, 4.2 and 4.3 against values
//! calculated independently here: a second, deliberately plain implementation of the chapter's
//! formulas on `[f64; 3]` arrays (Eqs. 4.1–4.16, with the sign conventions of
//! docs/conventions.md), and, where a value has a simple closed form, that closed form written
//! out by hand. No expected number in this file was copied from the program's output.
//!
//! A last test runs every exercise file in both precisions and checks that the f32 calculation
//! agrees with the f64 reference on every numeric leaf of the JSON.

use std::path::{Path, PathBuf};

use approx::relative_eq;
use phong::core::Precision;
use phong::report::file::solve_json;
use serde_json::Value;

/// Tolerance of the f64 comparisons: absolute for values up to 1, relative above.
const TOL: f64 = 1e-12;

// ---------------------------------------------------------------------------------------------
// A second, independent implementation of the chapter's model.
// ---------------------------------------------------------------------------------------------

type V3 = [f64; 3];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// Component-wise product ("multiplicação de cores", Section 4.3.1).
fn mul(a: V3, b: V3) -> V3 {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn length(a: V3) -> f64 {
    dot(a, a).sqrt()
}

fn normalize(a: V3) -> V3 {
    scale(a, 1.0 / length(a))
}

fn clamp01(c: V3) -> V3 {
    c.map(|x| x.clamp(0.0, 1.0))
}

/// round(255 · c), rounding halves away from zero, of a colour already in [0, 1].
fn rgb8(c: V3) -> [f64; 3] {
    c.map(|x| (255.0 * x).round())
}

#[derive(Clone, Copy)]
struct Material {
    /// O_a (k_a folded in, Eq. 4.6).
    o_a: V3,
    /// O_d (k_d folded in, Eq. 4.8).
    o_d: V3,
    /// O_s (k_s folded in, Eq. 4.10).
    o_s: V3,
    n_s: f64,
}

/// The material M of the exercises 4.2 and 4.3.
const M: Material = Material {
    o_a: [0.5, 0.4, 0.6],
    o_d: [0.7, 0.8, 0.6],
    o_s: [0.2, 0.3, 0.4],
    n_s: 1.0,
};

#[derive(Clone, Copy)]
struct PointLight {
    position: V3,
    color: V3,
    /// f in Eq. 4.3: 0 none, 1 linear, 2 quadratic.
    falloff: i32,
}

/// Every intermediate of the shading of one point by one point light, plus the totals.
struct Shading {
    /// N, unit.
    n: V3,
    /// L = (P − P_l)/‖P − P_l‖ (Eq. 4.1).
    l: V3,
    /// d = ‖P − P_l‖.
    d: f64,
    /// 1/d^f (Eq. 4.2).
    falloff_factor: f64,
    /// I_l = C_l/d^f (Eq. 4.2).
    i_l: V3,
    n_dot_l: f64,
    /// cos θ = −N·L (Eq. 4.7).
    cos_theta: f64,
    /// R = L − 2(N·L)N (Eq. 4.15).
    r: V3,
    /// V = (P − E)/‖P − E‖, from the eye to the point.
    v: V3,
    n_dot_v: f64,
    /// cos φ = −R·V (Eq. 4.9).
    cos_phi: f64,
    /// O_a I_a (Eq. 4.6), zero without an ambient light.
    ambient: V3,
    /// O_d I_l cos θ (Eq. 4.8), taken literally.
    diffuse_literal: V3,
    /// O_s I_l (cos φ)^n_s (Eq. 4.10), taken literally.
    specular_literal: V3,
    /// The diffuse term, gated (docs/conventions.md, "Gating"): only where cos θ > 0.
    diffuse: V3,
    /// The specular term, gated (docs/conventions.md, "Gating"): only where cos θ > 0 and
    /// cos φ > 0.
    specular: V3,
    /// Eq. 4.16 taken literally: ambient + literal diffuse + literal specular.
    literal: V3,
    /// Ambient + gated diffuse + gated specular.
    unclamped: V3,
    clamped: V3,
    rgb8: [f64; 3],
}

/// Shades P (normal `normal`, used unit-normalised) seen from `eye`, lit by an optional ambient
/// light and one point light, straight from the chapter's equations.
fn shade(
    p: V3,
    normal: V3,
    eye: V3,
    ambient_light: Option<V3>,
    light: PointLight,
    m: Material,
) -> Shading {
    let n = normalize(normal);

    let to_point = sub(p, light.position);
    let d = length(to_point);
    let l = scale(to_point, 1.0 / d);
    let falloff_factor = 1.0 / d.powi(light.falloff);
    let i_l = scale(light.color, falloff_factor);

    let n_dot_l = dot(n, l);
    let cos_theta = -n_dot_l;
    let r = sub(l, scale(n, 2.0 * n_dot_l));

    let v = normalize(sub(p, eye));
    let n_dot_v = dot(n, v);
    let cos_phi = -dot(r, v);

    let ambient = match ambient_light {
        Some(i_a) => mul(m.o_a, i_a),
        None => [0.0; 3],
    };
    let diffuse_literal = scale(mul(m.o_d, i_l), cos_theta);
    let specular_literal = scale(mul(m.o_s, i_l), cos_phi.powf(m.n_s));
    let diffuse = if cos_theta > 0.0 {
        diffuse_literal
    } else {
        [0.0; 3]
    };
    let specular = if cos_theta > 0.0 && cos_phi > 0.0 {
        specular_literal
    } else {
        [0.0; 3]
    };

    let literal = add(add(ambient, diffuse_literal), specular_literal);
    let unclamped = add(add(ambient, diffuse), specular);
    let clamped = clamp01(unclamped);
    Shading {
        n,
        l,
        d,
        falloff_factor,
        i_l,
        n_dot_l,
        cos_theta,
        r,
        v,
        n_dot_v,
        cos_phi,
        ambient,
        diffuse_literal,
        specular_literal,
        diffuse,
        specular,
        literal,
        unclamped,
        clamped,
        rgb8: rgb8(clamped),
    }
}

/// The parameter t where the line O + tD meets the plane through `q` with normal `n`:
/// n·(O + tD − q) = 0.
fn line_plane_t(origin: V3, direction: V3, q: V3, n: V3) -> f64 {
    dot(n, sub(q, origin)) / dot(n, direction)
}

// ---------------------------------------------------------------------------------------------
// Reading the program's JSON.
// ---------------------------------------------------------------------------------------------

fn exercise(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("exercises")
        .join(name)
}

fn solve(name: &str) -> Value {
    let path = exercise(name);
    solve_json(&path, Precision::F64)
        .unwrap_or_else(|e| panic!("{} does not solve: {e}", path.display()))
}

fn at<'a>(doc: &'a Value, pointer: &str) -> &'a Value {
    doc.pointer(pointer)
        .unwrap_or_else(|| panic!("the JSON has no {pointer}"))
}

fn num(doc: &Value, pointer: &str) -> f64 {
    at(doc, pointer)
        .as_f64()
        .unwrap_or_else(|| panic!("{pointer} is not a number: {}", at(doc, pointer)))
}

fn vec3(doc: &Value, pointer: &str) -> V3 {
    let a = at(doc, pointer)
        .as_array()
        .unwrap_or_else(|| panic!("{pointer} is not an array: {}", at(doc, pointer)));
    assert_eq!(a.len(), 3, "{pointer} does not have 3 components");
    [0, 1, 2].map(|i| {
        a[i].as_f64()
            .unwrap_or_else(|| panic!("{pointer}/{i} is not a number"))
    })
}

fn close(actual: f64, expected: f64) -> bool {
    relative_eq!(actual, expected, epsilon = TOL, max_relative = TOL)
}

/// The number at `pointer` equals `expected` to 1e-12 (absolute, or relative above 1).
fn check(doc: &Value, pointer: &str, expected: f64) {
    let actual = num(doc, pointer);
    assert!(
        close(actual, expected),
        "{pointer}: the program gives {actual:e}, the hand calculation {expected:e}"
    );
}

/// The vector at `pointer` equals `expected` component by component, to 1e-12.
fn check3(doc: &Value, pointer: &str, expected: V3) {
    let actual = vec3(doc, pointer);
    for i in 0..3 {
        assert!(
            close(actual[i], expected[i]),
            "{pointer}/{i}: the program gives {actual:?}, the hand calculation {expected:?}"
        );
    }
}

/// Two values of the independent implementation agree (a check of the closed forms).
fn same3(what: &str, a: V3, b: V3) {
    for i in 0..3 {
        assert!(close(a[i], b[i]), "{what}: {a:?} != {b:?}");
    }
}

fn same(what: &str, a: f64, b: f64) {
    assert!(close(a, b), "{what}: {a:e} != {b:e}");
}

fn check_str(doc: &Value, pointer: &str, expected: &str) {
    assert_eq!(at(doc, pointer).as_str(), Some(expected), "{pointer}");
}

/// The JSON pointer of the reading with this code.
fn reading(doc: &Value, code: &str) -> String {
    let readings = at(doc, "/readings")
        .as_array()
        .expect("readings is an array");
    let i = readings
        .iter()
        .position(|r| r["code"] == code)
        .unwrap_or_else(|| panic!("no reading {code:?} in {}", doc["readings"]));
    format!("/readings/{i}/solution")
}

fn finding<'a>(doc: &'a Value, code: &str) -> &'a Value {
    at(doc, "/findings")
        .as_array()
        .expect("findings is an array")
        .iter()
        .find(|f| f["code"] == code)
        .unwrap_or_else(|| panic!("no finding {code:?} in {}", doc["findings"]))
}

/// Checks one evaluation's record of a single point light (`light`, at index `index` in the
/// problem's lights) against the independent shading `s`, under the JSON object `base`.
fn check_light(doc: &Value, base: &str, index: usize, light: PointLight, s: &Shading) {
    let lp = format!("{base}/lights/0");
    assert_eq!(num(doc, &format!("{lp}/index")), index as f64, "{lp}/index");
    check_str(doc, &format!("{lp}/type"), "point");
    check3(doc, &format!("{lp}/position"), light.position);
    check3(doc, &format!("{lp}/color"), light.color);
    check(doc, &format!("{lp}/falloff"), f64::from(light.falloff));
    check3(doc, &format!("{lp}/l"), s.l);
    check(doc, &format!("{lp}/d"), s.d);
    check(doc, &format!("{lp}/falloff_factor"), s.falloff_factor);
    check3(doc, &format!("{lp}/i_l"), s.i_l);
    check(doc, &format!("{lp}/n_dot_l"), s.n_dot_l);
    check(doc, &format!("{lp}/cos_theta"), s.cos_theta);
    check3(doc, &format!("{lp}/diffuse/literal"), s.diffuse_literal);
    check3(doc, &format!("{lp}/diffuse/term"), s.diffuse);
    check3(doc, &format!("{lp}/specular/r"), s.r);
    check(doc, &format!("{lp}/specular/cos_phi"), s.cos_phi);
    check3(doc, &format!("{lp}/specular/literal"), s.specular_literal);
    check3(doc, &format!("{lp}/specular/term"), s.specular);
}

/// Checks the rest of an evaluation (normal, viewer, totals, colour) against `s`.
fn check_evaluation(doc: &Value, base: &str, s: &Shading) {
    check3(doc, &format!("{base}/normal/n"), s.n);
    check3(doc, &format!("{base}/viewer/v"), s.v);
    check(doc, &format!("{base}/viewer/n_dot_v"), s.n_dot_v);
    // The viewer is in front of the surface when V points into it (N·V < 0).
    let side = if s.n_dot_v < 0.0 { "front" } else { "back" };
    check_str(doc, &format!("{base}/viewer/side"), side);
    check3(doc, &format!("{base}/totals/ambient"), s.ambient);
    check3(doc, &format!("{base}/totals/diffuse"), s.diffuse);
    check3(doc, &format!("{base}/totals/specular"), s.specular);
    check3(doc, &format!("{base}/color/literal"), s.literal);
    check3(doc, &format!("{base}/color/unclamped"), s.unclamped);
    check3(doc, &format!("{base}/color/clamped"), s.clamped);
    check3(doc, &format!("{base}/color/rgb8"), s.rgb8);
}

// ---------------------------------------------------------------------------------------------
// Exercise 4.1: O_a = k_a · (0.5, 0.7, 0.3), k_a = 1, white ambient light.
// ---------------------------------------------------------------------------------------------

#[test]
fn exercise_4_1_colour_is_the_ambient_colour_under_white_light() {
    let doc = solve("4.1.json");
    let k_a = 1.0;
    let o_a = scale([0.5, 0.7, 0.3], k_a);
    let i_a = [1.0, 1.0, 1.0];
    let ambient = mul(o_a, i_a); // Eq. 4.5

    check3(&doc, "/solution/material/o_a", o_a);
    check3(&doc, "/solution/ambient/i_a", i_a);
    check3(&doc, "/solution/ambient/o_a", o_a);
    check3(&doc, "/solution/ambient/term", ambient);
    check3(&doc, "/solution/totals/ambient", ambient);
    check3(&doc, "/solution/totals/diffuse", [0.0; 3]);
    check3(&doc, "/solution/totals/specular", [0.0; 3]);
    assert_eq!(doc["solution"]["lights"], Value::Array(vec![]));

    // With no direct light the colour is the ambient term alone, already inside [0, 1].
    for key in ["literal", "unclamped", "clamped"] {
        check3(&doc, &format!("/solution/color/{key}"), ambient);
    }
    // 255 · (0.5, 0.7, 0.3) = (127.5, 178.5, 76.5): every channel is a half, rounded up.
    same3("rgb8 by hand", rgb8(ambient), [128.0, 179.0, 77.0]);
    check3(&doc, "/solution/color/rgb8", [128.0, 179.0, 77.0]);

    assert_eq!(doc["findings"], Value::Array(vec![]), "4.1 has no findings");
    assert_eq!(doc["readings"], Value::Array(vec![]), "4.1 has no readings");
}

// ---------------------------------------------------------------------------------------------
// Exercise 4.2: white point light at (1,1,1), linear falloff, P = (3,1,3), N = (3/5, 0, 4/5),
// viewer at (5,4,6), material M, no ambient light.
// ---------------------------------------------------------------------------------------------

const P_4_2: V3 = [3.0, 1.0, 3.0];
const N_4_2: V3 = [0.6, 0.0, 0.8];
const EYE_4_2: V3 = [5.0, 4.0, 6.0];
const LIGHT_4_2: PointLight = PointLight {
    position: [1.0, 1.0, 1.0],
    color: [1.0, 1.0, 1.0],
    falloff: 1,
};

/// The closed forms of exercise 4.2 as written, with the normal N = (3/5, 0, 4/5).
/// P − P_l = (2, 0, 2); P − E = (−2, −3, −3).
#[test]
fn exercise_4_2_independent_calculation_matches_the_closed_forms() {
    let s = shade(P_4_2, N_4_2, EYE_4_2, None, LIGHT_4_2, M);
    let r2 = 2f64.sqrt();
    let r22 = 22f64.sqrt();

    same3("L", s.l, [1.0 / r2, 0.0, 1.0 / r2]);
    same("d", s.d, 2.0 * r2);
    same("falloff factor", s.falloff_factor, 1.0 / (2.0 * r2));
    same3("I_l", s.i_l, [1.0 / (2.0 * r2); 3]);
    // N·L = (0.6 + 0.8)/√2.
    same("N·L", s.n_dot_l, 1.4 / r2);
    same("cos θ", s.cos_theta, -1.4 / r2);
    // R = L − 2(N·L)N = ((1 − 1.68), 0, (1 − 2.24))/√2.
    same3("R", s.r, [-0.68 / r2, 0.0, -1.24 / r2]);
    same3("V", s.v, [-2.0 / r22, -3.0 / r22, -3.0 / r22]);
    // N·V = (−1.2 − 2.4)/√22.
    same("N·V", s.n_dot_v, -3.6 / r22);
    // cos φ = −R·V = −(1.36 + 3.72)/(√2 √22).
    same("cos φ", s.cos_phi, -5.08 / (r2 * r22));
    // O_d I_l cos θ = O_d · (1/(2√2)) · (−1.4/√2) = −0.35 O_d.
    same3(
        "diffuse, literal",
        s.diffuse_literal,
        [-0.245, -0.28, -0.21],
    );
    // O_s I_l cos φ = O_s · (1/(2√2)) · (−5.08/√44) = −(1.27/√22) O_s.
    let k = -1.27 / r22;
    same3(
        "specular, literal",
        s.specular_literal,
        [0.2 * k, 0.3 * k, 0.4 * k],
    );
    same3(
        "Eq. 4.16 literally",
        s.literal,
        [-0.245 + 0.2 * k, -0.28 + 0.3 * k, -0.21 + 0.4 * k],
    );
    // Light behind the surface: nothing is added.
    same3("colour", s.unclamped, [0.0; 3]);

    // The same point with the normal reversed: cos θ changes sign, R does not (it depends on
    // (N·L)N, even in N), so cos φ stays negative.
    let rev = shade(P_4_2, scale(N_4_2, -1.0), EYE_4_2, None, LIGHT_4_2, M);
    same("reversed cos θ", rev.cos_theta, 1.4 / r2);
    same3("reversed R", rev.r, s.r);
    same("reversed cos φ", rev.cos_phi, s.cos_phi);
    same3("reversed diffuse", rev.diffuse, [0.245, 0.28, 0.21]);
    same3("reversed specular", rev.specular, [0.0; 3]);
    // 255 · (0.245, 0.28, 0.21) = (62.475, 71.4, 53.55).
    same3("reversed rgb8", rev.rgb8, [62.0, 71.0, 54.0]);
}

#[test]
fn exercise_4_2_light_is_behind_the_surface() {
    let doc = solve("4.2.json");
    let s = shade(P_4_2, N_4_2, EYE_4_2, None, LIGHT_4_2, M);
    let r2 = 2f64.sqrt();

    // Hand-written closed forms, checked against the program directly.
    check3(&doc, "/solution/lights/0/l", [1.0 / r2, 0.0, 1.0 / r2]);
    check(&doc, "/solution/lights/0/d", 2.0 * r2);
    check(&doc, "/solution/lights/0/i_l/0", 1.0 / (2.0 * r2));
    check(&doc, "/solution/lights/0/n_dot_l", 1.4 / r2);
    check(&doc, "/solution/lights/0/cos_theta", -1.4 / r2);
    let r22 = 22f64.sqrt();
    check3(
        &doc,
        "/solution/viewer/v",
        [-2.0 / r22, -3.0 / r22, -3.0 / r22],
    );

    // Every intermediate against the independent implementation.
    check3(&doc, "/solution/point", P_4_2);
    check3(&doc, "/solution/normal/given", N_4_2);
    check(&doc, "/solution/normal/length", 1.0);
    assert_eq!(doc["solution"]["normal"]["reversed"], false);
    check3(&doc, "/solution/material/o_a", M.o_a);
    check3(&doc, "/solution/material/o_d", M.o_d);
    check3(&doc, "/solution/material/o_s", M.o_s);
    check(&doc, "/solution/material/n_s", M.n_s);
    check3(&doc, "/solution/viewer/position", EYE_4_2);
    // No ambient light in the problem: no ambient term.
    assert_eq!(doc["solution"]["ambient"]["term"], Value::Null);
    check_light(&doc, "/solution", 0, LIGHT_4_2, &s);
    check_evaluation(&doc, "/solution", &s);

    // The gated terms are all zero: cos θ < 0.
    assert!(s.cos_theta < 0.0);
    check3(&doc, "/solution/lights/0/diffuse/term", [0.0; 3]);
    check3(&doc, "/solution/lights/0/specular/term", [0.0; 3]);
    check3(&doc, "/solution/color/unclamped", [0.0; 3]);
    check3(&doc, "/solution/color/clamped", [0.0; 3]);
    check3(&doc, "/solution/color/rgb8", [0.0; 3]);
    check_str(&doc, "/solution/lights/0/status", "behind_surface");
    assert_eq!(
        doc["solution"]["lights"][0]["specular"]["cos_phi_pow"],
        Value::Null
    );

    // The finding names the light and its cos θ.
    let f = finding(&doc, "light_behind_surface");
    assert_eq!(f["light"], 0);
    check(f, "/values/cos_theta", -1.4 / r2);
}

#[test]
fn exercise_4_2_reading_with_the_normal_reversed_lights_the_point_diffusely() {
    let doc = solve("4.2.json");
    let base = &reading(&doc, "normal_reversed");
    let n_reversed = scale(N_4_2, -1.0);
    let s = shade(P_4_2, n_reversed, EYE_4_2, None, LIGHT_4_2, M);

    check3(&doc, &format!("{base}/normal/given"), N_4_2);
    check3(&doc, &format!("{base}/normal/n"), n_reversed);
    assert_eq!(at(&doc, &format!("{base}/normal/reversed")), true);
    check_light(&doc, base, 0, LIGHT_4_2, &s);
    check_evaluation(&doc, base, &s);

    // The light is now in front: cos θ = +1.4/√2 and the diffuse term is 0.7·I_l·cos θ
    // = O_d · (1/(2√2)) · (1.4/√2) = 0.35 · O_d = (0.245, 0.28, 0.21) up to rounding.
    let r2 = 2f64.sqrt();
    check(&doc, &format!("{base}/lights/0/cos_theta"), 1.4 / r2);
    check3(
        &doc,
        &format!("{base}/lights/0/diffuse/term"),
        [0.245, 0.28, 0.21],
    );
    check_str(&doc, &format!("{base}/lights/0/status"), "lit");
    // cos φ < 0: the highlight points away from the viewer, no specular.
    assert!(s.cos_phi < 0.0);
    check3(&doc, &format!("{base}/lights/0/specular/term"), [0.0; 3]);
    check3(
        &doc,
        &format!("{base}/color/unclamped"),
        [0.245, 0.28, 0.21],
    );
    check3(&doc, &format!("{base}/color/rgb8"), [62.0, 71.0, 54.0]);
    // With N reversed, N·V > 0: the viewer is behind the surface in this reading.
    check_str(&doc, &format!("{base}/viewer/side"), "back");
}

#[test]
fn exercise_4_2_reading_with_the_light_vector_reversed_uses_every_term() {
    // L taken from the point to the light, the opposite of Eq. 4.1, is the light mirrored
    // through P: 2P − P_l = 2·(3,1,3) − (1,1,1) = (5,1,5), in front of the surface.
    let doc = solve("4.2.json");
    let base = &reading(&doc, "light_reversed");
    let mirrored = PointLight {
        position: [5.0, 1.0, 5.0],
        ..LIGHT_4_2
    };
    let s = shade(P_4_2, N_4_2, EYE_4_2, None, mirrored, M);
    check_light(&doc, base, 0, mirrored, &s);
    check_evaluation(&doc, base, &s);

    // Both cosines are now positive: cos θ = +1.4/√2, cos φ = +5.08/√44.
    let r2 = 2f64.sqrt();
    check(&doc, &format!("{base}/lights/0/cos_theta"), 1.4 / r2);
    check(
        &doc,
        &format!("{base}/lights/0/specular/cos_phi"),
        5.08 / 44f64.sqrt(),
    );
    check_str(&doc, &format!("{base}/lights/0/specular/status"), "lit");
    check_str(&doc, &format!("{base}/viewer/side"), "front");
    // With n_s = 1 (odd) every term is the negative of the literal Eq. 4.16 of the problem as
    // written, whose diffuse and specular parts are 0.35·O_d·(−1) and O_s·I_l·(−5.08/√44).
    let i_l = 1.0 / (2.0 * r2);
    let expected = add(scale(M.o_d, 0.35), scale(M.o_s, i_l * 5.08 / 44f64.sqrt()));
    check3(&doc, &format!("{base}/color/unclamped"), expected);
    let literal = vec3(&doc, "/solution/color/literal");
    same3(
        "minus the literal value as written",
        scale(literal, -1.0),
        expected,
    );
}

// ---------------------------------------------------------------------------------------------
// Exercise 4.3: ray from (8,4,6) along (4/5, 0, −3/5), plane through the origin with normal
// (1,1,1), material M, red ambient light, yellow point light at (0,0,5) without falloff,
// viewer at (0,10,0).
// ---------------------------------------------------------------------------------------------

const RAY_O: V3 = [8.0, 4.0, 6.0];
const RAY_D: V3 = [0.8, 0.0, -0.6];
const PLANE_N: V3 = [1.0, 1.0, 1.0];
const EYE_4_3: V3 = [0.0, 10.0, 0.0];
const RED: V3 = [1.0, 0.0, 0.0];
const LIGHT_4_3: PointLight = PointLight {
    position: [0.0, 0.0, 5.0],
    color: [1.0, 1.0, 0.0],
    falloff: 0,
};

/// The point where the ray's line meets the plane, by the independent implementation.
fn point_4_3() -> (f64, V3) {
    let d = normalize(RAY_D);
    let t = line_plane_t(RAY_O, d, [0.0; 3], PLANE_N);
    (t, add(RAY_O, scale(d, t)))
}

/// Closed forms of exercise 4.3: n·O = 18 and n·D = 0.2 give t = −90, P = (−64, 4, 60);
/// P − P_l = (−64, 4, 55), ‖·‖² = 7137; P − E = (−64, −6, 60), ‖·‖² = 7732.
#[test]
fn exercise_4_3_independent_calculation_matches_the_closed_forms() {
    let (t, p) = point_4_3();
    same("t", t, -90.0);
    same3("P", p, [-64.0, 4.0, 60.0]);

    let s = shade(p, PLANE_N, EYE_4_3, Some(RED), LIGHT_4_3, M);
    let r3 = 3f64.sqrt();
    let r7137 = 7137f64.sqrt();
    let r7732 = 7732f64.sqrt();
    // 3 · 7137 = 21411.
    let r21411 = 21411f64.sqrt();

    same3("N", s.n, [1.0 / r3; 3]);
    same("d", s.d, r7137);
    same3("L", s.l, [-64.0 / r7137, 4.0 / r7137, 55.0 / r7137]);
    same("falloff factor", s.falloff_factor, 1.0);
    same3("I_l", s.i_l, [1.0, 1.0, 0.0]);
    // N·L = (−64 + 4 + 55)/(√3 √7137).
    same("N·L", s.n_dot_l, -5.0 / r21411);
    same("cos θ", s.cos_theta, 5.0 / r21411);
    same3("ambient", s.ambient, [0.5, 0.0, 0.0]);
    let c = 5.0 / r21411;
    same3("diffuse", s.diffuse, [0.7 * c, 0.8 * c, 0.0]);
    // R = L + (10/√21411)(1,1,1)/√3 = ((−64, 4, 55) + (10/3)(1,1,1))/√7137.
    let k = 3.0 * r7137;
    same3("R", s.r, [-182.0 / k, 22.0 / k, 175.0 / k]);
    same3("V", s.v, [-64.0 / r7732, -6.0 / r7732, 60.0 / r7732]);
    // N·V = (−64 − 6 + 60)/(√3 √7732).
    same("N·V", s.n_dot_v, -10.0 / (r3 * r7732));
    // −R·V = −(11648 − 132 + 10500)/(3 √7137 √7732).
    let cos_phi = -22016.0 / (k * r7732);
    same("cos φ", s.cos_phi, cos_phi);
    same3(
        "specular, literal",
        s.specular_literal,
        [0.2 * cos_phi, 0.3 * cos_phi, 0.0],
    );
    same3("specular", s.specular, [0.0; 3]);
    same3("colour", s.unclamped, [0.5 + 0.7 * c, 0.8 * c, 0.0]);
    same3(
        "Eq. 4.16 literally",
        s.literal,
        [0.5 + 0.7 * c + 0.2 * cos_phi, 0.8 * c + 0.3 * cos_phi, 0.0],
    );
}

#[test]
fn exercise_4_3_ray_meets_the_plane_only_behind_its_origin() {
    let doc = solve("4.3.json");
    let (t, p) = point_4_3();

    assert_eq!(
        doc["solution"],
        Value::Null,
        "as written, the ray hits nothing"
    );
    for base in ["/intersection", "/readings/0/intersection"] {
        assert_eq!(at(&doc, &format!("{base}/hit")), false, "{base}/hit");
        check(&doc, &format!("{base}/t"), -90.0);
        check(&doc, &format!("{base}/t"), t);
        check3(&doc, &format!("{base}/point"), [-64.0, 4.0, 60.0]);
        check3(&doc, &format!("{base}/point"), p);
        check3(&doc, &format!("{base}/origin"), RAY_O);
        check3(&doc, &format!("{base}/direction_given"), RAY_D);
        check3(&doc, &format!("{base}/direction"), normalize(RAY_D));
        check_str(&doc, &format!("{base}/surface_type"), "plane");
        check(&doc, &format!("{base}/surface"), 0.0);
    }
    let f = finding(&doc, "hit_behind_origin");
    check(f, "/values/t", -90.0);
    let f = finding(&doc, "normal_normalized");
    check(f, "/values/length", 3f64.sqrt());
}

#[test]
fn exercise_4_3_reading_shades_the_point_where_the_line_meets_the_plane() {
    let doc = solve("4.3.json");
    let base = &reading(&doc, "line_behind_origin");
    let (_, p) = point_4_3();
    let s = shade(p, PLANE_N, EYE_4_3, Some(RED), LIGHT_4_3, M);

    // Hand-written closed forms, checked against the program directly.
    let r7137 = 7137f64.sqrt();
    let r21411 = 21411f64.sqrt();
    check3(&doc, &format!("{base}/point"), [-64.0, 4.0, 60.0]);
    check3(&doc, &format!("{base}/normal/n"), [1.0 / 3f64.sqrt(); 3]);
    check(&doc, &format!("{base}/normal/length"), 3f64.sqrt());
    check3(&doc, &format!("{base}/ambient/i_a"), RED);
    check3(&doc, &format!("{base}/ambient/term"), [0.5, 0.0, 0.0]);
    check3(
        &doc,
        &format!("{base}/lights/0/l"),
        [-64.0 / r7137, 4.0 / r7137, 55.0 / r7137],
    );
    check(&doc, &format!("{base}/lights/0/d"), r7137);
    check(&doc, &format!("{base}/lights/0/cos_theta"), 5.0 / r21411);
    let c = 5.0 / r21411;
    check3(
        &doc,
        &format!("{base}/lights/0/diffuse/term"),
        [0.7 * c, 0.8 * c, 0.0],
    );
    check3(
        &doc,
        &format!("{base}/color/unclamped"),
        [0.5 + 0.7 * c, 0.8 * c, 0.0],
    );

    // Every intermediate against the independent implementation.
    assert_eq!(at(&doc, &format!("{base}/normal/reversed")), false);
    check3(&doc, &format!("{base}/normal/given"), PLANE_N);
    check3(&doc, &format!("{base}/viewer/position"), EYE_4_3);
    check3(&doc, &format!("{base}/material/o_a"), M.o_a);
    check3(&doc, &format!("{base}/material/o_d"), M.o_d);
    check3(&doc, &format!("{base}/material/o_s"), M.o_s);
    check(&doc, &format!("{base}/material/n_s"), M.n_s);
    check3(&doc, &format!("{base}/ambient/term"), s.ambient);
    check_light(&doc, base, 1, LIGHT_4_3, &s);
    check_evaluation(&doc, base, &s);

    // The light is in front (cos θ > 0) but cos φ < 0: diffuse only, no specular.
    check_str(&doc, &format!("{base}/lights/0/status"), "lit");
    assert!(s.cos_theta > 0.0 && s.cos_phi < 0.0);
    check3(&doc, &format!("{base}/lights/0/specular/term"), [0.0; 3]);
    check3(&doc, &format!("{base}/totals/specular"), [0.0; 3]);
    // 255 · (0.5 + 0.7c, 0.8c, 0) with c = 5/√21411 ≈ 0.0342: (133.6…, 6.97…, 0).
    check3(&doc, &format!("{base}/color/rgb8"), [134.0, 7.0, 0.0]);
}

// ---------------------------------------------------------------------------------------------
// f32 against f64, on every exercise file.
// ---------------------------------------------------------------------------------------------

/// Bound on |f32 − f64| for a numeric leaf b (the f64 value): |a − b| ≤ F32_BOUND · max(1, |b|).
///
/// Why this bound: every input is rounded to f32 (unit roundoff u = 2⁻²⁴ ≈ 6e-8) and each
/// reported quantity is a short chain of at most a few dozen roundings. The quantities are unit
/// vectors, cosines and colours of order 1 or coordinates and distances of the scene's own size,
/// so the error is measured absolutely below 1 and relatively above. The worst conditioning in
/// these exercises is the cancellation in n·D (0.8 − 0.6) and in N·L for 4.3 (terms of ~0.4
/// summing to ~0.03); measured against max(1, |b|) it amplifies the error by well under 10.
/// That gives an expected error of a few tens of u at most, ~2e-6; 1e-5 (~170 u) leaves margin
/// while still catching any real loss of accuracy (an f32 path going wrong is off by ≫ 1e-5).
const F32_BOUND: f64 = 1e-5;

fn is_midpoint_of_rounding(x: f64) -> bool {
    // 255·c agrees between the precisions to 255·F32_BOUND; only within that of a half can
    // round() land on different integers.
    ((255.0 * x).fract() - 0.5).abs() <= 255.0 * F32_BOUND
}

fn compare(path: &str, single: &Value, double: &Value, problems: &mut Vec<String>) {
    match (single, double) {
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            let bound = if path.contains("/rgb8/") {
                // round(255·c): a difference of one step is allowed, and checked at the
                // parent object to happen only where 255·c is at a rounding midpoint.
                1.0
            } else {
                F32_BOUND * b.abs().max(1.0)
            };
            if !a.is_finite() || (a - b).abs() > bound {
                problems.push(format!("{path}: f32 {a:e}, f64 {b:e}"));
            }
        }
        (Value::Object(a), Value::Object(b)) => {
            let keys_a: Vec<_> = a.keys().collect();
            let keys_b: Vec<_> = b.keys().collect();
            if keys_a != keys_b {
                problems.push(format!("{path}: keys {keys_a:?} (f32) vs {keys_b:?} (f64)"));
                return;
            }
            if let (Some(Value::Array(ra)), Some(Value::Array(rb)), Some(clamped)) =
                (a.get("rgb8"), b.get("rgb8"), b.get("clamped"))
            {
                for (i, (x, y)) in ra.iter().zip(rb).enumerate() {
                    let c = clamped[i].as_f64().unwrap_or(f64::NAN);
                    if x != y && !is_midpoint_of_rounding(c) {
                        problems.push(format!(
                            "{path}/rgb8/{i}: f32 {x}, f64 {y}, but 255·c = {} is not at a \
                             rounding midpoint",
                            255.0 * c
                        ));
                    }
                }
            }
            for (key, va) in a {
                let child = format!("{path}/{key}");
                match key.as_str() {
                    // The precision's own name differs by design.
                    "precision" => {
                        if va != "f32" || b[key] != "f64" {
                            problems.push(format!("{child}: {va} (f32) vs {} (f64)", b[key]));
                        }
                    }
                    // Human text that prints numbers to the precision's own digits
                    // (−0.989949 in f64, −0.98995 in f32); the numbers themselves are compared
                    // through the findings' `values`.
                    "message" if va.is_string() && b[key].is_string() => {}
                    // A finding's bound on the rounding error is the precision's own.
                    "error_bound" | "error_bound_deg" => {}
                    _ => compare(&child, va, &b[key], problems),
                }
            }
        }
        (Value::Array(a), Value::Array(b)) => {
            if a.len() != b.len() {
                problems.push(format!(
                    "{path}: {} items (f32) vs {} (f64)",
                    a.len(),
                    b.len()
                ));
                return;
            }
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                compare(&format!("{path}/{i}"), x, y, problems);
            }
        }
        // Strings (codes, statuses), booleans and nulls are discrete outcomes: they must agree.
        (a, b) => {
            if a != b {
                problems.push(format!("{path}: {a} (f32) vs {b} (f64)"));
            }
        }
    }
}

#[test]
fn f32_agrees_with_f64_on_every_numeric_leaf_of_every_exercise() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("the exercises folder is readable")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    assert!(
        files.len() >= 3,
        "expected at least 4.1, 4.2 and 4.3 in {}",
        dir.display()
    );

    let mut problems = Vec::new();
    for file in &files {
        let mut single = solve_json(file, Precision::F32)
            .unwrap_or_else(|e| panic!("{} does not solve in f32: {e}", file.display()));
        // f32's own difference from f64 (issue 34) is f32's alone.
        let versus = single.as_object_mut().and_then(|o| o.remove("versus_f64"));
        assert!(versus.is_some(), "{}: no versus_f64 in f32", file.display());
        let double = solve_json(file, Precision::F64)
            .unwrap_or_else(|e| panic!("{} does not solve in f64: {e}", file.display()));
        let name = file.file_name().unwrap().to_string_lossy();
        compare(&name, &single, &double, &mut problems);
    }
    assert!(
        problems.is_empty(),
        "f32 and f64 disagree:\n{}",
        problems.join("\n")
    );
}

// several-lights.json: the literal (ungated) red channel of Eq. 4.16 is, by hand, the ambient
// 0.5·0.2 = 0.1; the key light at (0, 3, 4), L = (0, −3, −4)/5, cos θ = 0.8, diffuse 0.7·0.8 =
// 0.56, R = (0, −0.6, 0.8), V = (0, 3, −4)/5, cos φ = 1, specular 0.2; the blue and green lights
// add no red; the light under the floor at (0, 0, −1), L = (0, 0, 1), cos θ = −1, diffuse
// 0.7·(−1) = −0.7, R = (0, 0, −1), cos φ = −0.8, specular 0.2·(−0.8) = −0.16. Red: 0.1 + 0.56 +
// 0.2 − 0.7 − 0.16 = 0 exactly; green 0.64 + 0.3 + 0.8 + 0.24 − 0.8 − 0.24 = 0.94, blue 0.48 +
// 0.4 + 0.24 + 0.2 − 0.6 − 0.32 = 0.4. The sum's rounding (−2.8·10⁻¹⁷ in f64) is not a value:
// the JSON says 0 and the text prints no such number, in both precisions.
#[test]
fn a_literal_channel_that_cancels_is_zero_not_rounding_noise() {
    for precision in [Precision::F64, Precision::F32] {
        let doc = solve_json(&exercise("several-lights.json"), precision).expect("it solves");
        let literal = vec3(&doc, "/solution/color/literal");
        assert_eq!(literal[0], 0.0, "{precision:?}: {literal:?}");
        assert!(
            (literal[1] - 0.94).abs() < 1e-6,
            "{precision:?}: {literal:?}"
        );
        assert!(
            (literal[2] - 0.4).abs() < 1e-6,
            "{precision:?}: {literal:?}"
        );
    }
    let out = crate::support::phong_std()
        .args(["solve", "exercises/several-lights.json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("phong runs");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        text.contains("Eq. 4.16 taken literally (no gating): (0, 0.94, 0.4)"),
        "{text}"
    );
    assert!(!text.contains("e-1"), "{text}");
}
