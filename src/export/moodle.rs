//! Problems as a Moodle XML quiz (`phong moodle`): one Cloze (`multianswer`) question per
//! problem, in one category per problem set (a file, or what `phong new` printed).
//!
//! The rules followed are those of Moodle's own importer (`question/format/xml/format.php`) and
//! Cloze parser (`question/type/multianswer/questiontype.php`), gathered in the course's
//! platform notes:
//!
//! - each colour channel is a `NUMERICAL` part of weight 1 (integer weights only) whose first
//!   alternative, `=` (100 %), is the answer key with an **absolute** tolerance (a relative one
//!   would be zero-wide at a channel of 0); a channel above 1 also accepts its value before
//!   the clamp to [0, 1], as `phong check` does;
//! - the likely intended reading of a problem, where it has one, is a `%50%` alternative;
//! - each classic slip's colour (the same machinery as `phong check`'s diagnosis, single slips
//!   only) is a `%0%` alternative whose feedback names the slip and its equation; Moodle
//!   grades a part by the *first* alternative within its tolerance
//!   (`question/type/numerical/question.php`, `get_matching_answer`), so no two alternatives
//!   lie within the tolerance of each other: a slip that the right answer (or the reading)
//!   would shadow is left out, and slips whose numbers lie within the tolerance of an earlier
//!   slip's share that alternative, whose feedback names every one of them;
//! - a `*` catch-all closes every part;
//! - a problem whose ray hits nothing as written (exercise 4.3) asks one `SHORTANSWER` part of
//!   weight 3 that accepts "nenhuma", "none" and "no hit" (case-insensitive in Moodle), since no
//!   colour is right; the likely intended reading's colour is in the general feedback;
//! - inside Cloze answers and feedback `}` and `#` are written `\}` and `\#` (the parser's only
//!   escapes), and `~` and `\`, which have none, as the HTML references `&\#126;` and `&\#92;`
//!   (the feedback is HTML): no raw `~`, `}` or `#` can end an alternative early;
//! - the problem's own text in the question (its statement, the data table's names, the no-hit
//!   prompt) has every `{` and `}` as `&#123;` and `&#125;` ([`cloze_inert`]), so that Cloze
//!   syntax written there (`{2:SHORTANSWER:=x}`, LaTeX braces) is shown, never parsed: only
//!   phong's own sub-questions match the grammar;
//! - fractions come from Moodle's fixed list only (100, 50, 0);
//! - the category path is split by Moodle's importer (`question/format.php`,
//!   `split_category_path`) at each `/` that is not part of `//`, and `//` is a literal `/`,
//!   each name trimmed: each name is written as `assemble_category_path` writes it
//!   ([`category_name`]), so that `--category 'A/B 50%'` is one category, not two;
//! - the worked solution is the general feedback, in HTML with MathJax's `\( … \)` (a single `$`
//!   is no delimiter in Moodle), and each diagram an SVG `<file>` in base64 shown by
//!   `<img src="@@PLUGINFILE@@/…">`.

use std::fmt::Write;

use crate::check::{messages as check_messages, Expected, Slip};
use crate::problem::Problem;
use crate::report::diagram;
use crate::report::explain::{
    capitalised, latex_math, nest, runs, Explanation, Node, Run, Shading, Step,
};
use crate::report::html::{data_table, esc, STYLE};
use crate::text::lang::Lang;

/// One problem of a set: its label (file, or file and index), the validated problem and the
/// tolerances its answers are judged under, as the course policy gives them.
pub(crate) struct Entry {
    /// Where it came from, for the explanation's source line ("4.2.json", "-\[3\]").
    pub label: String,
    /// The validated problem.
    pub problem: Problem<f64>,
    /// The absolute tolerance per channel on the 0–1 scale.
    pub tolerance: f64,
    /// The absolute tolerance per channel on the 255 scale.
    pub tolerance_bits8: f64,
    /// The exercise's points under the course policy (`Policy::points_of` its file's name).
    pub points: f64,
}

