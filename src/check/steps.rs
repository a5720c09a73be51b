//! Step checking (`phong check FILE --step cos_theta=0.98995 --step R=0.6,0,0.8`, or
//! `--steps FILE.json`): a student's intermediate values, each judged against the same
//! quantity of the solver's solution, in the order of the solution, with the first wrong step
//! named with its equation.
//!
//! Every quantity `phong solve --format json` reports has a name ([`NAMES`]); a quantity of one
//! light takes its index in the file's `lights` as `[i]` (`cos_theta[1]`), and a bare name means
//! the first light that is not ambient. A step is judged against the problem as written, then
//! against its likely intended reading (verdict `reading`: wrong as written, right in that
//! reading), and a wrong one is explained where it can be: the sign, the ungated value, another
//! reading, or the value a classic slip gives.
//!
//! Tolerance ([`STEP_RELATIVE`], [`STEP_ABSOLUTE`]): a value is right when each component is
//! within 1 % of the quantity's size (its magnitude; a vector's largest component) or within
//! 0.005, whichever is larger. A hand calculation keeps 3–4 significant digits per step, and
//! its rounding grows step by step to a few parts in a thousand; 1 % accepts that, while the
//! slips a step check is for change a value by far more (a sign, a reversed vector, 1/d for
//! 1/d², a forgotten normalisation: 10 % and up). The absolute 0.005 is half a unit of the
//! second decimal, the colour's own default, for values near 0 (a component of R that is 0,
//! a term of 0.003).

use std::fmt::Write;
use std::path::Path;

use serde::Serialize;

use super::messages;
use super::report::{Failure, FailureKind, Said, CHECK_FORMAT_VERSION};
use super::slips::{self, Slip};
use crate::core::{LightKind, Vector};
use crate::problem::error::what_and_fix;
use crate::problem::{self, Problem};
use crate::solve::{Evaluation, Intersection, ReadingCode, Secondary, Solution};
use crate::text::lang::Lang;
use crate::text::number::num;
use crate::text::{Fault, Message, Show};

/// The relative tolerance of a step: 1 % of the quantity's size.
pub const STEP_RELATIVE: f64 = 1e-2;
/// The absolute tolerance of a step, for values near 0: half a unit of the second decimal.
pub const STEP_ABSOLUTE: f64 = 5e-3;

/// A step's value: a number or a vector (a colour is a vector too).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Value {
    /// A number (cos θ, d, a falloff factor).
    Scalar(f64),
    /// Three numbers (L, R, V, I_l, a term).
    Vector([f64; 3]),
    /// Yes or no (whether a secondary ray is traced).
    Flag(bool),
}

impl Value {
    fn parts(self) -> Vec<f64> {
        match self {
            Value::Scalar(x) => vec![x],
            Value::Vector(v) => v.to_vec(),
            Value::Flag(b) => vec![if b { 1.0 } else { 0.0 }],
        }
    }

    fn negated(self) -> Value {
        match self {
            Value::Scalar(x) => Value::Scalar(-x),
            Value::Vector(v) => Value::Vector(v.map(|x| -x)),
            // A yes or no has no sign: "the sign differs" never says it.
            Value::Flag(b) => Value::Flag(b),
        }
    }

    fn is_vector(self) -> bool {
        matches!(self, Value::Vector(_))
    }

    /// The text of the value, as the reports write numbers (a yes or no in English).
    pub fn text(self) -> String {
        self.text_in(Lang::En)
    }

    /// The text of the value in `lang`: numbers as the reports write them, a yes or no as
    /// "yes"/"no" or "sim"/"não".
    pub fn text_in(self, lang: Lang) -> String {
        match self {
            Value::Scalar(x) => num(x),
            Value::Vector(v) => format!("({}, {}, {})", num(v[0]), num(v[1]), num(v[2])),
            Value::Flag(b) => crate::report::messages::yes_no(b, lang).to_owned(),
        }
    }
}

/// Whether `given` is `expected` to within the step tolerance (see the module's note).
pub fn within(given: Value, expected: Value) -> bool {
    let (g, e) = (given.parts(), expected.parts());
    if g.len() != e.len() {
        return false;
    }
    let size = e.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let tolerance = STEP_ABSOLUTE.max(STEP_RELATIVE * size);
    g.iter()
        .zip(&e)
        .all(|(a, b)| (a - b).abs() <= tolerance * (1.0 + 1e-9))
}

/// What a named quantity is: its name, what it is a value of, its equation and formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Name {
    /// The name a student gives (`cos_theta`).
    pub name: &'static str,
    /// Per light (takes `[i]`), or of the point.
    pub per_light: bool,
    /// A vector, or a number.
    pub vector: bool,
    /// A yes or no (then `vector` is false).
    pub flag: bool,
    /// The chapter's equation, when it numbers one.
    pub equation: Option<&'static str>,
    /// The formula, in the chapter's symbols (and, for a yes-or-no step, its words in both
    /// languages).
    pub formula: Formula,
}

const fn name(
    name: &'static str,
    per_light: bool,
    vector: bool,
    equation: Option<&'static str>,
    formula: &'static str,
) -> Name {
    Name {
        name,
        per_light,
        vector,
        flag: false,
        equation,
        formula: Formula::symbols(formula),
    }
}

/// `n` with its formula's words in Portuguese (`O + tD on the surface`, `sobre a superfície`).
const fn in_portuguese(n: Name, pt: &'static str) -> Name {
    Name {
        formula: Formula {
            en: n.formula.en,
            pt,
        },
        ..n
    }
}

/// A yes-or-no quantity of the point (whether a secondary ray is traced).
const fn flag(name: &'static str, en: &'static str, pt: &'static str) -> Name {
    Name {
        name,
        per_light: false,
        vector: false,
        flag: true,
        equation: None,
        formula: Formula { en, pt },
    }
}

/// Every step that can be checked, in the order of the solution (as `phong solve` shows it).
pub const NAMES: [Name; 30] = [
    in_portuguese(
        name("t", false, false, None, "O + tD on the surface"),
        "O + tD sobre a superfície",
    ),
    name("P", false, true, None, "P = O + tD"),
    in_portuguese(
        name("N", false, true, None, "N, of unit length"),
        "N, de comprimento 1",
    ),
    name("V", false, true, Some("4.10"), "V = (P − E)/‖P − E‖"),
    in_portuguese(
        name("I_a", false, true, None, "I_a = Σ ambient lights"),
        "I_a = Σ das luzes ambientes",
    ),
    name("ambient", false, true, Some("4.6"), "O_a I_a"),
    name("L", true, true, Some("4.1"), "L = (P − P_l)/‖P − P_l‖"),
    name("d", true, false, None, "d = ‖P − P_l‖"),
    name("falloff_factor", true, false, Some("4.3"), "1/d^f"),
    name("cos_psi", true, false, Some("4.4"), "cos ψ = D_l·L"),
    name("spot_factor", true, false, Some("4.4"), "(cos ψ)^e"),
    name("I_l", true, true, Some("4.2"), "I_l = C_l/d^f"),
    name("n_dot_l", true, false, Some("4.7"), "N·L"),
    name("cos_theta", true, false, Some("4.7"), "cos θ = −N·L"),
    name("diffuse", true, true, Some("4.8"), "O_d I_l cos θ"),
    name("R", true, true, Some("4.15"), "R = L − 2(N·L)N"),
    name("cos_phi", true, false, Some("4.10"), "cos φ = −R·V"),
    name("cos_phi_pow", true, false, Some("4.10"), "(cos φ)^n_s"),
    name("specular", true, true, Some("4.10"), "O_s I_l (cos φ)^n_s"),
    name("total_diffuse", false, true, Some("4.8"), "Σ O_d I_l cos θ"),
    name(
        "total_specular",
        false,
        true,
        Some("4.10"),
        "Σ O_s I_l (cos φ)^n_s",
    ),
    name(
        "I",
        false,
        true,
        Some("4.16"),
        "I = O_a I_a + Σ (O_d I_l cos θ + O_s I_l (cos φ)^n_s)",
    ),
    // The secondary rays of a ray problem's hit, Section 4.4.
    name("r_v", false, true, Some("4.17"), "R_V = V − 2(N·V)N"),
    name(
        "reflection_weight",
        false,
        false,
        None,
        "w_s = w_p·max(O_r), w_p = 1",
    ),
    flag(
        "reflection_traced",
        "the reflection ray is traced: level ≤ maximum level and w_s > minimum weight",
        "o raio de reflexão é traçado: nível ≤ nível máximo e w_s > peso mínimo",
    ),
    name("cos_theta_i", false, false, None, "cos θ_i = −N·V"),
    name(
        "k",
        false,
        false,
        None,
        "k = 1 − η_r²(1 − cos²θ_i), η_r = η_i/η_t",
    ),
    name(
        "t_direction",
        false,
        true,
        None,
        "T = η_r V + (η_r cos θ_i − √k) N",
    ),
    name(
        "transmission_weight",
        false,
        false,
        None,
        "w_t = w_p·max(O_t), w_p = 1",
    ),
    flag(
        "transmission_traced",
        "the transmission ray is traced: k ≥ 0, level ≤ maximum level and w_t > minimum weight",
        "o raio de transmissão é traçado: k ≥ 0, nível ≤ nível máximo e w_t > peso mínimo",
    ),
];

