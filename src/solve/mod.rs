//! The solver: from a validated [`Problem`] to a [`Solution`] holding every intermediate of the
//! shading core, what the problem leaves out and why, the findings a student should know about
//! (a light behind the surface, a hit behind the ray's origin, …) and, where a problem as written
//! has a surprising property, the result of its likely intended reading, labelled as such.

mod conditioning;
pub(crate) mod faults;
mod file;
mod findings;
mod rounding;
mod secondary;
mod versus;

use crate::core::color::{self, clamp01};
use crate::core::real::to_f64_array;
use crate::core::vector::between;
use crate::core::{
    shade_with, AllVisible, Chapter, Formulas, Light, LightKind, LightSet, LightStatus, LightTerm,
    Real, Shade, Vector, Visibility, V3,
};
use crate::geometry::{Aggregate, Ray, Shape, SmoothNormal, SurfaceHit};
use crate::problem::validate::{light_label, show};
use crate::problem::{GivenVector, Invalid, NamedMaterial, Problem, SurfaceSource, Target};
use faults::{Overflowing, Resolve, Smaller, SolveFault};

pub use file::{solve_file, solve_source};
pub use findings::{ConeEdge, Finding, FindingData, GateDecision};
pub use secondary::{ReflectionRay, Secondary, TransmittedRay, PROBLEM_RAY_LEVEL};
pub use versus::{F32Differs, Gate, LightVersus, TotalsVersus, VersusF64, CHECK_TOLERANCE};

/// Everything the solver found out about one problem.
#[derive(Clone, Debug)]
pub struct Solution<R: Real> {
    /// The problem's title, as written.
    pub title: Option<String>,
    /// The problem's question, as written.
    pub question: Option<String>,
    /// Surprising properties and notes, most important first.
    pub findings: Vec<Finding>,
    /// For a ray problem: where the ray meets the surfaces.
    pub intersection: Option<Intersection<R>>,
    /// The problem as written; `None` when there is nothing to shade (the ray hits nothing).
    pub evaluation: Option<Evaluation<R>>,
    /// Likely intended readings of a problem whose literal reading is surprising.
    pub readings: Vec<Reading<R>>,
    /// For a ray problem whose ray hits a surface that reflects or transmits: the secondary
    /// rays of Section 4.4 at the hit (shown, not traced).
    pub secondary: Option<Secondary<R>>,
    /// Solved in f32 from a file: f32 − f64 of the problem as written (`solve::versus`);
    /// `None` in f64.
    pub versus_f64: Option<VersusF64>,
}

/// Where a ray problem's ray meets its surfaces.
#[derive(Clone, Copy, Debug)]
pub struct Intersection<R: Real> {
    /// O, the ray's origin.
    pub origin: V3<R>,
    /// D as given.
    pub direction_given: V3<R>,
    /// D, unit.
    pub direction: V3<R>,
    /// The surface met (index in the problem's surfaces, a mesh counted triangle by triangle),
    /// if any.
    pub surface: Option<usize>,
    /// Where that surface is in the file (its index in `surfaces`, and a mesh's triangle).
    pub source: Option<SurfaceSource>,
    /// The kind of surface met ("plane", "sphere" or "triangle"); `None` when none is.
    pub kind: Option<&'static str>,
    /// The parameter t of the hit along the line (negative: behind the origin).
    pub t: Option<R>,
    /// The meeting point O + tD; `None` when the line meets no surface.
    pub point: Option<V3<R>>,
    /// t > 0: a hit of the ray itself.
    pub in_front: bool,
    /// Where in the file a plane the ray lies in is, when the ray meets no surface otherwise:
    /// every point of the ray is on it, so there is no single hit point.
    pub lies_in: Option<SurfaceSource>,
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
    /// On a smooth triangle (a mesh with vertex normals): how the shading normal was
    /// interpolated from the vertex normals, `given` then being the geometric normal, which
    /// decides `reversed` (docs/conventions.md, "Smooth meshes"); `None` elsewhere.
    pub smooth: Option<SmoothNormal<R>>,
}

