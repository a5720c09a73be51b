//! The help of the commands that write problems and documents
//! (`super::super::args::documents`): `phong solve`, `phong new`, `phong moodle` and
//! `phong schema`.

use super::{Part, Texts};

crate::messages! {
    /// The help of `phong solve`, `phong new`, `phong moodle` and `phong schema`, and of their
    /// arguments.
    pub(crate) enum DocumentsHelp {
        /// `phong solve`.
        Solve =>
            "Solve problem files, printing every intermediate quantity with its equation",
            "Resolve arquivos de problema, mostrando cada grandeza intermediária com a sua \
             equação";
        /// `solve FILE...`.
        SolveFiles =>
            "Problem files (JSON). Each is solved even when another one is bad",
            "Arquivos de problema (JSON). Cada um é resolvido mesmo quando outro é inválido";
        /// `solve --format`.
        SolveFormat =>
            "Output format: text for people (a terminal), markdown, latex or html explanations \
             for notes and course pages, json for scripts (stable field names, format_version)",
            "Formato da saída: text para pessoas (um terminal), explicações em markdown, latex \
             ou html para notas e páginas do curso, json para scripts (nomes de campos \
             estáveis, format_version)";
        /// `solve --lang`.
        SolveLang =>
            "Language of the explanation (text, markdown, latex, html); json is \
             language-neutral.",
            "Idioma da explicação (text, markdown, latex, html); o json não depende do idioma.";
        /// `solve --color`.
        SolveColor =>
            "Colour in the text format: auto (on a terminal, unless NO_COLOR is set), always, \
             never",
            "Cores no formato text: auto (num terminal, a menos que NO_COLOR esteja definida), \
             always (sempre), never (nunca)";
        /// `solve --fragment`.
        SolveFragment =>
            "latex and html only: write the body without the preamble or page around it",
            "Só latex e html: escreve o corpo sem o preâmbulo ou a página em volta dele";
        /// `solve --part`.
        SolvePart =>
            "Which document: statement (the student's handout: numbered statements, the data as \
             a table), solution (the worked solutions), key (one answer-key table), or all three",
            "Qual documento: statement (a lista do aluno: enunciados numerados, os dados em \
             tabela), solution (as resoluções passo a passo), key (uma tabela com o gabarito) \
             ou all, os três";
        /// `solve --course`.
        SolveCourse =>
            "The problem set's course, printed in its header",
            "A disciplina da lista de exercícios, impressa no cabeçalho";
        /// `solve --title`.
        SolveTitle =>
            "The problem set's title, printed in its header (and the HTML page's title)",
            "O título da lista de exercícios, impresso no cabeçalho (e no título da página \
             HTML)";
        /// `solve --date`.
        SolveDate =>
            "The problem set's date, printed in its header as given",
            "A data da lista de exercícios, impressa no cabeçalho como foi dada";
        /// `solve --author`.
        SolveAuthor =>
            "The problem set's author, printed in its header",
            "O autor da lista de exercícios, impresso no cabeçalho";
        /// `solve --output`.
        SolveOutput =>
            "Write the output to this file (atomically) instead of standard output; a folder \
             (an existing one, or a path ending in /) gets one file per exercise, named after it",
            "Escreve a saída neste arquivo (atomicamente) em vez da saída padrão; uma pasta \
             (existente, ou um caminho terminado em /) recebe um arquivo por exercício, com o \
             nome dele";
        /// `phong new`.
        New =>
            "Write fresh problems with numbers friendly to hand calculation, each with its \
             answer key",
            "Escreve problemas novos com números fáceis de calcular à mão, cada um com o seu \
             gabarito";
        /// `new --kind`.
        NewKind => "The kind of problem", "O tipo de problema";
        /// `new --count`.
        NewCount => "How many problems", "Quantos problemas";
        /// `new --seed`.
        NewSeed =>
            "The seed: the same seed, kind and count give the same files, byte for byte",
            "A semente: a mesma semente, o mesmo tipo e a mesma quantidade dão os mesmos \
             arquivos, byte a byte";
        /// `new --output`.
        NewOutput =>
            "Write each problem to DIR/KIND-SEED-I.json (atomically); without it, or with -, \
             print them (one JSON document, or an array for several)",
            "Escreve cada problema em DIR/KIND-SEED-I.json (atomicamente); sem esta opção, ou \
             com -, mostra-os (um documento JSON, ou um array para vários)";
        /// `new --lang`.
        NewLang =>
            "With pt, each problem has its title and question in Portuguese too (`title_pt`, \
             `question_pt`), for `--lang pt` in solve, check and moodle.",
            "Com pt, cada problema tem também o título e o enunciado em português \
             (`title_pt`, `question_pt`), para `--lang pt` em solve, check e moodle.";
        /// `phong moodle`.
        Moodle =>
            "Write problem files (or what `phong new` prints, `-` for standard input) as a \
             Moodle XML quiz: one Cloze question per problem, the slips as 0 % answers, the \
             solution as feedback",
            "Escreve arquivos de problema (ou o que o `phong new` mostra, `-` para a entrada \
             padrão) como um questionário Moodle XML: uma questão Cloze por problema, os erros \
             como respostas de 0 %, a resolução como feedback";
        /// `moodle FILE...`.
        MoodleFiles =>
            "Problem files, each a problem or an array of problems; `-` is standard input",
            "Arquivos de problema, cada um com um problema ou um array de problemas; `-` é a \
             entrada padrão";
        /// `moodle --output`.
        MoodleOutput =>
            "Write the quiz to this file (atomically) instead of standard output",
            "Escreve o questionário neste arquivo (atomicamente) em vez da saída padrão";
        /// `moodle --category`.
        MoodleCategory =>
            "The question bank's category holding one sub-category per file",
            "A categoria do banco de questões que contém uma subcategoria por arquivo";
        /// `moodle --policy`.
        MoodlePolicy =>
            "The course policy the quiz grades by (tolerances, the reading's credit, 8-bit \
             answers, the words for \"no hit\") [default: course-policy.json beside the first \
             FILE, else the defaults]",
            "A política do curso pela qual o questionário dá as notas (tolerâncias, o crédito \
             da leitura, respostas de 8 bits, as palavras para \"no hit\") [padrão: \
             course-policy.json ao lado do primeiro FILE, senão os padrões]";
        /// `moodle --lang`.
        MoodleLang =>
            "Language of the questions, the feedback and the worked solutions.",
            "Idioma das questões, do feedback e das resoluções.";
        /// `phong schema`.
        Schema =>
            "Print the JSON Schema of the problem format",
            "Mostra o JSON Schema do formato de problema";
        /// `schema --output`.
        SchemaOutput =>
            "Write the schema to this file (atomically) instead of standard output",
            "Escreve o schema neste arquivo (atomicamente) em vez da saída padrão";
        /// `schema --lang`.
        SchemaLang =>
            "Language of the errors (the schema is the same in either).",
            "Idioma dos erros (o schema é o mesmo nos dois).";
    }
}

