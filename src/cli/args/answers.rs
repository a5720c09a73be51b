//! The arguments of the commands that judge answers: `phong check` and `phong grade`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    #[arg(required = true, value_name = "FILE")]
    pub(crate) files: Vec<PathBuf>,
    #[arg(long, value_name = "ANSWER", allow_hyphen_values = true)]
    pub(crate) answer: Option<String>,
    #[arg(long, value_enum)]
    pub(crate) scale: Option<check::Scale>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    #[arg(long)]
    pub(crate) strict: bool,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub(crate) step: Vec<String>,
    #[arg(long, value_name = "STEPS.json")]
    pub(crate) steps: Option<PathBuf>,
    #[arg(long, conflicts_with_all = ["answer", "format", "step", "steps"])]
    pub(crate) slips: bool,
    #[arg(long, value_enum, default_value_t = check::output::Format::Text)]
    pub(crate) format: check::output::Format,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct GradeArgs {
    #[arg(value_name = "SUBMISSIONS")]
    pub(crate) submissions: PathBuf,
    #[arg(long, value_name = "SEP", value_parser = parse_delimiter)]
    pub(crate) delimiter: Option<u8>,
    #[arg(long, value_name = "DIR")]
    pub(crate) exercises: PathBuf,
    #[arg(long, value_enum, default_value_t = GradeFormat::Csv)]
    pub(crate) format: GradeFormat,
    #[arg(long, value_enum)]
    pub(crate) scale: Option<check::Scale>,
    #[arg(long, value_name = "EX=P,...")]
    pub(crate) points: Option<String>,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    #[arg(long, value_name = "SHARE", value_parser = parse_share)]
    pub(crate) reading_credit: Option<f64>,
    #[arg(long, value_enum)]
    pub(crate) duplicates: Option<check::policy::Duplicates>,
    #[arg(long, value_name = "PATH")]
    pub(crate) by_student: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    #[arg(long, value_enum, default_value_t = check::grade::Input::Auto)]
    pub(crate) input: check::grade::Input,
    #[arg(long, value_name = "EX,...", value_delimiter = ',')]
    pub(crate) questions: Vec<String>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    #[arg(long)]
    pub(crate) strict: bool,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_name = "PATH.html")]
    pub(crate) class_report: Option<PathBuf>,
    #[arg(long, value_name = "PATH")]
    pub(crate) summary: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum GradeFormat {
    Csv,
    Json,
    Gradescope,
    Junit,
    Xlsx,
}

// `--policy`: the course policy file, for every command that judges answers.
#[derive(Debug, Args)]
pub(crate) struct PolicyArg {
    #[arg(long, value_name = "FILE", alias = "rubric")]
    pub(crate) policy: Option<PathBuf>,
}

// `phong policy`: the course policy in force.
#[derive(Debug, Args)]
pub(crate) struct PolicyCmdArgs {
    #[arg(value_name = "DIR")]
    pub(crate) folder: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}
