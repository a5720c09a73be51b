//! What `phong serve` says when it cannot start or refuses an API request, in English and
//! Portuguese (crate::text): the API's own sentences ([`ApiText`], the JSON's `message`, in
//! the request's `lang`), a problem larger than the server solves ([`TooMany`]), and why the
//! server did not start ([`StartText`], what [`super::StartError`] says).

use std::fmt;

use super::StartError;
use crate::text::{Echo, Lang, Message, Show};
use crate::{faults, messages};

messages! {
    /// The API's own refusals: the request, not the problem, is wrong.
    pub enum ApiText {
        /// The body is not sent as JSON.
        NotJson { shape: Shape } =>
            "the request body must be JSON, sent with the header Content-Type: \
             application/json, such as {shape}",
            "o corpo da requisição deve ser JSON, enviado com o cabeçalho Content-Type: \
             application/json, como {shape}";
        /// The body is not UTF-8.
        NotUtf8 { byte: usize } =>
            "the request body is not UTF-8 text (byte {byte} is not): JSON is UTF-8 text",
            "o corpo da requisição não é texto UTF-8 (o byte {byte} não é): JSON é texto UTF-8";
        /// The body is not one JSON object.
        NotAnObject { shape: Shape } =>
            "the request body must be one JSON object, such as {shape}",
            "o corpo da requisição deve ser um único objeto JSON, como {shape}";
        /// The body's JSON is not the API's (the parser's words in `reason`).
        NotTheApis { reason: super::api::Reason, shape: Shape } =>
            "the request is not the API's JSON: {reason}. Fix: send {shape}",
            "a requisição não é o JSON da API: {reason}. Correção: envie {shape}";
        /// `lang` names no language.
        NotALanguage { code: Echo } =>
            "lang: \"{code}\" is not a language: give \"en\" (the default) or \"pt\"",
            "lang: \"{code}\" não é um idioma: dê \"en\" (o padrão) ou \"pt\"";
        /// `precision` names no precision.
        NotAPrecision { value: Echo } =>
            "precision: \"{value}\" is not a precision: give \"f64\" (the default) or \"f32\"",
            "precision: \"{value}\" não é uma precisão: dê \"f64\" (o padrão) ou \"f32\"";
        /// `scale` is neither 1 nor 255.
        NotAScale =>
            "scale: give 1 (components on [0, 1], the default) or 255 (8-bit integers)",
            "scale: dê 1 (componentes em [0, 1], o padrão) ou 255 (inteiros de 8 bits)";
        /// Neither an answer nor steps were checked (not reached).
        NothingChecked => "nothing was checked", "nada foi verificado";
        /// `exercise` names none of the server's.
        NoSuchExercise { id: Echo, ids: String } =>
            "exercise: this server has no exercise \"{id}\"; it has {ids} (GET /api/exercises \
             lists them)",
            "exercise: este servidor não tem o exercício \"{id}\"; tem {ids} (GET \
             /api/exercises os lista)";
        /// Both a problem and an exercise.
        ProblemAndExercise =>
            "give either \"problem\" (a problem file's JSON) or \"exercise\" (the id of one of \
             this server's exercises), not both",
            "dê \"problem\" (o JSON de um arquivo de problema) ou \"exercise\" (o id de um dos \
             exercícios deste servidor), não os dois";
        /// Neither a problem nor an exercise.
        NoProblem =>
            "the request names no problem: give \"problem\" (a problem file's JSON, such as \
             {{\"problem\": {{\"lights\": […], …}}}}) or \"exercise\" (such as \"4.2\")",
            "a requisição não nomeia nenhum problema: dê \"problem\" (o JSON de um arquivo de \
             problema, como {{\"problem\": {{\"lights\": […], …}}}}) ou \"exercise\" (como \
             \"4.2\")";
    }
}

messages! {
    /// What a request may send only so many of.
    #[derive(Default)]
    pub enum Items {
        /// `lights`.
        #[default]
        Lights => "lights", "fontes de luz";
        /// `surfaces`.
        Surfaces => "surfaces", "superfícies";
    }
}

faults! {
    /// A problem sent larger than the server solves in one request.
    pub enum TooMany {
        /// More lights or surfaces than the limit.
        Items { n: usize, what: Items, max: usize } =>
            "{n} {what} are more than the {max} this server solves in one request",
            "{n} {what} são mais que as {max} que este servidor resolve numa requisição";
            fix "give at most {max} {what}, or solve the problem with the phong command, which \
                 has no such limit",
                "dê no máximo {max} {what}, ou resolva o problema com o comando phong, que não \
                 tem esse limite";
    }
}

messages! {
    /// Why the server did not start.
    pub enum StartText {
        /// An exercise of `--exercises` cannot be read or is invalid: the error in full.
        Exercises { error: String } => "--exercises: {error}", "--exercises: {error}";
        /// The address cannot be listened on.
        Bind { addr: String, error: OsError } =>
            "--addr: cannot listen on {addr}: {error}",
            "--addr: não é possível escutar em {addr}: {error}";
        /// The answers' log cannot be opened.
        Log { path: String, error: OsError } =>
            "--log-answers: cannot open {path} for appending: {error}",
            "--log-answers: não é possível abrir {path} para acrescentar: {error}";
        /// The runtime or the connection loop failed.
        Runtime { error: OsError } => "the server stopped: {error}", "o servidor parou: {error}";
    }
}

