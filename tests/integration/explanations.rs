//! The explanations of `phong solve --format text|markdown|latex|html` in English and
//! Portuguese: insta snapshots (in the top-level `snapshots/`) of every format and language for
//! the chapter's exercises 4.1–4.3, and the command line's handling of `--lang`, `--color`,
//! `NO_COLOR` and `--fragment`.
//!
//! The numbers in these outputs are the solver's, checked independently in
//! `tests/hand_calculations.rs`; here the snapshots pin the layout and the wording, and the
//! assertions check that every format tells the same steps.

use crate::support;

use std::path::Path;

use phong::core::Precision;
use phong::report::explain::{plain, Explanation};
use phong::report::file::explain_file;
use phong::report::html::{write_all as html, HtmlOptions};
use phong::report::lang::Lang;
use phong::report::latex::{write_all as latex, LatexOptions};
use phong::report::markdown::write_all as markdown;
use phong::report::text::write_explanation as text;

const CHAPTER: [&str; 3] = ["4.1", "4.2", "4.3"];

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

fn explain(exercise: &str, lang: Lang) -> Explanation {
    let path = format!("exercises/{exercise}.json");
    explain_file(Path::new(&path), Precision::F64, lang).expect("the chapter's exercises solve")
}

fn lang_code(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "en",
        Lang::Pt => "pt",
    }
}

#[test]
fn every_format_and_language_of_the_chapters_exercises_matches_its_snapshot() {
    settings().bind(|| {
        for exercise in CHAPTER {
            for lang in [Lang::En, Lang::Pt] {
                let x = explain(exercise, lang);
                let l = lang_code(lang);
                let xs = std::slice::from_ref(&x);
                if lang == Lang::Pt {
                    // English text is snapshotted, for every exercise, in tests/snapshots.rs.
                    insta::assert_snapshot!(format!("text-pt@{exercise}"), text(&x, false));
                }
                insta::assert_snapshot!(format!("markdown-{l}@{exercise}"), markdown(xs));
                insta::assert_snapshot!(
                    format!("latex-{l}@{exercise}"),
                    latex(xs, LatexOptions::default())
                );
                insta::assert_snapshot!(
                    format!("html-{l}@{exercise}"),
                    html(xs, HtmlOptions::default(), lang)
                );
            }
        }
    });
}

#[test]
fn every_format_and_language_of_the_secondary_rays_exercise_matches_its_snapshot() {
    settings().bind(|| {
        let exercise = "secondary-rays";
        for lang in [Lang::En, Lang::Pt] {
            let x = explain(exercise, lang);
            let l = lang_code(lang);
            let xs = std::slice::from_ref(&x);
            if lang == Lang::Pt {
                insta::assert_snapshot!(format!("text-pt@{exercise}"), text(&x, false));
            }
            insta::assert_snapshot!(format!("markdown-{l}@{exercise}"), markdown(xs));
            insta::assert_snapshot!(
                format!("latex-{l}@{exercise}"),
                latex(xs, LatexOptions::default())
            );
            insta::assert_snapshot!(
                format!("html-{l}@{exercise}"),
                html(xs, HtmlOptions::default(), lang)
            );
        }
    });
}

#[test]
fn coloured_text_of_exercise_4_2_matches_its_snapshot() {
    settings().bind(|| {
        insta::assert_snapshot!("text-color-en@4.2", text(&explain("4.2", Lang::En), true));
    });
}

/// The steps' lines as plain text, in order, for comparing formats.
fn step_lines(x: &Explanation) -> Vec<String> {
    x.parts
        .iter()
        .filter_map(|p| p.shading.as_ref())
        .flat_map(|s| s.given.iter().chain(&s.steps).chain(&s.total))
        .map(|s| plain(&s.line))
        .collect()
}

