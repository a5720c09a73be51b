//! The exhaustive walk: every variant of every message enum, rendered in both languages and
//! checked (under test only; each enum derives `strum::EnumIter` there). A new enum declared
//! with `messages!` or `faults!` and left out of [`walked!`]'s list fails
//! `every_message_enum_is_walked`.

#![cfg(test)]

use strum::IntoEnumIterator;

use crate::text::{Fault, Lang, Message};

/// One rendering of a variant: its enum and variant, then the English and the Portuguese.
struct Rendered {
    name: String,
    en: String,
    pt: String,
}

fn sentences<T: Message + IntoEnumIterator>(enum_name: &str) -> Vec<Rendered> {
    T::iter()
        .map(|m| Rendered {
            name: format!("{enum_name}::{m:?}"),
            en: m.text(Lang::En),
            pt: m.text(Lang::Pt),
        })
        .collect()
}

fn faults<T: Fault + IntoEnumIterator>(enum_name: &str) -> Vec<Rendered> {
    T::iter()
        .flat_map(|f| {
            let name = format!("{enum_name}::{f:?}");
            [
                Rendered {
                    name: format!("{name} (what)"),
                    en: f.what(Lang::En),
                    pt: f.what(Lang::Pt),
                },
                Rendered {
                    name: format!("{name} (fix)"),
                    en: f.fix(Lang::En),
                    pt: f.fix(Lang::Pt),
                },
            ]
        })
        .collect()
}

