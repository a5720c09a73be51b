//! `phong grade`: a CSV of answers graded row by row against the exercise files, the report
//! written (CSV or JSON) and, with `--summary`, the summary per exercise.

use crate::check;
use crate::cli::args::{GradeArgs, GradeFormat};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::output;

pub(crate) fn run(args: &GradeArgs) -> Result<Exit, CliError> {
    if let Some(t) = args.tolerance {
        check::answer::check_tolerance(t).map_err(|source| CliError::Value {
            flag: "--tolerance",
            source,
        })?;
    }
    if !args.exercises.is_dir() {
        return Err(CliError::NotAFolder {
            path: args.exercises.clone(),
            flag: "--exercises",
            fix: "give the folder that holds the exercise files (exercise 4.2 is DIR/4.2.json)",
        });
    }
    let options = check::grade::Options {
        exercises: args.exercises.clone(),
        scale: args.scale,
        tolerance: args.tolerance,
        strict: args.strict,
    };
    let report = check::grade::grade_file(&args.submissions, &options)?;
    let body = match args.format {
        GradeFormat::Csv => check::grade::rows_csv(&report),
        GradeFormat::Json => output::json_pretty(&report).into_bytes(),
    };
    let total =
        |f: fn(&check::grade::SummaryOut) -> usize| report.summary.iter().map(f).sum::<usize>();
    eprintln!(
        "graded {} rows: {} right, {} by the likely intended reading, {} wrong, {} invalid",
        report.rows.len(),
        total(|s| s.right),
        total(|s| s.reading),
        total(|s| s.wrong),
        total(|s| s.invalid)
    );
    let written = output::emit_bytes(args.output.as_deref(), &body);
    let Some(summary) = &args.summary else {
        return written.map(|()| Exit::Success);
    };
    // The summary is written even when the report could not be.
    let exit = error::carry_on(written);
    output::emit_bytes(Some(summary), &check::grade::summary_csv(&report))?;
    Ok(exit)
}
