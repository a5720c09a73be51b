//! The arguments of the tracer's commands: `phong render`, `phong tradeoff` and `phong export-pov`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct TradeoffArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    /// Precisions to sweep.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "f32,f64")]
    pub(crate) precisions: Vec<Precision>,
    /// Maximum levels to sweep, each 1 to 1000.
    #[arg(long, value_delimiter = ',', value_name = "N,...", default_value = "1,2,3,5,10",
          value_parser = parse_level)]
    pub(crate) levels: Vec<u32>,
    /// Minimum weights to sweep (decimals or fractions such as 1/255).
    #[arg(long, value_delimiter = ',', value_name = "W,...", value_parser = parse_fraction,
          default_value = "0,1/255,0.1")]
    pub(crate) min_weights: Vec<f64>,
    /// Samples per pixel to sweep, each 1 to 4096.
    #[arg(long, value_delimiter = ',', value_name = "N,...", default_value = "1,4,16",
          value_parser = parse_samples)]
    pub(crate) samples: Vec<u32>,
    /// Renders per setting, 1 to 1000; its time is their median.
    #[arg(long, value_name = "N", default_value_t = 3,
          value_parser = parse_runs)]
    pub(crate) runs: u32,
    /// The reference's maximum level, 1 to 1000 (it is f64 with minimum weight 0).
    #[arg(long, value_name = "N", default_value_t = 64, value_parser = parse_level)]
    pub(crate) reference_level: u32,
    /// The reference's samples per pixel, 1 to 4096.
    #[arg(long, value_name = "N", default_value_t = 64, value_parser = parse_samples)]
    pub(crate) reference_samples: u32,
    /// The error budget: which setting is the fastest with its error at most this?
    #[arg(long, value_name = "E", value_parser = parse_fraction, default_value = "1/255")]
    pub(crate) budget: f64,
    /// The error the budget and the Pareto front are judged by.
    #[arg(long, value_enum, default_value_t = crate::tradeoff::Metric::Rmse)]
    pub(crate) metric: crate::tradeoff::Metric,
    /// Render at this size instead of the camera's (quicker sweeps).
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub(crate) size: Option<(u32, u32)>,
    /// Worker threads, 1 to 1024 (default: one per core).
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub(crate) threads: Option<usize>,
    /// The tracer of every render (the reference too), as `phong render --engine`: packets of
    /// rays in SIMD lanes (wide) or one ray at a time (scalar). Both give the same images,
    /// errors and rays; only the times differ.
    #[arg(long, value_enum, default_value_t = crate::tracer::Engine::Wide)]
    pub(crate) engine: crate::tracer::Engine,
    /// Format of the table.
    #[arg(long, value_enum, default_value_t = TradeoffFormat::Text)]
    pub(crate) format: TradeoffFormat,
    /// Write the table to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// Write the plot of error against time (SVG) to this file.
    #[arg(long, value_name = "PATH.svg")]
    pub(crate) plot: Option<PathBuf>,
    /// Language of the table, the plot and the errors (json and csv are language-neutral).
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum TradeoffFormat {
    Text,
    Json,
    Csv,
}

#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.help(
    "Samples per pixel: only 1 can be exported (POV-Ray cannot average phong's stratified \
     samples) [scene's, or 1]"
)))]
pub(crate) struct ExportPovArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    /// Write the SDL to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// The tracer's settings over the scene's (POV-Ray can only match 1 sample per pixel).
    #[command(flatten)]
    pub(crate) settings: TraceSettings,
    /// Language of the errors (the SDL is the same in either).
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

/// The tracer's settings, each over the scene's `render` (or its default).
#[derive(Debug, Args)]
pub(crate) struct TraceSettings {
    /// The maximum recursion level, 1 to 1000 (primary rays are level 1) [scene's, or 5].
    #[arg(long, value_name = "N", value_parser = parse_level)]
    pub(crate) max_level: Option<u32>,
    /// The minimum weight of a reflection ray, a number ≥ 0 or a fraction [scene's, or 1/255].
    #[arg(long, value_name = "W", value_parser = parse_fraction)]
    pub(crate) min_weight: Option<f64>,
    /// Samples per pixel, 1 to 4096, stratified and deterministic [scene's, or 1].
    #[arg(long, value_name = "N", value_parser = parse_samples)]
    pub(crate) samples: Option<u32>,
    /// Shadow rays on or off [scene's, or on].
    #[arg(long, value_enum, value_name = "ON|OFF")]
    pub(crate) shadows: Option<Switch>,
}

#[derive(Debug, Args)]
pub(crate) struct RenderArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    /// The image to write (atomically): .png or .ppm. With --explain-pixel, the explanation's
    /// file instead (any name; standard output when omitted or -).
    #[arg(
        short,
        long,
        value_name = "PATH",
        required_unless_present = "explain_pixel"
    )]
    pub(crate) output: Option<PathBuf>,
    /// The image format, when the output's extension does not say.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub(crate) image_format: Option<ImageFormat>,
    #[command(flatten)]
    pub(crate) settings: TraceSettings,
    /// Floating-point precision of the whole calculation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub(crate) precision: Precision,
    /// Worker threads, 1 to 1024 (default: one per core). The image is the same for any number.
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub(crate) threads: Option<usize>,
    /// The tracer: packets of rays in SIMD lanes with queues per bounce (wide), or one ray at a
    /// time (scalar). The image is the same bytes by either; --explain-pixel is always scalar.
    #[arg(long, value_enum, default_value_t = crate::tracer::Engine::Wide)]
    pub(crate) engine: crate::tracer::Engine,
    /// Explain pixel X,Y (from the top-left corner, 0-based) step by step instead of writing
    /// the image: its rays, each hit solved as `phong solve` solves a ray problem.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub(crate) explain_pixel: Option<(u32, u32)>,
    /// Format of the explanation (text, markdown, latex, html or json).
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub(crate) format: Format,
    /// Language of the explanation and of the errors (json is language-neutral).
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    /// Print the number of rays traced and the time taken to stderr.
    #[arg(long)]
    pub(crate) stats: bool,
}

/// On or off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Switch {
    On,
    Off,
}
