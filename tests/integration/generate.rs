//! `phong new`: reproducible (same seed, same bytes), each problem right by its own key, and
//! friendly to hand calculation (short decimals, unit normals, integer distances, lights in
//! front of the surface).

use crate::support;

use std::path::{Path, PathBuf};

use serde_json::Value;

const KINDS: [&str; 8] = [
    "ambient",
    "point",
    "ray-plane",
    "directional",
    "spot",
    "several",
    "sphere",
    "secondary",
];

fn generate(kind: &str, count: u32, seed: u64, dir: &Path) -> Vec<PathBuf> {
    support::phong()
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
            v.as_object_mut().unwrap().remove("generated");
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
        let out = support::phong()
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

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn is_integer(x: f64) -> bool {
    (x - x.round()).abs() < 1e-9
}

#[test]
fn the_numbers_are_friendly_to_hand_calculation() {
    let (mut inside, mut outside) = (0, 0);
    for kind in KINDS {
        let dir = tempfile::tempdir().unwrap();
        for f in generate(kind, 25, 11, dir.path()) {
            let p = read(&f);
            let name = f.display().to_string();
            short_decimals(&p, &name);
            let lights = p["lights"].as_array().unwrap();
            // The shaded point and its normal: given, or where the ray meets the surface.
            let (at, n) = match kind {
                "ambient" => {
                    assert!(lights.iter().all(|l| l["type"] == "ambient"));
                    continue;
                }
                "point" | "directional" | "spot" | "several" => {
                    (v3(&p["point"]["position"]), v3(&p["point"]["normal"]))
                }
                "ray-plane" | "secondary" => {
                    let o = v3(&p["ray"]["origin"]);
                    let d = v3(&p["ray"]["direction"]);
                    let q = v3(&p["surfaces"][0]["point"]);
                    let n = v3(&p["surfaces"][0]["normal"]);
                    assert!((dot(d, d) - 1.0).abs() < 1e-12, "{name}: unit direction");
                    // t = N·(Q − O)/(N·D): an integer, in front of the origin.
                    let t = dot(n, sub(q, o)) / dot(n, d);
                    assert!(t > 0.5 && is_integer(t), "{name}: t = {t}");
                    assert!(dot(n, d) < 0.0, "{name}: the ray meets the front");
                    ([0, 1, 2].map(|i| o[i] + t * d[i]), n)
                }
                _ => {
                    // |O + tD − C|² = r²: t² + 2t D·(O − C) + |O − C|² − r² = 0 (|D| = 1).
                    let o = v3(&p["ray"]["origin"]);
                    let d = v3(&p["ray"]["direction"]);
                    let c = v3(&p["surfaces"][0]["center"]);
                    let r = p["surfaces"][0]["radius"].as_f64().unwrap();
                    assert!((dot(d, d) - 1.0).abs() < 1e-12, "{name}: unit direction");
                    let oc = sub(o, c);
                    let b = dot(d, oc);
                    let disc = b * b - (dot(oc, oc) - r * r);
                    assert!(disc > 0.0, "{name}: the ray meets the sphere");
                    let t = -b - disc.sqrt();
                    assert!(t > 0.5 && is_integer(t), "{name}: nearest t = {t}");
                    let hit = [0, 1, 2].map(|i| o[i] + t * d[i]);
                    (hit, sub(hit, c).map(|x| x / r))
                }
            };
            assert!((dot(n, n) - 1.0).abs() < 1e-9, "{name}: unit normal {n:?}");
            assert!(lights.iter().any(|l| l["type"] != "ambient"), "{name}");
            if kind == "several" {
                assert!(lights.len() >= 3, "{name}: several lights");
            }
            for l in lights {
                match l["type"].as_str().unwrap() {
                    "ambient" => {}
                    "directional" => {
                        // L = D_l, travelling towards the surface: −N·L ≥ 0.2.
                        let dl = v3(&l["direction"]);
                        assert!((norm(dl) - 1.0).abs() < 1e-12, "{name}");
                        assert!(-dot(dl, n) >= 0.2 - 1e-12, "{name}: the sun in front");
                    }
                    kind_of_light => {
                        // A point or spot light at an integer distance, in front (cos θ ≥ 0.2).
                        let to_light = sub(v3(&l["position"]), at);
                        let d = norm(to_light);
                        assert!(is_integer(d) && d.round() >= 1.0, "{name}: d = {d}");
                        assert!(
                            dot(to_light, n) / d >= 0.2 - 1e-12,
                            "{name}: light in front"
                        );
                        if kind_of_light == "spot" {
                            let axis = v3(&l["axis"]);
                            let psi = (-dot(axis, to_light) / d / norm(axis))
                                .clamp(-1.0, 1.0)
                                .acos()
                                .to_degrees();
                            let gamma = l["angle"].as_f64().unwrap();
                            assert!((psi - gamma).abs() >= 5.0 - 1e-9, "{name}: ψ = {psi}");
                            if psi < gamma {
                                inside += 1;
                            } else {
                                outside += 1;
                            }
                        }
                    }
                }
            }
            if let Some(e) = p.get("viewer").filter(|v| !v.is_null()) {
                let to_eye = sub(v3(e), at);
                let de = norm(to_eye);
                assert!(is_integer(de), "{name}: viewer distance {de}");
                assert!(dot(to_eye, n) > 0.0, "{name}: the viewer in front");
            }
        }
    }
    assert!(
        inside > 0 && outside > 0,
        "spots: {inside} inside, {outside} outside"
    );
}

/// A number as the statement writes it: as JSON does, with Portuguese's minus sign.
fn written(x: &Value, pt: bool) -> String {
    let s = x.to_string();
    if pt {
        s.replace('-', "\u{2212}")
    } else {
        s
    }
}

fn written3(v: &Value, pt: bool) -> String {
    let a = v.as_array().unwrap();
    format!(
        "({}, {}, {})",
        written(&a[0], pt),
        written(&a[1], pt),
        written(&a[2], pt)
    )
}

#[test]
fn the_statements_give_the_data_and_the_seed_is_metadata() {
    for kind in KINDS {
        let out = support::phong()
            .args([
                "new", "--kind", kind, "--count", "5", "--seed", "77", "--lang", "pt",
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
        for (i, p) in docs.as_array().unwrap().iter().enumerate() {
            let title = p["title"].as_str().unwrap();
            assert!(!title.contains("77") && !title.contains("seed"), "{title}");
            assert_eq!(p["generated"]["seed"], 77);
            assert_eq!(p["generated"]["kind"], kind);
            assert_eq!(p["generated"]["index"], i + 1);
            assert!(p["title_pt"]
                .as_str()
                .unwrap()
                .starts_with("Problema gerado"));
            for (field, pt) in [("question", false), ("question_pt", true)] {
                let q = p[field].as_str().unwrap();
                assert!(q.ends_with('?'), "{q}");
                for l in p["lights"].as_array().unwrap() {
                    assert!(
                        q.contains(&written3(&l["color"], pt)),
                        "{kind} {field}: {q}"
                    );
                    if let Some(pos) = l.get("position") {
                        assert!(q.contains(&written3(pos, pt)), "{kind} {field}: {q}");
                    }
                }
                if let Some(v) = p.get("viewer") {
                    assert!(q.contains(&written3(v, pt)), "{q}");
                }
                let m = &p["materials"]["M"];
                assert!(q.contains(&written3(&m["ambient"], pt)), "{q}");
            }
            let pt = p["question_pt"].as_str().unwrap();
            assert!(pt.contains("Qual") || pt.contains("Que cor"), "{pt}");
        }
        // Without --lang pt, English only.
        let out = support::phong()
            .args(["new", "--kind", kind, "--seed", "77"])
            .output()
            .unwrap();
        let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(doc.get("question_pt").is_none() && doc.get("title_pt").is_none());
    }
}

/// An ambient light drawn black, I_a = (0, 0, 0), lights nothing: no statement says it "lights
/// the scene" (spot seed 2's did); it is said to be black, in both languages, and its value is
/// still given.
#[test]
fn a_black_ambient_light_is_said_to_be_black() {
    let mut black = 0;
    for kind in KINDS {
        let out = support::phong()
            .args([
                "new", "--kind", kind, "--count", "30", "--seed", "1", "--lang", "pt",
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0));
        let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
        for p in docs.as_array().unwrap() {
            let (en, pt) = (
                p["question"].as_str().unwrap(),
                p["question_pt"].as_str().unwrap(),
            );
            assert!(!en.contains("(0, 0, 0) lights the scene"), "{en}");
            assert!(!pt.contains("(0, 0, 0) ilumina a cena"), "{pt}");
            let ambient: Vec<&Value> = p["lights"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|l| l["type"] == "ambient")
                .collect();
            if ambient.len() == 1 && v3(&ambient[0]["color"]) == [0.0; 3] {
                black += 1;
                assert!(
                    en.contains("The ambient light is black, I_a = (0, 0, 0)."),
                    "{en}"
                );
                assert!(
                    pt.contains("A luz ambiente é preta, I_a = (0, 0, 0)."),
                    "{pt}"
                );
            }
        }
    }
    assert!(
        black > 0,
        "30 problems of each kind draw a black ambient light"
    );
}

/// A problem of several lights names each light that is not ambient with its own symbols
/// (C_l1 and P_l1, C_l2 and P_l2 or D_l2), and its two point lights stand apart: seed 5's
/// two point lights were both at P_l = (5.4, 0.44, −1.92), in a statement that named both C_l
/// and P_l (one problem in about a hundred had its lights at one place).
#[test]
fn several_lights_stand_apart_and_each_has_its_own_symbols() {
    let out = support::phong()
        .args([
            "new", "--kind", "several", "--count", "200", "--seed", "5", "--lang", "pt",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
    for p in docs.as_array().unwrap() {
        let lights = p["lights"].as_array().unwrap();
        let others: Vec<&Value> = lights.iter().filter(|l| l["type"] != "ambient").collect();
        let at: Vec<&Value> = others.iter().filter_map(|l| l.get("position")).collect();
        if at.len() == 2 {
            assert_ne!(at[0], at[1], "{p}");
        }
        for field in ["question", "question_pt"] {
            let q = p[field].as_str().unwrap();
            assert_eq!(others.len(), 2, "{q}");
            assert!(q.contains("C_l1 = ") && q.contains("C_l2 = "), "{q}");
            assert!(!q.contains("C_l = "), "{q}");
        }
    }
}

#[test]
fn without_a_folder_the_problems_are_printed_as_one_json_document() {
    let out = support::phong()
        .args(["new", "--kind", "ambient", "--count", "3", "--seed", "1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let docs: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(docs.as_array().unwrap().len(), 3);
}

/// `-o -` is standard output, as for every command: the same document as without `-o`, and
/// no folder named `-`.
#[test]
fn dash_prints_the_problems_and_makes_no_folder() {
    let dir = tempfile::tempdir().unwrap();
    let run = |extra: &[&str]| {
        support::phong()
            .current_dir(dir.path())
            .args(["new", "--kind", "point", "--count", "2", "--seed", "4"])
            .args(extra)
            .output()
            .unwrap()
    };
    let (plain, dash) = (run(&[]), run(&["-o", "-"]));
    assert_eq!(dash.status.code(), Some(0));
    assert!(!plain.stdout.is_empty());
    assert_eq!(dash.stdout, plain.stdout);
    assert!(!dir.path().join("-").exists());
}

/// A folder for the problems that is a file, or that cannot be made: said, with what would
/// fix it, in both languages; exit 2 and nothing written.
#[test]
fn an_output_folder_that_cannot_be_one_is_said_with_its_fix() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("afile");
    std::fs::write(&file, "kept").unwrap();
    for (lang, says, fix) in [
        (
            "en",
            "is a file, not a folder",
            "Fix: give a folder for the problems' files",
        ),
        (
            "pt",
            "é um arquivo, não uma pasta",
            "Correção: dê uma pasta para os arquivos",
        ),
    ] {
        let out = support::phong()
            .args(["new", "--kind", "point", "--lang", lang, "-o"])
            .arg(format!("{}/", file.display()))
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains("afile") && err.contains(says) && err.contains(fix),
            "{err}"
        );
        assert_eq!(std::fs::read_to_string(&file).unwrap(), "kept");
    }
    // A folder inside that file cannot be made: the system's reason, then the fix.
    let out = support::phong()
        .args(["new", "--kind", "point", "--lang", "pt", "-o"])
        .arg(file.join("sub"))
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("não é possível criar a pasta") && err.contains("Correção: dê uma pasta"),
        "{err}"
    );
}
