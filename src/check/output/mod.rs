//! The output formats of `phong check`, each in a file of its own behind one trait
//! ([`Writer`]) and declared once in the list of `formats!` below: the `--format` values and
//! their help, and the writer each gives. A new format is a new file here and a line in the
//! list (hyperfine's `export/`, one `Exporter` per format).

pub(crate) mod html;
mod json;
mod markdown;
mod text;

use super::report::{Checked, Judged};
use super::steps::StepsChecked;
use super::{Against, Diagnosis, Nearest, ReadingTarget, VerdictKind};
use crate::text::Lang;

/// One entry of a page's "what the answer matches": decided here once, in order, for the HTML
/// and the Markdown page, each laying it out its own way (swatches and links to the solution's
/// steps, or `#RRGGBB` and the equations).
pub(crate) enum Match<'a> {
    /// A reading of the problem (`likely`: the verdict names it the intended one).
    Reading {
        reading: &'a ReadingTarget,
        likely: bool,
    },
    /// The background's colour: the ray hits nothing.
    Background([f64; 3]),
    /// The colour these slips give (each of a wrong answer's diagnoses).
    Slips(&'a Diagnosis),
    /// A wrong answer that no slip explains.
    NoDiagnosis,
    /// 0–1 numbers that look like 8-bit values.
    Looks8bit,
    /// The nearest colour missed.
    Nearest(&'a Nearest),
    /// Accepted as the colour before clamping.
    Unclamped,
}

/// What the answer of `j` matches, in the pages' order.
pub(crate) fn matches(j: &Judged) -> Vec<Match<'_>> {
    let v = &j.verdict;
    let mut items = Vec::new();
    if let Some(reading) = &v.reading {
        let likely = v.kind == VerdictKind::Reading;
        items.push(Match::Reading { reading, likely });
    }
    if let Some(colour) = v.background {
        items.push(Match::Background(colour));
    }
    if v.kind == VerdictKind::Wrong {
        if !v.diagnosis.is_empty() {
            items.extend(v.diagnosis.iter().map(Match::Slips));
        } else if j.answer.values.is_some() && !v.looks_8bit && v.background.is_none() {
            items.push(Match::NoDiagnosis);
        }
        if v.looks_8bit {
            items.push(Match::Looks8bit);
        }
        if let Some(n) = &v.nearest {
            items.push(Match::Nearest(n));
        }
    }
    if v.comparison
        .is_some_and(|c| c.within && c.against == Against::Unclamped)
    {
        items.push(Match::Unclamped);
    }
    items
}

/// What a format writes of the checks of a run: each file's answer (when one was checked) and
/// steps (when any were given), in order, then the whole output.
pub trait Writer {
    /// One file's check.
    fn add(&mut self, answer: Option<&Checked>, steps: Option<&StepsChecked>);
    /// The output; empty when there is nothing to write (nothing could be checked).
    fn finish(self: Box<Self>) -> String;
}

/// Declares the formats: `Variant => module::Writer,`, its doc the help of its `--format` value
/// (the value is the variant's name in lower case).
macro_rules! formats {
    ($($(#[$doc:meta])* $variant:ident => $module:ident::$writer:ident,)*) => {
        /// An output format of `phong check` (`--format`).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
        pub enum Format {
            $($(#[$doc])* $variant,)*
        }

        impl Format {
            /// A writer of this format; its words in `lang` (JSON has none).
            pub fn writer(self, lang: Lang) -> Box<dyn Writer> {
                match self {
                    $(Format::$variant => Box::new($module::$writer::new(lang)),)*
                }
            }
        }
    };
}

formats! {
    /// Text for people.
    Text => text::TextWriter,
    /// JSON for scripts (stable field names, format_version).
    Json => json::JsonWriter,
    /// A page for a browser: the colours as swatches, the slips linked to the solution's steps.
    Html => html::HtmlWriter,
    /// Markdown for notes and course pages.
    Markdown => markdown::MarkdownWriter,
}
