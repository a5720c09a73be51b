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
    Evaluation, Intersection, OmissionReason, ReadingCode, Secondary, Side, Solution, Term,
    ViewSource,
};
use crate::tracer::Stop;

/// The version of this output format.
pub const FORMAT_VERSION: u32 = 1;

/// One solved problem.
#[derive(Serialize)]
pub struct Document<'a, R: Real> {
    /// The version of this format, [`FORMAT_VERSION`] (1).
    pub format_version: u32,
    /// The problem file's path, as given.
    pub file: String,
    /// "f32" or "f64".
    pub precision: &'static str,
    /// The problem's `title`, as written in the file.
    pub title: Option<&'a str>,
    /// The problem's `question`, as written in the file.
    pub question: Option<&'a str>,
    /// What the solver noticed that a student should know (a light behind the surface, a hit
    /// behind the ray's origin, …), most important first.
    pub findings: Vec<FindingOut>,
    /// Where the ray meets the surfaces; `null` for a point problem.
    pub intersection: Option<IntersectionOut<R>>,
    /// The problem as written; `null` when there is nothing to shade (the ray hits nothing).
    pub solution: Option<EvaluationOut<R>>,
    /// Other readings of a problem whose literal reading is surprising.
    pub readings: Vec<ReadingOut<R>>,
    /// Likely unit mistakes in the file (never errors); absent when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<WarningOut>,
    /// A ray problem's secondary rays at its hit (Section 4.4), shown and not traced; absent
    /// for a point problem, a ray that hits nothing in front of its origin, and a material
    /// with neither O_r nor O_t.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub secondary_rays: Option<SecondaryOut<R>>,
    /// Solved in f32: f32 − f64 of the problem as written (the colour, and each intermediate
    /// both computed), with f64's colour and the check's tolerance; absent in f64.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub versus_f64: Option<&'a crate::solve::VersusF64>,
}

/// `secondary_rays`: the rays a ray problem's hit spawns (docs/conventions.md, "Recursion
/// level", "Weight", "Transmission").
#[derive(Serialize)]
pub struct SecondaryOut<R: Real> {
    /// The problem's ray's level: 1 (a primary ray).
    pub level: u32,
    /// The problem's ray's weight w_p: 1.
    pub weight: R,
    /// The problem's `render.max_level`: a ray is traced only if its level ≤ this.
    pub max_level: u32,
    /// The problem's `render.min_weight`: a ray is traced only if its weight > this.
    pub min_weight: R,
    /// V = D, the incoming ray's unit direction.
    pub v: V3<R>,
    /// N at the hit, turned to face the ray.
    pub n: V3<R>,
    /// N·V.
    pub n_dot_v: R,
    /// The reflection ray (Eq. 4.17); `null` when the material has no O_r.
    pub reflection: Option<ReflectionOut<R>>,
    /// The transmitted ray (Snell's law); `null` when the material has no O_t.
    pub transmission: Option<TransmittedOut<R>>,
    /// That the solver does not trace these rays, in English.
    pub note: &'static str,
}

/// `secondary_rays.reflection`: R_V = V − 2(N·V)N, Eq. 4.17.
#[derive(Serialize)]
pub struct ReflectionOut<R: Real> {
    /// O_r at the hit.
    pub reflectivity: V3<R>,
    /// R_V, unit; `null` only where it cannot be normalised.
    pub direction: Option<V3<R>>,
    /// Its level: 2.
    pub level: u32,
    /// w_s = w_p·max(O_r).
    pub weight: R,
    /// Whether the tracer traces it (level ≤ max_level, weight > min_weight, O_r ≠ 0).
    pub traced: bool,
    /// Why it is not traced ("not_reflective", "max_level", "min_weight"); `null` when it is.
    pub stop: Option<Stop>,
    /// The reason in `stop`, as an English sentence.
    pub stop_message: Option<&'static str>,
}

