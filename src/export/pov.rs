//! A validated scene as POV-Ray 3.7 scene description language (SDL) that computes the same
//! model as `phong render`, so that the two renderers can check each other pixel by pixel.
//!
//! Each part of the chapter's model maps onto POV-Ray 3.7 as follows (every mapping was checked
//! against POV-Ray's source, `source/core/render/trace.cpp`, and by rendering; see
//! `tests/integration/pov_crosscheck.rs`):
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
//! - **Transmission** (docs/conventions.md, "Transmission", "POV-Ray"): `interior { ior η }`
//!   and a pigment that lets O_t through. POV-Ray (`ComputeLightedTexture` in
//!   `source/backend/render/trace.cpp`) multiplies a layer's emission and diffuse light by the
//!   layer's opacity 1 − filter − transmit (not its `phong` highlight, not its reflection),
//!   adds the refracted colour times the product of the layers' `rgb·filter + transmit`
//!   (`filCol`) and traces the refracted ray with weight w·max(filCol). A grey O_t = T < 1 is
//!   one layer `rgbt <O_d/(1 − T), T>`: the opacity undoes the division, the transmitted
//!   colour is T·C_t, the weight w·T. Any other O_t is layers: the local ones each passing t,
//!   then a last `rgbf <O_t/above, 1>` layer, so that filCol = O_t. With shadows on, the
//!   transmitting object has `no_shadow` (POV-Ray would let coloured light through it) and an
//!   identical black copy with `no_image no_reflection` blocks the shadow rays: POV-Ray hides
//!   a `no_image` object from primary and refracted rays and a `no_reflection` one from every
//!   ray that has been reflected (`NoSomethingFlagRayObjectCondition`, `Ray::IsImageRay`), so
//!   the copy is seen by shadow rays only. What POV-Ray computes otherwise is refused:
//!   total internal reflection (POV-Ray traces a reflection ray there, with the transmission's
//!   weight, and drops the surface's own reflection), so only a sphere or a plane with η ≥ 1,
//!   seen from outside, that no reflecting or transmitting surface enters, may transmit; and
//!   an O_t whose greyscale POV-Ray's gate `trans > adc_bailout` would stop while phong
//!   traces the ray.
//!
//! What POV-Ray cannot express is refused with the reason, never approximated: more than one
//! sample per pixel, a transmitting surface where total internal reflection could occur, a
//! scene so large that POV-Ray's 1e7 limit on intersection distances would cut it, a light
//! too bright to scale for the falloff emulation within f32, and recursion settings that
//! POV-Ray's limits (256 levels, weight 1 for primary rays) change.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use glam::DVec3;

use crate::core::light::{Falloff, LightKind};
use crate::core::material::Transmission;
use crate::core::Material;
use crate::geometry::{Shape, Triangle};
use crate::problem::{Problem, Surface};
use crate::text::{Fault, Lang, Num, Show};
use crate::tracer::camera::CameraRays;

/// Why a scene cannot be written as POV-Ray SDL that computes the same image.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{what} cannot be expressed in POV-Ray 3.7: {}. Fix: {}", .fault.what(Lang::En), .fault.fix(Lang::En))]
pub struct Unexpressible {
    /// The part of the scene (a material, a light, a setting).
    pub what: String,
    /// Why POV-Ray cannot compute it as phong does, and what would make the scene expressible.
    pub fault: PovFault,
}

impl Unexpressible {
    /// Why POV-Ray cannot compute it as phong does, in English.
    pub fn why(&self) -> String {
        self.fault.what(Lang::En)
    }

    /// What would make the scene expressible, in English.
    pub fn fix(&self) -> String {
        self.fault.fix(Lang::En)
    }
}

fn refuse(what: impl Into<String>, fault: PovFault) -> Unexpressible {
    Unexpressible {
        what: what.into(),
        fault,
    }
}

/// A part of a scene that cannot be expressed in POV-Ray, as a problem's error says it:
/// `cannot be expressed in POV-Ray 3.7: WHY`, and the fix.
#[derive(Debug, Clone, PartialEq)]
pub struct Unexpressed(pub PovFault);

impl Fault for Unexpressed {
    fn what(&self, lang: Lang) -> String {
        match lang {
            Lang::En => format!("cannot be expressed in POV-Ray 3.7: {}", self.0.what(lang)),
            Lang::Pt => format!(
                "não pode ser expresso em POV-Ray 3.7: {}",
                self.0.what(lang)
            ),
        }
    }

    fn fix(&self, lang: Lang) -> String {
        self.0.fix(lang)
    }
}

