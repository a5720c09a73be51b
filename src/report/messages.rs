//! The words of the reports, in English and in Portuguese: every sentence about a finding, a
//! status, an omission or a reading, and every phrase of the step-by-step explanation, is written
//! here, once, so that every format says the same thing.
//!
//! A missing translation does not compile: a fixed phrase is declared with `phrases!`, whose
//! pattern takes exactly one English and one Portuguese text; a sentence with values is built
//! by [`pick`], which takes both. The JSON output is language-neutral and always uses the
//! English sentences.
//!
//! The Portuguese uses the chapter's own terms: luz ambiente, reflexão difusa, reflexão
//! especular, decaimento (linear, quadrático), fonte de luz, luz pontual, luz direcional, luz
//! spot, observador, normal, cone, eixo, geratriz, raio, interseção.

use crate::core::{LightStatus, Real, SpecularStatus};

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
/// translator reads, and the one `tests/integration/portuguese.rs` checks outputs against.
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
    AsWritten => "Solution (the problem as written)", "Solução (o problema como enunciado)";
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
    MarksAnd => " and ", " e ";
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
    Answer => "Answer (as written)", "Resposta (como enunciado)";
    NoHitAnswer => "no hit: the ray hits nothing", "nenhuma interseção: o raio não atinge nada";
}

/// The word for a light's kind, as the file names it ("point", "directional", "spot"), in
/// `lang`: the lights table's word (`problem::format`); "light" for a light of no kind.
pub fn light_kind(kind: &str, lang: Lang) -> &str {
    match crate::problem::format::LightType::ALL
        .iter()
        .find(|k| k.name() == kind)
    {
        Some(k) => k.word(lang),
        None if kind == "light" => pick(lang, "light", "luz"),
        None => kind,
    }
}

/// The word for a surface kind ("plane", "sphere"), in `lang`: the surfaces table's word.
pub fn surface_kind(kind: &str, lang: Lang) -> &str {
    match crate::problem::format::SurfaceType::ALL
        .iter()
        .find(|k| k.name() == kind)
    {
        Some(k) => k.word(lang),
        None => kind,
    }
}

/// A light or a surface named as a person names it in a document ("the yellow light", "the
/// second light", "the plane"; "a luz amarela", "a segunda luz", "o plano"): never by its
/// place in the file (`lights[1]`), which the JSON and the error messages keep. The noun comes
/// without its article; [`Noun::the`], [`Noun::of`], [`Noun::in_`] and [`Noun::for_`] add the
/// article, contracted in Portuguese where the language contracts it (de + a = da, em + o = no).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Noun {
    /// The English noun: "yellow light", "second light", "light “key”", "plane".
    en: String,
    /// The Portuguese noun: "luz amarela", "segunda luz", "luz “principal”", "plano".
    pt: String,
    /// Whether the Portuguese noun is masculine (o plano, o triângulo) or feminine (a luz, a
    /// esfera, a malha).
    masculine: bool,
}

impl Noun {
    /// With its article: "the yellow light", "a luz amarela", "o plano".
    pub fn the(&self, lang: Lang) -> String {
        match (lang, self.masculine) {
            (Lang::En, _) => format!("the {}", self.en),
            (Lang::Pt, true) => format!("o {}", self.pt),
            (Lang::Pt, false) => format!("a {}", self.pt),
        }
    }

    /// "of the yellow light", "da luz amarela", "do plano".
    pub fn of(&self, lang: Lang) -> String {
        match (lang, self.masculine) {
            (Lang::En, _) => format!("of the {}", self.en),
            (Lang::Pt, true) => format!("do {}", self.pt),
            (Lang::Pt, false) => format!("da {}", self.pt),
        }
    }

    /// "in the plane", "no plano", "na esfera".
    pub fn in_(&self, lang: Lang) -> String {
        match (lang, self.masculine) {
            (Lang::En, _) => format!("in the {}", self.en),
            (Lang::Pt, true) => format!("no {}", self.pt),
            (Lang::Pt, false) => format!("na {}", self.pt),
        }
    }

