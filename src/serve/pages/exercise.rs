//! `GET /exercise/{id}` and `POST /exercise/{id}`: an exercise's statement, its answer form
//! (a colour, or "no hit" for a ray problem), its optional step boxes (the quantities the step
//! checker knows that this exercise has), and, after a POST, the verdict: right or wrong, the
//! slips named and the near miss in the command line's own sentences (`check::report::text`,
//! `check::steps::step_message`), with the answer kept in its box; the worked solution (the
//! HTML `phong solve --format html` writes, with its diagrams) with `?solution=1` or the
//! form's box.

use std::fmt::Write;
use std::sync::Arc;

use crate::check::policy::Policy;

use axum::extract::{Path, State};
use axum::http::{HeaderMap, StatusCode, Uri};
use axum::response::Response;
use axum::Form;

use super::lang::{self, Text};
use super::layout::{href, page, posted};
use super::list::{exercise_path, title};
use crate::check::steps::{self, GivenStep, Name, NAMES};
use crate::check::{self, CheckOptions, Scale};
use crate::core::Precision;
use crate::report::html::{self, esc};
use crate::serve::catalogue::Exercise;
use crate::serve::Shared;
use crate::text::lang::Lang;
use crate::text::Message;

/// What the form sent (and is shown again in its boxes).
#[derive(Debug, Default)]
struct Input {
    /// The colour as written.
    answer: String,
    /// "The ray hits nothing" chosen.
    no_hit: bool,
    /// Each step box's label and what it holds (empty boxes included, to show them again).
    steps: Vec<(String, String)>,
    /// The worked solution asked for.
    solution: bool,
    /// The answer is in 8 bits (0–255), not on [0, 1].
    bits8: bool,
    /// The course policy the server judges by (not a field of the form).
    policy: Arc<Policy>,
}

impl Input {
    /// The answer given: `none` for "the ray hits nothing", else the colour as written, if any.
    fn given_answer(&self) -> Option<String> {
        if self.no_hit {
            Some("none".to_owned())
        } else {
            Some(self.answer.trim().to_owned()).filter(|a| !a.is_empty())
        }
    }

    /// `answer` checked as `phong check` checks it, against the exercise solved at start-up.
    fn check(&self, ex: &Exercise, answer: &str) -> check::report::Checked {
        check::check_prepared(
            &ex.prepared,
            &CheckOptions {
                answer: Some(answer.to_owned()),
                // Unticked: the 0–1 scale, 8-bit values read as the course policy says.
                scale: self.bits8.then_some(Scale::Bits8),
                policy: self.policy.clone(),
            },
        )
    }
}

/// A step box: the label a student writes (`cos_theta`, or `cos_theta[1]` with several lights)
/// and the quantity.
struct StepBox {
    label: String,
    name: Name,
}

/// `GET /exercise/{id}`.
pub(crate) async fn get(
    State(state): State<Shared>,
    Path(id): Path<String>,
    uri: Uri,
    headers: HeaderMap,
) -> Response {
    let lang = lang::of(&uri, &headers);
    let Some(ex) = state.catalogue.get(&id) else {
        return not_found(lang);
    };
    let input = Input {
        solution: lang::query(&uri, "solution") == Some("1"),
        policy: state.policy.clone(),
        ..Input::default()
    };
    let (status, main) = render(ex, lang, &input, false);
    page(
        status,
        lang,
        &title(&ex.file, &ex.id, lang),
        &path_of(ex, &input),
        &main,
    )
}

