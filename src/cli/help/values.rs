//! The help of the values of the flags that take one of a list (`--part key`, `--lang pt`),
//! which `--help` lists under the flag's help: the `ValueEnum`s' variants carry no doc comment
//! (it would be clap's help of the value), and [`described`] gives each flag of such an enum a
//! value parser that lists its values with their help in the help's language.

use std::any::TypeId;
use std::marker::PhantomData;

use clap::builder::{EnumValueParser, PossibleValue, TypedValueParser, ValueParser};
use clap::{Arg, ValueEnum};

use crate::check::grade::Input;
use crate::check::output::Format as CheckFormat;
use crate::check::policy::Duplicates;
use crate::check::Scale;
use crate::cli::args::ColorChoice;
use crate::generate::Kind;
use crate::report::document::Contents;
use crate::text::{Lang, Message};
use crate::tracer::Engine;
use crate::tradeoff::Metric;

crate::messages! {
    /// The help of one value of a flag.
    pub(crate) enum ValueHelp {
        /// `--lang en`.
        LangEn => "English", "Inglês";
        /// `--lang pt`.
        LangPt =>
            "Portuguese (português), as in the course notes", "Português, como nas notas do curso";
        /// `solve --color auto`.
        ColorAuto =>
            "Colour when writing to a terminal and NO_COLOR is not set",
            "Cores ao escrever num terminal, e NO_COLOR não definida";
        /// `solve --part statement`.
        PartStatement =>
            "The statements and their data only: the student's handout",
            "Só os enunciados e os seus dados: a lista do aluno";
        /// `solve --part solution`.
        PartSolution => "The worked solutions, step by step", "As resoluções, passo a passo";
        /// `solve --part key`.
        PartKey =>
            "The answer key: one table with every exercise's answer",
            "O gabarito: uma tabela com a resposta de cada exercício";
        /// `solve --part all`.
        PartAll =>
            "The statements, then the solutions, then the answer key",
            "Os enunciados, depois as resoluções, depois o gabarito";
        /// `--engine scalar`.
        EngineScalar =>
            "One ray at a time: each path traced to its end before the next",
            "Um raio por vez: cada caminho traçado até o fim antes do próximo";
        /// `--engine wide`.
        EngineWide =>
            "Packets of rays in SIMD lanes, a queue of rays per bounce; the default",
            "Pacotes de raios em vias SIMD, uma fila de raios por nível; o padrão";
        /// `--scale 1`.
        ScaleUnit =>
            "Components on [0, 1] (unclamped colours may exceed 1 or be negative)",
            "Componentes em [0, 1] (as cores não limitadas podem passar de 1 ou ser negativas)";
        /// `--scale 255`.
        Scale255 =>
            "8-bit integers 0–255 (the clamped colour times 255)",
            "Inteiros de 8 bits, de 0 a 255 (a cor limitada a [0, 1] vezes 255)";
        /// `check --format text`.
        CheckText => "Text for people", "Texto para pessoas";
        /// `check --format json`.
        CheckJson =>
            "JSON for scripts (stable field names, format_version)",
            "JSON para scripts (nomes de campos estáveis, format_version)";
        /// `check --format html`.
        CheckHtml =>
            "A page for a browser: the colours as swatches, the slips linked to the solution's \
             steps",
            "Uma página para o navegador: as cores como amostras, os erros ligados aos passos da \
             resolução";
        /// `check --format markdown`.
        CheckMarkdown =>
            "Markdown for notes and course pages", "Markdown para notas e páginas do curso";
        /// `grade --duplicates first`.
        DuplicatesFirst => "The first in the file", "A primeira no arquivo";
        /// `grade --duplicates last`.
        DuplicatesLast =>
            "The last in the file (a later answer replaces an earlier one): the default",
            "A última no arquivo (uma resposta posterior substitui uma anterior): o padrão";
        /// `grade --duplicates best`.
        DuplicatesBest =>
            "The one with the most points (the first of those on a tie)",
            "A de mais pontos (a primeira delas num empate)";
        /// `grade --input auto`.
        InputAuto =>
            "Moodle's Responses export when its header has a \"Response 1\" column, else the \
             plain CSV",
            "A exportação de respostas do Moodle quando o cabeçalho tem uma coluna \
             \"Response 1\", senão o CSV simples";
        /// `grade --input csv`.
        InputCsv =>
            "The plain CSV: student, exercise, answer", "O CSV simples: aluno, exercício, resposta";
        /// `grade --input moodle`.
        InputMoodle =>
            "Moodle's quiz Responses report downloaded as CSV (README, \"Grading\")",
            "O relatório de respostas do questionário do Moodle baixado como CSV (README, \
             \"Grading\")";
        /// `new --kind ambient`.
        KindAmbient =>
            "Ambient light only, like exercise 4.1", "Só luz ambiente, como o exercício 4.1";
        /// `new --kind point`.
        KindPoint =>
            "A point light, a point with its normal, and a viewer, like exercise 4.2",
            "Uma luz pontual, um ponto com a sua normal e um observador, como o exercício 4.2";
        /// `new --kind ray-plane`.
        KindRayPlane =>
            "A ray meeting a plane (in front of its origin), like exercise 4.3",
            "Um raio que encontra um plano (à frente da sua origem), como o exercício 4.3";
        /// `new --kind directional`.
        KindDirectional =>
            "A directional light (the sun: no position, no falloff), a point, its normal and a \
             viewer",
            "Uma luz direcional (o sol: sem posição, sem decaimento), um ponto, a sua normal e \
             um observador";
        /// `new --kind spot`.
        KindSpot =>
            "A spot light (Eq. 4.4) whose cone holds the point, or does not: the angle ψ \
             between the cone's axis and the point is at least 5° from the edge γ, never within \
             rounding of it",
            "Uma luz spot (Eq. 4.4) cujo cone contém o ponto, ou não: o ângulo ψ entre o eixo \
             do cone e o ponto fica a pelo menos 5° da borda γ, nunca a menos de um \
             arredondamento dela";
        /// `new --kind several`.
        KindSeveral =>
            "Several lights (two point lights, or a point and a directional light, and an \
             ambient light) at one point: the terms add up (Eq. 4.16)",
            "Várias luzes (duas luzes pontuais, ou uma pontual e uma direcional, e uma luz \
             ambiente) num ponto: os termos se somam (Eq. 4.16)";
        /// `new --kind sphere`.
        KindSphere =>
            "A ray meeting a sphere (the nearest of its two hits, in front of the ray's origin)",
            "Um raio que encontra uma esfera (a mais próxima das suas duas interseções, à \
             frente da origem do raio)";
        /// `new --kind secondary`.
        KindSecondary =>
            "A ray meeting a plane whose material reflects (O_r) and transmits (O_t, η), with \
             the render settings' maximum level and minimum weight: the local colour, then the \
             reflected ray R_V (Eq. 4.17) and the transmitted ray (Snell's law), each with its \
             level and weight, and whether it is traced (Section 4.4)",
            "Um raio que encontra um plano cujo material reflete (O_r) e transmite (O_t, η), \
             com o nível máximo e o peso mínimo das configurações de renderização: a cor local, \
             depois o raio de reflexão R_V (Eq. 4.17) e o raio de transmissão (lei de Snell), cada \
             um com o seu nível e o seu peso, e se ele é traçado (Seção 4.4)";
        /// `tradeoff --metric max-abs`.
        MetricMaxAbs =>
            "The largest error of any channel of any pixel (0–1 scale)",
            "O maior erro de qualquer canal de qualquer pixel (escala 0–1)";
        /// `tradeoff --metric rmse`.
        MetricRmse =>
            "The root mean square error over every channel (0–1 scale)",
            "A raiz do erro quadrático médio sobre todos os canais (escala 0–1)";
        /// `tradeoff --metric pixels-differ`.
        MetricPixelsDiffer =>
            "The share of pixels whose 8-bit colour differs (0–1)",
            "A fração dos pixels cuja cor de 8 bits difere (0–1)";
    }
}