impl Message for StartError {
    fn text(&self, lang: Lang) -> String {
        let said = match self {
            StartError::Exercises(e) => StartText::Exercises {
                error: e.text(lang),
            },
            StartError::Bind { addr, source } => StartText::Bind {
                addr: addr.to_string(),
                error: OsError::of(source),
            },
            StartError::Log { path, source } => StartText::Log {
                path: path.display().to_string(),
                error: OsError::of(source),
            },
            StartError::Runtime(source) => StartText::Runtime {
                error: OsError::of(source),
            },
        };
        said.text(lang)
    }
}

/// What the operating system said, as it said it (English), and in Portuguese for the errors
/// a server's start meets (an address in use, a permission refused, a missing folder).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OsError {
    /// The error as Rust writes it (`Address already in use (os error 98)`).
    text: String,
    /// The error's number, when the system gave one.
    code: Option<i32>,
    /// The Portuguese of its kind, when known.
    pt: Option<&'static str>,
}

impl OsError {
    /// `e` kept as a value.
    pub fn of(e: &std::io::Error) -> Self {
        use std::io::ErrorKind as K;
        let pt = match e.kind() {
            K::AddrInUse => Some("endereço já em uso"),
            K::AddrNotAvailable => Some("endereço indisponível"),
            K::PermissionDenied => Some("permissão negada"),
            K::NotFound => Some("arquivo ou pasta inexistente"),
            K::AlreadyExists => Some("o arquivo já existe"),
            K::IsADirectory => Some("é uma pasta"),
            K::NotADirectory => Some("não é uma pasta"),
            K::ReadOnlyFilesystem => Some("sistema de arquivos somente leitura"),
            K::StorageFull => Some("não há espaço no dispositivo"),
            _ => None,
        };
        OsError {
            text: e.to_string(),
            code: e.raw_os_error(),
            pt,
        }
    }
}

impl Show for OsError {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (lang, self.pt, self.code) {
            (Lang::En, _, _) | (Lang::Pt, None, None) => f.write_str(&self.text),
            (Lang::Pt, Some(pt), Some(n)) => write!(f, "{pt} (erro {n} do sistema)"),
            (Lang::Pt, Some(pt), None) => f.write_str(pt),
            (Lang::Pt, None, Some(n)) => write!(f, "erro {n} do sistema"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    #[test]
    fn a_start_error_reads_in_both_languages() {
        let e = StartError::Bind {
            addr: "127.0.0.1:8080".parse().unwrap(),
            source: std::io::Error::from_raw_os_error(98),
        };
        let en = e.text(Lang::En);
        assert_eq!(en, e.to_string());
        assert!(
            en.starts_with("--addr: cannot listen on 127.0.0.1:8080: "),
            "{en}"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "--addr: não é possível escutar em 127.0.0.1:8080: endereço já em uso (erro 98 do \
             sistema)"
        );
        let e = StartError::Log {
            path: PathBuf::from("/nope/answers.jsonl"),
            source: std::io::Error::from(std::io::ErrorKind::PermissionDenied),
        };
        assert_eq!(e.text(Lang::En), e.to_string());
        assert_eq!(
            e.text(Lang::Pt),
            "--log-answers: não é possível abrir /nope/answers.jsonl para acrescentar: \
             permissão negada"
        );
        let e = StartError::Runtime(std::io::Error::other("boom"));
        assert_eq!(e.text(Lang::En), "the server stopped: boom");
        assert_eq!(e.text(Lang::Pt), "o servidor parou: boom");
    }

    #[test]
    fn an_exercise_that_stops_the_start_is_said_in_the_language_asked() {
        let e = StartError::Exercises(
            crate::problem::Invalid::of("ray", crate::solve::faults::SolveFault::Scene)
                .at("exercises/x.json"),
        );
        assert_eq!(e.text(Lang::En), e.to_string());
        assert!(
            e.text(Lang::Pt)
                .starts_with("--exercises: exercises/x.json: ray: este arquivo é uma cena"),
            "{}",
            e.text(Lang::Pt)
        );
    }
}

messages! {
    /// What the body of a request looks like, for the messages that refuse one.
    #[derive(Default, Copy)]
    pub(crate) enum Shape {
        /// `POST /api/solve`.
        #[default]
        Solve =>
            "{{\"problem\": {{…a problem file…}}, \"lang\": \"pt\"}} or {{\"exercise\": \"4.2\"}}",
            "{{\"problem\": {{…um arquivo de problema…}}, \"lang\": \"pt\"}} ou \
             {{\"exercise\": \"4.2\"}}";
        /// `POST /api/check`.
        Check =>
            "{{\"problem\": {{…a problem file…}}, \"answer\": \"0.245 0.28 0.21\", \
             \"steps\": {{\"cos_theta\": \"0.98995\"}}}} or {{\"exercise\": \"4.2\", …}}",
            "{{\"problem\": {{…um arquivo de problema…}}, \"answer\": \"0.245 0.28 0.21\", \
             \"steps\": {{\"cos_theta\": \"0.98995\"}}}} ou {{\"exercise\": \"4.2\", …}}";
    }
}