#[test]
fn every_format_numbers_the_same_steps_with_the_same_equations() {
    // The walk is shared, so each format shows each step's equation number as many times as
    // the walk has it. Count "4.10" (cos φ, V and the specular term) in 4.2's explanation.
    let x = explain("4.2", Lang::En);
    let walk = x
        .parts
        .iter()
        .filter_map(|p| p.shading.as_ref())
        .flat_map(|s| s.given.iter().chain(&s.steps).chain(&s.total))
        .filter_map(|s| s.eq)
        .filter(|e| e.text(Lang::En).ends_with(" 4.10") && !e.text(Lang::En).contains('Σ'))
        .count();
    assert!(walk >= 9, "4.2 uses Eq. 4.10 at least 3 times per part");
    let xs = std::slice::from_ref(&x);
    let count = |s: &str, pat: &str| s.matches(pat).count();
    let text = text(&x, false);
    // Text: "Eq. 4.10" at the column (and "Σ Eq. 4.10" in each total).
    assert_eq!(count(&text, "  Eq. 4.10\n"), walk);
    let md = markdown(xs);
    assert_eq!(count(&md, "— *Eq. 4.10*\n"), walk);
    let tex = latex(xs, LatexOptions::default());
    assert_eq!(count(&tex, "{\\small Eq.~4.10}"), walk);
    let page = html(xs, HtmlOptions::default(), Lang::En);
    assert_eq!(count(&page, "<span class=\"eq\">Eq. 4.10</span>"), walk);
}

#[test]
fn the_portuguese_explanation_of_4_2_uses_the_chapters_terms() {
    let x = explain("4.2", Lang::Pt);
    let t = text(&x, false);
    for term in [
        "luz ambiente",
        "reflexão difusa",
        "reflexão especular",
        "decaimento",
        "A luz branca (pontual)",
        "observador",
        "normal",
        "Solução (o problema como enunciado)",
        "Leitura provavelmente pretendida",
    ] {
        assert!(t.contains(term), "missing «{term}» in:\n{t}");
    }
    // No English words of the explanation are left in the Portuguese steps.
    for line in step_lines(&x) {
        let words: Vec<&str> = line.split(|c: char| !c.is_alphabetic()).collect();
        for english in [
            "diffuse", "specular", "ambient", "falloff", "viewer", "left", "Light",
        ] {
            assert!(!words.contains(&english), "English «{english}» in «{line}»");
        }
    }
}

#[test]
fn json_stays_language_neutral() {
    let run = |lang: &str| {
        support::phong()
            .args([
                "solve",
                "exercises/4.2.json",
                "--format",
                "json",
                "--lang",
                lang,
            ])
            .output()
            .unwrap()
    };
    let (en, pt) = (run("en"), run("pt"));
    assert!(en.status.success() && pt.status.success());
    assert_eq!(en.stdout, pt.stdout);
}

fn solve(args: &[&str], no_color: Option<&str>) -> std::process::Output {
    let mut cmd = support::phong();
    cmd.arg("solve").args(args).env_remove("NO_COLOR");
    if let Some(v) = no_color {
        cmd.env("NO_COLOR", v);
    }
    cmd.output().unwrap()
}

const ESC: u8 = 0x1b;

#[test]
fn colour_is_off_when_not_writing_to_a_terminal_and_on_when_asked() {
    // assert_cmd captures stdout through a pipe: not a terminal, so auto means no colour.
    let auto = solve(&["exercises/4.2.json"], None);
    assert!(auto.status.success());
    assert!(!auto.stdout.contains(&ESC), "auto coloured a pipe");
    let always = solve(&["exercises/4.2.json", "--color", "always"], None);
    let out = String::from_utf8(always.stdout).unwrap();
    assert!(out.contains("\x1b[1m"), "no bold heading");
    // The swatch of the likely intended reading's colour, (76, 92, 81), as a 24-bit background.
    assert!(out.contains("\x1b[48;2;76;92;81m"), "no swatch:\n{out}");
    let never = solve(&["exercises/4.2.json", "--color", "never"], None);
    assert_eq!(never.stdout, auto.stdout);
}

