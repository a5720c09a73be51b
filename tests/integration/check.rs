//! `phong check` from the outside: exit codes (0 accepted, 1 wrong, 2 bad input), the forms
//! of answers, scales and tolerances, answer keys, readings, the JSON fields, and insta
//! snapshots of the text and JSON verdicts on the chapter's exercises.
//!
//! Expected colours are worked out by hand in the comments (4.1: O_a·I_a; the others are the
//! values README and tests/hand_calculations.rs derive independently).

use std::io::Write;

use crate::support;
use crate::support::phong;
use predicates::prelude::*;
use serde_json::Value;

fn check(file: &str, args: &[&str]) -> (i32, String, String) {
    let out = phong()
        .arg("check")
        .arg(format!("exercises/{file}"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn check_json(file: &str, args: &[&str]) -> (i32, Value) {
    let mut a = vec!["--format", "json"];
    a.extend_from_slice(args);
    let (code, out, _) = check(file, &a);
    (code, serde_json::from_str(&out).expect("JSON"))
}

fn temp_problem(text: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::Builder::new().suffix(".json").tempfile().unwrap();
    f.write_all(text.as_bytes()).unwrap();
    f
}

// Exercise 4.1: O_a = 1·(0.5, 0.7, 0.3), I_a = (1, 1, 1): the colour is (0.5, 0.7, 0.3).

#[test]
fn a_right_answer_exits_0_in_every_form_people_write() {
    for answer in [
        "0.5 0.7 0.3",
        "0.5, 0.7, 0.3",
        "(0.5, 0.7, 0.3)",
        "[0.5; 0.7; 0.3]",
        "0,5 0,7 0,3",
        "1/2 7/10 3/10",
    ] {
        let (code, out, _) = check("4.1.json", &["--answer", answer]);
        assert_eq!(code, 0, "{answer}: {out}");
        assert!(out.contains(": right"), "{out}");
    }
}

#[test]
fn the_default_tolerance_is_half_a_unit_of_the_second_decimal() {
    // 0.505 is 0.005 from 0.5: accepted (inclusive); 0.506 is not.
    assert_eq!(check("4.1.json", &["--answer", "0.505 0.7 0.3"]).0, 0);
    assert_eq!(check("4.1.json", &["--answer", "0.506 0.7 0.3"]).0, 1);
    // Two decimals, correctly rounded, always pass: 0.25 for 0.245 (4.2's reading below).
    assert_eq!(
        check(
            "4.1.json",
            &["--answer", "0.506 0.7 0.3", "--tolerance", "0.01"]
        )
        .0,
        0
    );
}

#[test]
fn eight_bit_answers_accept_round_floor_and_ceil_of_255_c() {
    // 255·(0.5, 0.7, 0.3) = (127.5, 178.5, 76.5): 127/128, 178/179, 76/77 all within 1.
    for answer in ["128 179 77", "127 178 76", "#80B34D", "#7fb24c"] {
        let (code, out, _) = check("4.1.json", &["--answer", answer, "--scale", "255"]);
        assert_eq!(code, 0, "{answer}: {out}");
    }
    assert_eq!(
        check("4.1.json", &["--answer", "126 178 76", "--scale", "255"]).0,
        1
    );
    let (code, json) = check_json("4.1.json", &["--answer", "#80B34D"]);
    assert_eq!(code, 0);
    assert_eq!(json["answer"]["scale"], 255);
    assert_eq!(json["tolerance"], 1.0);
    assert_eq!(
        json["expected"]["color"],
        serde_json::json!([127.5, 178.5, 76.5])
    );
}

// Issue 28: one verdict everywhere. Three whole numbers 0–255, one above 1, written without
// a scale, are read as 8-bit values by the course policy's default, as `phong grade` reads
// them: 4.1's (0.5, 0.7, 0.3) is (127.5, 178.5, 76.5) on the 255 scale, and 128 179 77 lies
// within 1 of it. Judged on the 0–1 scale (`--scale 1`, or a policy whose "eight_bit" is
// "hint"), they are wrong, with the hint.
#[test]
fn an_answer_that_looks_8_bit_is_read_as_8_bit_unless_the_scale_is_given() {
    let (code, json) = check_json("4.1.json", &["--answer", "128 179 77"]);
    assert_eq!(code, 0);
    assert_eq!(json["verdict"], "right");
    assert_eq!(json["answer"]["scale"], 255);
    assert_eq!(json["answer"]["read_as_8bit"], true);
    assert_eq!(json["credit"], 1.0);
    let (code, out, _) = check("4.1.json", &["--answer", "128 179 77", "--scale", "1"]);
    assert_eq!(code, 1);
    assert!(out.contains("--scale 255"), "{out}");
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy("exercises/4.1.json", dir.path().join("4.1.json")).unwrap();
    std::fs::write(
        dir.path().join("course-policy.json"),
        r#"{"eight_bit": "hint"}"#,
    )
    .unwrap();
    let out = phong()
        .args(["check", "--answer", "128 179 77", "--lang", "en"])
        .arg(dir.path().join("4.1.json"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("--scale 255"));
}

#[test]
fn an_unclamped_answer_is_accepted_and_said_to_be_unclamped() {
    // O_a·I_a = (0.5, 0.4, 0.2)·(3, 1, 1) = (1.5, 0.4, 0.2); clamped (1, 0.4, 0.2).
    let f = temp_problem(
        r#"{"lights": [{"type": "ambient", "color": [3, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.4, 0.2]}}}"#,
    );
    for (answer, against) in [("1 0.4 0.2", "clamped"), ("1.5 0.4 0.2", "unclamped")] {
        let out = phong()
            .args(["check", "--format", "json", "--answer", answer])
            .arg(f.path())
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{answer}");
        let json: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(json["expected"]["against"], against);
    }
    // The 8-bit colour is always the clamped one: 255·(1, 0.4, 0.2) = (255, 102, 51).
    phong()
        .args(["check", "--answer", "255 102 51", "--scale", "255"])
        .arg(f.path())
        .assert()
        .code(0);
}

#[test]
fn the_4_2_answer_with_the_normal_reversed_exits_1_and_names_the_slip() {
    // The reversed normal (|cos θ|): diffuse only, 0.7·cos θ/d etc. = (0.245, 0.28, 0.21).
    let (code, out, _) = check("4.2.json", &["--answer", "0.245 0.28 0.21"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("wrong"), "{out}");
    assert!(out.contains("the normal reversed"), "{out}");
    assert!(out.contains("|cos θ| taken"), "{out}");
    assert!(
        out.contains("it matches the reading \"normal reversed\""),
        "{out}"
    );
}

#[test]
fn the_likely_intended_reading_of_4_2_is_accepted_unless_strict() {
    // L reversed: (0.299153, 0.361229, 0.318306); the problem as written gives (0, 0, 0).
    let (code, json) = check_json("4.2.json", &["--answer", "0.3 0.36 0.32"]);
    assert_eq!(code, 0);
    assert_eq!(json["verdict"], "reading");
    assert_eq!(json["accepted"], true);
    assert_eq!(json["reading"]["code"], "light_reversed");
    assert_eq!(json["expected"]["source"], "reading");
    let (code, json) = check_json("4.2.json", &["--answer", "0.3 0.36 0.32", "--strict"]);
    assert_eq!(code, 1);
    assert_eq!(json["verdict"], "reading");
    assert_eq!(json["accepted"], false);
    // Under --strict the answer is held against the problem as written, (0, 0, 0), which it
    // misses by its own values: the reports never show the reading's colour as "expected"
    // with every channel "within".
    assert_eq!(json["expected"]["source"], "solution", "{json}");
    assert_eq!(
        json["expected"]["color"],
        serde_json::json!([0.0, 0.0, 0.0])
    );
    assert_eq!(json["difference"], serde_json::json!([0.3, 0.36, 0.32]));
    let (_, md, _) = check(
        "4.2.json",
        &[
            "--answer",
            "0.3 0.36 0.32",
            "--strict",
            "--format",
            "markdown",
        ],
    );
    assert!(
        md.contains("- Expected: (0, 0, 0) `#000000` (the problem as written"),
        "{md}"
    );
    assert!(
        md.contains("| R | 0.3 | 0 | +0.3 | outside the tolerance |"),
        "{md}"
    );
    assert!(!md.contains("within the tolerance"), "{md}");
    assert!(!md.contains("- as written:"), "{md}");
    // The problem as written is right too.
    assert_eq!(check("4.2.json", &["--answer", "0 0 0"]).0, 0);
}

#[test]
fn exercise_4_3_has_no_colour_as_written_and_its_reading_is_accepted() {
    let (code, out, _) = check("4.3.json", &["--answer", "0.52 0.03 0"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("its ray hits nothing"), "{out}");
}

#[test]
fn an_unreadable_answer_exits_2_naming_the_option_and_the_forms() {
    let (code, json) = check_json("4.1.json", &["--answer", "0.5 0.7"]);
    assert_eq!(code, 2);
    assert_eq!(json["verdict"], "invalid");
    assert_eq!(json["error"]["kind"], "answer");
    assert_eq!(json["error"]["field"], "--answer");
    let (code, _, err) = check("4.1.json", &["--answer", "0.5 0.7 x"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--answer") && err.contains("three numbers such as"),
        "{err}"
    );
    let (code, _, err) = check("4.1.json", &["--answer", "300 0 0", "--scale", "255"]);
    assert_eq!(code, 2);
    assert!(err.contains("0–255"), "{err}");
}

/// The forms an unreadable answer's fix names give the course's word for "no hit": under a
/// policy whose only word is "vazio", the fix says "vazio", never "none" or "nenhuma", which
/// that course refuses.
#[test]
fn an_unreadable_answer_names_the_courses_no_hit_word() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy("exercises/4.3.json", dir.path().join("4.3.json")).unwrap();
    std::fs::write(
        dir.path().join("course-policy.json"),
        r#"{"no_hit": ["vazio"]}"#,
    )
    .unwrap();
    for (lang, answer) in [("en", "none"), ("pt", "nenhuma"), ("pt", "0.5 0.7")] {
        let out = phong()
            .args(["check", "--answer", answer, "--lang", lang])
            .arg(dir.path().join("4.3.json"))
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains("\"vazio\""), "{lang} {answer}: {err}");
        assert!(!err.contains("\"none\" when"), "{err}");
        assert!(!err.contains("\"nenhuma\" quando"), "{err}");
    }
    // Under the default words, each language's own.
    let (_, _, err) = check("4.3.json", &["--answer", "abc", "--lang", "pt"]);
    assert!(
        err.contains("\"nenhuma\" quando o raio não atinge nada"),
        "{err}"
    );
}

#[test]
fn bad_usage_exits_2() {
    phong()
        .args([
            "check",
            "exercises/4.1.json",
            "exercises/4.2.json",
            "--answer",
            "0 0 0",
        ])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--answer checks one file"));
    phong()
        .args([
            "check",
            "exercises/4.1.json",
            "--answer",
            "0 0 0",
            "--tolerance",
            "-1",
        ])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--tolerance"));
    phong()
        .args([
            "check",
            "exercises/4.1.json",
            "--answer",
            "0 0 0",
            "--scale",
            "100",
        ])
        .assert()
        .code(2);
}

#[test]
fn every_answer_key_of_the_chapter_checks_in_one_command() {
    phong()
        .args([
            "check",
            "exercises/4.1.json",
            "exercises/4.2.json",
            "exercises/4.3.json",
        ])
        .assert()
        .code(0);
}

#[test]
fn a_batch_of_keys_goes_on_past_bad_files_and_reports_each_in_order() {
    let wrong_key = temp_problem(
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.7, 0.3]}},
            "answer": {"color": [0.5, 0.7, 0.33], "tolerance": 0.05}}"#,
    );
    let broken = temp_problem("{");
    let out = phong()
        .args(["check", "--format", "json", "exercises/4.1.json"])
        .arg(broken.path())
        .arg(wrong_key.path())
        .arg("exercises/spot-edge.json")
        .arg("exercises/4.3.json")
        .output()
        .unwrap();
    // The worst outcome decides: a bad file (2) over a wrong key (1) over right (0).
    assert_eq!(out.status.code(), Some(2));
    let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
    let verdicts: Vec<&str> = docs
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["verdict"].as_str().unwrap())
        .collect();
    // The key's own tolerance 0.05 accepts 0.33 for 0.3.
    assert_eq!(verdicts, ["right", "invalid", "right", "invalid", "right"]);
    assert_eq!(docs[1]["error"]["kind"], "syntax");
    assert_eq!(docs[3]["error"]["kind"], "no_answer");
    assert_eq!(docs[2]["tolerance"], 0.05);
    assert_eq!(docs[2]["answer"]["source"], "key");
}

