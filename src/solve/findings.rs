//! Findings: what a student should be told about a problem beyond its numbers. Each finding is
//! structured (a code, the light it concerns, named values) so that scripts can rely on it and
//! the report layer words it, in whatever language.

use std::collections::BTreeMap;

use super::{Side, Solution};
use crate::core::vector::is_unit_length;
use crate::core::{LightStatus, Real, Vector, V3};
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
    /// The point is exactly on a spot light's cone edge (lit).
    LightOnConeEdge,
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
            if t.arrival.cone.is_some_and(|c| c.on_edge) {
                out.push(f(FindingCode::LightOnConeEdge));
            }
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
