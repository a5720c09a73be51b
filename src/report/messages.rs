//! The words of the reports, in English and in Portuguese: every sentence about a finding, a
//! status, an omission or a reading, and every phrase of the step-by-step explanation, is written
//! here, once, so that every format says the same thing.
//!
//! A missing translation does not compile: a fixed phrase is declared with [`phrases!`], whose
//! pattern takes exactly one English and one Portuguese text; a sentence with values is built
//! by [`pick`], which takes both. The JSON output is language-neutral and always uses the
//! English sentences.
//!
//! The Portuguese uses the chapter's own terms: luz ambiente, reflexão difusa, reflexão
//! especular, decaimento (linear, quadrático), fonte de luz, luz pontual, luz direcional, luz
//! spot, observador, normal, cone, eixo, geratriz, raio, interseção.

use super::lang::Lang;
use super::number::num;
use crate::core::{LightStatus, Real, SpecularStatus};
use crate::problem::validate::show;
use crate::problem::warnings::{Warning, WarningKind};
use crate::problem::Problem;
use crate::solve::{
    ConeEdge, Finding, FindingData, GateDecision, Omission, OmissionReason, ReadingCode, Side, Term,
};

/// Chooses the text of a language; both texts must be given.
pub fn pick<T>(lang: Lang, en: T, pt: T) -> T {
    match lang {
        Lang::En => en,
        Lang::Pt => pt,
    }
}

