//! The Markdown explanation (`phong solve --format markdown`): numbered steps, each formula with
//! its value in `$…$` math (GitHub, GitLab, Obsidian, Jupyter and pandoc render it) and the
//! chapter's equation number, ready to paste into notes. It lays out an [`Explanation`].

use super::document::{exercise_word, Document};
use super::explain::{
    latex_math, nest, runs, DataRow, Explanation, Inline, Node, Run, Shading, Step,
};
use super::messages::Phrase;
use crate::text::lang::Lang;

/// Escapes text so that Markdown shows it as written.
pub(crate) fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        if matches!(
            c,
            '\\' | '`' | '*' | '_' | '[' | ']' | '<' | '>' | '#' | '|' | '$' | '{' | '}' | '~'
        ) {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// A line's pieces: words escaped, math in `$…$`.
pub(crate) fn pieces(line: &[Inline]) -> String {
    let mut s = String::new();
    for run in runs(line) {
        match run {
            Run::Text(t) => s.push_str(&escape(&t)),
            Run::Math(m) => {
                s.push('$');
                s.push_str(&latex_math(&m));
                s.push('$');
            }
            Run::Swatch(_) => {}
        }
    }
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// A line of a step: words escaped, math in `$…$`.
fn line(step: &Step, lang: Lang) -> String {
    let mut s = pieces(&step.line);
    if let Some(eq) = step.eq {
        s.push_str(&format!(" — *{}*", eq.text(lang)));
    }
    s
}

fn list(out: &mut String, nodes: &[Node], depth: usize, numbered: bool, lang: Lang) {
    for (i, node) in nodes.iter().enumerate() {
        let marker = if numbered {
            format!("{}.", i + 1)
        } else {
            "-".to_owned()
        };
        out.push_str(&format!(
            "{:indent$}{marker} {}\n",
            "",
            line(node.step, lang),
            indent = 4 * depth
        ));
        list(out, &node.children, depth + 1, numbered, lang);
    }
}

fn block(out: &mut String, heading: Phrase, steps: &[Step], numbered: bool, lang: Lang) {
    if steps.is_empty() {
        return;
    }
    out.push_str(&format!("**{}**\n\n", heading.get(lang)));
    list(out, &nest(steps), 0, numbered, lang);
    out.push('\n');
}

fn shading(out: &mut String, sh: &Shading, lang: Lang, id: &str) {
    block(out, Phrase::Given, &sh.given, false, lang);
    block(out, Phrase::Steps, &sh.steps, true, lang);
    block(out, Phrase::Total, &sh.total, false, lang);
    block(out, Phrase::SecondaryRays, &sh.secondary, false, lang);
    // The diagrams inline, as the same SVG as the HTML's (Markdown passes HTML through).
    for d in &sh.diagrams {
        out.push_str(&super::diagram::svg(
            d,
            &format!("{id}-light{}", d.light_index),
            lang,
        ));
        out.push('\n');
    }
}

/// The Markdown of one explanation.
pub fn write_explanation(x: &Explanation) -> String {
    explanation(x, &x.title, 0)
}

/// One explanation under `heading`; `index` makes its diagrams' ids unique in the document.
fn explanation(x: &Explanation, heading: &str, index: usize) -> String {
    let mut out = head(heading, &x.source(), x.question.as_deref());
    out.push_str(&write_parts(x, index, 2));
    out
}

/// The head of a document: its title (a level-1 heading, `##`), its source in italics, and
/// its question quoted.
pub(crate) fn head(title: &str, source: &str, question: Option<&str>) -> String {
    let mut out = format!("{} {}\n\n", hashes(1), escape(title));
    out.push_str(&format!("*{}*\n\n", escape(source)));
    if let Some(q) = question {
        out.push_str(&format!("> {}\n\n", escape(q)));
    }
    out
}

/// The marker of a heading of `level` (1 for a document's title, `##`).
pub(crate) fn hashes(level: usize) -> String {
    "#".repeat(level + 1)
}

/// The findings, the ray and the parts of an explanation, without its title and question
/// (a pixel's rays share their scene's), their headings at `level` (2 under an explanation's
/// own title).
pub(crate) fn write_parts(x: &Explanation, index: usize, level: usize) -> String {
    let lang = x.lang;
    let h = hashes(level);
    let mut out = String::new();
    if !x.findings.is_empty() {
        out.push_str(&format!("{h} {}\n\n", Phrase::Findings.get(lang)));
        for f in &x.findings {
            out.push_str(&format!("- **!** {}\n", escape(f)));
        }
        out.push('\n');
    }
    if let Some(ray) = &x.ray {
        out.push_str(&format!("{h} {}\n\n", Phrase::Ray.get(lang)));
        list(&mut out, &nest(ray), 0, false, lang);
        out.push('\n');
    }
    for (i, part) in x.parts.iter().enumerate() {
        out.push_str(&format!("{h} {}\n\n", escape(&part.heading)));
        if let Some(e) = &part.explanation {
            out.push_str(&format!("*{}*\n\n", escape(e)));
        }
        if let Some(ray) = &part.ray {
            list(&mut out, &nest(ray), 0, false, lang);
            out.push('\n');
        }
        match &part.shading {
            Some(sh) => shading(&mut out, sh, lang, &format!("diagram-{index}-{i}")),
            None => out.push_str(&format!("{}\n\n", escape(Phrase::NothingToShade.get(lang)))),
        }
    }
    out
}

/// The Markdown of several explanations, separated by rules.
pub fn write_all(xs: &[Explanation]) -> String {
    xs.iter()
        .enumerate()
        .map(|(i, x)| explanation(x, &x.title, i))
        .collect::<Vec<_>>()
        .join("---\n\n")
}

/// A problem's data as a table (nothing when there is none).
pub(crate) fn data_table(rows: &[DataRow], lang: Lang) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = format!(
        "| {} | {} |\n|---|---|\n",
        Phrase::Quantity.get(lang),
        Phrase::Value.get(lang)
    );
    for row in rows {
        out.push_str(&format!(
            "| {} | {} |\n",
            pieces(&row.what),
            pieces(&row.value)
        ));
    }
    out.push('\n');
    out
}

/// A document: the header, then the statements (each with its data as a table), the solutions
/// or the answer key (one table), or all three.
pub fn write_document(doc: &Document) -> String {
    let lang = doc.lang;
    let mut out = String::new();
    let h = doc.header;
    if !h.is_empty() {
        out.push_str(&format!("# {}\n\n", escape(&h.document_title(doc))));
        if let (Some(c), Some(_)) = (&h.course, &h.title) {
            out.push_str(&format!("**{}**\n\n", escape(c)));
        }
        if let Some(b) = h.byline() {
            out.push_str(&format!("{}\n\n", escape(&b)));
        }
    }
    if doc.contents.statements() {
        for (i, x) in doc.exercises.iter().enumerate() {
            out.push_str(&format!("## {}\n\n", escape(&doc.heading(i))));
            if let Some(q) = &x.question {
                out.push_str(&format!("{}\n\n", escape(q)));
            }
            out.push_str(&data_table(&x.data, lang));
        }
    }
    if doc.contents.solutions() {
        if doc.contents.statements() {
            out.push_str("---\n\n");
        }
        let bodies: Vec<String> = doc
            .exercises
            .iter()
            .enumerate()
            .map(|(i, x)| explanation(x, &doc.solution_heading(i), doc.first_number + i - 1))
            .collect();
        out.push_str(&bodies.join("---\n\n"));
    }
    if doc.contents.key() {
        if doc.contents.solutions() {
            out.push_str("---\n\n");
        }
        out.push_str(&format!(
            "## {}\n\n| {} | {} |\n|---|---|\n",
            Phrase::AnswerKey.get(lang),
            exercise_word(lang),
            Phrase::Answer.get(lang)
        ));
        for (i, x) in doc.exercises.iter().enumerate() {
            let (written, readings) = x.key();
            let mut cell = pieces(&written);
            for r in &readings {
                cell.push_str(&format!("<br>{}", pieces(r)));
            }
            out.push_str(&format!("| {} | {} |\n", escape(&doc.heading(i)), cell));
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markdown_special_characters_are_escaped() {
        assert_eq!(
            escape("a_b *c* [d] $5 #1"),
            "a\\_b \\*c\\* \\[d\\] \\$5 \\#1"
        );
    }
}
