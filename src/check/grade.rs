//! `phong grade`: a class's answers in a CSV file (student, exercise, answer), one verdict per
//! row with its diagnosis, and a summary per exercise.
//!
//! The file is read as people's spreadsheets write it: UTF-8 with or without a byte order mark,
//! or UTF-16 with one; fields separated by `,`, `;` or tabs (detected, or `Options::delimiter`);
//! lines ending in `\n`, `\r\n` or `\r`. A row is one line. Every line that holds data is one
//! row of the report, exactly once, in input order: a malformed row (a quote not closed on its
//! line, a line of a quoted cell holding a line break, a lone quote, text after a closing
//! quote, a wrong number of fields, bad UTF-8, a NUL byte, an empty field), an unknown exercise, a bad exercise file or an unreadable answer gets the verdict
//! `invalid` with the reason, and the batch goes on. A first line naming the three columns in
//! English or Portuguese (`aluno;exercício;resposta`, in any order) is a header, not a row; it
//! may name a fourth column, `steps` (`passos`), whose cell holds a row's step answers
//! (`cos_theta=0.98995; n_dot_l=-0.98995`, read by `steps::read_cell` and judged as
//! `phong check --step` judges them; they change no points). Each exercise is solved once (with
//! its slips) on first use, its steps' quantities when a row first gives steps; grading a row is
//! then a few comparisons.

use std::borrow::Cow;
use std::cell::OnceCell;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::policy::{Duplicates, Policy};
use super::report::{scale_number, verdict_code, CHECK_FORMAT_VERSION};
use super::steps::{self, StepsExpected, StepsOut};
use super::{answer, judge, messages, Expected, Scale, Slip, Verdict, VerdictKind};
use crate::solve::ReadingCode;
use crate::text::lang::Lang;
use crate::text::Said;

mod reasons;
pub use reasons::{
    AnswerNote, Column, ExerciseFault, ExerciseNote, Fields, FieldsHint, HeaderFault, NotCsv,
    Reason, RowReason, Sep, Width,
};

/// How answers are read and judged.
#[derive(Clone, Debug)]
pub struct Options {
    /// The folder of exercise files: exercise `4.2` is `DIR/4.2.json`.
    pub exercises: PathBuf,
    /// The scale of answers that are not `#RRGGBB`; `None` for the 0–1 scale, with 8-bit
    /// values read as the course policy says.
    pub scale: Option<Scale>,
    /// The fields' separator (`b','`, `b';'` or `b'\t'`); `None` to detect it ([`delimiter`]).
    pub delimiter: Option<u8>,
    /// The course policy: tolerances, strictness, 8-bit reading, no-hit words, points, the
    /// reading's credit and which answer counts when a student answers an exercise twice.
    pub policy: Policy,
    /// The language of the `feedback` column.
    pub lang: Lang,
    /// What the submissions file is.
    pub input: Input,
    /// A Moodle export's question slots: slot N is exercise `questions[N-1]` (empty: the
    /// exercise files of the folder in name order).
    pub questions: Vec<String>,
}

/// What the submissions file is (`grade --input`): `Auto` (detected from its header), `Csv`
/// or `Moodle`.
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
#[allow(missing_docs)]
pub enum Input {
    #[default]
    Auto,
    Csv,
    Moodle,
}

/// The exercises of a folder (its `*.json` files but the course policy, without `.json`), in
/// name order with numbers compared as numbers (4.2 before 4.10).
pub fn folder_exercises(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .filter(|e| crate::problem::is_exercise_file(&e.path()))
                .filter_map(|e| {
                    let name = e.file_name().to_string_lossy().into_owned();
                    name.strip_suffix(".json").map(str::to_owned)
                })
                .collect()
        })
        .unwrap_or_default();
    names.sort_by(|a, b| natural_order(a, b));
    names
}

/// Exercises in natural order: their names compared part by part at each `.`, a part that is
/// a number as a number (4.2 before 4.10, 4.9 before 4.10), one that is not after the numbers,
/// as text. Used wherever a list of exercises is shown (the totals' columns, the summary, the
/// platforms' tests), as the Moodle slots are numbered.
pub(crate) fn natural_order(a: &str, b: &str) -> std::cmp::Ordering {
    let parts = |s: &str| -> Vec<(u64, String)> {
        s.split('.')
            .map(|p| (p.parse().unwrap_or(u64::MAX), p.to_owned()))
            .collect()
    };
    parts(a).cmp(&parts(b))
}

impl Default for Options {
    /// No folder; the 0–1 scale with detection; each key's tolerance; 1 point per exercise, half
    /// for a reading; the last answer counts; English.
    fn default() -> Self {
        Options {
            exercises: PathBuf::new(),
            scale: None,
            delimiter: None,
            policy: Policy::default(),
            lang: Lang::En,
            input: Input::Auto,
            questions: Vec::new(),
        }
    }
}

/// One graded row.
#[derive(Clone, Debug, Serialize)]
pub struct RowOut {
    /// The row's number among the data rows, from 1.
    pub row: usize,
    /// The line of the CSV file where the row is (1 for the first; blank lines and a header
    /// count, whatever the line ends).
    pub line: u64,
    /// The `student` column, as written (control characters and NUL shown as U+FFFD).
    pub student: String,
    /// The `exercise` column, as written (exercise `4.2` is the file `4.2.json`); a number
    /// written with a decimal comma, `4,1`, is read as exercise `4.1` when there is one (a
    /// graded row's reason says so).
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
    /// Why the row is invalid, or a note: a value, said in English in the CSV's `reason` column
    /// and the JSON, in the chosen language in the feedback.
    pub reason: Option<Reason>,
    /// The answer's whole numbers were read as 8-bit values (per-row scale detection).
    pub scale_detected: bool,
    /// The points the answer earns: the exercise's for `right`, the reading credit's share of
    /// them for `reading` (nothing under `--strict`), 0 otherwise.
    pub points: f64,
    /// The exercise's points (`null` for an exercise that does not exist).
    pub max_points: Option<f64>,
    /// The row counts in its student's total: false for an answer another answer of the same
    /// student to the same exercise replaces (`--duplicates`), and for a row without a student.
    pub counted: bool,
    /// One sentence for the student, in the chosen language: the verdict, the slips in words,
    /// the near miss, the points; then, for a row with steps, a sentence per step and the first
    /// wrong one.
    pub feedback: String,
    /// The steps column, as written (empty: no steps, or no such column).
    pub steps_text: String,
    /// The row's steps judged as `phong check --step` judges them, in the order of the
    /// solution (`null`: no steps). They change no points.
    pub steps: Option<StepsOut>,
}

/// One student's points.
#[derive(Clone, Debug, Serialize)]
pub struct StudentOut {
    /// The student, as written.
    pub student: String,
    /// The points of the rows that count.
    pub points: f64,
    /// The points of every exercise graded (the class's exercises, and those the rubric names).
    pub max_points: f64,
    /// Per exercise, the points of the row that counts (`null`: no answer).
    pub exercises: BTreeMap<String, Option<f64>>,
    /// The rows that count, by exercise (the row's number), for the platforms' reports.
    #[serde(skip)]
    pub rows: BTreeMap<String, usize>,
}

/// The rows of one exercise, counted.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SummaryOut {
    /// The exercise, without `.json` (`4.2` and `4.2.json` are one exercise).
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
    /// Wrong rows that no classic slip (nor pair) explains.
    pub unnamed: usize,
    /// The diagnoses of wrong rows, most common first (a row several diagnoses explain counts
    /// under each).
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
    /// One entry per exercise, in natural order (4.2 before 4.10).
    pub summary: Vec<SummaryOut>,
    /// The exercises graded, in name order, with their points.
    pub exercises: BTreeMap<String, f64>,
    /// Each student's total, in the order the students first appear.
    pub students: Vec<StudentOut>,
}

