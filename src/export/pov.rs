//! A validated scene as POV-Ray 3.7 scene description language (SDL) that computes the same
//! model as `phong render`, so that the two renderers can check each other pixel by pixel.
//!
//! Each part of the chapter's model maps onto POV-Ray 3.7 as follows (every mapping was checked
//! against POV-Ray's source, `source/core/render/trace.cpp`, and by rendering; see
//! `tests/pov_crosscheck.rs`):
//!
//! - **Camera**: `location` E, `direction` the unit forward vector, `right` and `up` the
//!   camera's unit vectors scaled to the image plane's full width and height at distance 1.
//!   No `look_at` or `sky`, so POV-Ray uses the vectors as given: its rays are phong's rays
//!   in phong's own (right-handed) coordinates, and nothing needs mirroring.
//! - **Ambient**: O_a I_a is a constant per material, written as `emission` (which POV-Ray
//!   multiplies by the pigment and the layer's opacity, and not by `ambient_light`);
//!   `ambient 0` everywhere.
//! - **Diffuse**: pigment O_d, `diffuse 1`, brilliance 1: POV-Ray adds
//!   pigment·I_l·cos θ where cos θ ≥ 1e-10 (phong: > 0).
//! - **Specular**: `phong` k, `phong_size` n_s adds k·I_l·(cos φ)^n_s with the same R and
//!   cos φ as Eq. 4.10, gated by cos φ > 0, and not multiplied by the pigment. A grey O_s is
//!   `phong` O_s. A coloured O_s, or an ambient colour where O_d is zero, needs layered
//!   textures: POV-Ray multiplies each layer's light by the product of the transmitted colours
//!   of the layers above it (`filCol`), but not a layer's highlight by its own opacity. So a
//!   layer `rgbf <O_s/p, 1>` over a layer with `phong p` gives the highlight O_s exactly.
//! - **Lights**: a point light is a `light_source`; a spot light adds `spotlight`,
//!   `point_at` P + D_l, `radius` = `falloff` = γ (a hard cone, lit on its edge) and
//!   `tightness` e (POV-Ray multiplies by cos(ψ)^tightness); a directional light is a
//!   `parallel` light placed beyond any point a path can reach ((levels + 1)·1e7 units):
//!   POV-Ray's shadow rays to a parallel light stop at the plane through its location, and a
//!   point on an infinite plane can be far away. POV-Ray's only distance falloff is
//!   2/(1 + (d/D₀)^p): with D₀ tiny and the colour scaled by 1/(2D₀^p) it is
//!   C/(D₀^p + d^p) = C/d^p · 1/(1 + (D₀/d)^p); D₀ is chosen per light from the nearest
//!   surface so that the relative error (D₀/d)^p is at most 1e-9.
//! - **Reflection**: `reflection { rgb O_r }` adds O_r·C_r to the local colour without
//!   dimming it (no `conserve_energy`); the reflected ray's weight is w·max(O_r). POV-Ray
//!   traces a ray while its level ≤ `max_trace_level` (primary = 1) and its weight, rounded
//!   to f32, is ≥ `adc_bailout`; phong traces while w > min_weight, so `adc_bailout` is the
//!   next f32 above the minimum weight.
//! - **Shadows off**: `no_shadow` on every object (a `shadowless` light would also lose its
//!   highlights in POV-Ray).
//!
//! What POV-Ray cannot express is refused with the reason, never approximated: more than one
//! sample per pixel, a scene so large that POV-Ray's 1e7 limit on intersection distances
//! would cut it, a light too bright to scale for the falloff emulation within f32, and
//! recursion settings that POV-Ray's limits (256 levels, weight 1 for primary rays) change.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use glam::DVec3;

use crate::core::light::{Falloff, LightKind};
use crate::core::Material;
use crate::geometry::{Shape, Triangle};
use crate::problem::{Problem, Surface};
use crate::tracer::camera::CameraRays;

