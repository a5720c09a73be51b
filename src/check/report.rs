//! The verdict of `phong check` for people (text, English or Portuguese) and for scripts (stable
//! JSON, [`CHECK_FORMAT_VERSION`]). Field names are part of the interface: renaming or removing
//! one bumps the version; adding one does not.

use std::fmt::Write;

use serde::Serialize;

use super::matches::{expected_line, matches, ExpectedLine, Layout, Match};
use super::messages::{self, Line};
use super::{Answer, Candidate, Comparison, Scale, Verdict, VerdictKind};
use crate::problem::ProblemError;
use crate::solve::ReadingCode;
use crate::text::lang::Lang;
use crate::text::number::num;
use crate::text::Message;

/// The version of the JSON output of `phong check` and `phong grade`.
pub const CHECK_FORMAT_VERSION: u32 = 1;

/// Where the answer came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AnswerSource {
    /// `--answer` (or a CSV row).
    Argument,
    /// The problem file's `answer` field.
    Key,
}

/// One checked answer, or why it could not be checked.
#[derive(Clone, Debug)]
pub struct Checked {
    /// The problem file's path, as given.
    pub file: String,
    /// The answer as written, when there is one.
    pub text: Option<String>,
    /// Where the answer came from.
    pub source: AnswerSource,
    /// The judged answer, or why it could not be checked.
    pub outcome: Result<Judged, Failure>,
    /// Likely unit mistakes in the problem file (never errors).
    pub warnings: Vec<crate::problem::warnings::Warning>,
}

/// An answer that could be checked: the answer read, the tolerance it was judged under, and
/// the verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Judged {
    /// The answer, read.
    pub answer: Answer,
    /// The largest difference accepted per channel, on the answer's scale.
    pub tolerance: f64,
    /// The share of the exercise's points the verdict earns under the course policy.
    pub credit: f64,
    /// The answer's numbers, written without a scale, were read as 8-bit values.
    pub as_8bit: bool,
    /// The course policy's file; `None` for the defaults.
    pub policy: Option<std::path::PathBuf>,
    /// The verdict, with the comparisons and the diagnosis behind it.
    pub verdict: Verdict,
}

/// Why an answer could not be checked.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Failure {
    /// What could not be checked (`error.kind` in the JSON).
    pub kind: FailureKind,
    /// The field of the problem file at fault, where there is one (`lights[1].falloff`).
    pub field: Option<String>,
    /// The error, with its fix: rendered in a language where it is shown; the JSON has it in
    /// English.
    pub message: Said,
}

impl Failure {
    /// A problem file that cannot be read, parsed, validated or solved.
    pub(crate) fn problem(e: ProblemError) -> Self {
        Failure {
            kind: FailureKind::of(&e),
            field: e.field().map(str::to_owned),
            message: Said::new(e),
        }
    }
}

pub use crate::text::Said;

/// What could not be checked, as the JSON's `error.kind` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FailureKind {
    /// The problem file cannot be read.
    Read,
    /// The problem file is not a problem file's JSON.
    Syntax,
    /// The problem the file states is invalid (or cannot be solved).
    Invalid,
    /// A setting is out of range.
    Usage,
    /// The answer (given, or the file's key) cannot be read.
    Answer,
    /// No answer was given and the file has no key.
    NoAnswer,
}

impl FailureKind {
    /// The kind of a problem file's error.
    pub(crate) fn of(e: &ProblemError) -> Self {
        match e {
            ProblemError::Read { .. } => FailureKind::Read,
            ProblemError::Syntax { .. } => FailureKind::Syntax,
            ProblemError::Invalid { .. } => FailureKind::Invalid,
            ProblemError::Usage { .. } => FailureKind::Usage,
        }
    }

    /// The stable code (as in the JSON output).
    pub fn code(self) -> &'static str {
        match self {
            FailureKind::Read => "read",
            FailureKind::Syntax => "syntax",
            FailureKind::Invalid => "invalid",
            FailureKind::Usage => "usage",
            FailureKind::Answer => "answer",
            FailureKind::NoAnswer => "no_answer",
        }
    }
}