/// Which side of the surface the viewer is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// N·V < 0: the viewer is in front of the surface.
    Front,
    /// N·V > 0: the viewer is behind the surface.
    Back,
    /// N·V = 0: the viewer is in the surface's tangent plane.
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
    /// Where V comes from: the viewer, the ray, or the reversed ray.
    pub source: ViewSource,
    /// V, unit, from the eye to the point.
    pub v: V3<R>,
    /// N·V (negative when the viewer is in front of the surface); `None` without a normal.
    pub n_dot_v: Option<R>,
    /// Which side of the surface the viewer is on; `None` without a normal.
    pub side: Option<Side>,
}

/// A term of Eq. 4.16.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Term {
    /// O_a I_a, Eq. 4.6.
    Ambient,
    /// O_d I_l cos θ, Eq. 4.8.
    Diffuse,
    /// O_s I_l (cos φ)^n_s, Eq. 4.10.
    Specular,
}

/// A term the problem does not let us compute, and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OmissionReason {
    /// The problem gives no ambient light.
    NoAmbientLight,
    /// The material gives no ambient colour O_a.
    NoAmbientColor,
    /// The problem gives no point, directional or spot light.
    NoDirectLight,
    /// The material gives no diffuse colour O_d.
    NoDiffuseColor,
    /// The problem gives no viewer, so V and cos φ are unknown.
    NoViewer,
    /// The material gives no specular colour O_s.
    NoSpecularColor,
}

/// A term of Eq. 4.16 left out, and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Omission {
    /// The term left out.
    pub term: Term,
    /// Why it is left out.
    pub reason: OmissionReason,
}

/// The shading of one point, with every intermediate.
#[derive(Clone, Debug)]
pub struct Evaluation<R: Real> {
    /// P; `None` when the problem does not need it.
    pub point: Option<V3<R>>,
    /// N as given and as used; `None` when the problem does not need it.
    pub normal: Option<NormalUsed<R>>,
    /// V and where it came from; `None` without a viewer.
    pub viewer: Option<ViewerUsed<R>>,
    /// The material at P.
    pub material: NamedMaterial<R>,
    /// The lights as shaded, when a reading changed them (the problem's otherwise).
    pub light_set: Option<LightSet<R>>,
    /// The per-light record of the core.
    pub lights: Vec<LightTerm<R>>,
    /// The core's result: each term summed over the lights, and the total (Eq. 4.16).
    pub shade: Shade<R>,
    /// The terms the problem does not let the solver compute, and why.
    pub omitted: Vec<Omission>,
    /// The colour clamped to [0, 1] for display.
    pub clamped: V3<R>,
    /// The clamped colour in 8 bits, round(255·c).
    pub rgb8: [u8; 3],
    /// A bound on the error of each component of P where P was computed (a ray's hit);
    /// `None` where P was given.
    pub p_error: Option<V3<R>>,
    /// Set where a ray problem's hit was shaded in the frame of the ray's origin because it is
    /// far from the origin compared with its lights or viewer (`Frame::RayOrigin`).
    pub far_from_origin: Option<FarFromOrigin>,
}

/// Why a hit was shaded in the frame of the ray's origin: the rounding of P itself, and what
/// it would have cost the directions from P had P − P_l been computed from the rounded P.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct FarFromOrigin {
    /// ‖bound on the error of P‖.
    pub point_error: f64,
    /// The bound 2e/d on the error of L (or V) from it, at the nearest light or viewer at
    /// distance d (at most 2, the most a unit vector can move).
    pub direction_error: f64,
}

/// A reading of the problem other than the literal one.
#[derive(Clone, Debug)]
pub struct Reading<R: Real> {
    /// Which reading.
    pub code: ReadingCode,
    /// The reading's own intersection (the reversed ray of `line_behind_origin`); `None`
    /// otherwise.
    pub intersection: Option<Intersection<R>>,
    /// The shading of the point under this reading.
    pub evaluation: Evaluation<R>,
}

/// The ways of reading a problem other than the literal one.
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
    pub(crate) fn likely_intended(self) -> bool {
        match self {
            ReadingCode::LightReversed | ReadingCode::LineBehindOrigin => true,
            ReadingCode::NormalReversed => false,
        }
    }
}