/// `secondary_rays.transmission`: T by Snell's law.
#[derive(Serialize)]
pub struct TransmittedOut<R: Real> {
    /// O_t at the hit.
    pub transmissivity: V3<R>,
    /// η, the material's index of refraction.
    pub ior: R,
    /// Whether the ray enters the material (it meets the surface against its own normal).
    pub entering: bool,
    /// η_i, the index of the medium the ray travels in.
    pub eta_i: R,
    /// η_t, the index beyond the surface.
    pub eta_t: R,
    /// cos θ_i = −N·V.
    pub cos_i: R,
    /// k = 1 − η_r²(1 − cos²θ_i), η_r = η_i/η_t; negative under total internal reflection.
    pub k: R,
    /// T = η_r V + (η_r cos θ_i − √k) N, unit; `null` under total internal reflection.
    pub direction: Option<V3<R>>,
    /// Whether k < 0: total internal reflection, no transmitted ray.
    pub total_internal_reflection: bool,
    /// Its level: 2.
    pub level: u32,
    /// w_t = w_p·max(O_t).
    pub weight: R,
    /// Whether the tracer traces it.
    pub traced: bool,
    /// Why it is not traced ("not_transmissive", "max_level", "min_weight",
    /// "total_internal_reflection"); `null` when it is.
    pub stop: Option<Stop>,
    /// The reason in `stop`, as an English sentence.
    pub stop_message: Option<&'static str>,
}

/// The JSON form of a transmitted ray: a ray problem's (`secondary_rays.transmission`) and an
/// explained pixel's (`rays[i].transmission`) are the same object. η is the material's: η_t
/// for a ray entering it, η_i for one leaving it.
pub(crate) fn transmitted<R: Real>(
    o_t: V3<R>,
    f: crate::tracer::Refraction<R>,
    level: u32,
    weight: R,
    stop: Option<Stop>,
) -> TransmittedOut<R> {
    TransmittedOut {
        transmissivity: o_t,
        ior: if f.entering { f.eta_t } else { f.eta_i },
        entering: f.entering,
        eta_i: f.eta_i,
        eta_t: f.eta_t,
        cos_i: f.cos_i,
        k: f.k,
        direction: f.direction,
        total_internal_reflection: f.direction.is_none(),
        level,
        weight,
        traced: stop.is_none(),
        stop,
        stop_message: stop
            .map(|s| crate::report::pixel::transmission_stop_in(s, crate::text::lang::Lang::En)),
    }
}

/// The JSON form of a hit's secondary rays.
fn secondary<R: Real>(x: &Secondary<R>) -> SecondaryOut<R> {
    use crate::report::pixel::stop_reason_in;
    use crate::text::lang::Lang;
    SecondaryOut {
        level: x.level,
        weight: x.weight,
        max_level: x.max_level,
        min_weight: x.min_weight,
        v: x.v,
        n: x.n,
        n_dot_v: x.n_dot_v,
        reflection: x.reflection.map(|r| ReflectionOut {
            reflectivity: r.o_r,
            direction: r.direction,
            level: r.level,
            weight: r.weight,
            traced: r.traced(),
            stop: r.stop,
            stop_message: r.stop.map(|s| stop_reason_in(s, Lang::En)),
        }),
        transmission: x
            .transmission
            .map(|t| transmitted(t.o_t, t.refraction, t.level, t.weight, t.stop)),
        note: messages::SECONDARY_NOT_TRACED,
    }
}

/// A likely unit mistake: its code and the value given, the field, and the sentence (English).
#[derive(Serialize)]
pub struct WarningOut {
    /// Its code, the value given and the field.
    #[serde(flatten)]
    pub warning: crate::problem::warnings::Warning,
    /// The warning with its fix, in English.
    pub message: String,
}

/// The JSON form of a file's warnings.
pub(crate) fn warnings_out(list: &[crate::problem::warnings::Warning]) -> Vec<WarningOut> {
    list.iter()
        .map(|w| WarningOut {
            warning: w.clone(),
            message: crate::text::Message::text(w, crate::text::lang::Lang::En),
        })
        .collect()
}

/// An entry of `findings`.
#[derive(Serialize)]
pub struct FindingOut {
    /// The finding's `code`, the `light` it concerns (an index in the file's `lights`) and its
    /// numbers as `values`, by name: flattened into this object.
    #[serde(flatten)]
    pub finding: crate::solve::Finding,
    /// The finding as an English sentence.
    pub message: String,
}

