//! `phong moodle`: problem files (or what `phong new` prints, on standard input as `-`) as a
//! Moodle XML quiz, one category per file (`export::moodle`).

use std::path::Path;

use crate::check::answer::from_key;
use crate::check::policy::Policy;
use crate::check::Scale;
use crate::cli::args::MoodleArgs;
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::export::moodle::{quiz, Entry, Grading, Set};
use crate::problem::{self, ProblemError, MAX_PROBLEM_BYTES};
use crate::text::lang::Lang;

pub(crate) fn run(args: &MoodleArgs) -> Result<Exit, CliError> {
    // The course policy beside the first file (not standard input), or --policy.
    let folder = args
        .files
        .iter()
        .find(|p| !output::is_dash(p))
        .map(|p| match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_owned(),
            _ => std::path::PathBuf::from("."),
        });
    let policy = super::course_policy(args.policy.as_deref(), folder.as_deref())?;
    // No output may replace what the run reads: a problem file, the policy, a mesh a ray
    // problem names (read here only for their names; a file that cannot be read is reported
    // below).
    let meshes = super::named_meshes(args.files.iter().map(|p| p.as_path()));
    let inputs: Vec<&Path> = args
        .files
        .iter()
        .chain(&policy.source)
        .chain(&meshes)
        .map(|p| p.as_path())
        .collect();
    output::distinct(&inputs, &[("--output", args.output.as_deref())])?;
    // What the quiz's refusals of the course policy are said of: its file, or `--policy`.
    let policy_named = || {
        policy
            .source
            .as_ref()
            .map_or_else(|| "--policy".to_owned(), |p| p.display().to_string())
    };
    let mut grading = Grading::of(&policy, args.lang).map_err(|share| {
        CliError::usage(
            policy_named(),
            CliFault::MoodleCredit {
                credit: crate::text::Num(share),
                allowed: crate::export::moodle::fractions(),
            },
        )
    })?;
    // Every file read, and every problem made a question, before anything is written: each bad
    // one is said, in the order given (a file's problems in its order), and nothing is written.
    let mut sets = Vec::new();
    // Each set's problems' places in its file, and what could not be read, by file and place.
    let mut places = Vec::new();
    let mut errors: Vec<(usize, usize, ProblemError)> = Vec::new();
    for (i, path) in args.files.iter().enumerate() {
        let read = read_set(path, &policy, args.lang);
        errors.extend(read.errors.into_iter().map(|(at, e)| (i, at, e)));
        sets.push(read.set);
        places.push(read.places);
    }
    grading
        .weigh(&sets.iter().flat_map(|s| &s.entries).collect::<Vec<_>>())
        .map_err(|e| {
            CliError::usage(
                policy_named(),
                CliFault::MoodlePoints {
                    problem: e.label.clone(),
                    points: crate::text::Num(e.points),
                },
            )
        })?;
    let text = quiz(&sets, &args.category, &grading, args.lang).map_err(|unasked| {
        errors.extend(unasked.into_iter().map(|(i, k, e)| (i, places[i][k], e)));
    });
    if !errors.is_empty() {
        errors.sort_by_key(|&(i, at, _)| (i, at));
        for (_, _, e) in &errors {
            error::print_in(e, args.lang);
        }
        return Ok(Exit::BadInput);
    }
    if let Ok(text) = text {
        output::emit(args.output.as_deref(), &text)?;
    }
    Ok(Exit::Success)
}

/// A file read: its set of the problems that could be read, each one's place in the file
/// (`places`), and the errors of those that could not, by place (a file that cannot be read at
/// all: one error, at 0).
struct Read {
    set: Set,
    places: Vec<usize>,
    errors: Vec<(usize, ProblemError)>,
}

/// One file: a problem, or an array of problems (as `phong new --count N` prints them).
fn read_set(path: &Path, policy: &Policy, lang: Lang) -> Read {
    let mut read = Read {
        set: Set {
            category: String::new(),
            entries: Vec::new(),
        },
        places: Vec::new(),
        errors: Vec::new(),
    };
    match read_entries(path, policy, lang, &mut read) {
        Ok(category) => read.set.category = category,
        Err(e) => read.errors.push((0, e)),
    }
    read
}

/// The problems of the file `path` into `read`, each that cannot be read as its error; the
/// file's category, or why the file cannot be read at all.
fn read_entries(
    path: &Path,
    policy: &Policy,
    lang: Lang,
    read: &mut Read,
) -> Result<String, ProblemError> {
    let bytes = problem::read_limited(path, MAX_PROBLEM_BYTES, problem::Input::ProblemFile)
        .map_err(|source| ProblemError::Read {
            path: path.to_owned(),
            source,
        })?;
    let text = String::from_utf8_lossy(&bytes);
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let stdin = output::is_dash(path);
    let label = if stdin {
        "-".to_owned()
    } else {
        path.display().to_string()
    };
    let sources: Vec<(String, String)> = if text.trim_start().starts_with('[') {
        let items: Vec<serde_json::Value> =
            serde_json::from_str(text).map_err(|e| ProblemError::Syntax {
                path: path.to_owned(),
                line: e.line(),
                column: e.column(),
                field: None,
                fault: std::sync::Arc::new(crate::cli::faults::CliFault::NotProblems {
                    error: crate::problem::JsonError::of(&e),
                }),
            })?;
        items
            .iter()
            .enumerate()
            .map(|(i, v)| (format!("{label}[{}]", i + 1), v.to_string()))
            .collect()
    } else {
        vec![(label.clone(), text.to_owned())]
    };
    // The exercise the policy's points name: the file's name without `.json` ("4.2"), as
    // `phong grade` names it; every problem of an array file takes the file's.
    let exercise = path
        .file_name()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    for (place, (label, source)) in sources.into_iter().enumerate() {
        let at = Path::new(&label);
        let problem = problem::parse_str(at, &source).and_then(|file| {
            let problem = problem::validate::validate_in::<f64>(&file, path.parent())
                .map_err(|e| problem::written::as_written(e, &source).at(at))?;
            Ok((file, problem))
        });
        let (file, problem) = match problem {
            Ok(read) => read,
            Err(e) => {
                read.errors.push((place, e));
                continue;
            }
        };
        // The tolerances `phong check` judges this problem's answers under (the key's own, else
        // the course policy's), on each scale.
        let key = file.answer.as_ref().and_then(|k| from_key(k).ok());
        let on = |scale| policy.tolerance(scale, key.as_ref().and_then(|k| k.tolerance_on(scale)));
        read.set.entries.push(Entry {
            label,
            problem,
            tolerance: on(Scale::Unit),
            tolerance_bits8: on(Scale::Bits8),
            points: policy.points_of(&exercise),
        });
        read.places.push(place);
    }
    Ok(if stdin {
        match lang {
            Lang::En => "Generated problems".to_owned(),
            Lang::Pt => "Problemas gerados".to_owned(),
        }
    } else {
        path.file_stem()
            .map_or_else(|| label.clone(), |s| s.to_string_lossy().into_owned())
    })
}
