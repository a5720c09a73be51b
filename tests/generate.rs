//! `phong new`: reproducible (same seed, same bytes), each problem right by its own key, and
//! friendly to hand calculation (short decimals, unit normals, integer distances, lights in
//! front of the surface).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

const KINDS: [&str; 3] = ["ambient", "point", "ray-plane"];

fn generate(kind: &str, count: u32, seed: u64, dir: &Path) -> Vec<PathBuf> {
    Command::cargo_bin("phong")
        .unwrap()
        .args([
            "new",
            "--kind",
            kind,
            "--count",
            &count.to_string(),
            "--seed",
            &seed.to_string(),
            "-o",
        ])
        .arg(dir)
        .assert()
        .code(0);
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with(kind))
        .collect();
    files.sort();
    files
}

fn read(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn v3(v: &Value) -> [f64; 3] {
    let a = v.as_array().expect("a triple");
    [0, 1, 2].map(|i| a[i].as_f64().unwrap())
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Every number in the problem (but the answer key) has at most two decimals.
fn short_decimals(v: &Value, path: &str) {
    match v {
        Value::Number(n) => {
            let x = n.as_f64().unwrap();
            let hundredths = x * 100.0;
            assert!(
                (hundredths - hundredths.round()).abs() < 1e-9,
                "{path}: {x}"
            );
        }
        Value::Array(a) => a.iter().for_each(|x| short_decimals(x, path)),
        Value::Object(o) => o
            .iter()
            .filter(|(k, _)| *k != "answer")
            .for_each(|(k, x)| short_decimals(x, &format!("{path}.{k}"))),
        _ => {}
    }
}

#[test]
fn the_same_seed_gives_the_same_bytes_and_another_seed_other_problems() {
    for kind in KINDS {
        let (a, b, c) = (
            tempfile::tempdir().unwrap(),
            tempfile::tempdir().unwrap(),
            tempfile::tempdir().unwrap(),
        );
        let fa = generate(kind, 4, 2024, a.path());
        let fb = generate(kind, 4, 2024, b.path());
        let fc = generate(kind, 4, 2025, c.path());
        assert_eq!(fa.len(), 4);
        for (x, y) in fa.iter().zip(&fb) {
            assert_eq!(x.file_name(), y.file_name());
            assert_eq!(
                std::fs::read(x).unwrap(),
                std::fs::read(y).unwrap(),
                "{kind}"
            );
        }
        let body = |p: &Path| {
            let mut v = read(p);
            v.as_object_mut().unwrap().remove("title");
            v
        };
        assert!(
            fa.iter().zip(&fc).any(|(x, z)| body(x) != body(z)),
            "{kind}: seeds differ"
        );
    }
}

#[test]
fn problem_i_does_not_depend_on_how_many_are_written() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let two = generate("point", 2, 9, a.path());
    let five = generate("point", 5, 9, b.path());
    for (x, y) in two.iter().zip(&five) {
        assert_eq!(std::fs::read(x).unwrap(), std::fs::read(y).unwrap());
    }
}

#[test]
fn each_generated_problem_is_right_by_its_own_key() {
    for kind in KINDS {
        let dir = tempfile::tempdir().unwrap();
        let files = generate(kind, 12, 7, dir.path());
        let out = Command::cargo_bin("phong")
            .unwrap()
            .args(["check", "--format", "json"])
            .args(&files)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{kind}");
        let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
        for d in docs.as_array().unwrap() {
            assert_eq!(d["verdict"], "right", "{d:#}");
        }
    }
}

#[test]
fn the_numbers_are_friendly_to_hand_calculation() {
    for kind in KINDS {
        let dir = tempfile::tempdir().unwrap();
        for f in generate(kind, 25, 11, dir.path()) {
            let p = read(&f);
            let name = f.display().to_string();
            short_decimals(&p, &name);
            let lights = p["lights"].as_array().unwrap();
            let point_light = lights.iter().find(|l| l["type"] == "point");
            // The shaded point and its normal: given, or where the ray meets the plane.
            let (at, n) = match kind {
                "ambient" => {
                    assert!(point_light.is_none());
                    continue;
                }
                "point" => (v3(&p["point"]["position"]), v3(&p["point"]["normal"])),
                _ => {
                    let o = v3(&p["ray"]["origin"]);
                    let d = v3(&p["ray"]["direction"]);
                    let q = v3(&p["surfaces"][0]["point"]);
                    let n = v3(&p["surfaces"][0]["normal"]);
                    assert!((dot(d, d) - 1.0).abs() < 1e-12, "{name}: unit direction");
                    // t = N·(Q − O)/(N·D): an integer, in front of the origin.
                    let t = dot(n, sub(q, o)) / dot(n, d);
                    assert!(t > 0.5 && (t - t.round()).abs() < 1e-9, "{name}: t = {t}");
                    assert!(dot(n, d) < 0.0, "{name}: the ray meets the front");
                    ([0, 1, 2].map(|i| o[i] + t * d[i]), n)
                }
            };
            assert!((dot(n, n) - 1.0).abs() < 1e-12, "{name}: unit normal {n:?}");
            // The light at an integer distance, in front (cos θ ≥ 0.2).
            let l = v3(&point_light.unwrap()["position"]);
            let to_light = sub(l, at);
            let d = dot(to_light, to_light).sqrt();
            assert!(
                (d - d.round()).abs() < 1e-9 && d.round() >= 1.0,
                "{name}: d = {d}"
            );
            assert!(
                dot(to_light, n) / d >= 0.2 - 1e-12,
                "{name}: the light in front"
            );
            if let Some(e) = p.get("viewer").filter(|v| !v.is_null()) {
                let to_eye = sub(v3(e), at);
                let de = dot(to_eye, to_eye).sqrt();
                assert!(
                    (de - de.round()).abs() < 1e-9,
                    "{name}: viewer distance {de}"
                );
                assert!(dot(to_eye, n) > 0.0, "{name}: the viewer in front");
            }
        }
    }
}

#[test]
fn without_a_folder_the_problems_are_printed_as_one_json_document() {
    let out = Command::cargo_bin("phong")
        .unwrap()
        .args(["new", "--kind", "ambient", "--count", "3", "--seed", "1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(docs.as_array().unwrap().len(), 3);
}
