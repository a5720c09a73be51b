//! `phong grade`: a class's answers in a CSV file (student, exercise, answer), one verdict per
//! row with its diagnosis, and a summary per exercise.
//!
//! Every input row appears in the output exactly once, in input order: a malformed row (wrong
//! number of fields, bad UTF-8, an empty field), an unknown exercise, a bad exercise file or an
//! unreadable answer gets the verdict `invalid` with the reason, and the batch goes on. Each
//! exercise is solved once (with its slips) on first use; grading a row is then a few
//! comparisons. A first row whose first field is `student` is a header, not a row.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::report::{scale_number, verdict_code, CHECK_FORMAT_VERSION};
use super::{answer, judge, messages, Expected, Scale, Slip, Verdict, VerdictKind};
use crate::report::lang::Lang;
use crate::solve::ReadingCode;

/// How answers are read and judged.
#[derive(Clone, Debug)]
pub struct Options {
    /// The folder of exercise files: exercise `4.2` is `DIR/4.2.json`.
    pub exercises: PathBuf,
    /// The scale of answers that are not `#RRGGBB`.
    pub scale: Scale,
    /// The tolerance; `None` for each exercise key's own, else the scale's default (0.005, or 1
    /// on the 255 scale).
    pub tolerance: Option<f64>,
    /// Only the problem as written is right (a likely intended reading is not accepted).
    pub strict: bool,
}

/// One graded row.
#[derive(Clone, Debug, Serialize)]
pub struct RowOut {
    /// The row's number among the data rows, from 1.
    pub row: usize,
    /// The line of the CSV file where the row starts.
    pub line: u64,
    /// The `student` column, as written.
    pub student: String,
    /// The `exercise` column, as written (exercise `4.2` is the file `4.2.json`).
    pub exercise: String,
    /// The `answer` column, as written.
    pub answer: String,
    /// "right", "reading", "wrong" or "invalid".
    pub verdict: &'static str,
    /// Right, or a likely intended reading without `--strict`.
    pub accepted: bool,
    /// 1 or 255 (`null` for an invalid row).
    pub scale: Option<u32>,
    /// The largest difference accepted per channel, on the answer's scale (`null` for an
    /// invalid row).
    pub tolerance: Option<f64>,
    /// The colour compared with, on the answer's scale.
    pub expected: Option<[f64; 3]>,
    /// answer − expected.
    pub difference: Option<[f64; 3]>,
    /// The reading the answer matches.
    pub reading: Option<ReadingCode>,
    /// The slips (or pairs of slips) whose colour the answer matches.
    pub diagnosis: Vec<Vec<Slip>>,
    /// Why the row is invalid, or a note.
    pub reason: Option<String>,
}

/// The rows of one exercise, counted.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SummaryOut {
    /// The exercise, as the rows name it.
    pub exercise: String,
    /// The number of its rows.
    pub rows: usize,
    /// Rows whose verdict is "right".
    pub right: usize,
    /// Rows whose verdict is "reading" (the likely intended reading).
    pub reading: usize,
    /// Rows whose verdict is "wrong".
    pub wrong: usize,
    /// Rows that could not be checked (verdict "invalid").
    pub invalid: usize,
    /// The diagnoses of wrong rows, most common first.
    pub slips: Vec<SlipCount>,
}

/// An entry of `slips`: a diagnosis and how many wrong rows it explains.
#[derive(Clone, Debug, Serialize)]
pub struct SlipCount {
    /// The slips' codes (one, or two made together).
    pub slips: Vec<Slip>,
    /// The number of wrong rows whose answer they explain.
    pub count: usize,
}

/// A graded CSV.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The version of this format, [`CHECK_FORMAT_VERSION`] (1).
    pub format_version: u32,
    /// Each data row of the CSV, graded, in file order.
    pub rows: Vec<RowOut>,
    /// Each exercise's rows, counted, in order of first appearance.
    pub summary: Vec<SummaryOut>,
}

/// The CSV cannot be read at all (a row that cannot be read is reported in its place instead).
#[derive(Debug, thiserror::Error)]
#[error("{path}: cannot read the file: {source}. Fix: check the path, and that the file exists and is readable")]
pub(crate) struct Unreadable {
    pub path: PathBuf,
    #[source]
    pub source: std::io::Error,
}

/// An exercise solved once: what answers are judged against, and its answer key's own
/// tolerance (which, like `phong check`'s, judges every answer to it unless `--tolerance`).
struct Exercise {
    expected: Expected,
    key: Option<answer::Key>,
}

/// Each exercise solved once, or why it cannot be.
struct Cache<'a> {
    options: &'a Options,
    solved: BTreeMap<String, Result<Exercise, String>>,
}

