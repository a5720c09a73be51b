//! `phong serve`: the checker as a web application (see [`crate::serve`]).

use crate::cli::args::ServeArgs;
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::serve::{self, Config};

pub(crate) fn run(args: &ServeArgs) -> Result<Exit, CliError> {
    let time = std::time::Duration::from_secs(u64::from(args.timeout));
    let limits = serve::limits::Limits {
        concurrency: args.max_concurrent as usize,
        connections: args.max_connections as usize,
        connections_per_client: args.max_connections_per_client as usize,
        time,
        header_time: std::time::Duration::from_secs(u64::from(
            args.header_timeout.min(args.timeout),
        )),
        ..Default::default()
    };
    let policy = super::course_policy(args.policy.as_deref(), args.exercises.as_deref())?;
    // The answers are appended to --log-answers (and it is renamed to PATH.1 when full): never the
    // course policy the server judges by, nor an exercise file of --exercises (a folder that
    // cannot be read is reported when the catalogue reads it).
    let exercises = match (&args.log_answers, &args.exercises) {
        (Some(_), Some(dir)) => serve::catalogue::Catalogue::files(dir).unwrap_or_default(),
        _ => Vec::new(),
    };
    let inputs: Vec<&std::path::Path> = policy
        .source
        .iter()
        .chain(&exercises)
        .map(|p| p.as_path())
        .collect();
    // The full log is renamed to PATH.1: that is written too.
    let older = args.log_answers.as_deref().map(serve::log::older);
    crate::cli::output::distinct(
        &inputs,
        &[
            ("--log-answers", args.log_answers.as_deref()),
            ("--log-answers", older.as_deref()),
        ],
    )?;
    let config = Config {
        addr: args.addr,
        policy: std::sync::Arc::new(policy),
        exercises: args.exercises.clone(),
        log_answers: args.log_answers.clone(),
        log_answers_max_kb: args.log_answers_max,
        limits,
    };
    serve::run(&config)?;
    Ok(Exit::Success)
}
