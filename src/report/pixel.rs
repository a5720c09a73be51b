//! The report of `phong render --explain-pixel`: the pixel's path ray by ray (level, weight,
//! offset origin, why it stopped), each hit explained by the solver's own report of the
//! equivalent ray problem, the scene said once: as text, Markdown, LaTeX or HTML for people
//! (in English or Portuguese, [`report`] then `write_*`) and JSON for scripts ([`document`]).

use serde::Serialize;

use super::explain::{DataRow, Explanation};
use super::json;
use super::layout::{self, Layout};
use super::messages::{pick, F32Cost, Phrase};
use crate::core::real::to_f64_array;
use crate::core::{Real, Vector, V3};
use crate::problem::Problem;
use crate::solve::CHECK_TOLERANCE;
use crate::text::lang::Lang;
use crate::text::message::{Message, Num};
use crate::text::number::{num, vec3};
use crate::tracer::explain::{PixelExplanation, RayExplanation};
use crate::tracer::trace::{RayKind, RayRecord, Stop, TransmissionRecord};

fn v<R: Real>(x: V3<R>) -> String {
    vec3(to_f64_array::<R>(x))
}

fn n<R: Real>(x: R) -> String {
    num(x.to_f64())
}

/// Why a path stopped, in words (English, as the JSON has it).
pub(crate) fn stop_reason(stop: Stop) -> &'static str {
    stop_reason_in(stop, Lang::En)
}

/// Why a path stopped, in `lang`.
pub(crate) fn stop_reason_in(stop: Stop, lang: Lang) -> &'static str {
    match stop {
        Stop::Miss => pick(
            lang,
            "the ray hits nothing: its colour is the background",
            "o raio não atinge nada: sua cor é a do fundo",
        ),
        Stop::NotReflective => pick(
            lang,
            "the surface has no reflectivity O_r: no reflection ray",
            "a superfície não tem reflexividade O_r: sem raio de reflexão",
        ),
        Stop::MaxLevel => pick(
            lang,
            "the reflection ray's level would exceed the maximum level",
            "o nível de recursão do raio de reflexão passaria do nível máximo",
        ),
        Stop::MinWeight => pick(
            lang,
            "the reflection ray's weight w_s = w_p·max(O_r) would not exceed the minimum weight",
            "o peso do raio de reflexão w_s = w_p·max(O_r) não passaria do peso mínimo",
        ),
        Stop::NotTransmissive => pick(
            lang,
            "the surface's transmissivity O_t is zero: no transmission ray",
            "a transmissividade O_t da superfície é zero: sem raio de transmissão",
        ),
        Stop::TotalInternalReflection => pick(
            lang,
            "total internal reflection: k = 1 − η_r²(1 − cos²θ_i) < 0, the ray meets the surface \
             beyond the critical angle, and Snell's law has no transmitted direction",
            "reflexão interna total: k = 1 − η_r²(1 − cos²θ_i) < 0, o raio atinge a superfície \
             além do ângulo crítico e a lei de Snell não tem direção transmitida",
        ),
    }
}

/// Why a hit spawns no transmission ray, in `lang` (the level and weight rules said of the
/// transmission ray, the others as [`stop_reason_in`] says them).
pub(crate) fn transmission_stop_in(stop: Stop, lang: Lang) -> &'static str {
    match stop {
        Stop::MaxLevel => pick(
            lang,
            "the transmission ray's level would exceed the maximum level",
            "o nível de recursão do raio de transmissão passaria do nível máximo",
        ),
        Stop::MinWeight => pick(
            lang,
            "the transmission ray's weight w_t = w_p·max(O_t) would not exceed the minimum weight",
            "o peso do raio de transmissão w_t = w_p·max(O_t) não passaria do peso mínimo",
        ),
        other => stop_reason_in(other, lang),
    }
}

/// A pixel's explanation, decided once and laid out by every format: the scene said once
/// (title, description, lights and settings), then each sample's rays, each hit explained by
/// the solver (without the scene's title and description, and without a finding an earlier
/// ray already said).
pub struct PixelReport {
    /// The language of every phrase.
    pub lang: Lang,
    /// "Pixel (160, 150) of “Classic …”: 8-bit colour (37, 39, 45)".
    pub title: String,
    /// The scene file's name (and the precision when it is f32).
    pub source: String,
    /// The scene's description.
    pub question: Option<String>,
    /// The scene's lights and viewer, once.
    pub scene: Vec<DataRow>,
    /// The tracer's settings, as one line.
    pub settings: String,
    /// The samples, in order.
    pub samples: Vec<SampleReport>,
    /// How the pixel's colour comes from its samples.
    pub result: String,
    /// In f32: f32 − f64 of the pixel's colour, f64's colour and the check's tolerance
    /// ([`PixelReport::versus`]); `None` in f64.
    pub versus_f64: Option<String>,
    /// In f32, where a channel of the pixel's colour differs from f64's by more than the
    /// check's tolerance: which, by how much, and that `--precision f64` answers it.
    pub warning: Option<String>,
}

