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
    // The scene read with the flags' settings over the file's, then held to the image's bounds
    // with the settings in force, as `phong render` holds it (so `--max-level 3` exports a file
    // whose own `max_level` is 60).
    let problem::SceneFile {
        mut problem,
        camera,
        meshes,
    } = problem::load_scene_for::<f64>(path, problem::validate::Work::Rendered)?;
    // The meshes the scene names are inputs too: no output may replace one.
    let meshes: Vec<&std::path::Path> = meshes.iter().map(|p| p.as_path()).collect();
    output::distinct(&meshes, &[("--output", args.output.as_deref())])?;
    problem.render = problem
        .render
        .with(&super::overrides(&args.settings))
        .map_err(CliError::setting)?;
    super::check_settings(path, &args.settings, &problem, &camera)?;
    let sdl = crate::export::pov::export(&problem).map_err(|e| ProblemError::Invalid {
        path: path.clone(),
        field: e.what,
        fault: std::sync::Arc::new(crate::export::pov::Unexpressed(e.fault)),
    })?;
    output::emit(args.output.as_deref(), &sdl)?;
    Ok(Exit::Success)
}
