//! `phong tradeoff`'s outputs: the table for people, JSON and CSV for scripts. Each is laid out
//! from one [`Summary`].

use serde_json::{json, Value};

use super::messages::{Column, Count, Noun, SettingName, TradeoffText};
use super::{fastest_within, pareto_front, Measured, Metric, Outcome, Setting};
use crate::text::{Lang, Message};
use crate::tracer::Counts;

/// What the outputs say: the measurements, the metric the budget and the front are judged by,
/// the front, and the fastest setting within the budget.
pub struct Summary<'a> {
    pub scene: &'a str,
    pub outcome: &'a Outcome,
    pub metric: Metric,
    pub budget: f64,
    /// Indices into `outcome.rows`, in the rows' order.
    pub front: Vec<usize>,
    pub choice: Option<usize>,
}

impl<'a> Summary<'a> {
    pub fn new(scene: &'a str, outcome: &'a Outcome, metric: Metric, budget: f64) -> Self {
        Summary {
            scene,
            outcome,
            metric,
            budget,
            front: pareto_front(&outcome.rows, metric),
            choice: fastest_within(&outcome.rows, metric, budget),
        }
    }

    fn on_front(&self, i: usize) -> bool {
        self.front.contains(&i)
    }
}

/// A minimum weight as people write it: its shortest decimal when that is short (0, 0.05),
/// k/255 when it is one and the decimal is long (1/255), else three significant digits.
pub fn weight(w: f64) -> String {
    let decimal = format!("{w}");
    if decimal.len() <= 7 {
        return decimal;
    }
    let k = (w * 255.0).round();
    if k >= 1.0 && (w * 255.0 - k).abs() < 1e-9 {
        format!("{k}/255")
    } else {
        format!("{w:.2e}")
    }
}

/// Seconds as people read them: µs, ms or s.
pub fn seconds(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.1} µs", t * 1e6)
    } else if t < 1.0 {
        format!("{:.1} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

/// "f32, level 5, min weight 1/255, 4 samples", in either language.
pub fn describe(s: &Setting) -> SettingName {
    SettingName::Setting {
        precision: s.precision.name().to_owned(),
        level: s.max_level,
        weight: weight(s.min_weight),
        samples: Count(u64::from(s.samples), Noun::Sample),
    }
}

/// An error in three significant digits; 0 as "0".
fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.2e}")
    }
}

fn mrays(c: &Counts) -> String {
    format!("{:.2}", c.total() as f64 / 1e6)
}

/// The columns of the table, in order, each with its width in English; a column is as wide as
/// its heading in the language shown, at least that.
const COLUMNS: [(Column, usize); 13] = [
    (Column::Number, 3),
    (Column::Precision, 4),
    (Column::Level, 5),
    (Column::MinWeight, 10),
    (Column::Samples, 7),
    (Column::Time, 10),
    (Column::Rays, 8),
    (Column::MaxAbs, 9),
    (Column::Rmse, 9),
    (Column::Psnr, 9),
    (Column::Differ, 11),
    (Column::F32F64, 13),
    (Column::Front, 0),
];

/// The table and the verdict, for people, in `lang`.
pub fn text(s: &Summary, lang: Lang) -> String {
    let o = s.outcome;
    let mut out = String::new();
    let r = &o.reference;
    let mut line = |m: TradeoffText| {
        out.push_str(&m.text(lang));
        out.push('\n');
    };
    line(TradeoffText::Heading {
        scene: s.scene.to_owned(),
        size: format!("{}×{}", o.width, o.height),
        runs: Count(u64::from(o.runs), Noun::Run),
        threads: Count(o.threads as u64, Noun::Thread),
    });
    line(TradeoffText::Reference {
        setting: describe(&r.setting),
        mrays: mrays(&r.rays),
        time: seconds(r.time_s),
    });
    let builds: Vec<String> = o
        .build_s
        .iter()
        .map(|(p, t)| format!("{} {}", p.name(), seconds(*t)))
        .collect();
    line(TradeoffText::Build {
        builds: builds.join(", "),
    });
    out.push('\n');
    let heads = COLUMNS.map(|(c, _)| c.text(lang));
    let widths: [usize; 13] = std::array::from_fn(|k| COLUMNS[k].1.max(heads[k].chars().count()));
    table_line(&mut out, &widths, heads);
    for (i, m) in o.rows.iter().enumerate() {
        let st = &m.setting;
        let cells = [
            (i + 1).to_string(),
            st.precision.name().to_owned(),
            st.max_level.to_string(),
            weight(st.min_weight),
            st.samples.to_string(),
            format!("{:.1}", m.median_s * 1e3),
            mrays(&m.rays),
            sci(m.errors.max_abs),
            sci(m.errors.rmse),
            m.errors
                .psnr_db
                .map_or_else(|| "∞".to_owned(), |p| format!("{p:.1}")),
            format!("{:.2}%", m.errors.pixels_differ * 100.0),
            m.vs_f64.map_or_else(String::new, |e| sci(e.max_abs)),
            if s.on_front(i) { "*" } else { "" }.to_owned(),
        ];
        table_line(&mut out, &widths, cells);
    }
    out.push('\n');
    out.push_str(
        &TradeoffText::FrontNote {
            metric: s.metric.name(),
        }
        .text(lang),
    );
    out.push('\n');
    if let Some(p) = precision_note(o) {
        out.push_str(&p.text(lang));
        out.push('\n');
    }
    out.push_str(&verdict(s).text(lang));
    out.push('\n');
    out
}

