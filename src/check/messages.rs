//! Every sentence of `phong check` and `phong grade`, in English and in Portuguese (the
//! chapter's own terms: luz ambiente, decaimento, normal, observador, raio). The JSON output
//! carries the English sentences next to stable codes; `--lang pt` changes the text only.

use super::{Against, Slip, VerdictKind};
use crate::report::lang::Lang;
use crate::solve::ReadingCode;

/// What a slip is, in a few words.
pub fn slip(s: Slip, lang: Lang) -> &'static str {
    match lang {
        Lang::En => match s {
            Slip::HitBehindOrigin => "the intersection taken behind the ray's origin (t < 0)",
            Slip::LightReversed => {
                "L reversed: taken from the point to the light, the opposite of Eq. 4.1"
            }
            Slip::ViewerReversed => {
                "V reversed: taken from the point to the eye, the opposite of Eq. 4.10"
            }
            Slip::NormalReversed => "the normal reversed",
            Slip::AbsCosTheta => "|cos θ| taken: cos θ = |N·L| instead of −N·L (Eq. 4.7)",
            Slip::NormalNotNormalized => {
                "the normal not normalised (used with the length it was given)"
            }
            Slip::FalloffForgotten => {
                "the falloff forgotten (I_l = C_l instead of C_l/d^f, Eq. 4.2)"
            }
            Slip::FalloffLinearNotQuadratic => {
                "linear falloff where the problem says quadratic (Eq. 4.3)"
            }
            Slip::FalloffQuadraticNotLinear => {
                "quadratic falloff where the problem says linear (Eq. 4.3)"
            }
            Slip::AmbientForgotten => "the ambient term O_a I_a forgotten (Eq. 4.6)",
            Slip::HalfVector => "cos φ from Blinn's half-vector, N·H, instead of −R·V (Eq. 4.10)",
            Slip::CosPhiNotRaised => "cos φ not raised to n_s (Eq. 4.10)",
            Slip::SpotConeIgnored => {
                "the spot light's cone ignored (taken as a point light, Eq. 4.4)"
            }
            Slip::NoClamping => {
                "negative cosines kept: Eq. 4.16 taken literally, cos θ and cos φ not clamped at 0"
            }
        },
        Lang::Pt => match s {
            Slip::HitBehindOrigin => "a interseção tomada atrás da origem do raio (t < 0)",
            Slip::LightReversed => "L invertido: tomado do ponto para a luz, o oposto da Eq. 4.1",
            Slip::ViewerReversed => {
                "V invertido: tomado do ponto para o observador, o oposto da Eq. 4.10"
            }
            Slip::NormalReversed => "a normal invertida",
            Slip::AbsCosTheta => "|cos θ| usado: cos θ = |N·L| em vez de −N·L (Eq. 4.7)",
            Slip::NormalNotNormalized => "a normal não normalizada (usada com o comprimento dado)",
            Slip::FalloffForgotten => {
                "o decaimento esquecido (I_l = C_l em vez de C_l/d^f, Eq. 4.2)"
            }
            Slip::FalloffLinearNotQuadratic => {
                "decaimento linear onde o problema diz quadrático (Eq. 4.3)"
            }
            Slip::FalloffQuadraticNotLinear => {
                "decaimento quadrático onde o problema diz linear (Eq. 4.3)"
            }
            Slip::AmbientForgotten => "o termo de luz ambiente O_a I_a esquecido (Eq. 4.6)",
            Slip::HalfVector => "cos φ pelo vetor médio de Blinn, N·H, em vez de −R·V (Eq. 4.10)",
            Slip::CosPhiNotRaised => "cos φ não elevado a n_s (Eq. 4.10)",
            Slip::SpotConeIgnored => "o cone do spot ignorado (tomado como luz pontual, Eq. 4.4)",
            Slip::NoClamping => {
                "cossenos negativos mantidos: a Eq. 4.16 ao pé da letra, cos θ e cos φ sem o \
                 limite em 0"
            }
        },
    }
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

/// The short name of a reading.
pub fn reading(code: ReadingCode, lang: Lang) -> &'static str {
    match (lang, code) {
        (Lang::En, ReadingCode::LightReversed) => "light reversed (L from the point to the light)",
        (Lang::En, ReadingCode::NormalReversed) => "normal reversed",
        (Lang::En, ReadingCode::LineBehindOrigin) => "the line's hit behind the ray's origin",
        (Lang::Pt, ReadingCode::LightReversed) => "luz invertida (L do ponto para a luz)",
        (Lang::Pt, ReadingCode::NormalReversed) => "normal invertida",
        (Lang::Pt, ReadingCode::LineBehindOrigin) => "a interseção da reta atrás da origem do raio",
    }
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
    }
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

/// The problem as written has no colour (its ray hits nothing).
pub fn nothing_to_shade(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "as written, the problem has no colour: its ray hits nothing (t > 0)",
        Lang::Pt => "como enunciado, o problema não tem cor: o raio não atinge nada (t > 0)",
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
