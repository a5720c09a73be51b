//! Moodle's quiz "Responses" report, downloaded as CSV (`mod/quiz/report/responses`): one line
//! per attempt with the student's columns ("Surname", "First name", "Email address", …) and,
//! per question slot N, "Response N" and "Right answer N" (Portuguese sites: "Resposta N",
//! "Resposta correta N"). A Cloze response is its parts joined with `; `: `part 1: 0.52; part 2:
//! 0.03; part 3: 0` (`parte 1: 0,52; …` in Portuguese), read as the colour `0.52 0.03 0`; a
//! one-part response, `part 1: nenhuma`, as `nenhuma`. A response with a blank part (`part 2: `)
//! is judged wrong, the blank parts named ([`blank`] says why); one whose every part is blank is
//! invalid.
//!
//! The export becomes the plain `student, exercise, answer` rows that [`super::grade`] reads:
//! the student is the e-mail address where there is one, else "First name Surname"; question
//! slot N is the N-th of the exercises given (`--questions 4.1,4.2,4.3`; by default the
//! exercise files of the folder in name order). A response "-" or empty (not answered) and the
//! report's "Overall average" line are not rows.
//!
//! The export is separated by commas as Moodle writes it, or by `;` or tabs where a spreadsheet
//! saved it again ([`delimiter`]).

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

/// A Cloze response's parts, blank ones as `""`: Moodle 4.x writes every Cloze response, one
/// part too, as `part 1: …; part 2: …` (`qtype_multianswer_question::summarise_response`
/// joins its subquestions' summaries with `; `, each as the string `subqresponse`: English
/// `part {$a->i}: {$a->response}`, pt_br `parte {$a->i}: {$a->response}` (AMOS's
/// lang/pt_br/qtype_multianswer.php), French `partie {$a->i} : …`), and a part left blank as
/// `part 2: ` (its summary is empty). `None` when the response is not in that form: parts
/// numbered from 1, in order.
pub fn cloze_parts(response: &str) -> Option<Vec<&str>> {
    let mut values = Vec::new();
    for (i, segment) in response.split(';').enumerate() {
        let (label, value) = segment.trim().split_once(':')?;
        let label = label.trim().to_lowercase();
        let number = ["part ", "parte ", "partie "]
            .iter()
            .find_map(|w| label.strip_prefix(w))?;
        if number.trim().parse::<usize>().ok()? != i + 1 {
            return None;
        }
        values.push(value.trim());
    }
    Some(values)
}

/// A Cloze response's parts as one answer: `part 1: 0.52; part 2: 0.03; part 3: 0` → `0.52
/// 0.03 0`, `part 1: nenhuma` → `nenhuma`; a response with a blank part, and anything else, as
/// it is (trimmed): [`blank`] judges the blank parts of the row.
pub fn join_parts(response: &str) -> String {
    match cloze_parts(response) {
        Some(v) if v.iter().all(|p| !p.is_empty()) => v.join(" "),
        _ => response.trim().to_owned(),
    }
}

/// The blank parts of a Cloze response (`part 1: 0,5; part 2: ; part 3: 0,3`), `None` when it
/// has none or is not a Cloze response.
///
/// How a blank part counts: Moodle grades each part of a Cloze question on its own, a blank
/// part earning nothing and the others their own credit. phong judges an answer as one colour
/// (`phong check`, `/api/check` and a plain `grade` row alike: right, a reading, or wrong), and
/// a colour with a channel missing is none of the colours it could be compared with. So a blank
/// part is no answer for its channel: the row is judged, and it is wrong (incomplete), 0 points,
/// its feedback naming the blank parts. It is not "invalid" (the student answered the
/// question); only a response whose every part is blank is, as there is then nothing to judge.
pub fn blank(response: &str) -> Option<Blank> {
    let parts = cloze_parts(response)?;
    let blank: Vec<usize> = (1..=parts.len())
        .filter(|&n| parts[n - 1].is_empty())
        .collect();
    if blank.is_empty() {
        None
    } else if blank.len() == parts.len() {
        Some(Blank::All)
    } else {
        Some(Blank::Some {
            parts: Parts(blank),
            of: parts.len(),
        })
    }
}

/// Numbered parts of a Cloze response: `part 2`, `parts 1 and 3`, `parts 1, 2 and 4` (`parte
/// 2`, `partes 1 e 3`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Parts(pub Vec<usize>);