/// The CSV cannot be read at all (a row that cannot be read is reported in its place instead):
/// `PATH: cannot read the file: WHY. Fix: FIX`, said in a language by its
/// [`Message`](crate::text::Message), in English by its `Display`.
#[derive(Debug)]
pub struct Unreadable {
    /// The submissions' path.
    pub path: PathBuf,
    /// Why.
    pub source: std::io::Error,
}

impl crate::text::Message for Unreadable {
    fn text(&self, lang: Lang) -> String {
        let fault = crate::problem::reading::ReadFault::of(&self.source);
        format!(
            "{}: {}",
            self.path.display(),
            crate::problem::error::what_and_fix(&fault, lang)
        )
    }
}

impl std::fmt::Display for Unreadable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::text::Message::text(self, Lang::En))
    }
}

impl std::error::Error for Unreadable {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.source)
    }
}

/// An exercise solved once: what answers are judged against, and its answer key's own
/// tolerance (which, like `phong check`'s, judges every answer to it unless `--tolerance`).
struct Exercise {
    expected: Expected,
    key: Option<answer::Key>,
    /// The problem, for its steps' quantities.
    problem: crate::problem::Problem<f64>,
    /// The exercise file, for errors.
    path: PathBuf,
    /// The quantities steps are judged against, solved when a row first gives steps.
    steps: OnceCell<Result<StepsExpected, Reason>>,
}

impl Exercise {
    fn steps(&self) -> &Result<StepsExpected, Reason> {
        self.steps
            .get_or_init(|| StepsExpected::of(&self.problem).map_err(|e| e.at(&self.path).into()))
    }
}

/// The largest submissions file read: 256 MiB (100,000 rows are about 3 MB).
pub const MAX_SUBMISSIONS_BYTES: u64 = 256 << 20;

/// Each exercise solved once, or why it cannot be.
struct Cache<'a> {
    options: &'a Options,
    /// The exercises folder with its links resolved (`None` if it cannot be).
    folder: Option<PathBuf>,
    solved: BTreeMap<String, Result<Exercise, Reason>>,
}

/// An exercise's name without `.json`: `4.2` and `4.2.json` are one exercise.
fn exercise_key(exercise: &str) -> &str {
    exercise.strip_suffix(".json").unwrap_or(exercise)
}

impl Cache<'_> {
    fn get(&mut self, exercise: &str) -> &Result<Exercise, Reason> {
        let key = exercise_key(exercise);
        if !self.solved.contains_key(key) {
            let result = self.solve(key);
            self.solved.insert(key.to_owned(), result);
        }
        &self.solved[key]
    }

    /// Exercise `name` is the regular file `DIR/name.json`, inside the folder once links are
    /// followed (a link out of the folder is refused: the folder is what the instructor vouches
    /// for).
    fn solve(&self, name: &str) -> Result<Exercise, Reason> {
        let dir = &self.options.exercises;
        let safe = !name.is_empty()
            && !name.starts_with('.')
            && name
                .chars()
                .all(|c| c.is_alphanumeric() || matches!(c, '.' | '-' | '_'));
        let file = format!("{name}.json");
        let path = dir.join(&file);
        if !safe || std::fs::symlink_metadata(&path).is_err() {
            return Err(ExerciseFault::Unknown {
                file,
                dir: dir.clone(),
            }
            .into());
        }
        let real = std::fs::canonicalize(&path).map_err(|e| ExerciseFault::CannotFollow {
            path: path.clone(),
            cause: crate::problem::reading::Cause::of(&e),
        })?;
        if !self.folder.as_ref().is_some_and(|d| real.starts_with(d)) {
            return Err(ExerciseFault::LinkOut {
                path,
                real,
                dir: dir.clone(),
            }
            .into());
        }
        if !std::fs::metadata(&real).is_ok_and(|m| m.is_file()) {
            return Err(ExerciseFault::NotRegular { path }.into());
        }
        let (file, problem) = crate::problem::load::<f64>(&path)?;
        let expected = Expected::of(&problem).map_err(|e| e.at(&path))?;
        // A key that cannot be read judges nothing here (`phong check` reports it).
        let key = file.answer.as_ref().and_then(|k| answer::from_key(k).ok());
        Ok(Exercise {
            expected,
            key,
            problem,
            path,
            steps: OnceCell::new(),
        })
    }
}

/// Grades the CSV file at `path` (`-`: standard input), the whole report in memory (the
/// command streams it instead: [`read_submissions`], [`Graded`]).
pub fn grade_file(path: &Path, options: &Options) -> Result<Report, Unreadable> {
    let bytes = read_submissions(path, options)?;
    Ok(grade_bytes(&bytes, options))
}

/// The bytes of the submissions file at `path` (`-`: standard input), refused when larger than
/// [`MAX_SUBMISSIONS_BYTES`] or when it has more than [`MAX_ROWS`] rows (a header is not a row:
/// a header and 1,000,000 rows are read).
pub fn read_submissions(path: &Path, options: &Options) -> Result<Vec<u8>, Unreadable> {
    let bytes = crate::problem::read_limited(
        path,
        MAX_SUBMISSIONS_BYTES,
        crate::problem::Input::Submissions,
    )
    .map_err(|source| Unreadable {
        path: path.to_owned(),
        source,
    })?;
    if data_rows(&decode(&bytes), options) > MAX_ROWS {
        return Err(Unreadable {
            path: path.to_owned(),
            source: std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                crate::problem::TooMany {
                    limit: MAX_ROWS,
                    what: crate::problem::Counted::Rows,
                },
            ),
        });
    }
    Ok(bytes)
}

/// The lines of `text` that hold data, but a header: a plain CSV's first such line when it
/// names the columns, a Moodle export's header line.
fn data_rows(text: &[u8], options: &Options) -> u64 {
    let mut data = lines(text)
        .map(|(_, l)| l)
        .filter(|l| !l.iter().all(u8::is_ascii_whitespace));
    let Some(first) = data.next() else {
        return 0;
    };
    let moodle = match options.input {
        Input::Moodle => true,
        Input::Csv => false,
        Input::Auto => super::moodle::is_responses(text),
    };
    let d = options.delimiter.unwrap_or_else(|| delimiter(text));
    let is_header =
        moodle || fields(first, d).is_ok_and(|f| matches!(header(&f), First::Header(_)));
    1 + data.count() as u64 - u64::from(is_header)
}

/// The most rows a submissions file may have: 1,000,000 (a class of 1,000 students answering 50
/// exercises is 50,000).
pub const MAX_ROWS: u64 = 1_000_000;

/// The submissions as UTF-8 bytes: a UTF-8 byte order mark removed, UTF-16 with its byte order
/// mark (what spreadsheets save as "Unicode text") decoded. Anything else is taken as UTF-8; a
/// line that is not is reported as such.
pub fn decode(bytes: &[u8]) -> Cow<'_, [u8]> {
    if let Some(rest) = bytes.strip_prefix(b"\xEF\xBB\xBF") {
        return Cow::Borrowed(rest);
    }
    for (bom, encoding) in [
        (b"\xFF\xFE", encoding_rs::UTF_16LE),
        (b"\xFE\xFF", encoding_rs::UTF_16BE),
    ] {
        if let Some(rest) = bytes.strip_prefix(bom) {
            let (text, _) = encoding.decode_without_bom_handling(rest);
            return Cow::Owned(text.into_owned().into_bytes());
        }
    }
    if windows_1252(bytes) {
        let (text, _) = encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes);
        return Cow::Owned(text.into_owned().into_bytes());
    }
    Cow::Borrowed(bytes)
}

