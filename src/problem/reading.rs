//! Why an input cannot be read, as values: a file over the size phong reads ([`TooLarge`]), an
//! input of more items than it takes ([`TooMany`]), what the system said ([`IoCause`]), memory
//! refused, and the fix ([`ReadFix`]).

use std::fmt;

use crate::text::{IoCause, Lang, Message, Show};
use crate::{faults, messages};

messages! {
    /// What a file read is, in a message about its size.
    #[derive(Copy, Default)]
    pub enum Input {
        /// A problem (or scene) file.
        #[default]
        ProblemFile => "a problem file", "um arquivo de problema";
        /// A mesh's OBJ file.
        Mesh => "a mesh", "uma malha";
        /// The course policy (`course-policy.json`, `--policy`).
        Policy => "a course policy", "uma política do curso";
        /// `phong grade`'s submissions.
        Submissions => "a submissions file", "um arquivo de respostas";
    }
}

messages! {
    /// What is counted in an input of more items than phong takes.
    #[derive(Copy, Default)]
    pub enum Counted {
        /// The rows of a submissions file.
        #[default]
        Rows => "rows", "linhas";
    }
}

/// An amount of memory, as `2.1 GB` or `12 MB` (at least 1 MB).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bytes(pub usize);

impl Show for Bytes {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let b = self.0 as f64;
        if b >= 1e9 {
            write!(f, "{:.1} GB", b / 1e9)
        } else {
            write!(f, "{:.0} MB", (b / 1e6).max(1.0))
        }
    }
}

messages! {
    /// A limit an input passes: its size, its items, or the memory it needs.
    pub enum Limit {
        /// Larger than phong reads.
        Larger { mib: u64, what: Input } =>
            "it is larger than {mib} MiB, the most phong reads for {what}",
            "é maior que {mib} MiB, o máximo que phong lê de {what}";
        /// More items than phong takes.
        More { limit: u64, what: Counted } =>
            "it has more than {limit} {what}, the most phong takes",
            "tem mais de {limit} {what}, o máximo que phong aceita";
        /// An allocation refused.
        Memory { needs: Bytes } =>
            "out of memory: this needs about {needs}",
            "memória insuficiente: isto precisa de cerca de {needs}";
    }
}

impl Default for Limit {
    fn default() -> Self {
        Limit::Memory { needs: Bytes(0) }
    }
}

/// A file over the size phong reads for its kind, the error inside an [`std::io::Error`].
#[derive(Debug)]
pub struct TooLarge {
    /// The limit, in bytes.
    pub limit: u64,
    /// What the file is.
    pub what: Input,
}

/// An input of more items than phong takes (`rows` of a submissions file), the error inside an
/// [`std::io::Error`].
#[derive(Debug)]
pub struct TooMany {
    /// The limit.
    pub limit: u64,
    /// What is counted.
    pub what: Counted,
}

impl TooLarge {
    fn limit(&self) -> Limit {
        Limit::Larger {
            mib: self.limit >> 20,
            what: self.what,
        }
    }
}

impl TooMany {
    fn limit(&self) -> Limit {
        Limit::More {
            limit: self.limit,
            what: self.what,
        }
    }
}

impl fmt::Display for TooLarge {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.limit().text(Lang::En))
    }
}

impl fmt::Display for TooMany {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.limit().text(Lang::En))
    }
}

impl std::error::Error for TooLarge {}
impl std::error::Error for TooMany {}

/// Why an input cannot be read: a limit it passes, or what the system said.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Cause {
    /// The limit, when the input passes one.
    limit: Option<Limit>,
    /// What the system said, otherwise.
    io: IoCause,
}

impl Cause {
    /// The cause of `e`.
    pub fn of(e: &std::io::Error) -> Cause {
        let inner = e.get_ref();
        let limit = inner
            .and_then(|i| i.downcast_ref::<TooLarge>())
            .map(TooLarge::limit)
            .or_else(|| {
                inner
                    .and_then(|i| i.downcast_ref::<TooMany>())
                    .map(TooMany::limit)
            });
        Cause {
            limit,
            io: IoCause::of(e),
        }
    }

    /// Whether the input is refused for its size.
    pub fn too_large(&self) -> bool {
        self.limit.is_some()
    }
}

impl Show for Cause {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.limit {
            Some(limit) => limit.show(lang, f),
            None => self.io.show(lang, f),
        }
    }
}

