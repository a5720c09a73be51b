//! Findings: what a student should be told about a problem beyond its numbers. Each finding is
//! structured (what it is, with the numbers that back it, and the light it concerns) so that
//! scripts can rely on it and the report layer words it, in whatever language.

use super::conditioning::{self, PlaneHit};
use super::rounding::{cone_bound, cos_theta_bound, exactly_zero, HitError};
use super::{Evaluation, Intersection, Side, Solution};
use crate::core::vector::is_unit_length;
use crate::core::{LightKind, LightStatus, LightTerm, Real, Vector, V3};
use crate::geometry::{Ray, Shape};
use crate::problem::{GivenVector, Problem, Target};

/// One finding. In the JSON: its `code`, the `light` it concerns (when it concerns one), and
/// its numbers as `values`, by name (absent when it has none).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Finding {
    /// What was found, with its numbers.
    #[serde(flatten)]
    pub data: FindingData,
    /// The index in the file's `lights` array of the light it concerns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub light: Option<usize>,
}

impl Finding {
    pub(super) fn new(data: FindingData) -> Self {
        Finding { data, light: None }
    }
    fn light(mut self, i: usize) -> Self {
        self.light = Some(i);
        self
    }
}

/// What kind of finding, each with the numbers that back it (the JSON's `values`, named as the
/// fields are).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "code", content = "values")]
pub enum FindingData {
    /// Solved in f32, the answer is not f64's: a channel differs by more than the check's
    /// tolerance, a gate goes the other way, or a channel is 0 in one and not in the other;
    /// with the number of the file that lost its digits when read in f32 (`solve::versus`).
    F32DiffersFromF64(super::versus::F32Differs),
    /// The ray meets a surface only behind its origin (t ≤ 0): no hit.
    HitBehindOrigin {
        /// The t of the meeting along the ray's line, ≤ 0.
        t: f64,
    },
    /// The ray's line meets no surface at all.
    NoIntersection,
    /// The ray lies in a plane: every point of it is on the surface, so there is no single hit
    /// point (N·D = 0 and N·(Q − O) = 0 as computed).
    RayInPlane {
        /// The plane's index in the file's `surfaces`.
        surface: usize,
    },
    /// The ray nearly grazes the plane it meets, so its hit is sensitive to the last digits of
    /// the data (`solve::conditioning`): t and P are known only to within the bounds given,
    /// which count the rounding of the file's numbers and of the computation.
    HitIllConditioned {
        /// N·D as computed, N and D of unit length: the sine of the angle between ray and plane.
        n_dot_d: f64,
        /// The bound on the error of N·D.
        n_dot_d_error: f64,
        /// t as computed.
        t: f64,
        /// The bound on the error of t.
        t_error_bound: f64,
        /// The bound on the error of each coordinate of P = O + tD.
        p_error_bound: [f64; 3],
    },
    /// N·D is within its own rounding error of 0: the ray may be parallel to the plane, so
    /// whether and where it meets it depends on the last digits of the data.
    ParallelWithinRounding {
        /// N·D as computed, N and D of unit length.
        n_dot_d: f64,
        /// The bound on the error of N·D, at least |N·D|.
        n_dot_d_error: f64,
        /// N·(Q − O) is within its rounding error of 0 too: the ray may lie in the plane.
        may_lie_in_plane: bool,
    },
    /// The ray starts on a surface (t = 0), which is not a hit (t > 0).
    RayStartsOnSurface,
    /// A light is on the back side of the surface (cos θ < 0).
    LightBehindSurface {
        /// cos θ = −N·L (Eq. 4.7), < 0.
        cos_theta: f64,
    },
    /// A light lies in the tangent plane (cos θ = 0).
    LightInTangentPlane,
    /// The point is outside a spot light's cone: cos ψ < cos γ.
    LightOutsideCone {
        /// cos γ, the cosine of the cone's angle.
        cos_gamma: f64,
        /// cos ψ = D_l·L, < cos γ.
        cos_psi: f64,
    },
    /// The point is on a spot light's cone edge to within the rounding of ψ and γ (lit).
    LightOnConeEdge(ConeEdge),
    /// |cos θ| is within the rounding error of its own computation (0 included, unless it is
    /// exactly 0 for the given numbers): the gate's decision, lit or not, is not reliable in
    /// this precision.
    GateUndecidable {
        /// cos θ = −N·L as computed (Eq. 4.7).
        cos_theta: f64,
        /// How the core decided.
        decision: GateDecision,
        /// The bound on the rounding error of cos θ.
        error_bound: f64,
    },
    /// A ray's hit point and ψ − γ are rounded by more than ψ is from γ: inside or outside the
    /// cone cannot be decided in this precision.
    ConeEdgeUndecidable(ConeEdge),
    /// The viewer sees the back side of the surface (N·V > 0).
    ViewerBehindSurface {
        /// N·V, > 0.
        n_dot_v: f64,
    },
    /// The viewer lies in the surface's tangent plane.
    ViewerInTangentPlane,
    /// The viewer is not the ray's origin: V comes from the viewer, as the problem states.
    ViewerNotAtRayOrigin,
    /// The hit is far from the origin compared with its nearest light or viewer, so it was
    /// shaded in the frame of the ray's origin (P − P_l = (O − P_l) + tD), which keeps the
    /// digits that the rounding of P itself would cost the directions L and V.
    HitFarFromOrigin(super::FarFromOrigin),
    /// The normal in the hit was reversed to face the incoming ray.
    NormalTurnedToFaceRay,
    /// A given normal was not of unit length and was normalised.
    NormalNormalized {
        /// ‖N‖ as given.
        length: f64,
    },
    /// A given direction (ray, light, spot axis) was not of unit length and was normalised.
    DirectionNormalized {
        /// The direction's length as given.
        length: f64,
    },
    /// Eq. 4.16 taken literally, without gating, gives another colour.
    LiteralDiffers,
    /// The colour exceeds 1 in some channel and is clamped for display.
    Clamped,
}

