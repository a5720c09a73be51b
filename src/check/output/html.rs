//! `phong check --format html`: each verdict as a page a student reads in a browser, and the
//! same fragments for the web checker's verdict (`serve/pages/exercise.rs`): one layout, both
//! uses.
//!
//! An answer's verdict: the verdict in words and what it earns under the course policy; the
//! answer's and the expected colour side by side as swatches with their numbers on the answer's
//! scale (each swatch has a text alternative: colour is never the only signal); the difference
//! per channel against the tolerance, "within" or "outside" in words; each reading or slip the
//! answer matches, as a sentence with the colour it gives and a link to the step of the worked
//! solution where it departs (the first step applying its equation: `report::html::step_anchor`).
//! Steps (`--step`): a table of the steps given, each judged and linked to its step in the
//! solution, the first wrong one marked. The page ends with the worked solution, as `phong
//! solve --format html` writes it, so the links land on the page.

use std::fmt::Write;

use super::Writer;
use crate::check::matches::{matches, Layout, Match};
use crate::check::messages::{self as said, Line, Page};
use crate::check::report::{Checked, Judged};
use crate::check::steps::{self, StepVerdict, StepsChecked, StepsJudged};
use crate::check::{Candidate, Nearest, Scale, VerdictKind};
use crate::report::explain::{capitalised, Explanation, Ref};
use crate::report::html::{esc, step_anchor, swatch};
use crate::text::number::num;
use crate::text::{Lang, Message};

