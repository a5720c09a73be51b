//! Every sentence of `phong check` and `phong grade`, in English and in Portuguese (the
//! chapter's own terms: luz ambiente, decaimento, normal, observador, raio). The JSON output
//! carries the English sentences next to stable codes; `--lang pt` changes the text only.

use super::matches::{matches, Layout, Match};
use super::{Against, Slip, VerdictKind};
use crate::solve::ReadingCode;
use crate::text::lang::Lang;
use crate::text::{Message, Num};

/// What a slip is, in a few words (its row of `slips!`, check/slips.rs).
pub fn slip(s: Slip, lang: Lang) -> &'static str {
    s.name(lang)
}

/// Several slips made together: "A, and B".
pub fn slips(list: &[Slip], lang: Lang) -> String {
    let and = match lang {
        Lang::En => "; and ",
        Lang::Pt => "; e ",
    };
    list.iter()
        .map(|s| slip(*s, lang))
        .collect::<Vec<_>>()
        .join(and)
}

/// The name of a reading, as every command gives it ([`crate::report::messages::reading_name`]).
pub fn reading(code: ReadingCode, lang: Lang) -> &'static str {
    crate::report::messages::reading_name(code, lang)
}

/// The verdict word, as shown in the text report.
pub fn verdict(kind: VerdictKind, accepted: bool, lang: Lang) -> &'static str {
    match (lang, kind, accepted) {
        (Lang::En, VerdictKind::Right, _) => "right",
        (Lang::En, VerdictKind::Reading, true) => "right by the likely intended reading",
        (Lang::En, VerdictKind::Reading, false) => "not accepted (--strict): a reading",
        (Lang::En, VerdictKind::Wrong, _) => "wrong",
        (Lang::Pt, VerdictKind::Right, _) => "certa",
        (Lang::Pt, VerdictKind::Reading, true) => "certa pela leitura provavelmente pretendida",
        (Lang::Pt, VerdictKind::Reading, false) => "não aceita (--strict): uma leitura",
        (Lang::Pt, VerdictKind::Wrong, _) => "errada",
    }
}

/// The verdict on an answer that cannot be judged (a bad file or a bad answer).
pub fn invalid(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "cannot be checked",
        Lang::Pt => "não pode ser verificada",
    }
}

/// Labels of the text report's lines.
pub enum Line {
    Answer,
    Expected,
    Difference,
    Tolerance,
    Closest,
    Credit,
}

pub fn line(l: Line, lang: Lang) -> &'static str {
    match (lang, l) {
        (Lang::En, Line::Answer) => "answer",
        (Lang::En, Line::Expected) => "expected",
        (Lang::En, Line::Difference) => "difference",
        (Lang::En, Line::Tolerance) => "tolerance",
        (Lang::Pt, Line::Answer) => "resposta",
        (Lang::Pt, Line::Expected) => "esperado",
        (Lang::Pt, Line::Difference) => "diferença",
        (Lang::Pt, Line::Tolerance) => "tolerância",
        (Lang::En, Line::Closest) => "closest",
        (Lang::Pt, Line::Closest) => "mais perto",
        (Lang::En, Line::Credit) => "credit",
        (Lang::Pt, Line::Credit) => "crédito",
    }
}

/// The answer "the ray hits nothing", as the text report shows it.
pub fn no_hit_answer(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "none (the ray hits nothing)",
        Lang::Pt => "nenhuma (o raio não atinge nada)",
    }
}

/// An answer "no hit" to a problem that has a colour.
pub fn has_colour(ray: bool, lang: Lang) -> &'static str {
    match (lang, ray) {
        (Lang::En, true) => "the problem as written: its ray hits a surface (t > 0), so there is a colour to give",
        (Lang::En, false) => "the problem as written: a point problem has no ray to miss; give its colour",
        (Lang::Pt, true) => "o problema como enunciado: o raio atinge uma superfície (t > 0), então há uma cor a dar",
        (Lang::Pt, false) => "o problema como enunciado: um problema de ponto não tem raio, então não há o que errar; dê a cor do ponto",
    }
}

