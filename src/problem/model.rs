//! A validated problem, in the precision it will be solved in: the core's types plus what the
//! explanation needs to say about how each quantity was given.

use std::sync::Arc;

use super::error::Invalid;
use super::format::MaterialSpec;
use super::validate::{check_max_level, check_min_weight, check_samples};
use crate::core::{LightSet, Material, Real, V3};
use crate::geometry::{Ray, Shape};

/// A problem ready to solve.
#[derive(Clone, Debug)]
pub struct Problem<R: Real> {
    /// The file's `title`, shown as the explanation's heading.
    pub title: Option<Arc<str>>,
    /// The title in Portuguese, when the file gives one.
    pub title_pt: Option<Arc<str>>,
    /// The file's `question`, as written.
    pub question: Option<Arc<str>>,
    /// The question in Portuguese, when the file gives one.
    pub question_pt: Option<Arc<str>>,
    /// I_a and the point, directional and spot lights, as the core takes them.
    pub lights: LightSet<R>,
    /// For each light in `lights.lights`, where it came from.
    pub light_info: Vec<LightInfo<R>>,
    /// The ambient lights, each as given.
    pub ambient_info: Vec<AmbientInfo<R>>,
    /// E, the viewer's position.
    pub viewer: Option<V3<R>>,
    /// What is shaded: a point, the nearest hit of a ray, or a scene to render.
    pub target: Target<R>,
    /// The camera of a scene (`phong render`).
    pub camera: Option<Camera<R>>,
    /// The colour of a ray that hits nothing.
    pub background: V3<R>,
    /// How rays are traced (Section 4.4).
    pub render: RenderSettings<R>,
    /// Likely unit mistakes in the file (never errors): a 0–255 colour, a spot angle in
    /// radians.
    pub warnings: Vec<super::warnings::Warning>,
}

impl<R: Real> Problem<R> {
    /// The surfaces rays can hit: a ray problem's or a scene's (none for a point problem).
    pub fn surfaces(&self) -> &[Surface<R>] {
        match &self.target {
            Target::Point { .. } => &[],
            Target::Ray { surfaces, .. } | Target::Scene { surfaces } => surfaces,
        }
    }
}

/// A pinhole camera, validated: the eye differs from the look-at point and `up` is not along
/// the line of sight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera<R: Real> {
    /// The eye: E of every primary ray.
    pub eye: V3<R>,
    /// The point the camera looks at, seen at the image's centre.
    pub look_at: V3<R>,
    /// Which way is up in the image (any vector not along the line of sight).
    pub up: V3<R>,
    /// Vertical field of view in degrees, 0 < fov < 180.
    pub fov: R,
    /// The image's width in pixels.
    pub width: u32,
    /// The image's height in pixels.
    pub height: u32,
}

/// The tracer's settings (Section 4.4; docs/conventions.md, "Recursion level" and "Weight").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings<R: Real> {
    /// Rays are traced while their level ≤ this; the primary ray has level 1.
    pub max_level: u32,
    /// A reflection ray is traced only while its weight exceeds this.
    pub min_weight: R,
    /// Whether shadow rays are traced.
    pub shadows: bool,
    /// Samples per pixel.
    pub samples: u32,
}

impl<R: Real> Default for RenderSettings<R> {
    fn default() -> Self {
        RenderSettings {
            max_level: DEFAULT_MAX_LEVEL,
            min_weight: R::from_f64(DEFAULT_MIN_WEIGHT),
            shadows: true,
            samples: 1,
        }
    }
}

/// Settings given over a problem's own `render` (the command line's `--max-level`,
/// `--min-weight`, `--samples`, `--shadows`); `None` keeps the problem's.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct RenderOverrides {
    pub max_level: Option<u32>,
    pub min_weight: Option<f64>,
    pub samples: Option<u32>,
    pub shadows: Option<bool>,
}

impl<R: Real> RenderSettings<R> {
    /// These settings with `overrides` over them, each checked by the rules of the file's
    /// `render`; a refused one is named by its field in [`RenderOverrides`] (`max_level`).
    pub(crate) fn with(self, overrides: &RenderOverrides) -> Result<Self, Invalid> {
        let mut s = self;
        if let Some(level) = overrides.max_level {
            check_max_level(level).map_err(|e| e.at("max_level"))?;
            s.max_level = level;
        }
        if let Some(w) = overrides.min_weight {
            check_min_weight(w).map_err(|e| e.at("min_weight"))?;
            s.min_weight = R::from_f64(w);
        }
        if let Some(n) = overrides.samples {
            check_samples(n).map_err(|e| e.at("samples"))?;
            s.samples = n;
        }
        if let Some(on) = overrides.shadows {
            s.shadows = on;
        }
        Ok(s)
    }
}

/// The default maximum recursion level.
pub(crate) const DEFAULT_MAX_LEVEL: u32 = 5;
/// The default minimum weight, 1/255: a ray of lower weight cannot change an 8-bit pixel of a
/// colour in [0, 1] by a whole step. POV-Ray's `adc_bailout` default is the same.
pub(crate) const DEFAULT_MIN_WEIGHT: f64 = 1.0 / 255.0;
/// The largest image side accepted.
pub(crate) const MAX_IMAGE_SIDE: u32 = 16384;
/// The most samples per pixel accepted.
pub(crate) const MAX_SAMPLES: u32 = 4096;
/// The largest maximum recursion level: 1000. A path's k-th ray has weight ∏ O_r; past 1000
/// reflections it cannot change an 8-bit pixel (0.99^1000 ≈ 4e-5 < 1/510) unless its surfaces
/// reflect more than 99%, while a larger level only lets two facing mirrors trace without end.
pub(crate) const MAX_LEVEL: u32 = 1000;
/// The most primary rays (width × height × samples) one render may trace: 2^30, about
/// 1.07e9 (1920×1080 at 512 samples, or 16384² at 4), an hour or so on a laptop.
pub(crate) const MAX_PIXEL_SAMPLES: u64 = 1 << 30;
/// The most lights a problem may have: 100,000 (the chapter's have one to three).
pub(crate) const MAX_LIGHTS: usize = 100_000;