/// Other ways of writing a name (compared without case, spaces or underscores).
const ALIASES: [(&str, &str); 26] = [
    ("costheta", "cos_theta"),
    ("cosθ", "cos_theta"),
    ("cosphi", "cos_phi"),
    ("cosφ", "cos_phi"),
    ("cospsi", "cos_psi"),
    ("cosψ", "cos_psi"),
    ("n·l", "n_dot_l"),
    ("ndotl", "n_dot_l"),
    ("nl", "n_dot_l"),
    ("il", "I_l"),
    ("ia", "I_a"),
    ("falloff", "falloff_factor"),
    ("attenuation", "falloff_factor"),
    ("cosphipow", "cos_phi_pow"),
    ("total", "I"),
    ("color", "I"),
    ("rv", "r_v"),
    ("reflection_direction", "r_v"),
    ("w_s", "reflection_weight"),
    ("w_t", "transmission_weight"),
    ("transmitted_direction", "t_direction"),
    ("transmission_direction", "t_direction"),
    ("costhetai", "cos_theta_i"),
    ("cosθi", "cos_theta_i"),
    ("reflected", "reflection_traced"),
    ("transmitted", "transmission_traced"),
];

fn squash(s: &str) -> String {
    s.chars()
        .filter(|c| !c.is_whitespace() && *c != '_')
        .flat_map(char::to_lowercase)
        .collect()
}

/// The quantity a name means (without case, spaces or underscores; aliases such as `cosθ`).
pub fn lookup(text: &str) -> Option<Name> {
    let s = squash(text);
    let canonical = ALIASES
        .iter()
        .find(|(a, _)| squash(a) == s)
        .map_or(s.clone(), |(_, n)| squash(n));
    NAMES.iter().copied().find(|n| squash(n.name) == canonical)
}

/// A step as the student gives it: a name, an optional light index, a value.
#[derive(Clone, Debug, PartialEq)]
pub struct GivenStep {
    /// As written (`cos_theta[1]`), for the report.
    pub text: String,
    /// The quantity named.
    pub name: Name,
    /// The `[i]` given: an index in the file's `lights`.
    pub light: Option<usize>,
    /// The value given.
    pub value: Value,
}

/// A step that cannot be read: what is wrong and, where it can say, the fix; after the step as
/// written in a cell or a file (`"cos_theta=abc": …`) when it is one of several. It is a
/// [`Fault`]; its `Display` is the English `WHAT. Fix: FIX`.
#[derive(Clone, Debug, PartialEq)]
pub struct BadStep {
    /// The step as written, when the error is about one of several (a cell's, a file's).
    pub at: Option<String>,
    /// What is wrong, and what would fix it.
    pub fault: StepFault,
}

fn bad(fault: StepFault) -> BadStep {
    BadStep { at: None, fault }
}

impl BadStep {
    /// The same error, about the step written `at`.
    fn at(self, at: String) -> BadStep {
        BadStep {
            at: Some(at),
            ..self
        }
    }
}

impl Fault for BadStep {
    fn what(&self, lang: Lang) -> String {
        match &self.at {
            Some(at) => format!("\"{at}\": {}", self.fault.what(lang)),
            None => self.fault.what(lang),
        }
    }
    fn fix(&self, lang: Lang) -> String {
        self.fault.fix(lang)
    }
}

impl Message for BadStep {
    fn text(&self, lang: Lang) -> String {
        what_and_fix(self, lang)
    }
}

impl std::fmt::Display for BadStep {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&what_and_fix(self, Lang::En))
    }
}

impl std::error::Error for BadStep {}

/// Every step's name, in the solution's order, as `--step` reads them ("t, P, N, …"): the
/// error on an unknown name and `--step`'s help list them from here.
pub(crate) fn step_names() -> String {
    NAMES.iter().map(|n| n.name).collect::<Vec<_>>().join(", ")
}

