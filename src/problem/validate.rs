//! Validation: turns a parsed [`ProblemFile`] into a [`Problem`] in precision `R`, or says which
//! field is wrong and how to fix it. Every number is checked to be finite in `R`; every vector
//! that is used as a direction to be non-zero; every term the question needs to have its inputs.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::error::Invalid;
use super::faults::TargetFault;
use super::field::Field;
use super::format::{
    CameraSpec, ColorSpec, LightSpec, LightType, MaterialRef, MaterialSpec, ProblemFile,
    ReflectivitySpec, RenderSpec, ScaledColor, SurfaceSpec, SurfaceType, Triple,
};
use super::mesh;
use super::model::{
    AmbientInfo, Camera, GivenVector, LightInfo, NamedMaterial, Problem, ReflectivitySource,
    RenderSettings, Surface, SurfaceSource, Target, MAX_IMAGE_SIDE, MAX_LEVEL, MAX_LIGHTS,
    MAX_PIXEL_SAMPLES, MAX_SAMPLES,
};
use crate::core::vector::{between, is_unit_length, normalize};
use crate::core::{
    Cone, Falloff, Light, LightKind, LightSet, Material, Real, Transmission, Vector, V3,
};
use crate::geometry::{Plane, Ray, Shape, Sphere, Triangle};

/// Validates a parsed problem in precision `R`; mesh files are looked up from the working
/// folder (see [`validate_in`]).
pub fn validate<R: Real>(file: &ProblemFile) -> Result<Problem<R>, Invalid> {
    validate_in::<R>(file, None)
}

/// Validates a parsed problem in precision `R`, reading a mesh's OBJ file relative to `base`
/// (the problem file's folder).
pub fn validate_in<R: Real>(
    file: &ProblemFile,
    base: Option<&Path>,
) -> Result<Problem<R>, Invalid> {
    let Lights {
        lights,
        light_info,
        ambient_info,
    } = lights::<R>(&file.lights)?;
    let viewer = file
        .viewer
        .map(|v| vector::<R>(v, Field::Name("viewer")))
        .transpose()?;
    let first_light = light_info
        .first()
        .map(|i| light_label(i.file_index, i.kind));
    let has_ambient = !ambient_info.is_empty();

    let target =
        match (&file.point, &file.ray) {
            (Some(_), Some(_)) => return Err(Invalid::of("ray", TargetFault::PointAndRay)),
            (None, None) if file.camera.is_some() => {
                if file.surfaces.is_empty() {
                    return Err(Invalid::of("surfaces", TargetFault::SceneWithoutSurfaces));
                }
                let needs = Needs {
                    ambient: has_ambient,
                    diffuse: first_light.clone(),
                    // Every camera ray gives V: specular always has one.
                    specular: first_light.clone(),
                };
                Target::Scene {
                    surfaces: surfaces::<R>(file, base, &needs)?,
                }
            }
            // Surfaces without a ray or a camera: a scene whose camera is missing (what `phong
            // render` needs), more likely than a point problem with surfaces.
            (None, None) if !file.surfaces.is_empty() => {
                return Err(Invalid::of("camera", TargetFault::SurfacesWithoutCamera))
            }
            (None, None) => return Err(Invalid::new(
                "point",
                "the problem has nothing to shade",
                "give \"point\" (with \"material\", and \"position\" and \"normal\" where lights \
                 need them), \"ray\" with \"surfaces\", or a \"camera\" with \"surfaces\"",
            )),
            (Some(point), None) => {
                if !file.surfaces.is_empty() {
                    return Err(Invalid::new(
                        "surfaces",
                        "surfaces are only used by a ray problem, and this problem gives a point",
                        "remove \"surfaces\", or replace \"point\" with a \"ray\"",
                    ));
                }
                let position = point
                    .position
                    .map(|p| vector::<R>(p, Field::Name("point.position")))
                    .transpose()?;
                let normal = point
                    .normal
                    .map(|n| direction::<R>(n, Field::Name("point.normal"), "the normal N"))
                    .transpose()?;
                let (mat_field, material) =
                    resolve_material::<R>(file, &point.material, Field::Name("point.material"))?;
                let needs = Needs {
                    ambient: has_ambient,
                    diffuse: first_light.clone(),
                    specular: viewer.and(first_light.clone()),
                };
                needs.check(&material.spec, mat_field)?;
                // Point and normal: only where the question needs them.
                let positional = light_info
                    .iter()
                    .zip(&lights.lights)
                    .find(|(_, l)| l.position().is_some());
                if position.is_none() {
                    if let Some((info, _)) = positional {
                        return Err(Invalid::new(
                            "point.position",
                            format!(
                                "missing: {} needs P for L and d (Eq. 4.1)",
                                light_label(info.file_index, info.kind)
                            ),
                            "add \"position\": [x, y, z] to \"point\"",
                        ));
                    }
                    if viewer.is_some() {
                        return Err(Invalid::new(
                            "point.position",
                            "missing: the viewer needs P for V = (P − E)/‖P − E‖",
                            "add \"position\": [x, y, z] to \"point\", or remove \"viewer\"",
                        ));
                    }
                }
                if normal.is_none() {
                    if let Some(l) = &first_light {
                        return Err(Invalid::new(
                            "point.normal",
                            format!("missing: {l} needs N for cos θ = −N·L (Eq. 4.7)"),
                            "add \"normal\": [x, y, z] to \"point\"",
                        ));
                    }
                }
                Target::Point {
                    position,
                    normal,
                    material,
                }
            }
            (None, Some(ray)) => {
                let origin = vector::<R>(ray.origin, Field::Name("ray.origin"))?;
                let dir = direction::<R>(
                    ray.direction,
                    Field::Name("ray.direction"),
                    "the ray's direction",
                )?;
                if file.surfaces.is_empty() {
                    return Err(Invalid::new(
                        "surfaces",
                        "missing: a ray problem needs at least one surface for the ray to hit",
                        "add \"surfaces\": [{\"type\": \"plane\", ...}] or a sphere",
                    ));
                }
                let needs = Needs {
                    ambient: has_ambient,
                    diffuse: first_light.clone(),
                    // V comes from the viewer, or from the ray itself: specular always has one.
                    specular: first_light.clone(),
                };
                let surfaces = surfaces::<R>(file, base, &needs)?;
                Target::Ray {
                    ray: Ray {
                        origin,
                        direction: dir.unit,
                    },
                    direction: dir,
                    surfaces,
                }
            }
        };

    let camera = file.camera.as_ref().map(camera::<R>).transpose()?;
    let render = render_settings::<R>(file.render.as_ref())?;
    if let Some(c) = &camera {
        check_work(c.width, c.height, render.samples).map_err(|e| e.at("render.samples"))?;
    }
    let problem = Problem {
        title: file.title.as_deref().map(Arc::from),
        title_pt: file.title_pt.as_deref().map(Arc::from),
        question: file.question.as_deref().map(Arc::from),
        question_pt: file.question_pt.as_deref().map(Arc::from),
        lights,
        light_info,
        ambient_info,
        viewer,
        target,
        camera,
        background: match file.background {
            Some(c) => color::<R>(c, Field::Name("background"), ColorRange::Background)?,
            None => V3::<R>::ZERO,
        },
        render,
        warnings: super::warnings::warnings(file),
    };
    if problem.camera.is_some() {
        let s = &problem.render;
        check_tree(&problem, s.max_level, s.min_weight.to_f64())
            .map_err(|e| e.at("render.max_level"))?;
    }
    Ok(problem)
}

