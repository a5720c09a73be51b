//! The explanation of a solution, independent of any output format: the one walk over a
//! [`Solution`] that decides what the steps are, in which order, with which formula, value and
//! equation number. The text, Markdown, LaTeX and HTML renderers only lay it out, so they cannot
//! disagree about the steps.
//!
//! A step's line is a sequence of [`Inline`] pieces: words (already in the explanation's
//! language), formulas from [`Formula`] (each written in Unicode and in LaTeX), numbers,
//! vectors and colours. Each renderer writes the pieces in its own notation.

use super::formula::Formula;
use super::messages::{self, pick, Phrase};
use crate::core::real::to_f64_array;
use crate::core::{Falloff, LightKind, LightSet, LightStatus, LightTerm, Real, SpecularStatus, V3};
use crate::problem::format::ColorSpec;
use crate::problem::model::ReflectivitySource;
use crate::problem::Problem;
use crate::report::pixel::transmission_stop_in;
use crate::solve::{Evaluation, Intersection, Secondary, Solution, ViewSource};
use crate::text::lang::Lang;
use crate::text::Message;
use crate::tracer::Stop;

/// One piece of a step's line.
#[derive(Clone, Debug, PartialEq)]
pub enum Inline {
    /// Words in the explanation's language (may hold a user's text, such as a light's name).
    Text(String),
    /// A formula or symbol.
    Math(Formula),
    /// A number.
    Num(f64),
    /// A vector (or a colour that may be negative, such as a literal value).
    Vector([f64; 3]),
    /// A colour (HTML shows a swatch beside it, clamped to [0, 1]).
    Color([f64; 3]),
    /// An angle in degrees.
    Degrees(f64),
    /// An 8-bit colour "(r, g, b)".
    Rgb8([u8; 3]),
    /// Where a renderer that can show colour puts a swatch of this 8-bit colour (nothing in
    /// plain text).
    Swatch([u8; 3]),
}

/// A reference to the chapter: an equation, a range of equations, a sum of an equation over
/// the lights, or a section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ref {
    /// An equation: "Eq. 4.10".
    Eq(&'static str),
    /// A range of equations: "Eq. 4.5–4.6".
    Eqs(&'static str, &'static str),
    /// An equation summed over the lights: "Σ Eq. 4.8".
    SumEq(&'static str),
    /// A section: "Sec. 4.2".
    Sec(&'static str),
}

impl Ref {
    /// "Eq. 4.10", "Eq. 4.5–4.6", "Σ Eq. 4.8", "Sec. 4.2" (in `lang`).
    pub fn text(self, lang: Lang) -> String {
        let eq = Phrase::EqAbbrev.get(lang);
        match self {
            Ref::Eq(n) => format!("{eq} {n}"),
            Ref::Eqs(a, b) => format!("{eq} {a}–{b}"),
            Ref::SumEq(n) => format!("Σ {eq} {n}"),
            Ref::Sec(n) => format!("{} {n}", Phrase::SecAbbrev.get(lang)),
        }
    }

    /// The fragment of the id of the first step applying it (`eq-4-10`, `sec-4-2`; a sum
    /// over the lights is its equation's, a range `eq-4-5-to-4-6`).
    pub fn anchor(self) -> String {
        match self {
            Ref::Eq(n) | Ref::SumEq(n) => format!("eq-{}", n.replace('.', "-")),
            Ref::Eqs(a, b) => format!("eq-{}-to-{}", a.replace('.', "-"), b.replace('.', "-")),
            Ref::Sec(n) => format!("sec-{}", n.replace('.', "-")),
        }
    }

    /// [`Ref::anchor`] of a reference as a slip names it ("Eq. 4.7", "Eq. 4.16"): its first
    /// number; `None` when it names none.
    pub fn anchor_of(text: &str) -> Option<String> {
        let start = text.find(|c: char| c.is_ascii_digit())?;
        let n: String = text[start..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        let kind = if text.trim_start().starts_with("Sec") {
            "sec"
        } else {
            "eq"
        };
        Some(format!(
            "{kind}-{}",
            n.trim_end_matches('.').replace('.', "-")
        ))
    }
}

/// One step (or one given quantity): its line, its depth under the step above, and the
/// chapter's equation.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// 0 for a step, 1 for a part of the step above, 2 for a note on that part.
    pub depth: usize,
    /// What the step says, piece by piece.
    pub line: Vec<Inline>,
    /// The chapter's equation (or section) the step applies, if any.
    pub eq: Option<Ref>,
}

/// One row of a problem's data (the handout's table): what is given, and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct DataRow {
    /// What the row gives: "Point light “white light”", "Normal at P", …
    pub what: Vec<Inline>,
    /// Its value: "P_l = (1, 1, 1), C_l = (1, 1, 1), f = 1 (linear)".
    pub value: Vec<Inline>,
}

/// The explanation of one solved problem.
#[derive(Clone, Debug)]
pub struct Explanation {
    /// The language of its words.
    pub lang: Lang,
    /// The problem's title in `lang` (`title_pt` in Portuguese, when the file has one), or
    /// "Problem".
    pub title: String,
    /// The file's name, without its folder (no machine path reaches a document).
    pub file: String,
    /// "f32" or "f64".
    pub precision: &'static str,
    /// The problem's question, as written.
    pub question: Option<String>,
    /// What the problem gives, row by row, for the statement (the student's handout).
    pub data: Vec<DataRow>,
    /// The findings, as sentences.
    pub findings: Vec<String>,
    /// A ray problem's intersection, as written.
    pub ray: Option<Vec<Step>>,
    /// The problem as written, then any other readings.
    pub parts: Vec<Part>,
    /// Likely unit mistakes in the file, as sentences (`phong solve` prints them on standard
    /// error; the layouts leave them out).
    pub warnings: Vec<String>,
}

/// The problem as written, or another reading of it.
#[derive(Clone, Debug)]
pub struct Part {
    /// "Solution (the problem as written)", or the reading's label ("Likely intended reading:
    /// …").
    pub heading: String,
    /// The reading this part solves; `None` for the problem as written.
    pub reading: Option<crate::solve::ReadingCode>,
    /// Why a reading is shown and what it assumes.
    pub explanation: Option<String>,
    /// A reading's own intersection.
    pub ray: Option<Vec<Step>>,
    /// `None` when there is nothing to shade.
    pub shading: Option<Shading>,
}

/// The shading of the point, in three lists of steps.
#[derive(Clone, Debug)]
pub struct Shading {
    /// The quantities as given and as used: P, N, the material and the lights.
    pub given: Vec<Step>,
    /// V, the ambient term and the terms left out, then each light's arrival and terms.
    pub steps: Vec<Step>,
    /// Each term summed over the lights, the total I (Eq. 4.16), the colour clamped and in 8
    /// bits, and the literal value where it differs.
    pub total: Vec<Step>,
    /// The colour clamped to [0, 1].
    pub clamped: [f64; 3],
    /// The colour in 8 bits, round(255·c) of the clamped colour.
    pub rgb8: [u8; 3],
    /// One plane of incidence per light that has a direction at the point.
    pub diagrams: Vec<Diagram>,
    /// A ray problem's secondary rays at the hit (Section 4.4), after the local colour; empty
    /// where the material neither reflects nor transmits, and in a reading.
    pub secondary: Vec<Step>,
}

/// What a diagram of the plane of incidence needs: the unit vectors at P for one light.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// The light as a document names it, with its article ("the white light", "a luz
    /// branca": `report::messages::light_noun`).
    pub light: String,
    /// Its index in the file's `lights`.
    pub light_index: usize,
    /// Whether the light is directional (L = D_l, the same at every point).
    pub directional: bool,
    /// N, unit.
    pub n: [f64; 3],
    /// L, from the light to the point.
    pub l: [f64; 3],
    /// R, where the explanation computed it.
    pub r: Option<[f64; 3]>,
    /// V, from the eye to the point, when there is a viewer.
    pub v: Option<[f64; 3]>,
    /// Whether the light lights the point, and if not why.
    pub status: LightStatus,
    /// A spot's cone: its axis D_l (unit) and half-angle γ in degrees.
    pub cone: Option<([f64; 3], f64)>,
    /// A ray problem's ray: its unit direction D and the t of the point (negative: the point
    /// is behind the ray's origin, on its line).
    pub ray: Option<([f64; 3], f64)>,
    /// Its figure, laid out at its first drawing (`report::diagram::figure`) and kept for the
    /// other formats: the fields above must not change after it.
    pub(crate) laid: super::diagram::Laid,
}

