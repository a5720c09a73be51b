//! The four explanation layouts behind one entry point, as hyperfine's `Exporter` is: a
//! [`Layout`] turns a [`Document`] into text, Markdown, LaTeX or HTML and names its files'
//! extension. A command picks the layout once and writes every document through it; a new
//! layout is a type here and its file beside the others.
//!
//! A document that is not a problem set (a pixel's explanation, [`super::pixel`]) is walked
//! once by its own module and written block by block through the same layout: a head, data,
//! paragraphs, headings at a level, lists, and a solver's explanation whose headings sit at a
//! level below the block that holds it.

use super::document::{Contents, Document};
use super::explain::{DataRow, Explanation};
use super::html::HtmlOptions;
use super::latex::LatexOptions;
use super::{html, latex, markdown, text};
use crate::text::lang::Lang;

/// A way of writing a document.
///
/// Levels count from 1, a document's title; a block's `level` is the level of the heading it
/// stands under.
pub trait Layout {
    /// The extension of this layout's files, without the dot ("tex").
    fn extension(&self) -> &'static str;
    /// The document in this layout.
    fn write(&self, doc: &Document) -> String;

    /// Opens a part of a document of the kind `class` ("pixel", "ray"), where the layout marks
    /// one (an HTML `<article>` at level 1, a `<section>` below); empty elsewhere.
    fn open(&self, level: usize, class: &str) -> String {
        let _ = (level, class);
        String::new()
    }
    /// Closes what [`Layout::open`] opened at `level`.
    fn close(&self, level: usize) -> String {
        let _ = level;
        String::new()
    }
    /// The head of a document: its title, its source file, its question.
    fn head(&self, title: &str, source: &str, question: Option<&str>) -> String;
    /// A problem's data, as a table (nothing when there is none).
    fn data(&self, rows: &[DataRow], lang: Lang) -> String;
    /// A paragraph of prose under a heading of `level`.
    fn paragraph(&self, level: usize, text: &str) -> String;
    /// A heading of `level` (2 or more).
    fn heading(&self, level: usize, text: &str) -> String;
    /// A list of lines under a heading of `level`.
    fn list(&self, level: usize, items: &[String]) -> String;
    /// A paragraph set in bold (a result) under a heading of `level`.
    fn strong(&self, level: usize, text: &str) -> String;
    /// A solver's explanation without its title and question, its headings at `level`;
    /// `index` (its number among the explanations of the document) makes its ids unique.
    fn parts(&self, x: &Explanation, level: usize, index: usize) -> String;
    /// The written blocks as a whole document titled `title`: a page, a LaTeX document, or
    /// the blocks alone.
    fn finish(&self, body: String, title: &str, lang: Lang) -> String;
}

/// `body` without the blank line after its last block (the Markdown and LaTeX blocks end
/// with one, to stand apart from the next).
fn last_block(mut body: String) -> String {
    if body.ends_with("\n\n") {
        body.pop();
    }
    body
}

/// Plain text, coloured for a terminal when `color`.
pub struct Text {
    /// Whether to colour the text with ANSI escapes.
    pub color: bool,
}

/// Markdown.
pub struct Markdown;

/// LaTeX, standalone or a fragment.
pub struct Latex(pub LatexOptions);

/// HTML, a page or a fragment.
pub struct Html(pub HtmlOptions);

impl Layout for Text {
    fn extension(&self) -> &'static str {
        "txt"
    }
    fn write(&self, doc: &Document) -> String {
        // The worked solutions alone, with no header: the explanations one after the other.
        if doc.contents == Contents::Solution && doc.header.is_empty() {
            doc.exercises
                .iter()
                .map(|x| text::write_explanation(x, self.color))
                .collect::<Vec<_>>()
                .join("\n")
        } else {
            text::write_document(doc, self.color)
        }
    }
    fn head(&self, title: &str, source: &str, question: Option<&str>) -> String {
        text::head(title, source, question, self.color)
    }
    fn data(&self, rows: &[DataRow], _: Lang) -> String {
        text::data(rows)
    }
    fn paragraph(&self, level: usize, body: &str) -> String {
        let indent = 2 * level.saturating_sub(1);
        text::wrap(body, 92)
            .iter()
            .map(|line| format!("{:indent$}{line}\n", ""))
            .collect()
    }
    fn heading(&self, level: usize, body: &str) -> String {
        text::heading(level, body, self.color)
    }
    fn list(&self, level: usize, items: &[String]) -> String {
        let indent = 2 * level.saturating_sub(1);
        items
            .iter()
            .map(|line| format!("{:indent$}{line}\n", ""))
            .collect()
    }
    fn strong(&self, level: usize, body: &str) -> String {
        let indent = 2 * level.saturating_sub(1);
        format!("\n{:indent$}{body}\n", "")
    }
    fn parts(&self, x: &Explanation, level: usize, _: usize) -> String {
        text::parts(x, level, self.color)
    }
    fn finish(&self, body: String, _: &str, _: Lang) -> String {
        body
    }
}

