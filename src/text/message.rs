//! Messages as values: [`Message`] (a sentence) and [`Fault`] (what is wrong and what would fix
//! it), each rendered in a [`Lang`] by one exhaustive `match` per enum, declared with
//! [`messages!`](crate::messages) or [`faults!`](crate::faults).
//!
//! A message's arguments stay typed until it is rendered: a field of a message implements
//! [`Show`], which writes it in the language of the sentence around it (a number as
//! [`num`] writes it, a word in its language, a text echoed back shortened
//! with its length said in that language).

use std::fmt;
use std::sync::Arc;

use serde::Serialize;

use super::lang::Lang;
use super::number::num;

/// A sentence phong says (a warning, a verdict, a reason, a heading), as a value: rendered in a
/// language only where it is shown.
pub trait Message: fmt::Debug {
    /// The sentence in `lang`.
    fn text(&self, lang: Lang) -> String;
}

/// Something wrong and what would fix it, as a value: the two halves of an error
/// (`FIELD: WHAT. Fix: FIX`), each rendered in a language only where it is shown. The JSON
/// reports carry both halves in English (`message`, `fix`), for scripts.
pub trait Fault: fmt::Debug + Send + Sync {
    /// What is wrong, in `lang`.
    fn what(&self, lang: Lang) -> String;
    /// What would fix it, in `lang`; empty when nothing can be said.
    fn fix(&self, lang: Lang) -> String;
}

/// A value written inside a message, in the message's language.
pub trait Show {
    /// Writes the value as a sentence in `lang` shows it.
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result;
}

/// A value with the language it is shown in: what a message's `format!` writes.
pub struct In<'a, T: ?Sized>(pub &'a T, pub Lang);

impl<T: Show + ?Sized> fmt::Display for In<'_, T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.show(self.1, f)
    }
}

impl<T: Message> Show for T {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text(lang))
    }
}

/// Values that read the same in every language: names, paths, counts.
macro_rules! same_in_every_language {
    ($($t:ty),*) => {
        $(impl Show for $t {
            fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                fmt::Display::fmt(self, f)
            }
        })*
    };
}
same_in_every_language!(
    String,
    str,
    &'static str,
    char,
    usize,
    u64,
    u32,
    u16,
    u8,
    i64,
    i32
);

impl Show for std::path::PathBuf {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.display(), f)
    }
}

/// A number in a message, written as [`num`] writes it (six significant digits, no `-0`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Num(pub f64);

impl Show for Num {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&num(self.0))
    }
}

/// What a user wrote, echoed back in a message: whole up to a length, else its first
/// characters and how long it was (`0.5 0.5… (100000 characters)`, `(100000 caracteres)`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Echo {
    /// The text, or its first characters.
    head: String,
    /// The length of the whole text in characters, when it was cut.
    cut: Option<usize>,
}

impl Echo {
    /// `text` echoed whole up to `max` characters.
    pub fn new(text: &str, max: usize) -> Echo {
        let n = text.chars().count();
        if n <= max {
            Echo {
                head: text.to_owned(),
                cut: None,
            }
        } else {
            Echo {
                head: text.chars().take(max.saturating_sub(1)).collect(),
                cut: Some(n),
            }
        }
    }
}

impl Show for Echo {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.cut, lang) {
            (None, _) => f.write_str(&self.head),
            (Some(n), Lang::En) => write!(f, "{}… ({n} characters)", self.head),
            (Some(n), Lang::Pt) => write!(f, "{}… ({n} caracteres)", self.head),
        }
    }
}

/// A sentence kept as a value and shared (a check's failure carried into reports and
/// documents, a step's error inside a command-line error): rendered in a language where it is shown, in English in the JSON (`Display`,
/// `Serialize`). Two are equal when their English is.
#[derive(Clone)]
pub struct Said(Arc<dyn Message + Send + Sync>);

impl Said {
    /// `message`, kept.
    pub fn new(message: impl Message + Send + Sync + 'static) -> Said {
        Said(Arc::new(message))
    }

    /// `message` after `at` and a colon (`FILE: --answer: …`): `at` names files and flags, the
    /// same in every language.
    pub fn at(at: impl Into<String>, message: impl Message + Send + Sync + 'static) -> Said {
        Said::new(At {
            at: at.into(),
            message: Said::new(message),
        })
    }
}

impl Message for Said {
    fn text(&self, lang: Lang) -> String {
        self.0.text(lang)
    }
}

impl std::fmt::Debug for Said {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::fmt::Display for Said {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text(Lang::En))
    }
}

impl PartialEq for Said {
    fn eq(&self, other: &Said) -> bool {
        self.text(Lang::En) == other.text(Lang::En)
    }
}

impl Serialize for Said {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.text(Lang::En))
    }
}

/// A sentence after where it is about (`FILE: --answer: SENTENCE`).
#[derive(Debug)]
struct At {
    at: String,
    message: Said,
}

impl Message for At {
    fn text(&self, lang: Lang) -> String {
        format!("{}: {}", self.at, self.message.text(lang))
    }
}

impl Default for Said {
    /// Nothing said (the empty sentence).
    fn default() -> Said {
        Said::new(Nothing)
    }
}