/// Whether [`decode`] reads `bytes` as Windows-1252: they have no byte order mark and are not
/// UTF-8. Excel in Brazil saves "CSV" in Windows-1252 (a superset of Latin-1) unless told "CSV
/// UTF-8": `João` is the bytes `4A 6F E3 6F`, which no UTF-8 text holds, and every byte has a
/// Windows-1252 character, so a name comes through whole and no row is invalid for its
/// encoding alone. The command line says once which encoding it assumed.
pub fn windows_1252(bytes: &[u8]) -> bool {
    let bom = [&b"\xEF\xBB\xBF"[..], b"\xFF\xFE", b"\xFE\xFF"]
        .iter()
        .any(|b| bytes.starts_with(b));
    !bom && std::str::from_utf8(bytes).is_err()
}

/// The lines of `text`, each with its number (from 1): a line ends at `\n`, `\r\n` or a lone
/// `\r`, and the line end is not part of it.
pub fn lines(text: &[u8]) -> impl Iterator<Item = (u64, &[u8])> {
    let mut rest = text;
    let mut number = 0u64;
    std::iter::from_fn(move || {
        if rest.is_empty() {
            return None;
        }
        number += 1;
        let end = rest
            .iter()
            .position(|&b| b == b'\n' || b == b'\r')
            .unwrap_or(rest.len());
        let line = &rest[..end];
        let skip = match rest.get(end..end + 2) {
            Some(b"\r\n") => 2,
            _ if end < rest.len() => 1,
            _ => 0,
        };
        rest = &rest[end + skip..];
        Some((number, line))
    })
}

/// The fields of one line separated by `delimiter`. A field may be quoted (`"0.5, 0.5, 0.5"`,
/// `""` for a quote inside); a quote must close on its line (a row is one line: no answer
/// spans lines), and nothing but spaces may follow a closing quote (`"s2"x` is refused, not read
/// as `s2x`). Quotes that pair up inside an unquoted field are kept as written
/// (`=HYPERLINK("x")`); a lone one (`2"`: the rest of a cell that a line break cut, or a typo)
/// is refused. Empty fields after the third are dropped (a spreadsheet writes its empty columns
/// as trailing separators).
pub fn fields(line: &[u8], delimiter: u8) -> Result<Vec<Vec<u8>>, NotCsv> {
    let mut out: Vec<Vec<u8>> = Vec::new();
    let mut i = 0;
    loop {
        let blank = |b: u8| b == b' ' || (b == b'\t' && delimiter != b'\t');
        let mut j = i;
        while j < line.len() && blank(line[j]) {
            j += 1;
        }
        let mut field = Vec::new();
        if line.get(j) == Some(&b'"') {
            let n = out.len() + 1;
            let mut k = j + 1;
            loop {
                match line.get(k) {
                    None => return Err(NotCsv::Unclosed { field: n }),
                    Some(b'"') if line.get(k + 1) == Some(&b'"') => {
                        field.push(b'"');
                        k += 2;
                    }
                    Some(b'"') => {
                        k += 1;
                        break;
                    }
                    Some(&b) => {
                        field.push(b);
                        k += 1;
                    }
                }
            }
            while k < line.len() && blank(line[k]) {
                k += 1;
            }
            match line.get(k) {
                None => {
                    out.push(field);
                    break;
                }
                Some(&b) if b == delimiter => {
                    out.push(field);
                    i = k + 1;
                }
                Some(_) => {
                    return Err(NotCsv::AfterQuote {
                        field: n,
                        after: visible(&String::from_utf8_lossy(&line[k..]))
                            .chars()
                            .take(20)
                            .collect(),
                    })
                }
            }
        } else {
            let end = line[i..]
                .iter()
                .position(|&b| b == delimiter)
                .map_or(line.len(), |p| i + p);
            if line[i..end].iter().filter(|&&b| b == b'"').count() % 2 == 1 {
                return Err(NotCsv::StrayQuote {
                    field: out.len() + 1,
                });
            }
            out.push(line[i..end].to_vec());
            if end == line.len() {
                break;
            }
            i = end + 1;
        }
    }
    while out.len() > 3
        && out
            .last()
            .is_some_and(|f| f.iter().all(u8::is_ascii_whitespace))
    {
        out.pop();
    }
    Ok(out)
}

/// The most lines a quoted cell holding line breaks is looked for over: a quote left open
/// that no quote closes within them is a quote left open, and the lines after it are rows.
const CELL_LINES: u64 = 100;

/// Where a quoted field left open at the end of a line closes, as RFC 4180 reads a quoted
/// field holding line breaks: the number of line ends after the line (from 1) to the line whose
/// quote closes it, when that quote is a field's end (spaces, then the separator or the line's
/// end) within [`CELL_LINES`] lines. `rest` is the text after the line, from its line end.
/// `None` when the first lone quote is not such an end (`"0,5 0,7` then `bia;4.1;"0,5 …"`: a
/// quote left open, and a later row's quoted field) or there is none.
///
/// phong does not read such a cell as part of its row (a row is one line: docs on `fields`);
/// it finds the lines the cell spans so that each is an invalid line that says so, and none is
/// read as a row of its own (`"s⏎2",4.1,…` would make a student `2"`).
fn cell_closes(rest: &[u8], delimiter: u8) -> Option<u64> {
    let mut ends = 0u64;
    let mut k = 0;
    while k < rest.len() {
        match rest[k] {
            b'\r' | b'\n' => {
                if rest[k] == b'\r' && rest.get(k + 1) == Some(&b'\n') {
                    k += 1;
                }
                ends += 1;
                if ends > CELL_LINES {
                    return None;
                }
            }
            b'"' if rest.get(k + 1) == Some(&b'"') => k += 1,
            b'"' => {
                let after = rest[k + 1..]
                    .iter()
                    .find(|&&b| b != b' ' && (b != b'\t' || delimiter == b'\t'));
                return match after {
                    None | Some(b'\r' | b'\n') => Some(ends),
                    Some(&b) if b == delimiter => Some(ends),
                    Some(_) => None,
                };
            }
            _ => {}
        }
        k += 1;
    }
    None
}

/// A line with nothing in it: only spaces, or only separators and spaces (a spreadsheet's
/// empty row). It is not a row.
fn is_blank(line: &[u8], delimiter: u8) -> bool {
    line.iter()
        .all(|&b| b.is_ascii_whitespace() || b == delimiter)
}

/// The names a header gives each column, in English and Portuguese (compared lowercased): the
/// three columns of every file, then the optional steps column.
const HEADER_NAMES: [&[&str]; 4] = [
    &["student", "aluno", "estudante"],
    &["exercise", "exercicio", "exercício", "questao", "questão"],
    &["answer", "resposta"],
    &["steps", "passos", "etapas"],
];

/// Where each column is in a row: student, exercise and answer, and the optional steps
/// column with its name as the header writes it.
#[derive(Clone, Debug, PartialEq)]
struct Layout {
    at: [usize; 3],
    steps: Option<(usize, String)>,
}

impl Default for Layout {
    /// student, exercise, answer: a file without a header.
    fn default() -> Self {
        Layout {
            at: [0, 1, 2],
            steps: None,
        }
    }
}

impl Layout {
    /// The number of columns.
    fn width(&self) -> usize {
        3 + usize::from(self.steps.is_some())
    }