/// `intersection`: where a ray problem's ray meets its surfaces.
#[derive(Serialize)]
pub struct IntersectionOut<R: Real> {
    /// O, the ray's origin.
    pub origin: V3<R>,
    /// D as written in the file.
    pub direction_given: V3<R>,
    /// D as used: unit length.
    pub direction: V3<R>,
    /// The surface's index in the file's `surfaces`.
    pub surface: Option<usize>,
    /// For a mesh, the triangle's index in it (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangle: Option<usize>,
    /// The kind of surface met ("plane", "sphere" or "triangle"); `null` when none is.
    pub surface_type: Option<&'static str>,
    /// The parameter t of the nearest meeting along the ray's line (negative: behind the origin);
    /// `null` when the line meets no surface.
    pub t: Option<R>,
    /// The meeting point O + tD; `null` when the line meets no surface.
    pub point: Option<V3<R>>,
    /// t > 0.
    pub hit: bool,
    /// The index in the file's `surfaces` of a plane the ray lies in, when it meets no surface
    /// otherwise (absent otherwise): every point of the ray is on it, no single hit point.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lies_in_surface: Option<usize>,
}

/// An entry of `readings`: the problem read another way, solved by the same core.
#[derive(Serialize)]
pub struct ReadingOut<R: Real> {
    /// Which reading: "light_reversed", "normal_reversed" or "line_behind_origin".
    pub code: ReadingCode,
    /// The reading's label in English ("likely intended reading: …" or "another reading: …").
    pub label: String,
    /// What the reading changes, in English.
    pub explanation: &'static str,
    /// The reading's own intersection (a ray problem's reversed ray); `null` otherwise.
    pub intersection: Option<IntersectionOut<R>>,
    /// The shading of the point under this reading.
    pub solution: EvaluationOut<R>,
}

/// `solution` (and a reading's `solution`): the shading of one point, every intermediate.
#[derive(Serialize)]
pub struct EvaluationOut<R: Real> {
    /// P, the point shaded; `null` when the problem does not need it.
    pub point: Option<V3<R>>,
    /// N at P; `null` when the problem does not need it.
    pub normal: Option<NormalOut<R>>,
    /// V and where it came from; `null` when the problem has no viewer.
    pub viewer: Option<ViewerOut<R>>,
    /// The material at P.
    pub material: MaterialOut<R>,
    /// The ambient term, Eq. 4.5–4.6.
    pub ambient: AmbientOut<R>,
    /// Each point, directional and spot light's contribution, in file order.
    pub lights: Vec<LightOut<R>>,
    /// The ambient, diffuse and specular terms summed over the lights.
    pub totals: TotalsOut<R>,
    /// The colour at P, Eq. 4.16.
    pub color: ColorOut<R>,
    /// The terms of Eq. 4.16 the problem does not let the solver compute, and why.
    pub omitted: Vec<OmissionOut>,
}

/// `normal`: the normal at the point.
#[derive(Serialize)]
pub struct NormalOut<R: Real> {
    /// N as given, or the surface's own normal at P where the file gives none (a sphere, a
    /// triangle).
    pub given: V3<R>,
    /// ‖N‖ as given.
    pub length: R,
    /// N as used: unit, reversed where the solution says so.
    pub n: V3<R>,
    /// Whether N was reversed (to face the incoming ray, or by a reading).
    pub reversed: bool,
    /// On a smooth triangle only (a mesh with vertex normals): how N was interpolated; `given`
    /// is then the triangle's geometric normal. Absent elsewhere.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smooth: Option<SmoothOut<R>>,
}

/// `normal.smooth`: a smooth triangle's shading normal, interpolated from its vertex normals.
#[derive(Serialize)]
pub struct SmoothOut<R: Real> {
    /// The barycentric weights [b₀, b₁, b₂] of P.
    pub barycentric: [R; 3],
    /// The unit vertex normals [N₀, N₁, N₂] at the triangle's corners.
    pub vertex_normals: [V3<R>; 3],
    /// (b₀N₀ + b₁N₁ + b₂N₂)/‖b₀N₀ + b₁N₁ + b₂N₂‖, before N is turned to the ray; `null` where
    /// the sum is zero.
    pub interpolated: Option<V3<R>>,
    /// Whether the geometric normal was used instead, the interpolation being zero or on the
    /// other side of the surface.
    pub clamped: bool,
}

/// `viewer`: the viewing direction at the point.
#[derive(Serialize)]
pub struct ViewerOut<R: Real> {
    /// E; `null` when V comes from the ray.
    pub position: Option<V3<R>>,
    /// "viewer", "ray" (V = D) or "reversed_ray" (V = −D).
    pub source: ViewSource,
    /// V, unit, from the eye to the point.
    pub v: V3<R>,
    /// `null` when the problem gives no normal.
    pub n_dot_v: Option<R>,
    /// Which side of the surface the viewer is on: "front", "back" or "in_plane"; `null`
    /// without a normal.
    pub side: Option<Side>,
}

