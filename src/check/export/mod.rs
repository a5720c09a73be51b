//! A graded class in the formats course platforms read: Gradescope's `results.json`
//! ([`gradescope`]) and JUnit XML ([`junit`]), which GitLab and CI-based classrooms show as
//! test reports. Each student is one submission; each exercise of the class one test, judged by
//! the student's answer that counts (`--duplicates`). Every row of the report is in them once:
//! a student's rows that judge no exercise of the class (an unknown exercise, an answer that
//! does not count, a row naming an exercise only rows that cannot be read name) are tests of
//! their own after the exercises, and the rows without a student are the tests of one more
//! submission, `no_student_label`, after the students.

pub mod class;
pub mod gradescope;
pub mod junit;
pub mod xlsx;

use std::borrow::Cow;
use std::collections::BTreeMap;

use super::grade::{natural_order, Graded, Report, RowOut, StudentOut};
use crate::text::lang::Lang;

/// A graded class as the platforms' reports read it: in memory ([`Report`]) or graded again
/// row by row as it is written ([`Graded`]).
pub(crate) trait Class {
    /// The exercises graded, with their points.
    fn exercises(&self) -> &BTreeMap<String, f64>;
    /// The number of students.
    fn students(&self) -> usize;
    /// Student `s`'s name.
    fn name(&self, s: usize) -> &str;
    /// Student `s`'s total, and the rows that count for them.
    fn student(&self, s: usize) -> Cow<'_, StudentOut>;
    /// Row `i` (from 0).
    fn row(&self, i: usize) -> Cow<'_, RowOut>;
    /// Each student's rows, in input order, and the rows without a student.
    fn rows_by_student(&self) -> (Vec<Vec<u32>>, Vec<u32>);
}

impl Class for Report {
    fn exercises(&self) -> &BTreeMap<String, f64> {
        &self.exercises
    }
    fn students(&self) -> usize {
        self.students.len()
    }
    fn name(&self, s: usize) -> &str {
        &self.students[s].student
    }
    fn student(&self, s: usize) -> Cow<'_, StudentOut> {
        Cow::Borrowed(&self.students[s])
    }
    fn row(&self, i: usize) -> Cow<'_, RowOut> {
        Cow::Borrowed(&self.rows[i])
    }
    fn rows_by_student(&self) -> (Vec<Vec<u32>>, Vec<u32>) {
        let index: BTreeMap<&str, usize> = self
            .students
            .iter()
            .enumerate()
            .map(|(i, s)| (s.student.as_str(), i))
            .collect();
        let mut by: Vec<Vec<u32>> = vec![Vec::new(); self.students.len()];
        let mut nobody = Vec::new();
        for (i, r) in self.rows.iter().enumerate() {
            match index.get(r.student.as_str()) {
                Some(&s) if !r.student.is_empty() => by[s].push(i as u32),
                // A student without a total: a row that counts for no one from the start.
                None if !r.student.is_empty() => {}
                _ => nobody.push(i as u32),
            }
        }
        (by, nobody)
    }
}

impl Class for Graded<'_> {
    fn exercises(&self) -> &BTreeMap<String, f64> {
        Graded::exercises(self)
    }
    fn students(&self) -> usize {
        Graded::students(self)
    }
    fn name(&self, s: usize) -> &str {
        self.student_name(s)
    }
    fn student(&self, s: usize) -> Cow<'_, StudentOut> {
        Cow::Owned(Graded::student(self, s))
    }
    fn row(&self, i: usize) -> Cow<'_, RowOut> {
        Cow::Owned(Graded::row(self, i))
    }
    fn rows_by_student(&self) -> (Vec<Vec<u32>>, Vec<u32>) {
        Graded::rows_by_student(self)
    }
}

/// One test of a submission.
pub(crate) enum Test<'a> {
    /// An exercise of the class, with its points, and the row that counts for it (`None`: the
    /// student did not answer it).
    Exercise {
        /// The exercise, without `.json`.
        exercise: &'a str,
        /// Its points.
        max: f64,
        /// The row that counts (its index).
        row: Option<usize>,
    },
    /// A row that judges no exercise of the class for its student: an unknown exercise, an
    /// answer another one replaces (`--duplicates`), a row without a student. It earns nothing
    /// and costs nothing (0 of 0 points); its feedback says why.
    Row(usize),
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
/// of exactly one submission, or the row that counts for one of its exercises. Each submission
/// is made when it is asked for ([`Submissions::get`]), so that a class is written one student
/// at a time.
pub(crate) struct Submissions<'a, C: Class + ?Sized> {
    class: &'a C,
    lang: Lang,
    exercises: Vec<(&'a str, f64)>,
    by_student: Vec<Vec<u32>>,
    nobody: Vec<u32>,
}

impl<'a, C: Class + ?Sized> Submissions<'a, C> {
    pub(crate) fn new(class: &'a C, lang: Lang) -> Self {
        let mut exercises: Vec<(&str, f64)> = class
            .exercises()
            .iter()
            .map(|(k, &v)| (k.as_str(), v))
            .collect();
        exercises.sort_by(|a, b| natural_order(a.0, b.0));
        let (by_student, nobody) = class.rows_by_student();
        Submissions {
            class,
            lang,
            exercises,
            by_student,
            nobody,
        }
    }

    /// The number of submissions: the students, and one for the rows without a student.
    pub(crate) fn len(&self) -> usize {
        self.class.students() + usize::from(!self.nobody.is_empty())
    }

    /// Whether submission `k` is the rows without a student.
    pub(crate) fn is_nobody(&self, k: usize) -> bool {
        k == self.class.students()
    }

    /// The name submission `k` is shown under.
    pub(crate) fn name(&self, k: usize) -> &str {
        if self.is_nobody(k) {
            no_student_label(self.lang)
        } else {
            self.class.name(k)
        }
    }

    /// Submission `k`.
    pub(crate) fn get(&self, k: usize) -> Submission<'a> {
        if self.is_nobody(k) {
            return Submission {
                student: no_student_label(self.lang).to_owned(),
                points: 0.0,
                max_points: 0.0,
                tests: self.nobody.iter().map(|&i| Test::Row(i as usize)).collect(),
            };
        }
        let s = self.class.student(k);
        let mut tests: Vec<Test> = self
            .exercises
            .iter()
            .map(|&(exercise, max)| Test::Exercise {
                exercise,
                max,
                row: s.rows.get(exercise).copied(),
            })
            .collect();
        let counting: Vec<usize> = s.rows.values().copied().collect();
        tests.extend(
            self.by_student[k]
                .iter()
                .map(|&i| i as usize)
                .filter(|i| !counting.contains(i))
                .map(Test::Row),
        );
        Submission {
            student: s.student.clone(),
            points: s.points,
            max_points: s.max_points,
            tests,
        }
    }

    /// The row of a test (`None`: an exercise not answered).
    pub(crate) fn row_of(&self, test: &Test) -> Option<Cow<'a, RowOut>> {
        match test {
            Test::Exercise { row, .. } => row.map(|i| self.class.row(i)),
            Test::Row(i) => Some(self.class.row(*i)),
        }
    }
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
