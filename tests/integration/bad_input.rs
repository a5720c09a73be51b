//! Bad input: `phong solve` must never crash on it, never print NaN or infinity, and always say
//! where the problem is and how to fix it. Every rejection is checked for: exit code 2; standard
//! error naming the file, the field (or `FILE:LINE:COL` for broken JSON) and a fix; no panic; and,
//! with `--format json`, an `"error"` object (kind, field, message) in place of the solution.
//!
//! Each case starts from a valid problem ([`point_problem`], [`ray_problem`]) and breaks exactly
//! one thing, so the field the message must name is known. Also here: a bad file in a batch loses
//! no entry, `--output` is never left half-written, and every shipped exercise solves cleanly.

use crate::support;

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use predicates::prelude::*;
use serde_json::{json, Value};
use tempfile::TempDir;

/// The exit code for bad input.
const BAD_INPUT: i32 = 2;

// ---------------------------------------------------------------------------------------------
// Valid problems that the cases break
// ---------------------------------------------------------------------------------------------

/// A point problem with one light of each kind (so `lights[1]` is the point light, `lights[2]`
/// the directional light and `lights[3]` the spot light), every material field and a viewer.
/// The point is lit from the front by all of them.
fn point_problem() -> Value {
    json!({
        "title": "base point problem",
        "materials": { "M": material() },
        "lights": [
            { "type": "ambient", "color": [0.2, 0.2, 0.2] },
            { "type": "point", "position": [3, 1, 6], "color": [1, 1, 1], "falloff": 1 },
            { "type": "directional", "direction": [0, 0, -1], "color": [0.5, 0.5, 0.5] },
            {
                "type": "spot", "position": [3, 1, 8], "axis": [0, 0, -1], "angle": 30,
                "exponent": 1, "color": [1, 1, 0], "falloff": 2
            }
        ],
        "viewer": [5, 4, 6],
        "point": { "position": [3, 1, 3], "normal": [0, 0, 1], "material": "M" }
    })
}

/// A ray problem: the ray from (0, 0, 5) straight down meets the plane z = 0 at t = 5, exactly
/// at the origin. `lights[1]` is a point light.
fn ray_problem() -> Value {
    json!({
        "title": "base ray problem",
        "materials": { "M": material() },
        "lights": [
            { "type": "ambient", "color": [0.2, 0.2, 0.2] },
            { "type": "point", "position": [1, 0, 2], "color": [1, 1, 1], "falloff": 0 }
        ],
        "viewer": [0, 3, 4],
        "ray": { "origin": [0, 0, 5], "direction": [0, 0, -1] },
        "surfaces": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "M" }
        ]
    })
}

fn material() -> Value {
    json!({
        "ambient": [0.5, 0.4, 0.6],
        "diffuse": [0.7, 0.8, 0.6],
        "specular": [0.2, 0.3, 0.4],
        "shininess": 2
    })
}

/// `problem` with the value at the JSON pointer `at` replaced by `value` (created if absent).
fn with(mut problem: Value, at: &str, value: Value) -> Value {
    let (parent, key) = at.rsplit_once('/').expect("a JSON pointer");
    let parent = problem
        .pointer_mut(parent)
        .unwrap_or_else(|| panic!("no {parent} in the base problem"));
    match parent {
        Value::Object(map) => {
            map.insert(key.to_owned(), value);
        }
        Value::Array(items) => items[key.parse::<usize>().expect("an index")] = value,
        _ => panic!("{at} is not inside an object or array"),
    }
    problem
}

/// `problem` without the member at the JSON pointer `at`.
fn without(mut problem: Value, at: &str) -> Value {
    let (parent, key) = at.rsplit_once('/').expect("a JSON pointer");
    let removed = problem
        .pointer_mut(parent)
        .and_then(Value::as_object_mut)
        .and_then(|map| map.remove(key));
    assert!(removed.is_some(), "no {at} in the base problem");
    problem
}

fn pretty(problem: &Value) -> String {
    serde_json::to_string_pretty(problem).expect("a JSON value serialises")
}

// ---------------------------------------------------------------------------------------------
// Running phong and checking what it says
// ---------------------------------------------------------------------------------------------

/// What one run of `phong` gave.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

fn phong(args: &[&str]) -> Run {
    let out = crate::support::phong()
        .args(args)
        .output()
        .expect("phong runs");
    Run {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

fn utf8(path: &Path) -> &str {
    path.to_str().expect("temporary paths are UTF-8")
}

/// A number printed as NaN or infinity (`NaN`, `inf`, `-inf`, `infinity`), but not words such as
/// "finite" or "infinite".
fn shows_nan_or_inf() -> impl Predicate<str> {
    predicate::str::is_match(r"(?i)\b(nan|inf|infinity)\b").expect("a valid pattern")
}

fn panicked() -> impl Predicate<str> {
    predicate::str::contains("panicked")
}

/// Collects every unmet expectation of one case, so that a failure lists them all at once.
#[derive(Default)]
struct Checks {
    failures: Vec<String>,
}

impl Checks {
    fn expect(&mut self, ok: bool, what: impl Into<String>) {
        if !ok {
            self.failures.push(what.into());
        }
    }

    fn contains(&mut self, text: &str, part: &str, label: &str) {
        self.expect(
            predicate::str::contains(part).eval(text),
            format!("{label} does not contain {part:?}"),
        );
    }

    fn clean(&mut self, run: &Run, label: &str) {
        self.expect(
            !panicked().eval(&run.stderr),
            format!("{label}: phong panicked"),
        );
        self.expect(
            !shows_nan_or_inf().eval(&run.stdout),
            format!("{label}: standard output shows NaN or inf"),
        );
    }

    fn finish(self, context: &str) {
        assert!(
            self.failures.is_empty(),
            "{context}\n\nunmet expectations:\n  - {}",
            self.failures.join("\n  - ")
        );
    }
}

/// What a rejection must say.
#[derive(Clone, Copy)]
struct Expect<'a> {
    /// The field path, such as `lights[1].falloff`. `None` only where no field is to blame:
    /// broken JSON syntax (the position stands in for it) or a file that cannot be read.
    field: Option<&'a str>,
    /// Phrases that say what is wrong and how to fix it.
    says: &'a [&'a str],
}

/// Runs `phong solve FILE --precision P` in both formats and checks the rejection. Returns the
/// standard error of the text run.
fn check_rejected(path: &Path, precision: &str, expect: Expect) -> String {
    let file = utf8(path);
    let mut c = Checks::default();
    let mut context = String::new();

    // Text: the message goes to standard error.
    let text = phong(&["solve", file, "--precision", precision]);
    let label = format!("text, {precision}");
    c.expect(
        text.code == Some(BAD_INPUT),
        format!("{label}: exit code {:?}, expected {BAD_INPUT}", text.code),
    );
    c.clean(&text, &label);
    c.contains(&text.stderr, file, &format!("{label}: stderr (the file)"));
    if let Some(field) = expect.field {
        c.contains(&text.stderr, field, &format!("{label}: stderr (the field)"));
    }
    c.contains(&text.stderr, "Fix:", &format!("{label}: stderr (a fix)"));
    for phrase in expect.says {
        c.contains(&text.stderr, phrase, &format!("{label}: stderr"));
    }
    context += &format!("--- {label}: stderr ---\n{}\n", text.stderr);

    // JSON: the error takes the place of the solution, and is also reported on stderr.
    let js = phong(&["solve", file, "--precision", precision, "--format", "json"]);
    let label = format!("json, {precision}");
    c.expect(
        js.code == Some(BAD_INPUT),
        format!("{label}: exit code {:?}, expected {BAD_INPUT}", js.code),
    );
    c.clean(&js, &label);
    c.contains(&js.stderr, file, &format!("{label}: stderr (the file)"));
    match serde_json::from_str::<Value>(&js.stdout) {
        Ok(doc) => {
            let error = &doc["error"];
            c.expect(error.is_object(), format!("{label}: no \"error\" object"));
            c.expect(
                doc["file"] == file,
                format!("{label}: \"file\" is {}, expected {file:?}", doc["file"]),
            );
            c.expect(
                ["syntax", "invalid", "read"].contains(&error["kind"].as_str().unwrap_or("")),
                format!("{label}: error.kind is {}", error["kind"]),
            );
            let message = error["message"].as_str().unwrap_or("");
            c.contains(message, file, &format!("{label}: error.message"));
            if let Some(field) = expect.field {
                c.expect(
                    error["field"] == field,
                    format!(
                        "{label}: error.field is {}, expected {field:?}",
                        error["field"]
                    ),
                );
                c.contains(message, field, &format!("{label}: error.message"));
            }
            for phrase in expect.says {
                c.contains(message, phrase, &format!("{label}: error.message"));
            }
        }
        Err(e) => c.expect(false, format!("{label}: stdout is not JSON ({e})")),
    }
    context += &format!(
        "--- {label}: stdout ---\n{}\n--- {label}: stderr ---\n{}",
        js.stdout, js.stderr
    );

    c.finish(&format!(
        "phong solve {file} --precision {precision}\n{context}"
    ));
    text.stderr
}

