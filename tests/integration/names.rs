//! Documents name things as a person would (issue 29, item 3): "the yellow light", "the second
//! light", "the plane"; "a luz amarela", "a segunda luz", "o plano". Never `lights[1]` or
//! `surfaces[0]`, which stay in the JSON and in the error messages (where the fix goes).

use crate::support;

use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn phong(args: &[&str]) -> String {
    let out = support::phong()
        .current_dir(root())
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.code().is_some_and(|c| c <= 1),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn json_files(dir: &str) -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| p.strip_prefix(root()).unwrap().display().to_string())
        .collect();
    files.sort();
    files
}

/// The places in `doc` that name a light or a surface by its place in the file.
fn paths_in(doc: &str) -> Vec<String> {
    ["lights[", "surfaces["]
        .iter()
        .flat_map(|p| doc.match_indices(p))
        .map(|(i, _)| {
            let from = doc[..i].char_indices().rev().nth(40).map_or(0, |(k, _)| k);
            let to = doc[i..]
                .char_indices()
                .nth(40)
                .map_or(doc.len(), |(k, _)| i + k);
            doc[from..to].to_owned()
        })
        .collect()
}

#[test]
fn no_document_or_quiz_names_a_json_path() {
    let exercises = json_files("exercises");
    let scenes = json_files("scenes");
    assert!(exercises.len() >= 17 && scenes.len() >= 7);
    let mut bad = Vec::new();
    for lang in ["en", "pt"] {
        for format in ["text", "markdown", "latex", "html"] {
            // Every exercise, and the scenes that are problems too (a scene with a ray: 4.3).
            let solvable = scenes.iter().filter(|f| {
                std::fs::read_to_string(root().join(f)).is_ok_and(|t| t.contains("\"ray\""))
            });
            for file in exercises.iter().chain(solvable) {
                let doc = phong(&["solve", file, "--format", format, "--lang", lang]);
                assert!(!doc.is_empty(), "{file} {format} {lang}");
                for p in paths_in(&doc) {
                    bad.push(format!(
                        "solve {file} --format {format} --lang {lang}: …{p}…"
                    ));
                }
            }
            // A pixel of each scene, explained (its rays solved as ray problems).
            for file in &scenes {
                let doc = phong(&[
                    "render",
                    file,
                    "--explain-pixel",
                    "160,120",
                    "--format",
                    format,
                    "--lang",
                    lang,
                ]);
                for p in paths_in(&doc) {
                    bad.push(format!(
                        "render {file} --explain-pixel --format {format}: …{p}…"
                    ));
                }
            }
        }
        let mut args = vec!["moodle", "--lang", lang];
        args.extend(exercises.iter().map(String::as_str));
        let quiz = phong(&args);
        assert!(quiz.contains("<quiz>"), "{quiz}");
        for p in paths_in(&quiz) {
            bad.push(format!("moodle --lang {lang}: …{p}…"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_json_keeps_the_paths_for_scripts() {
    // The JSON's finding about several-lights' light under the floor still names it by its
    // place: lights[4] (the fifth entry, the ambient light being lights[0]).
    let json = phong(&["solve", "exercises/several-lights.json", "--format", "json"]);
    assert!(
        json.contains("lights[4] (point) \\\"under the floor\\\""),
        "{json}"
    );
}

#[test]
fn named_lights_are_called_by_their_names_in_both_languages() {
    // 4.3: one point light, "yellow light" / "luz amarela": the heading of its steps and the
    // diagram's title.
    let en = phong(&[
        "solve",
        "exercises/4.3.json",
        "--lang",
        "en",
        "--color",
        "never",
    ]);
    assert!(en.contains("The yellow light (point) at (0, 0, 5)"), "{en}");
    let pt = phong(&[
        "solve",
        "exercises/4.3.json",
        "--lang",
        "pt",
        "--color",
        "never",
    ]);
    assert!(pt.contains("A luz amarela (pontual) em (0, 0, 5)"), "{pt}");
    assert!(pt.contains("O plano: t = -90"), "{pt}");
    let html = phong(&[
        "solve",
        "exercises/4.3.json",
        "--lang",
        "pt",
        "--format",
        "html",
    ]);
    assert!(
        html.contains("<title>Diagrama para a luz amarela</title>"),
        "{html}"
    );
    // several-lights: a name that is not a noun for a light is quoted after "light"; a name
    // that is one keeps its own article (o spot verde); the finding about the light under
    // the floor names it so, contracted where Portuguese contracts.
    let en = phong(&[
        "solve",
        "exercises/several-lights.json",
        "--lang",
        "en",
        "--color",
        "never",
    ]);
    for want in [
        "The light “key” (point) at (0, 3, 4)",
        "The green spot at (0, 0, 2)",
        "The light “under the floor” (point) at (0, 0, -1)",
        "the light “under the floor” is on the back side of the surface",
    ] {
        assert!(en.contains(want), "{want} in {en}");
    }
    let pt = phong(&[
        "solve",
        "exercises/several-lights.json",
        "--lang",
        "pt",
        "--color",
        "never",
    ]);
    for want in [
        "A luz “principal” (pontual) em (0, 3, 4)",
        "O spot verde em (0, 0, 2)",
        "A luz “preenchimento” (direcional), direção D_l = (0, -0.6, -0.8)",
        "a luz “sob o chão” está do lado de trás da superfície",
    ] {
        assert!(pt.contains(want), "{want} in {pt}");
    }
    // A directional light named "sun"/"sol": a noun for a light, masculine in Portuguese.
    let pt = phong(&[
        "solve",
        "exercises/directional-light.json",
        "--lang",
        "pt",
        "--color",
        "never",
    ]);
    assert!(pt.contains("O sol (direcional), direção D_l"), "{pt}");
}

/// A file in the system's temporary folder, removed when dropped.
struct Temp(PathBuf);

impl Temp {
    fn new(name: &str, text: &str) -> Temp {
        let path = std::env::temp_dir().join(format!("phong-names-{}-{name}", std::process::id()));
        std::fs::write(&path, text).unwrap();
        Temp(path)
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn unnamed_things_are_called_by_their_place_among_their_kind() {
    // Two unnamed point lights and two spheres before a plane: the ray from (0, 0, 10) down
    // the z axis misses the first sphere (centre (5, 0, 0), radius 1: 5 away from the axis)
    // and meets the second (centre 0, radius 2) at z = 2, t = 10 − 2 = 8.
    let file = Temp::new(
        "two.json",
        r#"{
          "materials": { "M": { "ambient": [0.5, 0.5, 0.5], "diffuse": [0.5, 0.5, 0.5], "specular": [0, 0, 0], "shininess": 1 } },
          "lights": [
            { "type": "ambient", "color": [0.1, 0.1, 0.1] },
            { "type": "point", "position": [0, 3, 6], "color": [1, 1, 1], "falloff": 0 },
            { "type": "point", "position": [0, -3, 6], "color": [1, 1, 1], "falloff": 0 }
          ],
          "ray": { "origin": [0, 0, 10], "direction": [0, 0, -1] },
          "surfaces": [
            { "type": "sphere", "center": [5, 0, 0], "radius": 1, "material": "M" },
            { "type": "sphere", "center": [0, 0, 0], "radius": 2, "material": "M" },
            { "type": "plane", "point": [0, 0, -5], "normal": [0, 0, 1], "material": "M" }
          ]
        }"#,
    );
    let path = file.0.display().to_string();
    let en = phong(&["solve", &path, "--lang", "en", "--color", "never"]);
    for want in [
        "The second sphere: t = 8",
        "The first light (point) at (0, 3, 6)",
        "The second light (point) at (0, -3, 6)",
    ] {
        assert!(en.contains(want), "{want} in {en}");
    }
    let pt = phong(&["solve", &path, "--lang", "pt", "--color", "never"]);
    for want in [
        "A segunda esfera: t = 8",
        "A primeira luz (pontual) em (0, 3, 6)",
        "A segunda luz (pontual) em (0, -3, 6)",
    ] {
        assert!(pt.contains(want), "{want} in {pt}");
    }
    // A ray along the second of two planes lies in it: "no segundo plano" (em + o).
    let file = Temp::new(
        "in-plane.json",
        r#"{
          "materials": { "M": { "ambient": [0.5, 0.5, 0.5], "diffuse": [0.5, 0.5, 0.5], "specular": [0, 0, 0], "shininess": 1 } },
          "lights": [ { "type": "point", "position": [0, 3, 6], "color": [1, 1, 1], "falloff": 0 } ],
          "ray": { "origin": [0, 0, -5], "direction": [1, 0, 0] },
          "surfaces": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": "M" },
            { "type": "plane", "point": [0, 0, -5], "normal": [0, 0, 1], "material": "M" }
          ]
        }"#,
    );
    let path = file.0.display().to_string();
    let en = phong(&["solve", &path, "--lang", "en", "--color", "never"]);
    assert!(
        en.contains("the ray lies in the second plane (N·D = 0"),
        "{en}"
    );
    let pt = phong(&["solve", &path, "--lang", "pt", "--color", "never"]);
    assert!(
        pt.contains("o raio está contido no segundo plano (N·D = 0"),
        "{pt}"
    );
    let json = phong(&["solve", &path, "--format", "json"]);
    assert!(
        json.contains("the ray lies in the plane surfaces[1]"),
        "{json}"
    );
}