/// Where a light came from in the file.
#[derive(Clone, Debug)]
pub struct LightInfo<R: Real> {
    /// Its index in the file's `lights` array.
    pub file_index: usize,
    /// The light's `name` in the file.
    pub name: Option<Arc<str>>,
    /// The name in Portuguese, when the file gives one.
    pub name_pt: Option<Arc<str>>,
    /// "point", "directional" or "spot".
    pub kind: &'static str,
    /// The length of the given direction or axis, when it was not 1 (it was normalised).
    pub direction_length: Option<R>,
}

/// An ambient light as given.
#[derive(Clone, Debug)]
pub struct AmbientInfo<R: Real> {
    /// Its index in the file's `lights` array.
    pub file_index: usize,
    /// Its `name` in the file.
    pub name: Option<Arc<str>>,
    /// The name in Portuguese, when the file gives one.
    pub name_pt: Option<Arc<str>>,
    /// Its colour, which adds to I_a (Eq. 4.5).
    pub color: V3<R>,
}

/// A vector as given, its length and the unit vector used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GivenVector<R: Real> {
    /// The vector as written.
    pub given: V3<R>,
    /// Its length, ‖given‖.
    pub length: R,
    /// given/‖given‖, or `given` itself when its length is 1 within rounding.
    pub unit: V3<R>,
}

/// Where O_r came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReflectivitySource {
    /// O_r given as a colour.
    Explicit,
    /// O_r = O_s, as the problem asked.
    Specular,
}

/// A material with its name and how it was written.
#[derive(Clone, Debug)]
pub struct NamedMaterial<R: Real> {
    /// Its name in the file's `materials`; `None` for a material written in place.
    pub name: Option<Arc<str>>,
    /// The material as written (to say how each colour was given); shared by every surface of
    /// a named material (a scene of 100,000 spheres holds one copy per material, not per sphere).
    pub spec: std::sync::Arc<MaterialSpec>,
    /// The material as the core takes it; shared as `spec` is (184 bytes in f64, which made
    /// each surface of a 100,000-sphere scene twice as large).
    pub material: Shared<Material<R>>,
    /// Where O_r came from; `None` without O_r.
    pub reflectivity: Option<ReflectivitySource>,
}

/// A value held once by everything that has it (an [`Arc`]), read through `Deref` as the value
/// itself; a change through `DerefMut` changes a copy of its own ([`Arc::make_mut`]), so a
/// changed surface never changes another.
#[derive(Clone, Debug, PartialEq)]
pub struct Shared<T>(Arc<T>);

impl<T> Shared<T> {
    /// `value`, to be shared.
    pub fn new(value: T) -> Self {
        Shared(Arc::new(value))
    }
}

impl<T> std::ops::Deref for Shared<T> {
    type Target = T;
    #[inline]
    fn deref(&self) -> &T {
        &self.0
    }
}

impl<T: Clone> std::ops::DerefMut for Shared<T> {
    #[inline]
    fn deref_mut(&mut self) -> &mut T {
        Arc::make_mut(&mut self.0)
    }
}

/// What is shaded.
#[derive(Clone, Debug)]
pub enum Target<R: Real> {
    /// A given point: P, N and the material (P and N only where the question needs them).
    Point {
        /// P; `None` when the question does not need it.
        position: Option<V3<R>>,
        /// N as given; `None` when the question does not need it.
        normal: Option<GivenVector<R>>,
        /// The material at P.
        material: NamedMaterial<R>,
    },
    /// The nearest hit (t > 0) of a ray with the surfaces.
    Ray {
        /// The ray, with D of unit length.
        ray: Ray<R>,
        /// D as given, its length and the unit vector used.
        direction: GivenVector<R>,
        /// The surfaces it can hit.
        surfaces: Vec<Surface<R>>,
    },
    /// A scene to render: surfaces and a camera, nothing single to shade.
    Scene {
        /// The surfaces rays can hit (the camera is the problem's `camera`).
        surfaces: Vec<Surface<R>>,
    },
}

/// A surface of a ray problem.
#[derive(Clone, Debug)]
pub struct Surface<R: Real> {
    /// The surface's geometry.
    pub shape: Shape<R>,
    /// Its material.
    pub material: NamedMaterial<R>,
    /// A plane's normal as given. Boxed: a scene holds a plane or two and many spheres or
    /// triangles, and in place it made every surface 56 bytes larger (216 bytes in f64, 21.6 MB
    /// for 100,000 spheres, the largest block of a large scene's render).
    pub normal: Option<Box<GivenVector<R>>>,
    /// Where it came from: its index in the file's `surfaces`, and for a mesh the triangle's
    /// index in the mesh.
    pub source: SurfaceSource,
}

/// Where a surface came from in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SurfaceSource {
    /// Its index in the file's `surfaces`.
    pub index: usize,
    /// For a mesh, the triangle's index in it; `None` for other surfaces.
    pub triangle: Option<usize>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(target_pointer_width = "64")]
    fn a_validated_surface_stays_small() {
        // A scene of 100,000 spheres holds 100,000 of these for the whole render: a plane's
        // normal as given (56 bytes in f64) is boxed. 216 bytes in f64 before it was: the
        // shape 88, the material 40, the normal 64, the source 24.
        let size = std::mem::size_of::<Surface<f64>>();
        assert!(size <= 160, "Surface<f64> is {size} bytes");
    }
}