impl Cache<'_> {
    fn get(&mut self, exercise: &str) -> &Result<Exercise, String> {
        if !self.solved.contains_key(exercise) {
            let result = self.solve(exercise);
            self.solved.insert(exercise.to_owned(), result);
        }
        &self.solved[exercise]
    }

    fn solve(&self, exercise: &str) -> Result<Exercise, String> {
        let dir = &self.options.exercises;
        let safe = !exercise.starts_with('.')
            && exercise
                .chars()
                .all(|c| c.is_alphanumeric() || matches!(c, '.' | '-' | '_'));
        let file = if exercise.ends_with(".json") {
            exercise.to_owned()
        } else {
            format!("{exercise}.json")
        };
        let path = dir.join(&file);
        if !safe || !path.is_file() {
            return Err(format!(
                "unknown exercise: there is no {} in {}. Fix: name an exercise by its file name \
                 without .json (e.g. 4.2 for {}/4.2.json)",
                file,
                dir.display(),
                dir.display()
            ));
        }
        let (file, problem) = crate::problem::load::<f64>(&path).map_err(|e| e.to_string())?;
        let expected = Expected::of(&problem).map_err(|e| e.at(&path).to_string())?;
        // A key that cannot be read judges nothing here (`phong check` reports it).
        let key = file.answer.as_ref().and_then(|k| answer::from_key(k).ok());
        Ok(Exercise { expected, key })
    }
}

/// Grades the CSV file at `path`.
pub(crate) fn grade_file(path: &Path, options: &Options) -> Result<Report, Unreadable> {
    let bytes = std::fs::read(path).map_err(|source| Unreadable {
        path: path.to_owned(),
        source,
    })?;
    Ok(grade_bytes(&bytes, options))
}

/// Grades CSV text (bytes, so that a row of bad UTF-8 is reported rather than fatal).
pub fn grade_bytes(bytes: &[u8], options: &Options) -> Report {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(bytes);
    let mut cache = Cache {
        options,
        solved: BTreeMap::new(),
    };
    let mut rows = Vec::new();
    let mut first = true;
    let mut record = csv::ByteRecord::new();
    loop {
        let line = reader.position().line();
        let byte = reader.position().byte();
        let result = reader.read_byte_record(&mut record);
        let mut row = RowOut {
            row: rows.len() + 1,
            line,
            student: String::new(),
            exercise: String::new(),
            answer: String::new(),
            verdict: "invalid",
            accepted: false,
            scale: None,
            tolerance: None,
            expected: None,
            difference: None,
            reading: None,
            diagnosis: Vec::new(),
            reason: None,
        };
        match result {
            Ok(false) => break,
            Ok(true) => {
                row.line = record.position().map_or(line, |p| p.line());
                let fields: Vec<&[u8]> = record.iter().collect();
                let is_header = first
                    && fields.first().is_some_and(|f| {
                        String::from_utf8_lossy(f)
                            .trim()
                            .eq_ignore_ascii_case("student")
                    });
                first = false;
                if is_header {
                    continue;
                }
                grade_row(&mut row, &fields, options, &mut cache);
            }
            Err(e) => {
                // The reader goes on after a bad record; one that made no progress would loop.
                row.reason = Some(format!("the row cannot be read as CSV: {e}"));
                let stuck = reader.position().byte() == byte;
                rows.push(row);
                if stuck {
                    break;
                }
                continue;
            }
        }
        rows.push(row);
    }
    let summary = summarise(&rows);
    Report {
        format_version: CHECK_FORMAT_VERSION,
        rows,
        summary,
    }
}

fn grade_row(row: &mut RowOut, fields: &[&[u8]], options: &Options, cache: &mut Cache) {
    let text = |f: &[u8]| String::from_utf8_lossy(f).trim().to_owned();
    row.student = fields.first().map_or_else(String::new, |f| text(f));
    row.exercise = fields.get(1).map_or_else(String::new, |f| text(f));
    row.answer = fields.get(2).map_or_else(String::new, |f| text(f));
    const COLUMNS: [&str; 3] = ["student", "exercise", "answer"];
    let invalid = |row: &mut RowOut, reason: String| row.reason = Some(reason);
    if fields.len() != 3 {
        let hint = if fields.len() > 3 {
            "; an answer written with commas must be quoted: \"0.52, 0.03, 0\""
        } else {
            ""
        };
        return invalid(
            row,
            format!(
                "the row has {} field{}, expected 3 (student, exercise, answer){hint}",
                fields.len(),
                if fields.len() == 1 { "" } else { "s" }
            ),
        );
    }
    for (name, f) in COLUMNS.iter().zip(fields) {
        if std::str::from_utf8(f).is_err() {
            return invalid(row, format!("the {name} field is not valid UTF-8"));
        }
    }
    let empty = [&row.student, &row.exercise, &row.answer]
        .iter()
        .position(|v| v.is_empty());
    if let Some(i) = empty {
        return invalid(row, format!("the {} field is empty", COLUMNS[i]));
    }
    let Exercise { expected, key } = match cache.get(&row.exercise) {
        Ok(e) => e,
        Err(e) => return invalid(row, e.clone()),
    };
    let a = match answer::parse(&row.answer, options.scale) {
        Ok(a) => a,
        Err(e) => return invalid(row, format!("the answer cannot be read: {e}")),
    };
    let tolerance = options
        .tolerance
        .or_else(|| key.and_then(|k| k.tolerance_on(a.scale)))
        .unwrap_or_else(|| a.scale.default_tolerance());
    let v: Verdict = judge(expected, &a, tolerance, options.strict);
    row.verdict = verdict_code(v.kind);
    row.accepted = v.accepted;
    row.scale = Some(scale_number(a.scale));
    row.tolerance = Some(tolerance);
    row.expected = v
        .comparison
        .map(|c| c.expected)
        .or(v.has_colour.map(|(c, _)| c));
    row.difference = v.comparison.map(|c| c.difference);
    row.reading = v.reading.as_ref().map(|r| r.code);
    row.diagnosis = v.diagnosis.iter().map(|d| d.slips.clone()).collect();
    if v.looks_8bit {
        row.reason = Some(messages::looks_8bit(Lang::En).to_owned());
    } else if v.kind == VerdictKind::Right
        && v.comparison
            .is_some_and(|c| c.against == super::Against::Unclamped)
    {
        row.reason = Some(messages::unclamped_note(Lang::En).to_owned());
    }
}

