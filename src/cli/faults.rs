//! What the command line says went wrong, in English and Portuguese ([`crate::faults!`],
//! [`crate::messages!`]): flags that do not go together, a flag's value refused after parsing,
//! output that cannot be written, and what the operating system said.

use std::fmt;
use std::path::PathBuf;

use crate::problem::error::what_and_fix;
use crate::text::Said;
use crate::text::{Lang, Show};

crate::faults! {
    /// A flag's value, or flags given together, that the command refuses; and the output files'
    /// own faults.
    pub(crate) enum CliFault {
        /// The largest allocation of a sweep (`phong tradeoff`, whose `--size` sets the image)
        /// that the system cannot give.
        OutOfMemory { size: String } =>
            "out of memory: this needs about {size}",
            "memória insuficiente: isto precisa de cerca de {size}";
            fix "give a smaller image (--size, or the camera's width and height)",
                "dê uma imagem menor (--size, ou a largura e a altura da câmera)";
        /// The image of a render (`phong render`, whose image is the camera's) that the system
        /// cannot give.
        ImageOutOfMemory { size: String } =>
            "out of memory: this needs about {size}",
            "memória insuficiente: isto precisa de cerca de {size}";
            fix "give a smaller image (the camera's \"width\" and \"height\" in the scene file)",
                "dê uma imagem menor (\"width\" e \"height\" da câmera no arquivo da cena)";
        /// An allocation the system refused, anywhere in a run (`cli::memory`): `size` the
        /// amount asked for.
        MemoryRefused { size: String } =>
            "out of memory: the system refused {size} more, so phong stopped; an output file \
             being written was removed, not left half written",
            "memória insuficiente: o sistema recusou mais {size}, então a phong parou; um \
             arquivo de saída sendo escrito foi removido, não ficou escrito pela metade";
            fix "give phong more memory (the shell's ulimit -v, or a larger machine), or split \
                 the input into smaller files",
                "dê mais memória à phong (o ulimit -v do shell, ou uma máquina maior), ou divida \
                 a entrada em arquivos menores";
        /// `--threads 0`.
        ZeroThreads =>
            "0 threads cannot render", "0 threads não renderizam";
            fix "give --threads 1 or more (or leave it out: one per core)",
                "dê --threads 1 ou mais (ou omita: uma por núcleo)";
        /// `--plot` not an SVG file.
        PlotNotSvg { plot: PathBuf } =>
            "{plot} does not end in .svg", "{plot} não termina em .svg";
            fix "name the plot *.svg (it is written as SVG)",
                "dê ao gráfico um nome *.svg (ele é escrito em SVG)";
        /// A sweep that traces too many rays.
        SweepTooLarge { width: u32, height: u32, work: String, most: String } =>
            "the sweep at {width}×{height} is {work} primary rays (the reference, and every \
             setting's samples × --runs), more than the {most} (2^34) a sweep may trace",
            "a varredura em {width}×{height} tem {work} raios primários (a referência, e as \
             amostras × --runs de cada configuração), mais que os {most} (2^34) que uma \
             varredura pode traçar";
            fix "give a smaller --size, fewer --runs, --samples or --reference-samples",
                "dê um --size menor, menos --runs, --samples ou --reference-samples";
        /// A reference whose ray tree grows too large.
        ReferenceTree { level: u32, limit: u64, most: u32 } =>
            "the reference (maximum level {level}, minimum weight 0) would let one sample's ray \
             tree hold more than {limit} rays, since a material of the scene both reflects and \
             transmits and each hit can spawn two rays",
            "a referência (nível máximo {level}, peso mínimo 0) deixaria a árvore de raios de \
             uma amostra ter mais de {limit} raios, pois um material da cena reflete e transmite \
             e cada interseção pode gerar dois raios";
            fix "give --reference-level {most} or lower (the deepest whose tree fits)",
                "dê --reference-level {most} ou menos (o mais profundo cuja árvore cabe)";
        /// `-o` of a render not naming an image format.
        ImageExtension { output: PathBuf } =>
            "{output} does not end in .png or .ppm", "{output} não termina em .png ou .ppm";
            fix "name the image *.png or *.ppm, or give --image-format png|ppm",
                "dê à imagem um nome *.png ou *.ppm, ou dê --image-format png|ppm";
        /// `--explain-pixel` outside the image.
        PixelOutside { x: u32, y: u32, width: u32, height: u32, last_x: u32, last_y: u32 } =>
            "pixel {x},{y} is outside the {width}×{height} image",
            "o pixel {x},{y} está fora da imagem {width}×{height}";
            fix "give X from 0 to {last_x} and Y from 0 to {last_y}",
                "dê X de 0 a {last_x} e Y de 0 a {last_y}";
        /// The file of `--steps` cannot be read.
        StepsUnreadable { file: PathBuf, error: SystemError } =>
            "{file}: cannot read the file: {error}", "{file}: não é possível ler o arquivo: {error}";
            fix "check the path, and that the file exists and is UTF-8 text",
                "confira o caminho, e que o arquivo existe e é texto UTF-8";
        /// A file of `phong moodle` that starts as an array but is not JSON.
        NotProblems { error: crate::problem::JsonError } =>
            "{error}", "{error}";
            fix "give one problem, or an array of problems as `phong new --count N` prints",
                "dê um problema, ou uma lista de problemas como `phong new --count N` a imprime";
        /// A step that cannot be read, with its own fix.
        Step { before: String, why: Said, fix: Said } =>
            "{before}{why}", "{before}{why}";
            fix "{fix}", "{fix}";
        /// A step of `--step` that cannot be read.
        StepFlag { why: Said } =>
            "{why}", "{why}";
            fix "write NAME=VALUE, such as --step cos_theta=0.98995 or --step R=0.6,0,0.8",
                "escreva NOME=VALOR, como --step cos_theta=0.98995 ou --step R=0.6,0,0.8";
        /// The file of `--steps` that cannot be read as steps.
        StepsFile { before: String, why: Said } =>
            "{before}{why}", "{before}{why}";
            fix "one JSON object of names and values, such as {{\"cos_theta\": 0.98995}}",
                "um objeto JSON de nomes e valores, como {{\"cos_theta\": 0.98995}}";
        /// The course policy (`--policy`, or the file beside the exercises) cannot be read.
        PolicyUnreadable { why: Said } =>
            "{why}", "{why}";
            fix "give --policy the path of a course policy file (`phong policy > \
                 course-policy.json` writes one with every field)",
                "dê a --policy o caminho de um arquivo de política do curso (`phong policy > \
                 course-policy.json` escreve um com todos os campos)";
        /// The course policy (`--policy`, or the file beside the exercises) is refused.
        Policy { why: Said } =>
            "{why}", "{why}";
            fix "correct the file as docs/course-policy.md shows (`phong policy` prints the \
                 policy in force, every field with its value)",
                "corrija o arquivo como mostra docs/course-policy.md (`phong policy` imprime a \
                 política em vigor, cada campo com seu valor)";
        /// A reading credit a Moodle quiz cannot give.
        MoodleCredit { credit: crate::text::Num, allowed: String } =>
            "reading_credit: the course gives a likely intended reading {credit} of the points, \
             and Moodle grades an answer only by one of its fractions ({allowed})",
            "reading_credit: o curso dá a uma leitura provavelmente pretendida {credit} dos \
             pontos, e o Moodle avalia uma resposta só por uma de suas frações ({allowed})";
            fix "give the course policy a reading_credit Moodle has, such as 0.5",
                "dê à política do curso um reading_credit que o Moodle tenha, como 0.5";
        /// Points a Moodle quiz's whole weights cannot hold.
        MoodlePoints { problem: String, points: crate::text::Num } =>
            "points: {problem} is worth {points} points, finer than a thousandth of a point, and \
             a Moodle quiz weighs its questions in whole numbers",
            "points: {problem} vale {points} pontos, mais fino que um milésimo de ponto, e um \
             questionário do Moodle pesa suas questões em números inteiros";
            fix "give the course policy's points in thousandths of a point at most (0.333 rather \
                 than 0.3333)",
                "dê os pontos da política do curso em milésimos de ponto no máximo (0.333 em vez \
                 de 0.3333)";
        /// `--points` refused.
        Points { why: Said } =>
            "{why}", "{why}";
            fix "write --points 4.1=1,4.2=2", "escreva --points 4.1=1,4.2=2";
        /// `--reading-credit` refused.
        Credit { why: Said } =>
            "{why}", "{why}";
            fix "give a share from 0 to 1 (0.5 for half the points)",
                "dê uma fração de 0 a 1 (0.5 para metade dos pontos)";
        /// `--answer` with several files.
        AnswerOneFile { given: usize } =>
            "--answer checks one file, and {given} were given",
            "--answer confere um arquivo, e {given} foram dados";
            fix "check one file at a time, or put each file's answer in its \"answer\" field \
                 and leave out --answer",
                "confira um arquivo por vez, ou ponha a resposta de cada arquivo em seu campo \
                 \"answer\" e tire --answer";
        /// `--step` or `--steps` with several files.
        StepsOneFile { given: usize } =>
            "--step and --steps check one file, and {given} were given",
            "--step e --steps conferem um arquivo, e {given} foram dados";
            fix "check one file's steps at a time", "confira os passos de um arquivo por vez";
        /// `--fragment` with a format that has no fragment.
        Fragment =>
            "--fragment applies to --format latex and html only",
            "--fragment vale só para --format latex e html";
            fix "drop --fragment, or use --format latex or html",
                "tire --fragment, ou use --format latex ou html";
        /// A document's flags with `--format json`.
        JsonNoDocument =>
            "--part and the header flags apply to the documents, not to --format json",
            "--part e as opções do cabeçalho valem para os documentos, não para --format json";
            fix "drop --part, --course, --title, --date and --author, or choose --format text, \
                 markdown, latex or html",
                "tire --part, --course, --title, --date e --author, ou escolha --format text, \
                 markdown, latex ou html";
        /// An output that is an input.
        OutputIsInput { flag: String, output: PathBuf, input: PathBuf } =>
            "{flag} {output} is the input {input}: writing it would replace what is being read",
            "{flag} {output} é a entrada {input}: escrever nele substituiria o que está sendo \
             lido";
            fix "give {flag} another file", "dê outro arquivo a {flag}";
        /// Two outputs that are the same file.
        SameOutput { other: String, flag: String, output: PathBuf } =>
            "{other} and {flag} are the same file, {output}: one would replace the other",
            "{other} e {flag} são o mesmo arquivo, {output}: um substituiria o outro";
            fix "give {flag} another file", "dê outro arquivo a {flag}";
        /// `--exercises` (or `phong policy`'s DIR) not a folder.
        ExercisesNotAFolder =>
            "not a folder", "não é uma pasta";
            fix "give the folder that holds the exercise files (exercise 4.2 is DIR/4.2.json)",
                "dê a pasta que tem os arquivos dos exercícios (o exercício 4.2 é DIR/4.2.json)";
        /// `phong new -o DIR`'s folder a file that is there.
        ProblemsNotAFolder =>
            "is a file, not a folder", "é um arquivo, não uma pasta";
            fix "give a folder for the problems' files (it is made if missing), or - to print \
                 them", "dê uma pasta para os arquivos dos problemas (criada se faltar), ou - \
                 para mostrá-los";
        /// The plot cannot be drawn: a bug.
        PlotFailed { error: String } =>
            "the plot could not be drawn: {error}", "o gráfico não pôde ser desenhado: {error}";
            fix "report this as a bug; the table is still written without --plot",
                "relate isto como um defeito; a tabela ainda é escrita sem --plot";
        /// An output path that names a folder.
        IsAFolder =>
            "it is a folder", "é uma pasta";
            fix "give a file name in it (e.g. -o DIR/report.csv), or - for standard output",
                "dê um nome de arquivo nela (por exemplo -o DIR/report.csv), ou - para a saída \
                 padrão";
        /// Symbolic links in a loop.
        LinkLoop =>
            "too many levels of symbolic links (a loop?)",
            "níveis demais de links simbólicos (um ciclo?)";
            fix "", "";
        /// An output's folder that does not exist.
        NoFolder { folder: PathBuf } =>
            "the folder {folder} does not exist", "a pasta {folder} não existe";
            fix "create it first (mkdir -p {folder}), or give a path in a folder that exists",
                "crie-a antes (mkdir -p {folder}), ou dê um caminho numa pasta que existe";
        /// An output's folder that is a file.
        NotAFolder { folder: PathBuf } =>
            "{folder} is not a folder", "{folder} não é uma pasta";
            fix "give a path in a folder that exists", "dê um caminho numa pasta que existe";
        /// Two inputs of `phong solve -o DIR/` whose files in the folder would have one name.
        SharedOutput { first: PathBuf, second: PathBuf, output: PathBuf } =>
            "{first} and {second} would both be written to {output}: one would replace the \
             other",
            "{first} e {second} seriam ambos escritos em {output}: um substituiria o outro";
            fix "solve them into separate folders (one phong solve … -o DIR/ each), or rename \
                 one of them; give a file only once",
                "resolva-os em pastas separadas (um phong solve … -o DIR/ para cada), ou \
                 renomeie um deles; dê cada arquivo uma só vez";
        /// The same, where the two names differ only in case: `output` the first's.
        SharedOutputCase { first: PathBuf, second: PathBuf, output: PathBuf } =>
            "{first} and {second} would be written to files whose names differ only in case: \
             one file, {output}, where case is not told apart (macOS, Windows), so one would \
             replace the other",
            "{first} e {second} seriam escritos em arquivos cujos nomes diferem só em \
             maiúsculas e minúsculas: um só arquivo, {output}, onde elas não se distinguem \
             (macOS, Windows), então um substituiria o outro";
            fix "solve them into separate folders (one phong solve … -o DIR/ each), or rename \
                 one of them",
                "resolva-os em pastas separadas (um phong solve … -o DIR/ para cada), ou \
                 renomeie um deles";
        /// `grade --format gradescope -o FILE` of submissions from several students.
        GradescopeStudents { count: usize, first: crate::text::Echo, second: crate::text::Echo } =>
            "the submissions are from {count} students (\"{first}\", \"{second}\", …), and a \
             Gradescope results.json is one submission's",
            "as respostas são de {count} alunos (\"{first}\", \"{second}\", …), e um \
             results.json do Gradescope é de uma só entrega";
            fix "give -o DIR/ for a results.json per student, or leave out -o for one object \
                 keyed by student; if they are one student, write the name the same way on every \
                 row",
                "dê -o PASTA/ para um results.json por aluno, ou tire -o para um objeto com uma \
                 chave por aluno; se são um só aluno, escreva o nome do mesmo jeito em toda \
                 linha";
        /// `SOURCE_DATE_EPOCH` that is not a time a workbook can say it was made.
        SourceDateEpoch { value: crate::text::Echo } =>
            "\"{value}\" is not a whole number of seconds since 1970-01-01 00:00 UTC (up to the \
             year 9999)",
            "\"{value}\" não é um número inteiro de segundos desde 1970-01-01 00:00 UTC (até o \
             ano 9999)";
            fix "set SOURCE_DATE_EPOCH to such a number (as `git log -1 --format=%ct` prints), \
                 or unset it: the workbook then says it was made on 1980-01-01",
                "defina SOURCE_DATE_EPOCH com um número assim (como `git log -1 --format=%ct` \
                 imprime), ou remova-a: a planilha então diz que foi feita em 1980-01-01";
    }
}

