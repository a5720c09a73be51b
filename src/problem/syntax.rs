//! What is wrong with a problem file that does not parse, and what would fix it, as values:
//! serde_json's and serde's messages classified once, where a parse error becomes a
//! [`ProblemError::Syntax`](super::ProblemError::Syntax) ([`Parse::read`]), into variants that
//! hold the names, values and types they quote; the faults phong finds itself (a file that is
//! not UTF-8 or not an object, a decimal comma); and the fix phong adds ([`SyntaxFix`]).
//!
//! The English of every variant read from serde is serde's own text, byte for byte: a message
//! whose reading does not give back the text it was read from is kept as written
//! ([`Parse::Other`]).

use std::fmt;

use crate::messages;
use crate::text::{Echo, Fault, Lang, Message, Show};

/// The longest name (a key, a `type` word) a message repeats in full; a longer one is shown
/// shortened, with its length, so that a message stays a few lines whatever was written.
pub(crate) const LONGEST_NAME: usize = 60;

messages! {
    /// What the parser found where something else belongs (serde's `Unexpected`, as
    /// serde_json writes it).
    #[derive(Default)]
    pub enum Found {
        /// `true` or `false`.
        Boolean { value: String } => "boolean `{value}`", "booleano `{value}`";
        /// A whole number, as serde writes it.
        Integer { value: String } => "integer `{value}`", "inteiro `{value}`";
        /// A number with a fraction, as serde writes it.
        Float { value: String } => "floating point `{value}`", "número `{value}`";
        /// A string, quoted and escaped as serde writes it (`"3/5 0 4/5"`).
        Text { quoted: String } => "string {quoted}", "texto {quoted}";
        /// `null`.
        #[default]
        Null => "null", "null";
        /// An array.
        Sequence => "sequence", "lista";
        /// An object.
        Map => "map", "objeto";
    }
}

impl Found {
    /// serde's words for what it found, read back.
    fn read(text: &str) -> Option<Found> {
        let ticked = |prefix: &str| {
            text.strip_prefix(prefix)
                .and_then(|r| r.strip_suffix('`'))
                .map(str::to_owned)
        };
        Some(match text {
            "null" => Found::Null,
            "sequence" => Found::Sequence,
            "map" => Found::Map,
            _ if text.starts_with("string \"") && text.ends_with('"') => Found::Text {
                quoted: text["string ".len()..].to_owned(),
            },
            _ => {
                if let Some(value) = ticked("boolean `") {
                    Found::Boolean { value }
                } else if let Some(value) = ticked("integer `") {
                    Found::Integer { value }
                } else {
                    Found::Float {
                        value: ticked("floating point `")?,
                    }
                }
            }
        })
    }

    /// The text of a string found, as serde escapes it, without its quotes.
    fn string(&self) -> Option<&str> {
        match self {
            Found::Text { quoted } => quoted.strip_prefix('"')?.strip_suffix('"'),
            _ => None,
        }
    }
}