    /// A row's cells in column order (student, exercise, answer, and the steps when the file
    /// has that column), or `None` when the row has another number of fields. With a steps
    /// column, a row may leave out the last cell (a spreadsheet drops an empty last column); and
    /// when the steps column is the last, fields beyond it whose first holds `=` are its cell
    /// split at the separator (`ana;4.2;0 0 0;cos_theta=0,98995; n_dot_l=-0,98995` unquoted),
    /// joined back.
    fn cells<'a>(&self, fields: &'a [Vec<u8>], delimiter: u8) -> Option<Vec<Cow<'a, [u8]>>> {
        let width = self.width();
        let mut f: Vec<Cow<'a, [u8]>> = fields.iter().map(|x| Cow::Borrowed(&x[..])).collect();
        if let Some((at, _)) = &self.steps {
            if f.len() + 1 == width {
                f.push(Cow::Borrowed(&[]));
            } else if f.len() > width && *at + 1 == width && f[*at].contains(&b'=') {
                let tail = fields[*at..].join(&[delimiter][..]);
                f.truncate(*at);
                f.push(Cow::Owned(tail));
            }
        }
        if f.len() != width {
            return None;
        }
        let mut out: Vec<Cow<'a, [u8]>> = self.at.iter().map(|&i| f[i].clone()).collect();
        if let Some((at, _)) = &self.steps {
            out.push(std::mem::take(&mut f[*at]));
        }
        Some(out)
    }
}

/// What a first line is.
#[derive(Debug, PartialEq)]
enum First {
    /// A header: the columns it names, in its order.
    Header(Layout),
    /// Column names only, but not a header phong can read (a column missing or twice): why.
    BadHeader(HeaderFault),
    /// A row of data.
    Row,
}

/// What the first line's fields are. A header is a row of three or four fields, each naming a
/// different column, student, exercise and answer among them (steps is optional); a line of
/// two or more fields that are all column names but not such a header is a header phong
/// refuses, with the reason. A row whose student is `Student` but whose other fields are data
/// is a row.
fn header(fields: &[Vec<u8>]) -> First {
    let mut columns = Vec::with_capacity(fields.len());
    let mut names = Vec::with_capacity(fields.len());
    for f in fields {
        let Ok(text) = std::str::from_utf8(f) else {
            return First::Row;
        };
        let name = text.trim().to_lowercase();
        let Some(column) = HEADER_NAMES
            .iter()
            .position(|names| names.contains(&name.as_str()))
        else {
            return First::Row;
        };
        columns.push(column);
        names.push(text.trim().to_owned());
    }
    if columns.len() < 2 {
        return First::Row;
    }
    if let Some(twice) = (0..4).find(|c| columns.iter().filter(|&x| x == c).count() > 1) {
        return First::BadHeader(HeaderFault::Twice {
            column: Column::ALL[twice],
        });
    }
    if let Some(missing) = (0..3).find(|c| !columns.contains(c)) {
        return First::BadHeader(HeaderFault::Missing {
            column: Column::ALL[missing],
        });
    }
    let position = |column: usize| columns.iter().position(|&c| c == column);
    First::Header(Layout {
        at: [0, 1, 2].map(|c| position(c).expect("checked above")),
        steps: position(3).map(|at| (at, names[at].clone())),
    })
}

/// The separator of the submissions: the one under which the first line that holds data is a
/// header; else the one that splits the most of the first 100 such lines into exactly three
/// fields (`,` before `;` before a tab on a tie; `,` when none does).
pub fn delimiter(text: &[u8]) -> u8 {
    const CANDIDATES: [u8; 3] = [b',', b';', b'\t'];
    let sample: Vec<&[u8]> = lines(text)
        .map(|(_, l)| l)
        .filter(|l| !l.iter().all(u8::is_ascii_whitespace))
        .take(100)
        .collect();
    let Some(first) = sample.first() else {
        return b',';
    };
    for d in CANDIDATES {
        if fields(first, d).is_ok_and(|f| header(&f) != First::Row) {
            return d;
        }
    }
    let score = |d: u8| {
        sample
            .iter()
            .filter(|l| fields(l, d).is_ok_and(|f| f.len() == 3))
            .count()
    };
    let mut best = (0, b',');
    for d in CANDIDATES {
        let s = score(d);
        if s > best.0 {
            best = (s, d);
        }
    }
    best.1
}

/// A cell echoed in the report: lossy UTF-8, trimmed, with NUL and other control characters
/// (but tabs) shown as U+FFFD.
fn echo(f: &[u8]) -> String {
    visible(String::from_utf8_lossy(f).trim())
}

/// A field of a line that cannot be read as CSV, as a reader would take it: spaces around it
/// dropped, and the quotes around it when it has both (`"carla"` is `carla`).
fn unquote(field: &[u8]) -> &[u8] {
    let t = field.trim_ascii();
    match t {
        [b'"', inner @ .., b'"'] => inner,
        _ => t,
    }
}

/// `text` with NUL and other control characters (but tabs) shown as U+FFFD.
fn visible(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() && c != '\t' {
                '\u{FFFD}'
            } else {
                c
            }
        })
        .collect()
}

/// Grades CSV text (bytes, so that a row of bad UTF-8 is reported rather than fatal). Every
/// line that holds data is one row of the report, in order, whatever is wrong with it; blank
/// lines and a header are not rows. The whole report is in memory; [`Graded`] gives the same
/// rows one at a time.
pub fn grade_bytes(bytes: &[u8], options: &Options) -> Report {
    Graded::new(bytes, options).report()
}

/// A row's place in the text, and the answers it is counted among.
#[derive(Clone, Copy, Debug)]
struct At {
    /// The offset of the line in the text.
    start: usize,
    /// The line's number (from 1).
    line: u64,
    /// The line's length.
    len: u32,
    /// Its [`Group`], or [`NO_STUDENT`], or [`UNCOUNTED`].
    group: u32,
}

/// A row without a student: it counts for no one.
const NO_STUDENT: u32 = u32::MAX;
/// A row that counts for no one from the start: a header phong refuses, a Moodle export that
/// cannot be read.
const UNCOUNTED: u32 = u32::MAX - 1;

/// One student's answers to one exercise: the row that counts (`--duplicates`).
#[derive(Clone, Copy, Debug)]
struct Group {
    student: u32,
    /// The exercise (without `.json`), an index in [`Graded::exercise_names`].
    exercise: u32,
    /// The row that counts.
    winner: u32,
    /// Its points.
    points: f64,
    /// The student's next group ([`NO_STUDENT`]: none).
    next: u32,
}

/// The students in the order they first appear: their names end to end (one allocation, not
/// one per student), and while the rows are read, an index from a name's hash.
#[derive(Debug, Default)]
struct Students {
    names: String,
    ends: Vec<usize>,
    /// Each student's first group ([`NO_STUDENT`]: none yet).
    first_group: Vec<u32>,
    by_hash: std::collections::HashMap<u64, u32>,
    /// The students whose name's hash another name has.
    collided: std::collections::HashMap<String, u32>,
}

impl Students {
    fn len(&self) -> usize {
        self.ends.len()
    }

    fn name(&self, s: usize) -> &str {
        let start = if s == 0 { 0 } else { self.ends[s - 1] };
        &self.names[start..self.ends[s]]
    }

    /// The student named `name`, added if new.
    fn id(&mut self, name: &str) -> u32 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        name.hash(&mut h);
        let hash = h.finish();
        match self.by_hash.get(&hash) {
            Some(&s) if self.name(s as usize) == name => s,
            Some(_) => match self.collided.get(name) {
                Some(&s) => s,
                None => {
                    let s = self.push(name);
                    self.collided.insert(name.to_owned(), s);
                    s
                }
            },
            None => {
                let s = self.push(name);
                self.by_hash.insert(hash, s);
                s
            }
        }
    }

    fn push(&mut self, name: &str) -> u32 {
        self.names.push_str(name);
        self.ends.push(self.names.len());
        self.first_group.push(NO_STUDENT);
        (self.ends.len() - 1) as u32
    }
}