/// What a nearest candidate is, how far the answer is from it, against the tolerance.
pub fn nearest(c: &super::Candidate, distance: f64, tolerance: f64, lang: Lang) -> String {
    use crate::text::number::num;
    let what = match (lang, c) {
        (Lang::En, super::Candidate::Written) => "the problem as written".to_owned(),
        (Lang::Pt, super::Candidate::Written) => "o problema como enunciado".to_owned(),
        (Lang::En, super::Candidate::Reading(r, true)) => {
            format!("the likely intended reading \"{}\"", reading(*r, lang))
        }
        (Lang::Pt, super::Candidate::Reading(r, true)) => {
            format!(
                "a leitura provavelmente pretendida \"{}\"",
                reading(*r, lang)
            )
        }
        (Lang::En, super::Candidate::Reading(r, false)) => {
            format!("the reading \"{}\"", reading(*r, lang))
        }
        (Lang::Pt, super::Candidate::Reading(r, false)) => {
            format!("a leitura \"{}\"", reading(*r, lang))
        }
        (
            _,
            super::Candidate::Slips {
                slips: list,
                intended,
            },
        ) => slips_made(list, intended, lang),
    };
    let near = super::near_miss(distance, tolerance);
    match (lang, near) {
        (Lang::En, true) => format!(
            "close to {what}: {} away at most per channel (tolerance ±{})",
            num(distance),
            num(tolerance)
        ),
        (Lang::En, false) => format!(
            "the nearest is {what}: {} away at most per channel (tolerance ±{})",
            num(distance),
            num(tolerance)
        ),
        (Lang::Pt, true) => format!(
            "perto {}: no máximo {} de diferença por canal (tolerância ±{})",
            de(&what),
            num(distance),
            num(tolerance)
        ),
        (Lang::Pt, false) => format!(
            "o mais perto é {what}: no máximo {} de diferença por canal (tolerância ±{})",
            num(distance),
            num(tolerance)
        ),
    }
}

/// "de" before a Portuguese noun phrase, contracted with its article as Portuguese requires
/// ("perto da leitura", "perto do problema"): "de a" is not written.
fn de(phrase: &str) -> String {
    for (article, contracted) in [
        ("os ", "dos "),
        ("as ", "das "),
        ("o ", "do "),
        ("a ", "da "),
    ] {
        if let Some(rest) = phrase.strip_prefix(article) {
            return format!("{contracted}{rest}");
        }
    }
    format!("de {phrase}")
}

/// What the expected colour is: the problem as written or a reading, clamped or not.
pub fn expected_source(reading: Option<ReadingCode>, against: Against, lang: Lang) -> String {
    let what = match (lang, reading) {
        (Lang::En, None) => "the problem as written".to_owned(),
        (Lang::Pt, None) => "o problema como enunciado".to_owned(),
        (Lang::En, Some(r)) => format!("the reading \"{}\"", self::reading(r, lang)),
        (Lang::Pt, Some(r)) => format!("a leitura \"{}\"", self::reading(r, lang)),
    };
    let how = match (lang, against) {
        (Lang::En, Against::Clamped) => "clamped to [0, 1]",
        (Lang::En, Against::Unclamped) => "unclamped (Eq. 4.16 as summed)",
        (Lang::Pt, Against::Clamped) => "com a cor limitada a [0, 1]",
        (Lang::Pt, Against::Unclamped) => "com a cor sem limite (a soma da Eq. 4.16)",
    };
    format!("{what}, {how}")
}

/// "per channel, on the 0–1 scale".
pub fn per_channel(scale: super::Scale, lang: Lang) -> &'static str {
    match (lang, scale) {
        (Lang::En, super::Scale::Unit) => "per channel, 0–1 scale",
        (Lang::En, super::Scale::Bits8) => "per channel, 0–255 scale",
        (Lang::Pt, super::Scale::Unit) => "por canal, escala 0–1",
        (Lang::Pt, super::Scale::Bits8) => "por canal, escala 0–255",
    }
}

