//! What f32 cost: a problem solved with `--precision f32` is solved in f64 too (one problem
//! costs microseconds), and the difference f32 − f64 of its colour and intermediates is kept
//! ([`VersusF64`]). Where f32's answer is not f64's — a channel off by more than the check's
//! tolerance, a gate decided the other way, a channel one of them gives as 0 and the other not
//! — the finding `f32_differs_from_f64` says so and why: which number of the file lost its
//! digits when it was read in f32 (each number rounded to f32 on its own, the problem solved
//! in f64 again), or, where none did, f32's own range and rounding in the computation.

use crate::core::{LightStatus, Real, SpecularStatus, Vector, V3};
use crate::problem::{Problem, Source};

use super::{solve, Evaluation, Finding, FindingData, Solution};

/// The tolerance of `phong check` on the 0–1 scale, per channel (inclusive): half a unit of
/// the second decimal place (`check::answer::Scale::default_tolerance` explains the choice).
/// Declared here, below both, so that the solver's comparison of f32 with f64 and the checker
/// use one number.
pub const CHECK_TOLERANCE: f64 = 0.005;

/// f32 − f64 for the problem as written (`versus_f64` in the JSON): the final colour's
/// difference, and each intermediate's that both precisions computed. A quantity one of them
/// did not compute (no hit, no viewer) is `None`.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct VersusF64 {
    /// The check's tolerance on the 0–1 scale, [`CHECK_TOLERANCE`].
    pub tolerance: f64,
    /// f64's colour, unclamped (Eq. 4.16); `None` when f64 shades nothing.
    pub f64_color: Option<[f64; 3]>,
    /// f32 − f64 of the unclamped colour.
    pub color: Option<[f64; 3]>,
    /// f32 − f64 of the colour clamped to [0, 1].
    pub clamped: Option<[f64; 3]>,
    /// f32 − f64 of the 8-bit colour.
    pub rgb8: Option<[i16; 3]>,
    /// f32 − f64 of the ray's t (a ray problem).
    pub t: Option<f64>,
    /// f32 − f64 of the point P (a ray problem's hit).
    pub point: Option<[f64; 3]>,
    /// f32 − f64 of each term summed over the lights.
    pub totals: Option<TotalsVersus>,
    /// f32 − f64 of each light's intermediates, in the order of the solution's `lights`.
    pub lights: Vec<LightVersus>,
}

/// f32 − f64 of the terms summed over the lights.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct TotalsVersus {
    /// O_a I_a (0 where left out).
    pub ambient: [f64; 3],
    /// Σ diffuse.
    pub diffuse: [f64; 3],
    /// Σ specular.
    pub specular: [f64; 3],
}

/// f32 − f64 of one light's intermediates.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct LightVersus {
    /// The light's index in the file's `lights`.
    pub index: usize,
    /// cos θ.
    pub cos_theta: f64,
    /// cos φ, where both computed it.
    pub cos_phi: Option<f64>,
    /// I_l.
    pub i_l: [f64; 3],
    /// The gated diffuse term, where the material has O_d.
    pub diffuse: Option<[f64; 3]>,
    /// The gated specular term.
    pub specular: [f64; 3],
}

/// A decision of the model (a gate) that f32 and f64 take differently.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Gate {
    /// cos θ > 0: which side of the surface a light is on (Eq. 4.7).
    #[default]
    CosTheta,
    /// cos φ > 0: whether the reflection points towards the viewer (Eq. 4.10).
    CosPhi,
    /// ψ ≤ γ: inside a spot light's cone (Eq. 4.4).
    Cone,
    /// t > 0: whether, and what, the ray hits.
    Hit,
    /// Whether something blocks a light.
    Shadow,
}

/// How f32's answer differs from f64's, where it does by more than the tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Disagreement {
    /// max |f32 − f64| over the channels of the unclamped colour; `None` where one of them
    /// shades nothing.
    difference: Option<f64>,
    /// The first gate decided the other way.
    gate: Option<Gate>,
    /// A channel is 0 in one precision and not in the other.
    zeroed: bool,
}

