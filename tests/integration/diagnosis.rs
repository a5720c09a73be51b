//! One test per classic slip: the wrong answer is worked out by an independent calculation
//! written here (a plain-f64 Phong evaluation with the slip made by hand), then `phong check`
//! must call it wrong (exit 1) and name that slip in its JSON diagnosis. The program's own slip
//! switches are never called from these tests.

use crate::support;

use std::io::Write;

use serde_json::{json, Value};

type V = [f64; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn scale(a: V, k: f64) -> V {
    a.map(|x| x * k)
}
fn unit(a: V) -> V {
    scale(a, 1.0 / dot(a, a).sqrt())
}
fn add(a: &mut V, b: V) {
    for i in 0..3 {
        a[i] += b[i];
    }
}
fn mul(a: V, b: V) -> V {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2]]
}

#[derive(Clone)]
struct Spot {
    axis: V,
    angle_deg: f64,
    exponent: f64,
}

#[derive(Clone)]
struct HandLight {
    position: V,
    color: V,
    falloff: i32,
    spot: Option<Spot>,
}

/// A point problem, and how the hand calculation is made.
#[derive(Clone)]
struct Hand {
    ambient: Option<V>,
    o_a: V,
    o_d: V,
    o_s: V,
    n_s: f64,
    lights: Vec<HandLight>,
    p: V,
    /// N as given.
    n: V,
    viewer: Option<V>,
    // How the calculation is made (the chapter's way: true, false, false, false).
    normalize: bool,
    abs_cos: bool,
    half_vector: bool,
    literal: bool,
}

impl Hand {
    /// Eq. 4.1–4.16 by hand.
    fn color(&self) -> V {
        let n = if self.normalize { unit(self.n) } else { self.n };
        let v = self.viewer.map(|e| unit(sub(self.p, e)));
        let mut c = self.ambient.map_or([0.0; 3], |i_a| mul(self.o_a, i_a));
        for l in &self.lights {
            let to_p = sub(self.p, l.position);
            let d = dot(to_p, to_p).sqrt();
            let lv = unit(to_p);
            let mut i_l = scale(l.color, 1.0 / d.powi(l.falloff));
            if let Some(s) = &l.spot {
                let cos_psi = dot(unit(s.axis), lv);
                if cos_psi.acos().to_degrees() > s.angle_deg {
                    continue;
                }
                i_l = scale(i_l, cos_psi.powf(s.exponent));
            }
            let cos_theta = if self.abs_cos {
                dot(n, lv).abs()
            } else {
                -dot(n, lv)
            };
            if cos_theta <= 0.0 && !self.literal {
                continue;
            }
            add(&mut c, scale(mul(self.o_d, i_l), cos_theta));
            if let Some(v) = v {
                let r = sub(lv, scale(n, 2.0 * dot(n, lv)));
                let cos_phi = if self.half_vector {
                    dot(n, unit(sub(scale(lv, -1.0), v)))
                } else {
                    -dot(r, v)
                };
                if cos_phi > 0.0 || self.literal {
                    add(
                        &mut c,
                        scale(mul(self.o_s, i_l), cos_phi.powi(self.n_s as i32)),
                    );
                }
            }
        }
        c
    }

    /// The problem file.
    fn file(&self) -> Value {
        let mut lights = Vec::new();
        if let Some(a) = self.ambient {
            lights.push(json!({"type": "ambient", "color": a}));
        }
        for l in &self.lights {
            lights.push(match &l.spot {
                None => json!({"type": "point", "position": l.position, "color": l.color,
                               "falloff": l.falloff}),
                Some(s) => json!({"type": "spot", "position": l.position, "axis": s.axis,
                                  "angle": s.angle_deg, "exponent": s.exponent,
                                  "color": l.color, "falloff": l.falloff}),
            });
        }
        json!({
            "materials": {"M": {"ambient": self.o_a, "diffuse": self.o_d, "specular": self.o_s,
                                "shininess": self.n_s}},
            "lights": lights,
            "viewer": self.viewer,
            "point": {"position": self.p, "normal": self.n, "material": "M"}
        })
    }
}

