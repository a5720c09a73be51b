//! Why a row of `phong grade` is not graded, or a note on how it was read, as values
//! (crate::text, [`crate::messages!`], [`crate::faults!`]): the `reason` column and the JSON
//! say them in English, the feedback column and the platforms' reports in `--lang`.

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

use crate::problem::error::what_and_fix;
use crate::problem::reading::Cause;
use crate::problem::ProblemError;
use crate::text::{Lang, Message, Said, Show};
use crate::{faults, messages};

/// A column of the submissions: `student` in English (the column's name), `do aluno` in
/// Portuguese (after `o campo`, `a coluna`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Column {
    /// Who answered.
    #[default]
    Student,
    /// The exercise answered.
    Exercise,
    /// The colour answered.
    Answer,
    /// The steps given.
    Steps,
}

impl Column {
    /// The columns in the order of a row.
    pub const ALL: [Column; 4] = [
        Column::Student,
        Column::Exercise,
        Column::Answer,
        Column::Steps,
    ];

    /// The column's name, as the reports and a header name it.
    pub fn name(self) -> &'static str {
        match self {
            Column::Student => "student",
            Column::Exercise => "exercise",
            Column::Answer => "answer",
            Column::Steps => "steps",
        }
    }
}

impl Show for Column {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match lang {
            Lang::En => self.name(),
            Lang::Pt => match self {
                Column::Student => "do aluno",
                Column::Exercise => "do exercício",
                Column::Answer => "da resposta",
                Column::Steps => "dos passos",
            },
        })
    }
}

/// A number of fields: `1 field`, `5 fields` (`1 campo`, `5 campos`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Fields(pub usize);

impl Show for Fields {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.0;
        match (lang, n) {
            (Lang::En, 1) => f.write_str("1 field"),
            (Lang::En, _) => write!(f, "{n} fields"),
            (Lang::Pt, 1) => f.write_str("1 campo"),
            (Lang::Pt, _) => write!(f, "{n} campos"),
        }
    }
}

/// The fields a row should have: 3 (student, exercise, answer), or 4 with the steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Width {
    /// The file has a steps column.
    pub steps: bool,
}

impl Show for Width {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match (lang, self.steps) {
            (Lang::En, false) => "3 (student, exercise, answer)",
            (Lang::En, true) => "4 (student, exercise, answer, steps)",
            (Lang::Pt, false) => "3 (aluno, exercício, resposta)",
            (Lang::Pt, true) => "4 (aluno, exercício, resposta, passos)",
        })
    }
}

/// A separator of fields, named: `','`, `';'`, or a tab character (`uma tabulação`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sep(pub u8);

impl Default for Sep {
    fn default() -> Self {
        Sep(b',')
    }
}

impl Show for Sep {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.0, lang) {
            (b'\t', Lang::En) => f.write_str("a tab character"),
            (b'\t', Lang::Pt) => f.write_str("uma tabulação"),
            (d, _) => write!(f, "'{}'", d as char),
        }
    }
}

