//! Errors in problem files: each names the file, the field and what would fix it.

use std::path::PathBuf;

/// Something wrong with a problem file. Every variant maps to exit code 2.
#[derive(Debug, thiserror::Error)]
pub enum ProblemError {
    /// The file cannot be read (it does not exist, or is not readable).
    #[error("{path}: cannot read the file: {source}. Fix: check the path, and that the file exists and is readable")]
    Read {
        /// The file.
        path: PathBuf,
        /// What the operating system said.
        #[source]
        source: std::io::Error,
    },
    /// The file is not a problem file's JSON: not UTF-8 text, a syntax error, an unknown or
    /// missing field, or a value of the wrong type.
    #[error("{path}:{line}:{column}: {message}{}", fix_suffix(.fix))]
    Syntax {
        /// The file.
        path: PathBuf,
        /// The line where the parser stopped, from 1.
        line: usize,
        /// The column where the parser stopped, from 1.
        column: usize,
        /// The field where the parser stopped, when it knows (`lights[1].falloff`).
        field: Option<String>,
        /// What is wrong.
        message: String,
        /// What would fix it (empty when the parser cannot say).
        fix: String,
    },
    /// The file is well-formed but states a problem that is invalid (a zero normal, a negative
    /// exponent, …) or cannot be solved.
    #[error("{path}: {field}: {message}{}", fix_suffix(.fix))]
    Invalid {
        /// The file.
        path: PathBuf,
        /// The field at fault (`lights[1].falloff`).
        field: String,
        /// What is wrong with it.
        message: String,
        /// What would fix it.
        fix: String,
    },
    /// A command-line setting that is out of range (`--samples 0`).
    #[error("{flag}: {message}{}", fix_suffix(.fix))]
    Usage {
        /// The flag (`--samples`).
        flag: String,
        /// What is wrong with its value.
        message: String,
        /// What would fix it.
        fix: String,
    },
}

fn fix_suffix(fix: &str) -> String {
    if fix.is_empty() {
        String::new()
    } else {
        format!(". Fix: {fix}")
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

    /// The field the error is about, when there is one.
    pub(crate) fn field(&self) -> Option<&str> {
        match self {
            ProblemError::Invalid { field, .. } => Some(field),
            ProblemError::Usage { flag, .. } => Some(flag),
            ProblemError::Syntax { field, .. } => field.as_deref(),
            ProblemError::Read { .. } => None,
        }
    }
}

/// A validation failure before the file's path is attached.
#[derive(Debug, Clone, PartialEq)]
pub struct Invalid {
    /// The field at fault (`lights[1].falloff`).
    pub field: String,
    /// What is wrong with it.
    pub message: String,
    /// What would fix it.
    pub fix: String,
}

impl Invalid {
    pub(crate) fn new(
        field: impl Into<String>,
        message: impl Into<String>,
        fix: impl Into<String>,
    ) -> Self {
        Invalid {
            field: field.into(),
            message: message.into(),
            fix: fix.into(),
        }
    }

    /// The error in the file at `path`.
    pub fn at(self, path: impl Into<PathBuf>) -> ProblemError {
        ProblemError::Invalid {
            path: path.into(),
            field: self.field,
            message: self.message,
            fix: self.fix,
        }
    }
}
