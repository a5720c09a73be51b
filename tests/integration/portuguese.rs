//! With `--lang pt` every phrase the user can see is Portuguese: every command that takes
//! `--lang` (solve in every format and part, check, check --slips, render --explain-pixel in
//! every format) and their common errors, run on the bundled exercises and scenes; and the rarer
//! errors, each of its own template (lights, materials, points, rays, surfaces, meshes, the
//! camera, settings, syntax, answers, steps, refused flag values), one bad input each. The
//! test fails on any English word of a list: the English catalogue's words that its Portuguese
//! does not use, and the distinctive words of the other English messages.
//!
//! What is not prose is left out before the words are read: the file's own identifiers (JSON
//! field names in quotes or backticks, `lights[0]`, slip codes such as `light_reversed`), LaTeX
//! commands and environment names, TikZ's drawing commands (not its labels), HTML tags, the
//! CSS, and the file names.

use crate::support;

use std::collections::BTreeSet;
use std::path::Path;

use phong::report::catalogue;
use phong::report::lang::Lang;

/// Words that are rightly the same in both languages, or that are Portuguese too ("o que for
/// maior").
const SHARED: &[&str] = &[
    "material", "total", "linear", "spot", "normal", "pixel", "vs", "round", "Eq", "eq", "for",
];

/// The distinctive words of the English messages outside the phrase catalogue.
const ENGLISH: &[&str] = &[
    "the",
    "and",
    "with",
    "from",
    "light",
    "lights",
    "viewer",
    "error",
    "cannot",
    "file",
    "field",
    "missing",
    "unknown",
    "expected",
    "hit",
    "hits",
    "colour",
    "answer",
    "right",
    "wrong",
    "reading",
    "sample",
    "level",
    "weight",
    "path",
    "reflection",
    "primary",
    "background",
    "ends",
    "follows",
    "settings",
    "shadows",
    "clamped",
    "exercise",
    "solution",
    "statement",
    "key",
    "fix",
    "remove",
    "add",
    "give",
    "check",
    "which",
    "where",
    "not",
    "this",
    "that",
    "point",
    "surface",
    "behind",
    "front",
    "none",
    "quadratic",
    "falloff",
    "ambient",
    "diffuse",
    "specular",
    "direction",
    "origin",
    "plane",
    "sphere",
    "written",
    "problem",
    "steps",
    "given",
    "findings",
    "slip",
    "slips",
    "intended",
    "likely",
    "another",
    "tolerance",
    "difference",
    "channel",
    "scale",
    "mirror",
    "rendered",
    "ray",
    "write",
    "most",
    "least",
    "needs",
    "has",
    "such",
    "must",
    "comma",
    "trailing",
    "line",
    "outside",
    "negative",
    "vector",
    "number",
    "numbers",
    "gives",
    "warning",
];

/// The English words the output must not hold.
fn english_words() -> BTreeSet<String> {
    let words = |s: &str| -> Vec<String> {
        s.split(|c: char| !c.is_alphabetic())
            .filter(|w| w.chars().count() >= 3)
            .map(str::to_lowercase)
            .collect()
    };
    let portuguese: BTreeSet<String> = catalogue(Lang::Pt).into_iter().flat_map(words).collect();
    let mut out: BTreeSet<String> = catalogue(Lang::En)
        .into_iter()
        .flat_map(words)
        .filter(|w| !portuguese.contains(w))
        .collect();
    out.extend(ENGLISH.iter().map(|w| w.to_lowercase()));
    for w in SHARED {
        out.remove(&w.to_lowercase());
    }
    out
}

/// A file's field path (`viewer[0]`, `point.normal`, `surfaces[0].material.specular`), maybe
/// followed by punctuation: an identifier, not prose.
fn is_field_path(token: &str) -> bool {
    let t = token.trim_end_matches([':', ',', ';', ')']);
    if !(t.contains('[') || t.contains('.')) {
        return false;
    }
    let mut expect_name = true;
    let mut chars = t.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '[' => {
                if expect_name {
                    return false;
                }
                let mut closed = false;
                for d in chars.by_ref() {
                    if d == ']' {
                        closed = true;
                        break;
                    }
                    if !d.is_ascii_alphanumeric() {
                        return false;
                    }
                }
                if !closed {
                    return false;
                }
            }
            '.' => {
                if expect_name {
                    return false;
                }
                expect_name = true;
            }
            c if c.is_ascii_alphabetic() || c == '_' || (!expect_name && c.is_ascii_digit()) => {
                expect_name = false;
            }
            _ => return false,
        }
    }
    !expect_name
}

