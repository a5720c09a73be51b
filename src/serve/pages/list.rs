//! `GET /`: the exercises of the catalogue, each a link to its page, in the request's language.

use std::fmt::Write;

use axum::extract::State;
use axum::http::{HeaderMap, StatusCode, Uri};
use axum::response::Response;

use super::lang::{self, Text};
use super::layout::{href, page};
use crate::problem::ProblemFile;
use crate::report::html::esc;
use crate::serve::Shared;
use crate::text::lang::Lang;

/// The exercise's title in `lang` (`title_pt` in Portuguese when given), else its id.
pub(crate) fn title(file: &ProblemFile, id: &str, lang: Lang) -> String {
    let pt = match lang {
        Lang::Pt => file.title_pt.as_deref(),
        Lang::En => None,
    };
    pt.or(file.title.as_deref()).unwrap_or(id).to_owned()
}

/// `/exercise/{id}`, its id percent-encoded where it must be (an instructor's file names).
pub(crate) fn exercise_path(id: &str) -> String {
    let mut out = String::from("/exercise/");
    for b in id.bytes() {
        if b.is_ascii_alphanumeric() || matches!(b, b'-' | b'_' | b'.' | b'~') {
            out.push(char::from(b));
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

/// `GET /`.
pub(crate) async fn list(State(state): State<Shared>, uri: Uri, headers: HeaderMap) -> Response {
    let lang = lang::of(&uri, &headers);
    let t = |x: Text| x.get(lang);
    let mut main = format!(
        "<h1>{}</h1>\n<p>{}</p>\n<h2>{}</h2>\n<ul class=\"exercises\">\n",
        t(Text::SiteName),
        t(Text::ListIntro),
        t(Text::ListHeading)
    );
    for e in &state.catalogue.exercises {
        let kind = if e.file.ray.is_some() {
            Text::RayKind
        } else {
            Text::PointKind
        };
        let _ = writeln!(
            main,
            "<li><a href=\"{}\">{}</a> <span class=\"kind\">({})</span></li>",
            esc(&href(&exercise_path(&e.id), lang)),
            esc(&title(&e.file, &e.id, lang)),
            t(kind)
        );
    }
    main.push_str("</ul>\n");
    let _ = writeln!(
        main,
        "<p><a href=\"{}\">{}</a></p>",
        href("/own", lang),
        t(Text::OwnInvite)
    );
    page(StatusCode::OK, lang, t(Text::Home), "/", &main)
}
