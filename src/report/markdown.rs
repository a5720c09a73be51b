//! The Markdown explanation (`phong solve --format markdown`): numbered steps, each formula with
//! its value in `$…$` math (GitHub, GitLab, Obsidian, Jupyter and pandoc render it) and the
//! chapter's equation number, ready to paste into notes. It lays out an [`Explanation`].

use super::explain::{latex_math, nest, runs, Explanation, Node, Run, Shading, Step};
use super::lang::Lang;
use super::messages::Phrase;

/// Escapes text so that Markdown shows it as written.
pub(crate) fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        if matches!(
            c,
            '\\' | '`' | '*' | '_' | '[' | ']' | '<' | '>' | '#' | '|' | '$' | '{' | '}' | '~'
        ) {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// A line of a step: words escaped, math in `$…$`.
fn line(step: &Step, lang: Lang) -> String {
    let mut s = String::new();
    for run in runs(&step.line) {
        match run {
            Run::Text(t) => s.push_str(&escape(&t)),
            Run::Math(m) => {
                s.push('$');
                s.push_str(&latex_math(&m));
                s.push('$');
            }
            Run::Swatch(_) => {}
        }
    }
    let mut s = s.split_whitespace().collect::<Vec<_>>().join(" ");
    if let Some(eq) = step.eq {
        s.push_str(&format!(" — *{}*", eq.text(lang)));
    }
    s
}

fn list(out: &mut String, nodes: &[Node], depth: usize, numbered: bool, lang: Lang) {
    for (i, node) in nodes.iter().enumerate() {
        let marker = if numbered {
            format!("{}.", i + 1)
        } else {
            "-".to_owned()
        };
        out.push_str(&format!(
            "{:indent$}{marker} {}\n",
            "",
            line(node.step, lang),
            indent = 4 * depth
        ));
        list(out, &node.children, depth + 1, numbered, lang);
    }
}

fn block(out: &mut String, heading: Phrase, steps: &[Step], numbered: bool, lang: Lang) {
    if steps.is_empty() {
        return;
    }
    out.push_str(&format!("**{}**\n\n", heading.get(lang)));
    list(out, &nest(steps), 0, numbered, lang);
    out.push('\n');
}

fn shading(out: &mut String, sh: &Shading, lang: Lang) {
    block(out, Phrase::Given, &sh.given, false, lang);
    block(out, Phrase::Steps, &sh.steps, true, lang);
    block(out, Phrase::Total, &sh.total, false, lang);
}

/// The Markdown of one explanation.
pub fn write_explanation(x: &Explanation) -> String {
    let lang = x.lang;
    let mut out = String::new();
    out.push_str(&format!("## {}\n\n", escape(&x.title)));
    out.push_str(&format!("*{}, {}*\n\n", escape(&x.file), x.precision));
    if let Some(q) = &x.question {
        out.push_str(&format!("> {}\n\n", escape(q)));
    }
    if !x.findings.is_empty() {
        out.push_str(&format!("### {}\n\n", Phrase::Findings.get(lang)));
        for f in &x.findings {
            out.push_str(&format!("- **!** {}\n", escape(f)));
        }
        out.push('\n');
    }
    if let Some(ray) = &x.ray {
        out.push_str(&format!("### {}\n\n", Phrase::Ray.get(lang)));
        list(&mut out, &nest(ray), 0, false, lang);
        out.push('\n');
    }
    for part in &x.parts {
        out.push_str(&format!("### {}\n\n", escape(&part.heading)));
        if let Some(e) = &part.explanation {
            out.push_str(&format!("*{}*\n\n", escape(e)));
        }
        if let Some(ray) = &part.ray {
            list(&mut out, &nest(ray), 0, false, lang);
            out.push('\n');
        }
        match &part.shading {
            Some(sh) => shading(&mut out, sh, lang),
            None => out.push_str(&format!("{}\n\n", escape(Phrase::NothingToShade.get(lang)))),
        }
    }
    out
}

/// The Markdown of several explanations, separated by rules.
pub fn write_all(xs: &[Explanation]) -> String {
    xs.iter()
        .map(write_explanation)
        .collect::<Vec<_>>()
        .join("---\n\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markdown_special_characters_are_escaped() {
        assert_eq!(
            escape("a_b *c* [d] $5 #1"),
            "a\\_b \\*c\\* \\[d\\] \\$5 \\#1"
        );
    }
}