/// A point lit from the front by a point light (linear falloff, d = 5) and a spot light
/// (inside its cone, ψ = 36.87°), with ambient light, a viewer, n_s = 2, and a normal given
/// with length 2.
fn front_lit() -> Hand {
    Hand {
        ambient: Some([0.2, 0.2, 0.2]),
        o_a: [0.5, 0.4, 0.6],
        o_d: [0.7, 0.8, 0.6],
        o_s: [0.2, 0.3, 0.4],
        n_s: 2.0,
        lights: vec![
            HandLight {
                position: [3.0, 0.0, 4.0],
                color: [5.0, 5.0, 5.0],
                falloff: 1,
                spot: None,
            },
            HandLight {
                position: [0.0, -3.0, 4.0],
                color: [0.5, 0.5, 0.5],
                falloff: 0,
                spot: Some(Spot {
                    axis: [0.0, 0.0, -1.0],
                    angle_deg: 45.0,
                    exponent: 2.0,
                }),
            },
        ],
        p: [0.0, 0.0, 0.0],
        n: [0.0, 0.0, 2.0],
        viewer: Some([-4.0, 0.0, 3.0]),
        normalize: true,
        abs_cos: false,
        half_vector: false,
        literal: false,
    }
}

/// Exercise 4.2 as worded (the light behind the surface).
fn exercise_4_2() -> Hand {
    Hand {
        ambient: None,
        o_a: [0.5, 0.4, 0.6],
        o_d: [0.7, 0.8, 0.6],
        o_s: [0.2, 0.3, 0.4],
        n_s: 1.0,
        lights: vec![HandLight {
            position: [1.0, 1.0, 1.0],
            color: [1.0, 1.0, 1.0],
            falloff: 1,
            spot: None,
        }],
        p: [3.0, 1.0, 3.0],
        n: [0.6, 0.0, 0.8],
        viewer: Some([5.0, 4.0, 6.0]),
        normalize: true,
        abs_cos: false,
        half_vector: false,
        literal: false,
    }
}

/// Writes the problem and checks `answer` against it; returns the exit code and the JSON.
fn check(problem: &Value, answer: V) -> (i32, Value) {
    let mut f = tempfile::Builder::new().suffix(".json").tempfile().unwrap();
    f.write_all(problem.to_string().as_bytes()).unwrap();
    check_path(f.path(), answer)
}

fn check_path(path: &std::path::Path, answer: V) -> (i32, Value) {
    let text = format!("{} {} {}", answer[0], answer[1], answer[2]);
    let out = support::phong()
        .args(["check", "--format", "json", "--answer", &text])
        .arg(path)
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON output");
    (out.status.code().unwrap(), json)
}

/// The slip codes of each diagnosis.
fn diagnosed(json: &Value) -> Vec<Vec<String>> {
    json["diagnosis"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            d["slips"]
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s.as_str().unwrap().to_owned())
                .collect()
        })
        .collect()
}

/// The slipped hand calculation must differ from the right one, be called wrong, and be
/// explained by `slip`.
fn assert_diagnosed(right: &Hand, slipped: &Hand, slip: &str) {
    let good = right.color();
    let bad = slipped.color();
    let differs = (0..3).any(|i| (good[i].clamp(0.0, 1.0) - bad[i]).abs() > 0.01);
    assert!(
        differs,
        "{slip}: the slip must change the answer: {good:?} vs {bad:?}"
    );
    let (code, json) = check(&right.file(), bad);
    assert_eq!(code, 1, "{slip}: {json:#}");
    assert_eq!(json["verdict"], "wrong");
    let found = diagnosed(&json);
    assert!(
        found.iter().any(|d| d == &[slip.to_owned()]),
        "{slip} not among {found:?} for {bad:?}"
    );
}

#[test]
fn l_taken_from_the_point_to_the_light_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    for l in &mut slipped.lights {
        // L reversed: every L = (P − P_l)/d negated, i.e. the light mirrored through P.
        l.position = sub(scale(right.p, 2.0), l.position);
        if let Some(s) = &mut l.spot {
            s.axis = scale(s.axis, -1.0);
        }
    }
    assert_diagnosed(&right, &slipped, "light_reversed");
}

#[test]
fn v_taken_from_the_point_to_the_eye_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.viewer = Some(sub(scale(right.p, 2.0), right.viewer.unwrap()));
    assert_diagnosed(&right, &slipped, "viewer_reversed");
}

#[test]
fn a_reversed_normal_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.n = scale(right.n, -1.0);
    assert_diagnosed(&right, &slipped, "normal_reversed");
}

#[test]
fn a_normal_left_unnormalised_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.normalize = false;
    assert_diagnosed(&right, &slipped, "normal_not_normalized");
}

#[test]
fn a_forgotten_falloff_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.lights[0].falloff = 0;
    assert_diagnosed(&right, &slipped, "falloff_forgotten");
}

#[test]
fn quadratic_falloff_for_linear_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.lights[0].falloff = 2;
    assert_diagnosed(&right, &slipped, "falloff_quadratic_not_linear");
}