/// Why a scene cannot be written as POV-Ray SDL that computes the same image.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{what} cannot be expressed in POV-Ray 3.7: {why}. Fix: {fix}")]
pub struct Unexpressible {
    /// The part of the scene (a material, a light, a setting).
    pub what: String,
    /// Why POV-Ray cannot compute it as phong does.
    pub why: String,
    /// What would make the scene expressible.
    pub fix: String,
}

fn refuse(
    what: impl Into<String>,
    why: impl Into<String>,
    fix: impl Into<String>,
) -> Unexpressible {
    Unexpressible {
        what: what.into(),
        why: why.into(),
        fix: fix.into(),
    }
}

/// POV-Ray ignores intersections farther than this (`MAX_DISTANCE` in its source).
const POV_MAX_DISTANCE: f64 = 1.0e7;
/// The largest `max_trace_level` POV-Ray 3.7 accepts.
const POV_MAX_TRACE_LEVEL: u32 = 256;
/// The relative error allowed in the falloff emulation at the nearest surface point.
const FALLOFF_RELATIVE_ERROR: f64 = 1e-9;

/// The POV-Ray command line that renders an exported scene as phong renders it: no
/// anti-aliasing, highest quality, linear output, no display, quiet.
pub fn povray_args(width: u32, height: u32) -> Vec<String> {
    [
        "-D",
        "-A",
        "+Q9",
        "File_Gamma=1.0",
        "-GA",
        "+GF",
        "-P",
        "-V",
    ]
    .iter()
    .map(|s| s.to_string())
    .chain([format!("+W{width}"), format!("+H{height}")])
    .collect()
}