/// Declares the fixed phrases: `Name => "English", "Português";`. Leaving one language out is a
/// compile error (the macro's pattern does not match).
macro_rules! phrases {
    ($($(#[$doc:meta])* $name:ident => $en:literal, $pt:literal;)*) => {
        /// A fixed phrase of the explanations.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Phrase {
            $($(#[$doc])* $name,)*
        }

        impl Phrase {
            /// Every phrase, for tests.
            #[cfg(test)]
            pub const ALL: &'static [Phrase] = &[$(Phrase::$name,)*];

            /// The phrase in `lang`.
            pub fn get(self, lang: Lang) -> &'static str {
                match self {
                    $(Phrase::$name => pick(lang, $en, $pt),)*
                }
            }
        }
    };
}

phrases! {
    // Headings.
    Problem => "Problem", "Problema";
    Findings => "Findings", "Observações";
    Ray => "Ray", "Raio";
    AsWritten => "Solution (the problem as written)", "Solução (o problema como escrito)";
    ReadingHeading => "Reading: ", "Leitura: ";
    NothingToShade => "no point to shade: the ray hits nothing",
        "nenhum ponto a iluminar: o raio não atinge nada";
    Given => "Given", "Dados";
    Steps => "Steps", "Passos";
    Total => "Total", "Total";
    // The ray.
    Origin => "origin ", "origem ";
    Direction => "direction ", "direção ";
    Plane => "plane", "plano";
    Sphere => "sphere", "esfera";
    Hit => "hit (t > 0)", "interseção (t > 0)";
    NotAHit => "behind the origin (t ≤ 0): not a hit", "atrás da origem (t ≤ 0): não é interseção";
    LineMeetsNothing => "the ray's line meets no surface", "a reta do raio não encontra nenhuma superfície";
    // What is given.
    Viewer => "viewer ", "observador ";
    Material => "material", "material";
    Reversed => "reversed", "invertida";
    NormalisedFrom => "normalised from ", "normalizada de ";
    Length => "length ", "comprimento ";
    ThenReversed => ", then reversed", ", depois invertida";
    TakenEqualToOs => " (taken equal to O_s)", " (tomada igual a O_s)";
    // The viewer.
    RayFromEye => " (the ray comes from the eye)", " (o raio parte do olho)";
    ReversedRay => " (the reversed ray)", " (o raio invertido)";
    ViewerInFront => "the viewer is in front of the surface", "o observador está na frente da superfície";
    ViewerBehind => "the viewer is BEHIND the surface", "o observador está ATRÁS da superfície";
    ViewerInPlane => "the viewer is in the tangent plane", "o observador está no plano tangente";
    // Terms.
    Ambient => "ambient", "luz ambiente";
    Diffuse => "diffuse", "reflexão difusa";
    Specular => "specular", "reflexão especular";
    // A light.
    Light => "Light ", "Fonte de luz ";
    At => "at ", "em ";
    Axis => ", axis ", ", eixo ";
    NoFalloff => "; no falloff", "; sem decaimento";
    Falloff => "falloff ", "decaimento ";
    FalloffNone => "none", "sem decaimento";
    FalloffLinear => "linear", "linear";
    FalloffQuadratic => "quadratic", "quadrático";
    OnConeEdge => "on the edge (ψ = γ): lit", "na geratriz (ψ = γ): iluminado";
    InsideCone => "inside the cone (ψ < γ)", "dentro do cone (ψ < γ)";
    OutsideCone => "OUTSIDE the cone (ψ > γ)", "FORA do cone (ψ > γ)";
    Versus => " vs ", " vs ";
    SpotFactor => "spot factor ", "fator do spot ";
    Status => "status: ", "situação: ";
    Literally => "   [literally ", "   [literalmente ";
    LiterallyUndefined => "   [literally undefined: negative cos φ to a non-integer n_s]",
        "   [literalmente indefinido: cos φ negativo elevado a n_s não inteiro]";
    // The total.
    Colour => "colour: ", "cor: ";
    ClampedTo => " clamped to [0, 1]; 8-bit ", " limitada a [0, 1]; 8 bits ";
    LiteralTotal => "Eq. 4.16 taken literally (no gating): ",
        "Eq. 4.16 tomada literalmente (sem descartar termos): ";
    // Equation references.
    EqAbbrev => "Eq.", "Eq.";
    SecAbbrev => "Sec.", "Seç.";
    // The diagram.
    DiagramCaption => "The plane of incidence at P (the plane of N and L); the light and the viewer are drawn in the directions −L and −V.",
        "O plano de incidência em P (o plano de N e L); a fonte de luz e o observador estão nas direções −L e −V.";
    DiagramOf => "Diagram for ", "Diagrama para ";
    LightMark => "light", "fonte de luz";
    ViewerMark => "viewer", "observador";
    BackSide => "back side", "lado de trás";
    VProjected => "V is not in this plane: its projection is drawn.",
        "V não está neste plano: sua projeção é desenhada.";
    VOutOfPlane => "V is perpendicular to this plane and is not drawn.",
        "V é perpendicular a este plano e não é desenhado.";
    LAlongN => "L is along N: every plane through N is a plane of incidence; this one is chosen to hold V.",
        "L está na direção de N: todo plano que contém N é um plano de incidência; este foi escolhido para conter V.";
    Swatch => "the colour, clamped to [0, 1]", "a cor, limitada a [0, 1]";
}

/// The word for a light's kind, as the file names it ("point", "directional", "spot").
pub fn light_kind(kind: &str, lang: Lang) -> &str {
    match kind {
        "point" => pick(lang, "point", "pontual"),
        "directional" => pick(lang, "directional", "direcional"),
        "spot" => pick(lang, "spot", "spot"),
        "ambient" => pick(lang, "ambient", "ambiente"),
        "light" => pick(lang, "light", "luz"),
        other => other,
    }
}

/// The word for a surface kind ("plane", "sphere").
pub fn surface_kind(kind: &str, lang: Lang) -> &str {
    match kind {
        "plane" => Phrase::Plane.get(lang),
        "sphere" => Phrase::Sphere.get(lang),
        other => other,
    }
}

/// "lights[1] (point) \"key\"", or "lights[1] (pontual) \"key\"" in Portuguese.
pub fn light_name_in<R: Real>(problem: &Problem<R>, file_index: usize, lang: Lang) -> String {
    let info = problem
        .light_info
        .iter()
        .find(|i| i.file_index == file_index);
    let kind = light_kind(info.map_or("light", |i| i.kind), lang);
    let label = format!("lights[{file_index}] ({kind})");
    match info.and_then(|i| i.name.as_deref()) {
        Some(name) => format!("{label} \"{name}\""),
        None => label,
    }
}

/// The sentence for a finding, in English (as the JSON has it).
pub fn finding<R: Real>(problem: &Problem<R>, f: &Finding) -> String {
    finding_in(problem, f, Lang::En)
}

/// The sentence for a finding.
pub fn finding_in<R: Real>(problem: &Problem<R>, f: &Finding, lang: Lang) -> String {
    let p = R::NAME;
    let light = f
        .light
        .map(|i| light_name_in(problem, i, lang))
        .unwrap_or_default();
    match f.data {
        FindingData::HitBehindOrigin { t } => pick(
            lang,
            format!(
                "the ray meets the surface only behind its origin, at t = {} (a hit needs t > 0): \
                 as written, the ray hits nothing. The point where its line meets the surface is \
                 shown below as a separate reading",
                num(t)
            ),
            format!(
                "o raio encontra a superfície apenas atrás de sua origem, em t = {} (uma \
                 interseção exige t > 0): como escrito, o raio não atinge nada. O ponto onde a \
                 reta do raio encontra a superfície é mostrado abaixo como outra leitura",
                num(t)
            ),
        ),
        FindingData::NoIntersection => pick(
            lang,
            "the ray's line meets no surface: nothing to shade",
            "a reta do raio não encontra nenhuma superfície: nada a iluminar",
        )
        .into(),
        FindingData::RayStartsOnSurface => pick(
            lang,
            "the ray starts on a surface (t = 0), which is not a hit (a hit needs t > 0)",
            "o raio parte de uma superfície (t = 0), o que não é uma interseção (uma interseção \
             exige t > 0)",
        )
        .into(),
        FindingData::LightBehindSurface { cos_theta } => pick(
            lang,
            format!(
                "{light} is on the back side of the surface: cos θ = −N·L = {} < 0, so it adds \
                 no diffuse and no specular light",
                num(cos_theta)
            ),
            format!(
                "a fonte de luz {light} está do lado de trás da superfície: cos θ = −N·L = {} < \
                 0, logo não contribui com reflexão difusa nem com reflexão especular",
                num(cos_theta)
            ),
        ),
        FindingData::LightInTangentPlane => pick(
            lang,
            format!("{light} lies in the surface's tangent plane (cos θ = 0): it adds nothing"),
            format!(
                "a fonte de luz {light} está no plano tangente à superfície (cos θ = 0): não \
                 contribui com nada"
            ),
        ),
        FindingData::LightOutsideCone { cos_gamma, cos_psi } => pick(
            lang,
            format!(
                "the point is outside the cone of {light}: cos ψ = {} < cos γ = {} (ψ > γ), so \
                 I_l = 0 (Eq. 4.4)",
                num(cos_psi),
                num(cos_gamma)
            ),
            format!(
                "o ponto está fora do cone da fonte de luz {light}: cos ψ = {} < cos γ = {} \
                 (ψ > γ), logo I_l = 0 (Eq. 4.4)",
                num(cos_psi),
                num(cos_gamma)
            ),
        ),
        FindingData::LightOnConeEdge(ConeEdge {
            error_bound_deg, ..
        }) => pick(
            lang,
            format!(
                "the point is on the edge of the cone of {light} (ψ = γ to within the rounding \
                 of their computation in {p}, ±{}°): it counts as lit; exactly on the edge and \
                 a hair inside or outside cannot be told apart in this precision",
                num(error_bound_deg)
            ),
            format!(
                "o ponto está sobre uma geratriz do cone da fonte de luz {light} (ψ = γ a menos \
                 do arredondamento do seu cálculo em {p}, ±{}°): conta como iluminado; nesta \
                 precisão não se distingue se está exatamente sobre a geratriz ou ligeiramente \
                 dentro ou fora do cone",
                num(error_bound_deg)
            ),
        ),
        FindingData::GateUndecidable {
            cos_theta,
            decision,
            error_bound,
        } => {
            let (en, pt) = match decision {
                GateDecision::Lit => ("lit", "iluminando a superfície"),
                GateDecision::Behind => ("behind the surface", "atrás da superfície"),
                GateDecision::InTangentPlane => (
                    "0, in the tangent plane (no diffuse or specular term)",
                    "0, no plano tangente (sem reflexão difusa nem especular)",
                ),
            };
            let (fix_en, fix_pt) = if p == "f32" {
                (
                    "solve in f64 (--precision f64) or ",
                    "resolva em f64 (--precision f64) ou ",
                )
            } else {
                ("", "")
            };
            pick(
                lang,
                format!(
                    "cos θ = {} for {light} is within the rounding error of its own computation \
                     in {p} (±{}): whether the light is in front of the surface or behind it \
                     cannot be decided in this precision, and it is counted as {en}. The diffuse \
                     term changes by at most O_d·I_l·{} either way, but the specular term is all \
                     or nothing: {fix_en}move the light further from the tangent plane",
                    num(cos_theta),
                    num(error_bound),
                    num(error_bound)
                ),
                format!(
                    "cos θ = {} para a fonte de luz {light} está dentro do erro de \
                     arredondamento do seu próprio cálculo em {p} (±{}): nesta precisão não se \
                     pode decidir se a fonte de luz está na frente ou atrás da superfície, e ela \
                     conta como {pt}. A reflexão difusa muda no máximo O_d·I_l·{} de um modo ou \
                     de outro, mas a reflexão especular é tudo ou nada: {fix_pt}afaste a fonte \
                     de luz do plano tangente",
                    num(cos_theta),
                    num(error_bound),
                    num(error_bound)
                ),
            )
        }
        FindingData::ConeEdgeUndecidable(ConeEdge {
            error_bound_deg,
            gamma_deg,
            psi_deg,
        }) => {
            let inside = psi_deg <= gamma_deg;
            let (en, pt) = if inside {
                ("inside", "dentro")
            } else {
                ("outside", "fora")
            };
            pick(
                lang,
                format!(
                    "ψ = {}° and γ = {}° of {light} differ by less than the rounding error of the \
                     hit point and of their computation in {p} (±{}°): whether the point is \
                     inside or outside the cone cannot be decided in this precision, and it is \
                     taken as {en}",
                    num(psi_deg),
                    num(gamma_deg),
                    num(error_bound_deg)
                ),
                format!(
                    "ψ = {}° e γ = {}° da fonte de luz {light} diferem menos que o erro de \
                     arredondamento do ponto de interseção e do seu cálculo em {p} (±{}°): \
                     nesta precisão não se pode decidir se o ponto está dentro ou fora do cone, \
                     e ele é tomado como {pt}",
                    num(psi_deg),
                    num(gamma_deg),
                    num(error_bound_deg)
                ),
            )
        }
        FindingData::ViewerBehindSurface { n_dot_v } => pick(
            lang,
            format!(
                "the viewer is on the back side of the surface (N·V = {} > 0): it sees the side \
                 the normal points away from",
                num(n_dot_v)
            ),
            format!(
                "o observador está do lado de trás da superfície (N·V = {} > 0): vê o lado \
                 oposto ao da normal",
                num(n_dot_v)
            ),
        ),
        FindingData::ViewerInTangentPlane => pick(
            lang,
            "the viewer lies in the surface's tangent plane (N·V = 0)",
            "o observador está no plano tangente à superfície (N·V = 0)",
        )
        .into(),
        FindingData::ViewerNotAtRayOrigin => pick(
            lang,
            "the viewer is not at the ray's origin: V is taken from the viewer's position, as \
             the problem states",
            "o observador não está na origem do raio: V é tomado a partir da posição do \
             observador, como diz o problema",
        )
        .into(),
        FindingData::NormalTurnedToFaceRay => pick(
            lang,
            "the surface's normal was reversed to face the incoming ray (the ray hits the \
             surface's back side)",
            "a normal da superfície foi invertida para ficar voltada para o raio incidente (o \
             raio atinge o lado de trás da superfície)",
        )
        .into(),
        FindingData::NormalNormalized { length } => pick(
            lang,
            format!(
                "the normal given has length {}, not 1: it is used normalised",
                num(length)
            ),
            format!(
                "a normal dada tem comprimento {}, não 1: é usada normalizada",
                num(length)
            ),
        ),
        FindingData::DirectionNormalized { length } => {
            let what = match (light.is_empty(), lang) {
                (true, Lang::En) => "the ray's direction".to_owned(),
                (true, Lang::Pt) => "a direção do raio".to_owned(),
                (false, Lang::En) => format!("the direction of {light}"),
                (false, Lang::Pt) => format!("a direção da fonte de luz {light}"),
            };
            pick(
                lang,
                format!(
                    "{what} has length {}, not 1: it is used normalised",
                    num(length)
                ),
                format!(
                    "{what} tem comprimento {}, não 1: é usada normalizada",
                    num(length)
                ),
            )
        }
        FindingData::LiteralDiffers => pick(
            lang,
            "Eq. 4.16 applied literally (negative cosines included, no gating) gives a \
             different colour; both are shown",
            "a Eq. 4.16 aplicada literalmente (com os cossenos negativos, sem descartar termos) \
             dá outra cor; as duas são mostradas",
        )
        .into(),
        FindingData::Clamped => pick(
            lang,
            "the colour exceeds 1 in some channel: it is clamped to [0, 1] for display",
            "a cor excede 1 em algum canal: é limitada a [0, 1] para exibição",
        )
        .into(),
    }
}

/// The sentence for a light's status, in English (as the JSON has it).
pub fn light_status(s: LightStatus) -> &'static str {
    light_status_in(s, Lang::En)
}

/// The sentence for a light's status.
pub fn light_status_in(s: LightStatus, lang: Lang) -> &'static str {
    match s {
        LightStatus::Lit => pick(lang, "lit (cos θ > 0)", "iluminado (cos θ > 0)"),
        LightStatus::BehindSurface => pick(
            lang,
            "behind the surface (cos θ < 0): no diffuse, no specular",
            "atrás da superfície (cos θ < 0): sem reflexão difusa, sem reflexão especular",
        ),
        LightStatus::InTangentPlane => pick(
            lang,
            "in the tangent plane (cos θ = 0): no diffuse, no specular",
            "no plano tangente (cos θ = 0): sem reflexão difusa, sem reflexão especular",
        ),
        LightStatus::OutsideCone => pick(
            lang,
            "outside the spot's cone (ψ > γ): I_l = 0",
            "fora do cone do spot (ψ > γ): I_l = 0",
        ),
        LightStatus::AtLight => pick(
            lang,
            "the point is at the light",
            "o ponto está na posição da fonte de luz",
        ),
        LightStatus::InShadow => pick(lang, "in shadow", "na sombra"),
    }
}

