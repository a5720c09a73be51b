//! XML text: the one rule every document phong writes follows (the Moodle quiz, the JUnit
//! report, the HTML of the reports and the pages, the SVG diagrams and plots), so that each is
//! well formed whatever the text it holds (docs/conventions.md, "XML text").
//!
//! XML 1.0 (§2.2, `Char`) forbids the C0 control characters but tab, line feed and carriage
//! return, and U+FFFE and U+FFFF, even written as character references; a document holding one
//! is not XML, and Moodle's importer (libxml2) then refuses the whole file. A form feed pasted
//! from a PDF into a title is enough. Each such character is written as U+FFFD, the
//! replacement character, which shows where something was and is never mistaken for it.
//!
//! The C1 controls U+0080–U+009F and DEL (U+007F) are allowed by XML 1.0 but discouraged
//! (§2.2's note), must be written as references in XML 1.1, and in text they are almost always
//! Windows-1252 bytes read as Latin-1: they are replaced too. So the rule is "a control
//! character (Unicode's `Cc`) but tab, line feed and carriage return, U+FFFE or U+FFFF". The
//! other noncharacters (U+FDD0–U+FDEF, U+nFFFE and U+nFFFF above the first plane) are XML
//! characters and kept. Rust strings cannot hold lone surrogates.

use std::borrow::Cow;

/// What a character XML does not allow is written as.
pub const REPLACEMENT: char = '\u{FFFD}';

/// Whether `c` is written as itself: an XML 1.0 character that is not a discouraged control.
pub fn allowed(c: char) -> bool {
    !(c.is_control() && !matches!(c, '\t' | '\n' | '\r') || matches!(c, '\u{FFFE}' | '\u{FFFF}'))
}

/// `c`, or [`REPLACEMENT`] where it is not [`allowed`].
pub fn clean(c: char) -> char {
    if allowed(c) {
        c
    } else {
        REPLACEMENT
    }
}

/// `s` with every character that is not [`allowed`] replaced by [`REPLACEMENT`] (borrowed when
/// there is none).
pub fn sanitize(s: &str) -> Cow<'_, str> {
    if s.chars().all(allowed) {
        Cow::Borrowed(s)
    } else {
        Cow::Owned(s.chars().map(clean).collect())
    }
}

/// Appends `c` escaped for XML and HTML text and attribute values (`&`, `<`, `>`, `"`, `'` as
/// references; `'` as `&#39;`, which HTML 4 reads too), or [`REPLACEMENT`] where it is not
/// [`allowed`].
pub fn push_escaped(out: &mut String, c: char) {
    match c {
        '&' => out.push_str("&amp;"),
        '<' => out.push_str("&lt;"),
        '>' => out.push_str("&gt;"),
        '"' => out.push_str("&quot;"),
        '\'' => out.push_str("&#39;"),
        c => out.push(clean(c)),
    }
}

/// `s` escaped for XML and HTML text and attribute values ([`push_escaped`]).
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        push_escaped(&mut out, c);
    }
    out
}

/// `s` as a CDATA section, its characters [`sanitize`]d (a `]]>` inside is split across two
/// sections).
pub fn cdata(s: &str) -> String {
    format!(
        "<![CDATA[{}]]>",
        sanitize(s).replace("]]>", "]]]]><![CDATA[>")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// XML 1.0's `Char` production, written from §2.2, to check [`allowed`] against.
    fn xml_char(c: char) -> bool {
        matches!(c as u32, 0x9 | 0xA | 0xD | 0x20..=0xD7FF | 0xE000..=0xFFFD | 0x10000..=0x10_FFFF)
    }

    #[test]
    fn every_character_xml_forbids_is_replaced() {
        for c in (0..=0x10_FFFF).filter_map(char::from_u32) {
            if !xml_char(c) {
                assert!(!allowed(c), "U+{:04X} is not an XML character", c as u32);
            }
            let discouraged = (0x7F..=0x9F).contains(&(c as u32));
            assert_eq!(
                allowed(c),
                xml_char(c) && !discouraged,
                "U+{:04X}",
                c as u32
            );
        }
        assert_eq!(
            sanitize("a\u{C}b\u{1}\u{1B}\u{FFFE}\u{FFFF}\u{85}"),
            "a\u{FFFD}b\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD}"
        );
        assert!(matches!(
            sanitize("tab\tlf\ncr\r é ∑ \u{10FFFF}"),
            Cow::Borrowed(_)
        ));
    }

    #[test]
    fn escapes_markup_and_splits_cdata_ends() {
        assert_eq!(
            escape("a<b & \"c\" 'd'>\u{0}"),
            "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;\u{FFFD}"
        );
        assert_eq!(cdata("x]]>y\u{C}"), "<![CDATA[x]]]]><![CDATA[>y\u{FFFD}]]>");
    }
}
