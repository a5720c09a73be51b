//! The stable JSON output of `phong solve --format json`.
//!
//! Field names are part of the interface: scripts read them. A change that renames or removes a
//! field, or changes its meaning, must bump [`FORMAT_VERSION`]; adding a field need not.
//! Vectors and colours are `[x, y, z]`; a quantity that does not apply is `null`.

use serde::Serialize;

use super::messages;
use crate::core::LightSet;
use crate::core::{Falloff, LightKind, LightStatus, LightTerm, Real, SpecularStatus, Vector, V3};
use crate::problem::model::ReflectivitySource;
use crate::problem::Problem;
use crate::solve::{
    Evaluation, Intersection, OmissionReason, ReadingCode, Side, Solution, Term, ViewSource,
};

/// The version of this output format.
pub(crate) const FORMAT_VERSION: u32 = 1;

/// One solved problem.
#[derive(Serialize)]
pub struct Document<'a, R: Real> {
    pub format_version: u32,
    pub file: String,
    /// "f32" or "f64".
    pub precision: &'static str,
    pub title: Option<&'a str>,
    pub question: Option<&'a str>,
    pub findings: Vec<FindingOut>,
    pub intersection: Option<IntersectionOut<R>>,
    /// The problem as written; `null` when there is nothing to shade (the ray hits nothing).
    pub solution: Option<EvaluationOut<R>>,
    /// Other readings of a problem whose literal reading is surprising.
    pub readings: Vec<ReadingOut<R>>,
}

#[derive(Serialize)]
pub struct FindingOut {
    #[serde(flatten)]
    pub finding: crate::solve::Finding,
    pub message: String,
}

#[derive(Serialize)]
pub struct IntersectionOut<R: Real> {
    pub origin: V3<R>,
    pub direction_given: V3<R>,
    pub direction: V3<R>,
    /// The surface's index in the file's `surfaces`.
    pub surface: Option<usize>,
    /// For a mesh, the triangle's index in it (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangle: Option<usize>,
    pub surface_type: Option<&'static str>,
    pub t: Option<R>,
    pub point: Option<V3<R>>,
    /// t > 0.
    pub hit: bool,
}

#[derive(Serialize)]
pub struct ReadingOut<R: Real> {
    pub code: ReadingCode,
    pub label: &'static str,
    pub explanation: &'static str,
    pub intersection: Option<IntersectionOut<R>>,
    pub solution: EvaluationOut<R>,
}

#[derive(Serialize)]
pub struct EvaluationOut<R: Real> {
    pub point: Option<V3<R>>,
    pub normal: Option<NormalOut<R>>,
    pub viewer: Option<ViewerOut<R>>,
    pub material: MaterialOut<R>,
    pub ambient: AmbientOut<R>,
    pub lights: Vec<LightOut<R>>,
    pub totals: TotalsOut<R>,
    pub color: ColorOut<R>,
    pub omitted: Vec<OmissionOut>,
}

#[derive(Serialize)]
pub struct NormalOut<R: Real> {
    pub given: V3<R>,
    pub length: R,
    /// N as used: unit, reversed where the solution says so.
    pub n: V3<R>,
    pub reversed: bool,
}

#[derive(Serialize)]
pub struct ViewerOut<R: Real> {
    /// E; `null` when V comes from the ray.
    pub position: Option<V3<R>>,
    /// "viewer", "ray" (V = D) or "reversed_ray" (V = −D).
    pub source: ViewSource,
    pub v: V3<R>,
    /// `null` when the problem gives no normal.
    pub n_dot_v: Option<R>,
    pub side: Option<Side>,
}

#[derive(Serialize)]
pub struct MaterialOut<R: Real> {
    pub name: Option<String>,
    pub o_a: Option<V3<R>>,
    pub o_d: Option<V3<R>>,
    pub o_s: Option<V3<R>>,
    pub n_s: Option<R>,
    pub o_r: Option<V3<R>>,
    pub o_r_source: Option<ReflectivitySource>,
}