messages! {
    /// What the parser expected: serde's words for a type, and the format's own words for its
    /// objects and "either" values (format.rs writes these as the parser's `expecting`).
    #[derive(Default)]
    pub enum Expected {
        /// Any number.
        #[default]
        F64 => "f64", "um número";
        /// A whole number ≥ 0 (32 bits).
        U32 => "u32", "um número inteiro";
        /// A whole number ≥ 0 (8 bits).
        U8 => "u8", "um número inteiro";
        /// A whole number ≥ 0 (64 bits).
        U64 => "u64", "um número inteiro";
        /// A number, in words.
        ANumber => "a number", "um número";
        /// `true` or `false`.
        Boolean => "a boolean", "um booleano";
        /// A string.
        Text => "a string", "um texto";
        /// An array of any length.
        Sequence => "a sequence", "uma lista";
        /// An array of `len` items.
        Array { len: usize } => "an array of length {len}", "uma lista de comprimento {len}";
        /// A `type` word.
        Words { words: Quoted } => "one of the words {words}", "uma das palavras {words}";
        /// `point`.
        Point =>
            "the point: an object {{\"position\": [x, y, z], \"normal\": [x, y, z], \"material\": …}}",
            "o ponto: um objeto {{\"position\": [x, y, z], \"normal\": [x, y, z], \"material\": …}}";
        /// `ray`.
        Ray =>
            "the ray: an object {{\"origin\": [x, y, z], \"direction\": [x, y, z]}}",
            "o raio: um objeto {{\"origin\": [x, y, z], \"direction\": [x, y, z]}}";
        /// `camera`.
        Camera =>
            "the camera: an object {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": 45, \
             \"width\": 640, \"height\": 480}}",
            "a câmera: um objeto {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": 45, \
             \"width\": 640, \"height\": 480}}";
        /// `render`.
        Render =>
            "the render settings: an object {{\"max_level\": 5, \"shadows\": true, …}}",
            "as configurações do traçado de raios: um objeto {{\"max_level\": 5, \"shadows\": \
             true, …}}";
        /// `generated`.
        Generated =>
            "where a generated problem came from: an object {{\"kind\": \"point\", \"seed\": 1, \
             \"index\": 1}}",
            "a origem de um problema gerado: um objeto {{\"kind\": \"point\", \"seed\": 1, \
             \"index\": 1}}";
        /// An item of `lights`.
        Light =>
            "a light: an object {{\"type\": \"point\", …}}",
            "uma fonte de luz: um objeto {{\"type\": \"point\", …}}";
        /// An item of `surfaces`.
        Surface =>
            "a surface: an object {{\"type\": \"sphere\", …}}",
            "uma superfície: um objeto {{\"type\": \"sphere\", …}}";
        /// A material.
        Material =>
            "a material: an object {{\"ambient\": [r, g, b], \"diffuse\": [r, g, b], …}}",
            "um material: um objeto {{\"ambient\": [r, g, b], \"diffuse\": [r, g, b], …}}";
        /// `materials`.
        NamedMaterials =>
            "the named materials: an object {{\"name\": {{\"ambient\": …}}, …}}",
            "os materiais com nome: um objeto {{\"name\": {{\"ambient\": …}}, …}}";
        /// A material's colour.
        Colour =>
            "a colour [r, g, b] or {{\"k\": k, \"color\": [r, g, b]}}",
            "uma cor [r, g, b] ou {{\"k\": k, \"color\": [r, g, b]}}";
        /// A reflectivity.
        Reflectivity =>
            "a colour [r, g, b] or the word \"specular\"",
            "uma cor [r, g, b] ou a palavra \"specular\"";
        /// An answer key's colour.
        AnswerColour => "a colour [r, g, b] or \"#RRGGBB\"", "uma cor [r, g, b] ou \"#RRGGBB\"";
        /// An answer key.
        Answer =>
            "an answer: [r, g, b], \"#RRGGBB\" or {{\"color\": …, \"scale\": …, \"tolerance\": …}}",
            "uma resposta: [r, g, b], \"#RRGGBB\" ou {{\"color\": …, \"scale\": …, \"tolerance\": \
             …}}";
        /// A material's name or a material.
        MaterialRef =>
            "the name of a material in \"materials\", or a material object",
            "o nome de um material em \"materials\", ou um objeto de material";
        /// A course policy's `tolerance` (check/policy.rs).
        Tolerances =>
            "the tolerances: an object {{\"1\": 0.005, \"255\": 1}}",
            "as tolerâncias: um objeto {{\"1\": 0.005, \"255\": 1}}";
    }
}

impl Expected {
    /// The expectations without fields, to read serde's words back.
    fn fixed() -> [Expected; 23] {
        use Expected::*;
        [
            F64,
            U32,
            U8,
            U64,
            ANumber,
            Boolean,
            Text,
            Sequence,
            Point,
            Ray,
            Camera,
            Render,
            Generated,
            Light,
            Surface,
            Material,
            NamedMaterials,
            Colour,
            Reflectivity,
            AnswerColour,
            Answer,
            MaterialRef,
            Tolerances,
        ]
    }

    /// What the parser said it expected, read back.
    fn read(text: &str) -> Option<Expected> {
        if let Some(e) = Expected::fixed()
            .into_iter()
            .find(|e| e.text(Lang::En) == text)
        {
            return Some(e);
        }
        if let Some(len) = text.strip_prefix("an array of length ") {
            return Some(Expected::Array {
                len: len.parse().ok()?,
            });
        }
        let words = text.strip_prefix("one of the words ")?;
        let words = words
            .split(", ")
            .map(|w| Some(w.strip_prefix('"')?.strip_suffix('"')?.to_owned()))
            .collect::<Option<Vec<_>>>()?;
        Some(Expected::Words {
            words: Quoted(words),
        })
    }

    /// "esperado", "esperada" or "esperados", as the Portuguese of what is expected takes it.
    fn esperado(&self) -> &'static str {
        match self {
            Expected::Sequence
            | Expected::Array { .. }
            | Expected::Words { .. }
            | Expected::Camera
            | Expected::Generated
            | Expected::Light
            | Expected::Surface
            | Expected::Colour
            | Expected::Reflectivity
            | Expected::AnswerColour
            | Expected::Answer => "esperada",
            Expected::Render | Expected::Tolerances => "esperadas",
            Expected::NamedMaterials => "esperados",
            Expected::F64
            | Expected::U32
            | Expected::U8
            | Expected::U64
            | Expected::ANumber
            | Expected::Boolean
            | Expected::Text
            | Expected::Point
            | Expected::Ray
            | Expected::Material
            | Expected::MaterialRef => "esperado",
        }
    }
}