/// How the course policy grades the quiz's answers ([`Grading::of`]).
pub(crate) struct Grading {
    /// The fraction of a likely intended reading, as a Cloze alternative writes it (`%50%`).
    pub reading: String,
    /// Each part also accepts its numbers on the 255 scale (the policy's `eight_bit: read`).
    pub eight_bit: bool,
    /// The choice that answers "the ray meets nothing": the language's word ("none",
    /// "nenhuma") when the course accepts it, else the course's first word.
    pub none: String,
    /// What a point weighs in a part's weight ([`Grading::weigh`]).
    pub per_point: f64,
}

/// The share of a point a question's mark is exact to ([`Grading::weigh`]).
const POINT_STEPS: [f64; 4] = [1.0, 10.0, 100.0, 1000.0];

/// The fractions Moodle's importer accepts, in percent (`question/format.php`'s grade list,
/// as the course's platform notes give it): any other is an import error.
const MOODLE_GRADES: [f64; 21] = [
    100.0, 90.0, 83.33333, 80.0, 75.0, 70.0, 66.66667, 60.0, 50.0, 40.0, 33.33333, 30.0, 25.0,
    20.0, 16.66667, 14.28571, 12.5, 11.11111, 10.0, 5.0, 0.0,
];

/// Moodle's fractions as shares of the points, for a message: `1, 0.9, 0.8333333, …, 0`.
pub(crate) fn fractions() -> String {
    MOODLE_GRADES
        .iter()
        .map(|g| {
            let s = format!("{:.7}", g / 100.0);
            s.trim_end_matches('0').trim_end_matches('.').to_owned()
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl Grading {
    /// The quiz's grading under `policy`; `Err` with the share when its reading credit is not
    /// one of Moodle's fractions (1/3 is: 33.33333 %).
    pub(crate) fn of(policy: &crate::check::policy::Policy, lang: Lang) -> Result<Grading, f64> {
        use crate::check::VerdictKind;
        let share = policy.credit(VerdictKind::Reading);
        let percent = share * 100.0;
        let grade = MOODLE_GRADES
            .iter()
            .find(|g| (*g - percent).abs() < 1e-4)
            .ok_or(share)?;
        Ok(Grading {
            reading: if *grade == 100.0 {
                "=".to_owned()
            } else {
                format!("%{}%", number(*grade))
            },
            eight_bit: policy.eight_bit == crate::check::policy::EightBit::Read,
            per_point: 1.0,
            none: crate::check::answer::no_hit_word(lang, &policy.no_hit),
        })
    }
}

impl Grading {
    /// Weighs the quiz's questions by the course policy's points. Moodle's importer makes a
    /// Cloze question's mark the sum of its parts' weights, whole numbers
    /// (`question/type/multianswer/questiontype.php`, `qtype_multianswer_extract_question`; the
    /// question's `<defaultgrade>` is not read): a colour question has three parts and a no-hit
    /// question one, so a colour part weighs the points and the no-hit part three times them,
    /// each question's mark being three times its points. Points with decimals are scaled by 10,
    /// 100 or 1,000 for every question alike (to a thousandth of a point at most): `Err` with an
    /// entry whose points are finer (0.3333, 0.0001), which whole weights would round (0.0001
    /// to 0, a weight Moodle reads as 1).
    pub(crate) fn weigh<'e>(&mut self, entries: &[&'e Entry]) -> Result<(), &'e Entry> {
        let whole = |e: &Entry, k: f64| (e.points * k - (e.points * k).round()).abs() < 1e-9;
        let finest = POINT_STEPS[POINT_STEPS.len() - 1];
        if let Some(e) = entries.iter().find(|e| !whole(e, finest)) {
            return Err(e);
        }
        self.per_point = POINT_STEPS
            .into_iter()
            .find(|&k| entries.iter().all(|e| whole(e, k)))
            .unwrap_or(finest);
        Ok(())
    }

    /// The weight of each of a question's `parts` parts (3: a colour; 1: no hit) for `points`.
    fn weight(&self, points: f64, parts: u64) -> u64 {
        (points * self.per_point).round() as u64 * (3 / parts)
    }
}

/// A problem set: one category of the question bank.
pub(crate) struct Set {
    /// The category's last name, under `top/<parent>`.
    pub category: String,
    /// Its problems, in order.
    pub entries: Vec<Entry>,
}