crate::messages! {
    /// The command line's own sentences around an error of the system.
    pub(crate) enum CliText {
        /// Output to a file that cannot be written.
        CannotWrite { path: PathBuf, error: SystemError } =>
            "cannot write {path}: {error}", "não é possível escrever {path}: {error}";
        /// Output to standard output that cannot be written.
        CannotWriteStdout { error: SystemError } =>
            "cannot write standard output: {error}",
            "não é possível escrever na saída padrão: {error}";
        /// A folder for the output files that cannot be created.
        CannotCreateFolder { path: PathBuf, error: SystemError } =>
            "{path}: cannot create the folder: {error}. Fix: give a folder in a place you can \
             write to",
            "{path}: não é possível criar a pasta: {error}. Correção: dê uma pasta num lugar \
             onde você pode escrever";
        /// The worker threads refused.
        Threads { error: String } =>
            "--threads: cannot start the worker threads: {error}. Fix: give fewer --threads",
            "--threads: não é possível iniciar as threads de trabalho: {error}. Correção: dê \
             menos --threads";
    }
}

/// A fault of the output files carried inside an [`std::io::Error`] (the writers speak
/// `io::Result`): its English is the error's text, its Portuguese found again by
/// [`SystemError`].
#[derive(Debug)]
pub(crate) struct OutputFault(pub CliFault);

