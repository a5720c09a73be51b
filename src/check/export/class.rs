//! What the class got wrong (`phong grade --class-report aula.html`, and the workbook's class
//! sheet): what no course platform can tell an instructor, since none knows the slip behind a
//! wrong number. For each exercise, how many answers were right, right by the likely intended
//! reading, each named slip (a wrong answer several slips explain counts under each), wrong with
//! no slip named, and unreadable; and a histogram of the students' totals. One list of lines
//! ([`lines`]) feeds both the page and the sheet.

use std::fmt::Write;

use crate::check::grade::{Graded, SummaryOut};
use crate::report::html::esc;
use crate::text::{Lang, Message};

crate::messages! {
    /// The words of the class report.
    #[allow(missing_docs)]
    pub enum ClassWords {
        Title => "What the class got wrong", "O que a turma errou";
        Class => "Class", "Turma";
        /// The line under the title.
        Counts { students: usize, answers: usize, file: String } =>
            "{students} students, {answers} answers ({file})",
            "{students} alunos, {answers} respostas ({file})";
        Exercise => "Exercise", "Exercício";
        What => "What the answers were", "O que as respostas foram";
        Answers => "Answers", "Respostas";
        Right => "right", "certas";
        Reading => "right by the likely intended reading", "certas pela leitura provavelmente pretendida";
        /// A slip named, in words.
        Slip { slip: String } => "slip: {slip}", "erro: {slip}";
        Unnamed => "wrong, no classic slip gives it", "erradas, nenhum erro clássico as explica";
        Invalid => "unreadable (invalid)", "ilegíveis (inválidas)";
        Note =>
            "A wrong answer that several slips explain is counted under each.",
            "Uma resposta errada que vários erros explicam conta em cada um.";
        Totals => "The students' totals", "Os totais dos alunos";
        /// A bin of the histogram, as a share of the most points.
        Bin { from: usize, to: usize } => "{from}–{to} %", "{from}–{to} %";
        Students => "Students", "Alunos";
    }
}

/// One line of the report: the exercise, what its answers were, how many.
pub struct Line {
    /// The exercise.
    pub exercise: String,
    /// What the answers were, in words.
    pub what: String,
    /// How many.
    pub count: usize,
    /// The kind, for the page's colours: `right`, `reading`, `slip`, `unnamed`, `invalid`.
    pub kind: &'static str,
}

/// The lines of one exercise's summary, in the order the report shows them (right, the reading,
/// each slip most common first, the unnamed wrong ones, the unreadable ones); the counts that
/// are 0 are left out but for "right".
fn exercise_lines(s: &SummaryOut, lang: Lang) -> Vec<Line> {
    let line = |what: String, count, kind| Line {
        exercise: s.exercise.clone(),
        what,
        count,
        kind,
    };
    let mut out = vec![line(ClassWords::Right.text(lang), s.right, "right")];
    if s.reading > 0 {
        out.push(line(ClassWords::Reading.text(lang), s.reading, "reading"));
    }
    for c in &s.slips {
        let slip = crate::check::messages::slips(&c.slips, lang);
        out.push(line(ClassWords::Slip { slip }.text(lang), c.count, "slip"));
    }
    if s.unnamed > 0 {
        out.push(line(ClassWords::Unnamed.text(lang), s.unnamed, "unnamed"));
    }
    if s.invalid > 0 {
        out.push(line(ClassWords::Invalid.text(lang), s.invalid, "invalid"));
    }
    out
}

/// Every exercise's lines, exercises in natural order.
pub fn lines(graded: &Graded, lang: Lang) -> Vec<Line> {
    graded
        .summary()
        .iter()
        .flat_map(|s| exercise_lines(s, lang))
        .collect()
}

/// The students' totals as shares of their most points, in ten bins of 10 % (100 % in the
/// last): how many students in each.
pub fn histogram(graded: &Graded) -> [usize; 10] {
    let mut bins = [0; 10];
    for s in 0..graded.students() {
        let st = graded.student(s);
        if st.max_points <= 0.0 {
            continue;
        }
        let share = (st.points / st.max_points).clamp(0.0, 1.0);
        let bin = ((share * 10.0).floor() as usize).min(9);
        bins[bin] += 1;
    }
    bins
}

/// The bar colour of a line's kind.
fn colour(kind: &str) -> &'static str {
    match kind {
        "right" => "#2e7d32",
        "reading" => "#b36b00",
        "slip" => "#c62828",
        "unnamed" => "#7b1fa2",
        _ => "#757575",
    }
}