/// The camera: E ≠ the look-at point, `up` not along the line of sight, 0 < fov < 180, and an
/// image size the tracer accepts.
fn camera<R: Real>(c: &CameraSpec) -> Result<Camera<R>, Invalid> {
    let eye = vector::<R>(c.eye, Field::Name("camera.eye"))?;
    let look_at = vector::<R>(c.look_at, Field::Name("camera.look_at"))?;
    let up = vector::<R>(c.up.unwrap_or([0.0, 1.0, 0.0]), Field::Name("camera.up"))?;
    let Some(forward) = between::<R>(eye, look_at) else {
        return Err(Invalid::new(
            "camera.look_at",
            "the camera looks at its own eye: no line of sight",
            "give a look_at point different from eye",
        ));
    };
    if normalize::<R>(Vector::cross(forward.unit, up)).is_none() {
        return Err(Invalid::new(
            "camera.up",
            "up is zero or along the line of sight, so the image has no up direction",
            "give an up vector not parallel to look_at − eye, such as [0, 1, 0] or [0, 0, 1]",
        ));
    }
    if !(c.fov > 0.0 && c.fov < 180.0) {
        return Err(Invalid::new(
            "camera.fov",
            format!("{} degrees is not a field of view", show(c.fov)),
            "give the vertical field of view in degrees, 0 < fov < 180 (e.g. 45)",
        ));
    }
    // The image plane's half-height tan(fov/2), as the tracer computes it: in f32,
    // 179.999999999 rounds to 180 and the tangent of the rounded half-angle is negative (the
    // image would be upside down); 1e-46 rounds to 0.
    let fov = number::<R>(c.fov, Field::Name("camera.fov"))?;
    let half_height = (fov.to_radians() / R::TWO).tan();
    if !(half_height > R::ZERO && half_height.is_finite()) {
        let (what, fix) = if c.fov < 90.0 {
            (
                "too small",
                "give a larger field of view, or use --precision f64",
            )
        } else {
            (
                "too close to 180",
                "give a field of view of at most 179 degrees, or use --precision f64",
            )
        };
        return Err(Invalid::new(
            "camera.fov",
            format!("{} degrees is {what} for {}", show(c.fov), R::NAME),
            fix,
        ));
    }
    for (name, side) in [("width", c.width), ("height", c.height)] {
        if side == 0 || side > MAX_IMAGE_SIDE {
            return Err(Invalid::new(
                format!("camera.{name}"),
                format!("{side} pixels is outside 1 to {MAX_IMAGE_SIDE}"),
                format!("give the image {name} in pixels, 1 to {MAX_IMAGE_SIDE}"),
            ));
        }
    }
    Ok(Camera {
        eye,
        look_at,
        up,
        fov,
        width: c.width,
        height: c.height,
    })
}

/// The tracer's settings, with the defaults of [`RenderSettings::default`].
fn render_settings<R: Real>(r: Option<&RenderSpec>) -> Result<RenderSettings<R>, Invalid> {
    let mut s = RenderSettings::<R>::default();
    let Some(r) = r else { return Ok(s) };
    if let Some(level) = r.max_level {
        check_max_level(level).map_err(|e| e.at("render.max_level"))?;
        s.max_level = level;
    }
    if let Some(w) = r.min_weight {
        check_min_weight(w).map_err(|e| e.at("render.min_weight"))?;
        s.min_weight = number::<R>(w, Field::Name("render.min_weight"))?;
    }
    if let Some(n) = r.samples {
        check_samples(n).map_err(|e| e.at("render.samples"))?;
        s.samples = n;
    }
    if let Some(on) = r.shadows {
        s.shadows = on;
    }
    Ok(s)
}

