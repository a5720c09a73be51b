//! The layers of the crate, checked (under test only): the top-level modules form a DAG in the
//! order of [`LAYERS`], lowest first; a module may use only the modules below it. What many
//! modules need sits low (the language, numbers and message values in `text`; the shading core
//! and the rules of secondary rays in `core`), never in the higher of two modules that both
//! need it. ARCHITECTURE.md ("Layers") draws the same order. Tests may reach across layers:
//! `#[cfg(test)]` modules are not read.

/// The top-level modules of `src/`, lowest first. Modules on one line do not use each other.
const LAYERS: &[&[&str]] = &[
    &["text"],
    &["core"],
    &["geometry"],
    &["problem"],
    &["solve"],
    &["tracer"],
    &["report"],
    &["check"],
    &["export", "generate", "tradeoff"],
    &["serve"],
    &["cli"],
];

/// The layer of a top-level module.
fn layer(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

/// `text` without its comments and its `#[cfg(test)]` items.
fn code_of(text: &str) -> String {
    let mut out = String::new();
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        let t = line.trim_start();
        if t.starts_with("//") {
            continue;
        }
        if t.starts_with("#[cfg(test)]") {
            // Skip the item that follows, up to its closing brace (or its `;`).
            let mut depth = 0i32;
            let mut opened = false;
            for next in lines.by_ref() {
                for c in next.chars() {
                    match c {
                        '{' => {
                            depth += 1;
                            opened = true;
                        }
                        '}' => depth -= 1,
                        _ => {}
                    }
                }
                if (opened && depth <= 0) || (!opened && next.trim_end().ends_with(';')) {
                    break;
                }
            }
            continue;
        }
        let code = line.split(" //").next().unwrap_or(line);
        out.push_str(code);
        out.push('\n');
    }
    out
}

/// The top-level modules `code` names through `crate::` (`crate::solve::x`, and each path of
/// `use crate::{problem::X, report}`).
fn uses(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // The first segment of each path at the group's top level.
            let mut depth = 0;
            let mut start = true;
            let mut word = String::new();
            for c in group.chars() {
                match c {
                    '{' => {
                        depth += 1;
                        start = false;
                    }
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => start = true,
                    c if start && (c.is_alphanumeric() || c == '_') => word.push(c),
                    c if start && !word.is_empty() && !c.is_whitespace() => {
                        found.push(std::mem::take(&mut word));
                        start = false;
                    }
                    c if start && !word.is_empty() && c.is_whitespace() => {
                        found.push(std::mem::take(&mut word));
                        start = false;
                    }
                    _ => {}
                }
            }
            if !word.is_empty() {
                found.push(word);
            }
        } else {
            let word: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            found.push(word);
        }
    }
    found
}

/// Every use of one top-level module by another: (user, used, file).
fn edges() -> Vec<(String, String, String)> {
    let mut out = Vec::new();
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
            let rel = path.strip_prefix("src").unwrap();
            let mut parts = rel.iter();
            let first = parts.next().unwrap().to_string_lossy().into_owned();
            if parts.next().is_none() {
                // src/lib.rs, src/main.rs, this file: the crate's root.
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            // A module compiled for tests only (`#![cfg(test)]`, or a `tests.rs`).
            if text.contains("#![cfg(test)]") || path.ends_with("tests.rs") {
                continue;
            }
            let code = code_of(&text);
            for used in uses(&code) {
                if used != first && layer(&used).is_some() {
                    out.push((first.clone(), used, path.display().to_string()));
                }
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

#[test]
fn every_top_level_module_has_a_layer() {
    for entry in std::fs::read_dir("src").unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            assert!(
                layer(&name).is_some(),
                "src/{name}/ is in no layer of LAYERS"
            );
        }
    }
}

#[test]
fn no_module_uses_one_above_it_or_beside_it() {
    let wrong: Vec<String> = edges()
        .into_iter()
        .filter(|(user, used, _)| layer(used) >= layer(user))
        .map(|(user, used, file)| format!("{user} uses {used} ({file})"))
        .collect();
    assert!(
        wrong.is_empty(),
        "uses against the layers (src/layers.rs, ARCHITECTURE.md \"Layers\"):\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_reader_sees_grouped_and_plain_paths_and_skips_tests() {
    let code = code_of(
        "use crate::{problem::X, report};\nuse crate::solve::y; // crate::cli\n\
         #[cfg(test)]\nmod tests {\n    use crate::tracer::T;\n}\nfn f() { crate::core::g(); }\n",
    );
    let mut u = uses(&code);
    u.sort();
    assert_eq!(u, ["core", "problem", "report", "solve"]);
}