/// Total internal reflection, and why it differs between POV-Ray and phong.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tir;

impl Show for Tir {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match lang {
            Lang::En => {
                "total internal reflection, where POV-Ray traces a reflection ray in place of \
                 the transmitted one and phong adds nothing"
            }
            Lang::Pt => {
                "reflexão interna total, onde o POV-Ray traça um raio de reflexão em lugar do \
                 transmitido e phong não acrescenta nada"
            }
        })
    }
}

crate::messages! {
    /// A colour of a material, named in an error.
    #[derive(Default)]
    pub enum Colour {
        /// O_a.
        #[default]
        Ambient => "ambient", "ambiente";
        /// O_d.
        Diffuse => "diffuse", "difusa";
        /// O_s.
        Specular => "specular", "especular";
        /// O_t.
        Transmissivity => "transmissivity", "de transmissão";
    }
}

crate::faults! {
    /// Why POV-Ray cannot compute a part of a scene as phong does, and what would (the
    /// fields are the values the sentences hold).
    #[allow(missing_docs)]
    pub enum PovFault {
        /// No camera.
        NoCamera =>
            "it has no camera", "ela não tem câmera";
            fix "add \"camera\" to the file", "acrescente \"camera\" ao arquivo";
        /// More than one sample per pixel.
        Samples { samples: u32 } =>
            "phong averages {samples} stratified samples per pixel, and POV-Ray's anti-aliasing \
             samples differently",
            "phong faz a média de {samples} amostras estratificadas por pixel, e o anti-aliasing \
             do POV-Ray amostra de outro modo";
            fix "export with --samples 1 (POV-Ray then traces each pixel's centre, as phong does)",
                "exporte com --samples 1 (o POV-Ray então traça o centro de cada pixel, como \
                 phong faz)";
        /// A scene beyond POV-Ray's largest distance.
        TooLarge { radius: Num } =>
            "it spans {radius} units around its centre, and POV-Ray ignores intersections \
             farther than 1e7 units",
            "ela se estende por {radius} unidades em torno do seu centro, e o POV-Ray ignora \
             interseções a mais de 1e7 unidades";
            fix "scale the scene down (below 2.5e6 units)",
                "reduza a escala da cena (abaixo de 2.5e6 unidades)";
        /// A minimum weight that stops POV-Ray's primary rays.
        MinWeight { weight: Num, most: Num } =>
            "a minimum weight of {weight} ≥ 1 stops POV-Ray's primary rays, yet phong traces \
             reflection rays of weight up to {most}",
            "um peso mínimo de {weight} ≥ 1 detém os raios primários do POV-Ray, mas phong \
             traça raios de reflexão de peso até {most}";
            fix "give a minimum weight below 1", "dê um peso mínimo abaixo de 1";
        /// Reflections deeper than POV-Ray traces.
        MaxLevel { level: u32, most: u32 } =>
            "phong may trace reflections to level {level}, and POV-Ray stops at {most}",
            "phong pode traçar reflexões até o nível {level}, e o POV-Ray para em {most}";
            fix "give a maximum level of at most {most}, or a larger minimum weight",
                "dê um nível máximo de até {most}, ou um peso mínimo maior";
        /// A light with falloff on a surface.
        LightOnSurface =>
            "it touches a surface, so its falloff C/d^f grows without bound there, and \
             POV-Ray's fade 2/(1 + (d/D₀)^p) cannot follow it",
            "ela toca uma superfície, então seu decaimento C/d^f cresce sem limite ali, e o \
             fade 2/(1 + (d/D₀)^p) do POV-Ray não consegue acompanhá-lo";
            fix "move the light off the surface", "afaste a fonte de luz da superfície";
        /// A light too bright for the falloff emulation.
        LightOverflow =>
            "its colour scaled for the falloff emulation (C/(2·D₀^f)) overflows POV-Ray's f32 \
             colours",
            "sua cor escalada para emular o decaimento (C/(2·D₀^f)) excede as cores f32 do \
             POV-Ray";
            fix "use a dimmer light or a scene of another scale",
                "use uma fonte de luz mais fraca ou uma cena de outra escala";
        /// An index of refraction below 1.
        IorBelowOne { ior: Num, tir: Tir } =>
            "an index of refraction {ior} below 1 gives {tir}, already where a ray enters it",
            "um índice de refração {ior} abaixo de 1 dá {tir}, já onde um raio entra nele";
            fix "give an \"ior\" of at least 1, or export with --max-level 1",
                "dê um \"ior\" de pelo menos 1, ou exporte com --max-level 1";
        /// A transmitting triangle or mesh.
        OpenSurface { material: String, tir: Tir } =>
            "a triangle or mesh with a transmitting material ({material}) may show {tir}, and a \
             ray through an open surface has no inside that POV-Ray's stack of media agrees on",
            "um triângulo ou uma malha com material que transmite ({material}) pode mostrar \
             {tir}, e um raio através de uma superfície aberta não tem um interior com que a \
             pilha de meios do POV-Ray concorde";
            fix "make the transmitting surface a sphere or a plane, or give its material no \
                 \"transmissivity\"",
                "faça da superfície que transmite uma esfera ou um plano, ou tire \
                 \"transmissivity\" do seu material";
        /// The eye inside a transmitting sphere.
        EyeInSphere { material: String, tir: Tir } =>
            "the eye is inside this transmitting sphere ({material}), whose rays may show {tir}",
            "o olho está dentro desta esfera que transmite ({material}), cujos raios podem \
             mostrar {tir}";
            fix "move the eye outside the sphere", "ponha o olho fora da esfera";
        /// A reflecting surface inside a transmitting sphere.
        InsideSphere { material: String, tir: Tir } =>
            "a reflecting or transmitting surface reaches inside this transmitting sphere \
             ({material}): a ray reflected from it inside may show {tir}, and POV-Ray's stack \
             of media reads nested media otherwise than phong",
            "uma superfície que reflete ou transmite entra nesta esfera que transmite \
             ({material}): um raio de reflexão que parte dela lá dentro pode mostrar {tir}, e a pilha de \
             meios do POV-Ray lê meios aninhados de outro modo que phong";
            fix "move the other reflecting or transmitting surfaces out of the sphere (touching \
                 it is fine; matte opaque ones may stay)",
                "tire da esfera as outras superfícies que refletem ou transmitem (tocá-la não \
                 tem problema; as foscas opacas podem ficar)";
        /// The eye behind a transmitting plane.
        EyeBehindPlane { material: String, tir: Tir } =>
            "the eye is behind this transmitting plane ({material}), in its material, where its \
             rays may show {tir}",
            "o olho está atrás deste plano que transmite ({material}), dentro do seu material, \
             onde seus raios podem mostrar {tir}";
            fix "put the eye on the side the plane's normal points to",
                "ponha o olho do lado para onde aponta a normal do plano";
        /// A reflecting surface behind a transmitting plane.
        BehindPlane { material: String, tir: Tir } =>
            "a reflecting or transmitting surface reaches behind this transmitting plane \
             ({material}), into its material: a ray reflected from it there may show {tir}",
            "uma superfície que reflete ou transmite chega atrás deste plano que transmite \
             ({material}), dentro do seu material: um raio de reflexão que parte dela ali pode mostrar \
             {tir}";
            fix "keep every other reflecting or transmitting surface on the side the plane's \
                 normal points to (another plane only parallel to it and in front); matte \
                 opaque ones may be behind it",
                "mantenha toda outra superfície que reflete ou transmite do lado para onde aponta \
                 a normal do plano (outro plano, só paralelo a ele e à frente); as foscas opacas \
                 podem ficar atrás dele";
        /// A transmissivity whose greyscale POV-Ray does not trace.
        Greyscale { o_t: String, grey: Num } =>
            "POV-Ray traces a refracted ray only where the greyscale 0.297·R + 0.589·G + \
             0.114·B of O_t = {o_t} exceeds the minimum weight, and it is {grey}; phong traces \
             it while w·max(O_t) exceeds it",
            "o POV-Ray traça um raio refratado só onde o tom de cinza 0.297·R + 0.589·G + \
             0.114·B de O_t = {o_t} excede o peso mínimo, e ele é {grey}; phong o traça \
             enquanto w·max(O_t) o excede";
            fix "give a transmissivity whose greyscale is above the minimum weight, or a larger \
                 minimum weight",
                "dê uma transmissividade cujo tom de cinza esteja acima do peso mínimo, ou um \
                 peso mínimo maior";
        /// A colour beyond POV-Ray's f32 colours.
        ColourOverflow { colour: Colour, value: String } =>
            "its {colour} colour {value} overflows POV-Ray's f32 colours",
            "sua cor {colour} {value} excede as cores f32 do POV-Ray";
            fix "use colours below 1e32", "use cores abaixo de 1e32";
        /// A coloured specular colour with a zero channel where the material transmits.
        ZeroSpecular { specular: String, o_t: String } =>
            "its specular colour {specular} is zero where its transmissivity {o_t} is not, and \
             the layers POV-Ray needs for a coloured specular colour then pass no light in that \
             channel",
            "sua cor especular {specular} é zero onde sua transmissividade {o_t} não é, e as \
             camadas de que o POV-Ray precisa para uma cor especular colorida então não deixam \
             passar luz nesse canal";
            fix "give the specular colour no zero component, or make it grey",
                "dê à cor especular componentes diferentes de zero, ou torne-a cinza";
    }
}

