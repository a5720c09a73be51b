//! `phong solve`: each file solved and explained (text, Markdown, LaTeX, HTML) or written as
//! JSON; a bad file is reported and the others are still solved. `--part` chooses the
//! document (statements, solutions, answer key, or all three), `--course`/`--title`/`--date`/
//! `--author` its header, and `-o DIR/` writes one file per exercise (two inputs that would
//! share one are refused, before anything is written).

use std::path::Path;

use crate::cli::args::{Format, SolveArgs};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::report;
use crate::report::document::{Contents, Document, Header};
use crate::report::explain::Explanation;
use crate::report::file::{error_json, explain_file, solve_json_warned};
use crate::report::layout::{self, Layout};

pub(crate) fn run(args: &SolveArgs) -> Result<Exit, CliError> {
    let inputs: Vec<&std::path::Path> = args.files.iter().map(|p| p.as_path()).collect();
    output::distinct(&inputs, &[("--output", args.output.as_deref())])?;
    // A ray problem may name meshes, inputs too: no output may replace one.
    let meshes: Vec<std::path::PathBuf> = match args.output {
        Some(_) => super::named_meshes(inputs.iter().copied()),
        None => Vec::new(),
    };
    let meshes: Vec<&Path> = meshes.iter().map(|p| p.as_path()).collect();
    output::distinct(&meshes, &[("--output", args.output.as_deref())])?;
    if args.fragment && !matches!(args.format, Format::Latex | Format::Html) {
        return Err(CliError::conflict(CliFault::Fragment));
    }
    let header = Header {
        course: args.course.clone(),
        title: args.title.clone(),
        date: args.date.clone(),
        author: args.author.clone(),
    };
    if args.format == Format::Json && (args.part != Contents::Solution || !header.is_empty()) {
        return Err(CliError::conflict(CliFault::JsonNoDocument));
    }
    let folder = args.output.as_deref().filter(|p| is_folder(p));
    if let Some(dir) = folder {
        // The file each input would be written to: no two inputs to one file, and no input (or
        // mesh) replaced by one (`--format json ex/4.2.json -o ex/`), before anything is
        // written.
        let files: Vec<std::path::PathBuf> =
            inputs.iter().map(|p| exercise_file(dir, p, args)).collect();
        let shared = shared_outputs(&inputs, &files);
        if !shared.is_empty() {
            shared.iter().for_each(|e| error::print_in(e, args.lang));
            return Ok(Exit::BadInput);
        }
        let outputs: Vec<(&str, Option<&Path>)> = files
            .iter()
            .map(|f| ("--output", Some(f.as_path())))
            .collect();
        output::distinct(&inputs, &outputs)?;
        output::distinct(&meshes, &outputs)?;
    }
    let mut failed = false;
    let mut docs = Vec::new();
    let mut explanations = Vec::new();
    // The files solved, in order, for the names of the files written per exercise.
    let mut solved: Vec<&Path> = Vec::new();
    for path in &args.files {
        let result = match args.format {
            Format::Json => solve_json_warned(
                crate::problem::Source::File(path),
                args.precision,
                args.lang,
            )
            .map(|(v, warnings)| {
                warnings
                    .iter()
                    .for_each(|w| error::warn_in(path, w, args.lang));
                docs.push(v);
            }),
            _ => explain_file(path, args.precision, args.lang).map(|x| {
                x.warnings
                    .iter()
                    .for_each(|w| error::warn_in(path, w, args.lang));
                explanations.push(x);
            }),
        };
        match result {
            Ok(()) => solved.push(path),
            Err(e) => {
                failed = true;
                error::print_in(&e, args.lang);
                if args.format == Format::Json {
                    docs.push(error_json(path, &e));
                    solved.push(path);
                }
            }
        }
    }
    // Every file rejected and no JSON error documents: nothing to write (an empty or
    // bodiless output file would look like a result).
    if failed && explanations.is_empty() && docs.is_empty() {
        return Ok(Exit::BadInput);
    }
    match folder {
        Some(dir) => {
            // Every file written before any is put in place: a write that fails leaves the
            // folder as it was.
            let mut batch = output::Batch::new();
            batch.create_folder(dir)?;
            for (i, path) in solved.iter().enumerate() {
                let out = match args.format {
                    Format::Json => report::json::documents_text(vec![docs[i].clone()]),
                    _ => write(args, &header, std::slice::from_ref(&explanations[i]), i + 1),
                };
                batch.add(Some(&exercise_file(dir, path, args)), &mut |w| {
                    w.write_all(out.as_bytes())
                })?;
            }
            batch.commit()?;
        }
        None => {
            let out = match args.format {
                Format::Json => report::json::documents_text(docs),
                _ => write(args, &header, &explanations, 1),
            };
            output::emit(args.output.as_deref(), &out)?;
        }
    }
    Ok(if failed {
        Exit::BadInput
    } else {
        Exit::Success
    })
}

