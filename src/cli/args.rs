//! The command line's definition: every subcommand, flag, default and help text, as clap's
//! derive types. What a value is read as (`1/255`, `320x240`, `X,Y`, `f32`) is in
//! [`super::parse`]; what a command does with its arguments, in [`super::commands`].

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

use super::parse::{
    parse_delimiter, parse_fraction, parse_level, parse_pixel, parse_runs, parse_samples,
    parse_size, parse_threads, parse_tolerance,
};
use crate::check;
use crate::core::Precision;
use crate::generate;
use crate::report::document::Contents;
use crate::report::lang::Lang;
use crate::tracer::output::ImageFormat;

/// Solve and explain the illumination exercises of Chapter 4 (Phong's model).
#[derive(Debug, Parser)]
#[command(name = "phong", version, about, long_about = None)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
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
    /// Write problem files (or what `phong new` prints, `-` for standard input) as a Moodle XML
    /// quiz: one Cloze question per problem, the slips as 0 % answers, the solution as feedback.
    Moodle(MoodleArgs),
    /// Measure what each tracer setting (precision, level, minimum weight, samples) costs in
    /// time and buys in accuracy against a reference render; name the fastest within a budget.
    Tradeoff(TradeoffArgs),
}

impl Command {
    /// The language the command's messages (its errors included) are written in: `--lang`
    /// where the command has it, else English.
    pub fn lang(&self) -> Lang {
        match self {
            Command::Solve(a) => a.lang,
            Command::Render(a) => a.lang,
            Command::Check(a) => a.lang,
            Command::Moodle(a) => a.lang,
            Command::New(a) => a.lang,
            _ => Lang::En,
        }
    }
}

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
    /// Format of the table.
    #[arg(long, value_enum, default_value_t = TradeoffFormat::Text)]
    pub(crate) format: TradeoffFormat,
    /// Write the table to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// Write the plot of error against time (SVG) to this file.
    #[arg(long, value_name = "PATH.svg")]
    pub(crate) plot: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum TradeoffFormat {
    Text,
    Json,
    Csv,
}

#[derive(Debug, Args)]
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
    /// The image to write (atomically): .png or .ppm. Required unless --explain-pixel.
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
    #[arg(long, value_enum, default_value_t = Lang::En)]
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