/// Reads a name (with an optional `[i]`) and its value written as text.
pub fn parse_named(name_text: &str, value_text: &str) -> Result<GivenStep, BadStep> {
    let name_text = name_text.trim();
    let (base, light) = match name_text.strip_suffix(']').and_then(|s| s.split_once('[')) {
        Some((b, i)) => {
            let i = i.trim().parse::<usize>().map_err(|_| {
                bad(StepFault::NotAnIndex {
                    step: name_text.to_owned(),
                    index: i.to_owned(),
                })
            })?;
            (b, Some(i))
        }
        None => (name_text, None),
    };
    let name = lookup(base).ok_or_else(|| {
        bad(StepFault::UnknownName {
            name: base.to_owned(),
            names: step_names(),
        })
    })?;
    if light.is_some() && !name.per_light {
        return Err(bad(StepFault::NotOfOneLight {
            step: name_text.to_owned(),
            name: name.name,
        }));
    }
    let value_text = value_text.trim();
    let value_fault =
        |fault: fn(String, &'static str) -> StepFault| bad(fault(value_text.to_owned(), name.name));
    if name.flag {
        let value = parse_flag(value_text)
            .ok_or_else(|| value_fault(|value, name| StepFault::NotYesOrNo { value, name }))?;
        return Ok(GivenStep {
            text: name_text.to_owned(),
            name,
            light,
            value: Value::Flag(value),
        });
    }
    let value = parse_value(value_text).ok_or_else(|| {
        if name.vector {
            value_fault(|value, name| StepFault::NotThreeNumbers { value, name })
        } else {
            value_fault(|value, name| StepFault::NotOneNumber { value, name })
        }
    })?;
    if value.is_vector() != name.vector {
        return Err(if name.vector {
            value_fault(|value, name| StepFault::NumberForVector { value, name })
        } else {
            value_fault(|value, name| StepFault::VectorForNumber { value, name })
        });
    }
    Ok(GivenStep {
        text: name_text.to_owned(),
        name,
        light,
        value,
    })
}

/// A yes or no: yes, no, sim, não (nao), true, false, traced, not traced (traçado, não
/// traçado), without case.
fn parse_flag(text: &str) -> Option<bool> {
    let t = text.trim().to_lowercase();
    let t = t.trim_matches(|c: char| c == '"' || c == '.' || c == '!');
    match t {
        "yes" | "y" | "sim" | "s" | "true" | "traced" | "traçado" | "tracado" => Some(true),
        "no" | "n" | "não" | "nao" | "false" | "not traced" | "não traçado" | "nao tracado" => {
            Some(false)
        }
        _ => None,
    }
}

/// One number (a decimal comma is read as a point) or three.
fn parse_value(text: &str) -> Option<Value> {
    let t = text.trim();
    let one = super::answer::number(t).or_else(|| {
        (t.matches(',').count() == 1)
            .then(|| super::answer::number(&t.replace(',', ".")))
            .flatten()
    });
    if let Some(x) = one {
        return Some(Value::Scalar(x));
    }
    super::answer::three(t).map(Value::Vector)
}

/// Reads `--step NAME=VALUE`.
pub fn parse_step(text: &str) -> Result<GivenStep, BadStep> {
    let (name, value) = text.split_once('=').ok_or_else(|| {
        bad(StepFault::NotNameValue {
            text: text.to_owned(),
        })
    })?;
    parse_named(name, value)
}

/// Reads a cell of step answers, as `phong grade`'s steps column holds them: `NAME=VALUE`
/// pairs separated by `;` (`cos_theta=0.98995; R=0.6 0 0.8`). A step begins with its name (no
/// spaces in it) and `=`, so spaces or commas may separate steps too (`cos_theta=0,98995
/// n_dot_l=-0,98995`, as a `,` file's cells joined back give): a value is everything up to the
/// separator before the next step's name, one number (a decimal comma is read as a point) or
/// three (spaces, commas, semicolons, brackets). An empty cell is no steps. An error quotes the
/// step as written.
pub fn read_cell(text: &str) -> Result<Vec<GivenStep>, BadStep> {
    let sep = |c: char| c == ';' || c == ',' || c.is_whitespace();
    let cell = text.trim_matches(sep);
    if cell.is_empty() {
        return Ok(Vec::new());
    }
    let parts: Vec<&str> = cell.split('=').collect();
    if parts.len() < 2 {
        return Err(bad(StepFault::CellNotNameValue {
            cell: cell.to_owned(),
        }));
    }
    // parts[0] is the first name; every later part but the last is a value, a separator and
    // the next name; the last is a value.
    let mut names = vec![parts[0].trim()];
    let mut values = Vec::new();
    let last = parts.len() - 1;
    for (i, part) in parts.iter().enumerate().skip(1) {
        if i == last {
            values.push(part.trim_matches(sep));
            continue;
        }
        let part = part.trim_end();
        match part.char_indices().rev().find(|&(_, c)| sep(c)) {
            Some((k, c)) => {
                values.push(part[..k].trim_matches(sep));
                names.push(&part[k + c.len_utf8()..]);
            }
            None => {
                return Err(bad(StepFault::RunsOn {
                    name: names[names.len() - 1].to_owned(),
                    part: part.to_owned(),
                }))
            }
        }
    }
    names
        .iter()
        .zip(&values)
        .map(|(name, value)| parse_named(name, value).map_err(|e| e.at(format!("{name}={value}"))))
        .collect()
}

/// Reads a `--steps` file: one JSON object of names and values, a value a number, an array of
/// three numbers, or a string as `--step` takes it: `{"cos_theta": 0.98995, "R": [0.6, 0,
/// 0.8], "cos_theta[1]": "3/5"}`.
pub fn parse_steps_json(text: &str) -> Result<Vec<GivenStep>, BadStep> {
    let doc: serde_json::Value = serde_json::from_str(text).map_err(|e| {
        bad(StepFault::NotJson {
            error: crate::problem::JsonError::of(&e),
        })
    })?;
    let obj = doc.as_object().ok_or_else(|| bad(StepFault::NotAnObject))?;
    let mut out = Vec::new();
    for (k, v) in obj {
        let value = match v {
            serde_json::Value::Number(n) => n.to_string(),
            serde_json::Value::String(s) => s.clone(),
            serde_json::Value::Bool(b) => b.to_string(),
            serde_json::Value::Array(a) if a.iter().all(serde_json::Value::is_number) => a
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(" "),
            other => {
                return Err(bad(StepFault::NotAValue {
                    name: k.clone(),
                    value: other.to_string(),
                }))
            }
        };
        out.push(parse_named(k, &value).map_err(|e| e.at(k.clone()))?);
    }
    if out.is_empty() {
        return Err(bad(StepFault::NoSteps));
    }
    Ok(out)
}

/// One quantity of a solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantity {
    /// The quantity.
    pub name: Name,
    /// The light's index in the file's `lights` (per-light quantities).
    pub light: Option<usize>,
    /// Its place in the order of the solution.
    pub order: usize,
    /// Its value.
    pub value: Value,
    /// The ungated value, where gating changed it (a diffuse or specular term).
    pub literal: Option<Value>,
    /// The equation, where it depends on the light (I_l of a spot is Eq. 4.4).
    pub equation: Option<&'static str>,
}

fn order_of(n: &str) -> usize {
    NAMES.iter().position(|x| x.name == n).unwrap_or(usize::MAX)
}

/// Every quantity of a solution (its intersection and its evaluation), in the order of the
/// solution: the point's first, then each light's, then the totals.
pub fn quantities(
    problem: &Problem<f64>,
    intersection: Option<&Intersection<f64>>,
    e: Option<&Evaluation<f64>>,
) -> Vec<Quantity> {
    let mut out = Vec::new();
    let mut push = |n: &str, light: Option<usize>, value: Value, literal: Option<Value>| {
        let name = NAMES[order_of(n)];
        out.push(Quantity {
            name,
            light,
            order: 0,
            value,
            literal,
            equation: name.equation,
        });
    };
    let v3 = |v: crate::core::V3<f64>| Value::Vector(v.to_array());
    if let Some(x) = intersection {
        if let Some(t) = x.t {
            push("t", None, Value::Scalar(t), None);
        }
        if let Some(p) = x.point {
            push("P", None, v3(p), None);
        }
    }
    if let Some(e) = e {
        if intersection.is_none() {
            if let Some(p) = e.point {
                push("P", None, v3(p), None);
            }
        }
        if let Some(n) = &e.normal {
            push("N", None, v3(n.used), None);
        }
        if let Some(vw) = &e.viewer {
            push("V", None, v3(vw.v), None);
        }
        let lights = e.lights_used(problem);
        if let Some(i_a) = lights.ambient {
            push("I_a", None, v3(i_a), None);
        }
        if let Some(a) = e.shade.ambient {
            push("ambient", None, v3(a), None);
        }
        for term in &e.lights {
            let i = problem.light_info.get(term.index).map(|l| l.file_index);
            let a = &term.arrival;
            push("L", i, v3(a.l), None);
            if let Some(d) = a.distance {
                push("d", i, Value::Scalar(d), None);
                push("falloff_factor", i, Value::Scalar(a.falloff_factor), None);
            }
            if let Some(c) = &a.cone {
                push("cos_psi", i, Value::Scalar(c.cos_psi), None);
                push("spot_factor", i, Value::Scalar(c.factor), None);
            }
            push("I_l", i, v3(a.i_l), None);
            push("n_dot_l", i, Value::Scalar(term.n_dot_l), None);
            push("cos_theta", i, Value::Scalar(term.cos_theta), None);
            if let Some(d) = term.diffuse {
                let lit = term.diffuse_literal.filter(|l| *l != d).map(v3);
                push("diffuse", i, v3(d), lit);
            }
            let s = &term.specular;
            if let Some(r) = s.r {
                push("R", i, v3(r), None);
            }
            if let Some(c) = s.cos_phi {
                push("cos_phi", i, Value::Scalar(c), None);
            }
            if let Some(p) = s.cos_phi_pow {
                push("cos_phi_pow", i, Value::Scalar(p), None);
            }
            if s.cos_phi.is_some() {
                let lit = s.literal.filter(|l| *l != s.term).map(v3);
                push("specular", i, v3(s.term), lit);
            }
        }
        push("total_diffuse", None, v3(e.shade.diffuse), None);
        push("total_specular", None, v3(e.shade.specular), None);
        let lit = e.shade.literal.filter(|l| *l != e.shade.color).map(v3);
        push("I", None, v3(e.shade.color), lit);
    }
    // A spot's I_l is Eq. 4.4; a directional light's has no falloff (Sec. 4.2).
    for q in &mut out {
        if q.name.name == "I_l" {
            let kind = q
                .light
                .and_then(|i| light_kind(problem, i, e.map(|e| e.lights_used(problem))));
            q.equation = match kind {
                Some(LightKind::Spot { .. }) => Some("4.4"),
                Some(LightKind::Directional { .. }) => None,
                _ => Some("4.2"),
            };
        }
    }
    // The order of the solution: the point's quantities, each light's block in turn, totals.
    for (k, q) in out.iter_mut().enumerate() {
        q.order = k;
    }
    out
}