#[test]
fn linear_falloff_for_quadratic_is_diagnosed() {
    let mut right = front_lit();
    right.lights[0].falloff = 2;
    right.lights[0].color = [25.0, 25.0, 25.0];
    let mut slipped = right.clone();
    slipped.lights[0].falloff = 1;
    assert_diagnosed(&right, &slipped, "falloff_linear_not_quadratic");
}

#[test]
fn a_forgotten_ambient_term_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.ambient = None;
    assert_diagnosed(&right, &slipped, "ambient_forgotten");
}

#[test]
fn blinns_half_vector_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.half_vector = true;
    assert_diagnosed(&right, &slipped, "half_vector");
}

#[test]
fn cos_phi_not_raised_to_n_s_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.n_s = 1.0;
    assert_diagnosed(&right, &slipped, "cos_phi_not_raised");
}

#[test]
fn an_ignored_spot_cone_is_diagnosed() {
    let right = front_lit();
    let mut slipped = right.clone();
    slipped.lights[1].spot = None;
    assert_diagnosed(&right, &slipped, "spot_cone_ignored");
}

#[test]
fn abs_cos_theta_on_exercise_4_2_is_diagnosed() {
    let right = exercise_4_2();
    let mut slipped = right.clone();
    slipped.abs_cos = true;
    assert_diagnosed(&right, &slipped, "abs_cos_theta");
}

#[test]
fn eq_4_16_taken_literally_on_exercise_4_2_is_diagnosed() {
    let right = exercise_4_2();
    let mut slipped = right.clone();
    slipped.literal = true;
    assert_diagnosed(&right, &slipped, "no_clamping");
}

#[test]
fn the_ray_hit_behind_the_origin_is_diagnosed() {
    // A ray from the centre of a sphere of radius 5 along +z: its hit is (0, 0, 5), where the
    // normal turned to face the ray is (0, 0, −1); behind the origin, (0, 0, −5), with (0, 0, 1).
    let problem = json!({
        "materials": {"M": {"diffuse": [0.5, 0.5, 0.5], "specular": [0.5, 0.5, 0.5], "shininess": 1}},
        "lights": [{"type": "point", "position": [0, 3, 2], "color": [1, 1, 1], "falloff": 0}],
        "viewer": [0, 0, 0],
        "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
        "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 5, "material": "M"}]
    });
    let at = |p: V, n: V| Hand {
        ambient: None,
        o_a: [0.0; 3],
        o_d: [0.5; 3],
        o_s: [0.5; 3],
        n_s: 1.0,
        lights: vec![HandLight {
            position: [0.0, 3.0, 2.0],
            color: [1.0; 3],
            falloff: 0,
            spot: None,
        }],
        p,
        n,
        viewer: Some([0.0; 3]),
        normalize: true,
        abs_cos: false,
        half_vector: false,
        literal: false,
    };
    let right = at([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]).color();
    let behind = at([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]).color();
    assert!((right[0] - behind[0]).abs() > 0.01);
    let (code, json) = check(&problem, right);
    assert_eq!(code, 0, "{json:#}");
    let (code, json) = check(&problem, behind);
    assert_eq!(code, 1, "{json:#}");
    assert!(diagnosed(&json).contains(&vec!["hit_behind_origin".to_owned()]));
}

#[test]
fn the_acceptance_answer_to_4_2_names_the_reversed_normal_and_abs_cos_theta() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.2.json");
    let (code, json) = check_path(&path, [0.245, 0.28, 0.21]);
    assert_eq!(code, 1);
    let found = diagnosed(&json);
    assert!(
        found.contains(&vec!["normal_reversed".to_owned()]),
        "{found:?}"
    );
    assert!(
        found.contains(&vec!["abs_cos_theta".to_owned()]),
        "{found:?}"
    );
    assert_eq!(json["reading"]["code"], "normal_reversed");
    assert_eq!(json["reading"]["likely_intended"], false);
}

