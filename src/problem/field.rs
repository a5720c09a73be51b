//! The name of a field as errors and warnings write it (`surfaces[12].material.diffuse`),
//! written out only when one is reported.
//!
//! Validation walks every object of a file; a scene of 100,000 spheres has about a million
//! fields. Each check carries the [`Field`] it is about, a chain of borrowed parts on the
//! stack, and an error (or a warning) turns it into a `String`: a valid file formats no field
//! name at all.

use std::fmt;

/// A field of the file: a top-level name (or a dotted one, `camera.eye`), a key under another
/// field (`.diffuse`), or an index into one (`[12]`). Cheap to copy; [`fmt::Display`] (and
/// `String::from`) write it as the messages do.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Field<'a> {
    /// A name written as is: `viewer`, `camera.eye`, `point.material`.
    Name(&'a str),
    /// `parent.key`.
    Key(&'a Field<'a>, &'a str),
    /// `parent[index]`.
    Index(&'a Field<'a>, usize),
}

impl<'a> Field<'a> {
    /// `self.key`.
    pub(crate) fn key(&'a self, key: &'a str) -> Field<'a> {
        Field::Key(self, key)
    }

    /// `self[index]`.
    pub(crate) fn index(&'a self, index: usize) -> Field<'a> {
        Field::Index(self, index)
    }
}

impl fmt::Display for Field<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Field::Name(name) => f.write_str(name),
            Field::Key(parent, key) => {
                fmt::Display::fmt(parent, f)?;
                f.write_str(".")?;
                f.write_str(key)
            }
            Field::Index(parent, index) => {
                fmt::Display::fmt(parent, f)?;
                write!(f, "[{index}]")
            }
        }
    }
}

impl From<Field<'_>> for String {
    fn from(field: Field<'_>) -> String {
        field.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_field_is_written_as_the_messages_name_it() {
        let surfaces = Field::Name("surfaces");
        let s = surfaces.index(12);
        let m = s.key("material");
        assert_eq!(
            m.key("diffuse").to_string(),
            "surfaces[12].material.diffuse"
        );
        let v = s.key("vertices");
        assert_eq!(String::from(v.index(2)), "surfaces[12].vertices[2]");
        // A material's name is written as given, dots and all.
        let materials = Field::Name("materials");
        assert_eq!(materials.key("a.b").key("k").to_string(), "materials.a.b.k");
        assert_eq!(
            Field::Name("camera.eye").index(0).to_string(),
            "camera.eye[0]"
        );
    }
}
