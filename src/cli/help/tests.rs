//! The help checked: every command, argument and value has its help in both languages, clap
//! still says the English words [`super::ClapWords`] translates, and the Portuguese help
//! holds none of clap's English.

use clap::Command;

use super::*;

/// Every command of `command` (itself included), by name, but the `help` command, clap's own.
fn commands(command: &Command) -> Vec<&Command> {
    let mut all = vec![command];
    for sub in command.get_subcommands().filter(|s| s.get_name() != "help") {
        all.extend(commands(sub));
    }
    all
}

#[test]
fn every_argument_has_help_in_both_languages() {
    let en = with_texts(Cli::command(), Lang::En);
    let pt = with_texts(Cli::command(), Lang::Pt);
    let mut bad = Vec::new();
    for (e, p) in commands(&en).into_iter().zip(commands(&pt)) {
        let name = e.get_name();
        assert_eq!(name, p.get_name());
        let about = (
            e.get_about().map(|s| s.to_string()),
            p.get_about().map(|s| s.to_string()),
        );
        match about {
            (Some(e), Some(p)) if !e.is_empty() && !p.is_empty() && e != p => {}
            other => bad.push(format!("{name}: about {other:?}")),
        }
        for (a, b) in e.get_arguments().zip(p.get_arguments()) {
            let id = a.get_id();
            let help = (
                a.get_help().map(|s| s.to_string()),
                b.get_help().map(|s| s.to_string()),
            );
            match help {
                (Some(e), Some(p)) if !e.is_empty() && !p.is_empty() && e != p => {}
                other => bad.push(format!("{name} {id}: help {other:?}")),
            }
            for (v, w) in a.get_possible_values().iter().zip(b.get_possible_values()) {
                let help = (
                    v.get_help().map(|s| s.to_string()),
                    w.get_help().map(|s| s.to_string()),
                );
                match help {
                    (None, None) => {}
                    (Some(e), Some(p)) if e != p => {}
                    other => bad.push(format!(
                        "{name} {id} {}: value's help {other:?}",
                        v.get_name()
                    )),
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "help missing or untranslated:\n{}",
        bad.join("\n")
    );
}

#[test]
fn every_text_is_shown() {
    // A text whose flag was renamed or removed would never be shown: each variant of the help
    // enums is in the English help of some command, argument or value.
    use strum::IntoEnumIterator;
    let command = with_texts(Cli::command(), Lang::En);
    let mut shown = String::new();
    for c in commands(&command) {
        let texts = [c.get_about(), c.get_long_about()];
        shown.extend(texts.into_iter().flatten().map(|t| format!("{t}\n")));
        for a in c.get_arguments() {
            let texts = [a.get_help(), a.get_long_help()];
            shown.extend(texts.into_iter().flatten().map(|t| format!("{t}\n")));
            for v in a.get_possible_values() {
                shown.extend(v.get_help().map(|t| format!("{t}\n")));
            }
        }
    }
    let mut english: Vec<(String, String)> = Vec::new();
    let mut add = |name: String, text: String| english.push((name, text));
    CommonHelp::iter().for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    // (A text with a value is shown with the value the help gives it.)
    answers::AnswersHelp::iter()
        .map(|m| match m {
            answers::AnswersHelp::CheckStep { .. } => answers::AnswersHelp::CheckStep {
                names: crate::check::steps::step_names(),
            },
            m => m,
        })
        .for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    documents::DocumentsHelp::iter().for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    trace::TraceHelp::iter().for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    #[cfg(feature = "serve")]
    serve::ServeHelp::iter().for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    values::ValueHelp::iter().for_each(|m| add(format!("{m:?}"), m.text(Lang::En)));
    let unshown: Vec<&String> = english
        .iter()
        .filter(|(_, text)| !shown.contains(text.as_str()))
        .map(|(name, _)| name)
        .collect();
    assert!(unshown.is_empty(), "help texts of no argument: {unshown:?}");
}

#[test]
fn the_command_line_is_consistent_in_both_languages() {
    for lang in [Lang::En, Lang::Pt] {
        command(lang).debug_assert();
    }
}

#[test]
fn the_top_level_about_is_the_package_description() {
    assert_eq!(
        CommonHelp::Phong.text(Lang::En),
        env!("CARGO_PKG_DESCRIPTION")
    );
}

#[test]
fn clap_still_says_the_words_translated() {
    // clap's own English, as it builds `-h`, `-V` and the `help` command: if an update of clap
    // changes a word, its Portuguese in `ClapWords` must be looked at again.
    let mut en = command(Lang::En);
    en.build();
    let help = |c: &Command| {
        c.get_arguments()
            .find(|a| a.get_id() == "help")
            .map(|a| {
                (
                    a.get_help().map(|s| s.to_string()),
                    a.get_long_help().map(|s| s.to_string()),
                )
            })
            .unwrap()
    };
    assert_eq!(help(&en), (Some(ClapWords::PrintHelp.text(Lang::En)), None));
    let check = en.find_subcommand("check").unwrap();
    assert_eq!(
        help(check),
        (
            Some(ClapWords::PrintHelpMore.text(Lang::En)),
            Some(ClapWords::PrintHelpSummary.text(Lang::En))
        )
    );
    let version = en
        .get_arguments()
        .find(|a| a.get_id() == "version")
        .unwrap();
    assert_eq!(
        version.get_help().map(|s| s.to_string()),
        Some(ClapWords::PrintVersion.text(Lang::En))
    );
    let help_command = en.find_subcommand("help").unwrap();
    assert_eq!(
        help_command.get_about().map(|s| s.to_string()),
        Some(ClapWords::HelpCommand.text(Lang::En))
    );
    let long = en.render_long_help().to_string();
    for word in [ClapWords::Usage, ClapWords::Commands, ClapWords::Options] {
        assert!(long.contains(&word.text(Lang::En)), "{word:?}: {long}");
    }
    let check = en
        .find_subcommand_mut("check")
        .unwrap()
        .render_long_help()
        .to_string();
    for word in [ClapWords::Arguments, ClapWords::PossibleValues] {
        assert!(check.contains(&word.text(Lang::En)), "{word:?}: {check}");
    }
    assert!(check.contains(
        &ClapWords::Default {
            values: "text".into()
        }
        .text(Lang::En)
    ));
}

#[test]
fn the_portuguese_help_holds_none_of_clap_english() {
    let mut pt = command(Lang::Pt);
    let mut helps = vec![
        pt.render_help().to_string(),
        pt.render_long_help().to_string(),
    ];
    let names: Vec<String> = pt
        .get_subcommands()
        .map(|s| s.get_name().to_owned())
        .collect();
    for name in names {
        let sub = pt.find_subcommand_mut(&name).unwrap();
        helps.push(sub.render_help().to_string());
        helps.push(sub.render_long_help().to_string());
    }
    let english = [
        "Usage:",
        "Arguments:",
        "Options:",
        "Commands:",
        "Print help",
        "Print version",
        "Print this message",
        "[default:",
        "[possible values:",
        "Possible values:",
        "<COMMAND>",
    ];
    for help in &helps {
        for word in english {
            assert!(!help.contains(word), "{word:?} in:\n{help}");
        }
    }
}
