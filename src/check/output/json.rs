//! `phong check --format json`: one document per file (`check::report::document`), one object
//! for one file and an array for several, language-neutral.

use super::Writer;
use crate::check::report::Checked;
use crate::check::steps::StepsChecked;
use crate::text::Lang;

/// The JSON documents of a run's checks.
pub(crate) struct JsonWriter {
    docs: Vec<serde_json::Value>,
}

impl JsonWriter {
    pub(crate) fn new(_: Lang) -> Self {
        JsonWriter { docs: Vec::new() }
    }
}

impl Writer for JsonWriter {
    fn add(&mut self, answer: Option<&Checked>, steps: Option<&StepsChecked>) {
        self.docs
            .extend(crate::check::report::document(answer, steps));
    }

    fn finish(self: Box<Self>) -> String {
        crate::report::json::documents_text(self.docs)
    }
}
