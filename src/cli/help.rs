//! The command line's help (`phong --help`, `phong help CMD`, `phong CMD --help` and `-h`) in
//! the user's language: every text once, as a message value holding its English and its
//! Portuguese ([`crate::messages!`]), put on clap's command when the program starts.
//!
//! The clap types of [`super::args`] carry no help (a doc comment there would be clap's help
//! text): the texts are here, one file per family of commands as in `args/`
//! ([`answers`]: check, grade and policy; [`documents`]: solve, new, moodle and schema;
//! [`trace`]: render, tradeoff and export-pov; `serve`), each keyed by command and argument
//! ([`Part`]); the help of each value of a `ValueEnum` (`--part key`, `--lang pt`) is in
//! [`values`]; the top level's and what several families share, in [`CommonHelp`].
//!
//! [`command`] is the command line in a language, chosen as for usage errors
//! ([`super::usage::lang_of`]: `--lang` anywhere in the arguments, else the locale). In English
//! the rest of the help is clap's own layout and words. In Portuguese clap's own words are said
//! too ([`ClapWords`]): the headings (`Uso:`, `Argumentos:`, `Opções:`, `Comandos:`), the help
//! and version flags, the `help` command, `[padrão: …]` and the possible values. clap writes
//! these itself, in English, with no setting to translate them, so in Portuguese each is set
//! where clap allows it (a heading per argument, a help template with `Uso:`) or hidden from
//! clap and written into the argument's own help (the default, the possible values). Two things
//! stay as clap writes them: `[OPTIONS]` in the usage line, and the placeholders
//! (`<FILE>`, `<PATH>`, which the help texts name).

pub(crate) mod answers;
pub(crate) mod documents;
#[cfg(feature = "serve")]
pub(crate) mod serve;
#[cfg(test)]
mod tests;
pub(crate) mod trace;
pub(crate) mod values;

use clap::builder::{PossibleValue, Resettable, StyledStr};
use clap::{Arg, Command, CommandFactory};

use super::args::Cli;
use super::usage::UsageText;
use crate::text::{Lang, Message, Said};

/// What a help text is the help of, in a command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part<'a> {
    /// The command itself: its line in `phong --help` and the head of its own help.
    About,
    /// An argument, by its id (the field's name: `files`, `max_level`).
    Arg(&'a str),
}

/// A help text: its sentence, what the long help (`--help`) adds as a paragraph of its own, and
/// what follows the sentence after a space in both (the default of `--lang`).
pub(crate) struct Texts {
    text: Said,
    more: Option<Said>,
    then: Option<Said>,
}

impl Texts {
    /// The help `text`, the same in the short and the long help.
    pub(crate) fn new(text: impl Message + Send + Sync + 'static) -> Texts {
        Texts {
            text: Said::new(text),
            more: None,
            then: None,
        }
    }

    /// `--lang`'s help: `text`, then the default every command's `--lang` has.
    pub(crate) fn lang(text: impl Message + Send + Sync + 'static) -> Texts {
        Texts {
            then: Some(Said::new(CommonHelp::LocaleDefault)),
            ..Texts::new(text)
        }
    }

    /// With a paragraph that only the long help shows, after the text and a full stop.
    pub(crate) fn more(self, more: impl Message + Send + Sync + 'static) -> Texts {
        Texts {
            more: Some(Said::new(more)),
            ..self
        }
    }

    /// The short help in `lang`.
    fn short(&self, lang: Lang) -> String {
        match &self.then {
            Some(then) => format!("{} {}", self.text.text(lang), then.text(lang)),
            None => self.text.text(lang),
        }
    }

    /// The long help in `lang`, when it says more than the short one.
    fn long(&self, lang: Lang) -> Option<String> {
        let more = self.more.as_ref()?;
        Some(format!("{}.\n\n{}", self.short(lang), more.text(lang)))
    }
}

