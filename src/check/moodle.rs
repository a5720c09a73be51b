//! Moodle's quiz "Responses" report, downloaded as CSV (`mod/quiz/report/responses`): one line
//! per attempt with the student's columns ("Surname", "First name", "Email address", …) and,
//! per question slot N, "Response N" and "Right answer N" (Portuguese sites: "Resposta N",
//! "Resposta correta N"). A Cloze response is its parts joined with `; `: `part 1: 0.52; part 2:
//! 0.03; part 3: 0` (`parte 1: 0,52; …` in Portuguese), read as the colour `0.52 0.03 0`.
//!
//! The export becomes the plain `student, exercise, answer` rows that [`super::grade`] reads:
//! the student is the e-mail address where there is one, else "First name Surname"; question
//! slot N is the N-th of the exercises given (`--questions 4.1,4.2,4.3`; by default the
//! exercise files of the folder in name order). A response "-" or empty (not answered) and the
//! report's "Overall average" line are not rows.

use std::fmt;

use crate::messages;
use crate::text::{Lang, Show};

/// The file is Moodle's Responses export: a header with a "Response 1" (or "Resposta 1")
/// column.
pub fn is_responses(text: &[u8]) -> bool {
    let first = super::grade::lines(text)
        .map(|(_, l)| l)
        .next()
        .unwrap_or_default();
    let first = String::from_utf8_lossy(first).to_lowercase();
    first.contains("response 1") || first.contains("resposta 1")
}

/// The question slot of a header cell: `Response 3` → 3 (`Resposta 3`); not "Right answer".
fn response_slot(cell: &str) -> Option<usize> {
    let c = cell.trim().to_lowercase();
    let rest = c
        .strip_prefix("response ")
        .or_else(|| c.strip_prefix("resposta "))?;
    rest.trim().parse().ok()
}

/// A Cloze response's parts as one answer: `part 1: 0.52; part 2: 0.03; part 3: 0` → `0.52
/// 0.03 0`; anything else as it is.
pub fn join_parts(response: &str) -> String {
    let parts: Vec<&str> = response.split(';').map(str::trim).collect();
    let values: Option<Vec<&str>> = parts
        .iter()
        .map(|p| {
            let lower = p.to_lowercase();
            let is_part = ["part ", "parte ", "partie "]
                .iter()
                .any(|w| lower.starts_with(w));
            if is_part {
                p.split_once(':').map(|(_, v)| v.trim())
            } else {
                None
            }
        })
        .collect();
    match values {
        Some(v) if parts.len() > 1 => v.join(" "),
        _ => response.trim().to_owned(),
    }
}

/// One CSV field written for [`super::grade`]'s reader: quoted, `""` for a quote.
fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

/// What the CSV reader found wrong: text that is not UTF-8 (the reader's only error on text in
/// memory read flexibly), else the reader's own words.
fn csv_error(e: &csv::Error, header: bool) -> MoodleError {
    match (e.kind(), header) {
        (csv::ErrorKind::Utf8 { pos, .. }, header) => {
            let line = pos.as_ref().map_or(0, csv::Position::line);
            if header {
                MoodleError::HeaderNotUtf8 { line }
            } else {
                MoodleError::NotUtf8 { line }
            }
        }
        (_, true) => MoodleError::Header { why: e.to_string() },
        (_, false) => MoodleError::Unreadable { why: e.to_string() },
    }
}

/// The export as `student,exercise,answer` CSV text (a header, then a row per answered
/// question); `questions[N-1]` is the exercise of slot N. Errors say what is missing.
pub fn to_rows(text: &[u8], questions: &[String]) -> Result<Vec<u8>, MoodleError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(true)
        .from_reader(text);
    let header = reader.headers().map_err(|e| csv_error(&e, true))?.clone();
    let find = |names: &[&str]| {
        header
            .iter()
            .position(|h| names.contains(&h.trim().to_lowercase().as_str()))
    };
    let email = find(&[
        "email address",
        "endereço de email",
        "endereço de e-mail",
        "email",
    ]);
    let first = find(&["first name", "nome"]);
    let surname = find(&["surname", "sobrenome"]);
    let slots: Vec<(usize, usize)> = header
        .iter()
        .enumerate()
        .filter_map(|(at, h)| response_slot(h).map(|n| (at, n)))
        .collect();
    if slots.is_empty() {
        return Err(MoodleError::NoResponse);
    }
    let mut out = String::from("student,exercise,answer\n");
    for record in reader.records() {
        let record = record.map_err(|e| csv_error(&e, false))?;
        let cell = |at: Option<usize>| at.and_then(|a| record.get(a)).unwrap_or("").trim();
        let name = format!("{} {}", cell(first), cell(surname));
        let student = match cell(email) {
            "" => name.trim().to_owned(),
            e => e.to_owned(),
        };
        let lead = record.get(0).unwrap_or("").trim().to_lowercase();
        if lead == "overall average" || lead == "média geral" {
            continue;
        }
        for &(at, n) in &slots {
            let response = record.get(at).unwrap_or("").trim();
            if response.is_empty() || response == "-" {
                continue;
            }
            let exercise = questions.get(n - 1).ok_or(MoodleError::TooFewExercises {
                slot: n,
                given: Given(questions.len()),
            })?;
            out.push_str(&format!(
                "{},{},{}\n",
                quoted(&student),
                quoted(exercise),
                quoted(&join_parts(response))
            ));
        }
    }
    Ok(out.into_bytes())
}