/// A horizontal bar chart of `bars` (label, count, colour), as SVG with a text alternative;
/// the table beside it holds the same numbers.
fn bars(title: &str, bars: &[(String, usize, &str)]) -> String {
    let max = bars.iter().map(|b| b.1).max().unwrap_or(0).max(1);
    let (w, h, label_w) = (640.0, 22.0, 300.0);
    let height = h * bars.len() as f64 + 8.0;
    let mut out = format!(
        "<svg class=\"chart\" width=\"{w}\" height=\"{height}\" viewBox=\"0 0 {w} {height}\" \
         role=\"img\" aria-label=\"{}\"><title>{}</title>\n",
        esc(title),
        esc(title)
    );
    for (i, (label, count, fill)) in bars.iter().enumerate() {
        let y = 4.0 + h * i as f64;
        let len = (w - label_w - 40.0) * *count as f64 / max as f64;
        let shown: String = label.chars().take(38).collect();
        let shown = if shown.len() < label.len() {
            format!("{shown}…")
        } else {
            shown
        };
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\" font-size=\"12\">{}</text>\
             <rect x=\"{label_w}\" y=\"{}\" width=\"{len:.1}\" height=\"{}\" fill=\"{fill}\"/>\
             <text x=\"{:.1}\" y=\"{}\" font-size=\"12\">{count}</text>",
            label_w - 6.0,
            y + 15.0,
            esc(&shown),
            y + 3.0,
            h - 6.0,
            label_w + len + 4.0,
            y + 15.0
        );
    }
    out.push_str("</svg>\n");
    out
}

/// The class report, a self-contained page in `lang`.
pub fn html(graded: &Graded, file: &str, lang: Lang) -> String {
    let mut body = String::new();
    let _ = writeln!(
        body,
        "<main>\n<h1>{}</h1>\n<p class=\"source\">{}</p>",
        esc(&ClassWords::Title.text(lang)),
        esc(&ClassWords::Counts {
            students: graded.students(),
            answers: graded.len(),
            file: file.to_owned(),
        }
        .text(lang))
    );
    // The totals.
    let bins = histogram(graded);
    let labelled: Vec<(String, usize, &str)> = bins
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            let to = if i == 9 { 100 } else { 10 * i + 9 };
            (
                ClassWords::Bin { from: 10 * i, to }.text(lang),
                n,
                "#1565c0",
            )
        })
        .collect();
    let _ = writeln!(
        body,
        "<section>\n<h2>{}</h2>",
        esc(&ClassWords::Totals.text(lang))
    );
    body.push_str(&bars(&ClassWords::Totals.text(lang), &labelled));
    let _ = writeln!(
        body,
        "<table class=\"data\"><tr><th scope=\"col\">%</th><th scope=\"col\">{}</th></tr>",
        esc(&ClassWords::Students.text(lang))
    );
    for (label, n, _) in &labelled {
        let _ = writeln!(body, "<tr><td>{}</td><td>{n}</td></tr>", esc(label));
    }
    body.push_str("</table>\n</section>\n");
    // Each exercise.
    for s in graded.summary() {
        let ls = exercise_lines(s, lang);
        let _ = writeln!(
            body,
            "<section>\n<h2>{} {}</h2>",
            esc(&ClassWords::Exercise.text(lang)),
            esc(&s.exercise)
        );
        let chart: Vec<(String, usize, &str)> = ls
            .iter()
            .map(|l| (l.what.clone(), l.count, colour(l.kind)))
            .collect();
        body.push_str(&bars(
            &format!("{} {}", ClassWords::Exercise.text(lang), s.exercise),
            &chart,
        ));
        let _ = writeln!(
            body,
            "<table class=\"data\"><tr><th scope=\"col\">{}</th><th scope=\"col\">{}</th></tr>",
            esc(&ClassWords::What.text(lang)),
            esc(&ClassWords::Answers.text(lang))
        );
        for l in &ls {
            let _ = writeln!(
                body,
                "<tr data-kind=\"{}\"><td>{}</td><td>{}</td></tr>",
                l.kind,
                esc(&l.what),
                l.count
            );
        }
        body.push_str("</table>\n</section>\n");
    }
    let _ = writeln!(
        body,
        "<p class=\"help\">{}</p>\n</main>",
        esc(&ClassWords::Note.text(lang))
    );
    crate::report::html::page(&esc(&ClassWords::Title.text(lang)), &body, lang)
}
