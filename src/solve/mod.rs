//! The solver: from a validated [`Problem`] to a [`Solution`] holding every intermediate of the
//! shading core, what the problem leaves out and why, the findings a student should know about
//! (a light behind the surface, a hit behind the ray's origin, …) and, where a problem as written
//! has a surprising property, the result of its likely intended reading, labelled as such.

mod findings;

use crate::core::vector::between;
use crate::core::{
    shade_with, AllVisible, Chapter, Formulas, Light, LightKind, LightSet, LightStatus, LightTerm,
    Real, Shade, Vector, V3,
};
use crate::problem::validate::{light_label, show};
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

/// Where V comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ViewSource {
    /// V = (P − E)/‖P − E‖ from the viewer's position.
    Viewer,
    /// V = D: the ray comes from the eye.
    Ray,
    /// V = −D: the reversed ray of a reading.
    ReversedRay,
}

/// The viewing direction used at the point.
#[derive(Clone, Copy, Debug)]
pub struct ViewerUsed<R: Real> {
    /// E, when V comes from the viewer.
    pub position: Option<V3<R>>,
    pub source: ViewSource,
    /// V, unit, from the eye to the point.
    pub v: V3<R>,
    /// N·V (negative when the viewer is in front of the surface); `None` without a normal.
    pub n_dot_v: Option<R>,
    pub side: Option<Side>,
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
    /// The lights as shaded, when a reading changed them (the problem's otherwise).
    pub light_set: Option<LightSet<R>>,
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
    /// No light lights the surface as given and one is behind it: L taken from the point to
    /// the light, the opposite of Eq. 4.1, which is the same as mirroring each light through P
    /// to the front side. Light and viewer are then both in front.
    LightReversed,
    /// The same situation read as a surface lit from behind: the normal reversed (what taking
    /// |cos θ| amounts to); the viewer is then behind it.
    NormalReversed,
    /// The ray meets the surface only behind its origin: the point where its line does (t < 0),
    /// which is the hit of the reversed ray.
    LineBehindOrigin,
}

impl ReadingCode {
    /// Whether the reading is what the problem's author most likely meant (the report labels it
    /// "likely intended reading"), rather than another way to read it.
    pub fn likely_intended(self) -> bool {
        match self {
            ReadingCode::LightReversed | ReadingCode::LineBehindOrigin => true,
            ReadingCode::NormalReversed => false,
        }
    }
}

impl<R: Real> Evaluation<R> {
    /// The lights this evaluation shaded with.
    pub fn lights_used<'a>(&'a self, problem: &'a Problem<R>) -> &'a LightSet<R> {
        self.light_set.as_ref().unwrap_or(&problem.lights)
    }
}

/// Solves a validated problem.
pub fn solve<R: Real>(problem: &Problem<R>) -> Result<Solution<R>, Invalid> {
    solve_with(problem, Chapter)
}

