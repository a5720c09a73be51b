//! What can go wrong at the command line's edge, as one type, and the one place an error is
//! printed. Every error exits 2 ([`Exit::BadInput`]): exit 1 means a wrong answer.

use std::fmt::Display;
use std::path::{Path, PathBuf};

use super::exit::Exit;
use crate::check::answer::BadAnswer;
use crate::check::grade::Unreadable;
use crate::problem::{Invalid, ProblemError};
use crate::report::messages;
use crate::text::lang::Lang;
use crate::text::Message;

/// Why a command failed (or, in a batch, why one of its steps did).
#[derive(Debug, thiserror::Error)]
pub(crate) enum CliError {
    /// A problem file that cannot be read, parsed or validated (or, for `export-pov`, expressed
    /// in POV-Ray).
    #[error(transparent)]
    Problem(#[from] ProblemError),
    /// The submissions of `phong grade` cannot be read.
    #[error(transparent)]
    Submissions(#[from] Unreadable),
    /// `phong serve` could not start (its exercises, its address).
    #[cfg(feature = "serve")]
    #[error(transparent)]
    Serve(#[from] crate::serve::StartError),
    /// A flag's value refused after parsing: out of range, or not what the command can do.
    #[error("{flag}: {message}. Fix: {fix}")]
    Usage {
        flag: String,
        message: String,
        fix: String,
    },
    /// A flag's value that is not a value of its kind (`--tolerance -1`); the message says what
    /// is expected.
    #[error("{flag}: {source}")]
    Value {
        flag: &'static str,
        #[source]
        source: BadAnswer,
    },
    /// Flags or arguments that do not go together, said as one sentence.
    #[error("{message}. Fix: {fix}")]
    Conflict { message: String, fix: String },
    /// A flag naming a folder gives something else.
    #[error("{}: {flag}: not a folder. Fix: {fix}", path.display())]
    NotAFolder {
        path: PathBuf,
        flag: &'static str,
        fix: &'static str,
    },
    /// Output that cannot be written: to a file, or (`None`) to standard output.
    #[error("cannot write {}: {source}", destination(path.as_deref()))]
    Write {
        path: Option<PathBuf>,
        #[source]
        source: std::io::Error,
    },
    /// A folder for the output files that cannot be created.
    #[error("{}: cannot create the folder: {source}", path.display())]
    CreateFolder {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// The system refused the worker threads.
    #[error("--threads: cannot start the worker threads: {0}. Fix: give fewer --threads")]
    Threads(#[source] rayon::ThreadPoolBuildError),
    /// A bug of phong's own, found where `flag` is handled; `works` says what still works.
    #[error("{flag}: {message}. Fix: report this as a bug; {works}")]
    Bug {
        flag: &'static str,
        message: String,
        works: &'static str,
    },
}

/// Where output was going: a file, or standard output.
fn destination(path: Option<&Path>) -> String {
    path.map_or("standard output".into(), |p| p.display().to_string())
}

impl CliError {
    /// A setting refused by the library, named by its field (`max_level`, `min_weights`): the
    /// flag that gave it is that name in kebab case (`--max-level`, `--min-weights`).
    pub(crate) fn setting(e: Invalid) -> CliError {
        CliError::Usage {
            flag: format!("--{}", e.field.replace('_', "-")),
            message: e.message(),
            fix: e.fix(),
        }
    }
}

impl Message for CliError {
    fn text(&self, lang: Lang) -> String {
        match self {
            CliError::Problem(e) => e.text(lang),
            #[cfg(feature = "serve")]
            CliError::Serve(e) => e.text(lang),
            // Transitional: the variants not yet written as typed values are translated as a
            // whole by the old table.
            other => messages::error_in(&other.to_string(), lang),
        }
    }
}

/// Prints an error on standard error in `lang`, as `error: …` (`erro: …` in Portuguese); every
/// error of `phong` is printed here (a closed standard error is ignored:
/// [`super::output::say`]).
pub(crate) fn print_in(error: &dyn Message, lang: Lang) {
    super::output::say(&format_args!(
        "{}: {}",
        messages::error_word(lang),
        error.text(lang)
    ));
}

/// Transitional: prints an error written as English text, translated by the old table.
pub(crate) fn print_english_in(error: &dyn Display, lang: Lang) {
    super::output::say(&format_args!(
        "{}: {}",
        messages::error_word(lang),
        messages::error_in(&error.to_string(), lang)
    ));
}

/// A command line that clap refuses. With `--lang pt`, a flag's value that its parser refuses
/// (`--tolerance abc`, `--samples 0`, `--format foo`) is said in Portuguese, its parser's message
/// through the catalogue of [`crate::report::messages::error_in`]; clap's other usage errors (an
/// unknown flag, a missing argument) stay in clap's English, which has no localisation.
pub(crate) fn refused(e: &clap::Error, args: &[std::ffi::OsString]) -> Option<Exit> {
    use clap::error::ErrorKind;
    let pt = args.windows(2).any(|w| w[0] == "--lang" && w[1] == "pt")
        || args.iter().any(|a| a == "--lang=pt");
    if !pt
        || !matches!(
            e.kind(),
            ErrorKind::ValueValidation | ErrorKind::InvalidValue
        )
    {
        return None;
    }
    let text = e.render().to_string();
    let text = text
        .replacen("error: invalid value '", "valor inválido '", 1)
        .replacen("' for '", "' para '", 1)
        .replace("[possible values: ", "[valores possíveis: ")
        .replace(
            "tip: a similar value exists: ",
            "dica: há um valor parecido: ",
        )
        .replace(
            "For more information, try '--help'.",
            "Para mais informações, tente '--help'.",
        );
    print_english_in(&text.trim_end(), Lang::Pt);
    Some(Exit::BadInput)
}

/// Prints a warning (a likely mistake that is not an error) about the file at `file`, already
/// in `lang`, on standard error after `warning:` (`aviso:` in Portuguese) and the file, as an
/// error names its file: with several files, the warning says which one it is about.
pub(crate) fn warn_in(file: &Path, warning: &dyn Display, lang: Lang) {
    super::output::say(&format_args!("{}", warning_line(file, warning, lang)));
}

/// The line [`warn_in`] prints: `warning: FILE: …`.
fn warning_line(file: &Path, warning: &dyn Display, lang: Lang) -> String {
    format!(
        "{}: {}: {warning}",
        messages::warning_word(lang),
        file.display()
    )
}

/// The exit of a step a command goes on after (one file of several): success, or bad input
/// once its error is printed in `lang`.
pub(crate) fn carry_on_in(step: Result<(), CliError>, lang: Lang) -> Exit {
    match step {
        Ok(()) => Exit::Success,
        Err(e) => fail_in(&e, lang),
    }
}

/// Prints an error in `lang` and gives its exit.
pub(crate) fn fail_in(e: &CliError, lang: Lang) -> Exit {
    print_in(e, lang);
    Exit::BadInput
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_names_its_file() {
        // QA report A, finding 9: "warning: c255.json: materials.M.diffuse: …".
        assert_eq!(
            warning_line(Path::new("c255.json"), &"materials.M.diffuse: x", Lang::En),
            "warning: c255.json: materials.M.diffuse: x"
        );
        assert_eq!(
            warning_line(Path::new("c255.json"), &"materials.M.diffuse: x", Lang::Pt),
            "aviso: c255.json: materials.M.diffuse: x"
        );
    }

    #[test]
    fn a_setting_is_named_by_its_flag() {
        let e = CliError::setting(Invalid::new("min_weights", "is empty", "give one"));
        assert_eq!(e.to_string(), "--min-weights: is empty. Fix: give one");
    }
}
