//! A validated problem, in the precision it will be solved in: the core's types plus what the
//! explanation needs to say about how each quantity was given.

use super::format::MaterialSpec;
use crate::core::{LightSet, Material, Real, V3};
use crate::geometry::{Ray, Shape};

/// A problem ready to solve.
#[derive(Clone, Debug)]
pub struct Problem<R: Real> {
    pub title: Option<String>,
    pub question: Option<String>,
    /// I_a and the point, directional and spot lights, as the core takes them.
    pub lights: LightSet<R>,
    /// For each light in `lights.lights`, where it came from.
    pub light_info: Vec<LightInfo<R>>,
    /// The ambient lights, each as given.
    pub ambient_info: Vec<AmbientInfo<R>>,
    /// E, the viewer's position.
    pub viewer: Option<V3<R>>,
    pub target: Target<R>,
}

/// Where a light came from in the file.
#[derive(Clone, Debug)]
pub struct LightInfo<R: Real> {
    /// Its index in the file's `lights` array.
    pub file_index: usize,
    pub name: Option<String>,
    /// "point", "directional" or "spot".
    pub kind: &'static str,
    /// The length of the given direction or axis, when it was not 1 (it was normalised).
    pub direction_length: Option<R>,
}

/// An ambient light as given.
#[derive(Clone, Debug)]
pub struct AmbientInfo<R: Real> {
    pub file_index: usize,
    pub name: Option<String>,
    pub color: V3<R>,
}

/// A vector as given, its length and the unit vector used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GivenVector<R: Real> {
    pub given: V3<R>,
    pub length: R,
    pub unit: V3<R>,
}

/// Where O_r came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReflectivitySource {
    Explicit,
    /// O_r = O_s, as the problem asked.
    Specular,
}

/// A material with its name and how it was written.
#[derive(Clone, Debug)]
pub struct NamedMaterial<R: Real> {
    pub name: Option<String>,
    pub spec: MaterialSpec,
    pub material: Material<R>,
    pub reflectivity: Option<ReflectivitySource>,
}

/// What is shaded.
#[derive(Clone, Debug)]
pub enum Target<R: Real> {
    /// A given point: P, N and the material (P and N only where the question needs them).
    Point {
        position: Option<V3<R>>,
        normal: Option<GivenVector<R>>,
        material: NamedMaterial<R>,
    },
    /// The nearest hit (t > 0) of a ray with the surfaces.
    Ray {
        ray: Ray<R>,
        direction: GivenVector<R>,
        surfaces: Vec<Surface<R>>,
    },
}

/// A surface of a ray problem.
#[derive(Clone, Debug)]
pub struct Surface<R: Real> {
    pub shape: Shape<R>,
    pub material: NamedMaterial<R>,
    /// A plane's normal as given.
    pub normal: Option<GivenVector<R>>,
}
