//! `phong check --format markdown`: each verdict for notes and course pages, with the same
//! content as the HTML page (`html.rs`): the verdict and its credit, the answer's and the
//! expected colour (with their `#RRGGBB`, since Markdown has no swatch), each channel against
//! the tolerance, what the answer matches (the list [`crate::check::matches::matches`] decides
//! for every report) with the equation where each slip departs, the steps judged, then the
//! worked solution as `phong solve --format markdown` writes it.

use std::fmt::Write;

use super::Writer;
use crate::check::matches::{matches, Layout, Match};
use crate::check::messages::{self as said, Line, Page};
use crate::check::report::{Checked, Judged};
use crate::check::steps::{self, StepsChecked, StepsJudged};
use crate::check::Scale;
use crate::report::explain::capitalised;
use crate::report::markdown::{escape, head, write_parts};
use crate::text::number::num;
use crate::text::{Lang, Message};

/// The Markdown of a run's checks.
pub(crate) struct MarkdownWriter {
    lang: Lang,
    out: String,
    index: usize,
}

impl MarkdownWriter {
    pub(crate) fn new(lang: Lang) -> Self {
        MarkdownWriter {
            lang,
            out: String::new(),
            index: 0,
        }
    }
}

fn triple(v: [f64; 3]) -> String {
    crate::check::report::triple(v, num)
}

/// `#RRGGBB` of a colour on `scale` (clamped to [0, 1]), as the page's swatch shows it.
fn hex(v: [f64; 3], scale: Scale) -> String {
    let c = super::html::rgb8(v, scale);
    format!("#{:02X}{:02X}{:02X}", c[0], c[1], c[2])
}

fn answer(out: &mut String, j: &Judged, lang: Lang) {
    let v = &j.verdict;
    let scale = j.answer.scale;
    let _ = writeln!(
        out,
        "**{}.** {}: {}\n",
        escape(&capitalised(said::verdict(v.kind, v.accepted, lang))),
        escape(&capitalised(said::line(Line::Credit, lang))),
        escape(&said::Credit::of(j.credit, j.policy.as_deref()).text(lang))
    );
    match j.answer.values {
        Some(values) => {
            let _ = writeln!(
                out,
                "- {}: {} `{}`{}",
                escape(&Page::YourAnswer.text(lang)),
                escape(&triple(values)),
                hex(values, scale),
                if j.as_8bit {
                    format!(" ({})", escape(said::read_as_8bit(lang)))
                } else {
                    String::new()
                }
            );
        }
        None => {
            let _ = writeln!(
                out,
                "- {}: {}",
                escape(&Page::YourAnswer.text(lang)),
                escape(said::no_hit_answer(lang))
            );
        }
    }
    let (expected, source) = super::expected(v, lang);
    let label = escape(&Page::Expected.text(lang));
    let _ = match expected {
        Some(c) => writeln!(
            out,
            "- {label}: {} `{}` ({})\n",
            escape(&triple(c)),
            hex(c, scale),
            escape(&source)
        ),
        None => writeln!(out, "- {label}: {}\n", escape(&source)),
    };
    if let (Some(cmp), Some(values)) = (&v.comparison, j.answer.values) {
        let _ = writeln!(
            out,
            "{}\n\n| {} | {} | {} | {} | {} |\n|---|---|---|---|---|",
            escape(
                &Page::ChannelsCaption {
                    tolerance: crate::text::Num(j.tolerance),
                    scale: said::per_channel(scale, lang).to_owned(),
                }
                .text(lang)
            ),
            escape(&Page::Channel.text(lang)),
            escape(&Page::YourAnswer.text(lang)),
            escape(&Page::Expected.text(lang)),
            escape(&capitalised(said::line(Line::Difference, lang))),
            escape(&Page::Judged.text(lang)),
        );
        for (k, name) in ["R", "G", "B"].iter().enumerate() {
            let d = cmp.difference[k];
            let within = crate::check::within_tolerance(d, j.tolerance);
            let word = if within {
                Page::Within.text(lang)
            } else {
                Page::Outside.text(lang)
            };
            let signed = if d > 0.0 && num(d) != "0" {
                format!("+{}", num(d))
            } else {
                num(d)
            };
            let _ = writeln!(
                out,
                "| {name} | {} | {} | {} | {} |",
                num(values[k]),
                num(cmp.expected[k]),
                signed,
                escape(&word)
            );
        }
        out.push('\n');
    }
    // Each entry as Markdown: its words escaped, a colour's `#RRGGBB` as code.
    let swatch = |sentence: &str, colour: [f64; 3]| {
        format!(
            "{}: {} `{}`",
            escape(sentence),
            escape(&triple(colour)),
            hex(colour, scale)
        )
    };
    let mut items: Vec<String> = Vec::new();
    for m in matches(v, j.tolerance, Layout::WithExpected) {
        match m {
            // Said by the expected line above.
            Match::HasColour { .. } | Match::NothingToShade => {}
            Match::Reading { reading, likely } => {
                items.push(escape(&said::matches_reading(reading.code, likely, lang)))
            }
            Match::AsWritten(w) => items.push(swatch(said::as_written_phrase(lang), w.expected)),
            Match::NothingAsWritten => items.push(escape(said::nothing_to_shade(lang))),
            Match::Background(colour) => items.push(escape(&said::background(colour, lang))),
            // Each diagnosis an entry of its own, with its colour and its equations.
            Match::Slips { diagnoses, .. } => items.extend(diagnoses.iter().map(|d| {
                let text = said::slips_made(&d.slips, &d.intended, lang);
                let refs: Vec<&str> = d.mistakes().iter().map(|s| s.reference()).collect();
                format!(
                    "{} — {}",
                    swatch(&text, d.comparison.expected),
                    escape(&refs.join(", "))
                )
            })),
            Match::NoDiagnosis => items.push(escape(said::no_diagnosis(lang))),
            Match::Looks8bit => items.push(escape(said::looks_8bit(lang))),
            Match::Nearest(n) => items.push(swatch(
                &said::nearest(&n.candidate, n.comparison.distance(), j.tolerance, lang),
                n.comparison.expected,
            )),
            // The expected line above has this colour: the sentence only.
            Match::NearMiss(n) => items.push(escape(&said::nearest(
                &n.candidate,
                n.comparison.distance(),
                j.tolerance,
                lang,
            ))),
            Match::Unclamped => items.push(escape(said::unclamped_note(lang))),
        }
    }
    if !items.is_empty() {
        let _ = writeln!(out, "{}\n", escape(&Page::AboutTheAnswer.text(lang)));
        for i in items {
            let _ = writeln!(out, "- {i}");
        }
        out.push('\n');
    }
}

