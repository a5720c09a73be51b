//! Findings: what a student should be told about a problem beyond its numbers. Each finding is
//! structured (a code, the light it concerns, named values) so that scripts can rely on it and
//! the report layer words it, in whatever language.

use std::collections::BTreeMap;

use super::rounding::{cone_bound, cos_theta_bound, exactly_zero, HitError};
use super::{Evaluation, Side, Solution};
use crate::core::vector::is_unit_length;
use crate::core::{LightKind, LightStatus, LightTerm, Real, Vector, V3};
use crate::geometry::Shape;
use crate::problem::{GivenVector, Problem, Target};

/// What kind of finding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingCode {
    /// The ray meets a surface only behind its origin (t ≤ 0): no hit.
    HitBehindOrigin,
    /// The ray's line meets no surface at all.
    NoIntersection,
    /// The ray starts on a surface (t = 0), which is not a hit (t > 0).
    RayStartsOnSurface,
    /// A light is on the back side of the surface (cos θ < 0).
    LightBehindSurface,
    /// A light lies in the tangent plane (cos θ = 0).
    LightInTangentPlane,
    /// The point is outside a spot light's cone.
    LightOutsideCone,
    /// The point is on a spot light's cone edge to within the rounding of ψ and γ (lit).
    LightOnConeEdge,
    /// |cos θ| is within the rounding error of its own computation (0 included, unless it is
    /// exactly 0 for the given numbers): the gate's decision, lit or not, is not reliable in
    /// this precision. Values: `cos_theta`, `error_bound`.
    GateUndecidable,
    /// A ray's hit point and ψ − γ are rounded by more than ψ is from γ: inside or outside the
    /// cone cannot be decided in this precision. Values: `psi_deg`, `gamma_deg`,
    /// `error_bound_deg`.
    ConeEdgeUndecidable,
    /// The viewer sees the back side of the surface.
    ViewerBehindSurface,
    /// The viewer lies in the surface's tangent plane.
    ViewerInTangentPlane,
    /// The viewer is not the ray's origin: V comes from the viewer, as the problem states.
    ViewerNotAtRayOrigin,
    /// The normal in the hit was reversed to face the incoming ray.
    NormalTurnedToFaceRay,
    /// A given normal was not of unit length and was normalised.
    NormalNormalized,
    /// A given direction (ray, light, spot axis) was not of unit length and was normalised.
    DirectionNormalized,
    /// Eq. 4.16 taken literally, without gating, gives another colour.
    LiteralDiffers,
    /// The colour exceeds 1 in some channel and is clamped for display.
    Clamped,
}

/// One finding.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Finding {
    pub code: FindingCode,
    /// The index in the file's `lights` array of the light it concerns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub light: Option<usize>,
    /// Named values that back the finding (cos θ, t, a length, …).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub values: BTreeMap<&'static str, f64>,
}

impl Finding {
    fn new(code: FindingCode) -> Self {
        Finding {
            code,
            light: None,
            values: BTreeMap::new(),
        }
    }
    fn light(mut self, i: usize) -> Self {
        self.light = Some(i);
        self
    }
    fn value<R: Real>(mut self, name: &'static str, x: R) -> Self {
        self.values.insert(name, x.to_f64());
        self
    }
}

/// What was asked of the problem: the viewer E used, and for a ray, its direction as given.
pub(super) struct Query<'a, R: Real> {
    pub viewer: Option<V3<R>>,
    pub ray: Option<&'a GivenVector<R>>,
}

/// The findings of a solved problem, in order of importance.
pub(super) fn find<R: Real>(
    problem: &Problem<R>,
    query: &Query<R>,
    s: &Solution<R>,
    starts_on_surface: bool,
) -> Vec<Finding> {
    let mut out = Vec::new();
    if starts_on_surface && s.evaluation.is_none() {
        out.push(Finding::new(FindingCode::RayStartsOnSurface));
    }
    if let Some(x) = &s.intersection {
        match (x.t, x.in_front) {
            (Some(t), false) => out.push(Finding::new(FindingCode::HitBehindOrigin).value("t", t)),
            (None, _) => out.push(Finding::new(FindingCode::NoIntersection)),
            _ => {}
        }
    }
    if let Some(e) = &s.evaluation {
        for (t, info) in e.lights.iter().zip(&problem.light_info) {
            let f = |code| Finding::new(code).light(info.file_index);
            match t.status {
                LightStatus::BehindSurface => {
                    out.push(f(FindingCode::LightBehindSurface).value("cos_theta", t.cos_theta))
                }
                LightStatus::InTangentPlane => out.push(f(FindingCode::LightInTangentPlane)),
                LightStatus::OutsideCone => {
                    let c = t.arrival.cone.expect("an outside-cone light is a spot");
                    out.push(
                        f(FindingCode::LightOutsideCone)
                            .value("cos_psi", c.cos_psi)
                            .value("cos_gamma", c.cos_gamma),
                    )
                }
                _ => {}
            }
            out.extend(gates(problem, s, e, t).into_iter().map(|g| Finding {
                light: Some(info.file_index),
                ..g
            }));
        }
        if let Some(v) = &e.viewer {
            match (v.side, v.n_dot_v) {
                (Some(Side::Back), Some(d)) => {
                    out.push(Finding::new(FindingCode::ViewerBehindSurface).value("n_dot_v", d))
                }
                (Some(Side::InPlane), _) => {
                    out.push(Finding::new(FindingCode::ViewerInTangentPlane))
                }
                _ => {}
            }
        }
    }
    if let (Some(x), Some(e)) = (&s.intersection, query.viewer) {
        if e != x.origin {
            out.push(Finding::new(FindingCode::ViewerNotAtRayOrigin));
        }
    }
    if let Some(n) = s.evaluation.as_ref().and_then(|e| e.normal) {
        if n.reversed {
            out.push(Finding::new(FindingCode::NormalTurnedToFaceRay));
        }
    }
    // Normals and directions that were normalised.
    let normal_length = match &problem.target {
        Target::Point { normal, .. } => normal.map(|n| n.length),
        Target::Ray { .. } | Target::Scene { .. } => s
            .intersection
            .and_then(|x| x.surface)
            .and_then(|i| problem.surfaces()[i].normal)
            .map(|n| n.length),
    };
    if let Some(l) = normal_length.filter(|&l| !is_unit_length(l)) {
        out.push(Finding::new(FindingCode::NormalNormalized).value("length", l));
    }
    if let Some(direction) = query.ray {
        if !is_unit_length(direction.length) {
            out.push(
                Finding::new(FindingCode::DirectionNormalized).value("length", direction.length),
            );
        }
    }
    for info in &problem.light_info {
        if let Some(l) = info.direction_length {
            out.push(
                Finding::new(FindingCode::DirectionNormalized)
                    .light(info.file_index)
                    .value("length", l),
            );
        }
    }
    if let Some(e) = &s.evaluation {
        if e.shade.literal.is_some_and(|l| l != e.shade.color) {
            out.push(Finding::new(FindingCode::LiteralDiffers));
        }
        if e.shade.color.max_element() > R::ONE {
            out.push(Finding::new(FindingCode::Clamped));
        }
    }
    out
}

