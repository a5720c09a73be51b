//! The commands, one file each, as cargo's `commands/<name>.rs`: each `run` takes its parsed
//! arguments and returns how it ended, or the error that stopped it (printed by
//! [`crate::cli::run`]). Also what the tracer's commands share: the settings given over a
//! scene's, and the worker threads.

pub(crate) mod check;
pub(crate) mod export_pov;
pub(crate) mod grade;
pub(crate) mod moodle;
pub(crate) mod new;
pub(crate) mod policy;
pub(crate) mod render;
pub(crate) mod schema;
#[cfg(feature = "serve")]
pub(crate) mod serve;
pub(crate) mod solve;
pub(crate) mod tradeoff;

use super::args::{Switch, TraceSettings};
use super::error::CliError;
use super::faults::CliFault;
use crate::problem::RenderOverrides;

/// The course policy a judging command goes by: the file of `--policy`, else
/// `course-policy.json` in `folder` (the exercises' folder) when there is one, else the
/// defaults. A file that cannot be read or is not a policy stops the command (exit 2), naming it.
pub(crate) fn course_policy(
    flag: Option<&std::path::Path>,
    folder: Option<&std::path::Path>,
) -> Result<crate::check::policy::Policy, CliError> {
    use crate::check::policy::Policy;
    let (path, named) = match (flag, policy_file(flag, folder)) {
        (Some(file), _) => (file.to_owned(), format!("--policy {}", file.display())),
        (None, Some(path)) => {
            let named = path.display().to_string();
            (path, named)
        }
        (None, None) => return Ok(Policy::default()),
    };
    Policy::read_file(&path).map_err(|why| {
        let unreadable = matches!(why, crate::check::policy::PolicyError::Unreadable { .. });
        let why = crate::text::Said::new(why);
        let fault = if unreadable {
            CliFault::PolicyUnreadable { why }
        } else {
            CliFault::Policy { why }
        };
        CliError::usage(named, fault)
    })
}

/// The file [`course_policy`] reads, without reading it: the file of `--policy`, else the
/// `course-policy.json` of `folder` when there is one; `None` for the defaults. An input of
/// the run, which no output may replace ([`crate::cli::output::distinct`]).
pub(crate) fn policy_file(
    flag: Option<&std::path::Path>,
    folder: Option<&std::path::Path>,
) -> Option<std::path::PathBuf> {
    match flag {
        Some(file) => Some(file.to_owned()),
        None => folder.and_then(crate::check::policy::Policy::file_in),
    }
}

/// The mesh files (OBJ) the problem files `files` name ([`crate::problem::mesh_files`]):
/// inputs of the run too, which no output may replace (`phong check p.json -o m.obj`). Read
/// here only for their names, for the commands that refuse an output before they read their
/// problems (`solve`, `check`, `moodle`, `grade`; `render`, `export-pov` and `tradeoff` have
/// the names from the scene they load): a file that cannot be read or parsed names none (it is
/// reported when it is read for its work), and standard input (`-`) is read once, for the
/// work, and names none.
pub(crate) fn named_meshes<'a>(
    files: impl IntoIterator<Item = &'a std::path::Path>,
) -> Vec<std::path::PathBuf> {
    use crate::problem::{mesh_files, Source};
    files
        .into_iter()
        .filter(|p| !super::output::is_dash(p))
        .filter_map(|p| Some(mesh_files(&Source::File(p).parse().ok()?, p)))
        .flatten()
        .collect()
}

/// The command line's tracer settings, to put over a scene's.
fn overrides(s: &TraceSettings) -> RenderOverrides {
    RenderOverrides {
        max_level: s.max_level,
        min_weight: s.min_weight,
        samples: s.samples,
        shadows: s.shadows.map(|sw| sw == Switch::On),
    }
}

/// Holds a scene's image to its bounds with the settings in force (`given`'s over the file's,
/// already put in `problem.render`): its primary rays (width × height × samples) within
/// [`crate::problem::model::MAX_PIXEL_SAMPLES`] and one sample's ray tree within
/// [`crate::problem::validate::MAX_TREE_RAYS`]. A bound passed is said of the flag that set the
/// setting, or, where the file's own setting is in force, of the file's field
/// (`render.samples`, `render.max_level`) at `scene`, as reading it would.
fn check_settings<R: crate::core::Real>(
    scene: &std::path::Path,
    given: &TraceSettings,
    problem: &crate::problem::Problem<R>,
    camera: &crate::problem::Camera<R>,
) -> Result<(), CliError> {
    use crate::problem::faults::SettingFault;
    use crate::problem::validate::{check_tree, check_work};
    let said = |flag: Option<&str>, field: &str, e: SettingFault| match flag {
        Some(flag) => CliError::setting(e.at(flag)),
        None => CliError::Problem(e.at(field).at(scene)),
    };
    check_work(camera.width, camera.height, problem.render.samples)
        .map_err(|e| said(given.samples.map(|_| "samples"), "render.samples", e))?;
    let s = &problem.render;
    check_tree(problem, s.max_level, s.min_weight.to_f64()).map_err(|e| {
        let flag =
            (given.max_level.map(|_| "max_level")).or(given.min_weight.map(|_| "min_weight"));
        said(flag, "render.max_level", e)
    })
}

/// Refuses, with an "out of memory: this needs about N GB" error named by `flag`, work whose
/// largest allocation (`bytes`) the system cannot give: tried once with `try_reserve`, so that
/// the allocation that follows would not abort the program.
/// `fault` says it, given the size needed.
fn memory(bytes: usize, flag: &'static str, fault: fn(String) -> CliFault) -> Result<(), CliError> {
    let mut probe: Vec<u8> = Vec::new();
    crate::text::memory::handled(|| probe.try_reserve_exact(bytes))
        .map_err(|_| CliError::usage(flag, fault(super::faults::memory_size(bytes))))
}

/// The worker threads: `threads`, or one per core.
fn thread_pool(threads: Option<usize>) -> Result<rayon::ThreadPool, CliError> {
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        if n == 0 {
            return Err(CliError::usage("--threads", CliFault::ZeroThreads));
        }
        b = b.num_threads(n);
    }
    b.build().map_err(CliError::Threads)
}