messages! {
    /// Why a line's fields cannot be read as CSV.
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum NotCsv {
        /// A quote that does not close on its line.
        Unclosed { field: usize } =>
            "field {field} opens a quote \" that is not closed on its line (a row is one line)",
            "o campo {field} abre aspas \" que não se fecham na sua linha (cada linha é uma \
             resposta)";
        /// Text after a closing quote (its first characters).
        AfterQuote { field: usize, after: String } =>
            "field {field} has text after its closing quote (\"{after}\"): quote the whole \
             field, with \"\" for a quote inside",
            "o campo {field} tem texto depois das aspas que o fecham (\"{after}\"): ponha o \
             campo inteiro entre aspas, com \"\" para aspas dentro";
        /// A quoted field holding a line break: its quote closes on line `last`.
        LineBreak { field: usize, last: u64 } =>
            "field {field} is a quoted cell holding a line break (its quote closes on line \
             {last}), and a row is one line, so neither this line nor the ones up to line \
             {last} is a row. Fix: remove the line break from the cell (typed with Alt+Enter in \
             a spreadsheet)",
            "o campo {field} é uma célula entre aspas com uma quebra de linha (as aspas se \
             fecham na linha {last}), e cada linha é uma resposta, então nem esta linha nem as \
             seguintes até a linha {last} são respostas. Correção: tire a quebra de linha da \
             célula (digitada com Alt+Enter numa planilha)";
        /// The rest of a quoted field of an earlier line that holds a line break.
        Continues { field: usize, line: u64 } =>
            "this line is the rest of field {field} of line {line}, a quoted cell holding a \
             line break, not a row of its own. Fix: remove the line break from that cell",
            "esta linha é o resto do campo {field} da linha {line}, uma célula entre aspas com \
             uma quebra de linha, e não uma resposta. Correção: tire a quebra de linha dessa \
             célula";
        /// A quote left alone in a field that does not start with one.
        StrayQuote { field: usize } =>
            "field {field} holds a quote \" that pairs with none and does not start the field \
             (what is left of a cell cut at a line break, or a quote typed by mistake). Fix: \
             remove it, or quote the whole field with \"\" for a quote inside",
            "o campo {field} tem aspas \" que não formam par e não abrem o campo (o resto de \
             uma célula cortada numa quebra de linha, ou aspas digitadas por engano). \
             Correção: tire-as, ou ponha o campo inteiro entre aspas, com \"\" para aspas \
             dentro";
    }
}

impl NotCsv {
    /// The field (from 1) that cannot be read; the cells before it are whole. A line that is
    /// the rest of another line's field has none: 0.
    pub fn field(&self) -> usize {
        match self {
            NotCsv::Unclosed { field }
            | NotCsv::AfterQuote { field, .. }
            | NotCsv::LineBreak { field, .. }
            | NotCsv::StrayQuote { field } => *field,
            NotCsv::Continues { .. } => 0,
        }
    }
}

impl Default for NotCsv {
    fn default() -> Self {
        NotCsv::Unclosed { field: 1 }
    }
}

messages! {
    /// What a row of another number of fields tells of the file.
    #[allow(missing_docs)] // each field is named by its sentences
    #[derive(Default)]
    pub enum FieldsHint {
        /// Nothing more to say.
        #[default]
        Nothing => "", "";
        /// The row holds another separator than the file's.
        OtherSeparator { read: Sep, found: Sep, flag: String } =>
            "; the fields are read as separated by {read}, and this row has {found}: give \
             --delimiter {flag}",
            "; os campos são lidos como separados por {read}, e esta linha tem {found}: dê \
             --delimiter {flag}";
        /// Too many fields in a file of three columns: an answer not quoted.
        QuoteAnswer { sep: Sep } =>
            "; an answer written with {sep} must be quoted: \"0.52, 0.03, 0\"",
            "; uma resposta escrita com {sep} deve vir entre aspas: \"0.52, 0.03, 0\"";
        /// Too many fields in a file with steps: an answer or a steps cell not quoted.
        QuoteAnswerOrSteps { sep: Sep } =>
            "; an answer or a steps cell written with {sep} must be quoted: \"0.52, 0.03, 0\"",
            "; uma resposta ou uma célula de passos escrita com {sep} deve vir entre aspas: \
             \"0.52, 0.03, 0\"";
    }
}

