//! The help of the tracer's commands (`super::super::args::trace`): `phong render`,
//! `phong tradeoff` and `phong export-pov`.

use super::{Part, Texts};

crate::messages! {
    /// The help of `phong render`, `phong tradeoff` and `phong export-pov`, and of their
    /// arguments.
    pub(crate) enum TraceHelp {
        /// The scene of render, tradeoff and export-pov.
        Scene =>
            "The scene: a problem file with a \"camera\" and \"surfaces\"",
            "A cena: um arquivo de problema com \"camera\" e \"surfaces\"";
        /// `--max-level` of render and export-pov.
        MaxLevel =>
            "The maximum recursion level, 1 to 1000 (primary rays are level 1) [scene's, or 5]",
            "O nível máximo de recursão, de 1 a 1000 (os raios primários são de nível 1) [o da \
             cena, ou 5]";
        /// `--min-weight` of render and export-pov.
        MinWeight =>
            "The minimum weight of a reflection ray, a number ≥ 0 or a fraction [scene's, or \
             1/255]",
            "O peso mínimo de um raio de reflexão, um número ≥ 0 ou uma fração [o da cena, ou \
             1/255]";
        /// `--shadows` of render and export-pov.
        Shadows =>
            "Shadow rays on or off [scene's, or on]",
            "Raios de sombra ligados (on) ou desligados (off) [o da cena, ou on]";
        /// `phong render`.
        Render =>
            "Render a scene (a problem file with a camera) with the Whitted ray tracer, or \
             explain one pixel of it step by step",
            "Renderiza uma cena (um arquivo de problema com câmera) com o traçador de raios de \
             Whitted, ou explica passo a passo um pixel dela";
        /// `render --output`.
        RenderOutput =>
            "The image to write (atomically): .png or .ppm. With --explain-pixel, the \
             explanation's file instead (any name; standard output when omitted or -)",
            "A imagem a escrever (atomicamente): .png ou .ppm. Com --explain-pixel, o arquivo \
             da explicação (qualquer nome; a saída padrão quando omitido ou -)";
        /// `render --image-format`.
        RenderImageFormat =>
            "The image format, when the output's extension does not say",
            "O formato da imagem, quando a extensão da saída não o diz";
        /// `render --samples`.
        RenderSamples =>
            "Samples per pixel, 1 to 4096, stratified and deterministic [scene's, or 1]",
            "Amostras por pixel, de 1 a 4096, estratificadas e determinísticas [as da cena, ou \
             1]";
        /// `render --threads`.
        RenderThreads =>
            "Worker threads, 1 to 1024 (default: one per core). The image is the same for any \
             number",
            "Threads de trabalho, de 1 a 1024 (padrão: uma por núcleo). A imagem é a mesma com \
             qualquer número";
        /// `render --engine`.
        RenderEngine =>
            "The tracer: packets of rays in SIMD lanes with queues per bounce (wide), or one ray \
             at a time (scalar). The image is the same bytes by either; --explain-pixel is \
             always scalar",
            "O traçador: pacotes de raios em vias SIMD com filas por nível (wide), ou um raio \
             por vez (scalar). A imagem tem os mesmos bytes com qualquer um; --explain-pixel é \
             sempre scalar";
        /// `render --explain-pixel`.
        RenderExplainPixel =>
            "Explain pixel X,Y (from the top-left corner, 0-based) step by step instead of \
             writing the image: its rays, each hit solved as `phong solve` solves a ray problem",
            "Explica passo a passo o pixel X,Y (a partir do canto superior esquerdo, contando \
             de 0) em vez de escrever a imagem: os seus raios, cada interseção resolvida como o \
             `phong solve` resolve um problema de raio";
        /// `render --format`.
        RenderFormat =>
            "Format of the explanation (text, markdown, latex, html or json)",
            "Formato da explicação (text, markdown, latex, html ou json)";
        /// `render --lang`.
        RenderLang =>
            "Language of the explanation and of the errors (json is language-neutral).",
            "Idioma da explicação e dos erros (o json não depende do idioma).";
        /// `render --stats`.
        RenderStats =>
            "Print the number of rays traced and the time taken to stderr",
            "Mostra no stderr o número de raios traçados e o tempo gasto";
        /// `phong tradeoff`.
        Tradeoff =>
            "Measure what each tracer setting (precision, level, minimum weight, samples) costs \
             in time and buys in accuracy against a reference render; name the fastest within a \
             budget",
            "Mede o que cada configuração do traçador (precisão, nível, peso mínimo, amostras) \
             custa em tempo e ganha em exatidão contra uma renderização de referência; aponta a \
             mais rápida dentro de um orçamento de erro";
        /// `tradeoff --precisions`.
        TradeoffPrecisions => "Precisions to sweep", "Precisões a varrer";
        /// `tradeoff --levels`.
        TradeoffLevels =>
            "Maximum levels to sweep, each 1 to 1000",
            "Níveis máximos a varrer, cada um de 1 a 1000";
        /// `tradeoff --min-weights`.
        TradeoffMinWeights =>
            "Minimum weights to sweep (decimals or fractions such as 1/255)",
            "Pesos mínimos a varrer (decimais ou frações como 1/255)";
        /// `tradeoff --samples`.
        TradeoffSamples =>
            "Samples per pixel to sweep, each 1 to 4096",
            "Amostras por pixel a varrer, cada uma de 1 a 4096";
        /// `tradeoff --runs`.
        TradeoffRuns =>
            "Renders per setting, 1 to 1000; its time is their median",
            "Renderizações por configuração, de 1 a 1000; o tempo da configuração é a mediana \
             delas";
        /// `tradeoff --reference-level`.
        TradeoffReferenceLevel =>
            "The reference's maximum level, 1 to 1000 (it is f64 with minimum weight 0)",
            "O nível máximo da referência, de 1 a 1000 (ela é f64 com peso mínimo 0)";
        /// `tradeoff --reference-samples`.
        TradeoffReferenceSamples =>
            "The reference's samples per pixel, 1 to 4096",
            "As amostras por pixel da referência, de 1 a 4096";
        /// `tradeoff --budget`.
        TradeoffBudget =>
            "The error budget: which setting is the fastest with its error at most this?",
            "O orçamento de erro: qual configuração é a mais rápida com um erro de no máximo \
             este valor?";
        /// `tradeoff --metric`.
        TradeoffMetric =>
            "The error the budget and the Pareto front are judged by",
            "O erro pelo qual o orçamento e a fronteira de Pareto são julgados";
        /// `tradeoff --size`.
        TradeoffSize =>
            "Render at this size instead of the camera's (quicker sweeps)",
            "Renderiza neste tamanho em vez do da câmera (varreduras mais rápidas)";
        /// `tradeoff --threads`.
        TradeoffThreads =>
            "Worker threads, 1 to 1024 (default: one per core)",
            "Threads de trabalho, de 1 a 1024 (padrão: uma por núcleo)";
        /// `tradeoff --engine`.
        TradeoffEngine =>
            "The tracer of every render (the reference too), as `phong render --engine`: \
             packets of rays in SIMD lanes (wide) or one ray at a time (scalar). Both give the \
             same images, errors and rays; only the times differ",
            "O traçador de cada renderização (também da referência), como em `phong render \
             --engine`: pacotes de raios em vias SIMD (wide) ou um raio por vez (scalar). Os \
             dois dão as mesmas imagens, erros e raios; só os tempos diferem";
        /// `tradeoff --format`.
        TradeoffFormat => "Format of the table", "Formato da tabela";
        /// `tradeoff --output`.
        TradeoffOutput =>
            "Write the table to this file (atomically) instead of standard output",
            "Escreve a tabela neste arquivo (atomicamente) em vez da saída padrão";
        /// `tradeoff --plot`.
        TradeoffPlot =>
            "Write the plot of error against time (SVG) to this file",
            "Escreve neste arquivo o gráfico do erro contra o tempo (SVG)";
        /// `tradeoff --lang`.
        TradeoffLang =>
            "Language of the table, the plot and the errors (json and csv are \
             language-neutral).",
            "Idioma da tabela, do gráfico e dos erros (json e csv não dependem do idioma).";
        /// `phong export-pov`.
        ExportPov =>
            "Write a scene as POV-Ray 3.7 SDL that computes the same model (for \
             cross-checking), or say why POV-Ray cannot express it (exit 2)",
            "Escreve uma cena em SDL do POV-Ray 3.7 que calcula o mesmo modelo (para conferir \
             um com o outro), ou diz por que o POV-Ray não consegue expressá-la (saída 2)";
        /// What `phong export-pov --help` adds.
        ExportPovMore =>
            "A transmitting material is exported only where total internal reflection cannot \
             occur (POV-Ray traces a reflection ray there, phong nothing): on a sphere or a \
             plane with \"ior\" ≥ 1, seen from outside, that no reflecting or transmitting \
             surface enters; with shadows on, it casts phong's full shadow through a copy only \
             POV-Ray's shadow rays see.",
            "Um material que transmite só é exportado onde não pode haver reflexão interna \
             total (ali o POV-Ray traça um raio de reflexão, o phong nenhum): numa esfera ou num \
             plano com \"ior\" ≥ 1, visto de fora, em que nenhuma superfície que reflete ou \
             transmite entra; com as sombras ligadas, ele projeta a sombra inteira do phong por \
             meio de uma cópia que só os raios de sombra do POV-Ray veem.";
        /// `export-pov --output`.
        ExportPovOutput =>
            "Write the SDL to this file (atomically) instead of standard output",
            "Escreve o SDL neste arquivo (atomicamente) em vez da saída padrão";
        /// `export-pov --samples`: unlike render's, only 1.
        ExportPovSamples =>
            "Samples per pixel: only 1 can be exported (POV-Ray cannot average phong's \
             stratified samples) [scene's, or 1]",
            "Amostras por pixel: só 1 pode ser exportada (o POV-Ray não sabe tirar a média das \
             amostras estratificadas do phong) [as da cena, ou 1]";
        /// `export-pov --lang`.
        ExportPovLang =>
            "Language of the errors (the SDL is the same in either).",
            "Idioma dos erros (o SDL é o mesmo nos dois).";
    }
}

