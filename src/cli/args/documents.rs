//! The arguments of the commands that write problems and documents: `phong solve`, `phong new`,
//! `phong moodle` and `phong schema`.

use super::*;

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
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
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
    /// The course policy the quiz grades by (tolerances, the reading's credit, 8-bit answers,
    /// the words for "no hit") [default: course-policy.json beside the first FILE, else the
    /// defaults].
    #[arg(long, value_name = "FILE")]
    pub(crate) policy: Option<PathBuf>,
    /// Language of the questions, the feedback and the worked solutions.
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
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
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
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
    /// Language of the errors (the schema is the same in either).
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}