/// The scene as POV-Ray 3.7 SDL, with the problem's render settings (already overridden by
/// the command line, if at all).
pub fn export(problem: &Problem<f64>) -> Result<String, Unexpressible> {
    let camera = problem.camera.as_ref().ok_or_else(|| {
        refuse(
            "the scene",
            "it has no camera",
            "add \"camera\" to the file",
        )
    })?;
    let settings = problem.render;
    if settings.samples != 1 {
        return Err(refuse(
            "render.samples",
            format!(
                "phong averages {} stratified samples per pixel, and POV-Ray's anti-aliasing \
                 samples differently",
                settings.samples
            ),
            "export with --samples 1 (POV-Ray then traces each pixel's centre, as phong does)",
        ));
    }
    let surfaces = problem.surfaces();
    let extent = scene_extent(problem);
    if extent.radius * 4.0 > POV_MAX_DISTANCE {
        return Err(refuse(
            "the scene",
            format!(
                "it spans {} units around its centre, and POV-Ray ignores intersections \
                 farther than {POV_MAX_DISTANCE:e} units",
                num(extent.radius)
            ),
            "scale the scene down (below 2.5e6 units)",
        ));
    }

    // Recursion: level and weight rule.
    let reflective_max = surfaces
        .iter()
        .filter_map(|s| s.material.material.o_r)
        .map(|o| o.max_element())
        .fold(0.0f64, f64::max);
    let mw = settings.min_weight;
    let (adc, strip_reflection) = if mw >= 1.0 {
        // POV-Ray would stop the primary rays too (their weight is 1); phong still traces them.
        if reflective_max > mw {
            return Err(refuse(
                "render.min_weight",
                format!(
                    "a minimum weight of {} ≥ 1 stops POV-Ray's primary rays, yet phong traces \
                     reflection rays of weight up to {}",
                    num(mw),
                    num(reflective_max)
                ),
                "give a minimum weight below 1",
            ));
        }
        // No reflection ray passes the weight rule: none is traced in either renderer.
        (f64::from(f32_after(0.0)), true)
    } else {
        (f64::from(f32_after(mw)), false)
    };
    let max_level = effective_max_level(settings.max_level, mw, reflective_max)?;

    let mut out = String::new();
    let title = problem.title.as_deref().unwrap_or("a phong scene");
    let _ = writeln!(out, "// {}", sanitize(title));
    let _ = writeln!(
        out,
        "// Written by `phong export-pov`: POV-Ray 3.7 computing the model of `phong render`.\n\
         // Render: povray {} +FP +Oimage.ppm scene.pov",
        povray_args(camera.width, camera.height).join(" ")
    );
    let _ = writeln!(out, "#version 3.7;");
    let _ = writeln!(
        out,
        "global_settings {{ assumed_gamma 1.0 max_trace_level {max_level} adc_bailout {} \
         ambient_light rgb 0 }}",
        num(adc)
    );
    let _ = writeln!(out, "background {{ rgb {} }}", vec3(problem.background));

    // The camera: phong's rays, as vectors.
    let rays = CameraRays::<f64>::new(camera);
    let _ = writeln!(
        out,
        "camera {{ perspective location {} direction {} right {} up {} }}",
        vec3(rays.eye),
        vec3(rays.forward),
        vec3(rays.right * (2.0 * rays.half_width)),
        vec3(rays.up * (2.0 * rays.half_height)),
    );

    // Lights.
    for (i, light) in problem.lights.lights.iter().enumerate() {
        let name = problem
            .light_info
            .get(i)
            .map(|info| match &info.name {
                Some(n) => format!("lights[{}] (\"{}\")", info.file_index, sanitize(n)),
                None => format!("lights[{}]", info.file_index),
            })
            .unwrap_or_else(|| format!("light {i}"));
        let _ = writeln!(out, "// {name}");
        match light.kind {
            LightKind::Directional { direction } => {
                // POV-Ray's shadow rays to a parallel light end at the plane through
                // its location: put it beyond every point a ray can shade (each of the
                // max_level rays of a path travels at most 1e7 units from the eye's side).
                let reach = f64::from(max_level + 1) * POV_MAX_DISTANCE + 2.0 * extent.radius;
                let far = extent.center - direction * reach;
                let _ = writeln!(
                    out,
                    "light_source {{ {} color rgb {} parallel point_at {} }}",
                    vec3(far),
                    vec3(light.color),
                    vec3(far + direction),
                );
            }
            LightKind::Point { position, falloff } => {
                let (color, fade) = fade(&name, light.color, position, falloff, surfaces)?;
                let _ = writeln!(
                    out,
                    "light_source {{ {} color rgb {}{fade} }}",
                    vec3(position),
                    vec3(color)
                );
            }
            LightKind::Spot {
                position,
                falloff,
                cone,
            } => {
                let (color, fade) = fade(&name, light.color, position, falloff, surfaces)?;
                let _ = writeln!(
                    out,
                    "light_source {{ {} color rgb {} spotlight point_at {} radius {} falloff {} \
                     tightness {}{fade} }}",
                    vec3(position),
                    vec3(color),
                    vec3(position + cone.axis),
                    num(cone.angle_deg),
                    num(cone.angle_deg),
                    num(cone.exponent),
                );
            }
        }
    }

    // Materials, each declared once.
    let ambient = problem.lights.ambient;
    let mut textures: Vec<String> = Vec::new();
    let mut by_key: BTreeMap<[u64; 17], usize> = BTreeMap::new();
    let mut surface_texture = Vec::with_capacity(surfaces.len());
    for s in surfaces {
        let key = material_key(&s.material.material);
        let index = match by_key.get(&key) {
            Some(&k) => k,
            None => {
                let what = material_name(s);
                let body = texture(&what, &s.material.material, ambient, adc, strip_reflection)?;
                let k = textures.len();
                let _ = writeln!(out, "// {what}\n#declare T{k} = {body}");
                textures.push(body);
                by_key.insert(key, k);
                k
            }
        };
        surface_texture.push(index);
    }

    // Surfaces; a mesh's triangles (consecutive, from one file entry) become one `mesh`.
    let shadow = if settings.shadows { "" } else { " no_shadow" };
    let mut i = 0;
    while i < surfaces.len() {
        let s = &surfaces[i];
        let t = surface_texture[i];
        match &s.shape {
            Shape::Plane(p) => {
                let _ = writeln!(
                    out,
                    "plane {{ {}, {} texture {{ T{t} }}{shadow} }}",
                    vec3(p.normal),
                    num(p.normal.dot(p.point))
                );
                i += 1;
            }
            Shape::Sphere(sp) => {
                let _ = writeln!(
                    out,
                    "sphere {{ {}, {} texture {{ T{t} }}{shadow} }}",
                    vec3(sp.center),
                    num(sp.radius)
                );
                i += 1;
            }
            Shape::Triangle(tri) if s.source.triangle.is_none() => {
                let _ = writeln!(
                    out,
                    "triangle {{ {}, {}, {} texture {{ T{t} }}{shadow} }}",
                    vec3(tri.p[0]),
                    vec3(tri.p[1]),
                    vec3(tri.p[2])
                );
                i += 1;
            }
            Shape::Triangle(_) => {
                let _ = writeln!(out, "mesh {{");
                let index = s.source.index;
                while i < surfaces.len()
                    && surfaces[i].source.index == index
                    && surfaces[i].source.triangle.is_some()
                {
                    match &surfaces[i].shape {
                        // A smooth face (vertex normals): POV-Ray's smooth_triangle
                        // interpolates them as phong does (docs/conventions.md, "Smooth
                        // meshes").
                        Shape::Triangle(Triangle {
                            p,
                            normals: Some(n),
                        }) => {
                            let _ = writeln!(
                                out,
                                "  smooth_triangle {{ {}, {}, {}, {}, {}, {} }}",
                                vec3(p[0]),
                                vec3(n[0]),
                                vec3(p[1]),
                                vec3(n[1]),
                                vec3(p[2]),
                                vec3(n[2])
                            );
                        }
                        Shape::Triangle(tri) => {
                            let _ = writeln!(
                                out,
                                "  triangle {{ {}, {}, {} }}",
                                vec3(tri.p[0]),
                                vec3(tri.p[1]),
                                vec3(tri.p[2])
                            );
                        }
                        _ => {}
                    }
                    i += 1;
                }
                let _ = writeln!(out, "  texture {{ T{t} }}{shadow}\n}}");
            }
        }
    }
    Ok(out)
}

