//! The JSON problem format, as read from a file: plain serde types that mirror the file, with
//! unknown fields rejected everywhere. [`super::validate`] turns them into the core's types.
//!
//! The same types derive the JSON Schema that `phong schema` prints, so the two cannot drift.
//! Lights and surfaces are declared kind by kind, each family in one `kinds!` table: the
//! fields (parsed type, schema type and description, what each gives), then each kind's `type`
//! word and the fields it requires; the parse struct, the schema and the checks follow from it.

use std::collections::BTreeMap;
use std::fmt;
use std::marker::PhantomData;

use schemars::JsonSchema;
use serde::de::{self, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer};

use super::kinds::kinds;
use super::syntax::{Expected, Parse};
use crate::text::{Echo, Lang, Message};

/// An RGB colour or a 3-vector, `[x, y, z]`.
pub type Triple = [f64; 3];

/// A problem (or, with a camera in a later version, a scene). It names only what its question
/// needs: a material and an ambient light (4.1); a point, normal, viewer, lights and material
/// (4.2); a ray and surfaces whose nearest hit gives the point and normal (4.3).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(title = "phong problem")]
pub struct ProblemFile {
    /// The schema this file follows (ignored; lets editors validate the file).
    #[serde(rename = "$schema", default)]
    pub schema: Option<String>,
    /// A short title, such as "Exercise 4.2".
    #[serde(default)]
    pub title: Option<String>,
    /// The title in Portuguese, such as "Exercício 4.2" (used with `--lang pt`; `title` when
    /// absent).
    #[serde(default)]
    pub title_pt: Option<String>,
    /// The question as the exercise words it.
    #[serde(default)]
    pub question: Option<String>,
    /// The question in Portuguese (used with `--lang pt`; `question` when absent).
    #[serde(default)]
    pub question_pt: Option<String>,
    /// Named materials, referred to by name from `point.material` or `surfaces[i].material`.
    #[serde(default, deserialize_with = "materials")]
    pub materials: BTreeMap<String, MaterialSpec>,
    /// The lights: ambient, point, directional and spot, in any order.
    #[serde(default, deserialize_with = "objects")]
    pub lights: Vec<LightSpec>,
    /// E: the position of the viewer (observer). Needed for the specular term.
    #[serde(default)]
    pub viewer: Option<Triple>,
    /// A point problem: the point being shaded. Give either `point` or `ray` + `surfaces`.
    #[serde(default, deserialize_with = "optional_object")]
    pub point: Option<PointSpec>,
    /// A ray problem: the ray whose nearest hit (t > 0) with `surfaces` is shaded.
    #[serde(default, deserialize_with = "optional_object")]
    pub ray: Option<RaySpec>,
    /// The surfaces of a ray problem or a scene.
    #[serde(default, deserialize_with = "objects")]
    pub surfaces: Vec<SurfaceSpec>,
    /// A scene: the camera that `phong render` looks through. With a camera, `point` and `ray`
    /// are optional.
    #[serde(default, deserialize_with = "optional_object")]
    pub camera: Option<CameraSpec>,
    /// The colour of a ray that hits nothing (default black).
    #[serde(default)]
    pub background: Option<Triple>,
    /// How rays are traced: recursion level, minimum weight, shadows, samples per pixel.
    #[serde(default, deserialize_with = "optional_object")]
    pub render: Option<RenderSpec>,
    /// The expected answer (an answer key): `phong check FILE` with no `--answer` checks it
    /// against the solution; `phong solve` does not use it.
    #[serde(default)]
    pub answer: Option<AnswerSpec>,
    /// Where a generated problem came from (`phong new`): its kind, seed and number. Metadata
    /// only: no command reads it.
    #[serde(default, deserialize_with = "optional_object")]
    pub generated: Option<GeneratedSpec>,
}

/// Where a generated problem came from: `phong new --kind KIND --seed SEED` wrote it as its
/// problem number `index`.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GeneratedSpec {
    /// The kind of problem (`--kind`).
    pub kind: String,
    /// The seed (`--seed`).
    pub seed: u64,
    /// Its number in the set, from 1.
    pub index: u32,
}