/// A bad problem file in its own temporary folder.
struct BadFile {
    _dir: TempDir,
    path: PathBuf,
    /// Standard error of the text run in the first precision checked.
    stderr: String,
}

/// Writes `text` to a problem file in a new temporary folder and checks that `phong solve`
/// rejects it in each of `precisions`, in both formats, as `expect` says.
fn rejected_text(text: &str, precisions: &[&str], expect: Expect) -> BadFile {
    let dir = TempDir::new().expect("a temporary folder");
    let path = dir.path().join("problem-under-test.json");
    fs::write(&path, text).expect("the problem is written");
    let mut stderr = None;
    for precision in precisions {
        let s = check_rejected(&path, precision, expect);
        stderr.get_or_insert(s);
    }
    BadFile {
        _dir: dir,
        path,
        stderr: stderr.expect("at least one precision"),
    }
}

/// Checks that `problem` is rejected in both precisions, naming `field` and saying `says`.
fn rejected(problem: &Value, field: &str, says: &[&str]) -> BadFile {
    rejected_text(
        &pretty(problem),
        &["f64", "f32"],
        Expect {
            field: Some(field),
            says,
        },
    )
}

/// Checks that `text` solves with exit code 0 and no NaN or inf, in `precision` and both formats.
fn check_solves(text: &str, precision: &str) {
    let dir = TempDir::new().expect("a temporary folder");
    let path = dir.path().join("valid.json");
    fs::write(&path, text).expect("the problem is written");
    for format in ["text", "json"] {
        let run = phong(&[
            "solve",
            utf8(&path),
            "--precision",
            precision,
            "--format",
            format,
        ]);
        let mut c = Checks::default();
        c.expect(run.code == Some(0), format!("exit code {:?}", run.code));
        c.clean(&run, format);
        c.finish(&format!(
            "{format}, {precision}: a valid problem must solve\n{text}\n--- stdout ---\n{}\n--- stderr ---\n{}",
            run.stdout, run.stderr
        ));
    }
}

/// The `LINE:COL` right after `FILE:` in `stderr`.
fn position_after(stderr: &str, file: &str) -> Option<(usize, usize)> {
    let rest = &stderr[stderr.find(&format!("{file}:"))? + file.len() + 1..];
    let mut parts = rest.splitn(3, ':');
    let line = parts.next()?.parse().ok()?;
    let column = parts.next()?.parse().ok()?;
    Some((line, column))
}

// ---------------------------------------------------------------------------------------------
// The base problems are valid: each case below breaks exactly one thing
// ---------------------------------------------------------------------------------------------

#[test]
fn the_base_problems_solve_in_both_precisions() {
    for problem in [point_problem(), ray_problem()] {
        for precision in ["f64", "f32"] {
            check_solves(&pretty(&problem), precision);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Broken JSON
// ---------------------------------------------------------------------------------------------

/// The comma after `"viewer": [5, 4, 6]` (line 5) is missing; the parser meets `"point"` where it
/// expected `,` or `}`: line 6, column 3.
const MISSING_COMMA: &str = r#"{
  "materials": {
    "M": { "diffuse": [0.7, 0.8, 0.6] }
  },
  "viewer": [5, 4, 6]
  "point": { "position": [3, 1, 3], "normal": [0, 0, 1], "material": "M" }
}
"#;

#[test]
fn malformed_json_is_rejected_with_its_line_and_column() {
    let bad = rejected_text(
        MISSING_COMMA,
        &["f64", "f32"],
        Expect {
            field: None,
            says: &["comma"],
        },
    );
    let at = format!("{}:6:3: ", utf8(&bad.path));
    assert!(
        bad.stderr.contains(&at),
        "expected the position {at:?} in:\n{}",
        bad.stderr
    );
}

#[test]
fn malformed_json_does_not_name_a_meaningless_field() {
    let bad = rejected_text(
        MISSING_COMMA,
        &["f64"],
        Expect {
            field: None,
            says: &[],
        },
    );
    // serde_path_to_error writes an unknown path segment as `?`; that is no field name.
    assert!(
        !bad.stderr.contains(": ?"),
        "the message shows the placeholder path `?`:\n{}",
        bad.stderr
    );
}

#[test]
fn a_truncated_file_is_rejected_at_its_end() {
    let text = "{\n  \"viewer\": [5, 4, 6],\n  \"lights\": [\n";
    let bad = rejected_text(
        text,
        &["f64"],
        Expect {
            field: None,
            says: &["ends too early"],
        },
    );
    let (line, _) = position_after(&bad.stderr, utf8(&bad.path))
        .unwrap_or_else(|| panic!("no FILE:LINE:COL in:\n{}", bad.stderr));
    assert!(
        (3..=4).contains(&line),
        "the file ends on line 3 (or 4), the message says line {line}:\n{}",
        bad.stderr
    );
}

/// A point problem whose material's ambient colour is `color`, written as given (one line, so
/// that the array stays on the line the parser stops at).
fn with_ambient_color(color: &str) -> String {
    format!(
        "{{\n  \"lights\": [{{ \"type\": \"ambient\", \"color\": [1, 1, 1] }}],\n  \
         \"point\": {{ \"material\": {{ \"ambient\": {{ \"k\": 1, \"color\": {color} }} }} }}\n}}\n"
    )
}

#[test]
fn a_colour_mixing_decimal_commas_with_points_is_named_as_a_decimal_comma() {
    // A student writes one number or two with a comma, the others with a point: JSON reads
    // four or five numbers. The message is the one every comma gets, with the numbers mended;
    // no triangle.
    for (written, fixed) in [
        ("[0,5, 0.7, 0.3]", "[0.5, 0.7, 0.3]"),
        ("[0.5, 0,7, 0,3]", "[0.5, 0.7, 0.3]"),
        ("[1, 0,5, 0]", "[1, 0.5, 0]"),
    ] {
        let bad = rejected_text(
            &with_ambient_color(written),
            &["f64"],
            Expect {
                field: Some("point.material.ambient.color"),
                says: &[
                    &format!("{written} has numbers written with a decimal comma"),
                    &format!("Fix: write {fixed}"),
                ],
            },
        );
        assert!(!bad.stderr.contains("triangle"), "{}", bad.stderr);
        let pt = phong(&["solve", utf8(&bad.path), "--lang", "pt"]);
        assert_eq!(pt.code, Some(BAD_INPUT), "{}", pt.stderr);
        for says in [
            format!(
                "point.material.ambient.color: {written} tem números escritos com vírgula decimal"
            ),
            format!("Correção: escreva {fixed}"),
        ] {
            assert!(pt.stderr.contains(&says), "{says:?} not in:\n{}", pt.stderr);
        }
        assert!(!pt.stderr.contains("triângulo"), "{}", pt.stderr);
    }
    // Three integers, as JSON reads them, are a colour: [1, 0, 5] is no decimal comma.
    check_solves(&with_ambient_color("[1, 0, 5]"), "f64");
}

#[test]
fn an_array_too_long_names_a_triangle_only_for_a_triangle_s_vertices() {
    // A colour of four numbers: three numbers, and nothing about triangles.
    let bad = rejected_text(
        &with_ambient_color("[1, 1, 1, 1]"),
        &["f64"],
        Expect {
            field: Some("point.material.ambient.color"),
            says: &["Fix: give exactly three numbers [x, y, z]"],
        },
    );
    assert!(!bad.stderr.contains("triangle"), "{}", bad.stderr);
    let pt = phong(&["solve", utf8(&bad.path), "--lang", "pt"]);
    assert!(
        pt.stderr
            .contains("Correção: dê exatamente três números [x, y, z]"),
        "{}",
        pt.stderr
    );
    assert!(!pt.stderr.contains("triângulo"), "{}", pt.stderr);
    // A triangle of four vertices: a triangle has three.
    let four = with(
        ray_problem(),
        "/surfaces/0",
        json!({
            "type": "triangle",
            "vertices": [[-1, -1, 0], [1, -1, 0], [0, 1, 0], [0, 0, 1]],
            "material": "M"
        }),
    );
    let bad = rejected(
        &four,
        "surfaces[0].vertices",
        &["three vertices", "triangle"],
    );
    let pt = phong(&["solve", utf8(&bad.path), "--lang", "pt"]);
    assert!(
        pt.stderr.contains("três vértices") && pt.stderr.contains("triângulo"),
        "{}",
        pt.stderr
    );
}

// ---------------------------------------------------------------------------------------------
// Missing and unknown fields
// ---------------------------------------------------------------------------------------------

#[test]
fn a_point_light_without_falloff_is_rejected_naming_the_field_and_its_purpose() {
    let problem = without(point_problem(), "/lights/1/falloff");
    rejected(
        &problem,
        "lights[1].falloff",
        &["missing", "falloff", "quadratic"],
    );
}

#[test]
fn a_material_without_the_specular_colour_a_viewer_needs_is_rejected() {
    let problem = without(point_problem(), "/materials/M/specular");
    rejected(
        &problem,
        "materials.M.specular",
        &["missing", "specular term", "Eq. 4.10", "viewer"],
    );
}

#[test]
fn a_material_without_the_shininess_a_viewer_needs_is_rejected() {
    let problem = without(point_problem(), "/materials/M/shininess");
    rejected(&problem, "materials.M.shininess", &["missing", "n_s"]);
}

#[test]
fn a_material_without_the_ambient_colour_an_ambient_light_needs_is_rejected() {
    let problem = without(point_problem(), "/materials/M/ambient");
    rejected(
        &problem,
        "materials.M.ambient",
        &["missing", "ambient term", "Eq. 4.6"],
    );
}

#[test]
fn a_material_without_the_diffuse_colour_a_light_needs_is_rejected() {
    let problem = without(point_problem(), "/materials/M/diffuse");
    rejected(
        &problem,
        "materials.M.diffuse",
        &["missing", "diffuse term", "Eq. 4.8"],
    );
}

#[test]
fn an_inline_material_missing_a_field_is_named_under_the_point() {
    let mut inline = material();
    inline
        .as_object_mut()
        .expect("a material object")
        .remove("specular");
    let problem = with(point_problem(), "/point/material", inline);
    rejected(&problem, "point.material.specular", &["Eq. 4.10"]);
}

#[test]
fn an_unknown_material_field_is_rejected_and_named() {
    let m = with(
        point_problem(),
        "/materials/M/difuse",
        json!([0.7, 0.8, 0.6]),
    );
    let problem = without(m, "/materials/M/diffuse");
    rejected(
        &problem,
        "materials.M.difuse",
        &["unknown field", "spelling"],
    );
}

#[test]
fn an_unknown_light_field_is_rejected_and_named() {
    let problem = with(point_problem(), "/lights/1/falof", json!(2));
    rejected(&problem, "lights[1].falof", &["unknown field", "spelling"]);
}

#[test]
fn an_unknown_top_level_field_is_rejected_and_named() {
    let problem = with(point_problem(), "/veiwer", json!([5, 4, 6]));
    rejected(&problem, "veiwer", &["unknown field", "spelling"]);
}

// ---------------------------------------------------------------------------------------------
// Zero-length directions
// ---------------------------------------------------------------------------------------------

#[test]
fn a_zero_length_normal_is_rejected() {
    let problem = with(point_problem(), "/point/normal", json!([0, 0, 0]));
    rejected(&problem, "point.normal", &["zero vector", "non-zero"]);
}

#[test]
fn a_zero_length_ray_direction_is_rejected() {
    let problem = with(ray_problem(), "/ray/direction", json!([0, 0, 0]));
    rejected(&problem, "ray.direction", &["zero vector", "non-zero"]);
}

#[test]
fn a_zero_length_plane_normal_is_rejected() {
    let problem = with(ray_problem(), "/surfaces/0/normal", json!([0, 0, 0]));
    rejected(&problem, "surfaces[0].normal", &["zero vector", "non-zero"]);
}

#[test]
fn a_zero_length_spot_axis_is_rejected() {
    let problem = with(point_problem(), "/lights/3/axis", json!([0, 0, 0]));
    rejected(&problem, "lights[3].axis", &["zero vector", "non-zero"]);
}

#[test]
fn a_zero_length_directional_direction_is_rejected() {
    let problem = with(point_problem(), "/lights/2/direction", json!([0, 0, 0]));
    rejected(
        &problem,
        "lights[2].direction",
        &["zero vector", "non-zero"],
    );
}

#[test]
fn a_normal_that_underflows_to_zero_in_f32_is_rejected_in_f32() {
    let problem = with(point_problem(), "/point/normal", json!([1e-50, 0, 0]));
    check_solves(&pretty(&problem), "f64");
    rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("point.normal"),
            says: &["zero vector", "f32"],
        },
    );
}