    /// "for the yellow light", "para a luz amarela".
    pub fn for_(&self, lang: Lang) -> String {
        match lang {
            Lang::En => format!("for the {}", self.en),
            Lang::Pt => format!("para {}", self.the(lang)),
        }
    }
}

/// An ordinal word before a noun: "second", "segunda" (feminine) or "segundo"; past the
/// tenth, "11th", "11ª", "11º".
fn ordinal(n: usize, lang: Lang, masculine: bool) -> String {
    const EN: [&str; 10] = [
        "first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth",
        "tenth",
    ];
    const PT: [&str; 10] = [
        "primeir", "segund", "terceir", "quart", "quint", "sext", "sétim", "oitav", "non", "décim",
    ];
    let ending = if masculine { 'o' } else { 'a' };
    match (lang, n.checked_sub(1).filter(|&k| k < 10)) {
        (Lang::En, Some(k)) => EN[k].to_owned(),
        (Lang::Pt, Some(k)) => format!("{}{ending}", PT[k]),
        (Lang::En, None) => {
            let suffix = match (n % 10, n % 100) {
                (_, 11..=13) => "th",
                (1, _) => "st",
                (2, _) => "nd",
                (3, _) => "rd",
                _ => "th",
            };
            format!("{n}{suffix}")
        }
        (Lang::Pt, None) => format!("{n}{}", if masculine { 'º' } else { 'ª' }),
    }
}

/// How a document names the light of the file's `lights[file_index]` (a point, spot or
/// directional light): by its name when it has one ("the yellow light", "a luz amarela"; a
/// name that is not itself a noun for a light is quoted after "light": "the light “key”", "a
/// luz “principal”"), else by its place among the lights when there are several ("the second
/// light", "a segunda luz"), else "the light", "a luz".
pub fn light_noun<R: Real>(problem: &Problem<R>, file_index: usize) -> Noun {
    let infos = &problem.light_info;
    let place = infos
        .binary_search_by_key(&file_index, |i| i.file_index)
        .ok();
    let info = place.map(|k| &infos[k]);
    let several = infos.len() > 1;
    let unnamed = |lang: Lang| match (place, several) {
        (Some(k), true) => match lang {
            Lang::En => format!("{} light", ordinal(k + 1, lang, false)),
            Lang::Pt => format!("{} luz", ordinal(k + 1, lang, false)),
        },
        _ => pick(lang, "light", "luz").to_owned(),
    };
    let en_name = info.and_then(|i| i.name.as_deref());
    let pt_name = info.and_then(|i| i.name_pt.as_deref().or(i.name.as_deref()));
    let en = match en_name {
        Some(name) => {
            let last = name.split_whitespace().last().unwrap_or("").to_lowercase();
            if LIGHT_NOUNS_EN.contains(&last.as_str()) {
                name.to_owned()
            } else {
                format!("light {}", super::explain::quoted(name))
            }
        }
        None => unnamed(Lang::En),
    };
    let (pt, masculine) = match pt_name {
        Some(name) => {
            let first = name.split_whitespace().next().unwrap_or("").to_lowercase();
            if LIGHT_NOUNS_PT_F.contains(&first.as_str()) {
                (name.to_owned(), false)
            } else if LIGHT_NOUNS_PT_M.contains(&first.as_str()) {
                (name.to_owned(), true)
            } else {
                (format!("luz {}", super::explain::quoted(name)), false)
            }
        }
        None => (unnamed(Lang::Pt), false),
    };
    Noun { en, pt, masculine }
}

/// English nouns that end a light's name that names a light ("yellow light", "green spot").
const LIGHT_NOUNS_EN: &[&str] = &["light", "lamp", "spot", "spotlight", "sun", "sky", "bulb"];
/// Portuguese feminine nouns that begin a light's name that names a light ("luz amarela").
const LIGHT_NOUNS_PT_F: &[&str] = &["luz", "lâmpada", "fonte"];
/// Portuguese masculine nouns that begin a light's name that names a light ("spot verde").
const LIGHT_NOUNS_PT_M: &[&str] = &["spot", "sol", "céu", "holofote", "refletor", "foco"];

