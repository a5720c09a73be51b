//! The shell of every page: the language on `<html>`, the stylesheet (a file: the CSP allows no
//! inline style), a skip link, the header with the site's name, its navigation and the language
//! switch, and the page's `<main>`.

use std::fmt::Write;

use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};

use super::lang::{self, Text};
use crate::report::explain::language_tag;
use crate::report::html::esc;
use crate::text::lang::Lang;

/// The stylesheet's version in its URL (`/static/phong.css?v=…`): a hash of its text, computed
/// at compile time, so that the URL changes with the content and the file may be cached for a
/// year.
pub(crate) const CSS_VERSION: u64 = fnv1a(
    PAGES_CSS.as_bytes(),
    fnv1a(
        crate::check::output::html::STYLE.as_bytes(),
        fnv1a(crate::report::html::STYLE.as_bytes(), 0xcbf2_9ce4_8422_2325),
    ),
);

/// FNV-1a over `bytes`, from `hash`.
const fn fnv1a(bytes: &[u8], mut hash: u64) -> u64 {
    let mut i = 0;
    while i < bytes.len() {
        hash ^= bytes[i] as u64;
        hash = hash.wrapping_mul(0x0100_0000_01b3);
        i += 1;
    }
    hash
}

/// `path` with the page's language kept (`/exercise/4.2?lang=pt`); `path` may hold a query.
pub(crate) fn href(path: &str, lang: Lang) -> String {
    let sep = if path.contains('?') { '&' } else { '?' };
    format!("{path}{sep}lang={}", lang::code(lang))
}

/// A page: `title` (text, escaped here), `path` (this page, for the switch), `main` (HTML).
pub(crate) fn page(
    status: StatusCode,
    lang: Lang,
    title: &str,
    path: &str,
    main: &str,
) -> Response {
    let other = lang::other(lang);
    let switch = format!(
        "<a href=\"{}\" hreflang=\"{tag}\" lang=\"{tag}\">{}</a>",
        esc(&href(path, other)),
        Text::SwitchTo.get(lang),
        tag = language_tag(other),
    );
    shell(status, lang, title, &switch, main)
}

/// A page that answers a form: its language switch sends the same form again to `path` in the
/// other language (a button, styled as the link it replaces), so that the answer and its
/// verdict are kept across the switch.
pub(crate) fn posted(
    status: StatusCode,
    lang: Lang,
    title: &str,
    path: &str,
    fields: &[(String, String)],
    main: &str,
) -> Response {
    let other = lang::other(lang);
    let mut switch = format!(
        "<form method=\"post\" action=\"{}\" enctype=\"application/x-www-form-urlencoded\">\n",
        esc(&href(path, other))
    );
    for (k, v) in fields {
        let _ = writeln!(
            switch,
            "<input type=\"hidden\" name=\"{}\" value=\"{}\">",
            esc(k),
            esc(v)
        );
    }
    // The same answer shown in the other language: not a new answer (`--log-answers`).
    switch.push_str("<input type=\"hidden\" name=\"relang\" value=\"1\">\n");
    let _ = write!(
        switch,
        "<button type=\"submit\" class=\"link\" lang=\"{}\">{}</button>\n</form>",
        language_tag(other),
        Text::SwitchTo.get(lang)
    );
    shell(status, lang, title, &switch, main)
}

/// The shell around `main`, with `switch` (HTML) as the language switch.
fn shell(status: StatusCode, lang: Lang, title: &str, switch: &str, main: &str) -> Response {
    let t = |x: Text| x.get(lang);
    let body = format!(
        "<!DOCTYPE html>\n<html lang=\"{tag}\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title} — {site}</title>\n<link rel=\"stylesheet\" href=\"/static/phong.css?v={CSS_VERSION:016x}\">\n</head>\n\
         <body>\n<a class=\"skip\" href=\"#main\">{skip}</a>\n\
         <header class=\"site\">\n<p class=\"site-name\"><a href=\"{home}\">{site}</a></p>\n\
         <nav aria-label=\"{site}\">\n<ul>\n<li><a href=\"{home}\">{home_t}</a></li>\n\
         <li><a href=\"{own}\">{own_t}</a></li>\n</ul>\n</nav>\n\
         <nav aria-label=\"{lang_t}\" class=\"lang\">\n{switch}\n</nav>\n</header>\n\
         <main id=\"main\">\n{main}</main>\n</body>\n</html>\n",
        tag = language_tag(lang),
        title = esc(title),
        site = t(Text::SiteName),
        skip = t(Text::Skip),
        home = href("/", lang),
        home_t = t(Text::Home),
        own = href("/own", lang),
        own_t = t(Text::Own),
        lang_t = t(Text::LanguageNav),
    );
    (
        status,
        [
            (header::CONTENT_TYPE, "text/html; charset=utf-8"),
            (header::CONTENT_LANGUAGE, language_tag(lang)),
            (header::VARY, "Accept-Language"),
        ],
        body,
    )
        .into_response()
}

/// The stylesheet: the command line's HTML explanation's own (`report::html::STYLE`, so a
/// worked solution looks as `phong solve --format html` writes it), the verdict's
/// (`check::output::html::STYLE`, as `phong check --format html` lays it out), then the pages'.
pub(crate) const PAGES_CSS: &str = include_str!("static/phong.css");

/// `GET /static/phong.css`, cached for a year (its URL changes with it: [`CSS_VERSION`]).
pub(crate) async fn css() -> Response {
    (
        [
            (header::CONTENT_TYPE, "text/css; charset=utf-8"),
            (header::CACHE_CONTROL, "public, max-age=31536000, immutable"),
        ],
        format!(
            "{}{}{PAGES_CSS}",
            crate::report::html::STYLE,
            crate::check::output::html::STYLE
        ),
    )
        .into_response()
}
