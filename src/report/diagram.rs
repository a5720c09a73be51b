//! The diagram of the plane of incidence at P for one light, as inline SVG: the surface, N, L
//! arriving from the light, R and V arriving from the viewer, with the light and the viewer
//! marked and labelled. Every element the page's test looks for has an id.
//!
//! The drawing plane is the plane of N and L (the chapter's Figures 4.3 and 4.4): N points up,
//! the light is on the left. A vector is drawn by its components along N and along the part of
//! L perpendicular to N. R lies in this plane; V in general does not, and is drawn projected
//! (the caption says so). When L is along N any plane through N will do: the one holding V is
//! taken. Several lights: one diagram each, since each light has its own plane of incidence.

use std::fmt::Write;

use super::explain::Diagram;
use super::formula::push_html_escaped;
use super::lang::Lang;
use super::messages::Phrase;

type V = [f64; 3];

fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub_scaled(a: V, k: f64, b: V) -> V {
    [a[0] - k * b[0], a[1] - k * b[1], a[2] - k * b[2]]
}

fn unit(a: V) -> Option<V> {
    let len = dot(a, a).sqrt();
    (len > 1e-9).then(|| a.map(|x| x / len))
}

/// Any unit vector perpendicular to the unit vector `n`.
fn perpendicular(n: V) -> V {
    let axis = if n[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    unit(sub_scaled(axis, dot(axis, n), n)).unwrap_or([1.0, 0.0, 0.0])
}

/// The drawing plane: the unit "across" direction (with N as "up") and notes for the caption.
struct Plane {
    across: V,
    l_along_n: bool,
}

fn plane(d: &Diagram) -> Plane {
    let n = d.n;
    // The part of L across N; the light (at −L) is drawn on the left.
    if let Some(across) = unit(sub_scaled(d.l, dot(d.l, n), n)) {
        return Plane {
            across,
            l_along_n: false,
        };
    }
    // L along N: take the plane that holds V, with the viewer (at −V) on the right.
    let across =
        d.v.and_then(|v| unit(sub_scaled(v, dot(v, n), n)))
            .map(|a| a.map(|x| -x))
            .unwrap_or_else(|| perpendicular(n));
    Plane {
        across,
        l_along_n: true,
    }
}

const SCALE: f64 = 90.0;
const PX: f64 = 170.0;
const PY: f64 = 150.0;

/// Screen coordinates of P + k·(a, b) in the plane (a across, b along N).
fn at(a: f64, b: f64, k: f64) -> (f64, f64) {
    (PX + k * SCALE * a, PY - k * SCALE * b)
}

/// Where to put the label of a vector drawn along (a, b): at k along it, 12 px to one side
/// (`side` = 1 or −1)
/// (its text's baseline a little lower, so that the letter sits centred).
fn beside(a: f64, b: f64, k: f64, side: f64) -> (f64, f64) {
    let (x, y) = at(a, b, k);
    let len = (a * a + b * b).sqrt().max(1e-12);
    // The screen direction is (a, −b); a perpendicular is (b, a).
    (x + side * 12.0 * b / len, y + side * 12.0 * a / len + 5.0)
}

fn escaped(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        push_html_escaped(&mut out, c);
    }
    out
}

/// The colour of each vector's arrow: N, L, R, V.
const COLORS: [(&str, &str); 4] = [
    ("n", "#222222"),
    ("l", "#c77700"),
    ("r", "#1f5fbf"),
    ("v", "#1b6e2c"),
];

/// An arrow of vector `which` ("n", "l", "r", "v") from one point to another.
fn arrow(out: &mut String, id: &str, prefix: &str, which: &str, from: (f64, f64), to: (f64, f64)) {
    let color = COLORS
        .iter()
        .find(|(w, _)| *w == which)
        .map_or("#000", |(_, c)| c);
    let _ = writeln!(
        out,
        r#"<line id="{id}" class="vec {which}" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{color}" stroke-width="2.5" marker-end="url(#{prefix}-arrow-{which})"/>"#,
        from.0, from.1, to.0, to.1
    );
}