/// ψ and γ of a spot light that lie within rounding of each other (Eq. 4.4), in degrees.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ConeEdge {
    /// The bound on the rounding of ψ − γ (a ray's hit point's error included).
    pub error_bound_deg: f64,
    /// γ, the cone's angle.
    pub gamma_deg: f64,
    /// ψ, the angle between the cone's axis D_l and L.
    pub psi_deg: f64,
}

/// How the core decided a diffuse gate (cos θ > 0, Eq. 4.7) that rounding leaves undecided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GateDecision {
    /// cos θ > 0: the light lights the surface.
    Lit,
    /// cos θ counted as 0: the light is in the tangent plane.
    InTangentPlane,
    /// cos θ < 0: the light is behind the surface.
    Behind,
}

impl GateDecision {
    /// As the JSON writes it: 1 lit, 0 in the tangent plane, −1 behind.
    pub(crate) fn value(self) -> f64 {
        match self {
            GateDecision::Lit => 1.0,
            GateDecision::InTangentPlane => 0.0,
            GateDecision::Behind => -1.0,
        }
    }
}

impl serde::Serialize for GateDecision {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_f64(self.value())
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
        out.push(Finding::new(FindingData::RayStartsOnSurface));
    }
    if let Some(x) = &s.intersection {
        match (x.t, x.in_front) {
            (Some(t), false) => {
                out.push(Finding::new(FindingData::HitBehindOrigin { t: t.to_f64() }))
            }
            (None, _) => out.push(Finding::new(match x.lies_in {
                Some(source) => FindingData::RayInPlane {
                    surface: source.index,
                },
                None => FindingData::NoIntersection,
            })),
            _ => {}
        }
        out.extend(hit_conditioning(problem, x));
    }
    if let Some(e) = &s.evaluation {
        for (t, info) in e.lights.iter().zip(&problem.light_info) {
            let f = |code| Finding::new(code).light(info.file_index);
            match t.status {
                LightStatus::BehindSurface => out.push(f(FindingData::LightBehindSurface {
                    cos_theta: t.cos_theta.to_f64(),
                })),
                LightStatus::InTangentPlane => out.push(f(FindingData::LightInTangentPlane)),
                LightStatus::OutsideCone => {
                    let c = t.arrival.cone.expect("an outside-cone light is a spot");
                    out.push(f(FindingData::LightOutsideCone {
                        cos_gamma: c.cos_gamma.to_f64(),
                        cos_psi: c.cos_psi.to_f64(),
                    }))
                }
                _ => {}
            }
            out.extend(
                gates(problem, s, e, t)
                    .into_iter()
                    .map(|g| g.light(info.file_index)),
            );
        }
        if let Some(v) = &e.viewer {
            match (v.side, v.n_dot_v) {
                (Some(Side::Back), Some(d)) => {
                    out.push(Finding::new(FindingData::ViewerBehindSurface {
                        n_dot_v: d.to_f64(),
                    }))
                }
                (Some(Side::InPlane), _) => {
                    out.push(Finding::new(FindingData::ViewerInTangentPlane))
                }
                _ => {}
            }
        }
    }
    if let (Some(x), Some(e)) = (&s.intersection, query.viewer) {
        if e != x.origin {
            out.push(Finding::new(FindingData::ViewerNotAtRayOrigin));
        }
    }
    let far = s
        .evaluation
        .iter()
        .chain(s.readings.iter().map(|r| &r.evaluation))
        .find_map(|e| e.far_from_origin);
    if let Some(far) = far {
        out.push(Finding::new(FindingData::HitFarFromOrigin(far)));
    }
    if let Some(n) = s.evaluation.as_ref().and_then(|e| e.normal) {
        if n.reversed {
            out.push(Finding::new(FindingData::NormalTurnedToFaceRay));
        }
    }
    // Normals and directions that were normalised.
    let normal_length = match &problem.target {
        Target::Point { normal, .. } => normal.map(|n| n.length),
        Target::Ray { .. } | Target::Scene { .. } => s
            .intersection
            .and_then(|x| x.surface)
            .and_then(|i| problem.surfaces()[i].normal.as_deref().map(|n| n.length)),
    };
    if let Some(l) = normal_length.filter(|&l| !is_unit_length(l)) {
        out.push(Finding::new(FindingData::NormalNormalized {
            length: l.to_f64(),
        }));
    }
    if let Some(direction) = query.ray {
        if !is_unit_length(direction.length) {
            out.push(Finding::new(FindingData::DirectionNormalized {
                length: direction.length.to_f64(),
            }));
        }
    }
    for info in &problem.light_info {
        if let Some(l) = info.direction_length {
            out.push(
                Finding::new(FindingData::DirectionNormalized { length: l.to_f64() })
                    .light(info.file_index),
            );
        }
    }
    if let Some(e) = &s.evaluation {
        if e.shade.literal.is_some_and(|l| l != e.shade.color) {
            out.push(Finding::new(FindingData::LiteralDiffers));
        }
        if e.shade.color.max_element() > R::ONE {
            out.push(Finding::new(FindingData::Clamped));
        }
    }
    out
}