/// Why a setting (given in a file or on the command line) is refused, and what would fix it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SettingError {
    pub message: String,
    pub fix: String,
}

impl SettingError {
    fn new(message: impl Into<String>, fix: impl Into<String>) -> Self {
        SettingError {
            message: message.into(),
            fix: fix.into(),
        }
    }

    /// The error of the setting named `field` (`render.samples` in a file, `samples` among a
    /// command line's overrides).
    pub(crate) fn at(self, field: impl Into<String>) -> Invalid {
        Invalid::new(field, self.message, self.fix)
    }
}

/// The maximum level must let at least the primary rays through, and is at most [`MAX_LEVEL`].
pub(crate) fn check_max_level(level: u32) -> Result<(), SettingError> {
    if level == 0 {
        return Err(SettingError::new(
            "0 traces nothing: the primary ray already has level 1",
            format!("give a maximum level from 1 to {MAX_LEVEL} (1 = primary rays only)"),
        ));
    }
    if level > MAX_LEVEL {
        return Err(SettingError::new(
            format!("{level} is outside 1 to {MAX_LEVEL}"),
            format!(
                "give a maximum level from 1 to {MAX_LEVEL}: past {MAX_LEVEL} reflections a path \
                 cannot change an 8-bit pixel unless its surfaces reflect more than 99%"
            ),
        ));
    }
    Ok(())
}

/// A render's primary rays, width × height × samples, are at most [`MAX_PIXEL_SAMPLES`].
pub(crate) fn check_work(width: u32, height: u32, samples: u32) -> Result<(), SettingError> {
    let work = u64::from(width) * u64::from(height) * u64::from(samples);
    if work > MAX_PIXEL_SAMPLES {
        let most = MAX_PIXEL_SAMPLES / (u64::from(width) * u64::from(height)).max(1);
        return Err(SettingError::new(
            format!(
                "{width}×{height} pixels × {samples} samples is {work} primary rays, more than \
                 the {MAX_PIXEL_SAMPLES} (2^30) a render may trace (hours of work)"
            ),
            if most >= 1 {
                format!("give at most {most} samples per pixel at this size, or a smaller image")
            } else {
                "give a smaller image".to_owned()
            },
        ));
    }
    Ok(())
}

/// The most rays one sample's tree may hold (2^20): where a material both reflects and
/// transmits, a hit spawns two rays and the tree may double at each level.
pub(crate) const MAX_TREE_RAYS: u64 = 1 << 20;

/// The rays one sample's tree can hold at most, with `max_level` and `min_weight` (saturating
/// at `u64::MAX`). Each ray but the primary is its parent's only or larger child, whose weight
/// is its parent's times at most HI (the largest max(O_r) or max(O_t) of any material), or the
/// smaller child of a hit on a material that both reflects and transmits, times at most LO (the
/// largest smaller of the two of such a material). A ray of level d reached through i smaller
/// children has weight ≤ HI^(d−1−i)·LO^i, and at most C(d−1, i) rays of level d are reached so:
/// the bound counts those whose weight can exceed the minimum weight. Without such a material
/// the tree is a chain, of at most `max_level` rays.
pub(crate) fn tree_rays<R: Real>(problem: &Problem<R>, max_level: u32, min_weight: f64) -> u64 {
    let (mut hi, mut lo) = (0.0f64, 0.0f64);
    let mut branches = false;
    for s in problem.surfaces() {
        let m = &s.material.material;
        let o_r = m.o_r.map_or(0.0, |o| o.max_element().to_f64());
        let o_t = m.transmission.map_or(0.0, |t| t.o_t.max_element().to_f64());
        hi = hi.max(o_r).max(o_t);
        if o_r > 0.0 && o_t > 0.0 {
            branches = true;
            lo = lo.max(o_r.min(o_t));
        }
    }
    if !branches {
        return u64::from(max_level);
    }
    // In logarithms, so that no power underflows; a minimum weight of 0 lets every ray through.
    let (ln_hi, ln_lo, ln_min) = (hi.ln(), lo.ln(), min_weight.ln());
    let mut total = 1.0f64;
    // C(d − 1, i) for the current level d, as f64 (the count saturates long before it rounds
    // anything that matters).
    let mut row = vec![1.0f64];
    for d in 2..=max_level {
        let mut next = vec![1.0f64; row.len() + 1];
        for i in 1..row.len() {
            next[i] = row[i - 1] + row[i];
        }
        row = next;
        let k = f64::from(d - 1);
        for (i, c) in row.iter().enumerate() {
            let i = i as f64;
            let ln_w = (k - i) * ln_hi + i * ln_lo;
            if min_weight <= 0.0 || ln_w > ln_min {
                total += c;
            }
        }
        if total >= 1.8e19 {
            return u64::MAX;
        }
    }
    total as u64
}