impl<R: Real> Solution<R> {
    /// The problem's title and question, nothing found or shaded yet.
    fn empty(problem: &Problem<R>) -> Self {
        Solution {
            title: problem.title.as_deref().map(str::to_owned),
            question: problem.question.as_deref().map(str::to_owned),
            findings: Vec::new(),
            intersection: None,
            evaluation: None,
            readings: Vec::new(),
            secondary: None,
            versus_f64: None,
        }
    }
}

impl<R: Real> Evaluation<R> {
    /// The lights this evaluation shaded with.
    pub(crate) fn lights_used<'a>(&'a self, problem: &'a Problem<R>) -> &'a LightSet<R> {
        self.light_set.as_ref().unwrap_or(&problem.lights)
    }
}

/// Solves a validated problem.
pub fn solve<R: Real>(problem: &Problem<R>) -> Result<Solution<R>, Invalid> {
    solve_with(problem, Chapter)
}

/// Solves a validated problem with the core's formulas switched as `formulas` says: the mistake
/// diagnosis of `phong check` reproduces a slip inside a formula this way.
pub(crate) fn solve_with<R: Real, F: Formulas>(
    problem: &Problem<R>,
    formulas: F,
) -> Result<Solution<R>, Invalid> {
    let mut solution = Solution::empty(problem);
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
                smooth: None,
            });
            let at = |n, lights: Option<&LightSet<R>>| {
                let viewer = problem.viewer;
                let vis = &mut AllVisible;
                evaluate(
                    problem, formulas, viewer, *position, n, None, material, lights, vis,
                )
            };
            let eval = at(normal, None)?;
            // Readings: no light lights the surface as given, and one is behind it.
            let behind = eval
                .lights
                .iter()
                .any(|t| t.status == LightStatus::BehindSurface);
            let lit = eval.lights.iter().any(|t| t.status == LightStatus::Lit);
            if let (true, false, Some(p)) = (behind, lit, *position) {
                // A light mirrored through a far point can leave the precision's range
                // (2P − P_l overflows): that reading is then left out, not reported as inf.
                let mirrored = mirror_lights(&problem.lights, p);
                if positions_finite(&mirrored) {
                    solution.readings.push(Reading {
                        code: ReadingCode::LightReversed,
                        intersection: None,
                        evaluation: at(normal, Some(&mirrored))?,
                    });
                }
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
        Target::Ray { ray, direction, .. } => {
            let aggregate = aggregate(problem);
            return solve_ray_with(
                problem,
                formulas,
                problem.viewer,
                ray,
                direction,
                &aggregate,
                Frame::RayOrigin,
                true,
            );
        }
        Target::Scene { .. } => return Err(Invalid::of("ray", SolveFault::Scene)),
    }
    let query = findings::Query {
        viewer: problem.viewer,
        ray: None,
    };
    solution.findings = findings::find(problem, &query, &solution, false);
    Ok(solution)
}

/// The surfaces of a problem as one [`Aggregate`], to find hits and cast shadow rays.
pub(crate) fn aggregate<R: Real>(problem: &Problem<R>) -> Aggregate<R> {
    Aggregate::new(problem.surfaces().iter().map(|s| s.shape.clone()).collect())
}

/// Solves one ray against the problem's surfaces and lights: the nearest hit in front of the
/// origin (t > 0) found by the same [`Aggregate::nearest`] as the tracer, shaded by the core
/// with the tracer's shadow rays (when `problem.render.shadows`). `viewer` is E, or `None` for
/// V = D, the ray coming from the eye (as every ray of the tracer does); `direction` is D as
/// given. This is what `phong render --explain-pixel` calls for every ray of a pixel.
pub(crate) fn solve_ray<R: Real>(
    problem: &Problem<R>,
    viewer: Option<V3<R>>,
    ray: &Ray<R>,
    direction: &GivenVector<R>,
    aggregate: &Aggregate<R>,
) -> Result<Solution<R>, Invalid> {
    solve_ray_with(
        problem,
        Chapter,
        viewer,
        ray,
        direction,
        aggregate,
        Frame::Absolute,
        false,
    )
}

