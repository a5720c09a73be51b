//! `phong policy`: the course policy in force for a folder of exercises (its
//! `course-policy.json` over the defaults, or `--policy FILE`), written as a policy file writes
//! it, every field with its value.

use crate::cli::args::PolicyCmdArgs;
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;

pub(crate) fn run(args: &PolicyCmdArgs) -> Result<Exit, CliError> {
    let folder = args
        .folder
        .clone()
        .unwrap_or_else(|| std::path::PathBuf::from("."));
    // A folder that does not exist, or a file, has no policy of its own: the defaults printed
    // for it would pass for its policy. Refused as `grade --exercises` refuses it.
    if !folder.is_dir() {
        return Err(CliError::not_a_folder(
            folder,
            "DIR",
            CliFault::ExercisesNotAFolder,
        ));
    }
    // The policy read is an input: `-o DIR/course-policy.json` would replace it.
    let read = super::policy_file(args.policy.policy.as_deref(), Some(&folder));
    output::distinct(
        &read.iter().map(|p| p.as_path()).collect::<Vec<_>>(),
        &[("--output", args.output.as_deref())],
    )?;
    let policy = super::course_policy(args.policy.policy.as_deref(), Some(&folder))?;
    let text = crate::report::json::pretty(&policy.to_json());
    output::emit(args.output.as_deref(), &text)?;
    Ok(Exit::Success)
}
