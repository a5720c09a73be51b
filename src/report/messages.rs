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

use crate::core::{LightStatus, Real, SpecularStatus};
use crate::problem::mesh::MAX_TRIANGLES;
use crate::problem::model::MAX_LIGHTS;

use crate::problem::Problem;
use crate::solve::{
    ConeEdge, F32Differs, FarFromOrigin, Finding, FindingData, Gate, GateDecision, Omission,
    OmissionReason, ReadingCode, Side, Term,
};
use crate::text::lang::Lang;
use crate::text::number::num;
use crate::text::{Message, Num, Show};

/// Chooses the text of a language; both texts must be given.
pub fn pick<T>(lang: Lang, en: T, pt: T) -> T {
    match lang {
        Lang::En => en,
        Lang::Pt => pt,
    }
}

/// That a ray problem's solution shows its secondary rays without tracing them (the JSON's
/// `secondary_rays.note`, and the explanation's last line on them).
pub(crate) const SECONDARY_NOT_TRACED: &str = "The solver shows these rays but does not trace \
     them (their colours C_r and C_t are not computed here): phong render traces them.";

/// [`SECONDARY_NOT_TRACED`] in Portuguese.
pub(crate) const SECONDARY_NOT_TRACED_PT: &str = "O solucionador mostra estes raios mas não os \
     traça (as suas cores C_r e C_t não são calculadas aqui): quem os traça é o phong render.";

/// Every fixed phrase of the explanations in `lang`, in the order declared: the catalogue a
/// translator reads, and the one `tests/portuguese.rs` checks outputs against.
pub fn catalogue(lang: Lang) -> Vec<&'static str> {
    Phrase::ALL.iter().map(|p| p.get(lang)).collect()
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
            /// Every phrase, in the order declared.
            pub(crate) const ALL: &'static [Phrase] = &[$(Phrase::$name,)*];

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
    NothingToShade => "no point to shade: the ray hits nothing",
        "nenhum ponto a iluminar: o raio não atinge nada";
    Given => "Given", "Dados";
    Steps => "Steps", "Passos";
    Total => "Total", "Total";
    SecondaryRays => "Secondary rays (Section 4.4)", "Raios secundários (Seção 4.4)";
    // The ray.
    Origin => "origin ", "origem ";
    Direction => "direction ", "direção ";
    Plane => "plane", "plano";
    Sphere => "sphere", "esfera";
    Triangle => "triangle", "triângulo";
    Mesh => "mesh", "malha";
    Hit => "hit (t > 0)", "interseção (t > 0)";
    NotAHit => "behind the origin (t ≤ 0): not a hit", "atrás da origem (t ≤ 0): não é interseção";
    LineMeetsNothing => "the ray's line meets no surface", "a reta do raio não encontra nenhuma superfície";
    LineLiesInPlane => "the ray lies in the plane: every point of it is on the surface, so there is no single hit point", "o raio está contido no plano: todos os seus pontos estão na superfície, então não há um único ponto de interseção";
    // What is given.
    Viewer => "viewer ", "observador ";
    Material => "material", "material";
    Reversed => "reversed", "invertida";
    NormalisedFrom => "normalised from ", "normalizada de ";
    Length => "length ", "comprimento ";
    ThenReversed => ", then reversed", ", depois invertida";
    /// A smooth triangle's shading normal (docs/conventions.md, "Smooth meshes").
    SmoothInterpolated => "interpolated from the triangle's three vertex normals with the \
        barycentric weights of ",
        "interpolada das normais dos três vértices do triângulo com os pesos baricêntricos de ";
    SmoothGeometric => "the triangle's geometric normal (from the order of its corners; it \
        decides which side the ray is on and where new rays leave from): ",
        "a normal geométrica do triângulo (dada pela ordem dos vértices; é ela que decide de que \
        lado o raio está e de onde partem os novos raios): ";
    SmoothClamped => "the interpolation does not point to the geometric normal's side of the \
        surface, so N is the geometric normal",
        "a interpolação não aponta para o lado da superfície em que está a normal geométrica, \
        então N é a normal geométrica";
    TakenEqualToOs => " (taken equal to O_s)", " (tomada igual a O_s)";
    // The viewer.
    RayIsLineOfSight => " (the ray's direction: the ray is the line of sight)", " (a direção do raio: o raio é a linha de visão)";
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
    /// The line under the colour of a problem solved in f32 (`solve::versus`).
    VersusF64 => "f32 − f64 of the colour: ", "f32 − f64 da cor: ";
    VersusF64Gives => " (f64 gives ", " (f64 dá ";
    VersusF64Tolerance => "); the check's tolerance: ", "); tolerância da verificação: ";
    // Equation references.
    EqAbbrev => "Eq.", "Eq.";
    SecAbbrev => "Sec.", "Seç.";
    // The diagram.
    DiagramCaption => "The plane of incidence at P (the plane of N and L); the light and the viewer are drawn in the directions −L and −V.",
        "O plano de incidência em P (o plano de N e L); a fonte de luz e o observador estão nas direções −L e −V.";
    DiagramOf => "Diagram for ", "Diagrama para ";
    LightMark => "light", "fonte de luz";
    ViewerMark => "viewer", "observador";
    RayOriginMark => "ray's origin O", "origem O do raio";
    BackSide => "back side", "lado de trás";
    VProjected => "V is not in this plane: its projection is drawn.",
        "V não está neste plano: sua projeção é desenhada.";
    VOutOfPlane => "V is perpendicular to this plane and is not drawn.",
        "V é perpendicular a este plano e não é desenhado.";
    LAlongN => "L is along N: every plane through N is a plane of incidence; this one is chosen to hold V.",
        "L está na direção de N: todo plano que contém N é um plano de incidência; este foi escolhido para conter V.";
    Swatch => "the colour, clamped to [0, 1]", "a cor, limitada a [0, 1]";
    // The statement's data and the answer key.
    AmbientLight => "Ambient light", "Luz ambiente";
    PointLight => "Point light", "Luz pontual";
    SpotLight => "Spot light", "Luz spot";
    DirectionalLight => "Directional light", "Luz direcional";
    ThePoint => "Point", "Ponto";
    NormalAt => "Normal at ", "Normal em ";
    TheViewer => "Viewer", "Observador";
    Surface => "Surface", "Superfície";
    Statements => "Statements", "Enunciados";
    Solutions => "Solutions", "Soluções";
    AnswerKey => "Answer key", "Gabarito";
    Quantity => "Given", "Dado";
    Value => "Value", "Valor";
    Answer => "Answer (as written)", "Resposta (como escrito)";
    NoHitAnswer => "no hit: the ray hits nothing", "nenhuma interseção: o raio não atinge nada";
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
        "triangle" => Phrase::Triangle.get(lang),
        "mesh" => Phrase::Mesh.get(lang),
        other => other,
    }
}

/// "lights[1] (point) “key”", or "lights[1] (pontual) “principal”" in Portuguese (the
/// light's `name_pt`, when it has one).
pub(crate) fn light_name_in<R: Real>(
    problem: &Problem<R>,
    file_index: usize,
    lang: Lang,
) -> String {
    light_label(problem, file_index, lang, false)
}

/// A light's label; `json` keeps the English name in straight quotes, as the JSON's sentences
/// have always had it.
fn light_label<R: Real>(problem: &Problem<R>, file_index: usize, lang: Lang, json: bool) -> String {
    // The lights are in file order: a binary search, not a scan (a scan per light made the
    // report of a problem with many lights quadratic).
    let info = problem
        .light_info
        .binary_search_by_key(&file_index, |i| i.file_index)
        .ok()
        .map(|k| &problem.light_info[k]);
    let kind = light_kind(info.map_or("light", |i| i.kind), lang);
    let label = format!("lights[{file_index}] ({kind})");
    let name = info.and_then(|i| match lang {
        Lang::Pt => i.name_pt.as_deref().or(i.name.as_deref()),
        Lang::En => i.name.as_deref(),
    });
    match name {
        Some(name) if json => format!("{label} \"{name}\""),
        Some(name) => format!("{label} {}", super::explain::quoted(name)),
        None => label,
    }
}

/// The sentence for a finding, in English (as the JSON has it).
pub fn finding<R: Real>(problem: &Problem<R>, f: &Finding) -> String {
    finding_with(problem, f, Lang::En, true)
}

/// The sentence for a finding.
pub fn finding_in<R: Real>(problem: &Problem<R>, f: &Finding, lang: Lang) -> String {
    finding_with(problem, f, lang, false)
}

