//! Ray problems whose numbers can be trusted (issue 18, deliverable 5): a hit that grazes its
//! plane reports how little of t and P the data determine, a ray lying in its plane is said to,
//! and a hit far from the origin keeps the digits of P − P_l. Every expected number is worked
//! out in the comments from the problem as written, by exact rational arithmetic.

use crate::support;

use std::io::Write;

use phong::core::Precision;
use phong::report::file::solve_json;
use serde_json::{json, Value};

/// Solves a problem given as JSON, in one precision.
fn solve(problem: &Value, precision: Precision) -> Value {
    let file = written(problem);
    solve_json(file.path(), precision).expect("solved")
}

/// The problem in a temporary file.
fn written(problem: &Value) -> tempfile::NamedTempFile {
    let mut file = tempfile::NamedTempFile::new().expect("a temporary file");
    file.write_all(problem.to_string().as_bytes())
        .expect("written");
    file
}

/// The codes of a solved problem's findings, in order.
fn codes(doc: &Value) -> Vec<&str> {
    doc["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .map(|f| f["code"].as_str().expect("a code"))
        .collect()
}

/// The values of the finding with `code`.
fn values<'a>(doc: &'a Value, code: &str) -> &'a Value {
    &doc["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .find(|f| f["code"] == code)
        .unwrap_or_else(|| panic!("no {code} in {}", doc["findings"]))["values"]
}

/// `phong solve FILE --format FORMAT --lang LANG`, its standard output with every run of white
/// space made one space.
fn phong_solve(file: &tempfile::NamedTempFile, format: &str, lang: &str) -> String {
    let out = support::phong_std()
        .arg("solve")
        .arg(file.path())
        .args(["--format", format, "--lang", lang])
        .output()
        .expect("phong runs");
    assert!(out.status.success(), "{out:?}");
    // Lines wrap where the layout chooses: compare words, not line breaks.
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number, not {v}"))
}

/// The grazing ray: the plane x + y + z = 0 (N = (1, 1, 1)), the ray from
/// O = (0.5, 0.5, −0.999999999999) along D = (1, −1, −1e-12), about 4e-13 rad from the plane.
fn grazing() -> Value {
    json!({
        "materials": { "M": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.7, 0.8, 0.6],
                              "specular": [0.5, 0.5, 0.5], "shininess": 10 } },
        "lights": [
            { "type": "ambient", "color": [1, 1, 1] },
            { "type": "point", "position": [1.5, -0.5, 0], "color": [1, 1, 1], "falloff": 2 }
        ],
        "ray": { "origin": [0.5, 0.5, -0.999999999999], "direction": [1, -1, -1e-12] },
        "surfaces": [ { "type": "plane", "point": [0, 0, 0], "normal": [1, 1, 1], "material": "M" } ]
    })
}

#[test]
fn a_ray_grazing_its_plane_reports_bounds_that_hold_the_exact_hit() {
    // The exact hit, for the numbers as written (Python, fractions.Fraction):
    //   from fractions import Fraction as F
    //   O = [F(1, 2), F(1, 2), F("-0.999999999999")]; D = [F(1), F(-1), F("-1e-12")]
    //   a = -sum(O)            # N·(Q − O) with N = (1, 1, 1): -1e-12
    //   b = sum(D)             # N·D: -1e-12
    //   s = a / b              # 1: the hit is O + 1·D
    //   [o + s * d for o, d in zip(O, D)]   # [3/2, -1/2, -1]
    // t along the unit direction is s·‖D‖ = √(2 + 1e-24) = √2 (1 + 2.5e-25): √2 in f64.
    // The rounding of −0.999999999999 alone (up to 2⁻⁵⁴ ≈ 5.6e-17) moves N·(Q − O), which is
    // only 1e-12, by up to 5.6e-5 of itself: t and P lose that much, whatever the arithmetic.
    let doc = solve(&grazing(), Precision::F64);
    let exact_t = 2f64.sqrt();
    let exact_p = [1.5, -0.5, -1.0];
    let x = &doc["intersection"];
    let t = f(&x["t"]);
    let v = values(&doc, "hit_ill_conditioned");
    assert_eq!(f(&v["t"]), t);
    // The loss is real: far beyond what a well-conditioned hit loses (a few 1e-16) ...
    assert!((t - exact_t).abs() > 1e-6 * exact_t, "t = {t}");
    // ... and within the bound the report gives, on t and on every coordinate of P.
    let t_bound = f(&v["t_error_bound"]);
    assert!((t - exact_t).abs() <= t_bound, "|{t} − √2| > {t_bound}");
    assert!(t_bound < 1e-2 * exact_t, "a useful bound: {t_bound}");
    for i in 0..3 {
        let p = f(&x["point"][i]);
        let bound = f(&v["p_error_bound"][i]);
        assert!(
            (p - exact_p[i]).abs() <= bound,
            "P[{i}] = {p}, exact {}, bound {bound}",
            exact_p[i]
        );
    }
    // N·D = −1e-12/(√3·√2·(1 + 5e-25)) = −4.0824829e-13, and its bound is far below it.
    let n_dot_d = f(&v["n_dot_d"]);
    assert!((n_dot_d + 1e-12 / 6f64.sqrt()).abs() < 1e-20, "{n_dot_d}");
    assert!(f(&v["n_dot_d_error"]) < 1e-2 * n_dot_d.abs());
}