/// A pinhole camera.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CameraSpec {
    /// The eye (the viewer E of every primary ray).
    pub eye: Triple,
    /// The point the camera looks at (the centre of the image).
    pub look_at: Triple,
    /// Which way is up in the image (default [0, 1, 0]); need not be unit or perpendicular.
    #[serde(default)]
    pub up: Option<Triple>,
    /// The vertical field of view in degrees, 0 < fov < 180.
    pub fov: f64,
    /// Image width in pixels, 1 to 16384.
    #[schemars(range(min = 1, max = 16384))]
    pub width: u32,
    /// Image height in pixels, 1 to 16384.
    #[schemars(range(min = 1, max = 16384))]
    pub height: u32,
}

/// Settings of the ray tracer (Section 4.4); each can be overridden on the command line.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    /// The maximum recursion level: the primary ray has level 1 and a ray is traced while its
    /// level ≤ this (default 5; 1 means primary rays only), 1 to 1000.
    #[serde(default)]
    #[schemars(range(min = 1, max = 1000))]
    pub max_level: Option<u32>,
    /// A reflection ray is traced only while its weight w_s = w_p·max(O_r) exceeds this
    /// (default 1/255: below it a ray cannot change an 8-bit pixel of a colour in [0, 1]).
    #[serde(default)]
    pub min_weight: Option<f64>,
    /// Whether shadow rays are traced (default true).
    #[serde(default)]
    pub shadows: Option<bool>,
    /// Samples per pixel, 1 to 4096, on a stratified deterministic pattern (default 1: the
    /// pixel's centre).
    #[serde(default)]
    #[schemars(range(min = 1, max = 4096))]
    pub samples: Option<u32>,
}

/// An answer key: `[r, g, b]` on the 0–1 scale, `"#RRGGBB"` (8 bits), `"none"` (the ray hits
/// nothing), or an object with the colour and its own scale and tolerance.
#[derive(Debug, Clone, PartialEq, JsonSchema)]
#[serde(untagged)]
pub enum AnswerSpec {
    /// The colour `[r, g, b]` (0–1 scale) or `"#RRGGBB"`.
    Color(AnswerColor),
    /// The colour with its scale and tolerance.
    Key(AnswerKey),
}

/// The colour of an answer key.
#[derive(Debug, Clone, PartialEq, JsonSchema)]
#[serde(untagged)]
pub enum AnswerColor {
    /// `[r, g, b]`, on the key's scale (0–1 unless `scale` is 255).
    Rgb(Triple),
    /// `"#RRGGBB"`: 8 bits per channel; or `"none"` (also "nenhuma", "sem interseção", "no
    /// hit", "—"): the ray hits nothing.
    Hex(String),
}

/// An answer key with its scale and tolerance.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AnswerKey {
    /// `[r, g, b]` or `"#RRGGBB"`.
    pub color: AnswerColor,
    /// 1 (the default): components on [0, 1]; 255: 8-bit integers 0–255.
    #[serde(default)]
    pub scale: Option<f64>,
    /// The largest difference accepted in any channel, on the key's scale (default 0.005 on the
    /// 0–1 scale, 1 on the 255 scale).
    #[serde(default)]
    pub tolerance: Option<f64>,
}

impl AnswerSpec {
    /// The colour, the scale and the tolerance the key gives.
    pub fn parts(&self) -> (&AnswerColor, Option<f64>, Option<f64>) {
        match self {
            AnswerSpec::Color(c) => (c, None, None),
            AnswerSpec::Key(k) => (&k.color, k.scale, k.tolerance),
        }
    }
}

/// The point being shaded. `position` is needed by point and spot lights and by the viewer;
/// `normal` by every light other than ambient.
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    /// P.
    #[serde(default)]
    pub position: Option<Triple>,
    /// N (normalised if its length is not 1; the explanation says so).
    #[serde(default)]
    pub normal: Option<Triple>,
    /// The material at P: a name from `materials`, or a material written in place.
    pub material: MaterialRef,
}

/// A ray: origin and direction (normalised if its length is not 1).
#[derive(Debug, Clone, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
// Doc comments here would become descriptions in `phong schema`'s output: the fields are
// described in plain comments instead.
#[allow(missing_docs)]
pub struct RaySpec {
    // O, the ray's origin.
    pub origin: Triple,
    // D, the ray's direction (any non-zero length).
    pub direction: Triple,
}

