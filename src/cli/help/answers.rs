//! The help of the commands that judge answers (`super::super::args::answers`): `phong check`,
//! `phong grade` and `phong policy`.

use super::{Part, Texts};

crate::messages! {
    /// The help of `phong check`, `phong grade` and `phong policy`, and of their arguments.
    pub(crate) enum AnswersHelp {
        /// `phong check`.
        Check =>
            "Check an answer (or each file's answer key) and name the slips behind a wrong one",
            "Confere uma resposta (ou o gabarito de cada arquivo) e nomeia os erros por trás de \
             uma resposta errada";
        /// `check FILE...`.
        CheckFiles =>
            "Problem files (JSON). Without --answer, each file's answer key is checked",
            "Arquivos de problema (JSON). Sem --answer, confere-se o gabarito de cada arquivo";
        /// `check --answer`.
        CheckAnswer =>
            "The answer to check: \"0.52 0.03 0\", \"(0.52, 0.03, 0)\", \"[0.52; 0.03; 0]\", \
             \"#RRGGBB\", or three integers 0–255 with --scale 255. Only with one FILE",
            "A resposta a conferir: \"0.52 0.03 0\", \"(0.52, 0.03, 0)\", \"[0.52; 0.03; 0]\", \
             \"#RRGGBB\", ou três inteiros de 0 a 255 com --scale 255. Só com um FILE";
        /// `check --scale`.
        CheckScale =>
            "The answer's scale: 1 (components on [0, 1]) or 255 (8-bit integers). \"#RRGGBB\" \
             is 255 [default: 1, but three whole numbers 0–255, one above 1, are read as 8-bit \
             values unless the course policy says \"eight_bit\": \"hint\"]",
            "A escala da resposta: 1 (componentes em [0, 1]) ou 255 (inteiros de 8 bits). \
             \"#RRGGBB\" é 255 [padrão: 1, mas três números inteiros de 0 a 255, um deles acima \
             de 1, são lidos como valores de 8 bits, a menos que a política do curso diga \
             \"eight_bit\": \"hint\"]";
        /// `check --tolerance`.
        CheckTolerance =>
            "The largest difference accepted per channel, on the answer's scale [default: the \
             key's own, else the course policy's: 0.005 on the 0–1 scale, 1 on the 255 scale]",
            "A maior diferença aceita por canal, na escala da resposta [padrão: a do gabarito, \
             senão a da política do curso: 0.005 na escala 0–1, 1 na escala 255]";
        /// `--strict` of check and grade.
        Strict =>
            "Accept only the problem as written, not its likely intended reading (over the \
             course policy's \"strict\")",
            "Aceita só o problema como enunciado, não a sua leitura provavelmente pretendida \
             (acima do \"strict\" da política do curso)";
        /// `--policy` of check, grade and policy.
        Policy =>
            "The course policy (JSON: tolerances, the reading's credit, 8-bit answers, the \
             words for \"no hit\", points; docs/course-policy.md) [default: course-policy.json \
             in the exercises' folder, else the defaults]",
            "A política do curso (JSON: tolerâncias, o crédito da leitura, respostas de 8 bits, \
             as palavras para \"no hit\", pontos; docs/course-policy.md) [padrão: \
             course-policy.json na pasta dos exercícios, senão os padrões]";
        /// `check --step`; `names`: every step's name, as the check reads them.
        CheckStep { names: String } =>
            "Check an intermediate step, NAME=VALUE (repeatable): cos_theta=0.98995, \
             R=0.6,0,0.8, cos_theta[1]=0.5 for lights[1]. Names: {names}. Only with one FILE",
            "Confere um passo intermediário, NAME=VALUE (pode se repetir): cos_theta=0.98995, \
             R=0.6,0,0.8, cos_theta[1]=0.5 para lights[1]. Nomes: {names}. Só com um FILE";
        /// `check --steps`.
        CheckSteps =>
            "Check the steps in a JSON file: {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, 0.8]}}. \
             Only with one FILE",
            "Confere os passos de um arquivo JSON: {{\"cos_theta\": 0.98995, \"R\": [0.6, 0, \
             0.8]}}. Só com um FILE";
        /// `check --slips`.
        CheckSlips =>
            "Instead of checking an answer, list what each applicable slip (and pair) gives",
            "Em vez de conferir uma resposta, lista o que dá cada erro aplicável (e cada par de \
             erros)";
        /// `check --format`.
        CheckFormat =>
            "Output format: text for people, json for scripts (stable field names, \
             format_version), html for a browser (the colours as swatches, each slip linked to \
             its step of the worked solution), markdown for notes",
            "Formato da saída: text para pessoas, json para scripts (nomes de campos estáveis, \
             format_version), html para um navegador (as cores como amostras, cada erro ligado \
             ao seu passo da resolução), markdown para notas";
        /// `check --lang`.
        CheckLang => "Language of the text output.", "Idioma da saída em texto.";
        /// `check --output`.
        CheckOutput =>
            "Write the output to this file (atomically) instead of standard output",
            "Escreve a saída neste arquivo (atomicamente) em vez da saída padrão";
        /// `phong grade`.
        Grade =>
            "Grade a CSV of answers (student, exercise, answer): one verdict per row, a summary \
             per exercise",
            "Corrige um CSV de respostas (aluno, exercício, resposta): um veredito por linha, \
             um resumo por exercício";
        /// `grade SUBMISSIONS`.
        GradeSubmissions =>
            "The submissions: a CSV file (or - for standard input) with the columns student, \
             exercise, answer, separated by commas, semicolons or tabs; a first row that names \
             the three columns (student|aluno|estudante, exercise|exercicio|questao, \
             answer|resposta) is a header, and may name a fourth, steps|passos, of step answers \
             such as \"cos_theta=0.98995; n_dot_l=-0.98995\" (judged as check --step judges \
             them; they change no points)",
            "As respostas entregues: um arquivo CSV (ou - para a entrada padrão) com as colunas \
             aluno, exercício, resposta, separadas por vírgulas, pontos e vírgulas ou \
             tabulações; uma primeira linha que nomeia as três colunas (student|aluno|estudante, \
             exercise|exercicio|questao, answer|resposta) é um cabeçalho, e pode nomear uma \
             quarta, steps|passos, de respostas de passos como \"cos_theta=0.98995; \
             n_dot_l=-0.98995\" (julgadas como check --step as julga; não mudam os pontos)";
        /// `grade --delimiter`.
        GradeDelimiter =>
            "The separator of the submissions' fields: `,`, `;` or `tab` [default: detected \
             from the first rows]",
            "O separador dos campos das respostas: `,`, `;` ou `tab` [padrão: detectado pelas \
             primeiras linhas]";
        /// `grade --exercises`.
        GradeExercises =>
            "The folder of exercise files: exercise \"4.2\" is DIR/4.2.json",
            "A pasta dos arquivos de exercício: o exercício \"4.2\" é DIR/4.2.json";
        /// `grade --format`.
        GradeFormat =>
            "Report format: one CSV line per input row; JSON with the rows, the summary and the \
             students' totals; Gradescope's results.json (one student: the file; several: an \
             object keyed by student, or one file per student with -o DIR/); JUnit XML (a \
             testsuite per student, a testcase per exercise); xlsx, a workbook for Excel or \
             LibreOffice (sheets of the answers, the students' totals and a summary; numbers as \
             numbers, headers in --lang; give -o FILE.xlsx)",
            "Formato do relatório: uma linha CSV por linha da entrada; JSON com as linhas, o \
             resumo e os totais dos alunos; o results.json do Gradescope (um aluno: o arquivo; \
             vários: um objeto com uma chave por aluno, ou um arquivo por aluno com -o DIR/); \
             JUnit XML (uma testsuite por aluno, um testcase por exercício); xlsx, uma pasta de \
             trabalho para o Excel ou o LibreOffice (planilhas das respostas, dos totais dos \
             alunos e de um resumo; números como números, cabeçalhos no idioma de --lang; dê \
             -o FILE.xlsx)";
        /// `grade --scale`.
        GradeScale =>
            "The scale of answers that are not \"#RRGGBB\" [default: 0–1, but a row of three \
             whole numbers 0–255, one above 1, is read as 8-bit, and its feedback says so, \
             unless the course policy says \"eight_bit\": \"hint\"]",
            "A escala das respostas que não são \"#RRGGBB\" [padrão: 0–1, mas uma linha de três \
             números inteiros de 0 a 255, um deles acima de 1, é lida como 8 bits, e o seu \
             feedback o diz, a menos que a política do curso diga \"eight_bit\": \"hint\"]";
        /// `grade --points`.
        GradePoints =>
            "Points per exercise, e.g. 4.1=1,4.2=2 (over the course policy's) [default: the \
             policy's, else 1 each]",
            "Pontos por exercício, por exemplo 4.1=1,4.2=2 (acima dos da política do curso) \
             [padrão: os da política, senão 1 cada]";
        /// `grade --reading-credit`.
        GradeReadingCredit =>
            "The share of an exercise's points an answer in its likely intended reading earns, \
             0 to 1 (over the course policy's) [default: the policy's, else 0.5; nothing under \
             --strict]",
            "A parte dos pontos de um exercício que ganha uma resposta na leitura provavelmente \
             pretendida, de 0 a 1 (acima da política do curso) [padrão: a da política, senão \
             0.5; nada com --strict]";
        /// `grade --duplicates`.
        GradeDuplicates =>
            "Which answer counts when a student answers an exercise more than once (the others \
             stay in the report with counted false) [default: the course policy's, else last]",
            "Qual resposta conta quando um aluno responde a um exercício mais de uma vez (as \
             outras ficam no relatório com counted false) [padrão: a da política do curso, \
             senão last]";
        /// `grade --by-student`.
        GradeByStudent =>
            "Also write each student's total as CSV to this file (student, points, max_points, \
             then one column per exercise)",
            "Escreve também o total de cada aluno como CSV neste arquivo (student, points, \
             max_points, depois uma coluna por exercício)";
        /// `grade --lang`.
        GradeLang =>
            "Language of the feedback column and of the platforms' reports.",
            "Idioma da coluna de feedback e dos relatórios das plataformas.";
        /// `grade --input`.
        GradeInput =>
            "What the submissions are: the plain CSV, or Moodle's quiz Responses report \
             downloaded as CSV (\"Response 1\", …; Cloze parts \"part 1: …; part 2: …; part 3: \
             …\") [default: detected from the header]",
            "O que são as respostas entregues: o CSV simples, ou o relatório de respostas \
             (Responses) do questionário do Moodle baixado como CSV (\"Response 1\", …; partes \
             Cloze \"part 1: …; part 2: …; part 3: …\") [padrão: detectado pelo cabeçalho]";
        /// `grade --questions`.
        GradeQuestions =>
            "A Moodle export's question slots, in order: slot N is the N-th exercise [default: \
             the exercise files of --exercises in name order]",
            "As posições das questões de uma exportação do Moodle, em ordem: a posição N é o \
             N-ésimo exercício [padrão: os arquivos de exercício de --exercises em ordem de \
             nome]";
        /// `grade --tolerance`.
        GradeTolerance =>
            "The largest difference accepted per channel [default: each exercise key's own, \
             else the course policy's: 0.005 on the 0–1 scale, 1 on the 255 scale]",
            "A maior diferença aceita por canal [padrão: a do gabarito de cada exercício, senão \
             a da política do curso: 0.005 na escala 0–1, 1 na escala 255]";
        /// `grade --output`.
        GradeOutput =>
            "Write the report to this file (atomically) instead of standard output",
            "Escreve o relatório neste arquivo (atomicamente) em vez da saída padrão";
        /// `grade --class-report`.
        GradeClassReport =>
            "Also write what the class got wrong as a page (HTML, in --lang): per exercise, the \
             answers right, by the reading, each slip named with its count, the unnamed wrong \
             ones and the unreadable ones, and a histogram of the students' totals",
            "Escreve também numa página (HTML, no idioma de --lang) o que a turma errou: por \
             exercício, as respostas certas, as certas pela leitura, cada erro nomeado com a sua \
             contagem, as erradas sem erro nomeado e as ilegíveis, e um histograma dos totais \
             dos alunos";
        /// `grade --summary`.
        GradeSummary =>
            "Also write the summary per exercise as CSV to this file (atomically)",
            "Escreve também o resumo por exercício como CSV neste arquivo (atomicamente)";
        /// `phong policy`.
        PolicyCmd =>
            "Print the course policy in force (tolerances, the reading's credit, 8-bit answers, \
             the words for \"no hit\", points, duplicates) as a policy file writes it: the \
             folder's course-policy.json over the defaults. `phong policy > \
             exercises/course-policy.json` starts one",
            "Mostra a política do curso em vigor (tolerâncias, o crédito da leitura, respostas \
             de 8 bits, as palavras para \"no hit\", pontos, respostas repetidas) como um \
             arquivo de política a escreve: o course-policy.json da pasta sobre os padrões. \
             `phong policy > exercises/course-policy.json` começa um";
        /// `policy DIR`.
        PolicyFolder =>
            "The exercises' folder whose course-policy.json is read [default: the current \
             folder]",
            "A pasta dos exercícios cujo course-policy.json é lido [padrão: a pasta atual]";
        /// `policy --output`.
        PolicyOutput =>
            "Write the policy to this file (atomically) instead of standard output",
            "Escreve a política neste arquivo (atomicamente) em vez da saída padrão";
        /// `policy --lang`.
        PolicyLang =>
            "Language of the errors (the policy file is the same in either).",
            "Idioma dos erros (o arquivo de política é o mesmo nos dois).";
    }
}