/// What was expected, after the thing found: "expected f64", "esperado um número".
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expecting(pub Expected);

impl Show for Expecting {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match lang {
            Lang::En => write!(f, "expected {}", self.0.text(lang)),
            Lang::Pt => write!(f, "{} {}", self.0.esperado(), self.0.text(lang)),
        }
    }
}

/// Words of the file's format, each quoted: `"ambient", "point"` (the same in every language).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Quoted(pub Vec<String>);

impl Show for Quoted {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, w) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            write!(f, "\"{w}\"")?;
        }
        Ok(())
    }
}

/// The names serde lists as expected (`one of `a`, `b`, `c``), each shortened as a name is.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OneOf(pub Vec<Echo>);

impl OneOf {
    /// serde's list read back: "`a`", "`a` or `b`", "one of `a`, `b`, `c`".
    fn read(text: &str) -> Option<OneOf> {
        let ticked = |t: &str| Some(t.strip_prefix('`')?.strip_suffix('`')?.to_owned());
        let names: Vec<String> = if let Some(list) = text.strip_prefix("one of ") {
            list.split(", ").map(ticked).collect::<Option<_>>()?
        } else if let Some((a, b)) = text.split_once(" or ") {
            vec![ticked(a)?, ticked(b)?]
        } else {
            vec![ticked(text)?]
        };
        Some(OneOf(
            names.iter().map(|n| Echo::new(n, LONGEST_NAME)).collect(),
        ))
    }
}

impl Show for OneOf {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (or, one_of) = match lang {
            Lang::En => ("or", "one of"),
            Lang::Pt => ("ou", "um de"),
        };
        let n = |e: &Echo| crate::text::In(e, lang).to_string();
        match self.0.as_slice() {
            [] => Ok(()),
            [a] => write!(f, "`{}`", n(a)),
            [a, b] => write!(f, "`{}` {or} `{}`", n(a), n(b)),
            all => {
                write!(f, "{one_of} ")?;
                for (i, a) in all.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "`{}`", n(a))?;
                }
                Ok(())
            }
        }
    }
}

/// A message of the parser phong does not know, as written: in Portuguese, quoted as the
/// parser's words.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ParserWords(pub String);

impl Show for ParserWords {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match lang {
            _ if self.0.is_empty() => Ok(()),
            Lang::En => f.write_str(&self.0),
            Lang::Pt => write!(f, "o leitor de JSON diz: “{}”", self.0),
        }
    }
}

/// A byte, as `0xFF`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hex(pub u8);

impl Show for Hex {
    fn show(&self, _: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "0x{:02X}", self.0)
    }
}

messages! {
    /// What a document that is not an object is.
    #[derive(Default)]
    pub enum JsonKind {
        /// `[ … ]`.
        Array => "an array [ … ]", "uma lista [ … ]";
        /// `"…"`.
        Text => "a string", "um texto";
        /// `5`.
        Number => "a number", "um número";
        /// `true`, `false`.
        Boolean => "a boolean", "um booleano";
        /// `null`.
        #[default]
        Null => "null", "null";
    }
}

