//! Gradescope's autograder `results.json` (gradescope/autograder_samples, `docs/specs.md`): the
//! total `score`, an `output`, and one test per exercise with `name`, `number`, `score`,
//! `max_score`, `status` (`passed` | `failed`), `output` (the feedback, in the chosen language)
//! and `visibility`; then one test, of 0 points, per other row of the student's (an unknown
//! exercise, an answer that does not count), its feedback saying why. Only fields of
//! Gradescope's published list are written.

use serde_json::{json, Value};

use super::super::messages;
use super::{submissions, Submission, Test};
use crate::check::grade::Report;
use crate::text::lang::Lang;

/// One submission's `results.json`.
fn results(submission: &Submission, lang: Lang) -> Value {
    let tests: Vec<Value> = submission
        .tests
        .iter()
        .map(|test| match test {
            Test::Exercise { exercise, max, row } => {
                let (score, passed, output) = match row {
                    Some(r) => (r.points, r.accepted, r.feedback.clone()),
                    None => (0.0, false, messages::no_answer(lang).to_owned()),
                };
                json!({
                    "name": messages::exercise_name(exercise, lang),
                    "number": exercise,
                    "score": score,
                    "max_score": max,
                    "status": if passed { "passed" } else { "failed" },
                    "output": output,
                    "visibility": "visible",
                })
            }
            Test::Row(r) => json!({
                "name": row_title(r, lang),
                "number": r.exercise,
                "score": 0.0,
                "max_score": 0.0,
                "status": if r.accepted && r.counted { "passed" } else { "failed" },
                "output": r.feedback,
                "visibility": "visible",
            }),
        })
        .collect();
    json!({
        "score": submission.points,
        "output": format!(
            "{}: {}",
            submission.student,
            messages::total(submission.points, submission.max_points, lang)
        ),
        "visibility": "visible",
        "tests": tests,
    })
}

/// The name of a row's own test: `Exercise 4.9 (line 11)`, `Exercício 4.9 (linha 11)`, or
/// `Line 11` / `Linha 11` for a row without an exercise.
fn row_title(r: &crate::check::grade::RowOut, lang: Lang) -> String {
    if r.exercise.is_empty() {
        let mut name = super::row_name(r, lang);
        name[..1].make_ascii_uppercase();
        name
    } else {
        messages::exercise_name(&super::row_name(r, lang), lang)
    }
}

/// The class: one student's `results.json` itself (the rows without a student among its tests,
/// since the file is that student's submission), or, for several students, one object whose
/// keys are the students and whose values are their `results.json`, the rows without a
/// student under the key `(no student)` (`(sem aluno)`).
pub fn class(report: &Report, lang: Lang) -> Value {
    let mut all = submissions(report, lang);
    let students = report.students.len();
    if students <= 1 && !all.is_empty() {
        let mut first = all.remove(0);
        for other in all {
            first.tests.extend(other.tests);
        }
        return results(&first, lang);
    }
    let map: serde_json::Map<String, Value> = all
        .iter()
        .map(|s| (s.student.clone(), results(s, lang)))
        .collect();
    Value::Object(map)
}

/// One `results.json` per submission (`-o DIR/`): each student's, then the rows without a
/// student's, each with its file name (without `.json`, [`super::file_names`]).
pub fn files(report: &Report, lang: Lang) -> Vec<(String, Value)> {
    let all = submissions(report, lang);
    let names = super::file_names(all.iter().map(|s| s.student.as_str()));
    names
        .into_iter()
        .zip(all.iter().map(|s| results(s, lang)))
        .collect()
}