/// One sample's tree within [`MAX_TREE_RAYS`] rays: refused rather than run for hours.
pub(crate) fn check_tree<R: Real>(
    problem: &Problem<R>,
    max_level: u32,
    min_weight: f64,
) -> Result<(), SettingError> {
    let rays = tree_rays(problem, max_level, min_weight);
    if rays > MAX_TREE_RAYS {
        let shown = if rays == u64::MAX {
            "more than 2^63".to_owned()
        } else {
            rays.to_string()
        };
        use crate::report::messages::both;
        let w = show(min_weight);
        return Err(SettingError::new(
            both(
                &format!(
                    "maximum level {max_level} with minimum weight {w} lets one sample's ray \
                     tree hold {shown} rays (a material both reflects and transmits, so each \
                     hit can spawn two rays), more than the {MAX_TREE_RAYS} (2^20) a tree may \
                     hold"
                ),
                &format!(
                    "o nível máximo {max_level} com o peso mínimo {w} deixa a árvore de raios \
                     de uma amostra ter {shown} raios (um material reflete e transmite, e cada \
                     interseção pode gerar dois raios), mais que os {MAX_TREE_RAYS} (2^20) que \
                     uma árvore pode ter"
                ),
            ),
            both(
                "give a maximum level of at most 20, or a larger minimum weight (e.g. 0.01), \
                 which stops the rays whose weight w = w_p·max(O) has fallen below it",
                "dê um nível máximo de no máximo 20, ou um peso mínimo maior (por exemplo \
                 0.01), que para os raios cujo peso w = w_p·max(O) caiu abaixo dele",
            ),
        ));
    }
    Ok(())
}

/// The minimum weight is a finite number ≥ 0.
pub(crate) fn check_min_weight(w: f64) -> Result<(), SettingError> {
    if !(w.is_finite() && w >= 0.0) {
        return Err(SettingError::new(
            format!("{} is not a weight", show(w)),
            "give a minimum weight ≥ 0 (0 traces every reflection up to the maximum level)",
        ));
    }
    Ok(())
}

/// Samples per pixel: 1 to [`MAX_SAMPLES`].
pub(crate) fn check_samples(n: u32) -> Result<(), SettingError> {
    if n == 0 || n > MAX_SAMPLES {
        return Err(SettingError::new(
            format!("{n} samples per pixel is outside 1 to {MAX_SAMPLES}"),
            format!("give 1 to {MAX_SAMPLES} samples per pixel"),
        ));
    }
    Ok(())
}

/// Every surface of the file, a mesh expanded into its triangles.
fn surfaces<R: Real>(
    file: &ProblemFile,
    base: Option<&Path>,
    needs: &Needs,
) -> Result<Vec<Surface<R>>, Invalid> {
    let mut out = Vec::with_capacity(file.surfaces.len());
    let mut materials = MaterialCache::default();
    for (i, s) in file.surfaces.iter().enumerate() {
        surface::<R>(file, base, s, i, needs, &mut materials, &mut out)?;
        if out.len() > mesh::MAX_TRIANGLES {
            return Err(Invalid::new(
                format!("surfaces[{i}]"),
                format!(
                    "the scene has more than {} surfaces (a mesh's triangles each count)",
                    mesh::MAX_TRIANGLES
                ),
                "give at most 1,000,000 surfaces and triangles in all",
            ));
        }
    }
    Ok(out)
}

/// Named materials validated once, however many surfaces use them (a scene of 100,000
/// spheres names a handful of materials).
struct MaterialCache<R: Real> {
    named: std::collections::BTreeMap<String, NamedMaterial<R>>,
}

impl<R: Real> Default for MaterialCache<R> {
    fn default() -> Self {
        MaterialCache {
            named: Default::default(),
        }
    }
}

impl<R: Real> MaterialCache<R> {
    /// As [`resolve_material`], a named material validated only the first time.
    fn resolve<'a>(
        &mut self,
        file: &'a ProblemFile,
        r: &'a MaterialRef,
        field: Field<'a>,
    ) -> Result<(Field<'a>, NamedMaterial<R>), Invalid> {
        if let MaterialRef::Name(name) = r {
            if let Some(hit) = self.named.get(name.as_str()) {
                return Ok((MATERIALS.key(name), hit.clone()));
            }
            let (at, m) = resolve_material::<R>(file, r, field)?;
            self.named.insert(name.clone(), m.clone());
            return Ok((at, m));
        }
        resolve_material::<R>(file, r, field)
    }
}

/// `materials`, the field a named material's own fields are under.
static MATERIALS: Field<'static> = Field::Name("materials");

/// `surfaces`.
static SURFACES: Field<'static> = Field::Name("surfaces");

/// `lights`.
static LIGHTS: Field<'static> = Field::Name("lights");

/// `lights[1] (point)`.
pub(crate) fn light_label(file_index: usize, kind: &str) -> String {
    format!("lights[{file_index}] ({kind})")
}

/// Which terms the question computes, and so which material fields it needs.
struct Needs {
    ambient: bool,
    /// The first light that needs O_d, if any.
    diffuse: Option<String>,
    /// The first light that needs O_s and n_s (there is a viewer), if any.
    specular: Option<String>,
}

