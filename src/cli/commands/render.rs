//! `phong render`: the scene rendered into an image file, or one pixel of it explained step by
//! step (text, Markdown, LaTeX, HTML in English or Portuguese, or JSON), in the precision
//! asked for.

use std::path::Path;
use std::time::{Duration, Instant};

use crate::cli::args::{Format, RenderArgs};
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::faults::CliFault;
use crate::cli::output;
use crate::core::{Precision, Real};
use crate::problem::{self, Camera, Problem};
use crate::report;
use crate::text::lang::Lang;
use crate::tracer::output::ImageFormat;
use crate::tracer::{self, Scene};

pub(crate) fn run(args: &RenderArgs) -> Result<Exit, CliError> {
    match args.precision {
        Precision::F32 => render::<f32>(args),
        Precision::F64 => render::<f64>(args),
    }
}

fn render<R: Real>(args: &RenderArgs) -> Result<Exit, CliError> {
    let path = &args.scene;
    output::distinct(&[path], &[("--output", args.output.as_deref())])?;
    let started = Instant::now();
    let problem::SceneFile {
        mut problem,
        camera,
        meshes,
    } = problem::load_scene_for::<R>(path, work(args))?;
    let loaded = started.elapsed();
    // The meshes the scene names are inputs too: no output may replace one.
    let meshes: Vec<&Path> = meshes.iter().map(|p| p.as_path()).collect();
    output::distinct(&meshes, &[("--output", args.output.as_deref())])?;
    problem.render = problem
        .render
        .with(&super::overrides(&args.settings))
        .map_err(CliError::setting)?;
    if args.explain_pixel.is_some() {
        // Before the scene is built: an explanation too large to hold is refused at once. The
        // pixel's rays are all that is traced, and nothing is held by the image's size: the
        // image's bounds (its primary rays, its memory) are not the pixel's.
        crate::problem::validate::check_explanation(&problem)
            .map_err(|e| CliError::setting(e.at("explain_pixel")))?;
    } else {
        check_work(args, &problem, &camera)?;
    }
    // With --explain-pixel, --output names the explanation's file, whatever its extension;
    // otherwise the image's, whose format it (or --image-format) says. Checked before the build.
    let image_format = match (&args.output, args.image_format) {
        _ if args.explain_pixel.is_some() => None,
        (_, Some(f)) => Some(f),
        (Some(out), None) => Some(ImageFormat::from_path(out).ok_or_else(|| {
            CliError::usage(
                "--output",
                CliFault::ImageExtension {
                    output: out.clone(),
                },
            )
        })?),
        (None, None) => None,
    };
    let pool = super::thread_pool(args.threads)?;
    let building = Instant::now();
    let scene = pool.install(|| Scene::new(&problem));
    let built = building.elapsed();

    if let Some((x, y)) = args.explain_pixel {
        return explain_pixel(args, &problem, &camera, &scene, (x, y), &pool);
    }

    let out = args.output.as_deref().expect("clap requires --output here");
    let primary =
        u64::from(camera.width) * u64::from(camera.height) * u64::from(problem.render.samples);
    // A long render says how much work it is (and the bar its time left).
    let estimate = (primary >= 100_000_000).then(|| format!("{primary:.1e} primary rays"));
    let bar = output::progress_bar(u64::from(camera.height), estimate.as_deref());
    let tracing = Instant::now();
    let (image, counts) = pool
        .install(|| tracer::render_with(args.engine, &problem, &camera, &scene, &|| bar.inc(1)));
    bar.finish_and_clear();
    let traced = tracing.elapsed();
    let bytes = tracer::output::encode(&image, image_format.expect("known format"));
    output::write_file(out, &bytes)?;
    if args.stats {
        let threads = pool.current_num_threads();
        let times = (loaded, built, traced);
        output::say(&stats_line::<R>(
            args, &image, &problem, threads, times, &counts,
        ));
    }
    Ok(Exit::Success)
}

/// `--stats`: the image, the settings, and the time of each stage with the rays traced, in the
/// language of `--lang`. The numbers keep the decimal point in both languages, as every output
/// of phong does, so that a script reads either.
fn stats_line<R: Real>(
    args: &RenderArgs,
    image: &tracer::Image,
    problem: &Problem<R>,
    threads: usize,
    (loaded, built, traced): (Duration, Duration, Duration),
    counts: &tracer::Counts,
) -> String {
    let secs = traced.as_secs_f64();
    let rate = counts.total() as f64 / secs / 1e6;
    let (w, h, samples) = (image.width, image.height, problem.render.samples);
    let surfaces = problem.surfaces().len();
    let s = if surfaces == 1 { "" } else { "s" };
    let (read, build) = (loaded.as_secs_f64(), built.as_secs_f64());
    let (total, primary, reflection, transmission, shadow) = (
        counts.total(),
        counts.primary,
        counts.reflection,
        counts.transmission,
        counts.shadow,
    );
    let (precision, engine) = (R::NAME, args.engine.name());
    match args.lang {
        Lang::En => format!(
            "{w}×{h}, {samples} sample(s)/pixel, {precision}, {threads} thread(s): read and \
             validated in {read:.3} s, {surfaces} surface{s} prepared (BVH, flat lists) in \
             {build:.3} s, traced {total} rays ({primary} primary, {reflection} reflection, \
             {transmission} transmission, {shadow} shadow) in {secs:.3} s: {rate:.2} Mrays/s \
             ({engine} engine)"
        ),
        Lang::Pt => format!(
            "{w}×{h}, {samples} amostra(s)/pixel, {precision}, {threads} thread(s): lido e \
             validado em {read:.3} s, {surfaces} superfície{s} preparada{s} (BVH, listas) em \
             {build:.3} s, {total} raios traçados ({primary} primários, {reflection} de \
             reflexão, {transmission} de transmissão, {shadow} de sombra) em {secs:.3} s: \
             {rate:.2} Mraios/s (motor {engine})"
        ),
    }
}

