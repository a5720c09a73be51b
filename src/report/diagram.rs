//! The diagram of the plane of incidence at P for one light, laid out once ([`figure`]) and
//! written as SVG (HTML and Markdown, [`svg`]) or TikZ (LaTeX, [`tikz`]): the surface, N, L
//! arriving from the light, R and V arriving from the viewer, the angles θ (N, −L) and φ (R,
//! −V), a spot's cone, and a ray problem's ray with its origin and the point's t (also a t < 0
//! on the ray's line), with the light, the viewer and the origin marked. Each label is placed
//! where its box overlaps no other label and no line (tests/browser.rs measures them in the
//! browser). Every element the page's test looks for has an id.
//!
//! The drawing plane is the plane of N and L (the chapter's Figures 4.3 and 4.4): N points up,
//! the light is on the left. A vector is drawn by its components along N and along the part of
//! L perpendicular to N. R lies in this plane; V in general does not, and is drawn projected
//! (the caption says so). When L is along N any plane through N will do: the one holding V is
//! taken. Several lights: one diagram each, since each light has its own plane of incidence.

use std::fmt::Write;

use super::explain::Diagram;
use super::formula::push_html_escaped;
use super::messages::Phrase;
use crate::text::lang::Lang;

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
const PX: f64 = 180.0;
const PY: f64 = 160.0;
/// The drawing's size, in SVG pixels (TikZ draws it at 0.02 cm a pixel).
const WIDTH: f64 = 360.0;
const HEIGHT: f64 = 290.0;

/// Screen coordinates of P + k·(a, b) in the plane (a across, b along N).
fn at(a: f64, b: f64, k: f64) -> (f64, f64) {
    (PX + k * SCALE * a, PY - k * SCALE * b)
}

fn escaped(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        push_html_escaped(&mut out, c);
    }
    out
}

/// The colour of each vector's arrow: N, L, R, V, and the ray.
const COLORS: [(&str, &str); 5] = [
    ("n", "#222222"),
    ("l", "#c77700"),
    ("r", "#1f5fbf"),
    ("v", "#1b6e2c"),
    ("ray", "#8a2be2"),
];

fn color_of(which: &str) -> &'static str {
    COLORS
        .iter()
        .find(|(w, _)| *w == which)
        .map_or("#000000", |(_, c)| c)
}

/// A piece of the drawing, in screen coordinates (y down).
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A vector's arrow, or a plain line (`arrow` false), dashed or not.
    Line {
        id: String,
        class: &'static str,
        which: &'static str,
        from: (f64, f64),
        to: (f64, f64),
        arrow: bool,
        dashed: bool,
    },
    /// A filled disc (P, the light, the ray's origin).
    Dot {
        id: String,
        class: &'static str,
        at: (f64, f64),
        r: f64,
        fill: &'static str,
        stroke: &'static str,
    },
    /// The viewer's eye.
    Eye { id: String, at: (f64, f64) },
    /// A spot's cone: a translucent triangle from its apex.
    Cone { id: String, points: [(f64, f64); 3] },
    /// The back side of the surface: the lower half, grey.
    Back,
    /// An angle's arc at P, from one screen angle to another (radians, y down).
    Arc {
        id: String,
        which: &'static str,
        r: f64,
        from: f64,
        to: f64,
    },
}

/// A label, placed so that it overlaps no other label and no line.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    pub id: String,
    /// "sym" (a symbol, bold italic), "mark" (a word), "note" (small, grey).
    pub class: &'static str,
    /// The centre of its text's box.
    pub at: (f64, f64),
    pub text: String,
}

impl Label {
    /// Its font size in SVG pixels (the page's stylesheet says the same).
    fn size(class: &str) -> f64 {
        match class {
            "sym" => 15.0,
            "note" => 11.0,
            _ => 12.0,
        }
    }

    /// An estimate of its box (a little generous: DejaVu Sans is about 0.6 em a character).
    fn half_size(class: &str, text: &str) -> (f64, f64) {
        let size = Self::size(class);
        let w = text.chars().count() as f64 * size * 0.64 + 4.0;
        (w / 2.0, size * 0.62 + 2.0)
    }