impl Needs {
    fn check(&self, m: &MaterialSpec, field: Field<'_>) -> Result<(), Invalid> {
        const COLOR_FORM: &str = "[r, g, b] (or {\"k\": k, \"color\": [r, g, b]})";
        if self.ambient && m.ambient.is_none() {
            return Err(Invalid::new(
                field.key("ambient"),
                "missing: the ambient term O_a I_a (Eq. 4.6) needs it, since the problem has an \
                 ambient light",
                format!("add \"ambient\": {COLOR_FORM}; [0, 0, 0] if the surface reflects no ambient light"),
            ));
        }
        if let Some(l) = &self.diffuse {
            if m.diffuse.is_none() {
                return Err(Invalid::new(
                    field.key("diffuse"),
                    format!("missing: the diffuse term O_d I_l cos θ (Eq. 4.8) of {l} needs it"),
                    format!("add \"diffuse\": {COLOR_FORM}; [0, 0, 0] for no diffuse reflection"),
                ));
            }
        }
        if let Some(l) = &self.specular {
            if m.specular.is_none() {
                return Err(Invalid::new(
                    field.key("specular"),
                    format!(
                        "missing: the specular term O_s I_l (cos φ)^n_s (Eq. 4.10) of {l} needs it, \
                         since the problem has a viewer"
                    ),
                    format!("add \"specular\": {COLOR_FORM}; [0, 0, 0] for a matte surface"),
                ));
            }
            if m.shininess.is_none() {
                return Err(Invalid::new(
                    field.key("shininess"),
                    format!("missing: the specular term (Eq. 4.10) of {l} needs the exponent n_s"),
                    "add \"shininess\": n_s (a number ≥ 0)",
                ));
            }
        }
        Ok(())
    }
}

/// The lights of a file, validated: the core's set, and where each light and each ambient
/// light came from (the fields of [`Problem`] of the same names).
struct Lights<R: Real> {
    lights: LightSet<R>,
    light_info: Vec<LightInfo<R>>,
    ambient_info: Vec<AmbientInfo<R>>,
}

fn lights<R: Real>(specs: &[LightSpec]) -> Result<Lights<R>, Invalid> {
    let mut set = LightSet {
        ambient: None,
        lights: Vec::new(),
    };
    if specs.len() > MAX_LIGHTS {
        return Err(Invalid::new(
            "lights",
            format!(
                "{} lights are more than the {MAX_LIGHTS} a problem may have",
                specs.len()
            ),
            format!("give at most {MAX_LIGHTS} lights"),
        ));
    }
    let mut info = Vec::new();
    let mut ambient_info = Vec::new();
    for (i, spec) in specs.iter().enumerate() {
        let base = LIGHTS.index(i);
        let f = |name: &'static str| Field::Key(&base, name);
        let what = LightWhat(spec.kind);
        if spec.present_mask() & !spec.kind.fields_mask() != 0 {
            check_fields(base, &what, spec.kind.fields(), spec.present())?;
        }
        let name = spec.name.clone();
        let c = color::<R>(
            required(spec.color, base, "color", &what)?,
            f("color"),
            ColorRange::Light,
        )?;
        let mut direction_length = None;
        let kind = match spec.kind {
            LightType::Ambient => {
                set.ambient = Some(set.ambient.map_or(c, |a| a + c));
                ambient_info.push(AmbientInfo {
                    file_index: i,
                    name: name.map(Arc::from),
                    name_pt: spec.name_pt.as_deref().map(Arc::from),
                    color: c,
                });
                continue;
            }
            LightType::Point => {
                let (position, falloff) = position_and_falloff::<R>(spec, base, &what)?;
                LightKind::Point { position, falloff }
            }
            LightType::Directional => {
                let d = required(spec.direction, base, "direction", &what)?;
                let d = direction::<R>(d, f("direction"), "the light's direction D_l")?;
                direction_length = (!is_unit_length(d.length)).then_some(d.length);
                LightKind::Directional { direction: d.unit }
            }
            LightType::Spot => {
                let axis = required(spec.axis, base, "axis", &what)?;
                let axis = direction::<R>(axis, f("axis"), "the cone's axis D_l")?;
                direction_length = (!is_unit_length(axis.length)).then_some(axis.length);
                let angle = required(spec.angle, base, "angle", &what)?;
                if !(0.0..=90.0).contains(&angle) {
                    return Err(Invalid::new(
                        f("angle"),
                        format!("{}° is outside [0°, 90°]", show(angle)),
                        "γ is the angle between the cone's axis and its side, 0 ≤ γ ≤ 90 degrees \
                         (Eq. 4.4)",
                    ));
                }
                let exponent = required(spec.exponent, base, "exponent", &what)?;
                let e = number::<R>(exponent, f("exponent"))?;
                if e < R::ZERO {
                    return Err(Invalid::new(
                        f("exponent"),
                        format!("{} is negative", show(exponent)),
                        "the spot exponent e of cos(ψ)^e (Eq. 4.4) must be ≥ 0, e.g. 0, 1 or 2",
                    ));
                }
                let (position, falloff) = position_and_falloff::<R>(spec, base, &what)?;
                LightKind::Spot {
                    position,
                    falloff,
                    cone: Cone::new(axis.unit, number::<R>(angle, f("angle"))?, e),
                }
            }
        };
        set.lights.push(Light { color: c, kind });
        info.push(LightInfo {
            file_index: i,
            name: name.map(Arc::from),
            name_pt: spec.name_pt.as_deref().map(Arc::from),
            kind: spec.kind.name(),
            direction_length,
        });
    }
    Ok(Lights {
        lights: set,
        light_info: info,
        ambient_info,
    })
}

/// A light's kind as messages write it, `point light`, written out only for an error.
struct LightWhat(LightType);

impl fmt::Display for LightWhat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} light", self.0.name())
    }
}