/// `POST /exercise/{id}`: the form's fields, `application/x-www-form-urlencoded`.
pub(crate) async fn post(
    State(state): State<Shared>,
    Path(id): Path<String>,
    uri: Uri,
    headers: HeaderMap,
    Form(fields): Form<Vec<(String, String)>>,
) -> Response {
    let lang = lang::of(&uri, &headers);
    let Some(ex) = state.catalogue.get(&id) else {
        return not_found(lang);
    };
    let mut input = Input {
        policy: state.policy.clone(),
        ..Input::default()
    };
    let kept: Vec<(String, String)> = fields
        .iter()
        .filter(|(k, _)| k != "relang")
        .cloned()
        .collect();
    let mut relang = false;
    for (k, v) in fields {
        match k.as_str() {
            "relang" => relang = true,
            "answer" => input.answer = v,
            "scale" => input.bits8 = v == "255",
            "kind" => input.no_hit = v == "none",
            "solution" => input.solution = v == "1",
            _ => {
                if let Some(label) = k.strip_prefix("step:") {
                    input.steps.push((label.to_owned(), v));
                }
            }
        }
    }
    let (status, main) = render(ex, lang, &input, true);
    if let (Some(log), false) = (&state.answers, relang) {
        record(log, ex, &input);
    }
    posted(
        status,
        lang,
        &title(&ex.file, &ex.id, lang),
        &exercise_path(&ex.id),
        &kept,
        &main,
    )
}

/// This page's path for the language switch of a GET.
/// The answer and steps of a form sent, as a line of `--log-answers` (as `/api/check` writes
/// one): the answer checked again against the prepared exercise (microseconds), the steps as a
/// JSON object of the boxes filled in.
fn record(log: &crate::serve::log::AnswerLog, ex: &Exercise, input: &Input) {
    use crate::serve::log::{now, AnswerEntry};
    let answer = input.given_answer();
    let filled: serde_json::Map<String, serde_json::Value> = input
        .steps
        .iter()
        .filter(|(_, v)| !v.trim().is_empty())
        .map(|(k, v)| (k.clone(), serde_json::Value::String(v.clone())))
        .collect();
    if answer.is_none() && filled.is_empty() {
        return;
    }
    let verdict = answer
        .as_deref()
        .map(|a| check::report::json(&input.check(ex, a)).verdict);
    let steps = (!filled.is_empty())
        .then(|| {
            serde_json::value::RawValue::from_string(serde_json::Value::Object(filled).to_string())
                .ok()
        })
        .flatten();
    log.record(&AnswerEntry {
        time: now(),
        exercise: Some(&ex.id),
        problem: None,
        answer: answer.as_deref(),
        steps: steps.as_deref(),
        verdict: verdict.unwrap_or("steps"),
    });
}

fn path_of(ex: &Exercise, input: &Input) -> String {
    let mut p = exercise_path(&ex.id);
    if input.solution {
        p.push_str("?solution=1");
    }
    p
}

/// 404: no exercise of that name.
pub(crate) fn not_found(lang: Lang) -> Response {
    let main = format!(
        "<h1>{}</h1>\n<p>{}</p>\n<p><a href=\"{}\">{}</a></p>\n",
        Text::NotFound.get(lang),
        Text::NoSuchExercise.get(lang),
        href("/", lang),
        Text::BackToList.get(lang)
    );
    page(
        StatusCode::NOT_FOUND,
        lang,
        Text::NotFound.get(lang),
        "/",
        &main,
    )
}

/// Where a step box goes: the point's quantities (0), each light's (1), the totals (2); then
/// the light; then the quantity's place in [`NAMES`].
type SortKey = (usize, usize, usize);