crate::messages! {
    /// Feedback that depends on what the answer (or the step) given is: black where the ray
    /// hits nothing, the reversed ray's hit given as t.
    #[allow(missing_docs)]
    pub enum Feedback {
        /// Black (within the tolerance) as the colour of a problem whose ray, as written, hits
        /// nothing: black is what such a ray shows, not a colour of the point.
        Background =>
            "black is the background, the colour a ray that meets nothing shows: as written \
             the ray hits nothing (t > 0), so there is no colour to give, and the answer is \
             \"none\" (no hit)",
            "preto é o fundo, a cor vista por um raio que não encontra nada: como enunciado o \
             raio não atinge nada (t > 0), então não há cor a dar, e a resposta é \"nenhuma\" \
             (nenhuma interseção)";
        /// The file's own background colour (not black) given where the ray hits nothing.
        BackgroundColour { colour: String } =>
            "{colour} is the problem's background, the colour a ray that meets nothing shows: \
             as written the ray hits nothing (t > 0), so there is no colour to give, and the \
             answer is \"none\" (no hit)",
            "{colour} é o fundo do problema, a cor vista por um raio que não encontra nada: \
             como enunciado o raio não atinge nada (t > 0), então não há cor a dar, e a \
             resposta é \"nenhuma\" (nenhuma interseção)";
        /// A positive t that is the hit of the ray reversed (O − tD): along D that point is at
        /// −t, behind the ray's origin, so the value's sign is reversed.
        ReversedRayHit { given: Num, along: Num } =>
            "the hit of the ray reversed (O − tD, t > 0), which along D is at t = {along}, \
             behind the ray's origin: the sign of {given} is reversed",
            "a interseção do raio invertido (O − tD, t > 0), que ao longo de D está em \
             t = {along}, atrás da origem do raio: o sinal de {given} está trocado";
        /// A positive t given in the reading of the hit behind the origin, which is the ray
        /// reversed: its t is along −D, where the line's t along D is −t.
        ReversedRayReading { given: Num, along: Num } =>
            "in that reading the ray is reversed (O − tD): it meets the surface at t = {given} \
             along −D, which is t = {along} along D",
            "nessa leitura o raio é invertido (O − tD): ele encontra a superfície em \
             t = {given} ao longo de −D, que é t = {along} ao longo de D";
    }
}

/// What the background colour given as the answer means where the ray hits nothing.
pub(crate) fn background(colour: [f64; 3], lang: Lang) -> String {
    use crate::text::number::num;
    if colour == [0.0; 3] {
        Feedback::Background.text(lang)
    } else {
        let colour = format!(
            "({}, {}, {})",
            num(colour[0]),
            num(colour[1]),
            num(colour[2])
        );
        Feedback::BackgroundColour { colour }.text(lang)
    }
}

/// The problem as written has no colour (its ray hits nothing).
pub fn nothing_to_shade(lang: Lang) -> &'static str {
    match lang {
        Lang::En => {
            "as written, the problem has no colour: its ray hits nothing (t > 0), and the answer \
             is \"none\""
        }
        Lang::Pt => {
            "como enunciado, o problema não tem cor: o raio não atinge nada (t > 0), e a \
             resposta é \"nenhuma\""
        }
    }
}

/// A reading was matched (for a wrong answer: one not likely intended).
pub fn matches_reading(code: ReadingCode, likely: bool, lang: Lang) -> String {
    let name = reading(code, lang);
    match (lang, likely) {
        (Lang::En, true) => {
            format!("it matches the likely intended reading \"{name}\", not the problem as written")
        }
        (Lang::En, false) => {
            format!("it matches the reading \"{name}\", which is not the problem as written")
        }
        (Lang::Pt, true) => format!(
            "confere com a leitura provavelmente pretendida \"{name}\", não com o problema \
             como enunciado"
        ),
        (Lang::Pt, false) => {
            format!("confere com a leitura \"{name}\", que não é o problema como enunciado")
        }
    }
}

/// The label of the line with the problem as written's colour.
pub fn as_written(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "as written",
        Lang::Pt => "enunciado",
    }
}

/// The words before the problem as written's colour in a sentence ("as written: (0, 0, 0)",
/// "como enunciado: (0, 0, 0)"); [`as_written`] is the text report's column label.
pub(crate) fn as_written_phrase(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "as written",
        Lang::Pt => "como enunciado",
    }
}

/// Introduces the slips an answer matches.
pub fn diagnosis_intro(pairs: bool, lang: Lang) -> &'static str {
    match (lang, pairs) {
        (Lang::En, false) => "it matches what these slips give:",
        (Lang::En, true) => "no single slip gives it; these pairs of slips do:",
        (Lang::Pt, false) => "confere com o resultado destes erros:",
        (Lang::Pt, true) => "nenhum erro sozinho dá esse valor; estes pares de erros dão:",
    }
}

/// A slip made within the likely intended reading of the problem.
pub fn in_intended_reading(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "in the likely intended reading",
        Lang::Pt => "na leitura provavelmente pretendida",
    }
}

/// The slips of a diagnosis or a candidate in words: the mistakes among `list` (those of the
/// likely intended reading, `intended`, are not mistakes), said to be made in that reading when
/// it has any.
pub(crate) fn slips_made(list: &[Slip], intended: &[Slip], lang: Lang) -> String {
    let mistakes: Vec<Slip> = (list.iter().copied())
        .filter(|s| !intended.contains(s))
        .collect();
    let said = slips(if mistakes.is_empty() { list } else { &mistakes }, lang);
    if intended.is_empty() {
        said
    } else {
        format!("{said} ({})", in_intended_reading(lang))
    }
}

