//! What can go wrong at the command line's edge, as one type, and the one place an error is
//! printed. Every error exits 2 ([`Exit::BadInput`]): exit 1 means a wrong answer.

use std::fmt::{self, Display};
use std::path::{Path, PathBuf};

use super::exit::Exit;
use super::faults::{CliFault, CliText, SystemError};
use crate::check::answer::BadAnswer;
use crate::check::grade::Unreadable;
use crate::problem::error::{fix_word, FaultBox};
use crate::problem::{Invalid, ProblemError};
use crate::report::messages;
use crate::text::lang::Lang;
use crate::text::Message;

/// Why a command failed (or, in a batch, why one of its steps did). Each variant keeps its
/// values (the flag, the path, the fault, what the system said) until it is said in a
/// language ([`Message`]); its `Display` is the English.
#[derive(Debug)]
pub(crate) enum CliError {
    /// A problem file that cannot be read, parsed or validated (or, for `export-pov`, expressed
    /// in POV-Ray).
    Problem(ProblemError),
    /// The submissions of `phong grade` cannot be read.
    Submissions(Unreadable),
    /// `phong serve` could not start (its exercises, its address).
    #[cfg(feature = "serve")]
    Serve(crate::serve::StartError),
    /// A flag's value refused after parsing: out of range, or not what the command can do
    /// (`FLAG: WHAT. Fix: FIX`).
    Usage { flag: String, fault: FaultBox },
    /// A flag's value that is not a value of its kind (`--tolerance -1`); the message says what
    /// is expected.
    Value {
        flag: &'static str,
        // Boxed: the error stays small (its `Result` is every command's).
        source: Box<BadAnswer>,
    },
    /// Flags or arguments that do not go together, said as one sentence (`WHAT. Fix: FIX`).
    Conflict { fault: FaultBox },
    /// A flag (or an argument, as `DIR`) naming a folder gives something else (`PATH: FLAG: not
    /// a folder. Fix: FIX`).
    NotAFolder {
        path: PathBuf,
        flag: &'static str,
        fault: FaultBox,
    },
    /// Output that cannot be written: to a file, or (`None`) to standard output.
    Write {
        path: Option<PathBuf>,
        source: std::io::Error,
    },
    /// A folder for the output files that cannot be created.
    CreateFolder {
        path: PathBuf,
        source: std::io::Error,
    },
    /// The system refused the worker threads.
    Threads(rayon::ThreadPoolBuildError),
    /// A bug of phong's own, found where `flag` is handled; the fault's fix says to report it
    /// and what still works.
    Bug { flag: &'static str, fault: CliFault },
}

impl CliError {
    /// A setting refused by the library, named by its field (`max_level`, `min_weights`): the
    /// flag that gave it is that name in kebab case (`--max-level`, `--min-weights`).
    /// Its fault is kept as a value, to be said in the user's language.
    pub(crate) fn setting(e: Invalid) -> CliError {
        CliError::Problem(ProblemError::Usage {
            flag: format!("--{}", e.field.replace('_', "-")),
            fault: e.fault,
        })
    }

    /// A flag's value refused, with what is wrong and what would fix it.
    pub(crate) fn usage(flag: impl Into<String>, fault: CliFault) -> CliError {
        CliError::Usage {
            flag: flag.into(),
            fault: std::sync::Arc::new(fault),
        }
    }

    /// A flag (or an argument) naming `path`, which is not a folder.
    pub(crate) fn not_a_folder(path: PathBuf, flag: &'static str, fault: CliFault) -> CliError {
        CliError::NotAFolder {
            path,
            flag,
            fault: std::sync::Arc::new(fault),
        }
    }