impl fmt::Display for OutputFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&what_and_fix(&self.0, Lang::En))
    }
}

impl std::error::Error for OutputFault {}

impl OutputFault {
    /// `fault` as an I/O error of `kind`.
    pub(crate) fn io(kind: std::io::ErrorKind, fault: CliFault) -> std::io::Error {
        std::io::Error::new(kind, OutputFault(fault))
    }
}

/// What the operating system (or a writer of phong's own) said about a file, kept to be said
/// in a language: the system's English, its error number, and phong's own fault when it is one.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct SystemError {
    /// The error as Rust writes it (`No such file or directory (os error 2)`).
    english: String,
    /// The system's error number, when the system gave one.
    code: Option<i32>,
    /// What it is in Portuguese, when phong knows it.
    known: Option<Known>,
}

/// The errors of the system phong says in Portuguese, and its own.
#[derive(Clone, Debug, PartialEq)]
enum Known {
    Ours(Box<CliFault>),
    System(&'static str),
}

impl SystemError {
    /// What `e` says.
    pub(crate) fn of(e: &std::io::Error) -> SystemError {
        use std::io::ErrorKind as K;
        let ours = e
            .get_ref()
            .and_then(|inner| inner.downcast_ref::<OutputFault>())
            .map(|o| Known::Ours(Box::new(o.0.clone())));
        let code = e.raw_os_error();
        let system = code.and_then(|_| {
            Some(Known::System(match e.kind() {
                K::NotFound => "arquivo ou pasta inexistente",
                K::PermissionDenied => "permissão negada",
                K::AlreadyExists => "o arquivo já existe",
                K::NotADirectory => "não é uma pasta",
                K::IsADirectory => "é uma pasta",
                K::StorageFull => "o dispositivo está cheio",
                K::ReadOnlyFilesystem => "o sistema de arquivos é só de leitura",
                K::FileTooLarge => "o arquivo é grande demais",
                K::InvalidFilename => "o nome do arquivo é longo demais",
                _ => return None,
            }))
        });
        SystemError {
            english: e.to_string(),
            code,
            known: ours.or(system),
        }
    }
}

impl Show for SystemError {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (lang, &self.known) {
            (Lang::Pt, Some(Known::Ours(fault))) => {
                f.write_str(&what_and_fix(fault.as_ref(), lang))
            }
            (Lang::Pt, Some(Known::System(pt))) => match self.code {
                Some(n) => write!(f, "{pt} (erro {n} do sistema)"),
                None => f.write_str(pt),
            },
            // An error the system says only in English (or one of another module's) is shown as
            // it says it.
            _ => f.write_str(&self.english),
        }
    }
}

