//! The `phong` command line: parse the arguments, run the command, map the outcome to an exit
//! code (0 solved or right, 1 a checked answer is wrong, 2 bad input or usage). Output files are
//! written atomically.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::check;
use crate::core::Real;
use crate::generate;
use crate::problem::{self, ProblemError};
use crate::report;
use crate::report::file::{error_json, explain_file, solve_json};
use crate::report::lang::Lang;
use crate::tracer::output::ImageFormat;

/// Solve and explain the illumination exercises of Chapter 4 (Phong's model).
#[derive(Debug, Parser)]
#[command(name = "phong", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve problem files, printing every intermediate quantity with its equation.
    Solve(SolveArgs),
    /// Render a scene (a problem file with a camera) with the Whitted ray tracer, or explain
    /// one pixel of it step by step.
    Render(RenderArgs),
    /// Print the JSON Schema of the problem format.
    Schema(SchemaArgs),
    /// Write a scene as POV-Ray 3.7 SDL that computes the same model (for cross-checking),
    /// or say why POV-Ray cannot express it (exit 2).
    ExportPov(ExportPovArgs),
    /// Check an answer (or each file's answer key) and name the slips behind a wrong one.
    Check(CheckArgs),
    /// Grade a CSV of answers (student, exercise, answer): one verdict per row, a summary per exercise.
    Grade(GradeArgs),
    /// Write fresh problems with numbers friendly to hand calculation, each with its answer key.
    New(NewArgs),
    /// Measure what each tracer setting (precision, level, minimum weight, samples) costs in
    /// time and buys in accuracy against a reference render; name the fastest within a budget.
    Tradeoff(TradeoffArgs),
}

#[derive(Debug, Args)]
pub struct TradeoffArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub scene: PathBuf,
    /// Precisions to sweep.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "f32,f64")]
    pub precisions: Vec<Precision>,
    /// Maximum levels to sweep.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "N,...",
        default_value = "1,2,3,5,10"
    )]
    pub levels: Vec<u32>,
    /// Minimum weights to sweep (decimals or fractions such as 1/255).
    #[arg(long, value_delimiter = ',', value_name = "W,...", value_parser = parse_fraction,
          default_value = "0,1/255,0.1")]
    pub min_weights: Vec<f64>,
    /// Samples per pixel to sweep.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "N,...",
        default_value = "1,4,16"
    )]
    pub samples: Vec<u32>,
    /// Renders per setting; its time is their median.
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub runs: u32,
    /// The reference's maximum level (it is f64 with minimum weight 0).
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub reference_level: u32,
    /// The reference's samples per pixel.
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub reference_samples: u32,
    /// The error budget: which setting is the fastest with its error at most this?
    #[arg(long, value_name = "E", value_parser = parse_fraction, default_value = "1/255")]
    pub budget: f64,
    /// The error the budget and the Pareto front are judged by.
    #[arg(long, value_enum, default_value_t = crate::tradeoff::Metric::Rmse)]
    pub metric: crate::tradeoff::Metric,
    /// Render at this size instead of the camera's (quicker sweeps).
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Worker threads (default: one per core).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Format of the table.
    #[arg(long, value_enum, default_value_t = TradeoffFormat::Text)]
    pub format: TradeoffFormat,
    /// Write the table to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
    /// Write the plot of error against time (SVG) to this file.
    #[arg(long, value_name = "PATH.svg")]
    pub plot: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TradeoffFormat {
    Text,
    Json,
    Csv,
}

/// A number ≥ 0 written as a decimal or a fraction (1/255).
fn parse_fraction(s: &str) -> Result<f64, String> {
    match crate::check::answer::number(s) {
        Some(x) if x >= 0.0 => Ok(x),
        _ => Err(format!(
            "{s:?} is not a number ≥ 0; write a decimal (0.05) or a fraction (1/255)"
        )),
    }
}

/// WxH, each 1 to the largest image side.
fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let max = crate::problem::model::MAX_IMAGE_SIDE;
    let parsed = s
        .split_once(['x', '×'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)));
    match parsed {
        Some((w, h)) if (1..=max).contains(&w) && (1..=max).contains(&h) => Ok((w, h)),
        _ => Err(format!(
            "{s:?} is not a size; write WIDTHxHEIGHT, each 1 to {max} (e.g. 320x240)"
        )),
    }
}