#[test]
fn no_color_turns_colour_off_in_auto_but_not_when_asked_for_explicitly() {
    // NO_COLOR only changes `auto`; an explicit `--color always` wins (no-color.org).
    let auto = solve(&["exercises/4.1.json", "--color", "auto"], Some("1"));
    assert!(!auto.stdout.contains(&ESC));
    let always = solve(&["exercises/4.1.json", "--color", "always"], Some("1"));
    assert!(always.stdout.contains(&ESC));
}

#[test]
fn text_written_to_a_file_has_no_colour_in_auto() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.txt");
    let run = solve(&["exercises/4.1.json", "-o", path.to_str().unwrap()], None);
    assert!(run.status.success());
    let written = std::fs::read(&path).unwrap();
    assert!(!written.contains(&ESC));
    assert!(String::from_utf8(written)
        .unwrap()
        .starts_with("Exercise 4.1"));
}

#[test]
fn fragment_is_refused_for_formats_without_a_preamble() {
    for format in ["text", "markdown", "json"] {
        let run = solve(
            &["exercises/4.1.json", "--format", format, "--fragment"],
            None,
        );
        assert_eq!(run.status.code(), Some(2), "{format}");
        let err = String::from_utf8_lossy(&run.stderr);
        assert!(err.contains("--fragment") && err.contains("Fix:"), "{err}");
    }
}

#[test]
fn fragments_have_no_preamble_and_documents_do() {
    let out = |args: &[&str]| String::from_utf8(solve(args, None).stdout).unwrap();
    let doc = out(&["exercises/4.1.json", "--format", "latex"]);
    assert!(doc.starts_with("\\documentclass") && doc.ends_with("\\end{document}\n"));
    let frag = out(&["exercises/4.1.json", "--format", "latex", "--fragment"]);
    assert!(!frag.contains("\\documentclass") && !frag.contains("\\begin{document}"));
    assert!(frag.contains("\\section*{Exercise 4.1}"));
    let page = out(&["exercises/4.1.json", "--format", "html"]);
    assert!(page.starts_with("<!DOCTYPE html>") && page.contains("<style>"));
    let frag = out(&["exercises/4.1.json", "--format", "html", "--fragment"]);
    assert!(frag.starts_with("<article") && !frag.contains("<html"));
}

#[test]
fn the_html_page_fetches_nothing() {
    let page = html(
        &[explain("4.2", Lang::En), explain("4.3", Lang::Pt)],
        HtmlOptions::default(),
        Lang::En,
    );
    for network in [
        "http://", "https://", "<script", "<link", "@import", "url(http", "src=",
    ] {
        let allowed = network == "http://"
            && page.matches(network).count()
                == page.matches("xmlns=\"http://www.w3.org/2000/svg\"").count();
        assert!(
            allowed || !page.contains(network),
            "the page contains «{network}»"
        );
    }
}

#[test]
fn several_files_make_one_document_with_unique_ids_and_a_bad_file_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.json");
    std::fs::write(&bad, "{").unwrap();
    let run = solve(
        &[
            "exercises/4.2.json",
            bad.to_str().unwrap(),
            "exercises/several-lights.json",
            "--format",
            "html",
        ],
        None,
    );
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("bad.json"));
    let page = String::from_utf8(run.stdout).unwrap();
    assert_eq!(page.matches("<!DOCTYPE html>").count(), 1);
    assert_eq!(page.matches("<article").count(), 2);
    let mut ids: Vec<&str> = page
        .split(" id=\"")
        .skip(1)
        .map(|s| &s[..s.find('"').unwrap()])
        .collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "duplicate ids in the page");
}

#[test]
fn the_readmes_screenshot_is_there_and_stays_small() {
    let size = std::fs::metadata("docs/explain-4.2.png")
        .expect("README.md shows docs/explain-4.2.png")
        .len();
    assert!(
        size < 60_000,
        "docs/explain-4.2.png is {size} bytes: shrink it (pngquant)"
    );
    let readme = std::fs::read_to_string("README.md").unwrap();
    assert!(readme.contains("docs/explain-4.2.png"));
}
