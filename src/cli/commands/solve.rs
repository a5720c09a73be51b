//! `phong solve`: each file solved and explained (text, Markdown, LaTeX, HTML) or written as
//! JSON; a bad file is reported and the others are still solved. `--part` chooses the
//! document (statements, solutions, answer key, or all three), `--course`/`--title`/`--date`/
//! `--author` its header, and `-o DIR/` writes one file per exercise.

use std::path::Path;

use crate::cli::args::{Format, SolveArgs};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::problem::Source;
use crate::report;
use crate::report::document::{Contents, Document, Header};
use crate::report::explain::Explanation;
use crate::report::file::{error_json, explain_file, solve_json_warned};
use crate::report::layout::{self, Layout};

pub(crate) fn run(args: &SolveArgs) -> Result<Exit, CliError> {
    let inputs: Vec<&std::path::Path> = args.files.iter().map(|p| p.as_path()).collect();
    output::distinct(&inputs, &[("--output", args.output.as_deref())])?;
    // A ray problem may name meshes, inputs too: no output may replace one. Read here only for
    // their names (a file that cannot be read is reported when it is solved; standard input is
    // read once, when it is solved).
    if args.output.is_some() {
        let meshes: Vec<std::path::PathBuf> = inputs
            .iter()
            .filter(|p| p.as_os_str() != "-")
            .filter_map(|p| {
                Some(crate::problem::mesh_files(
                    &Source::File(p).parse().ok()?,
                    p,
                ))
            })
            .flatten()
            .collect();
        let meshes: Vec<&Path> = meshes.iter().map(|p| p.as_path()).collect();
        output::distinct(&meshes, &[("--output", args.output.as_deref())])?;
    }
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
            std::fs::create_dir_all(dir).map_err(|source| CliError::Write {
                path: Some(dir.to_owned()),
                source,
            })?;
            let ext = extension(args);
            for (i, path) in solved.iter().enumerate() {
                let file = dir.join(format!("{}.{ext}", stem(path)));
                let out = match args.format {
                    Format::Json => report::json::documents_text(vec![docs[i].clone()]),
                    _ => write(args, &header, std::slice::from_ref(&explanations[i]), i + 1),
                };
                output::emit(Some(&file), &out)?;
            }
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