crate::messages! {
    /// The help of the top level, and the sentences the commands of several families share.
    pub(crate) enum CommonHelp {
        /// `phong` itself; the package's description (Cargo.toml) in English.
        Phong =>
            "Solve and explain the illumination exercises of Chapter 4 (Phong's model) step by \
             step",
            "Resolve e explica passo a passo os exercícios de iluminação do Capítulo 4 (o modelo \
             de Phong)";
        /// After each command's `--lang` help.
        LocaleDefault =>
            "[default: the locale's language: pt where LC_ALL, LC_MESSAGES or LANG is pt_*, \
             else en]",
            "[padrão: o idioma do locale: pt quando LC_ALL, LC_MESSAGES ou LANG é pt_*, senão \
             en]";
        /// `--precision` of solve and render.
        Precision =>
            "Floating-point precision of the whole calculation",
            "Precisão de ponto flutuante de todo o cálculo";
    }
}

crate::messages! {
    /// The words clap writes itself in a help, said in Portuguese by [`command`] (in English
    /// they stay clap's own: each English text here is clap's, and a test checks that clap
    /// still says it).
    pub(crate) enum ClapWords {
        /// Before the usage line.
        Usage => "Usage:", "Uso:";
        /// The heading of the positional arguments.
        Arguments => "Arguments", "Argumentos";
        /// The heading of the flags.
        Options => "Options", "Opções";
        /// The heading of the commands.
        Commands => "Commands", "Comandos";
        /// The placeholder of the command in the usage line.
        Command => "COMMAND", "COMANDO";
        /// `-h, --help` of a command without a long help.
        PrintHelp => "Print help", "Mostra a ajuda";
        /// `-h` of a command with a long help.
        PrintHelpMore =>
            "Print help (see more with '--help')", "Mostra a ajuda (veja mais com '--help')";
        /// `--help` of a command with a long help.
        PrintHelpSummary =>
            "Print help (see a summary with '-h')", "Mostra a ajuda (veja um resumo com '-h')";
        /// `-V, --version`.
        PrintVersion => "Print version", "Mostra a versão";
        /// The `help` command.
        HelpCommand =>
            "Print this message or the help of the given subcommand(s)",
            "Mostra esta mensagem ou a ajuda do(s) subcomando(s) dado(s)";
        /// The `help` command's argument.
        HelpCommandArg =>
            "Print help for the subcommand(s)", "Mostra a ajuda do(s) subcomando(s)";
        /// An argument's default, after its help.
        Default { values: String } => "[default: {values}]", "[padrão: {values}]";
        /// The heading of an argument's values, each with its help, in the long help.
        PossibleValues => "Possible values:", "Valores possíveis:";
    }
}

/// The help texts of `part` of `command` (`phong` for the top level), `None` where there are
/// none (the `help` command, clap's own).
pub(crate) fn texts(command: &str, part: Part<'_>) -> Option<Texts> {
    match (command, part) {
        ("phong", Part::About) => return Some(Texts::new(CommonHelp::Phong)),
        ("solve" | "render", Part::Arg("precision")) => {
            return Some(Texts::new(CommonHelp::Precision))
        }
        _ => {}
    }
    let found = answers::of(command, part)
        .or_else(|| documents::of(command, part))
        .or_else(|| trace::of(command, part));
    #[cfg(feature = "serve")]
    let found = found.or_else(|| serve::of(command, part));
    found
}

/// phong's command line with its help in `lang`: [`with_texts`], and in Portuguese clap's own
/// words too ([`clap_words`]).
pub(crate) fn command(lang: Lang) -> Command {
    clap_words(with_texts(Cli::command(), lang), lang)
}