// ---------------------------------------------------------------------------------------------
// Numbers that are not finite
// ---------------------------------------------------------------------------------------------

/// The point problem, pretty-printed, with `viewer[1]` written as `1e999` (beyond f64).
/// Returns the text and the line and column span of `1e999`.
fn with_1e999() -> (String, usize, (usize, usize)) {
    let problem = with(point_problem(), "/viewer", json!([5, "HUGE", 6]));
    let text = pretty(&problem).replace("\"HUGE\"", "1e999");
    let offset = text.find("1e999").expect("the huge number is in the text");
    let line = text[..offset].matches('\n').count() + 1;
    let start = offset - text[..offset].rfind('\n').map_or(0, |i| i + 1) + 1;
    (text, line, (start, start + "1e999".len() - 1))
}

#[test]
fn a_number_beyond_f64_is_rejected_with_its_line_column_and_field() {
    let (text, line, (first, last)) = with_1e999();
    let bad = rejected_text(
        &text,
        &["f64", "f32"],
        Expect {
            field: Some("viewer[1]"),
            says: &[],
        },
    );
    let (l, c) = position_after(&bad.stderr, utf8(&bad.path))
        .unwrap_or_else(|| panic!("no FILE:LINE:COL in:\n{}", bad.stderr));
    assert!(
        l == line && (first..=last).contains(&c),
        "1e999 is on line {line}, columns {first}–{last}; the message says {l}:{c}:\n{}",
        bad.stderr
    );
}

#[test]
fn a_number_beyond_f64_gets_a_fix_about_the_number_not_about_commas() {
    let (text, _, _) = with_1e999();
    let bad = rejected_text(
        &text,
        &["f64"],
        Expect {
            field: None,
            says: &[],
        },
    );
    let fix = bad.stderr.split_once("Fix:").map_or("", |(_, f)| f);
    let about_the_number = ["finite", "too large", "too big", "largest", "1.8e308"]
        .iter()
        .any(|w| fix.contains(w));
    assert!(
        about_the_number && !fix.contains("comma"),
        "the fix should say the number is too large (not finite), not point at a comma:\n{}",
        bad.stderr
    );
}

#[test]
fn a_number_finite_in_f64_but_infinite_in_f32_is_rejected_in_f32_naming_the_field() {
    let problem = with(point_problem(), "/lights/1/position", json!([1e300, 1, 6]));
    check_solves(&pretty(&problem), "f64");
    rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("lights[1].position[0]"),
            says: &["f32", "f64"],
        },
    );
}

#[test]
fn a_shininess_infinite_in_f32_is_rejected_in_f32_naming_the_field() {
    let problem = with(point_problem(), "/materials/M/shininess", json!(1e300));
    check_solves(&pretty(&problem), "f64");
    rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("materials.M.shininess"),
            says: &["f32", "f64"],
        },
    );
}

#[test]
fn a_huge_number_is_quoted_briefly_not_as_hundreds_of_digits() {
    let problem = with(point_problem(), "/lights/1/position", json!([1e300, 1, 6]));
    let bad = rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("lights[1].position[0]"),
            says: &[],
        },
    );
    let long_digits = predicate::str::is_match(r"\d{25}").expect("a valid pattern");
    assert!(
        !long_digits.eval(&bad.stderr),
        "1e300 should be written as 1e300 (as in the file), not as 301 digits:\n{}",
        bad.stderr
    );
}

// ---------------------------------------------------------------------------------------------
// Values out of range
// ---------------------------------------------------------------------------------------------

#[test]
fn negative_shininess_is_rejected() {
    let problem = with(point_problem(), "/materials/M/shininess", json!(-1));
    rejected(&problem, "materials.M.shininess", &["negative", "≥ 0"]);
}

#[test]
fn falloff_outside_0_1_2_is_rejected() {
    for falloff in [json!(3), json!(1.5), json!(-1)] {
        let problem = with(point_problem(), "/lights/1/falloff", falloff);
        rejected(&problem, "lights[1].falloff", &["linear", "quadratic"]);
    }
}

#[test]
fn a_spot_falloff_outside_0_1_2_is_rejected() {
    let problem = with(point_problem(), "/lights/3/falloff", json!(1.5));
    rejected(&problem, "lights[3].falloff", &["linear", "quadratic"]);
}

#[test]
fn a_spot_angle_outside_0_90_is_rejected() {
    for angle in [95, -1] {
        let problem = with(point_problem(), "/lights/3/angle", json!(angle));
        rejected(&problem, "lights[3].angle", &["90"]);
    }
}

#[test]
fn spot_angles_of_exactly_0_and_90_degrees_are_accepted() {
    for angle in [0, 90] {
        let problem = with(point_problem(), "/lights/3/angle", json!(angle));
        for precision in ["f64", "f32"] {
            check_solves(&pretty(&problem), precision);
        }
    }
}

#[test]
fn a_negative_spot_exponent_is_rejected() {
    let problem = with(point_problem(), "/lights/3/exponent", json!(-1));
    rejected(&problem, "lights[3].exponent", &["negative", "≥ 0"]);
}

#[test]
fn a_k_coefficient_outside_0_1_is_rejected() {
    for k in [1.5, -0.5] {
        let colour = json!({ "k": k, "color": [0.7, 0.8, 0.6] });
        let problem = with(point_problem(), "/materials/M/diffuse", colour);
        rejected(&problem, "materials.M.diffuse.k", &["[0, 1]"]);
    }
}

