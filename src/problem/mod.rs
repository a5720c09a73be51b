//! The problem format: reading a JSON problem file, validating it, and the validated model.
//!
//! A problem names only what its question needs (DESIGN.md): the parser rejects unknown fields,
//! and validation checks that every term the question can compute has its inputs.

pub mod error;
pub mod format;
pub mod mesh;
pub mod model;
pub mod validate;

use std::path::Path;

pub use error::{Invalid, ProblemError};
pub use format::{schema_json, ProblemFile};
pub use model::{
    Camera, GivenVector, NamedMaterial, Problem, RenderSettings, Surface, SurfaceSource, Target,
};

use crate::core::Real;

/// Reads and parses a problem file (no validation).
pub fn parse_file(path: &Path) -> Result<ProblemFile, ProblemError> {
    let text = std::fs::read_to_string(path).map_err(|source| ProblemError::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_str(path, &text)
}

/// Parses the text of a problem file; `path` is only used in error messages.
pub fn parse_str(path: &Path, text: &str) -> Result<ProblemFile, ProblemError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let result = serde_path_to_error::deserialize(&mut de)
        .map_err(|e| (e.path().to_string(), e.into_inner()))
        .and_then(|f| de.end().map(|()| f).map_err(|e| (String::new(), e)));
    result.map_err(|(field, inner)| {
        let text = inner.to_string();
        let message = text
            .rsplit_once(" at line ")
            .map_or(text.as_str(), |(m, _)| m)
            .to_owned();
        let fix = syntax_fix(&inner, &message);
        // serde_path_to_error writes "." for the top level and "?" for an unknown position.
        let field = field.trim_end_matches(".?").to_owned();
        let field = (!field.is_empty() && field != "." && field != "?").then_some(field);
        let message = match &field {
            Some(f) => format!("{f}: {message}"),
            None => message,
        };
        ProblemError::Syntax {
            path: path.to_owned(),
            line: inner.line(),
            column: inner.column(),
            field,
            message,
            fix,
        }
    })
}

fn syntax_fix(e: &serde_json::Error, message: &str) -> String {
    use serde_json::error::Category;
    match e.classify() {
        Category::Eof => "the file ends too early: close every { and [".into(),
        Category::Syntax if message.starts_with("number out of range") => {
            "the number is beyond the range of f64 (about ±1.8e308); every number must be finite"
                .into()
        }
        Category::Syntax => "check the JSON just before this position (a missing comma, \
                             quote, bracket or brace, or a trailing comma)"
            .into(),
        Category::Io => String::new(),
        Category::Data => {
            if message.starts_with("unknown field") {
                "remove the field or correct its spelling (`phong schema` lists every field)".into()
            } else if let Some(name) = message
                .strip_prefix("missing field `")
                .and_then(|s| s.split('`').next())
            {
                match field_purpose(name) {
                    Some(p) => format!("add \"{name}\": it gives {p}"),
                    None => format!("add \"{name}\""),
                }
            } else {
                "see `phong schema` for the expected form".into()
            }
        }
    }
}

/// What a required field of the format is used for, to say why it is needed.
pub(crate) fn field_purpose(name: &str) -> Option<&'static str> {
    Some(match name {
        "falloff" => "f in I_l = C_l/d^f (Eq. 4.2, 4.3): 0 none, 1 linear, 2 quadratic",
        "position" => "P_l, for L and d (Eq. 4.1)",
        "color" => "the light's colour C_l (or a coefficient's colour O)",
        "direction" => "the direction of travel (L for a directional light, D for a ray)",
        "axis" => "the cone's axis D_l (Eq. 4.4)",
        "angle" => "the cone's half-angle γ in degrees (Eq. 4.4)",
        "exponent" => "the spot exponent e of cos(ψ)^e (Eq. 4.4)",
        "material" => "the material at the point",
        "origin" => "the ray's origin",
        "center" | "radius" => "the sphere",
        "normal" => "the plane's normal",
        "point" => "a point of the plane",
        "k" => "the coefficient k of k·O",
        "type" => {
            "the kind: ambient, point, directional or spot (lights); plane, sphere, triangle or \
             mesh (surfaces)"
        }
        "vertices" => "the triangle's three corners",
        "file" => "the mesh's Wavefront OBJ file",
        "eye" | "look_at" | "fov" | "width" | "height" => "the camera",
        _ => return None,
    })
}

/// Reads, parses and validates a problem file in precision `R`.
pub fn load<R: Real>(path: &Path) -> Result<(ProblemFile, Problem<R>), ProblemError> {
    let file = parse_file(path)?;
    let problem = validate::validate_in::<R>(&file, path.parent()).map_err(|e| e.at(path))?;
    Ok((file, problem))
}

/// Reads a scene: a problem file with a camera and surfaces (what the tracer needs).
pub fn load_scene<R: Real>(path: &Path) -> Result<(Problem<R>, Camera<R>), ProblemError> {
    let (_, problem) = load::<R>(path)?;
    let Some(camera) = problem.camera else {
        return Err(Invalid::new(
            "camera",
            "missing: rendering needs a camera",
            "add \"camera\": {\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": 45, \
             \"width\": 640, \"height\": 480}",
        )
        .at(path));
    };
    if problem.surfaces().is_empty() {
        return Err(Invalid::new(
            "surfaces",
            "missing: a scene needs surfaces for its rays to hit (this is a point problem)",
            "add \"surfaces\" and a \"camera\", or solve it with `phong solve`",
        )
        .at(path));
    }
    Ok((problem, camera))
}