/// Lists every message enum (`sentences` for `messages!`, `faults` for `faults!`), as the
/// renderings of all their variants and as the names the source test compares with.
macro_rules! walked {
    ($($(#[$cfg:meta])* $kind:ident $path:path;)*) => {
        fn every_rendering() -> Vec<Rendered> {
            let mut all = Vec::new();
            $($(#[$cfg])* all.extend($kind::<$path>(stringify!($path)));)*
            all
        }
        const WALKED: &[&str] = &[$(stringify!($path)),*];
    };
}

walked! {
    sentences crate::text::number::NotANumber;
    faults crate::problem::faults::TargetFault;
    faults crate::problem::faults::CameraFault;
    faults crate::problem::faults::SettingFault;
    faults crate::problem::faults::LightFault;
    faults crate::problem::faults::KindFault;
    faults crate::problem::faults::SurfaceFault;
    faults crate::problem::faults::MaterialFault;
    faults crate::problem::faults::ColourFault;
    faults crate::problem::faults::NumberFault;
    sentences crate::problem::faults::DirectionOf;
    sentences crate::problem::faults::PointOf;
    sentences crate::cli::parse::Whole;
    sentences crate::cli::parse::BadValue;
    faults crate::cli::faults::CliFault;
    sentences crate::cli::faults::CliText;
    sentences crate::cli::usage::UsageText;
    sentences crate::cli::usage::ClapReason;
    sentences crate::cli::help::CommonHelp;
    sentences crate::cli::help::ClapWords;
    sentences crate::cli::help::answers::AnswersHelp;
    sentences crate::cli::help::documents::DocumentsHelp;
    sentences crate::cli::help::trace::TraceHelp;
    #[cfg(feature = "serve")]
    sentences crate::cli::help::serve::ServeHelp;
    sentences crate::cli::help::values::ValueHelp;
    faults crate::tradeoff::sweep::SweepFault;
    sentences crate::tradeoff::messages::MetricName;
    sentences crate::tradeoff::messages::SettingName;
    sentences crate::tradeoff::messages::Column;
    sentences crate::tradeoff::messages::TradeoffText;
    sentences crate::tradeoff::messages::PlotText;
    sentences crate::export::pov::Colour;
    faults crate::export::pov::PovFault;
    faults crate::check::answer::AnswerFault;
    faults crate::check::steps::StepFault;
    faults crate::check::steps::StepMissing;
    sentences crate::check::CheckMessage;
    sentences crate::check::messages::Feedback;
    sentences crate::check::policy::PolicyError;
    sentences crate::check::messages::Credit;
    sentences crate::check::messages::PolicyUsed;
    sentences crate::check::messages::Page;
    sentences crate::check::messages::Encoding;
    sentences crate::check::export::xlsx::Sheet;
    sentences crate::check::export::class::ClassWords;
    sentences crate::check::Slip;
    sentences crate::problem::syntax::Found;
    sentences crate::problem::syntax::Expected;
    sentences crate::problem::syntax::JsonKind;
    sentences crate::problem::syntax::Parse;
    sentences crate::problem::syntax::Purpose;
    sentences crate::problem::syntax::SyntaxFix;
    sentences crate::problem::reading::Input;
    sentences crate::problem::reading::Counted;
    sentences crate::problem::reading::Limit;
    sentences crate::problem::reading::ReadFix;
    faults crate::problem::reading::ReadFault;
    faults crate::problem::reading::SourceFault;
    faults crate::problem::mesh_faults::MeshFault;
    faults crate::solve::faults::SolveFault;
    sentences crate::solve::faults::Overflowing;
    sentences crate::solve::faults::Smaller;
    sentences crate::solve::faults::Resolve;
    faults crate::tracer::faults::TracerFault;
    sentences crate::report::messages::F32Cost;
    sentences crate::report::messages::GateName;
    #[cfg(feature = "serve")]
    sentences crate::serve::faults::ApiText;
    #[cfg(feature = "serve")]
    sentences crate::serve::faults::Items;
    #[cfg(feature = "serve")]
    faults crate::serve::faults::TooMany;
    #[cfg(feature = "serve")]
    sentences crate::serve::faults::StartText;
    #[cfg(feature = "serve")]
    sentences crate::serve::faults::Shape;
    #[cfg(feature = "serve")]
    sentences crate::serve::log::LogMessage;
    sentences crate::check::grade::NotCsv;
    sentences crate::check::grade::FieldsHint;
    sentences crate::check::grade::RowReason;
    faults crate::check::grade::ExerciseFault;
    faults crate::check::grade::HeaderFault;
    sentences crate::check::grade::ExerciseNote;
    sentences crate::check::moodle::MoodleError;
    sentences crate::check::moodle::Blank;
}

/// English words that Portuguese never uses: one of them in a Portuguese rendering (outside
/// quotes and backticks, where a file's own field names stand) is an untranslated fragment.
/// ("no" is not one: Portuguese says "no ponto", "no máximo".)
const ENGLISH_ONLY: &[&str] = &[
    "the", "is", "are", "and", "not", "with", "give", "write", "must", "cannot", "Fix", "of",
    "which", "should", "an", "has", "have", "from", "to", "by", "it", "this", "that", "be", "or",
    "for", "only", "than", "when", "where", "there", "its", "was", "were",
];

/// `text` without what stands between quotes or backticks (a field's name, an example).
fn outside_quotes(text: &str) -> String {
    let mut out = String::new();
    let mut quote: Option<char> = None;
    for c in text.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if matches!(c, '"' | '`' | '“') => {
                quote = Some(if c == '“' { '”' } else { c })
            }
            None => out.push(c),
        }
    }
    out
}

#[test]
fn every_message_reads_in_both_languages() {
    let mut bad = Vec::new();
    for r in every_rendering() {
        if r.en.is_empty() != r.pt.is_empty() {
            bad.push(format!(
                "{}: one language is empty: {:?} / {:?}",
                r.name, r.en, r.pt
            ));
            continue;
        }
        let words = outside_quotes(&r.pt);
        let english: Vec<&str> = words
            .split(|c: char| !c.is_alphanumeric() && c != '\'')
            .filter(|w| ENGLISH_ONLY.contains(w))
            .collect();
        if !english.is_empty() {
            bad.push(format!(
                "{}: English in the Portuguese {:?}: {english:?}",
                r.name, r.pt
            ));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn every_message_enum_is_walked() {
    // Every `messages! {` and `faults! {` in src/, by the enum it declares.
    let mut declared = Vec::new();
    let mut stack = vec![std::path::PathBuf::from("src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            for (i, _) in text
                .match_indices("messages! {")
                .chain(text.match_indices("faults! {"))
            {
                // Skip the macros' own documentation examples and definitions.
                let line_start = text[..i].rfind('\n').map_or(0, |n| n + 1);
                let line = text[line_start..].lines().next().unwrap_or("");
                let head = line.trim_start().trim_start_matches("crate::");
                if !(head.starts_with("messages! {") || head.starts_with("faults! {")) {
                    continue;
                }
                let rest = &text[i..];
                let name = rest
                    .split("enum ")
                    .nth(1)
                    .and_then(|r| r.split(|c: char| !c.is_alphanumeric() && c != '_').next())
                    .unwrap_or("?")
                    .to_owned();
                declared.push((path.display().to_string(), name));
            }
        }
    }
    let missing: Vec<String> = declared
        .iter()
        .filter(|(_, name)| !WALKED.iter().any(|w| w.ends_with(&format!("::{name}"))))
        .map(|(file, name)| format!("{name} ({file})"))
        .collect();
    assert!(
        missing.is_empty(),
        "message enums missing from src/walk.rs's list: {missing:?}"
    );
    assert!(!declared.is_empty());
}