// `field: parsed type [as schema type] => what it gives,` (the schema's description, units and
// bounds above it), then `Kind "word" [the fields it requires],`: see `problem/kinds.rs`.
kinds! {
    /// A surface of a ray problem, as read: `type` and the fields of that type, parsed flat (see
    /// `problem::kinds`); [`SurfaceType::fields`] says which fields each type takes, and
    /// validation enforces it.
    pub struct SurfaceSpec;
    /// The kinds of surface.
    pub enum SurfaceType;
    /// A surface of a ray problem: `type` selects the kind.
    schema Surface in surface_schema;
    optional {}
    fields {
        // Boxed, as the vertices below: a scene holds a plane or two and many spheres.
        point: Box<Triple> as Triple => "a point of the plane", "um ponto do plano",
        normal: Box<Triple> as Triple => "the plane's normal", "a normal do plano",
        center: Triple => "the sphere", "a esfera",
        radius: f64 => "the sphere", "a esfera",
        // Boxed (as a written-in-place material is): a scene of 100,000 spheres holds 100,000
        // of these as read, and the few triangles should not make each of them 72 bytes larger.
        vertices: Box<[Triple; 3]> as [Triple; 3] => "the triangle's three corners",
            "os três vértices do triângulo",
        file: String => "the mesh's Wavefront OBJ file", "o arquivo Wavefront OBJ da malha",
        material: MaterialRef => "the material at the point", "o material no ponto",
    }
    kinds {
        /// The plane through `point` with normal `normal` (used as given, normalised).
        Plane "plane" "plano" [point, normal, material],
        /// The sphere with centre `center` and radius `radius` > 0; its normal points outward.
        Sphere "sphere" "esfera" [center, radius, material],
        /// The triangle with corners `vertices` (not all on one line); its normal is
        /// (v1 − v0) × (v2 − v0), turned to face the incoming ray.
        Triangle "triangle" "triângulo" [vertices, material],
        /// The triangles of a Wavefront OBJ file (`file`, relative to this file's folder), all of
        /// one material; polygons are split into triangles.
        Mesh "mesh" "malha" [file, material],
    }
}

kinds! {
    /// A light, as read: `type` and the fields of that type (see [`LightType::fields`]), parsed
    /// flat so that an error names its exact field. Colours are RGB, each component ≥ 0 (values
    /// above 1 are allowed for lights).
    pub struct LightSpec;
    /// The kinds of light.
    pub enum LightType;
    /// A light: `type` selects the kind. Colours are RGB, each component ≥ 0 (above 1 is allowed).
    schema Light in light_schema;
    optional {
        /// A name for the light, shown beside it in explanations and the JSON
        /// (`lights[1] (point) "key"`).
        name: String,
        /// The light's name in Portuguese, shown instead of `name` with `--lang pt`.
        name_pt: String,
    }
    fields {
        // Also the purpose of `color` in a scaled colour and an answer key.
        color: Triple => "the light's colour C_l (or a coefficient's colour O)",
            "a cor C_l da fonte de luz (ou a cor O de um coeficiente)",
        position: Triple => "P_l, for L and d (Eq. 4.1)", "P_l, para L e d (Eq. 4.1)",
        // Also the purpose of `ray.direction`.
        direction: Triple => "the direction of travel (L for a directional light, D for a ray)",
            "a direção de propagação (L de uma luz direcional, D de um raio)",
        axis: Triple => "the cone's axis D_l (Eq. 4.4)", "o eixo D_l do cone (Eq. 4.4)",
        /// γ_l in degrees, between the axis and the cone's side, 0 ≤ γ ≤ 90.
        angle: f64 => "the cone's half-angle γ in degrees (Eq. 4.4)",
            "o ângulo γ do cone, em graus (Eq. 4.4)",
        /// e_l ≥ 0.
        exponent: f64 => "the spot exponent e of cos(ψ)^e (Eq. 4.4)",
            "o expoente e do spot em cos(ψ)^e (Eq. 4.4)",
        // Read as any number, so that 1.5 is refused by validation with its reason.
        /// f: 0 none, 1 linear, 2 quadratic (Eq. 4.3).
        #[schemars(range(min = 0, max = 2))]
        falloff: f64 as u8 => "f in I_l = C_l/d^f (Eq. 4.2, 4.3): 0 none, 1 linear, 2 quadratic",
            "f em I_l = C_l/d^f (Eq. 4.2, 4.3): 0 sem decaimento, 1 linear, 2 quadrático",
    }
    kinds {
        /// Ambient light I_a (Eq. 4.5–4.6). Several ambient lights add up.
        Ambient "ambient" "ambiente" [color],
        /// A point light at `position` with colour C_l and falloff f ∈ {0, 1, 2} (Eq. 4.1–4.3).
        Point "point" "pontual" [position, color, falloff],
        /// A directional light travelling along `direction` (D_l), no falloff.
        Directional "directional" "direcional" [direction, color],
        /// A spot light (Eq. 4.4): apex `position`, cone axis `axis` (D_l), half-angle `angle`
        /// γ in degrees (0–90), exponent e ≥ 0 and falloff f ∈ {0, 1, 2}.
        Spot "spot" "spot" [position, axis, angle, exponent, color, falloff],
    }
}

