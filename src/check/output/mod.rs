//! The output formats of `phong check`, each in a file of its own behind one trait
//! ([`Writer`]) and declared once in the list of `formats!` below: the `--format` values and
//! their help, and the writer each gives. A new format is a new file here and a line in the
//! list (hyperfine's `export/`, one `Exporter` per format).

pub(crate) mod html;
mod json;
mod markdown;
mod text;

use super::matches::{expected_line, ExpectedLine};
use super::messages as said;
use super::report::Checked;
use super::steps::StepsChecked;
use super::Verdict;
use crate::text::Lang;

/// The pages' expected colour of verdict `v` ([`expected_line`]): the colour, if there is one,
/// and the words beside it (what that colour is, or why there is none).
fn expected(v: &Verdict, lang: Lang) -> (Option<[f64; 3]>, String) {
    match expected_line(v) {
        ExpectedLine::Compared {
            comparison,
            reading,
        } => (
            Some(comparison.expected),
            said::expected_source(reading, comparison.against, lang),
        ),
        ExpectedLine::HasColour { colour, ray } => {
            (Some(colour), said::has_colour(ray, lang).to_owned())
        }
        ExpectedLine::Nothing => (None, said::nothing_to_shade(lang).to_owned()),
    }
}

/// What a format writes of the checks of a run: each file's answer (when one was checked) and
/// steps (when any were given), in order, then the whole output.
pub trait Writer {
    /// One file's check.
    fn add(&mut self, answer: Option<&Checked>, steps: Option<&StepsChecked>);
    /// The output; empty when there is nothing to write (nothing could be checked).
    fn finish(self: Box<Self>) -> String;
}

/// Declares the formats: `Variant => module::Writer,` (the `--format` value is the variant's
/// name in lower case).
macro_rules! formats {
    ($($variant:ident => $module:ident::$writer:ident,)*) => {
        /// An output format of `phong check` (`--format`), each written by its [`Writer`].
        ///
        /// The variants carry no doc comment: clap would show it, in English only, as the help
        /// of the value; the command line says what each value means in both languages
        /// (`src/cli/help/values.rs`).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
        #[allow(missing_docs)]
        pub enum Format {
            $($variant,)*
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
    Text => text::TextWriter,
    Json => json::JsonWriter,
    Html => html::HtmlWriter,
    Markdown => markdown::MarkdownWriter,
}