/// The sentence for a specular status.
pub fn specular_status(s: SpecularStatus, lang: Lang) -> &'static str {
    match s {
        SpecularStatus::Lit => pick(
            lang,
            "cos φ > 0: the viewer sees the highlight",
            "cos φ > 0: o observador vê o brilho especular",
        ),
        SpecularStatus::AwayFromViewer => pick(
            lang,
            "cos φ ≤ 0: R points away from the viewer, no specular",
            "cos φ ≤ 0: R aponta para longe do observador, sem reflexão especular",
        ),
        SpecularStatus::LightNotLit => pick(
            lang,
            "the light does not light the point: no specular",
            "a fonte de luz não ilumina o ponto: sem reflexão especular",
        ),
        SpecularStatus::NoViewer => pick(
            lang,
            "no viewer: cos φ cannot be computed",
            "sem observador: cos φ não pode ser calculado",
        ),
        SpecularStatus::NoSpecularColor => pick(
            lang,
            "the material has no specular colour O_s",
            "o material não tem cor de reflexão especular O_s",
        ),
    }
}

/// Where the viewer is, for the step that computes N·V.
pub fn side(s: Side, lang: Lang) -> &'static str {
    match s {
        Side::Front => Phrase::ViewerInFront.get(lang),
        Side::Back => Phrase::ViewerBehind.get(lang),
        Side::InPlane => Phrase::ViewerInPlane.get(lang),
    }
}

