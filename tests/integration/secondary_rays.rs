//! `phong solve` on a ray problem shows the hit's secondary rays (Section 4.4): the reflection
//! ray R_V = V − 2(N·V)N (Eq. 4.17) and the transmitted ray by Snell's law, each with its level,
//! its weight and whether it is traced under the problem's maximum level and minimum weight;
//! and `phong check --step` judges them. Every expected number is worked by hand in the
//! comments, never taken from the program's output.

use crate::support;

use std::path::Path;

use phong::core::Precision;
use phong::report::file::solve_json;
use serde_json::Value;

const EXERCISE: &str = "exercises/secondary-rays.json";

/// The vector at `v`, as three numbers.
fn v3(v: &Value) -> [f64; 3] {
    let a = v.as_array().expect("a triple");
    [0, 1, 2].map(|i| a[i].as_f64().expect("a number"))
}

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= 1e-14, "{what}: {a} is not {b}");
}

fn close3(a: [f64; 3], b: [f64; 3], what: &str) {
    for i in 0..3 {
        close(a[i], b[i], what);
    }
}

/// A problem with one plane z = 0 (normal (0, 0, 1)) of a material with O_r, O_t and η = 1.5, a
/// ray from `origin` along `direction`, and the render settings.
fn plane_problem(origin: [f64; 3], direction: [f64; 3], max_level: u32, min_weight: f64) -> String {
    format!(
        r#"{{
  "materials": {{ "G": {{ "ambient": [0.2, 0.2, 0.2], "reflectivity": [0.3, 0.2, 0.1],
                         "transmissivity": [0.5, 0.6, 0.7], "ior": 1.5 }} }},
  "lights": [ {{ "type": "ambient", "color": [1, 1, 1] }} ],
  "ray": {{ "origin": {origin:?}, "direction": {direction:?} }},
  "surfaces": [ {{ "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "G" }} ],
  "render": {{ "max_level": {max_level}, "min_weight": {min_weight:?} }}
}}"#
    )
}

/// The JSON solution of a problem given as text.
fn solve_text(text: &str) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.json");
    std::fs::write(&path, text).unwrap();
    solve_json(&path, Precision::F64).expect("the problem solves")
}

#[test]
fn a_ray_at_45_degrees_onto_glass_reflects_and_refracts_as_worked_by_hand() {
    let doc = solve_json(Path::new(EXERCISE), Precision::F64).unwrap();
    let s = &doc["secondary_rays"];
    let h = std::f64::consts::FRAC_1_SQRT_2; // 1/√2
                                             // D = (1, 0, −1)/√2 from (−2, 0, 2) meets z = 0 at t = 2√2, at the origin. N = (0, 0, 1)
                                             // faces the ray (N·D = −1/√2 < 0), V = D.
    close3(v3(&s["v"]), [h, 0.0, -h], "V");
    close3(v3(&s["n"]), [0.0, 0.0, 1.0], "N");
    close(s["n_dot_v"].as_f64().unwrap(), -h, "N·V");
    assert_eq!(s["level"], 1);
    assert_eq!(s["max_level"], 2);
    // R_V = V − 2(N·V)N = (1/√2, 0, −1/√2) − 2(−1/√2)(0, 0, 1) = (1/√2, 0, 1/√2).
    let r = &s["reflection"];
    close3(v3(&r["direction"]), [h, 0.0, h], "R_V");
    assert_eq!(r["level"], 2);
    // w_s = 1·max(0.1, 0.05, 0.08) = 0.1, which is not > the minimum weight 0.1: not traced.
    assert_eq!(r["weight"].as_f64().unwrap(), 0.1);
    assert_eq!(r["traced"], false);
    assert_eq!(r["stop"], "min_weight");
    // Snell: the ray meets the plane against its own normal, so it enters: η_i = 1, η_t = 1.5,
    // η_r = 2/3; cos θ_i = −N·V = 1/√2; sin²θ_i = 1/2, so k = 1 − (4/9)(1/2) = 7/9.
    // T = η_r V + (η_r cos θ_i − √k) N = (2/3)(1/√2, 0, −1/√2) + ((2/3)/√2 − √7/3)(0, 0, 1)
    //   = (√2/3, 0, −√7/3): sin θ_t = √2/3 = sin 45°/1.5, and |T|² = 2/9 + 7/9 = 1.
    let t = &s["transmission"];
    assert_eq!(t["entering"], true);
    assert_eq!(t["eta_i"].as_f64().unwrap(), 1.0);
    assert_eq!(t["eta_t"].as_f64().unwrap(), 1.5);
    close(t["cos_i"].as_f64().unwrap(), h, "cos θ_i");
    close(t["k"].as_f64().unwrap(), 7.0 / 9.0, "k");
    let root2: f64 = 2.0;
    let root7: f64 = 7.0;
    close3(
        v3(&t["direction"]),
        [root2.sqrt() / 3.0, 0.0, -root7.sqrt() / 3.0],
        "T",
    );
    // w_t = max(0.5, 0.6, 0.7) = 0.7 > 0.1, level 2 ≤ 2: traced.
    assert_eq!(t["weight"].as_f64().unwrap(), 0.7);
    assert_eq!(t["level"], 2);
    assert_eq!(t["traced"], true);
    assert_eq!(t["stop"], Value::Null);
    assert_eq!(t["total_internal_reflection"], false);
    // The material's O_t and η, beside its O_r.
    let m = &doc["solution"]["material"];
    close3(v3(&m["o_t"]), [0.5, 0.6, 0.7], "O_t");
    assert_eq!(m["ior"].as_f64().unwrap(), 1.5);
}

