//! The arguments of the commands that write problems and documents: `phong solve`, `phong new`,
//! `phong moodle` and `phong schema`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct NewArgs {
    #[arg(long, value_enum)]
    pub(crate) kind: generate::Kind,
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub(crate) count: u32,
    #[arg(long, default_value_t = 1)]
    pub(crate) seed: u64,
    #[arg(short, long, value_name = "DIR")]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Args)]
pub(crate) struct MoodleArgs {
    #[arg(value_name = "FILE", required = true)]
    pub(crate) files: Vec<PathBuf>,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[arg(
        long,
        value_name = "NAME",
        default_value = "Cap. 4 - Modelos de Iluminação"
    )]
    pub(crate) category: String,
    #[arg(long, value_name = "FILE")]
    pub(crate) policy: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Args)]
pub(crate) struct SolveArgs {
    #[arg(required = true, value_name = "FILE")]
    pub(crate) files: Vec<PathBuf>,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub(crate) format: Format,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    #[arg(long, value_enum, default_value_t = ColorChoice::Auto)]
    pub(crate) color: ColorChoice,
    #[arg(long)]
    pub(crate) fragment: bool,
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub(crate) precision: Precision,
    #[arg(long, value_enum, default_value_t = Contents::Solution)]
    pub(crate) part: Contents,
    #[arg(long, value_name = "TEXT")]
    pub(crate) course: Option<String>,
    #[arg(long, value_name = "TEXT")]
    pub(crate) title: Option<String>,
    #[arg(long, value_name = "TEXT")]
    pub(crate) date: Option<String>,
    #[arg(long, value_name = "TEXT")]
    pub(crate) author: Option<String>,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct SchemaArgs {
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}