/// How far the rounding of a hit point P would carry into the directions from it: with
/// e = ‖p_error‖ and d the distance to the nearest point or spot light or to the viewer, L and V
/// computed from the rounded P are off by up to 2e/d (`solve::rounding`). `Some` when that
/// exceeds 1e4·ε, four of the precision's digits: a hit about 1000 times farther from the
/// origin than from its nearest light, where the frame of the ray's origin keeps those digits.
/// An ordinary scene's hits stay below it, so their ray problems are shaded exactly as the
/// tracer shades the same rays.
fn far_from_origin<R: Real>(
    problem: &Problem<R>,
    viewer: Option<V3<R>>,
    hit: &SurfaceHit<R>,
) -> Option<FarFromOrigin> {
    let e = norm(hit.p_error.to_array().map(|x| x.to_f64()));
    let p = hit.p.to_array().map(|x| x.to_f64());
    let distance = |q: V3<R>| {
        let q = q.to_array().map(|x| x.to_f64());
        norm(std::array::from_fn(|i| p[i] - q[i]))
    };
    let d = problem
        .lights
        .lights
        .iter()
        .filter_map(|l| l.position())
        .chain(viewer)
        .map(distance)
        .fold(f64::INFINITY, f64::min);
    // A unit vector moves by at most 2, however far its point is moved.
    let direction_error = (2.0 * e / d).min(2.0);
    let threshold = 1e4 * R::EPSILON.to_f64();
    (e.is_finite() && d.is_finite() && direction_error > threshold).then_some(FarFromOrigin {
        point_error: e,
        direction_error,
    })
}

/// The Euclidean length of `v`, scaled by its largest component so that no square overflows
/// (a hit 1e230 from the origin has an error bound whose square is beyond f64).
fn norm(v: [f64; 3]) -> f64 {
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * v.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}

/// The frame a ray's hit is shaded in (docs/accuracy.md, "Far from the origin").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Frame {
    /// The problem's own coordinates, P the hit point as computed: what the tracer does, so
    /// that an explained pixel is the rendered pixel to the bit.
    Absolute,
    /// Coordinates relative to the ray's origin O where the hit is far from the origin
    /// compared with its lights ([`far_from_origin`]): P − P_l is computed as tD − (P_l − O)
    /// and P − E as tD − (E − O), so that a hit 1e12 from the origin does not lose the digits
    /// of P − P_l to the rounding of P itself; the problem's coordinates elsewhere, as the
    /// tracer. A ray problem's frame.
    RayOrigin,
}

/// A ray problem's lights and viewer moved into the frame of the ray's origin O: each position
/// X becomes X − O (one rounding, relative to |X − O|, small when X is near O however far both
/// are from the origin). `None` when a moved position leaves the precision's range: the
/// absolute frame is used then.
struct Moved<R: Real> {
    lights: LightSet<R>,
    viewer: Option<V3<R>>,
}

impl<R: Real> Moved<R> {
    /// `lights` and `viewer` moved by −`origin`.
    fn new(lights: &LightSet<R>, viewer: Option<V3<R>>, origin: V3<R>) -> Option<Self> {
        let by = |x: V3<R>| x - origin;
        let lights = map_lights(lights, by, |d| d);
        let viewer = viewer.map(by);
        (positions_finite(&lights) && viewer.is_none_or(|e| e.is_finite()))
            .then_some(Moved { lights, viewer })
    }
}

/// The shadow rays of a hit shaded in the frame of the ray's origin: the core asks about a
/// moved light, and the rays are cast from the hit as computed to the light as given (the same
/// light by its place in the set).
struct MovedVisibility<'a, R: Real, V> {
    inner: &'a mut V,
    moved: &'a LightSet<R>,
    given: &'a LightSet<R>,
    p: V3<R>,
}

impl<R: Real, V: Visibility<R>> Visibility<R> for MovedVisibility<'_, R, V> {
    /// Whether the light as given reaches the hit as computed, asked of the inner visibility.
    fn visible(&mut self, _: V3<R>, light: &Light<R>, arrival: &crate::core::Arrival<R>) -> bool {
        // The core shades with `moved` itself (not a copy), so the light is found by address.
        let k = self
            .moved
            .lights
            .iter()
            .position(|l| std::ptr::eq(l, light));
        debug_assert!(k.is_some(), "a light of the moved set");
        let given = k.map_or(light, |k| &self.given.lights[k]);
        self.inner.visible(self.p, given, arrival)
    }
}

