//! The words of the reports: every sentence about a finding, a status, an omission or a
//! reading is written here, once, so that the text and the JSON say the same thing.

use super::number::num;
use crate::core::{LightStatus, Real, SpecularStatus};
use crate::problem::validate::light_label;
use crate::problem::Problem;
use crate::solve::{Finding, FindingCode, Omission, OmissionReason, ReadingCode, Term};

/// "lights[1] (point)" for the light at a file index.
pub fn light_name<R: Real>(problem: &Problem<R>, file_index: usize) -> String {
    let info = problem
        .light_info
        .iter()
        .find(|i| i.file_index == file_index);
    let kind = info.map_or("light", |i| i.kind);
    match info.and_then(|i| i.name.as_deref()) {
        Some(name) => format!("{} \"{name}\"", light_label(file_index, kind)),
        None => light_label(file_index, kind),
    }
}

/// The sentence for a finding.
pub fn finding<R: Real>(problem: &Problem<R>, f: &Finding) -> String {
    let v = |k: &str| f.values.get(k).copied().map_or_else(String::new, num);
    let light = f.light.map(|i| light_name(problem, i)).unwrap_or_default();
    match f.code {
        FindingCode::HitBehindOrigin => format!(
            "the ray meets the surface only behind its origin, at t = {} (a hit needs t > 0): \
             as written, the ray hits nothing. The point where its line meets the surface is \
             shown below as a separate reading",
            v("t")
        ),
        FindingCode::NoIntersection => "the ray's line meets no surface: nothing to shade".into(),
        FindingCode::RayStartsOnSurface => "the ray starts on a surface (t = 0), which is not a \
             hit (a hit needs t > 0)"
            .into(),
        FindingCode::LightBehindSurface => format!(
            "{light} is on the back side of the surface: cos θ = −N·L = {} < 0, so it adds no \
             diffuse and no specular light",
            v("cos_theta")
        ),
        FindingCode::LightInTangentPlane => {
            format!("{light} lies in the surface's tangent plane (cos θ = 0): it adds nothing")
        }
        FindingCode::LightOutsideCone => format!(
            "the point is outside the cone of {light}: cos ψ = {} < cos γ = {} (ψ > γ), so \
             I_l = 0 (Eq. 4.4)",
            v("cos_psi"),
            v("cos_gamma")
        ),
        FindingCode::LightOnConeEdge => format!(
            "the point is exactly on the edge of the cone of {light} (ψ = γ): it counts as lit"
        ),
        FindingCode::ViewerBehindSurface => format!(
            "the viewer is on the back side of the surface (N·V = {} > 0): it sees the side the \
             normal points away from",
            v("n_dot_v")
        ),
        FindingCode::ViewerInTangentPlane => {
            "the viewer lies in the surface's tangent plane (N·V = 0)".into()
        }
        FindingCode::ViewerNotAtRayOrigin => "the viewer is not at the ray's origin: V is taken \
             from the viewer's position, as the problem states"
            .into(),
        FindingCode::NormalTurnedToFaceRay => "the surface's normal was reversed to face the \
             incoming ray (the ray hits the surface's back side)"
            .into(),
        FindingCode::NormalNormalized => format!(
            "the normal given has length {}, not 1: it is used normalised",
            v("length")
        ),
        FindingCode::DirectionNormalized => {
            let what = if light.is_empty() {
                "the ray's direction".to_owned()
            } else {
                format!("the direction of {light}")
            };
            format!(
                "{what} has length {}, not 1: it is used normalised",
                v("length")
            )
        }
        FindingCode::LiteralDiffers => "Eq. 4.16 applied literally (negative cosines included, \
             no gating) gives a different colour; both are shown"
            .into(),
        FindingCode::Clamped => {
            "the colour exceeds 1 in some channel: it is clamped to [0, 1] for display".into()
        }
    }
}