/// How far the gates of light `t` can be trusted (`solve::rounding`): a cos θ within its
/// rounding error (0 included, unless exactly 0 for the given numbers) and a ψ within rounding
/// of γ. Only where the light arrives: outside the cone or at the light, cos θ decides nothing.
fn gates<R: Real>(
    problem: &Problem<R>,
    s: &Solution<R>,
    e: &Evaluation<R>,
    t: &LightTerm<R>,
) -> Vec<Finding> {
    let mut out = Vec::new();
    let (Some(normal), Some(p)) = (e.normal, e.point) else {
        return out;
    };
    let light = &e.lights_used(problem).lights[t.index];
    let a = &t.arrival;
    // A computed hit point's own error, and the sphere whose normal was computed from it.
    let hit = e.p_error.map(|p_error| {
        let radius = s.intersection.and_then(|x| x.surface).and_then(|i| {
            match problem.surfaces()[i].shape {
                Shape::Sphere(sp) => Some(sp.radius),
                _ => None,
            }
        });
        HitError::new(p_error, radius)
    });
    // The cone, Eq. 4.4: within the core's tolerance the point is on the edge (lit); a hit
    // point's error widens the band in which the test cannot be trusted.
    let cone = match light.kind {
        LightKind::Spot { cone, .. } => Some(cone),
        _ => None,
    };
    if let (Some(c), Some(cone), Some(d)) = (a.cone, cone, a.distance) {
        let tol = cone.edge_tolerance();
        let bound = cone_bound(tol, d, hit);
        let psi = c.psi_deg.to_f64().to_radians();
        let near = (psi - cone.gamma.to_f64()).abs() <= bound;
        let code = if c.on_edge {
            Some(FindingCode::LightOnConeEdge)
        } else {
            near.then_some(FindingCode::ConeEdgeUndecidable)
        };
        if let Some(code) = code {
            out.push(
                Finding::new(code)
                    .value("psi_deg", c.psi_deg)
                    .value("gamma_deg", cone.angle_deg)
                    .value("error_bound_deg", bound.to_degrees()),
            );
        }
    }
    // The diffuse gate, cos θ > 0 (Eq. 4.7).
    if a.reach == crate::core::Reach::Arrives {
        let bound = cos_theta_bound(normal.used, a.l, a.distance, hit);
        let c = t.cos_theta;
        // The core counts a cos θ within its rounding tolerance as 0 (the tangent plane).
        let counted_as_zero = t.status == LightStatus::InTangentPlane;
        let undecidable = if counted_as_zero {
            // Exactly in the tangent plane for the numbers as given (N·(P − P_l) = 0, or
            // N·D_l = 0 with D_l as used), or only to within rounding? A hit point is computed:
            // its exact position is not at hand, so its zero is never certain.
            let (x, from) = match light.position() {
                Some(p_l) => (p, Some(p_l)),
                None => (a.l, None),
            };
            let exact = hit.is_none() && exactly_zero::<R>(normal.given, x, from) == Some(true);
            !exact
        } else {
            c.abs().to_f64() <= bound
        };
        if undecidable {
            out.push(
                Finding::new(FindingCode::GateUndecidable)
                    .value("cos_theta", c)
                    .value("error_bound", bound)
                    // How the core decided: 1 lit, 0 counted as in the tangent plane, −1 behind.
                    .value(
                        "decision",
                        match t.status {
                            LightStatus::InTangentPlane => 0.0,
                            LightStatus::BehindSurface => -1.0,
                            _ => 1.0,
                        },
                    ),
            );
        }
    }
    out
}