/// The submissions graded, kept as little as the reports need: each row's place in the text
/// (a row is graded again, from its line, when it is written), the row that counts for each
/// student's exercise, the summary per exercise and the students. A report is then written one
/// row at a time ([`Graded::row`]), in bounded memory whatever the number of rows: 1,000,000
/// rows take tens of bytes each, not the kilobytes of their [`RowOut`].
pub struct Graded<'a> {
    options: &'a Options,
    text: Cow<'a, [u8]>,
    delimiter: u8,
    layout: Layout,
    /// Why the first line is a header phong refuses (row 1), or why the Moodle export cannot be
    /// read (the only row).
    refused: Option<Reason>,
    cache: std::cell::RefCell<Cache<'a>>,
    at: Vec<At>,
    /// The rows (from 0, in order) that are the rest of a quoted cell of an earlier row's line
    /// ([`cell_closes`]): each is invalid and no one's.
    continues: Vec<u32>,
    groups: Vec<Group>,
    exercise_names: Vec<String>,
    students: Students,
    summary: Vec<SummaryOut>,
    exercises: BTreeMap<String, f64>,
    max_points: f64,
}

impl<'a> Graded<'a> {
    /// Reads and grades `bytes` (the submissions file), as [`grade_bytes`] does.
    pub fn new(bytes: &'a [u8], options: &'a Options) -> Graded<'a> {
        let decoded = decode(bytes);
        let moodle = match options.input {
            Input::Moodle => true,
            Input::Csv => false,
            Input::Auto => super::moodle::is_responses(&decoded),
        };
        let mut forced = options.delimiter;
        let mut refused = None;
        let text = if moodle {
            let questions = if options.questions.is_empty() {
                folder_exercises(&options.exercises)
            } else {
                options.questions.clone()
            };
            forced = Some(b',');
            match super::moodle::to_rows(&decoded, &questions, options.delimiter) {
                Ok(rows) => Cow::Owned(rows),
                Err(why) => {
                    refused = Some(Reason::from(why));
                    Cow::Owned(Vec::new())
                }
            }
        } else {
            decoded
        };
        let d = forced.unwrap_or_else(|| delimiter(&text));
        let mut graded = Graded {
            options,
            delimiter: d,
            layout: Layout::default(),
            cache: std::cell::RefCell::new(Cache {
                options,
                folder: std::fs::canonicalize(&options.exercises).ok(),
                solved: BTreeMap::new(),
            }),
            at: Vec::new(),
            continues: Vec::new(),
            groups: Vec::new(),
            exercise_names: Vec::new(),
            students: Students::default(),
            summary: Vec::new(),
            exercises: BTreeMap::new(),
            max_points: 0.0,
            refused: None,
            text,
        };
        if let Some(why) = refused {
            graded.refused = Some(why);
            graded.at.push(At {
                start: 0,
                line: 1,
                len: 0,
                group: UNCOUNTED,
            });
        } else {
            graded.find_rows();
        }
        graded.grade();
        graded
    }

    /// Where each row is: every line that holds data, but a header.
    fn find_rows(&mut self) {
        let d = self.delimiter;
        let text: &[u8] = &self.text;
        let base = text.as_ptr() as usize;
        let mut at = Vec::new();
        let mut first = true;
        // The last line of a quoted cell holding line breaks, opened on an earlier line.
        let mut cell_until = 0;
        for (line, content) in lines(text) {
            if is_blank(content, d) {
                continue;
            }
            let start = content.as_ptr() as usize - base;
            if line <= cell_until {
                self.continues.push(at.len() as u32);
            } else if let Err(NotCsv::Unclosed { .. }) = fields(content, d) {
                if let Some(k) = cell_closes(&text[start + content.len()..], d) {
                    cell_until = line + k;
                }
            }
            let mut group = 0;
            if std::mem::take(&mut first) {
                match fields(content, d).as_ref().map(|f| header(f)) {
                    Ok(First::Header(l)) => {
                        self.layout = l;
                        continue;
                    }
                    // Reported in the header's place (no line is dropped); the rows after it
                    // are read as student, exercise, answer. It is no student's.
                    Ok(First::BadHeader(why)) => {
                        self.refused = Some(why.into());
                        group = UNCOUNTED;
                    }
                    _ => {}
                }
            }
            at.push(At {
                start,
                line,
                len: u32::try_from(content.len()).unwrap_or(u32::MAX),
                group,
            });
        }
        self.at = at;
    }

    /// Grades every row once: the summary per exercise, the row that counts for each student's
    /// exercise, the students and the exercises.
    fn grade(&mut self) {
        let mut tallies: BTreeMap<String, (SummaryOut, BTreeMap<Vec<Slip>, usize>)> =
            BTreeMap::new();
        let mut exercise_ids: BTreeMap<String, u32> = BTreeMap::new();
        for i in 0..self.at.len() {
            let r = self.graded_row(i);
            // The summary.
            let key = exercise_key(&r.exercise);
            if !tallies.contains_key(key) {
                let summary = SummaryOut {
                    exercise: key.to_owned(),
                    ..SummaryOut::default()
                };
                tallies.insert(key.to_owned(), (summary, BTreeMap::new()));
            }
            let (summary, slips) = tallies.get_mut(key).expect("inserted above");
            summary.rows += 1;
            match r.verdict {
                "right" => summary.right += 1,
                "reading" => summary.reading += 1,
                "wrong" => summary.wrong += 1,
                _ => summary.invalid += 1,
            }
            if r.verdict == "wrong" && r.diagnosis.is_empty() {
                summary.unnamed += 1;
            }
            for d in &r.diagnosis {
                match slips.get_mut(d.as_slice()) {
                    Some(n) => *n += 1,
                    None => {
                        slips.insert(d.clone(), 1);
                    }
                }
            }
            // The row that counts.
            if self.at[i].group == UNCOUNTED {
                continue;
            }
            if r.student.is_empty() {
                self.at[i].group = NO_STUDENT;
                continue;
            }
            let student = self.students.id(&r.student);
            let exercise = match exercise_ids.get(key) {
                Some(&e) => e,
                None => {
                    let e = self.exercise_names.len() as u32;
                    self.exercise_names.push(key.to_owned());
                    exercise_ids.insert(key.to_owned(), e);
                    e
                }
            };
            let mut g = self.students.first_group[student as usize];
            while g != NO_STUDENT && self.groups[g as usize].exercise != exercise {
                g = self.groups[g as usize].next;
            }
            let row = i as u32;
            if g == NO_STUDENT {
                g = self.groups.len() as u32;
                self.groups.push(Group {
                    student,
                    exercise,
                    winner: row,
                    points: r.points,
                    next: self.students.first_group[student as usize],
                });
                self.students.first_group[student as usize] = g;
            } else {
                let group = &mut self.groups[g as usize];
                let replaces = match self.options.policy.duplicates {
                    Duplicates::First => false,
                    Duplicates::Last => true,
                    // The most points; the first of those on a tie.
                    Duplicates::Best => r.points > group.points,
                };
                if replaces {
                    group.winner = row;
                    group.points = r.points;
                }
            }
            self.at[i].group = g;
        }
        self.students.by_hash = Default::default();
        self.students.collided = Default::default();
        let mut summary: Vec<SummaryOut> = tallies
            .into_values()
            .map(|(mut summary, slips)| {
                let mut counts: Vec<SlipCount> = slips
                    .into_iter()
                    .map(|(slips, count)| SlipCount { slips, count })
                    .collect();
                // Most common first, then single slips before pairs, then the slips' order:
                // stable.
                counts.sort_by(|a, b| {
                    (b.count, a.slips.len(), &a.slips).cmp(&(a.count, b.slips.len(), &b.slips))
                });
                summary.slips = counts;
                summary
            })
            .collect();
        summary.sort_by(|a, b| natural_order(&a.exercise, &b.exercise));
        self.summary = summary;
        let options = self.options;
        let mut exercises: BTreeMap<String, f64> = self
            .cache
            .borrow()
            .solved
            .iter()
            .filter(|(_, e)| e.is_ok())
            .map(|(k, _)| (k.clone(), options.policy.points_of(k)))
            .collect();
        for (k, &p) in &options.policy.points {
            exercises.insert(k.clone(), p);
        }
        self.max_points = exercises.values().sum();
        self.exercises = exercises;
    }

    /// Row `i` graded from its line, before the students' answers are counted.
    fn graded_row(&self, i: usize) -> RowOut {
        let at = self.at[i];
        let options = self.options;
        let mut row = blank_row(i + 1, at.line);
        if let (Some(why), UNCOUNTED) = (&self.refused, at.group) {
            row.counted = false;
            mark_invalid(&mut row, why.clone(), options.lang);
            return row;
        }
        let content = &self.text[at.start..at.start + at.len as usize];
        let d = self.delimiter;
        let cache = &mut *self.cache.borrow_mut();
        match self.cell(i).map_or_else(|| fields(content, d), Err) {
            Ok(f) => grade_row(&mut row, &f, &self.layout, d, options, cache),
            Err(e) => {
                // The student and the exercise as the line starts, so that the row stands under
                // its student's exercise (in the totals and the platforms' reports) rather than
                // leaving it unanswered: only the cells before the one that cannot be read,
                // which are whole (`"s⏎2",…`'s second line is no student `2"`).
                let mut cells = content
                    .split(|&b| b == d)
                    .map(unquote)
                    .take(e.field().saturating_sub(1));
                row.student = echo(cells.next().unwrap_or_default());
                row.exercise = echo(cells.next().unwrap_or_default());
                if let Some(point) = comma_exercise(&row.exercise, cache) {
                    row.exercise = point;
                }
                if !row.exercise.is_empty() && cache.get(&row.exercise).is_ok() {
                    row.max_points = Some(options.policy.points_of(&row.exercise));
                }
                let reason = RowReason::NotCsv { why: e }.into();
                mark_invalid(&mut row, reason, options.lang);
            }
        }
        row
    }

    /// Why row `i` is not read from its line alone, when its line is part of a quoted cell
    /// holding line breaks ([`cell_closes`]): the rest of an earlier row's cell, or the line
    /// that opens one.
    fn cell(&self, i: usize) -> Option<NotCsv> {
        let is_rest = |j: usize| self.continues.binary_search(&(j as u32)).is_ok();
        let field_of = |j: usize| {
            let at = self.at[j];
            let content = &self.text[at.start..at.start + at.len as usize];
            match fields(content, self.delimiter) {
                Err(NotCsv::Unclosed { field }) => field,
                _ => 1,
            }
        };
        if is_rest(i) {
            let opener = (0..i).rev().find(|&j| !is_rest(j))?;
            return Some(NotCsv::Continues {
                field: field_of(opener),
                line: self.at[opener].line,
            });
        }
        if !is_rest(i + 1) {
            return None;
        }
        let last = (i + 1..self.at.len()).take_while(|&j| is_rest(j)).last()?;
        Some(NotCsv::LineBreak {
            field: field_of(i),
            last: self.at[last].line,
        })
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.at.len()
    }

    /// Whether there is no row.
    pub fn is_empty(&self) -> bool {
        self.at.is_empty()
    }

    /// Row `i` (from 0) as the report gives it: graded, and marked when it does not count (a
    /// student's other answer to an exercise, by `--duplicates`; a row without a student).
    pub fn row(&self, i: usize) -> RowOut {
        let mut r = self.graded_row(i);
        let lang = self.options.lang;
        match self.at[i].group {
            UNCOUNTED => {}
            NO_STUDENT => {
                r.counted = false;
                r.feedback.insert_str(0, messages::no_student(lang));
            }
            g => {
                let winner = self.groups[g as usize].winner as usize;
                if winner != i {
                    r.counted = false;
                    let note = messages::not_counted(
                        winner + 1,
                        self.at[winner].line,
                        self.options.policy.duplicates.word(),
                        lang,
                    );
                    r.feedback.insert_str(0, &note);
                }
            }
        }
        r
    }

    /// The rows, in input order, each graded as it is asked for.
    pub fn rows(&self) -> impl Iterator<Item = RowOut> + use<'_, 'a> {
        (0..self.len()).map(|i| self.row(i))
    }

    /// One entry per exercise, in natural order (4.2 before 4.10).
    pub fn summary(&self) -> &[SummaryOut] {
        &self.summary
    }

    /// The exercises graded, in name order, with their points.
    pub fn exercises(&self) -> &BTreeMap<String, f64> {
        &self.exercises
    }

    /// The number of students.
    pub fn students(&self) -> usize {
        self.students.len()
    }

    /// The name of student `s` (from 0, in the order they first appear).
    pub fn student_name(&self, s: usize) -> &str {
        self.students.name(s)
    }

    /// Student `s`'s total.
    pub fn student(&self, s: usize) -> StudentOut {
        // The student's exercises in name order: their points are added in that order.
        let mut groups = Vec::new();
        let mut g = self.students.first_group[s];
        while g != NO_STUDENT {
            groups.push(&self.groups[g as usize]);
            g = self.groups[g as usize].next;
        }
        groups.sort_by(|a, b| {
            self.exercise_names[a.exercise as usize].cmp(&self.exercise_names[b.exercise as usize])
        });
        let mut out = StudentOut {
            student: self.students.name(s).to_owned(),
            points: 0.0,
            max_points: self.max_points,
            exercises: self.exercises.keys().map(|k| (k.clone(), None)).collect(),
            rows: BTreeMap::new(),
        };
        for group in groups {
            let exercise = &self.exercise_names[group.exercise as usize];
            if self.exercises.contains_key(exercise) {
                out.points += group.points;
                out.exercises.insert(exercise.clone(), Some(group.points));
                out.rows.insert(exercise.clone(), group.winner as usize);
            }
        }
        out
    }

    /// Each student's rows (the indices of their rows, in input order), and the rows without
    /// a student.
    pub(crate) fn rows_by_student(&self) -> (Vec<Vec<u32>>, Vec<u32>) {
        let mut by: Vec<Vec<u32>> = vec![Vec::new(); self.students()];
        let mut nobody = Vec::new();
        for (i, at) in self.at.iter().enumerate() {
            match at.group {
                NO_STUDENT | UNCOUNTED => nobody.push(i as u32),
                g => by[self.groups[g as usize].student as usize].push(i as u32),
            }
        }
        (by, nobody)
    }

    /// The whole report in memory.
    pub fn report(&self) -> Report {
        Report {
            format_version: CHECK_FORMAT_VERSION,
            rows: self.rows().collect(),
            summary: self.summary.clone(),
            exercises: self.exercises.clone(),
            students: (0..self.students()).map(|s| self.student(s)).collect(),
        }
    }

    /// The report as JSON, as [`Report`] serialises, written to `w` one row at a time.
    pub fn write_json(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        /// A sequence serialised as its items are made.
        struct Lazy<I>(std::cell::RefCell<Option<I>>);
        impl<I: Iterator<Item = T>, T: Serialize> Serialize for Lazy<I> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let items = self.0.borrow_mut().take().expect("serialised once");
                s.collect_seq(items)
            }
        }
        #[derive(Serialize)]
        struct Streamed<'r, R: Serialize, S: Serialize> {
            format_version: u32,
            rows: R,
            summary: &'r [SummaryOut],
            exercises: &'r BTreeMap<String, f64>,
            students: S,
        }
        let doc = Streamed {
            format_version: CHECK_FORMAT_VERSION,
            rows: Lazy(std::cell::RefCell::new(Some(self.rows()))),
            summary: &self.summary,
            exercises: &self.exercises,
            students: Lazy(std::cell::RefCell::new(Some(
                (0..self.students()).map(|s| self.student(s)),
            ))),
        };
        serde_json::to_writer_pretty(&mut *w, &doc).map_err(std::io::Error::from)?;
        w.write_all(b"\n")
    }

    /// The per-row report as CSV ([`rows_csv`]), written to `w` one row at a time.
    pub fn write_rows_csv(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        write_rows_csv(w, self.rows())
    }

    /// The summary per exercise as CSV.
    pub fn write_summary_csv(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        write_summary_csv(w, &self.summary)
    }

    /// Each student's total as CSV ([`students_csv`]), one student at a time.
    pub fn write_students_csv(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        write_students_csv(
            w,
            &self.exercises,
            (0..self.students()).map(|s| self.student(s)),
        )
    }
}

