//! Snapshots of `phong solve` for every file in `exercises/`, as text and as JSON (f64).
//!
//! The snapshots live in the top-level `snapshots/` folder. JSON numbers are rounded to 10
//! significant digits so that a last-bit change does not churn them; the text report prints
//! six significant digits already. f32 is compared with f64 numerically elsewhere
//! (`tests/hand_calculations.rs`), not snapshotted.

use std::path::Path;

use phong::core::Precision;
use phong::report::file::{solve_json, solve_text};
use serde_json::Value;

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

/// The path relative to the crate root, as a user would type it.
fn relative(path: &Path) -> &Path {
    path.strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap_or(path)
}

/// Rounds every non-integer number to 10 significant digits.
fn rounded(v: Value) -> Value {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().expect("an f64 number");
            let r: f64 = format!("{x:.9e}")
                .parse()
                .expect("a formatted number parses");
            // Fold -0 into 0: the sign of a zero is last-bit noise here.
            let r = if r == 0.0 { 0.0 } else { r };
            serde_json::Number::from_f64(r).map_or(Value::Null, Value::Number)
        }
        Value::Array(a) => Value::Array(a.into_iter().map(rounded).collect()),
        Value::Object(o) => Value::Object(o.into_iter().map(|(k, v)| (k, rounded(v))).collect()),
        other => other,
    }
}

#[test]
fn text_report_of_every_exercise() {
    settings().bind(|| {
        insta::glob!("../../exercises", "*.json", |path| {
            let text = solve_text(relative(path), Precision::F64).expect("every exercise solves");
            insta::assert_snapshot!("text", text);
        });
    });
}

#[test]
fn json_report_of_every_exercise() {
    settings().bind(|| {
        insta::glob!("../../exercises", "*.json", |path| {
            let json = solve_json(relative(path), Precision::F64).expect("every exercise solves");
            insta::assert_json_snapshot!("json", rounded(json));
        });
    });
}

#[test]
fn schema_of_the_problem_format() {
    settings().bind(|| {
        let schema: Value = serde_json::from_str(&phong::problem::schema_json()).unwrap();
        insta::assert_json_snapshot!("schema", schema);
    });
}