    /// Flags or arguments that do not go together.
    pub(crate) fn conflict(fault: CliFault) -> CliError {
        CliError::Conflict {
            fault: std::sync::Arc::new(fault),
        }
    }
}

impl From<ProblemError> for CliError {
    fn from(e: ProblemError) -> Self {
        CliError::Problem(e)
    }
}

impl From<Unreadable> for CliError {
    fn from(e: Unreadable) -> Self {
        CliError::Submissions(e)
    }
}

#[cfg(feature = "serve")]
impl From<crate::serve::StartError> for CliError {
    fn from(e: crate::serve::StartError) -> Self {
        CliError::Serve(e)
    }
}

/// `WHAT. Fix: FIX` in `lang`, the fix written even when empty (as the command line always
/// wrote it).
fn what_fix(fault: &dyn crate::text::Fault, lang: Lang) -> String {
    format!(
        "{}. {}: {}",
        fault.what(lang),
        fix_word(lang),
        fault.fix(lang)
    )
}

impl Message for CliError {
    fn text(&self, lang: Lang) -> String {
        match self {
            CliError::Problem(e) => e.text(lang),
            CliError::Submissions(e) => e.text(lang),
            #[cfg(feature = "serve")]
            CliError::Serve(e) => e.text(lang),
            CliError::Usage { flag, fault } => {
                format!("{flag}: {}", what_fix(fault.as_ref(), lang))
            }
            CliError::Value { flag, source } => format!("{flag}: {}", source.text(lang)),
            CliError::Conflict { fault } => what_fix(fault.as_ref(), lang),
            CliError::NotAFolder { path, flag, fault } => {
                format!("{}: {flag}: {}", path.display(), what_fix(fault, lang))
            }
            CliError::Write { path, source } => {
                let error = SystemError::of(source);
                match path {
                    Some(path) => CliText::CannotWrite {
                        path: path.clone(),
                        error,
                    },
                    None => CliText::CannotWriteStdout { error },
                }
                .text(lang)
            }
            CliError::CreateFolder { path, source } => CliText::CannotCreateFolder {
                path: path.clone(),
                error: SystemError::of(source),
            }
            .text(lang),
            CliError::Threads(e) => CliText::Threads {
                error: e.to_string(),
            }
            .text(lang),
            CliError::Bug { flag, fault } => format!("{flag}: {}", what_fix(fault, lang)),
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Problem(e) => Display::fmt(e, f),
            CliError::Submissions(e) => Display::fmt(e, f),
            #[cfg(feature = "serve")]
            CliError::Serve(e) => Display::fmt(e, f),
            CliError::Value { flag, source } => write!(f, "{flag}: {source}"),
            other => f.write_str(&other.text(Lang::En)),
        }
    }
}

impl std::error::Error for CliError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            CliError::Problem(e) => e.source(),
            CliError::Submissions(e) => e.source(),
            #[cfg(feature = "serve")]
            CliError::Serve(e) => e.source(),
            CliError::Value { source, .. } => Some(source.as_ref()),
            CliError::Write { source, .. } | CliError::CreateFolder { source, .. } => Some(source),
            CliError::Threads(e) => Some(e),
            CliError::Usage { .. } | CliError::Conflict { .. } | CliError::NotAFolder { .. } => {
                None
            }
            CliError::Bug { .. } => None,
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
    fn each_variant_reads_as_before_in_english_and_wholly_in_portuguese() {
        let cases = [
            (
                CliError::Bug {
                    flag: "--plot",
                    fault: CliFault::PlotFailed { error: "x".into() },
                },
                "--plot: the plot could not be drawn: x. Fix: report this as a bug; the table is \
                 still written without --plot",
                "--plot: o gráfico não pôde ser desenhado: x. Correção: relate isto como um \
                 defeito; a tabela ainda é escrita sem --plot",
            ),
            (
                CliError::usage("--threads", CliFault::ZeroThreads),
                "--threads: 0 threads cannot render. Fix: give --threads 1 or more (or leave it \
                 out: one per core)",
                "--threads: 0 threads não renderizam. Correção: dê --threads 1 ou mais (ou omita: \
                 uma por núcleo)",
            ),
            (
                CliError::usage(
                    "--size",
                    CliFault::OutOfMemory {
                        size: super::super::faults::memory_size(3_000_000_000),
                    },
                ),
                "--size: out of memory: this needs about 3.0 GB. Fix: give a smaller image \
                 (--size, or the camera's width and height)",
                "--size: memória insuficiente: isto precisa de cerca de 3.0 GB. Correção: dê uma \
                 imagem menor (--size, ou a largura e a altura da câmera)",
            ),
            (
                CliError::Write {
                    path: None,
                    source: std::io::Error::from_raw_os_error(13),
                },
                "cannot write standard output: Permission denied (os error 13)",
                "não é possível escrever na saída padrão: permissão negada (erro 13 do sistema)",
            ),
            (
                CliError::CreateFolder {
                    path: PathBuf::from("out"),
                    source: std::io::Error::from_raw_os_error(13),
                },
                "out: cannot create the folder: Permission denied (os error 13). Fix: give a \
                 folder in a place you can write to",
                "out: não é possível criar a pasta: permissão negada (erro 13 do sistema). \
                 Correção: dê uma pasta num lugar onde você pode escrever",
            ),
        ];
        for (e, en, pt) in cases {
            assert_eq!(e.to_string(), en);
            assert_eq!(e.text(Lang::En), en);
            assert_eq!(e.text(Lang::Pt), pt);
        }
    }

    #[test]
    fn a_setting_is_named_by_its_flag() {
        let fault = crate::problem::faults::SettingFault::LevelZero { max: 20 };
        let e = CliError::setting(Invalid::of("max_level", fault));
        assert_eq!(
            e.to_string(),
            "--max-level: 0 traces nothing: the primary ray already has level 1. Fix: give a \
             maximum level from 1 to 20 (1 = primary rays only)"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "--max-level: 0 não traça nada: o raio primário já tem nível 1. Correção: dê um \
             nível máximo de 1 a 20 (1 = só os raios primários)"
        );
    }
}