/// A row that cannot be judged: its reason, and feedback saying so (with its exercise's points
/// when the exercise is known).
fn mark_invalid(row: &mut RowOut, reason: Reason, lang: Lang) {
    row.feedback = messages::feedback(
        &messages::RowFacts {
            verdict: None,
            reason: Some(&reason as &dyn crate::text::Message),
            tolerance: 0.0,
            read_as_8bit: false,
            points: row.max_points.map(|m| (0.0, m)),
        },
        lang,
    );
    row.reason = Some(reason);
}

/// A row not yet graded: invalid, no student, nothing compared.
fn blank_row(row: usize, line: u64) -> RowOut {
    RowOut {
        row,
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
        scale_detected: false,
        points: 0.0,
        max_points: None,
        counted: true,
        feedback: String::new(),
        steps_text: String::new(),
        steps: None,
    }
}

fn grade_row(
    row: &mut RowOut,
    fields: &[Vec<u8>],
    layout: &Layout,
    delimiter: u8,
    options: &Options,
    cache: &mut Cache,
) {
    let cells = layout.cells(fields, delimiter);
    // The cells by column; a row of another width, as its fields come.
    let cell = |column: usize| -> &[u8] {
        match &cells {
            Some(c) => c.get(column).map_or(&[][..], |x| &x[..]),
            None => fields.get(column).map_or(&[][..], |x| &x[..]),
        }
    };
    row.student = echo(cell(0));
    row.exercise = echo(cell(1));
    row.answer = echo(cell(2));
    if layout.steps.is_some() {
        row.steps_text = echo(cell(3));
    }
    let invalid = |row: &mut RowOut, reason: Reason| mark_invalid(row, reason, options.lang);
    let width = layout.width();
    let Some(cells) = &cells else {
        let other = [b',', b';', b'\t']
            .into_iter()
            .find(|&o| o != delimiter && fields.iter().any(|f| f.contains(&o)));
        let hint = match other {
            Some(o) if fields.len() < width => FieldsHint::OtherSeparator {
                read: Sep(delimiter),
                found: Sep(o),
                flag: if o == b'\t' {
                    "tab".to_owned()
                } else {
                    (o as char).to_string()
                },
            },
            _ if fields.len() > width && width == 3 => FieldsHint::QuoteAnswer {
                sep: Sep(delimiter),
            },
            _ if fields.len() > width => FieldsHint::QuoteAnswerOrSteps {
                sep: Sep(delimiter),
            },
            _ => FieldsHint::Nothing,
        };
        let reason = RowReason::Fields {
            count: Fields(fields.len()),
            expected: Width { steps: width != 3 },
            hint,
        };
        return invalid(row, reason.into());
    };
    for (&column, f) in Column::ALL.iter().zip(cells) {
        if std::str::from_utf8(f).is_err() {
            return invalid(row, RowReason::NotUtf8 { column }.into());
        }
        if f.contains(&0) {
            return invalid(row, RowReason::Nul { column }.into());
        }
    }
    let empty = [&row.student, &row.exercise, &row.answer]
        .iter()
        .position(|v| v.is_empty());
    if let Some(i) = empty {
        let column = Column::ALL[i];
        return invalid(row, RowReason::Empty { column }.into());
    }
    let note = comma_exercise(&row.exercise, cache).map(|point| {
        let note = ExerciseNote::Comma {
            written: row.exercise.clone(),
            point: point.clone(),
        };
        row.exercise = point;
        note
    });
    let exercise = match cache.get(&row.exercise) {
        Ok(e) => e,
        Err(e) => return invalid(row, e.clone()),
    };
    let Exercise { expected, key, .. } = exercise;
    row.max_points = Some(options.policy.points_of(&row.exercise));
    // A Cloze response from Moodle with blank parts (`part 1: 0,5; part 2: ; part 3: 0,3`): a
    // blank part is no answer for its channel, so the colour is incomplete and the row wrong,
    // its feedback naming the blank parts; every part blank is nothing to judge (invalid).
    // Why, in super::moodle::blank.
    match super::moodle::blank(&row.answer) {
        None => {}
        Some(all @ super::moodle::Blank::All) => return invalid(row, Reason::Cloze(all)),
        Some(some) => {
            let scale = options.scale.unwrap_or(Scale::Unit);
            let tolerance = options
                .policy
                .tolerance(scale, key.and_then(|k| k.tolerance_on(scale)));
            let max = options.policy.points_of(&row.exercise);
            row.verdict = verdict_code(VerdictKind::Wrong);
            row.accepted = false;
            row.scale = Some(scale_number(scale));
            row.tolerance = Some(tolerance);
            row.points = 0.0;
            let lang = options.lang;
            let mut text = [
                messages::verdict(VerdictKind::Wrong, false, lang).to_owned(),
                crate::text::Message::text(&some, lang),
                messages::total(0.0, max, lang),
            ]
            .join("; ");
            if let Some(first) = text.chars().next() {
                text.replace_range(..first.len_utf8(), &first.to_uppercase().to_string());
            }
            text.push('.');
            row.feedback = text;
            row.reason = Some(Reason::Cloze(some));
            return;
        }
    }
    let a = match options.policy.read(&row.answer, options.scale) {
        Ok(read) => {
            row.scale_detected = read.as_8bit;
            read.answer
        }
        Err(e) => {
            let why = Said::new(e);
            return invalid(row, RowReason::Answer { why }.into());
        }
    };
    // The steps, read and judged against the exercise's quantities; a step that cannot be read
    // or judged is the row's error, naming the row, the column, the step as written and the fix.
    let judged = match &layout.steps {
        Some((_, column)) if !row.steps_text.is_empty() => {
            let at = |row: &RowOut, why: Said| {
                Reason::from(RowReason::Steps {
                    row: row.row,
                    line: row.line,
                    column: column.clone(),
                    why,
                })
            };
            let given = match steps::read_cell(&row.steps_text) {
                Ok(g) => g,
                Err(e) => return invalid(row, at(row, Said::new(e))),
            };
            if given.is_empty() {
                // Separators only (`;`): no steps.
                None
            } else {
                let x = match exercise.steps() {
                    Ok(x) => x,
                    Err(e) => return invalid(row, e.clone()),
                };
                match steps::judge(x, &given, options.policy.strict) {
                    Ok(j) => Some(j),
                    Err(e) => return invalid(row, at(row, Said::new(e))),
                }
            }
        }
        _ => None,
    };
    let tolerance = options
        .policy
        .tolerance(a.scale, key.and_then(|k| k.tolerance_on(a.scale)));
    let v: Verdict = judge(expected, &a, tolerance, options.policy.strict);
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
    let answer_note = if v.looks_8bit {
        Some(AnswerNote::Looks8bit)
    } else if row.scale_detected {
        Some(AnswerNote::ReadAs8bit)
    } else if v.kind == VerdictKind::Right
        && v.comparison
            .is_some_and(|c| c.against == super::Against::Unclamped)
    {
        Some(AnswerNote::Unclamped)
    } else {
        None
    };
    if note.is_some() || answer_note.is_some() {
        row.reason = Some(Reason::Note {
            exercise: note,
            answer: answer_note,
        });
    }
    let max = options.policy.points_of(&row.exercise);
    row.points = max * options.policy.credit(v.kind);
    row.feedback = messages::feedback(
        &messages::RowFacts {
            verdict: Some(&v),
            reason: None,
            tolerance,
            read_as_8bit: row.scale_detected,
            points: Some((row.points, max)),
        },
        options.lang,
    );
    if let Some(j) = judged {
        row.feedback.push(' ');
        row.feedback.push_str(&steps::feedback(&j, options.lang));
        row.steps = Some(steps::steps_json(&j));
    }
}