/// A material. Every field is optional: give what the question uses. A term whose light and
/// geometry are present but whose colour is missing is an error that names the field.
#[derive(Debug, Clone, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// O_a (or k_a and O_a), Eq. 4.5–4.6.
    #[serde(default)]
    pub ambient: Option<ColorSpec>,
    /// O_d (or k_d and O_d), Eq. 4.7–4.8.
    #[serde(default)]
    pub diffuse: Option<ColorSpec>,
    /// O_s (or k_s and O_s), Eq. 4.9–4.10.
    #[serde(default)]
    pub specular: Option<ColorSpec>,
    /// n_s ≥ 0, Eq. 4.9.
    #[serde(default)]
    pub shininess: Option<f64>,
    /// O_r (Section 4.4): an RGB colour, or "specular" to take O_r = O_s.
    #[serde(default)]
    pub reflectivity: Option<ReflectivitySpec>,
    /// O_t (Section 4.4, "idem para a transmissão ou refração"): an RGB colour ≥ 0; a hit
    /// spawns a transmission ray with colour O_t·C_t. Needs `ior`.
    #[serde(default)]
    pub transmissivity: Option<Triple>,
    /// η, 0.001 to 1000, the index of refraction of the surface's inside (the side its normal
    /// points away from; the outside's is 1), for Snell's law. Given with `transmissivity`.
    #[serde(default)]
    #[schemars(extend("minimum" = 0.001, "maximum" = 1000))]
    pub ior: Option<f64>,
}

/// A material colour: `[r, g, b]` (the product k·O) or `{"k": k, "color": [r, g, b]}`.
#[derive(Debug, Clone, Copy, PartialEq, JsonSchema)]
#[serde(untagged)]
pub enum ColorSpec {
    /// The product k·O, as one RGB colour.
    Rgb(Triple),
    /// A coefficient 0 ≤ k ≤ 1 and a colour O.
    Scaled(ScaledColor),
}

/// A coefficient k and a colour O; the material colour is k·O.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
// Doc comments here would become descriptions in `phong schema`'s output: the fields are
// described in plain comments instead.
#[allow(missing_docs)]
pub struct ScaledColor {
    // The coefficient k.
    pub k: f64,
    // The colour O, RGB.
    pub color: Triple,
}

impl ColorSpec {
    /// The product k·O.
    pub fn product(&self) -> Triple {
        match *self {
            ColorSpec::Rgb(c) => c,
            ColorSpec::Scaled(ScaledColor { k, color }) => color.map(|c| k * c),
        }
    }
}

/// The reflectivity O_r: an RGB colour, or the word "specular" for O_r = O_s.
#[derive(Debug, Clone, Copy, PartialEq, JsonSchema)]
#[serde(untagged)]
// Doc comments here would become descriptions in `phong schema`'s output: the fields are
// described in plain comments instead.
#[allow(missing_docs)]
pub enum ReflectivitySpec {
    // O_r as an RGB colour.
    Rgb(Triple),
    /// Always "specular".
    Same(SameAsSpecular),
}

/// The word "specular".
#[derive(Debug, Clone, Copy, PartialEq, JsonSchema)]
// Doc comments here would become descriptions in `phong schema`'s output: the fields are
// described in plain comments instead.
#[allow(missing_docs)]
pub enum SameAsSpecular {
    // The word itself.
    #[serde(rename = "specular")]
    Specular,
}