/// POV-Ray ignores intersections farther than this (`MAX_DISTANCE` in its source).
const POV_MAX_DISTANCE: f64 = 1.0e7;
/// The largest `max_trace_level` POV-Ray 3.7 accepts.
const POV_MAX_TRACE_LEVEL: u32 = 256;
/// The relative error allowed in the falloff emulation at the nearest surface point.
const FALLOFF_RELATIVE_ERROR: f64 = 1e-9;
/// The copy of a transmitting surface that blocks shadow rays and nothing else: POV-Ray's
/// `no_image` hides it from primary and refracted rays, `no_reflection` from every ray that
/// has been reflected (`NoSomethingFlagRayObjectCondition`), so only shadow rays meet it.
const SHADOW_COPY: &str =
    "texture { pigment { rgb 0 } finish { ambient 0 emission 0 diffuse 0 } } no_image no_reflection";
/// POV-Ray's `EPSILON`: an index ratio within it of 1 is not refracted but continued, at the
/// same trace level (`Trace::ComputeRefraction`).
const POV_EPSILON: f64 = 1.0e-10;
/// POV-Ray's greyscale weights (`RED_INTENSITY`, … in `source/base/types.h`), by which it
/// decides whether a surface passes enough light to trace its refracted ray.
const POV_GREY: [f64; 3] = [0.297, 0.589, 0.114];

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
    let camera = problem
        .camera
        .as_ref()
        .ok_or_else(|| refuse("the scene", PovFault::NoCamera))?;
    let settings = problem.render;
    if settings.samples != 1 {
        return Err(refuse(
            "render.samples",
            PovFault::Samples {
                samples: settings.samples,
            },
        ));
    }
    let surfaces = problem.surfaces();
    let extent = scene_extent(problem);
    if extent.radius * 4.0 > POV_MAX_DISTANCE {
        return Err(refuse(
            "the scene",
            PovFault::TooLarge {
                radius: Num(extent.radius),
            },
        ));
    }

    // Recursion: level and weight rule. A child ray's weight is its parent's times max(O_r)
    // or max(O_t), so the largest of these bounds every ray's weight by level.
    let reflective_max = surfaces
        .iter()
        .flat_map(|s| {
            let m = &s.material.material;
            [m.o_r, m.transmission.map(|t| t.o_t)]
        })
        .flatten()
        .map(|o| o.max_element())
        .fold(0.0f64, f64::max);
    let mw = settings.min_weight;
    let (adc, strip_reflection) = if mw >= 1.0 {
        // POV-Ray would stop the primary rays too (their weight is 1); phong still traces them.
        if reflective_max > mw {
            return Err(refuse(
                "render.min_weight",
                PovFault::MinWeight {
                    weight: Num(mw),
                    most: Num(reflective_max),
                },
            ));
        }
        // No reflection ray passes the weight rule: none is traced in either renderer.
        (f64::from(f32_after(0.0)), true)
    } else {
        (f64::from(f32_after(mw)), false)
    };
    let max_level = effective_max_level(settings.max_level, mw, reflective_max)?;
    // Which surfaces transmit in the export: none when no child ray passes the weight rule or
    // the level rule (at level 1 POV-Ray's refracted colour is black, as phong traces none).
    let transmits: Vec<bool> = surfaces
        .iter()
        .map(|s| {
            !strip_reflection && max_level >= 2 && transmission(&s.material.material).is_some()
        })
        .collect();
    for (s, _) in surfaces.iter().zip(&transmits).filter(|(_, &t)| t) {
        check_transmission(problem, s, adc, mw, max_level)?;
    }

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
    let mut by_key: BTreeMap<[u64; 21], usize> = BTreeMap::new();
    let mut surface_texture = Vec::with_capacity(surfaces.len());
    for (s, &transmit) in surfaces.iter().zip(&transmits) {
        let m = &s.material.material;
        let o_t = if transmit {
            transmission(m).map(|t| t.o_t)
        } else {
            None
        };
        let key = material_key(m, o_t.is_some());
        let index = match by_key.get(&key) {
            Some(&k) => k,
            None => {
                let what = material_name(s);
                let body = texture(&what, m, ambient, adc, strip_reflection, o_t)?;
                let k = textures.len();
                let _ = writeln!(out, "// {what}\n#declare T{k} = {body}");
                textures.push(body);
                by_key.insert(key, k);
                k
            }
        };
        surface_texture.push(index);
    }

    // Surfaces; a mesh's triangles (consecutive, from one file entry) become one `mesh`. A
    // transmitting surface has its `interior`, and with shadows on, `no_shadow` and a black
    // copy that only shadow rays see (see the module doc).
    let shadow = if settings.shadows { "" } else { " no_shadow" };
    let mut i = 0;
    while i < surfaces.len() {
        let s = &surfaces[i];
        let t = surface_texture[i];
        let glass = transmission(&s.material.material).filter(|_| transmits[i]);
        let (inside, own_shadow) = match glass {
            Some(g) => (
                format!(" interior {{ ior {} }}", num(pov_ior(g.eta))),
                " no_shadow",
            ),
            None => (String::new(), shadow),
        };
        let blocker = glass.is_some() && settings.shadows;
        match &s.shape {
            Shape::Plane(p) => {
                let geometry = format!("{}, {}", vec3(p.normal), num(p.normal.dot(p.point)));
                let _ = writeln!(
                    out,
                    "plane {{ {geometry} texture {{ T{t} }}{inside}{own_shadow} }}"
                );
                if blocker {
                    let _ = writeln!(out, "plane {{ {geometry} {SHADOW_COPY} }}");
                }
                i += 1;
            }
            Shape::Sphere(sp) => {
                let geometry = format!("{}, {}", vec3(sp.center), num(sp.radius));
                let _ = writeln!(
                    out,
                    "sphere {{ {geometry} texture {{ T{t} }}{inside}{own_shadow} }}"
                );
                if blocker {
                    let _ = writeln!(out, "sphere {{ {geometry} {SHADOW_COPY} }}");
                }
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
        PovFault::MaxLevel {
            level: max_level,
            most: POV_MAX_TRACE_LEVEL,
        },
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
        return Err(refuse(name, PovFault::LightOnSurface));
    }
    let pf = f64::from(f);
    let d0 = nearest * FALLOFF_RELATIVE_ERROR.powf(1.0 / pf);
    let scaled = color / (2.0 * d0.powf(pf));
    if scaled.max_element() > f64::from(f32::MAX) / 4.0 || (d0 / nearest).powf(pf) > 1e-6 {
        return Err(refuse(name, PovFault::LightOverflow));
    }
    Ok((scaled, format!(" fade_distance {} fade_power {f}", num(d0))))
}

fn material_name(s: &Surface<f64>) -> String {
    match &s.material.name {
        Some(n) => format!("material \"{}\"", sanitize(n)),
        None => format!("the material of surfaces[{}]", s.source.index),
    }
}

/// A key that identifies a material exactly as exported (bit patterns of all its numbers; O_t
/// only where the material transmits in the export, η apart, as it belongs to the object).
fn material_key(m: &Material<f64>, transmits: bool) -> [u64; 21] {
    let mut k = [0u64; 21];
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
    put(16, m.transmission.filter(|_| transmits).map(|t| t.o_t));
    k[20] = m.n_s.to_bits();
    k
}

/// The material's transmission where it has one with O_t ≠ 0 (a zero O_t traces no ray).
fn transmission(m: &Material<f64>) -> Option<Transmission<f64>> {
    m.transmission.filter(|t| t.o_t != DVec3::ZERO)
}

/// The index written for η: η itself, except within POV-Ray's `EPSILON` of 1, where POV-Ray
/// would continue the ray at its parent's trace level instead of refracting it; there η is
/// moved just beyond that band (2e-10 above 1), which bends a ray by at most about 2e-5 rad
/// at grazing incidence and keeps POV-Ray's level count phong's.
fn pov_ior(eta: f64) -> f64 {
    if (eta - 1.0).abs() < 2.0 * POV_EPSILON {
        1.0 + 2.0 * POV_EPSILON
    } else {
        eta
    }
}

/// POV-Ray's greyscale of a colour, in its f32 colour arithmetic.
fn pov_greyscale(c: DVec3) -> f64 {
    let g = (0..3)
        .map(|i| (POV_GREY[i] as f32) * (c[i] as f32))
        .fold(0.0f32, |a, b| a + b);
    f64::from(g)
}

/// Refuses a transmitting surface whose image POV-Ray would compute otherwise than phong
/// (docs/conventions.md, "Transmission", "POV-Ray"). Total internal reflection is where the
/// two differ (POV-Ray traces a reflection ray in place of the transmitted one and drops the
/// surface's own reflection; phong adds nothing), so a transmitting surface must be one where
/// it cannot occur: a sphere or a plane, η ≥ 1, seen from outside, that no reflecting or
/// transmitting surface enters (a matte opaque one inside ends every ray that meets it). A
/// ray then meets its inside only by refraction from the outside, at an angle below the
/// critical one, and (inside a sphere, where every chord meets the surface at equal angles at
/// its two ends) leaves it at that same angle. POV-Ray's stack of media then agrees with
/// phong's sides too: every ray inside the object entered it from the outside.
fn check_transmission(
    problem: &Problem<f64>,
    s: &Surface<f64>,
    adc: f64,
    min_weight: f64,
    max_level: u32,
) -> Result<(), Unexpressible> {
    let what = material_name(s);
    let surface = format!("surfaces[{}]", s.source.index);
    let t = transmission(&s.material.material).expect("a transmitting surface");
    if t.eta < 1.0 {
        return Err(refuse(
            format!("{what}: \"ior\""),
            PovFault::IorBelowOne {
                ior: Num(t.eta),
                tir: Tir,
            },
        ));
    }
    let eye = problem.camera.as_ref().map(|c| c.eye);
    // The other surfaces that send rays on: a matte opaque surface inside the material ends
    // every ray that meets it there, so it cannot send one back to the surface from inside.
    let others = problem
        .surfaces()
        .iter()
        .filter(|o| !std::ptr::eq(*o, s))
        .filter(|o| {
            let m = &o.material.material;
            m.o_r.is_some_and(|r| r != DVec3::ZERO) || transmission(m).is_some()
        })
        .map(|o| &o.shape);
    match s.shape {
        Shape::Triangle(_) => Err(refuse(
            surface,
            PovFault::OpenSurface {
                material: what.clone(),
                tir: Tir,
            },
        )),
        Shape::Sphere(sp) => {
            if eye.is_some_and(|e| (e - sp.center).length() <= sp.radius) {
                return Err(refuse(
                    surface,
                    PovFault::EyeInSphere {
                        material: what.clone(),
                        tir: Tir,
                    },
                ));
            }
            for o in others {
                if enters_ball(o, sp.center, sp.radius) {
                    return Err(refuse(
                        surface,
                        PovFault::InsideSphere {
                            material: what.clone(),
                            tir: Tir,
                        },
                    ));
                }
            }
            Ok(())
        }
        Shape::Plane(pl) => {
            let front = |p: DVec3| pl.normal.dot(p - pl.point);
            if eye.is_some_and(|e| front(e) <= 0.0) {
                return Err(refuse(
                    surface,
                    PovFault::EyeBehindPlane {
                        material: what.clone(),
                        tir: Tir,
                    },
                ));
            }
            for o in others {
                let behind = match o {
                    Shape::Sphere(b) => front(b.center) < b.radius,
                    Shape::Triangle(tr) => tr.p.iter().any(|&v| front(v) < 0.0),
                    Shape::Plane(q) => {
                        q.normal.cross(pl.normal) != DVec3::ZERO || front(q.point) <= 0.0
                    }
                };
                if behind {
                    return Err(refuse(
                        surface,
                        PovFault::BehindPlane {
                            material: what.clone(),
                            tir: Tir,
                        },
                    ));
                }
            }
            Ok(())
        }
    }?;
    // POV-Ray traces the refracted ray only where the greyscale of what the surface passes
    // exceeds adc_bailout, whatever the ray's weight.
    let traced_by_phong = max_level >= 2 && t.o_t.max_element() > min_weight;
    if traced_by_phong && pov_greyscale(t.o_t) <= adc {
        return Err(refuse(
            format!("{what}: \"transmissivity\""),
            PovFault::Greyscale {
                o_t: vec3(t.o_t),
                grey: Num(pov_greyscale(t.o_t)),
            },
        ));
    }
    Ok(())
}

/// Whether a shape reaches strictly inside the ball of centre `c` and radius `r` (touching
/// it from outside does not count). For a triangle the test is conservative: its plane or
/// its bounding ball must stay out of the ball.
fn enters_ball(shape: &Shape<f64>, c: DVec3, r: f64) -> bool {
    match shape {
        Shape::Sphere(o) => (o.center - c).length() < o.radius + r,
        Shape::Plane(p) => p.normal.dot(c - p.point).abs() < r,
        Shape::Triangle(t) => {
            let n = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).normalize_or_zero();
            let plane_clear = n != DVec3::ZERO && n.dot(c - t.p[0]).abs() >= r;
            let mid = (t.p[0] + t.p[1] + t.p[2]) / 3.0;
            let reach = t.p.iter().map(|&v| (v - mid).length()).fold(0.0, f64::max);
            let ball_clear = (mid - c).length() >= reach + r;
            !(plane_clear || ball_clear)
        }
    }
}