/// Solves a validated problem with the core's formulas switched as `formulas` says: the mistake
/// diagnosis of `phong check` reproduces a slip inside a formula this way.
pub fn solve_with<R: Real, F: Formulas>(
    problem: &Problem<R>,
    formulas: F,
) -> Result<Solution<R>, Invalid> {
    let mut solution = Solution {
        title: problem.title.clone(),
        question: problem.question.clone(),
        findings: Vec::new(),
        intersection: None,
        evaluation: None,
        readings: Vec::new(),
    };
    let mut starts_on_surface = false;
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
            let at = |n, lights: Option<LightSet<R>>| {
                evaluate(problem, formulas, *position, n, None, material, lights)
            };
            let eval = at(normal, None)?;
            // Readings: no light lights the surface as given, and one is behind it.
            let behind = eval
                .lights
                .iter()
                .any(|t| t.status == LightStatus::BehindSurface);
            let lit = eval.lights.iter().any(|t| t.status == LightStatus::Lit);
            if let (true, false, Some(p)) = (behind, lit, *position) {
                let mirrored = mirror_lights(&problem.lights, p);
                solution.readings.push(Reading {
                    code: ReadingCode::LightReversed,
                    intersection: None,
                    evaluation: at(normal, Some(mirrored))?,
                });
                let reversed = normal.map(|n| NormalUsed {
                    used: -n.used,
                    reversed: true,
                    ..n
                });
                solution.readings.push(Reading {
                    code: ReadingCode::NormalReversed,
                    intersection: None,
                    evaluation: at(reversed, None)?,
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
                starts_on_surface |= hits.at_origin();
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
            let at_hit = |(i, t): (usize, R), source: ViewSource| {
                let s = &surfaces[i];
                let p = s.shape.point_at(ray, t);
                let own = s.shape.normal_at(p).ok_or_else(|| {
                    Invalid::new(
                        format!("surfaces[{i}]"),
                        format!(
                            "the hit point cannot be told from the sphere's centre in {}: the \
                             radius is below the rounding of the coordinates",
                            R::NAME
                        ),
                        "use --precision f64, a larger radius, or coordinates nearer the origin",
                    )
                })?;
                let incoming = match source {
                    ViewSource::ReversedRay => -ray.direction,
                    _ => ray.direction,
                };
                // Turn the normal to face the incoming ray (DESIGN.md, as in the tracer).
                let reversed = own.dot(incoming) > R::ZERO;
                let normal = NormalUsed {
                    given: s.normal.map_or(own, |n| n.given),
                    length: s.normal.map_or(R::ONE, |n| n.length),
                    used: if reversed { -own } else { own },
                    reversed,
                };
                evaluate(
                    problem,
                    formulas,
                    Some(p),
                    Some(normal),
                    Some((incoming, source)),
                    &s.material,
                    None,
                )
            };
            match (front, behind) {
                (Some(hit), _) => {
                    solution.intersection = Some(record(Some(hit)));
                    solution.evaluation = Some(at_hit(hit, ViewSource::Ray)?);
                }
                (None, Some(hit)) => {
                    let rec = record(Some(hit));
                    solution.intersection = Some(rec);
                    solution.readings.push(Reading {
                        code: ReadingCode::LineBehindOrigin,
                        intersection: Some(rec),
                        evaluation: at_hit(hit, ViewSource::ReversedRay)?,
                    });
                }
                (None, None) => solution.intersection = Some(record(None)),
            }
        }
    }
    solution.findings = findings::find(problem, &solution, starts_on_surface);
    Ok(solution)
}

/// Each light mirrored through P: a point or spot light moves to 2P − P_l (a spot's axis
/// reversed with it), a directional light travels the other way. Every L, R and cos ψ is
/// then the negative of the original (cos ψ unchanged), d unchanged: exactly "L reversed".
pub(crate) fn mirror_lights<R: Real>(lights: &LightSet<R>, p: V3<R>) -> LightSet<R> {
    let mirror = |q: V3<R>| p * R::TWO - q;
    let mirrored = lights
        .lights
        .iter()
        .map(|l| Light {
            color: l.color,
            kind: match l.kind {
                LightKind::Point { position, falloff } => LightKind::Point {
                    position: mirror(position),
                    falloff,
                },
                LightKind::Directional { direction } => LightKind::Directional {
                    direction: -direction,
                },
                LightKind::Spot {
                    position,
                    falloff,
                    mut cone,
                } => {
                    cone.axis = -cone.axis;
                    LightKind::Spot {
                        position: mirror(position),
                        falloff,
                        cone,
                    }
                }
            },
        })
        .collect();
    LightSet {
        ambient: lights.ambient,
        lights: mirrored,
    }
}

/// Shades one point with the core, recording every intermediate. `ray` is the incoming
/// direction and where V comes from when the problem has no viewer; `lights` replaces the
/// problem's lights in a reading that changes them. Undefined L or V is an error here, for
/// point and ray problems alike.
fn evaluate<R: Real, F: Formulas>(
    problem: &Problem<R>,
    formulas: F,
    p: Option<V3<R>>,
    normal: Option<NormalUsed<R>>,
    ray: Option<(V3<R>, ViewSource)>,
    material: &NamedMaterial<R>,
    lights: Option<LightSet<R>>,
) -> Result<Evaluation<R>, Invalid> {
    let set = lights.as_ref().unwrap_or(&problem.lights);
    // The viewing direction V, from the eye to the point (Eq. 4.10).
    let viewer = match (problem.viewer, p, ray) {
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
            Some((Some(e), ViewSource::Viewer, v.unit))
        }
        (None, Some(_), Some((d, source))) => Some((None, source, d)),
        _ => None,
    };
    let viewer = viewer.map(|(position, source, v)| {
        let n_dot_v = normal.map(|n| n.used.dot(v));
        ViewerUsed {
            position,
            source,
            v,
            n_dot_v,
            side: n_dot_v.map(|d| {
                if d < R::ZERO {
                    Side::Front
                } else if d > R::ZERO {
                    Side::Back
                } else {
                    Side::InPlane
                }
            }),
        }
    });
    // A light exactly at the point: L (Eq. 4.1) is undefined.
    if let Some(p) = p {
        for (l, info) in set.lights.iter().zip(&problem.light_info) {
            if l.position() == Some(p) {
                return Err(Invalid::new(
                    format!("lights[{}].position", info.file_index),
                    "the light is exactly at the point being shaded, so \
                     L = (P − P_l)/‖P − P_l‖ (Eq. 4.1) is undefined",
                    "move the light or the point",
                ));
            }
        }
    }

    let at = crate::core::ShadingPoint {
        p: p.unwrap_or(V3::<R>::ZERO),
        n: normal.map_or(V3::<R>::ZERO, |n| n.used),
        v: viewer.map(|v| v.v),
    };
    let mut records = Vec::with_capacity(set.lights.len());
    let shade = shade_with(
        formulas,
        &at,
        &material.material,
        set,
        &mut AllVisible,
        &mut records,
    );
    check_finite(problem, &shade, &records)?;

    let m = &material.material;
    let mut omitted = Vec::new();
    let mut omit = |term, reason| omitted.push(Omission { term, reason });
    match (set.ambient, m.o_a) {
        (None, _) => omit(Term::Ambient, OmissionReason::NoAmbientLight),
        (Some(_), None) => omit(Term::Ambient, OmissionReason::NoAmbientColor),
        _ => {}
    }
    if set.lights.is_empty() {
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
        light_set: lights,
        lights: records,
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
    let fix = if R::NAME == "f32" {
        "use --precision f64, or bring the numbers into a smaller range"
    } else {
        "bring the numbers (colours, distances, coordinates) into a smaller range"
    };
    for (t, info) in lights.iter().zip(&problem.light_info) {
        let a = &t.arrival;
        let name = light_label(info.file_index, info.kind);
        let distance = a
            .distance
            .map_or(String::new(), |d| format!(" (d = {})", show(d.to_f64())));
        let what = if !a.distance.is_none_or(|d| d.is_finite()) {
            Some(format!("the distance from {name} to the point"))
        } else if !a.falloff_factor.is_finite() {
            Some(format!("the falloff factor 1/d^f of {name}{distance}"))
        } else if !a.i_l.is_finite() {
            Some(format!("the light I_l arriving from {name}{distance}"))
        } else if !(t.diffuse.is_none_or(|d| d.is_finite())
            && t.diffuse_literal.is_none_or(|d| d.is_finite())
            && t.specular.term.is_finite()
            && t.specular.literal.is_none_or(|d| d.is_finite()))
        {
            Some(format!("the diffuse or specular term of {name}"))
        } else {
            None
        };
        if let Some(what) = what {
            return Err(Invalid::new(
                format!("lights[{}]", info.file_index),
                format!("{what} overflows {}", R::NAME),
                fix,
            ));
        }
    }
    let literal_ok = shade.literal.is_none_or(|l| l.is_finite());
    if !shade.color.is_finite() || !literal_ok {
        return Err(Invalid::new(
            "lights",
            format!("the total colour overflows {}", R::NAME),
            fix,
        ));
    }
    Ok(())
}