/// The smallest f32 strictly greater than `x` (x ≥ 0), as POV-Ray rounds a ray's weight to
/// f32 before comparing it with `adc_bailout`.
fn f32_after(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x {
        f
    } else {
        f32::from_bits(f.to_bits() + 1)
    }
}

/// POV-Ray's `max_trace_level` for phong's maximum level: the same number when POV-Ray
/// accepts it, or the deepest level the weight rule lets any ray reach.
fn effective_max_level(
    max_level: u32,
    min_weight: f64,
    reflective_max: f64,
) -> Result<u32, Unexpressible> {
    if max_level <= POV_MAX_TRACE_LEVEL {
        return Ok(max_level);
    }
    if reflective_max == 0.0 {
        return Ok(1);
    }
    // A ray of level k has weight at most reflective_max^(k−1).
    if reflective_max < 1.0 && min_weight > 0.0 {
        let mut k = 1u32;
        let mut w = 1.0f64;
        while k < POV_MAX_TRACE_LEVEL {
            w *= reflective_max;
            if w <= min_weight {
                return Ok(k.min(max_level));
            }
            k += 1;
        }
    }
    Err(refuse(
        "render.max_level",
        format!(
            "phong may trace reflections to level {max_level}, and POV-Ray stops at \
             {POV_MAX_TRACE_LEVEL}"
        ),
        format!(
            "give a maximum level of at most {POV_MAX_TRACE_LEVEL}, or a larger minimum weight"
        ),
    ))
}

