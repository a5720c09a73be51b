//! Reports: a solved problem written for people (text) or for scripts (stable JSON). All
//! wording lives in [`messages`], so both formats say the same thing.

pub mod pixel;
pub mod json;
pub mod lang;
pub mod messages;
pub mod number;
pub mod text;