/// The step boxes of an exercise: every quantity of its solution as written and of its
/// readings (a ray that misses as written still has the intended reading's steps), then its
/// secondary rays' (a ray problem whose hit reflects or transmits), in the order of the
/// solution. A per-light name takes `[i]` when there is more than one light
/// other than ambient.
fn step_boxes(ex: &Exercise) -> Vec<StepBox> {
    let Ok((_, problem)) = ex.source().load::<f64>() else {
        return Vec::new();
    };
    let Ok(solution) = crate::solve::solve(&problem) else {
        return Vec::new();
    };
    let mut all = steps::quantities(
        &problem,
        solution.intersection.as_ref(),
        solution.evaluation.as_ref(),
    );
    for r in &solution.readings {
        all.extend(steps::quantities(
            &problem,
            r.intersection.as_ref(),
            Some(&r.evaluation),
        ));
    }
    // A ray problem's secondary rays (R_V, T, their weights and whether they are traced),
    // after the totals.
    if let Some(x) = &solution.secondary {
        all.extend(steps::secondary_quantities(x));
    }
    let indexed = problem.light_info.len() > 1;
    let position = |n: &Name| NAMES.iter().position(|x| x == n).unwrap_or(usize::MAX);
    // The point's quantities (t … ambient), each light's block, then the totals.
    let key = |n: &Name, light: Option<usize>| {
        let p = position(n);
        let group = if n.per_light {
            1
        } else if p < position(&NAMES[6]) {
            0
        } else {
            2
        };
        (group, light.unwrap_or(0), p)
    };
    let mut seen: Vec<(SortKey, Name, Option<usize>)> = Vec::new();
    // A point problem gives P: it is not a step.
    let given_point = ex.file.ray.is_none();
    for q in all
        .into_iter()
        .filter(|q| !(given_point && q.name.name == "P"))
    {
        let k = key(&q.name, q.light);
        if !seen.iter().any(|(s, _, _)| *s == k) {
            seen.push((k, q.name, q.light));
        }
    }
    seen.sort_by_key(|(k, _, _)| *k);
    seen.into_iter()
        .map(|(_, name, light)| StepBox {
            label: match light {
                Some(i) if indexed => format!("{}[{i}]", name.name),
                _ => name.name.to_owned(),
            },
            name,
        })
        .collect()
}

/// The page's `<main>`: the statement, the form, and after a POST the verdict (and, when
/// asked, the worked solution). 422 when what was sent cannot be read.
fn render(ex: &Exercise, lang: Lang, input: &Input, posted: bool) -> (StatusCode, String) {
    let t = |x: Text| x.get(lang);
    let explanation = crate::report::file::explain_source(ex.source(), Precision::F64, lang);
    let mut status = StatusCode::OK;
    let mut main = String::new();
    let _ = writeln!(main, "<h1>{}</h1>", esc(&title(&ex.file, &ex.id, lang)));
    let _ = writeln!(
        main,
        "<section aria-labelledby=\"statement-h\">\n<h2 id=\"statement-h\">{}</h2>",
        t(Text::Statement)
    );
    if let Ok(x) = &explanation {
        if let Some(q) = &x.question {
            let _ = writeln!(main, "<p class=\"question\">{}</p>", esc(q));
        }
        main.push_str(&html::data_table(&x.data, lang));
    }
    main.push_str("</section>\n");

    main.push_str(&form(ex, lang, input));

    if posted {
        // The verdict's links go to the worked solution's steps: on this page when it is
        // shown, else on the exercise's page with it shown.
        let base = if input.solution {
            String::new()
        } else {
            href(&format!("{}?solution=1", exercise_path(&ex.id)), lang)
        };
        let links = check::output::html::Links {
            index: 0,
            base: &base,
        };
        let (s, verdict) = verdict(ex, lang, input, explanation.as_ref().ok(), links);
        status = s;
        main.push_str(&verdict);
    } else {
        // The live region is on the page from the start, so that a screen reader announces
        // what a later page puts in it as it would an update.
        let _ = writeln!(
            main,
            "<section id=\"verdict\" role=\"status\" aria-label=\"{}\"></section>",
            t(Text::VerdictHeading)
        );
    }

    if input.solution {
        main.push_str(&solution(&explanation, lang));
    } else {
        let mut link = exercise_path(&ex.id);
        link.push_str("?solution=1");
        let _ = writeln!(
            main,
            "<p><a href=\"{}#solution\">{}</a></p>",
            esc(&href(&link, lang)),
            t(Text::SolutionLink)
        );
    }
    (status, main)
}