impl Disagreement {
    /// Whether it is worth a finding.
    fn matters(&self) -> bool {
        self.gate.is_some() || self.zeroed || self.difference.is_some_and(|d| d > CHECK_TOLERANCE)
    }

    /// How much it matters, to rank the file's numbers by: a gate, then a zeroed channel, then
    /// the difference.
    fn weight(&self) -> (bool, bool, f64) {
        (
            self.gate.is_some(),
            self.zeroed,
            self.difference.unwrap_or(0.0),
        )
    }
}

fn arr<R: Real>(v: V3<R>) -> [f64; 3] {
    crate::core::real::to_f64_array::<R>(v)
}

fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] - b[i])
}

/// f32's solution (any `R`) against f64's.
fn versus<R: Real>(problem: &Problem<R>, s: &Solution<R>, r: &Solution<f64>) -> VersusF64 {
    let both = s.evaluation.as_ref().zip(r.evaluation.as_ref());
    let hit = s.intersection.zip(r.intersection);
    VersusF64 {
        tolerance: CHECK_TOLERANCE,
        f64_color: r.evaluation.as_ref().map(|e| arr::<f64>(e.shade.color)),
        color: both.map(|(a, b)| sub3(arr::<R>(a.shade.color), arr::<f64>(b.shade.color))),
        clamped: both.map(|(a, b)| sub3(arr::<R>(a.clamped), arr::<f64>(b.clamped))),
        rgb8: both.map(|(a, b)| std::array::from_fn(|i| a.rgb8[i] as i16 - b.rgb8[i] as i16)),
        t: hit
            .and_then(|(a, b)| a.t.zip(b.t))
            .map(|(a, b)| a.to_f64() - b),
        point: hit
            .and_then(|(a, b)| a.point.zip(b.point))
            .map(|(a, b)| sub3(arr::<R>(a), arr::<f64>(b))),
        totals: both.map(|(a, b)| TotalsVersus {
            ambient: sub3(
                arr::<R>(a.shade.ambient.unwrap_or(V3::<R>::ZERO)),
                arr::<f64>(b.shade.ambient.unwrap_or(V3::<f64>::ZERO)),
            ),
            diffuse: sub3(arr::<R>(a.shade.diffuse), arr::<f64>(b.shade.diffuse)),
            specular: sub3(arr::<R>(a.shade.specular), arr::<f64>(b.shade.specular)),
        }),
        lights: both
            .filter(|(a, b)| a.lights.len() == b.lights.len())
            .map(|(a, b)| lights(problem, a, b))
            .unwrap_or_default(),
    }
}

fn lights<R: Real>(
    problem: &Problem<R>,
    a: &Evaluation<R>,
    b: &Evaluation<f64>,
) -> Vec<LightVersus> {
    a.lights
        .iter()
        .zip(&b.lights)
        .map(|(x, y)| LightVersus {
            index: problem.light_info[x.index].file_index,
            cos_theta: x.cos_theta.to_f64() - y.cos_theta,
            cos_phi: x
                .specular
                .cos_phi
                .zip(y.specular.cos_phi)
                .map(|(p, q)| p.to_f64() - q),
            i_l: sub3(arr::<R>(x.arrival.i_l), arr::<f64>(y.arrival.i_l)),
            diffuse: x
                .diffuse
                .zip(y.diffuse)
                .map(|(p, q)| sub3(arr::<R>(p), arr::<f64>(q))),
            specular: sub3(arr::<R>(x.specular.term), arr::<f64>(y.specular.term)),
        })
        .collect()
}

/// Which gate a light's status (or its specular status) differing between two solutions
/// shows.
fn light_gate(a: (LightStatus, SpecularStatus), b: (LightStatus, SpecularStatus)) -> Option<Gate> {
    use LightStatus::*;
    if a.0 != b.0 {
        return Some(match (a.0, b.0) {
            (OutsideCone, _) | (_, OutsideCone) => Gate::Cone,
            (InShadow, _) | (_, InShadow) => Gate::Shadow,
            _ => Gate::CosTheta,
        });
    }
    let on = |s: SpecularStatus| s == SpecularStatus::Lit;
    (a.0 == Lit && on(a.1) != on(b.1)).then_some(Gate::CosPhi)
}