fn v<R: Real>(x: V3<R>) -> [f64; 3] {
    to_f64_array::<R>(x)
}

fn t(s: impl Into<String>) -> Inline {
    Inline::Text(s.into())
}

fn p(phrase: Phrase, lang: Lang) -> Inline {
    Inline::Text(phrase.get(lang).to_owned())
}

use Inline::{Color, Math, Num, Vector};

const EQ: Inline = Math(Formula::Equals);

/// Collects steps.
struct Steps(Vec<Step>);

impl Steps {
    fn push(&mut self, depth: usize, line: Vec<Inline>, eq: Option<Ref>) {
        self.0.push(Step { depth, line, eq });
    }
}

/// Explains a solved problem in `lang`.
pub fn explain<R: Real>(
    file: &str,
    problem: &Problem<R>,
    s: &Solution<R>,
    lang: Lang,
) -> Explanation {
    let parts = std::iter::once(Part {
        heading: Phrase::AsWritten.get(lang).to_owned(),
        reading: None,
        explanation: None,
        ray: None,
        shading: s.evaluation.as_ref().map(|e| {
            let mut sh = shading(problem, e, lang, ray_mark(s.intersection.as_ref()));
            if let Some(line) = s.versus_f64.as_ref().and_then(|x| versus_f64(x, lang)) {
                sh.total.push(Step {
                    depth: 0,
                    line,
                    eq: None,
                });
            }
            Shading {
                secondary: s
                    .secondary
                    .as_ref()
                    .map_or_else(Vec::new, |x| secondary(x, lang)),
                ..sh
            }
        }),
    })
    .chain(s.readings.iter().map(|r| {
        Part {
            reading: Some(r.code),
            heading: capitalised(&messages::reading_label_in(r.code, lang)),
            explanation: Some(
                messages::reading_explanation_given(r.code, lang, problem.viewer.is_some())
                    .to_owned(),
            ),
            ray: r
                .intersection
                .as_ref()
                .map(|x| intersection(problem, x, lang)),
            shading: Some(shading(
                problem,
                &r.evaluation,
                lang,
                ray_mark(r.intersection.as_ref()),
            )),
        }
    }))
    .collect();
    let title = match lang {
        Lang::Pt => problem.title_pt.as_deref().or(s.title.as_deref()),
        Lang::En => s.title.as_deref(),
    };
    Explanation {
        lang,
        title: title.map_or_else(|| Phrase::Problem.get(lang).to_owned(), str::to_owned),
        file: file_name(file),
        precision: R::NAME,
        question: match lang {
            Lang::Pt => problem.question_pt.as_deref().or(s.question.as_deref()),
            Lang::En => s.question.as_deref(),
        }
        .map(str::to_owned),
        data: data(problem, lang),
        findings: s
            .findings
            .iter()
            .map(|f| messages::finding_in(problem, f, lang))
            .collect(),
        ray: s
            .intersection
            .as_ref()
            .map(|x| intersection(problem, x, lang)),
        parts,
        warnings: problem.warnings.iter().map(|w| w.text(lang)).collect(),
    }
}

/// The line a problem solved in f32 adds under its colour: f32 − f64 of the colour, f64's
/// colour, and the check's tolerance; `None` where f64 shades nothing.
fn versus_f64(x: &crate::solve::VersusF64, lang: Lang) -> Option<Vec<Inline>> {
    let (d, c) = (x.color?, x.f64_color?);
    Some(vec![
        p(Phrase::VersusF64, lang),
        Vector(d),
        p(Phrase::VersusF64Gives, lang),
        Vector(c),
        p(Phrase::VersusF64Tolerance, lang),
        Num(x.tolerance),
    ])
}

impl Explanation {
    /// The line under the title: the file's name, and the precision when it is not the default
    /// f64 ("4.2.json", "4.2.json, f32").
    pub fn source(&self) -> String {
        if self.precision == "f64" {
            self.file.clone()
        } else {
            format!("{}, {}", self.file, self.precision)
        }
    }

    /// The answer key's cells: the answer to the problem as written (its colour clamped to
    /// [0, 1] and in 8 bits, or that there is nothing to shade), then each other reading's
    /// label and colour.
    pub fn key(&self) -> (Vec<Inline>, Vec<Vec<Inline>>) {
        let answer = |sh: Option<&Shading>| match sh {
            Some(sh) => vec![
                Color(sh.clamped),
                t(" · "),
                Inline::Rgb8(sh.rgb8),
                Inline::Swatch(sh.rgb8),
            ],
            None => vec![p(Phrase::NoHitAnswer, self.lang)],
        };
        let mut parts = self.parts.iter();
        let written = answer(parts.next().and_then(|x| x.shading.as_ref()));
        let readings = parts
            .map(|x| {
                let mut line = vec![t(format!("{}: ", x.heading))];
                line.extend(answer(x.shading.as_ref()));
                line
            })
            .collect();
        (written, readings)
    }
}

/// A file's name without its folder: "exercises/4.2.json" is "4.2.json".
fn file_name(file: &str) -> String {
    std::path::Path::new(file)
        .file_name()
        .map_or_else(|| file.to_owned(), |n| n.to_string_lossy().into_owned())
}

