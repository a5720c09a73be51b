//! Regressions of `phong check --step`, its messages, `phong moodle` and `phong new` (QA
//! report A): each test states the expected behaviour from the problem's own reasoning.

use std::io::Write;

use crate::support::phong;

/// `phong ARGS…`: exit code, standard output, standard error.
fn run(args: &[&str]) -> (i32, String, String) {
    let out = phong().args(args).output().unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// A file in a fresh temporary folder holding `text`.
fn temp_file(name: &str, text: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::File::create(&path)
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    (dir, path)
}

// QA A #2. In 4.2 the light at (1, 1, 1) is behind the surface at P = (3, 1, 3) with
// N = (0.6, 0, 0.8): L = (P − P_l)/‖·‖ = (2, 0, 2)/√8, N·L = (1.2 + 1.6)/√8 = 0.99 > 0, so
// cos θ = −N·L < 0 and, as written, the light adds no specular term: there is no
// (cos φ)^n_s. Only the likely intended reading (light reversed) has one. 4.2 is a point
// problem: it has no ray, so "the ray hits nothing" is false.
#[test]
fn a_point_problems_missing_step_is_explained_by_the_light_not_by_a_ray() {
    let (code, out, err) = run(&[
        "check",
        "exercises/4.2.json",
        "--step",
        "cos_phi_pow=0.7658",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(!out.contains("ray"), "{out}");
    assert!(out.contains("behind the surface (cos θ < 0)"), "{out}");
    assert!(out.contains("no specular term"), "{out}");
    let (code, out, err) = run(&[
        "check",
        "exercises/4.2.json",
        "--step",
        "cos_phi_pow=0.7658",
        "--lang",
        "pt",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(!out.contains("raio"), "{out}");
    assert!(out.contains("atrás da superfície (cos θ < 0)"), "{out}");
    // A wrong value of the same step is told the reading's value, with the same reason.
    let (code, out, _) = run(&["check", "exercises/4.2.json", "--step", "cos_phi_pow=0.1"]);
    assert_eq!(code, 1, "{out}");
    assert!(!out.contains("ray"), "{out}");
    assert!(out.contains("behind the surface (cos θ < 0)"), "{out}");
}

// QA A #2, through `phong grade`: the feedback is the same sentence.
#[test]
fn grade_feedback_on_a_point_problems_missing_step_does_not_speak_of_a_ray() {
    let (_dir, csv) = temp_file(
        "turma.csv",
        "aluno;exercício;resposta;passos\neli;4.2;0 0 0;cos_phi_pow=0,7658\n",
    );
    let (code, out, err) = run(&[
        "grade",
        csv.to_str().unwrap(),
        "--exercises",
        "exercises",
        "--lang",
        "pt",
        "-o",
        "-",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(!out.contains("raio"), "{out}");
    assert!(out.contains("atrás da superfície (cos θ < 0)"), "{out}");
}

// 4.3 as written: the ray meets the plane only behind its origin (t = −90), so it hits
// nothing; that reason stays.
#[test]
fn a_ray_that_hits_nothing_is_still_the_reason_in_4_3() {
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--step", "cos_theta=0.03417"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("as written the ray hits nothing"), "{out}");
}

// QA A #12. 4.2's file has one light, lights[0] (a point light): a step of lights[3] names a
// light that is not there, and the fix is the index it has, or the bare name.
#[test]
fn a_step_of_a_light_not_in_the_file_says_which_to_use() {
    let (code, _, err) = run(&["check", "exercises/4.2.json", "--step", "cos_theta[3]=0.5"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("exercises/4.2.json: --step: cos_theta[3]"),
        "{err}"
    );
    assert!(err.contains("Fix: use cos_theta[0] or cos_theta"), "{err}");
    let (code, _, err) = run(&[
        "check",
        "exercises/4.2.json",
        "--step",
        "cos_theta[3]=0.5",
        "--lang",
        "pt",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("Correção: use cos_theta[0] ou cos_theta"),
        "{err}"
    );
}

// QA A #12. A step that cannot be read is an error of the check of that file: it names the
// file, as the error of a step the file does not have (cos_psi) does.
#[test]
fn a_step_that_cannot_be_read_names_the_file() {
    for (step, what) in [
        ("I_l=0.3535", "I_l is a vector"),
        ("cos_thet=0.5", "\"cos_thet\" is not the name of a step"),
        ("cos_theta", "\"cos_theta\" is not NAME=VALUE"),
    ] {
        let (code, _, err) = run(&["check", "exercises/4.2.json", "--step", step]);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains(&format!("exercises/4.2.json: --step: {what}")),
            "{step}: {err}"
        );
        assert!(err.contains("Fix: "), "{step}: {err}");
    }
}

// An ambient-only problem has no light of its own for a per-light step: the fix says which
// steps it has.
#[test]
fn a_light_step_of_an_ambient_only_problem_has_a_fix() {
    let (_dir, file) = temp_file(
        "amb.json",
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.5, 0.5]}}}"#,
    );
    for step in ["cos_theta=0.5", "cos_theta[2]=0.5"] {
        let (code, _, err) = run(&["check", file.to_str().unwrap(), "--step", step]);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("Fix: check a step of the ambient light: I_a or ambient"),
            "{err}"
        );
        let (_, _, err) = run(&[
            "check",
            file.to_str().unwrap(),
            "--step",
            step,
            "--lang",
            "pt",
        ]);
        assert!(
            err.contains("Correção: confira um passo da luz ambiente: I_a ou ambient"),
            "{err}"
        );
    }
}

// QA A #16. "nenhuma" (no hit) to a point problem: there is no value to compare with slips,
// so no "no classic slip gives it" line; the answer's own explanation is enough.
#[test]
fn a_no_hit_answer_to_a_point_problem_has_no_slip_line() {
    let (code, out, _) = run(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        "nenhuma",
        "--lang",
        "pt",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("um problema de ponto não tem raio, então não há o que errar"),
        "{out}"
    );
    assert!(!out.contains("erro clássico"), "{out}");
    let (_, out, _) = run(&["check", "exercises/4.2.json", "--answer", "none"]);
    assert!(!out.contains("no classic slip"), "{out}");
}

// QA A #16. "76 92 81" is 8-bit values (76/255 = 0.298, 92/255 = 0.361, 81/255 = 0.318: 4.2's
// likely intended reading). Without a scale the course policy reads them so (issue 28): the
// reading. Judged on the 0–1 scale (`--scale 1`), a near miss "90.98 away" measured there is
// noise; the hint to use --scale 255 is the message, with no near miss on the wrong scale (nor
// a slip line measured there).
#[test]
fn an_8_bit_answer_without_scale_gets_no_near_miss_on_the_wrong_scale() {
    let (code, out, _) = run(&["check", "exercises/4.2.json", "--answer", "76 92 81"]);
    assert_eq!(code, 0, "{out}");
    let (code, out, _) = run(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        "76 92 81",
        "--scale",
        "1",
        "--lang",
        "en",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("did you mean --scale 255?"), "{out}");
    assert!(!out.contains("closest"), "{out}");
    assert!(!out.contains("no classic slip"), "{out}");
    let (_, out, _) = run(&[
        "check",
        "exercises/4.2.json",
        "--answer",
        "76 92 81",
        "--scale",
        "1",
        "--format",
        "json",
    ]);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let nearest = doc
        .pointer("/nearest")
        .or_else(|| doc.pointer("/0/nearest"));
    assert!(nearest.is_none_or(|n| n.is_null()), "{out}");
}

// QA A #17. Each row of `--slips` is "(clamped)  ((unclamped))" where they differ. 4.2's
// no_clamping slip keeps the negative cosines: Eq. 4.16 gives (−0.299153, −0.361229, −0.318306)
// (the likely intended reading's colour, negated); clamped to [0, 1] that is (0, 0, 0).
#[test]
fn the_no_clamping_row_of_slips_shows_both_columns() {
    let (code, out, _) = run(&["check", "exercises/4.2.json", "--slips", "--lang", "pt"]);
    assert_eq!(code, 0, "{out}");
    let row = out
        .lines()
        .find(|l| l.trim_start().starts_with("no_clamping "))
        .unwrap_or_else(|| panic!("{out}"));
    assert!(
        row.trim_end()
            .ends_with(" (0, 0, 0)  ((-0.299153, -0.361229, -0.318306))"),
        "{row}"
    );
}

// QA A #14. Two ambient lights are two values: one symbol I_a for both, in two identical
// sentences, reads as a contradiction. They are named apart, I_a1 and I_a2, in one sentence;
// a single ambient light keeps I_a.
#[test]
fn two_generated_ambient_lights_are_named_apart() {
    let (code, out, err) = run(&[
        "new", "--kind", "ambient", "--count", "12", "--seed", "7", "--lang", "pt",
    ]);
    assert_eq!(code, 0, "{err}");
    let problems: Vec<serde_json::Value> = serde_json::from_str(&out).unwrap();
    let mut two = 0;
    for p in &problems {
        let ambient: Vec<String> = p["lights"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|l| l["type"] == "ambient")
            .map(|l| {
                let c: Vec<String> = l["color"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.to_string())
                    .collect();
                format!("({})", c.join(", "))
            })
            .collect();
        let (en, pt) = (
            p["question"].as_str().unwrap(),
            p["question_pt"].as_str().unwrap(),
        );
        if ambient.len() == 2 {
            two += 1;
            let want_en = format!(
                "Two ambient lights, I_a1 = {} and I_a2 = {}, light the scene.",
                ambient[0], ambient[1]
            );
            let want_pt = format!(
                "Duas luzes ambientes, I_a1 = {} e I_a2 = {}, iluminam a cena.",
                ambient[0], ambient[1]
            );
            assert!(en.contains(&want_en), "{en}");
            assert!(pt.contains(&want_pt), "{pt}");
            assert!(
                !en.contains("I_a =") && !pt.contains("I_a ="),
                "{en} / {pt}"
            );
        } else {
            assert_eq!(ambient.len(), 1);
            assert!(
                en.contains(&format!("An ambient light I_a = {} lights", ambient[0])),
                "{en}"
            );
            assert!(
                pt.contains(&format!("Uma luz ambiente I_a = {} ilumina", ambient[0])),
                "{pt}"
            );
        }
    }
    assert!(
        two > 0,
        "seed 7 draws a problem with two ambient lights (QA's ambient-7-001)"
    );
}

// Issue 28, item 4. 4.3's ray, O = (8, 4, 6), D = (0.8, 0, −0.6), meets the plane
// x + y + z = 0 where (O + tD)·(1, 1, 1) = 18 + 0.2 t = 0: t = −90, behind the origin. The
// ray reversed, O − tD, meets it at t = +90. That reversed ray is the likely intended reading
// (the answer (0.524, 0.027, 0) is its colour): a student who gives t = 90 took its hit, which
// is right in that reading, as the point P = (−64, 4, 60) is; the message says t = 90 is along
// −D (−90 along D), and never "t < 0" of a positive t. `--strict` refuses it, as any reading.
#[test]
fn a_positive_t_of_the_reversed_ray_is_the_intended_readings() {
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--step", "t=90"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains(
            "t          = 90  wrong as written, right in the likely intended reading (O + tD \
             on the surface): the problem as written gives -90 (the sign differs); yours is \
             the value of the likely intended reading \"the line's hit behind the ray's \
             origin\"; in that reading the ray is reversed (O − tD): it meets the surface at \
             t = 90 along −D, which is t = -90 along D\n"
        ),
        "{out}"
    );
    assert!(!out.contains("t < 0"), "{out}");
    let (code, pt, _) = run(&[
        "check",
        "exercises/4.3.json",
        "--step",
        "t=90",
        "--lang",
        "pt",
    ]);
    assert_eq!(code, 0, "{pt}");
    assert!(
        pt.contains("em t = 90 ao longo de −D, que é t = -90 ao longo de D"),
        "{pt}"
    );
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--step", "t=90", "--strict"]);
    assert_eq!(code, 1, "{out}");
    let (_, json, _) = run(&[
        "check",
        "exercises/4.3.json",
        "--step",
        "t=90",
        "--format",
        "json",
    ]);
    assert!(!json.contains("t < 0"), "{json}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let step = &doc["steps"]["steps"][0];
    assert_eq!(step["verdict"], "reading", "{json}");
    assert_eq!(step["reading"], "line_behind_origin", "{json}");
}

// A negative t other than the line's is still a slip's where one gives it; 4.3's t = −90 is the
// problem as written (the line's t along D): right.
#[test]
fn the_lines_own_t_is_right_as_written() {
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--step", "t=-90"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("t          = -90  right (O + tD on the surface)\n"),
        "{out}"
    );
}

// Black where the ray hits nothing (4.3, as above) is the background: the answer is "none".
// The verdict stays wrong (exit 1, not accepted); what explains it is the background, not
// the nearest dark slip ("the ambient term forgotten" in the intended reading).
#[test]
fn black_where_the_ray_hits_nothing_is_the_background() {
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--answer", "0 0 0"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("exercises/4.3.json: wrong\n"), "{out}");
    assert!(
        out.contains(
            "\n  black is the background, the colour a ray that meets nothing shows: as \
             written the ray hits nothing (t > 0), so there is no colour to give, and the \
             answer is \"none\" (no hit)\n"
        ),
        "{out}"
    );
    assert!(
        !out.contains("ambient term") && !out.contains("closest"),
        "{out}"
    );
    let (code, json, _) = run(&[
        "check",
        "exercises/4.3.json",
        "--answer",
        "#000000",
        "--format",
        "json",
    ]);
    assert_eq!(code, 1, "{json}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(doc["verdict"], "wrong");
    assert_eq!(doc["accepted"], false);
    assert!(doc.get("nearest").is_none(), "{json}");
    assert!(
        doc["message"]
            .as_str()
            .unwrap()
            .starts_with("the answer is wrong; black is the background"),
        "{json}"
    );
}

// A near miss of the colour the "expected" line shows is told it is one. 4.3's likely
// intended reading takes the hit at t = −90, P = (−64, 4, 60): L = (P − P_l)/‖·‖ with
// P_l = (0, 0, 5), (−64, 4, 55)/84.4808; N = (1, 1, 1)/√3 (O, the light and the viewer are on
// its side); cos θ = −N·L = 5/(√3·84.4808) = 0.034171; diffuse (0.7, 0.8, 0)·0.034171 =
// (0.023920, 0.027337, 0); ambient (0.5, 0.4, 0.6)·(1, 0, 0) = (0.5, 0, 0); R·V > 0 with
// V = (P − E)/‖·‖, so cos φ < 0 and no specular: (0.523920, 0.027337, 0). The answer
// (0.53, 0.03, 0) is 0.00608 off in red: outside ±0.005, a near miss of that reading.
#[test]
fn a_near_miss_of_the_expected_reading_names_it() {
    let (code, out, _) = run(&["check", "exercises/4.3.json", "--answer", "0.53 0.03 0"]);
    assert_eq!(code, 1, "{out}");
    let line = out
        .lines()
        .find(|l| l.starts_with("  close to "))
        .unwrap_or_else(|| panic!("no near miss told:\n{out}"));
    let rest = line
        .strip_prefix(
            "  close to the likely intended reading \"the line's hit behind the ray's origin\": ",
        )
        .unwrap_or_else(|| panic!("{line}"));
    let (away, tail) = rest.split_once(' ').unwrap();
    let away: f64 = away.parse().unwrap();
    assert!((away - 0.00608).abs() < 1e-5, "{line}");
    assert_eq!(tail, "away at most per channel (tolerance ±0.005)");
}