#[test]
fn leaving_glass_bends_away_from_the_normal_and_beyond_the_critical_angle_nothing_transmits() {
    // From below (inside the glass, against N = (0, 0, 1)'s side) along (1/2, 0, √3/2): θ_i =
    // 30°, the ray meets the plane along its own normal, so it leaves: η_i = 1.5, η_t = 1,
    // η_r = 3/2. N facing the ray is (0, 0, −1); cos θ_i = √3/2; k = 1 − (9/4)(1/4) = 7/16.
    // T = (3/2)(1/2, 0, √3/2) + ((3/2)(√3/2) − √7/4)(0, 0, −1) = (3/4, 0, √7/4):
    // sin θ_t = 3/4 = 1.5·sin 30°.
    let s3: f64 = 3.0;
    let d = [0.5, 0.0, s3.sqrt() / 2.0];
    let doc = solve_text(&plane_problem([-0.5, 0.0, -d[2]], d, 2, 0.1));
    let t = &doc["secondary_rays"]["transmission"];
    assert_eq!(t["entering"], false);
    assert_eq!(t["eta_i"].as_f64().unwrap(), 1.5);
    assert_eq!(t["eta_t"].as_f64().unwrap(), 1.0);
    close(t["k"].as_f64().unwrap(), 7.0 / 16.0, "k");
    let s7: f64 = 7.0;
    let got = v3(&t["direction"]);
    for (a, b) in got.iter().zip([0.75, 0.0, s7.sqrt() / 4.0]) {
        assert!((a - b).abs() < 1e-15, "T = {got:?}");
    }
    assert_eq!(t["traced"], true);

    // At 45° from inside: sin θ_i = 1/√2 > 1/1.5 (the critical angle is asin(2/3) ≈ 41.8°):
    // k = 1 − (9/4)(1/2) = −1/8 < 0, total internal reflection: no transmitted direction, not
    // traced, and the reflection ray is still there (from O_r, w_s = 0.3 > 0.1).
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let doc = solve_text(&plane_problem([-1.0, 0.0, -1.0], [h, 0.0, h], 2, 0.1));
    let s = &doc["secondary_rays"];
    let t = &s["transmission"];
    close(t["k"].as_f64().unwrap(), -0.125, "k");
    assert_eq!(t["direction"], Value::Null);
    assert_eq!(t["total_internal_reflection"], true);
    assert_eq!(t["traced"], false);
    assert_eq!(t["stop"], "total_internal_reflection");
    // R_V = V − 2(N·V)N with N = (0, 0, −1), N·V = −1/√2: (1/√2, 0, 1/√2) − √2(0, 0, 1)
    // = (1/√2, 0, −1/√2), back down into the glass.
    let r = &s["reflection"];
    close3(v3(&r["direction"]), [h, 0.0, -h], "R_V");
    assert_eq!(r["weight"].as_f64().unwrap(), 0.3);
    assert_eq!(r["traced"], true);
}

