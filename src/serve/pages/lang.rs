//! The pages' language: `?lang=pt|en` when given (the switch in every page's header, kept in
//! its links and forms), else the best of English and Portuguese in `Accept-Language` (by its
//! q-values), else English (as the command line). No cookie: the language rides in the URL.
//!
//! Every fixed string of the pages is in [`Text`], in both languages; the verdicts, slips and
//! solutions come from `check::messages` and `report::messages`, as the command line's do.

use axum::http::{header, HeaderMap, Uri};

use crate::text::lang::Lang;

/// The value of `key` in a URL's query (`?lang=pt&solution=1`), if present.
pub(crate) fn query<'a>(uri: &'a Uri, key: &str) -> Option<&'a str> {
    uri.query()?
        .split('&')
        .filter_map(|pair| pair.split_once('=').or(Some((pair, ""))))
        .find(|(k, _)| *k == key)
        .map(|(_, v)| v)
}

/// The language of a request: `?lang=`, else `Accept-Language`, else English.
pub(crate) fn of(uri: &Uri, headers: &HeaderMap) -> Lang {
    query(uri, "lang")
        .and_then(Lang::from_code)
        .or_else(|| {
            headers
                .get(header::ACCEPT_LANGUAGE)
                .and_then(|v| v.to_str().ok())
                .and_then(accept_language)
        })
        .unwrap_or(Lang::En)
}

/// The best of English and Portuguese in an `Accept-Language` value (RFC 9110 §12.5.4): the
/// highest q-value (1 when absent; 0 means "not this one"), the first listed on a tie; `*`
/// stands for either, English first. `None` when the value accepts neither.
pub(crate) fn accept_language(value: &str) -> Option<Lang> {
    let mut best: Option<(Lang, u16)> = None;
    for item in value.split(',').take(32) {
        let mut parts = item.split(';');
        let tag = parts.next().unwrap_or("").trim();
        let mut q = 1000u16;
        for p in parts {
            if let Some(v) = p.trim().strip_prefix("q=").or(p.trim().strip_prefix("Q=")) {
                q = quality(v.trim()).unwrap_or(0);
            }
        }
        let primary = tag.split('-').next().unwrap_or("").to_ascii_lowercase();
        let lang = match primary.as_str() {
            "en" => Lang::En,
            "pt" => Lang::Pt,
            "*" => Lang::En,
            _ => continue,
        };
        if q > 0 && best.is_none_or(|(_, b)| q > b) {
            best = Some((lang, q));
        }
    }
    best.map(|(l, _)| l)
}

/// A q-value ("0.8", "1", "0.125") in thousandths, or `None` when it is not one.
fn quality(v: &str) -> Option<u16> {
    let (int, frac) = v.split_once('.').unwrap_or((v, ""));
    if frac.len() > 3 || !frac.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let whole = match int {
        "0" => 0u16,
        "1" => 1000,
        _ => return None,
    };
    let mut thousandths = 0u16;
    for (i, b) in frac
        .bytes()
        .chain(std::iter::repeat(b'0'))
        .take(3)
        .enumerate()
    {
        thousandths += u16::from(b - b'0') * [100, 10, 1][i];
    }
    if whole == 1000 && thousandths > 0 {
        return None;
    }
    Some(whole + thousandths)
}

/// The other language, for the switch.
pub(crate) fn other(lang: Lang) -> Lang {
    match lang {
        Lang::En => Lang::Pt,
        Lang::Pt => Lang::En,
    }
}

/// The code in URLs (`?lang=pt`).
pub(crate) fn code(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "en",
        Lang::Pt => "pt",
    }
}

macro_rules! texts {
    ($($name:ident => $en:expr, $pt:expr;)*) => {
        /// Every fixed string of the pages, in English and Portuguese (leaving one out does not
        /// compile).
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub(crate) enum Text {
            $(
                #[allow(missing_docs)]
                $name,
            )*
        }

        impl Text {
            /// The string in `lang`.
            pub(crate) fn get(self, lang: Lang) -> &'static str {
                match (self, lang) {
                    $(
                        (Text::$name, Lang::En) => $en,
                        (Text::$name, Lang::Pt) => $pt,
                    )*
                }
            }
        }
    };
}