/// The text with its first letter in capitals ("likely …" becomes "Likely …").
pub(crate) fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(first) => first.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// A name as the explanation quotes it: “white light”.
pub fn quoted(name: &str) -> String {
    format!("“{name}”")
}

/// What a problem gives, row by row (the statement's table, and a pixel's scene).
pub(crate) fn data_rows<R: Real>(problem: &Problem<R>, lang: Lang) -> Vec<DataRow> {
    data(problem, lang)
}

/// What a problem gives, row by row: the lights, the point or the ray and its surfaces, the
/// viewer and the materials.
fn data<R: Real>(problem: &Problem<R>, lang: Lang) -> Vec<DataRow> {
    use crate::geometry::Shape;
    use crate::problem::model::{NamedMaterial, Target};
    let mut rows = Vec::new();
    let mut row = |what: Vec<Inline>, value: Vec<Inline>| rows.push(DataRow { what, value });
    let named = |base: String, name: Option<&str>| match name {
        Some(n) => format!("{base} {}", quoted(n)),
        None => base,
    };
    let local = |en: &Option<std::sync::Arc<str>>, pt: &Option<std::sync::Arc<str>>| match lang {
        Lang::Pt => pt.clone().or_else(|| en.clone()),
        Lang::En => en.clone(),
    };
    for a in &problem.ambient_info {
        row(
            vec![t(named(
                Phrase::AmbientLight.get(lang).to_owned(),
                local(&a.name, &a.name_pt).as_deref(),
            ))],
            vec![Math(Formula::IA), EQ, Color(v::<R>(a.color))],
        );
    }
    for (l, info) in problem.lights.lights.iter().zip(&problem.light_info) {
        let kind = match l.kind {
            LightKind::Point { .. } => Phrase::PointLight,
            LightKind::Spot { .. } => Phrase::SpotLight,
            LightKind::Directional { .. } => Phrase::DirectionalLight,
        };
        let what = named(
            kind.get(lang).to_owned(),
            local(&info.name, &info.name_pt).as_deref(),
        );
        let sep = || t(", ");
        let falloff = |f: Falloff| {
            let word = match f {
                Falloff::None => Phrase::FalloffNone,
                Falloff::Linear => Phrase::FalloffLinear,
                Falloff::Quadratic => Phrase::FalloffQuadratic,
            };
            vec![
                sep(),
                Math(Formula::F),
                EQ,
                Num(f64::from(f.exponent())),
                t(format!(" ({})", word.get(lang))),
            ]
        };
        let mut value = Vec::new();
        match l.kind {
            LightKind::Point {
                position,
                falloff: f,
            } => {
                value.extend([Math(Formula::PL), EQ, Vector(v::<R>(position)), sep()]);
                value.extend([Math(Formula::CL), EQ, Color(v::<R>(l.color))]);
                value.extend(falloff(f));
            }
            LightKind::Spot {
                position,
                falloff: f,
                cone,
            } => {
                value.extend([Math(Formula::PL), EQ, Vector(v::<R>(position)), sep()]);
                value.extend([Math(Formula::DL), EQ, Vector(v::<R>(cone.axis)), sep()]);
                value.extend([
                    Math(Formula::Gamma),
                    EQ,
                    Inline::Degrees(cone.angle_deg.to_f64()),
                    sep(),
                    Math(Formula::SpotExponent),
                    EQ,
                    Num(cone.exponent.to_f64()),
                    sep(),
                ]);
                value.extend([Math(Formula::CL), EQ, Color(v::<R>(l.color))]);
                value.extend(falloff(f));
            }
            LightKind::Directional { direction } => {
                value.extend([Math(Formula::DL), EQ, Vector(v::<R>(direction)), sep()]);
                value.extend([Math(Formula::CL), EQ, Color(v::<R>(l.color))]);
            }
        }
        row(vec![t(what)], value);
    }
    let mut materials: Vec<&NamedMaterial<R>> = Vec::new();
    match &problem.target {
        Target::Point {
            position,
            normal,
            material,
        } => {
            if let Some(pt) = position {
                row(
                    vec![p(Phrase::ThePoint, lang)],
                    vec![Math(Formula::P), EQ, Vector(v::<R>(*pt))],
                );
            }
            if let Some(nu) = normal {
                row(
                    vec![p(Phrase::NormalAt, lang), Math(Formula::P)],
                    vec![Math(Formula::N), EQ, Vector(v::<R>(nu.given))],
                );
            }
            materials.push(material);
        }
        Target::Ray {
            ray,
            direction,
            surfaces,
        } => {
            row(
                vec![p(Phrase::Ray, lang)],
                vec![
                    Math(Formula::O),
                    EQ,
                    Vector(v::<R>(ray.origin)),
                    t(", "),
                    Math(Formula::D),
                    EQ,
                    Vector(v::<R>(direction.given)),
                ],
            );
            for sf in surfaces {
                let mut value = match &sf.shape {
                    Shape::Plane(pl) => vec![
                        Math(Formula::Q),
                        EQ,
                        Vector(v::<R>(pl.point)),
                        t(", "),
                        Math(Formula::N),
                        EQ,
                        Vector(v::<R>(sf.normal.as_deref().map_or(pl.normal, |n| n.given))),
                    ],
                    Shape::Sphere(sp) => vec![
                        Math(Formula::Center),
                        EQ,
                        Vector(v::<R>(sp.center)),
                        t(", "),
                        Math(Formula::Radius),
                        EQ,
                        Num(sp.radius.to_f64()),
                    ],
                    Shape::Triangle(_) => continue,
                };
                if let Some(n) = &sf.material.name {
                    value.push(t(format!("; {} {}", Phrase::Material.get(lang), quoted(n))));
                }
                let kind = match sf.shape {
                    Shape::Plane(_) => Phrase::Plane,
                    _ => Phrase::Sphere,
                };
                row(
                    vec![t(format!(
                        "{}: {}",
                        Phrase::Surface.get(lang),
                        kind.get(lang)
                    ))],
                    value,
                );
                if !materials
                    .iter()
                    .any(|m| m.name.is_some() && m.name == sf.material.name)
                {
                    materials.push(&sf.material);
                }
            }
        }
        Target::Scene { .. } => {}
    }
    if let Some(e) = problem.viewer {
        row(
            vec![p(Phrase::TheViewer, lang)],
            vec![Math(Formula::E), EQ, Vector(v::<R>(e))],
        );
    }
    for m in materials {
        let mut value = Vec::new();
        let colors = [
            (Formula::OA, &m.spec.ambient),
            (Formula::OD, &m.spec.diffuse),
            (Formula::OS, &m.spec.specular),
        ];
        for (symbol, spec) in colors {
            if let Some(c) = spec {
                if !value.is_empty() {
                    value.push(t(", "));
                }
                value.extend([Math(symbol), EQ]);
                value.extend(color_spec(c));
            }
        }
        if m.spec.shininess.is_some() {
            value.extend([t(", "), Math(Formula::NS), EQ, Num(m.material.n_s.to_f64())]);
        }
        if let (Some(o_r), Some(ReflectivitySource::Explicit)) = (m.material.o_r, m.reflectivity) {
            value.extend([t(", "), Math(Formula::OR), EQ, Color(v::<R>(o_r))]);
        }
        if let Some(tr) = m.material.transmission {
            value.extend([
                t(", "),
                Math(Formula::OT),
                EQ,
                Color(v::<R>(tr.o_t)),
                t(", "),
                Math(Formula::Eta),
                EQ,
                Num(tr.eta.to_f64()),
            ]);
        }
        if value.is_empty() {
            continue;
        }
        row(
            vec![t(named(
                capitalised(Phrase::Material.get(lang)),
                m.name.as_deref(),
            ))],
            value,
        );
    }
    // A ray problem whose surfaces reflect or transmit: the tracer's settings decide which of
    // the hit's secondary rays are traced (Section 4.4).
    if let Target::Ray { surfaces, .. } = &problem.target {
        let spawns = surfaces.iter().any(|s| {
            s.material.material.o_r.is_some() || s.material.material.transmission.is_some()
        });
        if spawns {
            let s = &problem.render;
            row(
                vec![t(pick(lang, "Render settings", "Parâmetros do traçado"))],
                vec![t(pick(
                    lang,
                    format!(
                        "maximum level {}, minimum weight {}",
                        s.max_level,
                        crate::text::number::num(s.min_weight.to_f64())
                    ),
                    format!(
                        "nível máximo {}, peso mínimo {}",
                        s.max_level,
                        crate::text::number::num(s.min_weight.to_f64())
                    ),
                ))],
            );
        }
    }
    rows
}

