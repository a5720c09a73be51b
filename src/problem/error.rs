//! Errors in problem files: each names the file, the field and what would fix it.

use std::path::PathBuf;

/// Something wrong with a problem file. Every variant maps to exit code 2.
#[derive(Debug, thiserror::Error)]
pub enum ProblemError {
    #[error("{path}: cannot read the file: {source}. Fix: {}", super::read_fix(.source))]
    Read {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}:{line}:{column}: {message}{}", fix_suffix(.fix))]
    Syntax {
        path: PathBuf,
        line: usize,
        column: usize,
        /// The field where the parser stopped, when it knows (`lights[1].falloff`).
        field: Option<String>,
        message: String,
        fix: String,
    },
    #[error("{path}: {field}: {message}{}", fix_suffix(.fix))]
    Invalid {
        path: PathBuf,
        field: String,
        message: String,
        fix: String,
    },
    /// A command-line setting that is out of range (`--samples 0`).
    #[error("{flag}: {message}{}", fix_suffix(.fix))]
    Usage {
        flag: String,
        message: String,
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
    pub fn kind(&self) -> &'static str {
        match self {
            ProblemError::Read { .. } => "read",
            ProblemError::Syntax { .. } => "syntax",
            ProblemError::Invalid { .. } => "invalid",
            ProblemError::Usage { .. } => "usage",
        }
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

/// A validation failure before the file's path is attached.
#[derive(Debug, Clone, PartialEq)]
pub struct Invalid {
    pub field: String,
    pub message: String,
    pub fix: String,
}

impl Invalid {
    pub fn new(
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

    pub fn at(self, path: impl Into<PathBuf>) -> ProblemError {
        ProblemError::Invalid {
            path: path.into(),
            field: self.field,
            message: self.message,
            fix: self.fix,
        }
    }
}