/// [`solve_ray`] with the core's formulas switched as `formulas` says (mistake diagnosis).
/// `secondaries` asks for the hit's secondary rays ([`Solution::secondary`]): a ray problem
/// shows them; a pixel's explanation does not, since its tree shows the rays traced.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_ray_with<R: Real, F: Formulas>(
    problem: &Problem<R>,
    formulas: F,
    viewer: Option<V3<R>>,
    ray: &Ray<R>,
    direction: &GivenVector<R>,
    aggregate: &Aggregate<R>,
    frame: Frame,
    secondaries: bool,
) -> Result<Solution<R>, Invalid> {
    let mut solution = Solution::empty(problem);
    let surfaces = problem.surfaces();
    let moved = match frame {
        Frame::RayOrigin => Moved::new(&problem.lights, viewer, ray.origin),
        Frame::Absolute => None,
    };
    let record = |hit: Option<(usize, R, V3<R>)>| Intersection {
        origin: ray.origin,
        direction_given: direction.given,
        direction: ray.direction,
        surface: hit.map(|(i, _, _)| i),
        source: hit.map(|(i, _, _)| surfaces[i].source),
        kind: hit.map(|(i, _, _)| surfaces[i].shape.kind()),
        t: hit.map(|(_, t, _)| t),
        point: hit.map(|(_, _, p)| p),
        in_front: hit.is_some_and(|(_, t, _)| t > R::ZERO),
        lies_in: None,
    };
    // The shading at a hit, V from the incoming direction (the ray's, or the reversed ray's
    // for a hit behind) and N turned to face it by the hit, as in the tracer
    // (docs/conventions.md, "Orientation").
    let at_hit = |i: usize, hit: &SurfaceHit<R>, source: ViewSource| {
        let s = &surfaces[i];
        let incoming = match source {
            ViewSource::ReversedRay => -ray.direction,
            _ => ray.direction,
        };
        let facing = hit.facing(incoming);
        // A smooth triangle's interpolation, as its hit made it: the ray's own hit again, or
        // for the line behind the origin the weights of its point.
        let smooth = match &s.shape {
            Shape::Triangle(tri) if tri.normals.is_some() => match source {
                ViewSource::ReversedRay => {
                    tri.smooth(tri.barycentric_at(hit.p, hit.normal), hit.normal)
                }
                _ => tri.smooth_hit(ray, hit.t),
            },
            _ => None,
        };
        let normal = NormalUsed {
            given: s.normal.as_deref().map_or(hit.normal, |n| n.given),
            length: s.normal.as_deref().map_or(R::ONE, |n| n.length),
            used: facing.normal,
            reversed: facing.reversed,
            smooth,
        };
        let view = Some((incoming, source));
        // The hit's shadow rays, as the tracer casts them, when the problem has them on.
        let mut shadows = problem.render.shadows.then(|| hit.shadow_rays(aggregate));
        let m = &s.material;
        let far = far_from_origin(problem, viewer, hit);
        let e = match moved.as_ref().filter(|_| far.is_some()) {
            // P − O = tD, exactly the t the hit was found at.
            Some(mv) => {
                let mut vis = MovedVisibility {
                    inner: &mut shadows,
                    moved: &mv.lights,
                    given: &problem.lights,
                    p: hit.p,
                };
                let p_local = ray.direction * hit.t;
                let e = evaluate(
                    problem,
                    formulas,
                    mv.viewer,
                    Some(p_local),
                    Some(normal),
                    view,
                    m,
                    Some(&mv.lights),
                    &mut vis,
                )?;
                // Shown in the problem's own coordinates.
                Evaluation {
                    point: Some(hit.p),
                    viewer: e.viewer.map(|v| ViewerUsed {
                        position: viewer,
                        ..v
                    }),
                    light_set: None,
                    ..e
                }
            }
            None => evaluate(
                problem,
                formulas,
                viewer,
                Some(hit.p),
                Some(normal),
                view,
                m,
                None,
                &mut shadows,
            )?,
        };
        Ok(Evaluation {
            p_error: Some(hit.p_error),
            far_from_origin: far,
            ..e
        })
    };
    // The nearest hit in front of the origin, Section 4.4 (t > 0).
    let unresolved = |i: usize| {
        Invalid::of(
            format!("surfaces[{}]", surfaces[i].source.index),
            SolveFault::HitAtCentre {
                precision: R::NAME,
                fix: if R::NAME == "f32" {
                    Resolve::Precision
                } else {
                    Resolve::Radius
                },
            },
        )
    };
    let mut starts_on_surface = false;
    // A plane the ray lies in, which the hit search (N·D = 0) passes over.
    let mut lies_in = None;
    if let Some(h) = aggregate.nearest(ray, R::from_f64(f64::INFINITY)) {
        solution.intersection = Some(record(Some((h.index, h.hit.t, h.hit.p))));
        solution.evaluation = Some(at_hit(h.index, &h.hit, ViewSource::Ray)?);
        if secondaries {
            let m = &surfaces[h.index].material.material;
            solution.secondary = secondary::at_hit(&h.hit, ray.direction, m, &problem.render);
        }
    } else {
        // No hit in front: where does the line meet a surface behind the origin?
        let mut behind: Option<(usize, R)> = None;
        for (i, s) in surfaces.iter().enumerate() {
            // A hit in front that the aggregate dropped: its point has no normal here.
            let t_front = s.shape.hit_t(ray, R::from_f64(f64::INFINITY));
            if t_front.is_some_and(|t| s.shape.hit_at(ray, t).is_none()) {
                return Err(unresolved(i));
            }
            if lies_in.is_none() && s.shape.contains_line(ray) {
                lies_in = Some(s.source);
            }
            let hits = s.shape.line_hits(ray);
            starts_on_surface |= hits.at_origin();
            if let Some(t) = hits.nearest_behind() {
                if behind.is_none_or(|(_, best)| t > best) {
                    behind = Some((i, t));
                }
            }
        }
        match behind {
            Some((i, t)) => {
                let hit = SurfaceHit::behind_origin(&surfaces[i].shape, ray, t)
                    .ok_or_else(|| unresolved(i))?;
                let rec = record(Some((i, t, hit.p)));
                solution.intersection = Some(rec);
                solution.readings.push(Reading {
                    code: ReadingCode::LineBehindOrigin,
                    intersection: Some(rec),
                    evaluation: at_hit(i, &hit, ViewSource::ReversedRay)?,
                });
            }
            None => {
                solution.intersection = Some(Intersection {
                    lies_in,
                    ..record(None)
                })
            }
        }
    }
    let query = findings::Query {
        viewer,
        ray: Some(direction),
    };
    solution.findings = findings::find(problem, &query, &solution, starts_on_surface);
    Ok(solution)
}