/// `command` and its subcommands with their help texts ([`texts`]) and their values' help
/// ([`values::described`]) in `lang`; an argument without texts is left as it is (the test
/// `every_argument_has_help_in_both_languages` fails on it).
pub(crate) fn with_texts(command: Command, lang: Lang) -> Command {
    let name = command.get_name().to_owned();
    let mut command = command;
    if let Some(about) = texts(&name, Part::About) {
        command = command
            .about(about.short(lang))
            .long_about(resettable(about.long(lang)));
    }
    command
        .mut_args(|arg| {
            let arg = match texts(&name, Part::Arg(arg.get_id().as_str())) {
                Some(t) => arg.help(t.short(lang)).long_help(resettable(t.long(lang))),
                None => arg,
            };
            values::described(arg, lang)
        })
        .mut_subcommands(|sub| with_texts(sub, lang))
}

/// A text clap is given, or none (which removes one clap derived from a doc comment).
fn resettable(text: Option<String>) -> Resettable<StyledStr> {
    match text {
        Some(text) => Resettable::Value(text.into()),
        None => Resettable::Reset,
    }
}

/// In Portuguese, `command` with clap's own words said in Portuguese (the module's notes); in
/// English, `command` as it is: clap's words are English.
fn clap_words(command: Command, lang: Lang) -> Command {
    if lang == Lang::En {
        return command;
    }
    let mut command = headings(command, lang);
    // clap adds `-h`, `-V` and the `help` command when it builds the command: they are said
    // after that, as are the defaults and values (clap chose `-h`'s text by them).
    command.build();
    built(&mut command, lang);
    command
}

/// The arguments under the headings in `lang`, those of the positional arguments first: clap
/// lists the headings in the order of the first argument of each, so the others are moved
/// after them (their order on the screen is clap's display order, unchanged). Before clap
/// builds the command, which indexes the arguments by their place.
fn headings(command: Command, lang: Lang) -> Command {
    let arguments = ClapWords::Arguments.text(lang);
    let options = ClapWords::Options.text(lang);
    let flags: Vec<String> = command
        .get_arguments()
        .filter(|a| !a.is_positional())
        .map(|a| a.get_id().to_string())
        .collect();
    let mut command = command.mut_args(|a| {
        if a.is_positional() {
            a.help_heading(arguments.clone())
        } else {
            a
        }
    });
    for id in flags {
        command = command.mut_arg(id, |a| a.help_heading(options.clone()));
    }
    command.mut_subcommands(|sub| headings(sub, lang))
}

/// What clap built, said in `lang`: in every command, the usage line's heading, the commands'
/// heading and placeholder, `-h` and `-V`, the `help` command, and each argument's default and
/// values. Only what clap shows is changed (the arguments keep their places: clap has indexed
/// them).
fn built(command: &mut Command, lang: Lang) {
    let style = *command.get_styles().get_usage();
    let usage = format!(
        "{}{}{}",
        style.render(),
        ClapWords::Usage.text(lang),
        style.render_reset()
    );
    let shows_something = command.get_arguments().any(|a| !a.is_hide_set())
        || command.get_subcommands().any(|s| !s.is_hide_set());
    // clap's two templates, with the heading said in `lang`.
    let template = if shows_something {
        format!(
            "{{before-help}}{{about-with-newline}}\n{usage} {{usage}}\n\n{{all-args}}{{after-help}}"
        )
    } else {
        format!("{{before-help}}{{about-with-newline}}\n{usage} {{usage}}{{after-help}}")
    };
    let mut c = std::mem::take(command).help_template(template);
    if c.has_subcommands() {
        c = c
            .subcommand_help_heading(ClapWords::Commands.text(lang))
            .subcommand_value_name(ClapWords::Command.text(lang));
    }
    if c.get_name() == "help" {
        c = c.about(ClapWords::HelpCommand.text(lang));
    }
    let options = ClapWords::Options.text(lang);
    *command = c.mut_args(|arg| match arg.get_id().as_str() {
        "help" if arg.get_long() == Some("help") => {
            let arg = arg.help_heading(options.clone());
            if arg.get_long_help().is_some() {
                arg.help(ClapWords::PrintHelpMore.text(lang))
                    .long_help(ClapWords::PrintHelpSummary.text(lang))
            } else {
                arg.help(ClapWords::PrintHelp.text(lang))
            }
        }
        "version" if arg.get_long() == Some("version") => arg
            .help_heading(options.clone())
            .help(ClapWords::PrintVersion.text(lang)),
        // The `help` command's own argument.
        "subcommand" if arg.is_positional() => arg.help(ClapWords::HelpCommandArg.text(lang)),
        _ => specified(arg, lang),
    });
    for sub in command.get_subcommands_mut() {
        built(sub, lang);
    }
}