/// How a document names a surface of the file ("the plane", "the second sphere", "triangle 17
/// of the mesh"; "o plano", "a segunda esfera", "o triângulo 17 da malha"): by its kind, and
/// its place among the file's surfaces of that kind when there are several.
pub fn surface_noun<R: Real>(problem: &Problem<R>, source: crate::problem::SurfaceSource) -> Noun {
    // The file's surfaces by kind, in file order (a mesh's triangles are one surface).
    let kind_of = |s: &crate::problem::model::Surface<R>| match s.source.triangle {
        Some(_) => "mesh",
        None => s.shape.kind(),
    };
    let mut seen: Option<usize> = None;
    let (mut before, mut count, mut kind) = (0, 0, None);
    for s in problem.surfaces() {
        if seen == Some(s.source.index) {
            continue;
        }
        seen = Some(s.source.index);
        if s.source.index == source.index {
            kind = Some(kind_of(s));
        }
    }
    let kind = kind.unwrap_or(if source.triangle.is_some() {
        "mesh"
    } else {
        "surface"
    });
    seen = None;
    for s in problem.surfaces() {
        if seen == Some(s.source.index) {
            continue;
        }
        seen = Some(s.source.index);
        if kind_of(s) == kind {
            count += 1;
            if s.source.index < source.index {
                before += 1;
            }
        }
    }
    let (en_word, pt_word, masculine) = match kind {
        "plane" => ("plane", "plano", true),
        "sphere" => ("sphere", "esfera", false),
        "triangle" => ("triangle", "triângulo", true),
        "mesh" => ("mesh", "malha", false),
        _ => ("surface", "superfície", false),
    };
    let noun = |lang: Lang, word: &str| match count > 1 {
        true => format!("{} {word}", ordinal(before + 1, lang, masculine)),
        false => word.to_owned(),
    };
    let whole = Noun {
        en: noun(Lang::En, en_word),
        pt: noun(Lang::Pt, pt_word),
        masculine,
    };
    match source.triangle {
        None => whole,
        Some(t) => Noun {
            en: format!("triangle {t} {}", whole.of(Lang::En)),
            pt: format!("triângulo {t} {}", whole.of(Lang::Pt)),
            masculine: true,
        },
    }
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
    // The JSON's English names the light by its place in the file, for scripts; a document
    // names it as a person would (Portuguese is never JSON).
    let noun = f.light.map(|i| light_noun(problem, i));
    let light = match (&noun, json) {
        (None, _) => String::new(),
        (Some(_), true) => f
            .light
            .map(|i| light_label(problem, i, lang, json))
            .unwrap_or_default(),
        (Some(n), false) => n.the(lang),
    };
    let (of_light, for_light) = match (&noun, json) {
        (Some(n), false) => (n.of(lang), n.for_(lang)),
        _ => (format!("of {light}"), format!("for {light}")),
    };
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
                 interseção exige t > 0): como enunciado, o raio não atinge nada. O ponto onde a \
                 reta do raio encontra a superfície é mostrado abaixo como uma leitura à parte",
                num(t)
            ),
        ),
        FindingData::NoIntersection => pick(
            lang,
            "the ray's line meets no surface: nothing to shade",
            "a reta do raio não encontra nenhuma superfície: nada a iluminar",
        )
        .into(),
        FindingData::RayInPlane { surface } => {
            let plane = surface_noun(
                problem,
                crate::problem::SurfaceSource {
                    index: surface,
                    triangle: None,
                },
            );
            let in_plane = match json {
                true => format!("in the plane surfaces[{surface}]"),
                false => plane.in_(lang),
            };
            pick(
                lang,
                format!(
                    "the ray lies {in_plane} (N·D = 0 and N·(Q − O) = 0): \
                 every point of it is on the surface, so the problem has no single hit point \
                 and nothing is shaded"
                ),
                format!(
                    "o raio está contido {in_plane} (N·D = 0 e N·(Q − O) = 0): \
                 todos os seus pontos estão na superfície, então o problema não tem um único \
                 ponto de interseção, e nada é iluminado"
                ),
            )
        }
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
                "{light} está do lado de trás da superfície: cos θ = −N·L = {} < \
                 0, logo não contribui com reflexão difusa nem com reflexão especular",
                num(cos_theta)
            ),
        ),
        FindingData::LightInTangentPlane => pick(
            lang,
            format!("{light} lies in the surface's tangent plane (cos θ = 0): it adds nothing"),
            format!(
                "{light} está no plano tangente à superfície (cos θ = 0): não \
                 contribui com nada"
            ),
        ),
        FindingData::LightOutsideCone { cos_gamma, cos_psi } => pick(
            lang,
            format!(
                "the point is outside the cone {of_light}: cos ψ = {} < cos γ = {} (ψ > γ), so \
                 I_l = 0 (Eq. 4.4)",
                num(cos_psi),
                num(cos_gamma)
            ),
            format!(
                "o ponto está fora do cone {of_light}: cos ψ = {} < cos γ = {} \
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
                "the point is on the edge of the cone {of_light} (ψ = γ to within the rounding \
                 of their computation in {p}, ±{}°): it counts as lit; exactly on the edge and \
                 a hair inside or outside cannot be told apart in this precision",
                num(error_bound_deg)
            ),
            format!(
                "o ponto está sobre uma geratriz do cone {of_light} (ψ = γ a menos \
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
                    "cos θ = {} {for_light} is within the rounding error of its own computation \
                     in {p} (±{}): whether the light is in front of the surface or behind it \
                     cannot be decided in this precision, and it is counted as {en}. The diffuse \
                     term changes by at most O_d·I_l·{} either way, but the specular term is all \
                     or nothing: {fix_en}move the light further from the tangent plane",
                    num(cos_theta),
                    num(error_bound),
                    num(error_bound)
                ),
                format!(
                    "cos θ = {} {for_light} está dentro do erro de \
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
                    "ψ = {}° and γ = {}° {of_light} differ by less than the rounding error of the \
                     hit point and of their computation in {p} (±{}°): whether the point is \
                     inside or outside the cone cannot be decided in this precision, and it is \
                     taken as {en}",
                    num(psi_deg),
                    num(gamma_deg),
                    num(error_bound_deg)
                ),
                format!(
                    "ψ = {}° e γ = {}° {of_light} diferem menos que o erro de \
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
                (false, Lang::En) => format!("the direction {of_light}"),
                (false, Lang::Pt) => format!("a direção {of_light}"),
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
        /// The one channel of a pixel's colour that differs by more than the tolerance.
        Channel { channel: String } => "in channel {channel}", "no canal {channel}";
        /// The channels of a pixel's colour that differ by more than the tolerance.
        Channels { channels: String } => "in channels {channels}", "nos canais {channels}";
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
pub fn reading_label(code: ReadingCode) -> String {
    reading_label_in(code, Lang::En)
}

/// The label of a reading: whether it is the likely intended one, and its name.
pub fn reading_label_in(code: ReadingCode, lang: Lang) -> String {
    let kind = match code {
        ReadingCode::LightReversed | ReadingCode::LineBehindOrigin => pick(
            lang,
            "likely intended reading",
            "leitura provavelmente pretendida",
        ),
        ReadingCode::NormalReversed => pick(lang, "another reading", "outra leitura"),
    };
    format!("{kind}: {}", reading_name(code, lang))
}

/// The name of a reading, the one every command gives it (`phong solve`'s headings, `phong
/// check`'s and `phong grade`'s verdicts, the Moodle quiz's feedback).
pub fn reading_name(code: ReadingCode, lang: Lang) -> &'static str {
    match code {
        ReadingCode::LightReversed => pick(
            lang,
            "light reversed (L from the point to the light)",
            "luz invertida (L do ponto para a luz)",
        ),
        ReadingCode::NormalReversed => pick(lang, "normal reversed", "normal invertida"),
        ReadingCode::LineBehindOrigin => pick(
            lang,
            "the line's hit behind the ray's origin",
            "a interseção da reta atrás da origem do raio",
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
            "como enunciado, nenhuma fonte de luz ilumina a superfície e uma está atrás dela. \
             Tomar L = (P_l − P)/‖P_l − P‖, o oposto da Eq. 4.1 (um deslize comum, e a convenção \
             de muitos livros), equivale a espelhar cada fonte de luz através de P para a \
             frente: fonte de luz e observador ficam então do mesmo lado e todos os termos da \
             Eq. 4.16 são usados. Sua cor é o negativo da Eq. 4.16 literal onde n_s é ímpar. \
             Este não é o problema como enunciado",
        ),
        ReadingCode::NormalReversed => pick(
            lang,
            "the surface taken as lit from behind: reversing N makes \
             it face the light, which is what taking |cos θ| amounts to; the viewer is then on \
             the back side, so there is no specular term. This is not the problem as written",
            "a superfície tomada como iluminada por trás: inverter N a deixa voltada para a \
             fonte de luz, o que equivale a tomar |cos θ|; o observador fica então do lado de \
             trás, logo não há reflexão especular. Este não é o problema como enunciado",
        ),
        ReadingCode::LineBehindOrigin => pick(
            lang,
            "the hit at t < 0 is behind the ray's origin; it is \
             the hit of the ray with its direction reversed, so V = −D where no viewer is \
             given. This is not the problem as written",
            "a interseção em t < 0 está atrás da origem do raio; é a interseção do raio com a \
             direção invertida, logo V = −D quando não é dado observador. Este não é o \
             problema como enunciado",
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
             observador para o ponto). Este não é o problema como enunciado",
        ),
        _ => reading_explanation_in(code, lang),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ordinals_agree_with_their_noun_in_both_languages() {
        assert_eq!(ordinal(1, Lang::En, false), "first");
        assert_eq!(ordinal(2, Lang::En, true), "second");
        assert_eq!(ordinal(10, Lang::En, false), "tenth");
        assert_eq!(ordinal(11, Lang::En, false), "11th");
        assert_eq!(ordinal(21, Lang::En, false), "21st");
        assert_eq!(ordinal(22, Lang::En, false), "22nd");
        assert_eq!(ordinal(113, Lang::En, false), "113th");
        assert_eq!(ordinal(2, Lang::Pt, false), "segunda");
        assert_eq!(ordinal(2, Lang::Pt, true), "segundo");
        assert_eq!(ordinal(7, Lang::Pt, false), "sétima");
        assert_eq!(ordinal(9, Lang::Pt, true), "nono");
        assert_eq!(ordinal(12, Lang::Pt, false), "12ª");
        assert_eq!(ordinal(12, Lang::Pt, true), "12º");
    }

    #[test]
    fn a_noun_takes_its_article_and_contracts_it() {
        let light = Noun {
            en: "yellow light".into(),
            pt: "luz amarela".into(),
            masculine: false,
        };
        let plane = Noun {
            en: "plane".into(),
            pt: "plano".into(),
            masculine: true,
        };
        assert_eq!(light.the(Lang::En), "the yellow light");
        assert_eq!(light.the(Lang::Pt), "a luz amarela");
        assert_eq!(light.of(Lang::Pt), "da luz amarela");
        assert_eq!(light.for_(Lang::Pt), "para a luz amarela");
        assert_eq!(light.in_(Lang::Pt), "na luz amarela");
        assert_eq!(plane.the(Lang::Pt), "o plano");
        assert_eq!(plane.of(Lang::Pt), "do plano");
        assert_eq!(plane.in_(Lang::Pt), "no plano");
        assert_eq!(plane.in_(Lang::En), "in the plane");
        assert_eq!(plane.of(Lang::En), "of the plane");
    }

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