/// The sentence for a light's status.
pub fn light_status(s: LightStatus) -> &'static str {
    match s {
        LightStatus::Lit => "lit (cos θ > 0)",
        LightStatus::BehindSurface => "behind the surface (cos θ < 0): no diffuse, no specular",
        LightStatus::InTangentPlane => "in the tangent plane (cos θ = 0): no diffuse, no specular",
        LightStatus::OutsideCone => "outside the spot's cone (ψ > γ): I_l = 0",
        LightStatus::AtLight => "the point is at the light",
        LightStatus::InShadow => "in shadow",
    }
}

/// The sentence for a specular status.
pub fn specular_status(s: SpecularStatus) -> &'static str {
    match s {
        SpecularStatus::Lit => "cos φ > 0: the viewer sees the highlight",
        SpecularStatus::AwayFromViewer => "cos φ ≤ 0: R points away from the viewer, no specular",
        SpecularStatus::LightNotLit => "the light does not light the point: no specular",
        SpecularStatus::NoViewer => "no viewer: cos φ cannot be computed",
        SpecularStatus::NoSpecularColor => "the material has no specular colour O_s",
    }
}

/// The sentence for a term left out.
pub fn omission(o: &Omission) -> String {
    let term = match o.term {
        Term::Ambient => "ambient (Eq. 4.6)",
        Term::Diffuse => "diffuse (Eq. 4.8)",
        Term::Specular => "specular (Eq. 4.10)",
    };
    let why = match o.reason {
        OmissionReason::NoAmbientLight => "the problem gives no ambient light",
        OmissionReason::NoAmbientColor => "the material gives no ambient colour O_a",
        OmissionReason::NoDirectLight => "the problem gives no point, directional or spot light",
        OmissionReason::NoDiffuseColor => "the material gives no diffuse colour O_d",
        OmissionReason::NoViewer => "the problem gives no viewer, so V and cos φ are unknown",
        OmissionReason::NoSpecularColor => "the material gives no specular colour O_s",
    };
    format!("{term} left out: {why}")
}

/// The label of a reading.
pub fn reading_label(code: ReadingCode) -> &'static str {
    match code {
        ReadingCode::LightReversed => {
            "likely intended reading: L from the point to the light (the light mirrored to the front)"
        }
        ReadingCode::NormalReversed => "another reading: the normal reversed",
        ReadingCode::LineBehindOrigin => {
            "likely intended reading: the point where the ray's line meets the surface"
        }
    }
}

/// Why a reading is shown and what it assumes.
pub fn reading_explanation(code: ReadingCode) -> &'static str {
    match code {
        ReadingCode::LightReversed => {
            "as written, no light lights the surface and one is behind \
             it. Taking L = (P_l − P)/‖P_l − P‖, the opposite of Eq. 4.1 (a common slip, and the \
             convention of many textbooks), is the same as mirroring each light through P to the \
             front: light and viewer are then on the same side and every term of Eq. 4.16 is \
             used. Its colour is the negative of the literal Eq. 4.16 where n_s is odd. This is \
             not the problem as written"
        }
        ReadingCode::NormalReversed => {
            "the surface taken as lit from behind: reversing N makes \
             it face the light, which is what taking |cos θ| amounts to; the viewer is then on \
             the back side, so there is no specular term. This is not the problem as written"
        }
        ReadingCode::LineBehindOrigin => {
            "the hit at t < 0 is behind the ray's origin; it is \
             the hit of the ray with its direction reversed, so V = −D where no viewer is \
             given. This is not the problem as written"
        }
    }
}

/// "surfaces[2]", or "surfaces[2] (mesh), triangle 17".
pub fn surface_label(source: Option<crate::problem::SurfaceSource>) -> String {
    match source {
        None => "no surface".into(),
        Some(s) => match s.triangle {
            None => format!("surfaces[{}]", s.index),
            Some(t) => format!("surfaces[{}] (mesh), triangle {t}", s.index),
        },
    }
}