/// A size in memory as an error says it: `1.2 GB`, or `350 MB` (at least 1 MB).
pub(crate) fn memory_size(bytes: usize) -> String {
    let b = bytes as f64;
    if b >= 1e9 {
        format!("{:.1} GB", b / 1e9)
    } else {
        format!("{:.0} MB", (b / 1e6).max(1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_system_error_is_said_in_the_language() {
        let e = std::io::Error::from_raw_os_error(2);
        let s = SystemError::of(&e);
        let show = |lang| crate::text::In(&s, lang).to_string();
        assert_eq!(show(Lang::En), "No such file or directory (os error 2)");
        assert_eq!(
            show(Lang::Pt),
            "arquivo ou pasta inexistente (erro 2 do sistema)"
        );
        let ours = OutputFault::io(std::io::ErrorKind::Other, CliFault::IsAFolder);
        let s = SystemError::of(&ours);
        assert_eq!(
            ours.to_string(),
            "it is a folder. Fix: give a file name in it (e.g. -o DIR/report.csv), or - for \
             standard output"
        );
        assert_eq!(
            crate::text::In(&s, Lang::Pt).to_string(),
            "é uma pasta. Correção: dê um nome de arquivo nela (por exemplo -o DIR/report.csv), \
             ou - para a saída padrão"
        );
    }

    #[test]
    fn a_size_in_memory_reads_as_before() {
        assert_eq!(memory_size(3_000_000_000), "3.0 GB");
        assert_eq!(memory_size(10), "1 MB");
        assert_eq!(
            crate::problem::out_of_memory(3_000_000_000),
            format!(
                "out of memory: this needs about {}",
                memory_size(3_000_000_000)
            )
        );
    }
}