/// The help of `part` of `command`, for the commands of this family.
pub(super) fn of(command: &str, part: Part<'_>) -> Option<Texts> {
    use DocumentsHelp as H;
    use Part::{About, Arg};
    Some(match (command, part) {
        ("solve", About) => Texts::new(H::Solve),
        ("solve", Arg("files")) => Texts::new(H::SolveFiles),
        ("solve", Arg("format")) => Texts::new(H::SolveFormat),
        ("solve", Arg("lang")) => Texts::lang(H::SolveLang),
        ("solve", Arg("color")) => Texts::new(H::SolveColor),
        ("solve", Arg("fragment")) => Texts::new(H::SolveFragment),
        ("solve", Arg("part")) => Texts::new(H::SolvePart),
        ("solve", Arg("course")) => Texts::new(H::SolveCourse),
        ("solve", Arg("title")) => Texts::new(H::SolveTitle),
        ("solve", Arg("date")) => Texts::new(H::SolveDate),
        ("solve", Arg("author")) => Texts::new(H::SolveAuthor),
        ("solve", Arg("output")) => Texts::new(H::SolveOutput),
        ("new", About) => Texts::new(H::New),
        ("new", Arg("kind")) => Texts::new(H::NewKind),
        ("new", Arg("count")) => Texts::new(H::NewCount),
        ("new", Arg("seed")) => Texts::new(H::NewSeed),
        ("new", Arg("output")) => Texts::new(H::NewOutput),
        ("new", Arg("lang")) => Texts::lang(H::NewLang),
        ("moodle", About) => Texts::new(H::Moodle),
        ("moodle", Arg("files")) => Texts::new(H::MoodleFiles),
        ("moodle", Arg("output")) => Texts::new(H::MoodleOutput),
        ("moodle", Arg("category")) => Texts::new(H::MoodleCategory),
        ("moodle", Arg("policy")) => Texts::new(H::MoodlePolicy),
        ("moodle", Arg("lang")) => Texts::lang(H::MoodleLang),
        ("schema", About) => Texts::new(H::Schema),
        ("schema", Arg("output")) => Texts::new(H::SchemaOutput),
        ("schema", Arg("lang")) => Texts::lang(H::SchemaLang),
        _ => return None,
    })
}
