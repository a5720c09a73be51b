//! Gradescope's autograder `results.json` (gradescope/autograder_samples, `docs/specs.md`): the
//! total `score`, an `output`, and one test per exercise with `name`, `number`, `score`,
//! `max_score`, `status` (`passed` | `failed`), `output` (the feedback, in the chosen language)
//! and `visibility`; then one test, of 0 points, per other row of the student's (an unknown
//! exercise, an answer that does not count), its feedback saying why. Only fields of
//! Gradescope's published list are written.

use serde::ser::{SerializeMap, Serializer};
use serde::Serialize;
use serde_json::{json, Value};

use super::super::messages;
use super::{Class, Submission, Submissions, Test};
use crate::check::grade::Report;
use crate::text::lang::Lang;

/// One test of a submission, as `results.json` writes it.
fn test_json<C: Class + ?Sized>(subs: &Submissions<C>, test: &Test, lang: Lang) -> Value {
    let row = subs.row_of(test);
    match test {
        Test::Exercise { exercise, max, .. } => {
            let (score, passed, output) = match row.as_deref() {
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
        Test::Row(_) => {
            let r = row.as_deref().expect("a row");
            json!({
                "name": row_title(r, lang),
                "number": r.exercise,
                "score": 0.0,
                "max_score": 0.0,
                "status": if r.accepted { "passed" } else { "failed" },
                "output": r.feedback,
                "visibility": "visible",
            })
        }
    }
}

/// One submission's `results.json`, its tests made as they are written. Its keys in the order
/// a `serde_json::Value` object writes them (sorted).
struct Results<'s, 'a, C: Class + ?Sized> {
    subs: &'s Submissions<'a, C>,
    submission: Submission<'a>,
    lang: Lang,
}

impl<C: Class + ?Sized> Serialize for Results<'_, '_, C> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        struct Tests<'r, 's, 'a, C: Class + ?Sized>(&'r Results<'s, 'a, C>);
        impl<C: Class + ?Sized> Serialize for Tests<'_, '_, '_, C> {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let r = self.0;
                serializer.collect_seq(
                    r.submission
                        .tests
                        .iter()
                        .map(|t| test_json(r.subs, t, r.lang)),
                )
            }
        }
        let s = &self.submission;
        let mut map = serializer.serialize_map(Some(4))?;
        map.serialize_entry(
            "output",
            &format!(
                "{}: {}",
                s.student,
                messages::total(s.points, s.max_points, self.lang)
            ),
        )?;
        map.serialize_entry("score", &json!(s.points))?;
        map.serialize_entry("tests", &Tests(self))?;
        map.serialize_entry("visibility", "visible")?;
        map.end()
    }
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
    let mut out = Vec::new();
    write_class(report, lang, &mut out).expect("writing to memory");
    serde_json::from_slice(&out).expect("the document is JSON")
}

/// The class ([`class`]) pretty-printed with a final newline, written to `out` one test at a
/// time.
pub(crate) fn write_class<C: Class + ?Sized>(
    class: &C,
    lang: Lang,
    out: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let subs = Submissions::new(class, lang);
    let mut ser = serde_json::Serializer::pretty(&mut *out);
    if class.students() <= 1 && subs.len() > 0 {
        let mut first = subs.get(0);
        for k in 1..subs.len() {
            first.tests.extend(subs.get(k).tests);
        }
        Results {
            subs: &subs,
            submission: first,
            lang,
        }
        .serialize(&mut ser)?;
    } else {
        // An object's keys in order; a student named as the rows without a student is replaced
        // by them, as a key given twice is.
        let label = super::no_student_label(lang);
        let has_nobody = subs.len() > class.students();
        let mut order: Vec<usize> = (0..subs.len())
            .filter(|&k| subs.is_nobody(k) || !(has_nobody && subs.name(k) == label))
            .collect();
        order.sort_by(|&a, &b| subs.name(a).cmp(subs.name(b)));
        let mut map = ser.serialize_map(Some(order.len()))?;
        for k in order {
            map.serialize_entry(
                subs.name(k),
                &Results {
                    subs: &subs,
                    submission: subs.get(k),
                    lang,
                },
            )?;
        }
        map.end()?;
    }
    out.write_all(b"\n")?;
    out.flush()
}

/// One `results.json` per submission (`-o DIR/`): each student's, then the rows without a
/// student's, each with its file name (without `.json`, `file_names`).
pub fn files(report: &Report, lang: Lang) -> Vec<(String, Value)> {
    let mut out = Vec::new();
    let _ = write_files(report, lang, |name, write| {
        let mut bytes = Vec::new();
        write(&mut bytes)?;
        out.push((
            name.to_owned(),
            serde_json::from_slice(&bytes).expect("the document is JSON"),
        ));
        Ok::<(), std::io::Error>(())
    });
    out
}

/// One `results.json` per submission (`-o DIR/`), in the order of [`files`]: `each` is given
/// the file's name (without `.json`) and what writes its text (pretty-printed, with a final
/// newline); the first error stops.
pub(crate) fn write_files<C: Class + ?Sized, E>(
    class: &C,
    lang: Lang,
    mut each: impl FnMut(
        &str,
        &mut dyn FnMut(&mut dyn std::io::Write) -> std::io::Result<()>,
    ) -> Result<(), E>,
) -> Result<(), E> {
    let subs = Submissions::new(class, lang);
    let names = super::file_names((0..subs.len()).map(|k| subs.name(k)));
    for (k, name) in names.iter().enumerate() {
        each(name, &mut |out: &mut dyn std::io::Write| {
            let results = Results {
                subs: &subs,
                submission: subs.get(k),
                lang,
            };
            serde_json::to_writer_pretty(&mut *out, &results)?;
            out.write_all(b"\n")?;
            out.flush()
        })?;
    }
    Ok(())
}