/// No slip explains a wrong answer.
pub fn no_diagnosis(lang: Lang) -> &'static str {
    match lang {
        Lang::En => {
            "no classic slip (nor pair of slips) gives it: compare your steps with `phong solve`"
        }
        Lang::Pt => {
            "nenhum erro clássico (nem par de erros) dá esse valor: compare seus passos com \
             `phong solve`"
        }
    }
}

/// An answer accepted because it matches the colour before clamping.
pub fn unclamped_note(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "accepted as the colour before clamping; displayed, it is clamped to [0, 1]",
        Lang::Pt => "aceita como a cor antes de limitar; na tela ela é limitada a [0, 1]",
    }
}

/// A 0–1 answer whose numbers look like 8-bit values.
pub fn looks_8bit(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "the numbers look like 8-bit values: did you mean --scale 255?",
        Lang::Pt => "os números parecem valores de 8 bits: quis dizer --scale 255?",
    }
}

/// The one-sentence message of a verdict, in English, for the JSON output.
pub fn summary(kind: VerdictKind, accepted: bool, reading: Option<ReadingCode>) -> String {
    match (kind, reading) {
        (VerdictKind::Right, _) => "the answer is right".into(),
        (VerdictKind::Reading, Some(r)) => format!(
            "the answer matches the likely intended reading \"{}\", not the problem as written{}",
            self::reading(r, Lang::En),
            if accepted { "; accepted" } else { "; not accepted under --strict" }
        ),
        (_, Some(r)) => format!(
            "the answer is wrong; it matches the reading \"{}\", which is not the problem as written",
            self::reading(r, Lang::En)
        ),
        _ => "the answer is wrong".into(),
    }
}

/// The heading of a file's steps.
pub fn steps_heading(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "steps",
        Lang::Pt => "passos",
    }
}

/// A step's verdict word.
pub fn step_verdict(v: super::steps::StepVerdict, lang: Lang) -> &'static str {
    use super::steps::StepVerdict as V;
    match (lang, v) {
        (Lang::En, V::Right) => "right",
        (Lang::En, V::Reading) => "wrong as written, right in the likely intended reading",
        (Lang::En, V::Wrong) => "wrong",
        (Lang::Pt, V::Right) => "certo",
        (Lang::Pt, V::Reading) => {
            "errado como enunciado, certo na leitura provavelmente pretendida"
        }
        (Lang::Pt, V::Wrong) => "errado",
    }
}

