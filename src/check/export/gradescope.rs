//! Gradescope's autograder `results.json` (gradescope/autograder_samples, `docs/specs.md`): the
//! total `score`, an `output`, and one test per exercise with `name`, `number`, `score`,
//! `max_score`, `status` (`passed` | `failed`), `output` (the feedback, in the chosen language)
//! and `visibility`. Only fields of Gradescope's published list are written.

use serde_json::{json, Value};

use super::super::grade::{Report, StudentOut};
use super::super::messages;
use crate::report::lang::Lang;

/// One student's `results.json`.
pub fn results(report: &Report, student: &StudentOut, lang: Lang) -> Value {
    let tests: Vec<Value> = report
        .exercises
        .iter()
        .map(|(exercise, &max)| {
            let row = super::counted(report, student, exercise);
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
        })
        .collect();
    json!({
        "score": student.points,
        "output": format!("{}: {}", student.student, messages::total(student.points, student.max_points, lang)),
        "visibility": "visible",
        "tests": tests,
    })
}

/// The class: one student's `results.json` itself, or, for several students, one object whose
/// keys are the students and whose values are their `results.json`.
pub fn class(report: &Report, lang: Lang) -> Value {
    if let [only] = report.students.as_slice() {
        return results(report, only, lang);
    }
    let map: serde_json::Map<String, Value> = report
        .students
        .iter()
        .map(|s| (s.student.clone(), results(report, s, lang)))
        .collect();
    Value::Object(map)
}