texts! {
    SiteName => "Phong illumination exercises", "Exercícios de iluminação de Phong";
    Skip => "Skip to the content", "Pular para o conteúdo";
    Home => "Exercises", "Exercícios";
    Own => "Your own problem", "Seu próprio problema";
    LanguageNav => "Language", "Idioma";
    SwitchTo => "Português", "English";
    ListIntro => "Choose an exercise to read its statement, check your answer (and, if you like, your intermediate steps), and see the worked solution.", "Escolha um exercício para ler o enunciado, verificar sua resposta (e, se quiser, seus passos intermediários) e ver a resolução passo a passo.";
    ListHeading => "The exercises", "Os exercícios";
    OwnInvite => "Or write your own problem and solve it.", "Ou escreva seu próprio problema e resolva-o.";
    PointKind => "point", "ponto";
    RayKind => "ray", "raio";
    Statement => "Statement", "Enunciado";
    YourAnswer => "Your answer", "Sua resposta";
    AnswerKind => "The answer", "A resposta";
    AColour => "A colour", "Uma cor";
    NoHit => "The ray hits nothing", "O raio não atinge nada";
    ColourLabel => "Colour I = (R, G, B)", "Cor I = (R, G, B)";
    ColourHelp => "Three numbers, such as 0.245 0.28 0.21 (a decimal comma is fine: 0,245 0,28 0,21), or #RRGGBB.", "Três números, como 0,245 0,28 0,21 (vírgula ou ponto decimal), ou #RRGGBB.";
    Scale => "Scale of the colour", "Escala da cor";
    ScaleUnit => "0 to 1", "de 0 a 1";
    Scale255 => "0 to 255 (8 bits)", "de 0 a 255 (8 bits)";
    StepsHeading => "Intermediate steps (optional)", "Passos intermediários (opcional)";
    StepsHelp => "Fill in only the quantities you computed; empty boxes are ignored. A vector is three numbers.", "Preencha só as grandezas que calculou; as caixas vazias são ignoradas. Um vetor são três números.";
    ShowSolution => "Show the worked solution", "Mostrar a resolução passo a passo";
    Check => "Check", "Verificar";
    VerdictHeading => "Verdict", "Veredito";
    NothingGiven => "Write an answer or at least one step, then press Check.", "Escreva uma resposta ou pelo menos um passo e pressione Verificar.";
    SolutionHeading => "Worked solution", "Resolução passo a passo";
    SolutionLink => "See the worked solution", "Ver a resolução passo a passo";
    NotFound => "Not found", "Não encontrado";
    NoSuchExercise => "There is no exercise with this name.", "Não há exercício com este nome.";
    BackToList => "Back to the exercises", "Voltar aos exercícios";
    OwnIntro => "Give the data of a problem: a point with its normal, or a ray and a surface; the lights; the material. Numbers are separated by spaces or commas (a decimal comma is fine when numbers are separated by spaces or semicolons). Empty optional fields are left out.", "Dê os dados de um problema: um ponto com sua normal, ou um raio e uma superfície; as fontes de luz; o material. Números são separados por espaços ou vírgulas (vírgula decimal é aceita quando os números são separados por espaços ou ponto e vírgula). Campos opcionais vazios são omitidos.";
    ProblemKind => "The problem", "O problema";
    PointProblem => "A point P with its normal N", "Um ponto P com sua normal N";
    RayProblem => "A ray and a surface", "Um raio e uma superfície";
    PointPosition => "Point P", "Ponto P";
    PointNormal => "Normal N at P", "Normal N em P";
    RayOrigin => "Ray origin O", "Origem O do raio";
    RayDirection => "Ray direction D", "Direção D do raio";
    SurfaceKind => "Kind of surface", "Tipo de superfície";
    Plane => "plane", "plano";
    Sphere => "sphere", "esfera";
    PlanePoint => "A point of the plane", "Um ponto do plano";
    PlaneNormal => "Normal of the plane", "Normal do plano";
    SphereCenter => "Centre of the sphere", "Centro da esfera";
    SphereRadius => "Radius of the sphere", "Raio da esfera";
    Viewer => "Viewer E (optional)", "Observador E (opcional)";
    Lights => "Lights", "Fontes de luz";
    Ambient => "Ambient light I_a (optional)", "Luz ambiente I_a (opcional)";
    LightN => "Light", "Fonte de luz";
    LightOptional => "(optional: leave its colour empty to leave it out)", "(opcional: deixe a cor vazia para omiti-la)";
    LightKind => "Kind", "Tipo";
    PointLight => "point", "pontual";
    Directional => "directional", "direcional";
    SpotLight => "spot", "spot";
    LightPosition => "Position (a point or spot light)", "Posição (luz pontual ou spot)";
    SpotAxis => "Axis of the spot (the direction it points)", "Eixo do spot (a direção para onde aponta)";
    SpotAngle => "Half-angle of the spot's cone γ, in degrees", "Ângulo γ do cone do spot, em graus";
    SpotExponent => "Spot exponent e", "Expoente e do spot";
    LightDirection => "Direction of travel (a directional light)", "Direção de propagação (luz direcional)";
    LightColour => "Colour C_l", "Cor C_l";
    Falloff => "Falloff exponent f (0 none, 1 linear, 2 quadratic)", "Fator de decaimento f (0 nenhum, 1 linear, 2 quadrático)";
    Material => "Material", "Material";
    MatAmbient => "Ambient O_a", "Ambiente O_a";
    MatDiffuse => "Diffuse O_d", "Difusa O_d";
    MatSpecular => "Specular O_s", "Especular O_s";
    Shininess => "Shininess n_s", "Expoente de reflexão especular n_s";
    Solve => "Solve", "Resolver";
    ProblemJson => "The problem as a file", "O problema como arquivo";
    JsonHelp => "This is the problem in phong's file format: save it to solve or check it with the command line (phong solve problem.json).", "Este é o problema no formato de arquivo do phong: salve-o para resolvê-lo ou verificá-lo na linha de comando (phong solve problem.json).";
    Download => "Download problem.json", "Baixar problem.json";
    BadForm => "The problem cannot be solved as given", "O problema não pode ser resolvido como dado";
    OwnTitle => "Your problem", "Seu problema";
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accept_language_takes_the_highest_q_value_then_the_first() {
        assert_eq!(accept_language("pt-BR,pt;q=0.9,en;q=0.8"), Some(Lang::Pt));
        assert_eq!(accept_language("en;q=0.5, pt;q=0.8"), Some(Lang::Pt));
        assert_eq!(accept_language("pt;q=0.5, en;q=0.500"), Some(Lang::Pt));
        assert_eq!(accept_language("pt;q=0, en"), Some(Lang::En));
        assert_eq!(accept_language("pt;q=0.000"), None);
        assert_eq!(accept_language("de, fr;q=0.9"), None);
        assert_eq!(accept_language("fr, *;q=0.1"), Some(Lang::En));
        assert_eq!(accept_language(""), None);
        // A q-value that is not one counts as 0 (RFC 9110: at most three decimals, ≤ 1).
        assert_eq!(accept_language("pt;q=2, en;q=0.1"), Some(Lang::En));
        assert_eq!(accept_language("pt;q=0.1234, en;q=0.1"), Some(Lang::En));
        assert_eq!(accept_language("pt;q=abc"), None);
    }

    #[test]
    fn quality_reads_thousandths() {
        assert_eq!(quality("1"), Some(1000));
        assert_eq!(quality("1.000"), Some(1000));
        assert_eq!(quality("1.001"), None);
        assert_eq!(quality("0.8"), Some(800));
        assert_eq!(quality("0.125"), Some(125));
        assert_eq!(quality("0."), Some(0));
        assert_eq!(quality(".5"), None);
    }

    #[test]
    fn the_query_names_the_language() {
        let uri: Uri = "/exercise/4.2?solution=1&lang=pt".parse().unwrap();
        assert_eq!(query(&uri, "lang"), Some("pt"));
        assert_eq!(query(&uri, "solution"), Some("1"));
        assert_eq!(of(&uri, &HeaderMap::new()), Lang::Pt);
        let uri: Uri = "/?lang=xx".parse().unwrap();
        assert_eq!(of(&uri, &HeaderMap::new()), Lang::En);
    }
}