/// A pixel explained in f32 against the same pixel explained in f64: the JSON's `versus_f64`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelVersus {
    /// The check's tolerance on the 0–1 scale, [`CHECK_TOLERANCE`].
    pub tolerance: f64,
    /// f64's colour of the pixel: the mean of its samples' colours, each clamped to [0, 1].
    pub f64_color: [f64; 3],
    /// f64's 8-bit colour of the pixel.
    pub f64_rgb8: [u8; 3],
    /// f32 − f64 of the pixel's colour.
    pub color: [f64; 3],
    /// f32 − f64 of the pixel's 8-bit colour.
    pub rgb8: [i16; 3],
}

/// The pixel `e` (explained in f32) against the same pixel `f` explained in f64.
pub fn versus<R: Real>(e: &PixelExplanation<R>, f: &PixelExplanation<f64>) -> PixelVersus {
    PixelVersus {
        tolerance: CHECK_TOLERANCE,
        f64_color: f.color,
        f64_rgb8: f.rgb8,
        color: std::array::from_fn(|i| e.color[i] - f.color[i]),
        rgb8: std::array::from_fn(|i| i16::from(e.rgb8[i]) - i16::from(f.rgb8[i])),
    }
}

impl PixelVersus {
    /// The channels (R, G, B) whose difference exceeds the tolerance.
    pub fn beyond(&self) -> Vec<&'static str> {
        ["R", "G", "B"]
            .into_iter()
            .zip(self.color)
            .filter(|(_, d)| d.abs() > self.tolerance)
            .map(|(name, _)| name)
            .collect()
    }
}

impl PixelReport {
    /// The report with the line under the pixel's colour that compares it with f64's, and the
    /// warning where a channel differs by more than the check's tolerance.
    pub fn versus(mut self, x: &PixelVersus) -> PixelReport {
        let lang = self.lang;
        self.versus_f64 = Some(format!(
            "{}{}{}{}{}{}",
            Phrase::VersusF64.get(lang),
            vec3(x.color),
            Phrase::VersusF64Gives.get(lang),
            vec3(x.f64_color),
            Phrase::VersusF64Tolerance.get(lang),
            num(x.tolerance)
        ));
        let beyond = x.beyond();
        if !beyond.is_empty() {
            let difference = x.color.iter().fold(0.0f64, |m, d| m.max(d.abs()));
            let channels = match beyond.as_slice() {
                [one] => F32Cost::Channel {
                    channel: (*one).to_owned(),
                },
                [rest @ .., last] => F32Cost::Channels {
                    channels: format!("{} {} {last}", rest.join(", "), F32Cost::And.text(lang)),
                },
                [] => unreachable!("a channel differs"),
            };
            let differs = F32Cost::Differs {
                difference: Num(difference),
                tolerance: Num(x.tolerance),
            };
            self.warning = Some(super::explain::capitalised(&format!(
                "{}, {} {}; {}",
                F32Cost::InF32.text(lang),
                differs.text(lang),
                channels.text(lang),
                F32Cost::Fix.text(lang)
            )));
        }
        self
    }
}

/// One sample of a pixel: its rays and the path's colour.
pub struct SampleReport {
    /// "Sample 1 of 1 at (0.5, 0.5) in the pixel".
    pub heading: String,
    /// Its rays, primary first.
    pub rays: Vec<RayReport>,
    /// "Colour of the path: …".
    pub color: String,
}

/// One ray of a path: where it comes from, the solver's explanation of its hit, and what
/// follows.
pub struct RayReport {
    /// "Ray 2 (reflection): level 2, weight w = 0.3, factor in the pixel (0.3, 0.3, 0.3)".
    pub heading: String,
    /// Where the ray comes from and where it goes.
    pub origin: Vec<String>,
    /// The solver's explanation of the equivalent ray problem, when the ray hits a surface.
    pub explanation: Option<Explanation>,
    /// What follows: a miss, O_r and the weight, a reflection ray or the end of the path.
    pub after: Vec<String>,
}

