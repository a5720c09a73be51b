//! JUnit XML, as GitLab reads it (`doc/ci/testing/unit_test_reports.md`): a `testsuite` per
//! student, a `testcase` per exercise (classname the student, name the exercise), a `failure`
//! holding the feedback for a wrong answer or one not answered, an `error` for an answer that
//! cannot be judged; the feedback of an accepted one in `system-out`. A student's other rows
//! (an unknown exercise, an answer that does not count) are testcases of their own, and the rows
//! without a student a testsuite of their own, so that no row is missing.

use std::fmt::Write;

use super::super::grade::Report;
use super::super::messages;
use super::Test;
use crate::text::lang::Lang;

/// `text` escaped for XML text and attribute values.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // XML 1.0 allows no other control character, even escaped.
            c if c.is_control() && !matches!(c, '\t' | '\n' | '\r') => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// The class as one JUnit XML document: a `testsuite` per submission ([`super::submissions`]:
/// the students, then the rows without a student), a `testcase` per exercise of the class and
/// one per other row (named `4.9 (line 11)`). A row that does not count (an answer another one
/// replaces, a row without a student) is `skipped`, its feedback in `system-out`.
pub fn class(report: &Report, lang: Lang) -> String {
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let mut suites = String::new();
    let (mut all, mut all_failures, mut all_errors) = (0, 0, 0);
    for s in super::submissions(report, lang) {
        let mut cases = String::new();
        let (mut failures, mut errors, mut skipped) = (0, 0, 0);
        for test in &s.tests {
            let (name, row) = match test {
                Test::Exercise { exercise, row, .. } => (escape(exercise), *row),
                Test::Row(r) => (escape(&super::row_name(r, lang)), Some(*r)),
            };
            let _ = write!(
                cases,
                "    <testcase classname=\"{}\" name=\"{name}\" time=\"0\">",
                escape(&s.student)
            );
            match row {
                Some(r) if !r.counted => {
                    skipped += 1;
                    let _ = write!(
                        cases,
                        "<skipped message=\"not counted\" type=\"not_counted\"/>\
                         <system-out>{}</system-out>",
                        escape(&r.feedback)
                    );
                }
                Some(r) if r.verdict == "invalid" => {
                    errors += 1;
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
                    failures += 1;
                    let _ = write!(
                        cases,
                        "<failure message=\"{}\" type=\"{}\">{}</failure>",
                        r.verdict,
                        r.verdict,
                        escape(&r.feedback)
                    );
                }
                None => {
                    failures += 1;
                    let _ = write!(
                        cases,
                        "<failure message=\"no answer\" type=\"no_answer\">{}</failure>",
                        escape(messages::no_answer(lang))
                    );
                }
            }
            cases.push_str("</testcase>\n");
        }
        let tests = s.tests.len();
        all += tests;
        all_failures += failures;
        all_errors += errors;
        let _ = write!(
            suites,
            "  <testsuite name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" \
             errors=\"{errors}\" skipped=\"{skipped}\" time=\"0\">\n{cases}  </testsuite>\n",
            escape(&s.student)
        );
    }
    let _ = write!(
        out,
        "<testsuites name=\"phong grade\" tests=\"{all}\" failures=\"{all_failures}\" \
         errors=\"{all_errors}\" time=\"0\">\n{suites}</testsuites>\n"
    );
    out
}