#[test]
fn a_maximum_level_of_1_traces_no_child_and_says_why() {
    // The primary ray has level 1; its children would have level 2 > 1.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let doc = solve_text(&plane_problem([-1.0, 0.0, 1.0], [h, 0.0, -h], 1, 0.1));
    let s = &doc["secondary_rays"];
    for child in ["reflection", "transmission"] {
        assert_eq!(s[child]["traced"], false, "{child}");
        assert_eq!(s[child]["stop"], "max_level", "{child}");
    }
}

#[test]
fn a_ray_through_a_glass_spheres_centre_passes_undeviated() {
    // Along −z through the centre: N = (0, 0, 1) at the hit (0, 0, 1), cos θ_i = 1, k = 1,
    // T = η_r V + (η_r − 1) N = (0, 0, −2/3) + (−1/3)(0, 0, 1) = (0, 0, −1) = D.
    let text = r#"{
  "materials": { "G": { "ambient": [0.2, 0.2, 0.2], "transmissivity": [0.9, 0.9, 0.9], "ior": 1.5 } },
  "lights": [ { "type": "ambient", "color": [1, 1, 1] } ],
  "ray": { "origin": [0, 0, 5], "direction": [0, 0, -1] },
  "surfaces": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "G" } ]
}"#;
    let doc = solve_text(text);
    let s = &doc["secondary_rays"];
    assert_eq!(s["reflection"], Value::Null, "no O_r, no reflection ray");
    let t = &s["transmission"];
    close(t["cos_i"].as_f64().unwrap(), 1.0, "cos θ_i");
    close(t["k"].as_f64().unwrap(), 1.0, "k");
    close3(v3(&t["direction"]), [0.0, 0.0, -1.0], "T");
}

#[test]
fn an_opaque_matte_surface_has_no_secondary_rays_and_its_json_is_unchanged() {
    // sphere-hit.json's material has neither O_r nor O_t.
    let doc = solve_json(Path::new("exercises/sphere-hit.json"), Precision::F64).unwrap();
    assert!(doc.get("secondary_rays").is_none());
    assert!(doc["solution"]["material"].get("o_t").is_none());
    let text =
        phong::report::file::solve_text(Path::new("exercises/sphere-hit.json"), Precision::F64)
            .unwrap();
    assert!(!text.contains("Secondary rays"));
}