/// The words of the quiz in `lang`.
fn words(lang: Lang) -> Words {
    match lang {
        Lang::En => Words {
            right: "Right.",
            right_8bit: "Right (read as 8-bit values, 0–255).",
            as_8bit: "read as 8-bit values, 0–255",
            unclamped: "Right: this is the value before the clamp to [0, 1] (Eq. 4.16); the colour shown is clamped.",
            reading: "Partly right: this is the likely intended reading",
            slip: "Likely slip:",
            other: "Wrong: compare with the worked solution.",
            no_hit_question: "Choose the colour of the point the ray meets, or \u{201c}{none}\u{201d} if it meets nothing:",
            no_hit_right: "Right: as written, the ray meets nothing.",
            solution: "Worked solution",
        },
        Lang::Pt => Words {
            right: "Correto.",
            right_8bit: "Correto (lido como valores de 8 bits, 0–255).",
            as_8bit: "lido como valores de 8 bits, 0–255",
            unclamped: "Correto: este é o valor antes do corte em [0, 1] (Eq. 4.16); a cor exibida é cortada.",
            reading: "Parcialmente correto: esta é a leitura provavelmente pretendida",
            slip: "Erro provável:",
            other: "Incorreto: compare com a solução comentada.",
            no_hit_question: "Escolha a cor do ponto atingido pelo raio, ou \u{201c}{none}\u{201d} se ele não atinge nada:",
            no_hit_right: "Correto: como enunciado, o raio não atinge nada.",
            solution: "Solução comentada",
        },
    }
}

struct Words {
    right: &'static str,
    right_8bit: &'static str,
    as_8bit: &'static str,
    unclamped: &'static str,
    reading: &'static str,
    slip: &'static str,
    other: &'static str,
    no_hit_question: &'static str,
    no_hit_right: &'static str,
    solution: &'static str,
}

/// The equation a slip's name gives, or the one it changes where its name gives none.
fn slip_text(slip: Slip, lang: Lang) -> String {
    let text = check_messages::slip(slip, lang);
    if text.contains("Eq.") {
        return text.to_owned();
    }
    format!("{text} ({})", slip.reference())
}

/// Escapes text for a Cloze answer or feedback (see the module's notes).
pub(crate) fn cloze_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '}' => out.push_str("\\}"),
            '#' => out.push_str("\\#"),
            '~' => out.push_str("&\\#126;"),
            '\\' => out.push_str("&\\#92;"),
            c => out.push(c),
        }
    }
    out
}

/// The question's own HTML (its statement, the data table, the no-hit prompt), made inert for
/// Moodle's Cloze parser: a sub-question is `{` weight `:` TYPE `:` … `}` anywhere in the
/// question text, so a problem's text holding `{2:SHORTANSWER:=x}` (or `{` from LaTeX-ish
/// notes) would become a live sub-question and change the grade. Every `{` and `}` is written
/// as its HTML reference, `&#123;` and `&#125;`: the browser (and MathJax, which reads the
/// page's text) shows the brace, while the parser, reading the raw text, sees none, so only
/// phong's own sub-questions match the grammar; `~`, `#` and `=` are read only inside one.
pub(crate) fn cloze_inert(html: &str) -> String {
    html.replace('{', "&#123;").replace('}', "&#125;")
}

/// A number as a Cloze NUMERICAL answer: plain decimal, at most six decimals.
fn number(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.into()
    }
}

/// A colour's value on the 0–1 scale: clamped where it is (the key's), else as computed.
fn value(t: &crate::check::Target) -> [f64; 3] {
    t.clamped.unwrap_or(t.unclamped)
}

/// One alternative of a part: its fraction, its answer and its feedback (HTML, unescaped).
struct Alt {
    fraction: String,
    answer: String,
    tolerance: Option<f64>,
    feedback: Vec<String>,
}

