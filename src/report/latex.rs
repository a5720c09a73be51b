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

use super::document::{exercise_word, Document};
use super::explain::{
    latex_math, nest, runs, DataRow, Explanation, Inline, Node, Run, Shading, Step,
};
use super::messages::Phrase;
use crate::text::lang::Lang;

/// A symbol with a subscript written in prose ("k_a", "P_l", "O_R"): a letter, `_`, letters
/// and digits, standing alone as a word. Its length in characters, if `chars[i..]` starts one.
fn subscripted(chars: &[char], i: usize) -> Option<usize> {
    let word = |c: &char| c.is_ascii_alphanumeric();
    if i > 0 && (word(&chars[i - 1]) || chars[i - 1] == '_') {
        return None;
    }
    if !((chars.get(i)?.is_ascii_alphabetic() || greek(*chars.get(i)?).is_some())
        && *chars.get(i + 1)? == '_')
    {
        return None;
    }
    let sub = chars[i + 2..].iter().take_while(|c| word(c)).count();
    let end = i + 2 + sub;
    (sub > 0 && chars.get(end).is_none_or(|c| !word(c) && *c != '_')).then_some(end - i)
}

/// The LaTeX of a Greek letter that may carry a subscript in prose (η_i, θ_i).
fn greek(c: char) -> Option<&'static str> {
    match c {
        'η' => Some("\\eta"),
        'θ' => Some("\\theta"),
        _ => None,
    }
}

/// Escapes text for LaTeX (outside math). Symbols with a subscript ("n_s") become math, and
/// so does a minus sign before a number ("-0.5", "−3/5"), so that prose and formulas share one
/// minus sign.
pub(crate) fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let chars: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if let Some(n) = subscripted(&chars, i) {
            let sub: String = chars[i + 2..i + n].iter().collect();
            let base = greek(chars[i]).map_or_else(|| chars[i].to_string(), str::to_owned);
            out.push_str(&format!("\\ensuremath{{{base}_{{{sub}}}}}"));
            i += n;
            continue;
        }
        let c = chars[i];
        let before_number = chars.get(i + 1).is_some_and(|d| d.is_ascii_digit())
            && (i == 0 || !chars[i - 1].is_alphanumeric());
        i += 1;
        if c == '-' && before_number {
            out.push_str("\\ensuremath{-}");
            continue;
        }
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
            'η' => math("\\eta"),
            '√' => math("\\surd"),
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

/// A line's pieces: words escaped, each run of math in `$…$`.
pub(crate) fn pieces(line: &[Inline]) -> String {
    let mut s = String::new();
    for run in runs(line) {
        match run {
            Run::Text(t) => s.push_str(&super::explain::keep_triples(&escape(&t), |g| {
                format!("\\mbox{{{g}}}")
            })),
            Run::Math(m) => s.push_str(&format!("${}$", latex_math(&m))),
            Run::Swatch(rgb) => s.push_str(&swatch(rgb)),
        }
    }
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn line(step: &Step, lang: Lang) -> String {
    let mut s = pieces(&step.line);
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

/// The sectioning command of a heading of `level` (1 for a document's title, `section*`).
pub(crate) fn sectioning(level: usize) -> &'static str {
    match level {
        0 | 1 => "section*",
        2 => "subsection*",
        3 => "subsubsection*",
        4 => "paragraph*",
        _ => "subparagraph*",
    }
}

/// The run-in heading of a block of steps ("Given", "Steps") under a heading of `level`:
/// `\paragraph` under a `\subsection*`, `\subparagraph` under a `\paragraph*`.
fn run_in(level: usize) -> &'static str {
    if level <= 3 {
        "paragraph"
    } else {
        "subparagraph"
    }
}

fn block(
    out: &mut String,
    heading: Phrase,
    steps: &[Step],
    numbered: bool,
    lang: Lang,
    level: usize,
) {
    if steps.is_empty() {
        return;
    }
    out.push_str(&format!("\\{}{{{}}}\n", run_in(level), heading.get(lang)));
    list(out, &nest(steps), numbered, lang, 0);
}

fn shading(out: &mut String, sh: &Shading, lang: Lang, level: usize) {
    block(out, Phrase::Given, &sh.given, false, lang, level);
    block(out, Phrase::Steps, &sh.steps, true, lang, level);
    block(out, Phrase::Total, &sh.total, false, lang, level);
    block(
        out,
        Phrase::SecondaryRays,
        &sh.secondary,
        false,
        lang,
        level,
    );
    for d in &sh.diagrams {
        out.push_str(&super::diagram::tikz(d, lang));
    }
}

/// The LaTeX body of one explanation: a `\section*` with its subsections.
pub(crate) fn write_body(x: &Explanation) -> String {
    body(x, &x.title)
}

