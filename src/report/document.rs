//! A document made of several explanations, as an instructor hands it out: a problem-set
//! header (course, title, date, author), then the statements (numbered, each with its data as a
//! table: the student's handout), the worked solutions, or the answer key (one table), or all
//! three. The layouts are in [`super::text`], [`super::markdown`], [`super::latex`] and
//! [`super::html`] (`write_document`); this module only says what a document holds.

use super::explain::Explanation;
use super::messages::{pick, Phrase};
use crate::text::lang::Lang;

/// Which part of a problem set to write (`solve --part`): what each writes is said by
/// [`Contents::statements`], [`Contents::solutions`] and [`Contents::key`].
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum)]
#[allow(missing_docs)]
pub enum Contents {
    Statement,
    #[default]
    Solution,
    Key,
    All,
}

impl Contents {
    /// Whether the statements are written.
    pub fn statements(self) -> bool {
        matches!(self, Contents::Statement | Contents::All)
    }
    /// Whether the worked solutions are written.
    pub fn solutions(self) -> bool {
        matches!(self, Contents::Solution | Contents::All)
    }
    /// Whether the answer key is written.
    pub fn key(self) -> bool {
        matches!(self, Contents::Key | Contents::All)
    }
}

/// The problem set's header; every field is optional, and a header with none is not written.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Header {
    /// The course, such as "Computação Gráfica".
    pub course: Option<String>,
    /// The problem set's title, such as "Lista 4: Modelos de Iluminação".
    pub title: Option<String>,
    /// Its date, as it should be printed.
    pub date: Option<String>,
    /// Its author (the instructor).
    pub author: Option<String>,
}

impl Header {
    /// Whether nothing is given.
    pub fn is_empty(&self) -> bool {
        self.course.is_none()
            && self.title.is_none()
            && self.date.is_none()
            && self.author.is_none()
    }

    /// The document's title: the set's title, else its course, else the one exercise's title,
    /// else the part's name ("Answer key").
    pub fn document_title(&self, doc: &Document) -> String {
        if let Some(t) = self.title.as_ref().or(self.course.as_ref()) {
            return t.clone();
        }
        match (doc.exercises, doc.contents) {
            ([one], _) => one.title.clone(),
            (_, Contents::Key) => Phrase::AnswerKey.get(doc.lang).to_owned(),
            (_, Contents::Statement) => Phrase::Statements.get(doc.lang).to_owned(),
            _ => Phrase::Solutions.get(doc.lang).to_owned(),
        }
    }

    /// The line under the title: author and date, joined by " — ".
    pub fn byline(&self) -> Option<String> {
        let parts: Vec<&str> = [self.author.as_deref(), self.date.as_deref()]
            .into_iter()
            .flatten()
            .collect();
        (!parts.is_empty()).then(|| parts.join(" — "))
    }
}

/// A document: a header, which parts, and the exercises, numbered from `first_number`.
#[derive(Clone, Copy, Debug)]
pub struct Document<'a> {
    /// The problem set's header.
    pub header: &'a Header,
    /// Which parts are written.
    pub contents: Contents,
    /// The exercises' explanations, in order.
    pub exercises: &'a [Explanation],
    /// The number of the first exercise (a file per exercise keeps the set's numbers).
    pub first_number: usize,
    /// The language of the headings.
    pub lang: Lang,
}

impl Document<'_> {
    /// The heading of exercise `i` (0-based in `exercises`): "3. Exercício 4.3".
    pub fn heading(&self, i: usize) -> String {
        format!("{}. {}", self.first_number + i, self.exercises[i].title)
    }

    /// Whether the solutions are numbered as the statements are: not when they are the whole
    /// document and there is no header (`phong solve`'s plain explanation).
    pub fn numbered(&self) -> bool {
        self.contents != Contents::Solution || !self.header.is_empty()
    }

    /// The heading of exercise `i`'s solution: numbered when [`Document::numbered`], else its
    /// title.
    pub fn solution_heading(&self, i: usize) -> String {
        if self.numbered() {
            self.heading(i)
        } else {
            self.exercises[i].title.clone()
        }
    }
}

/// "Exercise" or "Exercício", for the key's column.
pub fn exercise_word(lang: Lang) -> &'static str {
    pick(lang, "Exercise", "Exercício")
}
