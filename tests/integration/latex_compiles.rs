//! The LaTeX explanation compiles: every exercise in `exercises/`, in English and in
//! Portuguese, and a problem whose title, question and light names hold TeX's special
//! characters, accents and a character the fonts lack, each compiled by pdflatex (Debian's
//! texlive, installed by `.ci/run`); the documents of `--part statement|key|all` with a set's
//! header; and the fragment `\input` into a preamble with `\usepackage[brazilian]{babel}` and
//! one with `[english]`. Every compilation fails on an overfull line and on any babel warning
//! (a missing language, a shorthand). Under `CI=true` a missing pdflatex is a failure;
//! elsewhere the test says it was skipped and why.

use crate::support;

use std::path::Path;
use std::process::Command;

use phong::core::Precision;
use phong::report::document::{Contents, Document, Header};
use phong::report::file::explain_file;
use phong::report::lang::Lang;
use phong::report::latex::{write_all, write_document, LatexOptions};

const INSTALL: &str = "apt-get install -y --no-install-recommends texlive-latex-base \
                       texlive-latex-recommended texlive-lang-portuguese texlive-pictures \
                       lmodern";

/// Compiles `tex` in `dir` as `name.tex`; on failure, panics with the errors of the log.
fn compile(pdflatex: &Path, dir: &Path, name: &str, tex: &str) {
    std::fs::write(dir.join(format!("{name}.tex")), tex).unwrap();
    let out = Command::new(pdflatex)
        .current_dir(dir)
        .args([
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-no-shell-escape",
            &format!("{name}.tex"),
        ])
        .output()
        .expect("pdflatex runs");
    let log = String::from_utf8_lossy(&out.stdout);
    let errors: Vec<&str> = log
        .lines()
        .skip_while(|l| !l.starts_with('!'))
        .take(12)
        .collect();
    assert!(
        out.status.success(),
        "pdflatex failed on {name}.tex:\n{}\n--- the LaTeX ---\n{tex}",
        errors.join("\n")
    );
    let pdf = std::fs::metadata(dir.join(format!("{name}.pdf"))).expect("a PDF is written");
    assert!(pdf.len() > 1000, "{name}.pdf is only {} bytes", pdf.len());
    // The log, not stdout: pdflatex wraps its lines at 79 columns in both, but the log has all.
    let log = std::fs::read(dir.join(format!("{name}.log"))).expect("a log is written");
    let log = String::from_utf8_lossy(&log);
    let lines: Vec<&str> = log.lines().collect();
    for (i, l) in lines.iter().enumerate() {
        let bad = l.starts_with("Overfull \\hbox")
            || l.starts_with("Package babel Warning")
            || l.contains("babel") && l.contains("Warning");
        assert!(
            !bad,
            "{name}.tex: {}\n--- the LaTeX ---\n{tex}",
            lines[i..(i + 4).min(lines.len())].join("\n")
        );
    }
}