/// The quantities of a ray problem's secondary rays (Section 4.4), in the order of the
/// solution; their `order` is set by the caller, after the local colour's.
pub fn secondary_quantities(x: &Secondary<f64>) -> Vec<Quantity> {
    let mut out = Vec::new();
    let mut push = |n: &str, value: Value| {
        let name = NAMES[order_of(n)];
        out.push(Quantity {
            name,
            light: None,
            order: 0,
            value,
            literal: None,
            equation: name.equation,
        });
    };
    if let Some(r) = &x.reflection {
        if let Some(d) = r.direction {
            push("r_v", Value::Vector(d.to_array()));
        }
        push("reflection_weight", Value::Scalar(r.weight));
        push("reflection_traced", Value::Flag(r.traced()));
    }
    if let Some(t) = &x.transmission {
        push("cos_theta_i", Value::Scalar(t.refraction.cos_i));
        push("k", Value::Scalar(t.refraction.k));
        if let Some(d) = t.refraction.direction {
            push("t_direction", Value::Vector(d.to_array()));
        }
        push("transmission_weight", Value::Scalar(t.weight));
        push("transmission_traced", Value::Flag(t.traced()));
    }
    out
}

fn light_kind(
    problem: &Problem<f64>,
    file_index: usize,
    set: Option<&crate::core::LightSet<f64>>,
) -> Option<LightKind<f64>> {
    let k = problem
        .light_info
        .iter()
        .position(|l| l.file_index == file_index)?;
    set.unwrap_or(&problem.lights).lights.get(k).map(|l| l.kind)
}

/// The quantities of one solution: the problem as written, a reading, or a slip.
#[derive(Clone, Debug)]
struct Source {
    quantities: Vec<Quantity>,
}

impl Source {
    fn of(problem: &Problem<f64>, s: &Solution<f64>) -> Self {
        let mut quantities = quantities(problem, s.intersection.as_ref(), s.evaluation.as_ref());
        if let Some(x) = &s.secondary {
            let after = quantities.len();
            quantities.extend(secondary_quantities(x));
            for (k, q) in quantities.iter_mut().enumerate().skip(after) {
                q.order = k;
            }
        }
        Source { quantities }
    }

    fn find(&self, name: Name, light: Option<usize>) -> Option<&Quantity> {
        self.quantities
            .iter()
            .find(|q| q.name == name && q.light == light)
    }
}

/// Why the problem as written has no such step (the likely intended reading has it): the
/// message says so in these words, never assuming a ray where the problem has a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Absence {
    /// As written the ray hits nothing (4.3): nothing is shaded, so no step of the point.
    NoHit,
    /// As written the step's light does not light the point (4.2: behind the surface), so it
    /// has no specular term (no R, cos φ or (cos φ)^n_s where the solver skips them).
    Light(crate::core::LightStatus),
    /// The light lights the point but its specular term is not there for this reason
    /// (cos φ ≤ 0: no (cos φ)^n_s).
    Specular(crate::core::SpecularStatus),
    /// None of those (kept so that every case has words).
    Other,
}

/// Everything steps are judged against, solved once.
pub struct StepsExpected {
    written: Source,
    /// Whether the problem as written shades a point at all (a ray that hits nothing does not).
    written_shaded: bool,
    /// Each light's status and specular status as written, by file index.
    written_status: Vec<(
        Option<usize>,
        crate::core::LightStatus,
        crate::core::SpecularStatus,
    )>,
    readings: Vec<(ReadingCode, bool, Source)>,
    slips: Vec<(Slip, Source)>,
    /// The file index of the first light that is not ambient (a bare name's light).
    first_light: Option<usize>,
    /// The file indices of the ambient lights.
    ambient_lights: Vec<usize>,
    /// The number of lights in the file.
    lights_in_file: usize,
}

impl StepsExpected {
    /// Solves the problem, its readings and each single slip (f64).
    pub fn of(problem: &Problem<f64>) -> Result<Self, crate::problem::Invalid> {
        let solution = crate::solve::solve(problem)?;
        let written = Source::of(problem, &solution);
        let written_shaded = solution.evaluation.is_some();
        let written_status = solution
            .evaluation
            .iter()
            .flat_map(|e| &e.lights)
            .map(|t| {
                (
                    problem.light_info.get(t.index).map(|l| l.file_index),
                    t.status,
                    t.specular.status,
                )
            })
            .collect();
        let readings = solution
            .readings
            .iter()
            .map(|r| {
                let mut quantities =
                    quantities(problem, r.intersection.as_ref(), Some(&r.evaluation));
                if r.code == ReadingCode::LineBehindOrigin {
                    reverse_t(&mut quantities);
                }
                (r.code, r.code.likely_intended(), Source { quantities })
            })
            .collect();
        let slips = slips::single_solutions(problem)
            .into_iter()
            .map(|(slip, s)| (slip, Source::of(problem, &s)))
            .collect();
        let ambient_lights: Vec<usize> =
            problem.ambient_info.iter().map(|a| a.file_index).collect();
        Ok(StepsExpected {
            written,
            written_shaded,
            written_status,
            readings,
            slips,
            first_light: problem.light_info.first().map(|l| l.file_index),
            lights_in_file: problem.light_info.len() + ambient_lights.len(),
            ambient_lights,
        })
    }

    /// Why the problem as written has no quantity `name` (of light `light`): no point shaded
    /// (the ray hits nothing), or the light's own status, or its specular term's.
    fn absence(&self, light: Option<usize>) -> Absence {
        use crate::core::{LightStatus, SpecularStatus};
        if !self.written_shaded {
            return Absence::NoHit;
        }
        let Some(i) = light else {
            return Absence::Other;
        };
        match self.written_status.iter().find(|(l, _, _)| *l == Some(i)) {
            Some((_, status, _)) if *status != LightStatus::Lit => Absence::Light(*status),
            Some((_, _, spec)) if *spec != SpecularStatus::Lit => Absence::Specular(*spec),
            _ => Absence::Other,
        }
    }