fn intersection<R: Real>(problem: &Problem<R>, x: &Intersection<R>, lang: Lang) -> Vec<Step> {
    let mut out = Steps(Vec::new());
    out.push(
        0,
        vec![
            p(Phrase::Origin, lang),
            Math(Formula::O),
            EQ,
            Vector(v::<R>(x.origin)),
        ],
        None,
    );
    let length = crate::core::vector::length::<R>(x.direction_given);
    let mut line = vec![p(Phrase::Direction, lang), Math(Formula::D), EQ];
    if !crate::core::vector::is_unit_length(length) {
        line.extend([
            Vector(v::<R>(x.direction_given)),
            t(" "),
            Math(Formula::OverNorm),
            EQ,
        ]);
    }
    line.push(Vector(v::<R>(x.direction)));
    out.push(0, line, None);
    match (x.t, x.point, x.kind) {
        (Some(tt), Some(pt), Some(kind)) => {
            let verdict = if x.in_front {
                Phrase::Hit
            } else {
                Phrase::NotAHit
            };
            out.push(
                0,
                vec![
                    t(format!(
                        "{}: ",
                        capitalised(&match x.source {
                            Some(source) => messages::surface_noun(problem, source).the(lang),
                            None => messages::surface_kind(kind, lang).to_owned(),
                        })
                    )),
                    Math(Formula::T),
                    EQ,
                    Num(tt.to_f64()),
                    t(", "),
                    Math(Formula::OPlusTD),
                    EQ,
                    Vector(v::<R>(pt)),
                    t("  → "),
                    p(verdict, lang),
                ],
                None,
            );
        }
        _ => match x.lies_in {
            Some(_) => out.push(0, vec![p(Phrase::LineLiesInPlane, lang)], None),
            None => out.push(0, vec![p(Phrase::LineMeetsNothing, lang)], None),
        },
    }
    out.0
}

/// The secondary rays at a ray problem's hit, Section 4.4: the level and weight rules, V and N,
/// the reflection ray R_V (Eq. 4.17) with its level, weight and whether it is traced, and the
/// transmitted ray by Snell's law likewise (docs/conventions.md, "Recursion level", "Weight",
/// "Transmission"); the last line says the solver does not trace them.
fn secondary<R: Real>(x: &Secondary<R>, lang: Lang) -> Vec<Step> {
    let mut out = Steps(Vec::new());
    let (max, min) = (x.max_level, x.min_weight.to_f64());
    out.push(
        0,
        vec![t(pick(
            lang,
            format!(
                "The problem's ray is a primary ray: level {}, weight w_p = 1. A ray it spawns \
                 has level {} and is traced only if its level ≤ the maximum level ({max}) and \
                 its weight > the minimum weight ({}).",
                x.level,
                x.level + 1,
                crate::text::number::num(min)
            ),
            format!(
                "O raio do problema é um raio primário: nível {}, peso w_p = 1. Um raio gerado \
                 por ele tem nível {} e só é traçado se o seu nível for ≤ o nível máximo ({max}) \
                 e o seu peso for > o peso mínimo ({}).",
                x.level,
                x.level + 1,
                crate::text::number::num(min)
            ),
        ))],
        Some(Ref::Sec("4.4")),
    );
    out.push(
        0,
        vec![
            Math(Formula::VIsD),
            EQ,
            Vector(v::<R>(x.v)),
            t(", "),
            Math(Formula::N),
            EQ,
            Vector(v::<R>(x.n)),
            t(pick(
                lang,
                " (facing the ray), ",
                " (voltada para o raio), ",
            )),
            Math(Formula::NDotV),
            EQ,
            Num(x.n_dot_v.to_f64()),
        ],
        None,
    );
    // Whether a child is traced, and the rule that says so.
    let verdict = |level: u32, weight: R, stop: Option<Stop>, adds: &str| {
        let (l, w) = (level, crate::text::number::num(weight.to_f64()));
        let m = crate::text::number::num(min);
        match stop {
            None => t(pick(
                lang,
                format!("traced: level {l} ≤ {max} and weight {w} > {m}; it adds {adds}"),
                format!("traçado: nível {l} ≤ {max} e peso {w} > {m}; ele soma {adds}"),
            )),
            Some(Stop::MaxLevel) => t(pick(
                lang,
                format!("not traced: level {l} > the maximum level {max}"),
                format!("não é traçado: nível {l} > o nível máximo {max}"),
            )),
            Some(Stop::MinWeight) => t(pick(
                lang,
                format!("not traced: weight {w} ≤ the minimum weight {m}"),
                format!("não é traçado: peso {w} ≤ o peso mínimo {m}"),
            )),
            Some(other) => t(pick(
                lang,
                format!("not traced: {}", transmission_stop_in(other, lang)),
                format!("não é traçado: {}", transmission_stop_in(other, lang)),
            )),
        }
    };
    // "O = (…); level l, w = …": a child's colour factor, level and weight.
    let weighed = |o: Formula, color: V3<R>, level: u32, w: Formula, weight: R| {
        vec![
            Math(o),
            EQ,
            Color(v::<R>(color)),
            t(pick(lang, "; level ", "; nível ")),
            Num(f64::from(level)),
            t(", "),
            Math(w),
            EQ,
            Num(weight.to_f64()),
        ]
    };
    if let Some(r) = &x.reflection {
        let mut line = vec![
            t(pick(lang, "Reflection ray: ", "Raio de reflexão: ")),
            Math(Formula::RV),
            EQ,
        ];
        line.push(match r.direction {
            Some(d) => Vector(v::<R>(d)),
            None => t(pick(lang, "undefined", "indefinido")),
        });
        out.push(0, line, Some(Ref::Eq("4.17")));
        out.push(
            1,
            weighed(Formula::OR, r.o_r, r.level, Formula::WS, r.weight),
            None,
        );
        out.push(1, vec![verdict(r.level, r.weight, r.stop, "O_r·C_r")], None);
    }
    if let Some(tr) = &x.transmission {
        let f = &tr.refraction;
        let mut line = vec![t(pick(
            lang,
            "Transmitted ray (Snell's law): ",
            "Raio de transmissão (lei de Snell): ",
        ))];
        match f.direction {
            Some(d) => line.extend([Math(Formula::SnellT), EQ, Vector(v::<R>(d))]),
            None => line.push(t(pick(
                lang,
                "none, total internal reflection",
                "nenhum, reflexão interna total",
            ))),
        }
        out.push(0, line, Some(Ref::Sec("4.4")));
        let side = if f.entering {
            pick(
                lang,
                "the ray enters the material (it meets the surface against its own normal): ",
                "o raio entra no material (atinge a superfície contra a sua própria normal): ",
            )
        } else {
            pick(
                lang,
                "the ray leaves the material (it meets the surface along its own normal): ",
                "o raio sai do material (atinge a superfície no sentido da sua própria normal): ",
            )
        };
        let eta_r = f.eta_i / f.eta_t;
        out.push(
            1,
            vec![
                t(side),
                Math(Formula::EtaI),
                EQ,
                Num(f.eta_i.to_f64()),
                t(", "),
                Math(Formula::EtaT),
                EQ,
                Num(f.eta_t.to_f64()),
                t(", "),
                Math(Formula::EtaR),
                EQ,
                Num(eta_r.to_f64()),
            ],
            None,
        );
        out.push(
            1,
            vec![
                Math(Formula::CosThetaI),
                EQ,
                Num(f.cos_i.to_f64()),
                t(", "),
                Math(Formula::SnellK),
                EQ,
                Num(f.k.to_f64()),
            ],
            None,
        );
        if f.direction.is_none() {
            out.push(
                2,
                vec![t(pick(
                    lang,
                    "k < 0: the ray meets the surface beyond the critical angle from the denser \
                     side; Snell's law has no transmitted direction, and no reflection ray \
                     replaces it (the reflection ray comes from O_r alone)",
                    "k < 0: o raio atinge a superfície além do ângulo crítico, vindo do meio \
                     mais denso; a lei de Snell não tem direção transmitida, e nenhum raio de \
                     reflexão a substitui (o raio de reflexão vem apenas de O_r)",
                ))],
                None,
            );
        }
        out.push(
            1,
            weighed(Formula::OT, tr.o_t, tr.level, Formula::WT, tr.weight),
            None,
        );
        out.push(
            1,
            vec![verdict(tr.level, tr.weight, tr.stop, "O_t·C_t")],
            None,
        );
    }
    out.push(
        0,
        vec![t(pick(
            lang,
            messages::SECONDARY_NOT_TRACED,
            messages::SECONDARY_NOT_TRACED_PT,
        ))],
        None,
    );
    out.0
}

