//! One vocabulary (issue 29, item 5): docs/glossary.md gives one Portuguese term per idea and
//! the words not to use for it; no message in `src/` uses those. And the small slips the issue
//! listed: "como escrito" beside "como enunciado", the answer key breaking "(76, 92, 81)"
//! across lines, the glass scene's "(0,85; 0,85; 0,85)" beside "0.85".

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
    assert!(out.status.code().is_some_and(|c| c <= 1), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The words the glossary's third column says phong does not use.
fn avoided() -> Vec<String> {
    let glossary = std::fs::read_to_string(root().join("docs/glossary.md")).unwrap();
    let mut words = Vec::new();
    for line in glossary.lines().filter(|l| l.starts_with('|')) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        // | English | Português | not |: cells[0] is empty, cells[3] the words to avoid.
        if let Some(not) = cells.get(3) {
            if not.starts_with("not") || not.starts_with("---") {
                continue;
            }
            words.extend(
                not.split(',')
                    .map(|w| w.trim().to_lowercase())
                    .filter(|w| !w.is_empty()),
            );
        }
    }
    words
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_message_uses_a_word_the_glossary_sets_aside() {
    let words = avoided();
    for w in [
        "como escrito",
        "solução resolvida",
        "refletividade",
        "raio refletido",
    ] {
        assert!(words.iter().any(|x| x == w), "{w} is in the glossary");
    }
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    let mut bad = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for (n, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            let lower = line.to_lowercase();
            for w in &words {
                if lower.contains(w.as_str()) {
                    bad.push(format!(
                        "{}:{}: «{w}»: {}",
                        file.display(),
                        n + 1,
                        line.trim()
                    ));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn the_portuguese_documents_say_como_enunciado() {
    for format in ["text", "markdown", "latex", "html"] {
        let doc = phong(&[
            "solve",
            "exercises/4.2.json",
            "exercises/4.3.json",
            "--format",
            format,
            "--lang",
            "pt",
        ]);
        assert!(doc.contains("o problema como enunciado"), "{format}");
        assert!(!doc.contains("como escrito"), "{format}");
    }
    let key = phong(&[
        "solve",
        "exercises/4.3.json",
        "--part",
        "key",
        "--lang",
        "pt",
    ]);
    assert!(key.contains("nenhuma interseção"), "{key}");
}

#[test]
fn the_answer_key_keeps_each_colour_on_one_line() {
    let files: Vec<String> = std::fs::read_dir(root().join("exercises"))
        .unwrap()
        .map(|e| e.unwrap().path().display().to_string())
        .filter(|p| p.ends_with(".json"))
        .collect();
    for lang in ["en", "pt"] {
        let mut args = vec!["solve", "--part", "key", "--lang", lang, "--color", "never"];
        args.extend(files.iter().map(String::as_str));
        // Text: every "(" that opens a number closes on its line.
        let text = phong(&args);
        for line in text.lines() {
            for (i, _) in line.match_indices('(') {
                let next = line[i + 1..].chars().next();
                if next.is_some_and(|c| c.is_ascii_digit() || c == '-') {
                    assert!(
                        line[i..].contains(')'),
                        "a colour broken across lines: {line}"
                    );
                }
            }
        }
        // 4.2's likely intended reading is (0.299, 0.361, 0.318): 255 × each, rounded, is
        // (76, 92, 81) (76.29, 92.11, 81.17), kept whole in every format.
        assert!(text.contains("· (76, 92, 81)"), "{text}");
        args.extend(["--format", "latex"]);
        let latex = phong(&args);
        assert!(latex.contains("\\mbox{(76, 92, 81)}"), "{latex}");
        let n = args.len();
        args[n - 1] = "html";
        let html = phong(&args);
        assert!(html.contains("(76,&nbsp;92,&nbsp;81)"), "{html}");
    }
}

#[test]
fn the_glass_scene_writes_its_numbers_as_phong_does() {
    let glass = std::fs::read_to_string(root().join("scenes/glass.json")).unwrap();
    let file: serde_json::Value = serde_json::from_str(&glass).unwrap();
    let pt = file["question_pt"].as_str().unwrap();
    assert!(pt.contains("O_t = (0.85, 0.85, 0.85)"), "{pt}");
    assert!(pt.contains("índice de refração 1.5"), "{pt}");
    assert!(!pt.contains("0,85"), "{pt}");
}
