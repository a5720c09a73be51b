//! Likely unit mistakes in a valid problem file: never an error (the file means something), but
//! worth a word before a student trusts the result. `phong solve` and `phong check` print each
//! on standard error (in the language of `--lang`: its [`Message`]) and put it in
//! their JSON (`warnings`).
//!
//! The rules (README "Warnings"):
//! - a **material colour** (`ambient`, `diffuse`, `specular`, `reflectivity`, the colour of
//!   `{"k", "color"}`) whose three channels are whole numbers 0–255, one of them 2 or more,
//!   looks like a 0–255 colour: a reflectance is a fraction of the light, at most 1;
//! - a **light colour** of the same form, on a light that does not fall off (ambient,
//!   directional, or point and spot with falloff 0): a light that falls off with distance may
//!   well be brighter than 1 (scenes/classic.json's point light of 40 with quadratic falloff is
//!   1/4 at a distance of 12.6), so there it is not a sign of anything;
//! - a **spot angle** γ strictly between 0 and 1.6 looks like radians (π/2 ≈ 1.571 is the
//!   largest half-angle in radians a cone can have): γ is in degrees, and 0.5236 is a cone of
//!   half-angle 0.5°, not 30°.

use serde::Serialize;

use super::field::Field;
use super::format::{ColorSpec, LightType, MaterialRef, MaterialSpec, ProblemFile};
use super::validate::show;
use crate::text::{Lang, Message};

/// What a warning is about.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "code")]
pub enum WarningKind {
    /// A material colour that looks like a 0–255 value.
    #[serde(rename = "material_color_0_255")]
    MaterialColor0To255 {
        /// The colour as given.
        given: [f64; 3],
    },
    /// A light colour that looks like a 0–255 value, on a light without falloff.
    #[serde(rename = "light_color_0_255")]
    LightColor0To255 {
        /// The colour as given.
        given: [f64; 3],
    },
    /// A spot angle that looks like radians.
    SpotAngleRadians {
        /// The angle as given (degrees, as the format reads it).
        given: f64,
    },
}

/// A likely unit mistake at a field.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Warning {
    /// What it is (and the value given).
    #[serde(flatten)]
    pub kind: WarningKind,
    /// The field, as errors name it (`materials.M.diffuse`, `lights[1].angle`).
    pub field: String,
}

/// Three whole numbers 0–255, one of them 2 or more.
fn looks_8bit(c: [f64; 3]) -> bool {
    c.iter()
        .all(|x| x.fract() == 0.0 && (0.0..=255.0).contains(x))
        && c.iter().any(|&x| x >= 2.0)
}

/// The warnings of a material at `base` (its field name is written only for a warning).
fn material(out: &mut Vec<Warning>, base: Field<'_>, m: &MaterialSpec) {
    let colours = [
        ("ambient", m.ambient),
        ("diffuse", m.diffuse),
        ("specular", m.specular),
    ];
    for (name, c) in colours {
        let Some(c) = c else { continue };
        let (scaled, given) = match c {
            ColorSpec::Rgb(v) => (false, v),
            ColorSpec::Scaled(s) => (true, s.color),
        };
        if looks_8bit(given) {
            let at = base.key(name);
            out.push(Warning {
                kind: WarningKind::MaterialColor0To255 { given },
                field: if scaled { at.key("color") } else { at }.to_string(),
            });
        }
    }
    if let Some(super::format::ReflectivitySpec::Rgb(given)) = m.reflectivity {
        if looks_8bit(given) {
            out.push(Warning {
                kind: WarningKind::MaterialColor0To255 { given },
                field: base.key("reflectivity").to_string(),
            });
        }
    }
}

/// The likely unit mistakes of a parsed file, in the order of its fields.
pub(crate) fn warnings(file: &ProblemFile) -> Vec<Warning> {
    let mut out = Vec::new();
    let materials = Field::Name("materials");
    for (name, m) in &file.materials {
        material(&mut out, materials.key(name), m);
    }
    if let Some(p) = &file.point {
        if let MaterialRef::Inline(m) = &p.material {
            material(&mut out, Field::Name("point.material"), m);
        }
    }
    let surfaces = Field::Name("surfaces");
    for (i, s) in file.surfaces.iter().enumerate() {
        if let Some(MaterialRef::Inline(m)) = &s.material {
            let at = surfaces.index(i);
            material(&mut out, at.key("material"), m);
        }
    }
    for (i, l) in file.lights.iter().enumerate() {
        let no_falloff = match l.kind {
            LightType::Ambient | LightType::Directional => true,
            LightType::Point | LightType::Spot => l.falloff == Some(0.0),
        };
        if let (Some(given), true) = (l.color, no_falloff) {
            if looks_8bit(given) {
                out.push(Warning {
                    kind: WarningKind::LightColor0To255 { given },
                    field: format!("lights[{i}].color"),
                });
            }
        }
        if let (LightType::Spot, Some(given)) = (l.kind, l.angle) {
            if given > 0.0 && given < 1.6 {
                out.push(Warning {
                    kind: WarningKind::SpotAngleRadians { given },
                    field: format!("lights[{i}].angle"),
                });
            }
        }
    }
    out
}

/// Three numbers as the file writes them.
fn warning_triple(c: [f64; 3]) -> String {
    format!("[{}, {}, {}]", show(c[0]), show(c[1]), show(c[2]))
}

/// A colour divided by 255, rounded to 3 decimals, as the fix writes it.
fn over_255(c: [f64; 3]) -> String {
    let r = |x: f64| show((x / 255.0 * 1000.0).round() / 1000.0);
    format!("[{}, {}, {}]", r(c[0]), r(c[1]), r(c[2]))
}