#[test]
fn the_text_says_each_rule_and_that_the_solver_does_not_trace() {
    let out = support::phong().args(["solve", EXERCISE]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let after = text
        .split("Secondary rays (Section 4.4)")
        .nth(1)
        .expect("the block");
    assert!(after.contains("R_V = V − 2(N·V)N = (0.707107, 0, 0.707107)"));
    assert!(after.contains("not traced: weight 0.1 ≤ the minimum weight 0.1"));
    assert!(after.contains("T = η_r V + (η_r cos θ_i − √k) N = (0.471405, 0, -0.881917)"));
    assert!(after.contains("traced: level 2 ≤ 2 and weight 0.7 > 0.1"));
    assert!(after.contains("does not trace them"));
    let out = support::phong()
        .args(["solve", EXERCISE, "--lang", "pt"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let after = text
        .split("Raios secundários (Seção 4.4)")
        .nth(1)
        .expect("o bloco");
    assert!(after.contains("Raio de reflexão: R_V"));
    assert!(after.contains("não é traçado: peso 0.1 ≤ o peso mínimo 0.1"));
    assert!(after.contains("o raio entra no material"));
    assert!(after.contains("não os traça"));
}

#[test]
fn the_handouts_data_give_o_t_the_index_and_the_render_settings() {
    for (lang, material, settings) in [
        (
            "en",
            "O_t = (0.5, 0.6, 0.7), η = 1.5",
            "Render settings: maximum level 2, minimum weight 0.1",
        ),
        (
            "pt",
            "O_t = (0.5, 0.6, 0.7), η = 1.5",
            "Parâmetros do traçado: nível máximo 2, peso mínimo 0.1",
        ),
    ] {
        let out = support::phong()
            .args(["solve", EXERCISE, "--part", "statement", "--lang", lang])
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains(material) && text.contains(settings), "{text}");
    }
}

/// `phong check EXERCISE --step …` with `args`, its exit code and its JSON.
fn check(args: &[&str]) -> (i32, Value) {
    let mut all = vec!["check", EXERCISE, "--format", "json"];
    for a in args {
        all.extend(["--step", a]);
    }
    let out = support::phong().args(&all).output().unwrap();
    let code = out.status.code().unwrap();
    (code, serde_json::from_slice(&out.stdout).expect("JSON"))
}

fn verdicts(doc: &Value) -> Vec<(String, String)> {
    doc["steps"]["steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["name"].as_str().unwrap().to_owned(),
                s["verdict"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

#[test]
fn right_steps_of_the_secondary_rays_are_accepted() {
    // The hand values above, at four digits: R_V = (0.7071, 0, 0.7071), w_s = 0.1, not traced;
    // cos θ_i = 0.7071, k = 7/9, T = (0.4714, 0, −0.8819), w_t = 0.7, traced.
    let (code, doc) = check(&[
        "r_v=0.7071,0,0.7071",
        "reflection_weight=0.1",
        "reflection_traced=no",
        "cos_theta_i=0.7071",
        "k=7/9",
        "t_direction=0.4714,0,-0.8819",
        "transmission_weight=0.7",
        "transmission_traced=sim",
    ]);
    assert_eq!(code, 0, "{doc}");
    assert!(verdicts(&doc).iter().all(|(_, v)| v == "right"), "{doc}");
}

#[test]
fn a_wrong_yes_or_no_is_wrong_and_says_what_the_answer_means() {
    // w_s = 0.1 is not > 0.1: "yes, it is traced" is wrong.
    let (code, doc) = check(&["reflection_traced=yes"]);
    assert_eq!(code, 1);
    let step = &doc["steps"]["steps"][0];
    assert_eq!(step["verdict"], "wrong");
    assert_eq!(step["expected"], false);
    assert!(step["message"]
        .as_str()
        .unwrap()
        .contains("no (the ray is not traced)"));
    let out = support::phong()
        .args([
            "check",
            EXERCISE,
            "--step",
            "reflection_traced=sim",
            "--lang",
            "pt",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("não (o raio não é traçado)"), "{text}");
}

#[test]
fn the_slips_of_the_secondary_rays_are_named() {
    // R_V with the sign of N·V flipped: V + 2(N·V)N = (1/√2, 0, −1/√2) + (0, 0, −√2)
    // = (1/√2, 0, −3/√2), of length √10/√2 = √5: (1, 0, −3)/√10 = (0.3162, 0, −0.9487).
    let (_, doc) = check(&["r_v=0.3162,0,-0.9487"]);
    let step = &doc["steps"]["steps"][0];
    assert_eq!(step["verdict"], "wrong");
    assert_eq!(
        step["slips"],
        serde_json::json!(["reflection_sign_flipped"]),
        "{doc}"
    );
    // Snell with η_i/η_t inverted: η_r = 3/2, k = 1 − (9/4)(1/2) = −1/8.
    let (_, doc) = check(&["k=-0.125"]);
    let step = &doc["steps"]["steps"][0];
    assert_eq!(step["slips"], serde_json::json!(["eta_inverted"]), "{doc}");
    // T reversed: the sign differs.
    let (_, doc) = check(&["t_direction=-0.4714,0,0.8819"]);
    assert_eq!(doc["steps"]["steps"][0]["sign_reversed"], true, "{doc}");
}

#[test]
fn a_yes_or_no_step_refuses_a_number_with_a_fix() {
    let out = support::phong()
        .args(["check", EXERCISE, "--step", "reflection_traced=0.5"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("reflection_traced") && err.contains("yes or no"),
        "{err}"
    );
}

/// `phong solve` of a problem given as text, with `extra` arguments: its exit code, output and
/// error.
fn solve_binary(text: &str, extra: &[&str]) -> (i32, String, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.json");
    std::fs::write(&path, text).unwrap();
    let out = support::phong()
        .arg("solve")
        .arg(&path)
        .args(extra)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn an_index_of_refraction_outside_0_001_to_1000_is_refused_and_its_bounds_give_a_finite_k() {
    // η_r is 1/η entering and η leaving, and k = 1 − η_r²(1 − cos²θ_i): η = 1e-300 entering
    // (the exercise's ray) makes η_r² = 1e600, beyond f64, and k = −inf, as does η = 1e200
    // leaving; in f32 η = 1e30 leaving is enough (1e60 > 3.4e38).
    let exercise = std::fs::read_to_string(EXERCISE).unwrap();
    let with = |text: &str, eta: &str| {
        let changed = text.replace("\"ior\": 1.5", &format!("\"ior\": {eta}"));
        assert_ne!(changed, text);
        changed
    };
    let h = std::f64::consts::FRAC_1_SQRT_2;
    // From below z = 0 along (1, 0, 1)/√2: the ray leaves the glass at 45°.
    let leaving = plane_problem([-1.0, 0.0, -1.0], [h, 0.0, h], 2, 0.1);
    let entering = plane_problem([-1.0, 0.0, 1.0], [h, 0.0, -h], 2, 0.1);
    for (text, eta, extra, field) in [
        (&exercise, "1e-300", &[][..], "materials.G.ior"),
        (
            &exercise,
            "1e-300",
            &["--format", "json"][..],
            "materials.G.ior",
        ),
        (&leaving, "1e200", &[][..], "materials.G.ior"),
        (
            &leaving,
            "1e30",
            &["--precision", "f32"][..],
            "materials.G.ior",
        ),
        (&entering, "0.000999", &[][..], "materials.G.ior"),
        (&leaving, "1000.001", &[][..], "materials.G.ior"),
    ] {
        let (code, out, err) = solve_binary(&with(text, eta), extra);
        assert_eq!(code, 2, "η = {eta}: {out}{err}");
        assert!(!out.contains("inf"), "η = {eta}: {out}");
        for says in [
            "p.json",
            field,
            &format!("{eta} is outside 0.001 to 1000"),
            "Fix: give an index of refraction from 0.001 to 1000",
        ] {
            assert!(err.contains(says), "η = {eta}: {says:?} in {err}");
        }
    }
    let (code, _, err) = solve_binary(&with(&exercise, "1e-300"), &["--lang", "pt"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("1e-300 está fora de 0.001 a 1000")
            && err.contains("dê um índice de refração de 0.001 a 1000"),
        "{err}"
    );
    // At the bounds, at 45° (sin²θ_i = 1/2): η = 1000 leaving and η = 0.001 entering both give
    // η_r = 1000, so k = 1 − 10^6/2 = −499999: total internal reflection, k finite in both
    // precisions (f32 rounds 0.001 and 1/√2, a relative error of a few 1e-7 in k).
    for (text, eta) in [(&leaving, "1000"), (&entering, "0.001")] {
        for (precision, tolerance) in [(Precision::F64, 1e-9), (Precision::F32, 1e-6)] {
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("p.json");
            std::fs::write(&path, with(text, eta)).unwrap();
            let doc = solve_json(&path, precision).expect("the problem solves");
            let t = &doc["secondary_rays"]["transmission"];
            let k = t["k"].as_f64().expect("k is a number");
            assert!(
                ((k + 499_999.0) / 499_999.0).abs() <= tolerance,
                "η = {eta}, {precision:?}: k = {k}"
            );
            assert_eq!(t["total_internal_reflection"], true);
            assert_eq!(t["traced"], false);
        }
        let (code, out, err) = solve_binary(&with(text, eta), &["--precision", "f32"]);
        assert_eq!(code, 0, "{err}");
        assert!(!out.contains("inf") && !out.contains("NaN"), "{out}");
    }
}