messages! {
    /// What is wrong with a file that does not parse: serde_json's and serde's words, read
    /// back into values, and the faults phong finds itself.
    #[derive(Default)]
    pub enum Parse {
        /// The file ends inside a value.
        #[default]
        EofValue => "EOF while parsing a value", "fim do arquivo em meio a um valor";
        /// The file ends inside an object.
        EofObject => "EOF while parsing an object", "fim do arquivo em meio a um objeto";
        /// The file ends inside an array.
        EofList => "EOF while parsing a list", "fim do arquivo em meio a uma lista";
        /// The file ends inside a string.
        EofString => "EOF while parsing a string", "fim do arquivo em meio a um texto";
        /// A key without its colon.
        ExpectedColon => "expected `:`", "esperado `:`";
        /// An array's item without a comma or the end after it.
        ExpectedCommaOrBracket => "expected `,` or `]`", "esperado `,` ou `]`";
        /// An object's field without a comma or the end after it.
        ExpectedCommaOrBrace => "expected `,` or `}}`", "esperado `,` ou `}}`";
        /// A word that is not `true`, `false` or `null`.
        ExpectedIdent => "expected ident", "esperada uma palavra do JSON (true, false ou null)";
        /// Something that is not a value.
        ExpectedValue => "expected value", "esperado um valor";
        /// A string without its quote.
        ExpectedQuote => "expected `\"`", "esperado `\"`";
        /// A backslash escape JSON does not have.
        InvalidEscape => "invalid escape", "sequência de escape inválida";
        /// A number JSON cannot read.
        InvalidNumber => "invalid number", "número inválido";
        /// A number beyond f64.
        NumberOutOfRange => "number out of range", "número fora do alcance";
        /// A `\u` escape of no character.
        InvalidCodePoint => "invalid unicode code point", "ponto de código Unicode inválido";
        /// A raw control character in a string.
        ControlCharacter =>
            "control character (\\u0000-\\u001F) found while parsing a string",
            "caractere de controle (\\u0000-\\u001F) dentro de um texto";
        /// A key that is not a string.
        KeyMustBeAString => "key must be a string", "a chave deve ser um texto";
        /// Half of a surrogate pair.
        LoneSurrogate =>
            "lone leading surrogate in hex escape",
            "metade inicial de um par substituto sem a outra metade num escape hexadecimal";
        /// A comma before `]` or `}`.
        TrailingComma => "trailing comma", "vírgula a mais antes de `]` ou `}}`";
        /// Text after the value.
        TrailingCharacters =>
            "trailing characters",
            "caracteres a mais depois do fim do documento JSON";
        /// A `\u` escape cut short.
        EndOfHexEscape => "unexpected end of hex escape", "fim inesperado de um escape hexadecimal";
        /// Values nested too deep.
        RecursionLimit => "recursion limit exceeded", "limite de aninhamento excedido";
        /// A field the object does not take.
        UnknownField { name: Echo, expected: OneOf } =>
            "unknown field `{name}`, expected {expected}",
            "campo desconhecido `{name}`, esperado {expected}";
        /// A `type` word that is not one.
        UnknownVariant { name: Echo, expected: OneOf } =>
            "unknown variant `{name}`, expected {expected}",
            "valor desconhecido `{name}`, esperado {expected}";
        /// A required field not given.
        MissingField { name: Echo } => "missing field `{name}`", "campo ausente `{name}`";
        /// A field given twice.
        DuplicateField { name: Echo } => "duplicate field `{name}`", "campo repetido `{name}`";
        /// A material named twice (format.rs's own words).
        DuplicateMaterial { name: Echo } =>
            "duplicate material `{name}`",
            "material repetido `{name}`";
        /// A value of the wrong type.
        InvalidType { found: Found, expected: Expecting } =>
            "invalid type: {found}, {expected}",
            "tipo inválido: {found}, {expected}";
        /// A value of the right type that is not one of the values taken.
        InvalidValue { found: Found, expected: Expecting } =>
            "invalid value: {found}, {expected}",
            "valor inválido: {found}, {expected}";
        /// An array of the wrong length.
        InvalidLength { len: usize, expected: Expecting } =>
            "invalid length {len}, {expected}",
            "comprimento {len} inválido, {expected}";
        /// A message of the parser this list does not know, as written.
        Other { text: ParserWords } => "{text}", "{text}";
        /// A byte that is not UTF-8.
        NotUtf8 { byte: Hex } => "byte {byte} is not UTF-8 text", "o byte {byte} não é texto UTF-8";
        /// The course policy (`course-policy.json`) given where a problem is read.
        CoursePolicy =>
            "this is the course policy (tolerances, credit, points), not a problem",
            "esta é a política do curso (tolerâncias, crédito, pontos), não um problema";
        /// A document that is not an object.
        NotAnObject { kind: JsonKind } =>
            "the file is {kind}, and a problem file is one JSON object {{ … }}",
            "o arquivo é {kind}, e um arquivo de problema é um objeto JSON {{ … }}";
        /// A number with a decimal comma (`0,5`).
        DecimalComma { written: String } =>
            "{written} is written with a decimal comma, and JSON reads a comma as the separator \
             of fields and of a list's items (a JSON number takes a decimal point)",
            "{written} está escrito com vírgula decimal, e o JSON lê a vírgula como separador \
             de campos e de itens de uma lista (um número JSON leva ponto decimal)";
        /// An array of numbers with decimal commas (`[0,5, 0,4, 0,6]`).
        DecimalCommas { written: String } =>
            "{written} has numbers written with a decimal comma, and JSON reads a comma as the \
             separator of fields and of a list's items (a JSON number takes a decimal point)",
            "{written} tem números escritos com vírgula decimal, e o JSON lê a vírgula como \
             separador de campos e de itens de uma lista (um número JSON leva ponto decimal)";
        /// An array longer than the `[x, y, z]` it is read into.
        TooManyElements =>
            "too many elements: expected an array of length 3",
            "elementos demais: esperada uma lista de comprimento 3";
    }
}