/// Decides a pixel's explanation in `lang`.
pub fn report<R: Real>(
    file: &str,
    problem: &Problem<R>,
    e: &PixelExplanation<R>,
    lang: Lang,
) -> PixelReport {
    let s = &problem.render;
    let [r, g, b] = e.rgb8;
    let mut seen: Vec<String> = Vec::new();
    let scene_x = problem_explanation(file, problem, lang);
    let title = pick(
        lang,
        format!(
            "Pixel ({}, {}) of {}: 8-bit colour ({r}, {g}, {b})",
            e.x, e.y, scene_x.0
        ),
        format!(
            "Pixel ({}, {}) de {}: cor em 8 bits ({r}, {g}, {b})",
            e.x, e.y, scene_x.0
        ),
    );
    let settings = pick(
        lang,
        format!(
            "Settings: maximum level {}, minimum weight {}, shadows {}, {} sample{} per pixel. A \
             ray is traced while its level ≤ {0} (the chapter's \"menor que\" read as ≤), a \
             reflection ray while its weight w_s = w_p·max(O_r) > {1} (the chapter's max(C_r) \
             read as the reflectivity O_r).",
            s.max_level,
            n(s.min_weight),
            if s.shadows { "on" } else { "off" },
            s.samples,
            if s.samples == 1 { "" } else { "s" },
        ),
        format!(
            "Parâmetros: nível máximo de recursão {}, peso mínimo {}, sombras {}, {} amostra{} \
             por pixel. Um raio é traçado enquanto seu nível ≤ {0} (o \"menor que\" do capítulo \
             lido como ≤), um raio de reflexão enquanto seu peso w_s = w_p·max(O_r) > {1} (o \
             max(C_r) do capítulo lido como a reflexividade O_r).",
            s.max_level,
            n(s.min_weight),
            if s.shadows { "ligadas" } else { "desligadas" },
            s.samples,
            if s.samples == 1 { "" } else { "s" },
        ),
    );
    let transmits = problem
        .surfaces()
        .iter()
        .any(|s| s.material.material.transmission.is_some());
    let settings = if transmits {
        let min = n(s.min_weight);
        settings
            + &pick(
                lang,
                format!(
                    " A transmission ray is traced under the same rules, with weight w_t = \
                     w_p·max(O_t) > {min}; total internal reflection spawns none \
                     (docs/conventions.md, \"Transmission\")."
                ),
                format!(
                    " Um raio de transmissão é traçado pelas mesmas regras, com peso w_t = \
                     w_p·max(O_t) > {min}; a reflexão interna total não gera nenhum \
                     (docs/conventions.md, \"Transmission\")."
                ),
            )
    } else {
        settings
    };
    let samples = e
        .samples
        .iter()
        .enumerate()
        .map(|(k, sample)| {
            let (sx, sy) = sample.position;
            let heading = pick(
                lang,
                format!(
                    "Sample {} of {} at ({}, {}) in the pixel",
                    k + 1,
                    e.samples.len(),
                    num(sx),
                    num(sy)
                ),
                format!(
                    "Amostra {} de {} em ({}, {}) no pixel",
                    k + 1,
                    e.samples.len(),
                    num(sx),
                    num(sy)
                ),
            );
            let records: Vec<&RayRecord<R>> = sample.rays.iter().map(|r| &r.record).collect();
            let tree = records.iter().any(|r| r.transmission.is_some());
            let rays = sample
                .rays
                .iter()
                .enumerate()
                .map(|(i, ray)| {
                    let at = Place {
                        index: i,
                        records: &records,
                        tree,
                    };
                    ray_report(file, problem, ray, at, lang, &mut seen)
                })
                .collect();
            let c = sample.color.to_array().map(|x| x.max(R::ZERO).min(R::ONE));
            let clamped = v::<R>(V3::<R>::new(c[0], c[1], c[2]));
            let color = match tree {
                false => pick(
                    lang,
                    format!(
                        "Colour of the path: C = Σ factor·C_local = {}, clamped {clamped}",
                        v::<R>(sample.color)
                    ),
                    format!(
                        "Cor do caminho: C = Σ fator·C_local = {}, limitada {clamped}",
                        v::<R>(sample.color)
                    ),
                ),
                true => pick(
                    lang,
                    format!(
                        "Colour of the ray tree: C = Σ factor·C_local over its {} rays = {}, \
                         clamped {clamped}",
                        records.len(),
                        v::<R>(sample.color)
                    ),
                    format!(
                        "Cor da árvore de raios: C = Σ fator·C_local sobre seus {} raios = {}, \
                         limitada {clamped}",
                        records.len(),
                        v::<R>(sample.color)
                    ),
                ),
            };
            SampleReport {
                heading,
                rays,
                color,
            }
        })
        .collect();
    let count = e.samples.len();
    let result = pick(
        lang,
        format!(
            "Pixel: the mean of {count} clamped sample{}, round(255·c) = ({r}, {g}, {b})",
            if count == 1 { "" } else { "s" }
        ),
        format!(
            "Pixel: a média de {count} amostra{} limitada{}, round(255·c) = ({r}, {g}, {b})",
            if count == 1 { "" } else { "s" },
            if count == 1 { "" } else { "s" }
        ),
    );
    PixelReport {
        lang,
        title,
        source: scene_x.1,
        question: match lang {
            Lang::Pt => problem
                .question_pt
                .as_deref()
                .or(problem.question.as_deref()),
            Lang::En => problem.question.as_deref(),
        }
        .map(str::to_owned),
        scene: scene_x.2,
        settings,
        samples,
        result,
        versus_f64: None,
        warning: None,
    }
}

