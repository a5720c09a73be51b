//! clap's usage errors (an unknown flag, a value refused, a missing argument) said in
//! Portuguese: each rebuilt from clap's error context ([`clap::error::ContextKind`]: the
//! argument, the value, the valid values, the suggestion) as a [`UsageText`], never by rewriting
//! clap's rendered English. English is clap's own output, untouched, as is the version. The
//! help is said in the same language ([`lang_of`]), by [`super::help`].

use std::ffi::OsString;
use std::fmt;

use clap::error::{ContextKind, ContextValue, ErrorKind};

use super::exit::Exit;
use super::parse::BadValue;
use crate::text::{Lang, Message, Show};

crate::messages! {
    /// A usage error of clap's, as its context gives it (the English is clap's wording).
    pub(crate) enum UsageText {
        /// A value that is not one of the flag's values.
        InvalidValue { value: String, arg: String } =>
            "invalid value '{value}' for '{arg}'", "valor inválido '{value}' para '{arg}'";
        /// A flag given without its value.
        MissingValue { arg: String } =>
            "a value is required for '{arg}' but none was supplied",
            "'{arg}' precisa de um valor, e nenhum foi dado";
        /// A value that the flag's parser refuses, with its parser's reason.
        ValueValidation { value: String, arg: String, why: Refused } =>
            "invalid value '{value}' for '{arg}': {why}",
            "valor inválido '{value}' para '{arg}': {why}";
        /// A flag's value refused by one of clap's own parsers (a whole number in a range).
        ValueRefused { value: String, arg: String, why: ClapReason } =>
            "invalid value '{value}' for '{arg}': {why}",
            "valor inválido '{value}' para '{arg}': {why}";
        /// A flag or argument the command does not take.
        UnknownArgument { arg: String } =>
            "unexpected argument '{arg}' found", "argumento inesperado '{arg}'";
        /// Required arguments left out, one per line.
        MissingRequired { args: Lines } =>
            "the following required arguments were not provided:{args}",
            "faltam os argumentos obrigatórios:{args}";
        /// Two flags that do not go together.
        Conflict { arg: String, prior: String } =>
            "the argument '{arg}' cannot be used with '{prior}'",
            "o argumento '{arg}' não pode ser usado com '{prior}'";
        /// A flag that does not go with several others, one per line.
        ConflictWith { arg: String, prior: Lines } =>
            "the argument '{arg}' cannot be used with:{prior}",
            "o argumento '{arg}' não pode ser usado com:{prior}";
        /// A flag given twice.
        UsedTwice { arg: String } =>
            "the argument '{arg}' cannot be used multiple times",
            "o argumento '{arg}' não pode ser usado mais de uma vez";
        /// A command phong does not have.
        InvalidSubcommand { name: String } =>
            "unrecognized subcommand '{name}'", "subcomando desconhecido '{name}'";
        /// A command left out.
        MissingSubcommand { name: String } =>
            "'{name}' requires a subcommand but one was not provided",
            "'{name}' precisa de um subcomando, e nenhum foi dado";
        /// A flag whose value must follow an equal sign.
        NoEquals { arg: String } =>
            "equal sign is needed when assigning values to '{arg}'",
            "é preciso o sinal de igual para dar um valor a '{arg}'";
        /// A value more than the flag takes.
        TooManyValues { value: String, arg: String } =>
            "unexpected value '{value}' for '{arg}' found; no more were expected",
            "valor inesperado '{value}' para '{arg}'; nenhum outro era esperado";
        /// A flag given a wrong number of values.
        WrongNumberOfValues { expected: usize, arg: String, actual: usize } =>
            "{expected} values required for '{arg}' but {actual} were provided",
            "'{arg}' pede {expected} valores, e {actual} foram dados";
        /// The values a flag takes.
        PossibleValues { values: String } =>
            "[possible values: {values}]", "[valores possíveis: {values}]";
        /// The commands phong has.
        Subcommands { names: String } =>
            "[subcommands: {names}]", "[subcomandos: {names}]";
        /// A flag spelt like the one given.
        SimilarArgument { names: String } =>
            "tip: a similar argument exists: {names}", "dica: há um argumento parecido: {names}";
        /// Flags spelt like the one given.
        SimilarArguments { names: String } =>
            "tip: some similar arguments exist: {names}",
            "dica: há argumentos parecidos: {names}";
        /// A value spelt like the one given.
        SimilarValue { names: String } =>
            "tip: a similar value exists: {names}", "dica: há um valor parecido: {names}";
        /// Values spelt like the one given.
        SimilarValues { names: String } =>
            "tip: some similar values exist: {names}", "dica: há valores parecidos: {names}";
        /// A command spelt like the one given.
        SimilarSubcommand { names: String } =>
            "tip: a similar subcommand exists: {names}",
            "dica: há um subcomando parecido: {names}";
        /// Commands spelt like the one given.
        SimilarSubcommands { names: String } =>
            "tip: some similar subcommands exist: {names}",
            "dica: há subcomandos parecidos: {names}";
        /// Where to read more.
        MoreInformation =>
            "For more information, try '--help'.", "Para mais informações, tente '--help'.";
    }
}