impl Serialize for FailureKind {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.code())
    }
}

/// What a check decided, in the three ways a caller acts on it (the command line maps them to
/// the exit codes 0, 1 and 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Status {
    /// Right, or the likely intended reading without `--strict`.
    Accepted,
    /// Wrong, or the likely intended reading under `--strict`.
    Refused,
    /// The answer or the problem could not be read, validated or solved.
    Unchecked,
}

impl Checked {
    /// Whether the answer was accepted, refused, or could not be checked.
    pub(crate) fn status(&self) -> Status {
        match &self.outcome {
            Ok(j) if j.verdict.accepted => Status::Accepted,
            Ok(_) => Status::Refused,
            Err(_) => Status::Unchecked,
        }
    }
}

fn signed(x: f64) -> String {
    let s = num(x);
    if x > 0.0 && s != "0" {
        format!("+{s}")
    } else {
        s
    }
}

/// A colour as `(r, g, b)`, each number written by `f`.
pub(crate) fn triple(v: [f64; 3], f: fn(f64) -> String) -> String {
    format!("({}, {}, {})", f(v[0]), f(v[1]), f(v[2]))
}

/// The text report of one check.
pub fn text(c: &Checked, lang: Lang) -> String {
    let mut out = String::new();
    let Judged {
        answer,
        tolerance,
        verdict: v,
        credit,
        as_8bit,
        policy,
    } = match &c.outcome {
        Err(f) => {
            let _ = writeln!(
                out,
                "{}: {}: {}",
                c.file,
                messages::invalid(lang),
                f.message.text(lang)
            );
            return out;
        }
        Ok(x) => x,
    };
    let _ = writeln!(
        out,
        "{}: {}",
        c.file,
        messages::verdict(v.kind, v.accepted, lang)
    );
    let label = |l| format!("{:<11}", messages::line(l, lang));
    let shown = match answer.values {
        Some(values) => triple(values, num),
        None => messages::no_hit_answer(lang).to_owned(),
    };
    let _ = writeln!(out, "  {}{shown}", label(Line::Answer));
    if *as_8bit {
        let _ = writeln!(out, "  {}", messages::read_as_8bit(lang));
    }
    match expected_line(v) {
        ExpectedLine::Compared {
            comparison,
            reading,
        } => {
            let _ = writeln!(
                out,
                "  {}{}  {}",
                label(Line::Expected),
                triple(comparison.expected, num),
                messages::expected_source(reading, comparison.against, lang)
            );
            let _ = writeln!(
                out,
                "  {}{}",
                label(Line::Difference),
                triple(comparison.difference, signed)
            );
        }
        ExpectedLine::HasColour { colour, ray } => {
            let _ = writeln!(
                out,
                "  {}{}  {}",
                label(Line::Expected),
                triple(colour, num),
                messages::has_colour(ray, lang)
            );
        }
        ExpectedLine::Nothing => {
            let _ = writeln!(out, "  {}", messages::nothing_to_shade(lang));
        }
    }
    let _ = writeln!(
        out,
        "  {}±{} {}",
        label(Line::Tolerance),
        num(*tolerance),
        messages::per_channel(answer.scale, lang)
    );
    let _ = writeln!(
        out,
        "  {}{}",
        label(Line::Credit),
        messages::Credit::of(*credit, policy.as_deref()).text(lang)
    );
    for m in matches(v, *tolerance, Layout::WithExpected) {
        let line = match m {
            // Said by the expected line above.
            Match::HasColour { .. } | Match::NothingToShade => continue,
            Match::Reading { reading, likely } => {
                messages::matches_reading(reading.code, likely, lang)
            }
            Match::AsWritten(w) => format!(
                "{:<11}{}",
                messages::as_written(lang),
                triple(w.expected, num)
            ),
            Match::NothingAsWritten => messages::nothing_to_shade(lang).to_owned(),
            Match::Background(colour) => messages::background(colour, lang),
            // The slips as a list under one line.
            Match::Slips { diagnoses, pairs } => {
                let mut list = messages::diagnosis_intro(pairs, lang).to_owned();
                for d in diagnoses {
                    let _ = write!(
                        list,
                        "\n    - {}: {}",
                        messages::slips_made(&d.slips, &d.intended, lang),
                        triple(d.comparison.expected, num)
                    );
                }
                list
            }
            Match::NoDiagnosis => messages::no_diagnosis(lang).to_owned(),
            Match::Looks8bit => messages::looks_8bit(lang).to_owned(),
            Match::Nearest(n) => format!(
                "{}{}  {}",
                label(Line::Closest),
                triple(n.comparison.expected, num),
                messages::nearest(&n.candidate, n.comparison.distance(), *tolerance, lang)
            ),
            // The expected line has the colour; this says it is a near miss, and of what.
            Match::NearMiss(n) => {
                messages::nearest(&n.candidate, n.comparison.distance(), *tolerance, lang)
            }
            Match::Unclamped => messages::unclamped_note(lang).to_owned(),
        };
        let _ = writeln!(out, "  {line}");
    }
    out
}