#[derive(Serialize)]
pub struct AmbientOut<R: Real> {
    /// The ambient lights' colours, in file order, and their sum I_a.
    pub lights: Vec<V3<R>>,
    pub i_a: Option<V3<R>>,
    pub o_a: Option<V3<R>>,
    /// O_a I_a, Eq. 4.6; `null` when left out.
    pub term: Option<V3<R>>,
}

#[derive(Serialize)]
pub struct ConeOut<R: Real> {
    pub axis: V3<R>,
    pub angle_deg: R,
    pub exponent: R,
    pub cos_psi: R,
    /// ψ in degrees, the angle between the axis and L.
    pub psi_deg: R,
    pub cos_gamma: R,
    pub inside: bool,
    pub on_edge: bool,
    /// (cos ψ)^e inside the cone, 0 outside.
    pub factor: R,
}

#[derive(Serialize)]
pub struct DiffuseOut<R: Real> {
    /// O_d I_l cos θ where the light is lit, else 0 (Eq. 4.8).
    pub term: V3<R>,
    /// O_d I_l cos θ regardless of sign.
    pub literal: Option<V3<R>>,
}

#[derive(Serialize)]
pub struct SpecularOut<R: Real> {
    pub status: SpecularStatus,
    pub r: Option<V3<R>>,
    pub cos_phi: Option<R>,
    pub cos_phi_pow: Option<R>,
    pub term: V3<R>,
    pub literal: Option<V3<R>>,
}

#[derive(Serialize)]
pub struct LightOut<R: Real> {
    /// The index in the file's `lights` array.
    pub index: usize,
    pub name: Option<String>,
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// C_l.
    pub color: V3<R>,
    pub position: Option<V3<R>>,
    pub status: LightStatus,
    pub status_message: &'static str,
    pub l: V3<R>,
    pub d: Option<R>,
    pub falloff: Option<u8>,
    pub falloff_factor: R,
    pub cone: Option<ConeOut<R>>,
    pub i_l: V3<R>,
    pub n_dot_l: R,
    pub cos_theta: R,
    pub diffuse: Option<DiffuseOut<R>>,
    pub specular: SpecularOut<R>,
}

#[derive(Serialize)]
pub struct TotalsOut<R: Real> {
    pub ambient: V3<R>,
    pub diffuse: V3<R>,
    pub specular: V3<R>,
}

#[derive(Serialize)]
pub struct ColorOut<R: Real> {
    /// Eq. 4.16 with gating, unclamped.
    pub unclamped: V3<R>,
    /// Clamped to [0, 1].
    pub clamped: V3<R>,
    /// round(255 · clamped).
    pub rgb8: [u8; 3],
    /// Eq. 4.16 taken literally (no gating); `null` when undefined.
    pub literal: Option<V3<R>>,
}

#[derive(Serialize)]
pub struct OmissionOut {
    pub term: Term,
    pub reason: OmissionReason,
    pub message: String,
}

/// Builds the JSON document of a solution.
pub fn document<'a, R: Real>(
    file: &str,
    problem: &'a Problem<R>,
    s: &'a Solution<R>,
) -> Document<'a, R> {
    Document {
        format_version: FORMAT_VERSION,
        file: file.to_owned(),
        precision: R::NAME,
        title: s.title.as_deref(),
        question: s.question.as_deref(),
        findings: s
            .findings
            .iter()
            .map(|f| FindingOut {
                finding: f.clone(),
                message: messages::finding(problem, f),
            })
            .collect(),
        intersection: s.intersection.as_ref().map(intersection),
        solution: s.evaluation.as_ref().map(|e| evaluation(problem, e)),
        readings: s
            .readings
            .iter()
            .map(|r| ReadingOut {
                code: r.code,
                label: messages::reading_label(r.code),
                explanation: messages::reading_explanation(r.code),
                intersection: r.intersection.as_ref().map(intersection),
                solution: evaluation(problem, &r.evaluation),
            })
            .collect(),
    }
}