/// The empty sentence.
#[derive(Debug)]
struct Nothing;

impl Message for Nothing {
    fn text(&self, _: Lang) -> String {
        String::new()
    }
}

/// What is wrong, of a fault, as a sentence of its own.
#[derive(Debug)]
pub struct WhatOf<F>(pub F);

impl<F: Fault> Message for WhatOf<F> {
    fn text(&self, lang: Lang) -> String {
        self.0.what(lang)
    }
}

/// A fault kept behind an `Arc` (an error's shared fault) says what the fault says.
impl<F: Fault + ?Sized> Fault for std::sync::Arc<F> {
    fn what(&self, lang: Lang) -> String {
        (**self).what(lang)
    }

    fn fix(&self, lang: Lang) -> String {
        (**self).fix(lang)
    }
}

/// What would fix it, of a fault, as a sentence of its own.
#[derive(Debug)]
pub struct FixOf<F>(pub F);

impl<F: Fault> Message for FixOf<F> {
    fn text(&self, lang: Lang) -> String {
        self.0.fix(lang)
    }
}

/// Declares an enum of sentences, each variant with its fields and its text in English and in
/// Portuguese, and implements [`Message`] for it by one `match`:
///
/// ```ignore
/// phong::messages! {
///     /// Why a row is not graded.
///     pub enum RowReason {
///         /// The student's cell is empty.
///         EmptyStudent => "the student field is empty", "o campo do aluno está vazio";
///         /// The exercise names no file.
///         UnknownExercise { name: Echo } =>
///             "unknown exercise: there is no {name} in the exercises folder",
///             "exercício desconhecido: não há {name} na pasta de exercícios";
///     }
/// }
/// ```
///
/// Each text is a `format!` string whose `{field}`s are the variant's fields, written by
/// [`Show`] in the text's language. Leaving a language out does not compile.
#[macro_export]
macro_rules! messages {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $(
                $(#[$vmeta:meta])*
                $variant:ident $({ $($field:ident : $ty:ty),* $(,)? })? => $en:literal, $pt:literal;
            )*
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Debug, PartialEq)]
        #[cfg_attr(test, derive(strum::EnumIter))]
        $vis enum $name {
            $( $(#[$vmeta])* $variant $({ $($field: $ty),* })?, )*
        }

        impl $crate::text::Message for $name {
            #[allow(unused_variables)]
            fn text(&self, lang: $crate::text::Lang) -> String {
                $crate::said!(self, lang, $name { $($variant $({ $($field),* })? => $en, $pt;)* })
            }
        }
    };
}

/// Declares an enum of faults, each variant with its fields, what is wrong and what would fix
/// it, each in English and in Portuguese, and implements [`Fault`] for it:
///
/// ```ignore
/// phong::faults! {
///     pub enum PointFault {
///         /// Both a point and a ray.
///         PointAndRay =>
///             "the problem gives both \"point\" and \"ray\"",
///             "o problema dá \"point\" e \"ray\" ao mesmo tempo";
///             fix "give either a point or a ray, not both", "dê um ponto ou um raio, não os dois";
///     }
/// }
/// ```
///
/// As in [`messages!`](crate::messages), `{field}`s are written by [`Show`] in the text's
/// language; a fault with nothing to say for its fix writes `fix "", ""`.
#[macro_export]
macro_rules! faults {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $(
                $(#[$vmeta:meta])*
                $variant:ident $({ $($field:ident : $ty:ty),* $(,)? })? =>
                    $en:literal, $pt:literal;
                    fix $fix_en:literal, $fix_pt:literal;
            )*
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Debug, PartialEq)]
        #[cfg_attr(test, derive(strum::EnumIter))]
        $vis enum $name {
            $( $(#[$vmeta])* $variant $({ $($field: $ty),* })?, )*
        }

        impl $crate::text::Fault for $name {
            #[allow(unused_variables)]
            fn what(&self, lang: $crate::text::Lang) -> String {
                $crate::said!(self, lang, $name { $($variant $({ $($field),* })? => $en, $pt;)* })
            }

            #[allow(unused_variables)]
            fn fix(&self, lang: $crate::text::Lang) -> String {
                $crate::said!(
                    self,
                    lang,
                    $name { $($variant $({ $($field),* })? => $fix_en, $fix_pt;)* }
                )
            }
        }
    };
}

/// The one `match` behind [`messages!`](crate::messages) and [`faults!`](crate::faults): the
/// variant of `$value` written in `$lang`, each field through [`Show`] in that language.
#[doc(hidden)]
#[macro_export]
macro_rules! said {
    (
        $value:expr, $lang:expr,
        $name:ident { $($variant:ident $({ $($field:ident),* })? => $en:literal, $pt:literal;)* }
    ) => {{
        let lang: $crate::text::Lang = $lang;
        match $value {
            $(
                $name::$variant $({ $($field),* })? => {
                    $($(let $field = $crate::text::In($field, lang);)*)?
                    match lang {
                        $crate::text::Lang::En => format!($en),
                        $crate::text::Lang::Pt => format!($pt),
                    }
                }
            )*
        }
    }};
}