#[derive(Debug, Args)]
pub struct ExportPovArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub scene: PathBuf,
    /// Write the SDL to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
    /// The tracer's settings over the scene's (POV-Ray can only match 1 sample per pixel).
    #[command(flatten)]
    pub settings: TraceSettings,
}

/// The tracer's settings, each over the scene's `render` (or its default).
#[derive(Debug, Args)]
pub struct TraceSettings {
    /// The maximum recursion level (primary rays are level 1) [scene's, or 5].
    #[arg(long, value_name = "N")]
    pub max_level: Option<u32>,
    /// The minimum weight of a reflection ray [scene's, or 1/255].
    #[arg(long, value_name = "W")]
    pub min_weight: Option<f64>,
    /// Samples per pixel, 1 to 4096, stratified and deterministic [scene's, or 1].
    #[arg(long, value_name = "N")]
    pub samples: Option<u32>,
    /// Shadow rays on or off [scene's, or on].
    #[arg(long, value_enum, value_name = "ON|OFF")]
    pub shadows: Option<Switch>,
}

#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The scene: a problem file with a "camera" and "surfaces".
    #[arg(value_name = "SCENE")]
    pub scene: PathBuf,
    /// The image to write (atomically): .png or .ppm. Required unless --explain-pixel.
    #[arg(
        short,
        long,
        value_name = "PATH",
        required_unless_present = "explain_pixel"
    )]
    pub output: Option<PathBuf>,
    /// The image format, when the output's extension does not say.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub image_format: Option<ImageFormat>,
    #[command(flatten)]
    pub settings: TraceSettings,
    /// Floating-point precision of the whole calculation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
    /// Worker threads (default: one per core). The image is the same for any number.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Explain pixel X,Y (from the top-left corner, 0-based) step by step instead of writing
    /// the image: its rays, each hit solved as `phong solve` solves a ray problem.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub explain_pixel: Option<(u32, u32)>,
    /// Format of the explanation.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Print the number of rays traced and the time taken to stderr.
    #[arg(long)]
    pub stats: bool,
}

/// On or off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Switch {
    On,
    Off,
}

fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s.split_once(',').ok_or_else(|| {
        format!("\"{s}\" is not X,Y (two whole numbers and a comma, e.g. 320,240)")
    })?;
    let int = |t: &str| {
        t.trim()
            .parse::<u32>()
            .map_err(|_| format!("\"{t}\" is not a pixel coordinate (a whole number ≥ 0)"))
    };
    Ok((int(x)?, int(y)?))
}

