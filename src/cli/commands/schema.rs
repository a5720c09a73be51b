//! `phong schema`: the JSON Schema of the problem format.

use crate::cli::args::SchemaArgs;
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::output;
use crate::problem;

pub(crate) fn run(args: &SchemaArgs) -> Result<Exit, CliError> {
    let mut text = problem::schema_json();
    text.push('\n');
    output::emit(args.output.as_deref(), &text)?;
    Ok(Exit::Success)
}