/// Why the problem as written has no such step, as a clause after "as written" ("como
/// enunciado"): the ray hits nothing (4.3), or, for a light's specular steps, why that light
/// adds no specular term (4.2: the light is behind the surface). Each reason the solver can
/// give has its own words, so that a point problem is never told of a ray.
pub fn step_absent_because(why: super::steps::Absence, lang: Lang) -> &'static str {
    use super::steps::Absence as A;
    use crate::core::{LightStatus as L, SpecularStatus as S};
    match (lang, why) {
        (Lang::En, A::NoHit) => "the ray hits nothing",
        (Lang::Pt, A::NoHit) => "o raio não atinge nada",
        (Lang::En, A::Light(L::BehindSurface)) => {
            "the light is behind the surface (cos θ < 0) and adds no specular term"
        }
        (Lang::Pt, A::Light(L::BehindSurface)) => {
            "a fonte de luz está atrás da superfície (cos θ < 0) e não contribui com reflexão \
             especular"
        }
        (Lang::En, A::Light(L::InTangentPlane)) => {
            "the light is in the tangent plane (cos θ = 0) and adds no specular term"
        }
        (Lang::Pt, A::Light(L::InTangentPlane)) => {
            "a fonte de luz está no plano tangente (cos θ = 0) e não contribui com reflexão \
             especular"
        }
        (Lang::En, A::Light(L::OutsideCone)) => {
            "the point is outside the spot's cone (ψ > γ), so the light adds no specular term"
        }
        (Lang::Pt, A::Light(L::OutsideCone)) => {
            "o ponto está fora do cone do spot (ψ > γ), então a fonte de luz não contribui com \
             reflexão especular"
        }
        (Lang::En, A::Light(L::AtLight)) => {
            "the point is at the light, so the light adds no specular term"
        }
        (Lang::Pt, A::Light(L::AtLight)) => {
            "o ponto está na posição da fonte de luz, que não contribui com reflexão especular"
        }
        (Lang::En, A::Light(L::InShadow)) => {
            "the point is in shadow, so the light adds no specular term"
        }
        (Lang::Pt, A::Light(L::InShadow)) => {
            "o ponto está na sombra, então a fonte de luz não contribui com reflexão especular"
        }
        (Lang::En, A::Specular(S::AwayFromViewer)) => {
            "R points away from the viewer (cos φ ≤ 0), so the light adds no specular term"
        }
        (Lang::Pt, A::Specular(S::AwayFromViewer)) => {
            "R aponta para longe do observador (cos φ ≤ 0), então a fonte de luz não contribui \
             com reflexão especular"
        }
        (Lang::En, A::Specular(S::NoViewer)) => "there is no viewer, so cos φ cannot be computed",
        (Lang::Pt, A::Specular(S::NoViewer)) => {
            "não há observador, então cos φ não pode ser calculado"
        }
        (Lang::En, A::Specular(S::NoSpecularColor)) => "the material has no specular colour O_s",
        (Lang::Pt, A::Specular(S::NoSpecularColor)) => {
            "o material não tem cor de reflexão especular O_s"
        }
        // A light that lights the point and a specular term that is lit have every step:
        // kept for completeness, in words that assume nothing.
        (Lang::En, A::Light(L::Lit) | A::Specular(S::Lit | S::LightNotLit) | A::Other) => {
            "the problem has no such quantity"
        }
        (Lang::Pt, A::Light(L::Lit) | A::Specular(S::Lit | S::LightNotLit) | A::Other) => {
            "o problema não tem essa grandeza"
        }
    }
}

/// A step of the likely intended reading of a problem that, as written, has no such quantity
/// (`why`: the ray hits nothing, the light does not light the point…).
pub fn step_no_hit(code: ReadingCode, why: super::steps::Absence, lang: Lang) -> String {
    match lang {
        Lang::En => format!(
            "as the likely intended reading \"{}\" has it; as written {}, so there is no such \
             step",
            reading(code, lang),
            step_absent_because(why, lang)
        ),
        Lang::Pt => format!(
            "como na leitura provavelmente pretendida \"{}\"; como enunciado {}, então não há \
             esse passo",
            reading(code, lang),
            step_absent_because(why, lang)
        ),
    }
}

/// What the step's value is (as written, or in the likely intended reading when the problem as
/// written has none, `why` saying why it has none).
pub fn step_exact(
    exact: &str,
    from: Option<(ReadingCode, super::steps::Absence)>,
    lang: Lang,
) -> String {
    match (lang, from) {
        (Lang::En, None) => format!("the problem as written gives {exact}"),
        (Lang::Pt, None) => format!("o problema como enunciado dá {exact}"),
        (Lang::En, Some((c, why))) => format!(
            "the likely intended reading \"{}\" gives {exact} (as written {})",
            reading(c, lang),
            step_absent_because(why, lang)
        ),
        (Lang::Pt, Some((c, why))) => format!(
            "a leitura provavelmente pretendida \"{}\" dá {exact} (como enunciado {})",
            reading(c, lang),
            step_absent_because(why, lang)
        ),
    }
}

/// A step wrong as written whose value is the likely intended reading's.
pub fn step_reading(code: ReadingCode, lang: Lang) -> String {
    match lang {
        Lang::En => format!(
            "yours is the value of the likely intended reading \"{}\"",
            reading(code, lang)
        ),
        Lang::Pt => format!(
            "o seu é o valor da leitura provavelmente pretendida \"{}\"",
            reading(code, lang)
        ),
    }
}

/// The given value is the expected one with its sign reversed.
pub fn step_sign(vector: bool, lang: Lang) -> &'static str {
    match (lang, vector) {
        (Lang::En, false) => " (the sign differs)",
        (Lang::En, true) => " (the vector is reversed: every sign differs)",
        (Lang::Pt, false) => " (o sinal é outro)",
        (Lang::Pt, true) => " (o vetor está invertido: todos os sinais trocados)",
    }
}

/// The given value is the ungated one.
pub fn step_literal(lang: Lang) -> &'static str {
    match lang {
        Lang::En => {
            "yours is the value without gating (a light behind the surface, cos θ ≤ 0, or \
             cos φ ≤ 0, adds nothing)"
        }
        Lang::Pt => {
            "o seu é o valor sem o limite (uma luz atrás da superfície, cos θ ≤ 0, ou \
             cos φ ≤ 0, não contribui)"
        }
    }
}

