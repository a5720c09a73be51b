//! The solver: from a validated [`Problem`] to a [`Solution`] holding every intermediate of the
//! shading core, what the problem leaves out and why, the findings a student should know about
//! (a light behind the surface, a hit behind the ray's origin, …) and, where a problem as written
//! has a surprising property, the result of its likely intended reading, labelled as such.

mod findings;

use crate::core::vector::between;
use crate::core::{shade, AllVisible, LightStatus, LightTerm, Real, Shade, Vector, V3};
use crate::problem::validate::light_label;
use crate::problem::{Invalid, NamedMaterial, Problem, Target};

pub use findings::{Finding, FindingCode};

/// Everything the solver found out about one problem.
#[derive(Clone, Debug)]
pub struct Solution<R: Real> {
    pub title: Option<String>,
    pub question: Option<String>,
    /// Surprising properties and notes, most important first.
    pub findings: Vec<Finding>,
    /// For a ray problem: where the ray meets the surfaces.
    pub intersection: Option<Intersection<R>>,
    /// The problem as written; `None` when there is nothing to shade (the ray hits nothing).
    pub evaluation: Option<Evaluation<R>>,
    /// Likely intended readings of a problem whose literal reading is surprising.
    pub readings: Vec<Reading<R>>,
}

/// Where a ray problem's ray meets its surfaces.
#[derive(Clone, Copy, Debug)]
pub struct Intersection<R: Real> {
    pub origin: V3<R>,
    /// D as given.
    pub direction_given: V3<R>,
    /// D, unit.
    pub direction: V3<R>,
    /// The surface met (index in `surfaces`), if any.
    pub surface: Option<usize>,
    pub kind: Option<&'static str>,
    /// The parameter t of the hit along the line (negative: behind the origin).
    pub t: Option<R>,
    pub point: Option<V3<R>>,
    /// t > 0: a hit of the ray itself.
    pub in_front: bool,
}

/// The normal used at the point.
#[derive(Clone, Copy, Debug)]
pub struct NormalUsed<R: Real> {
    /// N as given (a point problem or a plane), or the sphere's outward normal.
    pub given: V3<R>,
    /// ‖N‖ as given.
    pub length: R,
    /// N as used: unit, and turned to face the ray in a ray problem.
    pub used: V3<R>,
    /// Whether N was reversed (to face the incoming ray, or by a reading).
    pub reversed: bool,
}

/// Which side of the surface the viewer is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    Front,
    Back,
    InPlane,
}

/// The viewing direction used at the point.
#[derive(Clone, Copy, Debug)]
pub struct ViewerUsed<R: Real> {
    /// E; `None` when V is the ray's own direction.
    pub position: Option<V3<R>>,
    /// V = (P − E)/‖P − E‖, from the eye to the point.
    pub v: V3<R>,
    /// N·V (negative when the viewer is in front of the surface).
    pub n_dot_v: R,
    pub side: Side,
}

/// A term of Eq. 4.16.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Term {
    Ambient,
    Diffuse,
    Specular,
}

/// A term the problem does not let us compute, and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OmissionReason {
    NoAmbientLight,
    NoAmbientColor,
    NoDirectLight,
    NoDiffuseColor,
    NoViewer,
    NoSpecularColor,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Omission {
    pub term: Term,
    pub reason: OmissionReason,
}

/// The shading of one point, with every intermediate.
#[derive(Clone, Debug)]
pub struct Evaluation<R: Real> {
    pub point: Option<V3<R>>,
    pub normal: Option<NormalUsed<R>>,
    pub viewer: Option<ViewerUsed<R>>,
    pub material: NamedMaterial<R>,
    /// The per-light record of the core.
    pub lights: Vec<LightTerm<R>>,
    pub shade: Shade<R>,
    pub omitted: Vec<Omission>,
    /// The colour clamped to [0, 1] for display.
    pub clamped: V3<R>,
    /// The clamped colour in 8 bits, round(255·c).
    pub rgb8: [u8; 3],
}

