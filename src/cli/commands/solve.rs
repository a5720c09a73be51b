//! `phong solve`: each file solved and explained (text, Markdown, LaTeX, HTML) or written as
//! JSON; a bad file is reported and the others are still solved.

use crate::cli::args::{Format, SolveArgs};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::output;
use crate::report;
use crate::report::file::{error_json, explain_file, solve_json_warned};

pub(crate) fn run(args: &SolveArgs) -> Result<Exit, CliError> {
    if args.fragment && !matches!(args.format, Format::Latex | Format::Html) {
        return Err(CliError::Conflict {
            message: "--fragment applies to --format latex and html only".into(),
            fix: "drop --fragment, or use --format latex or html".into(),
        });
    }
    let mut failed = false;
    let mut docs = Vec::new();
    let mut explanations = Vec::new();
    for path in &args.files {
        let result = match args.format {
            Format::Json => {
                solve_json_warned(path, args.precision, args.lang).map(|(v, warnings)| {
                    warnings.iter().for_each(|w| error::warn(w));
                    docs.push(v);
                })
            }
            _ => explain_file(path, args.precision, args.lang).map(|x| {
                x.warnings.iter().for_each(|w| error::warn(w));
                explanations.push(x);
            }),
        };
        if let Err(e) = result {
            failed = true;
            error::print(&e);
            if args.format == Format::Json {
                docs.push(error_json(path, &e));
            }
        }
    }
    // Every file rejected and no JSON error documents: nothing to write (an empty or
    // bodiless output file would look like a result).
    if failed && explanations.is_empty() && docs.is_empty() {
        return Ok(Exit::BadInput);
    }
    let out = match args.format {
        Format::Text => {
            let color = output::use_color(args.color, args.output.is_some());
            explanations
                .iter()
                .map(|x| report::text::write_explanation(x, color))
                .collect::<Vec<_>>()
                .join("\n")
        }
        Format::Markdown => report::markdown::write_all(&explanations),
        Format::Latex => report::latex::write_all(
            &explanations,
            report::latex::LatexOptions {
                fragment: args.fragment,
            },
        ),
        Format::Html => report::html::write_all(
            &explanations,
            report::html::HtmlOptions {
                fragment: args.fragment,
            },
            args.lang,
        ),
        Format::Json => output::json_text(docs),
    };
    output::emit(args.output.as_deref(), &out)?;
    Ok(if failed {
        Exit::BadInput
    } else {
        Exit::Success
    })
}
