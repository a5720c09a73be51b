//! `phong grade`: a CSV of answers graded row by row against the exercise files, the report
//! written (CSV or JSON) and, with `--summary`, the summary per exercise.

use std::path::Path;

use crate::check;
use crate::cli::args::{GradeArgs, GradeFormat};
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::text::Said;

pub(crate) fn run(args: &GradeArgs) -> Result<Exit, CliError> {
    if let Some(t) = args.tolerance {
        check::answer::check_tolerance(t).map_err(|source| CliError::Value {
            flag: "--tolerance",
            source: Box::new(source),
        })?;
    }
    if !args.exercises.is_dir() {
        return Err(CliError::not_a_folder(
            args.exercises.clone(),
            "--exercises",
            CliFault::ExercisesNotAFolder,
        ));
    }
    let mut policy = super::course_policy(args.policy.policy.as_deref(), Some(&args.exercises))?;
    let policy_file = policy.source.clone();
    let mut inputs: Vec<&Path> = vec![&args.submissions];
    inputs.extend(policy_file.as_deref());
    // The exercise files are inputs too: `-o exercises/4.2.json` would replace one.
    let exercise_files: Vec<std::path::PathBuf> = std::fs::read_dir(&args.exercises)
        .map(|dir| {
            dir.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json"))
                .collect()
        })
        .unwrap_or_default();
    inputs.extend(exercise_files.iter().map(|p| p.as_path()));
    // So are the meshes an exercise names (a ray problem's OBJ file beside it), read for their
    // names where there is a file to write.
    let writes = [
        &args.output,
        &args.summary,
        &args.by_student,
        &args.class_report,
    ]
    .iter()
    .any(|o| o.is_some());
    let meshes = if writes {
        super::named_meshes(exercise_files.iter().map(|p| p.as_path()))
    } else {
        Vec::new()
    };
    inputs.extend(meshes.iter().map(|p| p.as_path()));
    output::distinct(
        &inputs,
        &[
            ("--output", args.output.as_deref()),
            ("--summary", args.summary.as_deref()),
            ("--by-student", args.by_student.as_deref()),
            ("--class-report", args.class_report.as_deref()),
        ],
    )?;
    for (flag, path) in [
        ("--output", args.output.as_deref()),
        ("--summary", args.summary.as_deref()),
        ("--by-student", args.by_student.as_deref()),
        ("--class-report", args.class_report.as_deref()),
    ] {
        // A Gradescope folder (`-o DIR/`) is created; any other output's folder must exist.
        let folder_output = flag == "--output" && args.format == GradeFormat::Gradescope;
        if let Some(path) = path.filter(|_| !folder_output) {
            folder_exists(path)?;
        }
    }
    let made = match args.format {
        GradeFormat::Xlsx => workbook_created()?,
        _ => check::export::xlsx::MADE,
    };
    // The flags over the course policy.
    if let Some(p) = &args.points {
        policy.give_points(p).map_err(|why| {
            CliError::usage(
                "--points",
                CliFault::Points {
                    why: Said::new(why),
                },
            )
        })?;
    }
    if let Some(c) = args.reading_credit {
        policy.reading_credit = check::policy::credit(c).map_err(|why| {
            CliError::usage(
                "--reading-credit",
                CliFault::Credit {
                    why: Said::new(why),
                },
            )
        })?;
    }
    if args.tolerance.is_some() {
        policy.tolerance_forced = args.tolerance;
    }
    policy.strict |= args.strict;
    if let Some(d) = args.duplicates {
        policy.duplicates = d;
    }
    let options = check::grade::Options {
        exercises: args.exercises.clone(),
        scale: args.scale,
        delimiter: args.delimiter,
        policy,
        lang: args.lang,
        input: args.input,
        questions: args.questions.clone(),
    };
    let bytes = check::grade::read_submissions(&args.submissions, &options)?;
    if check::grade::windows_1252(&bytes) {
        let said = check::messages::Encoding::Windows1252;
        error::warn_in(
            &args.submissions,
            &crate::text::Message::text(&said, args.lang),
            args.lang,
        );
    }
    // Each row is graded once to count the students' answers, then again as it is written: the
    // reports are written one row at a time, never whole in memory.
    let graded = check::grade::Graded::new(&bytes, &options);
    // Every output is written in full (the report, then the summary, the totals and the class
    // page) before any is put in place: a write that fails all the same (a full disk, a folder
    // that cannot be written) leaves every output as it was, and the `graded N rows` line,
    // which reads as success, is not written.
    let lang = args.lang;
    let written = write_outputs(&graded, args, &inputs, made);
    let exit = error::carry_on_in(written, lang);
    if exit != Exit::Success {
        return Ok(exit);
    }
    let total =
        |f: fn(&check::grade::SummaryOut) -> usize| graded.summary().iter().map(f).sum::<usize>();
    let used = match &options.policy.source {
        Some(file) => check::messages::PolicyUsed::File { file: file.clone() },
        None => check::messages::PolicyUsed::Default {
            folder: args.exercises.clone(),
        },
    };
    output::say(&crate::text::Message::text(&used, lang));
    output::say(&check::messages::graded(
        graded.len(),
        total(|s| s.right),
        total(|s| s.reading),
        total(|s| s.wrong),
        total(|s| s.invalid),
        lang,
    ));
    Ok(exit)
}

