//! The language of explanations and verdicts: English, or Portuguese (the chapter's own language,
//! with its terms: luz ambiente, reflexão difusa, reflexão especular, decaimento, …).

/// A language every user-facing phrase exists in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Portuguese (português), as in the course notes.
    Pt,
}

impl Lang {
    /// The language of a code as a request writes it: `en`, or `pt` (`pt-BR`), in any case;
    /// `None` for any other.
    pub fn from_code(code: &str) -> Option<Lang> {
        match code.to_ascii_lowercase().as_str() {
            "en" => Some(Lang::En),
            "pt" | "pt-br" => Some(Lang::Pt),
            _ => None,
        }
    }
}
