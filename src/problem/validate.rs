//! Validation: turns a parsed [`ProblemFile`] into a [`Problem`] in precision `R`, or says which
//! field is wrong and how to fix it. Every number is checked to be finite in `R`; every vector
//! that is used as a direction to be non-zero; every term the question needs to have its inputs.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::error::Invalid;
use super::faults::{
    Bytes, CameraFault, ColourFault, DirectionOf, Kind, KindFault, LightFault, LightLabel,
    MaterialFault, NumberFault, PointOf, Purpose, RayCount, SettingFault, SurfaceFault,
    TargetFault,
};
use super::field::Field;
use super::format::{
    CameraSpec, ColorSpec, LightSpec, LightType, MaterialRef, MaterialSpec, ProblemFile,
    ReflectivitySpec, RenderSpec, ScaledColor, SurfaceSpec, SurfaceType, Triple,
};
use super::mesh;
use super::model::{
    AmbientInfo, Camera, GivenVector, LightInfo, NamedMaterial, Problem, ReflectivitySource,
    RenderSettings, Shared, Surface, SurfaceSource, Target, MAX_IMAGE_SIDE, MAX_LEVEL, MAX_LIGHTS,
    MAX_PIXEL_SAMPLES, MAX_SAMPLES,
};
use crate::core::vector::{between, is_unit_length, normalize};
use crate::core::{
    Cone, Falloff, Light, LightKind, LightSet, Material, Real, Transmission, Vector, V3,
};
use crate::geometry::{Plane, Ray, Shape, Sphere, Triangle};
use crate::text::Num;

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
    validate_for::<R>(file, base, Work::Image)
}

/// What a scene is read for, which decides the bounds its render settings are held to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Work {
    /// The whole image (and every other use): its primary rays, width × height × samples,
    /// within [`MAX_PIXEL_SAMPLES`], and one sample's tree within [`MAX_TREE_RAYS`].
    Image,
    /// One pixel explained (`--explain-pixel`): nothing of the image is traced or held, so
    /// neither bound of the image applies; the caller holds the pixel to its own,
    /// [`check_explanation`] (its samples' trees within [`MAX_EXPLAINED_RAYS`], far below a
    /// tree's bound), with the settings in force.
    Pixel,
    /// The whole image rendered with the command's settings over the file's (`phong render`'s
    /// flags; `phong tradeoff`'s sweep, which sets the level, weight and samples of every
    /// render, and `--size`): the caller holds the image to both bounds with the settings in
    /// force ([`check_work`], [`check_tree`]), so the file's own settings (its 8 samples,
    /// where `--samples 1` is given; its maximum level 60, which a sweep never traces) do not
    /// refuse it first.
    Rendered,
}