/// How `s` (f32, or f64 on numbers rounded to f32) differs from the f64 solution `r`.
fn disagreement<R: Real>(s: &Solution<R>, r: &Solution<f64>) -> Disagreement {
    let mut gate = None;
    let hit = |x: &Solution<_>| x.intersection.map(|i| (i.in_front, i.surface));
    let (ha, hb) = (s.intersection.map(|i| (i.in_front, i.surface)), hit(r));
    if ha != hb || s.evaluation.is_some() != r.evaluation.is_some() {
        gate = Some(Gate::Hit);
    }
    let mut difference = None;
    let mut zeroed = false;
    if let (Some(a), Some(b)) = (&s.evaluation, &r.evaluation) {
        let (ca, cb) = (arr::<R>(a.shade.color), arr::<f64>(b.shade.color));
        difference = Some((0..3).map(|i| (ca[i] - cb[i]).abs()).fold(0.0, f64::max));
        zeroed = (0..3).any(|i| (ca[i] == 0.0) != (cb[i] == 0.0));
        if gate.is_none() && a.lights.len() == b.lights.len() {
            gate = a.lights.iter().zip(&b.lights).find_map(|(x, y)| {
                light_gate((x.status, x.specular.status), (y.status, y.specular.status))
            });
        }
    }
    Disagreement {
        difference,
        gate,
        zeroed,
    }
}

/// The number of the file whose reading in f32 changes the answer, as its path in the file
/// (`lights[1].direction[2]`), its value and its value in f32.
#[derive(Clone, Debug, PartialEq)]
struct Culprit {
    field: String,
    given: f64,
    read: f64,
}

/// Every number of a problem's JSON that f32 cannot hold exactly, with its path; the answer
/// key and the generator's record are not read by the solver and are left out.
fn inexact_numbers(v: &serde_json::Value, path: &mut String, out: &mut Vec<(String, f64)>) {
    match v {
        serde_json::Value::Number(n) => {
            if let Some(x) = n.as_f64() {
                if (x as f32 as f64) != x {
                    out.push((path.clone(), x));
                }
            }
        }
        serde_json::Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                let len = path.len();
                path.push_str(&format!("[{i}]"));
                inexact_numbers(item, path, out);
                path.truncate(len);
            }
        }
        serde_json::Value::Object(map) => {
            for (key, item) in map {
                if path.is_empty() && matches!(key.as_str(), "answer" | "generated") {
                    continue;
                }
                let len = path.len();
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
                inexact_numbers(item, path, out);
                path.truncate(len);
            }
        }
        _ => {}
    }
}

/// The JSON value at `path` (as [`inexact_numbers`] writes it), to change.
fn at_path<'v>(v: &'v mut serde_json::Value, path: &str) -> Option<&'v mut serde_json::Value> {
    let mut v = v;
    for part in path.split('.') {
        let (key, indices) = part
            .split_once('[')
            .map_or((part, ""), |(k, rest)| (k, rest));
        if !key.is_empty() {
            v = v.get_mut(key)?;
        }
        for index in indices.split('[').filter(|s| !s.is_empty()) {
            v = v.get_mut(index.trim_end_matches(']').parse::<usize>().ok()?)?;
        }
    }
    Some(v)
}

/// Solves in f64 the problem whose JSON is `doc`.
fn solve_f64(source: &Source<'_>, doc: &serde_json::Value) -> Option<Solution<f64>> {
    let file = source.parse_text(&doc.to_string()).ok()?;
    let problem = source.validate::<f64>(&file).ok()?;
    solve(&problem).ok()
}