/// The prose of an output: identifiers, markup and file names taken out.
fn prose(s: &str) -> String {
    // Field paths, before the brackets in them are read as markup; a program's name.
    let s: String = s
        .replace("POV-Ray", "POV")
        .lines()
        .map(|l| {
            l.split(' ')
                .filter(|w| !is_field_path(w))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join("\n");
    // TikZ's drawing commands (their options are TikZ's words); its \node labels stay.
    let mut s: String = s
        .lines()
        .filter(|l| {
            !["\\draw", "\\fill", "\\filldraw", "\\clip", "\\definecolor"]
                .iter()
                .any(|c| l.trim_start().starts_with(c))
        })
        .collect::<Vec<_>>()
        .join("\n");
    // The stylesheet, HTML tags and entities.
    if let (Some(a), Some(b)) = (s.find("<style>"), s.find("</style>")) {
        s.replace_range(a..b, " ");
    }
    let mut out = String::with_capacity(s.len());
    let chars: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let skip_to = |end: char, from: usize| {
            chars[from + 1..]
                .iter()
                .position(|&x| x == end)
                .map(|k| from + 1 + k + 1)
        };
        let next = match c {
            '<' => skip_to('>', i),
            '"' => skip_to('"', i),
            '`' => skip_to('`', i),
            '&' => skip_to(';', i).filter(|&e| e - i < 10),
            '\\' => {
                // A LaTeX command, and an environment's name or a colour's after it.
                let mut e = i + 1;
                while e < chars.len() && chars[e].is_ascii_alphabetic() {
                    e += 1;
                }
                if e < chars.len() && chars[e] == '{' {
                    let close = skip_to('}', e).unwrap_or(e);
                    let inside: String = chars[e + 1..close.saturating_sub(1).max(e + 1)]
                        .iter()
                        .collect();
                    if inside
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '*')
                    {
                        e = close;
                    }
                }
                Some(e.max(i + 1))
            }
            '[' => skip_to(']', i).filter(|&e| {
                chars[i + 1..e - 1]
                    .iter()
                    .all(|c| c.is_ascii_alphanumeric() || ",=.".contains(*c))
            }),
            _ => None,
        };
        match next {
            Some(e) => {
                out.push(' ');
                i = e;
            }
            None => {
                out.push(c);
                i += 1;
            }
        }
    }
    // Identifiers (slip codes, `lights[0]`, `4.2.json`) and LaTeX's {center}-like groups.
    // An error's field comes right after its file ("x.json: point: …", "x.json:1:5:
    // point.normal: …"); flags are names.
    let mut previous = "";
    let mut kept = Vec::new();
    for w in out.split_whitespace() {
        let identifier = w.contains('_')
            || w.contains("lights")
            || w.contains("surfaces")
            || w.contains(".json")
            || w.trim_start_matches(['\'', '(']).starts_with("--")
            || (previous.contains(".json:") && w.ends_with(':'));
        if !identifier {
            kept.push(w);
        }
        previous = w;
    }
    kept.join(" ")
}