/// The given value is that of a reading other than the likely intended one.
pub fn step_other_reading(code: ReadingCode, lang: Lang) -> String {
    match lang {
        Lang::En => format!("it is the value of the reading \"{}\"", reading(code, lang)),
        Lang::Pt => format!("é o valor da leitura \"{}\"", reading(code, lang)),
    }
}

/// The given value is what these slips give (each said as [`super::steps`] says it of the
/// value: its name, or what it means for that value).
pub fn step_slips(each: &[String], lang: Lang) -> String {
    match lang {
        Lang::En => format!("it is what this slip gives: {}", each.join("; or ")),
        Lang::Pt => format!("é o que este erro dá: {}", each.join("; ou ")),
    }
}

/// The first wrong step, with its equation.
pub fn first_wrong(label: &str, eq: &str, reading_only: bool, lang: Lang) -> String {
    match (lang, reading_only) {
        (Lang::En, false) => format!("first wrong step: {label} ({eq})"),
        (Lang::En, true) => format!(
            "first wrong step as written: {label} ({eq}); from there on you follow the likely \
             intended reading"
        ),
        (Lang::Pt, false) => format!("primeiro passo errado: {label} ({eq})"),
        (Lang::Pt, true) => format!(
            "primeiro passo errado como enunciado: {label} ({eq}); dali em diante você segue a \
             leitura provavelmente pretendida"
        ),
    }
}

/// Every step right.
pub fn all_steps_right(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "every step given is right",
        Lang::Pt => "todos os passos dados estão certos",
    }
}

/// One step of a row in `phong grade`'s feedback: "Step cos_theta\[0\] = 0.98995: right (…)".
pub(crate) fn step_sentence(label: &str, value: &str, message: &str, lang: Lang) -> String {
    match lang {
        Lang::En => format!("Step {label} = {value}: {message}"),
        Lang::Pt => format!("Passo {label} = {value}: {message}"),
    }
}

/// The line `phong grade` ends with on standard error: how many rows, and of each verdict.
pub(crate) fn graded(
    rows: usize,
    right: usize,
    reading: usize,
    wrong: usize,
    invalid: usize,
    lang: Lang,
) -> String {
    // One row, one verdict: the singular (Portuguese agrees the adjective too).
    let one = |n: usize, singular: &'static str, plural: &'static str| {
        if n == 1 {
            singular
        } else {
            plural
        }
    };
    match lang {
        Lang::En => format!(
            "graded {rows} {}: {right} right, {reading} by the likely intended reading, \
             {wrong} wrong, {invalid} invalid",
            one(rows, "row", "rows")
        ),
        Lang::Pt => format!(
            "{rows} {}: {right} {}, {reading} pela leitura provavelmente pretendida, \
             {wrong} {}, {invalid} {}",
            one(rows, "linha avaliada", "linhas avaliadas"),
            one(right, "certa", "certas"),
            one(wrong, "errada", "erradas"),
            one(invalid, "inválida", "inválidas"),
        ),
    }
}

/// The tolerance of steps.
pub fn step_tolerance(relative: f64, absolute: f64, lang: Lang) -> String {
    use crate::text::number::num;
    let pct = num(relative * 100.0);
    match lang {
        Lang::En => format!(
            "tolerance: {pct} % of the value's size or ±{}, whichever is larger (hand calculation)",
            num(absolute)
        ),
        Lang::Pt => format!(
            "tolerância: {pct} % do tamanho do valor ou ±{}, o que for maior (cálculo à mão)",
            num(absolute)
        ),
    }
}

/// What `phong grade` knows about a row when it writes its feedback.
pub(crate) struct RowFacts<'a> {
    /// The verdict, `None` for a row that cannot be judged.
    pub verdict: Option<&'a super::Verdict>,
    /// Why the row cannot be judged, said in the feedback's language.
    pub reason: Option<&'a dyn crate::text::Message>,
    /// The tolerance the answer was judged with.
    pub tolerance: f64,
    /// A whole-number triple on the 0–1 scale read as 8-bit values.
    pub read_as_8bit: bool,
    /// The points earned and the exercise's points.
    pub points: Option<(f64, f64)>,
}