/// The exercise `written` names when it is a number written with a decimal comma (`4,1`, how
/// a Brazilian spreadsheet writes the number cell 4.1 in its `;` CSV): `4.1`, when there is an
/// exercise 4.1. No exercise may be named with a comma (its file name would be refused), so the
/// reading is never ambiguous; `None` when `written` has no comma or `4.1` is not an exercise.
fn comma_exercise(written: &str, cache: &mut Cache) -> Option<String> {
    if !written.contains(',') || cache.get(written).is_ok() {
        return None;
    }
    let point = written.replace(',', ".");
    cache.get(&point).is_ok().then_some(point)
}

fn codes(slips: &[Slip]) -> String {
    slips.iter().map(|s| s.code()).collect::<Vec<_>>().join("+")
}

fn number(x: f64) -> String {
    // The shortest text that reads back as the same f64: exact and deterministic.
    format!("{x}")
}

/// A cell of text from the submissions as written into a CSV report: one that a spreadsheet
/// would take as a formula (starting with `=`, `+`, `-`, `@`, a tab or a carriage return) gets a
/// leading `'`, which spreadsheets show as text (OWASP's advice against CSV injection). So an
/// answer `-0.3 0 0` is written `'-0.3 0 0`; the JSON report keeps every cell as written.
pub fn safe_cell(text: &str) -> String {
    if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_owned()
    }
}