messages! {
    /// Why a row of the submissions cannot be judged (what its line holds).
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum RowReason {
        /// The line is not CSV.
        NotCsv { why: NotCsv } =>
            "the row cannot be read as CSV: {why}",
            "a linha não pode ser lida como CSV: {why}";
        /// Another number of fields.
        Fields { count: Fields, expected: Width, hint: FieldsHint } =>
            "the row has {count}, expected {expected}{hint}",
            "a linha tem {count}, e são esperados {expected}{hint}";
        /// A field that is not UTF-8.
        NotUtf8 { column: Column } =>
            "the {column} field is not valid UTF-8",
            "o campo {column} não é UTF-8 válido";
        /// A field with a NUL byte.
        Nul { column: Column } =>
            "the {column} field holds a NUL byte (shown as U+FFFD): is the file UTF-16 without \
             a byte order mark? Save it as UTF-8 (CSV UTF-8 in a spreadsheet)",
            "o campo {column} tem um byte NUL (mostrado como U+FFFD): o arquivo é UTF-16 sem \
             marca de ordem de bytes? Salve-o como UTF-8 (CSV UTF-8 numa planilha)";
        /// An empty field.
        Empty { column: Column } =>
            "the {column} field is empty",
            "o campo {column} está vazio";
        /// An answer that cannot be read.
        Answer { why: Said } =>
            "the answer cannot be read: {why}",
            "a resposta não pode ser lida: {why}";
        /// A steps cell that cannot be read or judged.
        Steps { row: usize, line: u64, column: String, why: Said } =>
            "the steps of row {row} (line {line}, column \"{column}\"): {why}",
            "os passos da resposta {row} (linha {line}, coluna \"{column}\"): {why}";
    }
}

faults! {
    /// Why the exercise a row names cannot be graded against (before its file is read).
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum ExerciseFault {
        /// No such exercise file.
        Unknown { file: String, dir: PathBuf } =>
            "unknown exercise: there is no {file} in the exercises folder {dir}",
            "exercício desconhecido: não há {file} na pasta de exercícios {dir}";
            fix "name an exercise by its file name without .json (e.g. 4.2 for {dir}/4.2.json)",
                "dê o nome do arquivo do exercício sem .json (por exemplo 4.2 para \
                 {dir}/4.2.json)";
        /// A link that cannot be followed.
        CannotFollow { path: PathBuf, cause: Cause } =>
            "{path}: the exercise file cannot be followed: {cause}",
            "{path}: o arquivo do exercício não pode ser seguido: {cause}";
            fix "replace the link by the file", "troque o link pelo arquivo";
        /// A link out of the folder.
        LinkOut { path: PathBuf, real: PathBuf, dir: PathBuf } =>
            "{path}: the exercise file is a link out of the exercises folder (to {real}), which \
             is refused",
            "{path}: o arquivo do exercício é um link para fora da pasta de exercícios (para \
             {real}), o que é recusado";
            fix "copy the file into {dir}", "copie o arquivo para {dir}";
        /// A folder, a FIFO or a device.
        NotRegular { path: PathBuf } =>
            "{path}: the exercise is not a regular file (a folder, a FIFO or a device)",
            "{path}: o exercício não é um arquivo comum (uma pasta, um FIFO ou um dispositivo)";
            fix "put the exercise's problem file there",
                "ponha ali o arquivo de problema do exercício";
    }
}

faults! {
    /// A first line of column names that is not a header phong can read.
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum HeaderFault {
        /// A column named twice.
        Twice { column: Column } =>
            "the header names the {column} column twice",
            "o cabeçalho nomeia duas vezes a coluna {column}";
            fix "name the columns `student` (or `aluno`), `exercise` (`exercício`) and `answer` \
                 (`resposta`), and, if the rows give steps, `steps` (`passos`), each once, in \
                 any order",
                "nomeie as colunas `aluno` (ou `student`), `exercício` (`exercise`) e \
                 `resposta` (`answer`) e, se as linhas dão passos, `passos` (`steps`), cada uma \
                 uma vez, em qualquer ordem";
        /// A column missing.
        Missing { column: Column } =>
            "the header names no {column} column",
            "o cabeçalho não tem a coluna {column}";
            fix "name the columns `student` (or `aluno`), `exercise` (`exercício`) and `answer` \
                 (`resposta`), and, if the rows give steps, `steps` (`passos`), each once, in \
                 any order",
                "nomeie as colunas `aluno` (ou `student`), `exercício` (`exercise`) e \
                 `resposta` (`answer`) e, se as linhas dão passos, `passos` (`steps`), cada uma \
                 uma vez, em qualquer ordem";
    }
}