/// One line of the table: the cells in their columns' `widths`, right-aligned but the
/// precision's; two spaces after the row's number and before the front's star, one elsewhere.
fn table_line(out: &mut String, widths: &[usize; 13], cells: [String; 13]) {
    for (k, cell) in cells.iter().enumerate() {
        let w = widths[k];
        let cell = match k {
            0 => format!("{cell:>w$}  "),
            1 => format!("{cell:<w$} "),
            11 => format!("{cell:>w$}  "),
            12 => cell.clone(),
            _ => format!("{cell:>w$} "),
        };
        out.push_str(&cell);
    }
    out.push('\n');
}

/// What f32 costs in accuracy by itself: the largest f32−f64 error and 8-bit share over the
/// settings swept in both.
fn precision_note(o: &Outcome) -> Option<TradeoffText> {
    let pairs: Vec<_> = o.rows.iter().filter_map(|m| m.vs_f64).collect();
    if pairs.is_empty() {
        return None;
    }
    let max = pairs.iter().map(|e| e.max_abs).fold(0.0, f64::max);
    let differ = pairs.iter().map(|e| e.pixels_differ).fold(0.0, f64::max);
    Some(TradeoffText::PrecisionNote {
        pairs: pairs.len(),
        most: sci(max),
        percent: format!("{:.3}", differ * 100.0),
    })
}

/// The sentence that answers "which setting is the fastest within the budget".
pub fn verdict(s: &Summary) -> TradeoffText {
    let rows = &s.outcome.rows;
    let (metric, bound) = (s.metric.name(), budget_text(s.budget, s.metric));
    let error = |i: usize| sci(rows[i].errors.get(s.metric));
    match s.choice {
        Some(i) => TradeoffText::Fastest {
            metric,
            bound,
            number: i + 1,
            setting: describe(&rows[i].setting),
            ms: format!("{:.1}", rows[i].median_s * 1e3),
            error: error(i),
        },
        None => {
            let best = (0..rows.len()).min_by(|&a, &b| {
                rows[a]
                    .errors
                    .get(s.metric)
                    .total_cmp(&rows[b].errors.get(s.metric))
            });
            match best {
                Some(b) => TradeoffText::NoneWithin {
                    metric,
                    bound,
                    number: b + 1,
                    setting: describe(&rows[b].setting),
                    error: error(b),
                    reference_samples: s.outcome.reference.setting.samples,
                },
                None => TradeoffText::NothingSwept { metric, bound },
            }
        }
    }
}

/// The budget as given and as a number: "1/255 (3.92e-3)".
fn budget_text(b: f64, metric: Metric) -> String {
    let w = weight(b);
    match metric {
        Metric::PixelsDiffer => format!("{:.2}%", b * 100.0),
        _ if w.contains('/') => format!("{w} ({})", sci(b)),
        _ => w,
    }
}

fn rays_json(c: &Counts) -> Value {
    json!({
        "primary": c.primary,
        "reflection": c.reflection,
        "transmission": c.transmission,
        "shadow": c.shadow,
        "total": c.total(),
    })
}

fn setting_json(st: &Setting) -> Value {
    json!({
        "precision": st.precision,
        "max_level": st.max_level,
        "min_weight": st.min_weight,
        "samples": st.samples,
    })
}