/// The NUMERICAL part of channel `c`.
fn channel(
    c: usize,
    expected: &Expected,
    entry: &Entry,
    grading: &Grading,
    lang: Lang,
) -> Option<String> {
    let w = words(lang);
    let tolerance = entry.tolerance;
    let right = value(&expected.solution?)[c];
    let mut alts = vec![Alt {
        fraction: "=".into(),
        answer: number(right),
        tolerance: Some(tolerance),
        feedback: vec![w.right.to_owned()],
    }];
    // Moodle grades by the first alternative within its tolerance (`get_matching_answer`),
    // inclusive and with a slack of 1e-14: an alternative within the tolerance of an earlier
    // one, as written, would never be reached. Within, here, is inclusive with a larger slack
    // (`phong check`'s own rule, `check::within_tolerance`: 0.675 − 0.67 is
    // 0.005000000000000004), measured
    // from the number written to the value's number as written and as computed, so that the
    // written alternatives lie more than the tolerance apart and `phong check` finds every
    // slip an alternative names within the tolerance of its number.
    let within = |a: f64, b: f64| crate::check::within_tolerance(a - b, tolerance);
    let written = |v: f64| number(v).parse::<f64>().unwrap_or(v);
    let shadowed = |v: f64, t: f64| within(t, v) || within(t, written(v));
    let right = written(right);
    let mut taken = vec![right];
    // `phong check` accepts the colour before the clamp to [0, 1] too (a channel above 1).
    let unclamped = expected.solution?.unclamped[c];
    if unclamped.is_finite() && !taken.iter().any(|&t| shadowed(unclamped, t)) {
        alts.push(Alt {
            fraction: "=".into(),
            answer: number(unclamped),
            tolerance: Some(tolerance),
            feedback: vec![w.unclamped.to_owned()],
        });
        taken.push(written(unclamped));
    }
    if let Some(r) = expected.readings.iter().find(|r| r.likely_intended) {
        let v = value(&r.target)[c];
        if v.is_finite() && !taken.iter().any(|&t| shadowed(v, t)) {
            alts.push(Alt {
                fraction: grading.reading.clone(),
                answer: number(v),
                tolerance: Some(tolerance),
                feedback: vec![format!(
                    "{} ({}).",
                    w.reading,
                    check_messages::reading(r.code, lang)
                )],
            });
            taken.push(written(v));
        }
    }
    // Each slip's number: left out where the right answer (or the reading) is met first;
    // joined to the first slip alternative within the tolerance of it, as Moodle would show
    // that one, whose feedback then names every slip that gives it.
    let mut slips: Vec<(f64, Alt)> = Vec::new();
    for o in expected.outcomes.iter().filter(|o| o.slips.len() == 1) {
        let v = value(&o.target)[c];
        if !v.is_finite() || taken.iter().any(|&t| shadowed(v, t)) {
            continue;
        }
        let text = format!("{} {}.", w.slip, slip_text(o.slips[0], lang));
        match slips.iter_mut().find(|(t, _)| shadowed(v, *t)) {
            Some((_, a)) => {
                if !a.feedback.contains(&text) {
                    a.feedback.push(text);
                }
            }
            None => slips.push((
                written(v),
                Alt {
                    fraction: "%0%".into(),
                    answer: number(v),
                    tolerance: Some(tolerance),
                    feedback: vec![text],
                },
            )),
        }
    }
    alts.extend(slips.into_iter().map(|(_, a)| a));
    // The course reads three whole numbers 0–255 written without a scale as 8-bit values: the
    // right answer's and the reading's numbers on the 255 scale, after every 0–1 alternative
    // (a number a 0–1 alternative takes is judged on the 0–1 scale first), each held above 1
    // ([`above_one`]).
    if grading.eight_bit {
        let t8 = entry.tolerance_bits8;
        let right8 = value(&expected.solution?)[c] * 255.0;
        let right_alt = above_one(right8, t8);
        if let Some((answer, tolerance)) = right_alt {
            alts.push(Alt {
                fraction: "=".into(),
                answer: number(answer),
                tolerance: Some(tolerance),
                feedback: vec![w.right_8bit.to_owned()],
            });
        }
        if let Some(r) = expected.readings.iter().find(|r| r.likely_intended) {
            let v = value(&r.target)[c] * 255.0;
            let shadowed = right_alt.is_some() && (v - right8).abs() <= t8 * (1.0 + 1e-9);
            if let Some((answer, tolerance)) = above_one(v, t8).filter(|_| !shadowed) {
                alts.push(Alt {
                    fraction: grading.reading.clone(),
                    answer: number(answer),
                    tolerance: Some(tolerance),
                    feedback: vec![format!(
                        "{} ({}; {}).",
                        w.reading,
                        check_messages::reading(r.code, lang),
                        w.as_8bit
                    )],
                });
            }
        }
    }
    alts.push(Alt {
        fraction: String::new(),
        answer: "*".into(),
        tolerance: None,
        feedback: vec![w.other.to_owned()],
    });
    Some(part(grading.weight(entry.points, 3), "NUMERICAL", &alts))
}

