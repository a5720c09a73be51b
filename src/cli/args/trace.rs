//! The arguments of the tracer's commands: `phong render`, `phong tradeoff` and `phong export-pov`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct TradeoffArgs {
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    #[arg(long, value_enum, value_delimiter = ',', default_value = "f32,f64")]
    pub(crate) precisions: Vec<Precision>,
    #[arg(long, value_delimiter = ',', value_name = "N,...", default_value = "1,2,3,5,10",
          value_parser = parse_level)]
    pub(crate) levels: Vec<u32>,
    #[arg(long, value_delimiter = ',', value_name = "W,...", value_parser = parse_fraction,
          default_value = "0,1/255,0.1")]
    pub(crate) min_weights: Vec<f64>,
    #[arg(long, value_delimiter = ',', value_name = "N,...", default_value = "1,4,16",
          value_parser = parse_samples)]
    pub(crate) samples: Vec<u32>,
    #[arg(long, value_name = "N", default_value_t = 3,
          value_parser = parse_runs)]
    pub(crate) runs: u32,
    #[arg(long, value_name = "N", default_value_t = 64, value_parser = parse_level)]
    pub(crate) reference_level: u32,
    #[arg(long, value_name = "N", default_value_t = 64, value_parser = parse_samples)]
    pub(crate) reference_samples: u32,
    #[arg(long, value_name = "E", value_parser = parse_fraction, default_value = "1/255")]
    pub(crate) budget: f64,
    #[arg(long, value_enum, default_value_t = crate::tradeoff::Metric::Rmse)]
    pub(crate) metric: crate::tradeoff::Metric,
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub(crate) size: Option<(u32, u32)>,
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub(crate) threads: Option<usize>,
    #[arg(long, value_enum, default_value_t = crate::tracer::Engine::Wide)]
    pub(crate) engine: crate::tracer::Engine,
    #[arg(long, value_enum, default_value_t = TradeoffFormat::Text)]
    pub(crate) format: TradeoffFormat,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_name = "PATH.svg")]
    pub(crate) plot: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum TradeoffFormat {
    Text,
    Json,
    Csv,
}

// `--samples` takes render's values, but its help says that only 1 can be exported
// (`help::trace::TraceHelp::ExportPovSamples`).
#[derive(Debug, Args)]
pub(crate) struct ExportPovArgs {
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) settings: TraceSettings,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

// The tracer's settings, each over the scene's `render` (or its default).
#[derive(Debug, Args)]
pub(crate) struct TraceSettings {
    #[arg(long, value_name = "N", value_parser = parse_level)]
    pub(crate) max_level: Option<u32>,
    #[arg(long, value_name = "W", value_parser = parse_fraction)]
    pub(crate) min_weight: Option<f64>,
    #[arg(long, value_name = "N", value_parser = parse_samples)]
    pub(crate) samples: Option<u32>,
    #[arg(long, value_enum, value_name = "ON|OFF")]
    pub(crate) shadows: Option<Switch>,
}

#[derive(Debug, Args)]
pub(crate) struct RenderArgs {
    #[arg(value_name = "SCENE")]
    pub(crate) scene: PathBuf,
    #[arg(
        short,
        long,
        value_name = "PATH",
        required_unless_present = "explain_pixel"
    )]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub(crate) image_format: Option<ImageFormat>,
    #[command(flatten)]
    pub(crate) settings: TraceSettings,
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub(crate) precision: Precision,
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub(crate) threads: Option<usize>,
    #[arg(long, value_enum, default_value_t = crate::tracer::Engine::Wide)]
    pub(crate) engine: crate::tracer::Engine,
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub(crate) explain_pixel: Option<(u32, u32)>,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub(crate) format: Format,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    #[arg(long)]
    pub(crate) stats: bool,
}

// On or off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Switch {
    On,
    Off,
}