/// Whether every point and spot light of `lights` is at a finite position.
pub(crate) fn positions_finite<R: Real>(lights: &LightSet<R>) -> bool {
    lights
        .lights
        .iter()
        .all(|l| l.position().is_none_or(|p| p.is_finite()))
}

/// Each light mirrored through P: a point or spot light moves to 2P − P_l (a spot's axis
/// reversed with it), a directional light travels the other way. Every L, R and cos ψ is
/// then the negative of the original (cos ψ unchanged), d unchanged: exactly "L reversed".
pub(crate) fn mirror_lights<R: Real>(lights: &LightSet<R>, p: V3<R>) -> LightSet<R> {
    map_lights(lights, |q| p * R::TWO - q, |d| -d)
}

/// The lights with each position (a point's, a spot's apex) taken through `place` and each
/// direction (a directional light's, a spot's axis) through `turn`; colours, falloffs, cones'
/// angles and the ambient light as they are.
fn map_lights<R: Real>(
    lights: &LightSet<R>,
    place: impl Fn(V3<R>) -> V3<R>,
    turn: impl Fn(V3<R>) -> V3<R>,
) -> LightSet<R> {
    let moved = lights
        .lights
        .iter()
        .map(|l| Light {
            color: l.color,
            kind: match l.kind {
                LightKind::Point { position, falloff } => LightKind::Point {
                    position: place(position),
                    falloff,
                },
                LightKind::Directional { direction } => LightKind::Directional {
                    direction: turn(direction),
                },
                LightKind::Spot {
                    position,
                    falloff,
                    mut cone,
                } => {
                    cone.axis = turn(cone.axis);
                    LightKind::Spot {
                        position: place(position),
                        falloff,
                        cone,
                    }
                }
            },
        })
        .collect();
    LightSet {
        ambient: lights.ambient,
        lights: moved,
    }
}

