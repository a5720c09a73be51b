//! The kinds of light and of surface, each declared once: `kinds!` reads one table per family
//! (the fields it has, then the kinds and which of those fields each takes) and writes every
//! piece of the problem format that lists them, so that they cannot drift apart:
//!
//! - the flat parse struct (`LightSpec`): `type`, the optional fields and every field of the
//!   table, each `Option`, parsed flat (not as a tagged enum) so that an error names its exact
//!   field; unknown fields are rejected, and serde lists the known ones in the table's order;
//! - the `type` enum (`LightType`): its words (`name`, `WORDS`), the fields each kind requires
//!   (`fields`), and its reader (a string only: `type_word`);
//! - `present` (the fields given in a file), `present_mask` and the kind's `fields_mask` (the
//!   same as bits, computed at compile time, so that validation asks every object whether it
//!   gives a field its kind does not take without comparing names) and `purpose` (what a field
//!   gives, for the message when it is missing);
//! - the schema twin for `phong schema`: one object per kind, with `type` as its constant, its
//!   fields required and the optional ones not, each field with the schema type, description and
//!   bounds of the table.
//!
//! The twin is derived by schemars from generated types: one transparent newtype per field
//! (carrying the field's schema type and attributes, so that a kind can name a field and get its
//! schema), one struct per kind and an internally tagged enum of them. schemars writes a
//! newtype variant of a struct that denies unknown fields exactly as it writes a struct variant.
//!
//! [`format`](super::format) holds the two tables; validation ([`super::validate`]) turns each
//! kind's fields into the core's types.

use std::fmt;

use serde::de::{self, Visitor};
use serde::Deserializer;

use super::syntax::{Expected, Quoted};
use crate::text::{Lang, Message};

