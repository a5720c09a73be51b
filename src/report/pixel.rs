//! The report of `phong render --explain-pixel`: the pixel's path ray by ray (level, weight,
//! offset origin, why it stopped), each hit explained by the solver's own report of the
//! equivalent ray problem, as text for people and JSON for scripts.

use std::fmt::Write;

use serde::Serialize;

use super::number::{num, vec3};
use super::{json, text};
use crate::core::real::to_f64_array;
use crate::core::{Real, Vector, V3};
use crate::problem::Problem;
use crate::tracer::explain::{PixelExplanation, RayExplanation};
use crate::tracer::trace::Stop;

fn v<R: Real>(x: V3<R>) -> String {
    vec3(to_f64_array::<R>(x))
}

fn n<R: Real>(x: R) -> String {
    num(x.to_f64())
}

/// Why a path stopped, in words.
pub(crate) fn stop_reason(stop: Stop) -> &'static str {
    match stop {
        Stop::Miss => "the ray hits nothing: its colour is the background",
        Stop::NotReflective => "the surface has no reflectivity O_r: no reflection ray",
        Stop::MaxLevel => "the reflection ray's level would exceed the maximum level",
        Stop::MinWeight => {
            "the reflection ray's weight w_s = w_p·max(O_r) would not exceed the minimum weight"
        }
    }
}

/// The text report.
pub fn render_text<R: Real>(file: &str, problem: &Problem<R>, e: &PixelExplanation<R>) -> String {
    let mut out = String::new();
    let s = &problem.render;
    let [r, g, b] = e.rgb8;
    let _ = writeln!(
        out,
        "Pixel ({}, {}) of {file}: 8-bit colour ({r}, {g}, {b})",
        e.x, e.y
    );
    let _ = writeln!(
        out,
        "Settings: maximum level {}, minimum weight {}, shadows {}, {} sample{} per pixel, {}",
        s.max_level,
        n(s.min_weight),
        if s.shadows { "on" } else { "off" },
        s.samples,
        if s.samples == 1 { "" } else { "s" },
        R::NAME
    );
    for (k, sample) in e.samples.iter().enumerate() {
        let (sx, sy) = sample.position;
        let _ = writeln!(
            out,
            "\nSample {} of {} at ({}, {}) in the pixel",
            k + 1,
            e.samples.len(),
            num(sx),
            num(sy)
        );
        for ray in &sample.rays {
            ray_text(&mut out, file, problem, ray);
        }
        let c = sample.color.to_array().map(|x| x.max(R::ZERO).min(R::ONE));
        let _ = writeln!(
            out,
            "\n  Colour of the path: C = Σ factor·C_local = {}, clamped {}",
            v::<R>(sample.color),
            v::<R>(V3::<R>::new(c[0], c[1], c[2]))
        );
    }
    let _ = writeln!(
        out,
        "\nPixel: the mean of {} clamped sample{}, round(255·c) = ({r}, {g}, {b})",
        e.samples.len(),
        if e.samples.len() == 1 { "" } else { "s" }
    );
    out
}

fn ray_text<R: Real>(out: &mut String, file: &str, problem: &Problem<R>, ray: &RayExplanation<R>) {
    let r = &ray.record;
    let kind = if r.level == 1 {
        "primary"
    } else {
        "reflection"
    };
    let _ = writeln!(
        out,
        "\n  Ray {} ({kind}): level {}, weight w = {}, factor in the pixel {}",
        r.level,
        r.level,
        n(r.weight),
        v::<R>(r.factor)
    );
    match &r.spawn {
        None => {
            let _ = writeln!(out, "    from the eye O = {}", v::<R>(r.ray.origin));
        }
        Some(sp) => {
            let _ = writeln!(
                out,
                "    R_V = V − 2(N·V)N = {}                            (Eq. 4.17)",
                v::<R>(r.ray.direction)
            );
            let _ = writeln!(
                out,
                "    leaves P = {} offset along the surface's normal by the error bound of P \
                 ({}) to O = {}",
                v::<R>(sp.from),
                v::<R>(sp.p_error),
                v::<R>(sp.origin)
            );
        }
    }
    let _ = writeln!(out, "    direction D = {}", v::<R>(r.ray.direction));
    if let Some(solution) = &ray.solution {
        out.push_str(
            "\n    The solver on this ray (`phong solve` of the equivalent ray problem):\n",
        );
        for line in text::render(file, problem, solution).lines() {
            if line.is_empty() {
                out.push('\n');
            } else {
                let _ = writeln!(out, "    │ {line}");
            }
        }
    } else {
        let _ = writeln!(
            out,
            "    hits nothing: C = background = {}",
            v::<R>(r.local)
        );
    }
    if let Some(o_r) = r.o_r {
        let _ = write!(out, "    O_r = {}", v::<R>(o_r));
        if let Some(w) = r.next_weight {
            let _ = write!(out, "; w_s = w_p·max(O_r) = {}", n(w));
        }
        out.push('\n');
    }
    match r.stop {
        Some(stop) => {
            let _ = writeln!(out, "    The path ends here: {}.", stop_reason(stop));
        }
        None => {
            let _ = writeln!(
                out,
                "    A reflection ray follows: level {} ≤ {} and weight {} > {}; it adds O_r·C_r.",
                r.level + 1,
                problem.render.max_level,
                n(r.next_weight.unwrap_or(R::ZERO)),
                n(problem.render.min_weight)
            );
        }
    }
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
    /// Each sample of the pixel, with its path.
    pub samples: Vec<SampleOut<'a, R>>,
    /// The pixel's 8-bit colour, as in the image: round(255·c) of its samples' clamped mean.
    pub rgb8: [u8; 3],
    /// How many rays of each kind the pixel's samples traced.
    pub rays: crate::tracer::Counts,
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
    /// The path's rays, primary first.
    pub rays: Vec<RayOut<'a, R>>,
    /// The path's colour, unclamped: Σ factor·local over its rays.
    pub color: V3<R>,
}

/// An entry of a sample's `rays`: one ray of the path.
#[derive(Serialize)]
pub struct RayOut<'a, R: Real> {
    /// The ray's level: 1 for the primary ray, its parent's + 1 for a reflection ray.
    pub level: u32,
    /// w: 1 for the primary ray, w_p·max(O_r) for a reflection ray.
    pub weight: R,
    /// The product of the O_r of the hits before this ray: its colour's factor in the pixel.
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
    /// Why the path ended at this ray; `null` when a reflection ray follows.
    pub stop: Option<Stop>,
    /// The reason in `stop`, as an English sentence.
    pub stop_message: Option<&'static str>,
    /// The solver's document for the equivalent ray problem (as `phong solve --format json`).
    pub solve: Option<json::Document<'a, R>>,
}

/// `spawned_from`: where a reflection ray left from.
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
    }
}