/// One sentence of feedback for a graded row: the verdict, what the answer matches (a reading,
/// the slips in words), how near it is to the nearest colour, the points.
pub(crate) fn feedback(f: &RowFacts, lang: Lang) -> String {
    let mut parts: Vec<String> = Vec::new();
    match f.verdict {
        None => {
            parts.push(invalid(lang).to_owned());
            if let Some(r) = f.reason {
                parts.push(r.text(lang));
            }
        }
        Some(v) => {
            parts.push(verdict(v.kind, v.accepted, lang).to_owned());
            if f.read_as_8bit {
                parts.push(read_as_8bit(lang).to_owned());
            }
            let clauses = matches(v, f.tolerance, Layout::Sentence)
                .into_iter()
                .map(|m| match m {
                    Match::HasColour { ray } => has_colour(ray, lang).to_owned(),
                    Match::NothingToShade | Match::NothingAsWritten => {
                        nothing_to_shade(lang).to_owned()
                    }
                    Match::Reading { reading, likely } => {
                        matches_reading(reading.code, likely, lang)
                    }
                    Match::AsWritten(w) => format!(
                        "{}: {}",
                        as_written_phrase(lang),
                        super::report::triple(w.expected, crate::text::number::num)
                    ),
                    Match::Background(colour) => background(colour, lang),
                    // The slips in one clause: "… gives it: A or B".
                    Match::Slips { diagnoses, pairs } => {
                        let or = match lang {
                            Lang::En => " or ",
                            Lang::Pt => " ou ",
                        };
                        let each: Vec<String> = (diagnoses.iter())
                            .map(|d| slips_made(&d.slips, &d.intended, lang))
                            .collect();
                        format!("{} {}", diagnosis_intro(pairs, lang), each.join(or))
                    }
                    Match::NoDiagnosis => no_diagnosis(lang).to_owned(),
                    Match::Looks8bit => looks_8bit(lang).to_owned(),
                    Match::Nearest(n) | Match::NearMiss(n) => {
                        nearest(&n.candidate, n.comparison.distance(), f.tolerance, lang)
                    }
                    Match::Unclamped => unclamped_note(lang).to_owned(),
                });
            parts.extend(clauses);
        }
    }
    if let Some((p, max)) = f.points {
        parts.push(total(p, max, lang));
    }
    let mut text = parts.join("; ");
    if let Some(first) = text.chars().next() {
        text.replace_range(..first.len_utf8(), &first.to_uppercase().to_string());
    }
    text.push('.');
    text
}

/// A whole-number answer on the 0–1 scale that `phong grade` read as 8-bit values.
pub(crate) fn read_as_8bit(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "read as 8-bit values (0–255): the numbers are whole and one is above 1",
        Lang::Pt => "lida como valores de 8 bits (0–255): os números são inteiros e um passa de 1",
    }
}

/// A row that does not count: another answer of the student's to the exercise does, the one
/// on `line` of the file (`row` among the data rows, the report's row column).
pub(crate) fn not_counted(row: usize, line: u64, rule: &str, lang: Lang) -> String {
    match lang {
        Lang::En => format!(
            "Not counted: the same student answered this exercise again, and the answer on line \
             {line} counts (row {row}; --duplicates {rule}). "
        ),
        Lang::Pt => format!(
            "Não conta: o mesmo aluno respondeu de novo a este exercício, e conta a resposta da \
             linha {line} (coluna row do relatório: {row}; --duplicates {rule}). "
        ),
    }
}

/// A row without a student's name: it counts for nobody.
pub(crate) fn no_student(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "Not counted: the row has no student. ",
        Lang::Pt => "Não conta: a linha não tem aluno. ",
    }
}

/// An exercise a student did not answer.
pub(crate) fn no_answer(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "No answer.",
        Lang::Pt => "Sem resposta.",
    }
}

/// The name of an exercise in a platform's list of tests.
pub(crate) fn exercise_name(exercise: &str, lang: Lang) -> String {
    match lang {
        Lang::En => format!("Exercise {exercise}"),
        Lang::Pt => format!("Exercício {exercise}"),
    }
}

/// A student's total, in words.
pub(crate) fn total(points: f64, max: f64, lang: Lang) -> String {
    use crate::text::number::num;
    let one = max == 1.0;
    match (lang, one) {
        (Lang::En, true) => format!("{} of {} point", num(points), num(max)),
        (Lang::En, false) => format!("{} of {} points", num(points), num(max)),
        (Lang::Pt, true) => format!("{} de {} ponto", num(points), num(max)),
        (Lang::Pt, false) => format!("{} de {} pontos", num(points), num(max)),
    }
}