/// Declares a family of kinds (lights, surfaces). The table, in this order:
///
/// ```text
/// /// doc of the flat parse struct
/// pub struct LightSpec;
/// /// doc of the `type` enum
/// pub enum LightType;
/// /// doc of the schema (its description in `phong schema`)
/// schema Light in light_schema;          // the schema's name, and a module for its types
/// optional { name: String, }             // taken by every kind, never required (a doc here
///                                        // documents the parse struct, not the schema)
/// fields {
///     /// description in the schema (optional), schemars attributes (optional)
///     #[schemars(range(min = 0, max = 2))]
///     falloff: f64 as u8 => "what it gives, for the message when it is missing",
///                           "o que ele dá, em português",
///     …                                  // `as T`: the schema's type, when not the parsed one
/// }
/// kinds {
///     /// doc of the kind (its description in the schema)
///     Point "point" [position, color, falloff],   // variant, `type` word, required fields
///     …
/// }
/// ```
///
/// A kind that names a field the table does not have does not compile.
macro_rules! kinds {
    (
        $(#[$spec_doc:meta])*
        pub struct $Spec:ident;
        $(#[$kind_doc:meta])*
        pub enum $Kind:ident;
        $(#[$schema_doc:meta])*
        schema $Schema:ident in $module:ident;
        optional $optional:tt
        fields {
            $(
                $(#[$field_meta:meta])*
                $field:ident: $ty:ty $(as $schema_ty:ty)? => $purpose:literal, $purpose_pt:literal,
            )*
        }
        kinds {
            $(
                $(#[$kind_meta:meta])*
                $Variant:ident $word:literal [$($takes:ident),* $(,)?],
            )*
        }
    ) => {
        $crate::problem::kinds::kinds!(
            @spec [$(#[$spec_doc])*] $Spec $Kind $optional
            [$($field: $ty => $purpose, $purpose_pt,)*]
        );

        $(#[$kind_doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum $Kind {
            $($(#[$kind_meta])* $Variant,)*
        }

        impl $Kind {
            /// Every kind, in the table's order.
            pub const ALL: &'static [$Kind] = &[$($Kind::$Variant),*];
            /// The `type` word of each kind of [`Self::ALL`].
            pub const WORDS: &'static [&'static str] = &[$($word),*];

            /// The `type` word.
            pub fn name(self) -> &'static str {
                match self {
                    $($Kind::$Variant => $word,)*
                }
            }

            /// The fields this kind takes besides `type` and the optional ones; all are required.
            pub fn fields(self) -> &'static [&'static str] {
                match self {
                    $($Kind::$Variant => &[$(stringify!($takes)),*],)*
                }
            }

            /// [`Self::fields`] as bits of the table's fields (see `present_mask`).
            pub(crate) fn fields_mask(self) -> u32 {
                match self {
                    $(
                        $Kind::$Variant => const {
                            0 $(| $crate::problem::kinds::bit($Spec::FIELDS, stringify!($takes)))*
                        },
                    )*
                }
            }
        }

        impl<'de> ::serde::Deserialize<'de> for $Kind {
            fn deserialize<D: ::serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                $crate::problem::kinds::type_word(d, Self::ALL, Self::WORDS)
            }
        }

        // The schema twin (see the module's documentation); never built, only described.
        #[allow(dead_code, non_camel_case_types)]
        mod $module {
            use super::*;

            /// One newtype per field: its schema type, description and bounds.
            pub mod field {
                use super::*;
                $(
                    $crate::problem::kinds::kinds!(
                        @field [$(#[$field_meta])*] $field $ty $(as $schema_ty)?
                    );
                )*
            }

            $($crate::problem::kinds::kinds!(@kind $Variant [$($takes),*] $optional);)*

            $(#[$schema_doc])*
            #[derive(::schemars::JsonSchema)]
            #[serde(tag = "type", deny_unknown_fields)]
            pub enum $Schema {
                $(
                    $(#[$kind_meta])*
                    #[serde(rename = $word)]
                    $Variant($Variant),
                )*
            }
        }

        impl ::schemars::JsonSchema for $Spec {
            fn schema_name() -> ::std::borrow::Cow<'static, str> {
                stringify!($Schema).into()
            }
            fn json_schema(g: &mut ::schemars::SchemaGenerator) -> ::schemars::Schema {
                <$module::$Schema as ::schemars::JsonSchema>::json_schema(g)
            }
        }
    };

    // The flat parse struct, `present` and `purpose`.
    (
        @spec [$(#[$spec_doc:meta])*] $Spec:ident $Kind:ident
        { $($(#[$opt_meta:meta])* $opt:ident: $opt_ty:ty),* $(,)? }
        [$($field:ident: $ty:ty => $purpose:literal, $purpose_pt:literal,)*]
    ) => {
        $(#[$spec_doc])*
        #[derive(Debug, Clone, ::serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct $Spec {
            /// The `type` word: which kind this is.
            #[serde(rename = "type")]
            pub kind: $Kind,
            $(
                $(#[$opt_meta])*
                #[serde(default)]
                pub $opt: Option<$opt_ty>,
            )*
            $(
                #[doc = $purpose]
                #[serde(default)]
                pub $field: Option<$ty>,
            )*
        }

        impl $Spec {
            /// The table's fields, in its order (bit `i` of a mask is `FIELDS[i]`).
            const FIELDS: &'static [&'static str] = &[$(stringify!($field)),*];

            /// The fields present in the file as bits of [`Self::FIELDS`]: validation asks every
            /// object whether it gives a field its kind does not take, and a mask answers without
            /// comparing names.
            pub(crate) fn present_mask(&self) -> u32 {
                let mut mask = 0;
                $(
                    if self.$field.is_some() {
                        mask |= const { $crate::problem::kinds::bit(Self::FIELDS, stringify!($field)) };
                    }
                )*
                mask
            }

            /// The names of the fields present in the file (besides `type` and the optional
            /// ones), in the table's order. Allocates nothing: validation asks every object.
            pub fn present(&self) -> impl Iterator<Item = &'static str> {
                [$(self.$field.is_some().then_some(stringify!($field))),*]
                    .into_iter()
                    .flatten()
            }

            /// What a field of the table gives, to say why it is needed, in both languages.
            pub fn purpose(name: &str) -> Option<$crate::problem::syntax::Purpose> {
                let (en, pt) = match name {
                    $(stringify!($field) => ($purpose, $purpose_pt),)*
                    _ => return None,
                };
                Some($crate::problem::syntax::Purpose::Table {
                    text: $crate::problem::syntax::Bilingual { en, pt },
                })
            }
        }
    };

    // A field's newtype: the parsed type, or the schema type given after `as`.
    (@field [$(#[$meta:meta])*] $field:ident $ty:ty) => {
        #[derive(::schemars::JsonSchema)]
        #[serde(transparent)]
        #[schemars(inline)]
        pub struct $field($(#[$meta])* pub $ty);
    };
    (@field [$(#[$meta:meta])*] $field:ident $ty:ty as $schema_ty:ty) => {
        $crate::problem::kinds::kinds!(@field [$(#[$meta])*] $field $schema_ty);
    };

    // A kind's object: its required fields, then the optional ones.
    // The optional fields' docs describe the parse struct only, not the schema.
    (@kind $Variant:ident [$($takes:ident),*]
        { $($(#[$opt_meta:meta])* $opt:ident: $opt_ty:ty),* $(,)? }) => {
        #[derive(::schemars::JsonSchema)]
        #[serde(deny_unknown_fields)]
        pub struct $Variant {
            $(pub $takes: field::$takes,)*
            $(pub $opt: Option<$opt_ty>,)*
        }
    };
}

pub(crate) use kinds;

/// The bit of the field `name` in a mask over `fields` (at most 32); evaluated at compile time by
/// `kinds!`, where a name that is not in the table does not compile.
pub(crate) const fn bit(fields: &[&str], name: &str) -> u32 {
    assert!(fields.len() <= 32, "a mask has 32 bits");
    let mut i = 0;
    while i < fields.len() {
        let (a, b) = (fields[i].as_bytes(), name.as_bytes());
        if a.len() == b.len() {
            let mut k = 0;
            while k < a.len() && a[k] == b[k] {
                k += 1;
            }
            if k == a.len() {
                return 1 << i;
            }
        }
        i += 1;
    }
    panic!("a field that is not in the table")
}

/// A `type` word, read only from a string. serde_json reads an enum from a string or an object
/// and answers any other value (`"type": 5`) with a syntax error, "expected value", although
/// the JSON is well formed.
pub(crate) fn type_word<'de, D: Deserializer<'de>, T: Copy + 'static>(
    d: D,
    all: &'static [T],
    names: &'static [&'static str],
) -> Result<T, D::Error> {
    struct V<T: 'static> {
        all: &'static [T],
        names: &'static [&'static str],
    }
    impl<'de, T: Copy> Visitor<'de> for V<T> {
        type Value = T;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            let words = self.names.iter().map(|n| (*n).to_owned()).collect();
            let expected = Expected::Words {
                words: Quoted(words),
            };
            f.write_str(&expected.text(Lang::En))
        }
        fn visit_str<E: de::Error>(self, s: &str) -> Result<T, E> {
            match self.names.iter().position(|n| *n == s) {
                Some(i) => Ok(self.all[i]),
                None => Err(E::unknown_variant(s, self.names)),
            }
        }
    }
    d.deserialize_str(V { all, names })
}