/// A material colour as given: "O", or "k·O = k × O".
fn color_spec(c: &ColorSpec) -> Vec<Inline> {
    match c {
        ColorSpec::Scaled(s) => vec![
            Color(c.product()),
            EQ,
            Num(s.k),
            Math(Formula::Times),
            Color(s.color),
        ],
        ColorSpec::Rgb(rgb) => vec![Color(*rgb)],
    }
}

/// The ray of an intersection, for the diagrams: its unit direction and the point's t.
fn ray_mark<R: Real>(x: Option<&Intersection<R>>) -> Option<([f64; 3], f64)> {
    x.and_then(|x| x.t.map(|t| (v::<R>(x.direction), t.to_f64())))
}

fn shading<R: Real>(
    problem: &Problem<R>,
    e: &Evaluation<R>,
    lang: Lang,
    ray: Option<([f64; 3], f64)>,
) -> Shading {
    // What is given.
    let mut given = Steps(Vec::new());
    if let Some(pt) = e.point {
        given.push(0, vec![Math(Formula::P), EQ, Vector(v::<R>(pt))], None);
    }
    if let Some(nu) = &e.normal {
        let mut line = vec![Math(Formula::N), EQ, Vector(v::<R>(nu.used))];
        let unit = crate::core::vector::is_unit_length(nu.length);
        match (unit, nu.reversed) {
            (true, false) => {}
            (true, true) => line.extend([t("  ("), p(Phrase::Reversed, lang), t(")")]),
            (false, reversed) => {
                line.extend([
                    t("  ("),
                    p(Phrase::NormalisedFrom, lang),
                    Vector(v::<R>(nu.given)),
                    t(" ("),
                    p(Phrase::Length, lang),
                    Num(nu.length.to_f64()),
                    t(")"),
                ]);
                if reversed {
                    line.push(p(Phrase::ThenReversed, lang));
                }
                line.push(t(")"));
            }
        }
        given.push(0, line, None);
        // A smooth triangle: where N came from (docs/conventions.md, "Smooth meshes").
        if let Some(s) = &nu.smooth {
            given.push(
                1,
                vec![
                    p(Phrase::SmoothInterpolated, lang),
                    Math(Formula::P),
                    t(": "),
                    Math(Formula::NSmooth),
                ],
                None,
            );
            let b = s.b.map(|x| x.to_f64());
            given.push(2, vec![Math(Formula::Barycentric), EQ, Vector(b)], None);
            let mut corners = Vec::new();
            for (k, symbol) in [Formula::N0, Formula::N1, Formula::N2]
                .into_iter()
                .enumerate()
            {
                if k > 0 {
                    corners.push(t(", "));
                }
                corners.extend([Math(symbol), EQ, Vector(v::<R>(s.vertex[k]))]);
            }
            given.push(2, corners, None);
            given.push(
                2,
                vec![
                    p(Phrase::SmoothGeometric, lang),
                    Math(Formula::NG),
                    EQ,
                    Vector(v::<R>(nu.given)),
                ],
                None,
            );
            if s.clamped {
                given.push(2, vec![p(Phrase::SmoothClamped, lang)], None);
            }
        }
    }
    if let Some(pos) = e.viewer.and_then(|vw| vw.position) {
        given.push(
            0,
            vec![
                p(Phrase::Viewer, lang),
                Math(Formula::E),
                EQ,
                Vector(v::<R>(pos)),
            ],
            None,
        );
    }
    let m = &e.material;
    let name = m
        .name
        .as_deref()
        .map_or(String::new(), |n| format!(" {}", quoted(n)));
    given.push(
        0,
        vec![p(Phrase::Material, lang), t(format!("{name}:"))],
        None,
    );
    let colors = [
        (Formula::OA, &m.spec.ambient, Ref::Eqs("4.5", "4.6")),
        (Formula::OD, &m.spec.diffuse, Ref::Eqs("4.7", "4.8")),
        (Formula::OS, &m.spec.specular, Ref::Eqs("4.9", "4.10")),
    ];
    for (symbol, spec, eq) in colors {
        if let Some(c) = spec {
            let mut line = vec![Math(symbol), EQ];
            line.extend(color_spec(c));
            given.push(1, line, Some(eq));
        }
    }
    if m.spec.shininess.is_some() {
        given.push(
            1,
            vec![Math(Formula::NS), EQ, Num(m.material.n_s.to_f64())],
            Some(Ref::Eq("4.9")),
        );
    }
    if let Some(o_r) = m.material.o_r {
        let mut line = vec![Math(Formula::OR), EQ, Color(v::<R>(o_r))];
        if m.reflectivity == Some(ReflectivitySource::Specular) {
            line.push(p(Phrase::TakenEqualToOs, lang));
        }
        given.push(1, line, Some(Ref::Sec("4.4")));
    }
    if let Some(tr) = m.material.transmission {
        given.push(
            1,
            vec![
                Math(Formula::OT),
                EQ,
                Color(v::<R>(tr.o_t)),
                t(", "),
                Math(Formula::Eta),
                EQ,
                Num(tr.eta.to_f64()),
            ],
            Some(Ref::Sec("4.4")),
        );
    }

    // The steps.
    let mut steps = Steps(Vec::new());
    if let Some(vw) = &e.viewer {
        let how = match vw.source {
            ViewSource::Viewer => vec![Math(Formula::VFromViewer)],
            ViewSource::Ray => vec![Math(Formula::VIsD), p(Phrase::RayIsLineOfSight, lang)],
            ViewSource::ReversedRay => vec![Math(Formula::VIsMinusD), p(Phrase::ReversedRay, lang)],
        };
        let mut line = how;
        line.extend([EQ, Vector(v::<R>(vw.v))]);
        steps.push(0, line, Some(Ref::Eq("4.10")));
        if let (Some(d), Some(side)) = (vw.n_dot_v, vw.side) {
            steps.push(
                1,
                vec![
                    Math(Formula::NDotV),
                    EQ,
                    Num(d.to_f64()),
                    t(": "),
                    t(messages::side(side, lang)),
                ],
                None,
            );
        }
    }
    // Ambient light, Eq. 4.6.
    if let (Some(i_a), Some(term)) = (e.lights_used(problem).ambient, e.shade.ambient) {
        let mut line = vec![Math(Formula::IA), EQ];
        if problem.ambient_info.len() > 1 {
            for (i, a) in problem.ambient_info.iter().enumerate() {
                if i > 0 {
                    line.push(Math(Formula::Plus));
                }
                line.push(Color(v::<R>(a.color)));
            }
            line.push(EQ);
        }
        line.push(Color(v::<R>(i_a)));
        steps.push(0, line, None);
        steps.push(
            0,
            vec![
                p(Phrase::Ambient, lang),
                t(" "),
                Math(Formula::Ambient),
                EQ,
                Color(v::<R>(term)),
            ],
            Some(Ref::Eq("4.6")),
        );
    }
    for o in &e.omitted {
        steps.push(0, vec![t(messages::omission_in(o, lang))], None);
    }
    let mut diagrams = Vec::new();
    for term in &e.lights {
        light(
            &mut steps,
            problem,
            e.lights_used(problem),
            term,
            lang,
            &mut diagrams,
            e,
        );
    }

    for d in &mut diagrams {
        d.ray = ray;
    }

    // The total.
    let mut total = Steps(Vec::new());
    let zero = <V3<R> as crate::core::Vector<R>>::ZERO;
    let labels = [Phrase::Ambient, Phrase::Diffuse, Phrase::Specular];
    let width = labels
        .iter()
        .map(|l| l.get(lang).chars().count())
        .max()
        .unwrap_or(0)
        + 2;
    let values = [
        (e.shade.ambient.unwrap_or(zero), None),
        (e.shade.diffuse, Some(Ref::SumEq("4.8"))),
        (e.shade.specular, Some(Ref::SumEq("4.10"))),
    ];
    for (label, (value, eq)) in labels.iter().zip(values) {
        let word = label.get(lang);
        let pad = width - word.chars().count();
        total.push(
            0,
            vec![t(word), t(" ".repeat(pad)), Color(v::<R>(value))],
            eq,
        );
    }
    total.push(
        0,
        vec![Math(Formula::I), EQ, Color(v::<R>(e.shade.color))],
        Some(Ref::Eq("4.16")),
    );
    total.push(
        0,
        vec![
            p(Phrase::Colour, lang),
            Color(v::<R>(e.clamped)),
            p(Phrase::ClampedTo, lang),
            Inline::Rgb8(e.rgb8),
            Inline::Swatch(e.rgb8),
        ],
        None,
    );
    if let Some(l) = e.shade.literal.filter(|l| *l != e.shade.color) {
        total.push(
            0,
            vec![p(Phrase::LiteralTotal, lang), Vector(v::<R>(l))],
            None,
        );
    }
    Shading {
        given: given.0,
        steps: steps.0,
        total: total.0,
        clamped: v::<R>(e.clamped),
        rgb8: e.rgb8,
        diagrams,
        secondary: Vec::new(),
    }
}

