//! What `phong tradeoff` says to people, in English and in Portuguese: the table's lines and
//! columns, the verdict, and the plot's labels (`--lang`). The JSON and the CSV are for scripts
//! and stay language-neutral.

use std::fmt;

use crate::messages;
use crate::text::{Lang, Show};

/// What a [`Count`] counts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Noun {
    /// Timed renders.
    #[default]
    Run,
    /// Worker threads.
    Thread,
    /// Samples per pixel.
    Sample,
}

/// A number with its noun, singular for 1: "3 runs", "1 execução".
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Count(pub u64, pub Noun);

impl Show for Count {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (one, many) = match (self.1, lang) {
            (Noun::Run, Lang::En) => ("run", "runs"),
            (Noun::Run, Lang::Pt) => ("execução", "execuções"),
            (Noun::Thread, _) => ("thread", "threads"),
            (Noun::Sample, Lang::En) => ("sample", "samples"),
            (Noun::Sample, Lang::Pt) => ("amostra", "amostras"),
        };
        write!(f, "{} {}", self.0, if self.0 == 1 { one } else { many })
    }
}

messages! {
    /// The name of an error metric ([`super::Metric`]) in the table's sentences and the plot.
    #[derive(Copy, Default)]
    pub enum MetricName {
        /// The largest error of any channel of any pixel.
        MaxAbs => "max abs error", "erro absoluto máximo";
        /// The root mean square error.
        #[default]
        Rmse => "RMSE", "RMSE";
        /// The share of pixels whose 8-bit colour differs.
        PixelsDiffer =>
            "share of 8-bit pixels that differ",
            "fração de pixels de 8 bits que diferem";
    }
}

messages! {
    /// A setting of the tracer, as the sentences name it: "f32, level 5, min weight 1/255, 4
    /// samples".
    pub enum SettingName {
        /// Precision, maximum level, minimum weight (as `report::weight` writes it), samples.
        Setting { precision: String, level: u32, weight: String, samples: Count } =>
            "{precision}, level {level}, min weight {weight}, {samples}",
            "{precision}, nível {level}, peso mínimo {weight}, {samples}";
    }
}

impl Default for SettingName {
    fn default() -> Self {
        SettingName::Setting {
            precision: String::new(),
            level: 0,
            weight: String::new(),
            samples: Count::default(),
        }
    }
}

messages! {
    /// The table's heading of each column.
    pub enum Column {
        /// The row's number.
        Number => "#", "#";
        /// f32 or f64.
        Precision => "prec", "prec";
        /// The maximum level.
        Level => "level", "nível";
        /// The minimum weight.
        MinWeight => "min weight", "peso mín";
        /// Samples per pixel.
        Samples => "samples", "amostras";
        /// The median time.
        Time => "time (ms)", "tempo (ms)";
        /// Rays traced, in millions.
        Rays => "rays (M)", "raios (M)";
        /// The largest error.
        MaxAbs => "max abs", "máx abs";
        /// The root mean square error.
        Rmse => "RMSE", "RMSE";
        /// The peak signal-to-noise ratio.
        Psnr => "PSNR (dB)", "PSNR (dB)";
        /// The share of 8-bit pixels that differ.
        Differ => "8-bit diff", "difer. 8 bits";
        /// The largest f32−f64 difference.
        F32F64 => "f32−f64 max", "f32−f64 máx";
        /// On the Pareto front.
        Front => "front", "fronteira";
    }
}

