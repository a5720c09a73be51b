//! `GET /own` and `POST /own`: one's own problem written as a form (a point with its normal, or
//! a ray and a plane or a sphere; a viewer; an ambient light and up to two point, directional
//! or spot lights; a material), turned into a problem file (the format of `phong solve`), solved and
//! explained as `phong solve --format html` explains it; the file is shown, and
//! `POST /own/problem.json` (the form's second button) downloads it.
//!
//! A box that does not hold numbers is put into the file as the text it holds, so that the
//! problem's own reader refuses it with the message the command line gives, naming the field
//! (`point.normal`); an empty optional box is left out of the file.

use std::fmt::Write;

use axum::http::{header, HeaderMap, StatusCode, Uri};
use axum::response::{IntoResponse, Response};
use axum::Form;
use serde_json::{json, Map, Value};

use super::exercise::solution;
use super::lang::{self, Text};
use super::layout::{href, page, posted};
use crate::check::answer::{number, three};
use crate::core::Precision;
use crate::problem::Source;
use crate::report::html::{self, esc};
use crate::text::lang::Lang;
use crate::text::Message;

/// The form's fields: name, label, and the value it starts with (exercise 4.2's data).
const FIELDS: &[(&str, Text, &str)] = &[
    ("p_position", Text::PointPosition, "3 1 3"),
    ("p_normal", Text::PointNormal, "0.6 0 0.8"),
    ("r_origin", Text::RayOrigin, "8 4 6"),
    ("r_direction", Text::RayDirection, "0.8 0 -0.6"),
    ("s_point", Text::PlanePoint, "0 0 0"),
    ("s_normal", Text::PlaneNormal, "1 1 1"),
    ("s_center", Text::SphereCenter, "0 0 0"),
    ("s_radius", Text::SphereRadius, "2"),
    ("viewer", Text::Viewer, "5 4 6"),
    ("ambient", Text::Ambient, ""),
    ("l1_position", Text::LightPosition, "1 1 1"),
    ("l1_direction", Text::LightDirection, ""),
    ("l1_color", Text::LightColour, "1 1 1"),
    ("l1_falloff", Text::Falloff, "1"),
    ("l1_axis", Text::SpotAxis, ""),
    ("l1_angle", Text::SpotAngle, ""),
    ("l1_exponent", Text::SpotExponent, ""),
    ("l2_position", Text::LightPosition, ""),
    ("l2_direction", Text::LightDirection, ""),
    ("l2_color", Text::LightColour, ""),
    ("l2_falloff", Text::Falloff, "0"),
    ("l2_axis", Text::SpotAxis, ""),
    ("l2_angle", Text::SpotAngle, ""),
    ("l2_exponent", Text::SpotExponent, ""),
    ("m_ambient", Text::MatAmbient, "0.5 0.4 0.6"),
    ("m_diffuse", Text::MatDiffuse, "0.7 0.8 0.6"),
    ("m_specular", Text::MatSpecular, "0.2 0.3 0.4"),
    ("m_shininess", Text::Shininess, "1"),
];

/// The choices: name, the values it may take, the first the default.
const CHOICES: &[(&str, &[&str])] = &[
    ("kind", &["point", "ray"]),
    ("s_kind", &["plane", "sphere"]),
    ("l1_kind", &["point", "directional", "spot"]),
    ("l2_kind", &["point", "directional", "spot"]),
];