#[test]
fn the_ill_conditioned_hit_is_worded_in_every_format_and_both_languages() {
    let file = written(&grazing());
    for format in ["text", "markdown", "latex", "html"] {
        let en = phong_solve(&file, format, "en");
        assert!(en.contains("ill-conditioned"), "{format}: {en}");
        assert!(en.contains("last digits of the data"), "{format}: {en}");
        let pt = phong_solve(&file, format, "pt");
        assert!(pt.contains("mal condicionada"), "{format}: {pt}");
        assert!(
            pt.contains("últimos algarismos dos dados"),
            "{format}: {pt}"
        );
    }
    let doc: Value = serde_json::from_str(&phong_solve(&file, "json", "en")).expect("JSON");
    let v = values(&doc, "hit_ill_conditioned");
    let mut keys: Vec<&str> = v
        .as_object()
        .expect("values")
        .keys()
        .map(|k| &**k)
        .collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        [
            "n_dot_d",
            "n_dot_d_error",
            "p_error_bound",
            "t",
            "t_error_bound"
        ]
    );
}

#[test]
fn a_ray_a_thousandth_of_a_radian_from_its_plane_is_reported_in_f32_only() {
    // N = (1, 1, 1), O = (0.5, 0.5, −0.999), D = (1, −1, −0.002): N·(Q − O) = −0.001,
    // N·D = −0.002, so the hit is O + D/2 = (1, 0, −1), about 8e-4 rad from the plane. f64
    // keeps 12 of its 16 digits there (nothing to report at the six the reports print); f32
    // keeps about 3 of its 7.
    let mut problem = grazing();
    problem["ray"] = json!({ "origin": [0.5, 0.5, -0.999], "direction": [1, -1, -0.002] });
    let f64_doc = solve(&problem, Precision::F64);
    assert!(
        !codes(&f64_doc).contains(&"hit_ill_conditioned"),
        "{f64_doc}"
    );
    let f32_doc = solve(&problem, Precision::F32);
    let v = values(&f32_doc, "hit_ill_conditioned");
    let t = f(&f32_doc["intersection"]["t"]);
    let exact_t = (2.0f64 + 4e-6).sqrt() / 2.0; // ‖D‖/2
    assert!(
        (t - exact_t).abs() <= f(&v["t_error_bound"]),
        "t = {t}, {v}"
    );
}

