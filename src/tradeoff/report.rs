//! `phong tradeoff`'s outputs: the table for people, JSON and CSV for scripts. Each is laid out
//! from one [`Summary`].

use serde_json::{json, Value};

use super::{fastest_within, pareto_front, Measured, Metric, Outcome, Setting};
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

/// "f32, level 5, min weight 1/255, 4 samples"
pub fn describe(s: &Setting) -> String {
    format!(
        "{}, level {}, min weight {}, {} sample{}",
        s.precision.name(),
        s.max_level,
        weight(s.min_weight),
        s.samples,
        if s.samples == 1 { "" } else { "s" }
    )
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

/// The table and the verdict, for people.
pub fn text(s: &Summary) -> String {
    let o = s.outcome;
    let mut out = String::new();
    let r = &o.reference;
    out.push_str(&format!(
        "Trade-off for {} ({}×{}): each setting's time is the median of {} run{} on {} thread{}.\n",
        s.scene,
        o.width,
        o.height,
        o.runs,
        if o.runs == 1 { "" } else { "s" },
        o.threads,
        if o.threads == 1 { "" } else { "s" },
    ));
    out.push_str(&format!(
        "Reference: {}: {} M rays in {}. Errors are against its pixel means (0–1 scale).\n",
        describe(&r.setting),
        mrays(&r.rays),
        seconds(r.time_s)
    ));
    let builds: Vec<String> = o
        .build_s
        .iter()
        .map(|(p, t)| format!("{} {}", p.name(), seconds(*t)))
        .collect();
    out.push_str(&format!(
        "Scene build (BVH), not in the times below: {}.\n\n",
        builds.join(", ")
    ));
    out.push_str(&format!(
        "{:>3}  {:<4} {:>5} {:>10} {:>7} {:>10} {:>8} {:>9} {:>9} {:>9} {:>11} {:>13}  {}\n",
        "#",
        "prec",
        "level",
        "min weight",
        "samples",
        "time (ms)",
        "rays (M)",
        "max abs",
        "RMSE",
        "PSNR (dB)",
        "8-bit diff",
        "f32−f64 max",
        "front"
    ));
    for (i, m) in o.rows.iter().enumerate() {
        let st = &m.setting;
        out.push_str(&format!(
            "{:>3}  {:<4} {:>5} {:>10} {:>7} {:>10.1} {:>8} {:>9} {:>9} {:>9} {:>10.2}% {:>13}  {}\n",
            i + 1,
            st.precision.name(),
            st.max_level,
            weight(st.min_weight),
            st.samples,
            m.median_s * 1e3,
            mrays(&m.rays),
            sci(m.errors.max_abs),
            sci(m.errors.rmse),
            m.errors
                .psnr_db
                .map_or_else(|| "∞".to_owned(), |p| format!("{p:.1}")),
            m.errors.pixels_differ * 100.0,
            m.vs_f64.map_or_else(String::new, |e| sci(e.max_abs)),
            if s.on_front(i) { "*" } else { "" }
        ));
    }
    out.push_str(&format!(
        "\n* on the Pareto front of time against {}: no other setting is both as fast and as \
         accurate.\n",
        s.metric.label()
    ));
    if let Some(p) = precision_note(o) {
        out.push_str(&p);
    }
    out.push_str(&verdict(s));
    out.push('\n');
    out
}

/// What f32 costs in accuracy by itself: the largest f32−f64 error and 8-bit share over the
/// settings swept in both.
fn precision_note(o: &Outcome) -> Option<String> {
    let pairs: Vec<_> = o.rows.iter().filter_map(|m| m.vs_f64).collect();
    if pairs.is_empty() {
        return None;
    }
    let max = pairs.iter().map(|e| e.max_abs).fold(0.0, f64::max);
    let differ = pairs.iter().map(|e| e.pixels_differ).fold(0.0, f64::max);
    Some(format!(
        "f32−f64 max: the largest difference between an f32 image and the f64 image of the same \
         level, weight and samples (the error of the precision alone). Over all {} pairs: at \
         most {}, and at most {:.3}% of 8-bit pixels differ.\n",
        pairs.len(),
        sci(max),
        differ * 100.0
    ))
}

/// The sentence that answers "which setting is the fastest within the budget".
pub fn verdict(s: &Summary) -> String {
    let rows = &s.outcome.rows;
    let budget = format!("{} ≤ {}", s.metric.label(), budget_text(s.budget, s.metric));
    match s.choice {
        Some(i) => {
            let m = &rows[i];
            format!(
                "Fastest within {budget}: #{} ({}): {:.1} ms, {} = {}.",
                i + 1,
                describe(&m.setting),
                m.median_s * 1e3,
                s.metric.label(),
                sci(m.errors.get(s.metric))
            )
        }
        None => {
            let best = (0..rows.len()).min_by(|&a, &b| {
                rows[a]
                    .errors
                    .get(s.metric)
                    .total_cmp(&rows[b].errors.get(s.metric))
            });
            match best {
                Some(b) => format!(
                    "No setting is within {budget}. The most accurate is #{} ({}): {} = {}. More \
                     samples per pixel (the reference has {}), a deeper level or a smaller \
                     minimum weight would bring it closer.",
                    b + 1,
                    describe(&rows[b].setting),
                    s.metric.label(),
                    sci(rows[b].errors.get(s.metric)),
                    s.outcome.reference.setting.samples
                ),
                None => format!("No setting is within {budget}: nothing was swept."),
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