/// What the form holds: every field and choice, by name.
struct Input {
    values: Vec<(&'static str, String)>,
}

impl Input {
    fn defaults() -> Input {
        let mut values: Vec<(&'static str, String)> = FIELDS
            .iter()
            .map(|(n, _, v)| (*n, (*v).to_owned()))
            .collect();
        values.extend(CHOICES.iter().map(|(n, c)| (*n, c[0].to_owned())));
        Input { values }
    }

    fn from(fields: Vec<(String, String)>) -> Input {
        let mut input = Input::defaults();
        // A field left out of the body is empty; a choice left out keeps its default.
        for (n, _, _) in FIELDS {
            input.set(n, String::new());
        }
        for (k, v) in fields {
            if let Some((n, _, _)) = FIELDS.iter().find(|(n, _, _)| *n == k) {
                input.set(n, v);
            } else if let Some((n, allowed)) = CHOICES.iter().find(|(n, _)| *n == k) {
                if allowed.contains(&v.as_str()) {
                    input.set(n, v);
                }
            }
        }
        input
    }

    fn set(&mut self, name: &str, value: String) {
        if let Some(slot) = self.values.iter_mut().find(|(n, _)| *n == name) {
            slot.1 = value;
        }
    }

    fn get(&self, name: &str) -> &str {
        self.values
            .iter()
            .find(|(n, _)| *n == name)
            .map_or("", |(_, v)| v.trim())
    }
}

/// Three numbers (as an answer is written: spaces, commas, brackets, decimal commas,
/// fractions), else the text itself, for the reader to refuse by name; `None` when empty.
fn triple(text: &str) -> Option<Value> {
    if text.is_empty() {
        return None;
    }
    Some(three(text).map_or_else(|| Value::String(text.to_owned()), |v| json!(v)))
}

/// One number (a decimal comma is read as a point), else the text itself; `None` when empty.
fn scalar(text: &str) -> Option<Value> {
    if text.is_empty() {
        return None;
    }
    let n = number(text).or_else(|| number(&text.replace(',', ".")));
    Some(n.map_or_else(|| Value::String(text.to_owned()), |x| json!(x)))
}

fn put(obj: &mut Map<String, Value>, key: &str, value: Option<Value>) {
    if let Some(v) = value {
        obj.insert(key.to_owned(), v);
    }
}

/// The problem file the form describes, titled in both languages (deterministic: the same
/// form gives the same bytes).
fn problem_file(input: &Input) -> String {
    let g = |n: &str| input.get(n);
    let mut doc = Map::new();
    doc.insert("title".into(), json!(Text::OwnTitle.get(Lang::En)));
    doc.insert("title_pt".into(), json!(Text::OwnTitle.get(Lang::Pt)));
    let mut material = Map::new();
    put(&mut material, "ambient", triple(g("m_ambient")));
    put(&mut material, "diffuse", triple(g("m_diffuse")));
    put(&mut material, "specular", triple(g("m_specular")));
    put(&mut material, "shininess", scalar(g("m_shininess")));
    doc.insert("materials".into(), json!({ "M": material }));
    let mut lights = Vec::new();
    if let Some(c) = triple(g("ambient")) {
        lights.push(json!({ "type": "ambient", "color": c }));
    }
    for l in ["l1", "l2"] {
        let v = |x: &str| input.get(&format!("{l}_{x}"));
        // A second light is given by its colour; the first always is.
        if l == "l2" && v("color").is_empty() {
            continue;
        }
        let mut light = Map::new();
        if v("kind") == "directional" {
            light.insert("type".into(), json!("directional"));
            put(&mut light, "direction", triple(v("direction")));
            put(&mut light, "color", triple(v("color")));
        } else {
            let spot = v("kind") == "spot";
            light.insert("type".into(), json!(if spot { "spot" } else { "point" }));
            put(&mut light, "position", triple(v("position")));
            if spot {
                put(&mut light, "axis", triple(v("axis")));
                put(&mut light, "angle", scalar(v("angle")));
                put(&mut light, "exponent", scalar(v("exponent")));
            }
            put(&mut light, "color", triple(v("color")));
            put(&mut light, "falloff", scalar(v("falloff")));
        }
        lights.push(Value::Object(light));
    }
    doc.insert("lights".into(), Value::Array(lights));
    put(&mut doc, "viewer", triple(g("viewer")));
    if g("kind") == "ray" {
        let mut ray = Map::new();
        put(&mut ray, "origin", triple(g("r_origin")));
        put(&mut ray, "direction", triple(g("r_direction")));
        doc.insert("ray".into(), Value::Object(ray));
        let mut s = Map::new();
        if g("s_kind") == "sphere" {
            s.insert("type".into(), json!("sphere"));
            put(&mut s, "center", triple(g("s_center")));
            put(&mut s, "radius", scalar(g("s_radius")));
        } else {
            s.insert("type".into(), json!("plane"));
            put(&mut s, "point", triple(g("s_point")));
            put(&mut s, "normal", triple(g("s_normal")));
        }
        s.insert("material".into(), json!("M"));
        doc.insert("surfaces".into(), json!([s]));
    } else {
        let mut p = Map::new();
        put(&mut p, "position", triple(g("p_position")));
        put(&mut p, "normal", triple(g("p_normal")));
        p.insert("material".into(), json!("M"));
        doc.insert("point".into(), Value::Object(p));
    }
    let mut text = serde_json::to_string_pretty(&Value::Object(doc)).unwrap_or_default();
    text.push('\n');
    text
}

/// `GET /own`: the form, holding exercise 4.2's data.
pub(crate) async fn get(uri: Uri, headers: HeaderMap) -> Response {
    let lang = lang::of(&uri, &headers);
    let main = format!(
        "<h1>{}</h1>\n<p>{}</p>\n{}",
        Text::Own.get(lang),
        Text::OwnIntro.get(lang),
        form(&Input::defaults(), lang)
    );
    page(StatusCode::OK, lang, Text::Own.get(lang), "/own", &main)
}

/// `POST /own`: the problem solved and explained, its file shown; 422 with the reader's
/// message when the problem cannot be solved as given.
pub(crate) async fn post(
    uri: Uri,
    headers: HeaderMap,
    Form(fields): Form<Vec<(String, String)>>,
) -> Response {
    let lang = lang::of(&uri, &headers);
    let t = |x: Text| x.get(lang);
    let kept = fields.clone();
    let input = Input::from(fields);
    let text = problem_file(&input);
    let name = std::path::Path::new("problem.json");
    let explained = crate::report::file::explain_source(
        Source::Text { name, text: &text },
        Precision::F64,
        lang,
    );
    let mut main = format!(
        "<h1>{}</h1>\n<p>{}</p>\n{}",
        t(Text::Own),
        t(Text::OwnIntro),
        form(&input, lang)
    );
    let status = match &explained {
        Ok(x) => {
            let _ = writeln!(
                main,
                "<section aria-labelledby=\"statement-h\">\n<h2 id=\"statement-h\">{}</h2>\n{}\
                 </section>",
                t(Text::Statement),
                html::data_table(&x.data, lang)
            );
            main.push_str(&solution(&explained, lang));
            StatusCode::OK
        }
        Err(e) => {
            let _ = writeln!(
                main,
                "<section id=\"verdict\" role=\"status\" aria-labelledby=\"verdict-h\">\n\
                 <div class=\"verdict invalid\">\n<h2 id=\"verdict-h\" class=\"headline\">{}</h2>\n\
                 <p class=\"error\">{}</p>\n</div>\n</section>",
                t(Text::BadForm),
                esc(&e.text(lang))
            );
            StatusCode::UNPROCESSABLE_ENTITY
        }
    };
    let _ = writeln!(
        main,
        "<section aria-labelledby=\"json-h\">\n<h2 id=\"json-h\">{}</h2>\n<p>{}</p>\n\
         <pre class=\"json\"><code>{}</code></pre>\n</section>",
        t(Text::ProblemJson),
        t(Text::JsonHelp),
        esc(&text)
    );
    posted(status, lang, t(Text::Own), "/own", &kept, &main)
}

/// `POST /own/problem.json`: the file the form describes, as a download.
pub(crate) async fn download(Form(fields): Form<Vec<(String, String)>>) -> Response {
    (
        [
            (header::CONTENT_TYPE, "application/json"),
            (
                header::CONTENT_DISPOSITION,
                "attachment; filename=\"problem.json\"",
            ),
        ],
        problem_file(&Input::from(fields)),
    )
        .into_response()
}

/// A labelled text box.
fn text_box(input: &Input, name: &str, lang: Lang, extra: &str) -> String {
    let label = FIELDS
        .iter()
        .find(|(n, _, _)| *n == name)
        .map_or("", |(_, l, _)| l.get(lang));
    format!(
        "<div class=\"field\"><label for=\"{name}\">{label}</label>\
         <input type=\"text\" id=\"{name}\" name=\"{name}\" value=\"{}\" autocomplete=\"off\" \
         spellcheck=\"false\"{extra}></div>\n",
        esc(input.get(name))
    )
}

/// A labelled group of radio buttons.
fn radios(input: &Input, name: &str, legend: &str, options: &[(&str, Text)], lang: Lang) -> String {
    let mut out = format!("<fieldset class=\"choice\">\n<legend>{legend}</legend>\n");
    for (value, label) in options {
        let checked = if input.get(name) == *value {
            " checked"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "<input type=\"radio\" name=\"{name}\" value=\"{value}\" id=\"{name}-{value}\"\
             {checked}> <label for=\"{name}-{value}\">{}</label>",
            label.get(lang)
        );
    }
    out.push_str("</fieldset>\n");
    out
}

/// The form, its boxes holding `input`.
fn form(input: &Input, lang: Lang) -> String {
    let t = |x: Text| x.get(lang);
    let mut f = format!(
        "<form class=\"own\" method=\"post\" action=\"{}\" \
         enctype=\"application/x-www-form-urlencoded\">\n",
        esc(&href("/own", lang))
    );
    f.push_str(&radios(
        input,
        "kind",
        t(Text::ProblemKind),
        &[("point", Text::PointProblem), ("ray", Text::RayProblem)],
        lang,
    ));
    let _ = writeln!(f, "<fieldset>\n<legend>{}</legend>", t(Text::PointProblem));
    f.push_str(&text_box(input, "p_position", lang, ""));
    f.push_str(&text_box(input, "p_normal", lang, ""));
    f.push_str("</fieldset>\n");
    let _ = writeln!(f, "<fieldset>\n<legend>{}</legend>", t(Text::RayProblem));
    f.push_str(&text_box(input, "r_origin", lang, ""));
    f.push_str(&text_box(input, "r_direction", lang, ""));
    f.push_str(&radios(
        input,
        "s_kind",
        t(Text::SurfaceKind),
        &[("plane", Text::Plane), ("sphere", Text::Sphere)],
        lang,
    ));
    for n in ["s_point", "s_normal", "s_center"] {
        f.push_str(&text_box(input, n, lang, ""));
    }
    f.push_str(&text_box(input, "s_radius", lang, " class=\"short\""));
    f.push_str("</fieldset>\n");
    f.push_str(&text_box(input, "viewer", lang, ""));
    let _ = writeln!(f, "<fieldset>\n<legend>{}</legend>", t(Text::Lights));
    f.push_str(&text_box(input, "ambient", lang, ""));
    for (k, l) in ["l1", "l2"].iter().enumerate() {
        let optional = if k == 1 {
            format!(" {}", t(Text::LightOptional))
        } else {
            String::new()
        };
        let _ = writeln!(
            f,
            "<fieldset>\n<legend>{} {}{optional}</legend>",
            t(Text::LightN),
            k + 1
        );
        f.push_str(&radios(
            input,
            &format!("{l}_kind"),
            t(Text::LightKind),
            &[
                ("point", Text::PointLight),
                ("directional", Text::Directional),
                ("spot", Text::SpotLight),
            ],
            lang,
        ));
        f.push_str(&text_box(input, &format!("{l}_color"), lang, ""));
        f.push_str(&text_box(input, &format!("{l}_position"), lang, ""));
        f.push_str(&text_box(input, &format!("{l}_direction"), lang, ""));
        f.push_str(&text_box(
            input,
            &format!("{l}_falloff"),
            lang,
            " class=\"short\"",
        ));
        f.push_str(&text_box(input, &format!("{l}_axis"), lang, ""));
        for n in ["angle", "exponent"] {
            f.push_str(&text_box(
                input,
                &format!("{l}_{n}"),
                lang,
                " class=\"short\"",
            ));
        }
        f.push_str("</fieldset>\n");
    }
    f.push_str("</fieldset>\n");
    let _ = writeln!(f, "<fieldset>\n<legend>{}</legend>", t(Text::Material));
    for n in ["m_ambient", "m_diffuse", "m_specular"] {
        f.push_str(&text_box(input, n, lang, ""));
    }
    f.push_str(&text_box(input, "m_shininess", lang, " class=\"short\""));
    f.push_str("</fieldset>\n");
    let _ = writeln!(
        f,
        "<p><button type=\"submit\">{}</button> <button type=\"submit\" formaction=\"{}\">{}\
         </button></p>\n</form>",
        t(Text::Solve),
        esc(&href("/own/problem.json", lang)),
        t(Text::Download)
    );
    f
}