#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Problem files (JSON). Without --answer, each file's answer key is checked.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
    /// The answer to check: "0.52 0.03 0", "(0.52, 0.03, 0)", "[0.52; 0.03; 0]", "#RRGGBB", or
    /// three integers 0–255 with --scale 255. Only with one FILE.
    #[arg(long, value_name = "ANSWER", allow_hyphen_values = true)]
    pub answer: Option<String>,
    /// The answer's scale: 1 (components on [0, 1]) or 255 (8-bit integers). "#RRGGBB" is 255.
    #[arg(long, value_enum, default_value = "1")]
    pub scale: check::Scale,
    /// The largest difference accepted per channel, on the answer's scale [default: the key's
    /// own, else 0.005 on the 0–1 scale, 1 on the 255 scale].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading.
    #[arg(long)]
    pub strict: bool,
    /// Instead of checking an answer, list what each applicable slip (and pair) gives.
    #[arg(long, conflicts_with_all = ["answer", "format"])]
    pub slips: bool,
    /// Output format: text for people, json for scripts (stable field names, format_version).
    #[arg(long, value_enum, default_value_t = CheckFormat::Text)]
    pub format: CheckFormat,
    /// Language of the text output.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub lang: Lang,
    /// Write the output to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct GradeArgs {
    /// The submissions: a CSV file with the columns student, exercise, answer (a first row
    /// starting with "student" is a header).
    #[arg(value_name = "SUBMISSIONS")]
    pub submissions: PathBuf,
    /// The folder of exercise files: exercise "4.2" is DIR/4.2.json.
    #[arg(long, value_name = "DIR")]
    pub exercises: PathBuf,
    /// Report format: one CSV line per input row, or JSON with the rows and the summary.
    #[arg(long, value_enum, default_value_t = GradeFormat::Csv)]
    pub format: GradeFormat,
    /// The scale of answers that are not "#RRGGBB".
    #[arg(long, value_enum, default_value = "1")]
    pub scale: check::Scale,
    /// The largest difference accepted per channel [default: 0.005 on the 0–1 scale, 1 on 255].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading.
    #[arg(long)]
    pub strict: bool,
    /// Write the report to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
    /// Also write the summary per exercise as CSV to this file (atomically).
    #[arg(long, value_name = "PATH")]
    pub summary: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct NewArgs {
    /// The kind of problem.
    #[arg(long, value_enum)]
    pub kind: generate::Kind,
    /// How many problems.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub count: u32,
    /// The seed: the same seed, kind and count give the same files, byte for byte.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write each problem to DIR/KIND-SEED-I.json (atomically); without it, print them (one JSON
    /// document, or an array for several).
    #[arg(short, long, value_name = "DIR")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CheckFormat {
    Text,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum GradeFormat {
    Csv,
    Json,
}

#[derive(Debug, Args)]
pub struct SolveArgs {
    /// Problem files (JSON). Each is solved even when another one is bad.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
    /// Output format: text for people (a terminal), markdown, latex or html explanations for
    /// notes and course pages, json for scripts (stable field names, format_version).
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Language of the explanation (text, markdown, latex, html); json is language-neutral.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub lang: Lang,
    /// Colour in the text format: auto (on a terminal, unless NO_COLOR is set), always, never.
    #[arg(long, value_enum, default_value_t = ColorChoice::Auto)]
    pub color: ColorChoice,
    /// latex and html only: write the body without the preamble or page around it.
    #[arg(long)]
    pub fragment: bool,
    /// Floating-point precision of the whole calculation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
    /// Write the output to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct SchemaArgs {
    /// Write the schema to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub output: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Markdown,
    Latex,
    Html,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    /// Colour when writing to a terminal and NO_COLOR is not set.
    Auto,
    Always,
    Never,
}

pub use crate::core::Precision;

/// `--precision f32|f64`.
impl ValueEnum for Precision {
    fn value_variants<'a>() -> &'a [Self] {
        &[Precision::F32, Precision::F64]
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
    }
}

/// Exit code: everything solved (or every checked answer accepted).
pub const EXIT_OK: u8 = 0;
/// Exit code: a checked answer is wrong.
pub const EXIT_WRONG: u8 = 1;
/// Exit code: bad input (a file that cannot be read, parsed or validated) or bad usage.
pub const EXIT_BAD_INPUT: u8 = 2;

/// The program: parse the arguments and run.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    ExitCode::from(run(&cli))
}

/// Runs a parsed command line and returns the exit code.
pub fn run(cli: &Cli) -> u8 {
    match &cli.command {
        Command::Solve(args) => solve_command(args),
        Command::Render(args) => render_command(args),
        Command::Tradeoff(args) => tradeoff_command(args),
        Command::Schema(args) => {
            let mut text = problem::schema_json();
            text.push('\n');
            emit(args.output.as_deref(), &text)
        }
        Command::ExportPov(args) => export_pov_command(args),
        Command::Check(args) => check_command(args),
        Command::Grade(args) => grade_command(args),
        Command::New(args) => new_command(args),
    }
}

/// `phong export-pov`: the scene in f64 (POV-Ray computes in double), with the command line's
/// settings, as POV-Ray SDL; exit 2 when the file is bad or POV-Ray cannot express the scene.
fn export_pov_command(args: &ExportPovArgs) -> u8 {
    let run = || -> Result<String, ProblemError> {
        let path = &args.scene;
        let (_, mut problem) = problem::load::<f64>(path)?;
        apply_settings(&args.settings, &mut problem)?;
        crate::export::pov::export(&problem).map_err(|e| ProblemError::Invalid {
            path: path.clone(),
            field: e.what,
            message: format!("cannot be expressed in POV-Ray 3.7: {}", e.why),
            fix: e.fix,
        })
    };
    match run() {
        Ok(sdl) => emit(args.output.as_deref(), &sdl),
        Err(e) => {
            eprintln!("error: {e}");
            EXIT_BAD_INPUT
        }
    }
}

