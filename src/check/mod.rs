//! Checking answers: `phong check` and `phong grade`.
//!
//! A problem is solved once into an `Expected`: the colour of the problem as written, the
//! colours of its readings, and the colour each classic slip (and pair of slips) gives, all
//! computed by the same solver and core (`slips`). Judging an answer against it is then a few
//! comparisons, cheap enough to grade a class's CSV in one pass ([`grade`]).
//!
//! Verdicts (see README "Checking answers"):
//! - `right` (accepted, exit 0): within the tolerance of the problem as written, its colour
//!   clamped to [0, 1] or, on the 0–1 scale, unclamped (Eq. 4.16 does not clamp; the chapter
//!   clamps only for display, so both are right answers);
//! - `reading` (accepted, exit 0, unless `--strict`): the problem as written is surprising and
//!   the answer matches the reading the solver labels *likely intended* (4.2: L reversed; 4.3:
//!   the line's hit behind the origin);
//! - `wrong` (exit 1): anything else, with the slips whose colour it matches, and the other
//!   reading it matches, if any (4.2's "normal reversed" is |cos θ|, a slip, not an intent).

pub mod answer;
pub mod export;
pub mod grade;
pub(crate) mod matches;
pub(crate) mod messages;
pub mod moodle;
pub mod output;
pub mod policy;
pub mod report;
pub(crate) mod slips;
pub(crate) mod steps;

use std::path::Path;

use crate::problem::{Problem, ProblemError, ProblemFile, Source};
use crate::solve::{Evaluation, ReadingCode};
use report::{AnswerSource, Checked, Failure, FailureKind, Judged};

pub(crate) use answer::Key;
pub use answer::{Answer, Scale};
pub(crate) use slips::Outcome;
pub use slips::Slip;

/// A colour an answer can be compared with, on the 0–1 scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target {
    /// The colour of Eq. 4.16 (for a literal slip: with negative cosines kept).
    pub unclamped: [f64; 3],
    /// Clamped to [0, 1]; `None` for the literal value, which is a colour only unclamped.
    pub clamped: Option<[f64; 3]>,
}

impl Target {
    fn of(e: &Evaluation<f64>) -> Self {
        use crate::core::Vector;
        Target {
            unclamped: e.shade.color.to_array(),
            clamped: Some(e.clamped.to_array()),
        }
    }
}

/// Which value of a target an answer was compared with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Against {
    /// The colour clamped to [0, 1] (times 255 on the 255 scale).
    Clamped,
    /// The colour before clamping.
    Unclamped,
}

/// An answer against one target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Which value of the target the answer was compared with.
    pub against: Against,
    /// The target's value on the answer's scale.
    pub expected: [f64; 3],
    /// answer − expected, per channel, on the answer's scale.
    pub difference: [f64; 3],
    /// Every |difference| within the tolerance.
    pub within: bool,
}

/// Whether a difference (or a distance) `d` is within `tolerance`: inclusive, with a slack for
/// decimals that are not exact in binary (0.25 − 0.245 is 0.0050000000000000044). The one rule
/// of every colour compared under a tolerance: the verdict, each channel of the check's pages,
/// the near miss, the Moodle quiz's alternatives.
pub(crate) fn within_tolerance(d: f64, tolerance: f64) -> bool {
    let slack = tolerance * 1e-9 + 1e-12;
    d.abs() <= tolerance + slack
}

/// Compares an answer with a target: the clamped colour first, then (0–1 scale only) the
/// unclamped one; the first within the tolerance, or else the clamped one. `None` when the
/// target has no value on the answer's scale (a literal value against an 8-bit answer).
pub(crate) fn compare(answer: &Answer, target: &Target, tolerance: f64) -> Option<Comparison> {
    let values = answer.values?;
    let with = |against, expected: [f64; 3]| {
        let difference = [0, 1, 2].map(|i| values[i] - expected[i]);
        Comparison {
            against,
            expected,
            difference,
            within: difference.iter().all(|&d| within_tolerance(d, tolerance)),
        }
    };
    let k = answer.scale.factor();
    let clamped = target
        .clamped
        .map(|c| with(Against::Clamped, c.map(|x| x * k)));
    let unclamped =
        (answer.scale == Scale::Unit).then(|| with(Against::Unclamped, target.unclamped));
    match (clamped, unclamped) {
        (Some(c), _) if c.within => Some(c),
        (_, Some(u)) if u.within => Some(u),
        (Some(c), _) => Some(c),
        (None, u) => u,
    }
}