/// The scene's title (quoted), source line and data rows, from an explanation of no solution.
fn problem_explanation<R: Real>(
    file: &str,
    problem: &Problem<R>,
    lang: Lang,
) -> (String, String, Vec<DataRow>) {
    let title = match lang {
        Lang::Pt => problem.title_pt.clone().or_else(|| problem.title.clone()),
        Lang::En => problem.title.clone(),
    };
    let name = std::path::Path::new(file)
        .file_name()
        .map_or_else(|| file.to_owned(), |n| n.to_string_lossy().into_owned());
    let source = if R::NAME == "f64" {
        name.clone()
    } else {
        format!("{name}, {}", R::NAME)
    };
    let title = title.map_or(name, |t| super::explain::quoted(&t));
    (title, source, super::explain::data_rows(problem, lang))
}

/// Where a ray stands in its sample's tree: its index among the records (breadth first), the
/// records, and whether the tree branches anywhere (a material transmits): a chain's rays are
/// said as before, a tree's name their parent and children.
#[derive(Clone, Copy)]
struct Place<'a, R: Real> {
    index: usize,
    records: &'a [&'a RayRecord<R>],
    tree: bool,
}

impl<R: Real> Place<'_, R> {
    /// The number (from 1) of this ray's child of `kind`, when it was traced.
    fn child(&self, kind: RayKind) -> Option<usize> {
        self.records
            .iter()
            .position(|r| r.parent == Some(self.index as u32) && r.kind == kind)
            .map(|j| j + 1)
    }
}

