//! Edge cases found in review: each test states the behaviour a user relies on. Expected values
//! are worked out in the comments.

use std::io::Write;

use phong::core::Precision;
use phong::report::file::solve_json;
use serde_json::{json, Value};

/// Solves a problem given as JSON, in one precision.
fn solve(problem: &Value, precision: Precision) -> Result<Value, String> {
    let mut file = tempfile::NamedTempFile::new().expect("a temporary file");
    file.write_all(problem.to_string().as_bytes())
        .expect("written");
    solve_json(file.path(), precision).map_err(|e| e.to_string())
}

fn codes(doc: &Value) -> Vec<String> {
    doc["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .map(|f| f["code"].as_str().expect("a code").to_owned())
        .collect()
}

fn material() -> Value {
    json!({ "ambient": [0.5, 0.4, 0.6], "diffuse": [0.7, 0.8, 0.6],
            "specular": [0.2, 0.3, 0.4], "shininess": 1 })
}

#[test]
fn literal_value_equals_the_colour_to_the_last_bit_when_nothing_is_gated() {
    // Six point lights, all in front of the surface, a diffuse-only material and no viewer:
    // nothing is gated, so Eq. 4.16 taken literally is the colour itself.
    let lights: Vec<Value> = (0..6)
        .map(|i| {
            let x = f64::from(i) * 0.7 - 2.0;
            json!({ "type": "point", "position": [x, 0.3 * x, 3.0 + x * x],
                    "color": [0.37, 0.51, 0.23], "falloff": 0 })
        })
        .collect();
    let problem = json!({
        "lights": lights,
        "point": { "position": [0.1, 0.2, 0], "normal": [0, 0, 1],
                   "material": { "diffuse": [0.7, 0.8, 0.6] } }
    });
    for precision in [Precision::F32, Precision::F64] {
        let doc = solve(&problem, precision).unwrap();
        let c = &doc["solution"]["color"];
        assert_eq!(c["literal"], c["unclamped"]);
        assert!(!codes(&doc).contains(&"literal_differs".to_owned()));
    }
}

#[test]
fn a_ray_that_starts_on_a_surface_and_leaves_it_is_not_a_hit_behind_its_origin() {
    // Origin on the plane z = 0, direction away from it: t = 0 only.
    let problem = json!({
        "materials": { "M": material() },
        "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
        "ray": { "origin": [1, 2, 0], "direction": [0, 0, 1] },
        "surfaces": [{ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "M" }]
    });
    let doc = solve(&problem, Precision::F64).unwrap();
    let found = codes(&doc);
    assert!(
        found.contains(&"ray_starts_on_surface".to_owned()),
        "{found:?}"
    );
    assert!(
        !found.contains(&"hit_behind_origin".to_owned()),
        "{found:?}"
    );
    assert_eq!(doc["solution"], Value::Null);
    assert_eq!(doc["readings"], json!([]));
}

#[test]
fn a_zero_degree_spot_is_decided_alike_in_f32_and_f64() {
    // Apex (0,0,4), axis (0,0,−1), γ = 0. P = (0.003,0,0) is at ψ = atan(0.003/4) ≈ 0.043°,
    // which f32's cos ψ cannot tell from 0° (1 − cos ψ ≈ 2.8e-7 ≈ 2.4 ulp); the angle test can.
    // P = (0,0,0) is on the axis, so exactly on the edge of a 0° cone: lit.
    for (x, status) in [(0.003, "outside_cone"), (0.0, "lit")] {
        let problem = json!({
            "materials": { "M": material() },
            "lights": [{ "type": "spot", "position": [0, 0, 4], "axis": [0, 0, -1], "angle": 0,
                         "exponent": 1, "color": [1, 1, 1], "falloff": 0 }],
            "point": { "position": [x, 0, 0], "normal": [0, 0, 1], "material": "M" }
        });
        for precision in [Precision::F32, Precision::F64] {
            let doc = solve(&problem, precision).unwrap();
            assert_eq!(
                doc["solution"]["lights"][0]["status"], status,
                "x = {x}, {precision:?}"
            );
        }
    }
}

#[test]
fn a_huge_shininess_with_the_viewer_behind_the_surface_solves() {
    // Viewer behind: cos φ < 0 and may round just below −1; (cos φ)^1e300 must not overflow.
    // The largest shininess each precision can hold: 1e300 in f64, 1e30 in f32.
    for (precision, n_s) in [(Precision::F32, 1e30), (Precision::F64, 1e300)] {
        let mut m = material();
        m["shininess"] = json!(n_s);
        let problem = json!({
            "materials": { "M": m },
            "lights": [{ "type": "point", "position": [0, 3, 4], "color": [1, 1, 1], "falloff": 0 }],
            "viewer": [0, -3, -4],
            "point": { "position": [0, 0, 0], "normal": [0, 0, 1], "material": "M" }
        });
        let doc = solve(&problem, precision).unwrap();
        // Diffuse only: cos θ = 0.8, O_d·0.8.
        let c = doc["solution"]["color"]["unclamped"].as_array().unwrap();
        let expected = [0.56, 0.64, 0.48];
        for (a, e) in c.iter().zip(expected) {
            assert!((a.as_f64().unwrap() - e).abs() < 1e-6);
        }
    }
}

#[test]
fn quadratic_falloff_divides_the_colour_so_a_huge_colour_far_away_stays_representable() {
    // C_l = 1e300 at d = 1e300, quadratic: I_l = 1e300/1e300/1e300 = 1e-300, not 0.
    let problem = json!({
        "lights": [{ "type": "point", "position": [0, 0, 1e300], "color": [1e300, 1e300, 1e300],
                     "falloff": 2 }],
        "point": { "position": [0, 0, 0], "normal": [0, 0, 1],
                   "material": { "diffuse": [1, 1, 1] } }
    });
    let doc = solve(&problem, Precision::F64).unwrap();
    let i_l = doc["solution"]["lights"][0]["i_l"][0].as_f64().unwrap();
    assert!((i_l / 1e-300 - 1.0).abs() < 1e-12, "I_l = {i_l}");
}

#[test]
fn a_sphere_too_small_for_its_coordinates_is_an_error_not_a_zero_normal() {
    // Radius 1 at x = 1e20, met by a ray along x: f64's spacing there is 16384, so the hit
    // point 1e20 − 1 rounds to the centre itself and the normal is undefined.
    let problem = json!({
        "materials": { "M": material() },
        "lights": [{ "type": "point", "position": [0, 5, 0], "color": [1, 1, 1], "falloff": 0 }],
        "ray": { "origin": [0, 0, 0], "direction": [1, 0, 0] },
        "surfaces": [{ "type": "sphere", "center": [1e20, 0, 0], "radius": 1, "material": "M" }]
    });
    let err = solve(&problem, Precision::F64).unwrap_err();
    assert!(err.contains("surfaces[0]"), "{err}");
    assert!(err.contains("rounding"), "{err}");
}

#[test]
fn a_viewer_without_a_normal_gets_no_side() {
    // Ambient light only: no normal is needed, so there is no side to tell.
    let problem = json!({
        "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
        "viewer": [0, 0, 5],
        "point": { "position": [0, 0, 0], "material": { "ambient": [0.5, 0.5, 0.5] } }
    });
    let doc = solve(&problem, Precision::F64).unwrap();
    assert_eq!(doc["solution"]["viewer"]["side"], Value::Null);
    assert!(
        codes(&doc).iter().all(|c| !c.starts_with("viewer_")),
        "{:?}",
        codes(&doc)
    );
}