/// The JSON form of a comparison's target.
#[derive(Serialize)]
pub struct ExpectedOut {
    /// The colour compared with, on the answer's scale.
    pub color: [f64; 3],
    /// "solution" (the problem as written) or "reading".
    pub source: &'static str,
    /// The reading's code when `source` is "reading".
    pub reading: Option<ReadingCode>,
    /// "clamped" or "unclamped".
    pub against: super::Against,
}

/// `answer`: the answer checked.
#[derive(Serialize)]
pub struct AnswerOut {
    /// The answer as written; `null` when there is none.
    pub text: Option<String>,
    /// Where it came from: "argument" (`--answer` or a CSV row) or "key" (the file's `answer`).
    pub source: AnswerSource,
    /// 1 or 255.
    pub scale: Option<u32>,
    /// The three numbers read, on `scale`; `null` when the answer could not be checked.
    pub values: Option<[f64; 3]>,
    /// Written without a scale, its numbers were read as 8-bit values (the course policy's
    /// `eight_bit`).
    pub read_as_8bit: bool,
}

/// `reading`: a reading of the problem the answer matches.
#[derive(Serialize)]
pub struct ReadingOut {
    /// Which reading: "light_reversed", "normal_reversed" or "line_behind_origin".
    pub code: ReadingCode,
    /// Whether the solver labels it the likely intended reading.
    pub likely_intended: bool,
    /// The reading in English.
    pub label: &'static str,
}

/// An entry of `diagnosis`: slips whose colour the answer matches.
#[derive(Serialize)]
pub struct DiagnosisOut {
    /// The slips' codes (one, or two made together).
    pub slips: Vec<super::Slip>,
    /// Those of `slips` that are the likely intended reading of the problem, not mistakes.
    pub intended: Vec<super::Slip>,
    /// The mistakes, in words.
    pub description: String,
    /// The colour those slips give, on the answer's scale.
    pub color: [f64; 3],
    /// answer − color, per channel, on the answer's scale.
    pub difference: [f64; 3],
}

/// One check, for scripts.
#[derive(Serialize)]
pub struct CheckOut {
    /// The version of this format, [`CHECK_FORMAT_VERSION`] (1).
    pub format_version: u32,
    /// The problem file's path, as given.
    pub file: String,
    /// The answer checked.
    pub answer: AnswerOut,
    /// The largest difference accepted per channel, on the answer's scale; `null` when the answer
    /// cannot be checked.
    pub tolerance: Option<f64>,
    /// "right", "reading", "wrong" or "invalid".
    pub verdict: &'static str,
    /// Exit code 0: right, or a likely intended reading without --strict.
    pub accepted: bool,
    /// The share of the exercise's points the verdict earns under the course policy (1, the
    /// reading credit, or 0); `null` when the answer cannot be checked.
    pub credit: Option<f64>,
    /// The course policy's file; `null` for the default policy (or when nothing was checked).
    pub policy: Option<String>,
    /// The verdict (or the error) as an English sentence.
    pub message: String,
    /// The colour the answer was compared with; `null` when there is none.
    pub expected: Option<ExpectedOut>,
    /// answer − expected, per channel, on the answer's scale; `null` without `expected`.
    pub difference: Option<[f64; 3]>,
    /// A reading of the problem the answer matches; `null` when it matches none.
    pub reading: Option<ReadingOut>,
    /// The slips (or pairs of slips) whose colour the answer matches.
    pub diagnosis: Vec<DiagnosisOut>,
    /// For a wrong answer: the closest candidate it does not match, and how far it is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nearest: Option<NearestOut>,
    /// Why the answer could not be checked (`kind`, `field`, `message`); `null` when it was.
    pub error: Option<Failure>,
    /// Likely unit mistakes in the problem file; absent when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<crate::report::json::WarningOut>,
}