/// Whether `-o` names a folder: an existing one, or a path ending in a separator.
fn is_folder(p: &Path) -> bool {
    p.is_dir()
        || p.as_os_str()
            .to_string_lossy()
            .ends_with(std::path::MAIN_SEPARATOR)
        || p.as_os_str().to_string_lossy().ends_with('/')
}

/// The file name of an exercise's own output: its file's stem ("4.2" for 4.2.json).
fn stem(path: &Path) -> String {
    path.file_stem().map_or_else(
        || "problem".to_owned(),
        |s| s.to_string_lossy().into_owned(),
    )
}

/// The file in `dir` that the exercise `path` is written to (`DIR/4.2.txt` for 4.2.json).
fn exercise_file(dir: &Path, path: &Path, args: &SolveArgs) -> std::path::PathBuf {
    dir.join(format!("{}.{}", stem(path), extension(args)))
}

/// Each input whose file in the folder (`files`, in the inputs' order) has the name of an
/// earlier input's, ignoring case (one file on macOS and Windows): the error naming both inputs
/// and the file. Refused rather than told apart by a suffix (`4.2-2.txt`): a file is named
/// after its input so that a reader finds 4.2's solution at 4.2.txt, and a suffix would say
/// neither which 4.2 it is nor stay the same when the inputs are given in another order.
fn shared_outputs(inputs: &[&Path], files: &[std::path::PathBuf]) -> Vec<CliError> {
    let mut taken: std::collections::BTreeMap<String, usize> = Default::default();
    let mut shared = Vec::new();
    for (i, file) in files.iter().enumerate() {
        let name = file
            .file_name()
            .map(|n| n.to_string_lossy().to_lowercase())
            .unwrap_or_default();
        let Some(&j) = taken.get(&name) else {
            taken.insert(name, i);
            continue;
        };
        let (first, second) = (inputs[j].to_owned(), inputs[i].to_owned());
        shared.push(CliError::conflict(if files[j] == *file {
            CliFault::SharedOutput {
                first,
                second,
                output: file.clone(),
            }
        } else {
            CliFault::SharedOutputCase {
                first,
                second,
                output: files[j].clone(),
            }
        }));
    }
    shared
}

/// The layout of a document format (JSON is not a document layout: the caller writes it).
fn layout(args: &SolveArgs) -> Box<dyn Layout> {
    match args.format {
        Format::Text => Box::new(layout::Text {
            color: output::use_color(args.color, args.output.is_some()),
        }),
        Format::Markdown => Box::new(layout::Markdown),
        Format::Latex => Box::new(layout::Latex(report::latex::LatexOptions {
            fragment: args.fragment,
        })),
        Format::Html => Box::new(layout::Html(report::html::HtmlOptions {
            fragment: args.fragment,
        })),
        Format::Json => unreachable!("JSON is written by the caller"),
    }
}

/// The extension of a format's files.
fn extension(args: &SolveArgs) -> &'static str {
    match args.format {
        Format::Json => "json",
        _ => layout(args).extension(),
    }
}

/// The document of `explanations`, numbered from `first`, in the chosen format.
fn write(args: &SolveArgs, header: &Header, explanations: &[Explanation], first: usize) -> String {
    let doc = Document {
        header,
        contents: args.part,
        exercises: explanations,
        first_number: first,
        lang: args.lang,
    };
    layout(args).write(&doc)
}