fn light<R: Real>(
    out: &mut Steps,
    problem: &Problem<R>,
    set: &LightSet<R>,
    term: &LightTerm<R>,
    lang: Lang,
    diagrams: &mut Vec<Diagram>,
    e: &Evaluation<R>,
) {
    let l = &set.lights[term.index];
    let info = &problem.light_info[term.index];
    let a = &term.arrival;
    // The light named as a person would ("The yellow light (point) at …"), its kind after it
    // unless its name says it ("The green spot at …").
    let noun = messages::light_noun(problem, info.file_index);
    let name = noun.the(lang);
    let kind = messages::light_kind(info.kind, lang);
    let mut head = vec![t(if name.contains(kind) {
        capitalised(&name)
    } else {
        format!("{} ({kind})", capitalised(&name))
    })];
    match l.kind {
        LightKind::Point { position, .. } => {
            head.extend([t(" "), p(Phrase::At, lang), Vector(v::<R>(position))]);
        }
        LightKind::Spot { position, cone, .. } => head.extend([
            t(" "),
            p(Phrase::At, lang),
            Vector(v::<R>(position)),
            p(Phrase::Axis, lang),
            Math(Formula::DL),
            EQ,
            Vector(v::<R>(cone.axis)),
            t(", "),
            Math(Formula::Gamma),
            EQ,
            Inline::Degrees(cone.angle_deg.to_f64()),
            t(", "),
            Math(Formula::SpotExponent),
            EQ,
            Num(cone.exponent.to_f64()),
        ]),
        LightKind::Directional { direction } => head.extend([
            t(", "),
            p(Phrase::Direction, lang),
            Math(Formula::DL),
            EQ,
            Vector(v::<R>(direction)),
        ]),
    }
    head.extend([t(", "), Math(Formula::CL), EQ, Color(v::<R>(l.color))]);
    out.push(0, head, None);
    if term.status == LightStatus::AtLight {
        out.push(
            1,
            vec![t(messages::light_status_in(term.status, lang))],
            None,
        );
        return;
    }
    let status_line = |out: &mut Steps| {
        out.push(
            1,
            vec![
                p(Phrase::Status, lang),
                t(messages::light_status_in(term.status, lang)),
            ],
            None,
        );
    };
    // Where the light comes from, Eq. 4.1–4.3.
    match (a.distance, a.falloff) {
        (Some(d), Some(f)) => {
            out.push(
                1,
                vec![Math(Formula::LFromLight), EQ, Vector(v::<R>(a.l))],
                Some(Ref::Eq("4.1")),
            );
            out.push(1, vec![Math(Formula::Distance), EQ, Num(d.to_f64())], None);
            let kind = match f {
                Falloff::None => Phrase::FalloffNone,
                Falloff::Linear => Phrase::FalloffLinear,
                Falloff::Quadratic => Phrase::FalloffQuadratic,
            };
            out.push(
                1,
                vec![
                    p(Phrase::Falloff, lang),
                    Math(Formula::F),
                    EQ,
                    Num(f64::from(f.exponent())),
                    t(format!(" ({}): ", kind.get(lang))),
                    Math(Formula::FalloffFactor),
                    EQ,
                    Num(a.falloff_factor.to_f64()),
                ],
                Some(Ref::Eq("4.3")),
            );
        }
        _ => out.push(
            1,
            vec![
                Math(Formula::LIsDl),
                EQ,
                Vector(v::<R>(a.l)),
                p(Phrase::NoFalloff, lang),
            ],
            Some(Ref::Sec("4.2")),
        ),
    }
    // The spot's cone, Eq. 4.4.
    if let Some(c) = &a.cone {
        let verdict = match (c.inside, c.on_edge) {
            (true, true) => Phrase::OnConeEdge,
            (true, false) => Phrase::InsideCone,
            _ => Phrase::OutsideCone,
        };
        let gamma = match l.kind {
            LightKind::Spot { cone, .. } => cone.angle_deg.to_f64(),
            _ => c.cos_gamma.to_f64().acos().to_degrees(),
        };
        out.push(
            1,
            vec![
                Math(Formula::CosPsi),
                EQ,
                Num(c.cos_psi.to_f64()),
                t(", "),
                Math(Formula::Psi),
                EQ,
                Inline::Degrees(c.psi_deg.to_f64()),
                p(Phrase::Versus, lang),
                Math(Formula::Gamma),
                EQ,
                Inline::Degrees(gamma),
                t(": "),
                p(verdict, lang),
            ],
            Some(Ref::Eq("4.4")),
        );
        out.push(
            1,
            vec![
                p(Phrase::SpotFactor, lang),
                Math(Formula::SpotFactor),
                EQ,
                Num(c.factor.to_f64()),
            ],
            Some(Ref::Eq("4.4")),
        );
    }
    // The light arriving at P, Eq. 4.2 or 4.4.
    let (formula, eq) = match (a.cone.is_some(), a.distance.is_some()) {
        (true, _) => (Formula::IlSpot, Ref::Eq("4.4")),
        (false, true) => (Formula::IlPoint, Ref::Eq("4.2")),
        (false, false) => (Formula::IlDirectional, Ref::Sec("4.2")),
    };
    out.push(1, vec![Math(formula), EQ, Color(v::<R>(a.i_l))], Some(eq));
    if term.status == LightStatus::OutsideCone {
        status_line(out);
        return;
    }
    // Diffuse reflection, Eq. 4.7–4.8.
    out.push(
        1,
        vec![
            Math(Formula::NDotL),
            EQ,
            Num(term.n_dot_l.to_f64()),
            t(";  "),
            Math(Formula::CosTheta),
            EQ,
            Num(term.cos_theta.to_f64()),
        ],
        Some(Ref::Eq("4.7")),
    );
    status_line(out);
    if let Some(d) = term.diffuse {
        let mut line = vec![
            p(Phrase::Diffuse, lang),
            t(" "),
            Math(Formula::Diffuse),
            EQ,
            Color(v::<R>(d)),
        ];
        if let Some(lit) = term.diffuse_literal.filter(|l| *l != d) {
            line.extend([p(Phrase::Literally, lang), Vector(v::<R>(lit)), t("]")]);
        }
        out.push(1, line, Some(Ref::Eq("4.8")));
    }
    // Specular reflection, Eq. 4.9–4.15.
    let s = &term.specular;
    match s.status {
        SpecularStatus::NoViewer | SpecularStatus::NoSpecularColor => out.push(
            1,
            vec![
                p(Phrase::Specular, lang),
                t(": "),
                t(messages::specular_status(s.status, lang)),
            ],
            None,
        ),
        _ => {
            if let Some(r) = s.r {
                out.push(
                    1,
                    vec![Math(Formula::R), EQ, Vector(v::<R>(r))],
                    Some(Ref::Eq("4.15")),
                );
            }
            if let Some(c) = s.cos_phi {
                out.push(
                    1,
                    vec![Math(Formula::CosPhi), EQ, Num(c.to_f64())],
                    Some(Ref::Eq("4.10")),
                );
            }
            if let Some(pow) = s.cos_phi_pow {
                out.push(
                    1,
                    vec![Math(Formula::CosPhiPow), EQ, Num(pow.to_f64())],
                    Some(Ref::Eq("4.10")),
                );
            }
            let mut line = vec![
                p(Phrase::Specular, lang),
                t(" "),
                Math(Formula::Specular),
                EQ,
                Color(v::<R>(s.term)),
            ];
            match s.literal {
                Some(lit) if lit != s.term => {
                    line.extend([p(Phrase::Literally, lang), Vector(v::<R>(lit)), t("]")]);
                }
                None if s.cos_phi.is_some() => line.push(p(Phrase::LiterallyUndefined, lang)),
                _ => {}
            }
            out.push(1, line, Some(Ref::Eq("4.10")));
            if s.status != SpecularStatus::Lit {
                out.push(2, vec![t(messages::specular_status(s.status, lang))], None);
            }
        }
    }
    // The plane of incidence, for the diagram.
    if let Some(nu) = &e.normal {
        diagrams.push(Diagram {
            light: name,
            light_index: info.file_index,
            directional: matches!(l.kind, LightKind::Directional { .. }),
            n: v::<R>(nu.used),
            l: v::<R>(a.l),
            r: s.r.map(v::<R>),
            v: e.viewer.map(|vw| v::<R>(vw.v)),
            status: term.status,
            cone: match l.kind {
                LightKind::Spot { cone, .. } => Some((v::<R>(cone.axis), cone.angle_deg.to_f64())),
                _ => None,
            },
            ray: None,
            laid: Default::default(),
        });
    }
}