/// A likely unit mistake in a problem file, with its fix, in `lang`.
impl Message for Warning {
    fn text(&self, lang: Lang) -> String {
        let w = self;
        let f = &w.field;
        match (w.kind, lang) {
            (WarningKind::MaterialColor0To255 { given }, Lang::En) => format!(
                "{f}: {} looks like a 0–255 colour, but a material's colour is a fraction of the \
                 light it reflects, from 0 to 1. Fix: divide by 255: {}",
                warning_triple(given),
                over_255(given)
            ),
            (WarningKind::MaterialColor0To255 { given }, Lang::Pt) => format!(
                "{f}: {} parece uma cor de 0 a 255, mas a cor de um material é a fração da luz \
                 que ele reflete, de 0 a 1. Correção: divida por 255: {}",
                warning_triple(given),
                over_255(given)
            ),
            (WarningKind::LightColor0To255 { given }, Lang::En) => format!(
                "{f}: {} looks like a 0–255 colour, on a light that does not fall off with \
                 distance, so it lights the point {} times too brightly if it was meant on the \
                 0–1 scale. Fix: divide by 255: {} (a light brighter than 1 is fine with falloff)",
                warning_triple(given),
                show(255.0),
                over_255(given)
            ),
            (WarningKind::LightColor0To255 { given }, Lang::Pt) => format!(
                "{f}: {} parece uma cor de 0 a 255, numa luz sem decaimento com a distância: se \
                 era na escala de 0 a 1, ilumina o ponto {} vezes demais. Correção: divida por \
                 255: {} (uma luz acima de 1 é normal com decaimento)",
                warning_triple(given),
                show(255.0),
                over_255(given)
            ),
            (WarningKind::SpotAngleRadians { given }, Lang::En) => format!(
                "{f}: {} looks like an angle in radians ({}°), but the angle is read in degrees: \
                 this cone's half-angle is {}°. Fix: write the angle in degrees, {}",
                show(given),
                show((given.to_degrees() * 100.0).round() / 100.0),
                show(given),
                show((given.to_degrees() * 100.0).round() / 100.0)
            ),
            (WarningKind::SpotAngleRadians { given }, Lang::Pt) => format!(
                "{f}: {} parece um ângulo em radianos ({}°), mas o ângulo é lido em graus: o \
                 semiângulo deste cone é {}°. Correção: escreva o ângulo em graus, {}",
                show(given),
                show((given.to_degrees() * 100.0).round() / 100.0),
                show(given),
                show((given.to_degrees() * 100.0).round() / 100.0)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::lang::Lang;

    fn message(w: &Warning, lang: Lang) -> String {
        w.text(lang)
    }

    fn of(json: &str) -> Vec<Warning> {
        let file = crate::problem::parse_str(std::path::Path::new("t.json"), json).unwrap();
        warnings(&file)
    }

    #[test]
    fn a_0_255_material_colour_is_warned_about_with_the_colour_over_255() {
        let w = of(r#"{"point": {"position": [0, 0, 0], "normal": [0, 0, 1],
            "material": {"diffuse": [178, 204, 153], "specular": [1, 1, 1]}},
            "lights": [{"type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1]}]}"#);
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(w[0].field, "point.material.diffuse");
        // 178/255 = 0.698, 204/255 = 0.8, 153/255 = 0.6.
        assert!(message(&w[0], Lang::En).contains("[0.698, 0.8, 0.6]"));
        assert!(message(&w[0], Lang::Pt).contains("divida por 255"));
    }

    #[test]
    fn a_bright_light_is_warned_about_only_without_falloff() {
        let w = of(r#"{"point": {"position": [0, 0, 0], "normal": [0, 0, 1],
            "material": {"diffuse": [0.5, 0.5, 0.5]}},
            "lights": [
              {"type": "point", "position": [0, 0, 5], "color": [40, 40, 40], "falloff": 2},
              {"type": "point", "position": [0, 0, 5], "color": [255, 255, 255], "falloff": 0},
              {"type": "directional", "direction": [0, 0, -1], "color": [1.5, 1.5, 1.5]}]}"#);
        let fields: Vec<&str> = w.iter().map(|w| w.field.as_str()).collect();
        assert_eq!(fields, ["lights[1].color"]);
    }

    #[test]
    fn a_spot_angle_below_1_6_is_warned_about_as_radians() {
        let w = of(r#"{"point": {"position": [0, 0, 0], "normal": [0, 0, 1],
            "material": {"diffuse": [0.5, 0.5, 0.5]}},
            "lights": [
              {"type": "spot", "position": [0, 0, 5], "axis": [0, 0, -1], "angle": 0.5236,
               "exponent": 1, "color": [1, 1, 1], "falloff": 0},
              {"type": "spot", "position": [0, 0, 5], "axis": [0, 0, -1], "angle": 0,
               "exponent": 1, "color": [1, 1, 1], "falloff": 0},
              {"type": "spot", "position": [0, 0, 5], "axis": [0, 0, -1], "angle": 30,
               "exponent": 1, "color": [1, 1, 1], "falloff": 0}]}"#);
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(w[0].field, "lights[0].angle");
        // 0.5236 rad · 180/π = 30.0001°, written to 2 decimals: 30.
        let m = message(&w[0], Lang::En);
        assert!(m.contains("in degrees, 30"), "{m}");
    }

    #[test]
    fn the_bundled_exercises_and_scenes_warn_about_nothing() {
        for dir in ["exercises", "scenes"] {
            for entry in std::fs::read_dir(dir).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "json") {
                    let file = crate::problem::parse_file(&path).unwrap();
                    assert_eq!(warnings(&file), [], "{}", path.display());
                }
            }
        }
    }
}