fn body(x: &Explanation, heading: &str) -> String {
    let mut out = head(heading, &x.source(), x.question.as_deref());
    out.push_str(&write_parts(x, 2));
    out
}

/// The head of a document: its title (`\section*`), its source in italics, and its question
/// quoted.
pub(crate) fn head(title: &str, source: &str, question: Option<&str>) -> String {
    let mut out = format!("\\{}{{{}}}\n", sectioning(1), escape(title));
    out.push_str(&format!("\\noindent\\emph{{{}}}\n\n", escape(source)));
    if let Some(q) = question {
        out.push_str(&format!(
            "\\begin{{quote}}\\raggedright\n{}\n\\end{{quote}}\n\n",
            escape(q)
        ));
    }
    out
}

/// The findings, the ray and the parts of an explanation, without its title and question
/// (a pixel's rays share their scene's), their headings at `level` (2 under an explanation's
/// own title). Ragged right: a step with a long value breaks its line early instead of running
/// into the margin (the equation number stays at the right).
pub(crate) fn write_parts(x: &Explanation, level: usize) -> String {
    let lang = x.lang;
    let h = sectioning(level);
    let mut out = String::new();
    out.push_str("\\begingroup\\raggedright\n");
    if !x.findings.is_empty() {
        out.push_str(&format!(
            "\\{h}{{{}}}\n\\begin{{itemize}}\n",
            Phrase::Findings.get(lang)
        ));
        for f in &x.findings {
            out.push_str(&format!("  \\item[\\textbf{{!}}] {}\n", escape(f)));
        }
        out.push_str("\\end{itemize}\n\n");
    }
    if let Some(ray) = &x.ray {
        out.push_str(&format!("\\{h}{{{}}}\n", Phrase::Ray.get(lang)));
        list(&mut out, &nest(ray), false, lang, 0);
        out.push('\n');
    }
    for part in &x.parts {
        out.push_str(&format!("\\{h}{{{}}}\n", escape(&part.heading)));
        if let Some(e) = &part.explanation {
            out.push_str(&format!("\\emph{{{}}}\n\n", escape(e)));
        }
        if let Some(ray) = &part.ray {
            list(&mut out, &nest(ray), false, lang, 0);
        }
        match &part.shading {
            Some(sh) => shading(&mut out, sh, lang, level),
            None => out.push_str(&format!("{}\n", escape(Phrase::NothingToShade.get(lang)))),
        }
        out.push('\n');
    }
    out.push_str("\\par\\endgroup\n");
    out
}

/// The LaTeX of several explanations: a complete document, or the bodies only.
pub fn write_all(xs: &[Explanation], options: LatexOptions) -> String {
    let body: String = xs
        .iter()
        .map(write_body)
        .collect::<Vec<_>>()
        .join("\n\\bigskip\n\n");
    let lang = xs.first().map_or(Lang::En, |x| x.lang);
    wrap(&body, options, lang)
}

/// The body as a complete document (babel in the explanation's language, so that Portuguese
/// is hyphenated as Portuguese), or as a fragment with a comment naming the packages it needs.
pub(crate) fn wrap(body: &str, options: LatexOptions, lang: Lang) -> String {
    if options.fragment {
        return format!(
            "% phong solve --format latex --fragment: needs \\usepackage{{amsmath,xcolor,tikz}}\n{body}"
        );
    }
    let babel = match lang {
        Lang::En => "english",
        Lang::Pt => "brazilian",
    };
    format!(
        "\\documentclass[11pt]{{article}}\n\
         \\usepackage[utf8]{{inputenc}}\n\
         \\usepackage[T1]{{fontenc}}\n\
         \\usepackage[{babel}]{{babel}}\n\
         \\usepackage{{lmodern}}\n\
         \\usepackage{{amsmath}}\n\
         \\usepackage{{xcolor}}\n\
         \\usepackage{{tikz}}\n\
         \\usepackage[a4paper,margin=2cm]{{geometry}}\n\
         \\setlength{{\\parindent}}{{0pt}}\n\
         \\begin{{document}}\n\n\
         {body}\n\
         \\end{{document}}\n"
    )
}

/// The problem set's header: course, title, author and date, centred.
fn header(out: &mut String, doc: &Document) {
    let h = doc.header;
    if h.is_empty() {
        return;
    }
    out.push_str("\\begin{center}\n");
    if let Some(c) = &h.course {
        out.push_str(&format!("{{\\large\\scshape {}}}\\\\[0.4em]\n", escape(c)));
    }
    if let Some(t) = &h.title {
        out.push_str(&format!("{{\\LARGE\\bfseries {}}}\\\\[0.4em]\n", escape(t)));
    }
    if let Some(b) = h.byline() {
        out.push_str(&format!("{}\n", escape(&b)));
    }
    out.push_str("\\end{center}\n\n");
}