/// The text of the pieces in Unicode (the plain-text notation), without swatches.
pub fn plain(line: &[Inline]) -> String {
    use crate::text::number::{num, vec3};
    let mut s = String::new();
    for piece in line {
        match piece {
            Inline::Text(x) => s.push_str(x),
            Inline::Math(f) => s.push_str(f.unicode()),
            Inline::Num(x) => s.push_str(&num(*x)),
            Inline::Vector(x) | Inline::Color(x) => s.push_str(&vec3(*x)),
            Inline::Degrees(x) => {
                s.push_str(&num(*x));
                s.push('°');
            }
            Inline::Rgb8([r, g, b]) => s.push_str(&format!("({r}, {g}, {b})")),
            Inline::Swatch(_) => {}
        }
    }
    s
}

/// Steps as a tree: each step with the steps below it (deeper ones), for renderers that nest
/// lists.
pub(crate) struct Node<'a> {
    pub step: &'a Step,
    pub children: Vec<Node<'a>>,
}

/// Nests a flat list of steps by depth.
pub(crate) fn nest(steps: &[Step]) -> Vec<Node<'_>> {
    fn take<'a>(steps: &'a [Step], i: &mut usize, depth: usize) -> Vec<Node<'a>> {
        let mut out = Vec::new();
        while *i < steps.len() && steps[*i].depth >= depth {
            let step = &steps[*i];
            *i += 1;
            let children = take(steps, i, step.depth + 1);
            out.push(Node { step, children });
        }
        out
    }
    let mut i = 0;
    let base = steps.iter().map(|s| s.depth).min().unwrap_or(0);
    take(steps, &mut i, base)
}