/// The per-row report as CSV (a header, then one line per input row, in input order).
pub fn rows_csv(report: &Report) -> Vec<u8> {
    let mut out = Vec::new();
    write_rows_csv(&mut out, report.rows.iter()).expect("writing to memory");
    out
}

/// The per-row report as CSV ([`rows_csv`]) of `rows`, written to `out` as they come.
fn write_rows_csv<R: std::borrow::Borrow<RowOut>>(
    out: &mut dyn std::io::Write,
    rows: impl Iterator<Item = R>,
) -> std::io::Result<()> {
    let mut w = csv::Writer::from_writer(out);
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
        "points",
        "max_points",
        "counted",
        "feedback",
        "steps_text",
        "step_verdicts",
        "first_wrong_step",
    ];
    w.write_record(header)?;
    for r in rows {
        let r: &RowOut = r.borrow();
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
            safe_cell(&r.student),
            safe_cell(&r.exercise),
            safe_cell(&r.answer),
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
            r.reason.as_ref().map_or(String::new(), Reason::to_string),
            number(r.points),
            r.max_points.map_or(String::new(), number),
            r.counted.to_string(),
            safe_cell(&r.feedback),
            safe_cell(&r.steps_text),
            r.steps.as_ref().map_or(String::new(), step_verdicts),
            r.steps
                .as_ref()
                .and_then(|s| s.first_wrong.as_ref())
                .map_or(String::new(), |f| step_label(f.name, f.light)),
        ])?;
    }
    w.flush()
}

/// A step's name with its light: `cos_theta[0]`.
fn step_label(name: &str, light: Option<usize>) -> String {
    match light {
        Some(i) => format!("{name}[{i}]"),
        None => name.to_owned(),
    }
}

/// The `step_verdicts` cell: each step's name and verdict in the order of the solution, a wrong
/// one's slips in brackets (`d[0]=right; I_l[0]=wrong(falloff_quadratic_not_linear)`).
fn step_verdicts(s: &StepsOut) -> String {
    s.steps
        .iter()
        .map(|x| {
            let mut cell = format!("{}={}", step_label(x.name, x.light), x.verdict.code());
            if !x.slips.is_empty() {
                cell.push('(');
                cell.push_str(
                    &x.slips
                        .iter()
                        .map(|s| s.code())
                        .collect::<Vec<_>>()
                        .join("|"),
                );
                cell.push(')');
            }
            cell
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The summary per exercise as CSV, written to `out`.
fn write_summary_csv(out: &mut dyn std::io::Write, summary: &[SummaryOut]) -> std::io::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record([
        "exercise", "rows", "right", "reading", "wrong", "invalid", "slips",
    ])?;
    for s in summary {
        let slips = s
            .slips
            .iter()
            .map(|c| format!("{}:{}", codes(&c.slips), c.count))
            .collect::<Vec<_>>()
            .join(";");
        w.write_record([
            safe_cell(&s.exercise),
            s.rows.to_string(),
            s.right.to_string(),
            s.reading.to_string(),
            s.wrong.to_string(),
            s.invalid.to_string(),
            slips,
        ])?;
    }
    w.flush()
}

/// Each student's total as CSV: `student, points, max_points`, then one column per exercise in
/// natural order, 4.2 before 4.10 (the points of the answer that counts; empty: no answer),
/// students in the order they first appear.
pub fn students_csv(report: &Report) -> Vec<u8> {
    let mut out = Vec::new();
    write_students_csv(&mut out, &report.exercises, report.students.iter())
        .expect("writing to memory");
    out
}

/// Each student's total as CSV ([`students_csv`]), written to `out` one student at a time.
fn write_students_csv<S: std::borrow::Borrow<StudentOut>>(
    out: &mut dyn std::io::Write,
    exercises: &BTreeMap<String, f64>,
    students: impl Iterator<Item = S>,
) -> std::io::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    let mut header = vec!["student".to_owned(), "points".into(), "max_points".into()];
    let mut exercises: Vec<&String> = exercises.keys().collect();
    exercises.sort_by(|a, b| natural_order(a, b));
    header.extend(exercises.iter().map(|k| safe_cell(k)));
    w.write_record(&header)?;
    for s in students {
        let s: &StudentOut = s.borrow();
        let mut line = vec![
            safe_cell(&s.student),
            number(s.points),
            number(s.max_points),
        ];
        line.extend(exercises.iter().map(|k| {
            s.exercises
                .get(*k)
                .copied()
                .flatten()
                .map_or(String::new(), number)
        }));
        w.write_record(&line)?;
    }
    w.flush()
}