    /// The light a step means (its `[i]`, or the first light that is not ambient), or why it
    /// means none, with the fix: the indices of the file's lights that are not ambient (or,
    /// where there is none, the ambient light's own steps).
    fn light_of(&self, step: &GivenStep) -> Result<Option<usize>, StepMissing> {
        if !step.name.per_light {
            return Ok(None);
        }
        let name = step.name.name;
        let text = step.text.clone();
        let no_light = || StepMissing::OnlyAmbient {
            step: text.clone(),
            name,
        };
        match step.light {
            None => self.first_light.map(Some).ok_or_else(no_light),
            Some(i) if self.ambient_lights.contains(&i) => Err(StepMissing::AmbientIndex {
                step: text,
                index: i,
                name,
            }),
            Some(_) if self.first_light.is_none() => Err(no_light()),
            Some(i) if i >= self.lights_in_file => {
                let indexed: Vec<String> = (0..self.lights_in_file)
                    .filter(|k| !self.ambient_lights.contains(k))
                    .map(|k| format!("{name}[{k}]"))
                    .collect();
                let (count, indexed) = (self.lights_in_file, indexed.join(", "));
                Err(if count == 1 {
                    StepMissing::NoSuchLightOfOne {
                        step: text,
                        index: i,
                        indexed,
                        name,
                    }
                } else {
                    StepMissing::NoSuchLight {
                        step: text,
                        index: i,
                        count,
                        indexed,
                        name,
                    }
                })
            }
            Some(i) => Ok(Some(i)),
        }
    }
}

/// The verdict on one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StepVerdict {
    /// Within the tolerance of the problem as written.
    Right,
    /// Wrong as written, and the value of the likely intended reading.
    Reading,
    /// Neither.
    Wrong,
}

/// One step judged.
#[derive(Clone, Debug, PartialEq)]
pub struct JudgedStep {
    /// The step as given.
    pub given: GivenStep,
    /// The light it was judged for (file index).
    pub light: Option<usize>,
    /// Right, the likely intended reading's, or wrong.
    pub verdict: StepVerdict,
    /// The quantity as written (or, when the problem as written has none, as the likely
    /// intended reading has it), for the order and the expected value.
    pub expected: Quantity,
    /// Whether `expected` is the likely intended reading's (the problem as written has no such
    /// quantity: 4.3's ray hits nothing, 4.2's light adds no specular term).
    pub expected_from_reading: Option<ReadingCode>,
    /// Why the problem as written has no such quantity, when `expected_from_reading` is set.
    pub absent_as_written: Option<Absence>,
    /// The likely intended reading's value, when the step matched it (verdict `reading`).
    pub reading: Option<ReadingCode>,
    /// The given value is the expected one with its sign reversed.
    pub sign: bool,
    /// The given value is the ungated one (Eq. 4.16 taken literally).
    pub literal: bool,
    /// Another reading (not the likely intended one) whose value it is.
    pub other_reading: Option<ReadingCode>,
    /// Slips whose value it is.
    pub slips: Vec<Slip>,
}

impl JudgedStep {
    /// The step's name with its light (`cos_theta[0]`).
    pub fn label(&self) -> String {
        match self.light {
            Some(i) => format!("{}[{i}]", self.given.name.name),
            None => self.given.name.name.to_owned(),
        }
    }
}

/// The steps of one file, judged.
#[derive(Clone, Debug, PartialEq)]
pub struct StepsJudged {
    /// In the order of the solution.
    pub steps: Vec<JudgedStep>,
    /// The first step (in the order of the solution) that is not right as written.
    pub first_wrong: Option<usize>,
    /// Exit 0: every step right, or right in the likely intended reading without `--strict`.
    pub accepted: bool,
}

/// The reading of the line's hit behind the ray's origin is the ray reversed (O − tD), whose
/// hit is in front of it: the reading's t is that ray's, −t of the line's t along D (which the
/// problem as written has). P and the rest are the same point's either way.
fn reverse_t(quantities: &mut [Quantity]) {
    for q in quantities.iter_mut().filter(|q| q.name.name == "t") {
        q.value = q.value.negated();
    }
}

/// Judges the steps against a solved problem; a step that names a quantity this problem does
/// not have is an error (the message says which it has).
pub fn judge(
    x: &StepsExpected,
    given: &[GivenStep],
    strict: bool,
) -> Result<StepsJudged, StepMissing> {
    let mut steps = Vec::new();
    for g in given {
        let light = x.light_of(g)?;
        let intended = x.readings.iter().find(|(_, likely, _)| *likely);
        let written = x.written.find(g.name, light);
        let in_reading = intended.and_then(|(c, _, s)| s.find(g.name, light).map(|q| (*c, q)));
        let (expected, from_reading) = match (written, in_reading) {
            (Some(q), _) => (*q, None),
            (None, Some((c, q))) => (*q, Some(c)),
            (None, None) => {
                let has: Vec<&str> = {
                    let mut v: Vec<&str> =
                        x.written.quantities.iter().map(|q| q.name.name).collect();
                    v.dedup();
                    v
                };
                return Err(StepMissing::NoSuchStep {
                    step: g.text.clone(),
                    name: g.name.name,
                    formula: g.name.formula,
                    has: has.join(", "),
                });
            }
        };
        let mut j = JudgedStep {
            given: g.clone(),
            light,
            verdict: StepVerdict::Wrong,
            expected,
            expected_from_reading: from_reading,
            absent_as_written: from_reading.map(|_| x.absence(light)),
            reading: None,
            sign: false,
            literal: false,
            other_reading: None,
            slips: Vec::new(),
        };
        if written.is_some_and(|q| within(g.value, q.value)) {
            j.verdict = StepVerdict::Right;
        } else if let Some((c, q)) = in_reading.filter(|(_, q)| within(g.value, q.value)) {
            let _ = q;
            j.verdict = StepVerdict::Reading;
            j.reading = Some(c);
        }
        if j.verdict != StepVerdict::Right {
            if let Some(q) = written {
                j.sign = within(g.value.negated(), q.value) && !within(g.value, q.value);
                j.literal = q.literal.is_some_and(|l| within(g.value, l));
            }
            j.other_reading = x
                .readings
                .iter()
                .filter(|(c, likely, _)| !likely && Some(*c) != j.reading)
                .find(|(_, _, s)| {
                    s.find(g.name, light)
                        .is_some_and(|q| within(g.value, q.value))
                })
                .map(|(c, _, _)| *c);
            if j.verdict == StepVerdict::Wrong {
                j.slips = x
                    .slips
                    .iter()
                    .filter(|(_, s)| {
                        s.find(g.name, light)
                            .is_some_and(|q| within(g.value, q.value))
                    })
                    .map(|(slip, _)| *slip)
                    .collect();
            }
        }
        steps.push(j);
    }
    steps.sort_by_key(|s| s.expected.order);
    let first_wrong = steps.iter().position(|s| s.verdict != StepVerdict::Right);
    let accepted = steps.iter().all(|s| match s.verdict {
        StepVerdict::Right => true,
        StepVerdict::Reading => !strict,
        StepVerdict::Wrong => false,
    });
    Ok(StepsJudged {
        steps,
        first_wrong,
        accepted,
    })
}

/// The steps of one file checked, or why they could not be.
#[derive(Clone, Debug)]
pub struct StepsChecked {
    /// The problem file, as given.
    pub file: String,
    /// The steps judged, or why they could not be.
    pub outcome: Result<StepsJudged, Failure>,
    /// Likely unit mistakes in the problem file (never errors).
    pub warnings: Vec<crate::problem::warnings::Warning>,
}

impl StepsChecked {
    /// Accepted (every step right, or right in the likely intended reading without `--strict`),
    /// refused (a wrong step, or a reading's under `--strict`), or not checked.
    pub(crate) fn status(&self) -> super::report::Status {
        use super::report::Status;
        match &self.outcome {
            Ok(j) if j.accepted => Status::Accepted,
            Ok(_) => Status::Refused,
            Err(_) => Status::Unchecked,
        }
    }
}

/// Checks the steps of one problem file.
pub fn check_steps(path: &Path, given: &[GivenStep], strict: bool) -> StepsChecked {
    check_steps_source(problem::Source::File(path), given, strict)
}