fn ray_report<R: Real>(
    file: &str,
    problem: &Problem<R>,
    ray: &RayExplanation<R>,
    at: Place<'_, R>,
    lang: Lang,
    seen: &mut Vec<String>,
) -> RayReport {
    let r = &ray.record;
    let kind = match (r.kind, lang) {
        (RayKind::Primary, Lang::En) => "primary",
        (RayKind::Reflection, Lang::En) => "reflection",
        (RayKind::Transmission, Lang::En) => "transmission",
        (RayKind::Primary, Lang::Pt) => "primário",
        (RayKind::Reflection, Lang::Pt) => "de reflexão",
        (RayKind::Transmission, Lang::Pt) => "de transmissão",
    };
    let number = at.index + 1;
    let from = match (at.tree, r.parent) {
        (true, Some(p)) => pick(
            lang,
            format!(", from ray {}", p + 1),
            format!(", do raio {}", p + 1),
        ),
        _ => String::new(),
    };
    let heading = pick(
        lang,
        format!(
            "Ray {number} ({kind}{from}): level {}, weight w = {}, factor in the pixel {}",
            r.level,
            n(r.weight),
            v::<R>(r.factor)
        ),
        format!(
            "Raio {number} ({kind}{from}): nível {}, peso w = {}, fator no pixel {}",
            r.level,
            n(r.weight),
            v::<R>(r.factor)
        ),
    );
    let mut origin = Vec::new();
    match &r.spawn {
        None => origin.push(pick(
            lang,
            format!("from the eye O = {}", v::<R>(r.ray.origin)),
            format!("parte do olho O = {}", v::<R>(r.ray.origin)),
        )),
        Some(sp) => {
            let parent = r.parent.and_then(|p| at.records.get(p as usize));
            let refraction = parent.and_then(|p| p.transmission);
            match (r.kind, refraction) {
                (RayKind::Transmission, Some(t)) => {
                    let f = t.refraction;
                    origin.push(pick(
                        lang,
                        format!(
                            "T = η_r V + (η_r cos θ_i − √k) N = {}  (Snell's law, η_r = η_i/η_t \
                             = {}/{})",
                            v::<R>(r.ray.direction),
                            n(f.eta_i),
                            n(f.eta_t)
                        ),
                        format!(
                            "T = η_r V + (η_r cos θ_i − √k) N = {}  (lei de Snell, η_r = η_i/η_t \
                             = {}/{})",
                            v::<R>(r.ray.direction),
                            n(f.eta_i),
                            n(f.eta_t)
                        ),
                    ));
                }
                _ => origin.push(format!(
                    "R_V = V − 2(N·V)N = {}  (Eq. 4.17)",
                    v::<R>(r.ray.direction)
                )),
            }
            let side = match r.kind {
                RayKind::Transmission => pick(
                    lang,
                    " (to the side it goes to: through the surface)",
                    " (para o lado para onde vai: através da superfície)",
                ),
                _ => "",
            };
            origin.push(pick(
                lang,
                format!(
                    "leaves P = {} offset along the surface's normal by the error bound of P ({}) \
                     to O = {}{side}",
                    v::<R>(sp.from),
                    v::<R>(sp.p_error),
                    v::<R>(sp.origin)
                ),
                format!(
                    "parte de P = {} deslocado ao longo da normal da superfície pela cota do erro \
                     de P ({}) para O = {}{side}",
                    v::<R>(sp.from),
                    v::<R>(sp.p_error),
                    v::<R>(sp.origin)
                ),
            ));
        }
    }
    origin.push(pick(
        lang,
        format!("direction D = {}", v::<R>(r.ray.direction)),
        format!("direção D = {}", v::<R>(r.ray.direction)),
    ));
    let explanation = ray.solution.as_ref().map(|solution| {
        let mut x = super::explain::explain(file, problem, solution, lang);
        x.question = None;
        x.findings.retain(|f| !seen.contains(f));
        seen.extend(x.findings.iter().cloned());
        x
    });
    let mut after = Vec::new();
    if ray.solution.is_none() {
        after.push(pick(
            lang,
            format!("hits nothing: C = background = {}", v::<R>(r.local)),
            format!("não atinge nada: C = fundo = {}", v::<R>(r.local)),
        ));
    }
    if let Some(o_r) = r.o_r {
        let mut line = format!("O_r = {}", v::<R>(o_r));
        if let Some(w) = r.next_weight {
            line.push_str(&format!("; w_s = w_p·max(O_r) = {}", n(w)));
        }
        after.push(line);
    }
    let (max, min) = (problem.render.max_level, n(problem.render.min_weight));
    let level = r.level + 1;
    // A chain's last ray says the path ends; a tree's rays say each child by itself.
    let ends = !at.tree || r.hit.is_none();
    after.push(match r.stop {
        Some(stop) if at.tree && ends => pick(
            lang,
            format!(
                "This branch of the tree ends here: {}.",
                stop_reason_in(stop, lang)
            ),
            format!(
                "Este ramo da árvore termina aqui: {}.",
                stop_reason_in(stop, lang)
            ),
        ),
        Some(stop) if ends => pick(
            lang,
            format!("The path ends here: {}.", stop_reason_in(stop, lang)),
            format!("O caminho termina aqui: {}.", stop_reason_in(stop, lang)),
        ),
        Some(stop) => pick(
            lang,
            format!("No reflection ray: {}.", stop_reason_in(stop, lang)),
            format!("Sem raio de reflexão: {}.", stop_reason_in(stop, lang)),
        ),
        None => {
            let w = n(r.next_weight.unwrap_or(R::ZERO));
            let which = match (at.tree, at.child(RayKind::Reflection)) {
                (true, Some(k)) => pick(lang, format!(" (ray {k})"), format!(" (raio {k})")),
                _ => String::new(),
            };
            pick(
                lang,
                format!(
                    "A reflection ray follows{which}: level {level} ≤ {max} and weight {w} > \
                     {min}; it adds O_r·C_r."
                ),
                format!(
                    "Segue um raio de reflexão{which}: nível {level} ≤ {max} e peso {w} > {min}; \
                     ele soma O_r·C_r."
                ),
            )
        }
    });
    if let Some(t) = &r.transmission {
        after.extend(transmission_lines(t, &at, (level, max, &min), lang));
    }
    if at.tree && r.hit.is_some() && r.is_leaf() {
        after.push(pick(
            lang,
            "This branch of the tree ends here.".to_owned(),
            "Este ramo da árvore termina aqui.".to_owned(),
        ));
    }
    RayReport {
        heading,
        origin,
        explanation,
        after,
    }
}