/// Every output of the run, written all or nothing ([`output::Batch`]); `inputs`: the files
/// the run reads, which no output may replace; `made`: when a workbook says it was made.
fn write_outputs(
    graded: &check::grade::Graded,
    args: &GradeArgs,
    inputs: &[&Path],
    made: i64,
) -> Result<(), CliError> {
    let mut batch = output::Batch::new();
    let out = args.output.as_deref();
    match args.format {
        GradeFormat::Csv => batch.add(out, &mut |w| graded.write_rows_csv(w))?,
        GradeFormat::Json => batch.add(out, &mut |w| graded.write_json(w))?,
        GradeFormat::Junit => batch.add(out, &mut |w| {
            check::export::junit::write(graded, args.lang, w)
        })?,
        GradeFormat::Xlsx => batch.add(out, &mut |w| {
            check::export::xlsx::write(graded, args.lang, made, w)
        })?,
        GradeFormat::Gradescope => gradescope(graded, args, inputs, &mut batch)?,
    }
    if let Some(summary) = &args.summary {
        batch.add(Some(summary), &mut |w| graded.write_summary_csv(w))?;
    }
    if let Some(by) = &args.by_student {
        batch.add(Some(by), &mut |w| graded.write_students_csv(w))?;
    }
    if let Some(path) = &args.class_report {
        let file = args.submissions.display().to_string();
        let page = check::export::class::html(graded, &file, args.lang);
        batch.add(Some(path), &mut |w| w.write_all(page.as_bytes()))?;
    }
    batch.commit()
}

/// When the workbook says it was made (a Unix time): `SOURCE_DATE_EPOCH` when it is set (as
/// reproducible builds set it), else [`check::export::xlsx::MADE`]. A value that is not a
/// whole number of seconds from 1970 to the year 9999 is refused, before anything is written.
fn workbook_created() -> Result<i64, CliError> {
    let Some(value) = std::env::var_os("SOURCE_DATE_EPOCH").filter(|v| !v.is_empty()) else {
        return Ok(check::export::xlsx::MADE);
    };
    let text = value.to_string_lossy();
    text.parse::<i64>()
        .ok()
        .filter(|_| text.bytes().all(|b| b.is_ascii_digit()))
        .filter(|&t| t < 253_402_300_800)
        .ok_or_else(|| {
            CliError::usage(
                "SOURCE_DATE_EPOCH",
                CliFault::SourceDateEpoch {
                    value: crate::text::Echo::new(&text, 40),
                },
            )
        })
}

/// Gradescope's results.json: to `-o FILE` (one student's, the file itself: several are
/// refused) or standard output (one student: the file itself; several: an object keyed by
/// student), or, with `-o DIR/` (a folder, or a path ending in
/// `/`), one `DIR/STUDENT.json` per student (and `DIR/_no_student_.json`, `_sem_aluno_.json`
/// in Portuguese, for the rows without a student). A student's file that would replace an input
/// (`-o` the exercises' folder, a student named "4.2") is refused, as `-o` itself would be.
fn gradescope(
    graded: &check::grade::Graded,
    args: &GradeArgs,
    inputs: &[&Path],
    batch: &mut output::Batch,
) -> Result<(), CliError> {
    let to_folder = args.output.as_deref().filter(|o| {
        o.is_dir()
            || o.as_os_str()
                .to_string_lossy()
                .ends_with(std::path::MAIN_SEPARATOR)
    });
    let Some(dir) = to_folder else {
        // A results.json is one submission's: a file of several students' (an object keyed by
        // student) would fail Gradescope's autograder, so only standard output gets one.
        let file = args.output.as_deref().filter(|o| !output::is_dash(o));
        if file.is_some() && graded.students() > 1 {
            use check::export::Class;
            return Err(CliError::usage(
                "--output",
                CliFault::GradescopeStudents {
                    count: graded.students(),
                    first: crate::text::Echo::new(graded.name(0), 40),
                    second: crate::text::Echo::new(graded.name(1), 40),
                },
            ));
        }
        return batch.add(args.output.as_deref(), &mut |w| {
            check::export::gradescope::write_class(graded, args.lang, w)
        });
    };
    batch.create_folder(dir)?;
    check::export::gradescope::write_files(graded, args.lang, |name, write| {
        let file = dir.join(format!("{name}.json"));
        output::distinct(inputs, &[("--output", Some(&file))])?;
        batch.add(Some(&file), write)
    })
}

/// Refuses, before anything is written, an output `path` whose folder does not exist or is not
/// a folder, so that a bad `--summary` does not leave the report written with an error; the
/// error is the one writing the file would give ([`crate::cli::files::folder_problem`]).
/// `-` (standard output) and a path in the current folder pass.
fn folder_exists(path: &Path) -> Result<(), CliError> {
    if output::is_dash(path) {
        return Ok(());
    }
    let Some(folder) = path.parent().filter(|f| !f.as_os_str().is_empty()) else {
        return Ok(());
    };
    match crate::cli::files::folder_problem(folder) {
        None => Ok(()),
        Some(source) => Err(CliError::Write {
            path: Some(path.to_owned()),
            source,
        }),
    }
}