impl Show for Parts {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (one, many, and) = match lang {
            Lang::En => ("part", "parts", "and"),
            Lang::Pt => ("parte", "partes", "e"),
        };
        match self.0.as_slice() {
            [] => f.write_str(many),
            [n] => write!(f, "{one} {n}"),
            [init @ .., last] => {
                let init: Vec<String> = init.iter().map(usize::to_string).collect();
                write!(f, "{many} {} {and} {last}", init.join(", "))
            }
        }
    }
}

messages! {
    /// A Cloze response with blank parts ([`blank`]): the note of a row judged wrong, or why a
    /// row with every part blank is invalid.
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum Blank {
        /// Some parts are blank: the colour is incomplete.
        Some { parts: Parts, of: usize } =>
            "{parts} of {of} left blank in the Moodle response: a blank part is no answer for \
             its channel, so the colour is incomplete",
            "{parts} de {of} em branco na resposta do Moodle: uma parte em branco é um canal \
             sem resposta, então a cor está incompleta";
        /// Every part is blank.
        All =>
            "every part of the Moodle response is blank: there is no answer to check",
            "todas as partes da resposta do Moodle estão em branco: não há resposta a \
             verificar";
    }
}

/// One CSV field written for [`super::grade`]'s reader: quoted, `""` for a quote, and its
/// line breaks as spaces (a response typed on several lines), since that reader's row is one
/// line.
fn quoted(text: &str) -> String {
    format!(
        "\"{}\"",
        text.replace('"', "\"\"").replace(['\r', '\n'], " ")
    )
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

/// The separator of the export: the one of `,`, `;` and tab under which its header has the
/// most "Response N" cells (`,` before `;` before a tab on a tie; `,` when none has one).
/// Moodle writes commas; a spreadsheet saving it again writes `;` where the decimal comma takes
/// `,` (Excel in pt-BR) or a tab ("text separated by tabs"), and quotes the cells that hold the
/// separator, so a Cloze response's `; ` stays inside its cell. Under the wrong separator the
/// header is cells like `Nota/6` and `00;Resposta 1;…`, none of them a response column.
pub fn delimiter(text: &[u8]) -> u8 {
    let slots = |d: u8| {
        csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .delimiter(d)
            .from_reader(text)
            .records()
            .next()
            .and_then(Result::ok)
            .map_or(0, |r| {
                r.iter().filter(|c| response_slot(c).is_some()).count()
            })
    };
    let mut best = (0, b',');
    for d in [b',', b';', b'\t'] {
        let n = slots(d);
        if n > best.0 {
            best = (n, d);
        }
    }
    best.1
}

/// The export as `student,exercise,answer` CSV text (a header, then a row per answered
/// question); `questions[N-1]` is the exercise of slot N; `separator` the one given
/// (`--delimiter`), else the export's own ([`delimiter`]). Errors say what is missing.
pub fn to_rows(
    text: &[u8],
    questions: &[String],
    separator: Option<u8>,
) -> Result<Vec<u8>, MoodleError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(true)
        .delimiter(separator.unwrap_or_else(|| delimiter(text)))
        .from_reader(text);
    let header = reader.headers().map_err(|e| csv_error(&e, true))?.clone();
    // The report's column names are Moodle's language strings, in the language of the teacher
    // who downloads it: English, and pt_br as AMOS's language pack translates them (read in
    // lang/pt_br of Moodle 3.5 and 3.11 sites' packs): "Response {$a}" / "Resposta {$a}"
    // (quiz_responses `responsex`), "Right answer {$a}" / "Resposta correta {$a}"
    // (`rightanswerx`), "Surname" / "Sobrenome" (core `lastname`), "First name" / "Nome"
    // (`firstname`), "Email address" / "Endereço de email" (`email`; "e-mail" and plain
    // "Email" where a site customises it), "Overall average" / "Média geral" (grades
    // `overallaverage`). The columns not read: "State" / "Estado" (quiz `attemptstate`),
    // "Started on" / "Iniciado em" (`startedon`), "Completed" / "Completo" (`timecompleted`),
    // "Time taken" / "Tempo empregado" (`timetaken`), the grade.
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
    fn one_part_and_blank_parts() {
        // Moodle 4.x writes a one-part Cloze response as `part 1: …` too.
        assert_eq!(join_parts("part 1: nenhuma"), "nenhuma");
        assert_eq!(join_parts("parte 1: nenhuma"), "nenhuma");
        assert_eq!(join_parts("partie 1 : aucune"), "aucune");
        // Parts out of order, or text that only looks like a label, are not a Cloze response.
        assert_eq!(cloze_parts("part 2: 0.5"), None);
        assert_eq!(cloze_parts("part one: 0.5"), None);
        assert_eq!(cloze_parts("0.5; 0.3"), None);
        // A blank part stays in the answer, for the row to say which part it was.
        let blank_2 = "part 1: 0,5; part 2: ; part 3: 0,3";
        assert_eq!(cloze_parts(blank_2), Some(vec!["0,5", "", "0,3"]));
        assert_eq!(join_parts(blank_2), blank_2);
        assert_eq!(
            blank(blank_2),
            Some(Blank::Some {
                parts: Parts(vec![2]),
                of: 3
            })
        );
        // The CSV cell trimmed: the last part's blank is `part 3:`.
        assert_eq!(
            blank("parte 1: ; parte 2: 0,7; parte 3:"),
            Some(Blank::Some {
                parts: Parts(vec![1, 3]),
                of: 3
            })
        );
        assert_eq!(blank("part 1: ; part 2: ; part 3:"), Some(Blank::All));
        assert_eq!(blank("part 1:"), Some(Blank::All));
        assert_eq!(blank("part 1: 0.5; part 2: 0.7; part 3: 0.3"), None);
        assert_eq!(blank("0.5 0.7 0.3"), None);
    }

    #[test]
    fn blank_parts_are_named() {
        let text = |parts: Vec<usize>, lang| {
            crate::text::Message::text(
                &Blank::Some {
                    parts: Parts(parts),
                    of: 3,
                },
                lang,
            )
        };
        assert!(text(vec![2], Lang::En).starts_with("part 2 of 3 left blank"));
        assert!(text(vec![1, 3], Lang::En).starts_with("parts 1 and 3 of 3 left blank"));
        assert!(text(vec![1, 2, 3], Lang::En).starts_with("parts 1, 2 and 3 of 3"));
        assert!(text(vec![2], Lang::Pt).starts_with("parte 2 de 3 em branco"));
        assert!(text(vec![1, 3], Lang::Pt).starts_with("partes 1 e 3 de 3 em branco"));
    }

    #[test]
    fn the_separator_is_the_one_that_finds_response_columns() {
        // Excel in pt-BR: `;`, the grade's decimal comma unquoted.
        let semi = "Sobrenome;Nome;Nota/6,00;Resposta 1;Resposta correta 1;Resposta 2\r\n";
        assert_eq!(delimiter(semi.as_bytes()), b';');
        let tab = "Surname\tFirst name\tGrade/6.00\tResponse 1\tRight answer 1\n";
        assert_eq!(delimiter(tab.as_bytes()), b'\t');
        let comma = "\"Surname\",\"Grade/6,00\",\"Response 1\",\"Right answer 1\"\n";
        assert_eq!(delimiter(comma.as_bytes()), b',');
        assert_eq!(delimiter(b"no responses here"), b',');
    }

    #[test]
    fn responses_become_rows() {
        let csv = "Surname,First name,Email address,State,Grade/3.00,Response 1,Right answer 1,\
                   Response 2,Right answer 2\n\
                   Silva,Ana,ana@x.br,Finished,1.00,\"part 1: 0.52; part 2: 0.03; part 3: 0\",\
                   \"part 1: 0.52; part 2: 0.03; part 3: 0\",-,x\n\
                   Overall average,,,,1.00,,,,\n";
        assert!(is_responses(csv.as_bytes()));
        let rows = to_rows(csv.as_bytes(), &["4.1".into(), "4.3".into()], None).unwrap();
        assert_eq!(
            String::from_utf8(rows).unwrap(),
            "student,exercise,answer\n\"ana@x.br\",\"4.1\",\"0.52 0.03 0\"\n"
        );
        assert!(to_rows(csv.as_bytes(), &["4.1".into()], None).is_ok());
        // A response on several lines is one row, its line breaks spaces.
        let csv = "Email address,Response 1\nana@x.br,\"0.5\r\n0.7\n0.3\"\n";
        let rows = to_rows(csv.as_bytes(), &["4.1".into()], None).unwrap();
        assert_eq!(
            String::from_utf8(rows).unwrap(),
            "student,exercise,answer\n\"ana@x.br\",\"4.1\",\"0.5  0.7 0.3\"\n"
        );
    }
}
