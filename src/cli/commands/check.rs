//! `phong check`: each answer (given, or each file's key) judged, with the slips behind a wrong
//! one; with `--slips`, what each applicable slip gives instead, for an instructor.

use crate::check;
use crate::cli::args::{CheckArgs, CheckFormat};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::output;
use crate::problem;

pub fn run(args: &CheckArgs) -> Result<Exit, CliError> {
    if args.answer.is_some() && args.files.len() > 1 {
        return Err(CliError::Conflict {
            message: format!(
                "--answer checks one file, and {} were given",
                args.files.len()
            ),
            fix: "check one file at a time, or put each file's answer in its \"answer\" field \
                  and leave out --answer"
                .into(),
        });
    }
    if let Some(t) = args.tolerance {
        check::answer::check_tolerance(t).map_err(|source| CliError::Value {
            flag: "--tolerance",
            source,
        })?;
    }
    if args.slips {
        return slips(args);
    }
    let options = check::CheckOptions {
        answer: args.answer.clone(),
        scale: args.scale,
        tolerance: args.tolerance,
        strict: args.strict,
    };
    let mut exit = Exit::Success;
    let mut text = String::new();
    let mut docs = Vec::new();
    for path in &args.files {
        let c = check::check_file(path, &options);
        exit = exit.max(c.exit_code());
        if let Err(f) = &c.outcome {
            error::print_in(&f.message, args.lang);
        }
        match args.format {
            CheckFormat::Text => {
                if c.outcome.is_ok() {
                    text.push_str(&check::report::text(&c, args.lang));
                }
            }
            CheckFormat::Json => docs
                .push(serde_json::to_value(check::report::json(&c)).expect("a verdict serialises")),
        }
    }
    let out = match args.format {
        CheckFormat::Text => text,
        CheckFormat::Json => output::json_text(docs),
    };
    // Nothing could be checked: no empty output file.
    if !out.is_empty() {
        output::emit(args.output.as_deref(), &out)?;
    }
    Ok(exit)
}

/// `phong check --slips`: what each applicable slip gives, for an instructor.
fn slips(args: &CheckArgs) -> Result<Exit, CliError> {
    let mut exit = Exit::Success;
    let mut text = String::new();
    for path in &args.files {
        let expected = problem::load::<f64>(path)
            .and_then(|(_, p)| check::Expected::of(&p).map_err(|e| e.at(path)));
        match expected {
            Ok(x) => text.push_str(&check::report::slips_text(
                &path.display().to_string(),
                &x,
                args.lang,
            )),
            Err(e) => {
                error::print_in(&e, args.lang);
                exit = Exit::BadInput;
            }
        }
    }
    if !text.is_empty() {
        output::emit(args.output.as_deref(), &text)?;
    }
    Ok(exit)
}
