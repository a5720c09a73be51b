//! `phong tradeoff`: the sweep checked, the scene loaded in the precisions it needs, every
//! setting measured, and the table (text, JSON, CSV) and the plot written.

use std::path::{Path, PathBuf};

use crate::cli::args::{TradeoffArgs, TradeoffFormat};
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::core::{Precision, Real};
use crate::problem::{self, ProblemError, SceneFile};
use crate::tradeoff::{self, report, ReferenceSettings, Scenes, Sweep};

pub(crate) fn run(args: &TradeoffArgs) -> Result<Exit, CliError> {
    output::distinct(
        &[&args.scene],
        &[
            ("--output", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
        ],
    )?;
    let sweep = Sweep::new(
        &args.precisions,
        &args.levels,
        &args.min_weights,
        &args.samples,
        args.runs,
        ReferenceSettings {
            max_level: args.reference_level,
            samples: args.reference_samples,
        },
    )
    .map_err(CliError::setting)?;
    if let Some(plot) = &args.plot {
        if !plot
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
        {
            return Err(CliError::usage(
                "--plot",
                CliFault::PlotNotSvg { plot: plot.clone() },
            ));
        }
    }
    let SceneFile {
        problem,
        camera,
        meshes,
    } = load::<f64>(&args.scene, args.size)?;
    let f64_scene = (problem, camera);
    // The meshes the scene names are inputs too: no output may replace one.
    let meshes: Vec<&Path> = meshes.iter().map(PathBuf::as_path).collect();
    output::distinct(
        &meshes,
        &[
            ("--output", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
        ],
    )?;
    let f32_scene = if args.precisions.contains(&Precision::F32) {
        let s = load::<f32>(&args.scene, args.size)?;
        Some((s.problem, s.camera))
    } else {
        None
    };
    let (w, h) = (f64_scene.1.width, f64_scene.1.height);
    let work = sweep.work(u64::from(w) * u64::from(h));
    if work > tradeoff::MAX_SWEEP_RAYS {
        return Err(CliError::usage(
            "--size",
            CliFault::SweepTooLarge {
                width: w,
                height: h,
                work: format!("{work:.2e}"),
                most: format!("{:.2e}", tradeoff::MAX_SWEEP_RAYS as f64),
            },
        ));
    }
    // The deepest trees it traces: the reference's (minimum weight 0), and the sweep's largest
    // level with its smallest weight.
    let fits = |level: u32, weight: f64| {
        crate::problem::validate::check_tree(&f64_scene.0, level, weight).is_ok()
    };
    let reference = sweep.reference.max_level;
    if !fits(reference, 0.0) {
        let most = (1..reference).rev().find(|&l| fits(l, 0.0)).unwrap_or(1);
        let limit = crate::problem::validate::MAX_TREE_RAYS;
        return Err(CliError::usage(
            "--reference-level",
            CliFault::ReferenceTree {
                level: reference,
                limit,
                most,
            },
        ));
    }
    if let (Some(&level), Some(weight)) = (
        sweep.levels.iter().max(),
        sweep.min_weights.iter().copied().reduce(f64::min),
    ) {
        crate::problem::validate::check_tree(&f64_scene.0, level, weight)
            .map_err(|e| CliError::setting(e.at("levels")))?;
    }
    for samples in sweep.samples.iter().chain([&sweep.reference.samples]) {
        crate::problem::validate::check_work(w, h, *samples)
            .map_err(|e| CliError::setting(e.at("size")))?;
    }
    super::memory(
        (w as usize)
            .saturating_mul(h as usize)
            .saturating_mul(3 * 8 * 2),
        "--size",
        |size| CliFault::OutOfMemory { size },
    )?;
    let pool = super::thread_pool(args.threads)?;
    let total = 1 + sweep.settings().len() as u64 * u64::from(sweep.runs);
    let estimate = (work >= 100_000_000).then(|| format!("{work:.1e} primary rays"));
    let bar = output::progress_bar(total, estimate.as_deref());
    let outcome = pool.install(|| {
        tradeoff::measure(
            args.engine,
            Scenes::new(f64_scene, f32_scene),
            &sweep,
            &|_| bar.inc(1),
        )
    });
    bar.finish_and_clear();
    let file = args.scene.display().to_string();
    let summary = report::Summary::new(&file, &outcome, args.metric, args.budget);
    // The plot and the table, all or nothing: a plot that cannot be drawn or written keeps the
    // old table, a table that cannot be written the old plot.
    let mut batch = output::Batch::new();
    if let Some(plot) = &args.plot {
        let svg = tradeoff::plot::svg(&summary, args.lang).map_err(|error| CliError::Bug {
            flag: "--plot",
            fault: CliFault::PlotFailed { error },
        })?;
        batch.add(Some(plot), &mut |w| w.write_all(svg.as_bytes()))?;
    }
    let text = match args.format {
        TradeoffFormat::Text => report::text(&summary, args.lang),
        TradeoffFormat::Json => crate::report::json::pretty(&report::json(&summary)),
        TradeoffFormat::Csv => report::csv(&summary),
    };
    batch.add(args.output.as_deref(), &mut |w| {
        w.write_all(text.as_bytes())
    })?;
    batch.commit()?;
    Ok(Exit::Success)
}

/// The scene in precision `R`, at `size` instead of the camera's when given, and the mesh files
/// it names. The file's own render settings (its maximum level, minimum weight and samples) are
/// never traced: the sweep sets its own, and [`run`] holds the image to its bounds with those
/// (and at `size`), so the file's are not held to them here.
fn load<R: Real>(path: &Path, size: Option<(u32, u32)>) -> Result<SceneFile<R>, ProblemError> {
    let mut scene = problem::load_scene_for::<R>(path, problem::validate::Work::Rendered)?;
    if let Some((w, h)) = size {
        scene.camera.width = w;
        scene.camera.height = h;
    }
    Ok(scene)
}