    fn rect(&self) -> Rect {
        let (hw, hh) = Self::half_size(self.class, &self.text);
        Rect {
            x0: self.at.0 - hw,
            y0: self.at.1 - hh,
            x1: self.at.0 + hw,
            y1: self.at.1 + hh,
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
}

impl Rect {
    fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
    fn inside_canvas(&self) -> bool {
        self.x0 >= 2.0 && self.y0 >= 2.0 && self.x1 <= WIDTH - 2.0 && self.y1 <= HEIGHT - 2.0
    }
    /// Whether the segment from `a` to `b` crosses this box.
    fn meets(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        // Liang–Barsky clipping.
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let mut t0: f64 = 0.0;
        let mut t1: f64 = 1.0;
        for (p, q) in [
            (-dx, a.0 - self.x0),
            (dx, self.x1 - a.0),
            (-dy, a.1 - self.y0),
            (dy, self.y1 - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        t0 <= t1
    }
}

/// A diagram laid out once, for SVG (HTML, Markdown) and TikZ (LaTeX) alike.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub items: Vec<Item>,
    pub labels: Vec<Label>,
    /// Its title ("Diagram for lights[0] …") and caption (the notes).
    pub title: String,
    pub caption: String,
}

/// Lays out labels one by one: each at the first of its candidate places whose box overlaps
/// no label placed before and no line, inside the drawing.
struct Placer {
    segments: Vec<((f64, f64), (f64, f64))>,
    dots: Vec<Rect>,
    labels: Vec<Label>,
}

impl Placer {
    fn free(&self, l: &Label) -> bool {
        let r = l.rect();
        r.inside_canvas()
            && !self.labels.iter().any(|o| o.rect().overlaps(&r))
            && !self.segments.iter().any(|&(a, b)| r.meets(a, b))
            && !self.dots.iter().any(|d| d.overlaps(&r))
    }

    /// Places `text` near `anchor`: tried at growing distances in the directions `prefer`
    /// (screen angles, radians) first, then all around.
    fn place(
        &mut self,
        id: String,
        class: &'static str,
        text: &str,
        anchor: (f64, f64),
        prefer: &[f64],
    ) {
        let mut dirs: Vec<f64> = prefer.to_vec();
        dirs.extend((0..16).map(|k| f64::from(k) * std::f64::consts::PI / 8.0));
        let mut first = None;
        for dist in [14.0, 20.0, 28.0, 38.0, 50.0, 64.0, 80.0] {
            for &a in &dirs {
                let l = Label {
                    id: id.clone(),
                    class,
                    at: (anchor.0 + dist * a.cos(), anchor.1 + dist * a.sin()),
                    text: text.to_owned(),
                };
                if self.free(&l) {
                    self.labels.push(l);
                    return;
                }
                if first.is_none() && l.rect().inside_canvas() {
                    first = Some(l);
                }
            }
        }
        // Nowhere free (never seen): the first place inside the drawing.
        self.labels.push(first.unwrap_or(Label {
            id,
            class,
            at: anchor,
            text: text.to_owned(),
        }));
    }
}

/// The screen angle (radians, y down) of the direction (a, b) in the plane.
fn screen_angle(a: f64, b: f64) -> f64 {
    (-b).atan2(a)
}

/// Lays out the diagram of one light.
pub fn figure(d: &Diagram, id: &str, lang: Lang) -> Figure {
    let pl = plane(d);
    let n = d.n;
    let comp = |x: V| (dot(x, pl.across), dot(x, n));
    let mut items = vec![Item::Back];
    let line = |items: &mut Vec<Item>, name: &str, which: &'static str, from, to, arrow, dashed| {
        items.push(Item::Line {
            id: format!("{id}-{name}"),
            class: if which == "surface" { "surface" } else { "vec" },
            which,
            from,
            to,
            arrow,
            dashed,
        });
    };
    let p = (PX, PY);
    line(
        &mut items,
        "surface",
        "surface",
        (10.0, PY),
        (WIDTH - 10.0, PY),
        false,
        false,
    );
    // N, up.
    let n_tip = at(0.0, 1.0, 0.7);
    line(&mut items, "N", "n", p, n_tip, true, false);
    // The light at −L, and L arriving at P.
    let (la, lb) = comp(d.l);
    let l_len = (la * la + lb * lb).sqrt().max(1e-12);
    let (la, lb) = (la / l_len, lb / l_len);
    let light_at = at(-la, -lb, 1.15);
    // A spot's cone, behind everything else: apex at the light, around its axis (projected).
    if let Some((axis, gamma)) = d.cone {
        let (xa, xb) = comp(axis);
        if (xa * xa + xb * xb).sqrt() > 1e-6 {
            let base = screen_angle(xa, xb);
            let g = gamma.to_radians().min(1.45);
            let len = 1.6 * SCALE / g.cos().max(0.2);
            let edge = |s: f64| {
                (
                    light_at.0 + len * (base + s * g).cos(),
                    light_at.1 + len * (base + s * g).sin(),
                )
            };
            items.insert(
                1,
                Item::Cone {
                    id: format!("{id}-cone"),
                    points: [light_at, edge(1.0), edge(-1.0)],
                },
            );
        }
    }
    line(
        &mut items,
        "L",
        "l",
        at(-la, -lb, 1.0),
        at(-la, -lb, 0.06),
        true,
        false,
    );
    // R, where it was computed.
    let r_dir = d.r.map(|r| {
        let (ra, rb) = comp(r);
        let len = (ra * ra + rb * rb).sqrt().max(1e-12);
        (ra / len, rb / len)
    });
    if let Some((ra, rb)) = r_dir {
        line(&mut items, "R", "r", p, at(ra, rb, 1.0), true, false);
    }
    // The viewer at −V (projected), and V arriving at P: dashed, so that a vector under it
    // (N, L) still shows.
    let mut notes = Vec::new();
    if pl.l_along_n {
        notes.push(Phrase::LAlongN.get(lang));
    }
    let mut v_dir = None;
    if let Some(v) = d.v {
        let (va, vb) = comp(v);
        let len = (va * va + vb * vb).sqrt();
        if len < 1e-6 {
            notes.push(Phrase::VOutOfPlane.get(lang));
        } else {
            if len < 1.0 - 1e-9 {
                notes.push(Phrase::VProjected.get(lang));
            }
            v_dir = Some((va / len, vb / len));
        }
    }
    // A ray problem's ray: its origin, the ray, the point and its t.
    let mut ray_marks = None;
    if let Some((dir, t)) = d.ray {
        let (da, db) = comp(dir);
        let len = (da * da + db * db).sqrt();
        if len > 1e-6 {
            let (da, db) = (da / len, db / len);
            // The origin is at P − tD: behind P along D for t > 0, ahead of it for t < 0.
            let s = if t > 0.0 { -1.0 } else { 1.0 };
            let origin = at(s * da, s * db, 1.35);
            if t > 0.0 {
                line(
                    &mut items,
                    "ray",
                    "ray",
                    origin,
                    at(-da, -db, 0.08),
                    true,
                    true,
                );
            } else {
                // The line back to the point (t < 0), and the ray leaving its origin along D.
                line(&mut items, "line", "ray", origin, p, false, true);
                line(
                    &mut items,
                    "ray",
                    "ray",
                    origin,
                    at(da, db, 1.85),
                    true,
                    false,
                );
            }
            items.push(Item::Dot {
                id: format!("{id}-origin"),
                class: "origin",
                at: origin,
                r: 4.5,
                fill: "#8a2be2",
                stroke: "#4b0082",
            });
            ray_marks = Some((origin, t, (da, db)));
        }
    }
    if let Some((va, vb)) = v_dir {
        line(
            &mut items,
            "V",
            "v",
            at(-va, -vb, 1.0),
            at(-va, -vb, 0.06),
            true,
            true,
        );
        items.push(Item::Eye {
            id: format!("{id}-viewer"),
            at: at(-va, -vb, 1.15),
        });
    }
    items.push(Item::Dot {
        id: format!("{id}-light"),
        class: "light",
        at: light_at,
        r: 9.0,
        fill: "#ffd633",
        stroke: "#a07800",
    });
    items.push(Item::Dot {
        id: format!("{id}-P"),
        class: "point",
        at: p,
        r: 3.5,
        fill: "#000000",
        stroke: "#000000",
    });
    // θ between N and −L, φ between R and −V, as arcs at P.
    let up = screen_angle(0.0, 1.0);
    let mut arcs = Vec::new();
    if lb < 0.0 {
        arcs.push(("theta", "l", 26.0, up, screen_angle(-la, -lb), "θ"));
    }
    if let (Some((ra, rb)), Some((va, vb))) = (r_dir, v_dir) {
        if d.r.is_some() {
            arcs.push((
                "phi",
                "r",
                40.0,
                screen_angle(ra, rb),
                screen_angle(-va, -vb),
                "φ",
            ));
        }
    }
    for (name, which, r, from, to, _) in &arcs {
        items.push(Item::Arc {
            id: format!("{id}-{name}"),
            which,
            r: *r,
            from: *from,
            to: *to,
        });
    }

    // The labels, most constrained first.
    let mut segments = Vec::new();
    for it in &items {
        if let Item::Line { from, to, .. } = it {
            segments.push((*from, *to));
        }
    }
    let mut dots = Vec::new();
    for it in &items {
        let (c, r) = match it {
            Item::Dot { at, r, .. } => (*at, *r),
            Item::Eye { at, .. } => (*at, 12.0),
            _ => continue,
        };
        dots.push(Rect {
            x0: c.0 - r,
            y0: c.1 - r,
            x1: c.0 + r,
            y1: c.1 + r,
        });
    }
    let mut placer = Placer {
        segments,
        dots,
        labels: Vec::new(),
    };
    let side = |a: f64, b: f64, s: f64| screen_angle(a, b) + s * std::f64::consts::FRAC_PI_2;
    let mid = |a: (f64, f64), b: (f64, f64)| ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    placer.place(format!("{id}-P-label"), "sym", "P", p, &[0.6, 2.5]);
    placer.place(
        format!("{id}-N-label"),
        "sym",
        "N",
        at(0.0, 1.0, 0.55),
        &[side(0.0, 1.0, -1.0)],
    );
    placer.place(
        format!("{id}-L-label"),
        "sym",
        "L",
        at(-la, -lb, 0.5),
        &[side(-la, -lb, 1.0)],
    );
    if let Some((ra, rb)) = r_dir {
        placer.place(
            format!("{id}-R-label"),
            "sym",
            "R",
            at(ra, rb, 0.75),
            &[side(ra, rb, -1.0)],
        );
    }
    if let Some((va, vb)) = v_dir {
        placer.place(
            format!("{id}-V-label"),
            "sym",
            "V",
            at(-va, -vb, 0.5),
            &[side(-va, -vb, 1.0)],
        );
    }
    for (name, _, r, from, to, text) in &arcs {
        let a = (from + to) / 2.0;
        let anchor = (PX + r * a.cos(), PY + r * a.sin());
        placer.place(format!("{id}-{name}-label"), "sym", text, anchor, &[a]);
    }
    placer.place(
        format!("{id}-light-label"),
        "mark",
        Phrase::LightMark.get(lang),
        light_at,
        &[-std::f64::consts::FRAC_PI_2],
    );
    if let Some((va, vb)) = v_dir {
        placer.place(
            format!("{id}-viewer-label"),
            "mark",
            Phrase::ViewerMark.get(lang),
            at(-va, -vb, 1.15),
            &[-std::f64::consts::FRAC_PI_2],
        );
    }
    if let Some((origin, t, (da, db))) = ray_marks {
        placer.place(
            format!("{id}-origin-label"),
            "mark",
            Phrase::RayOriginMark.get(lang),
            origin,
            &[-std::f64::consts::FRAC_PI_2],
        );
        let s = if t > 0.0 { -1.0 } else { 1.0 };
        let text = format!("t = {}", crate::text::number::num(t).replace('-', "−"));
        placer.place(
            format!("{id}-t-label"),
            "note",
            &text,
            mid(at(s * da, s * db, 0.7), at(s * da, s * db, 0.6)),
            &[side(s * da, s * db, 1.0), side(s * da, s * db, -1.0)],
        );
    }
    placer.place(
        format!("{id}-back"),
        "note",
        Phrase::BackSide.get(lang),
        (50.0, HEIGHT - 14.0),
        &[0.0],
    );
    let mut caption = Phrase::DiagramCaption.get(lang).to_owned();
    for note in notes {
        caption.push(' ');
        caption.push_str(note);
    }
    Figure {
        items,
        labels: placer.labels,
        title: format!("{}{}", Phrase::DiagramOf.get(lang), d.light),
        caption,
    }
}

/// The points of an arc at P, for SVG's path and TikZ alike: from `from` to `to` the short
/// way round.
fn arc_points(r: f64, from: f64, to: f64) -> ((f64, f64), (f64, f64), bool) {
    let mut delta = to - from;
    while delta > std::f64::consts::PI {
        delta -= 2.0 * std::f64::consts::PI;
    }
    while delta < -std::f64::consts::PI {
        delta += 2.0 * std::f64::consts::PI;
    }
    let a = (PX + r * from.cos(), PY + r * from.sin());
    let b = (PX + r * (from + delta).cos(), PY + r * (from + delta).sin());
    (a, b, delta > 0.0)
}

/// The SVG of one diagram; `id` must be unique in the page.
pub fn svg(d: &Diagram, id: &str, lang: Lang) -> String {
    let f = figure(d, id, lang);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg id="{id}" class="diagram" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {WIDTH} {HEIGHT}" width="{WIDTH}" height="{HEIGHT}" role="img">"#
    );
    let _ = writeln!(out, "<title>{}</title>", escaped(&f.title));
    out.push_str("<defs>");
    for (which, color) in COLORS {
        let _ = write!(
            out,
            r#"<marker id="{id}-arrow-{which}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{color}"/></marker>"#
        );
    }
    out.push_str("</defs>\n");
    for it in &f.items {
        match it {
            Item::Back => {
                let _ = writeln!(
                    out,
                    r##"<rect class="back" x="10" y="{PY}" width="{}" height="{:.1}" fill="#eeeeee"/>"##,
                    WIDTH - 20.0,
                    HEIGHT - PY
                );
            }
            Item::Line {
                id: lid,
                class,
                which,
                from,
                to,
                arrow,
                dashed,
            } => {
                let (color, width) = if *which == "surface" {
                    ("#444444", 2.0)
                } else {
                    (color_of(which), 2.5)
                };
                let marker = if *arrow {
                    format!(r#" marker-end="url(#{id}-arrow-{which})""#)
                } else {
                    String::new()
                };
                let dash = if *dashed {
                    r#" stroke-dasharray="7 4""#
                } else {
                    ""
                };
                let classes = if class == which {
                    (*class).to_owned()
                } else {
                    format!("{class} {which}")
                };
                let _ = writeln!(
                    out,
                    r#"<line id="{lid}" class="{classes}" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{color}" stroke-width="{width}"{dash}{marker}/>"#,
                    from.0, from.1, to.0, to.1
                );
            }
            Item::Dot {
                id: did,
                class,
                at,
                r,
                fill,
                stroke,
            } => {
                let _ = writeln!(
                    out,
                    r#"<circle id="{did}" class="{class}" cx="{:.1}" cy="{:.1}" r="{r}" fill="{fill}" stroke="{stroke}" stroke-width="1.5"/>"#,
                    at.0, at.1
                );
            }
            Item::Eye { id: eid, at } => {
                let _ = writeln!(
                    out,
                    r##"<g id="{eid}" class="viewer"><ellipse cx="{:.1}" cy="{:.1}" rx="12" ry="7" fill="#fff" stroke="#1b6e2c" stroke-width="1.5"/><circle cx="{:.1}" cy="{:.1}" r="3.5" fill="#1b6e2c"/></g>"##,
                    at.0, at.1, at.0, at.1
                );
            }
            Item::Cone { id: cid, points } => {
                let pts: Vec<String> = points
                    .iter()
                    .map(|(x, y)| format!("{x:.1},{y:.1}"))
                    .collect();
                let _ = writeln!(
                    out,
                    r##"<polygon id="{cid}" class="cone" points="{}" fill="#ffd633" fill-opacity="0.25" stroke="#a07800" stroke-dasharray="4 3"/>"##,
                    pts.join(" ")
                );
            }
            Item::Arc {
                id: aid,
                which,
                r,
                from,
                to,
            } => {
                let (a, b, sweep) = arc_points(*r, *from, *to);
                let _ = writeln!(
                    out,
                    r#"<path id="{aid}" class="angle" d="M{:.1},{:.1} A{r},{r} 0 0 {} {:.1},{:.1}" fill="none" stroke="{}" stroke-width="1.2"/>"#,
                    a.0,
                    a.1,
                    u8::from(sweep),
                    b.0,
                    b.1,
                    color_of(which)
                );
            }
        }
    }
    for l in &f.labels {
        // The label's box is centred on `at`; the baseline sits a third of the size lower.
        let _ = writeln!(
            out,
            r#"<text id="{}" class="{}" x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
            l.id,
            l.class,
            l.at.0,
            l.at.1 + Label::size(l.class) * 0.35,
            escaped(&l.text)
        );
    }
    out.push_str("</svg>\n");
    format!(
        "<figure class=\"diagram\">\n{out}<figcaption>{}. {}</figcaption>\n</figure>\n",
        escaped(&f.title),
        escaped(&f.caption)
    )
}

/// The TikZ of one diagram (LaTeX; needs `\usepackage{tikz}`): the same figure as the SVG, at
/// 0.02 cm a pixel, with its title and caption under it.
pub fn tikz(d: &Diagram, lang: Lang) -> String {
    use super::latex::escape;
    let f = figure(d, "d", lang);
    let pt = |(x, y): (f64, f64)| format!("({:.1},{:.1})", x, HEIGHT - y);
    // Each colour by its hex name, defined (xcolor's HTML model) inside the picture.
    let color = |c: &str| format!("ph{}", c.trim_start_matches('#'));
    let mut out = String::new();
    out.push_str("\\begin{center}\n\\begin{tikzpicture}[x=0.02cm,y=0.02cm,>=latex]\n");
    let mut defined: Vec<&str> = Vec::new();
    let used = COLORS.iter().map(|(_, c)| *c).chain([
        "#444444", "#ffd633", "#a07800", "#000000", "#8a2be2", "#4b0082",
    ]);
    for c in used {
        if !defined.contains(&c) {
            defined.push(c);
            let _ = writeln!(
                out,
                "\\definecolor{{{}}}{{HTML}}{{{}}}",
                color(c),
                c.trim_start_matches('#').to_uppercase()
            );
        }
    }
    let _ = writeln!(out, "\\clip (0,0) rectangle ({WIDTH},{HEIGHT});");
    for it in &f.items {
        match it {
            Item::Back => {
                let _ = writeln!(
                    out,
                    "\\fill[black!7] (10,0) rectangle ({},{:.1});",
                    WIDTH - 10.0,
                    HEIGHT - PY
                );
            }
            Item::Line {
                which,
                from,
                to,
                arrow,
                dashed,
                ..
            } => {
                let (c, w) = if *which == "surface" {
                    ("#444444", "1pt")
                } else {
                    (color_of(which), "1.2pt")
                };
                let style = format!(
                    "draw={},line width={w}{}{}",
                    color(c),
                    if *arrow { ",->" } else { "" },
                    if *dashed { ",dashed" } else { "" }
                );
                let _ = writeln!(out, "\\draw[{style}] {} -- {};", pt(*from), pt(*to));
            }
            Item::Dot {
                at,
                r,
                fill,
                stroke,
                ..
            } => {
                let _ = writeln!(
                    out,
                    "\\filldraw[fill={},draw={}] {} circle ({r});",
                    color(fill),
                    color(stroke),
                    pt(*at)
                );
            }
            Item::Eye { at, .. } => {
                let _ = writeln!(
                    out,
                    "\\filldraw[fill=white,draw={}] {} ellipse (12 and 7);\n\\fill[{}] {} circle (3.5);",
                    color("#1b6e2c"),
                    pt(*at),
                    color("#1b6e2c"),
                    pt(*at)
                );
            }
            Item::Cone { points, .. } => {
                let _ = writeln!(
                    out,
                    "\\filldraw[fill={},fill opacity=0.25,draw={},dashed] {} -- {} -- {} -- cycle;",
                    color("#ffd633"),
                    color("#a07800"),
                    pt(points[0]),
                    pt(points[1]),
                    pt(points[2])
                );
            }
            Item::Arc {
                which, r, from, to, ..
            } => {
                let (a, _, _) = arc_points(*r, *from, *to);
                // TikZ's angles go counter-clockwise with y up: the screen angle negated.
                let mut delta = to - from;
                while delta > std::f64::consts::PI {
                    delta -= 2.0 * std::f64::consts::PI;
                }
                while delta < -std::f64::consts::PI {
                    delta += 2.0 * std::f64::consts::PI;
                }
                let _ = writeln!(
                    out,
                    "\\draw[draw={},line width=0.5pt] {} arc[start angle={:.1},delta angle={:.1},radius={r}];",
                    color(color_of(which)),
                    pt(a),
                    -from.to_degrees(),
                    -delta.to_degrees()
                );
            }
        }
    }
    for l in &f.labels {
        let font = match l.class {
            "sym" => "\\bfseries\\itshape\\small",
            "note" => "\\scriptsize",
            _ => "\\footnotesize",
        };
        let _ = writeln!(
            out,
            "\\node[font={font}] at {} {{{}}};",
            pt(l.at),
            escape(&l.text)
        );
    }
    out.push_str("\\end{tikzpicture}\n\n");
    let _ = writeln!(
        out,
        "{{\\small \\emph{{{}.}} {}}}\n\\end{{center}}",
        escape(&f.title),
        escape(&f.caption)
    );
    out
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
            cone: None,
            ray: None,
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
