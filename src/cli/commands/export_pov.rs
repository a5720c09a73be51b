//! `phong export-pov`: the scene in f64 (POV-Ray computes in double), with the command line's
//! settings, as POV-Ray SDL; bad input when the file is bad or POV-Ray cannot express the scene.

use crate::cli::args::ExportPovArgs;
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::output;
use crate::problem::{self, ProblemError};

pub(crate) fn run(args: &ExportPovArgs) -> Result<Exit, CliError> {
    let path = &args.scene;
    output::distinct(&[path], &[("--output", args.output.as_deref())])?;
    let (file, mut problem) = problem::load::<f64>(path)?;
    // The meshes the scene names are inputs too: no output may replace one.
    let meshes = problem::mesh_files(&file, path);
    let meshes: Vec<&std::path::Path> = meshes.iter().map(|p| p.as_path()).collect();
    output::distinct(&meshes, &[("--output", args.output.as_deref())])?;
    problem.render = problem
        .render
        .with(&super::overrides(&args.settings))
        .map_err(CliError::setting)?;
    let sdl = crate::export::pov::export(&problem).map_err(|e| ProblemError::Invalid {
        path: path.clone(),
        field: e.what,
        fault: std::sync::Arc::new(crate::export::pov::Unexpressed(e.fault)),
    })?;
    output::emit(args.output.as_deref(), &sdl)?;
    Ok(Exit::Success)
}