fn label(out: &mut String, id: &str, class: &str, (x, y): (f64, f64), text: &str) {
    let _ = writeln!(
        out,
        r#"<text id="{id}" class="{class}" x="{x:.1}" y="{y:.1}" text-anchor="middle">{}</text>"#,
        escaped(text)
    );
}

/// The SVG of one diagram; `id` must be unique in the page.
pub fn svg(d: &Diagram, id: &str, lang: Lang) -> String {
    let pl = plane(d);
    let n = d.n;
    let comp = |x: V| (dot(x, pl.across), dot(x, n));
    let mut out = String::new();
    let marker = id;
    let _ = writeln!(
        out,
        r#"<svg id="{id}" class="diagram" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 340 270" width="340" height="270" role="img">"#
    );
    let _ = writeln!(
        out,
        "<title>{}{}</title>",
        Phrase::DiagramOf.get(lang),
        escaped(&d.light)
    );
    out.push_str("<defs>");
    for (which, color) in COLORS {
        let _ = write!(
            out,
            r#"<marker id="{id}-arrow-{which}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{color}"/></marker>"#
        );
    }
    out.push_str("</defs>\n");
    // The surface and its back side.
    let _ = writeln!(
        out,
        r##"<rect class="back" x="10" y="{PY}" width="320" height="{:.1}" fill="#eeeeee"/>"##,
        270.0 - PY
    );
    let _ = writeln!(
        out,
        r##"<line id="{id}-surface" class="surface" x1="10" y1="{PY}" x2="330" y2="{PY}" stroke="#444" stroke-width="2"/>"##
    );
    label(
        &mut out,
        &format!("{id}-back"),
        "note",
        (60.0, 262.0),
        Phrase::BackSide.get(lang),
    );
    let _ = writeln!(
        out,
        r##"<circle id="{id}-P" cx="{PX}" cy="{PY}" r="3.5" fill="#000"/>"##
    );
    label(
        &mut out,
        &format!("{id}-P-label"),
        "sym",
        (PX + 12.0, PY + 16.0),
        "P",
    );
    // N, up.
    arrow(
        &mut out,
        &format!("{id}-N"),
        marker,
        "n",
        (PX, PY),
        at(0.0, 1.0, 0.7),
    );
    label(
        &mut out,
        &format!("{id}-N-label"),
        "sym",
        beside(0.0, 1.0, 0.6, -1.0),
        "N",
    );
    // The light at −L, and L arriving at P.
    let (la, lb) = comp(d.l);
    let light_at = at(-la, -lb, 1.15);
    arrow(
        &mut out,
        &format!("{id}-L"),
        marker,
        "l",
        at(-la, -lb, 1.0),
        at(-la, -lb, 0.06),
    );
    label(
        &mut out,
        &format!("{id}-L-label"),
        "sym",
        beside(-la, -lb, 0.5, 1.0),
        "L",
    );
    let _ = writeln!(
        out,
        r##"<circle id="{id}-light" class="light" cx="{:.1}" cy="{:.1}" r="9" fill="#ffd633" stroke="#a07800" stroke-width="1.5"/>"##,
        light_at.0, light_at.1
    );
    label(
        &mut out,
        &format!("{id}-light-label"),
        "mark",
        (light_at.0, light_at.1 - 14.0),
        Phrase::LightMark.get(lang),
    );
    // R, where it was computed.
    if let Some(r) = d.r {
        let (ra, rb) = comp(r);
        arrow(
            &mut out,
            &format!("{id}-R"),
            marker,
            "r",
            (PX, PY),
            at(ra, rb, 1.0),
        );
        label(
            &mut out,
            &format!("{id}-R-label"),
            "sym",
            beside(ra, rb, 0.8, -1.0),
            "R",
        );
    }
    // The viewer at −V (projected), and V arriving at P.
    let mut notes = Vec::new();
    if pl.l_along_n {
        notes.push(Phrase::LAlongN.get(lang));
    }
    if let Some(v) = d.v {
        let (va, vb) = comp(v);
        let len = (va * va + vb * vb).sqrt();
        if len < 1e-6 {
            notes.push(Phrase::VOutOfPlane.get(lang));
        } else {
            if len < 1.0 - 1e-9 {
                notes.push(Phrase::VProjected.get(lang));
            }
            // Drawn at unit length in the plane, so that its direction is what shows.
            let (va, vb) = (va / len, vb / len);
            let eye = at(-va, -vb, 1.15);
            arrow(
                &mut out,
                &format!("{id}-V"),
                marker,
                "v",
                at(-va, -vb, 1.0),
                at(-va, -vb, 0.06),
            );
            label(
                &mut out,
                &format!("{id}-V-label"),
                "sym",
                beside(-va, -vb, 0.5, 1.0),
                "V",
            );
            let _ = writeln!(
                out,
                r##"<g id="{id}-viewer" class="viewer"><ellipse cx="{:.1}" cy="{:.1}" rx="12" ry="7" fill="#fff" stroke="#1b6e2c" stroke-width="1.5"/><circle cx="{:.1}" cy="{:.1}" r="3.5" fill="#1b6e2c"/></g>"##,
                eye.0, eye.1, eye.0, eye.1
            );
            label(
                &mut out,
                &format!("{id}-viewer-label"),
                "mark",
                (eye.0, eye.1 - 13.0),
                Phrase::ViewerMark.get(lang),
            );
        }
    }
    out.push_str("</svg>\n");
    let mut caption = format!(
        "{}{}. {}",
        Phrase::DiagramOf.get(lang),
        d.light,
        Phrase::DiagramCaption.get(lang)
    );
    for note in notes {
        caption.push(' ');
        caption.push_str(note);
    }
    format!(
        "<figure class=\"diagram\">\n{out}<figcaption>{}</figcaption>\n</figure>\n",
        escaped(&caption)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::LightStatus;

    fn diagram(n: V, l: V, v: Option<V>) -> Diagram {
        Diagram {
            light: "lights[0] (point)".into(),
            light_index: 0,
            directional: false,
            n,
            l,
            r: None,
            v,
            status: LightStatus::Lit,
        }
    }

    #[test]
    fn the_light_is_drawn_on_the_left_above_the_surface_when_it_is_in_front() {
        // L from the upper left: the light is at −L, up and to the left of P.
        let s = 0.5f64.sqrt();
        let d = diagram([0.0, 0.0, 1.0], [s, 0.0, -s], None);
        let pl = plane(&d);
        assert!((dot(pl.across, [1.0, 0.0, 0.0]) - 1.0).abs() < 1e-12);
        let svg = svg(&d, "t", Lang::En);
        // −L across = −s·90 → x = 170 − 73.2 (at 1.15); up → y < 150.
        let x = PX - 1.15 * SCALE * s;
        let y = PY - 1.15 * SCALE * s;
        assert!(
            svg.contains(&format!(
                r#"id="t-light" class="light" cx="{x:.1}" cy="{y:.1}""#
            )),
            "{svg}"
        );
    }

    #[test]
    fn a_light_along_the_normal_takes_the_plane_that_holds_the_viewer() {
        let d = diagram([0.0, 0.0, 1.0], [0.0, 0.0, -1.0], Some([0.0, -0.6, -0.8]));
        let pl = plane(&d);
        // −V = (0, 0.6, 0.8): its part across N is +y, drawn on the right.
        assert!((pl.across[1] - 1.0).abs() < 1e-12);
        let svg = svg(&d, "t", Lang::En);
        assert!(svg.contains(Phrase::LAlongN.get(Lang::En)));
        assert!(svg.contains(r#"id="t-viewer""#));
    }

    #[test]
    fn a_viewer_perpendicular_to_the_plane_is_not_drawn_and_the_caption_says_so() {
        let d = diagram([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], Some([0.0, 1.0, 0.0]));
        let svg = svg(&d, "t", Lang::Pt);
        assert!(!svg.contains(r#"id="t-viewer""#));
        assert!(svg.contains(Phrase::VOutOfPlane.get(Lang::Pt)));
    }
}