#[test]
#[ignore = "needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended lmodern texlive-lang-portuguese texlive-pictures (.ci/run does)"]
fn the_latex_of_every_exercise_compiles_in_both_languages() {
    let Some(pdflatex) = support::require("pdflatex", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let mut exercises: Vec<_> = std::fs::read_dir("exercises")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    exercises.sort();
    assert!(exercises.len() >= 16, "the exercises are there");
    for path in &exercises {
        for (lang, code) in [(Lang::En, "en"), (Lang::Pt, "pt")] {
            let x = explain_file(path, Precision::F64, lang).expect("every exercise solves");
            let tex = write_all(std::slice::from_ref(&x), LatexOptions::default());
            let stem = path
                .file_stem()
                .unwrap()
                .to_str()
                .unwrap()
                .replace('.', "-");
            compile(&pdflatex, dir.path(), &format!("{stem}-{code}"), &tex);
        }
    }
}

#[test]
#[ignore = "needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended lmodern texlive-lang-portuguese texlive-pictures (.ci/run does)"]
fn user_text_with_special_characters_and_accents_compiles() {
    let Some(pdflatex) = support::require("pdflatex", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let problem = serde_json::json!({
        "title": r"Exercício 4.2 — 50% de $x_1 & #2 {a} ~ ^ \ «ção» 光",
        "question": "Qual é a cor? Reflexão difusa, decaimento quadrático: ã é í ó ú ç à ê ô õ Ç É. \\end{document} %",
        "materials": { "M_1 & {x}": { "diffuse": [0.7, 0.8, 0.6], "specular": [0.2, 0.3, 0.4], "shininess": 1 } },
        "lights": [
            { "type": "point", "position": [0, 0, 5], "color": [1, 1, 1], "falloff": 0, "name": "luz #1 $\\alpha$ ~ 100%" }
        ],
        "viewer": [0, 3, 4],
        "point": { "position": [0, 0, 0], "normal": [0, 0, 1], "material": "M_1 & {x}" }
    });
    let path = dir.path().join("hostile.json");
    std::fs::write(&path, problem.to_string()).unwrap();
    for (lang, code) in [(Lang::En, "en"), (Lang::Pt, "pt")] {
        let x = explain_file(&path, Precision::F64, lang).expect("the problem solves");
        let tex = write_all(std::slice::from_ref(&x), LatexOptions::default());
        assert!(
            tex.contains("\\texttt{[U+5149]}"),
            "the CJK character is shown as its code"
        );
        compile(&pdflatex, dir.path(), &format!("hostile-{code}"), &tex);
    }
}

#[test]
#[ignore = "needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended lmodern texlive-lang-portuguese texlive-pictures (.ci/run does)"]
fn a_fragment_compiles_inside_a_document_that_loads_amsmath_xcolor_and_tikz() {
    let Some(pdflatex) = support::require("pdflatex", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let xs: Vec<_> = ["exercises/4.2.json", "exercises/4.3.json"]
        .iter()
        .map(|p| explain_file(Path::new(p), Precision::F64, Lang::Pt).unwrap())
        .collect();
    let body = write_all(&xs, LatexOptions { fragment: true });
    let tex = format!(
        "\\documentclass{{article}}\n\\usepackage[utf8]{{inputenc}}\n\\usepackage[T1]{{fontenc}}\n\
         \\usepackage{{lmodern,amsmath,xcolor,tikz}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    compile(&pdflatex, dir.path(), "notes", &tex);
}

/// The exercises of the chapter, in `lang`.
fn chapter(lang: Lang) -> Vec<phong::report::explain::Explanation> {
    [
        "exercises/4.1.json",
        "exercises/4.2.json",
        "exercises/4.3.json",
    ]
    .iter()
    .map(|p| explain_file(Path::new(p), Precision::F64, lang).unwrap())
    .collect()
}

#[test]
#[ignore = "needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended lmodern texlive-lang-portuguese texlive-pictures (.ci/run does)"]
fn the_handout_the_key_and_the_whole_set_compile_in_both_languages() {
    let Some(pdflatex) = support::require("pdflatex", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let header = Header {
        course: Some("Computação Gráfica".into()),
        title: Some("Lista 4 — Modelos de Iluminação".into()),
        date: Some("1 de dezembro de 2026".into()),
        author: Some("Paulo Pagliosa".into()),
    };
    for (lang, code) in [(Lang::En, "en"), (Lang::Pt, "pt")] {
        let xs = chapter(lang);
        for (contents, part) in [
            (Contents::Statement, "statement"),
            (Contents::Key, "key"),
            (Contents::All, "all"),
        ] {
            let doc = Document {
                header: &header,
                contents,
                exercises: &xs,
                first_number: 1,
                lang,
            };
            let tex = write_document(&doc, LatexOptions::default());
            compile(&pdflatex, dir.path(), &format!("{part}-{code}"), &tex);
        }
    }
}

#[test]
#[ignore = "needs pdflatex: apt-get install texlive-latex-base texlive-latex-recommended lmodern texlive-lang-portuguese texlive-pictures (.ci/run does)"]
fn a_fragment_input_under_babel_brazilian_or_english_compiles_without_warnings() {
    let Some(pdflatex) = support::require("pdflatex", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    for (lang, code, babel) in [(Lang::Pt, "pt", "brazilian"), (Lang::En, "en", "english")] {
        let xs = chapter(lang);
        let header = Header::default();
        let doc = Document {
            header: &header,
            contents: Contents::All,
            exercises: &xs,
            first_number: 1,
            lang,
        };
        let body = write_document(&doc, LatexOptions { fragment: true });
        std::fs::write(dir.path().join(format!("body-{code}.tex")), body).unwrap();
        let tex = format!(
            "\\documentclass[11pt]{{article}}\n\\usepackage[utf8]{{inputenc}}\n\
             \\usepackage[T1]{{fontenc}}\n\\usepackage[{babel}]{{babel}}\n\
             \\usepackage{{lmodern,amsmath,xcolor,tikz}}\n\\usepackage[a4paper,margin=2cm]{{geometry}}\n\
             \\begin{{document}}\n\\input{{body-{code}}}\n\\end{{document}}\n"
        );
        compile(&pdflatex, dir.path(), &format!("babel-{code}"), &tex);
    }
}