/// The language tag of a page or document.
pub(crate) fn language_tag(lang: Lang) -> &'static str {
    pick(lang, "en", "pt-BR")
}

/// A stretch of a line in one notation: words, or a run of math (formulas and the numbers
/// they equal, with the spaces between them), or a swatch.
#[derive(Debug, PartialEq)]
pub(crate) enum Run<'a> {
    Text(String),
    Math(Vec<&'a Inline>),
    Swatch([u8; 3]),
}

/// Splits a line into runs of words and runs of math, so that LaTeX and Markdown put a whole
/// formula with its value in one `$…$`. A piece of blank text between two math pieces stays
/// inside the math.
pub(crate) fn runs(line: &[Inline]) -> Vec<Run<'_>> {
    let is_math = |x: &Inline| {
        matches!(
            x,
            Inline::Math(_)
                | Inline::Num(_)
                | Inline::Vector(_)
                | Inline::Color(_)
                | Inline::Degrees(_)
        )
    };
    let mut out: Vec<Run> = Vec::new();
    for (i, piece) in line.iter().enumerate() {
        let blank_between_math = matches!(piece, Inline::Text(s) if s.trim().is_empty())
            && i > 0
            && is_math(&line[i - 1])
            && line.get(i + 1).is_some_and(is_math);
        if is_math(piece) || blank_between_math {
            match out.last_mut() {
                Some(Run::Math(m)) => m.push(piece),
                _ => out.push(Run::Math(vec![piece])),
            }
            continue;
        }
        let text = match piece {
            Inline::Swatch(rgb) => {
                out.push(Run::Swatch(*rgb));
                continue;
            }
            other => plain(std::slice::from_ref(other)),
        };
        match out.last_mut() {
            Some(Run::Text(s)) => s.push_str(&text),
            _ => out.push(Run::Text(text)),
        }
    }
    out
}

/// `text` with each triple of numbers in parentheses ("(76, 92, 81)", "(0.5, -1, 2)") replaced
/// by `keep(triple)`: how a layout keeps a colour or a vector on one line (an answer key's
/// column is narrow, and "(76, 92," at the end of a line and "81)" on the next reads as two
/// answers).
pub(crate) fn keep_triples(text: &str, keep: impl Fn(&str) -> String) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(open) = rest.find('(') {
        out.push_str(&rest[..open]);
        let after = &rest[open..];
        let triple = after.find(')').map(|close| &after[..=close]).filter(|g| {
            let inner = &g[1..g.len() - 1];
            inner.matches(',').count() == 2
                && inner.contains(' ')
                && inner
                    .chars()
                    .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '−' | ',' | ' ' | 'e'))
        });
        match triple {
            Some(g) => {
                out.push_str(&keep(g));
                rest = &after[g.len()..];
            }
            None => {
                out.push('(');
                rest = &after[1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// A colour clamped to [0, 1] in 8 bits, for a swatch (the solver's and the tracer's rounding).
pub(crate) use crate::core::color::rgb8 as to_rgb8;

/// A number in LaTeX math: "1.5e9" becomes "1.5 \times 10^{9}".
pub(crate) fn latex_number(x: f64) -> String {
    let s = crate::text::number::num(x);
    match s.split_once('e') {
        Some((m, e)) => format!("{m} \\times 10^{{{e}}}"),
        None => s,
    }
}

/// A math run in LaTeX.
pub(crate) fn latex_math(run: &[&Inline]) -> String {
    let mut s = String::new();
    let vector = |x: &[f64; 3]| {
        format!(
            "({}, {}, {})",
            latex_number(x[0]),
            latex_number(x[1]),
            latex_number(x[2])
        )
    };
    for piece in run {
        match piece {
            Inline::Math(f) => s.push_str(f.latex()),
            Inline::Num(x) => s.push_str(&latex_number(*x)),
            Inline::Vector(x) | Inline::Color(x) => s.push_str(&vector(x)),
            Inline::Degrees(x) => {
                s.push_str(&latex_number(*x));
                s.push_str("^\\circ");
            }
            Inline::Text(t) => s.push_str(if t.trim().is_empty() { " " } else { t }),
            Inline::Rgb8(_) | Inline::Swatch(_) => {}
        }
    }
    s.trim().to_owned()
}

#[cfg(test)]
mod tests {
    use super::keep_triples;

    #[test]
    fn a_triple_of_numbers_is_kept_whole_and_nothing_else_is() {
        let mark = |g: &str| format!("[{g}]");
        assert_eq!(
            keep_triples("8 bits (76, 92, 81) and (0.5, -1, 2)", mark),
            "8 bits [(76, 92, 81)] and [(0.5, -1, 2)]"
        );
        // Two numbers, words, or no closing parenthesis: left as they are.
        for text in ["(1, 2)", "(pontual) em", "(a, b, c)", "(1, 2, 3", "f(x)"] {
            assert_eq!(keep_triples(text, mark), text);
        }
    }
}