fn steps_table(out: &mut String, j: &StepsJudged, lang: Lang) {
    let _ = writeln!(
        out,
        "**{}**\n\n| {} | {} | {} |\n|---|---|---|",
        escape(&capitalised(said::steps_heading(lang))),
        escape(&Page::Quantity.text(lang)),
        escape(&Page::YourValue.text(lang)),
        escape(&Page::Judged.text(lang)),
    );
    for (k, s) in j.steps.iter().enumerate() {
        let mark = if j.first_wrong == Some(k) {
            format!(" **({})**", escape(&Page::FirstWrong.text(lang)))
        } else {
            String::new()
        };
        let _ = writeln!(
            out,
            "| `{}` | {} | {}{mark} |",
            s.label(),
            escape(&s.given.value.text()),
            escape(&steps::step_message(s, lang))
        );
    }
    let closing = steps::closing(j, lang);
    let _ = writeln!(out, "\n{}\n", escape(&closing));
}

impl Writer for MarkdownWriter {
    fn add(&mut self, answer_checked: Option<&Checked>, steps: Option<&StepsChecked>) {
        let lang = self.lang;
        let judged = answer_checked.and_then(|c| c.outcome.as_ref().ok());
        let steps_judged = steps.and_then(|s| s.outcome.as_ref().ok());
        let file = answer_checked
            .map(|c| c.file.clone())
            .or_else(|| steps.map(|s| s.file.clone()));
        let (Some(file), true) = (file, judged.is_some() || steps_judged.is_some()) else {
            return;
        };
        let x = crate::report::file::explain_source(
            crate::problem::Source::File(std::path::Path::new(&file)),
            crate::core::Precision::F64,
            lang,
        )
        .ok();
        if !self.out.is_empty() {
            self.out.push_str("\n---\n\n");
        }
        let title = x.as_ref().map_or_else(|| file.clone(), |x| x.title.clone());
        self.out.push_str(&head(
            &title,
            &file,
            x.as_ref().and_then(|x| x.question.as_deref()),
        ));
        if let Some(j) = judged {
            answer(&mut self.out, j, lang);
        }
        if let Some(j) = steps_judged {
            steps_table(&mut self.out, j, lang);
        }
        if let Some(x) = &x {
            let _ = writeln!(
                self.out,
                "## {}\n",
                escape(&Page::WorkedSolution.text(lang))
            );
            self.out.push_str(&write_parts(x, self.index, 2));
        }
        self.index += 1;
    }

    fn finish(self: Box<Self>) -> String {
        self.out
    }
}