/// What a hit's transmission says: O_t and the weight, Snell's law there, and the transmission
/// ray that follows or why none does. `next` is the child's level, the maximum level and the
/// minimum weight.
fn transmission_lines<R: Real>(
    t: &TransmissionRecord<R>,
    at: &Place<'_, R>,
    next: (u32, u32, &str),
    lang: Lang,
) -> Vec<String> {
    let (level, max, min) = next;
    let f = &t.refraction;
    let mut lines = vec![format!(
        "O_t = {}; w_t = w_p·max(O_t) = {}",
        v::<R>(t.o_t),
        n(t.weight)
    )];
    let (side_en, side_pt) = if f.entering {
        (
            "the ray enters the material (it meets the surface against its normal)",
            "o raio entra no material (atinge a superfície contra a sua normal)",
        )
    } else {
        (
            "the ray leaves the material (it meets the surface along its normal)",
            "o raio sai do material (atinge a superfície no sentido da sua normal)",
        )
    };
    lines.push(pick(
        lang,
        format!(
            "Snell's law: {side_en}, η_i = {}, η_t = {}; cos θ_i = −N·V = {}; k = 1 − \
             η_r²(1 − cos²θ_i) = {}",
            n(f.eta_i),
            n(f.eta_t),
            n(f.cos_i),
            n(f.k)
        ),
        format!(
            "Lei de Snell: {side_pt}, η_i = {}, η_t = {}; cos θ_i = −N·V = {}; k = 1 − \
             η_r²(1 − cos²θ_i) = {}",
            n(f.eta_i),
            n(f.eta_t),
            n(f.cos_i),
            n(f.k)
        ),
    ));
    lines.push(match t.stop {
        Some(stop) => pick(
            lang,
            format!("No transmission ray: {}.", transmission_stop_in(stop, lang)),
            format!(
                "Sem raio de transmissão: {}.",
                transmission_stop_in(stop, lang)
            ),
        ),
        None => {
            let which = match at.child(RayKind::Transmission) {
                Some(k) => pick(lang, format!(" (ray {k})"), format!(" (raio {k})")),
                None => String::new(),
            };
            let w = n(t.weight);
            pick(
                lang,
                format!(
                    "A transmission ray follows{which}: level {level} ≤ {max} and weight {w} > \
                     {min}; it adds O_t·C_t."
                ),
                format!(
                    "Segue um raio de transmissão{which}: nível {level} ≤ {max} e peso {w} > \
                     {min}; ele soma O_t·C_t."
                ),
            )
        }
    });
    lines
}

/// The text report, in English.
pub fn render_text<R: Real>(file: &str, problem: &Problem<R>, e: &PixelExplanation<R>) -> String {
    write_text(&report(file, problem, e, Lang::En))
}

/// A pixel's explanation through `layout`, walked once: the scene (level 1), each sample
/// (level 2) and each of its rays (level 3), a ray's hit explained by the solver with its
/// headings at level 4.
pub fn write(layout: &dyn Layout, p: &PixelReport) -> String {
    let mut out = layout.open(1, "pixel");
    out.push_str(&layout.head(&p.title, &p.source, p.question.as_deref()));
    out.push_str(&layout.data(&p.scene, p.lang));
    out.push_str(&layout.paragraph(1, &p.settings));
    let mut index = 0;
    for sample in &p.samples {
        out.push_str(&layout.heading(2, &sample.heading));
        for ray in &sample.rays {
            out.push_str(&layout.open(3, "ray"));
            out.push_str(&layout.heading(3, &ray.heading));
            out.push_str(&layout.list(3, &ray.origin));
            if let Some(x) = &ray.explanation {
                out.push_str(&layout.parts(x, 4, index));
                index += 1;
            }
            out.push_str(&layout.list(3, &ray.after));
            out.push_str(&layout.close(3));
        }
        out.push_str(&layout.strong(2, &sample.color));
    }
    out.push_str(&layout.strong(1, &p.result));
    for line in [&p.versus_f64, &p.warning].into_iter().flatten() {
        out.push_str(&layout.paragraph(1, line));
    }
    out.push_str(&layout.close(1));
    layout.finish(out, &p.title, p.lang)
}

/// A pixel's explanation as text.
pub fn write_text(p: &PixelReport) -> String {
    write(&layout::Text { color: false }, p)
}

/// A pixel's explanation as Markdown.
pub fn write_markdown(p: &PixelReport) -> String {
    write(&layout::Markdown, p)
}