#[test]
fn a_negative_material_colour_component_is_rejected() {
    let problem = with(
        point_problem(),
        "/materials/M/diffuse",
        json!([0.7, -0.1, 0.6]),
    );
    rejected(&problem, "materials.M.diffuse", &["negative", "≥ 0"]);
}

#[test]
fn a_negative_colour_under_a_k_coefficient_is_rejected() {
    let colour = json!({ "k": 0.5, "color": [0.7, -0.1, 0.6] });
    let problem = with(point_problem(), "/materials/M/specular", colour);
    rejected(&problem, "materials.M.specular.color", &["negative", "≥ 0"]);
}

#[test]
fn a_negative_light_colour_component_is_rejected() {
    let problem = with(point_problem(), "/lights/1/color", json!([1, -1, 1]));
    rejected(&problem, "lights[1].color", &["negative", "≥ 0"]);
}

#[test]
fn a_sphere_of_radius_0_or_less_is_rejected() {
    for radius in [0.0, -1.0] {
        let sphere =
            json!({ "type": "sphere", "center": [0, 0, 0], "radius": radius, "material": "M" });
        let problem = with(ray_problem(), "/surfaces/0", sphere);
        rejected(&problem, "surfaces[0].radius", &["radius > 0"]);
    }
}

// ---------------------------------------------------------------------------------------------
// Degenerate geometry: L or V undefined
// ---------------------------------------------------------------------------------------------

#[test]
fn a_point_light_exactly_at_the_point_is_rejected() {
    let problem = with(point_problem(), "/lights/1/position", json!([3, 1, 3]));
    rejected(&problem, "lights[1].position", &["Eq. 4.1", "move"]);
}

#[test]
fn a_spot_light_exactly_at_the_point_is_rejected() {
    let problem = with(point_problem(), "/lights/3/position", json!([3, 1, 3]));
    rejected(&problem, "lights[3].position", &["Eq. 4.1", "move"]);
}

#[test]
fn a_light_that_meets_the_point_only_in_f32_is_rejected_in_f32() {
    // 3.00000001 rounds to 3 in f32.
    let problem = with(
        point_problem(),
        "/lights/1/position",
        json!([3.00000001, 1, 3]),
    );
    check_solves(&pretty(&problem), "f64");
    rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("lights[1].position"),
            says: &["Eq. 4.1", "move"],
        },
    );
}

#[test]
fn a_viewer_exactly_at_the_point_is_rejected() {
    let problem = with(point_problem(), "/viewer", json!([3, 1, 3]));
    rejected(&problem, "viewer", &["move"]);
}

#[test]
fn a_light_exactly_at_the_ray_hit_point_is_rejected() {
    let problem = with(ray_problem(), "/lights/1/position", json!([0, 0, 0]));
    rejected(&problem, "lights[1].position", &["Eq. 4.1", "move"]);
}

#[test]
fn a_viewer_exactly_at_the_ray_hit_point_is_rejected() {
    let problem = with(ray_problem(), "/viewer", json!([0, 0, 0]));
    rejected(&problem, "viewer", &["move"]);
}

// ---------------------------------------------------------------------------------------------
// The shape of the problem
// ---------------------------------------------------------------------------------------------

#[test]
fn an_undefined_material_name_is_rejected_listing_the_defined_ones() {
    let problem = with(point_problem(), "/point/material", json!("Q"));
    rejected(&problem, "point.material", &["\"Q\"", "\"M\""]);
}

#[test]
fn an_undefined_surface_material_name_is_rejected() {
    let problem = with(ray_problem(), "/surfaces/0/material", json!("Q"));
    rejected(&problem, "surfaces[0].material", &["\"Q\"", "\"M\""]);
}

#[test]
fn a_problem_with_both_point_and_ray_is_rejected() {
    let point = point_problem()["point"].clone();
    let problem = with(ray_problem(), "/point", point);
    rejected(&problem, "ray", &["\"point\"", "\"ray\"", "not both"]);
}

#[test]
fn a_problem_with_neither_point_nor_ray_is_rejected() {
    let problem = without(point_problem(), "/point");
    rejected(&problem, "point", &["nothing to shade", "\"ray\""]);
}

// ---------------------------------------------------------------------------------------------
// Files
// ---------------------------------------------------------------------------------------------

#[test]
fn a_file_that_does_not_exist_is_rejected() {
    let dir = TempDir::new().expect("a temporary folder");
    let path = dir.path().join("no-such-problem.json");
    for precision in ["f64", "f32"] {
        check_rejected(
            &path,
            precision,
            Expect {
                field: None,
                says: &["cannot read"],
            },
        );
    }
}

/// A `course-policy.json` beside the exercises that is a folder, or a link to nothing, is the
/// course's policy failing to read: `phong policy`, `check` and `grade` stop (exit 2) naming
/// it. They took it for no policy and judged by the defaults, saying "there is no
/// course-policy.json".
#[test]
fn a_course_policy_that_is_a_folder_or_a_broken_link_stops_the_command() {
    let dir = TempDir::new().expect("a temporary folder");
    let folder = dir.path().join("broken-link");
    fs::create_dir(&folder).expect("created");
    std::os::unix::fs::symlink(
        dir.path().join("nowhere.json"),
        folder.join("course-policy.json"),
    )
    .expect("linked");
    let other = dir.path().join("a-folder");
    fs::create_dir_all(other.join("course-policy.json")).expect("created");
    for folder in [folder, other] {
        fs::write(folder.join("4.1.json"), pretty(&point_problem())).expect("written");
        let csv = folder.join("answers.csv");
        fs::write(
            &csv,
            "student,exercise,answer
a,4.1,0 0 0
",
        )
        .expect("written");
        let policy = folder.join("course-policy.json").display().to_string();
        for args in [
            vec!["policy".to_owned(), folder.display().to_string()],
            vec![
                "check".to_owned(),
                folder.join("4.1.json").display().to_string(),
                "--answer".to_owned(),
                "0 0 0".to_owned(),
            ],
            vec![
                "grade".to_owned(),
                "--exercises".to_owned(),
                folder.display().to_string(),
                csv.display().to_string(),
            ],
        ] {
            let out = crate::support::phong()
                .args(&args)
                .args(["--lang", "en"])
                .output()
                .expect("phong runs");
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(BAD_INPUT), "{args:?}: {err}");
            assert!(
                err.contains(&format!("{policy}: cannot read the course policy")),
                "{args:?}: {err}"
            );
        }
    }
}

