//! Errors in problem files: each names the file, the field and what would fix it. What is wrong
//! and its fix are a [`Fault`] value (crate::text), rendered in the user's language only where
//! the error is shown; the English rendering is the error's `Display` and its JSON.

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

use super::reading::ReadFault;
use crate::text::{Fault, Lang, Message};

/// A fault kept as a shared value, so that an error carrying it can be cloned and compared.
pub type FaultBox = Arc<dyn Fault>;

/// Something wrong with a problem file. Every variant maps to exit code 2.
#[derive(Debug)]
pub enum ProblemError {
    /// The file cannot be read (it does not exist, is not readable, or is too large).
    Read {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// The file is not a problem file's JSON: not UTF-8 text, a syntax error, an unknown or
    /// missing field, or a value of the wrong type.
    Syntax {
        /// The file.
        path: PathBuf,
        /// The line where the parser stopped, from 1.
        line: usize,
        /// The column where the parser stopped, from 1.
        column: usize,
        /// The field where the parser stopped, when it knows (`lights[1].falloff`).
        field: Option<String>,
        /// What is wrong and what would fix it (no fix when the parser cannot say).
        fault: FaultBox,
    },
    /// The file is well-formed but states a problem that is invalid (a zero normal, a negative
    /// exponent, …) or cannot be solved.
    Invalid {
        /// The file.
        path: PathBuf,
        /// The field at fault (`lights[1].falloff`).
        field: String,
        /// What is wrong with it and what would fix it.
        fault: FaultBox,
    },
    /// A command-line setting that is out of range (`--samples 0`).
    Usage {
        /// The flag (`--samples`).
        flag: String,
        /// What is wrong with its value and what would fix it.
        fault: FaultBox,
    },
}

/// `WHAT. Fix: FIX` in `lang` (`WHAT. Correção: FIX`), or `WHAT` alone when there is no fix.
pub fn what_and_fix(fault: &dyn Fault, lang: Lang) -> String {
    let what = fault.what(lang);
    let fix = fault.fix(lang);
    if fix.is_empty() {
        what
    } else {
        format!("{what}. {}: {fix}", fix_word(lang))
    }
}

/// "Fix" or "Correção", before what would fix an error.
pub fn fix_word(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "Fix",
        Lang::Pt => "Correção",
    }
}

impl Message for ProblemError {
    fn text(&self, lang: Lang) -> String {
        if let Some(fault) = self.fault().filter(|f| f.untranslated()) {
            // Transitional: a message not yet written as a typed value is translated as a
            // whole by the old table (removed once every message is typed).
            let _ = fault;
            return crate::report::messages::error_in(&self.text_in(Lang::En), lang);
        }
        self.text_in(lang)
    }
}

impl ProblemError {
    /// The error in `lang`, composed from its parts.
    fn text_in(&self, lang: Lang) -> String {
        match self {
            ProblemError::Read { path, source } => {
                let fault = ReadFault::of(source);
                format!("{}: {}", path.display(), what_and_fix(&fault, lang))
            }
            ProblemError::Syntax {
                path,
                line,
                column,
                field,
                fault,
            } => {
                let field = field
                    .as_deref()
                    .map(|f| format!("{f}: "))
                    .unwrap_or_default();
                format!(
                    "{}:{line}:{column}: {field}{}",
                    path.display(),
                    what_and_fix(fault.as_ref(), lang)
                )
            }
            ProblemError::Invalid { path, field, fault } => format!(
                "{}: {field}: {}",
                path.display(),
                what_and_fix(fault.as_ref(), lang)
            ),
            ProblemError::Usage { flag, fault } => {
                format!("{flag}: {}", what_and_fix(fault.as_ref(), lang))
            }
        }
    }

    /// What is wrong and its fix, where the error carries them as a value.
    fn fault(&self) -> Option<&dyn Fault> {
        match self {
            ProblemError::Read { .. } => None,
            ProblemError::Syntax { fault, .. }
            | ProblemError::Invalid { fault, .. }
            | ProblemError::Usage { fault, .. } => Some(fault.as_ref()),
        }
    }

