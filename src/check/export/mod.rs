//! A graded class in the formats course platforms read: Gradescope's `results.json`
//! ([`gradescope`]) and JUnit XML ([`junit`]), which GitLab and CI-based classrooms show as
//! test reports. Each student is one submission; each exercise of the class one test, judged by
//! the student's answer that counts (`--duplicates`). Every row of the report is in them once:
//! a student's rows that judge no exercise of the class (an unknown exercise, an answer that
//! does not count, a row naming an exercise only rows that cannot be read name) are tests of
//! their own after the exercises, and the rows without a student are the tests of one more
//! submission, [`no_student_label`], after the students.

pub mod gradescope;
pub mod junit;

use std::collections::BTreeMap;

use super::grade::{natural_order, Report, RowOut};
use crate::text::lang::Lang;

/// One test of a submission.
pub(crate) enum Test<'a> {
    /// An exercise of the class, with its points, and the row that counts for it (`None`: the
    /// student did not answer it).
    Exercise {
        /// The exercise, without `.json`.
        exercise: &'a str,
        /// Its points.
        max: f64,
        /// The row that counts.
        row: Option<&'a RowOut>,
    },
    /// A row that judges no exercise of the class for its student: an unknown exercise, an
    /// answer another one replaces (`--duplicates`), a row without a student. It earns nothing
    /// and costs nothing (0 of 0 points); its feedback says why.
    Row(&'a RowOut),
}

/// One submission: a student's tests and total, or the rows without a student.
pub(crate) struct Submission<'a> {
    /// The student as written; for the rows without a student, [`no_student_label`].
    pub student: String,
    /// The points of the rows that count.
    pub points: f64,
    /// The points of every exercise graded.
    pub max_points: f64,
    /// The class's exercises in natural order (4.2 before 4.10), then the other rows in input
    /// order.
    pub tests: Vec<Test<'a>>,
}

/// The name under which the rows without a student are shown: a student's name cannot be
/// empty, and the parentheses keep it apart from a name a class would use.
pub(crate) fn no_student_label(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "(no student)",
        Lang::Pt => "(sem aluno)",
    }
}

/// A row that is a test of its own, named by its exercise and line so that the student finds
/// it in their file: `4.9 (line 11)`, `4.9 (linha 11)`; `line 11` for a row without an
/// exercise.
pub(crate) fn row_name(row: &RowOut, lang: Lang) -> String {
    let line = match lang {
        Lang::En => "line",
        Lang::Pt => "linha",
    };
    if row.exercise.is_empty() {
        format!("{line} {}", row.line)
    } else {
        format!("{} ({line} {})", row.exercise, row.line)
    }
}

/// The class as the platforms show it: each student in the order they first appear, then, when
/// some rows have no student, one submission holding them. Every row of the report is one test
/// of exactly one submission, or the row that counts for one of its exercises.
pub(crate) fn submissions(report: &Report, lang: Lang) -> Vec<Submission<'_>> {
    let mut exercises: Vec<(&String, &f64)> = report.exercises.iter().collect();
    exercises.sort_by(|a, b| natural_order(a.0, b.0));
    // Each student's rows, in input order; the rows without a student apart.
    let mut by_student: BTreeMap<&str, Vec<&RowOut>> = BTreeMap::new();
    let mut nobody: Vec<&RowOut> = Vec::new();
    for r in &report.rows {
        if r.student.is_empty() {
            nobody.push(r);
        } else {
            by_student.entry(&r.student).or_default().push(r);
        }
    }
    let mut out: Vec<Submission> = report
        .students
        .iter()
        .map(|s| {
            let counted = |exercise: &str| s.rows.get(exercise).and_then(|&i| report.rows.get(i));
            let mut tests: Vec<Test> = exercises
                .iter()
                .map(|&(exercise, &max)| Test::Exercise {
                    exercise,
                    max,
                    row: counted(exercise),
                })
                .collect();
            let theirs = by_student.get(s.student.as_str()).map_or(&[][..], |v| v);
            let counting: Vec<usize> = s.rows.values().copied().collect();
            tests.extend(
                theirs
                    .iter()
                    .filter(|r| !counting.iter().any(|&i| report.rows[i].row == r.row))
                    .map(|&r| Test::Row(r)),
            );
            Submission {
                student: s.student.clone(),
                points: s.points,
                max_points: s.max_points,
                tests,
            }
        })
        .collect();
    if !nobody.is_empty() {
        out.push(Submission {
            student: no_student_label(lang).to_owned(),
            points: 0.0,
            max_points: 0.0,
            tests: nobody.into_iter().map(Test::Row).collect(),
        });
    }
    out
}

/// A file name for each submission (`-o DIR/`), in the order of `names`: letters, digits, `.`,
/// `-` and `_` kept, anything else `_`, a leading `.` replaced; a name already taken gets `-2`,
/// `-3`, …
pub(crate) fn file_names<'a>(names: impl IntoIterator<Item = &'a str>) -> Vec<String> {
    let mut taken = std::collections::BTreeSet::new();
    names
        .into_iter()
        .map(|s| {
            let mut base: String = s
                .chars()
                .map(|c| {
                    if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
            if base.starts_with('.') || base.is_empty() {
                base.insert(0, '_');
            }
            let mut name = base.clone();
            let mut n = 1;
            while !taken.insert(name.to_lowercase()) {
                n += 1;
                name = format!("{base}-{n}");
            }
            name
        })
        .collect()
}
