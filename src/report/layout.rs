//! The four explanation layouts behind one entry point, as hyperfine's `Exporter` is: a
//! [`Layout`] turns a [`Document`] into text, Markdown, LaTeX or HTML and names its files'
//! extension. A command picks the layout once and writes every document through it; a new
//! layout is a type here and its file beside the others.

use super::document::{Contents, Document};
use super::html::HtmlOptions;
use super::latex::LatexOptions;
use super::{html, latex, markdown, text};

/// A way of writing a document.
pub trait Layout {
    /// The extension of this layout's files, without the dot ("tex").
    fn extension(&self) -> &'static str;
    /// The document in this layout.
    fn write(&self, doc: &Document) -> String;
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
}

impl Layout for Markdown {
    fn extension(&self) -> &'static str {
        "md"
    }
    fn write(&self, doc: &Document) -> String {
        markdown::write_document(doc)
    }
}

impl Layout for Latex {
    fn extension(&self) -> &'static str {
        "tex"
    }
    fn write(&self, doc: &Document) -> String {
        latex::write_document(doc, self.0)
    }
}

impl Layout for Html {
    fn extension(&self) -> &'static str {
        "html"
    }
    fn write(&self, doc: &Document) -> String {
        html::write_document(doc, self.0)
    }
}