/// The smallest number an 8-bit alternative takes: below the smallest whole number above 1.
const EIGHT_BIT_FLOOR: f64 = 1.5;

/// An 8-bit alternative for `v8` (a value on the 255 scale, tolerance `t8`) as (answer,
/// tolerance), taking only numbers above 1: a part is graded alone, and `phong check` reads an
/// answer as 8-bit values only when one of its whole numbers is above 1
/// ([`crate::check::policy::looks_8bit`]), so a number up to 1 is on the 0–1 scale. An interval
/// reaching down to 1 would take a 0–1 number that every 0–1 alternative missed: 4.2's black
/// key, 0 ± 1 on the 255 scale, took 0.7 as right. The interval's lower end is raised to
/// [`EIGHT_BIT_FLOOR`]; `None` when no whole number above 1 is within the tolerance.
fn above_one(v8: f64, t8: f64) -> Option<(f64, f64)> {
    let (low, high) = (v8 - t8, v8 + t8);
    if !v8.is_finite() || high < 2.0 {
        None
    } else if low >= EIGHT_BIT_FLOOR {
        Some((v8, t8))
    } else {
        Some((
            (EIGHT_BIT_FLOOR + high) / 2.0,
            (high - EIGHT_BIT_FLOOR) / 2.0,
        ))
    }
}

/// A Cloze sub-question.
fn part(weight: u64, kind: &str, alts: &[Alt]) -> String {
    let body: Vec<String> = alts
        .iter()
        .map(|a| {
            let tol = a
                .tolerance
                .map_or(String::new(), |t| format!(":{}", number(t)));
            format!(
                "{}{}{tol}#{}",
                a.fraction,
                cloze_escape(&a.answer),
                cloze_escape(&esc(&a.feedback.join(" ")))
            )
        })
        .collect();
    format!("{{{weight}:{kind}:{}}}", body.join("~"))
}