/// The help of `part` of `command`, for the commands of this family.
pub(super) fn of(command: &str, part: Part<'_>) -> Option<Texts> {
    use Part::{About, Arg};
    use TraceHelp as H;
    Some(match (command, part) {
        ("render" | "tradeoff" | "export-pov", Arg("scene")) => Texts::new(H::Scene),
        ("render" | "export-pov", Arg("max_level")) => Texts::new(H::MaxLevel),
        ("render" | "export-pov", Arg("min_weight")) => Texts::new(H::MinWeight),
        ("render" | "export-pov", Arg("shadows")) => Texts::new(H::Shadows),
        ("render", About) => Texts::new(H::Render),
        ("render", Arg("output")) => Texts::new(H::RenderOutput),
        ("render", Arg("image_format")) => Texts::new(H::RenderImageFormat),
        ("render", Arg("samples")) => Texts::new(H::RenderSamples),
        ("render", Arg("threads")) => Texts::new(H::RenderThreads),
        ("render", Arg("engine")) => Texts::new(H::RenderEngine),
        ("render", Arg("explain_pixel")) => Texts::new(H::RenderExplainPixel),
        ("render", Arg("format")) => Texts::new(H::RenderFormat),
        ("render", Arg("lang")) => Texts::lang(H::RenderLang),
        ("render", Arg("stats")) => Texts::new(H::RenderStats),
        ("tradeoff", About) => Texts::new(H::Tradeoff),
        ("tradeoff", Arg("precisions")) => Texts::new(H::TradeoffPrecisions),
        ("tradeoff", Arg("levels")) => Texts::new(H::TradeoffLevels),
        ("tradeoff", Arg("min_weights")) => Texts::new(H::TradeoffMinWeights),
        ("tradeoff", Arg("samples")) => Texts::new(H::TradeoffSamples),
        ("tradeoff", Arg("runs")) => Texts::new(H::TradeoffRuns),
        ("tradeoff", Arg("reference_level")) => Texts::new(H::TradeoffReferenceLevel),
        ("tradeoff", Arg("reference_samples")) => Texts::new(H::TradeoffReferenceSamples),
        ("tradeoff", Arg("budget")) => Texts::new(H::TradeoffBudget),
        ("tradeoff", Arg("metric")) => Texts::new(H::TradeoffMetric),
        ("tradeoff", Arg("size")) => Texts::new(H::TradeoffSize),
        ("tradeoff", Arg("threads")) => Texts::new(H::TradeoffThreads),
        ("tradeoff", Arg("engine")) => Texts::new(H::TradeoffEngine),
        ("tradeoff", Arg("format")) => Texts::new(H::TradeoffFormat),
        ("tradeoff", Arg("output")) => Texts::new(H::TradeoffOutput),
        ("tradeoff", Arg("plot")) => Texts::new(H::TradeoffPlot),
        ("tradeoff", Arg("lang")) => Texts::lang(H::TradeoffLang),
        ("export-pov", About) => Texts::new(H::ExportPov).more(H::ExportPovMore),
        ("export-pov", Arg("output")) => Texts::new(H::ExportPovOutput),
        ("export-pov", Arg("samples")) => Texts::new(H::ExportPovSamples),
        ("export-pov", Arg("lang")) => Texts::lang(H::ExportPovLang),
        _ => return None,
    })
}