/// `material`: the material's colours and exponent.
#[derive(Serialize)]
pub struct MaterialOut<R: Real> {
    /// The material's name in the file's `materials`; `null` for an inline material.
    pub name: Option<String>,
    /// O_a, the ambient colour (Eq. 4.6); `null` when not given.
    pub o_a: Option<V3<R>>,
    /// O_d, the diffuse colour (Eq. 4.8); `null` when not given.
    pub o_d: Option<V3<R>>,
    /// O_s, the specular colour (Eq. 4.10); `null` when not given.
    pub o_s: Option<V3<R>>,
    /// n_s, the specular exponent (Eq. 4.10); `null` when not given.
    pub n_s: Option<R>,
    /// O_r, the reflectivity (Eq. 4.17); `null` when not given.
    pub o_r: Option<V3<R>>,
    /// Where O_r came from: "explicit" or "specular" (O_r = O_s); `null` without O_r.
    pub o_r_source: Option<ReflectivitySource>,
    /// O_t, the transmissivity (Section 4.4); absent for an opaque material.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub o_t: Option<V3<R>>,
    /// η, the index of refraction of the material's inside; absent for an opaque material.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ior: Option<R>,
}

/// `ambient`: the ambient term, Eq. 4.5–4.6.
#[derive(Serialize)]
pub struct AmbientOut<R: Real> {
    /// The ambient lights' colours, in file order, and their sum I_a.
    pub lights: Vec<V3<R>>,
    /// I_a, the sum of the ambient lights; `null` when there is none.
    pub i_a: Option<V3<R>>,
    /// O_a, the material's ambient colour; `null` when not given.
    pub o_a: Option<V3<R>>,
    /// O_a I_a, Eq. 4.6; `null` when left out.
    pub term: Option<V3<R>>,
}

/// `cone`: a spot light's cone test, ψ against γ (Eq. 4.4).
#[derive(Serialize)]
pub struct ConeOut<R: Real> {
    /// D_l, the cone's unit axis, pointing away from the apex.
    pub axis: V3<R>,
    /// γ_l in degrees, the angle between the axis and the cone's side.
    pub angle_deg: R,
    /// e_l, the exponent of cos ψ.
    pub exponent: R,
    /// cos ψ = D_l·L.
    pub cos_psi: R,
    /// ψ in degrees, the angle between the axis and L.
    pub psi_deg: R,
    /// cos γ_l.
    pub cos_gamma: R,
    /// ψ ≤ γ: P is inside the cone (a point on the edge counts as inside).
    pub inside: bool,
    /// |ψ − γ| within rounding: P is on the cone's edge.
    pub on_edge: bool,
    /// (cos ψ)^e inside the cone, 0 outside.
    pub factor: R,
}

/// `diffuse`: one light's diffuse term, Eq. 4.7–4.8.
#[derive(Serialize)]
pub struct DiffuseOut<R: Real> {
    /// O_d I_l cos θ where the light is lit, else 0 (Eq. 4.8).
    pub term: V3<R>,
    /// O_d I_l cos θ regardless of sign.
    pub literal: Option<V3<R>>,
}

/// `specular`: one light's specular term, Eq. 4.9–4.15.
#[derive(Serialize)]
pub struct SpecularOut<R: Real> {
    /// Why the term is what it is: "lit", "away_from_viewer", "light_not_lit", "no_viewer" or
    /// "no_specular_color".
    pub status: SpecularStatus,
    /// R = L − 2(N·L)N, Eq. 4.15; `null` where it was not needed.
    pub r: Option<V3<R>>,
    /// cos φ = −R·V, Eq. 4.10; `null` where it was not computed.
    pub cos_phi: Option<R>,
    /// (cos φ)^n_s where it was used (status "lit"); `null` otherwise.
    pub cos_phi_pow: Option<R>,
    /// O_s I_l (cos φ)^n_s where the status is "lit", else 0.
    pub term: V3<R>,
    /// O_s I_l (−R·V)^n_s without gating; `null` where undefined (a negative cos φ raised to a
    /// non-integer n_s).
    pub literal: Option<V3<R>>,
}