messages! {
    /// What would fix an input that cannot be read.
    #[derive(Copy, Default)]
    pub enum ReadFix {
        /// Too large.
        Smaller =>
            "give a smaller file (the limits are in README, \"Limits and safety\")",
            "dê um arquivo menor (os limites estão na seção \"Limits and safety\" do README)";
        /// Not found, not readable.
        #[default]
        CheckPath =>
            "check the path, and that the file exists and is readable",
            "verifique o caminho, e que o arquivo existe e pode ser lido";
        /// A mesh's OBJ file not found, not readable.
        CheckMeshPath =>
            "check the path; it is relative to the scene file's folder (to the working folder \
             for a scene read from standard input)",
            "confira o caminho; ele é relativo à pasta do arquivo da cena (à pasta de trabalho \
             para uma cena lida da entrada padrão)";
    }
}

impl ReadFix {
    /// The fix for `e`: a smaller file when it is too large, else the path.
    pub fn of(e: &std::io::Error) -> ReadFix {
        if Cause::of(e).too_large() {
            ReadFix::Smaller
        } else {
            ReadFix::CheckPath
        }
    }
}

faults! {
    /// A problem file that cannot be read.
    pub enum ReadFault {
        /// Why, and the fix.
        Unreadable { cause: Cause, fix: ReadFix } =>
            "cannot read the file: {cause}", "não é possível ler o arquivo: {cause}";
            fix "{fix}", "{fix}";
    }
}

impl ReadFault {
    /// The fault of `e`.
    pub fn of(e: &std::io::Error) -> ReadFault {
        ReadFault::Unreadable {
            cause: Cause::of(e),
            fix: ReadFix::of(e),
        }
    }
}

faults! {
    /// A problem that cannot be used for what it is given to.
    pub enum SourceFault {
        /// A problem sent as text (`phong serve`) that names a mesh.
        MeshInText =>
            "a problem sent as text cannot name a mesh file: no file is read on its behalf",
            "um problema enviado como texto não pode nomear um arquivo de malha: nenhum arquivo \
             é lido em seu nome";
            fix "give the mesh's triangles as surfaces of \"type\": \"triangle\", or solve the \
                 file with the phong command, which reads a mesh beside the problem file",
                "dê os triângulos da malha como superfícies de \"type\": \"triangle\", ou \
                 resolva o arquivo com o comando phong, que lê uma malha ao lado do arquivo de \
                 problema";
        /// A file rendered without a camera.
        NoCamera =>
            "missing: rendering needs a camera",
            "ausente: a renderização precisa de uma câmera";
            fix "add \"camera\": {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": 45, \
                 \"width\": 640, \"height\": 480}}",
                "acrescente \"camera\": {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": \
                 45, \"width\": 640, \"height\": 480}}";
        /// A point problem rendered.
        NoSurfaces =>
            "missing: a scene needs surfaces for its rays to hit (this is a point problem)",
            "ausente: uma cena precisa de superfícies para seus raios atingirem (este é um \
             problema de ponto)";
            fix "add \"surfaces\" and a \"camera\", or solve it with `phong solve`",
                "acrescente \"surfaces\" e uma \"camera\", ou resolva-o com `phong solve`";
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::Fault;

    #[test]
    fn a_file_too_large_says_its_limit_and_its_fix_in_each_language() {
        let e = std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            TooLarge {
                limit: 64 << 20,
                what: Input::ProblemFile,
            },
        );
        let f = ReadFault::of(&e);
        assert_eq!(
            f.what(Lang::En),
            "cannot read the file: it is larger than 64 MiB, the most phong reads for a \
             problem file"
        );
        assert_eq!(
            f.what(Lang::Pt),
            "não é possível ler o arquivo: é maior que 64 MiB, o máximo que phong lê de um \
             arquivo de problema"
        );
        assert!(f.fix(Lang::Pt).starts_with("dê um arquivo menor"));
        assert_eq!(ReadFix::of(&e), ReadFix::Smaller);
        let e = std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            TooMany {
                limit: 100,
                what: Counted::Rows,
            },
        );
        assert_eq!(
            Cause::of(&e),
            Cause {
                limit: Some(Limit::More {
                    limit: 100,
                    what: Counted::Rows
                }),
                io: IoCause::of(&e)
            }
        );
        assert_eq!(
            e.to_string(),
            "it has more than 100 rows, the most phong takes"
        );
    }

    #[test]
    fn memory_is_said_in_gigabytes_or_megabytes() {
        // 2.1e9 bytes is 2.1 GB; 12.4e6 is 12 MB; a few bytes are at least 1 MB.
        let m = |b: usize| Limit::Memory { needs: Bytes(b) };
        assert_eq!(
            m(2_100_000_000).text(Lang::En),
            "out of memory: this needs about 2.1 GB"
        );
        assert_eq!(
            m(12_400_000).text(Lang::Pt),
            "memória insuficiente: isto precisa de cerca de 12 MB"
        );
        assert_eq!(m(10).text(Lang::En), "out of memory: this needs about 1 MB");
    }
}