/// How well the data determine a ray's hit on a plane (`solve::conditioning`): a finding when
/// the ray grazes the plane so that t and P lose digits, or when N·D is within rounding of 0.
fn hit_conditioning<R: Real>(problem: &Problem<R>, x: &Intersection<R>) -> Option<Finding> {
    let (Some(i), Some(t)) = (x.surface, x.t) else {
        return None;
    };
    let Shape::Plane(plane) = problem.surfaces()[i].shape else {
        return None;
    };
    let ray = Ray {
        origin: x.origin,
        direction: x.direction,
    };
    match conditioning::plane_hit(&plane, &ray, t) {
        PlaneHit::WellConditioned => None,
        PlaneHit::Ill {
            n_dot_d,
            n_dot_d_error,
            t_error,
            p_error,
        } => Some(Finding::new(FindingData::HitIllConditioned {
            n_dot_d,
            n_dot_d_error,
            t: t.to_f64(),
            t_error_bound: t_error,
            p_error_bound: p_error,
        })),
        PlaneHit::Parallel {
            n_dot_d,
            n_dot_d_error,
            may_lie_in_plane,
        } => Some(Finding::new(FindingData::ParallelWithinRounding {
            n_dot_d,
            n_dot_d_error,
            may_lie_in_plane,
        })),
    }
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
        let edge = ConeEdge {
            error_bound_deg: bound.to_degrees(),
            gamma_deg: cone.angle_deg.to_f64(),
            psi_deg: c.psi_deg.to_f64(),
        };
        if c.on_edge {
            out.push(Finding::new(FindingData::LightOnConeEdge(edge)));
        } else if near {
            out.push(Finding::new(FindingData::ConeEdgeUndecidable(edge)));
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
            let zero = match light.position() {
                Some(p_l) => exactly_zero::<R>(normal.given, p, Some(p_l)),
                None => exactly_zero::<R>(normal.given, a.l, None),
            };
            let exact = hit.is_none() && zero == Some(true);
            !exact
        } else {
            c.abs().to_f64() <= bound
        };
        if undecidable {
            out.push(Finding::new(FindingData::GateUndecidable {
                cos_theta: c.to_f64(),
                decision: match t.status {
                    LightStatus::InTangentPlane => GateDecision::InTangentPlane,
                    LightStatus::BehindSurface => GateDecision::Behind,
                    _ => GateDecision::Lit,
                },
                error_bound: bound,
            }));
        }
    }
    out
}
