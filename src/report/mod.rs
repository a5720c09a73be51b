//! Reports: a solved problem written for people (text, Markdown, LaTeX, HTML, in English or
//! Portuguese) or for scripts (stable, language-neutral JSON).
//!
//! [`explain`] walks a solution once and decides the steps; [`text`], [`markdown`], [`latex`]
//! and [`html`] only lay them out. All wording lives in `messages`, every formula in
//! [`formula`].

pub(crate) mod diagram;
pub mod document;
pub mod explain;
pub mod file;
pub mod formula;
pub mod html;
pub mod json;
pub mod latex;
pub mod layout;
pub mod markdown;
pub(crate) mod messages;
pub mod pixel;
pub mod text;
/// The language of a report ([`crate::text::lang`], where it is declared).
pub use crate::text::lang;
pub use messages::catalogue;
