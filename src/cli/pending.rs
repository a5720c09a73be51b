//! TEMPORARY, deleted at merge: the Portuguese of errors other modules still write as English
//! text (their typed values are being written in other branches), through the old table of
//! substrings. Nothing else in `cli/` calls that table.

use crate::check::grade::Unreadable;
use crate::report::messages::error_in;
use crate::text::{Lang, Message};

impl Message for Unreadable {
    fn text(&self, lang: Lang) -> String {
        error_in(&self.to_string(), lang)
    }
}