/// A material: the name of one in `materials`, or one written in place.
#[derive(Debug, Clone, JsonSchema)]
#[serde(untagged)]
// Doc comments here would become descriptions in `phong schema`'s output: the fields are
// described in plain comments instead.
#[allow(missing_docs)]
pub enum MaterialRef {
    // The name of a material in the file's `materials` (in place up to 24 bytes: no allocation
    // per surface).
    Name(#[schemars(with = "String")] compact_str::CompactString),
    // A material written in place (boxed: most surfaces name one, and a `SurfaceSpec` as read
    // would otherwise be 168 bytes larger).
    Inline(Box<MaterialSpec>),
}

// Objects only. serde's derived structs also read an array of the fields in order, so
// `"ray": [[0, 0, 5], [0, 0, -1]]` was a ray, `"render": [5]` a maximum level, and `"point":
// [3, 1, 3]` failed with `point[0]: expected an array of length 3`, pointing the wrong way. The
// structs of the format are read through `Object`, which takes a JSON object and nothing else,
// and says which object was expected.

/// What an object of the format is, for the error when something else is found (also the
/// course policy's objects, check/policy.rs).
pub(crate) trait Described {
    const WHAT: Expected;
}

impl Described for PointSpec {
    const WHAT: Expected = Expected::Point;
}
impl Described for RaySpec {
    const WHAT: Expected = Expected::Ray;
}
impl Described for CameraSpec {
    const WHAT: Expected = Expected::Camera;
}
impl Described for RenderSpec {
    const WHAT: Expected = Expected::Render;
}
impl Described for GeneratedSpec {
    const WHAT: Expected = Expected::Generated;
}
impl Described for LightSpec {
    const WHAT: Expected = Expected::Light;
}
impl Described for SurfaceSpec {
    const WHAT: Expected = Expected::Surface;
}
impl Described for MaterialSpec {
    const WHAT: Expected = Expected::Material;
}

/// Writes what the parser expects, as serde's message says it (in English: the message is
/// read back into a value where the error is made, problem::syntax).
fn expecting(f: &mut fmt::Formatter, what: Expected) -> fmt::Result {
    f.write_str(&what.text(Lang::En))
}

/// A struct of the format, read only from a JSON object.
struct Object<T>(T);

impl<'de, T: Deserialize<'de> + Described> Deserialize<'de> for Object<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de> + Described> Visitor<'de> for V<T> {
            type Value = Object<T>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, T::WHAT)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Object<T>, A::Error> {
                T::deserialize(de::value::MapAccessDeserializer::new(map)).map(Object)
            }
        }
        d.deserialize_map(V(PhantomData))
    }
}

/// An optional field read through [`Object`]: a JSON object, or `null`, and nothing else.
pub(crate) fn optional_object<'de, D, T>(d: D) -> Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de> + Described,
{
    Ok(Option::<Object<T>>::deserialize(d)?.map(|o| o.0))
}

fn objects<'de, D, T>(d: D) -> Result<Vec<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de> + Described,
{
    let v = Vec::<Object<T>>::deserialize(d)?;
    Ok(v.into_iter().map(|o| o.0).collect())
}

/// Named materials. A name given twice is an error, as a field given twice is (a map would keep
/// the last one silently).
fn materials<'de, D: Deserializer<'de>>(d: D) -> Result<BTreeMap<String, MaterialSpec>, D::Error> {
    struct V;
    impl<'de> Visitor<'de> for V {
        type Value = BTreeMap<String, MaterialSpec>;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            expecting(f, Expected::NamedMaterials)
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            let mut out = BTreeMap::new();
            while let Some(name) = map.next_key::<String>()? {
                if out.contains_key(&name) {
                    let duplicate = Parse::DuplicateMaterial {
                        name: Echo::new(&name, usize::MAX),
                    };
                    return Err(de::Error::custom(duplicate.text(Lang::En)));
                }
                let Object(m) = map.next_value::<Object<MaterialSpec>>()?;
                out.insert(name, m);
            }
            Ok(out)
        }
    }
    d.deserialize_map(V)
}

// Hand-written deserializers for the "either" types: serde's untagged enums would replace the
// precise error ("unknown field `difuse`") with "data did not match any variant".