/// The help of `part` of `command`, for the commands of this family.
pub(super) fn of(command: &str, part: Part<'_>) -> Option<Texts> {
    use AnswersHelp as H;
    use Part::{About, Arg};
    Some(match (command, part) {
        ("check" | "grade", Arg("strict")) => Texts::new(H::Strict),
        ("check" | "grade" | "policy", Arg("policy")) => Texts::new(H::Policy),
        ("check", About) => Texts::new(H::Check),
        ("check", Arg("files")) => Texts::new(H::CheckFiles),
        ("check", Arg("answer")) => Texts::new(H::CheckAnswer),
        ("check", Arg("scale")) => Texts::new(H::CheckScale),
        ("check", Arg("tolerance")) => Texts::new(H::CheckTolerance),
        ("check", Arg("step")) => Texts::new(H::CheckStep {
            names: crate::check::steps::step_names(),
        }),
        ("check", Arg("steps")) => Texts::new(H::CheckSteps),
        ("check", Arg("slips")) => Texts::new(H::CheckSlips),
        ("check", Arg("format")) => Texts::new(H::CheckFormat),
        ("check", Arg("lang")) => Texts::lang(H::CheckLang),
        ("check", Arg("output")) => Texts::new(H::CheckOutput),
        ("grade", About) => Texts::new(H::Grade),
        ("grade", Arg("submissions")) => Texts::new(H::GradeSubmissions),
        ("grade", Arg("delimiter")) => Texts::new(H::GradeDelimiter),
        ("grade", Arg("exercises")) => Texts::new(H::GradeExercises),
        ("grade", Arg("format")) => Texts::new(H::GradeFormat),
        ("grade", Arg("scale")) => Texts::new(H::GradeScale),
        ("grade", Arg("points")) => Texts::new(H::GradePoints),
        ("grade", Arg("reading_credit")) => Texts::new(H::GradeReadingCredit),
        ("grade", Arg("duplicates")) => Texts::new(H::GradeDuplicates),
        ("grade", Arg("by_student")) => Texts::new(H::GradeByStudent),
        ("grade", Arg("lang")) => Texts::lang(H::GradeLang),
        ("grade", Arg("input")) => Texts::new(H::GradeInput),
        ("grade", Arg("questions")) => Texts::new(H::GradeQuestions),
        ("grade", Arg("tolerance")) => Texts::new(H::GradeTolerance),
        ("grade", Arg("output")) => Texts::new(H::GradeOutput),
        ("grade", Arg("class_report")) => Texts::new(H::GradeClassReport),
        ("grade", Arg("summary")) => Texts::new(H::GradeSummary),
        ("policy", About) => Texts::new(H::PolicyCmd),
        ("policy", Arg("folder")) => Texts::new(H::PolicyFolder),
        ("policy", Arg("output")) => Texts::new(H::PolicyOutput),
        ("policy", Arg("lang")) => Texts::lang(H::PolicyLang),
        _ => return None,
    })
}