/// The English words found in `text`.
fn english_in(text: &str, english: &BTreeSet<String>) -> Vec<String> {
    let p = prose(text);
    let mut found: Vec<String> = p
        .split(|c: char| !c.is_alphabetic())
        .filter(|w| english.contains(&w.to_lowercase()))
        .map(str::to_owned)
        .collect();
    found.sort();
    found.dedup();
    found
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs phong with `args` in the crate's folder: its standard output and error.
fn run(args: &[&str]) -> (String, String) {
    let out = support::phong()
        .current_dir(root())
        .args(args)
        .output()
        .unwrap();
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn exercises() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(root().join("exercises"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| format!("exercises/{}", p.file_name().unwrap().to_string_lossy()))
        .collect();
    v.sort();
    v
}

#[test]
fn every_command_with_lang_pt_speaks_portuguese() {
    let english = english_words();
    let mut failures = Vec::new();
    let mut check = |what: String, (stdout, stderr): (String, String)| {
        for (stream, text) in [("stdout", &stdout), ("stderr", &stderr)] {
            let found = english_in(text, &english);
            if !found.is_empty() {
                failures.push(format!("{what} ({stream}): {found:?}"));
            }
        }
        assert!(
            !stdout.is_empty() || !stderr.is_empty(),
            "{what} says nothing"
        );
    };
    let files = exercises();
    let files: Vec<&str> = files.iter().map(String::as_str).collect();
    for format in ["text", "markdown", "latex", "html"] {
        for part in ["statement", "solution", "key", "all"] {
            let mut args = vec!["solve", "--lang", "pt", "--format", format, "--part", part];
            args.extend(&files);
            check(format!("solve --format {format} --part {part}"), run(&args));
        }
        check(
            format!("render --explain-pixel --format {format}"),
            run(&[
                "render",
                "scenes/4.3.json",
                "--explain-pixel",
                "160,120",
                "--lang",
                "pt",
                "--format",
                format,
            ]),
        );
    }
    // Every bundled scene: its title, question and light names.
    for scene in ["classic", "mesh", "pov-lights", "pov-materials"] {
        let file = format!("scenes/{scene}.json");
        check(
            format!("render {file} --explain-pixel"),
            run(&[
                "render",
                &file,
                "--explain-pixel",
                "100,100",
                "--lang",
                "pt",
            ]),
        );
    }
    let mut args = vec!["check", "--lang", "pt"];
    args.extend(&files);
    check("check".into(), run(&args));
    // The quiz: its categories are the files' names, and "none" and "no hit" are answers it
    // accepts (as `phong check` does), not its prose.
    let mut args = vec!["moodle", "--lang", "pt"];
    args.extend(&files);
    let (quiz, errors) = run(&args);
    let quiz: String = quiz
        .lines()
        .filter(|l| !l.starts_with("<category>"))
        .collect::<Vec<_>>()
        .join("\n");
    let quiz = quiz.replace("~=none#", "~").replace("~=no hit#", "~");
    check("moodle".into(), (quiz, errors));
    check(
        "check --answer (wrong)".into(),
        run(&[
            "check",
            "--lang",
            "pt",
            "exercises/4.2.json",
            "--answer",
            "0.5 0.5 0.5",
        ]),
    );
    check(
        "check --step".into(),
        run(&[
            "check",
            "--lang",
            "pt",
            "exercises/4.3.json",
            "--step",
            "t=5",
            "--step",
            "N=1,0,0",
            "--step",
            "I_a=0,0,0",
            "--step",
            "diffuse=1,1,1",
        ]),
    );
    check(
        "check --slips".into(),
        run(&[
            "check",
            "--slips",
            "--lang",
            "pt",
            "exercises/4.2.json",
            "exercises/4.3.json",
        ]),
    );
    // The common errors.
    let dir = tempfile::tempdir().unwrap();
    let bad = [
        ("unknown-field", r#"{"x": 1}"#),
        ("syntax", r#"{"title": 1"#),
        ("wrong-type", r#"{"title": 1}"#),
        (
            "missing-field",
            r#"{"lights": [{"type": "point", "color": [1, 1, 1]}], "point": {"material": {"ambient": [1, 1, 1]}}}"#,
        ),
        ("nothing-to-shade", "{}"),
    ];
    for (name, text) in bad {
        let path = dir.path().join(format!("{name}.json"));
        std::fs::write(&path, text).unwrap();
        let p = path.to_str().unwrap();
        check(format!("solve {name}"), run(&["solve", "--lang", "pt", p]));
        check(format!("check {name}"), run(&["check", "--lang", "pt", p]));
    }
    let colour = dir.path().join("0-255.json");
    std::fs::write(
        &colour,
        r#"{"lights": [{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": 0}], "point": {"position": [0, 0, 0], "normal": [0, 0, 1], "material": {"diffuse": [200, 100, 50]}}}"#,
    )
    .unwrap();
    let colour = colour.to_str().unwrap();
    for command in ["solve", "check"] {
        let (stdout, stderr) = run(&[command, "--lang", "pt", colour]);
        assert!(stderr.starts_with("aviso: "), "{command}: {stderr}");
        check(format!("{command} with a warning"), (stdout, stderr));
    }
    check(
        "solve of a missing file".into(),
        run(&["solve", "--lang", "pt", "no-such-file.json"]),
    );
    check(
        "check --answer abc".into(),
        run(&[
            "check",
            "--lang",
            "pt",
            "exercises/4.2.json",
            "--answer",
            "abc",
        ]),
    );
    check(
        "render without a camera".into(),
        run(&[
            "render",
            "--lang",
            "pt",
            "exercises/4.2.json",
            "-o",
            "x.png",
        ]),
    );
    check(
        "solve --format json --part key".into(),
        run(&[
            "solve",
            "--lang",
            "pt",
            "--format",
            "json",
            "--part",
            "key",
            "exercises/4.1.json",
        ]),
    );
    assert!(
        failures.is_empty(),
        "English words with --lang pt:\n{}",
        failures.join("\n")
    );
}

#[test]
fn the_word_list_catches_english_and_spares_portuguese() {
    let english = english_words();
    assert_eq!(
        english_in("the light is behind the surface", &english),
        ["behind", "light", "surface", "the"]
    );
    assert!(english_in("a fonte de luz está atrás da superfície", &english).is_empty());
    // Identifiers and markup are not prose.
    assert!(english_in(
        "\\begin{center} `title` \"point\" light_reversed lights[0] <span class=\"m\">x</span>",
        &english
    )
    .is_empty());
}

/// A light, a point and a material that are valid, for the bad files below to change one
/// thing of.
const LIGHT: &str =
    r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": 0}"#;
const POINT: &str = r#""point": {"position": [0, 0, 0], "normal": [0, 0, 1], "material": {"ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.5, 0.5]}}"#;
const CAMERA: &str =
    r#""camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45, "width": 4, "height": 4}"#;
const SPHERE: &str = r#"{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1}}"#;

/// A problem with one point light, the point, and `rest`.
fn with_point(rest: &str) -> String {
    format!(r#"{{"lights": [{LIGHT}], {POINT}{rest}}}"#)
}

/// A point problem whose light is `light`.
fn with_light(light: &str) -> String {
    format!(r#"{{"lights": [{light}], {POINT}}}"#)
}

/// A point problem whose material is `material` (with `rest` at the top level).
fn with_material(material: &str, rest: &str) -> String {
    format!(
        r#"{{"lights": [{LIGHT}], "point": {{"position": [0, 0, 0], "normal": [0, 0, 1], "material": {material}}}{rest}}}"#
    )
}

/// A scene with a camera, a sphere, and `surface` and `rest`.
fn scene(surface: &str, rest: &str) -> String {
    format!(r#"{{"lights": [{LIGHT}], {CAMERA}, "surfaces": [{SPHERE}, {surface}]{rest}}}"#)
}

/// The rarer errors a student meets, each of a different template: lights, materials, points,
/// rays, surfaces, meshes, the camera and the tracer's settings, the syntax, the answer key, and
/// the `check` flags. Each must be an error, in Portuguese.
#[test]
fn the_rarer_errors_speak_portuguese_too() {
    let english = english_words();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(
        d.join("bad-vertex.obj"),
        "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    std::fs::write(d.join("no-faces.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n").unwrap();
    std::fs::write(
        d.join("far-vertex.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    )
    .unwrap();
    std::fs::write(d.join("line.obj"), "v 0 0 0\nv 1 0 0\nl 1 2\n").unwrap();
    std::fs::write(d.join("two-vertices.obj"), "v 0 0 0\nv 1 0 0\nf 1 2\n").unwrap();
    let mesh = |file: &str| {
        scene(
            &format!(
                r#"{{"type": "mesh", "file": "{file}", "material": {{"diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1}}}}"#
            ),
            "",
        )
    };
    let camera =
        |c: &str| format!(r#"{{"lights": [{LIGHT}], "camera": {c}, "surfaces": [{SPHERE}]}}"#);
    let spot = |angle: &str, exponent: &str| {
        with_light(&format!(
            r#"{{"type": "spot", "color": [1, 1, 1], "position": [0, 0, 10], "axis": [0, 0, -1], "angle": {angle}, "exponent": {exponent}, "falloff": 0}}"#
        ))
    };
    let ray = |surfaces: &str| {
        format!(
            r#"{{"lights": [{LIGHT}], "ray": {{"origin": [0, 0, 5], "direction": [0, 0, -1]}}, "surfaces": [{surfaces}]}}"#
        )
    };
    let bad: Vec<(&str, String)> = vec![
        // Point, ray or scene.
        ("point-and-ray", with_point(r#", "ray": {"origin": [0, 0, 5], "direction": [0, 0, -1]}"#)),
        ("scene-without-surfaces", format!(r#"{{"lights": [{LIGHT}], {CAMERA}}}"#)),
        ("point-with-surfaces", with_point(&format!(r#", "surfaces": [{SPHERE}]"#))),
        ("ray-without-surfaces", ray("")),
        (
            "point-without-position",
            format!(r#"{{"lights": [{LIGHT}], "point": {{"normal": [0, 0, 1], "material": {{"diffuse": [1, 1, 1]}}}}}}"#),
        ),
        (
            "viewer-without-position",
            r#"{"lights": [{"type": "directional", "color": [1, 1, 1], "direction": [0, 0, -1]}], "viewer": [0, 0, 5], "point": {"normal": [0, 0, 1], "material": {"diffuse": [1, 1, 1], "specular": [1, 1, 1], "shininess": 1}}}"#.into(),
        ),
        (
            "point-without-normal",
            format!(r#"{{"lights": [{LIGHT}], "point": {{"position": [0, 0, 0], "material": {{"diffuse": [1, 1, 1]}}}}}}"#),
        ),
        ("zero-normal", with_material(r#"{"diffuse": [1, 1, 1]}"#, "").replace("[0, 0, 1]", "[0, 0, 0]")),
        ("f32-long-normal", with_material(r#"{"diffuse": [1, 1, 1]}"#, "").replace("[0, 0, 1]", "[3e38, 3e38, 0]")),
        ("f32-number", with_point(r#", "viewer": [1e39, 0, 0]"#)),
        ("f32-radius", ray(r#"{"type": "sphere", "center": [0, 0, 0], "radius": 1e-50, "material": {"diffuse": [1, 1, 1]}}"#)),
        ("zero-ray-direction", ray(SPHERE).replace("[0, 0, -1]", "[0, 0, 0]")),
        // Lights.
        ("falloff-3", with_light(r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": 3}"#)),
        ("falloff-word", with_light(r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": "quadratic"}"#)),
        ("falloff-other-word", with_light(r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": "strong"}"#)),
        ("number-in-quotes", with_light(r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": "1"}"#)),
        ("point-light-with-axis", with_light(r#"{"type": "point", "color": [1, 1, 1], "position": [0, 0, 10], "falloff": 0, "axis": [0, 0, 1]}"#)),
        ("spot-without-axis", with_light(r#"{"type": "spot", "color": [1, 1, 1], "position": [0, 0, 10], "angle": 30, "exponent": 1, "falloff": 0}"#)),
        ("spot-angle", spot("120", "1")),
        ("spot-exponent", spot("30", "-1")),
        ("zero-spot-axis", spot("30", "1").replace("[0, 0, -1]", "[0, 0, 0]")),
        ("directional-without-direction", with_light(r#"{"type": "directional", "color": [1, 1, 1]}"#)),
        ("negative-light", with_light(r#"{"type": "point", "color": [1, -1, 1], "position": [0, 0, 10], "falloff": 0}"#)),
        // Materials.
        ("no-ambient", format!(r#"{{"lights": [{{"type": "ambient", "color": [1, 1, 1]}}, {LIGHT}], "point": {{"position": [0, 0, 0], "normal": [0, 0, 1], "material": {{"diffuse": [1, 1, 1]}}}}}}"#)),
        ("no-diffuse", with_material(r#"{"ambient": [1, 1, 1]}"#, "")),
        ("no-specular", with_material(r#"{"diffuse": [1, 1, 1]}"#, r#", "viewer": [0, 0, 5]"#)),
        ("no-shininess", with_material(r#"{"diffuse": [1, 1, 1], "specular": [1, 1, 1]}"#, r#", "viewer": [0, 0, 5]"#)),
        ("negative-shininess", with_material(r#"{"diffuse": [1, 1, 1], "shininess": -1}"#, "")),
        ("k-outside", with_material(r#"{"diffuse": {"k": 2, "color": [1, 1, 1]}}"#, "")),
        ("negative-material", with_material(r#"{"diffuse": [1, -1, 1]}"#, "")),
        ("reflectivity-without-specular", with_material(r#"{"diffuse": [1, 1, 1], "reflectivity": "specular"}"#, "")),
        ("no-material-named", with_material(r#""X""#, "")),
        ("no-material-named-of-some", with_material(r#""X""#, r#", "materials": {"M": {"diffuse": [1, 1, 1]}}"#)),
        ("duplicate-material", with_material(r#""M""#, r#", "materials": {"M": {"diffuse": [1, 1, 1]}, "M": {"diffuse": [1, 1, 1]}}"#)),
        // Surfaces and meshes.
        ("sphere-with-normal", ray(r#"{"type": "sphere", "center": [0, 0, 0], "radius": 1, "normal": [0, 0, 1], "material": {"diffuse": [1, 1, 1]}}"#)),
        ("plane-without-point", ray(r#"{"type": "plane", "normal": [0, 0, 1], "material": {"diffuse": [1, 1, 1]}}"#)),
        ("negative-radius", ray(r#"{"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": {"diffuse": [1, 1, 1]}}"#)),
        ("degenerate-triangle", scene(r#"{"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": {"diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1}}"#, "")),
        ("four-numbers", scene(r#"{"type": "triangle", "vertices": [[0, 0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1}}"#, "")),
        ("missing-mesh", mesh("no-such.obj")),
        ("mesh-bad-vertex", mesh("bad-vertex.obj")),
        ("mesh-no-faces", mesh("no-faces.obj")),
        ("mesh-far-vertex", mesh("far-vertex.obj")),
        ("mesh-line", mesh("line.obj")),
        ("mesh-two-vertices", mesh("two-vertices.obj")),
        // The camera and the tracer's settings.
        ("camera-at-its-eye", camera(r#"{"eye": [0, 0, 5], "look_at": [0, 0, 5], "fov": 45, "width": 4, "height": 4}"#)),
        ("camera-up", camera(r#"{"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 45, "width": 4, "height": 4}"#)),
        ("camera-fov", camera(r#"{"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 200, "width": 4, "height": 4}"#)),
        ("camera-width", camera(r#"{"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45, "width": 0, "height": 4}"#)),
        ("max-level-0", scene(SPHERE, r#", "render": {"max_level": 0}"#)),
        ("max-level-5000", scene(SPHERE, r#", "render": {"max_level": 5000}"#)),
        ("min-weight", scene(SPHERE, r#", "render": {"min_weight": -1}"#)),
        ("samples-0", scene(SPHERE, r#", "render": {"samples": 0}"#)),
        ("too-much-work", camera(r#"{"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 45, "width": 16384, "height": 16384}"#).replace("}]}", r#"}], "render": {"samples": 64}}"#)),
        // The syntax.
        ("not-an-object", "[1, 2]".into()),
        ("duplicate-field", r#"{"title": "a", "title": "b"}"#.into()),
        ("out-of-range", with_point(r#", "viewer": [1e400, 0, 0]"#)),
        ("nan", with_point(r#", "viewer": [NaN, 0, 0]"#)),
        ("trailing-comma", with_point(r#", "viewer": [1, 0, 0],"#)),
        // The answer key.
        ("answer-word", with_point(r#", "answer": "red""#)),
        ("answer-hex", with_point(r##", "answer": "#12345""##)),
        ("answer-scale", with_point(r#", "answer": {"color": [1, 0, 0], "scale": 3}"#)),
        ("answer-255", with_point(r#", "answer": {"color": [0.5, 0, 0], "scale": 255}"#)),
        ("answer-hex-on-1", with_point(r##", "answer": {"color": "#FF0000", "scale": 1}"##)),
        ("answer-tolerance", with_point(r#", "answer": {"color": [1, 0, 0], "tolerance": -1}"#)),
    ];
    let mut runs: Vec<(String, Vec<String>)> = Vec::new();
    for (name, text) in &bad {
        let path = d.join(format!("{name}.json"));
        std::fs::write(&path, text).unwrap();
        let p = path.to_string_lossy().into_owned();
        let command = if name.starts_with("answer") {
            "check"
        } else {
            "solve"
        };
        let mut args: Vec<String> = vec![command.into(), "--lang".into(), "pt".into(), p];
        if name.starts_with("f32") {
            args.extend(["--precision".into(), "f32".into()]);
        }
        runs.push((name.to_string(), args));
    }
    std::fs::write(d.join("not-utf8.json"), b"{\"title\": \"\xff\"}").unwrap();
    let file = |n: &str| d.join(n).to_string_lossy().into_owned();
    runs.push((
        "not-utf8".into(),
        vec![
            "solve".into(),
            "--lang".into(),
            "pt".into(),
            file("not-utf8.json"),
        ],
    ));
    // A point problem given to the tracer.
    std::fs::write(
        d.join("point-scene.json"),
        with_point(&format!(", {CAMERA}")),
    )
    .unwrap();
    runs.push((
        "render a point problem".into(),
        vec![
            "render".into(),
            "--lang".into(),
            "pt".into(),
            file("point-scene.json"),
            "-o".into(),
            file("x.png"),
        ],
    ));
    // The answers and steps given on the command line.
    let check = |flags: &[&str]| {
        let mut v: Vec<String> = ["check", "--lang", "pt", "exercises/4.2.json"]
            .map(String::from)
            .to_vec();
        v.extend(flags.iter().map(|s| s.to_string()));
        v
    };
    std::fs::write(d.join("steps-not-json.json"), "cos_theta").unwrap();
    std::fs::write(d.join("steps-empty.json"), "{}").unwrap();
    std::fs::write(d.join("steps-array.json"), "[1]").unwrap();
    std::fs::write(d.join("steps-bool.json"), r#"{"cos_theta": true}"#).unwrap();
    let steps = |n: &str| file(n);
    for (name, flags) in [
        ("--answer empty", vec!["--answer", ""]),
        (
            "--answer unicode minus",
            vec!["--answer", "\u{2212}0.5 0 0"],
        ),
        ("--answer full-width", vec!["--answer", "０.5 0 0"]),
        ("--answer 1e400", vec!["--answer", "1e400 0 0"]),
        ("--answer two numbers", vec!["--answer", "0.5 0.5"]),
        (
            "--answer --scale 255",
            vec!["--answer", "0.5 0 0", "--scale", "255"],
        ),
        ("--answer hex", vec!["--answer", "#12"]),
        ("--step unknown", vec!["--step", "foo=1"]),
        ("--step index", vec!["--step", "cos_theta[x]=1"]),
        ("--step not per light", vec!["--step", "N[0]=1"]),
        ("--step value", vec!["--step", "cos_theta=abc"]),
        ("--step vector", vec!["--step", "cos_theta=1,2,3"]),
        ("--step scalar", vec!["--step", "R=1"]),
        ("--step no =", vec!["--step", "cos_theta"]),
        ("--step no such light", vec!["--step", "cos_theta[5]=1"]),
        ("--steps not JSON", vec!["--steps", "STEPS-NOT-JSON"]),
        ("--steps empty", vec!["--steps", "STEPS-EMPTY"]),
        ("--steps array", vec!["--steps", "STEPS-ARRAY"]),
        ("--steps bool", vec!["--steps", "STEPS-BOOL"]),
    ] {
        let flags: Vec<String> = flags
            .iter()
            .map(|f| match *f {
                "STEPS-NOT-JSON" => steps("steps-not-json.json"),
                "STEPS-EMPTY" => steps("steps-empty.json"),
                "STEPS-ARRAY" => steps("steps-array.json"),
                "STEPS-BOOL" => steps("steps-bool.json"),
                other => other.to_owned(),
            })
            .collect();
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        runs.push((name.into(), check(&flags)));
    }
    // Flag values that their parsers refuse (clap prints them; phong says them in Portuguese).
    let render = |flags: &[&str]| {
        let mut v: Vec<String> = ["render", "--lang", "pt", "scenes/4.3.json"]
            .map(String::from)
            .to_vec();
        v.extend(flags.iter().map(|s| s.to_string()));
        v
    };
    for (name, args) in [
        (
            "--tolerance abc",
            check(&["--answer", "0 0 0", "--tolerance", "abc"]),
        ),
        (
            "--tolerance 1e400",
            check(&["--answer", "0 0 0", "--tolerance", "1e400"]),
        ),
        ("--samples 0", render(&["--samples", "0", "-o", "x.png"])),
        ("--samples x", render(&["--samples", "x", "-o", "x.png"])),
        (
            "--max-level 5000",
            render(&["--max-level", "5000", "-o", "x.png"]),
        ),
        (
            "--min-weight -1",
            render(&["--min-weight=-1", "-o", "x.png"]),
        ),
        ("--threads 0", render(&["--threads", "0", "-o", "x.png"])),
        ("--explain-pixel 5", render(&["--explain-pixel", "5"])),
        ("--explain-pixel a,b", render(&["--explain-pixel", "a,b"])),
        (
            "--explain-pixel outside",
            render(&["--explain-pixel", "5000,5000"]),
        ),
    ] {
        runs.push((name.into(), args));
    }
    // The commands' own conflicts.
    runs.push((
        "--answer with two files".into(),
        check(&["exercises/4.1.json", "--answer", "0 0 0"]),
    ));
    runs.push((
        "--step with two files".into(),
        check(&["exercises/4.1.json", "--step", "cos_theta=1"]),
    ));
    runs.push(("render to .jpg".into(), render(&["-o", "x.jpg"])));
    std::fs::copy(root().join("exercises/4.1.json"), d.join("input.json")).unwrap();
    let input = file("input.json");
    runs.push((
        "-o the input".into(),
        ["solve", "--lang", "pt", &input, "-o", &input]
            .map(String::from)
            .to_vec(),
    ));
    // In parallel: a run is a process, and most of the time is its start.
    let results: Vec<(String, String)> = std::thread::scope(|s| {
        let handles: Vec<_> = runs
            .iter()
            .map(|(_, args)| {
                s.spawn(move || {
                    let args: Vec<&str> = args.iter().map(String::as_str).collect();
                    run(&args)
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let mut failures = Vec::new();
    let mut messages = BTreeSet::new();
    for ((name, _), (stdout, stderr)) in runs.iter().zip(&results) {
        if !stderr.starts_with("erro: ") {
            failures.push(format!("{name}: no error in Portuguese: {stdout}{stderr}"));
            continue;
        }
        // The step names listed in a fix are the names to type, not prose.
        let text = match (stderr.find("use um de "), stderr.find(" (os passos de uma")) {
            (Some(a), Some(b)) if a < b => format!("{}{}", &stderr[..a], &stderr[b..]),
            _ => stderr.clone(),
        };
        let found = english_in(&text, &english);
        if !found.is_empty() {
            failures.push(format!("{name}: {found:?} in {stderr}"));
        }
        // The message without its file: the templates differ, not the paths.
        messages.insert(stderr.replace(&d.to_string_lossy().into_owned(), ""));
    }
    assert!(
        failures.is_empty(),
        "English with --lang pt:\n{}",
        failures.join("\n")
    );
    assert!(
        messages.len() == runs.len(),
        "{} distinct errors of {} runs",
        messages.len(),
        runs.len()
    );
}

/// `text` without the step names a fix lists (the names to type, not prose): from "use um de "
/// to " (os passos de uma", and from "confira um passo que ele tem: " to the next ";".
fn without_step_names(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let (Some(a), Some(b)) = (rest.find("use um de "), rest.find(" (os passos de uma")) {
        if b < a {
            break;
        }
        out.push_str(&rest[..a]);
        rest = &rest[b..];
    }
    out.push_str(rest);
    const HAS: &str = "confira um passo que ele tem: ";
    if let Some(a) = out.find(HAS) {
        let end = out[a..].find(';').map_or(out.len(), |e| a + e);
        out.replace_range(a + HAS.len()..end, "");
    }
    out
}

#[test]
fn grade_and_its_own_errors_speak_portuguese() {
    let english = english_words();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let ex = d.join("exercicios");
    std::fs::create_dir(&ex).unwrap();
    for f in ["4.1.json", "4.2.json", "4.3.json"] {
        std::fs::copy(root().join("exercises").join(f), ex.join(f)).unwrap();
    }
    std::fs::write(ex.join("quebrado.json"), "{ \"lights\": [").unwrap();
    let ex = ex.to_str().unwrap().to_owned();
    let write = |name: &str, bytes: &[u8]| {
        let p = d.join(name);
        std::fs::write(&p, bytes).unwrap();
        p.to_str().unwrap().to_owned()
    };
    // Every kind of row `grade` cannot judge, and its notes (duplicates, no student, steps).
    let mut rows = b"student,exercise,answer,steps\n\
        a,4.1,0.5 0.7 0.3\n\
        b,4.1,0.5,0.7,0.3\n\
        c,4.1\n\
        e,4.1,\"0 0 0\n\
        f,4.1,\"0 0 0\"x\n\
        g,,0 0 0\n\
        h,4.9,0 0 0\n\
        i,quebrado,0 0 0\n\
        j,4.1,meio\n\
        k,4.2,0 0 0,cos_thet=0.5\n\
        l,4.2,0 0 0,cos_theta=abc\n\
        m,4.2,0 0 0,cos_psi=0.5\n\
        n,4.3,nenhuma,cos_theta[0]=0.5\n\
        o,4.2,0 0 0,R=0.5\n\
        q,4.1,0.5 0.7 0.3,0.5\n\
        s;4.1;0 0 0\n\
        ,4.1,0.5 0.7 0.3\n\
        p,4.1,0.4 0.7 0.3\n\
        p,4.1,0.5 0.7 0.3\n\
        t,4.2,0.299 0.361 0.318,cos_theta=0.98995; I_l=0.125 0.125 0.125\n"
        .to_vec();
    rows.extend_from_slice(b"d\xff,4.1,0 0 0\nr,4.1,0\x00 0 0\n");
    let rows = write("turma.csv", &rows);
    let header = write(
        "cabecalho.csv",
        "aluno;exercício;passos\nana;4.1;0,5 0,7 0,3\n".as_bytes(),
    );
    let plain = write(
        "simples.csv",
        b"aluno,exercicio,resposta\nana,4.1,0.5 0.7 0.3\n",
    );
    let many = write("muitas.csv", &b"a\n".repeat(1_000_001));
    let bad_json = write("rubrica-ruim.json", b"{\"points\": {\"4.1\": 1}");
    let unknown = write("rubrica-campo.json", br#"{"pontos": {"4.1": 1}}"#);
    let negative = write("rubrica-negativa.json", br#"{"points": {"4.1": -1}}"#);
    let credit = write("rubrica-credito.json", br#"{"reading_credit": 2}"#);
    let occupied = write("ocupado", b"x");
    let missing_dir = d.join("pasta-inexistente").join("relatorio.csv");
    let missing_dir = missing_dir.to_str().unwrap();
    let missing_summary = d.join("pasta-inexistente").join("resumo.csv");
    let missing_summary = missing_summary.to_str().unwrap();
    let grade = |extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = ["grade", "--lang", "pt", "--exercises", &ex]
            .iter()
            .map(|s| (*s).to_owned())
            .collect();
        v.extend(extra.iter().map(|s| (*s).to_owned()));
        v
    };
    // The runs whose errors stop `grade` (each its own template), and those that write reports.
    let errors: Vec<(&str, Vec<String>)> = vec![
        (
            "not a folder",
            vec![
                "grade".into(),
                "--lang".into(),
                "pt".into(),
                "--exercises".into(),
                "sem-pasta".into(),
                plain.clone(),
            ],
        ),
        ("no such file", grade(&["arquivo-inexistente.csv"])),
        ("too many rows", grade(&[&many])),
        ("--points without =", grade(&[&plain, "--points", "4.1"])),
        (
            "--points not a number",
            grade(&[&plain, "--points", "4.1=x"]),
        ),
        ("--points negative", grade(&[&plain, "--points", "4.1=-1"])),
        (
            "--reading-credit 2",
            grade(&[&plain, "--reading-credit", "2"]),
        ),
        (
            "--rubric missing",
            grade(&[&plain, "--rubric", "rubrica-inexistente.json"]),
        ),
        ("--rubric syntax", grade(&[&plain, "--rubric", &bad_json])),
        (
            "--rubric unknown field",
            grade(&[&plain, "--rubric", &unknown]),
        ),
        ("--rubric negative", grade(&[&plain, "--rubric", &negative])),
        ("--rubric credit", grade(&[&plain, "--rubric", &credit])),
        ("-o the input", grade(&[&plain, "-o", &plain])),
        (
            "-o in a missing folder",
            grade(&[&plain, "-o", missing_dir]),
        ),
        (
            "--summary in a missing folder",
            grade(&[&plain, "--summary", missing_summary]),
        ),
        (
            "gradescope -o a file as a folder",
            grade(&[
                &plain,
                "--format",
                "gradescope",
                "-o",
                &format!("{occupied}/"),
            ]),
        ),
    ];
    let reports: Vec<(&str, Vec<String>)> = vec![
        ("bad rows", grade(&[&rows, "--format", "json"])),
        (
            "a header without the answer",
            grade(&[&header, "--format", "json"]),
        ),
        (
            "not a Moodle export",
            grade(&[&plain, "--input", "moodle", "--format", "json"]),
        ),
    ];
    let mut failures = Vec::new();
    let mut messages = BTreeSet::new();
    for (name, args) in &errors {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (stdout, stderr) = run(&args);
        if !stderr.starts_with("erro: ") {
            failures.push(format!("{name}: no error in Portuguese: {stdout}{stderr}"));
            continue;
        }
        let found = english_in(&stderr, &english);
        if !found.is_empty() {
            failures.push(format!("{name}: {found:?} in {stderr}"));
        }
        let template = stderr
            .lines()
            .next()
            .unwrap_or("")
            .replace(&*d.to_string_lossy(), "");
        messages.insert(template);
    }
    for (name, args) in &reports {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (stdout, stderr) = run(&args);
        let found = english_in(&stderr, &english);
        if !found.is_empty() {
            failures.push(format!("{name} (stderr): {found:?} in {stderr}"));
        }
        let report: serde_json::Value = serde_json::from_str(&stdout)
            .unwrap_or_else(|e| panic!("{name}: {e}: {stdout}{stderr}"));
        for row in report["rows"].as_array().unwrap() {
            let feedback = row["feedback"].as_str().unwrap();
            let found = english_in(&without_step_names(feedback), &english);
            if !found.is_empty() {
                failures.push(format!(
                    "{name}, row {}: {found:?} in {feedback}",
                    row["row"]
                ));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "English with --lang pt:\n{}",
        failures.join("\n")
    );
    assert_eq!(
        messages.len(),
        errors.len(),
        "distinct errors: {messages:#?}"
    );
}

#[test]
fn new_reports_a_file_it_cannot_write_in_portuguese() {
    let english = english_words();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap().to_owned();
    // The first run names the file; a folder of that name then stands in its way.
    let (_, err) = run(&["new", "--kind", "ambient", "--seed", "1", "-o", &out]);
    assert!(err.is_empty(), "{err}");
    let name = std::fs::read_dir(dir.path())
        .unwrap()
        .next()
        .unwrap()
        .unwrap()
        .path();
    std::fs::remove_file(&name).unwrap();
    std::fs::create_dir(&name).unwrap();
    let (_, err) = run(&[
        "new", "--kind", "ambient", "--seed", "1", "--lang", "pt", "-o", &out,
    ]);
    assert!(err.starts_with("erro:"), "{err}");
    let leaked = english_in(&err, &english);
    assert!(leaked.is_empty(), "English in {err:?}: {leaked:?}");
}
