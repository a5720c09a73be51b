//! What the operating system said when a file could not be read or written, as a value: the
//! kind of the error and its code, shown in the message's language ([`IoCause`]).

use std::fmt;
use std::io::ErrorKind;

use super::lang::Lang;
use super::message::Show;

/// Why an operation on a file failed, from its [`std::io::Error`]: in English the system's own
/// words (`No such file or directory (os error 2)`), in Portuguese the common kinds in
/// Portuguese with the system's code (`arquivo ou pasta inexistente (erro 2 do sistema)`), and
/// any other kind in the system's words.
#[derive(Clone, Debug, PartialEq)]
pub struct IoCause {
    /// The kind of error.
    kind: ErrorKind,
    /// The operating system's code, when the system gave the error.
    code: Option<i32>,
    /// Whether the error carries a message of its own (not the system's), which only its text
    /// says.
    custom: bool,
    /// The error as the system (or its maker) wrote it.
    text: String,
}

impl Default for IoCause {
    fn default() -> Self {
        IoCause {
            kind: ErrorKind::Other,
            code: None,
            custom: false,
            text: String::new(),
        }
    }
}

impl IoCause {
    /// The cause of `e`.
    pub fn of(e: &std::io::Error) -> IoCause {
        IoCause {
            kind: e.kind(),
            code: e.raw_os_error(),
            custom: e.get_ref().is_some(),
            text: e.to_string(),
        }
    }

    /// The kind in Portuguese, when it is one of the kinds said in Portuguese.
    fn portuguese(&self) -> Option<&'static str> {
        if self.custom {
            return None;
        }
        Some(match self.kind {
            ErrorKind::NotFound => "arquivo ou pasta inexistente",
            ErrorKind::PermissionDenied => "permissão negada",
            ErrorKind::IsADirectory => "é uma pasta",
            ErrorKind::NotADirectory => "não é uma pasta",
            ErrorKind::AlreadyExists => "já existe",
            ErrorKind::DirectoryNotEmpty => "a pasta não está vazia",
            ErrorKind::ReadOnlyFilesystem => "sistema de arquivos somente leitura",
            ErrorKind::StorageFull => "não há espaço no disco",
            ErrorKind::InvalidFilename => "nome de arquivo inválido",
            _ => return None,
        })
    }
}

impl Show for IoCause {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (lang, self.portuguese()) {
            (Lang::Pt, Some(words)) => {
                f.write_str(words)?;
                match self.code {
                    Some(n) => write!(f, " (erro {n} do sistema)"),
                    None => Ok(()),
                }
            }
            _ => f.write_str(&self.text),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::In;

    fn shown(e: std::io::Error) -> (String, String) {
        let c = IoCause::of(&e);
        (In(&c, Lang::En).to_string(), In(&c, Lang::Pt).to_string())
    }

    #[test]
    fn the_common_kinds_are_said_in_portuguese_with_the_system_s_code() {
        // Linux's codes: ENOENT 2, EACCES 13, EISDIR 21, ENOTDIR 20, EEXIST 17.
        for (code, pt) in [
            (2, "arquivo ou pasta inexistente (erro 2 do sistema)"),
            (13, "permissão negada (erro 13 do sistema)"),
            (21, "é uma pasta (erro 21 do sistema)"),
            (20, "não é uma pasta (erro 20 do sistema)"),
            (17, "já existe (erro 17 do sistema)"),
        ] {
            let e = std::io::Error::from_raw_os_error(code);
            let english = e.to_string();
            if cfg!(target_os = "linux") {
                assert_eq!(shown(e), (english, pt.to_owned()));
            }
        }
    }

    #[test]
    fn a_kind_without_portuguese_and_a_message_of_its_own_keep_their_words() {
        let e = std::io::Error::new(ErrorKind::NotFound, "the rubric went away");
        assert_eq!(
            shown(e),
            ("the rubric went away".into(), "the rubric went away".into())
        );
        let e = std::io::Error::from(ErrorKind::NotFound);
        assert_eq!(shown(e).1, "arquivo ou pasta inexistente");
        let e = std::io::Error::from(ErrorKind::Interrupted);
        assert_eq!(
            shown(e).0,
            shown(std::io::Error::from(ErrorKind::Interrupted)).1
        );
    }
}