/// serde_json's error on a text that is not the JSON asked for (a rubric, a steps file), read
/// into a value: what is wrong (`Parse`) and where, `at line L column C` in English.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JsonError {
    /// Boxed: a JSON error sits inside faults that are themselves inside errors.
    what: Box<Parse>,
    line: usize,
    column: usize,
}

impl JsonError {
    /// serde_json's error, read.
    pub fn of(e: &serde_json::Error) -> JsonError {
        let text = e.to_string();
        JsonError {
            what: Box::new(Parse::read(
                text.rsplit_once(" at line ")
                    .map_or(text.as_str(), |(m, _)| m),
            )),
            line: e.line(),
            column: e.column(),
        }
    }
}

impl Message for JsonError {
    fn text(&self, lang: Lang) -> String {
        let what = self.what.text(lang);
        match (self.line, lang) {
            // serde_json says no position for an error that has none (line 0).
            (0, _) => what,
            (l, Lang::En) => format!("{what} at line {l} column {}", self.column),
            (l, Lang::Pt) => format!("{what} na linha {l}, coluna {}", self.column),
        }
    }
}

impl Parse {
    /// serde_json's message (without its " at line L column C"), read into a value; a message
    /// whose reading does not give back the text serde wrote (its names shortened, as
    /// [`Echo`] writes them) is kept as written.
    pub(crate) fn read(message: &str) -> Parse {
        let written = shorten_quoted(message);
        match Parse::classify(message) {
            Some(p) if p.text(Lang::En) == written => p,
            _ => Parse::Other {
                text: ParserWords(written),
            },
        }
    }

    fn classify(m: &str) -> Option<Parse> {
        use Parse::*;
        let fixed = [
            EofValue,
            EofObject,
            EofList,
            EofString,
            ExpectedColon,
            ExpectedCommaOrBracket,
            ExpectedCommaOrBrace,
            ExpectedIdent,
            ExpectedValue,
            ExpectedQuote,
            InvalidEscape,
            InvalidNumber,
            NumberOutOfRange,
            InvalidCodePoint,
            ControlCharacter,
            KeyMustBeAString,
            LoneSurrogate,
            TrailingComma,
            TrailingCharacters,
            EndOfHexEscape,
            RecursionLimit,
        ];
        if let Some(p) = fixed.into_iter().find(|p| p.text(Lang::En) == m) {
            return Some(p);
        }
        let name = |prefix: &str| {
            let n = m.strip_prefix(prefix)?.strip_suffix('`')?;
            Some(Echo::new(n, LONGEST_NAME))
        };
        let listed = |prefix: &str| {
            let (n, list) = m.strip_prefix(prefix)?.split_once("`, expected ")?;
            Some((Echo::new(n, LONGEST_NAME), OneOf::read(list)?))
        };
        let typed = |prefix: &str| {
            let (found, expected) = m.strip_prefix(prefix)?.rsplit_once(", expected ")?;
            Some((Found::read(found)?, Expecting(Expected::read(expected)?)))
        };
        if let Some((name, expected)) = listed("unknown field `") {
            return Some(UnknownField { name, expected });
        }
        if let Some((name, expected)) = listed("unknown variant `") {
            return Some(UnknownVariant { name, expected });
        }
        if let Some(name) = name("missing field `") {
            return Some(MissingField { name });
        }
        if let Some(name) = name("duplicate field `") {
            return Some(DuplicateField { name });
        }
        if let Some(name) = name("duplicate material `") {
            return Some(DuplicateMaterial { name });
        }
        if let Some((found, expected)) = typed("invalid type: ") {
            return Some(InvalidType { found, expected });
        }
        if let Some((found, expected)) = typed("invalid value: ") {
            return Some(InvalidValue { found, expected });
        }
        let (len, expected) = m
            .strip_prefix("invalid length ")?
            .split_once(", expected ")?;
        Some(InvalidLength {
            len: len.parse().ok()?,
            expected: Expecting(Expected::read(expected)?),
        })
    }

    /// The string found where a value of type `expected` belongs, as serde escapes it.
    pub(crate) fn string_for(&self, expected: impl Fn(&Expected) -> bool) -> Option<&str> {
        match self {
            Parse::InvalidType {
                found,
                expected: Expecting(e),
            } if expected(e) => found.string(),
            _ => None,
        }
    }
}

/// `message` with each name it quotes between backticks (serde's `unknown field `…``, `unknown
/// variant `…``) shortened to [`LONGEST_NAME`]: serde's text as phong shows it.
fn shorten_quoted(message: &str) -> String {
    let mut out = String::with_capacity(message.len().min(1024));
    for (i, part) in message.split('`').enumerate() {
        if i > 0 {
            out.push('`');
        }
        if i % 2 == 1 {
            out.push_str(&crate::text::number::shorten(part, LONGEST_NAME));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// A constant text in both languages (a field's purpose in the tables of format.rs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bilingual {
    /// The English.
    pub en: &'static str,
    /// The Portuguese.
    pub pt: &'static str,
}

impl Show for Bilingual {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match lang {
            Lang::En => self.en,
            Lang::Pt => self.pt,
        })
    }
}