#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// Problem files (JSON). Without --answer, each file's answer key is checked.
    #[arg(required = true, value_name = "FILE")]
    pub(crate) files: Vec<PathBuf>,
    /// The answer to check: "0.52 0.03 0", "(0.52, 0.03, 0)", "[0.52; 0.03; 0]", "#RRGGBB", or
    /// three integers 0–255 with --scale 255. Only with one FILE.
    #[arg(long, value_name = "ANSWER", allow_hyphen_values = true)]
    pub(crate) answer: Option<String>,
    /// The answer's scale: 1 (components on [0, 1]) or 255 (8-bit integers). "#RRGGBB" is 255.
    #[arg(long, value_enum, default_value = "1")]
    pub(crate) scale: check::Scale,
    /// The largest difference accepted per channel, on the answer's scale [default: the key's
    /// own, else 0.005 on the 0–1 scale, 1 on the 255 scale].
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading.
    #[arg(long)]
    pub(crate) strict: bool,
    /// Check an intermediate step, NAME=VALUE (repeatable): cos_theta=0.98995, R=0.6,0,0.8,
    /// cos_theta[1]=0.5 for lights[1]. Names: t, P, N, V, I_a, ambient, L, d, falloff_factor,
    /// cos_psi, spot_factor, I_l, n_dot_l, cos_theta, diffuse, R, cos_phi, cos_phi_pow,
    /// specular, total_diffuse, total_specular, I. Only with one FILE.
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub(crate) step: Vec<String>,
    /// Check the steps in a JSON file: {"cos_theta": 0.98995, "R": [0.6, 0, 0.8]}. Only with
    /// one FILE.
    #[arg(long, value_name = "STEPS.json")]
    pub(crate) steps: Option<PathBuf>,
    /// Instead of checking an answer, list what each applicable slip (and pair) gives.
    #[arg(long, conflicts_with_all = ["answer", "format", "step", "steps"])]
    pub(crate) slips: bool,
    /// Output format: text for people, json for scripts (stable field names, format_version).
    #[arg(long, value_enum, default_value_t = CheckFormat::Text)]
    pub(crate) format: CheckFormat,
    /// Language of the text output.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub(crate) lang: Lang,
    /// Write the output to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct GradeArgs {
    /// The submissions: a CSV file (or - for standard input) with the columns student,
    /// exercise, answer, separated by commas, semicolons or tabs; a first row that names the
    /// three columns (student|aluno|estudante, exercise|exercicio|questao, answer|resposta) is a
    /// header.
    #[arg(value_name = "SUBMISSIONS")]
    pub(crate) submissions: PathBuf,
    /// The separator of the submissions' fields: `,`, `;` or `tab` [default: detected from the
    /// first rows].
    #[arg(long, value_name = "SEP", value_parser = parse_delimiter)]
    pub(crate) delimiter: Option<u8>,
    /// The folder of exercise files: exercise "4.2" is DIR/4.2.json.
    #[arg(long, value_name = "DIR")]
    pub(crate) exercises: PathBuf,
    /// Report format: one CSV line per input row, or JSON with the rows and the summary.
    #[arg(long, value_enum, default_value_t = GradeFormat::Csv)]
    pub(crate) format: GradeFormat,
    /// The scale of answers that are not "#RRGGBB".
    #[arg(long, value_enum, default_value = "1")]
    pub(crate) scale: check::Scale,
    /// The largest difference accepted per channel [default: each exercise key's own, else
    /// 0.005 on the 0–1 scale, 1 on the 255 scale].
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading.
    #[arg(long)]
    pub(crate) strict: bool,
    /// Write the report to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// Also write the summary per exercise as CSV to this file (atomically).
    #[arg(long, value_name = "PATH")]
    pub(crate) summary: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct NewArgs {
    /// The kind of problem.
    #[arg(long, value_enum)]
    pub(crate) kind: generate::Kind,
    /// How many problems.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub(crate) count: u32,
    /// The seed: the same seed, kind and count give the same files, byte for byte.
    #[arg(long, default_value_t = 1)]
    pub(crate) seed: u64,
    /// Write each problem to DIR/KIND-SEED-I.json (atomically); without it, print them (one JSON
    /// document, or an array for several).
    #[arg(short, long, value_name = "DIR")]
    pub(crate) output: Option<PathBuf>,
    /// With pt, each problem has its title and question in Portuguese too (`title_pt`,
    /// `question_pt`), for `--lang pt` in solve, check and moodle.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Args)]
pub(crate) struct MoodleArgs {
    /// Problem files, each a problem or an array of problems; `-` is standard input.
    #[arg(value_name = "FILE", required = true)]
    pub(crate) files: Vec<PathBuf>,
    /// Write the quiz to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// The question bank's category holding one sub-category per file.
    #[arg(
        long,
        value_name = "NAME",
        default_value = "Cap. 4 - Modelos de Iluminação"
    )]
    pub(crate) category: String,
    /// Language of the questions, the feedback and the worked solutions.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub(crate) lang: Lang,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum CheckFormat {
    Text,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum GradeFormat {
    Csv,
    Json,
}