/// [`check_steps`] for a problem from any [`problem::Source`] (text held in memory, for `phong serve`).
pub fn check_steps_source(
    source: problem::Source<'_>,
    given: &[GivenStep],
    strict: bool,
) -> StepsChecked {
    let path = source.name();
    let file = path.display().to_string();
    let mut warnings = Vec::new();
    let outcome = source
        .load::<f64>()
        .map_err(Failure::problem)
        .and_then(|(_, p)| {
            warnings.clone_from(&p.warnings);
            StepsExpected::of(&p).map_err(|e| Failure::problem(e.at(path)))
        })
        .and_then(|x| {
            judge(&x, given, strict).map_err(|m| Failure {
                kind: FailureKind::Answer,
                field: Some("--step".into()),
                message: Said::at(format!("{file}: --step"), m),
            })
        });
    StepsChecked {
        file,
        outcome,
        warnings,
    }
}

/// "Eq. 4.7: cos θ = −N·L", or the formula alone.
pub(crate) fn equation(q: &Quantity, lang: Lang) -> String {
    let eq = match lang {
        Lang::En => "Eq.",
        Lang::Pt => "Eq.",
    };
    let formula = q.name.formula.get(lang);
    match q.equation {
        Some(n) => format!("{eq} {n}: {formula}"),
        None => formula.to_owned(),
    }
}

/// The sentence on one step: its verdict, its equation, and what the value is when it is
/// not right as written.
pub fn step_message(s: &JudgedStep, lang: Lang) -> String {
    let mut out = format!(
        "{} ({})",
        messages::step_verdict(s.verdict, lang),
        equation(&s.expected, lang)
    );
    let exact = match s.expected.value {
        // A yes or no says what it means: "no (the ray is not traced)".
        Value::Flag(b) => format!(
            "{} ({})",
            s.expected.value.text_in(lang),
            crate::report::messages::ray_traced(b, lang)
        ),
        other => other.text_in(lang),
    };
    let mut parts = Vec::new();
    let why = s.absent_as_written.unwrap_or(Absence::Other);
    match (s.verdict, s.expected_from_reading) {
        (StepVerdict::Right, None) => {}
        (StepVerdict::Right | StepVerdict::Reading, Some(c)) => {
            parts.push(messages::step_no_hit(c, why, lang));
        }
        (_, from) => {
            let from = from.map(|c| (c, why));
            let mut p = messages::step_exact(&exact, from, lang);
            if s.sign {
                p.push_str(messages::step_sign(s.expected.value.is_vector(), lang));
            }
            parts.push(p);
            if let Some(c) = s.reading {
                parts.push(messages::step_reading(c, lang));
                if let (ReadingCode::LineBehindOrigin, "t", Value::Scalar(t)) =
                    (c, s.given.name.name, s.given.value)
                {
                    parts.push(
                        messages::Feedback::ReversedRayReading {
                            given: crate::text::Num(t),
                            along: crate::text::Num(-t),
                        }
                        .text(lang),
                    );
                }
            }
        }
    }
    if s.verdict != StepVerdict::Right {
        if s.literal {
            parts.push(messages::step_literal(lang).to_owned());
        }
        if let Some(c) = s.other_reading {
            parts.push(messages::step_other_reading(c, lang));
        }
        if !s.slips.is_empty() {
            let each: Vec<String> = s.slips.iter().map(|&k| slip_in_step(s, k, lang)).collect();
            parts.push(messages::step_slips(&each, lang));
        }
    }
    if !parts.is_empty() {
        out.push_str(": ");
        out.push_str(&parts.join("; "));
    }
    out
}

/// What a slip is, said of the value given for a step: its name, except where the name would
/// contradict the value. The hit behind the origin is the ray reversed, whose own t is
/// positive: a t given as +90 is that hit, and is told so (its sign reversed), never "t < 0".
fn slip_in_step(s: &JudgedStep, slip: Slip, lang: Lang) -> String {
    match (slip, s.given.name.name, s.given.value) {
        (Slip::HitBehindOrigin, "t", Value::Scalar(t)) if t > 0.0 => {
            messages::Feedback::ReversedRayHit {
                given: crate::text::Num(t),
                along: crate::text::Num(-t),
            }
            .text(lang)
        }
        _ => slip.name(lang).to_owned(),
    }
}

/// The text report of one file's steps.
pub fn text(c: &StepsChecked, lang: Lang) -> String {
    let mut out = String::new();
    let Ok(j) = &c.outcome else {
        return out;
    };
    let _ = writeln!(out, "{}: {}", c.file, messages::steps_heading(lang));
    let width = j
        .steps
        .iter()
        .map(|s| s.label().chars().count())
        .max()
        .unwrap_or(0)
        .max(8)
        + 2;
    for s in &j.steps {
        let label = s.label();
        let pad = width - label.chars().count();
        let _ = writeln!(
            out,
            "  {label}{} = {}  {}",
            " ".repeat(pad),
            s.given.value.text_in(lang),
            step_message(s, lang)
        );
    }
    let _ = writeln!(out, "  {}", closing(j, lang));
    let _ = writeln!(
        out,
        "  {}",
        messages::step_tolerance(STEP_RELATIVE, STEP_ABSOLUTE, lang)
    );
    out
}

/// What the steps come to: the first wrong one and its equation (and whether the likely
/// intended reading goes on from there), or that every step is right. Every layout of the
/// steps (text, a grade row's feedback, the page, Markdown) closes with it.
pub(crate) fn closing(j: &StepsJudged, lang: Lang) -> String {
    match j.first_wrong {
        Some(k) => {
            let s = &j.steps[k];
            messages::first_wrong(
                &s.label(),
                &equation(&s.expected, lang),
                s.verdict == StepVerdict::Reading,
                lang,
            )
        }
        None => messages::all_steps_right(lang).to_owned(),
    }
}

/// The steps of one row of `phong grade`, as its feedback says them: a sentence per step (its
/// name and light, the value given, its verdict with the equation and what the value is), then
/// the first wrong step, or that every step is right.
pub(crate) fn feedback(j: &StepsJudged, lang: Lang) -> String {
    let mut sentences: Vec<String> = j
        .steps
        .iter()
        .map(|s| {
            messages::step_sentence(
                &s.label(),
                &s.given.value.text_in(lang),
                &step_message(s, lang),
                lang,
            )
        })
        .collect();
    sentences.push(capitalised(&closing(j, lang)));
    sentences
        .iter()
        .map(|s| format!("{s}."))
        .collect::<Vec<_>>()
        .join(" ")
}

/// `text` with its first letter in upper case.
fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}

impl StepVerdict {
    /// The verdict's code, as the JSON writes it: `right`, `reading` or `wrong`.
    pub fn code(self) -> &'static str {
        match self {
            StepVerdict::Right => "right",
            StepVerdict::Reading => "reading",
            StepVerdict::Wrong => "wrong",
        }
    }
}

/// One step, for scripts.
#[derive(Clone, Debug, Serialize)]
pub struct StepOut {
    /// The step's name (`cos_theta`).
    pub name: &'static str,
    /// The light's index in the file's `lights`, for a light's quantity.
    pub light: Option<usize>,
    /// As the student wrote it.
    pub text: String,
    /// The chapter's equation, when it numbers one.
    pub equation: Option<&'static str>,
    /// The formula, in the chapter's symbols.
    pub formula: &'static str,
    /// The value given.
    pub given: Value,
    /// The quantity as written (or in the likely intended reading, when the problem as written
    /// has none: see `expected_source`).
    pub expected: Value,
    /// "solution" or "reading".
    pub expected_source: &'static str,
    /// "right", "reading" or "wrong".
    pub verdict: StepVerdict,
    /// The likely intended reading the value matches (verdict "reading").
    pub reading: Option<ReadingCode>,
    /// The value is the expected one with the sign reversed.
    pub sign_reversed: bool,
    /// The value is the ungated one.
    pub literal: bool,
    /// Another reading whose value it is.
    pub other_reading: Option<ReadingCode>,
    /// Slips whose value it is.
    pub slips: Vec<Slip>,
    /// In words (English).
    pub message: String,
}