impl Comparison {
    /// The largest |difference| of a channel: how far the answer is, on its scale.
    pub(crate) fn distance(&self) -> f64 {
        self.difference.iter().fold(0.0, |m, d| m.max(d.abs()))
    }
}

/// What a nearest candidate is: the problem as written, a reading, or a slip (or pair).
#[derive(Clone, Debug, PartialEq)]
pub enum Candidate {
    /// The problem as written.
    Written,
    /// A reading of the problem (its code; whether it is the likely intended one).
    Reading(ReadingCode, bool),
    /// The colour these slips give (with those that are the likely intended reading).
    Slips {
        /// The slips made.
        slips: Vec<Slip>,
        /// Those of them that are the likely intended reading, not mistakes.
        intended: Vec<Slip>,
    },
}

/// The candidate colour closest to a wrong answer, with how far it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Nearest {
    /// What the colour is.
    pub candidate: Candidate,
    /// The answer against it (the clamped or unclamped value, whichever is closer).
    pub comparison: Comparison,
}

/// A reading of the problem and its colour.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadingTarget {
    /// Which reading.
    pub code: ReadingCode,
    /// The solver labels it the likely intended reading.
    pub likely_intended: bool,
    /// The reading's colour.
    pub target: Target,
}

/// Everything an answer to one problem is judged against, computed once.
#[derive(Clone, Debug)]
pub(crate) struct Expected {
    /// The problem as written; `None` when there is nothing to shade (the ray hits nothing).
    pub solution: Option<Target>,
    pub readings: Vec<ReadingTarget>,
    /// What each applicable slip, and pair of slips, gives.
    pub outcomes: Vec<Outcome>,
    /// The problem has a ray (a ray problem), rather than a point.
    pub ray: bool,
    /// What a ray that hits nothing shows: the file's `background` (black unless it says).
    pub background: [f64; 3],
}

impl Expected {
    /// Solves the problem, its readings and its slips (f64, the reference precision).
    pub(crate) fn of(problem: &Problem<f64>) -> Result<Expected, crate::problem::Invalid> {
        let solution = crate::solve::solve(problem)?;
        let base = solution.evaluation.as_ref().map(Target::of);
        let readings = solution
            .readings
            .iter()
            .map(|r| ReadingTarget {
                code: r.code,
                likely_intended: r.code.likely_intended(),
                target: Target::of(&r.evaluation),
            })
            .collect();
        Ok(Expected {
            solution: base,
            readings,
            outcomes: slips::outcomes(problem, base.as_ref()),
            ray: matches!(problem.target, crate::problem::Target::Ray { .. }),
            background: {
                use crate::core::Vector;
                problem.background.to_array()
            },
        })
    }

    /// The slips that are the problem's likely intended reading (L reversed in 4.2, the hit
    /// behind the origin in 4.3): made with one other slip, they are that one slip, made in the
    /// intended reading.
    pub(crate) fn intended_slips(&self) -> Vec<Slip> {
        self.readings
            .iter()
            .filter(|r| r.likely_intended)
            .filter_map(|r| match r.code {
                ReadingCode::LightReversed => Some(Slip::LightReversed),
                ReadingCode::LineBehindOrigin => Some(Slip::HitBehindOrigin),
                ReadingCode::NormalReversed => None,
            })
            .collect()
    }

    /// The colour an answer is measured against: the problem as written, or, when it has none,
    /// its likely intended reading.
    pub(crate) fn reference(&self) -> Option<Reference> {
        match self.solution {
            Some(target) => Some(Reference {
                target,
                reading: None,
            }),
            None => self
                .readings
                .iter()
                .find(|r| r.likely_intended)
                .map(|r| Reference {
                    target: r.target,
                    reading: Some(r.code),
                }),
        }
    }
}

/// The colour an answer is measured against ([`Expected::reference`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Reference {
    pub target: Target,
    /// `None` for the problem as written, or the reading whose colour it is.
    pub reading: Option<ReadingCode>,
}

/// The verdict on an answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum VerdictKind {
    /// Within the tolerance of the problem as written.
    Right,
    /// Within the tolerance of a likely intended reading, not of the problem as written.
    Reading,
    /// Neither.
    Wrong,
}

/// A slip (or pair) the answer matches.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnosis {
    /// The slips' codes (one, or two made together).
    pub slips: Vec<Slip>,
    /// Those of `slips` that are the likely intended reading (not counted as mistakes).
    pub intended: Vec<Slip>,
    /// The answer against the colour these slips give.
    pub comparison: Comparison,
}