messages! {
    /// How a graded row's exercise was read: written with a decimal comma.
    #[allow(missing_docs)] // each field is named by its sentences
    pub enum ExerciseNote {
        /// `4,1` read as 4.1.
        Comma { written: String, point: String } =>
            "the exercise is written \"{written}\", read as {point} (a decimal comma, as a \
             spreadsheet writes the number {point}; write {point} with a point to be sure)",
            "o exercício está escrito \"{written}\", lido como {point} (uma vírgula decimal, \
             como uma planilha escreve o número {point}; escreva {point} com ponto para ter \
             certeza)";
    }
}

/// A note on how a graded row's answer was judged (the sentences of `phong check`, in
/// super::super::messages).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnswerNote {
    /// 0–1 numbers that look like 8-bit values.
    Looks8bit,
    /// Whole numbers read as 8-bit values (per-row scale detection).
    ReadAs8bit,
    /// Accepted as the colour before clamping.
    Unclamped,
}

impl Message for AnswerNote {
    fn text(&self, lang: Lang) -> String {
        use crate::check::messages;
        match self {
            AnswerNote::Looks8bit => messages::looks_8bit(lang),
            AnswerNote::ReadAs8bit => messages::read_as_8bit(lang),
            AnswerNote::Unclamped => messages::unclamped_note(lang),
        }
        .to_owned()
    }
}

/// Why a row is invalid, or a note on how a graded row was read: a value, said in English in
/// the `reason` column and the JSON (its `Display` and its serialisation), in `--lang` in the
/// feedback.
#[derive(Clone, Debug)]
pub enum Reason {
    /// What the row's line holds.
    Row(RowReason),
    /// The exercise named cannot be found or followed (`WHAT. Fix: FIX`).
    Exercise(ExerciseFault),
    /// The exercise's file cannot be read, or is not a valid problem, or its steps cannot be
    /// solved.
    Problem(Arc<ProblemError>),
    /// The first line names the columns but is not a header phong reads (`WHAT. Fix: FIX`).
    Header(HeaderFault),
    /// The Moodle export cannot be read.
    Moodle(super::super::moodle::MoodleError),
    /// A Cloze response with blank parts: the note of a row judged wrong (incomplete), or why
    /// a row whose every part is blank is invalid.
    Cloze(super::super::moodle::Blank),
    /// A graded row's notes: its exercise written with a decimal comma, then how its answer
    /// was judged (`NOTE; NOTE`).
    Note {
        /// The exercise written with a decimal comma.
        exercise: Option<ExerciseNote>,
        /// How the answer was judged.
        answer: Option<AnswerNote>,
    },
}

impl Message for Reason {
    fn text(&self, lang: Lang) -> String {
        match self {
            Reason::Row(r) => r.text(lang),
            Reason::Exercise(f) => what_and_fix(f, lang),
            Reason::Problem(e) => e.text(lang),
            Reason::Header(f) => what_and_fix(f, lang),
            Reason::Moodle(m) => m.text(lang),
            Reason::Cloze(b) => b.text(lang),
            Reason::Note { exercise, answer } => {
                let notes: Vec<String> = exercise
                    .iter()
                    .map(|n| n.text(lang))
                    .chain(answer.iter().map(|n| n.text(lang)))
                    .collect();
                notes.join("; ")
            }
        }
    }
}

impl fmt::Display for Reason {
    /// The reason in English, as the `reason` column writes it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text(Lang::En))
    }
}

impl serde::Serialize for Reason {
    /// The reason in English, as a string (the JSON report's `reason`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.text(Lang::En))
    }
}

impl From<RowReason> for Reason {
    fn from(r: RowReason) -> Self {
        Reason::Row(r)
    }
}

impl From<ExerciseFault> for Reason {
    fn from(f: ExerciseFault) -> Self {
        Reason::Exercise(f)
    }
}

impl From<ProblemError> for Reason {
    fn from(e: ProblemError) -> Self {
        Reason::Problem(Arc::new(e))
    }
}

impl From<HeaderFault> for Reason {
    fn from(f: HeaderFault) -> Self {
        Reason::Header(f)
    }
}