/// The answer form, its boxes holding what was sent.
fn form(ex: &Exercise, lang: Lang, input: &Input) -> String {
    let t = |x: Text| x.get(lang);
    let mut f = String::new();
    let _ = writeln!(
        f,
        "<form class=\"answer\" method=\"post\" action=\"{}\" \
         enctype=\"application/x-www-form-urlencoded\" aria-labelledby=\"answer-h\">\n\
         <h2 id=\"answer-h\">{}</h2>",
        esc(&href(&exercise_path(&ex.id), lang)),
        t(Text::YourAnswer)
    );
    if ex.file.ray.is_some() {
        let checked = |on: bool| if on { " checked" } else { "" };
        let _ = writeln!(
            f,
            "<fieldset class=\"choice\">\n<legend>{}</legend>\n\
             <input type=\"radio\" name=\"kind\" value=\"colour\" id=\"kind-colour\"{}> \
             <label for=\"kind-colour\">{}</label>\n\
             <input type=\"radio\" name=\"kind\" value=\"none\" id=\"kind-none\"{}> \
             <label for=\"kind-none\">{}</label>\n</fieldset>",
            t(Text::AnswerKind),
            checked(!input.no_hit),
            t(Text::AColour),
            checked(input.no_hit),
            t(Text::NoHit)
        );
    }
    let _ = writeln!(
        f,
        "<div class=\"field\">\n<label for=\"answer\">{}</label>\n\
         <input type=\"text\" id=\"answer\" name=\"answer\" value=\"{}\" autocomplete=\"off\" \
         spellcheck=\"false\" aria-describedby=\"answer-help\">\n\
         <p class=\"help\" id=\"answer-help\">{}</p>\n</div>",
        t(Text::ColourLabel),
        esc(&input.answer),
        t(Text::ColourHelp)
    );
    let on = |b: bool| if b { " checked" } else { "" };
    let _ = writeln!(
        f,
        "<fieldset class=\"choice\">\n<legend>{}</legend>\n\
         <input type=\"radio\" name=\"scale\" value=\"1\" id=\"scale-1\"{}> \
         <label for=\"scale-1\">{}</label>\n\
         <input type=\"radio\" name=\"scale\" value=\"255\" id=\"scale-255\"{}> \
         <label for=\"scale-255\">{}</label>\n</fieldset>",
        t(Text::Scale),
        on(!input.bits8),
        t(Text::ScaleUnit),
        on(input.bits8),
        t(Text::Scale255)
    );
    let boxes = step_boxes(ex);
    if !boxes.is_empty() {
        let open = if input.steps.iter().any(|(_, v)| !v.trim().is_empty()) {
            " open"
        } else {
            ""
        };
        let _ = writeln!(
            f,
            "<details class=\"steps\"{open}>\n<summary>{}</summary>\n\
             <p class=\"help\" id=\"steps-help\">{}</p>\n<table class=\"steps\">",
            t(Text::StepsHeading),
            t(Text::StepsHelp)
        );
        for (k, b) in boxes.iter().enumerate() {
            let value = input
                .steps
                .iter()
                .find(|(l, _)| *l == b.label)
                .map_or("", |(_, v)| v.as_str());
            let formula = b.name.formula.get(lang);
            let eq = b.name.equation.map_or(String::new(), |e| {
                format!(" <span class=\"eq\">Eq. {e}</span>")
            });
            let _ = writeln!(
                f,
                "<tr><td><label for=\"step-{k}\"><code>{}</code> <span class=\"m\">{}</span>\
                 </label>{eq}</td><td><input type=\"text\" id=\"step-{k}\" name=\"step:{}\" \
                 value=\"{}\" autocomplete=\"off\" spellcheck=\"false\" \
                 aria-describedby=\"steps-help\"></td></tr>",
                esc(&b.label),
                esc(formula),
                esc(&b.label),
                esc(value)
            );
        }
        f.push_str("</table>\n</details>\n");
    }
    let _ = writeln!(
        f,
        "<div class=\"field choice\">\n<input type=\"checkbox\" id=\"solution\" name=\"solution\" \
         value=\"1\"{}> <label for=\"solution\">{}</label>\n</div>\n\
         <p><button type=\"submit\">{}</button></p>\n</form>",
        if input.solution { " checked" } else { "" },
        t(Text::ShowSolution),
        t(Text::Check)
    );
    f
}

