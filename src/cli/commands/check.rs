//! `phong check`: each answer (given, or each file's key) judged, with the slips behind a wrong
//! one; with `--slips`, what each applicable slip gives instead, for an instructor.

use crate::check;
use crate::cli::args::CheckArgs;
use crate::cli::error::{self, CliError};
use crate::cli::exit::Exit;
use crate::cli::faults::{CliFault, SystemError};
use crate::cli::output;
use crate::problem;
use crate::text::{FixOf, Said, WhatOf};

pub(crate) fn run(args: &CheckArgs) -> Result<Exit, CliError> {
    // The course policy each file is judged by is read too: `-o ex/course-policy.json` would
    // replace it with the report.
    let policies: Vec<std::path::PathBuf> = args
        .files
        .iter()
        .filter_map(|p| super::policy_file(args.policy.policy.as_deref(), folder_of(p)))
        .collect();
    // So is the file of `--steps` (`-` is standard input, which no file names).
    let steps_file = args.steps.iter().filter(|p| p.as_os_str() != "-");
    // And so are the meshes a ray problem names (`-o m.obj`).
    let meshes = match args.output {
        Some(_) => super::named_meshes(args.files.iter().map(|p| p.as_path())),
        None => Vec::new(),
    };
    let inputs: Vec<&std::path::Path> = args
        .files
        .iter()
        .chain(&policies)
        .chain(steps_file)
        .chain(&meshes)
        .map(|p| p.as_path())
        .collect();
    output::distinct(&inputs, &[("--output", args.output.as_deref())])?;
    if args.answer.is_some() && args.files.len() > 1 {
        return Err(CliError::conflict(CliFault::AnswerOneFile {
            given: args.files.len(),
        }));
    }
    if let Some(t) = args.tolerance {
        check::answer::check_tolerance(t).map_err(|source| CliError::Value {
            flag: "--tolerance",
            source: Box::new(source),
        })?;
    }
    if args.slips {
        return slips(args);
    }
    let steps = given_steps(args)?;
    if !steps.is_empty() {
        return with_steps(args, &steps);
    }
    let mut exit = Exit::Success;
    let mut writer = args.format.writer(args.lang);
    for path in &args.files {
        let options = check::CheckOptions {
            answer: args.answer.clone(),
            scale: args.scale,
            policy: std::sync::Arc::new(policy_of(args, path)?),
        };
        let c = check::check_file(path, &options);
        exit = exit.max(exit_of(c.status()));
        for w in &c.warnings {
            let warning = crate::text::Message::text(w, args.lang);
            error::warn_in(path, &warning, args.lang);
        }
        if let Err(f) = &c.outcome {
            error::print_in(&f.message, args.lang);
        }
        writer.add(Some(&c), None);
    }
    let out = writer.finish();
    // Nothing could be checked: no empty output file.
    if !out.is_empty() {
        output::emit(args.output.as_deref(), &out)?;
    }
    Ok(exit)
}

/// The course policy `path` is judged by (`--policy`, else the one beside it), with the flags
/// over it.
fn policy_of(args: &CheckArgs, path: &std::path::Path) -> Result<check::policy::Policy, CliError> {
    let mut policy = super::course_policy(args.policy.policy.as_deref(), folder_of(path))?;
    if args.tolerance.is_some() {
        policy.tolerance_forced = args.tolerance;
    }
    policy.strict |= args.strict;
    Ok(policy)
}

/// The folder of the file `path`, whose `course-policy.json` it is judged by (`.` for a name
/// without a folder).
fn folder_of(path: &std::path::Path) -> Option<&std::path::Path> {
    path.parent().map(|p| {
        if p.as_os_str().is_empty() {
            std::path::Path::new(".")
        } else {
            p
        }
    })
}

/// A check's exit: 0 accepted, 1 refused, 2 not checked.
fn exit_of(status: check::report::Status) -> Exit {
    match status {
        check::report::Status::Accepted => Exit::Success,
        check::report::Status::Refused => Exit::Wrong,
        check::report::Status::Unchecked => Exit::BadInput,
    }
}

/// The steps of `--step` and `--steps`, read (an unreadable one is a usage error, exit 2).
fn given_steps(args: &CheckArgs) -> Result<Vec<check::steps::GivenStep>, CliError> {
    let by_flag = !args.step.is_empty() || args.steps.is_some();
    if by_flag && args.files.len() > 1 {
        return Err(CliError::conflict(CliFault::StepsOneFile {
            given: args.files.len(),
        }));
    }
    let mut out = Vec::new();
    // A step is of the one file checked: its error names that file, as a judged step's does.
    let step_flag = match args.files.first() {
        Some(f) => format!("{}: --step", f.display()),
        None => "--step".to_owned(),
    };
    for text in &args.step {
        out.push(
            check::steps::parse_step(text)
                .map_err(|e| step_usage(&step_flag, "", e, |why| CliFault::StepFlag { why }))?,
        );
    }
    if let Some(path) = &args.steps {
        let shown = path.display();
        let text = std::fs::read_to_string(path).map_err(|e| {
            CliError::usage(
                "--steps",
                CliFault::StepsUnreadable {
                    file: path.clone(),
                    error: SystemError::of(&e),
                },
            )
        })?;
        let before = format!("{shown}: ");
        let read = check::steps::parse_steps_json(&text).map_err(|e| {
            step_usage("--steps", &before, e, |why| CliFault::StepsFile {
                before: before.clone(),
                why,
            })
        })?;
        out.extend(read);
    }
    Ok(out)
}

/// A step that cannot be read, as a usage error: its own fix where it gives one, else the
/// fault `otherwise` makes of it (`before` the message: the file it is in).
fn step_usage(
    flag: &str,
    before: &str,
    e: check::steps::BadStep,
    otherwise: impl Fn(Said) -> CliFault,
) -> CliError {
    use crate::text::{Fault, Lang};
    let fault = if e.fix(Lang::En).is_empty() {
        otherwise(Said::new(WhatOf(e)))
    } else {
        CliFault::Step {
            before: before.to_owned(),
            why: Said::new(WhatOf(e.clone())),
            fix: Said::new(FixOf(e)),
        }
    };
    CliError::usage(flag, fault)
}

/// `phong check FILE --step …`: the steps judged (and the answer, when one is given too).
fn with_steps(args: &CheckArgs, steps: &[check::steps::GivenStep]) -> Result<Exit, CliError> {
    let path = &args.files[0];
    let policy = policy_of(args, path)?;
    let checked = check::steps::check_steps(path, steps, policy.strict);
    let mut exit = exit_of(checked.status());
    for w in &checked.warnings {
        let warning = crate::text::Message::text(w, args.lang);
        error::warn_in(path, &warning, args.lang);
    }
    let policy = std::sync::Arc::new(policy);
    let answer = args.answer.as_ref().map(|_| {
        check::check_file(
            path,
            &check::CheckOptions {
                answer: args.answer.clone(),
                scale: args.scale,
                policy: policy.clone(),
            },
        )
    });
    if let Err(f) = &checked.outcome {
        error::print_in(&f.message, args.lang);
    }
    if let Some(c) = &answer {
        exit = exit.max(exit_of(c.status()));
        if let Err(f) = &c.outcome {
            error::print_in(&f.message, args.lang);
        }
    }
    let mut writer = args.format.writer(args.lang);
    writer.add(answer.as_ref(), Some(&checked));
    let out = writer.finish();
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
