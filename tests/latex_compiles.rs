//! The LaTeX explanation compiles: every exercise in `exercises/`, in English and in
//! Portuguese, and a problem whose title, question and light names hold TeX's special
//! characters, accents and a character the fonts lack, each compiled by pdflatex (Debian's
//! texlive, installed by `.ci/run`). Under `CI=true` a missing pdflatex is a failure; elsewhere
//! the test says it was skipped and why.

mod support;

use std::path::Path;
use std::process::Command;

use phong::core::Precision;
use phong::report::file::explain_file;
use phong::report::lang::Lang;
use phong::report::latex::{write_all, LatexOptions};

const INSTALL: &str = "apt-get install -y --no-install-recommends texlive-latex-base \
                       texlive-latex-recommended lmodern";

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
}

#[test]
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
fn a_fragment_compiles_inside_a_document_that_loads_amsmath_and_xcolor() {
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
         \\usepackage{{lmodern,amsmath,xcolor}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    compile(&pdflatex, dir.path(), "notes", &tex);
}