impl Diagnosis {
    /// The slips that are mistakes (all but the likely intended reading's).
    pub(crate) fn mistakes(&self) -> Vec<Slip> {
        let m: Vec<Slip> = self
            .slips
            .iter()
            .copied()
            .filter(|s| !self.intended.contains(s))
            .collect();
        if m.is_empty() {
            self.slips.clone()
        } else {
            m
        }
    }
}

/// The verdict on one answer, with everything the report says about it.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// Right, reading or wrong.
    pub kind: VerdictKind,
    /// Right, or a likely intended reading without `--strict`: exit 0.
    pub accepted: bool,
    /// The answer against the problem as written (or the reading it matches, or, when the
    /// problem as written has no colour, its likely intended reading).
    pub comparison: Option<Comparison>,
    /// The answer against the problem as written; `None` when it has no colour.
    pub written: Option<Comparison>,
    /// What `comparison` is against: `None` for the problem as written, or a reading.
    pub compared_reading: Option<ReadingCode>,
    /// A reading the answer matches (for a wrong answer: one not likely intended).
    pub reading: Option<ReadingTarget>,
    /// The slips whose colour the answer matches: single slips, or pairs where no single does.
    pub diagnosis: Vec<Diagnosis>,
    /// The diagnosis needed pairs of slips (no single slip matched).
    pub pairs: bool,
    /// A wrong 0–1 answer whose numbers look like 8-bit values (integers, some above 1).
    pub looks_8bit: bool,
    /// For a wrong answer: the closest of the problem as written, its readings and every slip's
    /// colour that it does not match (a near miss is told how near it is, and to what).
    pub nearest: Option<Nearest>,
    /// For an answer "no hit" to a problem that has a colour: that colour (clamped, on the
    /// answer's scale), and whether the problem has a ray at all.
    pub has_colour: Option<([f64; 3], bool)>,
    /// A wrong answer that is the background colour (within the tolerance; black unless the
    /// file says otherwise) of a problem whose ray, as written, hits nothing: that is what such
    /// a ray shows, and the answer is "no hit". The report says so in place of the nearest slip
    /// (a slip of the likely intended reading that happens to be dark says nothing of what
    /// black means there). The background's colour, on the 0–1 scale.
    pub background: Option<[f64; 3]>,
}