fn check_command(args: &CheckArgs) -> u8 {
    if args.answer.is_some() && args.files.len() > 1 {
        eprintln!(
            "error: --answer checks one file, and {} were given. Fix: check one file at a time, \
             or put each file's answer in its \"answer\" field and leave out --answer",
            args.files.len()
        );
        return EXIT_BAD_INPUT;
    }
    if let Some(t) = args.tolerance {
        if let Err(e) = check::answer::check_tolerance(t) {
            eprintln!("error: --tolerance: {e}");
            return EXIT_BAD_INPUT;
        }
    }
    if args.slips {
        return slips_command(args);
    }
    let options = check::CheckOptions {
        answer: args.answer.clone(),
        scale: args.scale,
        tolerance: args.tolerance,
        strict: args.strict,
    };
    let mut code = EXIT_OK;
    let mut text = String::new();
    let mut docs = Vec::new();
    for path in &args.files {
        let c = check::check_file(path, &options);
        code = code.max(c.exit_code());
        if let Err(f) = &c.outcome {
            eprintln!("error: {}", f.message);
        }
        match args.format {
            CheckFormat::Text => {
                if c.outcome.is_ok() {
                    text.push_str(&check::report::text(&c, args.lang));
                }
            }
            CheckFormat::Json => docs
                .push(serde_json::to_value(check::report::json(&c)).expect("a verdict serialises")),
        }
    }
    let out = match args.format {
        CheckFormat::Text => text,
        CheckFormat::Json => json_text(docs),
    };
    // Nothing could be checked: no empty output file.
    if out.is_empty() {
        return code;
    }
    code.max(emit(args.output.as_deref(), &out))
}

/// `phong check --slips`: what each applicable slip gives, for an instructor.
fn slips_command(args: &CheckArgs) -> u8 {
    let mut code = EXIT_OK;
    let mut text = String::new();
    for path in &args.files {
        let expected = problem::load::<f64>(path)
            .and_then(|(_, p)| check::Expected::of(&p).map_err(|e| e.at(path)));
        match expected {
            Ok(x) => text.push_str(&check::report::slips_text(
                &path.display().to_string(),
                &x,
                args.lang,
            )),
            Err(e) => {
                eprintln!("error: {e}");
                code = EXIT_BAD_INPUT;
            }
        }
    }
    if text.is_empty() {
        return code;
    }
    code.max(emit(args.output.as_deref(), &text))
}

fn grade_command(args: &GradeArgs) -> u8 {
    if let Some(t) = args.tolerance {
        if let Err(e) = check::answer::check_tolerance(t) {
            eprintln!("error: --tolerance: {e}");
            return EXIT_BAD_INPUT;
        }
    }
    if !args.exercises.is_dir() {
        eprintln!(
            "error: {}: --exercises: not a folder. Fix: give the folder that holds the exercise \
             files (exercise 4.2 is DIR/4.2.json)",
            args.exercises.display()
        );
        return EXIT_BAD_INPUT;
    }
    let options = check::grade::Options {
        exercises: args.exercises.clone(),
        scale: args.scale,
        tolerance: args.tolerance,
        strict: args.strict,
    };
    let report = match check::grade::grade_file(&args.submissions, &options) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return EXIT_BAD_INPUT;
        }
    };
    let body = match args.format {
        GradeFormat::Csv => check::grade::rows_csv(&report),
        GradeFormat::Json => {
            let mut s = serde_json::to_string_pretty(&report).expect("a report serialises");
            s.push('\n');
            s.into_bytes()
        }
    };
    let total =
        |f: fn(&check::grade::SummaryOut) -> usize| report.summary.iter().map(f).sum::<usize>();
    eprintln!(
        "graded {} rows: {} right, {} by the likely intended reading, {} wrong, {} invalid",
        report.rows.len(),
        total(|s| s.right),
        total(|s| s.reading),
        total(|s| s.wrong),
        total(|s| s.invalid)
    );
    let mut code = emit_bytes(args.output.as_deref(), &body);
    if let Some(p) = &args.summary {
        code = code.max(emit_bytes(Some(p), &check::grade::summary_csv(&report)));
    }
    code
}