impl Layout for Markdown {
    fn extension(&self) -> &'static str {
        "md"
    }
    fn write(&self, doc: &Document) -> String {
        markdown::write_document(doc)
    }
    fn head(&self, title: &str, source: &str, question: Option<&str>) -> String {
        markdown::head(title, source, question)
    }
    fn data(&self, rows: &[DataRow], lang: Lang) -> String {
        markdown::data_table(rows, lang)
    }
    fn paragraph(&self, _: usize, body: &str) -> String {
        format!("{}\n\n", markdown::escape(body))
    }
    fn heading(&self, level: usize, body: &str) -> String {
        format!("{} {}\n\n", markdown::hashes(level), markdown::escape(body))
    }
    fn list(&self, _: usize, items: &[String]) -> String {
        let mut out: String = items
            .iter()
            .map(|l| format!("- {}\n", markdown::escape(l)))
            .collect();
        out.push('\n');
        out
    }
    fn strong(&self, _: usize, body: &str) -> String {
        format!("**{}**\n\n", markdown::escape(body))
    }
    fn parts(&self, x: &Explanation, level: usize, index: usize) -> String {
        markdown::write_parts(x, index, level)
    }
    fn finish(&self, body: String, _: &str, _: Lang) -> String {
        last_block(body)
    }
}

impl Layout for Latex {
    fn extension(&self) -> &'static str {
        "tex"
    }
    fn write(&self, doc: &Document) -> String {
        latex::write_document(doc, self.0)
    }
    fn head(&self, title: &str, source: &str, question: Option<&str>) -> String {
        latex::head(title, source, question)
    }
    fn data(&self, rows: &[DataRow], lang: Lang) -> String {
        latex::data_table(rows, lang)
    }
    fn paragraph(&self, _: usize, body: &str) -> String {
        format!("{}\n\n", latex::escape(body))
    }
    fn heading(&self, level: usize, body: &str) -> String {
        format!(
            "\\{}{{{}}}\n",
            latex::sectioning(level),
            latex::escape(body)
        )
    }
    fn list(&self, _: usize, items: &[String]) -> String {
        let mut out = String::from("\\begin{itemize}\n");
        for l in items {
            out.push_str(&format!("  \\item {}\n", latex::escape(l)));
        }
        out.push_str("\\end{itemize}\n");
        out
    }
    fn strong(&self, _: usize, body: &str) -> String {
        format!("\\textbf{{{}}}\n\n", latex::escape(body))
    }
    fn parts(&self, x: &Explanation, level: usize, _: usize) -> String {
        latex::write_parts(x, level)
    }
    fn finish(&self, body: String, _: &str, lang: Lang) -> String {
        latex::wrap(&last_block(body), self.0, lang)
    }
}

impl Layout for Html {
    fn extension(&self) -> &'static str {
        "html"
    }
    fn write(&self, doc: &Document) -> String {
        html::write_document(doc, self.0)
    }
    fn open(&self, level: usize, class: &str) -> String {
        let tag = if level <= 1 { "article" } else { "section" };
        format!("<{tag} class=\"{}\">\n", html::esc(class))
    }
    fn close(&self, level: usize) -> String {
        let tag = if level <= 1 { "article" } else { "section" };
        format!("</{tag}>\n")
    }
    fn head(&self, title: &str, source: &str, question: Option<&str>) -> String {
        html::head(title, source, question)
    }
    fn data(&self, rows: &[DataRow], lang: Lang) -> String {
        html::data_table(rows, lang)
    }
    fn paragraph(&self, _: usize, body: &str) -> String {
        format!("<p>{}</p>\n", html::esc(body))
    }
    fn heading(&self, level: usize, body: &str) -> String {
        let h = level.clamp(1, 6);
        format!("<h{h}>{}</h{h}>\n", html::esc(body))
    }
    fn list(&self, _: usize, items: &[String]) -> String {
        let mut out = String::from("<ul>\n");
        for l in items {
            out.push_str(&format!("<li>{}</li>\n", html::esc(l)));
        }
        out.push_str("</ul>\n");
        out
    }
    fn strong(&self, _: usize, body: &str) -> String {
        format!("<p><strong>{}</strong></p>\n", html::esc(body))
    }
    fn parts(&self, x: &Explanation, level: usize, index: usize) -> String {
        html::write_parts(x, index, level)
    }
    fn finish(&self, body: String, title: &str, lang: Lang) -> String {
        if self.0.fragment {
            return body;
        }
        html::page(&html::esc(title), &body, lang)
    }
}