/// Judges an answer.
pub(crate) fn judge(expected: &Expected, answer: &Answer, tolerance: f64, strict: bool) -> Verdict {
    let mut v = Verdict {
        kind: VerdictKind::Wrong,
        accepted: false,
        comparison: None,
        written: None,
        compared_reading: None,
        reading: None,
        diagnosis: Vec::new(),
        pairs: false,
        looks_8bit: false,
        nearest: None,
        has_colour: None,
        background: None,
    };
    if answer.values.is_none() {
        // "No hit": right exactly when the problem as written has nothing to shade.
        match &expected.solution {
            None => {
                v.kind = VerdictKind::Right;
                v.accepted = true;
            }
            Some(t) => {
                let k = answer.scale.factor();
                let c = t.clamped.unwrap_or(t.unclamped).map(|x| x * k);
                v.has_colour = Some((c, expected.ray));
            }
        }
        return v;
    }
    if let Some(t) = &expected.solution {
        v.comparison = compare(answer, t, tolerance);
        v.written = v.comparison;
        if v.comparison.is_some_and(|c| c.within) {
            v.kind = VerdictKind::Right;
            v.accepted = true;
            return v;
        }
    }
    for r in &expected.readings {
        if let Some(c) = compare(answer, &r.target, tolerance).filter(|c| c.within) {
            v.reading = Some(r.clone());
            if r.likely_intended {
                v.kind = VerdictKind::Reading;
                v.accepted = !strict;
                // Under `--strict` only the problem as written is right: the answer stays
                // compared with it (or with nothing, where it has no colour), not with the
                // reading it matches.
                if !strict {
                    v.comparison = Some(c);
                    v.compared_reading = Some(r.code);
                }
                return v;
            }
        }
    }
    if v.comparison.is_none() {
        if let Some(r) = expected.reference() {
            v.comparison = compare(answer, &r.target, tolerance);
            v.compared_reading = r.reading;
        }
    }
    // A slip that is the likely intended reading of the problem (L reversed in 4.2, the hit
    // behind the origin in 4.3) does not count as a second slip: a pair made of it and one
    // slip is the one slip, made in the intended reading.
    let intended = expected.intended_slips();
    let level = |o: &&Outcome| {
        let free = o.slips.iter().filter(|s| intended.contains(s)).count();
        o.slips.len() - free.min(o.slips.len() - 1)
    };
    // A slip whose colour the tolerance cannot tell from a right one (the problem as written's,
    // or its likely intended reading's) is never named: an answer near it is as near a right
    // answer, and the slip says nothing of it (the 8-bit value truncated, 127 where 127.6
    // rounds to 128, under the 255 scale's tolerance of 1).
    let right: Vec<&Target> = (expected.solution.iter())
        .chain(
            expected
                .readings
                .iter()
                .filter(|r| r.likely_intended)
                .map(|r| &r.target),
        )
        .collect();
    // (The slip's colour as the answer matched it: clamped, or before clamping.)
    let told_apart = |c: &Comparison| {
        let slip = Answer {
            values: Some(c.expected),
            scale: answer.scale,
        };
        !(right.iter()).any(|t| compare(&slip, t, tolerance).is_some_and(|c| c.within))
    };
    let matching = |pairs: bool| {
        expected
            .outcomes
            .iter()
            .filter(|o| (level(o) > 1) == pairs)
            .filter_map(|o| {
                compare(answer, &o.target, tolerance)
                    .filter(|c| c.within && told_apart(c))
                    .map(|comparison| Diagnosis {
                        slips: o.slips.clone(),
                        intended: o
                            .slips
                            .iter()
                            .copied()
                            .filter(|s| o.slips.len() > 1 && intended.contains(s))
                            .collect(),
                        comparison,
                    })
            })
            .collect::<Vec<_>>()
    };
    v.diagnosis = matching(false);
    if v.diagnosis.is_empty() {
        v.diagnosis = matching(true);
        v.pairs = !v.diagnosis.is_empty();
    }
    let values = answer.values.unwrap_or_default();
    v.looks_8bit = answer.scale == Scale::Unit && policy::looks_8bit(&values);
    v.nearest = nearest(expected, answer, tolerance, &intended);
    // Where slips explain the answer, the nearest other colour is news only if it is the problem
    // as written or a reading, and near (a few hundredths on the 0–1 scale).
    if !v.diagnosis.is_empty() {
        v.nearest = nearest_reading(expected, answer, tolerance)
            .filter(|n| near_miss(n.comparison.distance(), tolerance));
    }
    // 8-bit numbers read on the 0–1 scale: every distance is measured on the wrong scale (76
    // is "75 away" from a 0.3), so no near miss is told; the hint to use --scale 255 is.
    if v.looks_8bit {
        v.nearest = None;
    }
    // The background (black) where the ray hits nothing: the report explains it instead of
    // naming the nearest dark slip.
    let background = Target {
        unclamped: expected.background,
        clamped: Some(expected.background.map(|x| x.clamp(0.0, 1.0))),
    };
    v.background = (expected.solution.is_none()
        && expected.ray
        && compare(answer, &background, tolerance).is_some_and(|c| c.within))
    .then_some(expected.background);
    if v.background.is_some() {
        v.nearest = None;
    }
    v
}

/// A wrong answer within this many tolerances of a colour (a few hundredths on the 0–1 scale)
/// is a near miss of it: the report says "close to" that colour.
pub(crate) const NEAR_MISS_TOLERANCES: f64 = 10.0;

/// `distance` (on the answer's scale) is a near miss under `tolerance`.
pub(crate) fn near_miss(distance: f64, tolerance: f64) -> bool {
    distance <= NEAR_MISS_TOLERANCES * tolerance
}

/// [`nearest`] among the problem as written and its readings only.
fn nearest_reading(expected: &Expected, answer: &Answer, tolerance: f64) -> Option<Nearest> {
    let only = Expected {
        outcomes: Vec::new(),
        ..expected.clone()
    };
    nearest(&only, answer, tolerance, &[])
}

/// The answer against a target's clamped and (0–1 scale) unclamped value: the closer one.
fn closest(answer: &Answer, target: &Target) -> Option<Comparison> {
    let clamped = compare(answer, target, f64::INFINITY).filter(|c| c.against == Against::Clamped);
    let unclamped = (answer.scale == Scale::Unit)
        .then(|| {
            let t = Target {
                clamped: None,
                ..*target
            };
            compare(answer, &t, f64::INFINITY)
        })
        .flatten();
    match (clamped, unclamped) {
        (Some(c), Some(u)) if u.distance() < c.distance() => Some(u),
        (Some(c), _) => Some(c),
        (None, u) => u,
    }
}

