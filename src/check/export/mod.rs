//! A graded class in the formats course platforms read: Gradescope's `results.json`
//! ([`gradescope`]) and JUnit XML ([`junit`]), which GitLab and CI-based classrooms show as
//! test reports. Each student is one submission; each exercise of the class one test, judged by
//! the student's answer that counts (`--duplicates`).

pub mod gradescope;
pub mod junit;

use super::grade::{Report, RowOut, StudentOut};

/// The row that counts for `student` on `exercise`, if they answered it.
fn counted<'a>(report: &'a Report, student: &StudentOut, exercise: &str) -> Option<&'a RowOut> {
    student.rows.get(exercise).and_then(|&i| report.rows.get(i))
}

/// A file name for each student (`-o DIR/`): letters, digits, `.`, `-` and `_` kept, anything
/// else `_`, a leading `.` replaced; a name already taken gets `-2`, `-3`, … Same order as
/// `report.students`.
pub fn file_names(report: &Report) -> Vec<String> {
    let mut taken = std::collections::BTreeSet::new();
    report
        .students
        .iter()
        .map(|s| {
            let mut base: String = s
                .student
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