#[test]
fn a_slip_that_does_not_apply_is_not_listed() {
    // 4.2 has no ambient light, no spot, n_s = 1 and a unit normal: none of those slips can be
    // offered, whatever the answer.
    let out = support::phong()
        .args(["check", "--slips"])
        .arg(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.2.json"))
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    for absent in [
        "ambient_forgotten",
        "spot_cone_ignored",
        "cos_phi_not_raised",
        "normal_not_normalized",
        "hit_behind_origin",
    ] {
        assert!(!text.contains(absent), "{absent} listed:\n{text}");
    }
    assert!(text.contains("falloff_forgotten"), "{text}");
}

/// Checks `answer` (text) against a problem file given as JSON text, with extra arguments.
fn check_text(problem: &str, answer: &str, extra: &[&str]) -> (i32, Value) {
    let mut f = tempfile::Builder::new().suffix(".json").tempfile().unwrap();
    f.write_all(problem.as_bytes()).unwrap();
    let out = support::phong()
        .args(["check", "--format", "json", "--answer", answer])
        .args(extra)
        .arg(f.path())
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON output");
    (out.status.code().unwrap(), json)
}

/// 4.2's likely intended reading, by hand (L from the point to the light):
/// L = ((1,1,1) − (3,1,3))/‖·‖ = (−2, 0, −2)/(2√2); d = 2√2; I_l = 1/d = 1/(2√2);
/// N·L = (0.6·(−2) + 0.8·(−2))/(2√2) = −2.8/(2√2) = −1.4/√2, cos θ = 1.4/√2 = 0.989949;
/// diffuse = O_d · I_l · cos θ = O_d · 1.4/4 = O_d · 0.35 = (0.245, 0.28, 0.21);
/// R = L − 2(N·L)N = (0.480833, 0, 0.876812); V = (−2, −3, −3)/√22;
/// cos φ = −R·V = (0.480833·2 + 0.876812·3)/√22 = 0.765839;
/// specular = O_s · I_l · cos φ = O_s · 0.270765 = (0.054153, 0.081230, 0.108306);
/// total (0.299153, 0.361230, 0.318306).
const INTENDED_4_2: V = [0.299153, 0.361230, 0.318306];

#[test]
fn ambient_assumed_an_assumed_white_ambient_on_4_2s_intended_reading() {
    // 4.2 gives no ambient light; the material's O_a = (0.5, 0.4, 0.6) with an assumed white
    // I_a = (1, 1, 1) adds (0.5, 0.4, 0.6) to the intended (0.299153, 0.361230, 0.318306):
    // (0.799153, 0.761230, 0.918306), written to three decimals (0.799, 0.761, 0.918).
    let by_hand = [
        INTENDED_4_2[0] + 0.5,
        INTENDED_4_2[1] + 0.4,
        INTENDED_4_2[2] + 0.6,
    ];
    assert!((by_hand[0] - 0.799).abs() < 5e-4 && (by_hand[2] - 0.918).abs() < 5e-4);
    let (code, json) = check_path(
        std::path::Path::new("exercises/4.2.json"),
        [0.799, 0.761, 0.918],
    );
    assert_eq!(code, 1);
    assert_eq!(
        diagnosed(&json),
        [vec![
            "light_reversed".to_owned(),
            "ambient_assumed".to_owned()
        ]]
    );
    assert_eq!(json["diagnosis"][0]["intended"], json!(["light_reversed"]));
}

#[test]
fn intermediates_rounded_to_two_decimals_on_4_2s_intended_reading() {
    // Every intermediate rounded to 2 decimals before the next step (by hand):
    // V = (−0.4264, −0.6396, −0.6396) → (−0.43, −0.64, −0.64); L → (−0.71, 0, −0.71);
    // I_l = 0.35355 → 0.35; N·L = 0.6·(−0.71) + 0.8·(−0.71) = −0.994 → −0.99, cos θ = 0.99;
    // diffuse = O_d·0.35·0.99 = O_d·0.3465 = (0.24255, 0.2772, 0.2079) → (0.24, 0.28, 0.21);
    // R = L − 2(−0.99)N = (−0.71 + 1.188, 0, −0.71 + 1.584) = (0.478, 0, 0.874) → (0.48, 0, 0.87);
    // cos φ = −R·V = 0.48·0.43 + 0.87·0.64 = 0.2064 + 0.5568 = 0.7632 → 0.76 (n_s = 1);
    // specular = O_s·0.35·0.76 = O_s·0.266 = (0.0532, 0.0798, 0.1064) → (0.05, 0.08, 0.11);
    // total (0.29, 0.36, 0.32): 0.0092 from the intended red, outside ±0.005.
    let (code, json) = check_path(
        std::path::Path::new("exercises/4.2.json"),
        [0.29, 0.36, 0.32],
    );
    assert_eq!(code, 1);
    assert_eq!(
        diagnosed(&json),
        [vec![
            "light_reversed".to_owned(),
            "intermediates_rounded".to_owned()
        ]]
    );
}

#[test]
fn truncated_decimals_and_the_nearest_candidate_on_4_2() {
    // The intended (0.299153, 0.361230, 0.318306) cut to 2 decimals: (0.29, 0.36, 0.31);
    // rounded it would be (0.30, 0.36, 0.32). The nearest candidate is the intended reading,
    // 0.299153 − 0.29 = 0.009153 away (the largest channel difference).
    let (code, json) = check_path(
        std::path::Path::new("exercises/4.2.json"),
        [0.29, 0.36, 0.31],
    );
    assert_eq!(code, 1);
    assert_eq!(
        diagnosed(&json),
        [vec![
            "light_reversed".to_owned(),
            "truncated_decimals".to_owned()
        ]]
    );
    assert_eq!(json["nearest"]["source"], "reading");
    assert_eq!(json["nearest"]["reading"], "light_reversed");
    let d = json["nearest"]["distance"].as_f64().unwrap();
    assert!((d - 0.009153).abs() < 1e-5, "{d}");
    assert!(json["nearest"]["description"]
        .as_str()
        .unwrap()
        .starts_with("close to the likely intended reading"));
}

#[test]
fn the_nearest_candidate_is_named_when_no_slip_matches() {
    // 4.2 as written is (0, 0, 0) and its intended reading (0.299153, 0.361230, 0.318306);
    // (0.31, 0.35, 0.33) differs from the intended by (+0.010847, −0.011230, +0.011694): at
    // most 0.011694 (blue, 0.33 − 0.318306); black is 0.35 away, and no slip is nearer (the
    // |cos θ| diffuse alone, (0.245, 0.28, 0.21), is 0.12 away; intermediates rounded,
    // (0.29, 0.36, 0.32), 0.02).
    let (code, json) = check_path(
        std::path::Path::new("exercises/4.2.json"),
        [0.31, 0.35, 0.33],
    );
    assert_eq!(code, 1);
    assert_eq!(diagnosed(&json), Vec::<Vec<String>>::new());
    assert_eq!(json["nearest"]["reading"], "light_reversed");
    let d = json["nearest"]["distance"].as_f64().unwrap();
    assert!((d - 0.011694).abs() < 1e-5, "{d}");
}

#[test]
fn truncated_rgb8_under_a_keys_tolerance_of_half_a_step() {
    // O_a = (0.7, 0.45, 0.99) under white ambient light: 255·c = (178.5, 114.75, 252.45),
    // rounded (179, 115, 252), truncated (178, 114, 252). The key's tolerance 0.5 accepts the
    // rounded value (differences 0.5, 0.25, 0.45) and not the truncated one (0.75 in green).
    let problem = r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
        "point": {"material": {"ambient": [0.7, 0.45, 0.99]}},
        "answer": {"color": [179, 115, 252], "scale": 255, "tolerance": 0.5}}"#;
    let (code, json) = check_text(problem, "179 115 252", &["--scale", "255"]);
    assert_eq!(code, 0, "{json}");
    assert_eq!(json["tolerance"], 0.5);
    let (code, json) = check_text(problem, "178 114 252", &["--scale", "255"]);
    assert_eq!(code, 1, "{json}");
    assert_eq!(diagnosed(&json), [vec!["truncated_rgb8".to_owned()]]);
}