/// Words of the format joined as a list is read: "a, b or c", "a, b ou c".
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OrList(pub &'static [&'static str]);

impl Show for OrList {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let or = match lang {
            Lang::En => "or",
            Lang::Pt => "ou",
        };
        match self.0.split_last() {
            Some((last, [])) => f.write_str(last),
            Some((last, rest)) => write!(f, "{} {or} {last}", rest.join(", ")),
            None => Ok(()),
        }
    }
}

messages! {
    /// What a field of the format gives, to say why it is needed when it is missing.
    #[derive(Default)]
    pub enum Purpose {
        /// A field of a light's or a surface's table, which says it in both languages.
        Table { text: Bilingual } => "{text}", "{text}";
        /// `origin`.
        #[default]
        Origin => "the ray's origin", "a origem do raio";
        /// `k`.
        K => "the coefficient k of k·O", "o coeficiente k de k·O";
        /// `type`: the kinds of each table.
        Kind { lights: OrList, surfaces: OrList } =>
            "the kind: {lights} (lights); {surfaces} (surfaces)",
            "o tipo: {lights} (fontes de luz); {surfaces} (superfícies)";
        /// A field of the camera.
        Camera => "the camera", "a câmera";
    }
}

messages! {
    /// What would fix a file that does not parse.
    #[derive(Default)]
    pub enum SyntaxFix {
        /// Nothing to say.
        #[default]
        Nothing => "", "";
        /// The file ends too early.
        EndsEarly =>
            "the file ends too early: close every {{ and [",
            "o arquivo termina cedo demais: feche cada {{ e [";
        /// A number beyond f64.
        OutOfRange =>
            "the number is beyond the range of f64 (about ±1.8e308); every number must be finite",
            "o número está além do alcance de f64 (cerca de ±1.8e308); todo número deve ser finito";
        /// Any other syntax error.
        CheckJson =>
            "check the JSON just before this position (a missing comma, quote, bracket or brace, \
             or a trailing comma)",
            "confira o JSON logo antes desta posição (falta uma vírgula, aspa, colchete ou \
             chave, ou sobra uma vírgula antes de ] ou }})";
        /// A field the object does not take.
        UnknownField =>
            "remove the field or correct its spelling (`phong schema` lists every field)",
            "remova o campo ou corrija sua grafia (`phong schema` lista todos os campos)";
        /// A field given twice.
        DuplicateField =>
            "give the field once: remove one of the two (the parser does not pick one)",
            "dê o campo uma vez só: remova um dos dois (a leitura não escolhe um)";
        /// A material named twice.
        DuplicateMaterial =>
            "give each material its own name, or remove one of the two",
            "dê a cada material seu próprio nome, ou remova um dos dois";
        /// A kind written in Portuguese (`"type": "pontual"`).
        KindInEnglish { kind: String, word: String } =>
            "a kind is written in English in the file: write \"{kind}\" for \"{word}\"",
            "o arquivo escreve cada tipo em inglês: escreva \"{kind}\" para \"{word}\"";
        /// A required field, whose purpose is not known.
        Add { name: String } => "add \"{name}\"", "acrescente \"{name}\"";
        /// A required field, and what it gives.
        AddFor { name: String, purpose: Purpose } =>
            "add \"{name}\": it gives {purpose}",
            "acrescente \"{name}\": dá {purpose}";
        /// A value of the wrong form.
        SeeSchema =>
            "see `phong schema` for the expected form",
            "veja em `phong schema` a forma esperada";
        /// An array longer than three numbers.
        ThreeNumbers =>
            "give exactly three numbers [x, y, z]",
            "dê exatamente três números [x, y, z]";
        /// A triangle given more than three vertices.
        ThreeVertices =>
            "a triangle has three vertices: give exactly three, [[x, y, z], [x, y, z], [x, y, \
             z]] (a polygon with more is made of several triangles)",
            "um triângulo tem três vértices: dê exatamente três, [[x, y, z], [x, y, z], [x, y, \
             z]] (um polígono com mais vértices é feito de vários triângulos)";
        /// `NaN`, `Infinity` or `inf`, as written.
        NotFinite { word: String } =>
            "JSON has no {word}: every number must be finite, such as 0 or 1e300",
            "o JSON não tem {word}: todo número deve ser finito, como 0 ou 1e300";
        /// A string of three numbers where an array belongs: the array.
        AsArray { array: String } =>
            "write the three numbers as a JSON array, without quotes, {array}",
            "escreva os três números como uma lista JSON, sem aspas, {array}";
        /// A string where an array of three numbers belongs.
        InBrackets =>
            "give three numbers in brackets, such as [1, 1, 1] (a colour: red, green and blue \
             from 0 to 1)",
            "dê três números entre colchetes, como [1, 1, 1] (uma cor: vermelho, verde e azul \
             de 0 a 1)";
        /// A fraction `a/b`: its decimal.
        Fraction { a: String, b: String, decimal: String } =>
            "JSON has no fractions: write {a}/{b} as a decimal, {decimal}",
            "o JSON não aceita frações: escreva {a}/{b} como decimal, {decimal}";
        /// A word for a falloff: its number.
        FalloffWord { f: u8, word: String } =>
            "the falloff is the exponent f of d^f, a number: write {f} for \"{word}\" (0 none, \
             1 linear, 2 quadratic)",
            "o decaimento é o expoente f de d^f, um número: escreva {f} para \"{word}\" (0 sem \
             decaimento, 1 linear, 2 quadrático)";
        /// A number in quotes.
        Unquoted { number: String } =>
            "a number is written without quotes: {number}",
            "um número se escreve sem aspas: {number}";
        /// A word where a falloff belongs.
        NotFalloffWord { word: String } =>
            "a number belongs here, not the word \"{word}\": the falloff is 0 (none), 1 (linear) \
             or 2 (quadratic)",
            "aqui vai um número, não a palavra \"{word}\": o decaimento é 0 (sem decaimento), 1 \
             (linear) ou 2 (quadrático)";
        /// A word where a number belongs.
        NotWord { word: String } =>
            "a number belongs here, not the word \"{word}\"",
            "aqui vai um número, não a palavra \"{word}\"";
        /// A decimal comma: the number with a point.
        DecimalPoint { fixed: String } => "write {fixed}", "escreva {fixed}";
        /// A file that is not UTF-8.
        Utf8 =>
            "save the file as UTF-8 (JSON is UTF-8 text); the byte may come from another \
             encoding, such as Latin-1, or from a file that is not a problem file",
            "salve o arquivo como UTF-8 (JSON é texto UTF-8); o byte pode vir de outra \
             codificação, como Latin-1, ou de um arquivo que não é um arquivo de problema";
        /// The course policy given among problem files; `folder` is the folder it was given
        /// in, as written, with its separator (`exercicios/`), or empty.
        LeavePolicyOut { folder: String } =>
            "leave it out of the problem files ({folder}4.*.json, not {folder}*.json): check, \
             grade, serve and moodle read it from the exercises' folder themselves",
            "deixe-a fora dos arquivos de problema ({folder}4.*.json, não {folder}*.json): \
             check, grade, serve e moodle a leem da pasta dos exercícios";
        /// A document that is not an object.
        OneObject =>
            "write the problem's fields in one object, {{\"lights\": [ … ], \"point\": {{ … }}, \
             …}}; several problems go in several files (`phong schema` lists every field)",
            "escreva os campos do problema num só objeto, {{\"lights\": [ … ], \"point\": {{ … \
             }}, …}}; vários problemas vão em vários arquivos (`phong schema` lista todos os \
             campos)";
    }
}