/// The centre and radius of a sphere around every finite thing: the eye, the lights, the
/// spheres, the triangles and each plane's given point.
struct Extent {
    center: DVec3,
    radius: f64,
}

fn scene_extent(problem: &Problem<f64>) -> Extent {
    let mut lo = DVec3::splat(f64::INFINITY);
    let mut hi = DVec3::splat(f64::NEG_INFINITY);
    let mut add = |p: DVec3, r: f64| {
        lo = lo.min(p - DVec3::splat(r));
        hi = hi.max(p + DVec3::splat(r));
    };
    if let Some(c) = &problem.camera {
        add(c.eye, 0.0);
    }
    for l in &problem.lights.lights {
        if let Some(p) = l.position() {
            add(p, 0.0);
        }
    }
    for s in problem.surfaces() {
        match &s.shape {
            Shape::Plane(p) => add(p.point, 0.0),
            Shape::Sphere(sp) => add(sp.center, sp.radius),
            Shape::Triangle(t) => t.p.iter().for_each(|&p| add(p, 0.0)),
        }
    }
    if !lo.is_finite() {
        return Extent {
            center: DVec3::ZERO,
            radius: 1.0,
        };
    }
    let center = (lo + hi) * 0.5;
    let radius = ((hi - lo) * 0.5).length().max(f64::MIN_POSITIVE);
    Extent { center, radius }
}