fn new_command(args: &NewArgs) -> u8 {
    let problems = generate::generate(args.kind, args.count, args.seed);
    match &args.output {
        None => emit(None, &generate::text_of_all(&problems)),
        Some(dir) => {
            if let Err(e) = std::fs::create_dir_all(dir) {
                eprintln!("error: {}: cannot create the folder: {e}", dir.display());
                return EXIT_BAD_INPUT;
            }
            let mut code = EXIT_OK;
            for p in problems {
                let path = dir.join(&p.file_name);
                code = code.max(emit(Some(&path), &p.text()));
            }
            code
        }
    }
}

/// One JSON document, or an array for several, pretty-printed with a final newline.
fn json_text(mut docs: Vec<serde_json::Value>) -> String {
    let value = if docs.len() == 1 {
        docs.pop().expect("one document")
    } else {
        serde_json::Value::Array(docs)
    };
    let mut s = serde_json::to_string_pretty(&value).expect("JSON values serialise");
    s.push('\n');
    s
}

fn solve_command(args: &SolveArgs) -> u8 {
    if args.fragment && !matches!(args.format, Format::Latex | Format::Html) {
        eprintln!(
            "error: --fragment applies to --format latex and html only. Fix: drop --fragment, \
             or use --format latex or html"
        );
        return EXIT_BAD_INPUT;
    }
    let mut failed = false;
    let mut docs = Vec::new();
    let mut explanations = Vec::new();
    for path in &args.files {
        let result = match args.format {
            Format::Json => solve_json(path, args.precision).map(|v| docs.push(v)),
            _ => explain_file(path, args.precision, args.lang).map(|x| explanations.push(x)),
        };
        if let Err(e) = result {
            failed = true;
            eprintln!("error: {e}");
            if args.format == Format::Json {
                docs.push(error_json(path, &e));
            }
        }
    }
    // Every file rejected and no JSON error documents: nothing to write (an empty or
    // bodiless output file would look like a result).
    if failed && explanations.is_empty() && docs.is_empty() {
        return EXIT_BAD_INPUT;
    }
    let out = match args.format {
        Format::Text => {
            let color = use_color(args.color, args.output.is_some());
            explanations
                .iter()
                .map(|x| report::text::write_explanation(x, color))
                .collect::<Vec<_>>()
                .join("\n")
        }
        Format::Markdown => report::markdown::write_all(&explanations),
        Format::Latex => report::latex::write_all(
            &explanations,
            report::latex::LatexOptions {
                fragment: args.fragment,
            },
        ),
        Format::Html => report::html::write_all(
            &explanations,
            report::html::HtmlOptions {
                fragment: args.fragment,
            },
            args.lang,
        ),
        Format::Json => {
            let value = if docs.len() == 1 {
                docs.pop().expect("one document")
            } else {
                serde_json::Value::Array(docs)
            };
            let mut s = serde_json::to_string_pretty(&value).expect("JSON values serialise");
            s.push('\n');
            s
        }
    };
    let code = emit(args.output.as_deref(), &out);
    if failed {
        EXIT_BAD_INPUT
    } else {
        code
    }
}

fn render_command(args: &RenderArgs) -> u8 {
    let result = match args.precision {
        Precision::F32 => render_scene::<f32>(args),
        Precision::F64 => render_scene::<f64>(args),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            EXIT_BAD_INPUT
        }
    }
}

/// Applies the command line's settings over the scene's; an invalid one names its flag.
fn apply_settings<R: Real>(
    args: &TraceSettings,
    problem: &mut problem::Problem<R>,
) -> Result<(), ProblemError> {
    let overrides = problem::RenderOverrides {
        max_level: args.max_level,
        min_weight: args.min_weight,
        samples: args.samples,
        shadows: args.shadows.map(|sw| sw == Switch::On),
    };
    problem.render = problem.render.with(&overrides).map_err(flag)?;
    Ok(())
}