/// A number of exercises given: `1 exercise is given`, `2 exercises are given` (`1 exercício
/// é dado`, `2 exercícios são dados`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Given(pub usize);

impl Show for Given {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.0;
        match (lang, n) {
            (Lang::En, 1) => f.write_str("1 exercise is given"),
            (Lang::En, _) => write!(f, "{n} exercises are given"),
            (Lang::Pt, 1) => f.write_str("1 exercício é dado"),
            (Lang::Pt, _) => write!(f, "{n} exercícios são dados"),
        }
    }
}

messages! {
    /// Why a Moodle Responses export cannot be read (the report's only row says it).
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum MoodleError {
        /// The header's line is not UTF-8.
        HeaderNotUtf8 { line: u64 } =>
            "the Moodle export's header cannot be read: line {line} is not UTF-8 text. Fix: \
             save the export as UTF-8 (CSV UTF-8)",
            "o cabeçalho da exportação do Moodle não pode ser lido: a linha {line} não é texto \
             UTF-8. Correção: salve a exportação como UTF-8 (CSV UTF-8)";
        /// The header cannot be read, in the CSV reader's own words.
        Header { why: String } =>
            "the Moodle export's header cannot be read: {why}",
            "o cabeçalho da exportação do Moodle não pode ser lido: {why}";
        /// A line that is not UTF-8.
        NotUtf8 { line: u64 } =>
            "the Moodle export cannot be read: line {line} is not UTF-8 text. Fix: save the \
             export as UTF-8 (CSV UTF-8)",
            "a exportação do Moodle não pode ser lida: a linha {line} não é texto UTF-8. \
             Correção: salve a exportação como UTF-8 (CSV UTF-8)";
        /// A line that cannot be read, in the CSV reader's own words.
        Unreadable { why: String } =>
            "the Moodle export cannot be read: {why}",
            "a exportação do Moodle não pode ser lida: {why}";
        /// No question slot.
        NoResponse =>
            "the Moodle export has no \"Response 1\" column. Fix: download the quiz's \
             Responses report as CSV, or give --input csv for a plain CSV",
            "a exportação do Moodle não tem a coluna \"Response 1\". Correção: baixe o \
             relatório \"Responses\" do questionário como CSV, ou dê --input csv para um CSV \
             simples";
        /// A question slot beyond the exercises given.
        TooFewExercises { slot: usize, given: Given } =>
            "the Moodle export has a \"Response {slot}\" column but only {given}: name one per \
             question slot with --questions",
            "a exportação do Moodle tem uma coluna \"Response {slot}\", mas só {given}: dê um \
             por pergunta com --questions";
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cloze_parts_become_one_colour() {
        assert_eq!(
            join_parts("part 1: 0.52; part 2: 0.03; part 3: 0"),
            "0.52 0.03 0"
        );
        assert_eq!(
            join_parts("parte 1: 0,52; parte 2: 0,03; parte 3: 0"),
            "0,52 0,03 0"
        );
        assert_eq!(join_parts("none"), "none");
        assert_eq!(join_parts("0.52; 0.03; 0"), "0.52; 0.03; 0");
    }

    #[test]
    fn responses_become_rows() {
        let csv = "Surname,First name,Email address,State,Grade/3.00,Response 1,Right answer 1,\
                   Response 2,Right answer 2\n\
                   Silva,Ana,ana@x.br,Finished,1.00,\"part 1: 0.52; part 2: 0.03; part 3: 0\",\
                   \"part 1: 0.52; part 2: 0.03; part 3: 0\",-,x\n\
                   Overall average,,,,1.00,,,,\n";
        assert!(is_responses(csv.as_bytes()));
        let rows = to_rows(csv.as_bytes(), &["4.1".into(), "4.3".into()]).unwrap();
        assert_eq!(
            String::from_utf8(rows).unwrap(),
            "student,exercise,answer\n\"ana@x.br\",\"4.1\",\"0.52 0.03 0\"\n"
        );
        assert!(to_rows(csv.as_bytes(), &["4.1".into()]).is_ok());
    }
}