#[test]
fn the_course_policy_given_as_a_problem_names_the_folder_given_in_its_fix() {
    // `phong solve exercicios/*.json` where `exercicios/course-policy.json` is the course
    // policy: the fix lists the problems of that folder, as written, not of `exercises/`.
    let dir = TempDir::new().expect("a temporary folder");
    let folder = dir.path().join("exercicios");
    fs::create_dir(&folder).expect("created");
    fs::write(folder.join("4.1.json"), pretty(&point_problem())).expect("written");
    fs::write(folder.join("course-policy.json"), "{ \"strict\": true }\n").expect("written");
    let run = |at: &Path, args: &[&str]| {
        let out = crate::support::phong()
            .current_dir(at)
            .args(args)
            .output()
            .expect("phong runs");
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let given = ["exercicios/4.1.json", "exercicios/course-policy.json"];
    let (code, _, en) = run(dir.path(), &[&["solve"], &given[..]].concat());
    assert_eq!(code, Some(BAD_INPUT), "{en}");
    assert!(
        en.contains(
            "exercicios/course-policy.json:1:1: this is the course policy (tolerances, credit, \
             points), not a problem. Fix: leave it out of the problem files \
             (exercicios/4.*.json, not exercicios/*.json)"
        ),
        "{en}"
    );
    assert!(!en.contains("exercises/"), "{en}");
    let (code, _, pt) = run(
        dir.path(),
        &[&["solve", "--lang", "pt"], &given[..]].concat(),
    );
    assert_eq!(code, Some(BAD_INPUT), "{pt}");
    assert!(
        pt.contains(
            "Correção: deixe-a fora dos arquivos de problema (exercicios/4.*.json, não \
             exercicios/*.json)"
        ),
        "{pt}"
    );
    // The JSON error keeps its kind and (no) field.
    let (_, out, _) = run(
        dir.path(),
        &["solve", "exercicios/course-policy.json", "--format", "json"],
    );
    let doc: Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(doc["error"]["kind"], "syntax", "{doc}");
    assert_eq!(doc["error"]["field"], Value::Null, "{doc}");
    assert!(
        doc["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("(exercicios/4.*.json, not exercicios/*.json)")),
        "{doc}"
    );
    // Given from inside the folder, with no folder written: the names alone.
    let (code, _, en) = run(&folder, &["solve", "4.1.json", "course-policy.json"]);
    assert_eq!(code, Some(BAD_INPUT), "{en}");
    assert!(
        en.contains("Fix: leave it out of the problem files (4.*.json, not *.json)"),
        "{en}"
    );
    // A policy of the defaults (`{}`, or an empty file) would read as an empty problem ("nothing
    // to shade"): it is named as the course policy too.
    for defaults in ["{}\n", ""] {
        fs::write(folder.join("course-policy.json"), defaults).expect("written");
        let (code, _, en) = run(&folder, &["solve", "4.1.json", "course-policy.json"]);
        assert_eq!(code, Some(BAD_INPUT), "{en}");
        assert!(
            en.contains("course-policy.json:1:1: this is the course policy"),
            "{defaults:?}: {en}"
        );
        assert!(!en.contains("nothing to shade"), "{defaults:?}: {en}");
    }
}

/// A folder with `good.json` (the point problem), `bad.json` (falloff 3) and `good2.json` (the ray
/// problem).
fn batch_folder() -> (TempDir, [PathBuf; 3]) {
    let dir = TempDir::new().expect("a temporary folder");
    let good = dir.path().join("good.json");
    let bad = dir.path().join("bad.json");
    let good2 = dir.path().join("good2.json");
    fs::write(&good, pretty(&point_problem())).expect("written");
    fs::write(
        &bad,
        pretty(&with(point_problem(), "/lights/1/falloff", json!(3))),
    )
    .expect("written");
    fs::write(&good2, pretty(&ray_problem())).expect("written");
    (dir, [good, bad, good2])
}

/// The JSON document `phong solve FILE --format json` gives for one good file.
fn solved_alone(path: &Path) -> Value {
    let run = phong(&["solve", utf8(path), "--format", "json"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    serde_json::from_str(&run.stdout).expect("JSON output")
}

/// Checks the 3-entry batch document: the good files solved as when alone, the bad one an error.
fn check_batch_document(doc: &Value, files: &[PathBuf; 3]) {
    let entries = doc.as_array().expect("a batch prints a JSON array");
    assert_eq!(entries.len(), 3, "one entry per file, none dropped");
    for (entry, path) in entries.iter().zip(files) {
        assert_eq!(entry["file"], utf8(path), "entries in the order given");
    }
    for i in [0, 2] {
        assert!(
            entries[i].get("error").is_none(),
            "{} is good",
            files[i].display()
        );
        assert_eq!(
            entries[i],
            solved_alone(&files[i]),
            "a good file's entry is what it gives alone"
        );
    }
    let error = &entries[1]["error"];
    assert_eq!(error["kind"], "invalid");
    assert_eq!(error["field"], "lights[1].falloff");
    let message = error["message"].as_str().expect("a message");
    assert!(message.contains(utf8(&files[1])), "{message}");
    assert!(message.contains("lights[1].falloff"), "{message}");
    assert!(message.contains("quadratic"), "{message}");
}

#[test]
fn a_batch_with_a_bad_file_exits_2_and_keeps_every_entry_in_order() {
    let (_dir, files) = batch_folder();
    let [good, bad, good2] = &files;
    let assert = support::phong()
        .args([
            "solve",
            utf8(good),
            utf8(bad),
            utf8(good2),
            "--format",
            "json",
        ])
        .assert()
        .code(BAD_INPUT)
        .stdout(shows_nan_or_inf().not())
        .stderr(predicate::str::contains(utf8(bad)))
        .stderr(predicate::str::contains("lights[1].falloff"))
        .stderr(predicate::str::contains(utf8(good)).not())
        .stderr(panicked().not());
    let doc: Value =
        serde_json::from_slice(&assert.get_output().stdout).expect("stdout is one JSON document");
    check_batch_document(&doc, &files);
}

#[test]
fn a_batch_in_text_still_prints_the_good_files() {
    let (_dir, files) = batch_folder();
    let [good, bad, good2] = &files;
    support::phong()
        .args(["solve", utf8(good), utf8(bad), utf8(good2)])
        .assert()
        .code(BAD_INPUT)
        .stdout(predicate::str::contains("base point problem"))
        .stdout(predicate::str::contains("base ray problem"))
        .stdout(shows_nan_or_inf().not())
        .stderr(predicate::str::contains(utf8(bad)))
        .stderr(predicate::str::contains("lights[1].falloff"))
        .stderr(panicked().not());
}

#[test]
fn a_batch_names_the_field_of_a_parse_error_in_its_json_entry() {
    let dir = TempDir::new().expect("a temporary folder");
    let good = dir.path().join("good.json");
    let typo = dir.path().join("typo.json");
    let missing = dir.path().join("missing.json");
    fs::write(&good, pretty(&point_problem())).expect("written");
    let m = with(
        point_problem(),
        "/materials/M/difuse",
        json!([0.7, 0.8, 0.6]),
    );
    fs::write(&typo, pretty(&without(m, "/materials/M/diffuse"))).expect("written");
    let assert = support::phong()
        .args([
            "solve",
            utf8(&typo),
            utf8(&good),
            utf8(&missing),
            "--format",
            "json",
        ])
        .assert()
        .code(BAD_INPUT)
        .stderr(panicked().not());
    let doc: Value =
        serde_json::from_slice(&assert.get_output().stdout).expect("stdout is one JSON document");
    let entries = doc.as_array().expect("a JSON array");
    assert_eq!(entries.len(), 3, "one entry per file, none dropped");
    assert_eq!(entries[0]["error"]["kind"], "syntax");
    assert!(entries[1].get("error").is_none());
    assert_eq!(entries[2]["error"]["kind"], "read");
    assert_eq!(entries[2]["file"], utf8(&missing));
    assert_eq!(
        entries[0]["error"]["field"], "materials.M.difuse",
        "the field is known (the message names it) and belongs in error.field"
    );
}

// ---------------------------------------------------------------------------------------------
// --output
// ---------------------------------------------------------------------------------------------

fn folder_entries(dir: &Path) -> BTreeSet<String> {
    fs::read_dir(dir)
        .expect("the folder is readable")
        .map(|e| {
            e.expect("an entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .collect()
}

#[test]
fn output_to_a_file_with_a_bad_input_exits_2_and_leaves_only_the_complete_document() {
    let (dir, files) = batch_folder();
    let [good, bad, good2] = &files;
    let out = dir.path().join("out.json");
    support::phong()
        .args([
            "solve",
            utf8(good),
            utf8(bad),
            utf8(good2),
            "--format",
            "json",
            "--output",
            utf8(&out),
        ])
        .assert()
        .code(BAD_INPUT)
        .stdout(predicate::str::is_empty())
        .stderr(predicate::str::contains(utf8(bad)))
        .stderr(predicate::str::contains("lights[1].falloff"))
        .stderr(panicked().not());

    // No temporary file is left behind; the output file, if written, is the whole document.
    let names = folder_entries(dir.path());
    let inputs: BTreeSet<String> = ["good.json", "bad.json", "good2.json"]
        .map(String::from)
        .into();
    let mut with_out = inputs.clone();
    with_out.insert("out.json".into());
    assert!(
        names == inputs || names == with_out,
        "unexpected files in the output folder: {names:?}"
    );
    if out.exists() {
        let text = fs::read_to_string(&out).expect("the output is readable");
        assert!(!shows_nan_or_inf().eval(&text), "{text}");
        let doc: Value = serde_json::from_str(&text).expect("the output is one complete document");
        check_batch_document(&doc, &files);
    }
}

#[test]
fn output_over_an_existing_file_with_a_bad_input_is_never_partial() {
    let (dir, files) = batch_folder();
    let [good, bad, good2] = &files;
    let out = dir.path().join("out.json");
    let old = "{\"old\": true}\n";
    fs::write(&out, old).expect("written");
    let run = phong(&[
        "solve",
        utf8(good),
        utf8(bad),
        utf8(good2),
        "--format",
        "json",
        "--output",
        utf8(&out),
    ]);
    assert_eq!(run.code, Some(BAD_INPUT), "{}", run.stderr);
    assert!(!panicked().eval(&run.stderr), "{}", run.stderr);
    assert_eq!(
        folder_entries(dir.path()),
        ["bad.json", "good.json", "good2.json", "out.json"]
            .map(String::from)
            .into(),
        "no temporary file is left behind"
    );
    let text = fs::read_to_string(&out).expect("the output is readable");
    if text != old {
        let doc: Value = serde_json::from_str(&text).expect("the output is one complete document");
        check_batch_document(&doc, &files);
    }
}

#[test]
fn output_into_a_folder_that_does_not_exist_exits_2_without_panicking() {
    let (dir, files) = batch_folder();
    let good = &files[0];
    let out = dir.path().join("no-such-folder").join("out.json");
    support::phong()
        .args(["solve", utf8(good), "--output", utf8(&out)])
        .assert()
        .code(BAD_INPUT)
        .stderr(predicate::str::contains(utf8(&out)))
        .stderr(panicked().not());
    assert!(!out.exists());
    assert!(!dir.path().join("no-such-folder").exists());
}

/// `phong solve A/p.json B/p.json -o DIR/`: both would be written to DIR/p.txt, the second
/// over the first (QA: exit 0, one problem silently dropped). Refused before anything is
/// written, naming both inputs and the file they would share; the same when the names differ
/// only in case (one file on macOS and Windows), and when a file is given twice. A folder that
/// holds an older p.txt keeps it.
#[test]
fn two_inputs_sharing_a_file_in_the_output_folder_are_refused_naming_both() {
    let dir = TempDir::new().expect("a temporary folder");
    for sub in ["a", "b"] {
        fs::create_dir(dir.path().join(sub)).expect("created");
    }
    let first = dir.path().join("a").join("p.json");
    let second = dir.path().join("b").join("p.json");
    let upper = dir.path().join("b").join("P.json");
    fs::write(&first, pretty(&point_problem())).expect("written");
    fs::write(&second, pretty(&ray_problem())).expect("written");
    fs::write(&upper, pretty(&ray_problem())).expect("written");
    let out = format!("{}/", dir.path().join("od").display());
    let shared = format!("{out}p.txt");
    for inputs in [[&first, &second], [&first, &upper], [&first, &first]] {
        let run = support::phong()
            .arg("solve")
            .args(inputs)
            .args(["-o", &out])
            .output()
            .expect("phong runs");
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(BAD_INPUT), "{inputs:?}: {err}");
        assert!(run.stdout.is_empty());
        for named in [utf8(inputs[0]), utf8(inputs[1]), &shared] {
            assert!(err.contains(named), "{inputs:?}: {named} not in {err}");
        }
        assert!(err.contains("Fix: "), "{err}");
        assert!(err.contains("separate folders"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(
            !dir.path().join("od").exists(),
            "{inputs:?}: a folder was made"
        );
    }
    // Into a folder that exists: its file is left as it was.
    fs::create_dir(dir.path().join("od")).expect("created");
    fs::write(&shared, "OLD\n").expect("written");
    support::phong()
        .args(["solve", utf8(&first), utf8(&second), "-o", &out])
        .assert()
        .code(BAD_INPUT);
    assert_eq!(fs::read_to_string(&shared).expect("kept"), "OLD\n");
    assert_eq!(folder_entries(&dir.path().join("od")).len(), 1);
    // Different names: each written, named after its input.
    let other = dir.path().join("b").join("q.json");
    fs::write(&other, pretty(&ray_problem())).expect("written");
    support::phong()
        .args(["solve", utf8(&first), utf8(&other), "-o", &out])
        .args(["--format", "markdown"])
        .assert()
        .code(0);
    assert_eq!(
        folder_entries(&dir.path().join("od")),
        ["p.md", "p.txt", "q.md"].map(String::from).into()
    );
}

/// `phong solve --format json ex/p.json -o ex/` would write ex/p.json, its own input: refused
/// as `-o ex/p.json` is, the input left as it was.
#[test]
fn a_file_in_the_output_folder_never_replaces_an_input() {
    let dir = TempDir::new().expect("a temporary folder");
    let input = dir.path().join("p.json");
    let text = pretty(&point_problem());
    fs::write(&input, &text).expect("written");
    let out = format!("{}/", dir.path().display());
    support::phong()
        .args(["solve", utf8(&input), "--format", "json", "-o", &out])
        .assert()
        .code(BAD_INPUT)
        .stderr(predicate::str::contains(utf8(&input)))
        .stderr(predicate::str::contains("is the input"))
        .stderr(panicked().not());
    assert_eq!(fs::read_to_string(&input).expect("kept"), text);
}

// ---------------------------------------------------------------------------------------------
// The shipped exercises are all good
// ---------------------------------------------------------------------------------------------

#[test]
fn every_exercise_solves_in_both_precisions_and_formats_without_nan_or_inf() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("exercises");
    let mut exercises: Vec<PathBuf> = fs::read_dir(&folder)
        .expect("the exercises folder is readable")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    exercises.sort();
    assert!(
        exercises.len() >= 3,
        "the chapter's exercises 4.1–4.3 at least: {exercises:?}"
    );
    let mut c = Checks::default();
    for path in &exercises {
        for precision in ["f64", "f32"] {
            for format in ["text", "json"] {
                let run = phong(&[
                    "solve",
                    utf8(path),
                    "--precision",
                    precision,
                    "--format",
                    format,
                ]);
                let label = format!("{} ({precision}, {format})", path.display());
                c.expect(
                    run.code == Some(0),
                    format!("{label}: exit code {:?}: {}", run.code, run.stderr),
                );
                c.expect(!run.stdout.is_empty(), format!("{label}: no output"));
                c.clean(&run, &label);
                if format == "json" {
                    match serde_json::from_str::<Value>(&run.stdout) {
                        Ok(doc) => c.expect(
                            doc.get("error").is_none(),
                            format!("{label}: an error entry"),
                        ),
                        Err(e) => c.expect(false, format!("{label}: not JSON ({e})")),
                    }
                }
            }
        }
    }
    c.finish("every exercise must solve cleanly");
}

/// A field name or a `type` word thousands of characters long (a pasted blob, a fuzzer's key) is
/// named shortened, with its length, in the message and the JSON's `field`: the message stays a
/// few lines, whatever was written. Found by the fuzz test of `phong serve`'s API, whose answers
/// must be of bounded size.
#[test]
fn a_very_long_unknown_name_is_echoed_shortened() {
    let dir = TempDir::new().expect("a temporary folder");
    let long = "x".repeat(10_000);
    let cases = [
        ("field", {
            let mut p = point_problem();
            p[&long] = json!(1);
            p
        }),
        ("type", {
            let mut p = point_problem();
            p["lights"][1]["type"] = json!(long.clone());
            p
        }),
    ];
    for (what, problem) in cases {
        let file = dir.path().join(format!("{what}.json"));
        fs::write(&file, pretty(&problem)).expect("written");
        let run = phong(&["solve", utf8(&file), "--format", "json"]);
        assert_eq!(run.code, Some(BAD_INPUT), "{what}");
        assert!(
            run.stderr.len() < 1_000,
            "{what}: the message is {} bytes long",
            run.stderr.len()
        );
        assert!(
            run.stderr.contains("10000 characters"),
            "{what}: {}",
            run.stderr
        );
        let doc: Value = serde_json::from_str(&run.stdout).expect("a JSON document");
        let field = doc["error"]["field"].as_str().unwrap_or("");
        assert!(field.len() < 200, "{what}: field {} bytes", field.len());
        assert!(doc["error"]["message"].as_str().unwrap_or("").len() < 1_000);
    }
}

// ---------------------------------------------------------------------------------------------
// Coordinates too large for the precision, a sphere too small for it, a policy of another type
// ---------------------------------------------------------------------------------------------

/// The triangle with corners (−x, −x, 0), (x, −x, 0) and (0, x, 0): it holds the point (0, 0, 0)
/// where the base ray problem's ray meets the plane z = 0.
fn triangle(x: f64) -> Value {
    json!({ "type": "triangle", "vertices": [[-x, -x, 0], [x, -x, 0], [0, x, 0]],
            "material": "M" })
}

/// A triangle whose coordinates are too large for the ray–triangle test of the precision is
/// refused as too large, naming the coordinate and the bound that works: at ±1e308 its edges
/// overflowed and it was refused as "on one line"; at ±1e300 it was accepted, and the ray that
/// meets it at (0, 0, 0) missed it (the test's products overflowed), without a word.
#[test]
fn a_triangle_too_large_for_the_precision_is_refused_naming_the_bound_that_works() {
    for x in [1e308, 1e300, 2e100] {
        let problem = with(ray_problem(), "/surfaces/0", triangle(x));
        let bad = rejected_text(
            &pretty(&problem),
            &["f64"],
            Expect {
                field: Some("surfaces[0].vertices[0][0]"),
                says: &["too large for a triangle", "within ±1e100"],
            },
        );
        assert!(!bad.stderr.contains("one line"), "{}", bad.stderr);
        assert!(!bad.stderr.contains("--precision f64"), "{}", bad.stderr);
    }
    // In f32 the bound is 1e12, and f64 is a way out: the same triangle solves there.
    let problem = with(ray_problem(), "/surfaces/0", triangle(1e13));
    let bad = rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("surfaces[0].vertices[0][0]"),
            says: &[
                "too large for a triangle",
                "within ±1e12",
                "--precision f64",
            ],
        },
    );
    let pt = phong(&[
        "solve",
        utf8(&bad.path),
        "--precision",
        "f32",
        "--lang",
        "pt",
    ]);
    assert!(
        pt.stderr
            .contains("grande demais para um vértice de triângulo em f32")
            && pt.stderr.contains("dentro de ±1e12"),
        "{}",
        pt.stderr
    );
    // At the bound, the ray from the bound itself meets the triangle (at t = 1e100 in f64,
    // 1e12 in f32): the bound is one that works, not only one that is refused past.
    for (precision, x) in [("f64", 1e100), ("f32", 1e12)] {
        let problem = with(ray_problem(), "/surfaces/0", triangle(x));
        let problem = with(problem, "/ray/origin", json!([0, 0, x]));
        let problem = with(problem, "/lights/1/position", json!([0, 0, x / 2.0]));
        check_solves(&pretty(&problem), precision);
        let dir = TempDir::new().expect("a temporary folder");
        let path = dir.path().join("at-the-bound.json");
        fs::write(&path, pretty(&problem)).expect("written");
        let run = phong(&["solve", utf8(&path), "--precision", precision]);
        assert!(
            run.code == Some(0) && !run.stdout.contains("meets no surface"),
            "{precision}: {}{}",
            run.stdout,
            run.stderr
        );
    }
}
/// A sphere of centre (0, 0, z) and radius r for the base ray problem.
fn sphere(z: f64, r: f64) -> Value {
    json!({ "type": "sphere", "center": [0, 0, z], "radius": r, "material": "M" })
}

/// A ray's origin, a sphere's centre and radius and a plane's point past the bound the
/// intersection tests can multiply are refused, naming the coordinate and the bound that works,
/// as a triangle's corner is. Before, each was taken: the ray from (0, 0, 5) straight down the
/// axis of a sphere of radius 1e199 centred 1e200 below missed it (its discriminant
/// (r − 0)(r + 0) = 1e398 overflowed), and a ray from 1e200 missed a triangle around the
/// origin, each without a word ("the ray's line meets no surface").
#[test]
fn a_far_point_or_a_huge_sphere_is_refused_naming_the_bound_that_works() {
    let within = "within ±1e100";
    let cases = [
        (
            with(ray_problem(), "/ray/origin", json!([0, 0, 1e200])),
            "ray.origin[2]",
            "1e200 is too large for the ray's origin in f64",
            within,
        ),
        (
            with(ray_problem(), "/surfaces/0", sphere(-1e200, 1e199)),
            "surfaces[0].radius",
            "1e199 is too large for a sphere's radius in f64",
            "a radius of at most 1e100",
        ),
        (
            with(ray_problem(), "/surfaces/0", sphere(-1e200, 1.0)),
            "surfaces[0].center[2]",
            "-1e200 is too large for a sphere's centre in f64",
            within,
        ),
        (
            with(ray_problem(), "/surfaces/0/point", json!([0, 0, -1e200])),
            "surfaces[0].point[2]",
            "-1e200 is too large for a plane's point in f64",
            within,
        ),
        (
            with(
                with(ray_problem(), "/ray/origin", json!([0, 0, 1e200])),
                "/surfaces/0",
                triangle(1.0),
            ),
            "ray.origin[2]",
            "1e200 is too large for the ray's origin in f64",
            within,
        ),
    ];
    for (problem, field, says, bound) in &cases {
        let bad = rejected_text(
            &pretty(problem),
            &["f64"],
            Expect {
                field: Some(field),
                says: &[says, bound],
            },
        );
        assert!(!bad.stderr.contains("--precision f64"), "{}", bad.stderr);
    }
    // In f32 the bound is 1e12, and f64 is a way out: the same problem solves there.
    let problem = with(ray_problem(), "/ray/origin", json!([0, 0, 1e13]));
    let bad = rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("ray.origin[2]"),
            says: &[
                "too large for the ray's origin in f32",
                "within ±1e12",
                "--precision f64",
            ],
        },
    );
    check_solves(&pretty(&problem), "f64");
    let pt = phong(&[
        "solve",
        utf8(&bad.path),
        "--precision",
        "f32",
        "--lang",
        "pt",
    ]);
    assert!(
        pt.stderr
            .contains("grande demais para a origem do raio em f32")
            && pt.stderr.contains("dentro de ±1e12"),
        "{}",
        pt.stderr
    );
    let problem = with(ray_problem(), "/surfaces/0", sphere(-1e13, 1e13));
    rejected_text(
        &pretty(&problem),
        &["f32"],
        Expect {
            field: Some("surfaces[0].radius"),
            says: &["too large for a sphere's radius in f32", "at most 1e12"],
        },
    );
    // At the bound the tests hold: the ray from (0, 0, B) down the axis meets the sphere of
    // radius B centred at (0, 0, −B) at its top, the origin, at t = B.
    for (precision, b) in [("f64", 1e100), ("f32", 1e12)] {
        let problem = with(ray_problem(), "/ray/origin", json!([0, 0, b]));
        let problem = with(problem, "/surfaces/0", sphere(-b, b));
        let problem = with(problem, "/lights/1/position", json!([0, 0, b / 2.0]));
        check_solves(&pretty(&problem), precision);
        let dir = TempDir::new().expect("a temporary folder");
        let path = dir.path().join("at-the-bound.json");
        fs::write(&path, pretty(&problem)).expect("written");
        let run = phong(&[
            "solve",
            utf8(&path),
            "--precision",
            precision,
            "--format",
            "json",
        ]);
        let doc: Value = serde_json::from_str(&run.stdout).expect("a JSON document");
        let hit = &doc["intersection"];
        let t = hit["t"].as_f64().unwrap_or(f64::NAN);
        let z = hit["point"][2].as_f64().unwrap_or(f64::NAN);
        assert!(
            hit["hit"] == json!(true) && (t / b - 1.0).abs() < 1e-6 && z.abs() <= b * 1e-6,
            "{precision}: {hit}"
        );
    }
}

/// A camera whose eye is past the bound is refused before anything is traced, naming the
/// coordinate (and look_at as well): before, the eye at 1e200 looking at a sphere that fills
/// the view rendered the background alone (every ray's discriminant overflowed).
#[test]
fn a_camera_too_far_away_is_refused_and_no_image_is_written() {
    let dir = TempDir::new().expect("a temporary folder");
    for (at, value, field, says) in [
        (
            "eye",
            json!([0, 0, 1e200]),
            "camera.eye[2]",
            "1e200 is too large for the camera's eye in f64",
        ),
        (
            "look_at",
            json!([-1e101, 0, 0]),
            "camera.look_at[0]",
            "-1e101 is too large for the point the camera looks at in f64",
        ),
    ] {
        let mut scene = json!({
            "materials": { "M": material() },
            "lights": [{ "type": "ambient", "color": [1, 1, 1] }],
            "surfaces": [sphere(0.0, 1e99)],
            "camera": { "eye": [0, 0, 1e100], "look_at": [0, 0, 0], "fov": 40,
                        "width": 4, "height": 4 }
        });
        scene["camera"][at] = value;
        let path = dir.path().join("far.json");
        fs::write(&path, pretty(&scene)).expect("written");
        let image = dir.path().join("far.png");
        let run = phong(&["render", utf8(&path), "-o", utf8(&image)]);
        assert_eq!(run.code, Some(BAD_INPUT), "{}", run.stderr);
        assert!(
            run.stderr.contains(&format!("far.json: {field}: {says}"))
                && run.stderr.contains("within ±1e100"),
            "{}",
            run.stderr
        );
        assert!(!image.exists(), "an image was written");
    }
}

/// A number below the smallest f64 above 0 (about 4.9e-324) is read as 0: an error about it
/// said "0 is not a radius" where the file writes 1e-330. It says what the file writes, why it
/// was read as 0, and the fix of the error its 0 gave, in both precisions and formats, for a
/// file and for standard input; a vector that reads as the zero vector names its element.
#[test]
fn a_number_read_as_zero_is_quoted_as_written() {
    let radius = with(ray_problem(), "/surfaces/0", sphere(-5.0, 1.0));
    let text = pretty(&radius).replace("\"radius\": 1.0", "\"radius\": 1e-330");
    assert!(text.contains("1e-330"), "{text}");
    let bad = rejected_text(
        &text,
        &["f64", "f32"],
        Expect {
            field: Some("surfaces[0].radius"),
            says: &[
                "surfaces[0].radius: 1e-330 is too small to represent",
                "so it is read as 0: 0 is not a radius",
                "Fix: give the sphere a radius > 0",
            ],
        },
    );
    let dash = crate::support::phong()
        .args(["solve", "-"])
        .write_stdin(text.clone())
        .output()
        .expect("phong runs");
    let stderr = String::from_utf8_lossy(&dash.stderr);
    assert_eq!(dash.status.code(), Some(BAD_INPUT), "{stderr}");
    assert!(
        stderr.contains("-: surfaces[0].radius: 1e-330 is too small to represent"),
        "{stderr}"
    );
    let pt = phong(&["solve", utf8(&bad.path), "--lang", "pt"]);
    assert!(
        pt.stderr.contains(
            "surfaces[0].radius: 1e-330 é pequeno demais para ser representado (o menor número \
             acima de 0 é cerca de 4.9e-324), e é lido como 0: 0 não é um raio. Correção: dê à \
             esfera um raio > 0"
        ),
        "{}",
        pt.stderr
    );
    let direction = pretty(&ray_problem()).replace(
        "\"direction\": [\n      0,\n      0,\n      -1\n    ]",
        "\"direction\": [0, -1e-400, 0]",
    );
    assert!(direction.contains("-1e-400"), "{direction}");
    rejected_text(
        &direction,
        &["f64"],
        Expect {
            field: Some("ray.direction[1]"),
            says: &[
                "-1e-400 is too small to represent",
                "the ray's direction is the zero vector",
                "give a non-zero vector",
            ],
        },
    );
    // A number written as 0 is said as before.
    let zero = pretty(&radius).replace("\"radius\": 1.0", "\"radius\": 0.0e-400");
    let bad = rejected_text(
        &zero,
        &["f64"],
        Expect {
            field: Some("surfaces[0].radius"),
            says: &["0 is not a radius"],
        },
    );
    assert!(!bad.stderr.contains("too small"), "{}", bad.stderr);
}

/// A sphere whose hit point rounding cannot tell from its centre: the fix is what would help in
/// the precision in force. In f64 (the default) there is no "--precision f64" to use; a larger
/// radius, or the sphere and the ray nearer the origin, is what helps.
#[test]
fn a_sphere_too_small_for_its_coordinates_gets_the_fix_of_the_precision_in_force() {
    let sphere = json!({ "type": "sphere", "center": [0, 0, 1], "radius": 1e-20,
                         "material": "M" });
    let problem = with(ray_problem(), "/surfaces/0", sphere);
    let text = pretty(&problem);
    let f64 = rejected_text(
        &text,
        &["f64"],
        Expect {
            field: Some("surfaces[0]"),
            says: &["from the sphere's centre in f64", "larger radius"],
        },
    );
    assert!(!f64.stderr.contains("--precision"), "{}", f64.stderr);
    let pt = phong(&["solve", utf8(&f64.path), "--lang", "pt"]);
    assert!(
        pt.stderr.contains("raio maior") && !pt.stderr.contains("--precision"),
        "{}",
        pt.stderr
    );
    let f32 = rejected_text(
        &text,
        &["f32"],
        Expect {
            field: Some("surfaces[0]"),
            says: &["from the sphere's centre in f32", "--precision f64"],
        },
    );
    drop(f32);
}
/// A course policy's field of the wrong type is named by its path, as a problem file's is:
/// `--policy p.json: strict: invalid type: …`, where the error said only "invalid type: …
/// at line 1 column 12", and `{"duplicates": 3}` only "expected value at line 1 column 16".
/// The same through `check --policy`, `grade` and `policy` (the file beside the exercises), in
/// both languages.
#[test]
fn a_course_policy_field_of_the_wrong_type_is_named_by_its_path() {
    let dir = TempDir::new().expect("a temporary folder");
    let folder = dir.path().join("ex");
    fs::create_dir(&folder).expect("created");
    let problem = folder.join("4.1.json");
    fs::write(&problem, pretty(&point_problem())).expect("written");
    let given = dir.path().join("policy.json");
    for (text, says) in [
        (
            r#"{"strict": 1}"#,
            "strict: invalid type: integer `1`, expected a boolean at line 1 column 12",
        ),
        (
            r#"{"reading_credit": true}"#,
            "reading_credit: invalid type: boolean `true`, expected f64",
        ),
        (
            r#"{"tolerance": {"1": 0.01, "255": "one"}}"#,
            "tolerance.255: invalid type: string \"one\", expected f64",
        ),
        (
            r#"{"points": {"4.1": "two"}}"#,
            "points.4.1: invalid type: string \"two\", expected f64",
        ),
        (
            r#"{"no_hit": ["none", 3]}"#,
            "no_hit[1]: invalid type: integer `3`, expected a string",
        ),
        // The words it may be, where serde_json said only "expected value".
        (
            r#"{"duplicates": 3}"#,
            "duplicates: invalid type: integer `3`, expected one of the words \"first\", \
             \"last\", \"best\" at line 1 column 17",
        ),
        (
            r#"{"eight_bit": [1]}"#,
            "eight_bit: invalid type: sequence, expected one of the words \"read\", \"hint\"",
        ),
        (
            r#"{"duplicates": "lastest"}"#,
            "duplicates: unknown variant `lastest`, expected one of `first`, `last`, `best`",
        ),
    ] {
        fs::write(&given, text).expect("written");
        let run = phong(&[
            "check",
            utf8(&problem),
            "--answer",
            "0 0 0",
            "--policy",
            utf8(&given),
        ]);
        assert_eq!(run.code, Some(BAD_INPUT), "{text}: {}", run.stderr);
        let named = format!("--policy {}: {says}", given.display());
        assert!(run.stderr.contains(&named), "{text}: {}", run.stderr);
    }
    // The file beside the exercises, through grade and policy; in Portuguese too.
    let beside = folder.join("course-policy.json");
    fs::write(&beside, r#"{"strict": 1}"#).expect("written");
    let subs = dir.path().join("subs.csv");
    fs::write(&subs, "ana,4.1,0 0 0\n").expect("written");
    for (args, lang, says) in [
        (
            vec!["grade", utf8(&subs), "--exercises", utf8(&folder)],
            "en",
            "strict: invalid type: integer `1`, expected a boolean",
        ),
        (
            vec!["policy", utf8(&folder)],
            "pt",
            "strict: tipo inválido: inteiro `1`, esperado um booleano na linha 1, coluna 12",
        ),
    ] {
        let run = phong(&[&args[..], &["--lang", lang]].concat());
        assert_eq!(run.code, Some(BAD_INPUT), "{args:?}: {}", run.stderr);
        let named = format!("{}: {says}", beside.display());
        assert!(run.stderr.contains(&named), "{args:?}: {}", run.stderr);
    }
    fs::write(&beside, r#"{"duplicates": 3}"#).expect("written");
    let run = phong(&["policy", utf8(&folder), "--lang", "pt"]);
    assert_eq!(run.code, Some(BAD_INPUT), "{}", run.stderr);
    assert!(
        run.stderr.contains(
            "duplicates: tipo inválido: inteiro `3`, esperada uma das palavras \"first\", \
             \"last\", \"best\""
        ),
        "{}",
        run.stderr
    );
}

/// A course policy that is not a JSON object (an array, a number, a string, null, a boolean) is
/// said to be one, naming the file, in both languages: never by the name of a Rust type of
/// phong's own ("expected struct PolicyFile with 9 elements"). The same for its "tolerance".
#[test]
fn a_course_policy_that_is_not_an_object_is_said_so_in_the_users_words() {
    let dir = TempDir::new().expect("a temporary folder");
    let folder = dir.path().join("ex");
    fs::create_dir(&folder).expect("created");
    let problem = folder.join("4.1.json");
    fs::write(&problem, pretty(&point_problem())).expect("written");
    let beside = folder.join("course-policy.json");
    let given = dir.path().join("policy.json");
    for (text, en, pt) in [
        ("[]", "an array [ … ]", "uma lista [ … ]"),
        ("[{\"4.1\": 2}]", "an array [ … ]", "uma lista [ … ]"),
        ("  3\n", "a number", "um número"),
        ("\"policy\"", "a string", "um texto"),
        ("null", "null", "null"),
        ("true", "a boolean", "um booleano"),
    ] {
        for (file, flag) in [(&given, true), (&beside, false)] {
            fs::write(file, text).expect("written");
            let mut args = vec![
                "check".to_owned(),
                problem.display().to_string(),
                "--answer".to_owned(),
                "0 0 0".to_owned(),
            ];
            if flag {
                args.extend(["--policy".to_owned(), file.display().to_string()]);
            }
            for (lang, kind, says) in [
                ("en", en, "a course policy is one JSON object { … }"),
                ("pt", pt, "uma política do curso é um objeto JSON { … }"),
            ] {
                let out = crate::support::phong()
                    .args(&args)
                    .args(["--lang", lang])
                    .output()
                    .expect("phong runs");
                let err = String::from_utf8_lossy(&out.stderr);
                assert_eq!(out.status.code(), Some(BAD_INPUT), "{text}: {err}");
                assert!(err.contains(&file.display().to_string()), "{text}: {err}");
                assert!(err.contains(says) && err.contains(kind), "{text}: {err}");
                assert!(
                    !err.contains("PolicyFile") && !err.contains("struct"),
                    "{text}: {err}"
                );
            }
            fs::remove_file(file).expect("removed");
        }
    }
    // Nor does a field of the policy of the wrong type; and the tolerances, an object, are not
    // read from an array in order (`[0.5, 3]` was a tolerance of 0.5 on the 1 scale).
    for (text, lang) in [
        (r#"{"tolerance": 3}"#, "en"),
        (r#"{"tolerance": 3}"#, "pt"),
        (r#"{"tolerance": [0.5, 3]}"#, "en"),
    ] {
        fs::write(&given, text).expect("written");
        let says = match lang {
            "en" => "expected the tolerances: an object {\"1\": 0.005, \"255\": 1}",
            _ => "esperadas as tolerâncias: um objeto {\"1\": 0.005, \"255\": 1}",
        };
        let run = phong(&[
            "check",
            utf8(&problem),
            "--answer",
            "0 0 0",
            "--policy",
            utf8(&given),
            "--lang",
            lang,
        ]);
        assert_eq!(run.code, Some(BAD_INPUT), "{text}: {}", run.stderr);
        assert!(run.stderr.contains(says), "{text}: {}", run.stderr);
        assert!(!run.stderr.contains("TolerancesFile"), "{}", run.stderr);
    }
}