/// The first wrong step, for scripts.
#[derive(Clone, Debug, Serialize)]
pub struct FirstWrongOut {
    /// The step's name.
    pub name: &'static str,
    /// The light's index in the file's `lights`, for a light's quantity.
    pub light: Option<usize>,
    /// The chapter's equation, when it numbers one.
    pub equation: Option<&'static str>,
    /// The formula, in the chapter's symbols.
    pub formula: &'static str,
}

/// The tolerance of every step.
#[derive(Clone, Debug, Serialize)]
pub struct StepToleranceOut {
    /// The fraction of the quantity's size accepted (0.01).
    pub relative: f64,
    /// The difference accepted near 0 (0.005).
    pub absolute: f64,
}

/// A file's steps, for scripts.
#[derive(Clone, Debug, Serialize)]
pub struct StepsOut {
    /// Every step right, or the likely intended reading's without `--strict` (exit 0).
    pub accepted: bool,
    /// The tolerance of every step.
    pub tolerance: StepToleranceOut,
    /// In the order of the solution.
    pub steps: Vec<StepOut>,
    /// The first step that is not right as written; `null` when all are.
    pub first_wrong: Option<FirstWrongOut>,
}

/// The steps as JSON (`None` when they could not be checked: the error says why).
pub fn steps_json(j: &StepsJudged) -> StepsOut {
    StepsOut {
        accepted: j.accepted,
        tolerance: StepToleranceOut {
            relative: STEP_RELATIVE,
            absolute: STEP_ABSOLUTE,
        },
        steps: j
            .steps
            .iter()
            .map(|s| StepOut {
                name: s.given.name.name,
                light: s.light,
                text: s.given.text.clone(),
                equation: s.expected.equation,
                formula: s.given.name.formula.en,
                given: s.given.value,
                expected: s.expected.value,
                expected_source: if s.expected_from_reading.is_some() {
                    "reading"
                } else {
                    "solution"
                },
                verdict: s.verdict,
                reading: s.reading,
                sign_reversed: s.sign,
                literal: s.literal,
                other_reading: s.other_reading,
                slips: s.slips.clone(),
                message: step_message(s, Lang::En),
            })
            .collect(),
        first_wrong: j.first_wrong.map(|k| {
            let s = &j.steps[k];
            FirstWrongOut {
                name: s.given.name.name,
                light: s.light,
                equation: s.expected.equation,
                formula: s.given.name.formula.en,
            }
        }),
    }
}

/// The JSON document of a steps-only check (no `--answer`).
#[derive(Serialize)]
pub struct StepsDocument {
    /// The version of the JSON of `phong check` and `phong grade`.
    pub format_version: u32,
    /// The problem file, as given.
    pub file: String,
    /// "right" (every step), "reading", "wrong" or "invalid".
    pub verdict: &'static str,
    /// Exit 0: every step right, or the likely intended reading's without `--strict`.
    pub accepted: bool,
    /// The steps; `null` when they could not be checked.
    pub steps: Option<StepsOut>,
    /// Why the steps could not be checked.
    pub error: Option<Failure>,
    /// Likely unit mistakes in the problem file; absent when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<crate::report::json::WarningOut>,
}

/// The verdict of a file's steps as a whole: the worst step's.
pub fn overall(j: &StepsJudged) -> &'static str {
    if j.steps.iter().any(|s| s.verdict == StepVerdict::Wrong) {
        "wrong"
    } else if j.steps.iter().any(|s| s.verdict == StepVerdict::Reading) {
        "reading"
    } else {
        "right"
    }
}