fn finding_with<R: Real>(problem: &Problem<R>, f: &Finding, lang: Lang, json: bool) -> String {
    let p = R::NAME;
    let light = f
        .light
        .map(|i| light_label(problem, i, lang, json))
        .unwrap_or_default();
    match f.data.clone() {
        FindingData::F32DiffersFromF64(d) => f32_cost(&d, lang),
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
        FindingData::RayInPlane { surface } => pick(
            lang,
            format!(
                "the ray lies in the plane surfaces[{surface}] (N·D = 0 and N·(Q − O) = 0): \
                 every point of it is on the surface, so the problem has no single hit point \
                 and nothing is shaded"
            ),
            format!(
                "o raio está contido no plano surfaces[{surface}] (N·D = 0 e N·(Q − O) = 0): \
                 todos os seus pontos estão na superfície, então o problema não tem um único \
                 ponto de interseção, e nada é iluminado"
            ),
        ),
        FindingData::HitIllConditioned {
            n_dot_d,
            n_dot_d_error,
            t,
            t_error_bound,
            p_error_bound,
        } => {
            let relative = num(t_error_bound / t.abs());
            let p_bound = crate::text::number::vec3(p_error_bound);
            pick(
                lang,
                format!(
                    "the hit is ill-conditioned: the ray almost grazes the plane (N·D = {}, \
                     known only to ±{}), so t = {} is known only to ±{} (a relative error of \
                     {relative}) and P only to ±{p_bound}, counting the rounding of the numbers \
                     as written and of the computation in {p}. The answer is sensitive to the last digits \
                     of the data: changing the last digit of the ray's origin or direction, or \
                     of the plane, can move the hit point that much, and change the colour \
                     with it",
                    num(n_dot_d),
                    num(n_dot_d_error),
                    num(t),
                    num(t_error_bound)
                ),
                format!(
                    "a interseção é mal condicionada: o raio quase tangencia o plano (N·D = {}, \
                     conhecido apenas a menos de ±{}), então t = {} é conhecido apenas a menos \
                     de ±{} (erro relativo de até {relative}) e P apenas a menos de \
                     ±{p_bound}, levando em conta o arredondamento dos números como foram \
                     escritos e o do cálculo em {p}. \
                     A resposta é sensível aos últimos algarismos dos dados: mudar o último \
                     algarismo da origem ou da direção do raio, ou do plano, pode deslocar o \
                     ponto de interseção desse tanto e, com ele, mudar a cor",
                    num(n_dot_d),
                    num(n_dot_d_error),
                    num(t),
                    num(t_error_bound)
                ),
            )
        }
        FindingData::ParallelWithinRounding {
            n_dot_d,
            n_dot_d_error,
            may_lie_in_plane,
        } => {
            let (en, pt) = if may_lie_in_plane {
                (
                    ", or even lie in it (N·(Q − O) is within rounding of 0 too)",
                    ", ou até estar contido nele (N·(Q − O) também está dentro do \
                     arredondamento de 0)",
                )
            } else {
                ("", "")
            };
            pick(
                lang,
                format!(
                    "N·D = {} is within the rounding of its own computation in {p} (±{}): the \
                     ray may be parallel to the plane{en}, so whether it meets the plane, and \
                     where, depends on the last digits of the data; the hit shown cannot be \
                     trusted",
                    num(n_dot_d),
                    num(n_dot_d_error)
                ),
                format!(
                    "N·D = {} está dentro do arredondamento do seu próprio cálculo em {p} (±{}): \
                     o raio pode ser paralelo ao plano{pt}, então se ele encontra o plano, e \
                     onde, depende dos últimos algarismos dos dados; a interseção mostrada não \
                     é confiável",
                    num(n_dot_d),
                    num(n_dot_d_error)
                ),
            )
        }
        FindingData::HitFarFromOrigin(FarFromOrigin {
            point_error,
            direction_error,
        }) => pick(
            lang,
            format!(
                "the hit is far from the origin compared with its distance to the lights or the \
                 viewer: P itself may be off by up to {} in {p}, which would move L and V by up \
                 to {}, so the vectors from the lights and the viewer to P are computed as \
                 (O − P_l) + tD, from the numbers as given, keeping their digits",
                num(point_error),
                num(direction_error)
            ),
            format!(
                "o ponto de interseção está longe da origem em comparação com a sua distância às \
                 fontes de luz ou ao observador: o próprio P pode ter um erro de até {} em {p}, \
                 o que deslocaria L e V em até {}; por isso os vetores das fontes de luz e do \
                 observador até P são calculados como (O − P_l) + tD, a partir dos números \
                 dados, o que preserva os seus algarismos",
                num(point_error),
                num(direction_error)
            ),
        ),
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

crate::messages! {
    /// The parts of the finding `f32_differs_from_f64` (f32's answer is not f64's): what
    /// differs, why, and what answers it; [`f32_cost`] joins them.
    pub enum F32Cost {
        /// The lead: the precision the problem was solved in.
        InF32 => "in f32", "em f32";
        /// Two parts of what differs, joined.
        And => "and", "e";
        /// A channel of the colour differs by more than the check's tolerance.
        Differs { difference: Num, tolerance: Num } =>
            "the colour differs from f64's by {difference}, more than the check's tolerance \
             ({tolerance})",
            "a cor difere da cor em f64 em {difference}, mais que a tolerância da verificação \
             ({tolerance})";
        /// A gate goes the other way.
        Gate { gate: GateName } =>
            "{gate} goes the other way than in f64",
            "{gate} dá o resultado oposto ao de f64";
        /// A channel is 0 in one precision and not in the other.
        Zeroed =>
            "a channel of the colour is 0 where f64's is not, or the reverse",
            "um canal da cor é 0 onde o de f64 não é, ou o contrário";
        /// The number of the file that lost its digits when read.
        Read { field: String, given: Digits, read: Digits } =>
            "{field} = {given} in the file reads as {read} in f32, which loses the digits that \
             decide the answer",
            "{field} = {given} no arquivo é lido como {read} em f32, que perde os algarismos \
             que decidem a resposta";
        /// No number of the file did.
        Computed =>
            "no number of the file lost its digits when read in f32: f32's own range and \
             rounding in the computation did",
            "nenhum número do arquivo perdeu algarismos ao ser lido em f32: foram o alcance e o \
             arredondamento do próprio f32 no cálculo";
        /// What answers it.
        Fix => "--precision f64 answers it", "--precision f64 dá a resposta certa";
    }
}

crate::messages! {
    /// A gate of the model, as the finding `f32_differs_from_f64` names it.
    #[derive(Default)]
    pub enum GateName {
        /// cos θ > 0.
        #[default]
        CosTheta =>
            "the gate cos θ > 0 (which side of the surface a light is on)",
            "o teste cos θ > 0 (de que lado da superfície está a fonte de luz)";
        /// cos φ > 0.
        CosPhi =>
            "the gate cos φ > 0 (whether the reflection points towards the viewer)",
            "o teste cos φ > 0 (se a reflexão aponta para o observador)";
        /// ψ ≤ γ.
        Cone => "the spot light's cone test (ψ ≤ γ)", "o teste do cone da luz spot (ψ ≤ γ)";
        /// t > 0.
        Hit => "the ray's hit (t > 0)", "a interseção do raio (t > 0)";
        /// The shadow ray.
        Shadow => "the shadow test", "o teste de sombra";
    }
}

impl From<Gate> for GateName {
    fn from(g: Gate) -> GateName {
        match g {
            Gate::CosTheta => GateName::CosTheta,
            Gate::CosPhi => GateName::CosPhi,
            Gate::Cone => GateName::Cone,
            Gate::Hit => GateName::Hit,
            Gate::Shadow => GateName::Shadow,
        }
    }
}

/// A number of the file written with every digit it has (the shortest text that reads back
/// as the same f64), so that a number and its f32 reading can be told apart.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Digits(pub f64);

impl Show for Digits {
    fn show(&self, _: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.0.abs();
        if a != 0.0 && !(1e-4..1e7).contains(&a) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

/// The sentence of the finding `f32_differs_from_f64`.
fn f32_cost(d: &F32Differs, lang: Lang) -> String {
    let mut what = Vec::new();
    if let Some(g) = d.gate {
        what.push(F32Cost::Gate { gate: g.into() }.text(lang));
    }
    if let Some(x) = d.difference.filter(|&x| x > d.tolerance) {
        what.push(
            F32Cost::Differs {
                difference: Num(x),
                tolerance: Num(d.tolerance),
            }
            .text(lang),
        );
    }
    if d.zeroed && what.is_empty() {
        what.push(F32Cost::Zeroed.text(lang));
    }
    let cause = match (&d.input, d.given, d.read) {
        (Some(field), Some(given), Some(read)) => F32Cost::Read {
            field: field.clone(),
            given: Digits(given),
            read: Digits(read),
        },
        _ => F32Cost::Computed,
    };
    format!(
        "{}, {}: {}; {}",
        F32Cost::InF32.text(lang),
        what.join(&format!(" {} ", F32Cost::And.text(lang))),
        cause.text(lang),
        F32Cost::Fix.text(lang)
    )
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

/// Why a reading is shown, for a problem that gives a viewer or not: the line's hit keeps the
/// problem's viewer where it gives one, so its V is not −D then.
pub fn reading_explanation_given(code: ReadingCode, lang: Lang, viewer: bool) -> &'static str {
    match code {
        ReadingCode::LineBehindOrigin if viewer => pick(
            lang,
            "the hit at t < 0 is behind the ray's origin; it is the hit of the ray with its \
             direction reversed, shaded for the viewer the problem gives (V from the viewer to \
             the point). This is not the problem as written",
            "a interseção em t < 0 está atrás da origem do raio; é a interseção do raio com a \
             direção invertida, iluminada para o observador dado pelo problema (V do \
             observador para o ponto). Este não é o problema como escrito",
        ),
        _ => reading_explanation_in(code, lang),
    }
}

/// The Portuguese of the error messages' common parts, longest first where one contains
/// another: each English fragment is replaced by its Portuguese wherever it occurs. Field
/// names, file names and values are left as they are (a file's fields are its own words).
/// A fragment not listed stays English: extend the list as messages are added.
const ERRORS_PT: &[(&str, &str)] = &[
    // The frame of every message.
    (". Fix: ", ". Correção: "),
    // Flag values (cli/parse.rs), before the validation's phrases they share parts with.
    (
        "Correção: give a maximum level (1 = primary rays only) from 1 to ",
        "Correção: dê um nível máximo (1 = só os raios primários) de 1 a ",
    ),
    ("Correção: give samples per pixel from 1 to ", "Correção: dê as amostras por pixel de 1 a "),
    (
        "Correção: give the renders per setting from 1 to ",
        "Correção: dê as renderizações por configuração de 1 a ",
    ),
    ("Correção: give worker threads from 1 to ", "Correção: dê as threads de trabalho de 1 a "),
    (" is not a whole number", " não é um número inteiro"),
    (" is not a number ≥ 0", " não é um número ≥ 0"),
    (
        "write a decimal (0.05) or a fraction (1/255)",
        "escreva um decimal (0.05) ou uma fração (1/255)",
    ),
    (
        "give a number ≥ 0 (e.g. 0.005 on the 0–1 scale)",
        "dê um número ≥ 0 (por exemplo 0.005 na escala 0–1)",
    ),
    (
        " is not a tolerance. Correção: give the largest difference accepted per channel, a number ≥ 0 (e.g. 0.005 on the 0–1 scale, 1 on the 255 scale)",
        " não é uma tolerância. Correção: dê a maior diferença aceita por canal, um número ≥ 0 (por exemplo 0.005 na escala 0–1, 1 na escala 255)",
    ),
    (" is not a separator: give , or ; or tab", " não é um separador: dê , ou ; ou tab"),
    (
        " is not a size; write WIDTHxHEIGHT, each 1 to ",
        " não é um tamanho; escreva LARGURAxALTURA, cada um de 1 a ",
    ),
    (" (e.g. 320x240)", " (por exemplo 320x240)"),
    (
        " is not X,Y (two whole numbers and a comma, e.g. 320,240)",
        " não é X,Y (dois números inteiros e uma vírgula, por exemplo 320,240)",
    ),
    (
        " is not a pixel coordinate (a whole number ≥ 0)",
        " não é uma coordenada de pixel (um número inteiro ≥ 0)",
    ),
    // `phong grade` (check/grade.rs, check/moodle.rs, check/rubric.rs, cli/commands/grade.rs):
    // its rows' reasons (in the feedback) and its own errors, before the general phrases.
    ("the row cannot be read as CSV: field ", "a linha não pode ser lida como CSV: o campo "),
    (" opens a quote \" that is not closed on its line (a row is one line)", " abre aspas \" que não se fecham na sua linha (cada linha é uma resposta)"),
    (" has text after its closing quote (\"", " tem texto depois das aspas que o fecham (\""),
    ("\"): quote the whole field, with \"\" for a quote inside", "\"): ponha o campo inteiro entre aspas, com \"\" para aspas dentro"),
    ("the row has ", "a linha tem "),
    (" fields, expected 3 (student, exercise, answer)", " campos, e são esperados 3 (aluno, exercício, resposta)"),
    (" field, expected 3 (student, exercise, answer)", " campo, e são esperados 3 (aluno, exercício, resposta)"),
    (" fields, expected 4 (student, exercise, answer, steps)", " campos, e são esperados 4 (aluno, exercício, resposta, passos)"),
    (" field, expected 4 (student, exercise, answer, steps)", " campo, e são esperados 4 (aluno, exercício, resposta, passos)"),
    ("; the fields are read as separated by ", "; os campos são lidos como separados por "),
    (", and this row has ", ", e esta linha tem "),
    (": give --delimiter ", ": dê --delimiter "),
    ("a tab character", "uma tabulação"),
    ("; an answer or a steps cell written with ", "; uma resposta ou uma célula de passos escrita com "),
    ("; an answer written with ", "; uma resposta escrita com "),
    (" must be quoted: ", " deve vir entre aspas: "),
    ("the student field is not valid UTF-8", "o campo do aluno não é UTF-8 válido"),
    ("the student field holds a NUL byte", "o campo do aluno tem um byte NUL"),
    ("the student field is empty", "o campo do aluno está vazio"),
    ("the exercise field is not valid UTF-8", "o campo do exercício não é UTF-8 válido"),
    ("the exercise field holds a NUL byte", "o campo do exercício tem um byte NUL"),
    ("the exercise field is empty", "o campo do exercício está vazio"),
    ("the answer field is not valid UTF-8", "o campo da resposta não é UTF-8 válido"),
    ("the answer field holds a NUL byte", "o campo da resposta tem um byte NUL"),
    ("the answer field is empty", "o campo da resposta está vazio"),
    ("the steps field is not valid UTF-8", "o campo dos passos não é UTF-8 válido"),
    ("the steps field holds a NUL byte", "o campo dos passos tem um byte NUL"),
    (" (shown as U+FFFD): is the file UTF-16 without a byte order mark? Save it as UTF-8 (CSV UTF-8 in a spreadsheet)", " (mostrado como U+FFFD): o arquivo é UTF-16 sem marca de ordem de bytes? Salve-o como UTF-8 (CSV UTF-8 numa planilha)"),
    ("unknown exercise: there is no ", "exercício desconhecido: não há "),
    (" in the exercises folder ", " na pasta de exercícios "),
    (". Correção: name an exercise by its file name without .json (e.g. 4.2 for ", ". Correção: dê o nome do arquivo do exercício sem .json (por exemplo 4.2 para "),
    (": the exercise file cannot be followed: ", ": o arquivo do exercício não pode ser seguido: "),
    (". Correção: replace the link by the file", ". Correção: troque o link pelo arquivo"),
    (": the exercise file is a link out of the exercises folder (to ", ": o arquivo do exercício é um link para fora da pasta de exercícios (para "),
    ("), which is refused. Correção: copy the file into ", "), o que é recusado. Correção: copie o arquivo para "),
    (": the exercise is not a regular file (a folder, a FIFO or a device). Correção: put the exercise's problem file there", ": o exercício não é um arquivo comum (uma pasta, um FIFO ou um dispositivo). Correção: ponha ali o arquivo de problema do exercício"),
    ("the answer cannot be read: ", "a resposta não pode ser lida: "),
    ("the Moodle export's header cannot be read: line ", "o cabeçalho da exportação do Moodle não pode ser lido: a linha "),
    ("the Moodle export's header cannot be read: ", "o cabeçalho da exportação do Moodle não pode ser lido: "),
    ("the Moodle export cannot be read: line ", "a exportação do Moodle não pode ser lida: a linha "),
    ("the Moodle export cannot be read: ", "a exportação do Moodle não pode ser lida: "),
    (" is not UTF-8 text. Correção: save the export as UTF-8 (CSV UTF-8)", " não é texto UTF-8. Correção: salve a exportação como UTF-8 (CSV UTF-8)"),
    ("the Moodle export has no \"Response 1\" column. Correção: download the quiz's Responses report as CSV, or give --input csv for a plain CSV", "a exportação do Moodle não tem a coluna \"Response 1\". Correção: baixe o relatório \"Responses\" do questionário como CSV, ou dê --input csv para um CSV simples"),
    ("the Moodle export has a \"Response ", "a exportação do Moodle tem uma coluna \"Response "),
    ("\" column but only ", "\", mas só "),
    (" exercise is given: name one per question slot with --questions", " exercício é dado: dê um por pergunta com --questions"),
    (" exercises are given: name one per question slot with --questions", " exercícios são dados: dê um por pergunta com --questions"),
    ("the steps of row ", "os passos da resposta "),
    (" (line ", " (linha "),
    (", column \"", ", coluna \""),
    ("write each step as its name, = and its value, separated by ;, ", "escreva cada passo como seu nome, = e seu valor, separados por ;, "),
    (": a value runs into the next step's name", ": um valor emenda no nome do passo seguinte"),
    ("separate the steps with ;, ", "separe os passos com ;, "),
    ("the header names the student column twice", "o cabeçalho nomeia duas vezes a coluna do aluno"),
    ("the header names the exercise column twice", "o cabeçalho nomeia duas vezes a coluna do exercício"),
    ("the header names the answer column twice", "o cabeçalho nomeia duas vezes a coluna da resposta"),
    ("the header names the steps column twice", "o cabeçalho nomeia duas vezes a coluna dos passos"),
    ("the header names no student column", "o cabeçalho não tem a coluna do aluno"),
    ("the header names no exercise column", "o cabeçalho não tem a coluna do exercício"),
    ("the header names no answer column", "o cabeçalho não tem a coluna da resposta"),
    ("Correção: name the columns `student` (or `aluno`), `exercise` (`exercício`) and `answer` (`resposta`), and, if the rows give steps, `steps` (`passos`), each once, in any order", "Correção: nomeie as colunas `aluno` (ou `student`), `exercício` (`exercise`) e `resposta` (`answer`) e, se as linhas dão passos, `passos` (`steps`), cada uma uma vez, em qualquer ordem"),
    ("give the folder that holds the exercise files (exercise 4.2 is DIR/4.2.json)", "dê a pasta que tem os arquivos dos exercícios (o exercício 4.2 é DIR/4.2.json)"),
    ("give a rubric file as the README's Grading section shows", "dê um arquivo de rubrica como mostra a seção \"Grading\" do README"),
    (" (a rubric is ", " (uma rubrica é "),
    (", every field optional)", ", todos os campos opcionais)"),
    ("the points of an exercise the rubric does not name", "os pontos de um exercício que a rubrica não nomeia"),
    ("the points of ", "os pontos de "),
    (") must be a number 0 or more", ") devem ser um número 0 ou mais"),
    (" is not EXERCISE=POINTS", " não é EXERCÍCIO=PONTOS"),
    (": the points are not a number", ": os pontos não são um número"),
    ("write --points 4.1=1,4.2=2", "escreva --points 4.1=1,4.2=2"),
    ("the reading credit is ", "o crédito da leitura é "),
    (": it is a share of the points, 0 to 1 (0.5 for half)", ": é uma fração dos pontos, de 0 a 1 (0.5 para metade)"),
    ("give a share from 0 to 1 (0.5 for half the points)", "dê uma fração de 0 a 1 (0.5 para metade dos pontos)"),
    ("it has more than ", "tem mais de "),
    (" rows, the most phong takes", " linhas, o máximo que phong aceita"),
    (" MiB, the most phong reads for a submissions file", " MiB, o máximo que phong lê de um arquivo de respostas"),
    (" MiB, the most phong reads for a rubric file", " MiB, o máximo que phong lê de um arquivo de rubrica"),
    ("File exists (os error 17)", "o arquivo já existe (erro 17 do sistema)"),
    ("Not a directory (os error 20)", "não é uma pasta (erro 20 do sistema)"),
    // The rarer validation messages (problem/validate.rs), whole phrases before their parts.
    // A light's or a surface's kind, after its label.
    ("] (point)", "] (pontual)"),
    ("] (directional)", "] (direcional)"),
    ("] (ambient)", "] (ambiente)"),
    // Point or ray.
    (
        "the problem gives both \"point\" and \"ray\"",
        "o problema dá \"point\" e \"ray\" ao mesmo tempo",
    ),
    (
        "give either a point (with its normal) or a ray with surfaces, not both",
        "dê um ponto (com sua normal) ou um raio com superfícies, não os dois",
    ),
    (
        "a scene needs at least one surface for its rays to hit",
        "uma cena precisa de pelo menos uma superfície para seus raios atingirem",
    ),
    (
        "a scene needs surfaces for its rays to hit (this is a point problem)",
        "uma cena precisa de superfícies para seus raios atingirem (este é um problema de ponto)",
    ),
    (
        "add \"surfaces\" and a \"camera\", or solve it with `phong solve`",
        "acrescente \"surfaces\" e uma \"camera\", ou resolva-o com `phong solve`",
    ),
    (
        "add \"surfaces\": [{\"type\": \"sphere\", ...}], a plane, a triangle or a mesh",
        "acrescente \"surfaces\": [{\"type\": \"sphere\", ...}], um plano, um triângulo ou uma malha",
    ),
    (
        "a ray problem needs at least one surface for the ray to hit",
        "um problema de raio precisa de pelo menos uma superfície para o raio atingir",
    ),
    (
        "add \"surfaces\": [{\"type\": \"plane\", ...}] or a sphere",
        "acrescente \"surfaces\": [{\"type\": \"plane\", ...}] ou uma esfera",
    ),
    (
        "surfaces are only used by a ray problem, and this problem gives a point",
        "as superfícies só são usadas num problema de raio, e este problema dá um ponto",
    ),
    (
        "remove \"surfaces\", or replace \"point\" with a \"ray\"",
        "remova \"surfaces\", ou troque \"point\" por um \"ray\"",
    ),
    (" needs P for L and d (Eq. 4.1)", " precisa de P para L e d (Eq. 4.1)"),
    (
        "the viewer needs P for V = (P − E)/‖P − E‖",
        "o observador precisa de P para V = (P − E)/‖P − E‖",
    ),
    (" needs N for cos θ = −N·L (Eq. 4.7)", " precisa de N para cos θ = −N·L (Eq. 4.7)"),
    (", or remove \"viewer\"", ", ou remova \"viewer\""),
    (" to \"point\"", " a \"point\""),
    // The camera.
    (
        "the camera looks at its own eye: no line of sight",
        "a câmera olha para o próprio olho: não há linha de visada",
    ),
    ("give a look_at point different from eye", "dê um ponto `look_at` diferente de `eye`"),
    (
        "up is zero or along the line of sight, so the image has no up direction",
        "`up` é nulo ou está na linha de visada, e a imagem fica sem direção para cima",
    ),
    (
        "give an up vector not parallel to look_at − eye, such as [0, 1, 0] or [0, 0, 1]",
        "dê um vetor `up` não paralelo a `look_at` − `eye`, como [0, 1, 0] ou [0, 0, 1]",
    ),
    (" degrees is not a field of view", " graus não é um campo de visão"),
    (
        "give the vertical field of view in degrees, 0 < fov < 180 (e.g. 45)",
        "dê o campo de visão vertical em graus, 0 < fov < 180 (por exemplo 45)",
    ),
    (" degrees is too small for ", " graus é pequeno demais para "),
    (" degrees is too close to 180 for ", " graus é próximo demais de 180 para "),
    (
        "give a larger field of view, or use --precision f64",
        "dê um campo de visão maior, ou use --precision f64",
    ),
    (
        "give a field of view of at most 179 degrees, or use --precision f64",
        "dê um campo de visão de no máximo 179 graus, ou use --precision f64",
    ),
    (" pixels is outside 1 to ", " pixels está fora de 1 a "),
    ("give the image width in pixels, 1 to ", "dê a largura da imagem em pixels, de 1 a "),
    ("give the image height in pixels, 1 to ", "dê a altura da imagem em pixels, de 1 a "),
    // The tracer's settings.
    (
        "0 traces nothing: the primary ray already has level 1",
        "0 não traça nada: o raio primário já tem nível 1",
    ),
    ("give a maximum level from 1 to ", "dê um nível máximo de 1 a "),
    (" (1 = primary rays only)", " (1 = só os raios primários)"),
    (
        " reflections a path cannot change an 8-bit pixel unless its surfaces reflect more than 99%",
        " reflexões um caminho não muda um pixel de 8 bits, a menos que suas superfícies reflitam mais de 99%",
    ),
    (": past ", ": depois de "),
    (" samples per pixel is outside 1 to ", " amostras por pixel está fora de 1 a "),
    (" is outside 1 to ", " está fora de 1 a "),
    (" samples is ", " amostras são "),
    (" primary rays, more than the ", " raios primários, mais que os "),
    (
        " (2^30) a render may trace (hours of work)",
        " (2^30) que uma renderização pode traçar (horas de trabalho)",
    ),
    (
        " samples per pixel at this size, or a smaller image",
        " amostras por pixel neste tamanho, ou uma imagem menor",
    ),
    (
        "give a smaller image (--size, or the camera's width and height)",
        "dê uma imagem menor (--size, ou a largura e a altura da câmera)",
    ),
    ("give a smaller image", "dê uma imagem menor"),
    ("give 1 to ", "dê de 1 a "),
    (" samples per pixel", " amostras por pixel"),
    (" is not a weight", " não é um peso"),
    (
        "give a minimum weight ≥ 0 (0 traces every reflection up to the maximum level)",
        "dê um peso mínimo ≥ 0 (0 traça todas as reflexões até o nível máximo)",
    ),
    // Surfaces and meshes.
    ("the scene has more than ", "a cena tem mais de "),
    (
        " surfaces (a mesh's triangles each count)",
        " superfícies (cada triângulo de uma malha conta)",
    ),
    (
        "give at most 1,000,000 surfaces and triangles in all",
        "dê no máximo 1,000,000 superfícies e triângulos ao todo",
    ),
    ("give at most ", "dê no máximo "),
    ("give a smaller mesh, or free memory", "dê uma malha menor, ou libere memória"),
    ("out of memory: this needs about ", "memória insuficiente: isto precisa de cerca de "),
    // The material's terms.
    (
        "the ambient term O_a I_a (Eq. 4.6) needs it, since the problem has an ambient light",
        "o termo de luz ambiente O_a I_a (Eq. 4.6) precisa dele, pois o problema tem uma luz ambiente",
    ),
    (
        "; [0, 0, 0] if the surface reflects no ambient light",
        "; [0, 0, 0] se a superfície não reflete luz ambiente",
    ),
    (
        "the diffuse term O_d I_l cos θ (Eq. 4.8) of ",
        "o termo de reflexão difusa O_d I_l cos θ (Eq. 4.8) de ",
    ),
    ("; [0, 0, 0] for no diffuse reflection", "; [0, 0, 0] para nenhuma reflexão difusa"),
    (
        "the specular term O_s I_l (cos φ)^n_s (Eq. 4.10) of ",
        "o termo de reflexão especular O_s I_l (cos φ)^n_s (Eq. 4.10) de ",
    ),
    (
        " needs it, since the problem has a viewer",
        " precisa dele, pois o problema tem um observador",
    ),
    (" needs it", " precisa dele"),
    ("; [0, 0, 0] for a matte surface", "; [0, 0, 0] para uma superfície fosca"),
    ("the specular term (Eq. 4.10) of ", "o termo de reflexão especular (Eq. 4.10) de "),
    (" needs the exponent n_s", " precisa do expoente n_s"),
    ("add \"shininess\": n_s (a number ≥ 0)", "acrescente \"shininess\": n_s (um número ≥ 0)"),
    (" (or {\"k\": k", " (ou {\"k\": k"),
    // Lights.
    (" lights are more than the ", " fontes de luz são mais que as "),
    (" a problem may have", " que um problema pode ter"),
    ("° is outside [0°, 90°]", "° está fora de [0°, 90°]"),
    (
        "γ is the angle between the cone's axis and its side, 0 ≤ γ ≤ 90 degrees (Eq. 4.4)",
        "γ é o ângulo entre o eixo do cone e sua geratriz, 0 ≤ γ ≤ 90 graus (Eq. 4.4)",
    ),
    (
        "the spot exponent e of cos(ψ)^e (Eq. 4.4) must be ≥ 0, e.g. 0, 1 or 2",
        "o expoente e do spot em cos(ψ)^e (Eq. 4.4) deve ser ≥ 0, por exemplo 0, 1 ou 2",
    ),
    (" is negative", " é negativo"),
    (" is not a falloff exponent", " não é um expoente de decaimento"),
    (
        "use 0 (no falloff), 1 (linear) or 2 (quadratic), Eq. 4.3",
        "use 0 (sem decaimento), 1 (linear) ou 2 (quadrático), Eq. 4.3",
    ),
    // A field the light's or surface's type does not take, or needs.
    ("remove it; a point light takes ", "remova-o; uma luz pontual aceita "),
    ("remove it; a spot light takes ", "remova-o; uma luz spot aceita "),
    ("remove it; a directional light takes ", "remova-o; uma luz direcional aceita "),
    ("remove it; an ambient light takes ", "remova-o; uma luz ambiente aceita "),
    ("remove it; a ambient light takes ", "remova-o; uma luz ambiente aceita "),
    ("remove it; a plane takes ", "remova-o; um plano aceita "),
    ("remove it; a sphere takes ", "remova-o; uma esfera aceita "),
    ("remove it; a triangle takes ", "remova-o; um triângulo aceita "),
    ("remove it; a mesh takes ", "remova-o; uma malha aceita "),
    ("a point light has no ", "uma luz pontual não tem "),
    ("a spot light has no ", "uma luz spot não tem "),
    ("a directional light has no ", "uma luz direcional não tem "),
    ("a ambient light has no ", "uma luz ambiente não tem "),
    ("a ambient light needs ", "uma luz ambiente precisa de "),
    ("a plane has no ", "um plano não tem "),
    ("a sphere has no ", "uma esfera não tem "),
    ("a triangle has no ", "um triângulo não tem "),
    ("a mesh has no ", "uma malha não tem "),
    ("a plane needs ", "um plano precisa de "),
    ("a sphere needs ", "uma esfera precisa de "),
    ("a triangle needs ", "um triângulo precisa de "),
    ("a mesh needs ", "uma malha precisa de "),
    // Spheres and triangles.
    (": it rounds to 0", ": é arredondado para 0"),
    (" is too small for ", " é pequeno demais para "),
    ("use --precision f64, or scale the problem", "use --precision f64, ou mude a escala do problema"),
    (" is not a radius", " não é um raio"),
    ("give the sphere a radius > 0", "dê à esfera um raio > 0"),
    ("the triangle is degenerate in ", "o triângulo é degenerado em "),
    (
        ": its corners lie on one line, so it has no area and no normal",
        ": seus vértices estão numa reta, e ele não tem área nem normal",
    ),
    ("give three corners that are not on one line", "dê três vértices que não estejam numa reta"),
    // Materials.
    ("there is no material named ", "não há material chamado "),
    (
        "define it under \"materials\", or write the material in place",
        "defina-o em \"materials\", ou escreva o material no lugar",
    ),
    (", or define it under \"materials\"", ", ou defina-o em \"materials\""),
    ("use one of ", "use um de "),
    (
        "the specular exponent n_s (Eq. 4.9) must be ≥ 0",
        "o expoente especular n_s (Eq. 4.9) deve ser ≥ 0",
    ),
    (
        "is \"specular\" but the material has no specular colour",
        "é \"specular\", mas o material não tem cor especular",
    ),
    (
        "give \"specular\", or give the reflectivity as [r, g, b]",
        "dê \"specular\", ou dê a refletividade como [r, g, b]",
    ),
    (" is outside [0, 1]", " está fora de [0, 1]"),
    (
        "the chapter's coefficients k_a, k_d, k_s lie in [0, 1] (Eq. 4.5, 4.7, 4.9); give the product as one colour [r, g, b] if you mean something else",
        "os coeficientes k_a, k_d, k_s do capítulo estão em [0, 1] (Eq. 4.5, 4.7, 4.9); dê o produto como uma só cor [r, g, b] se quer outra coisa",
    ),
    ("a material colour has a negative component", "uma cor de material tem um componente negativo"),
    // Numbers and directions.
    (" is not a finite f64 number", " não é um número finito em f64"),
    (" is not a finite f32 number", " não é um número finito em f32"),
    (
        "use a number within ±3.4e38, or --precision f64",
        "use um número dentro de ±3.4e38, ou --precision f64",
    ),
    ("use a finite number", "use um número finito"),
    ("the normal N ", "a normal N "),
    ("the ray's direction ", "a direção do raio "),
    ("the light's direction D_l ", "a direção D_l da fonte de luz "),
    ("the cone's axis D_l ", "o eixo D_l do cone "),
    ("the plane's normal ", "a normal do plano "),
    (" is too long for ", " tem comprimento grande demais para "),
    (": its length overflows", ": seu comprimento estoura"),
    (
        "give a shorter vector in the same direction (only the direction is used)",
        "dê um vetor mais curto na mesma direção (só a direção é usada)",
    ),
    (" is the zero vector (in ", " é o vetor nulo (em "),
    ("), which has no direction", "), que não tem direção"),
    ("give a non-zero vector", "dê um vetor não nulo"),
    // Reading and parsing (problem/mod.rs).
    ("invalid number", "número inválido"),
    ("key must be a string", "a chave deve ser um texto"),
    // The parser's types (serde's words), and the fix of a word where a number belongs.
    (", expected f64", ", esperado um número"),
    (", expected u32", ", esperado um número inteiro"),
    (", expected u8", ", esperado um número inteiro"),
    (", expected a number", ", esperado um número"),
    (" for \"", " para \""),
    (
        "save the file as UTF-8 (JSON is UTF-8 text); the byte may come from another encoding, such as Latin-1, or from a file that is not a problem file",
        "salve o arquivo como UTF-8 (JSON é texto UTF-8); o byte pode vir de outra codificação, como Latin-1, ou de um arquivo que não é um arquivo de problema",
    ),
    ("it is larger than ", "é maior que "),
    (" MiB, the most phong reads for a problem file", " MiB, o máximo que phong lê de um arquivo de problema"),
    (" MiB, the most phong reads for a mesh", " MiB, o máximo que phong lê de uma malha"),
    (
        "give a smaller file (the limits are in README, \"Limits and safety\")",
        "dê um arquivo menor (os limites estão no README, \"Limits and safety\")",
    ),
    (" is not UTF-8 text", " não é texto UTF-8"),
    (
        "too many elements: expected an array of length 3",
        "elementos demais: esperada uma lista de comprimento 3",
    ),
    (
        "give exactly three numbers [x, y, z] (a triangle: three vertices)",
        "dê exatamente três números [x, y, z] (um triângulo: três vértices)",
    ),
    (": every number must be finite, such as 0 or 1e300", ": todo número deve ser finito, como 0 ou 1e300"),
    ("JSON has no ", "JSON não tem "),
    (", and a problem file is one JSON object { … }", ", e um arquivo de problema é um objeto JSON { … }"),
    ("the file is an array [ … ]", "o arquivo é uma lista [ … ]"),
    ("the file is a string", "o arquivo é um texto"),
    ("the file is a number", "o arquivo é um número"),
    ("the file is a boolean", "o arquivo é um booleano"),
    ("the file is null", "o arquivo é null"),
    (
        "write the problem's fields in one object, ",
        "escreva os campos do problema num só objeto, ",
    ),
    (
        "; several problems go in several files (`phong schema` lists every field)",
        "; vários problemas vão em vários arquivos (`phong schema` lista todos os campos)",
    ),
    (
        "the falloff is the exponent f of d^f, a number: write ",
        "o decaimento é o expoente f de d^f, um número: escreva ",
    ),
    (" (0 none, 1 linear, 2 quadratic)", " (0 sem decaimento, 1 linear, 2 quadrático)"),
    ("a number is written without quotes: ", "um número se escreve sem aspas: "),
    ("a number belongs here, not the word ", "aqui vai um número, não a palavra "),
    (
        ": the falloff is 0 (none), 1 (linear) or 2 (quadratic)",
        ": o decaimento é 0 (sem decaimento), 1 (linear) ou 2 (quadrático)",
    ),
    ("the file ends too early: close every { and [", "o arquivo termina cedo demais: feche cada { e ["),
    (
        "the number is beyond the range of f64 (about ±1.8e308); every number must be finite",
        "o número está além do alcance de f64 (cerca de ±1.8e308); todo número deve ser finito",
    ),
    ("number out of range", "número fora do alcance"),
    (
        "check the JSON just before this position (a missing comma, quote, bracket or brace, or a trailing comma)",
        "confira o JSON logo antes desta posição (falta uma vírgula, aspa, colchete ou chave, ou sobra uma vírgula no fim)",
    ),
    (
        "give the field once: remove one of the two (the parser does not pick one)",
        "dê o campo uma vez só: remova um dos dois (a leitura não escolhe um)",
    ),
    ("duplicate field ", "campo repetido "),
    ("duplicate material ", "material repetido "),
    (
        "give each material its own name, or remove one of the two",
        "dê a cada material seu próprio nome, ou remova um dos dois",
    ),
    ("the ray's origin", "a origem do raio"),
    ("the coefficient k of k·O", "o coeficiente k de k·O"),
    ("the kind: ", "o tipo: "),
    (" (lights); ", " (fontes de luz); "),
    (" (surfaces)", " (superfícies)"),
    ("the camera", "a câmera"),
    // After the fixes that hold them.
    ("trailing comma", "vírgula sobrando no fim"),
    // OBJ files (problem/mesh.rs).
    (": line ", ": linha "),
    ("cannot be read: ", "não pode ser lido: "),
    (
        "check the path; it is relative to the scene file's folder (to the working folder for a \
         scene read from standard input)",
        "confira o caminho; ele é relativo à pasta do arquivo da cena (à pasta de trabalho para \
         uma cena lida da entrada padrão)",
    ),
    ("is not a valid Wavefront OBJ file: ", "não é um arquivo Wavefront OBJ válido: "),
    (
        "give an OBJ file with `v x y z` vertices and `f i j k` faces",
        "dê um arquivo OBJ com vértices `v x y z` e faces `f i j k`",
    ),
    (
        "give an OBJ file with at least one face (`f i j k`)",
        "dê um arquivo OBJ com pelo menos uma face (`f i j k`)",
    ),
    ("has no faces", "não tem faces"),
    ("the vertex ", "o vértice "),
    (" is not `v x y z` (three numbers)", " não é `v x y z` (três números)"),
    ("write each vertex as `v x y z`", "escreva cada vértice como `v x y z`"),
    ("give finite coordinates (or use --precision f64)", "dê coordenadas finitas (ou use --precision f64)"),
    ("give finite coordinates", "dê coordenadas finitas"),
    (" is a line element, which has no surface to hit", " é um elemento de linha, que não tem superfície a atingir"),
    ("remove the `l` lines (faces are `f i j k`)", "remova as linhas `l` (as faces são `f i j k`)"),
    ("a face refers to vertex ", "uma face se refere ao vértice "),
    ("the face ", "a face "),
    (" vertices, and a face needs at least 3", " vértices, e uma face precisa de pelo menos 3"),
    (
        "give each face three or more vertices (`f i j k`)",
        "dê a cada face três ou mais vértices (`f i j k`)",
    ),
    (" refers to vertex ", " se refere ao vértice "),
    (" vertices come before it", " vértices vêm antes dele"),
    (
        "correct the face's vertex indices (1 is the first vertex)",
        "corrija os índices de vértices da face (1 é o primeiro vértice)",
    ),
    ("correct the face's vertex indices", "corrija os índices de vértices da face"),
    ("the mesh has more than ", "a malha tem mais de "),
    (" which does not exist", ", que não existe"),
    (" is not finite in ", " não é finito em "),
    (": the face's triangle ", ": o triângulo "),
    (
        " is degenerate in ",
        " é degenerado em ",
    ),
    (": its corners lie on one line", ": seus vértices estão numa reta"),
    ("remove the degenerate face from the OBJ file", "remova a face degenerada do arquivo OBJ"),
    (" (object ", " (objeto "),
    // Answers (check/answer.rs).
    ("the answer is empty: ", "a resposta está vazia: "),
    (
        "write three numbers such as \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" or \"[0.52; 0.03; 0]\", ",
        "escreva três números como \"0.52 0.03 0\", \"(0.52, 0.03, 0)\" ou \"[0.52; 0.03; 0]\", ",
    ),
    (" is not three numbers", " não são três números"),
    (" (it has a Unicode minus", " (tem um sinal de menos Unicode"),
    (
        "has a Unicode minus or dash (−, –): write the minus as the ASCII hyphen-minus -",
        "tem um sinal de menos ou travessão Unicode (−, –): escreva o menos como o hífen ASCII -",
    ),
    (" or dash (−, –): write the minus as the ASCII hyphen-minus -", " ou travessão (−, –): escreva o menos como o hífen ASCII -"),
    (
        "has full-width digits (０-９): write the digits 0-9 and the point . in ASCII",
        "tem dígitos de largura dupla (０-９): escreva os dígitos 0-9 e o ponto . em ASCII",
    ),
    (
        "is out of range: beyond ±1.8e308, the largest number f64 holds",
        "está fora do alcance: além de ±1.8e308, o maior número de f64",
    ),
    (" (it ", " ("),
    (" is not a number", " não é um número"),
    (
        " is not three integers 0–255, as --scale 255 expects: give 8-bit values, or leave out --scale for components on [0, 1]",
        " não são três inteiros 0–255, como --scale 255 espera: dê valores de 8 bits, ou tire --scale para componentes em [0, 1]",
    ),
    (
        " is not a scale: use 1 (components on [0, 1]) or 255 (8-bit)",
        " não é uma escala: use 1 (componentes em [0, 1]) ou 255 (8 bits)",
    ),
    (" is not a colour: write \"#RRGGBB\" or [r, g, b], ", " não é uma cor: escreva \"#RRGGBB\" ou [r, g, b], "),
    (
        "a \"#RRGGBB\" colour has 8 bits per channel: remove \"scale\" or set it to 255",
        "uma cor \"#RRGGBB\" tem 8 bits por canal: remova \"scale\" ou ponha 255",
    ),
    (
        " is not a colour \"#RRGGBB\": six hexadecimal digits after #",
        " não é uma cor \"#RRGGBB\": seis dígitos hexadecimais depois de #",
    ),
    (
        " is not a tolerance: give the largest difference accepted per channel, a number ≥ 0 (e.g. 0.005 on the 0–1 scale, 1 on the 255 scale)",
        " não é uma tolerância: dê a maior diferença aceita por canal, um número ≥ 0 (por exemplo 0.005 na escala 0–1, 1 na escala 255)",
    ),
    ("\" in \"", "\" em \""),
    // Steps (check/steps.rs).
    // The steps' formulas that hold words (step_formula), in an error.
    ("O + tD on the surface", "O + tD sobre a superfície"),
    ("N, of unit length", "N, de comprimento 1"),
    ("I_a = Σ ambient lights", "I_a = Σ das luzes ambientes"),
    ("write {\"cos_theta\"", "escreva {\"cos_theta\""),
    (
        " is not a light's index: write the index of the light in the file's \"lights\", from 0, such as cos_theta[1]",
        " não é o índice de uma fonte de luz: escreva o índice da fonte de luz em \"lights\" do arquivo, a partir de 0, como cos_theta[1]",
    ),
    (" is not the name of a step", " não é o nome de um passo"),
    (
        " (a light's own with [i], such as cos_theta[1])",
        " (o de uma fonte de luz com [i], como cos_theta[1])",
    ),
    (" is not a quantity of one light", " não é uma grandeza de uma só fonte de luz"),
    ("leave out the [i]", "tire o [i]"),
    (" is not a value for ", " não é um valor para "),
    (": write three numbers, such as ", ": escreva três números, como "),
    (": write one number, such as ", ": escreva um número, como "),
    (" is a vector, and ", " é um vetor, e "),
    (" is a number, and ", " é um número, e "),
    (" is three numbers", " são três números"),
    (" is one number", " é um número"),
    ("give three numbers, such as ", "dê três números, como "),
    ("give one number", "dê um número"),
    (" is not NAME=VALUE", " não é NOME=VALOR"),
    (
        "write the step's name, =, and its value, such as ",
        "escreva o nome do passo, =, e seu valor, como ",
    ),
    ("not JSON: ", "não é JSON: "),
    ("write one object of names and values, such as ", "escreva um objeto de nomes e valores, como "),
    ("the file is not one JSON object", "o arquivo não é um objeto JSON"),
    ("the file has no steps", "o arquivo não tem passos"),
    (
        " is not a value. Correção: give a number, [x, y, z], or a string such as ",
        " não é um valor. Correção: dê um número, [x, y, z], ou um texto como ",
    ),
    (
        ": the problem has no light other than ambient light, so no ",
        ": o problema não tem fonte de luz além da luz ambiente, e portanto não tem ",
    ),
    (" is an ambient light, which has no ", " é uma luz ambiente, que não tem "),
    (
        "give the index of a point, directional or spot light",
        "dê o índice de uma luz pontual, direcional ou spot",
    ),
    (": there is no ", ": não há "),
    ("]: the file has ", "]: o arquivo tem "),
    (" lights, from ", " fontes de luz, a partir de "),
    (" light, from ", " fonte de luz, a partir de "),
    (": this problem has no ", ": este problema não tem "),
    ("check a step of the ambient light: ", "confira um passo da luz ambiente: "),
    ("check a step it has: ", "confira um passo que ele tem: "),
    // The check command's steps (cli/commands/check.rs).
    (
        "write NAME=VALUE, such as --step cos_theta=0.98995 or --step R=0.6,0,0.8",
        "escreva NOME=VALOR, como --step cos_theta=0.98995 ou --step R=0.6,0,0.8",
    ),
    (
        "check the path, and that the file exists and is UTF-8 text",
        "confira o caminho, e que o arquivo existe e é texto UTF-8",
    ),
    ("one JSON object of names and values, such as ", "um objeto JSON de nomes e valores, como "),
    ("check one file's steps at a time", "confira os passos de um arquivo por vez"),
    (" at line ", " na linha "),
    (" column ", " coluna "),
    // Output files (cli/output.rs, cli/commands).
    (" at path ", " no caminho "),
    (
        "it is a folder. Correção: give a file name in it (e.g. -o DIR/report.csv), or - for standard output",
        "é uma pasta. Correção: dê um nome de arquivo nela (por exemplo -o DIR/report.csv), ou - para a saída padrão",
    ),
    ("too many levels of symbolic links (a loop?)", "níveis demais de links simbólicos (um ciclo?)"),
    (": writing it would replace what is being read", ": escrever nele substituiria o que está sendo lido"),
    (" is the input ", " é a entrada "),
    (" are the same file, ", " são o mesmo arquivo, "),
    (": one would replace the other", ": um substituiria o outro"),
    (" another file", " outro arquivo"),
    ("0 threads cannot render", "0 threads não renderizam"),
    (
        "give --threads 1 or more (or leave it out: one per core)",
        "dê --threads 1 ou mais (ou omita: uma por núcleo)",
    ),
    // The commands' own conflicts (cli/commands).
    ("--answer checks one file, and ", "--answer confere um arquivo, e "),
    ("--step and --steps check one file, and ", "--step e --steps conferem um arquivo, e "),
    (" were given", " foram dados"),
    (
        "check one file at a time, or put each file's answer in its \"answer\" field and leave out --answer",
        "confira um arquivo por vez, ou ponha a resposta de cada arquivo no seu campo \"answer\" e tire --answer",
    ),
    (" does not end in .png or .ppm", " não termina em .png ou .ppm"),
    (
        "name the image *.png or *.ppm, or give --image-format png|ppm",
        "dê à imagem um nome *.png ou *.ppm, ou dê --image-format png|ppm",
    ),
    // The command line (cli/error.rs).
    (": not a folder", ": não é uma pasta"),
    (": cannot create the folder: ", ": não é possível criar a pasta: "),
    ("cannot start the worker threads: ", "não é possível iniciar as threads de trabalho: "),
    ("give fewer --threads", "dê menos --threads"),
    ("report this as a bug; ", "relate isto como um defeito; "),
    // Files.
    ("cannot read the file: ", "não é possível ler o arquivo: "),
    ("No such file or directory (os error 2)", "arquivo ou pasta inexistente (erro 2 do sistema)"),
    ("Permission denied (os error 13)", "permissão negada (erro 13 do sistema)"),
    ("Is a directory (os error 21)", "é uma pasta (erro 21 do sistema)"),
    (
        "check the path, and that the file exists and is readable",
        "confira o caminho, e que o arquivo existe e pode ser lido",
    ),
    ("cannot write ", "não é possível escrever "),
    ("standard output", "a saída padrão"),
    // Syntax (serde's words).
    ("unknown field ", "campo desconhecido "),
    ("unknown variant ", "valor desconhecido "),
    (", expected an array of length ", ", esperada uma lista de comprimento "),
    (", expected one of ", ", esperado um de "),
    (
        "remove the field or correct its spelling (`phong schema` lists every field)",
        "remova o campo ou corrija sua grafia (`phong schema` lista todos os campos)",
    ),
    ("invalid type: ", "tipo inválido: "),
    ("integer ", "inteiro "),
    ("floating point ", "número "),
    ("string ", "texto "),
    (", expected a string", ", esperado um texto"),
    (", expected a sequence", ", esperada uma lista"),
    ("see `phong schema` for the expected form", "veja em `phong schema` a forma esperada"),
    ("EOF while parsing a value", "fim do arquivo no meio de um valor"),
    ("EOF while parsing an object", "fim do arquivo no meio de um objeto"),
    ("EOF while parsing a list", "fim do arquivo no meio de uma lista"),
    ("EOF while parsing a string", "fim do arquivo no meio de um texto"),
    ("expected value", "esperado um valor"),
    ("expected `,` or `}`", "esperado `,` ou `}`"),
    ("expected `,` or `]`", "esperado `,` ou `]`"),
    ("trailing characters", "caracteres a mais no fim"),
    ("one of the words ", "uma das palavras "),
    // Missing and refused values.
    ("missing field ", "campo ausente "),
    ("missing: ", "ausente: "),
    ("a point light needs ", "uma luz pontual precisa de "),
    ("a spot light needs ", "uma luz spot precisa de "),
    ("a directional light needs ", "uma luz direcional precisa de "),
    ("an ambient light needs ", "uma luz ambiente precisa de "),
    (": it gives ", ": dá "),
    ("Correção: add ", "Correção: acrescente "),
    ("the problem has nothing to shade", "o problema não tem nada a iluminar"),
    ("the file has no answer key to check", "o arquivo não tem gabarito para conferir"),
    ("pass --answer ", "passe --answer "),
    (" to the file", " ao arquivo"),
    (
        "give \"point\" (with \"material\", and \"position\" and \"normal\" where lights need them), \"ray\" with \"surfaces\", or a \"camera\" with \"surfaces\"",
        "dê \"point\" (com \"material\", e \"position\" e \"normal\" onde as fontes de luz precisarem), \"ray\" com \"surfaces\", ou uma \"camera\" com \"surfaces\"",
    ),
    // What each field gives (problem/format.rs's purposes).
    ("P_l, for L and d (Eq. 4.1)", "P_l, para L e d (Eq. 4.1)"),
    ("a point of the plane", "um ponto do plano"),
    (
        "f in I_l = C_l/d^f (Eq. 4.2, 4.3): 0 none, 1 linear, 2 quadratic",
        "f em I_l = C_l/d^f (Eq. 4.2, 4.3): 0 sem decaimento, 1 linear, 2 quadrático",
    ),
    ("the cone's half-angle γ in degrees (Eq. 4.4)", "o ângulo γ do cone, em graus (Eq. 4.4)"),
    (
        "the direction of travel (L for a directional light, D for a ray)",
        "a direção de propagação (L de uma luz direcional, D de um raio)",
    ),
    (
        "the light's colour C_l (or a coefficient's colour O)",
        "a cor C_l da fonte de luz (ou a cor O de um coeficiente)",
    ),
    ("the material at the point", "o material no ponto"),
    ("the mesh's Wavefront OBJ file", "o arquivo Wavefront OBJ da malha"),
    ("the plane's normal", "a normal do plano"),
    ("the spot exponent e of cos(ψ)^e (Eq. 4.4)", "o expoente de decaimento e de cos(ψ)^e (Eq. 4.4)"),
    ("the triangle's three corners", "os três vértices do triângulo"),
    ("the sphere", "a esfera"),
    ("rendering needs a camera", "a renderização precisa de uma câmera"),
    ("a light's colour has a negative component", "a cor de uma fonte de luz tem um componente negativo"),
    ("the background colour has a negative component", "a cor de fundo tem um componente negativo"),
    ("colour components must be ≥ 0", "os componentes de uma cor devem ser ≥ 0"),
    ("is not three numbers: write three numbers such as ", "não são três números: escreva três números como "),
    ("three integers 0–255 with --scale 255, or ", "três inteiros 0–255 com --scale 255, ou "),
    ("three integers 0–255 with --scale 255, ", "três inteiros 0–255 com --scale 255, "),
    (
        "or \"none\" when the ray hits nothing",
        "ou \"nenhuma\" quando o raio não atinge nada",
    ),
    // The command line.
    ("--fragment applies to --format latex and html only", "--fragment vale só para --format latex e html"),
    ("drop --fragment, or use --format latex or html", "tire --fragment, ou use --format latex ou html"),
    (
        "--part and the header flags apply to the documents, not to --format json",
        "--part e as opções do cabeçalho valem para os documentos, não para --format json",
    ),
    (
        "drop --part, --course, --title, --date and --author, or choose --format text, markdown, latex or html",
        "tire --part, --course, --title, --date e --author, ou escolha --format text, markdown, latex ou html",
    ),
    ("is outside the ", "está fora da imagem "),
    (" image. Correção: ", ". Correção: "),
    ("give X from 0 to ", "dê X de 0 a "),
    (" and Y from 0 to ", " e Y de 0 a "),
    // Last, the small words left between the fragments above.
    (" or ", " ou "),
    ("ou add ", "ou acrescente "),
    (" with ", " com "),
    (" and ", " e "),
    ("such as ", "como "),
    ("e.g. ", "por exemplo "),
    ("give ", "dê "),
    ("vertex ", "vértice "),
    (" triangles", " triângulos"),
    (" has ", " tem "),
    ("remove ", "remova "),
];

/// Where a message carries its own Portuguese: `English (Português: Portuguese)`, written by
/// [`both`].
const ASIDE: &str = " (Português: ";

/// An error message in `lang`: in English, without the Portuguese of the parts written in both
/// languages ([`both`]); in Portuguese, each such part replaced by its Portuguese, and the common
/// parts of the rest translated ([`ERRORS_PT`]). The word before it ("error", "erro") is
/// [`error_word`].
pub fn error_in(message: &str, lang: Lang) -> String {
    let (mut s, portuguese) = with_asides_held(message, lang);
    match lang {
        Lang::En => s,
        Lang::Pt => {
            // The phrases that hold a limit, first (a const table cannot format them).
            let limits = [
                (
                    format!("give at most {MAX_LIGHTS} lights"),
                    format!("dê no máximo {MAX_LIGHTS} fontes de luz"),
                ),
                (
                    format!(" triangles take the scene past {MAX_TRIANGLES} surfaces"),
                    format!(" triângulos levam a cena além de {MAX_TRIANGLES} superfícies"),
                ),
            ];
            for (en, pt) in &limits {
                s = s.replace(en.as_str(), pt);
            }
            for (en, pt) in ERRORS_PT {
                s = s.replace(en, pt);
            }
            for (k, pt) in portuguese.iter().enumerate() {
                s = s.replace(&held(k), pt);
            }
            s
        }
    }
}

/// The mark that holds the place of the `k`th Portuguese part while the table translates the
/// rest: characters of Unicode's private use area, which no message and no table entry holds.
fn held(k: usize) -> String {
    format!("\u{E000}{k}\u{E001}")
}

/// `message` with each part written by [`both`] (its English and its aside) replaced by a mark
/// ([`held`]), and the Portuguese of each part, in order; in English, each part's English
/// without its aside (and no mark). A part is the text from the last `. Fix: ` before its
/// aside (a fix), else from the last `: ` (a message after its field), else from the start; an
/// aside whose parentheses do not close is left as written.
fn with_asides_held(message: &str, lang: Lang) -> (String, Vec<String>) {
    let mut out = String::with_capacity(message.len());
    let mut portuguese = Vec::new();
    let mut rest = message;
    while let Some(start) = rest.find(ASIDE) {
        let after = &rest[start + ASIDE.len()..];
        let mut depth = 1;
        let end = after.char_indices().find_map(|(i, c)| {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ => {}
            }
            (depth == 0).then_some(i)
        });
        let Some(end) = end else { break };
        let before = &rest[..start];
        const FIX: &str = ". Fix: ";
        let part = before
            .rfind(FIX)
            .map(|i| i + FIX.len())
            .or_else(|| before.rfind(": ").map(|i| i + 2))
            .unwrap_or(0);
        match lang {
            Lang::En => out.push_str(before),
            Lang::Pt => {
                out.push_str(&before[..part]);
                out.push_str(&held(portuguese.len()));
                portuguese.push(after[..end].to_owned());
            }
        }
        rest = &after[end + 1..];
    }
    out.push_str(rest);
    (out, portuguese)
}

/// The formulas of `phong check --step` that hold words (check/steps.rs's `NAMES`), in
/// `lang`; the others are symbols only and the same in both languages.
pub fn step_formula(formula: &'static str, lang: Lang) -> &'static str {
    match (formula, lang) {
        (_, Lang::En) => formula,
        ("O + tD on the surface", Lang::Pt) => "O + tD sobre a superfície",
        ("N, of unit length", Lang::Pt) => "N, de comprimento 1",
        ("I_a = Σ ambient lights", Lang::Pt) => "I_a = Σ das luzes ambientes",
        (
            "the reflection ray is traced: level ≤ maximum level and w_s > minimum weight",
            Lang::Pt,
        ) => "o raio de reflexão é traçado: nível ≤ nível máximo e w_s > peso mínimo",
        (
            "the transmission ray is traced: k ≥ 0, level ≤ maximum level and w_t > minimum \
             weight",
            Lang::Pt,
        ) => "o raio de transmissão é traçado: k ≥ 0, nível ≤ nível máximo e w_t > peso mínimo",
        (other, Lang::Pt) => other,
    }
}

/// "yes"/"no" or "sim"/"não": a yes-or-no step's value (whether a secondary ray is traced).
pub fn yes_no(b: bool, lang: Lang) -> &'static str {
    match (b, lang) {
        (true, Lang::En) => "yes",
        (false, Lang::En) => "no",
        (true, Lang::Pt) => "sim",
        (false, Lang::Pt) => "não",
    }
}

/// Whether a secondary ray is traced, as a clause: "the ray is traced", "o raio não é traçado".
pub fn ray_traced(b: bool, lang: Lang) -> &'static str {
    match (b, lang) {
        (true, Lang::En) => "the ray is traced",
        (false, Lang::En) => "the ray is not traced",
        (true, Lang::Pt) => "o raio é traçado",
        (false, Lang::Pt) => "o raio não é traçado",
    }
}

/// "warning" or "aviso", before a warning on standard error.
pub fn warning_word(lang: Lang) -> &'static str {
    pick(lang, "warning", "aviso")
}

/// "error" or "erro", before a message on standard error.
pub fn error_word(lang: Lang) -> &'static str {
    pick(lang, "error", "erro")
}