/// [`validate_in`], for `work`.
pub(crate) fn validate_for<R: Real>(
    file: &ProblemFile,
    base: Option<&Path>,
    work: Work,
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
        .and_then(|i| LightLabel::of(i.file_index, i.kind));
    let has_ambient = !ambient_info.is_empty();

    let target = match (&file.point, &file.ray) {
        (Some(_), Some(_)) => return Err(Invalid::of("ray", TargetFault::PointAndRay)),
        (None, None) if file.camera.is_some() => {
            if file.surfaces.is_empty() {
                return Err(Invalid::of("surfaces", TargetFault::SceneWithoutSurfaces));
            }
            let needs = Needs {
                ambient: has_ambient,
                diffuse: first_light,
                // Every camera ray gives V: specular always has one.
                specular: first_light,
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
        (None, None) => return Err(Invalid::of("point", TargetFault::NothingToShade)),
        (Some(point), None) => {
            if !file.surfaces.is_empty() {
                return Err(Invalid::of("surfaces", TargetFault::SurfacesWithPoint));
            }
            let position = point
                .position
                .map(|p| vector::<R>(p, Field::Name("point.position")))
                .transpose()?;
            let normal = point
                .normal
                .map(|n| direction::<R>(n, Field::Name("point.normal"), DirectionOf::Normal))
                .transpose()?;
            let (mat_field, material) =
                resolve_material::<R>(file, &point.material, Field::Name("point.material"))?;
            let needs = Needs {
                ambient: has_ambient,
                diffuse: first_light,
                specular: viewer.and(first_light),
            };
            needs.check(&material.spec, mat_field)?;
            // Point and normal: only where the question needs them.
            let positional = light_info
                .iter()
                .zip(&lights.lights)
                .find(|(_, l)| l.position().is_some());
            if position.is_none() {
                if let Some(light) =
                    positional.and_then(|(info, _)| LightLabel::of(info.file_index, info.kind))
                {
                    return Err(Invalid::of(
                        "point.position",
                        TargetFault::PositionForLight { light },
                    ));
                }
                if viewer.is_some() {
                    return Err(Invalid::of(
                        "point.position",
                        TargetFault::PositionForViewer,
                    ));
                }
            }
            if normal.is_none() {
                if let Some(light) = first_light {
                    return Err(Invalid::of(
                        "point.normal",
                        TargetFault::NormalForLight { light },
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
            let origin = position::<R>(ray.origin, Field::Name("ray.origin"), PointOf::RayOrigin)?;
            let dir = direction::<R>(
                ray.direction,
                Field::Name("ray.direction"),
                DirectionOf::RayDirection,
            )?;
            if file.surfaces.is_empty() {
                return Err(Invalid::of("surfaces", TargetFault::RayWithoutSurfaces));
            }
            let needs = Needs {
                ambient: has_ambient,
                diffuse: first_light,
                // V comes from the viewer, or from the ray itself: specular always has one.
                specular: first_light,
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
    if let (Some(c), Work::Image) = (&camera, work) {
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
    if problem.camera.is_some() && work == Work::Image {
        let s = &problem.render;
        check_tree(&problem, s.max_level, s.min_weight.to_f64())
            .map_err(|e| e.at("render.max_level"))?;
    }
    Ok(problem)
}

/// The camera: E ≠ the look-at point, `up` not along the line of sight, 0 < fov < 180, and an
/// image size the tracer accepts.
fn camera<R: Real>(c: &CameraSpec) -> Result<Camera<R>, Invalid> {
    let eye = position::<R>(c.eye, Field::Name("camera.eye"), PointOf::Eye)?;
    let look_at = position::<R>(c.look_at, Field::Name("camera.look_at"), PointOf::LookAt)?;
    let up = vector::<R>(c.up.unwrap_or([0.0, 1.0, 0.0]), Field::Name("camera.up"))?;
    let Some(forward) = between::<R>(eye, look_at) else {
        return Err(Invalid::of("camera.look_at", CameraFault::LooksAtEye));
    };
    if normalize::<R>(Vector::cross(forward.unit, up)).is_none() {
        return Err(Invalid::of("camera.up", CameraFault::NoUp));
    }
    if !(c.fov > 0.0 && c.fov < 180.0) {
        return Err(Invalid::of(
            "camera.fov",
            CameraFault::NotAFov { fov: show(c.fov) },
        ));
    }
    // The image plane's half-height tan(fov/2), as the tracer computes it: in f32,
    // 179.999999999 rounds to 180 and the tangent of the rounded half-angle is negative (the
    // image would be upside down); 1e-46 rounds to 0.
    let fov = number::<R>(c.fov, Field::Name("camera.fov"))?;
    let half_height = (fov.to_radians() / R::TWO).tan();
    if !(half_height > R::ZERO && half_height.is_finite()) {
        let (fov, precision) = (show(c.fov), R::NAME);
        let fault = if c.fov < 90.0 {
            CameraFault::FovTooSmall { fov, precision }
        } else {
            CameraFault::FovNear180 { fov, precision }
        };
        return Err(Invalid::of("camera.fov", fault));
    }
    let max = MAX_IMAGE_SIDE;
    for (name, side, fault) in [
        (
            "width",
            c.width,
            CameraFault::WidthOutside { side: c.width, max },
        ),
        (
            "height",
            c.height,
            CameraFault::HeightOutside {
                side: c.height,
                max,
            },
        ),
    ] {
        if side == 0 || side > MAX_IMAGE_SIDE {
            return Err(Invalid::of(format!("camera.{name}"), fault));
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

/// The maximum level must let at least the primary rays through, and is at most [`MAX_LEVEL`].
pub(crate) fn check_max_level(level: u32) -> Result<(), SettingFault> {
    if level == 0 {
        return Err(SettingFault::LevelZero { max: MAX_LEVEL });
    }
    if level > MAX_LEVEL {
        return Err(SettingFault::LevelOutside {
            level,
            max: MAX_LEVEL,
        });
    }
    Ok(())
}

/// A render's primary rays, width × height × samples, are at most [`MAX_PIXEL_SAMPLES`].
pub(crate) fn check_work(width: u32, height: u32, samples: u32) -> Result<(), SettingFault> {
    let work = u64::from(width) * u64::from(height) * u64::from(samples);
    if work > MAX_PIXEL_SAMPLES {
        let most = MAX_PIXEL_SAMPLES / (u64::from(width) * u64::from(height)).max(1);
        let max = MAX_PIXEL_SAMPLES;
        return Err(if most >= 1 {
            SettingFault::TooMuchWork {
                width,
                height,
                samples,
                work,
                max,
                most,
            }
        } else {
            SettingFault::ImageTooLarge {
                width,
                height,
                samples,
                work,
                max,
            }
        });
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
/// the tree is a chain, one ray a level while its weight HI^(d−1) can exceed the minimum
/// weight: the primary ray alone where no material reflects or transmits.
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
        if hi <= 0.0 {
            return 1;
        }
        let (ln_hi, ln_min) = (hi.ln(), min_weight.ln());
        let levels = (1..=max_level)
            .take_while(|&d| d == 1 || min_weight <= 0.0 || f64::from(d - 1) * ln_hi > ln_min)
            .count();
        return levels as u64;
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
) -> Result<(), SettingFault> {
    let rays = tree_rays(problem, max_level, min_weight);
    if rays > MAX_TREE_RAYS {
        return Err(SettingFault::TreeTooLarge {
            level: max_level,
            weight: show(min_weight),
            rays: RayCount(rays),
            max: MAX_TREE_RAYS,
        });
    }
    Ok(())
}

/// The most rays an explained pixel (`--explain-pixel`) may hold in all its samples (2^13).
/// Each ray is solved and written out in full: measured on the glass scene, about 4 KB of text,
/// 10 KB of JSON and 18 KB of HTML per ray, and while the document is laid out up to about
/// 170 KB of memory per ray (Markdown, LaTeX, HTML). 8192 rays are then at most about 150 MB of
/// output and 1.4 GB of memory, where a render's own bounds would let one pixel hold 4096
/// samples of 2^20 rays each (terabytes). The bundled scenes at their own settings (one sample)
/// hold at most 41 rays (the glass scene's tree; the others are chains of at most 8).
pub(crate) const MAX_EXPLAINED_RAYS: u64 = 1 << 13;

/// An explained pixel's samples within [`MAX_EXPLAINED_RAYS`] rays in all, each sample's tree
/// counted as [`tree_rays`] bounds it with the problem's render settings: refused before
/// anything is traced, rather than filling the memory and the disk.
pub(crate) fn check_explanation<R: Real>(problem: &Problem<R>) -> Result<(), SettingFault> {
    let s = &problem.render;
    let (level, min_weight) = (s.max_level, s.min_weight.to_f64());
    let tree = tree_rays(problem, level, min_weight);
    if tree > MAX_EXPLAINED_RAYS {
        return Err(SettingFault::ExplainedTreeTooLarge {
            level,
            weight: show(min_weight),
            tree: RayCount(tree),
            max: MAX_EXPLAINED_RAYS,
        });
    }
    let rays = tree.saturating_mul(u64::from(s.samples));
    if rays > MAX_EXPLAINED_RAYS {
        return Err(SettingFault::ExplanationTooLarge {
            samples: s.samples,
            level,
            weight: show(min_weight),
            tree: RayCount(tree),
            rays: RayCount(rays),
            max: MAX_EXPLAINED_RAYS,
            most: MAX_EXPLAINED_RAYS / tree.max(1),
        });
    }
    Ok(())
}

/// The minimum weight is a finite number ≥ 0.
pub(crate) fn check_min_weight(w: f64) -> Result<(), SettingFault> {
    if !(w.is_finite() && w >= 0.0) {
        return Err(SettingFault::NotAWeight { weight: show(w) });
    }
    Ok(())
}

/// Samples per pixel: 1 to [`MAX_SAMPLES`].
pub(crate) fn check_samples(n: u32) -> Result<(), SettingFault> {
    if n == 0 || n > MAX_SAMPLES {
        return Err(SettingFault::SamplesOutside {
            samples: n,
            max: MAX_SAMPLES,
        });
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
            return Err(Invalid::of(
                format!("surfaces[{i}]"),
                SurfaceFault::TooMany {
                    max: mesh::MAX_TRIANGLES,
                },
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
            self.named.insert(name.to_string(), m.clone());
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

/// `lights[1] (point)`, in English. Transitional, for the solver's messages still written as
/// English text; a message names a light by a [`LightLabel`], in its language.
pub(crate) fn light_label(file_index: usize, kind: &str) -> String {
    format!("lights[{file_index}] ({kind})")
}

/// Which terms the question computes, and so which material fields it needs.
struct Needs {
    ambient: bool,
    /// The first light that needs O_d, if any.
    diffuse: Option<LightLabel>,
    /// The first light that needs O_s and n_s (there is a viewer), if any.
    specular: Option<LightLabel>,
}

impl Needs {
    fn check(&self, m: &MaterialSpec, field: Field<'_>) -> Result<(), Invalid> {
        if self.ambient && m.ambient.is_none() {
            return Err(Invalid::of(
                field.key("ambient"),
                MaterialFault::AmbientMissing,
            ));
        }
        if let Some(light) = self.diffuse {
            if m.diffuse.is_none() {
                return Err(Invalid::of(
                    field.key("diffuse"),
                    MaterialFault::DiffuseMissing { light },
                ));
            }
        }
        if let Some(light) = self.specular {
            if m.specular.is_none() {
                return Err(Invalid::of(
                    field.key("specular"),
                    MaterialFault::SpecularMissing { light },
                ));
            }
            if m.shininess.is_none() {
                return Err(Invalid::of(
                    field.key("shininess"),
                    MaterialFault::ShininessMissing { light },
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
        return Err(Invalid::of(
            "lights",
            LightFault::TooMany {
                count: specs.len(),
                max: MAX_LIGHTS,
            },
        ));
    }
    let mut info = Vec::new();
    let mut ambient_info = Vec::new();
    for (i, spec) in specs.iter().enumerate() {
        let base = LIGHTS.index(i);
        let f = |name: &'static str| Field::Key(&base, name);
        let what = Kind::Light(spec.kind);
        if spec.present_mask() & !spec.kind.fields_mask() != 0 {
            check_fields(base, what, spec.kind.fields(), spec.present())?;
        }
        let name = spec.name.clone();
        let c = color::<R>(
            required(spec.color, base, "color", what)?,
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
                let (position, falloff) = position_and_falloff::<R>(spec, base, what)?;
                LightKind::Point { position, falloff }
            }
            LightType::Directional => {
                let d = required(spec.direction, base, "direction", what)?;
                let d = direction::<R>(d, f("direction"), DirectionOf::LightDirection)?;
                direction_length = (!is_unit_length(d.length)).then_some(d.length);
                LightKind::Directional { direction: d.unit }
            }
            LightType::Spot => {
                let axis = required(spec.axis, base, "axis", what)?;
                let axis = direction::<R>(axis, f("axis"), DirectionOf::ConeAxis)?;
                direction_length = (!is_unit_length(axis.length)).then_some(axis.length);
                let angle = required(spec.angle, base, "angle", what)?;
                if !(0.0..=90.0).contains(&angle) {
                    return Err(Invalid::of(
                        f("angle"),
                        LightFault::AngleOutside { angle: show(angle) },
                    ));
                }
                let exponent = required(spec.exponent, base, "exponent", what)?;
                let e = number::<R>(exponent, f("exponent"))?;
                if e < R::ZERO {
                    return Err(Invalid::of(
                        f("exponent"),
                        LightFault::NegativeExponent {
                            exponent: show(exponent),
                        },
                    ));
                }
                let (position, falloff) = position_and_falloff::<R>(spec, base, what)?;
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

/// P_l and f of a point or spot light.
fn position_and_falloff<R: Real>(
    spec: &LightSpec,
    base: Field<'_>,
    what: Kind,
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
    kind: Kind,
    takes: &[&str],
    mut present: impl Iterator<Item = &'static str>,
) -> Result<(), Invalid> {
    match present.find(|f| !takes.contains(f)) {
        Some(extra) => Err(Invalid::of(
            base.key(extra),
            KindFault::NotTaken {
                kind,
                extra: extra.to_owned(),
                takes: quoted(takes),
            },
        )),
        None => Ok(()),
    }
}

/// A field the type requires: its value, or an error naming it and what it is for.
fn required<T>(value: Option<T>, base: Field<'_>, name: &str, kind: Kind) -> Result<T, Invalid> {
    value.ok_or_else(|| {
        Invalid::of(
            base.key(name),
            KindFault::Missing {
                kind,
                name: name.to_owned(),
                purpose: Purpose::of(name),
            },
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
    f.ok_or_else(|| Invalid::of(field, LightFault::NotAFalloff { falloff: show(x) }))
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
    let what = Kind::Surface(s.kind);
    if s.present_mask() & !s.kind.fields_mask() != 0 {
        check_fields(base, what, s.kind.fields(), s.present())?;
    }
    let (shape, normal) = match s.kind {
        SurfaceType::Plane => {
            let n = required(s.normal.as_deref().copied(), base, "normal", what)?;
            let n = direction::<R>(n, f("normal"), DirectionOf::PlaneNormal)?;
            let plane = Plane {
                point: position::<R>(
                    required(s.point.as_deref().copied(), base, "point", what)?,
                    f("point"),
                    PointOf::PlanePoint,
                )?,
                normal: n.unit,
            };
            (Shape::Plane(plane), Some(Box::new(n)))
        }
        SurfaceType::Sphere => {
            let radius = required(s.radius, base, "radius", what)?;
            let r = number::<R>(radius, f("radius"))?;
            if radius > 0.0 && r == R::ZERO {
                return Err(Invalid::of(
                    f("radius"),
                    SurfaceFault::RadiusRoundsToZero {
                        radius: show(radius),
                        precision: R::NAME,
                    },
                ));
            }
            if r <= R::ZERO {
                return Err(Invalid::of(
                    f("radius"),
                    SurfaceFault::NotARadius {
                        radius: show(radius),
                    },
                ));
            }
            // Within the bound the ray–sphere test can square (see `max_coordinate`).
            let max = crate::geometry::max_coordinate::<R>();
            if radius > max {
                let (radius, max) = (show(radius), Num(max));
                return Err(Invalid::of(
                    f("radius"),
                    if R::NAME == "f32" {
                        SurfaceFault::RadiusTooLargeF32 { radius, max }
                    } else {
                        SurfaceFault::RadiusTooLarge {
                            radius,
                            max,
                            precision: R::NAME,
                        }
                    },
                ));
            }
            let center = required(s.center, base, "center", what)?;
            let sphere = Sphere {
                center: position::<R>(center, f("center"), PointOf::SphereCentre)?,
                radius: r,
            };
            (Shape::Sphere(sphere), None)
        }
        SurfaceType::Triangle => {
            let v = required(s.vertices.as_deref(), base, "vertices", what)?;
            let vertices = f("vertices");
            let mut p = [V3::<R>::ZERO; 3];
            // Within the bound the ray–triangle test can multiply: past it a ray could miss the
            // triangle without a word, and its edges overflow (it would read as degenerate).
            for (k, corner) in v.iter().enumerate() {
                p[k] = vector::<R>(*corner, vertices.index(k))?;
                if let Some(j) = beyond_bound::<R>(corner) {
                    let max = crate::geometry::max_coordinate::<R>();
                    let (value, max) = (show(corner[j]), Num(max));
                    return Err(Invalid::of(
                        vertices.index(k).index(j),
                        if R::NAME == "f32" {
                            SurfaceFault::CornerTooLargeF32 { value, max }
                        } else {
                            SurfaceFault::CornerTooLarge {
                                value,
                                max,
                                precision: R::NAME,
                            }
                        },
                    ));
                }
            }
            let t = Triangle { p, normals: None };
            if t.normal().is_none() {
                return Err(Invalid::of(
                    f("vertices"),
                    SurfaceFault::Degenerate { precision: R::NAME },
                ));
            }
            (Shape::Triangle(t), None)
        }
        SurfaceType::Mesh => {
            let name = required(s.file.as_ref(), base, "file", what)?;
            let mref = required(s.material.as_ref(), base, "material", what)?;
            let (mat_field, material) = materials.resolve(file, mref, f("material"))?;
            needs.check(&material.spec, mat_field)?;
            let path = mesh_path(folder, name);
            let triangles =
                mesh::load_obj::<R>(&path).map_err(|e| Invalid::of(f("file"), e.at(&path)))?;
            if out.len() + triangles.len() > mesh::MAX_TRIANGLES {
                return Err(Invalid::of(
                    f("file"),
                    SurfaceFault::MeshTooLarge {
                        path,
                        triangles: triangles.len(),
                        max: mesh::MAX_TRIANGLES,
                    },
                ));
            }
            crate::text::memory::handled(|| out.try_reserve(triangles.len())).map_err(|_| {
                let bytes = triangles
                    .len()
                    .saturating_mul(std::mem::size_of::<Surface<R>>());
                Invalid::of(
                    f("file"),
                    SurfaceFault::MeshOutOfMemory { size: Bytes(bytes) },
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
    let mref = required(s.material.as_ref(), base, "material", what)?;
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
        MaterialRef::Name(name) => match file.materials.get(name.as_str()) {
            Some(spec) => (MATERIALS.key(name), Some(name.to_string()), spec),
            None => {
                let known: Vec<_> = file.materials.keys().map(|k| format!("\"{k}\"")).collect();
                let name = name.to_string();
                let fault = if known.is_empty() {
                    MaterialFault::NoSuchMaterial { name }
                } else {
                    MaterialFault::NoSuchMaterialOf {
                        name,
                        known: known.join(", "),
                    }
                };
                return Err(Invalid::of(field, fault));
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
                return Err(Invalid::of(
                    f("shininess"),
                    MaterialFault::NegativeShininess { shininess: show(x) },
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
                return Err(Invalid::of(
                    f("reflectivity"),
                    MaterialFault::ReflectivityWithoutSpecular,
                ))
            }
        },
    };
    let transmission = transmission::<R>(spec, &field)?;
    Ok(NamedMaterial {
        name: None,
        spec: std::sync::Arc::new(spec.clone()),
        material: Shared::new(Material {
            o_a,
            o_d,
            o_s,
            n_s,
            o_r,
            transmission,
        }),
        reflectivity: source,
    })
}

/// The smallest index of refraction a material may give ([`MAX_IOR`] is the largest).
pub(crate) const MIN_IOR: f64 = 1e-3;

/// The largest index of refraction a material may give: 1000, far past any material's
/// (diamond's is 2.42, germanium's about 4 in the infrared), and small enough that Snell's law
/// cannot overflow in f32 or f64 (`core::secondary::Refraction::at`). With
/// 10^-3 ≤ η ≤ 10^3 (η rounded to f32 stays inside to a relative 2^-24), η_r = η_i/η_t is η
/// or 1/η, so 10^-3(1 − u) ≤ η_r ≤ 10^3(1 + u) for the precision's unit roundoff u ≤ 2^-24;
/// sin²θ_i = max(1 − cos²θ_i, 0) lies in [0, 1] for unit N and V; so
/// η_r² sin²θ_i ≤ 10^6(1 + u)^3, k = 1 − η_r² sin²θ_i ≥ −1.01e6, and each component of
/// T = η_r V + (η_r cos θ_i − √k) N, with |V|, |N|, |cos θ_i| ≤ 1 + u and √k ≤ 1, is at most
/// about 2·10^3 + 1: every quantity is within 10^7 of 0, against f32's largest 3.4·10^38,
/// and no square underflows (η_r² ≥ 10^-6(1 − u)^3, f32's smallest normal is 1.2·10^-38).
/// An η of 10^-300 or 10^200 gave k = −inf (the report printed `k = … = -inf`).
pub(crate) const MAX_IOR: f64 = 1e3;

/// O_t and η (docs/conventions.md, "Transmission"): both or neither, O_t a colour in [0, 1]
/// and η a number from [`MIN_IOR`] to [`MAX_IOR`].
fn transmission<R: Real>(
    spec: &MaterialSpec,
    field: &Field<'_>,
) -> Result<Option<Transmission<R>>, Invalid> {
    let f = |name: &'static str| Field::Key(field, name);
    match (spec.transmissivity, spec.ior) {
        (None, None) => Ok(None),
        (Some(_), None) => Err(Invalid::of(f("ior"), MaterialFault::IorMissing)),
        (None, Some(_)) => Err(Invalid::of(
            f("transmissivity"),
            MaterialFault::TransmissivityMissing,
        )),
        (Some(o_t), Some(eta)) => {
            let o_t = color::<R>(o_t, f("transmissivity"), ColorRange::Material)?;
            if eta <= 0.0 {
                return Err(Invalid::of(
                    f("ior"),
                    MaterialFault::IorNotPositive { ior: show(eta) },
                ));
            }
            if !(MIN_IOR..=MAX_IOR).contains(&eta) {
                return Err(Invalid::of(
                    f("ior"),
                    MaterialFault::IorOutside {
                        ior: show(eta),
                        min: show(MIN_IOR),
                        max: show(MAX_IOR),
                    },
                ));
            }
            let value = number::<R>(eta, f("ior"))?;
            Ok(Some(Transmission { o_t, eta: value }))
        }
    }
}

fn material_color<R: Real>(c: &ColorSpec, field: Field<'_>) -> Result<V3<R>, Invalid> {
    if let ColorSpec::Scaled(ScaledColor { k, color: o }) = c {
        if !(0.0..=1.0).contains(k) {
            return Err(Invalid::of(
                field.key("k"),
                MaterialFault::CoefficientOutside { k: show(*k) },
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
        // The numbers as the file writes them (2, not 2.0; 1e39, not 40 digits).
        let [r, g, b] = c.map(show);
        let fault = match range {
            ColorRange::Light => ColourFault::Light { r, g, b },
            ColorRange::Material => ColourFault::Material { r, g, b },
            ColorRange::Background => ColourFault::Background { r, g, b },
        };
        return Err(Invalid::of(field, fault));
    }
    Ok(v)
}

fn number<R: Real>(x: f64, field: Field<'_>) -> Result<R, Invalid> {
    let r = R::from_f64(x);
    if !x.is_finite() || !r.is_finite() {
        let value = show(x);
        return Err(Invalid::of(
            field,
            if R::NAME == "f32" {
                NumberFault::NotFiniteF32 { value }
            } else {
                NumberFault::NotFinite {
                    value,
                    precision: R::NAME,
                }
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

/// The first coordinate of `a` beyond what the intersection tests can multiply in `R`
/// ([`crate::geometry::max_coordinate`]), if any.
fn beyond_bound<R: Real>(a: &Triple) -> Option<usize> {
    let max = crate::geometry::max_coordinate::<R>();
    a.iter().position(|x| x.abs() > max)
}

/// A point the intersection tests take the coordinates of (`of`: a ray's origin, the camera's
/// eye, a sphere's centre, …): finite in `R` ([`vector`]), and within the bound the tests can
/// multiply ([`crate::geometry::max_coordinate`]), past which a ray could miss a surface
/// without a word.
fn position<R: Real>(a: Triple, field: Field<'_>, of: PointOf) -> Result<V3<R>, Invalid> {
    let v = vector::<R>(a, field)?;
    if let Some(j) = beyond_bound::<R>(&a) {
        let (value, max) = (show(a[j]), Num(crate::geometry::max_coordinate::<R>()));
        return Err(Invalid::of(
            field.index(j),
            if R::NAME == "f32" {
                NumberFault::CoordinateTooLargeF32 { value, of, max }
            } else {
                NumberFault::CoordinateTooLarge {
                    value,
                    of,
                    max,
                    precision: R::NAME,
                }
            },
        ));
    }
    Ok(v)
}

fn direction<R: Real>(
    a: Triple,
    field: Field<'_>,
    of: DirectionOf,
) -> Result<GivenVector<R>, Invalid> {
    let v = vector::<R>(a, field)?;
    match normalize::<R>(v) {
        // Its length is reported (and a length beyond the precision's range would be infinity).
        Some(n) if !n.length.is_finite() => Err(Invalid::of(
            field,
            if R::NAME == "f32" {
                NumberFault::TooLongF32 { vector: of }
            } else {
                NumberFault::TooLong {
                    vector: of,
                    precision: R::NAME,
                }
            },
        )),
        // A vector of length 1 within rounding is used as given, so that a direction written
        // out by phong itself (an explained ray) is read back bit for bit.
        Some(n) => Ok(GivenVector {
            given: v,
            length: n.length,
            unit: if is_unit_length(n.length) { v } else { n.unit },
        }),
        None => Err(Invalid::of(
            field,
            NumberFault::ZeroVector {
                vector: of,
                precision: R::NAME,
            },
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