/// `arg` with its default and its possible values written into its help in `lang`, and hidden
/// from clap (which would write them in English), laid out as clap lays them out: in the short
/// help `HELP [padrão: …] [valores possíveis: …]`; in the long help the values with their help
/// listed under the help (or in brackets when none has help), then the default.
fn specified(arg: Arg, lang: Lang) -> Arg {
    let takes_values = arg.get_num_args().is_some_and(|n| n.takes_values());
    let default =
        (takes_values && !arg.is_hide_default_value_set() && !arg.get_default_values().is_empty())
            .then(|| {
                let values = arg
                    .get_default_values()
                    .iter()
                    .map(|v| quoted(&v.to_string_lossy()))
                    .collect::<Vec<_>>()
                    .join(" ");
                ClapWords::Default { values }.text(lang)
            });
    let values: Vec<PossibleValue> = if arg.is_hide_possible_values_set() {
        Vec::new()
    } else {
        arg.get_possible_values()
            .into_iter()
            .filter(|v| !v.is_hide_set())
            .collect()
    };
    if default.is_none() && values.is_empty() {
        return arg;
    }
    let inline = (!values.is_empty()).then(|| {
        let values = values
            .iter()
            .map(|v| quoted(v.get_name()))
            .collect::<Vec<_>>()
            .join(", ");
        UsageText::PossibleValues { values }.text(lang)
    });
    let help = arg.get_help().map(|h| h.to_string()).unwrap_or_default();
    let long_help = arg
        .get_long_help()
        .map(|h| h.to_string())
        .unwrap_or_else(|| help.clone());
    let joined = |parts: &[&str], sep: &str| {
        parts
            .iter()
            .filter(|p| !p.is_empty())
            .copied()
            .collect::<Vec<_>>()
            .join(sep)
    };
    let short = joined(
        &[
            &help,
            default.as_deref().unwrap_or(""),
            inline.as_deref().unwrap_or(""),
        ],
        " ",
    );
    let listed = values.iter().any(|v| v.get_help().is_some());
    let mut long = long_help;
    if listed {
        let width = values
            .iter()
            .map(|v| v.get_name().chars().count())
            .max()
            .unwrap_or(0);
        long += &format!("\n\n{}", ClapWords::PossibleValues.text(lang));
        for v in &values {
            match v.get_help() {
                Some(h) => {
                    let pad = width - v.get_name().chars().count();
                    long += &format!("\n- {}: {:pad$}{h}", v.get_name(), "");
                }
                None => long += &format!("\n- {}", v.get_name()),
            }
        }
    }
    let after = joined(
        &[
            default.as_deref().unwrap_or(""),
            if listed {
                ""
            } else {
                inline.as_deref().unwrap_or("")
            },
        ],
        "\n",
    );
    if !after.is_empty() {
        long += &format!("\n\n{after}");
    }
    arg.help(short)
        .long_help(long)
        .hide_default_value(true)
        .hide_possible_values(true)
}

/// A value as clap shows it: in double quotes when empty or holding a space.
fn quoted(value: &str) -> String {
    if value.is_empty() || value.contains(char::is_whitespace) {
        format!("{value:?}")
    } else {
        value.to_owned()
    }
}