/// One exercise's rows as they are counted: the summary, and how often each diagnosis occurs.
struct Tally<'a> {
    summary: SummaryOut,
    slips: BTreeMap<&'a [Slip], usize>,
}

fn summarise(rows: &[RowOut]) -> Vec<SummaryOut> {
    let mut by: BTreeMap<&str, Tally> = BTreeMap::new();
    for r in rows {
        let Tally { summary, slips } = by.entry(&r.exercise).or_insert_with(|| Tally {
            summary: SummaryOut {
                exercise: r.exercise.clone(),
                ..SummaryOut::default()
            },
            slips: BTreeMap::new(),
        });
        summary.rows += 1;
        match r.verdict {
            "right" => summary.right += 1,
            "reading" => summary.reading += 1,
            "wrong" => summary.wrong += 1,
            _ => summary.invalid += 1,
        }
        for d in &r.diagnosis {
            *slips.entry(d.as_slice()).or_default() += 1;
        }
    }
    by.into_values()
        .map(|Tally { mut summary, slips }| {
            let mut counts: Vec<SlipCount> = slips
                .into_iter()
                .map(|(k, count)| SlipCount {
                    slips: k.to_vec(),
                    count,
                })
                .collect();
            // Most common first, then single slips before pairs, then the slips' order: stable.
            counts.sort_by(|a, b| {
                (b.count, a.slips.len(), &a.slips).cmp(&(a.count, b.slips.len(), &b.slips))
            });
            summary.slips = counts;
            summary
        })
        .collect()
}

fn codes(slips: &[Slip]) -> String {
    slips.iter().map(|s| s.code()).collect::<Vec<_>>().join("+")
}

fn number(x: f64) -> String {
    // The shortest text that reads back as the same f64: exact and deterministic.
    format!("{x}")
}

/// The per-row report as CSV (a header, then one line per input row, in input order).
pub fn rows_csv(report: &Report) -> Vec<u8> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let header = [
        "row",
        "line",
        "student",
        "exercise",
        "answer",
        "verdict",
        "accepted",
        "scale",
        "tolerance",
        "expected_r",
        "expected_g",
        "expected_b",
        "diff_r",
        "diff_g",
        "diff_b",
        "reading",
        "diagnosis",
        "reason",
    ];
    w.write_record(header).expect("writing to memory");
    for r in &report.rows {
        let three = |v: Option<[f64; 3]>| {
            v.map_or([String::new(), String::new(), String::new()], |v| {
                v.map(number)
            })
        };
        let [er, eg, eb] = three(r.expected);
        let [dr, dg, db] = three(r.difference);
        let diagnosis = r
            .diagnosis
            .iter()
            .map(|d| codes(d))
            .collect::<Vec<_>>()
            .join(";");
        let reading = r.reading.map_or(String::new(), |c| {
            serde_json::to_value(c)
                .ok()
                .and_then(|v| v.as_str().map(str::to_owned))
                .unwrap_or_default()
        });
        w.write_record([
            r.row.to_string(),
            r.line.to_string(),
            r.student.clone(),
            r.exercise.clone(),
            r.answer.clone(),
            r.verdict.to_owned(),
            r.accepted.to_string(),
            r.scale.map_or(String::new(), |s| s.to_string()),
            r.tolerance.map_or(String::new(), number),
            er,
            eg,
            eb,
            dr,
            dg,
            db,
            reading,
            diagnosis,
            r.reason.clone().unwrap_or_default(),
        ])
        .expect("writing to memory");
    }
    w.into_inner().expect("writing to memory")
}

/// The summary per exercise as CSV.
pub(crate) fn summary_csv(report: &Report) -> Vec<u8> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "exercise", "rows", "right", "reading", "wrong", "invalid", "slips",
    ])
    .expect("writing to memory");
    for s in &report.summary {
        let slips = s
            .slips
            .iter()
            .map(|c| format!("{}:{}", codes(&c.slips), c.count))
            .collect::<Vec<_>>()
            .join(";");
        w.write_record([
            s.exercise.clone(),
            s.rows.to_string(),
            s.right.to_string(),
            s.reading.to_string(),
            s.wrong.to_string(),
            s.invalid.to_string(),
            slips,
        ])
        .expect("writing to memory");
    }
    w.into_inner().expect("writing to memory")
}
