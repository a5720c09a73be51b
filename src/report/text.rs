//! The text report of `phong solve`: every step of the hand calculation, in order, each with
//! the chapter's equation number, then the findings and any other reading. It lays out an
//! [`Explanation`]; with colour on (a terminal), headings are bold, findings stand out, the
//! equation numbers are dimmed and the final colour is shown as a swatch (a 24-bit background
//! block). With colour off the output is plain text.

use std::fmt::Write;

use super::document::Document;
use super::explain::{explain, plain, DataRow, Explanation, Inline, Shading, Step};
use super::messages::Phrase;
use crate::core::Real;
use crate::problem::Problem;
use crate::solve::Solution;
use crate::text::lang::Lang;

/// Column at which equation references start.
const EQ_COLUMN: usize = 64;

/// ANSI styles, or nothing when colour is off.
struct Style {
    on: bool,
}

impl Style {
    fn wrap(&self, code: &str, s: &str) -> String {
        if self.on {
            format!("\x1b[{code}m{s}\x1b[0m")
        } else {
            s.to_owned()
        }
    }
    fn bold(&self, s: &str) -> String {
        self.wrap("1", s)
    }
    fn dim(&self, s: &str) -> String {
        self.wrap("2", s)
    }
    fn warn(&self, s: &str) -> String {
        self.wrap("1;33", s)
    }
    /// A block of the colour, as a 24-bit background.
    fn swatch(&self, [r, g, b]: [u8; 3]) -> String {
        if self.on {
            format!("  \x1b[48;2;{r};{g};{b}m      \x1b[0m")
        } else {
            String::new()
        }
    }
}

/// The text report of one solved problem, in English without colour.
pub fn render<R: Real>(file: &str, problem: &Problem<R>, s: &Solution<R>) -> String {
    write_explanation(&explain(file, problem, s, Lang::default()), false)
}

/// Lays out an explanation as text.
pub fn write_explanation(x: &Explanation, color: bool) -> String {
    explanation(x, &x.title, color)
}

fn explanation(x: &Explanation, heading: &str, color: bool) -> String {
    let mut out = head(heading, &x.source(), x.question.as_deref(), color);
    out.push_str(&write_parts(x, color));
    out
}

/// The head of a document: its title (bold when `color`) and source on one line, then its
/// question, indented.
pub(crate) fn head(title: &str, source: &str, question: Option<&str>, color: bool) -> String {
    let style = Style { on: color };
    let mut out = format!("{}  ({source})\n", style.bold(title));
    if let Some(q) = question {
        for line in wrap(q, 92) {
            let _ = writeln!(out, "  {line}");
        }
    }
    out
}

/// A problem's data, a row a line: `  what: value`.
pub(crate) fn data(rows: &[DataRow]) -> String {
    let mut out = String::new();
    for row in rows {
        let _ = writeln!(out, "  {}: {}", plain(&row.what), plain(&row.value));
    }
    out
}

/// Text of a heading of `level` (1 for a document's title, 2 for its sections): a blank line,
/// then the heading indented two spaces a level below 2, bold when `color`.
pub(crate) fn heading(level: usize, text: &str, color: bool) -> String {
    let indent = 2 * level.saturating_sub(2);
    format!("\n{:indent$}{}\n", "", Style { on: color }.bold(text))
}

/// The explanation's parts under a heading of `level - 1`: as [`write_parts`] writes them
/// at level 2, and below that each line set off by a bar, indented as the headings of `level`.
pub(crate) fn parts(x: &Explanation, level: usize, color: bool) -> String {
    let body = write_parts(x, color);
    if level <= 2 {
        return body;
    }
    let indent = 2 * (level - 2);
    let mut out = String::new();
    for line in body.lines() {
        if line.is_empty() {
            out.push('\n');
        } else {
            let _ = writeln!(out, "{:indent$}│ {line}", "");
        }
    }
    out
}