/// A `ValueEnum` whose values have help: each value's, `None` for a value without help.
pub(crate) trait Described: ValueEnum + Clone + Send + Sync + 'static {
    /// The help of this value.
    fn help(&self) -> Option<ValueHelp>;
}

impl Described for Lang {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Lang::En => ValueHelp::LangEn,
            Lang::Pt => ValueHelp::LangPt,
        })
    }
}

impl Described for ColorChoice {
    fn help(&self) -> Option<ValueHelp> {
        match self {
            ColorChoice::Auto => Some(ValueHelp::ColorAuto),
            ColorChoice::Always | ColorChoice::Never => None,
        }
    }
}

impl Described for Contents {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Contents::Statement => ValueHelp::PartStatement,
            Contents::Solution => ValueHelp::PartSolution,
            Contents::Key => ValueHelp::PartKey,
            Contents::All => ValueHelp::PartAll,
        })
    }
}

impl Described for Engine {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Engine::Scalar => ValueHelp::EngineScalar,
            Engine::Wide => ValueHelp::EngineWide,
        })
    }
}

impl Described for Scale {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Scale::Unit => ValueHelp::ScaleUnit,
            Scale::Bits8 => ValueHelp::Scale255,
        })
    }
}

impl Described for CheckFormat {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            CheckFormat::Text => ValueHelp::CheckText,
            CheckFormat::Json => ValueHelp::CheckJson,
            CheckFormat::Html => ValueHelp::CheckHtml,
            CheckFormat::Markdown => ValueHelp::CheckMarkdown,
        })
    }
}