/// A setting refused by the library, named by its field: its flag is that name in kebab case.
fn flag(e: problem::Invalid) -> ProblemError {
    ProblemError::Usage {
        flag: format!("--{}", e.field.replace('_', "-")),
        message: e.message,
        fix: e.fix,
    }
}

fn render_scene<R: Real>(args: &RenderArgs) -> Result<u8, ProblemError> {
    let path = &args.scene;
    let started = std::time::Instant::now();
    let (mut problem, camera) = problem::load_scene::<R>(path)?;
    let loaded = started.elapsed();
    apply_settings(&args.settings, &mut problem)?;
    let image_format = match (&args.output, args.image_format) {
        (_, Some(f)) => Some(f),
        (Some(out), None) => {
            Some(
                ImageFormat::from_path(out).ok_or_else(|| ProblemError::Usage {
                    flag: "--output".into(),
                    message: format!("{} does not end in .png or .ppm", out.display()),
                    fix: "name the image *.png or *.ppm, or give --image-format png|ppm".into(),
                })?,
            )
        }
        (None, None) => None,
    };
    let pool = thread_pool(args.threads)?;
    let building = std::time::Instant::now();
    let scene = pool.install(|| crate::tracer::Scene::new(&problem));
    let built = building.elapsed();
    let file = path.display().to_string();

    if let Some((x, y)) = args.explain_pixel {
        if x >= camera.width || y >= camera.height {
            return Err(ProblemError::Usage {
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
        let e = crate::tracer::explain_pixel(&problem, &camera, &scene, x, y)
            .map_err(|e| e.at(path))?;
        let out = match args.format {
            Format::Markdown | Format::Latex | Format::Html => {
                return Err(ProblemError::Usage {
                    flag: "--format".into(),
                    message: "a pixel's explanation is written as text or json".into(),
                    fix: "give --format text or --format json with --explain-pixel".into(),
                })
            }
            Format::Text => report::pixel::render_text(&file, &problem, &e),
            Format::Json => {
                let doc = report::pixel::document(&file, &problem, &e);
                let mut s = serde_json::to_string_pretty(
                    &serde_json::to_value(doc).expect("the explanation serialises"),
                )
                .expect("JSON values serialise");
                s.push('\n');
                s
            }
        };
        return Ok(emit(args.output.as_deref(), &out));
    }

    let out = args.output.as_deref().expect("clap requires --output here");
    let bar = progress_bar(u64::from(camera.height));
    let tracing = std::time::Instant::now();
    let (image, counts) =
        pool.install(|| crate::tracer::render(&problem, &camera, &scene, &|| bar.inc(1)));
    bar.finish_and_clear();
    let traced = tracing.elapsed();
    let bytes = crate::tracer::output::encode(&image, image_format.expect("known format"));
    if let Err(e) = write_atomically(out, &bytes) {
        eprintln!("error: cannot write {}: {e}", out.display());
        return Ok(EXIT_BAD_INPUT);
    }
    if args.stats {
        let secs = traced.as_secs_f64();
        eprintln!(
            "{}×{}, {} sample(s)/pixel, {}, {} thread(s): read and validated in {:.3} s, BVH of \
             {} surfaces built in {:.3} s, traced {} rays ({} primary, {} reflection, {} shadow) \
             in {:.3} s: {:.2} Mrays/s",
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
            counts.total() as f64 / secs / 1e6
        );
    }
    Ok(EXIT_OK)
}

/// The worker threads: `threads`, or one per core.
fn thread_pool(threads: Option<usize>) -> Result<rayon::ThreadPool, ProblemError> {
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        if n == 0 {
            return Err(ProblemError::Usage {
                flag: "--threads".into(),
                message: "0 threads cannot render".into(),
                fix: "give --threads 1 or more (or leave it out: one per core)".into(),
            });
        }
        b = b.num_threads(n);
    }
    b.build().map_err(|e| ProblemError::Usage {
        flag: "--threads".into(),
        message: format!("cannot start the worker threads: {e}"),
        fix: "give fewer --threads".into(),
    })
}

fn tradeoff_command(args: &TradeoffArgs) -> u8 {
    match tradeoff_run(args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            EXIT_BAD_INPUT
        }
    }
}

fn tradeoff_run(args: &TradeoffArgs) -> Result<u8, ProblemError> {
    use crate::tradeoff::{self, report, ReferenceSettings, Scenes, Sweep};
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
    .map_err(flag)?;
    if let Some(plot) = &args.plot {
        if !plot
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"))
        {
            return Err(ProblemError::Usage {
                flag: "--plot".into(),
                message: format!("{} does not end in .svg", plot.display()),
                fix: "name the plot *.svg (it is written as SVG)".into(),
            });
        }
    }
    fn load<R: Real>(
        path: &Path,
        size: Option<(u32, u32)>,
    ) -> Result<(problem::Problem<R>, problem::Camera<R>), ProblemError> {
        let (p, mut camera) = problem::load_scene::<R>(path)?;
        if let Some((w, h)) = size {
            camera.width = w;
            camera.height = h;
        }
        Ok((p, camera))
    }
    let f64_scene = load::<f64>(&args.scene, args.size)?;
    let f32_scene = if args.precisions.contains(&Precision::F32) {
        Some(load::<f32>(&args.scene, args.size)?)
    } else {
        None
    };
    let pool = thread_pool(args.threads)?;
    let total = 1 + sweep.settings().len() as u64 * u64::from(sweep.runs);
    let bar = progress_bar(total);
    let outcome = pool
        .install(|| tradeoff::measure(Scenes::new(f64_scene, f32_scene), &sweep, &|_| bar.inc(1)));
    bar.finish_and_clear();
    let file = args.scene.display().to_string();
    let summary = report::Summary::new(&file, &outcome, args.metric, args.budget);
    if let Some(plot) = &args.plot {
        let svg = tradeoff::plot::svg(&summary).map_err(|e| ProblemError::Usage {
            flag: "--plot".into(),
            message: format!("the plot could not be drawn: {e}"),
            fix: "report this as a bug; the table is still written without --plot".into(),
        })?;
        if let Err(e) = write_atomically(plot, svg.as_bytes()) {
            eprintln!("error: cannot write {}: {e}", plot.display());
            return Ok(EXIT_BAD_INPUT);
        }
    }
    let text = match args.format {
        TradeoffFormat::Text => report::text(&summary),
        TradeoffFormat::Json => json_text(vec![report::json(&summary)]),
        TradeoffFormat::Csv => report::csv(&summary),
    };
    Ok(emit(args.output.as_deref(), &text))
}

/// A progress bar on stderr when it is a terminal; hidden otherwise (and under CI).
fn progress_bar(rows: u64) -> indicatif::ProgressBar {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(rows);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("rendering {bar:40} {pos}/{len} rows {elapsed}")
    {
        bar.set_style(style);
    }
    bar
}

/// Whether the text report is coloured: `always`, `never`, or for `auto` when writing to a
/// terminal (not a file or a pipe), NO_COLOR is unset or empty (no-color.org) and TERM is not
/// "dumb".
fn use_color(choice: ColorChoice, to_file: bool) -> bool {
    use std::io::IsTerminal;
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => {
            let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
            let dumb = std::env::var_os("TERM").is_some_and(|t| t == "dumb");
            !to_file && !no_color && !dumb && std::io::stdout().is_terminal()
        }
    }
}

/// Writes the output to stdout, or atomically to a file (a temporary file in the same folder,
/// renamed into place), so that a failure never leaves a half-written file.
fn emit(path: Option<&Path>, text: &str) -> u8 {
    emit_bytes(path, text.as_bytes())
}

fn emit_bytes(path: Option<&Path>, bytes: &[u8]) -> u8 {
    let result = match path {
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes).and_then(|_| out.flush())
        }
        Some(p) => write_atomically(p, bytes),
    };
    match result {
        Ok(()) => EXIT_OK,
        // A closed pipe (`phong solve … | head`) is not an error of ours.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => EXIT_OK,
        Err(e) => {
            let what = path.map_or("standard output".into(), |p| p.display().to_string());
            eprintln!("error: cannot write {what}: {e}");
            EXIT_BAD_INPUT
        }
    }
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
    tmp.write_all(bytes)?;
    // A temporary file is private (0600); the result should have an ordinary file's mode.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map_or(0o644, |m| m.permissions().mode());
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))?;
    }
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
