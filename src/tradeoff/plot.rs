//! The plot of `phong tradeoff`: error against time, both on log scales, f32 and f64 apart, the
//! Pareto front joined, the budget drawn across. SVG only (plotters' SVG backend): text stays
//! text, so no font library is needed and the file is small.

use plotters::prelude::*;

use super::messages::{Count, Noun, PlotText};
use super::report::{weight, Summary};
use crate::core::Precision;
use crate::text::{Lang, Message};

/// Errors of exactly 0 cannot sit on a log scale: they are drawn at this fraction of the
/// smallest non-zero value (and the caption says so).
const ZERO_FRACTION: f64 = 0.1;

/// The plot as SVG text, its words in `lang`.
pub fn svg(s: &Summary, lang: Lang) -> Result<String, String> {
    let rows = &s.outcome.rows;
    let metric = s.metric;
    let err = |i: usize| rows[i].errors.get(metric);
    let smallest = (0..rows.len())
        .map(err)
        .chain(std::iter::once(s.budget))
        .filter(|&e| e > 0.0)
        .fold(f64::INFINITY, f64::min);
    let floor = if smallest.is_finite() {
        smallest * ZERO_FRACTION
    } else {
        1e-6
    };
    let y = |e: f64| if e > 0.0 { e } else { floor };
    let x = |i: usize| rows[i].median_s * 1e3;
    let any_zero = (0..rows.len()).any(|i| err(i) == 0.0);
    let (mut x0, mut x1) = (f64::INFINITY, 0.0f64);
    let (mut y0, mut y1) = (if any_zero { floor } else { f64::INFINITY }, 0.0f64);
    for i in 0..rows.len() {
        x0 = x0.min(x(i));
        x1 = x1.max(x(i));
        y0 = y0.min(y(err(i)));
        y1 = y1.max(y(err(i)));
    }
    if s.budget > 0.0 {
        y0 = y0.min(s.budget);
        y1 = y1.max(s.budget);
    }
    if !(x0.is_finite() && x0 > 0.0) {
        (x0, x1) = (1e-3, 1.0);
    }
    if !(y0.is_finite() && y0 > 0.0) {
        (y0, y1) = (floor, floor);
    }
    let (x0, x1) = (x0 / 1.3, x1 * 1.3);
    let (y0, y1) = (y0 / 2.0, y1 * 2.0);

    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (900, 560)).into_drawing_area();
        let e = |e: DrawingAreaErrorKind<_>| e.to_string();
        root.fill(&WHITE).map_err(e)?;
        let title = PlotText::Title {
            scene: s.scene.to_owned(),
            metric: metric.name(),
            size: format!("{}×{}", s.outcome.width, s.outcome.height),
            threads: Count(s.outcome.threads as u64, Noun::Thread),
        }
        .text(lang);
        let mut chart = ChartBuilder::on(&root)
            // plotters escapes the markup; the characters XML forbids (a file name may hold
            // them) are `text::xml`'s rule (docs/conventions.md, "XML text").
            .caption(crate::text::xml::sanitize(&title), ("sans-serif", 18))
            .margin(18)
            .x_label_area_size(48)
            .y_label_area_size(80)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(e)?;
        let zero = if (0..rows.len()).any(|i| err(i) == 0.0) {
            let at = format!("{floor:.1e}");
            PlotText::ZeroAt { at }.text(lang)
        } else {
            String::new()
        };
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .x_label_formatter(&|v| match *v {
                v if v >= 10.0 => format!("{v:.0}"),
                v if v >= 1.0 => format!("{v:.1}"),
                v => format!("{v:.3}"),
            })
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .x_desc(PlotText::TimeAxis.text(lang))
            .y_desc(
                PlotText::ErrorAxis {
                    metric: metric.name(),
                    zero,
                }
                .text(lang),
            )
            .axis_desc_style(("sans-serif", 14))
            .draw()
            .map_err(e)?;

        let f32_colour = RGBColor(31, 119, 180);
        let f64_colour = RGBColor(214, 39, 40);
        let of = |p: Precision| -> Vec<(f64, f64)> {
            (0..rows.len())
                .filter(|&i| rows[i].setting.precision == p)
                .map(|i| (x(i), y(err(i))))
                .collect()
        };
        chart
            .draw_series(
                of(Precision::F32)
                    .into_iter()
                    .map(|p| Circle::new(p, 4, f32_colour.filled())),
            )
            .map_err(e)?
            .label("f32")
            .legend(move |(a, b)| Circle::new((a + 10, b), 4, f32_colour.filled()));
        chart
            .draw_series(
                of(Precision::F64)
                    .into_iter()
                    .map(|p| TriangleMarker::new(p, 5, f64_colour.filled())),
            )
            .map_err(e)?
            .label("f64")
            .legend(move |(a, b)| TriangleMarker::new((a + 10, b), 5, f64_colour.filled()));

        let mut front: Vec<usize> = s.front.clone();
        front.sort_by(|&a, &b| x(a).total_cmp(&x(b)));
        chart
            .draw_series(LineSeries::new(
                front.iter().map(|&i| (x(i), y(err(i)))),
                BLACK.stroke_width(2),
            ))
            .map_err(e)?
            .label(PlotText::Front.text(lang))
            .legend(|(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], BLACK.stroke_width(2)));
        chart
            .draw_series(
                front
                    .iter()
                    .map(|&i| Circle::new((x(i), y(err(i))), 7, BLACK.stroke_width(1))),
            )
            .map_err(e)?;
        // Labels alternate above and below their points, and a point too close to the last
        // labelled one (in the log-log plane) gets none, so that labels do not pile up.
        let mut last: Option<(f64, f64)> = None;
        let mut k = 0;
        for &i in &front {
            let at = (x(i).log10(), y(err(i)).log10());
            if last
                .is_some_and(|l: (f64, f64)| (at.0 - l.0).abs() < 0.06 && (at.1 - l.1).abs() < 0.1)
            {
                continue;
            }
            last = Some(at);
            let dy = if k % 2 == 0 { -16 } else { 6 };
            k += 1;
            let text = format!("#{} {}", i + 1, short(&rows[i].setting));
            // Near the right edge the label goes to the left of its point (about 6 px a letter).
            let right = (x(i) / x0).ln() / (x1 / x0).ln() > 0.7;
            let dx = if right {
                -8 - 6 * text.chars().count() as i32
            } else {
                8
            };
            let label = EmptyElement::at((x(i), y(err(i))))
                + Text::new(text, (dx, dy), ("sans-serif", 11).into_font().color(&BLACK));
            chart.draw_series(std::iter::once(label)).map_err(e)?;
        }
        if s.budget > 0.0 {
            let grey = RGBColor(120, 120, 120);
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(x0, s.budget), (x1, s.budget)],
                    grey.stroke_width(1),
                )))
                .map_err(e)?
                .label(
                    PlotText::Budget {
                        budget: format!("{:.2e}", s.budget),
                    }
                    .text(lang),
                )
                .legend(move |(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], grey));
        }
        if let Some(c) = s.choice {
            chart
                .draw_series(std::iter::once(Circle::new(
                    (x(c), y(err(c))),
                    11,
                    RGBColor(44, 160, 44).stroke_width(3),
                )))
                .map_err(e)?
                .label(PlotText::Fastest { number: c + 1 }.text(lang))
                .legend(|(a, b)| {
                    Circle::new((a + 10, b), 6, RGBColor(44, 160, 44).stroke_width(3))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(e)?;
        root.present().map_err(e)?;
    }
    Ok(out)
}

/// "f32 L5 w1/255 4spp", for the labels on the front.
fn short(s: &super::Setting) -> String {
    format!(
        "{} L{} w{} {}spp",
        s.precision.name(),
        s.max_level,
        weight(s.min_weight),
        s.samples
    )
}