/// The render's bounds with the settings in force ([`super::check_settings`]: its primary rays,
/// each sample's ray tree), and its image (and the rows gathered before it) within memory:
/// refused with exit 2 rather than aborting.
fn check_work<R: Real>(
    args: &RenderArgs,
    problem: &Problem<R>,
    camera: &Camera<R>,
) -> Result<(), CliError> {
    super::check_settings(&args.scene, &args.settings, problem, camera)?;
    let bytes = (camera.width as usize)
        .saturating_mul(camera.height as usize)
        .saturating_mul(3 * 2);
    super::memory(bytes, "--output", |size| CliFault::ImageOutOfMemory {
        size,
    })
}

/// What the scene is read for: one pixel (`--explain-pixel`), held to the pixel's bounds only,
/// or the whole image, held to the image's bounds by [`check_work`] with the flags' settings
/// over the file's.
fn work(args: &RenderArgs) -> crate::problem::validate::Work {
    match args.explain_pixel {
        Some(_) => crate::problem::validate::Work::Pixel,
        // `check_work` holds the image to its bounds once the flags are over the file's.
        None => crate::problem::validate::Work::Rendered,
    }
}

/// `--explain-pixel X,Y`: the pixel's rays, each hit solved as `phong solve` solves a ray.
fn explain_pixel<R: Real>(
    args: &RenderArgs,
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    (x, y): (u32, u32),
    pool: &rayon::ThreadPool,
) -> Result<Exit, CliError> {
    if x >= camera.width || y >= camera.height {
        return Err(CliError::usage(
            "--explain-pixel",
            CliFault::PixelOutside {
                x,
                y,
                width: camera.width,
                height: camera.height,
                last_x: camera.width - 1,
                last_y: camera.height - 1,
            },
        ));
    }
    let path: &Path = &args.scene;
    let e = tracer::explain_pixel(problem, camera, scene, x, y).map_err(|e| e.at(path))?;
    // In f32, the same pixel explained in f64 too, to show what f32 cost; nothing more in f64.
    let versus = match R::NAME {
        "f64" => None,
        _ => pixel_in_f64(args, (x, y), pool).map(|f| report::pixel::versus(&e, &f)),
    };
    let file = path.display().to_string();
    let pixel = || {
        let p = report::pixel::report(&file, problem, &e, args.lang);
        match &versus {
            Some(v) => p.versus(v),
            None => p,
        }
    };
    let out = match args.format {
        Format::Text => report::pixel::write_text(&pixel()),
        Format::Markdown => report::pixel::write_markdown(&pixel()),
        Format::Latex => {
            report::pixel::write_latex(&pixel(), report::latex::LatexOptions::default())
        }
        Format::Html => report::pixel::write_html(&pixel(), report::html::HtmlOptions::default()),
        Format::Json => report::json::pretty(
            &serde_json::to_value(report::pixel::PixelOut {
                versus_f64: versus,
                ..report::pixel::document(&file, problem, &e)
            })
            .expect("the explanation serialises"),
        ),
    };
    output::emit(args.output.as_deref(), &out)?;
    Ok(Exit::Success)
}

/// The pixel `(x, y)` of the scene read in f64, with the same settings, explained: what an f32
/// explanation is compared with. `None` where the scene does not load or the pixel does not
/// trace in f64 (f32 did, so that is a limit of f32's range already reported, or none).
fn pixel_in_f64(
    args: &RenderArgs,
    (x, y): (u32, u32),
    pool: &rayon::ThreadPool,
) -> Option<tracer::explain::PixelExplanation<f64>> {
    let problem::SceneFile {
        mut problem,
        camera,
        ..
    } = problem::load_scene_for::<f64>(&args.scene, work(args)).ok()?;
    problem.render = problem
        .render
        .with(&super::overrides(&args.settings))
        .ok()?;
    let scene = pool.install(|| Scene::new(&problem));
    tracer::explain_pixel(&problem, &camera, &scene, x, y).ok()
}
