//! `phong render`: the scene rendered into an image file, or one pixel of it explained step by
//! step (text or JSON), in the precision asked for.

use std::path::Path;
use std::time::Instant;

use crate::cli::args::{Format, RenderArgs};
use crate::cli::error::CliError;
use crate::cli::exit::Exit;
use crate::cli::output;
use crate::core::{Precision, Real};
use crate::problem::{self, Camera, Problem};
use crate::report;
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
    let started = Instant::now();
    let (mut problem, camera) = problem::load_scene::<R>(path)?;
    let loaded = started.elapsed();
    problem.render = problem
        .render
        .with(&super::overrides(&args.settings))
        .map_err(CliError::setting)?;
    let image_format = match (&args.output, args.image_format) {
        (_, Some(f)) => Some(f),
        (Some(out), None) => Some(ImageFormat::from_path(out).ok_or_else(|| CliError::Usage {
            flag: "--output".into(),
            message: format!("{} does not end in .png or .ppm", out.display()),
            fix: "name the image *.png or *.ppm, or give --image-format png|ppm".into(),
        })?),
        (None, None) => None,
    };
    let pool = super::thread_pool(args.threads)?;
    let building = Instant::now();
    let scene = pool.install(|| Scene::new(&problem));
    let built = building.elapsed();

    if let Some((x, y)) = args.explain_pixel {
        return explain_pixel(args, &problem, &camera, &scene, (x, y));
    }

    let out = args.output.as_deref().expect("clap requires --output here");
    let bar = output::progress_bar(u64::from(camera.height));
    let tracing = Instant::now();
    let (image, counts) = pool
        .install(|| tracer::render_with(args.engine, &problem, &camera, &scene, &|| bar.inc(1)));
    bar.finish_and_clear();
    let traced = tracing.elapsed();
    let bytes = tracer::output::encode(&image, image_format.expect("known format"));
    output::write_file(out, &bytes)?;
    if args.stats {
        let secs = traced.as_secs_f64();
        eprintln!(
            "{}×{}, {} sample(s)/pixel, {}, {} thread(s): read and validated in {:.3} s, BVH of \
             {} surfaces built in {:.3} s, traced {} rays ({} primary, {} reflection, {} shadow) \
             in {:.3} s: {:.2} Mrays/s ({} engine)",
            image.width,
            image.height,
            problem.render.samples,
            R::NAME,
            pool.current_num_threads(),
            loaded.as_secs_f64(),
            problem.surfaces().len(),
            built.as_secs_f64(),
            counts.total(),
            counts.primary,
            counts.reflection,
            counts.shadow,
            secs,
            counts.total() as f64 / secs / 1e6,
            args.engine.name()
        );
    }
    Ok(Exit::Success)
}

/// `--explain-pixel X,Y`: the pixel's rays, each hit solved as `phong solve` solves a ray.
fn explain_pixel<R: Real>(
    args: &RenderArgs,
    problem: &Problem<R>,
    camera: &Camera<R>,
    scene: &Scene<R>,
    (x, y): (u32, u32),
) -> Result<Exit, CliError> {
    if x >= camera.width || y >= camera.height {
        return Err(CliError::Usage {
            flag: "--explain-pixel".into(),
            message: format!(
                "pixel {x},{y} is outside the {}×{} image",
                camera.width, camera.height
            ),
            fix: format!(
                "give X from 0 to {} and Y from 0 to {}",
                camera.width - 1,
                camera.height - 1
            ),
        });
    }
    let path: &Path = &args.scene;
    let e = tracer::explain_pixel(problem, camera, scene, x, y).map_err(|e| e.at(path))?;
    let file = path.display().to_string();
    let out = match args.format {
        Format::Markdown | Format::Latex | Format::Html => {
            return Err(CliError::Usage {
                flag: "--format".into(),
                message: "a pixel's explanation is written as text or json".into(),
                fix: "give --format text or --format json with --explain-pixel".into(),
            })
        }
        Format::Text => report::pixel::render_text(&file, problem, &e),
        Format::Json => output::json_pretty(
            &serde_json::to_value(report::pixel::document(&file, problem, &e))
                .expect("the explanation serialises"),
        ),
    };
    output::emit(args.output.as_deref(), &out)?;
    Ok(Exit::Success)
}