impl From<super::super::moodle::MoodleError> for Reason {
    fn from(m: super::super::moodle::MoodleError) -> Self {
        Reason::Moodle(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::moodle::{Given, MoodleError};

    fn both(m: &dyn Message) -> (String, String) {
        (m.text(Lang::En), m.text(Lang::Pt))
    }

    #[test]
    fn a_count_a_separator_and_a_width_are_said_in_each_language() {
        let r = RowReason::Fields {
            count: Fields(1),
            expected: Width { steps: true },
            hint: FieldsHint::OtherSeparator {
                read: Sep(b';'),
                found: Sep(b'\t'),
                flag: "tab".into(),
            },
        };
        assert_eq!(
            both(&r),
            (
                "the row has 1 field, expected 4 (student, exercise, answer, steps); the fields \
                 are read as separated by ';', and this row has a tab character: give \
                 --delimiter tab"
                    .into(),
                "a linha tem 1 campo, e são esperados 4 (aluno, exercício, resposta, passos); os \
                 campos são lidos como separados por ';', e esta linha tem uma tabulação: dê \
                 --delimiter tab"
                    .into()
            )
        );
        let m = MoodleError::TooFewExercises {
            slot: 3,
            given: Given(2),
        };
        assert!(m.text(Lang::En).contains("only 2 exercises are given:"));
        assert!(m.text(Lang::Pt).contains("mas só 2 exercícios são dados:"));
    }

    #[test]
    fn a_reason_wraps_its_fault_and_joins_its_notes() {
        let r = Reason::from(HeaderFault::Missing {
            column: Column::Answer,
        });
        let (en, pt) = both(&r);
        assert!(
            en.starts_with("the header names no answer column. Fix: name the columns"),
            "{en}"
        );
        assert!(
            pt.starts_with("o cabeçalho não tem a coluna da resposta. Correção: nomeie"),
            "{pt}"
        );
        assert_eq!(r.to_string(), en);
        assert_eq!(serde_json::to_value(&r).unwrap(), en.as_str());
        let notes = Reason::Note {
            exercise: Some(ExerciseNote::Comma {
                written: "4,1".into(),
                point: "4.1".into(),
            }),
            answer: Some(AnswerNote::Unclamped),
        };
        let (en, pt) = both(&notes);
        assert!(
            en.ends_with(
                "with a point to be sure); accepted as the colour before clamping; \
                          displayed, it is clamped to [0, 1]"
            ),
            "{en}"
        );
        assert!(
            pt.starts_with("o exercício está escrito \"4,1\", lido como 4.1 (uma vírgula decimal"),
            "{pt}"
        );
        assert!(pt.ends_with("na tela ela é limitada a [0, 1]"), "{pt}");
    }

    #[test]
    fn unreadable_submissions_are_said_whole_in_each_language() {
        let e = crate::check::grade::Unreadable {
            path: "turma.csv".into(),
            source: std::io::Error::from_raw_os_error(2),
        };
        assert_eq!(
            e.to_string(),
            "turma.csv: cannot read the file: No such file or directory (os error 2). Fix: check \
             the path, and that the file exists and is readable"
        );
        assert_eq!(
            e.text(Lang::Pt),
            "turma.csv: não é possível ler o arquivo: arquivo ou pasta inexistente (erro 2 do \
             sistema). Correção: verifique o caminho, e que o arquivo existe e pode ser lido"
        );
        let big = crate::check::grade::Unreadable {
            path: "turma.csv".into(),
            source: std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                crate::problem::TooMany {
                    limit: 1_000_000,
                    what: crate::problem::Counted::Rows,
                },
            ),
        };
        assert_eq!(
            big.to_string(),
            "turma.csv: cannot read the file: it has more than 1000000 rows, the most phong \
             takes. Fix: give a smaller file (the limits are in README, \"Limits and safety\")"
        );
        assert_eq!(
            big.text(Lang::Pt),
            "turma.csv: não é possível ler o arquivo: tem mais de 1000000 linhas, o máximo que \
             phong aceita. Correção: dê um arquivo menor (os limites estão na seção \"Limits and \
             safety\" do README)"
        );
    }
}