#[test]
fn a_wrong_key_exits_1() {
    let f = temp_problem(
        r##"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.7, 0.3]}}, "answer": "#FFFFFF"}"##,
    );
    phong().arg("check").arg(f.path()).assert().code(1);
}

#[test]
fn the_json_verdict_has_its_stable_fields() {
    let (_, json) = check_json("4.2.json", &["--answer", "0.245 0.28 0.21"]);
    let keys: Vec<&str> = json
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(
        keys,
        [
            "accepted",
            "answer",
            "credit",
            "diagnosis",
            "difference",
            "error",
            "expected",
            "file",
            "format_version",
            "message",
            "policy",
            "reading",
            "tolerance",
            "verdict"
        ]
    );
    assert_eq!(json["format_version"], 1);
    let d = &json["diagnosis"][0];
    for k in ["slips", "intended", "description", "color", "difference"] {
        assert!(d.get(k).is_some(), "{k}");
    }
}

#[test]
fn solve_ignores_the_answer_key() {
    // The key is checked by `phong check`; `phong solve` reads the file as before.
    phong()
        .args(["solve", "exercises/4.1.json"])
        .assert()
        .code(0)
        .stdout(predicate::str::contains("answer").not());
}

#[test]
fn a_mesh_is_found_beside_the_problem_file_as_solve_finds_it() {
    // A ray along −z meets a triangle of `sub/tri.obj`, named by `sub/problem.json` as
    // "tri.obj"; run from the folder above `sub`, check must read the same mesh as solve.
    // Ambient light only: O_a·I_a = (0.5, 0.4, 0.3).
    let dir = tempfile::TempDir::new().unwrap();
    let sub = dir.path().join("sub");
    std::fs::create_dir(&sub).unwrap();
    std::fs::write(
        sub.join("tri.obj"),
        "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    std::fs::write(
        sub.join("problem.json"),
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "ray": {"origin": [0, 0, 5], "direction": [0, 0, -1]},
            "surfaces": [{"type": "mesh", "file": "tri.obj",
                          "material": {"ambient": [0.5, 0.4, 0.3]}}],
            "answer": [0.5, 0.4, 0.3]}"#,
    )
    .unwrap();
    let run = |args: &[&str]| {
        support::phong()
            .current_dir(dir.path())
            .args(args)
            .output()
            .unwrap()
    };
    let solved = run(&["solve", "--format", "json", "sub/problem.json"]);
    assert_eq!(solved.status.code(), Some(0), "{solved:?}");
    let doc: Value = serde_json::from_slice(&solved.stdout).unwrap();
    let colour = &doc["solution"]["color"]["clamped"];
    assert_eq!(colour, &serde_json::json!([0.5, 0.4, 0.3]), "{doc}");
    let answer = format!("{} {} {}", colour[0], colour[1], colour[2]);
    for args in [
        vec![
            "check",
            "--format",
            "json",
            "sub/problem.json",
            "--answer",
            &answer,
        ],
        vec!["check", "--format", "json", "sub/problem.json"],
    ] {
        let checked = run(&args);
        let verdict: Value = serde_json::from_slice(&checked.stdout).unwrap();
        assert_eq!(checked.status.code(), Some(0), "{args:?}: {verdict}");
        assert_eq!(verdict["verdict"], "right", "{args:?}: {verdict}");
    }
}