/// "surfaces[2]", or "surfaces[2] (mesh), triangle 17" ("(malha), triângulo 17" in
/// Portuguese; the triangle's index in the mesh, from 0).
pub fn surface_label(source: Option<crate::problem::SurfaceSource>, lang: Lang) -> String {
    match source {
        None => pick(lang, "no surface", "nenhuma superfície").into(),
        Some(s) => match s.triangle {
            None => format!("surfaces[{}]", s.index),
            Some(t) => format!(
                "surfaces[{}] ({}), {} {t}",
                s.index,
                Phrase::Mesh.get(lang),
                Phrase::Triangle.get(lang)
            ),
        },
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
    fn no_error_fragment_is_hidden_by_an_earlier_one() {
        // The fragments are replaced in order: one that holds an earlier one's English would
        // never match, its words replaced already.
        for (j, (later, _)) in ERRORS_PT.iter().enumerate() {
            for (earlier, _) in &ERRORS_PT[..j] {
                assert!(
                    !later.contains(earlier),
                    "{later:?} holds the earlier {earlier:?}: list it first"
                );
            }
        }
    }

    #[test]
    fn an_error_in_portuguese_keeps_its_numbers_and_fields() {
        let en = "x.json: lights[1].falloff: 3 is not a falloff exponent. Fix: use 0 (no \
                  falloff), 1 (linear) or 2 (quadratic), Eq. 4.3";
        assert_eq!(
            error_in(en, Lang::Pt),
            "x.json: lights[1].falloff: 3 não é um expoente de decaimento. Correção: use 0 (sem \
             decaimento), 1 (linear) ou 2 (quadrático), Eq. 4.3"
        );
        assert_eq!(error_in(en, Lang::En), en);
        assert_eq!(
            error_in(
                "x.json:1:2: lights[0].falloff: invalid type: string \"linear\", expected f64. \
                 Fix: the falloff is the exponent \
                 f of d^f, a number: write 1 for \"linear\" (Português: o decaimento é o \
                 expoente f de d^f (Eq. 4.3): escreva 1)",
                Lang::Pt
            ),
            "x.json:1:2: lights[0].falloff: tipo inválido: texto \"linear\", esperado um número. \
             Correção: o decaimento é o expoente \
             f de d^f (Eq. 4.3): escreva 1"
        );
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
        for s in LightStatus::ALL {
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