/// The candidate closest to a wrong answer.
#[derive(Serialize)]
pub struct NearestOut {
    /// "solution" (the problem as written), "reading" or "slips".
    pub source: &'static str,
    /// The reading's code when `source` is "reading".
    pub reading: Option<ReadingCode>,
    /// The slips' codes when `source` is "slips".
    pub slips: Vec<super::Slip>,
    /// Its colour, on the answer's scale.
    pub color: [f64; 3],
    /// answer − color, per channel, on the answer's scale.
    pub difference: [f64; 3],
    /// The largest |difference| of a channel.
    pub distance: f64,
    /// In words (English).
    pub description: String,
}

fn expected_out(cmp: &Comparison, reading: Option<ReadingCode>) -> ExpectedOut {
    ExpectedOut {
        color: cmp.expected,
        source: if reading.is_some() {
            "reading"
        } else {
            "solution"
        },
        reading,
        against: cmp.against,
    }
}

/// The JSON document of one check.
pub fn json(c: &Checked) -> CheckOut {
    let mut out = CheckOut {
        format_version: CHECK_FORMAT_VERSION,
        file: c.file.clone(),
        answer: AnswerOut {
            text: c.text.clone(),
            source: c.source,
            scale: None,
            values: None,
            read_as_8bit: false,
        },
        tolerance: None,
        credit: None,
        policy: None,
        verdict: "invalid",
        accepted: false,
        message: String::new(),
        expected: None,
        difference: None,
        reading: None,
        diagnosis: Vec::new(),
        nearest: None,
        error: None,
        warnings: crate::report::json::warnings_out(&c.warnings),
    };
    match &c.outcome {
        Err(f) => {
            out.message = f.message.text(Lang::En);
            out.error = Some(f.clone());
        }
        Ok(Judged {
            answer,
            tolerance,
            verdict: v,
            credit,
            as_8bit,
            policy,
        }) => {
            out.answer.scale = Some(scale_number(answer.scale));
            out.answer.read_as_8bit = *as_8bit;
            out.credit = Some(*credit);
            out.policy = policy.as_ref().map(|p| p.display().to_string());
            out.answer.values = answer.values;
            out.tolerance = Some(*tolerance);
            out.verdict = verdict_code(v.kind);
            out.accepted = v.accepted;
            out.message = messages::summary(v.kind, v.accepted, v.reading.as_ref().map(|r| r.code));
            if let Some(colour) = v.background {
                out.message = format!(
                    "{}; {}",
                    out.message,
                    messages::background(colour, Lang::En)
                );
            }
            out.expected = v
                .comparison
                .as_ref()
                .map(|cmp| expected_out(cmp, v.compared_reading));
            out.difference = v.comparison.map(|c| c.difference);
            out.reading = v.reading.as_ref().map(|r| ReadingOut {
                code: r.code,
                likely_intended: r.likely_intended,
                label: messages::reading(r.code, Lang::En),
            });
            out.diagnosis = v
                .diagnosis
                .iter()
                .map(|d| DiagnosisOut {
                    slips: d.slips.clone(),
                    intended: d.intended.clone(),
                    description: messages::slips(&d.mistakes(), Lang::En),
                    color: d.comparison.expected,
                    difference: d.comparison.difference,
                })
                .collect();
            out.nearest = v.nearest.as_ref().map(|n| {
                let (source, reading, slips) = match &n.candidate {
                    Candidate::Written => ("solution", None, Vec::new()),
                    Candidate::Reading(code, _) => ("reading", Some(*code), Vec::new()),
                    Candidate::Slips { slips, .. } => ("slips", None, slips.clone()),
                };
                NearestOut {
                    source,
                    reading,
                    slips,
                    color: n.comparison.expected,
                    difference: n.comparison.difference,
                    distance: n.comparison.distance(),
                    description: messages::nearest(
                        &n.candidate,
                        n.comparison.distance(),
                        *tolerance,
                        Lang::En,
                    ),
                }
            });
            if let Some((colour, _)) = v.has_colour {
                out.expected = Some(ExpectedOut {
                    color: colour,
                    source: "solution",
                    reading: None,
                    against: super::Against::Clamped,
                });
            }
        }
    }
    out
}