/// A pixel's explanation as LaTeX: a document, or (`fragment`) its body.
pub fn write_latex(p: &PixelReport, options: super::latex::LatexOptions) -> String {
    write(&layout::Latex(options), p)
}

/// A pixel's explanation as HTML: a page, or (`fragment`) its body.
pub fn write_html(p: &PixelReport, options: super::html::HtmlOptions) -> String {
    write(&layout::Html(options), p)
}

/// The JSON document.
#[derive(Serialize)]
pub struct PixelOut<'a, R: Real> {
    /// The version of the format, the solver's [`json::FORMAT_VERSION`] (1).
    pub format_version: u32,
    /// The scene file's path, as given.
    pub file: String,
    /// "f32" or "f64".
    pub precision: &'static str,
    /// The pixel explained, `[x, y]`, from the image's top-left corner.
    pub pixel: [u32; 2],
    /// The tracer's settings the pixel was traced with.
    pub settings: SettingsOut<R>,
    /// Each sample of the pixel, with its ray tree.
    pub samples: Vec<SampleOut<'a, R>>,
    /// The pixel's 8-bit colour, as in the image: round(255·c) of its samples' clamped mean.
    pub rgb8: [u8; 3],
    /// How many rays of each kind the pixel's samples traced.
    pub rays: crate::tracer::Counts,
    /// In f32 only: the same pixel explained in f64, its colour and f32 − f64 of the pixel's
    /// colour and 8-bit colour, with the check's tolerance; absent in f64.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub versus_f64: Option<PixelVersus>,
}

/// `settings`: how rays were traced (Section 4.4).
#[derive(Serialize)]
pub struct SettingsOut<R: Real> {
    /// Rays are traced while their level ≤ this; the primary ray has level 1.
    pub max_level: u32,
    /// A reflection ray is traced only while its weight exceeds this.
    pub min_weight: R,
    /// Whether shadow rays were traced.
    pub shadows: bool,
    /// Samples per pixel.
    pub samples: u32,
}

/// An entry of `samples`: one sample of the pixel and its path.
#[derive(Serialize)]
pub struct SampleOut<'a, R: Real> {
    /// (sx, sy) in [0, 1)², from the pixel's top-left corner.
    pub position: [f64; 2],
    /// The tree's rays, primary first, breadth first.
    pub rays: Vec<RayOut<'a, R>>,
    /// The path's colour, unclamped: Σ factor·local over its rays.
    pub color: V3<R>,
}

/// An entry of a sample's `rays`: one ray of the tree, breadth first (reflection before
/// transmission at each hit).
#[derive(Serialize)]
pub struct RayOut<'a, R: Real> {
    /// "primary", "reflection" or "transmission".
    pub kind: RayKind,
    /// The index in `rays` of the ray it was spawned from; `null` for the primary ray.
    pub parent: Option<u32>,
    /// The ray's level: 1 for the primary ray, its parent's + 1 for a secondary ray.
    pub level: u32,
    /// w: 1 for the primary ray, w_p·max(O_r) for a reflection ray, w_p·max(O_t) for a
    /// transmission ray.
    pub weight: R,
    /// The product of the O_r and O_t on the way from the primary ray: its colour's factor in
    /// the pixel.
    pub factor: V3<R>,
    /// The ray's origin.
    pub origin: V3<R>,
    /// The ray's direction, unit.
    pub direction: V3<R>,
    /// For a reflection ray: the hit point it leaves, that point's error bound, the surface's
    /// own normal, and the offset origin.
    pub spawned_from: Option<SpawnOut<R>>,
    /// Whether the ray hits a surface.
    pub hit: bool,
    /// The local colour (Eq. 4.16) at the hit, or the background.
    pub local: V3<R>,
    /// O_r at the hit; `null` when the material has none (or the ray hits nothing).
    pub reflectivity: Option<V3<R>>,
    /// The weight a reflection ray from this hit would have; `null` when there is none to
    /// weigh.
    pub next_weight: Option<R>,
    /// Why no reflection ray follows this one ("miss" on a miss); `null` when one does.
    pub stop: Option<Stop>,
    /// The reason in `stop`, as an English sentence.
    pub stop_message: Option<&'static str>,
    /// The transmission at the hit, as a ray problem's `secondary_rays.transmission`; `null`
    /// when the material has no transmissivity.
    pub transmission: Option<json::TransmittedOut<R>>,
    /// The solver's document for the equivalent ray problem (as `phong solve --format json`).
    pub solve: Option<json::Document<'a, R>>,
}

