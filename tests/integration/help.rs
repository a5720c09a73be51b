//! The help of every command (`phong --help`, `phong CMD -h`, `phong help CMD`), pinned as
//! snapshots (`snapshots/help-en@*.snap`, `snapshots/help-pt@*.snap`), in English (clap's own
//! layout and words, the bytes phong printed before its help could be Portuguese) and in
//! Portuguese (under a Portuguese locale, or with `--lang pt`), where clap's own words are
//! Portuguese too.

use crate::support;

/// The commands, as `phong --help` lists them (`serve` with the default feature `serve`).
fn commands() -> Vec<&'static str> {
    let mut all = vec![
        "solve",
        "render",
        "schema",
        "export-pov",
        "check",
        "grade",
        "new",
        "moodle",
        "policy",
        "tradeoff",
    ];
    if cfg!(feature = "serve") {
        all.push("serve");
    }
    all
}

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

/// What `phong ARGS` prints on standard output, under the locale `LANG=lang`; it must succeed.
fn help(lang: &str, args: &[&str]) -> String {
    let out = support::phong()
        .env("LANG", lang)
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "phong {args:?}: {out:?}");
    assert!(out.stderr.is_empty(), "phong {args:?}: {out:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The help of the top level (`None`) or of a command, short (`-h`) and long (`--help`), each
/// pinned as `help-NAME@COMMAND-h` and `help-NAME@COMMAND--help`; `phong help [COMMAND]` is the
/// long help.
fn pinned(name: &str, lang: &str) {
    settings().bind(|| {
        let top: Option<&str> = None;
        for command in std::iter::once(top).chain(commands().into_iter().map(Some)) {
            // Without `serve`, the top level lists one command less than its snapshot.
            if command.is_none() && !cfg!(feature = "serve") {
                continue;
            }
            let base: Vec<&str> = command.into_iter().collect();
            let key = command.unwrap_or("phong");
            for flag in ["-h", "--help"] {
                let text = help(lang, &[&base[..], &[flag]].concat());
                insta::assert_snapshot!(format!("help-{name}@{key}{flag}"), text);
            }
            let long = help(lang, &[&base[..], &["--help"]].concat());
            assert_eq!(help(lang, &[&["help"], &base[..]].concat()), long, "{key}");
        }
    });
}

#[test]
fn every_help_in_english() {
    pinned("en", "C");
    // A locale of another language is English too.
    assert_eq!(
        help("es_ES.UTF-8", &["check", "-h"]),
        help("C", &["check", "-h"])
    );
}

#[test]
fn every_help_in_portuguese() {
    pinned("pt", "pt_BR.UTF-8");
    // `--lang pt` anywhere on the line chooses Portuguese too, as for usage errors.
    let pt = help("pt_BR.UTF-8", &["check", "--help"]);
    assert_eq!(help("C", &["check", "--help", "--lang", "pt"]), pt);
    assert_eq!(help("C", &["check", "--lang=pt", "--help"]), pt);
    assert_eq!(
        help("C", &["--help", "--lang", "pt"]),
        help("pt_BR.UTF-8", &["--help"])
    );
    // … and `--lang en` English under a Portuguese locale.
    assert_eq!(
        help("pt_BR.UTF-8", &["check", "-h", "--lang", "en"]),
        help("C", &["check", "-h"])
    );
}

#[test]
fn the_portuguese_help_says_clap_words_in_portuguese() {
    let top = help("pt_BR.UTF-8", &["--help"]);
    for said in [
        "Resolve e explica passo a passo os exercícios de iluminação do Capítulo 4",
        "\nUso: phong <COMANDO>\n",
        "\nComandos:\n",
        "\nOpções:\n",
        "  check       Confere uma resposta (ou o gabarito de cada arquivo)",
        "Mostra esta mensagem ou a ajuda do(s) subcomando(s) dado(s)",
        "  -h, --help     Mostra a ajuda\n",
        "  -V, --version  Mostra a versão\n",
    ] {
        assert!(top.contains(said), "{said:?} not in:\n{top}");
    }
    let short = help("pt_BR.UTF-8", &["check", "-h"]);
    let long = help("pt_BR.UTF-8", &["check", "--help"]);
    for text in [&short, &long] {
        for said in [
            "\nUso: phong check [OPTIONS] <FILE>...\n",
            "\nArgumentos:\n  <FILE>...",
            "\nOpções:\n",
            "Sem --answer, confere-se o gabarito de cada arquivo",
            "A maior diferença aceita por canal, na escala da resposta [padrão: a do gabarito",
        ] {
            assert!(text.contains(said), "{said:?} not in:\n{text}");
        }
    }
    // The positional arguments come first, as in English.
    assert!(long.find("Argumentos:") < long.find("Opções:"));
    assert!(short.contains(
        "markdown para notas [padrão: text] [valores possíveis: text, json, html, markdown]"
    ));
    assert!(short.contains("Mostra a ajuda (veja mais com '--help')"));
    assert!(long.contains("Mostra a ajuda (veja um resumo com '-h')"));
    assert!(long.contains(
        "Valores possíveis:\n          - text:     Texto para pessoas\n          - json:     \
         JSON para scripts"
    ));
    assert!(long.contains("\n          [padrão: text]\n"));
    for english in [
        "Usage:",
        "Arguments:",
        "Options:",
        "Commands:",
        "Print help",
        "Print version",
        "[default:",
        "[possible values:",
        "Possible values:",
        "Check an answer",
    ] {
        for text in [&top, &short, &long] {
            assert!(!text.contains(english), "{english:?} in:\n{text}");
        }
    }
}

/// `check --step`'s help names every step the check reads: the names an unknown step's error
/// lists (the secondary rays' `r_v`, `reflection_weight`, … among them, which the help left out
/// when it kept a list of its own), in both languages.
#[test]
fn the_step_help_names_every_step_the_check_reads() {
    let err = support::phong()
        .args(["check", "exercises/4.1.json", "--step", "nonsense=1"])
        .output()
        .unwrap();
    let err = String::from_utf8(err.stderr).unwrap();
    let list = err
        .split("use one of ")
        .nth(1)
        .and_then(|rest| rest.split(" (").next())
        .unwrap_or_else(|| panic!("no list of names in: {err}"));
    let names: Vec<&str> = list.split(", ").collect();
    assert!(names.contains(&"transmission_traced"), "{names:?}");
    for lang in ["en", "pt"] {
        let out = support::phong()
            .args(["check", "--help", "--lang", lang])
            .output()
            .unwrap();
        let help = String::from_utf8(out.stdout).unwrap();
        let listed = help
            .split(if lang == "en" { "Names: " } else { "Nomes: " })
            .nth(1)
            .and_then(|rest| rest.split(". ").next())
            .unwrap_or_else(|| panic!("no names in the help:\n{help}"));
        assert_eq!(listed.split(", ").collect::<Vec<_>>(), names, "{lang}");
    }
}