impl<'de> Deserialize<'de> for ColorSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ColorSpec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, Expected::Colour)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<ColorSpec, A::Error> {
                Triple::deserialize(de::value::SeqAccessDeserializer::new(seq)).map(ColorSpec::Rgb)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<ColorSpec, A::Error> {
                ScaledColor::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(ColorSpec::Scaled)
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for ReflectivitySpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ReflectivitySpec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, Expected::Reflectivity)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<ReflectivitySpec, A::Error> {
                Triple::deserialize(de::value::SeqAccessDeserializer::new(seq))
                    .map(ReflectivitySpec::Rgb)
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<ReflectivitySpec, E> {
                if s == "specular" {
                    Ok(ReflectivitySpec::Same(SameAsSpecular::Specular))
                } else {
                    Err(E::invalid_value(de::Unexpected::Str(s), &self))
                }
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for AnswerColor {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = AnswerColor;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, Expected::AnswerColour)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<AnswerColor, A::Error> {
                Triple::deserialize(de::value::SeqAccessDeserializer::new(seq))
                    .map(AnswerColor::Rgb)
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<AnswerColor, E> {
                Ok(AnswerColor::Hex(s.to_owned()))
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for AnswerSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = AnswerSpec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, Expected::Answer)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<AnswerSpec, A::Error> {
                Triple::deserialize(de::value::SeqAccessDeserializer::new(seq))
                    .map(|c| AnswerSpec::Color(AnswerColor::Rgb(c)))
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<AnswerSpec, E> {
                Ok(AnswerSpec::Color(AnswerColor::Hex(s.to_owned())))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<AnswerSpec, A::Error> {
                AnswerKey::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(AnswerSpec::Key)
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for MaterialRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = MaterialRef;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                expecting(f, Expected::MaterialRef)
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<MaterialRef, E> {
                Ok(MaterialRef::Name(s.into()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<MaterialRef, A::Error> {
                MaterialSpec::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(|m| MaterialRef::Inline(Box::new(m)))
            }
        }
        d.deserialize_any(V)
    }
}

/// The JSON Schema of the problem format, pretty-printed.
pub fn schema_json() -> String {
    let schema = schemars::schema_for!(ProblemFile);
    serde_json::to_string_pretty(&schema).expect("a schema always serialises")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The property names of each `type` in a oneOf schema, without `type`, `name` and `name_pt`.
    fn schema_fields(schema: &serde_json::Value) -> Vec<(String, Vec<String>)> {
        let mut out = Vec::new();
        for variant in schema["oneOf"].as_array().expect("one shape per type") {
            let props = variant["properties"].as_object().expect("properties");
            let kind = props["type"]["const"]
                .as_str()
                .expect("a const type")
                .to_owned();
            let mut fields: Vec<String> = props
                .keys()
                .filter(|k| *k != "type" && *k != "name" && *k != "name_pt")
                .cloned()
                .collect();
            fields.sort();
            out.push((kind, fields));
        }
        out
    }

    fn sorted(fields: &[&str]) -> Vec<String> {
        let mut v: Vec<String> = fields.iter().map(|s| s.to_string()).collect();
        v.sort();
        v
    }

    #[test]
    #[cfg(target_pointer_width = "64")]
    fn a_surface_as_read_stays_small() {
        // A scene of 100,000 spheres holds 100,000 of these while it is validated: the rare
        // large fields (a triangle's corners, a plane's point and normal, a material written
        // in place) are boxed. 392 bytes before they were.
        let size = std::mem::size_of::<SurfaceSpec>();
        assert!(size <= 128, "SurfaceSpec is {size} bytes");
    }

    #[test]
    fn light_schema_and_parser_agree_on_the_fields_of_each_type() {
        let schema = serde_json::to_value(schemars::schema_for!(LightSpec)).unwrap();
        let by_type = schema_fields(&schema);
        assert_eq!(by_type.len(), 4);
        for (kind, fields) in by_type {
            let t: LightType = serde_json::from_value(serde_json::Value::String(kind)).unwrap();
            assert_eq!(fields, sorted(t.fields()), "{}", t.name());
        }
    }

    #[test]
    fn surface_schema_and_parser_agree_on_the_fields_of_each_type() {
        let schema = serde_json::to_value(schemars::schema_for!(SurfaceSpec)).unwrap();
        let by_type = schema_fields(&schema);
        assert_eq!(by_type.len(), 4);
        for (kind, fields) in by_type {
            let t: SurfaceType = serde_json::from_value(serde_json::Value::String(kind)).unwrap();
            assert_eq!(fields, sorted(t.fields()), "{}", t.name());
        }
    }
}