/// 1 or 255.
pub(crate) fn scale_number(s: Scale) -> u32 {
    match s {
        Scale::Unit => 1,
        Scale::Bits8 => 255,
    }
}

/// The stable code of a verdict.
pub(crate) fn verdict_code(k: VerdictKind) -> &'static str {
    match k {
        VerdictKind::Right => "right",
        VerdictKind::Reading => "reading",
        VerdictKind::Wrong => "wrong",
    }
}

/// What the problem, its readings and each applicable slip give (`phong check --slips`).
pub(crate) fn slips_text(file: &str, x: &super::Expected, lang: Lang) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{file}");
    // "(clamped)  ((unclamped))" where they differ. The literal colour (no_clamping) has no
    // clamped target of its own (it is detected unclamped only), but its row shows both columns
    // like the others: the first is then that colour clamped to [0, 1], as a screen shows it.
    let show = |t: &super::Target| {
        let c = t
            .clamped
            .unwrap_or_else(|| t.unclamped.map(|x| x.clamp(0.0, 1.0)));
        if c == t.unclamped {
            triple(c, num)
        } else {
            format!("{}  ({})", triple(c, num), triple(t.unclamped, num))
        }
    };
    match &x.solution {
        Some(t) => {
            let _ = writeln!(out, "  {:<11}{}", messages::as_written(lang), show(t));
        }
        None => {
            let _ = writeln!(out, "  {}", messages::nothing_to_shade(lang));
        }
    }
    for r in &x.readings {
        let _ = writeln!(
            out,
            "  {}: {}",
            messages::reading(r.code, lang),
            show(&r.target)
        );
    }
    for o in &x.outcomes {
        let codes: Vec<_> = o.slips.iter().map(|s| s.code()).collect();
        let _ = writeln!(out, "  {:<44} {}", codes.join(" + "), show(&o.target));
        // What the codes mean, in the language asked for.
        let _ = writeln!(out, "      {}", messages::slips(&o.slips, lang));
    }
    out
}

/// The JSON document `phong check --format json` writes for one problem (and `POST /api/check`
/// answers): the answer's verdict ([`json`]) with, when steps were given too, the steps judged
/// under `steps` (and why they could not be, under `steps_error`); with steps and no answer,
/// the steps' own document (`steps::document`). `None` when there is neither.
pub fn document(
    answer: Option<&Checked>,
    steps: Option<&super::steps::StepsChecked>,
) -> Option<serde_json::Value> {
    match (answer, steps) {
        (Some(c), steps) => {
            let mut v = value(&json(c));
            if let Some(s) = steps {
                v["steps"] = value(&s.outcome.as_ref().ok().map(super::steps::steps_json));
                if let Err(f) = &s.outcome {
                    v["steps_error"] = value(f);
                }
            }
            Some(v)
        }
        (None, Some(s)) => Some(value(&super::steps::document(s))),
        (None, None) => None,
    }
}

/// `v` as a JSON value. These types cannot fail to serialise (their maps have string keys, and
/// serde_json writes a non-finite number as null); `null` would stand in, never a panic.
fn value<T: Serialize>(v: &T) -> serde_json::Value {
    serde_json::to_value(v).unwrap_or(serde_json::Value::Null)
}
