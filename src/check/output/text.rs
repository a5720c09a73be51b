//! `phong check --format text`: the verdict of each answer and the judgement of each step, in
//! the user's language.

use super::Writer;
use crate::check::report::Checked;
use crate::check::steps::StepsChecked;
use crate::text::Lang;

/// The text of a run's checks.
pub(crate) struct TextWriter {
    lang: Lang,
    out: String,
}

impl TextWriter {
    pub(crate) fn new(lang: Lang) -> Self {
        TextWriter {
            lang,
            out: String::new(),
        }
    }
}

impl Writer for TextWriter {
    fn add(&mut self, answer: Option<&Checked>, steps: Option<&StepsChecked>) {
        // An answer that could not be checked has no report: its error is on standard error.
        if let Some(c) = answer.filter(|c| c.outcome.is_ok()) {
            self.out.push_str(&crate::check::report::text(c, self.lang));
        }
        if let Some(s) = steps {
            self.out.push_str(&crate::check::steps::text(s, self.lang));
        }
    }

    fn finish(self: Box<Self>) -> String {
        self.out
    }
}
