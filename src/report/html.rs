//! The HTML explanation (`phong solve --format html`): one self-contained page (inline CSS and
//! SVG, no scripts, no fonts or anything else fetched), with colour swatches beside every
//! colour, the final colour as a large swatch, and a diagram of the plane of incidence for each
//! light (`report::diagram`). It lays out an [`Explanation`]; `--fragment` gives the
//! `<article>`s only, for embedding in a page that brings the same stylesheet (`STYLE`).

use std::fmt::Write;

use super::diagram;
use super::document::{exercise_word, Document};
use super::explain::{
    language_tag, nest, to_rgb8, DataRow, Explanation, Inline, Node, Shading, Step,
};
use super::formula::{push_html_escaped, unicode_to_html};
use super::messages::Phrase;
use crate::text::lang::Lang;
use crate::text::number::{num, vec3};

/// The page's stylesheet.
pub(crate) const STYLE: &str = "\
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,'DejaVu Sans',sans-serif;max-width:60rem;margin:1.5rem auto;padding:0 1rem;line-height:1.45;color:#1a1a1a;background:#fff}
h1{font-size:1.5rem;margin-bottom:.2rem}h2{font-size:1.2rem;margin-top:1.6rem;border-bottom:1px solid #ddd}h3{font-size:1rem;margin:.9rem 0 .3rem}
.source{color:#666;margin-top:0}
blockquote{margin:.5rem 0;padding:.4rem .8rem;border-left:4px solid #bbb;background:#f7f7f7}
.findings li{list-style:none;margin-left:-1.2rem}.findings li::before{content:'! ';font-weight:bold;color:#b36b00}
ol,ul{padding-left:1.6rem}li{margin:.1rem 0}
.eq{float:right;color:#777;font-size:.85em;margin-left:1rem}
.m{font-family:'DejaVu Serif',Georgia,serif;font-style:italic;white-space:nowrap}
.sw{display:inline-block;width:.9em;height:.9em;border:1px solid #555;vertical-align:-.1em;margin-left:.25em}
.result{display:flex;align-items:center;gap:1rem;margin:.6rem 0;padding:.5rem;background:#fafafa;border:1px solid #e3e3e3}
.big{width:4rem;height:4rem;border:1px solid #333;flex:none}
.reading{color:#444;font-style:italic}
.diagrams{display:flex;flex-wrap:wrap;gap:1rem}
figure.diagram{margin:.4rem 0;max-width:340px}figcaption{font-size:.8em;color:#555}
table.data,table.key{border-collapse:collapse;margin:.6rem 0}table.data td,table.data th,table.key td,table.key th{border-top:1px solid #ddd;padding:.25rem .6rem;text-align:left;vertical-align:top}
.set{text-align:center;margin-bottom:1.5rem}.set .course{font-variant:small-caps;font-size:1.1rem}.set h1{font-size:1.8rem}
svg text{font-family:'DejaVu Sans',sans-serif;font-size:14px}svg text.sym{font-weight:bold;font-style:italic}svg text.note{font-size:11px;fill:#777}svg text.mark{font-size:12px}
";

/// Escapes text for HTML.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        push_html_escaped(&mut out, c);
    }
    out
}

/// A colour's swatch: a square SVG filled by a presentation attribute (`fill`), not a `style`
/// attribute, so that a page served under a Content-Security-Policy without `'unsafe-inline'`
/// styles (`phong serve`) shows it too; named for screen readers by `title`, hidden without one.
/// Its size in pixels is also given as attributes, for a page without the stylesheet (a Moodle
/// question's text), where it would otherwise be an SVG's default 300 × 150.
pub(crate) fn swatch(rgb: [u8; 3], class: &str, title: &str) -> String {
    let [r, g, b] = rgb;
    let size = if class == "big" { 64 } else { 14 };
    let named = if title.is_empty() {
        " aria-hidden=\"true\">".to_owned()
    } else {
        let t = esc(title);
        format!(" role=\"img\" aria-label=\"{t}\"><title>{t}</title>")
    };
    format!(
        "<svg class=\"{class}\" width=\"{size}\" height=\"{size}\" viewBox=\"0 0 1 1\" \
         preserveAspectRatio=\"none\"{named}\
         <rect width=\"1\" height=\"1\" fill=\"rgb({r},{g},{b})\"/></svg>"
    )
}

/// A line's pieces as HTML.
pub(crate) fn line(pieces: &[Inline]) -> String {
    let mut s = String::new();
    for piece in pieces {
        match piece {
            Inline::Text(t) => s.push_str(&esc(t)),
            Inline::Math(f) => {
                let _ = write!(
                    s,
                    "<span class=\"m\">{}</span>",
                    unicode_to_html(f.unicode())
                );
            }
            Inline::Num(x) => s.push_str(&num(*x)),
            Inline::Vector(x) => s.push_str(&vec3(*x)),
            Inline::Color(x) => {
                s.push_str(&vec3(*x));
                s.push_str(&swatch(to_rgb8(*x), "sw", &vec3(*x)));
            }
            Inline::Degrees(x) => {
                s.push_str(&num(*x));
                s.push('°');
            }
            Inline::Rgb8([r, g, b]) => {
                let _ = write!(s, "({r}, {g}, {b})");
            }
            Inline::Swatch(_) => {}
        }
    }
    s
}

fn step(step: &Step, lang: Lang) -> String {
    let eq = step.eq.map_or(String::new(), |e| {
        format!("<span class=\"eq\">{}</span>", esc(&e.text(lang)))
    });
    format!("{eq}{}", line(&step.line))
}

/// The ids of a part's steps: the first step applying each equation is
/// `part-{article}-{part}-eq-4-7`, so that a verdict can link to the step where a slip departs
/// ([`step_anchor`]).
struct Anchors {
    prefix: String,
    seen: Vec<String>,
}

impl Anchors {
    fn new(prefix: String) -> Self {
        Anchors {
            prefix,
            seen: Vec::new(),
        }
    }

    /// The id of `step`, if it is the first of the part to apply its equation.
    fn id(&mut self, step: &Step) -> Option<String> {
        let a = step.eq?.anchor();
        if self.seen.contains(&a) {
            return None;
        }
        let id = format!("{}-{a}", self.prefix);
        self.seen.push(a);
        Some(id)
    }
}

/// The id of the step of part `part` of article `index` that first applies the equation of
/// `anchor` (`Ref::anchor`), as [`write_parts`] writes it; `None` when no step of the part
/// applies it.
pub(crate) fn step_anchor(
    x: &Explanation,
    index: usize,
    part: usize,
    anchor: &str,
) -> Option<String> {
    let p = x.parts.get(part)?;
    let mut steps = p.ray.iter().flatten();
    let shading = p
        .shading
        .iter()
        .flat_map(|sh| sh.steps.iter().chain(&sh.total).chain(&sh.secondary));
    steps
        .by_ref()
        .chain(shading)
        .any(|s| s.eq.is_some_and(|e| e.anchor() == anchor))
        .then(|| format!("part-{index}-{part}-{anchor}"))
}

fn list(out: &mut String, nodes: &[Node], numbered: bool, lang: Lang) {
    list_in(out, nodes, numbered, lang, None);
}

fn list_in(
    out: &mut String,
    nodes: &[Node],
    numbered: bool,
    lang: Lang,
    mut anchors: Option<&mut Anchors>,
) {
    if nodes.is_empty() {
        return;
    }
    let tag = if numbered { "ol" } else { "ul" };
    let _ = writeln!(out, "<{tag}>");
    for node in nodes {
        match anchors.as_deref_mut().and_then(|a| a.id(node.step)) {
            Some(id) => {
                let _ = write!(out, "<li id=\"{id}\">{}", step(node.step, lang));
            }
            None => {
                let _ = write!(out, "<li>{}", step(node.step, lang));
            }
        }
        if !node.children.is_empty() {
            out.push('\n');
            list_in(out, &node.children, numbered, lang, anchors.as_deref_mut());
        }
        out.push_str("</li>\n");
    }
    let _ = writeln!(out, "</{tag}>");
}

fn shading(
    out: &mut String,
    sh: &Shading,
    lang: Lang,
    id: &str,
    level: usize,
    anchors: &mut Anchors,
) {
    // The result first: the colour, large.
    let total = sh
        .total
        .iter()
        .find(|s| s.line.first() == Some(&Inline::Math(super::formula::Formula::I)));
    let _ = writeln!(
        out,
        "<div class=\"result\">{}<div>{}<br>{}</div></div>",
        swatch(sh.rgb8, "big", Phrase::Swatch.get(lang)),
        total.map_or(String::new(), |s| line(&s.line)),
        sh.total
            .iter()
            .find(|s| s.line.iter().any(|p| matches!(p, Inline::Swatch(_))))
            .map_or(String::new(), |s| line(&s.line)),
    );
    if !sh.diagrams.is_empty() {
        out.push_str("<div class=\"diagrams\">\n");
        for d in &sh.diagrams {
            let did = format!("{id}-light{}", d.light_index);
            out.push_str(&diagram::svg(d, &did, lang));
        }
        out.push_str("</div>\n");
    }
    // The data given has no anchors: a slip departs in a step computed.
    for (heading, steps, numbered, anchored) in [
        (Phrase::Given, &sh.given, false, false),
        (Phrase::Steps, &sh.steps, true, true),
        (Phrase::Total, &sh.total, false, true),
        (Phrase::SecondaryRays, &sh.secondary, false, true),
    ] {
        if !steps.is_empty() {
            let h = level + 1;
            let _ = writeln!(out, "<h{h}>{}</h{h}>", heading.get(lang));
            let a = anchored.then_some(&mut *anchors);
            list_in(out, &nest(steps), numbered, lang, a);
        }
    }
}

/// The `<article>` of one explanation; `index` makes its ids unique in the page.
pub(crate) fn write_article(x: &Explanation, index: usize) -> String {
    article(x, index, &x.title)
}

fn article(x: &Explanation, index: usize, heading: &str) -> String {
    let mut out = format!("<article class=\"problem\" id=\"problem-{index}\">\n");
    out.push_str(&head(heading, &x.source(), x.question.as_deref()));
    out.push_str(&write_parts(x, index, 2));
    out.push_str("</article>\n");
    out
}

/// The head of a document: its title (`<h1>`), its source, and its question quoted.
pub(crate) fn head(title: &str, source: &str, question: Option<&str>) -> String {
    let mut out = format!(
        "<h1>{}</h1>\n<p class=\"source\">{}</p>\n",
        esc(title),
        esc(source)
    );
    if let Some(q) = question {
        let _ = writeln!(
            out,
            "<blockquote class=\"question\">{}</blockquote>",
            esc(q)
        );
    }
    out
}

/// The findings, the ray and the parts of an explanation, without its title and question
/// (a pixel's rays share their scene's), their headings at `level` (`<h2>` under an
/// explanation's own `<h1>`); `index` makes its ids unique in the page.
pub(crate) fn write_parts(x: &Explanation, index: usize, level: usize) -> String {
    let lang = x.lang;
    let h = level;
    let mut out = String::new();
    if !x.findings.is_empty() {
        let _ = writeln!(
            out,
            "<section class=\"findings\">\n<h{h}>{}</h{h}>\n<ul>",
            Phrase::Findings.get(lang)
        );
        for f in &x.findings {
            let _ = writeln!(out, "<li>{}</li>", esc(f));
        }
        out.push_str("</ul>\n</section>\n");
    }
    if let Some(ray) = &x.ray {
        let _ = writeln!(
            out,
            "<section class=\"ray\">\n<h{h}>{}</h{h}>",
            Phrase::Ray.get(lang)
        );
        list(&mut out, &nest(ray), false, lang);
        out.push_str("</section>\n");
    }
    for (i, part) in x.parts.iter().enumerate() {
        let id = format!("diagram-{index}-{i}");
        let _ = writeln!(
            out,
            "<section class=\"part\" id=\"part-{index}-{i}\">\n<h{h}>{}</h{h}>",
            esc(&part.heading)
        );
        if let Some(e) = &part.explanation {
            let _ = writeln!(out, "<p class=\"reading\">{}</p>", esc(e));
        }
        let mut anchors = Anchors::new(format!("part-{index}-{i}"));
        if let Some(ray) = &part.ray {
            list_in(&mut out, &nest(ray), false, lang, Some(&mut anchors));
        }
        match &part.shading {
            Some(sh) => shading(&mut out, sh, lang, &id, level, &mut anchors),
            None => {
                let _ = writeln!(out, "<p>{}</p>", esc(Phrase::NothingToShade.get(lang)));
            }
        }
        out.push_str("</section>\n");
    }
    out
}

/// One exercise's statement: its numbered heading, the question, and its data as a table.
fn statement(out: &mut String, doc: &Document, i: usize) {
    let x = &doc.exercises[i];
    let _ = writeln!(
        out,
        "<article class=\"statement\" id=\"statement-{i}\">\n<h2>{}</h2>",
        esc(&doc.heading(i))
    );
    if let Some(q) = &x.question {
        let _ = writeln!(out, "<p class=\"question\">{}</p>", esc(q));
    }
    out.push_str(&data_table(&x.data, doc.lang));
    out.push_str("</article>\n");
}

/// A problem's data as a table (nothing when there is none).
pub(crate) fn data_table(rows: &[DataRow], lang: Lang) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = format!(
        "<table class=\"data\">\n<tr><th>{}</th><th>{}</th></tr>\n",
        Phrase::Quantity.get(lang),
        Phrase::Value.get(lang)
    );
    for row in rows {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{}</td></tr>",
            line(&row.what),
            line(&row.value)
        );
    }
    out.push_str("</table>\n");
    out
}

/// The answer key: one table, a row per exercise.
fn key(out: &mut String, doc: &Document) {
    let lang = doc.lang;
    let _ = writeln!(
        out,
        "<section class=\"key\">\n<h2>{}</h2>\n<table class=\"key\">\n<tr><th>{}</th><th>{}</th></tr>",
        Phrase::AnswerKey.get(lang),
        exercise_word(lang),
        Phrase::Answer.get(lang)
    );
    for (i, x) in doc.exercises.iter().enumerate() {
        let (written, readings) = x.key();
        let mut cell = key_cell(&written);
        for r in &readings {
            let _ = write!(cell, "<br><small>{}</small>", key_cell(r));
        }
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{cell}</td></tr>",
            esc(&doc.heading(i))
        );
    }
    out.push_str("</table>\n</section>\n");
}

/// A key's cell: the line, with a swatch where it shows an 8-bit colour.
fn key_cell(pieces: &[Inline]) -> String {
    let mut s = String::new();
    for piece in pieces {
        match piece {
            Inline::Swatch(rgb) => s.push_str(&swatch(*rgb, "sw", "")),
            // A colour is not broken across lines in the key's narrow column.
            Inline::Color(x) => s.push_str(&vec3(*x).replace(' ', "&nbsp;")),
            Inline::Rgb8([r, g, b]) => {
                let _ = write!(s, "({r},&nbsp;{g},&nbsp;{b})");
            }
            other => s.push_str(&line(std::slice::from_ref(other))),
        }
    }
    s
}

/// A document: the header, then the statements, the solutions or the answer key (or all
/// three), as one page or (`fragment`) its body only.
pub fn write_document(doc: &Document, options: HtmlOptions) -> String {
    let mut out = String::new();
    let h = doc.header;
    if !h.is_empty() {
        out.push_str("<header class=\"set\">\n");
        if let (Some(c), Some(_)) = (&h.course, &h.title) {
            let _ = writeln!(out, "<div class=\"course\">{}</div>", esc(c));
        }
        let _ = writeln!(out, "<h1>{}</h1>", esc(&h.document_title(doc)));
        if let Some(b) = h.byline() {
            let _ = writeln!(out, "<div class=\"byline\">{}</div>", esc(&b));
        }
        out.push_str("</header>\n");
    }
    if doc.contents.statements() {
        for i in 0..doc.exercises.len() {
            statement(&mut out, doc, i);
        }
    }
    if doc.contents.solutions() {
        for (i, x) in doc.exercises.iter().enumerate() {
            out.push_str(&article(
                x,
                doc.first_number + i - 1,
                &doc.solution_heading(i),
            ));
        }
    }
    if doc.contents.key() {
        key(&mut out, doc);
    }
    if options.fragment {
        return out;
    }
    page(&esc(&doc.header.document_title(doc)), &out, doc.lang)
}

/// A complete page around `body`.
pub(crate) fn page(title: &str, body: &str, lang: Lang) -> String {
    page_styled(title, body, lang, "")
}

/// [`page`] with `extra` rules after the stylesheet's.
pub(crate) fn page_styled(title: &str, body: &str, lang: Lang, extra: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>\n{STYLE}{extra}</style>\n</head>\n<body>\n{body}</body>\n\
         </html>\n",
        language_tag(lang)
    )
}

/// How to write the HTML.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HtmlOptions {
    /// The `<article>`s only, without `<html>`, `<head>` and the stylesheet.
    pub fragment: bool,
}

/// The HTML of several explanations: one page, or the articles only.
pub fn write_all(xs: &[Explanation], options: HtmlOptions, lang: Lang) -> String {
    let articles: String = xs
        .iter()
        .enumerate()
        .map(|(i, x)| write_article(x, i))
        .collect();
    if options.fragment {
        return articles;
    }
    let title = match xs {
        [one] => esc(&one.title),
        _ => esc(Phrase::Solutions.get(lang)),
    };
    page(&title, &articles, lang)
}
