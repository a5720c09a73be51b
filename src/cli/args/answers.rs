//! The arguments of the commands that judge answers: `phong check` and `phong grade`.

use super::*;

#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// Problem files (JSON). Without --answer, each file's answer key is checked.
    #[arg(required = true, value_name = "FILE")]
    pub(crate) files: Vec<PathBuf>,
    /// The answer to check: "0.52 0.03 0", "(0.52, 0.03, 0)", "[0.52; 0.03; 0]", "#RRGGBB", or
    /// three integers 0–255 with --scale 255. Only with one FILE.
    #[arg(long, value_name = "ANSWER", allow_hyphen_values = true)]
    pub(crate) answer: Option<String>,
    /// The answer's scale: 1 (components on [0, 1]) or 255 (8-bit integers). "#RRGGBB" is 255
    /// [default: 1, but three whole numbers 0–255, one above 1, are read as 8-bit values
    /// unless the course policy says "eight_bit": "hint"].
    #[arg(long, value_enum)]
    pub(crate) scale: Option<check::Scale>,
    /// The largest difference accepted per channel, on the answer's scale [default: the key's
    /// own, else the course policy's: 0.005 on the 0–1 scale, 1 on the 255 scale].
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading (over the course
    /// policy's "strict").
    #[arg(long)]
    pub(crate) strict: bool,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    /// Check an intermediate step, NAME=VALUE (repeatable): cos_theta=0.98995, R=0.6,0,0.8,
    /// cos_theta\[1\]=0.5 for lights\[1\]. Names: t, P, N, V, I_a, ambient, L, d, falloff_factor,
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
    /// Output format: text for people, json for scripts (stable field names, format_version),
    /// html for a browser (the colours as swatches, each slip linked to its step of the worked
    /// solution), markdown for notes.
    #[arg(long, value_enum, default_value_t = check::output::Format::Text)]
    pub(crate) format: check::output::Format,
    /// Language of the text output.
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
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
    /// header, and may name a fourth, steps|passos, of step answers such as "cos_theta=0.98995;
    /// n_dot_l=-0.98995" (judged as check --step judges them; they change no points).
    #[arg(value_name = "SUBMISSIONS")]
    pub(crate) submissions: PathBuf,
    /// The separator of the submissions' fields: `,`, `;` or `tab` [default: detected from the
    /// first rows].
    #[arg(long, value_name = "SEP", value_parser = parse_delimiter)]
    pub(crate) delimiter: Option<u8>,
    /// The folder of exercise files: exercise "4.2" is DIR/4.2.json.
    #[arg(long, value_name = "DIR")]
    pub(crate) exercises: PathBuf,
    /// Report format: one CSV line per input row; JSON with the rows, the summary and the
    /// students' totals; Gradescope's results.json (one student: the file; several: an object
    /// keyed by student, or one file per student with -o DIR/); JUnit XML (a testsuite per
    /// student, a testcase per exercise); xlsx, a workbook for Excel or LibreOffice (sheets of the
    /// answers, the students' totals and a summary; numbers as numbers, headers in --lang; give
    /// -o FILE.xlsx).
    #[arg(long, value_enum, default_value_t = GradeFormat::Csv)]
    pub(crate) format: GradeFormat,
    /// The scale of answers that are not "#RRGGBB" [default: 0–1, but a row of three whole
    /// numbers 0–255, one above 1, is read as 8-bit, and its feedback says so, unless the
    /// course policy says "eight_bit": "hint"].
    #[arg(long, value_enum)]
    pub(crate) scale: Option<check::Scale>,
    /// Points per exercise, e.g. 4.1=1,4.2=2 (over the course policy's) [default: the
    /// policy's, else 1 each].
    #[arg(long, value_name = "EX=P,...")]
    pub(crate) points: Option<String>,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    /// The share of an exercise's points an answer in its likely intended reading earns, 0 to 1
    /// (over the course policy's) [default: the policy's, else 0.5; nothing under --strict].
    #[arg(long, value_name = "SHARE", value_parser = parse_share)]
    pub(crate) reading_credit: Option<f64>,
    /// Which answer counts when a student answers an exercise more than once (the others stay
    /// in the report with counted false) [default: the course policy's, else last].
    #[arg(long, value_enum)]
    pub(crate) duplicates: Option<check::policy::Duplicates>,
    /// Also write each student's total as CSV to this file (student, points, max_points, then
    /// one column per exercise).
    #[arg(long, value_name = "PATH")]
    pub(crate) by_student: Option<PathBuf>,
    /// Language of the feedback column and of the platforms' reports.
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
    /// What the submissions are: the plain CSV, or Moodle's quiz Responses report downloaded
    /// as CSV ("Response 1", …; Cloze parts "part 1: …; part 2: …; part 3: …") [default:
    /// detected from the header].
    #[arg(long, value_enum, default_value_t = check::grade::Input::Auto)]
    pub(crate) input: check::grade::Input,
    /// A Moodle export's question slots, in order: slot N is the N-th exercise [default: the
    /// exercise files of --exercises in name order].
    #[arg(long, value_name = "EX,...", value_delimiter = ',')]
    pub(crate) questions: Vec<String>,
    /// The largest difference accepted per channel [default: each exercise key's own, else the
    /// course policy's: 0.005 on the 0–1 scale, 1 on the 255 scale].
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_tolerance)]
    pub(crate) tolerance: Option<f64>,
    /// Accept only the problem as written, not its likely intended reading (over the course
    /// policy's "strict").
    #[arg(long)]
    pub(crate) strict: bool,
    /// Write the report to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// Also write what the class got wrong as a page (HTML, in --lang): per exercise, the
    /// answers right, by the reading, each slip named with its count, the unnamed wrong ones and
    /// the unreadable ones, and a histogram of the students' totals.
    #[arg(long, value_name = "PATH.html")]
    pub(crate) class_report: Option<PathBuf>,
    /// Also write the summary per exercise as CSV to this file (atomically).
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

/// `--policy`: the course policy file, for every command that judges answers.
#[derive(Debug, Args)]
pub(crate) struct PolicyArg {
    /// The course policy (JSON: tolerances, the reading's credit, 8-bit answers, the words for
    /// "no hit", points; docs/course-policy.md) [default: course-policy.json in the exercises'
    /// folder, else the defaults].
    #[arg(long, value_name = "FILE", alias = "rubric")]
    pub(crate) policy: Option<PathBuf>,
}

/// `phong policy`: the course policy in force.
#[derive(Debug, Args)]
pub(crate) struct PolicyCmdArgs {
    /// The exercises' folder whose course-policy.json is read [default: the current folder].
    #[arg(value_name = "DIR")]
    pub(crate) folder: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) policy: PolicyArg,
    /// Write the policy to this file (atomically) instead of standard output.
    #[arg(short, long, value_name = "PATH")]
    pub(crate) output: Option<PathBuf>,
    /// Language of the errors (the policy file is the same in either).
    /// [default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, else en]
    #[arg(long, value_enum, default_value_t = Lang::from_locale(), hide_default_value = true)]
    pub(crate) lang: Lang,
}