/// A reading of the problem other than the literal one.
#[derive(Clone, Debug)]
pub struct Reading<R: Real> {
    pub code: ReadingCode,
    pub intersection: Option<Intersection<R>>,
    pub evaluation: Evaluation<R>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReadingCode {
    /// Every direct light is behind the surface: the normal reversed, as if the surface faced
    /// the light (what taking |cos θ| amounts to).
    NormalReversed,
    /// The ray meets the surface only behind its origin: the point where its line does (t < 0),
    /// which is the hit of the reversed ray.
    LineBehindOrigin,
}

/// Solves a validated problem.
pub fn solve<R: Real>(problem: &Problem<R>) -> Result<Solution<R>, Invalid> {
    let mut solution = Solution {
        title: problem.title.clone(),
        question: problem.question.clone(),
        findings: Vec::new(),
        intersection: None,
        evaluation: None,
        readings: Vec::new(),
    };
    match &problem.target {
        Target::Point {
            position,
            normal,
            material,
        } => {
            let normal = normal.map(|n| NormalUsed {
                given: n.given,
                length: n.length,
                used: n.unit,
                reversed: false,
            });
            let eval = evaluate(problem, *position, normal, None, material)?;
            // Reading: every direct light behind the surface.
            let behind = eval
                .lights
                .iter()
                .any(|t| t.status == LightStatus::BehindSurface);
            let lit = eval.lights.iter().any(|t| t.status == LightStatus::Lit);
            if behind && !lit {
                let reversed = normal.map(|n| NormalUsed {
                    used: -n.used,
                    reversed: true,
                    ..n
                });
                let alt = evaluate(problem, *position, reversed, None, material)?;
                solution.readings.push(Reading {
                    code: ReadingCode::NormalReversed,
                    intersection: None,
                    evaluation: alt,
                });
            }
            solution.evaluation = Some(eval);
        }
        Target::Ray {
            ray,
            direction,
            surfaces,
        } => {
            // Find the nearest hit in front of the origin, Section 4.4 (t > 0).
            let mut front: Option<(usize, R)> = None;
            let mut behind: Option<(usize, R)> = None;
            for (i, s) in surfaces.iter().enumerate() {
                let hits = s.shape.line_hits(ray);
                if let Some(t) = hits.nearest_in_front() {
                    if front.is_none_or(|(_, best)| t < best) {
                        front = Some((i, t));
                    }
                }
                if let Some(t) = hits.nearest_behind() {
                    if behind.is_none_or(|(_, best)| t > best) {
                        behind = Some((i, t));
                    }
                }
            }
            let record = |hit: Option<(usize, R)>| Intersection {
                origin: ray.origin,
                direction_given: direction.given,
                direction: ray.direction,
                surface: hit.map(|(i, _)| i),
                kind: hit.map(|(i, _)| surfaces[i].shape.kind()),
                t: hit.map(|(_, t)| t),
                point: hit.map(|(i, t)| surfaces[i].shape.point_at(ray, t)),
                in_front: hit.is_some_and(|(_, t)| t > R::ZERO),
            };
            // The incoming direction: the ray's, or the reversed ray's for a hit behind.
            let at_hit = |(i, t): (usize, R), incoming: V3<R>| {
                let s = &surfaces[i];
                let p = s.shape.point_at(ray, t);
                let own = s.shape.normal_at(p);
                // Turn the normal to face the incoming ray (DESIGN.md, as in the tracer).
                let reversed = own.dot(incoming) > R::ZERO;
                let normal = NormalUsed {
                    given: s.normal.map_or(own, |n| n.given),
                    length: s.normal.map_or(R::ONE, |n| n.length),
                    used: if reversed { -own } else { own },
                    reversed,
                };
                evaluate(problem, Some(p), Some(normal), Some(incoming), &s.material)
            };
            match (front, behind) {
                (Some(hit), _) => {
                    solution.intersection = Some(record(Some(hit)));
                    solution.evaluation = Some(at_hit(hit, ray.direction)?);
                }
                (None, Some(hit)) => {
                    let rec = record(Some(hit));
                    solution.intersection = Some(rec);
                    let eval = at_hit(hit, -ray.direction)?;
                    solution.readings.push(Reading {
                        code: ReadingCode::LineBehindOrigin,
                        intersection: Some(rec),
                        evaluation: eval,
                    });
                }
                (None, None) => solution.intersection = Some(record(None)),
            }
        }
    }
    solution.findings = findings::find(problem, &solution);
    Ok(solution)
}

/// Shades one point with the core, recording every intermediate.
fn evaluate<R: Real>(
    problem: &Problem<R>,
    p: Option<V3<R>>,
    normal: Option<NormalUsed<R>>,
    ray_direction: Option<V3<R>>,
    material: &NamedMaterial<R>,
) -> Result<Evaluation<R>, Invalid> {
    // The viewing direction V = (P − E)/‖P − E‖, from the eye to the point (Eq. 4.10).
    let viewer = match (problem.viewer, p, ray_direction) {
        (Some(e), Some(p), _) => {
            let v = between::<R>(e, p).ok_or_else(|| {
                Invalid::new(
                    "viewer",
                    "the viewer is exactly at the point being shaded, so V is undefined",
                    "move the viewer away from the point",
                )
            })?;
            if !v.length.is_finite() {
                return Err(Invalid::new(
                    "viewer",
                    format!(
                        "the distance from the viewer to the point overflows {}",
                        R::NAME
                    ),
                    "bring the coordinates into a smaller range",
                ));
            }
            Some((Some(e), v.unit))
        }
        (None, Some(_), Some(d)) => Some((None, d)),
        _ => None,
    };
    let n_used = normal.map_or(V3::<R>::ZERO, |n| n.used);
    let viewer = viewer.map(|(position, v)| {
        let n_dot_v = n_used.dot(v);
        ViewerUsed {
            position,
            v,
            n_dot_v,
            side: if n_dot_v < R::ZERO {
                Side::Front
            } else if n_dot_v > R::ZERO {
                Side::Back
            } else {
                Side::InPlane
            },
        }
    });
    // Lights exactly at a hit point (ray problems; point problems are checked on loading).
    if let Some(p) = p {
        for (l, info) in problem.lights.lights.iter().zip(&problem.light_info) {
            if l.position() == Some(p) {
                return Err(Invalid::new(
                    format!("lights[{}].position", info.file_index),
                    "the light is exactly at the point being shaded, so L (Eq. 4.1) is undefined",
                    "move the light",
                ));
            }
        }
    }

    let at = crate::core::ShadingPoint {
        p: p.unwrap_or(V3::<R>::ZERO),
        n: n_used,
        v: viewer.map(|v| v.v),
    };
    let mut lights = Vec::with_capacity(problem.lights.lights.len());
    let shade = shade(
        &at,
        &material.material,
        &problem.lights,
        &mut AllVisible,
        &mut lights,
    );
    check_finite(problem, &shade, &lights)?;

    let m = &material.material;
    let mut omitted = Vec::new();
    let mut omit = |term, reason| omitted.push(Omission { term, reason });
    match (problem.lights.ambient, m.o_a) {
        (None, _) => omit(Term::Ambient, OmissionReason::NoAmbientLight),
        (Some(_), None) => omit(Term::Ambient, OmissionReason::NoAmbientColor),
        _ => {}
    }
    if problem.lights.lights.is_empty() {
        omit(Term::Diffuse, OmissionReason::NoDirectLight);
        omit(Term::Specular, OmissionReason::NoDirectLight);
    } else {
        if m.o_d.is_none() {
            omit(Term::Diffuse, OmissionReason::NoDiffuseColor);
        }
        if m.o_s.is_none() {
            omit(Term::Specular, OmissionReason::NoSpecularColor);
        } else if viewer.is_none() {
            omit(Term::Specular, OmissionReason::NoViewer);
        }
    }

    let clamped = clamp01::<R>(shade.color);
    let c = clamped.to_array();
    let rgb8 = [0, 1, 2].map(|i| (c[i].to_f64() * 255.0).round() as u8);
    Ok(Evaluation {
        point: p,
        normal,
        viewer,
        material: material.clone(),
        lights,
        shade,
        omitted,
        clamped,
        rgb8,
    })
}

fn clamp01<R: Real>(c: V3<R>) -> V3<R> {
    let a = c.to_array().map(|x| x.max(R::ZERO).min(R::ONE));
    V3::<R>::new(a[0], a[1], a[2])
}

/// Refuses a result that is not finite in this precision: never print NaN or infinity.
fn check_finite<R: Real>(
    problem: &Problem<R>,
    shade: &Shade<R>,
    lights: &[LightTerm<R>],
) -> Result<(), Invalid> {
    for (t, info) in lights.iter().zip(&problem.light_info) {
        let ok = t.arrival.distance.is_none_or(|d| d.is_finite())
            && t.arrival.i_l.is_finite()
            && t.arrival.falloff_factor.is_finite()
            && t.diffuse.is_none_or(|d| d.is_finite())
            && t.diffuse_literal.is_none_or(|d| d.is_finite())
            && t.specular.term.is_finite()
            && t.specular.literal.is_none_or(|d| d.is_finite());
        if !ok {
            return Err(Invalid::new(
                format!("lights[{}]", info.file_index),
                format!(
                    "the light reaching the point from {} overflows {} (d = {})",
                    light_label(info.file_index, info.kind),
                    R::NAME,
                    t.arrival.distance.map_or("∞".into(), |d| d.to_string())
                ),
                "use --precision f64, or bring the numbers into a smaller range",
            ));
        }
    }
    let literal_ok = shade.literal.is_none_or(|l| l.is_finite());
    if !shade.color.is_finite() || !literal_ok {
        return Err(Invalid::new(
            "lights",
            format!("the total colour overflows {}", R::NAME),
            "use --precision f64, or bring the numbers into a smaller range",
        ));
    }
    Ok(())
}