#[cfg(test)]
mod tests {
    use super::de;

    #[test]
    fn de_is_contracted_with_the_article_as_portuguese_writes_it() {
        assert_eq!(
            de("a leitura provavelmente pretendida"),
            "da leitura provavelmente pretendida"
        );
        assert_eq!(
            de("o problema como enunciado"),
            "do problema como enunciado"
        );
        assert_eq!(de("os erros"), "dos erros");
        assert_eq!(de("as cores"), "das cores");
        assert_eq!(de("erro de sinal"), "de erro de sinal");
    }
}

crate::messages! {
    /// What a verdict earns under the course policy, and which policy that is.
    #[allow(missing_docs)]
    pub enum Credit {
        /// By the policy of a file.
        InFile { percent: crate::text::Num, file: std::path::PathBuf } =>
            "{percent}% of the exercise's points in this course (the course policy: {file})",
            "{percent}% dos pontos do exercício neste curso (política do curso: {file})";
        /// By the default policy.
        Default { percent: crate::text::Num } =>
            "{percent}% of the exercise's points (phong's default course policy)",
            "{percent}% dos pontos do exercício (a política padrão do phong)";
    }
}

impl Credit {
    /// The credit `share` (0 to 1) by the policy of `file` (`None`: the default).
    pub(crate) fn of(share: f64, file: Option<&std::path::Path>) -> Credit {
        let percent = crate::text::Num(share * 100.0);
        match file {
            Some(f) => Credit::InFile {
                percent,
                file: f.to_owned(),
            },
            None => Credit::Default { percent },
        }
    }
}

crate::messages! {
    /// Which course policy a command judged by, said once on standard error.
    #[allow(missing_docs)]
    pub enum PolicyUsed {
        /// A file's.
        File { file: std::path::PathBuf } =>
            "judged by the course policy in {file}",
            "julgado pela política do curso em {file}";
        /// The defaults: no file in the folder.
        Default { folder: std::path::PathBuf } =>
            "judged by phong's default course policy (there is no course-policy.json in \
             {folder}; `phong policy` shows it)",
            "julgado pela política padrão do phong (não há course-policy.json em {folder}; \
             `phong policy` a mostra)";
    }
}

crate::messages! {
    /// The words of the verdict as a page (`phong check --format html` and `markdown`, and the
    /// web checker's verdict).
    #[allow(missing_docs)]
    pub enum Page {
        Verdict => "Verdict", "Veredito";
        YourAnswer => "Your answer", "Sua resposta";
        Expected => "Expected", "Esperado";
        Channel => "Channel", "Canal";
        Judged => "Verdict", "Veredito";
        Within => "within the tolerance", "dentro da tolerância";
        Outside => "outside the tolerance", "fora da tolerância";
        /// The caption of the table of channels.
        ChannelsCaption { tolerance: crate::text::Num, scale: String } =>
            "Each channel against the tolerance ±{tolerance} ({scale})",
            "Cada canal contra a tolerância ±{tolerance} ({scale})";
        /// The heading of what is said beside the verdict: the readings and slips the answer
        /// matches, or that none does, the nearest colour, notes on its scale.
        AboutTheAnswer => "About the answer:", "Sobre a resposta:";
        /// A link to the step of the solution where a slip departs.
        SeeStep { reference: String } =>
            "see the step ({reference}) in the solution",
            "veja o passo ({reference}) na solução";
        SeeSolution => "see it in the solution", "veja na solução";
        Quantity => "Quantity", "Grandeza";
        YourValue => "Your value", "Seu valor";
        FirstWrong => "the first wrong step", "o primeiro passo errado";
        CannotCheck => "This could not be checked", "Não foi possível verificar";
        WorkedSolution => "Worked solution", "Solução comentada";
    }
}

crate::messages! {
    /// What `phong grade` says of the submissions' encoding, once, on standard error.
    #[allow(missing_docs)]
    pub enum Encoding {
        /// Not UTF-8 and no byte order mark: read as Windows-1252.
        Windows1252 =>
            "the file is not UTF-8: it was read as Windows-1252 (Latin-1), the \"CSV\" of Excel \
             in Brazil, so accented names come through; to avoid this, save as \"CSV UTF-8\"",
            "o arquivo não é UTF-8: foi lido como Windows-1252 (Latin-1), o \"CSV\" do Excel \
             no Brasil, então os nomes acentuados chegam inteiros; para evitar isto, salve como \
             \"CSV UTF-8\"";
    }
}