/// The closest candidate a wrong answer does not match: the problem as written, a reading, or
/// a slip's (or pair's) colour; truncations are left out (an answer they explain matches one).
/// Ties go to the first in that order.
fn nearest(
    expected: &Expected,
    answer: &Answer,
    tolerance: f64,
    intended: &[Slip],
) -> Option<Nearest> {
    let written = expected.solution.iter().map(|t| (Candidate::Written, *t));
    let readings = expected
        .readings
        .iter()
        .map(|r| (Candidate::Reading(r.code, r.likely_intended), r.target));
    let slips = expected
        .outcomes
        .iter()
        .filter(|o| !o.slips.iter().any(|s| s.is_truncation()))
        .map(|o| {
            let mine: Vec<Slip> = o
                .slips
                .iter()
                .copied()
                .filter(|s| o.slips.len() > 1 && intended.contains(s))
                .collect();
            (
                Candidate::Slips {
                    slips: o.slips.clone(),
                    intended: mine,
                },
                o.target,
            )
        });
    let mut best: Option<Nearest> = None;
    for (candidate, target) in written.chain(readings).chain(slips) {
        let Some(c) = closest(answer, &target) else {
            continue;
        };
        if within_tolerance(c.distance(), tolerance) {
            continue;
        }
        if best
            .as_ref()
            .is_none_or(|b| c.distance() < b.comparison.distance())
        {
            best = Some(Nearest {
                candidate,
                comparison: c,
            });
        }
    }
    best
}

/// How `phong check` reads and judges an answer.
#[derive(Clone, Debug, Default)]
pub struct CheckOptions {
    /// The answer as written; `None` to check the file's answer key.
    pub answer: Option<String>,
    /// The scale of an answer that is not `#RRGGBB`; `None` for the 0–1 scale, with 8-bit
    /// values read as the course policy says.
    pub scale: Option<Scale>,
    /// The course policy (its tolerances, strictness, 8-bit reading, no-hit words, credit).
    pub policy: std::sync::Arc<policy::Policy>,
}

/// Checks one problem file's answer (given, or its key). Never fails: a bad file or answer is
/// reported in the result, which names the file, the field and the fix.
pub fn check_file(path: &Path, options: &CheckOptions) -> report::Checked {
    check_source(Source::File(path), options)
}

/// [`check_file`] for a problem from any [`Source`] (text held in memory, for `phong serve`).
pub fn check_source(problem: Source<'_>, options: &CheckOptions) -> report::Checked {
    check_prepared(&Prepared::of(problem), options)
}

/// One problem read, and everything its answers are judged against solved once (`Expected`):
/// `phong serve` prepares each of its exercises at start-up and checks every answer to it with
/// [`check_prepared`], which gives what [`check_source`] gives, without solving again.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The name in messages.
    file: String,
    /// The parsed file, its warnings, and what an answer is judged against (or why the problem
    /// is invalid: reported only after the answer is read); or why the file cannot be read or
    /// parsed, reported before the answer.
    loaded: Result<PreparedFile, Failure>,
}

#[derive(Clone, Debug)]
struct PreparedFile {
    file: ProblemFile,
    warnings: Vec<crate::problem::warnings::Warning>,
    expected: Result<Expected, Failure>,
}

impl Prepared {
    /// Reads, validates and solves the problem of `source` (its readings and slips too).
    pub fn of(source: Source<'_>) -> Prepared {
        let path = source.name();
        let loaded = Loaded::read(source)
            .map_err(Failure::problem)
            .map(|loaded| {
                let warnings = loaded
                    .problem
                    .as_ref()
                    .map_or_else(|_| Vec::new(), |p| p.warnings.clone());
                let expected = loaded
                    .problem
                    .map_err(Failure::problem)
                    .and_then(|p| Expected::of(&p).map_err(|e| Failure::problem(e.at(path))));
                PreparedFile {
                    file: loaded.file,
                    warnings,
                    expected,
                }
            });
        Prepared {
            file: path.display().to_string(),
            loaded,
        }
    }
}

/// Checks an answer (given, or the key) against a [`Prepared`] problem: what [`check_source`]
/// gives for the same source.
pub fn check_prepared(prepared: &Prepared, options: &CheckOptions) -> report::Checked {
    let file = &prepared.file;
    let source = if options.answer.is_some() {
        AnswerSource::Argument
    } else {
        AnswerSource::Key
    };
    let checked = |text, outcome, warnings| Checked {
        file: file.clone(),
        text,
        source,
        outcome,
        warnings,
    };
    let loaded = match &prepared.loaded {
        Ok(l) => l,
        Err(f) => return checked(options.answer.clone(), Err(f.clone()), Vec::new()),
    };
    let key = loaded.file.answer.as_ref();
    let text = options
        .answer
        .clone()
        .or_else(|| key.map(|k| serde_json::to_string(&key_json(k)).unwrap_or_default()));
    checked(
        text,
        judge_loaded(file, loaded, options),
        loaded.warnings.clone(),
    )
}