/// P_l and f of a point or spot light.
fn position_and_falloff<R: Real>(
    spec: &LightSpec,
    base: Field<'_>,
    what: &dyn fmt::Display,
) -> Result<(V3<R>, Falloff), Invalid> {
    let position = required(spec.position, base, "position", what)?;
    let f = required(spec.falloff, base, "falloff", what)?;
    Ok((
        vector::<R>(position, base.key("position"))?,
        falloff(f, base.key("falloff"))?,
    ))
}

/// Rejects a field that the light's or surface's type does not take (`present`: the fields the
/// file gives, in the table's order).
fn check_fields(
    base: Field<'_>,
    what: &dyn fmt::Display,
    takes: &[&str],
    mut present: impl Iterator<Item = &'static str>,
) -> Result<(), Invalid> {
    match present.find(|f| !takes.contains(f)) {
        Some(extra) => Err(Invalid::new(
            base.key(extra),
            format!("a {what} has no \"{extra}\""),
            format!("remove it; a {what} takes {}", quoted(takes)),
        )),
        None => Ok(()),
    }
}

/// A field the type requires: its value, or an error naming it and what it is for.
fn required<T>(
    value: Option<T>,
    base: Field<'_>,
    name: &str,
    what: &dyn fmt::Display,
) -> Result<T, Invalid> {
    value.ok_or_else(|| {
        let purpose = super::field_purpose(name).map_or(String::new(), |p| {
            format!(
                ": it gives {}",
                crate::text::Message::text(&p, crate::text::Lang::En)
            )
        });
        Invalid::new(
            base.key(name),
            format!("missing: a {what} needs \"{name}\"{purpose}"),
            format!("add \"{name}\""),
        )
    })
}

fn quoted(fields: &[&str]) -> String {
    let q: Vec<String> = fields.iter().map(|f| format!("\"{f}\"")).collect();
    q.join(", ")
}

/// A number as a person wrote it: `3`, `1.5`, `1e300` (never hundreds of digits).
pub(crate) fn show(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{x}")
    } else {
        format!("{x:?}")
    }
}

fn falloff(x: f64, field: Field<'_>) -> Result<Falloff, Invalid> {
    let f = if x == 0.0 || x == 1.0 || x == 2.0 {
        Falloff::from_exponent(x as u8)
    } else {
        None
    };
    f.ok_or_else(|| {
        Invalid::new(
            field,
            format!("{} is not a falloff exponent", show(x)),
            "use 0 (no falloff), 1 (linear) or 2 (quadratic), Eq. 4.3",
        )
    })
}

fn surface<R: Real>(
    file: &ProblemFile,
    folder: Option<&Path>,
    s: &SurfaceSpec,
    i: usize,
    needs: &Needs,
    materials: &mut MaterialCache<R>,
    out: &mut Vec<Surface<R>>,
) -> Result<(), Invalid> {
    let base = SURFACES.index(i);
    let f = |name: &'static str| Field::Key(&base, name);
    let what = s.kind.name();
    if s.present_mask() & !s.kind.fields_mask() != 0 {
        check_fields(base, &what, s.kind.fields(), s.present())?;
    }
    let (shape, normal) = match s.kind {
        SurfaceType::Plane => {
            let n = required(s.normal.as_deref().copied(), base, "normal", &what)?;
            let n = direction::<R>(n, f("normal"), "the plane's normal")?;
            let plane = Plane {
                point: vector::<R>(
                    required(s.point.as_deref().copied(), base, "point", &what)?,
                    f("point"),
                )?,
                normal: n.unit,
            };
            (Shape::Plane(plane), Some(n))
        }
        SurfaceType::Sphere => {
            let radius = required(s.radius, base, "radius", &what)?;
            let r = number::<R>(radius, f("radius"))?;
            if radius > 0.0 && r == R::ZERO {
                return Err(Invalid::new(
                    f("radius"),
                    format!(
                        "{} is too small for {}: it rounds to 0",
                        show(radius),
                        R::NAME
                    ),
                    "use --precision f64, or scale the problem",
                ));
            }
            if r <= R::ZERO {
                return Err(Invalid::new(
                    f("radius"),
                    format!("{} is not a radius", show(radius)),
                    "give the sphere a radius > 0",
                ));
            }
            let sphere = Sphere {
                center: vector::<R>(required(s.center, base, "center", &what)?, f("center"))?,
                radius: r,
            };
            (Shape::Sphere(sphere), None)
        }
        SurfaceType::Triangle => {
            let v = required(s.vertices.as_deref(), base, "vertices", &what)?;
            let vertices = f("vertices");
            let mut p = [V3::<R>::ZERO; 3];
            for (k, corner) in v.iter().enumerate() {
                p[k] = vector::<R>(*corner, vertices.index(k))?;
            }
            let t = Triangle { p, normals: None };
            if t.normal().is_none() {
                return Err(Invalid::new(
                    f("vertices"),
                    format!(
                        "the triangle is degenerate in {}: its corners lie on one line, so it \
                         has no area and no normal",
                        R::NAME
                    ),
                    "give three corners that are not on one line",
                ));
            }
            (Shape::Triangle(t), None)
        }
        SurfaceType::Mesh => {
            let name = required(s.file.as_ref(), base, "file", &what)?;
            let mref = required(s.material.as_ref(), base, "material", &what)?;
            let (mat_field, material) = materials.resolve(file, mref, f("material"))?;
            needs.check(&material.spec, mat_field)?;
            let path = mesh_path(folder, name);
            let triangles =
                mesh::load_obj::<R>(&path).map_err(|e| Invalid::of(f("file"), e.at(&path)))?;
            if out.len() + triangles.len() > mesh::MAX_TRIANGLES {
                return Err(Invalid::new(
                    f("file"),
                    format!(
                        "{}: its {} triangles take the scene past {} surfaces",
                        path.display(),
                        triangles.len(),
                        mesh::MAX_TRIANGLES
                    ),
                    "give at most 1,000,000 surfaces and triangles in all",
                ));
            }
            out.try_reserve(triangles.len()).map_err(|_| {
                Invalid::new(
                    f("file"),
                    super::out_of_memory(
                        triangles
                            .len()
                            .saturating_mul(std::mem::size_of::<Surface<R>>()),
                    ),
                    "give a smaller mesh, or free memory",
                )
            })?;
            out.extend(triangles.into_iter().enumerate().map(|(k, t)| Surface {
                shape: Shape::Triangle(t),
                material: material.clone(),
                normal: None,
                source: SurfaceSource {
                    index: i,
                    triangle: Some(k),
                },
            }));
            return Ok(());
        }
    };
    let mref = required(s.material.as_ref(), base, "material", &what)?;
    let (mat_field, material) = materials.resolve(file, mref, f("material"))?;
    needs.check(&material.spec, mat_field)?;
    out.push(Surface {
        shape,
        material,
        normal,
        source: SurfaceSource {
            index: i,
            triangle: None,
        },
    });
    Ok(())
}