fn intersection<R: Real>(x: &Intersection<R>) -> IntersectionOut<R> {
    IntersectionOut {
        origin: x.origin,
        direction_given: x.direction_given,
        direction: x.direction,
        surface: x.source.map(|s| s.index),
        triangle: x.source.and_then(|s| s.triangle),
        surface_type: x.kind,
        t: x.t,
        point: x.point,
        hit: x.in_front,
    }
}

fn evaluation<R: Real>(problem: &Problem<R>, e: &Evaluation<R>) -> EvaluationOut<R> {
    let m = &e.material.material;
    let ambient_term = e.shade.ambient;
    EvaluationOut {
        point: e.point,
        normal: e.normal.map(|n| NormalOut {
            given: n.given,
            length: n.length,
            n: n.used,
            reversed: n.reversed,
        }),
        viewer: e.viewer.map(|v| ViewerOut {
            position: v.position,
            source: v.source,
            v: v.v,
            n_dot_v: v.n_dot_v,
            side: v.side,
        }),
        material: MaterialOut {
            name: e.material.name.clone(),
            o_a: m.o_a,
            o_d: m.o_d,
            o_s: m.o_s,
            n_s: e.material.spec.shininess.map(|_| m.n_s),
            o_r: m.o_r,
            o_r_source: e.material.reflectivity,
        },
        ambient: AmbientOut {
            lights: problem.ambient_info.iter().map(|a| a.color).collect(),
            i_a: e.lights_used(problem).ambient,
            o_a: m.o_a,
            term: ambient_term,
        },
        lights: e
            .lights
            .iter()
            .map(|t| light(problem, e.lights_used(problem), t))
            .collect(),
        totals: TotalsOut {
            ambient: ambient_term.unwrap_or(V3::<R>::ZERO),
            diffuse: e.shade.diffuse,
            specular: e.shade.specular,
        },
        color: ColorOut {
            unclamped: e.shade.color,
            clamped: e.clamped,
            rgb8: e.rgb8,
            literal: e.shade.literal,
        },
        omitted: e
            .omitted
            .iter()
            .map(|o| OmissionOut {
                term: o.term,
                reason: o.reason,
                message: messages::omission(o),
            })
            .collect(),
    }
}

fn light<R: Real>(problem: &Problem<R>, set: &LightSet<R>, t: &LightTerm<R>) -> LightOut<R> {
    let light = &set.lights[t.index];
    let info = &problem.light_info[t.index];
    let a = &t.arrival;
    let cone = match (light.kind, a.cone) {
        (LightKind::Spot { cone, .. }, Some(test)) => Some(ConeOut {
            axis: cone.axis,
            angle_deg: cone.angle_deg,
            exponent: cone.exponent,
            cos_psi: test.cos_psi,
            psi_deg: test.psi_deg,
            cos_gamma: test.cos_gamma,
            inside: test.inside,
            on_edge: test.on_edge,
            factor: test.factor,
        }),
        _ => None,
    };
    LightOut {
        index: info.file_index,
        name: info.name.clone(),
        kind: info.kind,
        color: light.color,
        position: light.position(),
        status: t.status,
        status_message: messages::light_status(t.status),
        l: a.l,
        d: a.distance,
        falloff: a.falloff.map(Falloff::exponent),
        falloff_factor: a.falloff_factor,
        cone,
        i_l: a.i_l,
        n_dot_l: t.n_dot_l,
        cos_theta: t.cos_theta,
        diffuse: t.diffuse.map(|term| DiffuseOut {
            term,
            literal: t.diffuse_literal,
        }),
        specular: SpecularOut {
            status: t.specular.status,
            r: t.specular.r,
            cos_phi: t.specular.cos_phi,
            cos_phi_pow: t.specular.cos_phi_pow,
            term: t.specular.term,
            literal: t.specular.literal,
        },
    }
}
