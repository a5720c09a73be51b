//! Numbers as the file writes them, for validation's errors. serde_json reads a number below
//! the smallest f64 above 0 (about 4.9e-324: `1e-330`) as 0 without a word, and validation sees
//! only the number read: its error would echo 0 where the file writes 1e-330 ("0 is not a
//! radius"). Where an error's field holds such a number, the error is said of what the file
//! writes, with why it was read as 0 ([`as_written`]).
//!
//! Only on the error path: the field's text is found again in the document's text (a raw
//! reading of the values on the field's path, `serde_json::value::RawValue`), so a valid file
//! is read as before, with no number kept as text.

use std::collections::BTreeMap;

use serde_json::value::RawValue;

use super::error::Invalid;
use super::faults::NumberFault;
use crate::text::{FixOf, Said, WhatOf};

/// `e`, said of what the file writes where the value it is about is a number the file does
/// not write as 0 but f64 reads as 0 (or an array of numbers that all read as 0, such as the
/// direction `[1e-330, 0, 0]`, named by the element): what it says and its fix are kept, after
/// why the number was read as 0. Any other error is `e` as it is. `text` is the problem's
/// JSON.
pub(crate) fn as_written(e: Invalid, text: &str) -> Invalid {
    let Some((index, written)) = literal_at(text, &e.field).and_then(read_as_zero) else {
        return e;
    };
    let field = match index {
        Some(i) => format!("{}[{i}]", e.field),
        None => e.field.clone(),
    };
    Invalid::of(
        field,
        NumberFault::ReadAsZero {
            written: written.to_owned(),
            what: Said::new(WhatOf(e.fault.clone())),
            fix: Said::new(FixOf(e.fault)),
        },
    )
}

/// The text of the value at `field` (`surfaces[0].radius`, `camera.eye[2]`, `materials.M.ior`)
/// in the JSON document `text`, as written; `None` where the document has no such value (or the
/// field is no path in it, such as `surfaces[0]`'s own errors of a whole surface, which are
/// objects and hold no number anyway).
fn literal_at<'t>(text: &'t str, field: &str) -> Option<&'t str> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut value: &'t RawValue = serde_json::from_str(text).ok()?;
    let mut rest = field;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let (index, after) = r.split_once(']')?;
            let items: Vec<&'t RawValue> = serde_json::from_str(value.get()).ok()?;
            value = items.get(index.parse::<usize>().ok()?)?;
            rest = after;
        } else {
            let r = rest.strip_prefix('.').unwrap_or(rest);
            let members: BTreeMap<String, &'t RawValue> = serde_json::from_str(value.get()).ok()?;
            // The longest member the path goes on with (a material's name may hold a dot).
            let (key, member) = members
                .iter()
                .filter(|(k, _)| {
                    r.strip_prefix(k.as_str())
                        .is_some_and(|after| after.is_empty() || after.starts_with(['.', '[']))
                })
                .max_by_key(|(k, _)| k.len())?;
            value = member;
            rest = &r[key.len()..];
        }
    }
    Some(value.get())
}

/// A number `literal` (or the first element of an array of numbers) that the file writes with
/// a digit other than 0 but f64 reads as 0, where the whole value reads as 0: the element's
/// index in the array (`None` for a number), and the number as written.
fn read_as_zero(literal: &str) -> Option<(Option<usize>, &str)> {
    let zero = |t: &str| t.parse::<f64>().is_ok_and(|x| x == 0.0);
    // A digit from 1 to 9 before the exponent: not a way of writing 0 (`0.0e-400` is one).
    let written_nonzero = |t: &str| {
        t.split(['e', 'E'])
            .next()
            .is_some_and(|m| m.bytes().any(|b| (b'1'..=b'9').contains(&b)))
    };
    let literal = literal.trim();
    if literal.starts_with('[') {
        let items: Vec<&RawValue> = serde_json::from_str(literal).ok()?;
        let tokens: Vec<&str> = items.iter().map(|r| r.get().trim()).collect();
        if !tokens.iter().all(|t| zero(t)) {
            return None;
        }
        let i = tokens.iter().position(|t| written_nonzero(t))?;
        Some((Some(i), tokens[i]))
    } else {
        (zero(literal) && written_nonzero(literal)).then_some((None, literal))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::faults::SurfaceFault;
    use crate::text::{Fault, Lang};

    const DOC: &str = r#"{"surfaces": [{"type": "sphere", "center": [0, 0, 0],
        "radius": 1e-330}, {"type": "plane", "normal": [0, 1E-400, -0.0e-999]}],
        "materials": {"a.b": {"ior": 2}, "a": {"ior": 3}}}"#;

    #[test]
    fn a_field_s_text_is_found_as_written() {
        assert_eq!(literal_at(DOC, "surfaces[0].radius"), Some("1e-330"));
        assert_eq!(literal_at(DOC, "surfaces[0].center[2]"), Some("0"));
        assert_eq!(
            literal_at(DOC, "surfaces[1].normal"),
            Some("[0, 1E-400, -0.0e-999]")
        );
        // A name with a dot is found whole, and beside a name that is its start.
        assert_eq!(literal_at(DOC, "materials.a.b.ior"), Some("2"));
        assert_eq!(literal_at(DOC, "materials.a.ior"), Some("3"));
        assert_eq!(literal_at(DOC, "surfaces[2]"), None);
        assert_eq!(literal_at(DOC, "camera.eye"), None);
        assert_eq!(literal_at("not JSON", "radius"), None);
    }

    #[test]
    fn only_a_number_written_nonzero_and_read_as_zero_is_one() {
        assert_eq!(read_as_zero("1e-330"), Some((None, "1e-330")));
        assert_eq!(read_as_zero("-2.5E-400"), Some((None, "-2.5E-400")));
        assert_eq!(read_as_zero("0"), None);
        assert_eq!(read_as_zero("-0.000e-400"), None);
        // The smallest subnormal, 4.9e-324, is not 0.
        assert_eq!(read_as_zero("5e-324"), None);
        assert_eq!(read_as_zero("[0, 1E-400, -0.0]"), Some((Some(1), "1E-400")));
        // A vector that is not the zero vector as read is not said of its tiny element.
        assert_eq!(read_as_zero("[1, 1e-400, 0]"), None);
        assert_eq!(read_as_zero("\"1e-400\""), None);
    }

    #[test]
    fn an_error_about_a_number_read_as_zero_says_what_was_written() {
        let e = Invalid::of(
            "surfaces[0].radius",
            SurfaceFault::NotARadius {
                radius: "0".to_owned(),
            },
        );
        let said = as_written(e.clone(), DOC);
        assert_eq!(said.field, "surfaces[0].radius");
        assert_eq!(
            said.fault.what(Lang::En),
            "1e-330 is too small to represent (the smallest number above 0 is about \
             4.9e-324), so it is read as 0: 0 is not a radius"
        );
        assert_eq!(said.fault.fix(Lang::En), "give the sphere a radius > 0");
        assert!(said
            .fault
            .what(Lang::Pt)
            .starts_with("1e-330 é pequeno demais"));
        assert_eq!(said.fault.fix(Lang::Pt), "dê à esfera um raio > 0");
        // Where the value is not such a number, the error is as it was.
        let other = Invalid::of(
            "surfaces[0].center[2]",
            SurfaceFault::NotARadius {
                radius: "0".to_owned(),
            },
        );
        assert_eq!(as_written(other.clone(), DOC), other);
    }
}