/// Looks a material up by name, or takes it in place; returns the field path to report
/// errors in it under, and the material.
fn resolve_material<'a, R: Real>(
    file: &'a ProblemFile,
    r: &'a MaterialRef,
    field: Field<'a>,
) -> Result<(Field<'a>, NamedMaterial<R>), Invalid> {
    let (path, name, spec) = match r {
        MaterialRef::Inline(spec) => (field, None, &**spec),
        MaterialRef::Name(name) => match file.materials.get(name) {
            Some(spec) => (MATERIALS.key(name), Some(name.clone()), spec),
            None => {
                let known: Vec<_> = file.materials.keys().map(|k| format!("\"{k}\"")).collect();
                let fix = if known.is_empty() {
                    "define it under \"materials\", or write the material in place".to_owned()
                } else {
                    format!(
                        "use one of {}, or define it under \"materials\"",
                        known.join(", ")
                    )
                };
                return Err(Invalid::new(
                    field,
                    format!("there is no material named \"{name}\""),
                    fix,
                ));
            }
        },
    };
    let mut m = material::<R>(spec, path)?;
    m.name = name.map(Arc::from);
    Ok((path, m))
}

fn material<R: Real>(spec: &MaterialSpec, field: Field<'_>) -> Result<NamedMaterial<R>, Invalid> {
    let f = |name: &'static str| Field::Key(&field, name);
    let col = |c: &Option<ColorSpec>, name: &'static str| -> Result<Option<V3<R>>, Invalid> {
        c.as_ref()
            .map(|c| material_color::<R>(c, f(name)))
            .transpose()
    };
    let o_a = col(&spec.ambient, "ambient")?;
    let o_d = col(&spec.diffuse, "diffuse")?;
    let o_s = col(&spec.specular, "specular")?;
    let n_s = match spec.shininess {
        Some(x) => {
            let n = number::<R>(x, f("shininess"))?;
            if n < R::ZERO {
                return Err(Invalid::new(
                    f("shininess"),
                    format!("{} is negative", show(x)),
                    "the specular exponent n_s (Eq. 4.9) must be ≥ 0",
                ));
            }
            n
        }
        None => R::ZERO,
    };
    let (o_r, source) = match &spec.reflectivity {
        None => (None, None),
        Some(ReflectivitySpec::Rgb(c)) => (
            Some(color::<R>(*c, f("reflectivity"), ColorRange::Material)?),
            Some(ReflectivitySource::Explicit),
        ),
        Some(ReflectivitySpec::Same(_)) => match o_s {
            Some(s) => (Some(s), Some(ReflectivitySource::Specular)),
            None => {
                return Err(Invalid::new(
                    f("reflectivity"),
                    "is \"specular\" but the material has no specular colour",
                    "give \"specular\", or give the reflectivity as [r, g, b]",
                ))
            }
        },
    };
    let transmission = transmission::<R>(spec, &field)?;
    Ok(NamedMaterial {
        name: None,
        spec: std::sync::Arc::new(spec.clone()),
        material: Material {
            o_a,
            o_d,
            o_s,
            n_s,
            o_r,
            transmission,
        },
        reflectivity: source,
    })
}