/// The verdict on what was sent: the answer's (when one was written), then the steps'.
fn verdict(
    ex: &Exercise,
    lang: Lang,
    input: &Input,
    x: Option<&crate::report::explain::Explanation>,
    links: check::output::html::Links<'_>,
) -> (StatusCode, String) {
    let t = |x: Text| x.get(lang);
    let mut status = StatusCode::OK;
    let mut out = format!(
        "<section id=\"verdict\" role=\"status\" aria-labelledby=\"verdict-h\">\n\
         <h2 id=\"verdict-h\">{}</h2>\n",
        t(Text::VerdictHeading)
    );
    let answer = input.given_answer();
    let mut given = Vec::new();
    let mut bad = Vec::new();
    for (label, value) in &input.steps {
        if value.trim().is_empty() {
            continue;
        }
        match steps::parse_named(label, value) {
            Ok(s) => given.push(s),
            Err(e) => bad.push(crate::text::Said::new(e)),
        }
    }
    if answer.is_none() && given.is_empty() && bad.is_empty() {
        let _ = writeln!(out, "<p>{}</p>", t(Text::NothingGiven));
        out.push_str("</section>\n");
        return (StatusCode::UNPROCESSABLE_ENTITY, out);
    }
    if let Some(a) = answer {
        let c = input.check(ex, &a);
        match &c.outcome {
            Ok(j) => out.push_str(&check::output::html::answer_fragment(&c, j, x, links, lang)),
            Err(f) => {
                status = StatusCode::UNPROCESSABLE_ENTITY;
                out.push_str(&check::output::html::cannot_fragment(&[&f.message], lang));
            }
        }
    }
    if !bad.is_empty() {
        status = StatusCode::UNPROCESSABLE_ENTITY;
        let bad: Vec<&crate::text::Said> = bad.iter().collect();
        out.push_str(&check::output::html::cannot_fragment(&bad, lang));
    }
    if !given.is_empty() {
        let (s, html) = steps_verdict(ex, &given, x, links, lang);
        if s != StatusCode::OK {
            status = s;
        }
        out.push_str(&html);
    }
    out.push_str("</section>\n");
    (status, out)
}

/// The steps judged, laid out as `phong check --format html` lays them out
/// (`check::output::html::steps_fragment`).
fn steps_verdict(
    ex: &Exercise,
    given: &[GivenStep],
    x: Option<&crate::report::explain::Explanation>,
    links: check::output::html::Links<'_>,
    lang: Lang,
) -> (StatusCode, String) {
    let c = steps::check_steps_source(ex.source(), given, false);
    match &c.outcome {
        Ok(j) => (
            StatusCode::OK,
            check::output::html::steps_fragment(j, x, links, lang),
        ),
        Err(f) => (
            StatusCode::UNPROCESSABLE_ENTITY,
            check::output::html::cannot_fragment(&[&f.message], lang),
        ),
    }
}

/// The worked solution: the parts of the explanation as `phong solve --format html` writes
/// them (its diagrams inline SVG), byte for byte. Their own `<h2>`s ("Solution (the problem
/// as written)", a reading's) are the page's second level, beside the verdict's, so the
/// section is named by a label, not by a heading above them.
pub(crate) fn solution(
    explanation: &Result<crate::report::explain::Explanation, crate::problem::ProblemError>,
    lang: Lang,
) -> String {
    let mut out = format!(
        "<section class=\"solution\" id=\"solution\" aria-label=\"{}\">\n",
        Text::SolutionHeading.get(lang)
    );
    match explanation {
        Ok(x) => {
            out.push_str("<article class=\"problem\" id=\"problem-0\">\n");
            out.push_str(&html::write_parts(x, 0, 2));
            out.push_str("</article>\n");
        }
        Err(e) => {
            let _ = writeln!(
                out,
                "<h2>{}</h2>\n<p>{}</p>",
                Text::SolutionHeading.get(lang),
                esc(&e.text(lang))
            );
        }
    }
    out.push_str("</section>\n");
    out
}