/// A file that does not parse: what is wrong and what would fix it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SyntaxFault {
    /// What is wrong.
    pub what: Parse,
    /// What would fix it.
    pub fix: SyntaxFix,
}

impl Fault for SyntaxFault {
    fn what(&self, lang: Lang) -> String {
        self.what.text(lang)
    }
    fn fix(&self, lang: Lang) -> String {
        self.fix.text(lang)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// serde's message, read and written back in English.
    fn again(m: &str) -> Parse {
        let p = Parse::read(m);
        assert_eq!(p.text(Lang::En), shorten_quoted(m), "{p:?}");
        p
    }

    #[test]
    fn serde_s_words_are_read_into_values_and_written_back_byte_for_byte() {
        let p = again("unknown field `lihgts`, expected one of `title`, `lights`, `viewer`");
        assert!(matches!(p, Parse::UnknownField { .. }), "{p:?}");
        assert_eq!(
            p.text(Lang::Pt),
            "campo desconhecido `lihgts`, esperado um de `title`, `lights`, `viewer`"
        );
        let p = again("unknown variant `x`, expected `a` or `b`");
        assert_eq!(
            p.text(Lang::Pt),
            "valor desconhecido `x`, esperado `a` ou `b`"
        );
        assert!(matches!(
            again("unknown variant `x`, expected `a`"),
            Parse::UnknownVariant { .. }
        ));
        let p = again("invalid type: string \"3/5 0 4/5\", expected an array of length 3");
        assert_eq!(
            p.text(Lang::Pt),
            "tipo inválido: texto \"3/5 0 4/5\", esperada uma lista de comprimento 3"
        );
        assert_eq!(
            p.string_for(|e| *e == Expected::Array { len: 3 }),
            Some("3/5 0 4/5")
        );
        let p = again("invalid value: integer `-1`, expected u32");
        assert_eq!(
            p.text(Lang::Pt),
            "valor inválido: inteiro `-1`, esperado um número inteiro"
        );
        let p = again("invalid type: floating point `10.5`, expected u32");
        assert!(matches!(p, Parse::InvalidType { .. }), "{p:?}");
        let p = again("invalid type: boolean `true`, expected the render settings: an object {\"max_level\": 5, \"shadows\": true, …}");
        assert!(p.text(Lang::Pt).starts_with(
            "tipo inválido: booleano `true`, esperadas as configurações do traçado de raios"
        ));
        let p = again("invalid type: null, expected one of the words \"ambient\", \"point\"");
        assert_eq!(
            p.text(Lang::Pt),
            "tipo inválido: null, esperada uma das palavras \"ambient\", \"point\""
        );
        let p = again("invalid length 2, expected an array of length 3");
        assert_eq!(
            p.text(Lang::Pt),
            "comprimento 2 inválido, esperada uma lista de comprimento 3"
        );
        for m in [
            "missing field `direction`",
            "duplicate field `viewer`",
            "duplicate material `m`",
            "invalid type: map, expected a sequence",
            "invalid type: sequence, expected a string",
            "EOF while parsing a value",
            "expected `,` or `}`",
            "trailing characters",
            "recursion limit exceeded",
            "control character (\\u0000-\\u001F) found while parsing a string",
        ] {
            assert!(!matches!(again(m), Parse::Other { .. }), "{m}");
        }
    }

    #[test]
    fn every_word_of_serde_and_of_the_format_reads_back_as_itself() {
        use strum::IntoEnumIterator;
        for e in Expected::iter() {
            let e = match e {
                Expected::Array { .. } => Expected::Array { len: 3 },
                Expected::Words { .. } => Expected::Words {
                    words: Quoted(vec!["point".into(), "spot".into()]),
                },
                e => e,
            };
            assert_eq!(Expected::read(&e.text(Lang::En)), Some(e.clone()), "{e:?}");
        }
        // serde_json's own messages: every variant without fields but phong's own.
        for p in Parse::iter() {
            let with_fields = format!("{p:?}").contains('{');
            if with_fields || p == Parse::TooManyElements || p == Parse::CoursePolicy {
                continue;
            }
            assert_eq!(Parse::read(&p.text(Lang::En)), p, "{p:?}");
        }
    }

    #[test]
    fn a_long_name_is_shortened_with_its_length_in_the_reader_s_language() {
        let long = "a".repeat(81);
        let p = again(&format!("unknown field `{long}`, expected `x` or `y`"));
        let pt = p.text(Lang::Pt);
        assert!(pt.contains("(81 caracteres)`"), "{pt}");
        assert!(p.text(Lang::En).contains("(81 characters)`"));
    }

    #[test]
    fn a_message_not_known_is_kept_as_written_and_quoted_in_portuguese() {
        let p = again("float key must be finite (got NaN or +/-inf)");
        assert_eq!(
            p,
            Parse::Other {
                text: ParserWords("float key must be finite (got NaN or +/-inf)".into())
            }
        );
        assert_eq!(
            p.text(Lang::Pt),
            "o leitor de JSON diz: “float key must be finite (got NaN or +/-inf)”"
        );
        // A reading that would not give the text back (an unknown expectation).
        let p = again("invalid type: integer `1`, expected struct Foo");
        assert!(matches!(p, Parse::Other { .. }), "{p:?}");
    }

    #[test]
    fn a_syntax_fault_is_its_two_halves_in_each_language() {
        let f = SyntaxFault {
            what: Parse::NotUtf8 { byte: Hex(0xE9) },
            fix: SyntaxFix::Utf8,
        };
        assert_eq!(f.what(Lang::En), "byte 0xE9 is not UTF-8 text");
        assert_eq!(f.what(Lang::Pt), "o byte 0xE9 não é texto UTF-8");
        assert!(f.fix(Lang::Pt).starts_with("salve o arquivo como UTF-8"));
        assert_eq!(
            crate::problem::error::what_and_fix(&f, Lang::Pt),
            format!("{}. Correção: {}", f.what(Lang::Pt), f.fix(Lang::Pt))
        );
    }
}