/// A problem file loaded as `solve` and `grade` load it ([`crate::problem::load`], which finds
/// a mesh beside the file), with its parsed form for the answer key.
struct Loaded {
    file: ProblemFile,
    /// The validated problem, or why it is invalid: reported only after the answer is read, as
    /// a file that cannot be read or parsed is reported before it.
    problem: Result<Problem<f64>, ProblemError>,
}

impl Loaded {
    fn read(source: Source<'_>) -> Result<Loaded, ProblemError> {
        match source.load::<f64>() {
            Ok((file, problem)) => Ok(Loaded {
                file,
                problem: Ok(problem),
            }),
            // The file parsed, but its problem is invalid. `load` keeps no parsed file then:
            // parse it again (only on this path) for its key, which is reported first.
            Err(invalid @ ProblemError::Invalid { .. }) => Ok(Loaded {
                file: source.parse()?,
                problem: Err(invalid),
            }),
            Err(e) => Err(e),
        }
    }
}

/// The answer (`--answer`, or the file's key) judged against the prepared problem.
fn judge_loaded(
    file: &str,
    loaded: &PreparedFile,
    options: &CheckOptions,
) -> Result<Judged, Failure> {
    let answer_failure = |field: &str, message| Failure {
        kind: FailureKind::Answer,
        field: Some(field.into()),
        message,
    };
    use report::Said;
    let policy = &options.policy;
    let mut as_8bit = false;
    let key = match (&options.answer, &loaded.file.answer) {
        (Some(text), file_key) => policy
            .read(text, options.scale)
            .map(|read| {
                as_8bit = read.as_8bit;
                Key {
                    answer: read.answer,
                    // The file's key says how closely its exercise is judged: an answer given
                    // on the command line is judged so too (on its own scale).
                    tolerance: file_key
                        .as_ref()
                        .and_then(|k| answer::from_key(k).ok())
                        .and_then(|k| k.tolerance_on(read.answer.scale)),
                }
            })
            .map_err(|e| answer_failure("--answer", Said::at(format!("{file}: --answer"), e)))?,
        (None, Some(key)) => {
            answer::from_key(key).map_err(|e| answer_failure("answer", Said::at(file, e)))?
        }
        (None, None) => {
            return Err(Failure {
                kind: FailureKind::NoAnswer,
                field: Some("answer".into()),
                message: Said::new(CheckMessage::NoAnswerKey { file: file.into() }),
            })
        }
    };
    let expected = loaded.expected.as_ref().map_err(Clone::clone)?;
    let tolerance = policy.tolerance(key.answer.scale, key.tolerance);
    let verdict = judge(expected, &key.answer, tolerance, policy.strict);
    Ok(Judged {
        answer: key.answer,
        tolerance,
        credit: policy.credit(verdict.kind),
        as_8bit,
        policy: policy.source.clone(),
        verdict,
    })
}

/// The key as the file wrote it, for the report.
fn key_json(key: &crate::problem::format::AnswerSpec) -> serde_json::Value {
    use crate::problem::format::{AnswerColor, AnswerSpec};
    let color = |c: &AnswerColor| match c {
        AnswerColor::Rgb(v) => serde_json::json!(v),
        AnswerColor::Hex(h) => serde_json::json!(h),
    };
    match key {
        AnswerSpec::Color(c) => color(c),
        AnswerSpec::Key(k) => serde_json::json!({
            "color": color(&k.color), "scale": k.scale, "tolerance": k.tolerance
        }),
    }
}

