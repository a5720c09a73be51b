//! The LaTeX explanation (`phong solve --format latex`): numbered steps with every formula in
//! math mode and the chapter's equation number at the right margin. By default a complete
//! document that pdflatex compiles (UTF-8 input, T1 fonts, so Portuguese accents work);
//! `--fragment` gives the body only, for `\input` into course notes whose preamble loads
//! `amsmath` and `xcolor`. It lays out an [`Explanation`].
//!
//! Every string that reaches the output, including a user's title, question and light names,
//! goes through `escape`: TeX's special characters are escaped, the Greek letters and math
//! signs of the sentences become math, and a character the T1 fonts lack is written as its
//! code point rather than breaking the build.

use super::explain::{latex_math, nest, runs, Explanation, Node, Run, Shading, Step};
use super::lang::Lang;
use super::messages::Phrase;

/// Escapes text for LaTeX (outside math).
pub(crate) fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        let math = |m: &str| format!("\\ensuremath{{{m}}}");
        let piece: String = match c {
            '\\' => "\\textbackslash{}".into(),
            '{' => "\\{".into(),
            '}' => "\\}".into(),
            '$' => "\\$".into(),
            '&' => "\\&".into(),
            '#' => "\\#".into(),
            '%' => "\\%".into(),
            '_' => "\\_".into(),
            '^' => "\\^{}".into(),
            '~' => "\\textasciitilde{}".into(),
            '<' => math("<"),
            '>' => math(">"),
            '|' => math("|"),
            'θ' => math("\\theta"),
            'φ' => math("\\phi"),
            'ψ' => math("\\psi"),
            'γ' => math("\\gamma"),
            'Σ' => math("\\Sigma"),
            '−' => math("-"),
            '·' => math("\\cdot"),
            '‖' => math("\\|"),
            '≤' => math("\\le"),
            '≥' => math("\\ge"),
            '≠' => math("\\ne"),
            '→' => math("\\rightarrow"),
            '×' => math("\\times"),
            '°' => math("^\\circ"),
            '²' => math("^2"),
            // Characters T1 and the UTF-8 input encoding cover: ASCII, Latin-1, Latin
            // Extended-A, and the usual dashes and quotes.
            c if (c.is_ascii() && !c.is_ascii_control())
                || ('\u{00A0}'..='\u{017F}').contains(&c)
                || matches!(c, '–' | '—' | '‘' | '’' | '“' | '”' | '…') =>
            {
                c.to_string()
            }
            '\n' | '\t' | '\r' => " ".into(),
            c if c.is_control() => String::new(),
            c => format!("\\texttt{{[U+{:04X}]}}", c as u32),
        };
        out.push_str(&piece);
    }
    out
}

/// How to write the LaTeX.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LatexOptions {
    /// The body only, without preamble and `\begin{document}`.
    pub fragment: bool,
}

/// A swatch of an 8-bit colour (xcolor).
fn swatch([r, g, b]: [u8; 3]) -> String {
    format!(
        "\\,\\fcolorbox{{black}}[RGB]{{{r},{g},{b}}}{{\\rule{{0pt}}{{0.8em}}\\hspace{{1.6em}}}}"
    )
}

fn line(step: &Step, lang: Lang) -> String {
    let mut s = String::new();
    for run in runs(&step.line) {
        match run {
            Run::Text(t) => s.push_str(&escape(&t)),
            Run::Math(m) => s.push_str(&format!("${}$", latex_math(&m))),
            Run::Swatch(rgb) => s.push_str(&swatch(rgb)),
        }
    }
    let mut s = s.split_whitespace().collect::<Vec<_>>().join(" ");
    if let Some(eq) = step.eq {
        let eq = escape(&eq.text(lang)).replace(". ", ".~");
        s.push_str(&format!("\\hfill\\mbox{{\\small {eq}}}"));
    }
    s
}

fn list(out: &mut String, nodes: &[Node], numbered: bool, lang: Lang, depth: usize) {
    if nodes.is_empty() {
        return;
    }
    let env = if numbered { "enumerate" } else { "itemize" };
    let pad = "  ".repeat(depth);
    out.push_str(&format!("{pad}\\begin{{{env}}}\n"));
    for node in nodes {
        out.push_str(&format!("{pad}  \\item{{}} {}\n", line(node.step, lang)));
        list(out, &node.children, numbered, lang, depth + 1);
    }
    out.push_str(&format!("{pad}\\end{{{env}}}\n"));
}

