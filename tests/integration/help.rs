//! The help of every command (`phong --help`, `phong CMD -h`, `phong help CMD`), pinned as
//! snapshots (`snapshots/help-*.snap`): the English is clap's layout of the help texts, the
//! same bytes whatever the way it is asked for.

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
    let out = support::phong().env("LANG", lang).args(args).output().unwrap();
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
    assert_eq!(help("es_ES.UTF-8", &["check", "-h"]), help("C", &["check", "-h"]));
}