/// The sentence for a term left out, in English (as the JSON has it).
pub fn omission(o: &Omission) -> String {
    omission_in(o, Lang::En)
}

/// The sentence for a term left out.
pub fn omission_in(o: &Omission, lang: Lang) -> String {
    let term = match o.term {
        Term::Ambient => pick(lang, "ambient (Eq. 4.6)", "luz ambiente (Eq. 4.6)"),
        Term::Diffuse => pick(lang, "diffuse (Eq. 4.8)", "reflexão difusa (Eq. 4.8)"),
        Term::Specular => pick(lang, "specular (Eq. 4.10)", "reflexão especular (Eq. 4.10)"),
    };
    let why = match o.reason {
        OmissionReason::NoAmbientLight => pick(
            lang,
            "the problem gives no ambient light",
            "o problema não dá luz ambiente",
        ),
        OmissionReason::NoAmbientColor => pick(
            lang,
            "the material gives no ambient colour O_a",
            "o material não dá a cor de reflexão difusa ambiente O_a",
        ),
        OmissionReason::NoDirectLight => pick(
            lang,
            "the problem gives no point, directional or spot light",
            "o problema não dá luz pontual, direcional ou spot",
        ),
        OmissionReason::NoDiffuseColor => pick(
            lang,
            "the material gives no diffuse colour O_d",
            "o material não dá a cor de reflexão difusa O_d",
        ),
        OmissionReason::NoViewer => pick(
            lang,
            "the problem gives no viewer, so V and cos φ are unknown",
            "o problema não dá observador, logo V e cos φ são desconhecidos",
        ),
        OmissionReason::NoSpecularColor => pick(
            lang,
            "the material gives no specular colour O_s",
            "o material não dá a cor de reflexão especular O_s",
        ),
    };
    pick(
        lang,
        format!("{term} left out: {why}"),
        format!("{term} omitida: {why}"),
    )
}

