//! With `--lang pt` every phrase the user can see is Portuguese: every command that takes
//! `--lang` (solve in every format and part, check, check --slips, render --explain-pixel in
//! every format) and their common errors, run on the bundled exercises and the 4.3 scene. The
//! test fails on any English word of a list: the English catalogue's words that its Portuguese
//! does not use, and the distinctive words of the other English messages.
//!
//! What is not prose is left out before the words are read: the file's own identifiers (JSON
//! field names in quotes or backticks, `lights[0]`, slip codes such as `light_reversed`), LaTeX
//! commands and environment names, TikZ's drawing commands (not its labels), HTML tags, the
//! CSS, and the file names.

use std::collections::BTreeSet;
use std::path::Path;

use assert_cmd::Command;
use phong::report::catalogue;
use phong::report::lang::Lang;

/// Words that are rightly the same in both languages, or that are Portuguese too.
const SHARED: &[&str] = &[
    "material", "total", "linear", "spot", "normal", "pixel", "vs", "round", "Eq", "eq",
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

/// The prose of an output: identifiers, markup and file names taken out.
fn prose(s: &str) -> String {
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
    // An error's field comes right after its file ("x.json: point: …"); flags are names.
    let mut previous = "";
    let mut kept = Vec::new();
    for w in out.split_whitespace() {
        let identifier = w.contains('_')
            || w.contains("lights")
            || w.contains("surfaces")
            || w.contains(".json")
            || w.starts_with("--")
            || previous.ends_with(".json:");
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
    let out = Command::cargo_bin("phong")
        .unwrap()
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
