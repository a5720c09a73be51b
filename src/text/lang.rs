//! The language of explanations and verdicts: English, or Portuguese (the chapter's own language,
//! with its terms: luz ambiente, reflexão difusa, reflexão especular, decaimento, …).

/// A language every user-facing phrase exists in: English (`En`, `--lang en`) or Portuguese
/// (`Pt`, `--lang pt`).
///
/// The variants carry no doc comment: clap would show it, in English only, as the help of the
/// value; the command line says what each value means in both languages
/// (`src/cli/help/values.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "snake_case")]
#[allow(missing_docs)]
pub enum Lang {
    #[default]
    En,
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

impl Lang {
    /// The language of the user's locale, as gettext programs choose it: the first of
    /// `LC_ALL`, `LC_MESSAGES` and `LANG` that is set and not empty decides, and a locale whose
    /// language is Portuguese (`pt_BR.UTF-8`, `pt_PT`, `pt`) gives Portuguese; any other
    /// (`C`, `POSIX`, `en_US.UTF-8`, none) gives English. `--lang` overrides it.
    pub fn from_locale() -> Lang {
        Lang::from_locale_vars(|name| std::env::var_os(name))
    }

    /// [`Lang::from_locale`] with the environment given as a function (for tests).
    pub fn from_locale_vars(var: impl Fn(&str) -> Option<std::ffi::OsString>) -> Lang {
        let locale = ["LC_ALL", "LC_MESSAGES", "LANG"]
            .into_iter()
            .filter_map(&var)
            .find(|value| !value.is_empty());
        let Some(locale) = locale else {
            return Lang::En;
        };
        let locale = locale.to_string_lossy();
        // language[_territory][.codeset][@modifier]
        let language = locale.split(['_', '.', '@', '-']).next().unwrap_or("");
        if language.eq_ignore_ascii_case("pt") {
            Lang::Pt
        } else {
            Lang::En
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsString;

    fn with(vars: &[(&str, &str)]) -> Lang {
        Lang::from_locale_vars(|name| {
            vars.iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| OsString::from(v))
        })
    }

    #[test]
    fn a_brazilian_terminal_reads_portuguese() {
        assert_eq!(with(&[("LANG", "pt_BR.UTF-8")]), Lang::Pt);
        assert_eq!(with(&[("LANG", "pt_PT")]), Lang::Pt);
        assert_eq!(with(&[("LANG", "pt")]), Lang::Pt);
    }

    #[test]
    fn other_locales_and_none_read_english() {
        assert_eq!(with(&[("LANG", "C")]), Lang::En);
        assert_eq!(with(&[("LANG", "C.UTF-8")]), Lang::En);
        assert_eq!(with(&[("LANG", "en_US.UTF-8")]), Lang::En);
        assert_eq!(with(&[("LANG", "es_ES.UTF-8")]), Lang::En);
        assert_eq!(with(&[]), Lang::En);
    }

    #[test]
    fn lc_all_then_lc_messages_then_lang_decide() {
        assert_eq!(with(&[("LC_ALL", "C"), ("LANG", "pt_BR.UTF-8")]), Lang::En);
        assert_eq!(
            with(&[("LC_MESSAGES", "pt_BR.UTF-8"), ("LANG", "C")]),
            Lang::Pt
        );
        // An empty variable is as good as unset (POSIX).
        assert_eq!(with(&[("LC_ALL", ""), ("LANG", "pt_BR.UTF-8")]), Lang::Pt);
    }
}