impl Described for Duplicates {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Duplicates::First => ValueHelp::DuplicatesFirst,
            Duplicates::Last => ValueHelp::DuplicatesLast,
            Duplicates::Best => ValueHelp::DuplicatesBest,
        })
    }
}

impl Described for Input {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Input::Auto => ValueHelp::InputAuto,
            Input::Csv => ValueHelp::InputCsv,
            Input::Moodle => ValueHelp::InputMoodle,
        })
    }
}

impl Described for Kind {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Kind::Ambient => ValueHelp::KindAmbient,
            Kind::Point => ValueHelp::KindPoint,
            Kind::RayPlane => ValueHelp::KindRayPlane,
            Kind::Directional => ValueHelp::KindDirectional,
            Kind::Spot => ValueHelp::KindSpot,
            Kind::Several => ValueHelp::KindSeveral,
            Kind::Sphere => ValueHelp::KindSphere,
            Kind::Secondary => ValueHelp::KindSecondary,
        })
    }
}

impl Described for Metric {
    fn help(&self) -> Option<ValueHelp> {
        Some(match self {
            Metric::MaxAbs => ValueHelp::MetricMaxAbs,
            Metric::Rmse => ValueHelp::MetricRmse,
            Metric::PixelsDiffer => ValueHelp::MetricPixelsDiffer,
        })
    }
}

/// Values of `E` read as clap reads a `ValueEnum` ([`EnumValueParser`]), listed with their help
/// in `lang`.
struct Values<E> {
    lang: Lang,
    of: PhantomData<fn() -> E>,
}

impl<E> Clone for Values<E> {
    fn clone(&self) -> Self {
        Values {
            lang: self.lang,
            of: PhantomData,
        }
    }
}

impl<E: Described> TypedValueParser for Values<E> {
    type Value = E;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<E, clap::Error> {
        EnumValueParser::<E>::new().parse_ref(cmd, arg, value)
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(E::value_variants().iter().filter_map(|v| {
            let value = v.to_possible_value()?;
            Some(match v.help() {
                Some(help) => value.help(help.text(self.lang)),
                None => value,
            })
        })))
    }
}

/// `arg` with its values' help in `lang`, when its values are of a [`Described`] enum; else
/// `arg` as it is.
pub(crate) fn described(arg: Arg, lang: Lang) -> Arg {
    fn values<E: Described>(lang: Lang) -> (TypeId, ValueParser) {
        (
            TypeId::of::<E>(),
            ValueParser::new(Values::<E> {
                lang,
                of: PhantomData,
            }),
        )
    }
    let parsers = [
        values::<Lang>(lang),
        values::<ColorChoice>(lang),
        values::<Contents>(lang),
        values::<Engine>(lang),
        values::<Scale>(lang),
        values::<CheckFormat>(lang),
        values::<Duplicates>(lang),
        values::<Input>(lang),
        values::<Kind>(lang),
        values::<Metric>(lang),
    ];
    let id = arg.get_value_parser().type_id();
    match parsers.into_iter().find(|(type_id, _)| id == *type_id) {
        Some((_, parser)) => arg.value_parser(parser),
        None => arg,
    }
}