/// O_t and η (docs/conventions.md, "Transmission"): both or neither, O_t a colour in [0, 1]
/// and η a finite number > 0.
fn transmission<R: Real>(
    spec: &MaterialSpec,
    field: &Field<'_>,
) -> Result<Option<Transmission<R>>, Invalid> {
    let f = |name: &'static str| Field::Key(field, name);
    use crate::report::messages::both;
    match (spec.transmissivity, spec.ior) {
        (None, None) => Ok(None),
        (Some(_), None) => Err(Invalid::new(
            f("ior"),
            both(
                "is missing, and the material has a transmissivity",
                "falta, e o material tem uma transmissividade",
            ),
            both(
                "give the index of refraction of the material's inside, e.g. \"ior\": 1.5 for \
                 glass (the outside's is 1); Snell's law needs it to bend the transmitted ray",
                "dê o índice de refração do interior do material, por exemplo \"ior\": 1.5 \
                 para o vidro (o do exterior é 1); a lei de Snell precisa dele para desviar o \
                 raio transmitido",
            ),
        )),
        (None, Some(_)) => Err(Invalid::new(
            f("transmissivity"),
            both(
                "is missing, and the material has an index of refraction",
                "falta, e o material tem um índice de refração",
            ),
            both(
                "give the transmissivity O_t as [r, g, b] (e.g. [0.9, 0.9, 0.9]), or remove \
                 \"ior\": without O_t no ray is transmitted",
                "dê a transmissividade O_t como [r, g, b] (por exemplo [0.9, 0.9, 0.9]), ou \
                 retire \"ior\": sem O_t nenhum raio é transmitido",
            ),
        )),
        (Some(o_t), Some(eta)) => {
            let o_t = color::<R>(o_t, f("transmissivity"), ColorRange::Material)?;
            let value = number::<R>(eta, f("ior"))?;
            if eta <= 0.0 || value <= R::ZERO {
                return Err(Invalid::new(
                    f("ior"),
                    both(
                        &format!("{} is not a positive number", show(eta)),
                        &format!("{} não é um número positivo", show(eta)),
                    ),
                    both(
                        "an index of refraction is > 0 (1 for air, 1.33 for water, 1.5 for glass)",
                        "um índice de refração é > 0 (1 para o ar, 1.33 para a água, 1.5 para o \
                         vidro)",
                    ),
                ));
            }
            Ok(Some(Transmission { o_t, eta: value }))
        }
    }
}

fn material_color<R: Real>(c: &ColorSpec, field: Field<'_>) -> Result<V3<R>, Invalid> {
    if let ColorSpec::Scaled(ScaledColor { k, color: o }) = c {
        if !(0.0..=1.0).contains(k) {
            return Err(Invalid::new(
                field.key("k"),
                format!("{} is outside [0, 1]", show(*k)),
                "the chapter's coefficients k_a, k_d, k_s lie in [0, 1] (Eq. 4.5, 4.7, 4.9); \
                 give the product as one colour [r, g, b] if you mean something else",
            ));
        }
        color::<R>(*o, field.key("color"), ColorRange::Material)?;
    }
    color::<R>(c.product(), field, ColorRange::Material)
}

#[derive(Clone, Copy)]
enum ColorRange {
    Light,
    Material,
    Background,
}

fn color<R: Real>(c: Triple, field: Field<'_>, range: ColorRange) -> Result<V3<R>, Invalid> {
    let v = vector::<R>(c, field)?;
    if c.iter().any(|&x| x < 0.0) {
        let what = match range {
            ColorRange::Light => "a light's colour",
            ColorRange::Material => "a material colour",
            ColorRange::Background => "the background colour",
        };
        // The numbers as the file writes them (2, not 2.0; 1e39, not 40 digits).
        let [r, g, b] = c.map(show);
        return Err(Invalid::new(
            field,
            format!("{what} has a negative component: [{r}, {g}, {b}]"),
            "colour components must be ≥ 0",
        ));
    }
    Ok(v)
}

fn number<R: Real>(x: f64, field: Field<'_>) -> Result<R, Invalid> {
    let r = R::from_f64(x);
    if !x.is_finite() || !r.is_finite() {
        return Err(Invalid::new(
            field,
            format!("{} is not a finite {} number", show(x), R::NAME),
            if R::NAME == "f32" {
                "use a number within ±3.4e38, or --precision f64"
            } else {
                "use a finite number"
            },
        ));
    }
    Ok(r)
}

fn vector<R: Real>(a: Triple, field: Field<'_>) -> Result<V3<R>, Invalid> {
    let x = number::<R>(a[0], field.index(0))?;
    let y = number::<R>(a[1], field.index(1))?;
    let z = number::<R>(a[2], field.index(2))?;
    Ok(V3::<R>::new(x, y, z))
}

fn direction<R: Real>(a: Triple, field: Field<'_>, what: &str) -> Result<GivenVector<R>, Invalid> {
    let v = vector::<R>(a, field)?;
    match normalize::<R>(v) {
        // Its length is reported (and a length beyond the precision's range would be infinity).
        Some(n) if !n.length.is_finite() => Err(Invalid::new(
            field,
            format!("{what} is too long for {}: its length overflows", R::NAME),
            if R::NAME == "f32" {
                "give a shorter vector in the same direction (only the direction is used), or use \
                 --precision f64"
            } else {
                "give a shorter vector in the same direction (only the direction is used)"
            },
        )),
        // A vector of length 1 within rounding is used as given, so that a direction written
        // out by phong itself (an explained ray) is read back bit for bit.
        Some(n) => Ok(GivenVector {
            given: v,
            length: n.length,
            unit: if is_unit_length(n.length) { v } else { n.unit },
        }),
        None => Err(Invalid::new(
            field,
            format!(
                "{what} is the zero vector (in {}), which has no direction",
                R::NAME
            ),
            "give a non-zero vector",
        )),
    }
}

/// The path of a mesh's OBJ file named `name` in a problem file in `folder` (relative names are
/// relative to the problem file's folder; `None`: to the working folder).
pub(crate) fn mesh_path(folder: Option<&Path>, name: &str) -> PathBuf {
    match folder {
        Some(dir) => dir.join(name),
        None => PathBuf::from(name),
    }
}