fn block(out: &mut String, heading: Phrase, steps: &[Step], numbered: bool, lang: Lang) {
    if steps.is_empty() {
        return;
    }
    out.push_str(&format!("\\paragraph{{{}}}\n", heading.get(lang)));
    list(out, &nest(steps), numbered, lang, 0);
}

fn shading(out: &mut String, sh: &Shading, lang: Lang) {
    block(out, Phrase::Given, &sh.given, false, lang);
    block(out, Phrase::Steps, &sh.steps, true, lang);
    block(out, Phrase::Total, &sh.total, false, lang);
}

/// The LaTeX body of one explanation: a `\section*` with its subsections.
pub(crate) fn write_body(x: &Explanation) -> String {
    let lang = x.lang;
    let mut out = String::new();
    out.push_str(&format!("\\section*{{{}}}\n", escape(&x.title)));
    out.push_str(&format!(
        "\\noindent\\emph{{{}, {}}}\n\n",
        escape(&x.file),
        x.precision
    ));
    if let Some(q) = &x.question {
        out.push_str(&format!(
            "\\begin{{quote}}\n{}\n\\end{{quote}}\n\n",
            escape(q)
        ));
    }
    if !x.findings.is_empty() {
        out.push_str(&format!(
            "\\subsection*{{{}}}\n\\begin{{itemize}}\n",
            Phrase::Findings.get(lang)
        ));
        for f in &x.findings {
            out.push_str(&format!("  \\item[\\textbf{{!}}] {}\n", escape(f)));
        }
        out.push_str("\\end{itemize}\n\n");
    }
    if let Some(ray) = &x.ray {
        out.push_str(&format!("\\subsection*{{{}}}\n", Phrase::Ray.get(lang)));
        list(&mut out, &nest(ray), false, lang, 0);
        out.push('\n');
    }
    for part in &x.parts {
        out.push_str(&format!("\\subsection*{{{}}}\n", escape(&part.heading)));
        if let Some(e) = &part.explanation {
            out.push_str(&format!("\\emph{{{}}}\n\n", escape(e)));
        }
        if let Some(ray) = &part.ray {
            list(&mut out, &nest(ray), false, lang, 0);
        }
        match &part.shading {
            Some(sh) => shading(&mut out, sh, lang),
            None => out.push_str(&format!("{}\n", escape(Phrase::NothingToShade.get(lang)))),
        }
        out.push('\n');
    }
    out
}

/// The LaTeX of several explanations: a complete document, or the bodies only.
pub fn write_all(xs: &[Explanation], options: LatexOptions) -> String {
    let body: String = xs
        .iter()
        .map(write_body)
        .collect::<Vec<_>>()
        .join("\n\\bigskip\n\n");
    if options.fragment {
        return format!(
            "% phong solve --format latex --fragment: needs \\usepackage{{amsmath,xcolor}}\n{body}"
        );
    }
    format!(
        "\\documentclass[11pt]{{article}}\n\
         \\usepackage[utf8]{{inputenc}}\n\
         \\usepackage[T1]{{fontenc}}\n\
         \\usepackage{{lmodern}}\n\
         \\usepackage{{amsmath}}\n\
         \\usepackage{{xcolor}}\n\
         \\usepackage[a4paper,margin=2cm]{{geometry}}\n\
         \\setlength{{\\parindent}}{{0pt}}\n\
         \\begin{{document}}\n\n\
         {body}\n\
         \\end{{document}}\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tex_special_characters_in_user_text_are_escaped() {
        assert_eq!(
            escape(r"50% of $x_1 & #2 {a} ~ ^ \ "),
            r"50\% of \$x\_1 \& \#2 \{a\} \textasciitilde{} \^{} \textbackslash{} "
        );
    }

    #[test]
    fn greek_letters_and_math_signs_become_math_and_accents_stay() {
        assert_eq!(
            escape("cos θ ≤ 0"),
            "cos \\ensuremath{\\theta} \\ensuremath{\\le} 0"
        );
        assert_eq!(escape("reflexão difusa"), "reflexão difusa");
    }

    #[test]
    fn a_character_the_fonts_lack_is_written_as_its_code_point() {
        assert_eq!(escape("光"), "\\texttt{[U+5149]}");
    }
}