#[derive(Debug, Args)]
pub(crate) struct SolveArgs {
    /// Problem files (JSON). Each is solved even when another one is bad.
    #[arg(required = true, value_name = "FILE")]
    pub(crate) files: Vec<PathBuf>,
    /// Output format: text for people (a terminal), markdown, latex or html explanations for
    /// notes and course pages, json for scripts (stable field names, format_version).
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub(crate) format: Format,
    /// Language of the explanation (text, markdown, latex, html); json is language-neutral.
    #[arg(long, value_enum, default_value_t = Lang::En)]
    pub(crate) lang: Lang,
    /// Colour in the text format: auto (on a terminal, unless NO_COLOR is set), always, never.
    #[arg(long, value_enum, default_value_t = ColorChoice::Auto)]
    pub(crate) color: ColorChoice,
    /// latex and html only: write the body without the preamble or page around it.
    #[arg(long)]
    pub(crate) fragment: bool,
    /// Floating-point precision of the whole calculation.
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub(crate) precision: Precision,
    /// Which document: statement (the student's handout: numbered statements, the data as a
    /// table), solution (the worked solutions), key (one answer-key table), or all three.
    #[arg(long, value_enum, default_value_t = Contents::Solution)]
    pub(crate) part: Contents,
    /// The problem set's course, printed in its header.
    #[arg(long, value_name = "TEXT")]
    pub(crate) course: Option<String>,
    /// The problem set's title, printed in its header (and the HTML page's title).
    #[arg(long, value_name = "TEXT")]
    pub(crate) title: Option<String>,
    /// The problem set's date, printed in its header as given.
    #[arg(long, value_name = "TEXT")]
    pub(crate) date: Option<String>,
    /// The problem set's author, printed in its header.
    #[arg(long, value_name = "TEXT")]
    pub(crate) author: Option<String>,
    /// Write the output to this file (atomically) instead of standard output; a folder (an
    /// existing one, or a path ending in /) gets one file per exercise, named after it.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub(crate) struct SchemaArgs {
    /// Write the schema to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Format {
    Text,
    Markdown,
    Latex,
    Html,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ColorChoice {
    /// Colour when writing to a terminal and NO_COLOR is not set.
    Auto,
    Always,
    Never,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn numeric_flags_are_parsed_or_refused_never_a_panic() {
        // Moved from tests/fuzz.rs: the argument types are the crate's own (the binary's edge).
        use clap::Parser;
        use proptest::prelude::*;
        use proptest::sample::select;
        use proptest::test_runner::{Config, RngSeed, TestRunner};
        let value = prop_oneof![
            Just("0".to_owned()),
            Just("1".to_owned()),
            Just("4096".to_owned()),
            Just("4097".to_owned()),
            Just("1000".to_owned()),
            Just("1001".to_owned()),
            Just("4294967295".to_owned()),
            Just("4294967296".to_owned()),
            Just("18446744073709551616".to_owned()),
            Just("-1".to_owned()),
            Just("1e400".to_owned()),
            Just("1/255".to_owned()),
            Just("nan".to_owned()),
            Just("\u{2212}1".to_owned()),
            Just("64x48".to_owned()),
            Just("16384x16384".to_owned()),
            "[0-9x,./e\\-]{0,12}",
        ];
        let flag = select(vec![
            ("render", "--max-level"),
            ("render", "--samples"),
            ("render", "--threads"),
            ("render", "--min-weight"),
            ("render", "--explain-pixel"),
            ("tradeoff", "--runs"),
            ("tradeoff", "--levels"),
            ("tradeoff", "--samples"),
            ("tradeoff", "--reference-level"),
            ("tradeoff", "--reference-samples"),
            ("tradeoff", "--threads"),
            ("tradeoff", "--size"),
            ("tradeoff", "--budget"),
            ("tradeoff", "--min-weights"),
            ("check", "--tolerance"),
            ("grade", "--tolerance"),
            ("new", "--count"),
        ]);
        TestRunner::new(Config {
            cases: 400,
            rng_seed: RngSeed::Fixed(43),
            failure_persistence: None,
            ..Config::default()
        })
        .run(&(flag, value), |((command, flag), value)| {
            let mut args = vec!["phong", command, "x.json"];
            match command {
                "render" => args.extend(["-o", "x.png"]),
                "grade" => args.extend(["--exercises", "."]),
                "new" => args = vec!["phong", "new", "--kind", "point"],
                _ => {}
            }
            args.push(flag);
            args.push(&value);
            if let Ok(Cli { command, .. }) = Cli::try_parse_from(&args) {
                // What clap accepts is within the documented ranges.
                if let Command::Render(r) = &command {
                    prop_assert!(r.settings.max_level.is_none_or(|l| (1..=1000).contains(&l)));
                    prop_assert!(r.settings.samples.is_none_or(|n| (1..=4096).contains(&n)));
                    prop_assert!(r.threads.is_none_or(|n| (1..=1024).contains(&n)));
                    prop_assert!(r.settings.min_weight.is_none_or(f64::is_finite));
                }
                if let Command::Tradeoff(t) = &command {
                    prop_assert!((1..=1000).contains(&t.runs));
                    prop_assert!(t.levels.iter().all(|l| (1..=1000).contains(l)));
                    prop_assert!(t.budget.is_finite());
                }
                if let Command::Check(c) = &command {
                    prop_assert!(c.tolerance.is_none_or(f64::is_finite));
                }
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    }
}