#[test]
fn a_bad_answer_is_reported_before_an_invalid_problem() {
    // The point light has no falloff: the problem is invalid, and its key is reported first.
    let invalid = |key: &str| {
        temp_problem(&format!(
            r#"{{"lights": [{{"type": "point", "position": [1, 0, 0], "color": [1, 1, 1]}}],
                "point": {{"position": [0, 0, 0], "normal": [0, 0, 1],
                           "material": {{"diffuse": [1, 1, 1]}}}}{key}}}"#
        ))
    };
    let kind = |f: &tempfile::NamedTempFile, args: &[&str]| {
        let out = phong()
            .args(["check", "--format", "json"])
            .arg(f.path())
            .args(args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        let json: Value = serde_json::from_slice(&out.stdout).unwrap();
        json["error"]["kind"].as_str().unwrap().to_owned()
    };
    assert_eq!(kind(&invalid(""), &[]), "no_answer");
    assert_eq!(kind(&invalid(""), &["--answer", "0.1 0.2"]), "answer");
    let bad_key = invalid(r#", "answer": {"color": [1, 2, 3], "scale": 7}"#);
    assert_eq!(kind(&bad_key, &[]), "answer");
    assert_eq!(
        kind(&invalid(r#", "answer": [0.1, 0.2, 0.3]"#), &[]),
        "invalid"
    );
}

#[test]
fn portuguese_verdicts_use_the_chapters_terms() {
    let (code, out, _) = check("4.2.json", &["--answer", "0.245 0.28 0.21", "--lang", "pt"]);
    assert_eq!(code, 1);
    assert!(
        out.contains("errada") && out.contains("a normal invertida"),
        "{out}"
    );
}

// Snapshots: the verdicts a student sees for the chapter's exercises.

/// Rounds every non-integer number to 10 significant digits (as tests/snapshots.rs does), and
/// differences below 1e-12 (last-bit noise) to 0.
#[test]
fn exercise_4_3_accepts_no_hit_in_either_language_even_under_strict() {
    // As written the ray meets the plane at t = −90, behind its origin: it hits nothing.
    for answer in [
        "nenhuma",
        "none",
        "Sem interseção",
        "sem intersecao",
        "no hit",
        "—",
        "Nenhum",
    ] {
        let (code, out, err) = check("4.3.json", &["--answer", answer, "--strict"]);
        assert_eq!(code, 0, "{answer}: {out}{err}");
        assert!(out.contains(": right"), "{out}");
    }
    // The key says so too, and the line's colour is the likely intended reading.
    assert_eq!(check("4.3.json", &[]).0, 0);
    let (code, json) = check_json("4.3.json", &["--answer", "0.524 0.027 0"]);
    assert_eq!((code, json["verdict"].as_str()), (0, Some("reading")));
    assert_eq!(
        check("4.3.json", &["--answer", "0.524 0.027 0", "--strict"]).0,
        1
    );
    // A point problem always has a colour: "no hit" is wrong there, and the colour is shown.
    let (code, json) = check_json("4.1.json", &["--answer", "nenhuma"]);
    assert_eq!(code, 1);
    assert_eq!(
        json["expected"]["color"],
        serde_json::json!([0.5, 0.7, 0.3])
    );
    assert_eq!(json["answer"]["values"], Value::Null);
}

#[test]
fn the_keys_own_tolerance_judges_an_answer_given_on_the_command_line() {
    // O_a = (0.5, 0.7, 0.3) under white light; the key allows ±0.05. (0.53, 0.7, 0.3) is 0.03
    // off: wrong under the default ±0.005, right under the key's ±0.05 (before the fix the key's
    // tolerance was used only when the key itself was checked).
    let f = temp_problem(
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [0.5, 0.7, 0.3]}},
            "answer": {"color": [0.5, 0.7, 0.3], "tolerance": 0.05}}"#,
    );
    let out = phong()
        .args(["check", "--format", "json", "--answer", "0.53 0.7 0.3"])
        .arg(f.path())
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{json}");
    assert_eq!(json["tolerance"], 0.05);
    // On the 255 scale the key's 0.05 is 0.05·255 = 12.75: 255·0.5 = 127.5, so 140 is in.
    let out = phong()
        .args([
            "check",
            "--format",
            "json",
            "--scale",
            "255",
            "--answer",
            "140 179 77",
        ])
        .arg(f.path())
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{json}");
    assert!((json["tolerance"].as_f64().unwrap() - 12.75).abs() < 1e-9);
    // --tolerance still wins.
    let out = phong()
        .args(["check", "--answer", "0.53 0.7 0.3", "--tolerance", "0.01"])
        .arg(f.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn check_help_says_the_keys_tolerance_is_the_default() {
    let out = phong().args(["check", "--help"]).output().unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(help.contains("the key's"), "{help}");
    assert!(help.contains("--step"), "{help}");
}

// Exercise 4.2 by hand: L = ((3,1,3) − (1,1,1))/‖·‖ = (2, 0, 2)/(2√2) = (0.707107, 0, 0.707107);
// N·L = (0.6·2 + 0.8·2)/(2√2) = 2.8/(2√2) = 0.989949, so cos θ = −N·L = −0.989949 (Eq. 4.7): the
// light is behind the surface. In the likely intended reading (L reversed) cos θ = +0.989949.
#[test]
fn a_step_with_the_wrong_sign_of_cos_theta_is_wrong_as_written_and_names_eq_4_7() {
    let (code, out, _) = check("4.2.json", &["--step", "cos_theta=0.98995"]);
    assert!(out.contains("cos_theta[0]"), "{out}");
    assert!(out.contains("wrong as written"), "{out}");
    assert!(out.contains("Eq. 4.7"), "{out}");
    assert!(out.contains("-0.989949 (the sign differs)"), "{out}");
    assert!(out.contains("likely intended reading"), "{out}");
    assert!(
        out.contains("first wrong step as written: cos_theta[0] (Eq. 4.7"),
        "{out}"
    );
    // It is the likely intended reading's value: accepted as a reading, refused under --strict.
    assert_eq!(code, 0);
    assert_eq!(
        check("4.2.json", &["--step", "cos_theta=0.98995", "--strict"]).0,
        1
    );
    // The value as written is right.
    let (code, out, _) = check("4.2.json", &["--step", "cos_theta=-0.98995"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("every step given is right"), "{out}");
}

#[test]
fn steps_are_judged_in_the_order_of_the_solution_with_the_first_wrong_named() {
    // By hand (see above): d = 2√2 = 2.828427, I_l = 1/d = 0.353553 (linear falloff, Eq. 4.2);
    // quadratic by mistake gives 1/d² = 0.125. V = ((3,1,3) − (5,4,6))/√22 = (−0.4264, −0.6396,
    // −0.6396). R = L − 2(N·L)N = (0.707107 − 1.187939, 0, 0.707107 − 1.583919)
    // = (−0.480833, 0, −0.876812).
    let (code, json) = check_json(
        "4.2.json",
        &[
            "--step",
            "R=-0.48,0,-0.88",
            "--step",
            "I_l=0.125,0.125,0.125",
            "--step",
            "V=-0.426,-0.64,-0.64",
            "--step",
            "d=2.83",
        ],
    );
    assert_eq!(code, 1, "{json}");
    let steps = json["steps"]["steps"].as_array().unwrap();
    let names: Vec<&str> = steps.iter().map(|s| s["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["V", "d", "I_l", "R"]);
    let verdicts: Vec<&str> = steps
        .iter()
        .map(|s| s["verdict"].as_str().unwrap())
        .collect();
    assert_eq!(verdicts, ["right", "right", "wrong", "right"]);
    assert_eq!(
        steps[2]["slips"],
        serde_json::json!(["falloff_quadratic_not_linear"])
    );
    assert_eq!(json["steps"]["first_wrong"]["name"], "I_l");
    assert_eq!(json["steps"]["first_wrong"]["equation"], "4.2");
    assert_eq!(json["verdict"], "wrong");
}

#[test]
fn steps_from_a_file_and_in_portuguese() {
    let steps =
        temp_problem(r#"{"cos_theta": -0.98995, "L": [0.7071, 0, 0.7071], "diffuse": "0 0 0"}"#);
    let out = phong()
        .args(["check", "exercises/4.2.json", "--lang", "pt", "--steps"])
        .arg(steps.path())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(text.contains("passos"), "{text}");
    assert!(
        text.contains("todos os passos dados estão certos"),
        "{text}"
    );
}

#[test]
fn exercise_4_3s_steps_are_those_of_its_likely_intended_reading() {
    // The line meets the plane where (8 + 0.8t) + 4 + (6 − 0.6t) = 0: 18 + 0.2t = 0, t = −90,
    // P = (8 − 72, 4, 6 + 54) = (−64, 4, 60). The yellow light at (0, 0, 5):
    // L = (P − P_l)/‖·‖ = (−64, 4, 55)/√(4096 + 16 + 3025) = (−64, 4, 55)/84.4808
    //   = (−0.757569, 0.047348, 0.651036); N = (1, 1, 1)/√3; N·L = −0.059185/√3 … cos θ
    //   = −N·L = (0.757569 − 0.047348 − 0.651036)/√3 = 0.059185/1.732051 = 0.034171.
    let (code, out, _) = check(
        "4.3.json",
        &[
            "--step",
            "t=-90",
            "--step",
            "P=-64,4,60",
            "--step",
            "cos_theta=0.03417",
        ],
    );
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("t              = -90  right"), "{out}");
    assert!(out.contains("cos_theta[1]"), "{out}");
    assert!(out.contains("as written the ray hits nothing"), "{out}");
}

#[test]
fn bad_steps_exit_2_naming_the_names_and_the_lights() {
    let (code, _, err) = check("4.2.json", &["--step", "cos_thet=0.5"]);
    assert_eq!(code, 2);
    assert!(err.contains("cos_theta"), "{err}");
    let (code, _, err) = check("4.2.json", &["--step", "R=0.5"]);
    assert_eq!(code, 2);
    assert!(err.contains("three numbers"), "{err}");
    let (code, _, err) = check("4.3.json", &["--step", "cos_theta[0]=0.5"]);
    assert_eq!(code, 2);
    assert!(err.contains("ambient light"), "{err}");
    let (code, _, err) = check("4.2.json", &["--step", "cos_psi=0.5"]);
    assert_eq!(code, 2);
    assert!(err.contains("has no cos_psi"), "{err}");
}

#[test]
fn a_0_255_colour_is_a_warning_not_an_error() {
    let f = temp_problem(
        r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
            "point": {"material": {"ambient": [128, 179, 77]}}}"#,
    );
    let out = phong()
        .args(["check", "--format", "json", "--answer", "1 1 1"])
        .arg(f.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8(out.stderr).unwrap();
    // The warning names its file, as an error does (QA report A, finding 9).
    let named = format!("warning: {}: point.material.ambient", f.path().display());
    assert!(err.contains(&named), "{err}");
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["warnings"][0]["code"], "material_color_0_255");
    let out = phong()
        .arg("solve")
        .arg(f.path())
        .args(["--lang", "pt"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("divida por 255"), "{err}");
}

fn rounded(v: Value) -> Value {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap();
            let r: f64 = format!("{x:.9e}").parse().unwrap();
            let r = if r.abs() < 1e-12 { 0.0 } else { r };
            serde_json::Number::from_f64(r).map_or(Value::Null, Value::Number)
        }
        Value::Array(a) => Value::Array(a.into_iter().map(rounded).collect()),
        Value::Object(o) => Value::Object(o.into_iter().map(|(k, v)| (k, rounded(v))).collect()),
        other => other,
    }
}

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

const CASES: [(&str, &str, &str); 8] = [
    ("4.1", "4.1.json", "0.5 0.7 0.3"),
    ("4.1-8bit", "4.1.json", "#80B34D"),
    ("4.2-as-written", "4.2.json", "0 0 0"),
    ("4.2-light-reversed", "4.2.json", "0.299 0.361 0.318"),
    ("4.2-normal-reversed", "4.2.json", "0.245 0.28 0.21"),
    ("4.2-literal", "4.2.json", "-0.299 -0.361 -0.318"),
    ("4.3-line", "4.3.json", "0.52 0.03 0"),
    ("4.3-ambient-forgotten", "4.3.json", "0.024 0.027 0"),
];

#[test]
fn text_verdicts_on_the_chapters_exercises() {
    settings().bind(|| {
        for (name, file, answer) in CASES {
            let (_, out, _) = check(file, &["--answer", answer]);
            insta::assert_snapshot!(format!("check-text@{name}"), out);
        }
        let (_, out, _) = check("4.2.json", &["--answer", "0.245 0.28 0.21", "--lang", "pt"]);
        insta::assert_snapshot!("check-text-pt@4.2-normal-reversed", out);
    });
}

#[test]
fn json_verdicts_on_the_chapters_exercises() {
    settings().bind(|| {
        for (name, file, answer) in CASES {
            let (_, json) = check_json(file, &["--answer", answer]);
            insta::assert_json_snapshot!(format!("check-json@{name}"), rounded(json));
        }
    });
}

/// The `id`s of a page.
fn ids(html: &str) -> Vec<String> {
    html.match_indices(" id=\"")
        .map(|(i, m)| {
            let rest = &html[i + m.len()..];
            rest[..rest.find('"').unwrap()].to_owned()
        })
        .collect()
}

// Issue 33: `phong check --format html` writes the verdict as a page: the verdict and its
// credit, the answer's and the expected colour as swatches (each an image named in words), the
// channels against the tolerance in a table, and each slip the answer matches linked to the step
// of the worked solution (on the same page) where it departs. 4.2's 0.245 0.28 0.21 is |cos θ|
// (or the normal reversed): both depart at cos θ = −N·L, Eq. 4.7, of the problem as written.
#[test]
fn the_verdict_as_a_page_has_swatches_and_slips_linked_to_their_steps() {
    let (code, page, _) = check(
        "4.2.json",
        &[
            "--answer",
            "0.245 0.28 0.21",
            "--format",
            "html",
            "--lang",
            "en",
        ],
    );
    assert_eq!(code, 1);
    assert!(page.starts_with("<!DOCTYPE html>"), "{page}");
    assert!(!page.contains("<pre"));
    assert!(page.contains("<div class=\"verdict wrong\" data-verdict=\"wrong\""));
    assert!(
        page.contains("Credit: 0% of the exercise&#39;s points"),
        "{page}"
    );
    // Two swatches named in words: the answer's (0.245·255 = 62.5 → 62, 71.4 → 71, 53.55 → 54)
    // and the expected black.
    assert!(page.contains(
        "aria-label=\"Your answer: (0.245, 0.28, 0.21)\"><title>Your answer: (0.245, 0.28, \
         0.21)</title><rect width=\"1\" height=\"1\" fill=\"rgb(62,71,54)\"/>"
    ));
    assert!(page.contains("aria-label=\"Expected: (0, 0, 0)\""));
    // Each channel outside the tolerance, said in words, not only in colour.
    assert_eq!(
        page.matches("<td class=\"outside\">outside the tolerance</td>")
            .count(),
        3
    );
    // The slips' links land on steps of this page.
    let targets = ids(&page);
    let links: Vec<&str> = page
        .match_indices("href=\"#")
        .map(|(i, m)| {
            let rest = &page[i + m.len()..];
            &rest[..rest.find('"').unwrap()]
        })
        .collect();
    assert!(links.contains(&"part-0-0-eq-4-7"), "{links:?}");
    for l in &links {
        assert!(targets.iter().any(|t| t == l), "a link to nowhere: #{l}");
    }
    // The step it lands on is the cos θ of the problem as written.
    let at = page.find("id=\"part-0-0-eq-4-7\"").unwrap();
    assert!(
        page[at..at + 200].contains("Eq. 4.7"),
        "{}",
        &page[at..at + 200]
    );
}

// A right answer, the likely intended reading, a no-hit answer and a step check, as pages (and
// in Markdown): each verdict said in words, with its credit; the steps in a table, the first
// wrong one marked and linked to its step.
#[test]
fn every_kind_of_verdict_is_a_page_and_a_markdown_document() {
    for (file, args, verdict) in [
        ("4.1.json", vec!["--answer", "0.5 0.7 0.3"], "right"),
        ("4.2.json", vec!["--answer", "0.299 0.361 0.318"], "reading"),
        ("4.3.json", vec!["--answer", "nenhuma"], "right"),
        ("4.3.json", vec!["--answer", "0 0 0"], "wrong"),
    ] {
        let mut a = args.clone();
        a.extend(["--format", "html", "--lang", "pt"]);
        let (_, page, _) = check(file, &a);
        assert!(
            page.contains(&format!("data-verdict=\"{verdict}\"")),
            "{file} {args:?}"
        );
        assert!(page.contains("Crédito: "), "{file} {args:?}");
        assert!(page.contains("<html lang=\"pt-BR\">"), "{page}");
        let mut a = args.clone();
        a.extend(["--format", "markdown", "--lang", "en"]);
        let (_, md, _) = check(file, &a);
        assert!(md.contains("Credit: "), "{md}");
        assert!(md.starts_with("## "), "{md}");
    }
    // 4.2's steps: cos θ = 0.98995 is wrong as written (−N·L = −0.98995: the light is behind
    // the surface) and right in the likely intended reading (L reversed), which is accepted
    // (exit 0): the first step wrong as written is marked, and linked to cos θ's step.
    let (code, page, _) = check(
        "4.2.json",
        &[
            "--step",
            "cos_theta=0.98995",
            "--format",
            "html",
            "--lang",
            "en",
        ],
    );
    assert_eq!(code, 0);
    assert!(page.contains("<table class=\"judged\">"), "{page}");
    assert!(
        page.contains("<tr class=\"first-wrong\" data-step=\"cos_theta[0]\""),
        "{page}"
    );
    assert!(page.contains("(the first wrong step)"), "{page}");
    assert!(page.contains("href=\"#part-0-0-eq-4-7\""), "{page}");
    let (_, md, _) = check(
        "4.2.json",
        &[
            "--step",
            "cos_theta=0.98995",
            "--format",
            "markdown",
            "--lang",
            "en",
        ],
    );
    assert!(md.contains("| `cos_theta[0]` | 0.98995 |"), "{md}");
}

/// Every report of a verdict says the same of what an answer matches: the text report, the
/// HTML and Markdown pages and `phong grade`'s feedback (one list, `check::matches`, each
/// laying it out). The sentences with no colour of their own: "before clamping" for an answer
/// accepted as the unclamped colour, "no classic slip" for a wrong answer no slip explains
/// (the Markdown page left both out); for a ray that hits nothing, "as written, the problem
/// has no colour" said once (the text report said it twice, the feedback never); beside an
/// answer accepted as a likely intended reading, the problem as written's colour (4.2: black,
/// as no light reaches its lit side) or that it has none (4.3); a slip made in the likely
/// intended reading, said to be (the feedback left that out). Where the reports have an
/// expected line, what it shows is not said again: the nearest colour when it is that line's
/// and not a near miss; the feedback, a sentence, says it, and leaves "no colour" to the
/// background's own sentence.
#[test]
fn every_report_says_the_same_of_what_an_answer_matches() {
    let dir = tempfile::tempdir().unwrap();
    // O_a·I_a = (0.5, 0.4, 0.2)·(3, 1, 1) = (1.5, 0.4, 0.2); clamped (1, 0.4, 0.2).
    let unclamped = r#"{"lights": [{"type": "ambient", "color": [3, 1, 1]}],
        "point": {"material": {"ambient": [0.5, 0.4, 0.2]}}}"#;
    // The ray along −z from (0, 0, 10) passes the sphere at x = 5 (radius 2) by 3.
    let miss = r#"{"lights": [{"type": "ambient", "color": [1, 1, 1]}],
        "ray": {"origin": [0, 0, 10], "direction": [0, 0, -1]},
        "surfaces": [{"type": "sphere", "center": [5, 0, 0], "radius": 2,
                      "material": {"ambient": [1, 1, 1]}}]}"#;
    std::fs::write(dir.path().join("unclamped.json"), unclamped).unwrap();
    std::fs::write(dir.path().join("miss.json"), miss).unwrap();
    let exercises = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises");
    for e in ["4.1", "4.2", "4.3"] {
        let name = format!("{e}.json");
        std::fs::copy(exercises.join(&name), dir.path().join(&name)).unwrap();
    }
    let no_colour = "as written, the problem has no colour";
    // (exercise, answer, sentence, times said by the text report, the HTML page, the Markdown
    // page, the feedback)
    let cases = [
        (
            "unclamped",
            "1.5 0.4 0.2",
            "accepted as the colour before clamping",
            [1, 1, 1, 1],
        ),
        (
            "unclamped",
            "0.1 0.9 0.9",
            "no classic slip (nor pair of slips) gives it",
            [1; 4],
        ),
        ("miss", "0.5 0.5 0.5", no_colour, [1, 1, 1, 1]),
        ("miss", "0 0 0", "black is the background", [1, 1, 1, 1]),
        ("miss", "0 0 0", no_colour, [1, 1, 1, 0]),
        (
            "4.2",
            "0.299 0.361 0.318",
            "as written (0, 0, 0)",
            [1, 1, 1, 1],
        ),
        // V reversed, made in 4.2's likely intended reading (L reversed): the feedback left the
        // reading out.
        (
            "4.2",
            "0.245 0.28 0.21",
            "V reversed: taken from the point to the eye",
            [1; 4],
        ),
        (
            "4.2",
            "0.245 0.28 0.21",
            "(in the likely intended reading)",
            [1; 4],
        ),
        // 4.3's likely intended reading, the hit behind the origin: (0.524, 0.027, 0).
        ("4.3", "0.524 0.027 0", no_colour, [1, 1, 1, 1]),
        // 4.1 as written is (0.5, 0.7, 0.3), the expected line's colour: 0.2 away is no near
        // miss, 0.02 is.
        (
            "4.1",
            "0.5 0.5 0.5",
            "the nearest is the problem as written",
            [0, 0, 0, 1],
        ),
        (
            "4.1",
            "0.52 0.7 0.3",
            "close to the problem as written",
            [1, 1, 1, 1],
        ),
    ];
    let mut csv = String::from("student,exercise,answer\n");
    for (i, (exercise, answer, _, _)) in cases.iter().enumerate() {
        csv.push_str(&format!(
            "s{i},{exercise},\"{}\"\n",
            answer.replace(' ', ",")
        ));
    }
    let submissions = dir.path().join("submissions.csv");
    std::fs::write(&submissions, csv).unwrap();
    let out = phong()
        .args(["grade", "--lang", "en", "--format", "json", "--exercises"])
        .arg(dir.path())
        .arg(&submissions)
        .output()
        .unwrap();
    let graded: Value = serde_json::from_slice(&out.stdout).unwrap();
    let feedback = |i: usize| {
        let rows = graded["rows"].as_array().unwrap();
        let row = rows.iter().find(|r| r["student"] == format!("s{i}"));
        row.unwrap()["feedback"].as_str().unwrap().to_owned()
    };
    for (i, (exercise, answer, sentence, times)) in cases.into_iter().enumerate() {
        let file = dir.path().join(format!("{exercise}.json"));
        let mut reports = Vec::new();
        for format in ["text", "html", "markdown"] {
            let out = phong()
                .args([
                    "check", "--lang", "en", "--format", format, "--answer", answer,
                ])
                .arg(&file)
                .output()
                .unwrap();
            reports.push((format, String::from_utf8(out.stdout).unwrap()));
        }
        reports.push(("feedback", feedback(i)));
        for ((format, report), times) in reports.into_iter().zip(times) {
            // A colour after "as written": on the text report's padded line, or after a colon.
            let said = report.split_whitespace().collect::<Vec<_>>().join(" ");
            let said = said.replace("as written:", "as written");
            assert_eq!(
                said.matches(sentence).count(),
                times,
                "{exercise} {answer}, {format}: {report}"
            );
            // The Markdown page's colours as code, not escaped.
            if format == "markdown" && exercise == "4.2" {
                assert!(report.contains("(0, 0, 0) `#000000`"), "{report}");
            }
        }
    }
}