/// The number of the file whose rounding to f32 changes f64's answer the most, where rounding
/// the file's numbers to f32 changes it at all; `None` when the answer's loss is f32's own
/// computation. Each number is rounded on its own and the problem solved again in f64: one
/// solve per number that f32 cannot hold (a file with a mesh is not searched: its triangles
/// would be read again for each).
fn culprit(source: &Source<'_>, text: &str, r: &Solution<f64>) -> Option<Culprit> {
    let doc: serde_json::Value = serde_json::from_str(text).ok()?;
    let mesh = doc
        .get("surfaces")
        .and_then(|s| s.as_array())
        .is_some_and(|s| {
            s.iter()
                .any(|s| s.get("type").and_then(|t| t.as_str()) == Some("mesh"))
        });
    if mesh {
        return None;
    }
    let mut numbers = Vec::new();
    inexact_numbers(&doc, &mut String::new(), &mut numbers);
    let rounded = |doc: &mut serde_json::Value, path: &str, x: f64| {
        if let Some(slot) = at_path(doc, path) {
            *slot = serde_json::json!(x as f32 as f64);
        }
    };
    let mut best: Option<(Disagreement, Culprit)> = None;
    for (path, x) in &numbers {
        let mut one = doc.clone();
        rounded(&mut one, path, *x);
        let Some(s) = solve_f64(source, &one) else {
            continue;
        };
        let d = disagreement(&s, r);
        let moved = d.gate.is_some() || d.zeroed || d.difference.is_some_and(|d| d > 0.0);
        if moved && best.as_ref().is_none_or(|(b, _)| d.weight() > b.weight()) {
            best = Some((
                d,
                Culprit {
                    field: path.clone(),
                    given: *x,
                    read: *x as f32 as f64,
                },
            ));
        }
    }
    let (d, culprit) = best?;
    if d.matters() {
        return Some(culprit);
    }
    // No number alone: all of them rounded together?
    let mut all = doc;
    for (path, x) in &numbers {
        rounded(&mut all, path, *x);
    }
    let together = solve_f64(source, &all).is_some_and(|s| disagreement(&s, r).matters());
    together.then_some(culprit)
}

/// The f32 solution `s` of the problem read from `source` (its `text`) against f64's: the
/// differences kept in the solution, and the finding where f32's answer is not f64's. Nothing
/// when the problem does not solve in f64 (f32 solved it, so that is a limit of f32's range
/// already reported, or none).
pub(super) fn compare<R: Real>(
    source: &Source<'_>,
    text: &str,
    problem: &Problem<R>,
    s: &mut Solution<R>,
) {
    let Ok(file) = source.parse_text(text) else {
        return;
    };
    let Some(r) = source
        .validate::<f64>(&file)
        .ok()
        .and_then(|p: Problem<f64>| solve(&p).ok())
    else {
        return;
    };
    s.versus_f64 = Some(versus(problem, s, &r));
    let d = disagreement(s, &r);
    if !d.matters() {
        return;
    }
    let culprit = culprit(source, text, &r);
    let finding = FindingData::F32DiffersFromF64(F32Differs {
        difference: d.difference,
        tolerance: CHECK_TOLERANCE,
        gate: d.gate,
        zeroed: d.zeroed,
        input: culprit.as_ref().map(|c| c.field.clone()),
        given: culprit.as_ref().map(|c| c.given),
        read: culprit.as_ref().map(|c| c.read),
    });
    s.findings.insert(0, Finding::new(finding));
}

/// The numbers of the finding `f32_differs_from_f64`.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct F32Differs {
    /// max |f32 − f64| over the channels of the unclamped colour; `null` where one of them
    /// shades nothing.
    pub difference: Option<f64>,
    /// The check's tolerance, [`CHECK_TOLERANCE`].
    pub tolerance: f64,
    /// The first gate f32 decides the other way (`cos_theta`, `cos_phi`, `cone`, `hit`,
    /// `shadow`); `null` when none does.
    pub gate: Option<Gate>,
    /// A channel is 0 in one precision and not in the other.
    pub zeroed: bool,
    /// The number of the file whose reading in f32 changes the answer the most, as its path
    /// (`lights[0].direction[2]`); `null` when none does alone or together with the others:
    /// f32's range and rounding in the computation lost the answer.
    pub input: Option<String>,
    /// That number as written in the file.
    pub given: Option<f64>,
    /// That number as f32 reads it.
    pub read: Option<f64>,
}