/// One material as a POV-Ray texture (see the module doc).
fn texture(
    what: &str,
    m: &Material<f64>,
    ambient_light: Option<DVec3>,
    adc: f64,
    strip_reflection: bool,
    o_t: Option<DVec3>,
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
    for (colour, v) in [
        (Colour::Ambient, amb),
        (Colour::Diffuse, diffuse),
        (Colour::Specular, specular),
        (Colour::Transmissivity, o_t),
    ] {
        if let Some(v) = v {
            if v.max_element() > limit {
                return Err(refuse(
                    what,
                    PovFault::ColourOverflow {
                        colour,
                        value: vec3(v),
                    },
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
    // A grey O_t = T < 1 fits the one layer as its transmit T: POV-Ray multiplies the layer's
    // emission and diffuse light by its opacity 1 − T, which the pigment's division by 1 − T
    // undoes, and passes T·C_t (not its highlight, not its reflection, are multiplied).
    let one_layer_transmit = match o_t {
        None => Some(0.0),
        Some(o) if o.x == o.y && o.y == o.z && o.x < 1.0 => Some(o.x),
        Some(_) => None,
    };
    let one_layer = one_layer_transmit.filter(|&tr| {
        let fits = |v: Option<DVec3>| v.is_none_or(|v| v.max_element() / (1.0 - tr) <= limit);
        fits(diffuse) && (diffuse.is_some() || amb.is_none() || 1.0 / (1.0 - tr) <= limit)
    });
    if let (true, Some(tr)) = (grey_specular && ambient_fits, one_layer) {
        // One layer: pigment O_d (white without one), emission O_a·I_a / O_d; with a
        // transmit T, the pigment's colour divided by 1 − T.
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
        let colour = if tr == 0.0 {
            format!("rgb {}", vec3(pigment))
        } else if diffuse.is_none() && amb.is_none() {
            format!("rgbt <0, 0, 0, {}>", num(tr))
        } else {
            format!("rgbt <{}, {}>", vec3_inner(pigment / (1.0 - tr)), num(tr))
        };
        return Ok(format!(
            "texture {{ pigment {{ {colour} }} finish {{ ambient 0 emission rgb {} diffuse {} \
             brilliance 1{}{} }} }}",
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
    let mut passed = DVec3::ONE; // what every layer so far passes, by channel
    let scalar: Vec<(DVec3, &str)> = [
        (amb, "emission 1 diffuse 0"),
        (diffuse, "emission 0 diffuse 1"),
    ]
    .into_iter()
    .filter_map(|(v, f)| v.map(|v| (v, f)))
    .collect();
    let n_scalar = scalar.len();
    for (k, (v, finish)) in scalar.into_iter().enumerate() {
        let last = k + 1 == n_scalar && specular.is_none() && o_t.is_none();
        let pigment = if last {
            format!("rgb {}", vec3(v / above))
        } else {
            let p = format!("rgbt <{}, {}>", vec3_inner(v / (above * (1.0 - t))), num(t));
            above *= t;
            p
        };
        passed = DVec3::splat(above);
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
        // Opaque, or passing everything where the material transmits.
        let white = if o_t.is_some() {
            "rgbt <0, 0, 0, 1>"
        } else {
            "rgb 1"
        };
        layers.push(format!(
            "pigment {{ {white} }} finish {{ ambient 0 emission 0 diffuse 0{} }}",
            phong(p)
        ));
        passed = s / p;
    }
    if let Some(o) = o_t {
        // The last layer lets O_t through: POV-Ray multiplies the refracted colour by the
        // product of every layer's rgb·filter + transmit, `passed` so far.
        let mut c = DVec3::ZERO;
        for i in 0..3 {
            if o[i] == 0.0 {
                continue;
            }
            if passed[i] <= 0.0 || o[i] / passed[i] > limit {
                return Err(refuse(
                    what,
                    PovFault::ZeroSpecular {
                        specular: vec3(specular.unwrap_or(DVec3::ZERO)),
                        o_t: vec3(o),
                    },
                ));
            }
            c[i] = o[i] / passed[i];
        }
        layers.push(format!(
            "pigment {{ rgbf <{}, 1> }} finish {{ ambient 0 emission 0 diffuse 0 }}",
            vec3_inner(c)
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
    fn a_refusal_reads_as_before_in_english_and_wholly_in_portuguese() {
        // The sentences write POV-Ray's limits as figures.
        assert_eq!(format!("{POV_MAX_DISTANCE:e}"), "1e7");
        let e = refuse(
            "surfaces[1]",
            PovFault::EyeInSphere {
                material: "material \"glass\"".into(),
                tir: Tir,
            },
        );
        assert_eq!(
            e.to_string(),
            "surfaces[1] cannot be expressed in POV-Ray 3.7: the eye is inside this transmitting \
             sphere (material \"glass\"), whose rays may show total internal reflection, where \
             POV-Ray traces a reflection ray in place of the transmitted one and phong adds \
             nothing. Fix: move the eye outside the sphere"
        );
        let fault = Unexpressed(e.fault.clone());
        assert_eq!(
            fault.what(Lang::En),
            format!("cannot be expressed in POV-Ray 3.7: {}", e.why())
        );
        assert_eq!(
            fault.what(Lang::Pt),
            "não pode ser expresso em POV-Ray 3.7: o olho está dentro desta esfera que transmite \
             (material \"glass\"), cujos raios podem mostrar reflexão interna total, onde o \
             POV-Ray traça um raio de reflexão em lugar do transmitido e phong não acrescenta \
             nada"
        );
        assert_eq!(fault.fix(Lang::Pt), "ponha o olho fora da esfera");
        assert_eq!(fault.fix(Lang::En), e.fix());
    }

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
    fn an_index_within_povrays_epsilon_of_one_is_moved_just_beyond_it() {
        assert_eq!(pov_ior(1.5), 1.5);
        assert_eq!(pov_ior(1.0), 1.0 + 2e-10);
        assert_eq!(pov_ior(1.0 + 1e-10), 1.0 + 2e-10);
        assert_eq!(pov_ior(1.0 + 1e-9), 1.0 + 1e-9);
    }

    #[test]
    fn the_greyscale_is_povrays_weighted_sum() {
        // By hand: 0.297·0.5 + 0.589·0.25 + 0.114·1 = 0.1485 + 0.14725 + 0.114 = 0.40975.
        let g = pov_greyscale(DVec3::new(0.5, 0.25, 1.0));
        assert!((g - 0.40975).abs() < 1e-7, "{g}");
        // The weights sum to 1: a grey colour is its own greyscale (within f32 rounding).
        assert!((pov_greyscale(DVec3::splat(0.85)) - 0.85).abs() < 1e-7);
    }

    #[test]
    fn a_surface_touching_a_glass_ball_does_not_enter_it() {
        use crate::geometry::{Plane, Sphere, Triangle};
        let c = DVec3::new(0.0, 1.0, 0.0);
        let floor = |y: f64| {
            Shape::Plane(Plane {
                point: DVec3::new(0.0, y, 0.0),
                normal: DVec3::Y,
            })
        };
        // Tangent.
        assert!(!enters_ball(&floor(0.0), c, 1.0));
        assert!(enters_ball(&floor(0.1), c, 1.0));
        let ball = |x: f64| {
            Shape::Sphere(Sphere {
                center: DVec3::new(x, 1.0, 0.0),
                radius: 0.5,
            })
        };
        // Touching from outside.
        assert!(!enters_ball(&ball(1.5), c, 1.0));
        assert!(enters_ball(&ball(1.4), c, 1.0));
        // Inside.
        assert!(enters_ball(&ball(0.0), c, 1.0));
        // A triangle in the plane x = 2, and one through the ball's centre.
        let tri = |x: f64| {
            Shape::Triangle(Triangle {
                p: [
                    DVec3::new(x, 0.0, 0.0),
                    DVec3::new(x, 2.0, 0.0),
                    DVec3::new(x, 0.0, 2.0),
                ],
                normals: None,
            })
        };
        assert!(!enters_ball(&tri(2.0), c, 1.0));
        assert!(enters_ball(&tri(0.0), c, 1.0));
    }

    #[test]
    fn numbers_are_written_so_that_they_read_back_exactly() {
        for x in [0.1, 1.0 / 3.0, 1e-10, 5e35, -2.5, 40.0] {
            assert_eq!(num(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(num(-0.0), "0.0");
    }
}