crate::messages! {
    /// What `phong check` says of an answer it cannot check (beside the answer's and the
    /// problem file's own errors).
    #[allow(missing_docs)]
    pub enum CheckMessage {
        /// No `--answer`, and the file has no key.
        NoAnswerKey { file: String } =>
            "{file}: answer: missing: the file has no answer key to check. Fix: pass --answer \
             \"r g b\", or add \"answer\": [r, g, b] to the file",
            "{file}: answer: ausente: o arquivo não tem gabarito para conferir. Correção: passe \
             --answer \"r g b\", ou acrescente \"answer\": [r, g, b] ao arquivo";
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The one rule of a difference within a tolerance: inclusive, a decimal's binary error
    /// forgiven, and nothing beyond tolerance + tolerance·1e-9 + 1e-12. The check's pages and
    /// the Moodle quiz judged each channel by tolerance·(1 + 1e-9) + 1e-12, one ulp above this
    /// at 0.01: a channel could read "within" beside a verdict of "outside".
    #[test]
    fn a_difference_is_within_a_tolerance_by_one_rule() {
        assert!(within_tolerance(0.01, 0.01) && within_tolerance(-0.01, 0.01));
        // 0.25 − 0.245 is 0.0050000000000000044 in binary
        assert!(within_tolerance(0.25 - 0.245, 0.005));
        let edge = 0.01 + (0.01 * 1e-9 + 1e-12);
        assert!(within_tolerance(edge, 0.01));
        let beyond = 0.01 * (1.0 + 1e-9) + 1e-12;
        assert!(beyond > edge, "the old pages' bound is one ulp above");
        assert!(!within_tolerance(beyond, 0.01));
        assert!(!within_tolerance(0.0101, 0.01));
    }
    use crate::text::{Lang, Message};

    fn exercise(name: &str) -> std::path::PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("exercises")
            .join(name)
    }

    fn check(name: &str, answer: &str, scale: Scale) -> Checked {
        check_file(
            &exercise(name),
            &CheckOptions {
                answer: Some(answer.into()),
                scale: Some(scale),
                ..Default::default()
            },
        )
    }

    fn verdict(c: &Checked) -> &Verdict {
        &c.outcome.as_ref().unwrap().verdict
    }

    // 4.3's ray, O = (8, 4, 6), D = (0.8, 0, −0.6), meets the plane x + y + z = 0 where
    // 18 + 0.2 t = 0, t = −90: behind its origin, so as written it hits nothing and shows the
    // background. Black (within ±0.005, on either scale) is that background, not a colour the
    // point has; the verdict stays "wrong" (the answer is "none"), only what explains it changes.
    #[test]
    fn black_where_the_ray_hits_nothing_is_told_it_is_the_background() {
        for (answer, scale) in [
            ("0 0 0", Scale::Unit),
            ("0.004 0 0.003", Scale::Unit),
            ("0 0 0", Scale::Bits8),
            ("#000000", Scale::Unit),
        ] {
            let c = check("4.3.json", answer, scale);
            let v = verdict(&c);
            assert_eq!(v.kind, VerdictKind::Wrong, "{answer}");
            assert!(!v.accepted, "{answer}");
            assert_eq!(v.background, Some([0.0; 3]), "{answer}");
            assert_eq!(v.nearest, None, "{answer}");
            let en = report::text(&c, Lang::En);
            assert!(
                en.contains(
                    "  black is the background, the colour a ray that meets nothing shows: as \
                     written the ray hits nothing (t > 0), so there is no colour to give, and \
                     the answer is \"none\" (no hit)\n"
                ),
                "{en}"
            );
            assert!(!en.contains("ambient") && !en.contains("closest"), "{en}");
            assert!(!en.contains("no classic slip"), "{en}");
            let pt = report::text(&c, Lang::Pt);
            assert!(
                pt.contains(
                    "  preto é o fundo, a cor vista por um raio que não encontra nada: como \
                     enunciado o raio não atinge nada (t > 0), então não há cor a dar, e a \
                     resposta é \"nenhuma\" (nenhuma interseção)\n"
                ),
                "{pt}"
            );
            assert!(
                !pt.contains("ambiente") && !pt.contains("mais perto"),
                "{pt}"
            );
        }
        // `phong grade`'s feedback on the row says the same, and names no slip.
        let c = check("4.3.json", "0 0 0", Scale::Unit);
        for (lang, background, wrong) in [
            (Lang::En, "black is the background", "Wrong; "),
            (Lang::Pt, "preto é o fundo", "Errada; "),
        ] {
            let row = messages::feedback(
                &messages::RowFacts {
                    verdict: Some(verdict(&c)),
                    reason: None,
                    tolerance: 0.005,
                    read_as_8bit: false,
                    points: None,
                },
                lang,
            );
            assert!(row.starts_with(&format!("{wrong}{background}")), "{row}");
            assert!(
                !row.contains("O_a I_a") && !row.contains("phong solve"),
                "{row}"
            );
        }
        // Not black: 0.006 is outside the tolerance of black, and 4.1's ray-less point has
        // no background to show.
        assert_eq!(
            verdict(&check("4.3.json", "0.006 0 0", Scale::Unit)).background,
            None
        );
        assert_eq!(
            verdict(&check("4.1.json", "0 0 0", Scale::Unit)).background,
            None
        );
    }

    // A file may give its own background: then that colour, not black, is what 4.3's ray
    // shows, and black is judged as any other colour (its nearest candidate is named).
    #[test]
    fn a_files_own_background_is_the_one_told() {
        let text = std::fs::read_to_string(exercise("4.3.json"))
            .unwrap()
            .replacen(
                "\"answer\"",
                "\"background\": [0.2, 0.3, 0.4], \"answer\"",
                1,
            );
        let name = Path::new("grey.json");
        let check = |answer: &str| {
            check_source(
                crate::problem::Source::Text { name, text: &text },
                &CheckOptions {
                    answer: Some(answer.into()),
                    scale: Some(Scale::Unit),
                    ..Default::default()
                },
            )
        };
        let c = check("0.2 0.3 0.4");
        assert_eq!(verdict(&c).kind, VerdictKind::Wrong);
        assert_eq!(verdict(&c).background, Some([0.2, 0.3, 0.4]));
        let en = report::text(&c, Lang::En);
        assert!(
            en.contains(
                "  (0.2, 0.3, 0.4) is the problem's background, the colour a ray that meets \
                 nothing shows: as written the ray hits nothing (t > 0), so there is no colour \
                 to give, and the answer is \"none\" (no hit)\n"
            ),
            "{en}"
        );
        let pt = report::text(&c, Lang::Pt);
        assert!(
            pt.contains("  (0.2, 0.3, 0.4) é o fundo do problema, a cor vista por um raio"),
            "{pt}"
        );
        let black = check("0 0 0");
        assert_eq!(verdict(&black).background, None);
        assert!(verdict(&black).nearest.is_some());
    }

    // Every colour a wrong answer can be near (the problem as written, each reading, each
    // slip and pair but the truncations), moved 0.006 off in one channel: just outside the
    // tolerance ±0.005 of it, well within ten tolerances. Where that answer matches nothing
    // (no slip, no reading), the report says it is close to something, and names it, in
    // both languages, even when the colour it misses is the one the "expected" line shows.
    #[test]
    fn a_near_miss_is_told_what_it_is_close_to() {
        let mut told = 0;
        for name in ["4.1.json", "4.2.json", "4.3.json"] {
            let (_, problem) = crate::problem::Source::File(&exercise(name))
                .load::<f64>()
                .unwrap();
            let x = Expected::of(&problem).unwrap();
            let colours = x
                .solution
                .iter()
                .copied()
                .chain(x.readings.iter().map(|r| r.target))
                .chain(
                    x.outcomes
                        .iter()
                        .filter(|o| !o.slips.iter().any(|s| s.is_truncation()))
                        .map(|o| o.target),
                );
            for t in colours {
                let c = t.clamped.unwrap_or(t.unclamped);
                for k in 0..3 {
                    let mut a = c;
                    a[k] += if c[k] > 0.5 { -0.006 } else { 0.006 };
                    let text = format!("{} {} {}", a[0], a[1], a[2]);
                    let checked = check(name, &text, Scale::Unit);
                    let v = verdict(&checked);
                    if v.kind != VerdictKind::Wrong
                        || !v.diagnosis.is_empty()
                        || v.reading.is_some()
                    {
                        continue;
                    }
                    let n = v
                        .nearest
                        .as_ref()
                        .expect("a near miss has a nearest colour");
                    assert!(n.comparison.distance() <= 0.006 + 1e-9, "{name} {text}");
                    for lang in [Lang::En, Lang::Pt] {
                        let out = report::text(&checked, lang);
                        let said =
                            messages::nearest(&n.candidate, n.comparison.distance(), 0.005, lang);
                        let close = match lang {
                            Lang::En => "close to ",
                            Lang::Pt => "perto d",
                        };
                        assert!(said.starts_with(close), "{said}");
                        assert!(out.contains(&said), "{name} {text}:\n{out}");
                    }
                    told += 1;
                }
            }
        }
        assert!(told > 0);
    }

    // The sentences of this module's typed messages render in both languages (walk.rs checks
    // them all; this names the two of issue 28).
    #[test]
    fn the_feedback_messages_render() {
        let m = messages::Feedback::ReversedRayHit {
            given: crate::text::Num(90.0),
            along: crate::text::Num(-90.0),
        };
        assert_eq!(
            m.text(Lang::En),
            "the hit of the ray reversed (O − tD, t > 0), which along D is at t = -90, behind \
             the ray's origin: the sign of 90 is reversed"
        );
        assert_eq!(
            m.text(Lang::Pt),
            "a interseção do raio invertido (O − tD, t > 0), que ao longo de D está em t = -90, \
             atrás da origem do raio: o sinal de 90 está trocado"
        );
    }
}