/// A slip whose colour the tolerance cannot tell from the right one is not named. 4.1 as
/// written is (0.5, 0.7, 0.3): on the 255 scale (127.5, 178.5, 76.5), which the 8-bit value
/// truncated makes (127, 178, 76), 0.5 from it, inside the scale's tolerance of 1 (127 is
/// right). So 126 178 76, 1.5 from the right colour, is wrong, and "truncated" (1 from it)
/// said nothing of it: it was named. Under a tolerance of 0.4 the two are told apart, and an
/// answer of the truncated value is the slip.
#[test]
fn a_slip_the_tolerance_cannot_tell_from_the_right_colour_is_not_named() {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises/4.1.json");
    let judge = |answer: &str, extra: &[&str]| {
        let out = support::phong()
            .args(["check", "--format", "json", "--answer", answer])
            .args(extra)
            .arg(&file)
            .output()
            .unwrap();
        let json: Value = serde_json::from_slice(&out.stdout).unwrap();
        (out.status.code(), json)
    };
    let (code, json) = judge("126 178 76", &[]);
    assert_eq!(code, Some(1), "{json:#}");
    assert_eq!(json["verdict"], "wrong");
    assert!(diagnosed(&json).is_empty(), "{json:#}");
    let (code, json) = judge("127 178 76", &[]);
    assert_eq!((code, &json["verdict"]), (Some(0), &Value::from("right")));
    let (code, json) = judge("127 178 76", &["--tolerance", "0.4"]);
    assert_eq!(code, Some(1), "{json:#}");
    assert_eq!(diagnosed(&json), vec![vec!["truncated_rgb8".to_owned()]]);
}
