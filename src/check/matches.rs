//! What a report says beside a verdict, decided once for every report that shows one: the
//! text report (`phong check`), the HTML and Markdown pages, and the one-sentence feedback of
//! `phong grade` (a gradebook's, a Moodle or Gradescope export's). Each lays the decisions out
//! its own way (a line, a swatch with links to the solution's steps, `#RRGGBB` and the
//! equations, a clause of a sentence); none decides again what to say.

use super::{
    Against, Candidate, Comparison, Diagnosis, Nearest, ReadingTarget, Verdict, VerdictKind,
};
use crate::solve::ReadingCode;

/// The colour the answer was held against, or why there is none.
#[derive(Clone, Copy, Debug)]
pub(crate) enum ExpectedLine<'a> {
    /// The colour compared with: the problem as written's, or `reading`'s.
    Compared {
        comparison: &'a Comparison,
        reading: Option<ReadingCode>,
    },
    /// An answer "no hit" where the problem as written has this colour (`ray`: the problem has
    /// a ray; a point problem has none to miss).
    HasColour { colour: [f64; 3], ray: bool },
    /// Nothing to compare with: as written the problem has no colour (its ray hits nothing),
    /// and no reading gives one.
    Nothing,
}

/// The expected line of verdict `v`.
pub(crate) fn expected_line(v: &Verdict) -> ExpectedLine<'_> {
    match (&v.comparison, v.has_colour) {
        (Some(comparison), _) => ExpectedLine::Compared {
            comparison,
            reading: v.compared_reading,
        },
        (None, Some((colour, ray))) => ExpectedLine::HasColour { colour, ray },
        (None, None) => ExpectedLine::Nothing,
    }
}

/// How a report lays its verdict out, which decides what it needs said beside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Layout {
    /// With an expected line (the text report, the HTML and Markdown pages): what that line
    /// shows is not said again.
    WithExpected,
    /// One sentence (grade's feedback): no expected line, so why there is no colour to
    /// compare with is an entry, and the nearest colour is always said.
    Sentence,
}

/// One entry of "what the answer matches".
#[derive(Clone, Copy, Debug)]
pub(crate) enum Match<'a> {
    /// An answer "no hit" where the problem as written has a colour (`ray`: it has a ray); in
    /// a sentence only, where the expected line is not shown.
    HasColour { ray: bool },
    /// As written the problem has no colour (its ray hits nothing), and no reading gives one
    /// either; in a sentence only, where the expected line is not shown.
    NothingToShade,
    /// A reading of the problem (`likely`: the verdict names it the intended one).
    Reading {
        reading: &'a ReadingTarget,
        likely: bool,
    },
    /// Beside an answer accepted as the likely intended reading: the problem as written's
    /// colour.
    AsWritten(&'a Comparison),
    /// The expected colour is a reading's because the problem as written has none (its ray
    /// hits nothing), and the answer is not the background.
    NothingAsWritten,
    /// The background's colour: the ray hits nothing.
    Background([f64; 3]),
    /// The colours these slips give (a wrong answer's diagnoses; `pairs`: pairs of slips, no
    /// single slip matching).
    Slips {
        diagnoses: &'a [Diagnosis],
        pairs: bool,
    },
    /// A wrong answer, a colour on its own scale, that no slip explains.
    NoDiagnosis,
    /// 0–1 numbers that look like 8-bit values.
    Looks8bit,
    /// The nearest colour missed, with its colour.
    Nearest(&'a Nearest),
    /// A near miss of the colour the expected line shows: the sentence only (the line has the
    /// colour).
    NearMiss(&'a Nearest),
    /// Accepted as the colour before clamping.
    Unclamped,
}

/// What the answer judged by `v` matches, in the order every report gives it, for a report
/// laid out as `layout`. `tolerance` is the one the answer was judged with.
pub(crate) fn matches(v: &Verdict, tolerance: f64, layout: Layout) -> Vec<Match<'_>> {
    let mut items = Vec::new();
    let wrong = v.kind == VerdictKind::Wrong;
    if layout == Layout::Sentence && wrong {
        match expected_line(v) {
            ExpectedLine::Compared { .. } => {}
            ExpectedLine::HasColour { ray, .. } => items.push(Match::HasColour { ray }),
            // The background's entry says it, where the answer is the background.
            ExpectedLine::Nothing if v.background.is_some() => {}
            ExpectedLine::Nothing => items.push(Match::NothingToShade),
        }
    }
    let likely = v.kind == VerdictKind::Reading;
    if let Some(reading) = &v.reading {
        items.push(Match::Reading { reading, likely });
    }
    // (Under `--strict` the expected line is the problem as written's already.)
    if likely && (layout == Layout::Sentence || v.compared_reading.is_some()) {
        if let Some(written) = &v.written {
            items.push(Match::AsWritten(written));
        }
    }
    if let Some(colour) = v.background {
        items.push(Match::Background(colour));
    } else if v.comparison.is_some() && v.written.is_none() {
        items.push(Match::NothingAsWritten);
    }
    if wrong {
        // "No classic slip gives it" only where a colour was compared on its own scale: not
        // for an answer "no hit" (`judge` sets `has_colour` for a wrong one, and only then),
        // nor for 8-bit numbers read on the 0–1 scale (the hint to use --scale 255 is what
        // helps), nor for the background where the ray hits nothing (said above).
        let compared = v.has_colour.is_none() && !v.looks_8bit && v.background.is_none();
        if !v.diagnosis.is_empty() {
            items.push(Match::Slips {
                diagnoses: &v.diagnosis,
                pairs: v.pairs,
            });
        } else if compared {
            items.push(Match::NoDiagnosis);
        }
        if v.looks_8bit {
            items.push(Match::Looks8bit);
        }
        if let Some(n) = &v.nearest {
            match layout {
                Layout::WithExpected if shown_as_expected(n, v) => {
                    if super::near_miss(n.comparison.distance(), tolerance) {
                        items.push(Match::NearMiss(n));
                    }
                }
                _ => items.push(Match::Nearest(n)),
            }
        }
    }
    if v.comparison
        .is_some_and(|c| c.within && c.against == Against::Unclamped)
    {
        items.push(Match::Unclamped);
    }
    items
}

/// Whether the nearest candidate is the colour the expected line shows: the problem as
/// written, or the reading compared with.
fn shown_as_expected(n: &Nearest, v: &Verdict) -> bool {
    match (&n.candidate, v.compared_reading) {
        (Candidate::Written, None) => true,
        (Candidate::Reading(code, _), Some(r)) => *code == r,
        _ => false,
    }
}