/// A value's parser's reason, in the message's language.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Refused(BadValue);

impl Default for Refused {
    fn default() -> Self {
        Refused(BadValue::NotASeparator {
            text: String::new(),
        })
    }
}

impl Show for Refused {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.text(lang))
    }
}

/// Names listed one per line, indented as clap indents them.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Lines(Vec<String>);

impl Show for Lines {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.iter().try_for_each(|l| write!(f, "\n  {l}"))
    }
}

/// The language of a command line's usage errors: its `--lang` (the last one given, before
/// any `--`), else the locale's ([`Lang::from_locale`]).
pub(crate) fn lang_of(args: &[OsString]) -> Lang {
    let mut lang = None;
    let mut args = args.iter().skip(1).map(|a| a.to_string_lossy());
    while let Some(a) = args.next() {
        if a == "--" {
            break;
        }
        let value = match a.strip_prefix("--lang") {
            Some("") => args.next().map(|v| v.into_owned()),
            Some(rest) => rest.strip_prefix('=').map(str::to_owned),
            None => None,
        };
        if let Some(code) = value {
            lang = Lang::from_code(&code).or(lang);
        }
    }
    lang.unwrap_or_else(Lang::from_locale)
}

/// A command line that clap refuses, said in Portuguese when that is its language; `None`
/// where clap says it itself (English, help, version, and the kinds not rebuilt here).
pub(crate) fn refused(e: &clap::Error, args: &[OsString]) -> Option<Exit> {
    if lang_of(args) != Lang::Pt {
        return None;
    }
    let text = said(e, Lang::Pt)?;
    super::output::say(&text);
    Some(Exit::BadInput)
}

/// A context value as one string.
fn string(e: &clap::Error, kind: ContextKind) -> Option<String> {
    match e.get(kind)? {
        ContextValue::String(s) => Some(s.clone()),
        _ => None,
    }
}

/// A context value as a list of strings (one string is a list of one).
fn strings(e: &clap::Error, kind: ContextKind) -> Option<Vec<String>> {
    match e.get(kind)? {
        ContextValue::Strings(v) => Some(v.clone()),
        ContextValue::String(s) => Some(vec![s.clone()]),
        _ => None,
    }
}

fn number(e: &clap::Error, kind: ContextKind) -> Option<usize> {
    match e.get(kind)? {
        ContextValue::Number(n) => usize::try_from(*n).ok(),
        _ => None,
    }
}

/// The error's first sentence, from its context; `None` for a kind (or a context) not rebuilt.
fn sentence(e: &clap::Error) -> Option<UsageText> {
    use ContextKind as C;
    let arg = || string(e, C::InvalidArg);
    let value = || string(e, C::InvalidValue);
    Some(match e.kind() {
        ErrorKind::InvalidValue => match (arg()?, value()?) {
            (arg, value) if value.is_empty() => UsageText::MissingValue { arg },
            (arg, value) => UsageText::InvalidValue { value, arg },
        },
        ErrorKind::ValueValidation => {
            // The reasons of phong's own parsers, and of clap's whole numbers in a range.
            let source = std::error::Error::source(e)?;
            match source.downcast_ref::<BadValue>() {
                Some(why) => UsageText::ValueValidation {
                    value: value()?,
                    arg: arg()?,
                    why: Refused(why.clone()),
                },
                None => UsageText::ValueRefused {
                    value: value()?,
                    arg: arg()?,
                    why: ClapReason::read(&source.to_string())?,
                },
            }
        }
        ErrorKind::UnknownArgument => UsageText::UnknownArgument { arg: arg()? },
        ErrorKind::MissingRequiredArgument => UsageText::MissingRequired {
            args: Lines(strings(e, C::InvalidArg)?),
        },
        ErrorKind::ArgumentConflict => {
            let arg = arg()?;
            match e.get(C::PriorArg) {
                Some(ContextValue::String(prior)) if *prior == arg => UsageText::UsedTwice { arg },
                Some(ContextValue::String(prior)) => UsageText::Conflict {
                    arg,
                    prior: prior.clone(),
                },
                Some(ContextValue::Strings(prior)) => UsageText::ConflictWith {
                    arg,
                    prior: Lines(prior.clone()),
                },
                _ => return None,
            }
        }
        ErrorKind::InvalidSubcommand => UsageText::InvalidSubcommand {
            name: string(e, C::InvalidSubcommand)?,
        },
        ErrorKind::MissingSubcommand => UsageText::MissingSubcommand {
            name: string(e, C::InvalidSubcommand)?,
        },
        ErrorKind::NoEquals => UsageText::NoEquals { arg: arg()? },
        ErrorKind::TooManyValues => UsageText::TooManyValues {
            value: value()?,
            arg: arg()?,
        },
        ErrorKind::WrongNumberOfValues => UsageText::WrongNumberOfValues {
            expected: number(e, C::ExpectedNumValues)?,
            arg: arg()?,
            actual: number(e, C::ActualNumValues)?,
        },
        _ => return None,
    })
}

