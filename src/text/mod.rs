//! How phong speaks: the language a user reads ([`Lang`], from `--lang` or the locale), numbers
//! as people write and read them ([`number`]), and messages as values ([`Message`], [`Fault`]).
//!
//! This is the lowest layer of the crate beside [`crate::core`]: every other module may use it,
//! and it uses none of them (ARCHITECTURE.md, "Layers").
//!
//! A message is data first (rustc's diagnostics are structs; ARCHITECTURE.md, "Messages"):
//! a value holding its field, the value written, the bounds, the fix, rendered in a language
//! only at the edge. Each message enum is declared with [`messages!`](crate::messages) or
//! [`faults!`](crate::faults), whose every variant takes its English and its Portuguese text
//! side by side: a missing translation does not compile. Every variant of every message enum is walked in both
//! languages by the crate's test `src/walk.rs` (the enums derive `strum::EnumIter` under test).

pub mod io;
pub mod lang;
pub mod memory;
pub mod message;
pub mod number;
pub mod xml;

pub use io::IoCause;
pub use lang::Lang;
pub use message::{Echo, Fault, FixOf, In, Message, Num, Said, Show, WhatOf};