#[test]
fn a_grazing_ray_on_an_axis_aligned_plane_loses_nothing_and_is_not_reported() {
    // The floor y = 0, the ray from (0, 1e-12, 0) along (1, −1e-12, 0): N·D = D_y and
    // N·(Q − O) = −O_y, each one rounding from the numbers as written, so t = 1 and
    // P = (1, 0, 0) to within a few ulps however close to the plane the ray runs.
    let problem = json!({
        "materials": { "M": { "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1 } },
        "lights": [ { "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1] } ],
        "ray": { "origin": [0, 1e-12, 0], "direction": [1, -1e-12, 0] },
        "surfaces": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "M" } ]
    });
    for precision in [Precision::F32, Precision::F64] {
        let doc = solve(&problem, precision);
        assert!(!codes(&doc).contains(&"hit_ill_conditioned"), "{doc}");
        let x = f(&doc["intersection"]["point"][0]);
        assert!((x - 1.0).abs() < 1e-6, "{doc}");
    }
}

#[test]
fn a_ray_parallel_to_its_plane_to_within_rounding_is_reported() {
    // N = (1, 2, 3), D = (0.7, 0.1, −0.3): N·D = 0.7 + 0.2 − 0.9 = 0 exactly for the numbers as
    // written (Fraction("0.7") + 2*Fraction("0.1") - 3*Fraction("0.3") == 0), so the line from
    // (0, 0, 1) never meets the plane through the origin; rounded, N·D comes out about 1e-17,
    // and t about 1e16. That hit is no answer: the report says so.
    let problem = json!({
        "materials": { "M": { "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1 } },
        "lights": [ { "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] } ],
        "ray": { "origin": [0, 0, 1], "direction": [0.7, 0.1, -0.3] },
        "surfaces": [ { "type": "plane", "point": [0, 0, 0], "normal": [1, 2, 3], "material": "M" } ]
    });
    let doc = solve(&problem, Precision::F64);
    let v = values(&doc, "parallel_within_rounding");
    assert!(f(&v["n_dot_d"]).abs() <= f(&v["n_dot_d_error"]), "{v}");
    assert_eq!(v["may_lie_in_plane"], false);
    let file = written(&problem);
    assert!(phong_solve(&file, "text", "en").contains("the ray may be parallel to the plane"));
    assert!(phong_solve(&file, "text", "pt").contains("o raio pode ser paralelo ao plano"));
}

#[test]
fn a_ray_lying_in_its_plane_meets_it_everywhere_not_nowhere() {
    // The plane x + y + z = 0 holds O = (1, −1, 0) and D = (1, −1, 0): N·D = 0 and
    // N·(Q − O) = 0, so every point of the ray is on it. A sphere far away comes first in the
    // file, so the plane is surfaces[1].
    let problem = json!({
        "materials": { "M": { "diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1 } },
        "lights": [ { "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] } ],
        "ray": { "origin": [1, -1, 0], "direction": [1, -1, 0] },
        "surfaces": [
            { "type": "sphere", "center": [0, 0, 50], "radius": 1, "material": "M" },
            { "type": "plane", "point": [0, 0, 0], "normal": [1, 1, 1], "material": "M" }
        ]
    });
    for precision in [Precision::F32, Precision::F64] {
        let doc = solve(&problem, precision);
        let found = codes(&doc);
        assert!(found.contains(&"ray_in_plane"), "{found:?}");
        assert!(!found.contains(&"no_intersection"), "{found:?}");
        assert_eq!(values(&doc, "ray_in_plane")["surface"], 1);
        assert_eq!(doc["intersection"]["lies_in_surface"], 1);
        assert_eq!(doc["intersection"]["point"], Value::Null);
    }
    let file = written(&problem);
    let en = phong_solve(&file, "text", "en");
    assert!(
        en.contains("every point of it is on the surface, so the problem has no single hit"),
        "{en}"
    );
    let pt = phong_solve(&file, "text", "pt");
    assert!(
        pt.contains("todos os seus pontos estão na superfície, então o problema não tem um único"),
        "{pt}"
    );
    assert!(!en.contains("meets no surface"), "{en}");

    // Moved off the plane, the same ray is parallel to it and meets nothing: said as before.
    let mut off = problem.clone();
    off["ray"]["origin"] = json!([1, -1, 0.5]);
    let doc = solve(&off, Precision::F64);
    assert!(codes(&doc).contains(&"no_intersection"), "{doc}");
    assert!(doc["intersection"].get("lies_in_surface").is_none());
}

#[test]
fn far_from_the_origin_the_light_vector_keeps_its_digits() {
    // Everything 1e12 from the origin, the numbers exact in f64 (1e12 + 1 < 2⁵³): the floor
    // z = 0, the ray from O = (1e12, 1e12, 1) along D = (1, 2, −3), a light at
    // (1e12 + 1, 1e12 + 1, 1) with quadratic falloff, diffuse and specular white, n_s = 50.
    // Exactly (fractions.Fraction, then one square root):
    //   t = ‖D‖/3, P = O + D/3 = (1e12 + 1/3, 1e12 + 2/3, 0), not a number of f64: P rounds
    //   by up to 2⁻¹⁴ ≈ 6e-5, and P − P_l computed from it would lose that much of its 1.2.
    //   P − P_l = (O − P_l) + D/3 = (−2/3, −1/3, −1), d = √14/3, L = (−2, −1, −3)/√14,
    //   1/d² = 9/14, cos θ = 3/√14, R = (−2, −1, 3)/√14, V = (1, 2, −3)/√14, cos φ = 13/14,
    //   I = 9/14 · (3/√14 + (13/14)^50).
    let problem = json!({
        "materials": { "M": { "diffuse": [1, 1, 1], "specular": [1, 1, 1], "shininess": 50 } },
        "lights": [ { "type": "point", "position": [1000000000001i64, 1000000000001i64, 1],
                      "color": [1, 1, 1], "falloff": 2 } ],
        "ray": { "origin": [1000000000000i64, 1000000000000i64, 1], "direction": [1, 2, -3] },
        "surfaces": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "M" } ]
    });
    let doc = solve(&problem, Precision::F64);
    let light = &doc["solution"]["lights"][0];
    let s14 = 14f64.sqrt();
    let exact_l = [-2.0 / s14, -1.0 / s14, -3.0 / s14];
    for (i, exact) in exact_l.iter().enumerate() {
        let l = f(&light["l"][i]);
        assert!(
            (l - exact).abs() <= 4.0 * f64::EPSILON,
            "L[{i}] = {l}, exact {exact}"
        );
    }
    let d = f(&light["d"]);
    assert!((d - s14 / 3.0).abs() <= 4.0 * f64::EPSILON * d, "d = {d}");
    let exact = 9.0 / 14.0 * (3.0 / s14 + (13.0f64 / 14.0).powi(50));
    for c in doc["solution"]["color"]["unclamped"]
        .as_array()
        .expect("RGB")
    {
        let c = f(c);
        assert!(
            (c - exact).abs() <= 16.0 * f64::EPSILON * exact,
            "I = {c}, exact {exact}"
        );
    }
    // Said, with the bound on P's own rounding and what it would have cost L.
    let v = values(&doc, "hit_far_from_origin");
    assert!(f(&v["direction_error"]) > 1e-5, "{v}");
    let file = written(&problem);
    assert!(phong_solve(&file, "text", "en").contains("(O − P_l) + tD"));
    assert!(phong_solve(&file, "text", "pt").contains("preserva os seus algarismos"));
    // An ordinary ray problem is shaded in its own coordinates, as the tracer shades the same
    // ray, and says nothing of it.
    let ordinary = serde_json::from_str::<Value>(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/exercises/sphere-hit.json"
        ))
        .expect("the exercise"),
    )
    .expect("JSON");
    assert!(!codes(&solve(&ordinary, Precision::F64)).contains(&"hit_far_from_origin"));
    // P itself is shown as computed, in the problem's coordinates.
    let p = f(&doc["intersection"]["point"][0]);
    assert!((p - (1e12 + 1.0 / 3.0)).abs() <= 1.3e-4, "P_x = {p}");
}

/// The largest difference between the f32 and the f64 colour (unclamped, every channel) of a
/// solved problem and of each of its readings.
fn f32_against_f64(problem: &Value) -> f64 {
    let colours = |doc: &Value| -> Vec<Vec<f64>> {
        let mut out = Vec::new();
        let mut add = |s: &Value| {
            if let Some(c) = s["color"]["unclamped"].as_array() {
                out.push(c.iter().map(f).collect());
            }
        };
        add(&doc["solution"]);
        for r in doc["readings"].as_array().into_iter().flatten() {
            add(&r["solution"]);
        }
        out
    };
    let (a, b) = (
        colours(&solve(problem, Precision::F32)),
        colours(&solve(problem, Precision::F64)),
    );
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(&b)
        .flat_map(|(x, y)| x.iter().zip(y).map(|(p, q)| (p - q).abs()))
        .fold(0.0, f64::max)
}

/// Whether f32 reports a gate it cannot decide (`gate_undecidable`, `light_on_cone_edge`,
/// `cone_edge_undecidable`): there a light's term may be in one precision and not the other.
fn f32_reports_a_gate(problem: &Value) -> bool {
    codes(&solve(problem, Precision::F32)).iter().any(|c| {
        matches!(
            *c,
            "gate_undecidable" | "light_on_cone_edge" | "cone_edge_undecidable"
        )
    })
}

/// A grazing directional light on the plane through the origin with normal (1, 1, 1): it
/// travels along (1, −1, −k), so cos θ = k/√(3(2 + k²)) ≈ k/√6, seen by a viewer near its
/// mirror direction, at P + 5(L + 0.01N̂), where (cos φ)^10 ≈ 0.9995: the specular term
/// O_s I_l (cos φ)^n_s is nearly the whole O_s = 0.2.
fn grazing_light(k: f64) -> Value {
    let norm = (2.0 + k * k).sqrt();
    let l = [1.0 / norm, -1.0 / norm, -k / norm];
    let n = 1.0 / 3f64.sqrt();
    let viewer: Vec<f64> = l.iter().map(|li| 5.0 * (li + 0.01 * n)).collect();
    json!({
        "point": { "position": [0, 0, 0], "normal": [1, 1, 1],
                   "material": { "diffuse": [0.5, 0.5, 0.5], "specular": [0.2, 0.2, 0.2],
                                 "shininess": 10 } },
        "lights": [ { "type": "directional", "direction": [1, -1, -k], "color": [1, 1, 1] } ],
        "viewer": viewer
    })
}

/// The bound docs/accuracy.md and the README state for f32 against f64 where f32 decides
/// every gate (reports none of them), on the bundled exercises and on the grazing sweep: the
/// worst measured are 1.80e-7 (spot-inside.json) and 1.53e-7 (k = 1e-2).
const F32_DECIDED: f64 = 1.9e-7;

#[test]
fn f32_against_f64_holds_its_documented_bound_where_f32_decides_every_gate() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut worst = 0.0f64;
    for dir in ["exercises", "scenes"] {
        for entry in std::fs::read_dir(root.join(dir)).expect("a folder") {
            let path = entry.expect("an entry").path();
            let Ok(text) = std::fs::read_to_string(&path) else {
                continue;
            };
            let Ok(problem) = serde_json::from_str::<Value>(&text) else {
                continue;
            };
            // Scenes are images (README, "f32 against f64" of `phong tradeoff`); a ray or a
            // point is solved.
            if problem.get("camera").is_some() || path.extension() != Some("json".as_ref()) {
                continue;
            }
            if f32_reports_a_gate(&problem) {
                continue;
            }
            let d = f32_against_f64(&problem);
            println!("{}: {d:.3e}", path.display());
            assert!(d <= F32_DECIDED, "{}: {d}", path.display());
            worst = worst.max(d);
        }
    }
    println!("bundled: worst {worst:.3e}");
    // The sweep: k from 1e-1 to 1e-12, cos θ from 4e-2 to 4e-13.
    let mut decided_worst = 0.0f64;
    let mut reported_worst = 0.0f64;
    for e in 1..=24 {
        let k = 10f64.powf(-f64::from(e) / 2.0);
        let problem = grazing_light(k);
        let d = f32_against_f64(&problem);
        let reported = f32_reports_a_gate(&problem);
        println!("k = {k:.1e}: f32 − f64 = {d:.3e}, f32 reports a gate: {reported}");
        if reported {
            reported_worst = reported_worst.max(d);
        } else {
            assert!(d <= F32_DECIDED, "k = {k}: {d}");
            decided_worst = decided_worst.max(d);
        }
    }
    println!("sweep: decided worst {decided_worst:.3e}, reported worst {reported_worst:.3e}");
}

#[test]
fn a_grazing_light_near_its_mirror_direction_loses_its_whole_specular_term_in_f32() {
    // k = 3e-6: cos θ = 3e-6/√(3(2 + 9e-12)) = 1.2247e-6, above f64's tangent tolerance
    // (about 1e-15 here) and below f32's (γ₄₀·Σ|N_i L_i| = 40·2⁻²⁴/(1 − 40·2⁻²⁴)·(2/√6) ≈
    // 1.95e-6). f64 lights the point: diffuse 0.5·cos θ = 6.1e-7, specular
    // 0.2·(cos φ)^10 with cos φ = −R·V ≈ 0.99995: 0.1999. f32 counts the light as in the tangent
    // plane and says so (gate_undecidable): both terms are dropped, 0.1999 of the colour, 51 of
    // 255, far beyond the 1.9e-7 of f32 where it decides every gate.
    let problem = grazing_light(3e-6);
    let f64_doc = solve(&problem, Precision::F64);
    assert_eq!(f64_doc["solution"]["lights"][0]["status"], "lit");
    let f32_doc = solve(&problem, Precision::F32);
    assert_eq!(
        f32_doc["solution"]["lights"][0]["status"],
        "in_tangent_plane"
    );
    assert!(codes(&f32_doc).contains(&"gate_undecidable"));
    let d = f32_against_f64(&problem);
    assert!(d > 0.19 && d < 0.2, "f32 − f64 = {d}");
    assert!(d > 1e6 * F32_DECIDED);
    // What f64 adds is the light's whole specular term, plus O_d I_l cos θ.
    let cos_theta = 3e-6 / (3.0 * (2.0 + 9e-12f64)).sqrt();
    let spec = f(&f64_doc["solution"]["lights"][0]["specular"]["term"][0]);
    assert!((d - spec - 0.5 * cos_theta).abs() < 1e-7, "{d} vs {spec}");
}