    /// What is wrong, in English, without the file, the field or the fix.
    pub fn message(&self) -> String {
        match self {
            ProblemError::Read { source, .. } => ReadFault::of(source).what(Lang::En),
            _ => self.fault().map(|f| f.what(Lang::En)).unwrap_or_default(),
        }
    }

    /// What would fix it, in English.
    pub fn fix(&self) -> String {
        match self {
            ProblemError::Read { source, .. } => ReadFault::of(source).fix(Lang::En),
            _ => self.fault().map(|f| f.fix(Lang::En)).unwrap_or_default(),
        }
    }
}

impl fmt::Display for ProblemError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text_in(Lang::En))
    }
}

impl std::error::Error for ProblemError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ProblemError::Read { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl ProblemError {
    /// A stable machine-readable kind for the JSON output: "read", "syntax", "invalid" or "usage".
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            ProblemError::Read { .. } => "read",
            ProblemError::Syntax { .. } => "syntax",
            ProblemError::Invalid { .. } => "invalid",
            ProblemError::Usage { .. } => "usage",
        }
    }

    /// Whether this is a syntax error of text after the end of the document (serde_json's
    /// "trailing characters" at the top level, with no field).
    pub fn is_trailing(&self) -> bool {
        matches!(self, ProblemError::Syntax { field: None, fault, .. }
            if fault.what(Lang::En) == super::syntax::Parse::TrailingCharacters.text(Lang::En))
    }

    /// The field the error is about, when there is one.
    pub fn field(&self) -> Option<&str> {
        match self {
            ProblemError::Invalid { field, .. } => Some(field),
            ProblemError::Usage { flag, .. } => Some(flag),
            ProblemError::Syntax { field, .. } => field.as_deref(),
            ProblemError::Read { .. } => None,
        }
    }
}

/// A message written as English text only, translated as a whole by the old table of
/// substrings: the state of every message before it is written as a typed value. Transitional;
/// no new message may use it.
#[derive(Debug, Clone, PartialEq)]
pub struct Untranslated {
    /// What is wrong, in English.
    pub message: String,
    /// What would fix it, in English.
    pub fix: String,
}

impl Fault for Untranslated {
    /// The English as written (with its "(Português: …)" asides, as before): the error it is
    /// part of is translated as a whole ([`ProblemError`]'s `text`).
    fn what(&self, _: Lang) -> String {
        self.message.clone()
    }
    fn fix(&self, _: Lang) -> String {
        self.fix.clone()
    }
    fn untranslated(&self) -> bool {
        true
    }
}

/// A validation failure before the file's path is attached.
#[derive(Debug, Clone)]
pub struct Invalid {
    /// The field at fault (`lights[1].falloff`).
    pub field: String,
    /// What is wrong with it and what would fix it.
    pub fault: FaultBox,
}

impl PartialEq for Invalid {
    fn eq(&self, other: &Self) -> bool {
        self.field == other.field
            && self.fault.what(Lang::En) == other.fault.what(Lang::En)
            && self.fault.fix(Lang::En) == other.fault.fix(Lang::En)
    }
}

impl Invalid {
    /// The field at fault and what is wrong with it, as a typed value.
    pub fn of(field: impl Into<String>, fault: impl Fault + 'static) -> Self {
        Invalid {
            field: field.into(),
            fault: Arc::new(fault),
        }
    }

    /// Transitional: a message written as English text (translated by the old table).
    pub(crate) fn new(
        field: impl Into<String>,
        message: impl Into<String>,
        fix: impl Into<String>,
    ) -> Self {
        Invalid::of(
            field,
            Untranslated {
                message: message.into(),
                fix: fix.into(),
            },
        )
    }

    /// What is wrong, in English (the JSON's words).
    pub fn message(&self) -> String {
        self.fault.what(Lang::En)
    }

    /// What would fix it, in English.
    pub fn fix(&self) -> String {
        self.fault.fix(Lang::En)
    }

    /// The error in the file at `path`.
    pub fn at(self, path: impl Into<PathBuf>) -> ProblemError {
        ProblemError::Invalid {
            path: path.into(),
            field: self.field,
            fault: self.fault,
        }
    }
}