/// The verdict's own rules, beside the explanation's stylesheet (`report::html::STYLE`), in the
/// page `phong check` writes and in `phong serve`'s stylesheet.
pub(crate) const STYLE: &str = "\
.verdict{margin:1rem 0;padding:.6rem 1rem;border-left:6px solid #888;background:#f6f6f6}
.verdict.right{border-left-color:#2e7d32;background:#eef7ee}
.verdict.wrong{border-left-color:#c62828;background:#fbeeee}
.verdict.reading{border-left-color:#b36b00;background:#fff6e5;color:inherit;font-style:normal}
.verdict .headline{font-size:1.15rem;font-weight:bold;margin:.2rem 0}
.verdict .credit{margin:.2rem 0 .6rem}
.colours{display:flex;flex-wrap:wrap;gap:1.5rem;margin:.5rem 0}
.colours figure{margin:0;display:flex;gap:.6rem;align-items:center}
.colours figcaption{line-height:1.4}
table.channels,table.judged{border-collapse:collapse;margin:.5rem 0}
table.channels td,table.channels th,table.judged td,table.judged th{border-top:1px solid #ddd;padding:.25rem .5rem;text-align:left;vertical-align:top}
td.within,td.right{color:#2e7d32}td.outside,td.wrong{color:#c62828}td.reading{color:#8a5200}
tr.first-wrong th,tr.first-wrong td{background:#fbeeee}
ul.matches li{margin:.3rem 0}
.errors li{color:#a00}
";

/// Where the verdict's links point: the worked solution's article `index` (its ids are
/// `part-{index}-…`), on this page (`base` empty) or on the page `base` (the web checker's
/// exercise with its solution shown).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Links<'a> {
    /// The article's index in the solution's page.
    pub index: usize,
    /// The page the solution is on (`""`: this one).
    pub base: &'a str,
}

impl Links<'_> {
    fn href(&self, id: &str) -> String {
        format!("{}#{id}", self.base)
    }

    /// A link to the part of `x` solving `reading` (`None`: the problem as written).
    fn part(
        &self,
        x: &Explanation,
        reading: Option<crate::solve::ReadingCode>,
        lang: Lang,
    ) -> String {
        match x.parts.iter().position(|p| p.reading == reading) {
            Some(i) => format!(
                " <a href=\"{}\">{}</a>",
                esc(&self.href(&format!("part-{}-{i}", self.index))),
                esc(&Page::SeeSolution.text(lang))
            ),
            None => String::new(),
        }
    }

    /// A link to the step of `x`'s part `reading` that first applies `reference` (`Eq. 4.7`),
    /// or nothing when no step does.
    fn step(
        &self,
        x: &Explanation,
        reading: Option<crate::solve::ReadingCode>,
        reference: &str,
        lang: Lang,
    ) -> String {
        match self.step_href(x, reading, reference) {
            Some(href) => format!(
                " <a href=\"{}\">{}</a>",
                esc(&href),
                esc(&Page::SeeStep {
                    reference: reference.to_owned()
                }
                .text(lang))
            ),
            None => String::new(),
        }
    }

    /// Where [`Links::step`] links to, if a step of the part applies `reference`.
    fn step_href(
        &self,
        x: &Explanation,
        reading: Option<crate::solve::ReadingCode>,
        reference: &str,
    ) -> Option<String> {
        let part = x.parts.iter().position(|p| p.reading == reading)?;
        let anchor = Ref::anchor_of(reference)?;
        step_anchor(x, self.index, part, &anchor).map(|id| self.href(&id))
    }
}

/// The likely intended reading of `x`, the part a slip made in it departs in.
fn intended(x: &Explanation) -> Option<crate::solve::ReadingCode> {
    x.parts
        .iter()
        .filter_map(|p| p.reading)
        .find(|r| r.likely_intended())
}

fn triple(v: [f64; 3]) -> String {
    crate::check::report::triple(v, num)
}

/// A colour on `scale` as 8 bits for a swatch (clamped to [0, 1] first).
pub(crate) fn rgb8(v: [f64; 3], scale: Scale) -> [u8; 3] {
    crate::core::color::rgb8(v.map(|x| x / scale.factor()))
}

/// A colour as a swatch with its numbers and a caption, the swatch named for a reader that does
/// not see it.
fn colour_figure(caption: &str, v: [f64; 3], scale: Scale, note: &str, lang: Lang) -> String {
    let shown = triple(v);
    let alt = format!("{caption}: {shown}");
    let _ = lang;
    format!(
        "<figure class=\"colour\">{}<figcaption><strong>{}</strong> {}<br><small>{}</small>\
         </figcaption></figure>\n",
        swatch(rgb8(v, scale), "big", &alt),
        esc(caption),
        esc(&shown),
        esc(note)
    )
}

/// The verdict on one judged answer, as an HTML fragment (the module's notes). The verdict's
/// code and the slips' codes (each diagnosis's `slips`, joined by `+`) are in `data-`
/// attributes, as `phong check --format json` names them.
pub(crate) fn answer_fragment(
    c: &Checked,
    j: &Judged,
    x: Option<&Explanation>,
    links: Links<'_>,
    lang: Lang,
) -> String {
    let v = &j.verdict;
    let class = match (v.kind, v.accepted) {
        (VerdictKind::Right, _) => "right",
        (VerdictKind::Reading, true) => "reading",
        _ => "wrong",
    };
    let codes: Vec<String> = v
        .diagnosis
        .iter()
        .map(|d| {
            d.slips
                .iter()
                .map(|s| s.code())
                .collect::<Vec<_>>()
                .join("+")
        })
        .collect();
    let mut out = format!(
        "<div class=\"verdict {class}\" data-verdict=\"{}\" data-slips=\"{}\">\n\
         <p class=\"headline\">{}</p>\n<p class=\"credit\">{}: {}</p>\n",
        crate::check::report::verdict_code(v.kind),
        esc(&codes.join(" ")),
        esc(&capitalised(said::verdict(v.kind, v.accepted, lang))),
        esc(&capitalised(said::line(Line::Credit, lang))),
        esc(&said::Credit::of(j.credit, j.policy.as_deref()).text(lang))
    );
    let scale = j.answer.scale;
    // The two colours side by side.
    out.push_str("<div class=\"colours\">\n");
    match j.answer.values {
        Some(values) => {
            let note = if j.as_8bit {
                said::read_as_8bit(lang).to_owned()
            } else {
                said::per_channel(scale, lang).to_owned()
            };
            out.push_str(&colour_figure(
                &Page::YourAnswer.text(lang),
                values,
                scale,
                &note,
                lang,
            ));
        }
        None => {
            let _ = writeln!(
                out,
                "<p><strong>{}</strong> {}</p>",
                esc(&Page::YourAnswer.text(lang)),
                esc(said::no_hit_answer(lang))
            );
        }
    }
    let (expected, source) = super::expected(v, lang);
    match expected {
        Some(c) => out.push_str(&colour_figure(
            &Page::Expected.text(lang),
            c,
            scale,
            &source,
            lang,
        )),
        None => {
            let _ = writeln!(
                out,
                "<p><strong>{}</strong> {}</p>",
                esc(&Page::Expected.text(lang)),
                esc(&source)
            );
        }
    }
    out.push_str("</div>\n");
    // The difference per channel against the tolerance.
    if let (Some(cmp), Some(values)) = (&v.comparison, j.answer.values) {
        let _ = writeln!(
            out,
            "<table class=\"channels\">\n<caption>{}</caption>\n<tr><th scope=\"col\">{}</th>\
             <th scope=\"col\">{}</th><th scope=\"col\">{}</th><th scope=\"col\">{}</th>\
             <th scope=\"col\">{}</th></tr>",
            esc(&Page::ChannelsCaption {
                tolerance: crate::text::Num(j.tolerance),
                scale: said::per_channel(scale, lang).to_owned(),
            }
            .text(lang)),
            esc(&Page::Channel.text(lang)),
            esc(&Page::YourAnswer.text(lang)),
            esc(&Page::Expected.text(lang)),
            esc(&capitalised(said::line(Line::Difference, lang))),
            esc(&Page::Judged.text(lang)),
        );
        for (k, name) in ["R", "G", "B"].iter().enumerate() {
            let d = cmp.difference[k];
            let within = crate::check::within_tolerance(d, j.tolerance);
            let (class, word) = if within {
                ("within", Page::Within.text(lang))
            } else {
                ("outside", Page::Outside.text(lang))
            };
            let signed = if d > 0.0 && num(d) != "0" {
                format!("+{}", num(d))
            } else {
                num(d)
            };
            let _ = writeln!(
                out,
                "<tr><th scope=\"row\">{name}</th><td>{}</td><td>{}</td><td>{}</td>\
                 <td class=\"{class}\">{}</td></tr>",
                esc(&num(values[k])),
                esc(&num(cmp.expected[k])),
                esc(&signed),
                esc(&word)
            );
        }
        out.push_str("</table>\n");
    }
    // What the answer matches, each with its colour and where it departs.
    let nearest = |n: &Nearest| {
        let sentence = said::nearest(&n.candidate, n.comparison.distance(), j.tolerance, lang);
        let link = x.map_or(String::new(), |x| match &n.candidate {
            Candidate::Written => links.part(x, None, lang),
            Candidate::Reading(code, _) => links.part(x, Some(*code), lang),
            Candidate::Slips { slips, intended: i } => {
                let reading = if i.is_empty() { None } else { intended(x) };
                slips
                    .iter()
                    .filter(|s| !i.contains(s))
                    .map(|s| links.step(x, reading, s.reference(), lang))
                    .collect()
            }
        });
        (sentence, link)
    };
    let mut items: Vec<String> = Vec::new();
    for m in matches(v, j.tolerance, Layout::WithExpected) {
        match m {
            // Said by the expected colour above.
            Match::HasColour { .. } | Match::NothingToShade => {}
            Match::Reading { reading, likely } => {
                let link = x.map_or(String::new(), |x| links.part(x, Some(reading.code), lang));
                items.push(format!(
                    "{}{link}",
                    esc(&said::matches_reading(reading.code, likely, lang))
                ));
            }
            Match::AsWritten(w) => items.push(coloured(
                said::as_written_phrase(lang),
                w.expected,
                scale,
                &x.map_or(String::new(), |x| links.part(x, None, lang)),
            )),
            Match::NothingAsWritten => items.push(esc(said::nothing_to_shade(lang))),
            Match::Background(colour) => items.push(esc(&said::background(colour, lang))),
            // Each diagnosis an entry of its own, with its colour and its steps.
            Match::Slips { diagnoses, .. } => items.extend(diagnoses.iter().map(|d| {
                let text = said::slips_made(&d.slips, &d.intended, lang);
                let reading = if d.intended.is_empty() {
                    None
                } else {
                    x.and_then(intended)
                };
                let links_html: String = x.map_or(String::new(), |x| {
                    d.mistakes()
                        .iter()
                        .map(|s| links.step(x, reading, s.reference(), lang))
                        .collect()
                });
                coloured(&text, d.comparison.expected, scale, &links_html)
            })),
            Match::NoDiagnosis => items.push(esc(said::no_diagnosis(lang))),
            Match::Looks8bit => items.push(esc(said::looks_8bit(lang))),
            Match::Nearest(n) => {
                let (sentence, link) = nearest(n);
                items.push(coloured(&sentence, n.comparison.expected, scale, &link));
            }
            // The expected colour above is this one: the sentence only.
            Match::NearMiss(n) => {
                let (sentence, link) = nearest(n);
                items.push(format!("{}{link}", esc(&sentence)));
            }
            Match::Unclamped => items.push(esc(said::unclamped_note(lang))),
        }
    }
    if !items.is_empty() {
        let _ = writeln!(
            out,
            "<p>{}</p>\n<ul class=\"matches\">",
            esc(&Page::AboutTheAnswer.text(lang))
        );
        for i in items {
            let _ = writeln!(out, "<li>{i}</li>");
        }
        out.push_str("</ul>\n");
    }
    let _ = c;
    out.push_str("</div>\n");
    out
}

/// An entry of "what it matches" with a colour: its swatch, the sentence and the colour, then
/// `links` (HTML) to where it departs in the solution.
fn coloured(sentence: &str, colour: [f64; 3], scale: Scale, links: &str) -> String {
    format!(
        "{} {}{links}",
        swatch(rgb8(colour, scale), "sw", &triple(colour)),
        esc(&format!("{sentence}: {}", triple(colour)))
    )
}

/// The steps judged, as an HTML fragment: a table (the quantity, linked to its step in the
/// solution; the value given; the verdict with its equation and what the value is), the first
/// wrong step marked, then a sentence on it, and the tolerance.
pub(crate) fn steps_fragment(
    j: &StepsJudged,
    x: Option<&Explanation>,
    links: Links<'_>,
    lang: Lang,
) -> String {
    let overall = steps::overall(j);
    let mut out = format!(
        "<div class=\"verdict step-check {overall}\" data-verdict=\"{overall}\">\n\
         <p class=\"headline\">{}</p>\n<table class=\"judged\">\n<tr><th scope=\"col\">{}</th>\
         <th scope=\"col\">{}</th><th scope=\"col\">{}</th></tr>\n",
        esc(&capitalised(said::steps_heading(lang))),
        esc(&Page::Quantity.text(lang)),
        esc(&Page::YourValue.text(lang)),
        esc(&Page::Judged.text(lang)),
    );
    for (k, s) in j.steps.iter().enumerate() {
        let class = match s.verdict {
            StepVerdict::Right => "right",
            StepVerdict::Reading => "reading",
            StepVerdict::Wrong => "wrong",
        };
        let first = j.first_wrong == Some(k);
        let row_class = if first { " class=\"first-wrong\"" } else { "" };
        let reading = s.expected_from_reading;
        let equation = steps::equation(&s.expected, lang);
        let name = format!("<code>{}</code>", esc(&s.label()));
        let name = match x.and_then(|x| links.step_href(x, reading, &equation)) {
            Some(href) => format!("<a href=\"{}\">{name}</a>", esc(&href)),
            None => name,
        };
        let mark = if first {
            format!(" <strong>({})</strong>", esc(&Page::FirstWrong.text(lang)))
        } else {
            String::new()
        };
        let _ = writeln!(
            out,
            "<tr{row_class} data-step=\"{}\" data-verdict=\"{}\"><th scope=\"row\">{name}</th>\
             <td>{}</td><td class=\"{class}\">{}{mark}</td></tr>",
            esc(&s.label()),
            s.verdict.code(),
            esc(&s.given.value.text()),
            esc(&steps::step_message(s, lang))
        );
    }
    out.push_str("</table>\n");
    let closing = steps::closing(j, lang);
    let _ = writeln!(
        out,
        "<p>{}</p>\n<p class=\"help\">{}</p>\n</div>",
        esc(&closing),
        esc(&said::step_tolerance(
            steps::STEP_RELATIVE,
            steps::STEP_ABSOLUTE,
            lang
        ))
    );
    out
}

/// What could not be checked, as an HTML fragment.
pub(crate) fn cannot_fragment(messages: &[&crate::text::Said], lang: Lang) -> String {
    let mut out = format!(
        "<div class=\"verdict invalid\">\n<p class=\"headline\">{}</p>\n<ul class=\"errors\">\n",
        esc(&Page::CannotCheck.text(lang))
    );
    for m in messages {
        let _ = writeln!(out, "<li>{}</li>", esc(&m.text(lang)));
    }
    out.push_str("</ul>\n</div>\n");
    out
}

/// The page of a run's checks.
pub(crate) struct HtmlWriter {
    lang: Lang,
    body: String,
    index: usize,
}

impl HtmlWriter {
    pub(crate) fn new(lang: Lang) -> Self {
        HtmlWriter {
            lang,
            body: String::new(),
            index: 0,
        }
    }
}

impl Writer for HtmlWriter {
    fn add(&mut self, answer: Option<&Checked>, steps: Option<&StepsChecked>) {
        let lang = self.lang;
        let file = answer
            .map(|c| c.file.clone())
            .or_else(|| steps.map(|s| s.file.clone()));
        let Some(file) = file else { return };
        let judged = answer.and_then(|c| c.outcome.as_ref().ok().map(|j| (c, j)));
        let steps_judged = steps.and_then(|s| s.outcome.as_ref().ok());
        // Nothing judged: the errors are on standard error, as in the text.
        if judged.is_none() && steps_judged.is_none() {
            return;
        }
        let x = crate::report::file::explain_source(
            crate::problem::Source::File(std::path::Path::new(&file)),
            crate::core::Precision::F64,
            lang,
        )
        .ok();
        let links = Links {
            index: self.index,
            base: "",
        };
        let _ = writeln!(
            self.body,
            "<article class=\"checked\">\n<h1>{}</h1>\n<p class=\"source\">{}</p>",
            esc(&x.as_ref().map_or_else(|| file.clone(), |x| x.title.clone())),
            esc(&file)
        );
        if let Some(q) = x.as_ref().and_then(|x| x.question.as_deref()) {
            let _ = writeln!(
                self.body,
                "<blockquote class=\"question\">{}</blockquote>",
                esc(q)
            );
        }
        let _ = writeln!(
            self.body,
            "<section class=\"verdicts\" role=\"status\" aria-label=\"{}\">",
            esc(&Page::Verdict.text(lang))
        );
        match answer.map(|c| (c, &c.outcome)) {
            Some((c, Ok(j))) => self
                .body
                .push_str(&answer_fragment(c, j, x.as_ref(), links, lang)),
            // The steps were judged, the answer given with them could not be: say why here too.
            Some((_, Err(f))) => self.body.push_str(&cannot_fragment(&[&f.message], lang)),
            None => {}
        }
        if let Some(j) = steps_judged {
            self.body
                .push_str(&steps_fragment(j, x.as_ref(), links, lang));
        }
        self.body.push_str("</section>\n");
        if let Some(x) = &x {
            let _ = writeln!(
                self.body,
                "<section class=\"solution\" aria-label=\"{}\">",
                esc(&Page::WorkedSolution.text(lang))
            );
            self.body
                .push_str(&crate::report::html::write_parts(x, self.index, 2));
            self.body.push_str("</section>\n");
        }
        self.body.push_str("</article>\n");
        self.index += 1;
    }

    fn finish(self: Box<Self>) -> String {
        if self.body.is_empty() {
            return String::new();
        }
        crate::report::html::page_styled(
            &esc(&Page::Verdict.text(self.lang)),
            &format!("<main>\n{}</main>\n", self.body),
            self.lang,
            STYLE,
        )
    }
}