/// Names quoted and separated as clap lists them: `'a', 'b'`.
fn quoted(names: &[String]) -> String {
    names
        .iter()
        .map(|n| format!("'{n}'"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The whole error in `lang`, laid out as clap lays it out (the sentence, the valid values,
/// the suggestions, where to read more), without the usage line; `None` where clap's own
/// rendering stands.
pub(crate) fn said(e: &clap::Error, lang: Lang) -> Option<String> {
    use ContextKind as C;
    let mut out = format!(
        "{}: {}",
        crate::report::messages::error_word(lang),
        sentence(e)?.text(lang)
    );
    let listed = |kind| strings(e, kind).filter(|v| !v.is_empty());
    if let Some(values) = listed(C::ValidValue) {
        let values = values.join(", ");
        out += &format!("\n  {}", UsageText::PossibleValues { values }.text(lang));
    }
    if let Some(names) = listed(C::ValidSubcommand) {
        let names = names.join(", ");
        out += &format!("\n  {}", UsageText::Subcommands { names }.text(lang));
    }
    let mut suggested = false;
    for (kind, one, many) in [
        (
            C::SuggestedSubcommand,
            (|names| UsageText::SimilarSubcommand { names }) as fn(String) -> UsageText,
            (|names| UsageText::SimilarSubcommands { names }) as fn(String) -> UsageText,
        ),
        (
            C::SuggestedArg,
            |names| UsageText::SimilarArgument { names },
            |names| UsageText::SimilarArguments { names },
        ),
        (
            C::SuggestedValue,
            |names| UsageText::SimilarValue { names },
            |names| UsageText::SimilarValues { names },
        ),
    ] {
        if let Some(names) = listed(kind) {
            out += if suggested { "\n" } else { "\n\n" };
            suggested = true;
            let tip = if names.len() == 1 { one } else { many };
            out += &format!("  {}", tip(quoted(&names)).text(lang));
        }
    }
    out += &format!("\n\n{}", UsageText::MoreInformation.text(lang));
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<OsString> {
        list.iter().map(OsString::from).collect()
    }

    #[test]
    fn the_language_is_the_last_lang_flag() {
        assert_eq!(
            lang_of(&args(&["phong", "check", "--lang", "pt"])),
            Lang::Pt
        );
        assert_eq!(lang_of(&args(&["phong", "check", "--lang=pt"])), Lang::Pt);
        assert_eq!(
            lang_of(&args(&["phong", "--lang=pt", "check", "--lang", "en"])),
            Lang::En
        );
        // After `--`, a `--lang` is a file's name.
        assert_eq!(
            lang_of(&args(&[
                "phong",
                "check",
                "--lang",
                "en",
                "--",
                "--lang=pt"
            ])),
            Lang::En
        );
    }
}

crate::messages! {
    /// Why one of clap's own value parsers (`value_parser!(u32).range(…)`) refuses a value, read
    /// back from its English (which it keeps as text only).
    #[derive(Default)]
    pub(crate) enum ClapReason {
        /// A whole number outside the flag's range.
        NotInRange { n: String, lo: String, hi: String } =>
            "{n} is not in {lo}..={hi}", "{n} está fora do intervalo de {lo} a {hi}";
        /// Not a whole number.
        #[default]
        InvalidDigit =>
            "invalid digit found in string",
            "há um caractere que não é um algarismo: dê um número inteiro";
        /// Nothing where a whole number belongs.
        Empty =>
            "cannot parse integer from empty string", "vazio: dê um número inteiro";
        /// A whole number beyond the type.
        TooLarge =>
            "number too large to fit in target type", "número grande demais";
    }
}

impl ClapReason {
    /// clap's reason read into a value, when it is one of these and reads back exactly as
    /// clap wrote it; `None` otherwise (the error is then clap's own, in English).
    fn read(text: &str) -> Option<ClapReason> {
        let reason = match text {
            "invalid digit found in string" => ClapReason::InvalidDigit,
            "cannot parse integer from empty string" => ClapReason::Empty,
            "number too large to fit in target type" => ClapReason::TooLarge,
            _ => {
                let (n, range) = text.split_once(" is not in ")?;
                let (lo, hi) = range.split_once("..=")?;
                ClapReason::NotInRange {
                    n: n.to_owned(),
                    lo: lo.to_owned(),
                    hi: hi.to_owned(),
                }
            }
        };
        (reason.text(Lang::En) == text).then_some(reason)
    }
}