/// The label of a reading, in English (as the JSON has it).
pub fn reading_label(code: ReadingCode) -> &'static str {
    reading_label_in(code, Lang::En)
}

/// The label of a reading.
pub fn reading_label_in(code: ReadingCode, lang: Lang) -> &'static str {
    match code {
        ReadingCode::LightReversed => pick(
            lang,
            "likely intended reading: L from the point to the light (the light mirrored to the \
             front)",
            "leitura provavelmente pretendida: L do ponto para a fonte de luz (a fonte de luz \
             espelhada para a frente)",
        ),
        ReadingCode::NormalReversed => pick(
            lang,
            "another reading: the normal reversed",
            "outra leitura: a normal invertida",
        ),
        ReadingCode::LineBehindOrigin => pick(
            lang,
            "likely intended reading: the point where the ray's line meets the surface",
            "leitura provavelmente pretendida: o ponto onde a reta do raio encontra a superfície",
        ),
    }
}

/// Why a reading is shown and what it assumes, in English (as the JSON has it).
pub fn reading_explanation(code: ReadingCode) -> &'static str {
    reading_explanation_in(code, Lang::En)
}

/// Why a reading is shown and what it assumes.
pub fn reading_explanation_in(code: ReadingCode, lang: Lang) -> &'static str {
    match code {
        ReadingCode::LightReversed => pick(
            lang,
            "as written, no light lights the surface and one is behind \
             it. Taking L = (P_l − P)/‖P_l − P‖, the opposite of Eq. 4.1 (a common slip, and the \
             convention of many textbooks), is the same as mirroring each light through P to the \
             front: light and viewer are then on the same side and every term of Eq. 4.16 is \
             used. Its colour is the negative of the literal Eq. 4.16 where n_s is odd. This is \
             not the problem as written",
            "como escrito, nenhuma fonte de luz ilumina a superfície e uma está atrás dela. \
             Tomar L = (P_l − P)/‖P_l − P‖, o oposto da Eq. 4.1 (um deslize comum, e a convenção \
             de muitos livros), equivale a espelhar cada fonte de luz através de P para a \
             frente: fonte de luz e observador ficam então do mesmo lado e todos os termos da \
             Eq. 4.16 são usados. Sua cor é o negativo da Eq. 4.16 literal onde n_s é ímpar. \
             Este não é o problema como escrito",
        ),
        ReadingCode::NormalReversed => pick(
            lang,
            "the surface taken as lit from behind: reversing N makes \
             it face the light, which is what taking |cos θ| amounts to; the viewer is then on \
             the back side, so there is no specular term. This is not the problem as written",
            "a superfície tomada como iluminada por trás: inverter N a deixa voltada para a \
             fonte de luz, o que equivale a tomar |cos θ|; o observador fica então do lado de \
             trás, logo não há reflexão especular. Este não é o problema como escrito",
        ),
        ReadingCode::LineBehindOrigin => pick(
            lang,
            "the hit at t < 0 is behind the ray's origin; it is \
             the hit of the ray with its direction reversed, so V = −D where no viewer is \
             given. This is not the problem as written",
            "a interseção em t < 0 está atrás da origem do raio; é a interseção do raio com a \
             direção invertida, logo V = −D quando não é dado observador. Este não é o \
             problema como escrito",
        ),
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

/// Three numbers as the file writes them.
fn warning_triple(c: [f64; 3]) -> String {
    format!("[{}, {}, {}]", show(c[0]), show(c[1]), show(c[2]))
}

/// A colour divided by 255, rounded to 3 decimals, as the fix writes it.
fn over_255(c: [f64; 3]) -> String {
    let r = |x: f64| show((x / 255.0 * 1000.0).round() / 1000.0);
    format!("[{}, {}, {}]", r(c[0]), r(c[1]), r(c[2]))
}

/// A likely unit mistake in a problem file, with its fix, in `lang`.
pub fn warning(w: &Warning, lang: Lang) -> String {
    let f = &w.field;
    match (w.kind, lang) {
        (WarningKind::MaterialColor0To255 { given }, Lang::En) => format!(
            "{f}: {} looks like a 0–255 colour, but a material's colour is a fraction of the \
                 light it reflects, from 0 to 1. Fix: divide by 255: {}",
            warning_triple(given),
            over_255(given)
        ),
        (WarningKind::MaterialColor0To255 { given }, Lang::Pt) => format!(
            "{f}: {} parece uma cor de 0 a 255, mas a cor de um material é a fração da luz \
                 que ele reflete, de 0 a 1. Correção: divida por 255: {}",
            warning_triple(given),
            over_255(given)
        ),
        (WarningKind::LightColor0To255 { given }, Lang::En) => format!(
            "{f}: {} looks like a 0–255 colour, on a light that does not fall off with \
                 distance, so it lights the point {} times too brightly if it was meant on the \
                 0–1 scale. Fix: divide by 255: {} (a light brighter than 1 is fine with falloff)",
            warning_triple(given),
            show(255.0),
            over_255(given)
        ),
        (WarningKind::LightColor0To255 { given }, Lang::Pt) => format!(
            "{f}: {} parece uma cor de 0 a 255, numa luz sem decaimento com a distância: se \
                 era na escala de 0 a 1, ilumina o ponto {} vezes demais. Correção: divida por \
                 255: {} (uma luz acima de 1 é normal com decaimento)",
            warning_triple(given),
            show(255.0),
            over_255(given)
        ),
        (WarningKind::SpotAngleRadians { given }, Lang::En) => format!(
            "{f}: {} looks like an angle in radians ({}°), but the angle is read in degrees: \
                 this cone's half-angle is {}°. Fix: write the angle in degrees, {}",
            show(given),
            show((given.to_degrees() * 100.0).round() / 100.0),
            show(given),
            show((given.to_degrees() * 100.0).round() / 100.0)
        ),
        (WarningKind::SpotAngleRadians { given }, Lang::Pt) => format!(
            "{f}: {} parece um ângulo em radianos ({}°), mas o ângulo é lido em graus: o \
                 semiângulo deste cone é {}°. Correção: escreva o ângulo em graus, {}",
            show(given),
            show((given.to_degrees() * 100.0).round() / 100.0),
            show(given),
            show((given.to_degrees() * 100.0).round() / 100.0)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Phrases that are rightly the same word in both languages.
    const SAME_IN_BOTH: &[Phrase] = &[
        Phrase::Total,
        Phrase::Material,
        Phrase::FalloffLinear,
        Phrase::Versus,
        Phrase::EqAbbrev,
    ];

    #[test]
    fn every_phrase_exists_in_both_languages_and_is_translated() {
        for &p in Phrase::ALL {
            let (en, pt) = (p.get(Lang::En), p.get(Lang::Pt));
            assert!(!en.trim().is_empty(), "{p:?} has no English text");
            assert!(!pt.trim().is_empty(), "{p:?} has no Portuguese text");
            if !SAME_IN_BOTH.contains(&p) {
                assert_ne!(en, pt, "{p:?} is not translated");
            }
            // Leading and trailing spaces are part of the layout: they must agree.
            assert_eq!(
                en.starts_with(' '),
                pt.starts_with(' '),
                "{p:?}: leading space differs"
            );
            assert_eq!(
                en.ends_with(' '),
                pt.ends_with(' '),
                "{p:?}: trailing space differs"
            );
        }
    }

    #[test]
    fn portuguese_uses_the_chapters_terms() {
        let pt = |p: Phrase| p.get(Lang::Pt);
        assert_eq!(pt(Phrase::Ambient), "luz ambiente");
        assert_eq!(pt(Phrase::Diffuse), "reflexão difusa");
        assert_eq!(pt(Phrase::Specular), "reflexão especular");
        assert!(pt(Phrase::Falloff).starts_with("decaimento"));
        assert_eq!(pt(Phrase::FalloffQuadratic), "quadrático");
        assert!(pt(Phrase::Light).starts_with("Fonte de luz"));
        assert!(pt(Phrase::Viewer).starts_with("observador"));
        assert_eq!(light_kind("point", Lang::Pt), "pontual");
        assert_eq!(light_kind("directional", Lang::Pt), "direcional");
    }

    #[test]
    fn every_status_and_reading_has_a_distinct_portuguese_sentence() {
        let statuses = [
            LightStatus::Lit,
            LightStatus::BehindSurface,
            LightStatus::InTangentPlane,
            LightStatus::OutsideCone,
            LightStatus::AtLight,
            LightStatus::InShadow,
        ];
        for s in statuses {
            assert_ne!(light_status_in(s, Lang::En), light_status_in(s, Lang::Pt));
        }
        let readings = [
            ReadingCode::LightReversed,
            ReadingCode::NormalReversed,
            ReadingCode::LineBehindOrigin,
        ];
        for r in readings {
            assert_ne!(reading_label_in(r, Lang::En), reading_label_in(r, Lang::Pt));
            assert_ne!(
                reading_explanation_in(r, Lang::En),
                reading_explanation_in(r, Lang::Pt)
            );
        }
    }
}