/// `spawned_from`: where a secondary ray left from.
#[derive(Serialize)]
pub struct SpawnOut<R: Real> {
    /// The hit point it leaves.
    pub point: V3<R>,
    /// The bound on the error of each component of that point.
    pub point_error: V3<R>,
    /// The surface's own normal there (not turned to face the ray).
    pub normal: V3<R>,
    /// The ray's origin: the point offset along the normal by its error bound, rounded outward.
    pub origin: V3<R>,
}

/// The JSON document of a pixel's explanation.
pub fn document<'a, R: Real>(
    file: &str,
    problem: &'a Problem<R>,
    e: &'a PixelExplanation<R>,
) -> PixelOut<'a, R> {
    let s = &problem.render;
    PixelOut {
        format_version: json::FORMAT_VERSION,
        file: file.to_owned(),
        precision: R::NAME,
        pixel: [e.x, e.y],
        settings: SettingsOut {
            max_level: s.max_level,
            min_weight: s.min_weight,
            shadows: s.shadows,
            samples: s.samples,
        },
        samples: e
            .samples
            .iter()
            .map(|sample| SampleOut {
                position: [sample.position.0, sample.position.1],
                color: sample.color,
                rays: sample
                    .rays
                    .iter()
                    .map(|ray| {
                        let r = &ray.record;
                        RayOut {
                            kind: r.kind,
                            parent: r.parent,
                            level: r.level,
                            weight: r.weight,
                            factor: r.factor,
                            origin: r.ray.origin,
                            direction: r.ray.direction,
                            spawned_from: r.spawn.map(|sp| SpawnOut {
                                point: sp.from,
                                point_error: sp.p_error,
                                normal: sp.normal,
                                origin: sp.origin,
                            }),
                            hit: r.hit.is_some(),
                            local: r.local,
                            reflectivity: r.o_r,
                            next_weight: r.next_weight,
                            stop: r.stop,
                            stop_message: r.stop.map(stop_reason),
                            transmission: r.transmission.map(|t| {
                                json::transmitted(
                                    t.o_t,
                                    t.refraction,
                                    r.level + 1,
                                    t.weight,
                                    t.stop,
                                )
                            }),
                            solve: ray
                                .solution
                                .as_ref()
                                .map(|sol| json::document(file, problem, sol)),
                        }
                    })
                    .collect(),
            })
            .collect(),
        rgb8: e.rgb8,
        rays: e.counts,
        versus_f64: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn empty(lang: Lang) -> PixelReport {
        PixelReport {
            lang,
            title: String::new(),
            source: String::new(),
            question: None,
            scene: Vec::new(),
            settings: String::new(),
            samples: Vec::new(),
            result: String::new(),
            versus_f64: None,
            warning: None,
        }
    }

    fn differing(color: [f64; 3]) -> PixelVersus {
        PixelVersus {
            tolerance: CHECK_TOLERANCE,
            f64_color: [0.5; 3],
            f64_rgb8: [128; 3],
            color,
            rgb8: [0; 3],
        }
    }

    #[test]
    fn a_channel_beyond_the_tolerance_is_warned_of_by_name() {
        let t = CHECK_TOLERANCE;
        let one = differing([0.0, -2.0 * t, t]);
        assert_eq!(one.beyond(), ["G"]);
        let en = empty(Lang::En).versus(&one);
        let warning = en.warning.expect("a warning");
        assert!(warning.starts_with("In f32, the colour differs from f64's by"));
        assert!(
            warning.contains("in channel G; --precision f64 answers it"),
            "{warning}"
        );
        let pt = empty(Lang::Pt).versus(&differing([3.0 * t, 0.0, -2.0 * t]));
        let warning = pt.warning.expect("um aviso");
        assert!(warning.contains("nos canais R e B;"), "{warning}");
        assert!(
            warning.ends_with("--precision f64 dá a resposta certa"),
            "{warning}"
        );
        // Within the tolerance: the line under the colour, no warning.
        let within = empty(Lang::En).versus(&differing([t, -t, 0.0]));
        assert!(within.warning.is_none());
        let line = within.versus_f64.expect("the line");
        assert!(line.starts_with("f32 − f64 of the colour: ("), "{line}");
    }

    #[test]
    fn the_warning_follows_the_line_under_the_pixels_colour_in_every_format() {
        let p = empty(Lang::En).versus(&differing([0.0, 0.0, 0.5]));
        for out in [write_text(&p), write_markdown(&p)] {
            let line = out.find("f32 − f64 of the colour").expect("the line");
            let warning = out.find("In f32, the colour differs").expect("the warning");
            assert!(line < warning, "{out}");
        }
    }
}