/// A colour as a choice of the no-hit part: `(0.524, 0.027, 0)`, three decimals (six where the
/// tolerance is finer than 0.005), as `phong check` and `phong grade` read it back.
fn colour_choice(c: [f64; 3], tolerance: f64) -> String {
    let digits = if tolerance >= 0.005 { 3 } else { 6 };
    let n = |x: f64| {
        let s = format!("{x:.digits$}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" || s.is_empty() {
            "0".to_owned()
        } else {
            s.to_owned()
        }
    };
    format!("({}, {}, {})", n(c[0]), n(c[1]), n(c[2]))
}

/// The part of a problem with nothing to shade (its ray meets nothing as written): one
/// `MULTICHOICE_VS` part (vertical, shuffled) whose choices are "none" (the course's word, full
/// credit), the likely intended reading's colour (the reading's credit), the background's colour
/// (what a ray that meets nothing shows: none) and each slip's colour (none, its feedback naming
/// the slip). A Cloze question's grade is the weighted sum of its parts', and a blank part earns
/// nothing, so no layout of a text part beside three NUMERICAL parts can give "none" full
/// credit *and* a colour the reading's: one part whose choices are both can. Colours within the
/// tolerance of an earlier choice are not choices of their own: a slip's joins that choice's
/// feedback (the reading's and "none" shadow it, as in [`channel`]).
fn no_hit_choice(expected: &Expected, entry: &Entry, grading: &Grading, lang: Lang) -> String {
    let w = words(lang);
    let tolerance = entry.tolerance;
    let close = |a: [f64; 3], b: [f64; 3]| {
        (0..3).all(|k| crate::check::within_tolerance(a[k] - b[k], tolerance))
    };
    let mut alts = vec![Alt {
        fraction: "=".into(),
        answer: grading.none.clone(),
        tolerance: None,
        feedback: vec![w.no_hit_right.into()],
    }];
    // Each colour taken, and whether a slip may join its alternative.
    let mut taken: Vec<([f64; 3], usize, bool)> = Vec::new();
    if let Some(r) = expected.readings.iter().find(|r| r.likely_intended) {
        let v = value(&r.target);
        if v.iter().all(|x| x.is_finite()) {
            taken.push((v, alts.len(), false));
            alts.push(Alt {
                fraction: grading.reading.clone(),
                answer: colour_choice(v, tolerance),
                tolerance: None,
                feedback: vec![format!(
                    "{} ({}).",
                    w.reading,
                    check_messages::reading(r.code, lang)
                )],
            });
        }
    }
    let background = expected.background;
    if !taken.iter().any(|(t, _, _)| close(*t, background)) {
        taken.push((background, alts.len(), true));
        alts.push(Alt {
            fraction: "%0%".into(),
            answer: colour_choice(background, tolerance),
            tolerance: None,
            feedback: vec![capitalised(&check_messages::background(background, lang)) + "."],
        });
    }
    // Each slip, made alone or in the likely intended reading (with the hit behind the
    // origin: one slip, as `phong check` counts it).
    let intended = expected.intended_slips();
    for o in &expected.outcomes {
        let mistakes: Vec<Slip> = o
            .slips
            .iter()
            .copied()
            .filter(|s| o.slips.len() == 1 || !intended.contains(s))
            .collect();
        let v = value(&o.target);
        if mistakes.len() != 1 || !v.iter().all(|x| x.is_finite()) {
            continue;
        }
        let text = if mistakes.len() < o.slips.len() {
            format!(
                "{} {} ({}).",
                w.slip,
                slip_text(mistakes[0], lang),
                check_messages::in_intended_reading(lang)
            )
        } else {
            format!("{} {}.", w.slip, slip_text(mistakes[0], lang))
        };
        match taken.iter().find(|(t, _, _)| close(*t, v)) {
            Some(&(_, i, true)) => {
                if !alts[i].feedback.contains(&text) {
                    alts[i].feedback.push(text);
                }
            }
            Some(_) => {}
            None => {
                taken.push((v, alts.len(), true));
                alts.push(Alt {
                    fraction: "%0%".into(),
                    answer: colour_choice(v, tolerance),
                    tolerance: None,
                    feedback: vec![text],
                });
            }
        }
    }
    part(grading.weight(entry.points, 1), "MULTICHOICE_VS", &alts)
}

/// A line of a solution in HTML with MathJax's inline delimiters.
fn mathjax_line(step: &Step, lang: Lang) -> String {
    let mut s = String::new();
    for run in runs(&step.line) {
        match run {
            Run::Text(t) => s.push_str(&esc(&t)),
            Run::Math(m) => {
                let _ = write!(s, "\\({}\\)", esc(&latex_math(&m)));
            }
            Run::Swatch(_) => {}
        }
    }
    if let Some(eq) = step.eq {
        let _ = write!(s, " <small>({})</small>", esc(&eq.text(lang)));
    }
    s
}

fn mathjax_list(out: &mut String, nodes: &[Node], lang: Lang) {
    if nodes.is_empty() {
        return;
    }
    out.push_str("<ul>");
    for node in nodes {
        let _ = write!(out, "<li>{}", mathjax_line(node.step, lang));
        mathjax_list(out, &node.children, lang);
        out.push_str("</li>");
    }
    out.push_str("</ul>\n");
}

/// The general feedback (HTML) and the files it shows.
fn solution(x: &Explanation, q: usize, lang: Lang) -> (String, Vec<(String, String)>) {
    let w = words(lang);
    let mut out = format!("<h3>{}</h3>\n", esc(w.solution));
    let mut files = Vec::new();
    if !x.findings.is_empty() {
        out.push_str("<ul>");
        for f in &x.findings {
            let _ = write!(out, "<li>{}</li>", esc(f));
        }
        out.push_str("</ul>\n");
    }
    if let Some(ray) = &x.ray {
        mathjax_list(&mut out, &nest(ray), lang);
    }
    for (i, part) in x.parts.iter().enumerate() {
        let _ = writeln!(out, "<h4>{}</h4>", esc(&part.heading));
        if let Some(e) = &part.explanation {
            let _ = writeln!(out, "<p><em>{}</em></p>", esc(e));
        }
        if let Some(ray) = &part.ray {
            mathjax_list(&mut out, &nest(ray), lang);
        }
        let Some(sh) = &part.shading else {
            continue;
        };
        shading(&mut out, &mut files, sh, q, i, lang);
    }
    (out, files)
}

fn shading(
    out: &mut String,
    files: &mut Vec<(String, String)>,
    sh: &Shading,
    q: usize,
    i: usize,
    lang: Lang,
) {
    for d in &sh.diagrams {
        let name = format!("diagrama-{q}-{i}-{}.svg", d.light_index);
        let id = format!("d{q}-{i}-{}", d.light_index);
        let figure = diagram::figure(d, &id, lang);
        let _ = writeln!(
            out,
            "<p><img src=\"@@PLUGINFILE@@/{name}\" alt=\"{}\"><br><small>{}. {}</small></p>",
            esc(&figure.title),
            esc(&figure.title),
            esc(&figure.caption)
        );
        files.push((
            name,
            base64(standalone_svg(&diagram::svg(d, &id, lang)).as_bytes()),
        ));
    }
    for steps in [&sh.given, &sh.steps, &sh.total] {
        mathjax_list(out, &nest(steps), lang);
    }
}

/// The `<svg>` of a diagram's HTML figure as a file of its own: an `<img>` gets no page
/// stylesheet, so the SVG rules of the HTML report's (`report::html::STYLE`) go inside it.
fn standalone_svg(figure: &str) -> String {
    let start = figure.find("<svg").unwrap_or(0);
    let end = figure
        .find("</svg>")
        .map_or(figure.len(), |e| e + "</svg>".len());
    let svg = &figure[start..end];
    let rules: String = STYLE.lines().filter(|l| l.starts_with("svg ")).collect();
    match svg.find('>') {
        Some(open) => format!(
            "{}<style>{rules}</style>{}\n",
            &svg[..=open],
            &svg[open + 1..]
        ),
        None => svg.to_owned(),
    }
}

/// Standard base64 (RFC 4648, with padding).
pub(crate) fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Text for a CDATA section: `text::xml`'s one rule (docs/conventions.md, "XML text").
fn cdata(s: &str) -> String {
    crate::text::xml::cdata(s)
}

/// A category's name as one name of a Moodle category path: each `/` doubled, and a space
/// before a leading `/` and after a trailing one (which Moodle's importer trims), as Moodle's
/// own `assemble_category_path` writes it, so that its `split_category_path` gives the name
/// back whole.
pub(crate) fn category_name(name: &str) -> String {
    let mut escaped = name.replace('/', "//");
    if escaped.starts_with('/') {
        escaped.insert(0, ' ');
    }
    if escaped.ends_with('/') {
        escaped.push(' ');
    }
    escaped
}

/// Text escaped for an XML element: `text::xml`'s one rule (docs/conventions.md, "XML text").
fn xml(s: &str) -> String {
    crate::text::xml::escape(s)
}

/// A problem that cannot be a question: the index of its set, its index among the set's
/// entries, and why.
pub(crate) type Unasked = (usize, usize, crate::problem::ProblemError);

/// The quiz: every set's category, then its questions. `parent` is the categories' parent
/// under `top`. Every problem that cannot be a question is said, in order, not only the first.
pub(crate) fn quiz(
    sets: &[Set],
    parent: &str,
    grading: &Grading,
    lang: Lang,
) -> Result<String, Vec<Unasked>> {
    let mut unasked = Vec::new();
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n");
    let mut q = 0;
    for (i, set) in sets.iter().enumerate() {
        let path = format!(
            "$course$/top/{}/{}",
            category_name(parent),
            category_name(&set.category)
        );
        let _ = writeln!(
            out,
            "<question type=\"category\">\n<category><text>{}</text></category>\n</question>",
            xml(&path)
        );
        for (k, entry) in set.entries.iter().enumerate() {
            q += 1;
            if let Err(e) = question(&mut out, entry, q, grading, lang) {
                unasked.push((i, k, e.at(std::path::Path::new(&entry.label))));
            }
        }
    }
    if !unasked.is_empty() {
        return Err(unasked);
    }
    out.push_str("</quiz>\n");
    Ok(out)
}

fn question(
    out: &mut String,
    entry: &Entry,
    q: usize,
    grading: &Grading,
    lang: Lang,
) -> Result<(), crate::problem::Invalid> {
    let expected = Expected::of(&entry.problem)?;
    let solved = crate::solve::solve(&entry.problem)?;
    let x = crate::report::explain::explain(&entry.label, &entry.problem, &solved, lang);
    let w = words(lang);
    let mut text = String::new();
    if let Some(question) = &x.question {
        let _ = writeln!(text, "<p>{}</p>", cloze_inert(&esc(question)));
    }
    text.push_str(&cloze_inert(&data_table(&x.data, lang)));
    match (0..3)
        .map(|c| channel(c, &expected, entry, grading, lang))
        .collect::<Option<Vec<String>>>()
    {
        Some(parts) => {
            let _ = writeln!(
                text,
                "<p>R = {} &nbsp; G = {} &nbsp; B = {}</p>",
                parts[0], parts[1], parts[2]
            );
        }
        None => {
            let _ = writeln!(
                text,
                "<p>{} {}</p>",
                cloze_inert(&esc(&w.no_hit_question.replace("{none}", &grading.none))),
                no_hit_choice(&expected, entry, grading, lang)
            );
        }
    }
    let (feedback, files) = solution(&x, q, lang);
    let _ = writeln!(out, "<question type=\"cloze\">");
    let _ = writeln!(
        out,
        "<name><text>{}</text></name>",
        xml(&format!("{q:03}. {}", x.title))
    );
    let _ = writeln!(
        out,
        "<questiontext format=\"html\"><text>{}</text></questiontext>",
        cdata(&text)
    );
    let _ = write!(
        out,
        "<generalfeedback format=\"html\"><text>{}</text>",
        cdata(&feedback)
    );
    for (name, data) in &files {
        let _ = write!(
            out,
            "\n<file name=\"{}\" path=\"/\" encoding=\"base64\">{data}</file>",
            xml(name)
        );
    }
    let _ = writeln!(out, "</generalfeedback>");
    out.push_str("<penalty>0.3333333</penalty>\n<hidden>0</hidden>\n</question>\n");
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_examples() {
        // RFC 4648, section 10.
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn cloze_specials_are_escaped() {
        assert_eq!(cloze_escape("a}b#c~d\\e"), "a\\}b\\#c&\\#126;d&\\#92;e");
    }

    #[test]
    fn the_questions_own_braces_are_html_references() {
        assert_eq!(
            cloze_inert("a {2:SHORTANSWER:=x} \\frac{1}{2}"),
            "a &#123;2:SHORTANSWER:=x&#125; \\frac&#123;1&#125;&#123;2&#125;"
        );
    }

    #[test]
    fn category_names_are_written_as_moodles_assemble_category_path_writes_them() {
        // Moodle's own test of its path functions (question/tests/importexport_test.php).
        assert_eq!(
            category_name("Tricky things like / // and so on"),
            "Tricky things like // //// and so on"
        );
        assert_eq!(
            category_name("Category name ending in /"),
            "Category name ending in // "
        );
        assert_eq!(
            category_name("/ and one that starts with one"),
            " // and one that starts with one"
        );
        assert_eq!(category_name("A/B 50%"), "A//B 50%");
        assert_eq!(
            category_name("Cap. 4 - Modelos de Iluminação"),
            "Cap. 4 - Modelos de Iluminação"
        );
    }

    #[test]
    fn numbers_are_plain_decimals() {
        assert_eq!(number(0.52), "0.52");
        assert_eq!(number(1.0), "1");
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(0.1234567), "0.123457");
    }
}