/// One exercise's statement: its numbered heading, the question, and its data as a table.
fn statement(out: &mut String, doc: &Document, i: usize) {
    let x = &doc.exercises[i];
    out.push_str(&format!("\\subsection*{{{}}}\n", escape(&doc.heading(i))));
    if let Some(q) = &x.question {
        out.push_str(&format!("{}\n\n", escape(q)));
    }
    out.push_str(&data_table(&x.data, doc.lang));
}

/// A problem's data as a table (nothing when there is none).
pub(crate) fn data_table(rows: &[DataRow], lang: Lang) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = String::from(
        "\\begin{center}\n\\begin{tabular}{@{}p{0.3\\linewidth}p{0.64\\linewidth}@{}}\n\\hline\n",
    );
    out.push_str(&format!(
        "\\textbf{{{}}} & \\textbf{{{}}} \\\\\n\\hline\n",
        Phrase::Quantity.get(lang),
        Phrase::Value.get(lang)
    ));
    for row in rows {
        out.push_str(&format!(
            "\\raggedright {} & \\raggedright {} \\tabularnewline\n",
            pieces(&row.what),
            pieces(&row.value)
        ));
    }
    out.push_str("\\hline\n\\end{tabular}\n\\end{center}\n\n");
    out
}

/// The answer key: one table, a row per exercise.
fn key(out: &mut String, doc: &Document) {
    let lang = doc.lang;
    out.push_str(&format!("\\section*{{{}}}\n", Phrase::AnswerKey.get(lang)));
    out.push_str(
        "\\begin{center}\n\\begin{tabular}{@{}p{0.25\\linewidth}p{0.7\\linewidth}@{}}\n\\hline\n",
    );
    out.push_str(&format!(
        "\\textbf{{{}}} & \\textbf{{{}}} \\\\\n\\hline\n",
        exercise_word(lang),
        Phrase::Answer.get(lang)
    ));
    for i in 0..doc.exercises.len() {
        let (written, readings) = doc.exercises[i].key();
        let mut cell = pieces(&written);
        for r in &readings {
            cell.push_str(&format!("\\newline {{\\small {}}}", pieces(r)));
        }
        out.push_str(&format!(
            "\\raggedright {} & \\raggedright {} \\tabularnewline\n",
            escape(&doc.heading(i)),
            cell
        ));
    }
    out.push_str("\\hline\n\\end{tabular}\n\\end{center}\n");
}

/// A document: the header, then the statements, the solutions or the key (or all three).
pub fn write_document(doc: &Document, options: LatexOptions) -> String {
    let mut out = String::new();
    header(&mut out, doc);
    if doc.contents.statements() {
        if doc.contents.solutions() {
            out.push_str(&format!(
                "\\section*{{{}}}\n",
                Phrase::Statements.get(doc.lang)
            ));
        }
        for i in 0..doc.exercises.len() {
            statement(&mut out, doc, i);
        }
    }
    if doc.contents.solutions() {
        if doc.contents.statements() {
            out.push_str("\\clearpage\n");
        }
        let bodies: Vec<String> = (0..doc.exercises.len())
            .map(|i| body(&doc.exercises[i], &doc.solution_heading(i)))
            .collect();
        out.push_str(&bodies.join("\n\\bigskip\n\n"));
    }
    if doc.contents.key() {
        if doc.contents.solutions() {
            out.push_str("\\clearpage\n");
        }
        key(&mut out, doc);
    }
    wrap(&out, options, doc.lang)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tex_special_characters_in_user_text_are_escaped() {
        assert_eq!(
            escape(r"50% of $x_1 & #2 {a} ~ ^ \ "),
            r"50\% of \$\ensuremath{x_{1}} \& \#2 \{a\} \textasciitilde{} \^{} \textbackslash{} "
        );
    }

    #[test]
    fn greek_letters_and_math_signs_become_math_and_accents_stay() {
        assert_eq!(
            escape("cos θ ≤ 0"),
            "cos \\ensuremath{\\theta} \\ensuremath{\\le} 0"
        );
        assert_eq!(escape("reflexão difusa"), "reflexão difusa");
        assert_eq!(
            escape("k_a = 1, O_R(8, 4, 6), t = -90, 8-bit"),
            "\\ensuremath{k_{a}} = 1, \\ensuremath{O_{R}}(8, 4, 6), t = \\ensuremath{-}90, 8-bit"
        );
        assert_eq!(escape("lights[0]_x"), "lights[0]\\_x");
    }

    #[test]
    fn a_character_the_fonts_lack_is_written_as_its_code_point() {
        assert_eq!(escape("光"), "\\texttt{[U+5149]}");
    }
}