messages! {
    /// The lines around `phong tradeoff`'s table, and its verdict (the budget: the metric and
    /// its bound, "RMSE ≤ 1/255 (3.92e-3)").
    pub enum TradeoffText {
        /// The first line: the scene, its size, how each time was taken.
        Heading { scene: String, size: String, runs: Count, threads: Count } =>
            "Trade-off for {scene} ({size}): each setting's time is the median of {runs} on \
             {threads}.",
            "Velocidade contra precisão em {scene} ({size}): o tempo de cada configuração é a mediana de \
             {runs} em {threads}.";
        /// The reference render.
        Reference { setting: SettingName, mrays: String, time: String } =>
            "Reference: {setting}: {mrays} M rays in {time}. Errors are against its pixel means \
             (0–1 scale).",
            "Referência: {setting}: {mrays} M raios em {time}. Os erros são medidos contra as \
             médias dos seus pixels (escala 0–1).";
        /// The scene's build, per precision ("f32 4.7 µs, f64 22.0 µs").
        Build { builds: String } =>
            "Scene build (BVH), not in the times below: {builds}.",
            "Construção da cena (BVH), fora dos tempos abaixo: {builds}.";
        /// What the star of the last column means.
        FrontNote { metric: MetricName } =>
            "* on the Pareto front of time against {metric}: no other setting is both as fast \
             and as accurate.",
            "* na fronteira de Pareto de tempo contra {metric}: nenhuma outra configuração é ao \
             mesmo tempo tão rápida e tão precisa.";
        /// What f32 costs by itself, over the settings swept in both precisions.
        PrecisionNote { pairs: usize, most: String, percent: String } =>
            "f32−f64 max: the largest difference between an f32 image and the f64 image of the \
             same level, weight and samples (the error of the precision alone). Over all \
             {pairs} pairs: at most {most}, and at most {percent}% of 8-bit pixels differ.",
            "f32−f64 máx: a maior diferença entre uma imagem f32 e a imagem f64 de mesmos \
             nível, peso e amostras (o erro só da precisão). Nos {pairs} pares: no máximo \
             {most}, e no máximo {percent}% dos pixels de 8 bits diferem.";
        /// The verdict: the fastest setting within the budget.
        Fastest {
            metric: MetricName,
            bound: String,
            number: usize,
            setting: SettingName,
            ms: String,
            error: String,
        } =>
            "Fastest within {metric} ≤ {bound}: #{number} ({setting}): {ms} ms, {metric} = \
             {error}.",
            "A mais rápida dentro de {metric} ≤ {bound}: #{number} ({setting}): {ms} ms, \
             {metric} = {error}.";
        /// The verdict when no setting is within the budget.
        NoneWithin {
            metric: MetricName,
            bound: String,
            number: usize,
            setting: SettingName,
            error: String,
            reference_samples: u32,
        } =>
            "No setting is within {metric} ≤ {bound}. The most accurate is #{number} ({setting}): {metric} \
             = {error}. More samples per pixel (the reference has {reference_samples}), a \
             deeper level or a smaller minimum weight would bring it closer.",
            "Nenhuma configuração fica dentro de {metric} ≤ {bound}. A mais precisa é a #{number} \
             ({setting}): {metric} = {error}. Mais amostras por pixel (a referência tem \
             {reference_samples}), um nível mais profundo ou um peso mínimo menor a deixariam \
             mais perto.";
        /// The verdict when nothing was swept.
        NothingSwept { metric: MetricName, bound: String } =>
            "No setting is within {metric} ≤ {bound}: nothing was swept.",
            "Nenhuma configuração fica dentro de {metric} ≤ {bound}: nada foi medido.";
    }
}

messages! {
    /// The plot's title, axes and legend.
    pub enum PlotText {
        /// The title.
        Title { scene: String, metric: MetricName, size: String, threads: Count } =>
            "{scene}: {metric} against time ({size}, {threads})",
            "{scene}: {metric} contra o tempo ({size}, {threads})";
        /// The time axis.
        TimeAxis => "median time (ms), log scale", "tempo mediano (ms), escala log";
        /// The error axis; `zero` is [`PlotText::ZeroAt`] where some error is 0.
        ErrorAxis { metric: MetricName, zero: String } =>
            "{metric}{zero}, log scale",
            "{metric}{zero}, escala log";
        /// Where errors of exactly 0 are drawn.
        ZeroAt { at: String } => " (0 drawn at {at})", " (0 desenhado em {at})";
        /// The Pareto front's line.
        Front => "Pareto front", "fronteira de Pareto";
        /// The budget's line.
        Budget { budget: String } => "budget {budget}", "orçamento {budget}";
        /// The setting the verdict names.
        Fastest { number: usize } =>
            "fastest within budget: #{number}",
            "mais rápida dentro do orçamento: #{number}";
    }
}
