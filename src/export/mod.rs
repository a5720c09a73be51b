//! Exports of a scene to other renderers, so that `phong render` can be checked against an
//! independent implementation of the same model.
//!
//! - [`pov`]: POV-Ray 3.7 scene description language, written so that POV-Ray computes the
//!   chapter's model exactly (within 1/255 per 8-bit channel) or the scene is refused with the
//!   reason.

//! - `moodle`: problems as a Moodle XML quiz (Cloze questions, slips as 0 % answers).

pub(crate) mod moodle;
pub mod pov;