fn row_json(s: &Summary, i: usize, m: &Measured) -> Value {
    let e = &m.errors;
    json!({
        "setting": setting_json(&m.setting),
        "median_s": m.median_s,
        "times_s": m.times_s,
        "rays": rays_json(&m.rays),
        "errors": e,
        "vs_f64": m.vs_f64,
        "pareto": s.on_front(i),
        "within_budget": e.get(s.metric) <= s.budget,
    })
}

/// The stable JSON (`format_version` 1). `psnr_db` is null when a setting's image equals the
/// reference (infinite PSNR); `fastest_within_budget` is an index into `settings`, or null.
pub fn json(s: &Summary) -> Value {
    let o = s.outcome;
    let build: serde_json::Map<String, Value> = o
        .build_s
        .iter()
        .map(|(p, t)| (p.name().to_owned(), json!(t)))
        .collect();
    json!({
        "format_version": 1,
        "scene": s.scene,
        "width": o.width,
        "height": o.height,
        "threads": o.threads,
        "runs": o.runs,
        "metric": s.metric,
        "budget": s.budget,
        "reference": {
            "setting": setting_json(&o.reference.setting),
            "time_s": o.reference.time_s,
            "rays": rays_json(&o.reference.rays),
        },
        "build_s": build,
        "settings": o.rows.iter().enumerate().map(|(i, m)| row_json(s, i, m)).collect::<Vec<_>>(),
        "pareto": s.front,
        "fastest_within_budget": s.choice,
    })
}

/// One CSV row per setting. `psnr_db` is empty when the image equals the reference.
pub fn csv(s: &Summary) -> String {
    let mut w = ::csv::Writer::from_writer(Vec::new());
    let header = [
        "precision",
        "max_level",
        "min_weight",
        "samples",
        "median_s",
        "rays_primary",
        "rays_reflection",
        "rays_transmission",
        "rays_shadow",
        "rays_total",
        "max_abs",
        "rmse",
        "psnr_db",
        "pixels_differ",
        "vs_f64_max_abs",
        "vs_f64_pixels_differ",
        "pareto",
        "within_budget",
    ];
    w.write_record(header).expect("writing to memory");
    for (i, m) in s.outcome.rows.iter().enumerate() {
        let st = &m.setting;
        let e = &m.errors;
        let record = [
            st.precision.name().to_owned(),
            st.max_level.to_string(),
            st.min_weight.to_string(),
            st.samples.to_string(),
            m.median_s.to_string(),
            m.rays.primary.to_string(),
            m.rays.reflection.to_string(),
            m.rays.transmission.to_string(),
            m.rays.shadow.to_string(),
            m.rays.total().to_string(),
            e.max_abs.to_string(),
            e.rmse.to_string(),
            e.psnr_db.map(|p| p.to_string()).unwrap_or_default(),
            e.pixels_differ.to_string(),
            m.vs_f64.map(|v| v.max_abs.to_string()).unwrap_or_default(),
            m.vs_f64
                .map(|v| v.pixels_differ.to_string())
                .unwrap_or_default(),
            s.on_front(i).to_string(),
            (e.get(s.metric) <= s.budget).to_string(),
        ];
        w.write_record(&record).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("flushed to memory")).expect("the fields are UTF-8")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The headings line as the table had it before it spoke Portuguese (its widths fixed in
    /// the format string); in Portuguese each column widens to its heading.
    #[test]
    fn the_headings_keep_their_columns() {
        let line = |lang: Lang| {
            let heads = COLUMNS.map(|(c, _)| c.text(lang));
            let widths = std::array::from_fn(|k| COLUMNS[k].1.max(heads[k].chars().count()));
            let mut out = String::new();
            table_line(&mut out, &widths, heads);
            out
        };
        assert_eq!(
            line(Lang::En),
            "  #  prec level min weight samples  time (ms) rays (M)   max abs      RMSE PSNR \
             (dB)  8-bit diff   f32−f64 max  front\n"
        );
        assert_eq!(
            line(Lang::Pt),
            "  #  prec nível   peso mín amostras tempo (ms) raios (M)   máx abs      RMSE PSNR \
             (dB) difer. 8 bits   f32−f64 máx  fronteira\n"
        );
    }

    #[test]
    fn weights_read_as_people_write_them() {
        assert_eq!(weight(0.0), "0");
        assert_eq!(weight(1.0 / 255.0), "1/255");
        assert_eq!(weight(2.0 / 255.0), "2/255");
        assert_eq!(weight(0.05), "0.05");
        assert_eq!(weight(0.2), "0.2");
        assert_eq!(weight(1.0), "1");
        assert_eq!(weight(0.123456789), "1.23e-1");
    }
}