/// The steps-only JSON document.
pub fn document(c: &StepsChecked) -> StepsDocument {
    match &c.outcome {
        Ok(j) => StepsDocument {
            format_version: CHECK_FORMAT_VERSION,
            file: c.file.clone(),
            verdict: overall(j),
            accepted: j.accepted,
            steps: Some(steps_json(j)),
            error: None,
            warnings: crate::report::json::warnings_out(&c.warnings),
        },
        Err(f) => StepsDocument {
            format_version: CHECK_FORMAT_VERSION,
            file: c.file.clone(),
            verdict: "invalid",
            accepted: false,
            steps: None,
            error: Some(f.clone()),
            warnings: Vec::new(),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(cell: &str) -> Vec<(String, Value)> {
        read_cell(cell)
            .unwrap()
            .into_iter()
            .map(|g| (g.text, g.value))
            .collect()
    }

    #[test]
    fn a_cell_of_steps_reads_with_any_separator_and_decimal_commas() {
        let two = vec![
            ("cos_theta".to_owned(), Value::Scalar(0.98995)),
            ("n_dot_l".to_owned(), Value::Scalar(-0.98995)),
        ];
        assert_eq!(names("cos_theta=0.98995; n_dot_l=-0.98995"), two);
        assert_eq!(names("cos_theta=0,98995;n_dot_l=-0,98995;"), two);
        assert_eq!(names("cos_theta = 0,98995  n_dot_l = -0,98995"), two);
        assert_eq!(names("cos_theta=0.98995, n_dot_l=-0.98995"), two);
        let r = Value::Vector([-0.48, 0.0, -0.88]);
        for cell in [
            "R=-0.48,0,-0.88",
            "R=-0,48 0 -0,88",
            "R=(-0.48, 0, -0.88)",
            "R=-0.48;0;-0.88",
        ] {
            assert_eq!(names(cell), [("R".to_owned(), r)], "{cell}");
        }
        assert_eq!(
            names("R=-0,48 0 -0,88; cos_theta[0]=3/5"),
            [
                ("R".to_owned(), r),
                ("cos_theta[0]".to_owned(), Value::Scalar(0.6))
            ]
        );
        assert!(names("").is_empty());
        assert!(names(" ; ").is_empty());
    }

    #[test]
    fn a_bad_cell_quotes_the_step_as_written() {
        let e = |cell: &str| read_cell(cell).unwrap_err().to_string();
        let pt = |cell: &str| read_cell(cell).unwrap_err().text(Lang::Pt);
        assert_eq!(
            pt("cos_theta=abc"),
            "\"cos_theta=abc\": \"abc\" não é um valor para cos_theta: escreva um número, como \
             0.98995 ou 3/5"
        );
        assert!(pt("cos_theta=0.9; cos_thet=0.5").starts_with(
            "\"cos_thet=0.5\": \"cos_thet\" não é o nome de um passo. Correção: use um de t, P,"
        ));
        let m = e("cos_theta=0.9; cos_thet=0.5");
        assert!(
            m.starts_with("\"cos_thet=0.5\": \"cos_thet\" is not the name"),
            "{m}"
        );
        assert!(m.contains("Fix: use one of"), "{m}");
        assert!(e("cos_theta=abc").starts_with("\"cos_theta=abc\": \"abc\" is not a value"));
        assert!(e("0.98995").contains("is not NAME=VALUE"));
        assert!(e("cos_theta=0.9n_dot_l=1").contains("runs into the next step's name"));
        assert!(e("R=0.5").contains("R is a vector"));
    }
}

crate::faults! {
    /// Why a step as written cannot be read (`--step`, `--steps`, a cell of `phong grade`, a
    /// form of `phong serve`). A fault whose fix is empty says what to write in its first half.
    #[allow(missing_docs)]
    pub enum StepFault {
        /// `[i]` that is not an index.
        NotAnIndex { step: String, index: String } =>
            "\"{step}\": [{index}] is not a light's index: write the index of the light in the \
             file's \"lights\", from 0, such as cos_theta[1]",
            "\"{step}\": [{index}] não é o índice de uma fonte de luz: escreva o índice da fonte \
             de luz em \"lights\" do arquivo, a partir de 0, como cos_theta[1]";
            fix "", "";
        /// A name that is no step's.
        UnknownName { name: String, names: String } =>
            "\"{name}\" is not the name of a step",
            "\"{name}\" não é o nome de um passo";
            fix "use one of {names} (a light's own with [i], such as cos_theta[1])",
                "use um de {names} (os passos de uma fonte de luz com [i], como cos_theta[1])";
        /// `[i]` after a quantity of the point.
        NotOfOneLight { step: String, name: &'static str } =>
            "\"{step}\": {name} is not a quantity of one light",
            "\"{step}\": {name} não é uma grandeza de uma só fonte de luz";
            fix "leave out the [i]", "tire o [i]";
        /// A yes-or-no step given something else.
        NotYesOrNo { value: String, name: &'static str } =>
            "\"{value}\" is not a value for {name}: write yes or no (sim or não)",
            "\"{value}\" não é um valor para {name}: escreva sim ou não";
            fix "", "";
        /// A number step given something that is not a number.
        NotOneNumber { value: String, name: &'static str } =>
            "\"{value}\" is not a value for {name}: write one number, such as 0.98995 or 3/5",
            "\"{value}\" não é um valor para {name}: escreva um número, como 0.98995 ou 3/5";
            fix "", "";
        /// A vector step given something that is not three numbers.
        NotThreeNumbers { value: String, name: &'static str } =>
            "\"{value}\" is not a value for {name}: write three numbers, such as 0.6,0,0.8 or \
             \"(0.6, 0, 0.8)\"",
            "\"{value}\" não é um valor para {name}: escreva três números, como 0.6,0,0.8 ou \
             \"(0.6, 0, 0.8)\"";
            fix "", "";
        /// A vector step given one number.
        NumberForVector { value: String, name: &'static str } =>
            "{name} is a vector, and \"{value}\" is one number",
            "{name} é um vetor, e \"{value}\" é um número";
            fix "give three numbers, such as 0.6,0,0.8", "dê três números, como 0.6,0,0.8";
        /// A number step given three numbers.
        VectorForNumber { value: String, name: &'static str } =>
            "{name} is a number, and \"{value}\" is three numbers",
            "{name} é um número, e \"{value}\" são três números";
            fix "give one number", "dê um número";
        /// `--step` without `=`.
        NotNameValue { text: String } =>
            "\"{text}\" is not NAME=VALUE",
            "\"{text}\" não é NOME=VALOR";
            fix "write the step's name, =, and its value, such as cos_theta=0.98995 or \
                 R=0.6,0,0.8",
                "escreva o nome do passo, =, e seu valor, como cos_theta=0.98995 ou R=0.6,0,0.8";
        /// A cell of steps without `=`.
        CellNotNameValue { cell: String } =>
            "\"{cell}\" is not NAME=VALUE",
            "\"{cell}\" não é NOME=VALOR";
            fix "write each step as its name, = and its value, separated by ;, such as \
                 cos_theta=0.98995; R=0.6 0 0.8",
                "escreva cada passo como seu nome, = e seu valor, separados por ;, como \
                 cos_theta=0.98995; R=0.6 0 0.8";
        /// A value with no separator before the next step's name.
        RunsOn { name: String, part: String } =>
            "\"{name}={part}=…\": a value runs into the next step's name",
            "\"{name}={part}=…\": um valor emenda com o nome do passo seguinte";
            fix "separate the steps with ;, such as cos_theta=0.98995; n_dot_l=-0.98995",
                "separe os passos com ;, como cos_theta=0.98995; n_dot_l=-0.98995";
        /// A `--steps` file that is not JSON (`error`: the JSON parser's words).
        NotJson { error: crate::problem::JsonError } =>
            "not JSON: {error}",
            "não é JSON: {error}";
            fix "write one object of names and values, such as {{\"cos_theta\": 0.98995, \
                 \"R\": [0.6, 0, 0.8]}}",
                "escreva um objeto de nomes e valores, como {{\"cos_theta\": 0.98995, \
                 \"R\": [0.6, 0, 0.8]}}";
        /// A `--steps` file that is JSON but not one object.
        NotAnObject =>
            "the file is not one JSON object",
            "o arquivo não é um objeto JSON";
            fix "write {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, 0.8]}}",
                "escreva {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, 0.8]}}";
        /// A JSON value that is no step's value (`value`: as JSON writes it).
        NotAValue { name: String, value: String } =>
            "\"{name}\": {value} is not a value",
            "\"{name}\": {value} não é um valor";
            fix "give a number, [x, y, z], or a string such as \"3/5\"",
                "dê um número, [x, y, z], ou um texto como \"3/5\"";
        /// An empty object.
        NoSteps =>
            "the file has no steps",
            "o arquivo não tem passos";
            fix "write {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, 0.8]}}",
                "escreva {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, 0.8]}}";
    }
}

crate::faults! {
    /// A step read that names a quantity the problem does not have (`step`: as written).
    #[allow(missing_docs)]
    pub enum StepMissing {
        /// A light's step, and the problem has only ambient light.
        OnlyAmbient { step: String, name: &'static str } =>
            "{step}: the problem has no light other than ambient light, so no {name}",
            "{step}: o problema não tem fonte de luz além da luz ambiente, e portanto não tem \
             {name}";
            fix "check a step of the ambient light: I_a or ambient",
                "confira um passo da luz ambiente: I_a ou ambient";
        /// A light's step of an ambient light.
        AmbientIndex { step: String, index: usize, name: &'static str } =>
            "{step}: lights[{index}] is an ambient light, which has no {name}",
            "{step}: lights[{index}] é uma luz ambiente, que não tem {name}";
            fix "give the index of a point, directional or spot light",
                "dê o índice de uma luz pontual, direcional ou spot";
        /// A light's index beyond the file's one light.
        NoSuchLightOfOne { step: String, index: usize, indexed: String, name: &'static str } =>
            "{step}: there is no lights[{index}]: the file has 1 light, from lights[0]",
            "{step}: não há lights[{index}]: o arquivo tem 1 fonte de luz, a partir de lights[0]";
            fix "use {indexed} or {name}", "use {indexed} ou {name}";
        /// A light's index beyond the file's lights.
        NoSuchLight {
            step: String,
            index: usize,
            count: usize,
            indexed: String,
            name: &'static str,
        } =>
            "{step}: there is no lights[{index}]: the file has {count} lights, from lights[0]",
            "{step}: não há lights[{index}]: o arquivo tem {count} fontes de luz, a partir de \
             lights[0]";
            fix "use {indexed} or {name}", "use {indexed} ou {name}";
        /// A quantity the problem does not have (`has`: those it has).
        NoSuchStep { step: String, name: &'static str, formula: Formula, has: String } =>
            "{step}: this problem has no {name} ({formula})",
            "{step}: este problema não tem {name} ({formula})";
            fix "check a step it has: {has}", "confira um passo que ele tem: {has}";
    }
}

impl Message for StepMissing {
    fn text(&self, lang: Lang) -> String {
        what_and_fix(self, lang)
    }
}

/// A step's formula, its words (where it has any) in both languages side by side.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Formula {
    /// In English (the JSON's).
    pub en: &'static str,
    /// In Portuguese.
    pub pt: &'static str,
}

impl Formula {
    /// A formula of symbols only, the same in every language.
    const fn symbols(f: &'static str) -> Formula {
        Formula { en: f, pt: f }
    }

    /// The formula in `lang`.
    pub fn get(self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.en,
            Lang::Pt => self.pt,
        }
    }
}

impl Show for Formula {
    fn show(&self, lang: Lang, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.get(lang))
    }
}