/// The findings, the ray and the parts of an explanation, without its title and question
/// (a pixel's rays share their scene's).
pub(crate) fn write_parts(x: &Explanation, color: bool) -> String {
    let style = Style { on: color };
    let lang = x.lang;
    let mut out = String::new();
    if !x.findings.is_empty() {
        let _ = writeln!(out, "\n{}", style.bold(Phrase::Findings.get(lang)));
        for f in &x.findings {
            for (i, line) in wrap(f, 90).iter().enumerate() {
                let mark = if i == 0 { style.warn("!") } else { " ".into() };
                let _ = writeln!(out, "  {mark} {line}");
            }
        }
    }
    if let Some(ray) = &x.ray {
        let _ = writeln!(out, "\n{}", style.bold(Phrase::Ray.get(lang)));
        steps(&mut out, &style, 2, ray, lang);
    }
    for part in &x.parts {
        let _ = writeln!(out, "\n{}", style.bold(&part.heading));
        if let Some(e) = &part.explanation {
            for line in wrap(e, 90) {
                let _ = writeln!(out, "  {line}");
            }
        }
        if let Some(ray) = &part.ray {
            steps(&mut out, &style, 2, ray, lang);
        }
        match &part.shading {
            Some(sh) => shading(&mut out, &style, sh, lang),
            None => {
                let _ = writeln!(out, "  {}", Phrase::NothingToShade.get(lang));
            }
        }
    }
    out
}

fn shading(out: &mut String, style: &Style, sh: &Shading, lang: Lang) {
    for (heading, list) in [
        (Phrase::Given, &sh.given),
        (Phrase::Steps, &sh.steps),
        (Phrase::Total, &sh.total),
        (Phrase::SecondaryRays, &sh.secondary),
    ] {
        if list.is_empty() && heading == Phrase::SecondaryRays {
            continue;
        }
        let _ = writeln!(out, "  {}", style.bold(heading.get(lang)));
        steps(out, style, 4, list, lang);
    }
}

/// Writes steps, each with its equation reference right-aligned in a column.
fn steps(out: &mut String, style: &Style, indent: usize, list: &[Step], lang: Lang) {
    for step in list {
        let indent = indent + 2 * step.depth;
        let text = plain(&step.line);
        let mut line = format!("{:indent$}{text}", "");
        let width = line.chars().count();
        let is_total = step.line.first() == Some(&Inline::Math(super::formula::Formula::I));
        if is_total {
            line = format!("{:indent$}{}", "", style.bold(&text));
        }
        if let Some(eq) = step.eq {
            let pad = EQ_COLUMN.saturating_sub(width).max(2);
            let _ = write!(line, "{:pad$}{}", "", style.dim(&eq.text(lang)));
        }
        for piece in &step.line {
            if let Inline::Swatch(rgb) = piece {
                line.push_str(&style.swatch(*rgb));
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
}

/// A document as text: the header, then the statements (each with its data), the solutions or
/// the answer key, or all three.
pub fn write_document(doc: &Document, color: bool) -> String {
    let style = Style { on: color };
    let lang = doc.lang;
    let mut blocks = Vec::new();
    let h = doc.header;
    if !h.is_empty() {
        let mut b = String::new();
        if let (Some(c), Some(_)) = (&h.course, &h.title) {
            let _ = writeln!(b, "{c}");
        }
        let _ = writeln!(b, "{}", style.bold(&h.document_title(doc)));
        if let Some(by) = h.byline() {
            let _ = writeln!(b, "{by}");
        }
        blocks.push(b);
    }
    if doc.contents.statements() {
        for (i, x) in doc.exercises.iter().enumerate() {
            let mut b = String::new();
            let _ = writeln!(b, "{}", style.bold(&doc.heading(i)));
            if let Some(q) = &x.question {
                for line in wrap(q, 92) {
                    let _ = writeln!(b, "  {line}");
                }
            }
            b.push_str(&data(&x.data));
            blocks.push(b);
        }
    }
    if doc.contents.solutions() {
        for (i, x) in doc.exercises.iter().enumerate() {
            blocks.push(explanation(x, &doc.solution_heading(i), color));
        }
    }
    if doc.contents.key() {
        let mut b = String::new();
        let _ = writeln!(
            b,
            "{}",
            style.bold(super::messages::Phrase::AnswerKey.get(lang))
        );
        for (i, x) in doc.exercises.iter().enumerate() {
            let (written, readings) = x.key();
            let _ = writeln!(b, "  {}: {}", doc.heading(i), plain(&written));
            for r in &readings {
                // A colour is kept on one line: its spaces are held by a mark while wrapping.
                let held = super::explain::keep_triples(&plain(r), |g| g.replace(' ', "\u{E000}"));
                for line in wrap(&held, 88) {
                    let _ = writeln!(b, "      {}", line.replace('\u{E000}', " "));
                }
            }
        }
        blocks.push(b);
    }
    blocks.join("\n")
}

/// Word-wraps a paragraph to lines of at most `width` characters.
pub(crate) fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}