/// Shades one point with the core, recording every intermediate. `ray` is the incoming
/// direction and where V comes from when the problem has no viewer; `lights` replaces the
/// problem's lights in a reading that changes them. Undefined L or V is an error here, for
/// point and ray problems alike.
#[allow(clippy::too_many_arguments)]
fn evaluate<R: Real, F: Formulas, Vis: Visibility<R>>(
    problem: &Problem<R>,
    formulas: F,
    viewer: Option<V3<R>>,
    p: Option<V3<R>>,
    normal: Option<NormalUsed<R>>,
    ray: Option<(V3<R>, ViewSource)>,
    material: &NamedMaterial<R>,
    lights: Option<&LightSet<R>>,
    visibility: &mut Vis,
) -> Result<Evaluation<R>, Invalid> {
    let set = lights.unwrap_or(&problem.lights);
    // The viewing direction V, from the eye to the point (Eq. 4.10).
    let viewer = match (viewer, p, ray) {
        (Some(e), Some(p), _) => {
            let v = between::<R>(e, p)
                .ok_or_else(|| Invalid::of("viewer", SolveFault::ViewerAtPoint))?;
            if !v.length.is_finite() {
                return Err(Invalid::of(
                    "viewer",
                    SolveFault::ViewerTooFar { precision: R::NAME },
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
                return Err(Invalid::of(
                    format!("lights[{}].position", info.file_index),
                    SolveFault::LightAtPoint,
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
        visibility,
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
    let rgb8 = color::rgb8(to_f64_array::<R>(clamped));
    Ok(Evaluation {
        point: p,
        normal,
        viewer,
        material: material.clone(),
        light_set: lights.cloned(),
        lights: records,
        shade,
        omitted,
        clamped,
        rgb8,
        p_error: None,
        far_from_origin: None,
    })
}

/// Refuses a result that is not finite in this precision: never print NaN or infinity.
fn check_finite<R: Real>(
    problem: &Problem<R>,
    shade: &Shade<R>,
    lights: &[LightTerm<R>],
) -> Result<(), Invalid> {
    let fix = if R::NAME == "f32" {
        Smaller::Precision
    } else {
        Smaller::Numbers
    };
    for (t, info) in lights.iter().zip(&problem.light_info) {
        let a = &t.arrival;
        // Named and formatted only for a light that fails: the diagnosis of `phong check`
        // solves a problem once per slip and pair, and names cost more than the checks.
        let name = || light_label(info.file_index, info.kind);
        let distance = || {
            a.distance
                .map_or(String::new(), |d| format!(" (d = {})", show(d.to_f64())))
        };
        let what = if !a.distance.is_none_or(|d| d.is_finite()) {
            Some(Overflowing::Distance { light: name() })
        } else if !a.falloff_factor.is_finite() {
            Some(Overflowing::Falloff {
                light: name(),
                distance: distance(),
            })
        } else if !a.i_l.is_finite() {
            Some(Overflowing::Arriving {
                light: name(),
                distance: distance(),
            })
        } else if !(t.diffuse.is_none_or(|d| d.is_finite())
            && t.diffuse_literal.is_none_or(|d| d.is_finite())
            && t.specular.term.is_finite()
            && t.specular.literal.is_none_or(|d| d.is_finite()))
        {
            Some(Overflowing::Terms { light: name() })
        } else {
            None
        };
        if let Some(what) = what {
            return Err(Invalid::of(
                format!("lights[{}]", info.file_index),
                SolveFault::LightOverflows {
                    what,
                    precision: R::NAME,
                    fix: fix.clone(),
                },
            ));
        }
    }
    let literal_ok = shade.literal.is_none_or(|l| l.is_finite());
    if !shade.color.is_finite() || !literal_ok {
        return Err(Invalid::of(
            "lights",
            SolveFault::TotalOverflows {
                precision: R::NAME,
                fix,
            },
        ));
    }
    Ok(())
}