/// An entry of `lights`: what one point, directional or spot light adds at P.
#[derive(Serialize)]
pub struct LightOut<R: Real> {
    /// The index in the file's `lights` array.
    pub index: usize,
    /// The light's `name` in the file.
    pub name: Option<String>,
    /// The light's `type`: "point", "directional" or "spot".
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// C_l.
    pub color: V3<R>,
    /// P_l, the light's position; `null` for a directional light.
    pub position: Option<V3<R>>,
    /// Why the light does or does not add diffuse and specular light: "lit",
    /// "behind_surface", "in_tangent_plane", "outside_cone", "at_light" or "in_shadow".
    pub status: LightStatus,
    /// The status as an English sentence.
    pub status_message: &'static str,
    /// L, unit, from the light to P (Eq. 4.1); for a directional light its direction of travel.
    pub l: V3<R>,
    /// d = ‖P − P_l‖; `null` for a directional light.
    pub d: Option<R>,
    /// The falloff exponent f (0, 1 or 2, Eq. 4.3); `null` for a directional light.
    pub falloff: Option<u8>,
    /// 1/d^f (1 for a directional light).
    pub falloff_factor: R,
    /// The spot cone test; `null` for other lights.
    pub cone: Option<ConeOut<R>>,
    /// I_l, the light's colour at P (Eq. 4.2–4.4).
    pub i_l: V3<R>,
    /// N·L.
    pub n_dot_l: R,
    /// cos θ = −N·L, Eq. 4.7.
    pub cos_theta: R,
    /// The diffuse term; `null` when the material has no O_d.
    pub diffuse: Option<DiffuseOut<R>>,
    /// The specular term.
    pub specular: SpecularOut<R>,
}

/// `totals`: each term of Eq. 4.16 summed over the lights.
#[derive(Serialize)]
pub struct TotalsOut<R: Real> {
    /// O_a I_a (0 when left out).
    pub ambient: V3<R>,
    /// Σ of the lights' gated diffuse terms.
    pub diffuse: V3<R>,
    /// Σ of the lights' gated specular terms.
    pub specular: V3<R>,
}

/// `color`: the colour at P, Eq. 4.16.
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

/// An entry of `omitted`: a term of Eq. 4.16 left out, and why.
#[derive(Serialize)]
pub struct OmissionOut {
    /// The term: "ambient", "diffuse" or "specular".
    pub term: Term,
    /// Why: "no_ambient_light", "no_ambient_color", "no_direct_light", "no_diffuse_color",
    /// "no_viewer" or "no_specular_color".
    pub reason: OmissionReason,
    /// The omission as an English sentence.
    pub message: String,
}

/// One JSON document, or an array for several, pretty-printed with a final newline: what
/// `--format json` writes for the files of a run.
pub fn documents_text(mut docs: Vec<serde_json::Value>) -> String {
    let value = if docs.len() == 1 {
        docs.swap_remove(0)
    } else {
        serde_json::Value::Array(docs)
    };
    pretty(&value)
}

/// `value` pretty-printed with a final newline (a struct's fields in their order, a
/// [`serde_json::Value`]'s keys sorted).
pub fn pretty(value: &impl Serialize) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("the output serialises");
    s.push('\n');
    s
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
        warnings: warnings_out(&problem.warnings),
        secondary_rays: s.secondary.as_ref().map(secondary),
        versus_f64: s.versus_f64.as_ref(),
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
        lies_in_surface: x.lies_in.map(|s| s.index),
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
            smooth: n.smooth.map(|s| SmoothOut {
                barycentric: s.b,
                vertex_normals: s.vertex,
                interpolated: s.interpolated,
                clamped: s.clamped,
            }),
        }),
        viewer: e.viewer.map(|v| ViewerOut {
            position: v.position,
            source: v.source,
            v: v.v,
            n_dot_v: v.n_dot_v,
            side: v.side,
        }),
        material: MaterialOut {
            name: e.material.name.as_deref().map(str::to_owned),
            o_a: m.o_a,
            o_d: m.o_d,
            o_s: m.o_s,
            n_s: e.material.spec.shininess.map(|_| m.n_s),
            o_r: m.o_r,
            o_r_source: e.material.reflectivity,
            o_t: m.transmission.map(|t| t.o_t),
            ior: m.transmission.map(|t| t.eta),
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
        name: info.name.as_deref().map(str::to_owned),
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
