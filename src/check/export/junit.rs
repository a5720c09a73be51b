//! JUnit XML, as GitLab reads it (`doc/ci/testing/unit_test_reports.md`): a `testsuite` per
//! student, a `testcase` per exercise (classname the student, name the exercise), a `failure`
//! holding the feedback for a wrong answer or one not answered, an `error` for an answer that
//! cannot be judged; the feedback of an accepted one in `system-out`. A student's other rows
//! (an unknown exercise, an answer that does not count) are testcases of their own, and the rows
//! without a student a testsuite of their own, so that no row is missing.

use std::fmt::Write as _;

use super::super::grade::Report;
use super::super::messages;
use super::{Class, Submissions, Test};
use crate::text::lang::Lang;
use crate::text::xml::escape;

/// The class as one JUnit XML document: a `testsuite` per submission (`Submissions`:
/// the students, then the rows without a student), a `testcase` per exercise of the class and
/// one per other row (named `4.9 (line 11)`). A row that does not count (an answer another one
/// replaces, a row without a student) is `skipped`, its feedback in `system-out`.
pub fn class(report: &Report, lang: Lang) -> String {
    let mut out = Vec::new();
    write(report, lang, &mut out).expect("writing to memory");
    String::from_utf8(out).expect("the document is UTF-8")
}

/// What a testcase is.
enum Case {
    Passed,
    Skipped,
    Error,
    Failure,
}

/// How a test of `subs` is reported.
fn case<C: Class + ?Sized>(subs: &Submissions<C>, test: &Test) -> Case {
    match subs.row_of(test) {
        Some(r) if !r.counted => Case::Skipped,
        Some(r) if r.verdict == "invalid" => Case::Error,
        Some(r) if r.accepted => Case::Passed,
        _ => Case::Failure,
    }
}

/// The class as one JUnit XML document ([`class`]), written to `out` one testcase at a time.
/// The counts come first in the document, so the tests are judged twice: once to count them,
/// once to write them.
pub(crate) fn write<C: Class + ?Sized>(
    class: &C,
    lang: Lang,
    out: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let subs = Submissions::new(class, lang);
    // (failures, errors, skipped) of each submission.
    let mut counts: Vec<[usize; 3]> = Vec::with_capacity(subs.len());
    let (mut all, mut all_failures, mut all_errors) = (0, 0, 0);
    for k in 0..subs.len() {
        let s = subs.get(k);
        let mut c = [0; 3];
        for test in &s.tests {
            match case(&subs, test) {
                Case::Failure => c[0] += 1,
                Case::Error => c[1] += 1,
                Case::Skipped => c[2] += 1,
                Case::Passed => {}
            }
        }
        all += s.tests.len();
        all_failures += c[0];
        all_errors += c[1];
        counts.push(c);
    }
    write!(
        out,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <testsuites name=\"phong grade\" tests=\"{all}\" failures=\"{all_failures}\" \
         errors=\"{all_errors}\" time=\"0\">\n"
    )?;
    for (k, [failures, errors, skipped]) in counts.into_iter().enumerate() {
        let s = subs.get(k);
        let tests = s.tests.len();
        writeln!(
            out,
            "  <testsuite name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" \
             errors=\"{errors}\" skipped=\"{skipped}\" time=\"0\">",
            escape(&s.student)
        )?;
        let mut cases = String::new();
        for test in &s.tests {
            cases.clear();
            let row = subs.row_of(test);
            let name = match test {
                Test::Exercise { exercise, .. } => escape(exercise),
                Test::Row(_) => escape(&super::row_name(row.as_deref().expect("a row"), lang)),
            };
            let _ = write!(
                cases,
                "    <testcase classname=\"{}\" name=\"{name}\" time=\"0\">",
                escape(&s.student)
            );
            match row.as_deref() {
                Some(r) if !r.counted => {
                    let _ = write!(
                        cases,
                        "<skipped message=\"not counted\" type=\"not_counted\"/>\
                         <system-out>{}</system-out>",
                        escape(&r.feedback)
                    );
                }
                Some(r) if r.verdict == "invalid" => {
                    let _ = write!(
                        cases,
                        "<error message=\"invalid\" type=\"invalid\">{}</error>",
                        escape(&r.feedback)
                    );
                }
                Some(r) if r.accepted => {
                    let _ = write!(cases, "<system-out>{}</system-out>", escape(&r.feedback));
                }
                Some(r) => {
                    let _ = write!(
                        cases,
                        "<failure message=\"{}\" type=\"{}\">{}</failure>",
                        r.verdict,
                        r.verdict,
                        escape(&r.feedback)
                    );
                }
                None => {
                    let _ = write!(
                        cases,
                        "<failure message=\"no answer\" type=\"no_answer\">{}</failure>",
                        escape(messages::no_answer(lang))
                    );
                }
            }
            cases.push_str("</testcase>\n");
            out.write_all(cases.as_bytes())?;
        }
        out.write_all(b"  </testsuite>\n")?;
    }
    out.write_all(b"</testsuites>\n")?;
    out.flush()
}