/// A lower bound of the distance from `p` to any surface.
fn nearest_surface(p: DVec3, surfaces: &[Surface<f64>]) -> f64 {
    surfaces
        .iter()
        .map(|s| match &s.shape {
            Shape::Plane(pl) => pl.normal.dot(p - pl.point).abs(),
            Shape::Sphere(sp) => ((p - sp.center).length() - sp.radius).abs(),
            Shape::Triangle(t) => {
                let n = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]);
                let plane = n.normalize_or_zero().dot(p - t.p[0]).abs();
                let c = (t.p[0] + t.p[1] + t.p[2]) / 3.0;
                let r = t.p.iter().map(|&v| (v - c).length()).fold(0.0, f64::max);
                plane.max((p - c).length() - r)
            }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The light's colour and `fade_distance`/`fade_power` that give C/d^f (see the module doc).
fn fade(
    name: &str,
    color: DVec3,
    position: DVec3,
    falloff: Falloff,
    surfaces: &[Surface<f64>],
) -> Result<(DVec3, String), Unexpressible> {
    let f = falloff.exponent();
    if f == 0 {
        return Ok((color, String::new()));
    }
    let nearest = nearest_surface(position, surfaces);
    if !(nearest > 0.0 && nearest.is_finite()) {
        return Err(refuse(
            name,
            "it touches a surface, so its falloff C/d^f grows without bound there, and \
             POV-Ray's fade 2/(1 + (d/D₀)^p) cannot follow it",
            "move the light off the surface",
        ));
    }
    let pf = f64::from(f);
    let d0 = nearest * FALLOFF_RELATIVE_ERROR.powf(1.0 / pf);
    let scaled = color / (2.0 * d0.powf(pf));
    if scaled.max_element() > f64::from(f32::MAX) / 4.0 || (d0 / nearest).powf(pf) > 1e-6 {
        return Err(refuse(
            name,
            "its colour scaled for the falloff emulation (C/(2·D₀^f)) overflows POV-Ray's f32 \
             colours",
            "use a dimmer light or a scene of another scale",
        ));
    }
    Ok((scaled, format!(" fade_distance {} fade_power {f}", num(d0))))
}

fn material_name(s: &Surface<f64>) -> String {
    match &s.material.name {
        Some(n) => format!("material \"{}\"", sanitize(n)),
        None => format!("the material of surfaces[{}]", s.source.index),
    }
}

/// A key that identifies a material exactly (bit patterns of all its numbers).
fn material_key(m: &Material<f64>) -> [u64; 17] {
    let mut k = [0u64; 17];
    let mut put = |at: usize, v: Option<DVec3>| {
        if let Some(v) = v {
            k[at] = 1;
            k[at + 1] = v.x.to_bits();
            k[at + 2] = v.y.to_bits();
            k[at + 3] = v.z.to_bits();
        }
    };
    put(0, m.o_a);
    put(4, m.o_d);
    put(8, m.o_s);
    put(12, m.o_r);
    k[16] = m.n_s.to_bits();
    k
}

/// One material as a POV-Ray texture (see the module doc).
fn texture(
    what: &str,
    m: &Material<f64>,
    ambient_light: Option<DVec3>,
    adc: f64,
    strip_reflection: bool,
) -> Result<String, Unexpressible> {
    let nonzero = |v: Option<DVec3>| v.filter(|v| *v != DVec3::ZERO);
    let amb = match (m.o_a, ambient_light) {
        (Some(a), Some(i)) => nonzero(Some(a * i)),
        _ => None,
    };
    let diffuse = nonzero(m.o_d);
    let specular = nonzero(m.o_s);
    let reflection = if strip_reflection {
        None
    } else {
        nonzero(m.o_r)
    };
    let reflect = reflection
        .map(|r| format!(" reflection {{ rgb {} }}", vec3(r)))
        .unwrap_or_default();
    let phong = |s: f64| format!(" phong {} phong_size {}", num(s), num(m.n_s));
    // The largest colour component written: POV-Ray's colours are f32, with room to add up.
    let limit = f64::from(f32::MAX) / 1e6;
    for (name, v) in [
        ("ambient", amb),
        ("diffuse", diffuse),
        ("specular", specular),
    ] {
        if let Some(v) = v {
            if v.max_element() > limit {
                return Err(refuse(
                    what,
                    format!(
                        "its {name} colour {} overflows POV-Ray's f32 colours",
                        vec3(v)
                    ),
                    "use colours below 1e32",
                ));
            }
        }
    }

    let grey_specular = specular.is_none_or(|s| s.x == s.y && s.y == s.z);
    // One layer needs the emission O_a·I_a / O_d within POV-Ray's colours (a tiny O_d would
    // make it overflow).
    let ambient_fits = match (amb, diffuse) {
        (None, _) | (_, None) => true,
        (Some(a), Some(d)) => (0..3).all(|c| a[c] == 0.0 || (d[c] > 0.0 && a[c] / d[c] <= limit)),
    };
    if grey_specular && ambient_fits {
        // One layer: pigment O_d (white without one), emission O_a·I_a / O_d.
        let pigment = diffuse.unwrap_or(DVec3::ONE);
        let emission = amb.map_or(DVec3::ZERO, |a| {
            DVec3::from_array(std::array::from_fn(|c| {
                if a[c] == 0.0 {
                    0.0
                } else {
                    a[c] / pigment[c]
                }
            }))
        });
        return Ok(format!(
            "texture {{ pigment {{ rgb {} }} finish {{ ambient 0 emission rgb {} diffuse {} \
             brilliance 1{}{} }} }}",
            vec3(pigment),
            vec3(emission),
            if diffuse.is_some() { 1 } else { 0 },
            specular.map(|s| phong(s.x)).unwrap_or_default(),
            reflect,
        ));
    }

    // Layers, top first. Each transparent layer passes t of the light to the layers below
    // it (POV-Ray multiplies by its opacity 1 − t); t² > adc_bailout so POV-Ray does not stop
    // before the last layer.
    let t = ((1.0 + adc) / 2.0).sqrt();
    let mut layers: Vec<String> = Vec::new();
    let mut above = 1.0f64; // the product of the transmitted fractions above this layer
    let scalar: Vec<(DVec3, &str)> = [
        (amb, "emission 1 diffuse 0"),
        (diffuse, "emission 0 diffuse 1"),
    ]
    .into_iter()
    .filter_map(|(v, f)| v.map(|v| (v, f)))
    .collect();
    let n_scalar = scalar.len();
    for (k, (v, finish)) in scalar.into_iter().enumerate() {
        let last = k + 1 == n_scalar && specular.is_none();
        let pigment = if last {
            format!("rgb {}", vec3(v / above))
        } else {
            let p = format!("rgbt <{}, {}>", vec3_inner(v / (above * (1.0 - t))), num(t));
            above *= t;
            p
        };
        layers.push(format!(
            "pigment {{ {pigment} }} finish {{ ambient 0 {finish} }}"
        ));
    }
    if let Some(s) = specular {
        // A filter layer colours every layer below it by O_s/(above·p); the highlight of the
        // last layer, phong p, is then O_s.
        // (At least the smallest normal number: a tiny O_s must not make p zero.)
        let p = (s.max_element() / 100.0).max(f64::MIN_POSITIVE);
        layers.push(format!(
            "pigment {{ rgbf <{}, 1> }} finish {{ ambient 0 emission 0 diffuse 0 }}",
            vec3_inner(s / (above * p))
        ));
        layers.push(format!(
            "pigment {{ rgb 1 }} finish {{ ambient 0 emission 0 diffuse 0{} }}",
            phong(p)
        ));
    }
    if layers.is_empty() {
        layers.push("pigment { rgb 0 } finish { ambient 0 emission 0 diffuse 0 }".into());
    }
    // The reflection belongs to the top layer, whose weight is the ray's own.
    if !reflect.is_empty() {
        let top = layers[0].trim_end_matches(" }").to_owned();
        layers[0] = format!("{top}{reflect} }}");
    }
    // POV-Ray puts the texture written last on top.
    Ok(layers
        .iter()
        .rev()
        .map(|l| format!("texture {{ {l} }}"))
        .collect::<Vec<_>>()
        .join("\n  "))
}

/// A number as POV-Ray reads it back exactly (shortest round-trip form).
fn num(x: f64) -> String {
    let x = if x == 0.0 { 0.0 } else { x };
    format!("{x:?}")
}

fn vec3_inner(v: DVec3) -> String {
    format!("{}, {}, {}", num(v.x), num(v.y), num(v.z))
}

fn vec3(v: DVec3) -> String {
    format!("<{}>", vec3_inner(v))
}

/// Text safe inside a `//` comment.
fn sanitize(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bailout_is_the_next_f32_above_the_minimum_weight() {
        let w = 1.0 / 255.0;
        let a = f32_after(w);
        assert!(f64::from(a) > w);
        let below = f32::from_bits(a.to_bits() - 1);
        assert!(f64::from(below) <= w);
        // An f32 value itself: the next one up.
        assert_eq!(f32_after(0.5), f32::from_bits(0.5f32.to_bits() + 1));
        assert!(f32_after(0.0) > 0.0);
    }

    #[test]
    fn a_level_beyond_povrays_limit_is_cut_where_the_weight_rule_stops_every_ray() {
        // O_r ≤ 0.5 and minimum weight 0.01: 0.5^6 = 0.015625 > 0.01 ≥ 0.5^7, so level 8 is
        // the first a ray can never reach and 7 the deepest traced.
        assert_eq!(effective_max_level(1000, 0.01, 0.5).unwrap(), 7);
        assert_eq!(effective_max_level(5, 0.01, 0.5).unwrap(), 5);
        assert!(effective_max_level(1000, 0.0, 0.5).is_err());
    }

    #[test]
    fn numbers_are_written_so_that_they_read_back_exactly() {
        for x in [0.1, 1.0 / 3.0, 1e-10, 5e35, -2.5, 40.0] {
            assert_eq!(num(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(num(-0.0), "0.0");
    }
}
