//! The diagram of the plane of incidence at P for one light, laid out once ([`figure`]) and
//! written as SVG (HTML and Markdown, [`svg`]) or TikZ (LaTeX, [`tikz`]): the surface, N, L
//! arriving from the light, R and V arriving from the viewer, the angles θ (N, −L) and φ (R,
//! −V), a spot's cone, and a ray problem's ray with its origin and the point's t (also a t < 0
//! on the ray's line), with the light, the viewer and the origin marked. Each label is placed
//! where its box overlaps no other label and no line (tests/integration/browser.rs measures them in the
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

/// What a label names, where it is drawn: the label is placed beside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Near {
    /// A mark (P, the light, the viewer, the ray's origin): its centre and half sizes.
    Point((f64, f64), (f64, f64)),
    /// A vector or a line: its two ends.
    Segment((f64, f64), (f64, f64)),
    /// An angle's arc at P: its radius and its screen angles (radians, y down).
    Arc(f64, f64, f64),
}

/// A label, placed so that it overlaps no other label and no line, beside what it names.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    pub id: String,
    /// "sym" (a symbol, bold italic), "mark" (a word), "note" (small, grey).
    pub class: &'static str,
    /// The centre of its text's box.
    pub at: (f64, f64),
    pub text: String,
    /// What it names.
    pub near: Near,
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

    /// An estimate of its box, a little generous: each character's advance in DejaVu Sans
    /// (the pages' font; LaTeX's Computer Modern at the same size is narrower), 10 % more in
    /// bold italic, 5 % more for the renderer, and 2 px each side.
    fn half_size(class: &str, text: &str) -> (f64, f64) {
        let size = Self::size(class);
        let em = text
            .split('\n')
            .map(|line| line.chars().map(advance).sum::<f64>())
            .fold(0.0, f64::max);
        let lines = text.split('\n').count() as f64;
        let bold = if class == "sym" { 1.1 } else { 1.0 };
        let w = em * size * bold * 1.05 + 4.0;
        // DejaVu Sans's line is 1.164 em high (ascent and descent), as a browser measures it.
        (
            w / 2.0,
            (lines - 1.0) * size * LEADING / 2.0 + size * 0.6 + 1.0,
        )
    }

    /// How far its box is from what it names (0 where it touches it): for the tests, which
    /// check the layout from its labels alone (the layout keeps each place's distance).
    #[cfg(test)]
    fn distance(&self) -> f64 {
        let arc = match self.near {
            Near::Arc(radius, from, to) => arc_segments(radius, from, to),
            _ => Vec::new(),
        };
        distance_from(&self.rect(), self.near, &arc)
    }

    /// Its box (for the tests, as [`Label::distance`]).
    #[cfg(test)]
    fn rect(&self) -> Rect {
        Rect::around(self.at, Self::half_size(self.class, &self.text))
    }
}

/// How far the box `r` is from what a label names (0 where it touches it); an arc's segments
/// given.
fn distance_from(r: &Rect, near: Near, arc: &[Segment]) -> f64 {
    match near {
        Near::Point(c, (rx, ry)) => {
            let dx = (c.0 - rx - r.x1).max(r.x0 - c.0 - rx).max(0.0);
            let dy = (c.1 - ry - r.y1).max(r.y0 - c.1 - ry).max(0.0);
            dx.hypot(dy)
        }
        Near::Segment(a, b) => r.distance_to_segment(a, b),
        Near::Arc(..) => arc
            .iter()
            .map(|&(a, b)| r.distance2_to_segment(a, b))
            .fold(f64::INFINITY, f64::min)
            .sqrt(),
    }
}

/// The distance between the baselines of a label's lines, in font sizes.
const LEADING: f64 = 1.2;

/// A character's advance in DejaVu Sans, in em (its metrics, rounded up; 0.75 for what the
/// table does not hold).
fn advance(c: char) -> f64 {
    match c {
        ' ' | ',' | '.' | ':' | ';' | '\'' => 0.32,
        'i' | 'j' | 'l' | 'I' | '|' => 0.28,
        'f' | 't' | '(' | ')' | '[' | ']' => 0.40,
        'r' => 0.42,
        's' | 'z' | 'c' => 0.56,
        'a' | 'e' | 'o' | 'v' | 'x' | 'y' | 'k' => 0.62,
        'b' | 'd' | 'g' | 'h' | 'n' | 'p' | 'q' | 'u' => 0.64,
        'w' => 0.82,
        'm' => 0.98,
        '0'..='9' => 0.64,
        'θ' | 'φ' | 'ψ' | 'γ' => 0.66,
        'J' => 0.30,
        'L' | 'F' => 0.58,
        'E' | 'P' | 'T' | 'Z' | 'S' | 'K' | 'X' | 'Y' | 'B' | 'R' => 0.70,
        'A' | 'V' | 'C' => 0.70,
        'D' | 'G' | 'H' | 'N' | 'U' | 'O' | 'Q' => 0.79,
        'M' | 'W' => 0.99,
        '=' | '−' | '+' | '<' | '>' | '-' => 0.84,
        'á' | 'à' | 'â' | 'ã' | 'é' | 'ê' | 'ó' | 'ô' | 'õ' | 'ú' => 0.64,
        'í' => 0.28,
        'ç' => 0.56,
        _ => 0.75,
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
    /// The box of half sizes `(hw, hh)` centred on `at`.
    fn around(at: (f64, f64), (hw, hh): (f64, f64)) -> Rect {
        Rect {
            x0: at.0 - hw,
            y0: at.1 - hh,
            x1: at.0 + hw,
            y1: at.1 + hh,
        }
    }

    /// The box grown by `m` on every side.
    fn grown(&self, m: f64) -> Rect {
        Rect {
            x0: self.x0 - m,
            y0: self.y0 - m,
            x1: self.x1 + m,
            y1: self.y1 + m,
        }
    }

    /// The square of the distance from the box to the point `p` (0 inside).
    fn distance2_to(&self, p: (f64, f64)) -> f64 {
        let dx = (self.x0 - p.0).max(p.0 - self.x1).max(0.0);
        let dy = (self.y0 - p.1).max(p.1 - self.y1).max(0.0);
        dx * dx + dy * dy
    }

    /// The distance from the box to the segment from `a` to `b` (0 where it crosses it).
    fn distance_to_segment(&self, a: (f64, f64), b: (f64, f64)) -> f64 {
        self.distance2_to_segment(a, b).sqrt()
    }

    /// The square of [`Rect::distance_to_segment`]: the least of the ends' squared distances to
    /// the box and the corners' squared distances to the segment (one square root for many
    /// segments: a label is tried at about a thousand places, an arc is 12 segments).
    fn distance2_to_segment(&self, a: (f64, f64), b: (f64, f64)) -> f64 {
        if self.meets(a, b) {
            return 0.0;
        }
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let len2 = dx * dx + dy * dy;
        let to_segment = |p: (f64, f64)| {
            let t = if len2 > 0.0 {
                (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let (ex, ey) = (p.0 - a.0 - t * dx, p.1 - a.1 - t * dy);
            ex * ex + ey * ey
        };
        [
            self.distance2_to(a),
            self.distance2_to(b),
            to_segment((self.x0, self.y0)),
            to_segment((self.x1, self.y0)),
            to_segment((self.x0, self.y1)),
            to_segment((self.x1, self.y1)),
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min)
    }

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
    /// Its title ("Diagram for lights\[0\] …") and caption (the notes).
    pub title: String,
    pub caption: String,
}

/// Room kept around a label: from another label (on each side), and from a line or a mark.
const LABEL_GAP: f64 = 2.0;
const LINE_GAP: f64 = 1.5;

/// Lays out labels one by one: each at the nearest place beside what it names whose box, with
/// a margin, overlaps no label placed before, no line or arc and no mark, inside the drawing.
struct Placer {
    segments: Vec<((f64, f64), (f64, f64))>,
    dots: Vec<Rect>,
    /// The labels placed so far in this try.
    placed: Vec<Placed>,
    /// The labels to lay out, in the order asked: id, class, text, what it names, the
    /// directions preferred.
    specs: Vec<(String, &'static str, String, Near, Vec<f64>)>,
}

/// One place a label may take: the centre of its text's box, the box, and how far the box is
/// from what the label names. Computed once per layout; the tries only read them.
#[derive(Clone, Copy, Debug)]
struct Place {
    at: (f64, f64),
    rect: Rect,
    distance: f64,
}

/// A form of a label's text (one line, or a mark's name on two or three) and the places it may
/// take, nearest first.
struct Form {
    text: String,
    places: Vec<Place>,
}

/// A label placed in a try: which it is (its spec), in which form, where, and its box grown by
/// the room kept from other labels.
#[derive(Clone, Copy, Debug)]
struct Placed {
    spec: usize,
    form: usize,
    place: Place,
    spaced: Rect,
}

/// How far a label may sit from what it names and still be beside it: about a line of its
/// text (pixels); an angle's symbol, half as far again, where the angle's wedge opens.
pub const BESIDE: f64 = 16.0;

impl Near {
    /// How far a label of this may sit from it ([`BESIDE`]).
    pub fn beside(&self) -> f64 {
        match self {
            Near::Arc(..) => BESIDE * 1.5,
            _ => BESIDE,
        }
    }
}

impl Placer {
    /// Whether a label with this box overlaps nothing placed or drawn, inside the drawing.
    fn free(&self, r: &Rect) -> bool {
        let near = r.grown(LINE_GAP);
        let spaced = r.grown(LABEL_GAP);
        r.inside_canvas()
            && !self.placed.iter().any(|o| o.spaced.overlaps(&spaced))
            && !self.segments.iter().any(|&(a, b)| near.meets(a, b))
            && !self.dots.iter().any(|d| d.overlaps(&near))
    }

    /// The places tried for a label of half sizes `hw`, `hh` beside `near`, nearest first;
    /// at each distance the directions in `prefer` (screen angles, radians) first.
    fn candidates(near: Near, hw: f64, hh: f64, prefer: &[f64]) -> Vec<(f64, f64)> {
        // How far a box reaches from its centre in the direction (c, s).
        let reach = |c: f64, s: f64| c.abs() * hw + s.abs() * hh;
        let around =
            |centre: (f64, f64), (rx, ry): (f64, f64), gaps: &[f64], out: &mut Vec<(f64, f64)>| {
                let mut dirs: Vec<f64> = prefer.to_vec();
                dirs.extend((0..16).map(|k| f64::from(k) * std::f64::consts::PI / 8.0));
                for &g in gaps {
                    for &a in &dirs {
                        let (c, s) = (a.cos(), a.sin());
                        // The box's edge at the distance, then slid along it (a wide label
                        // above a mark near the drawing's edge sits off centre).
                        let k = c.abs() * rx + s.abs() * ry + g + reach(c, s);
                        let slide = s.abs() * hw + c.abs() * hh;
                        for t in [0.0, 0.45, -0.45, 0.9, -0.9] {
                            out.push((
                                centre.0 + c * k - s * t * slide,
                                centre.1 + s * k + c * t * slide,
                            ));
                        }
                        out.push((centre.0 + c * (rx + g + hw), centre.1 + s * (ry + g + hh)));
                    }
                }
            };
        let gaps = [2.0, 4.0, 7.0, 11.0, 16.0];
        let mut out = Vec::new();
        match near {
            Near::Point(c, r) => around(c, r, &[2.0, 4.0, 7.0, 11.0, 16.0, 22.0, 30.0], &mut out),
            Near::Segment(a, b) => {
                let len = (b.0 - a.0).hypot(b.1 - a.1).max(1e-9);
                let (ux, uy) = ((b.0 - a.0) / len, (b.1 - a.1) / len);
                // The two sides, the preferred one first.
                let mut sides = [(-uy, ux), (uy, -ux)];
                if let Some(&p) = prefer.first() {
                    if sides[1].0 * p.cos() + sides[1].1 * p.sin()
                        > sides[0].0 * p.cos() + sides[0].1 * p.sin()
                    {
                        sides.swap(0, 1);
                    }
                }
                for g in gaps {
                    for f in [0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0.03, 0.97] {
                        let anchor = (a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1));
                        for (nx, ny) in sides {
                            let k = g + reach(nx, ny);
                            out.push((anchor.0 + nx * k, anchor.1 + ny * k));
                        }
                    }
                }
                // Around either end, the one farther from P first (N's tip, L's tail).
                let far = |q: (f64, f64)| (q.0 - PX).hypot(q.1 - PY);
                let (first, second) = if far(a) >= far(b) { (a, b) } else { (b, a) };
                around(first, (0.0, 0.0), &gaps, &mut out);
                around(second, (0.0, 0.0), &gaps, &mut out);
            }
            Near::Arc(r, from, to) => {
                let mut delta = to - from;
                while delta > std::f64::consts::PI {
                    delta -= 2.0 * std::f64::consts::PI;
                }
                while delta < -std::f64::consts::PI {
                    delta += 2.0 * std::f64::consts::PI;
                }
                for g in gaps {
                    for f in [0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9] {
                        let a = from + f * delta;
                        let (c, s) = (a.cos(), a.sin());
                        let out_k = r + g + reach(c, s);
                        out.push((PX + c * out_k, PY + s * out_k));
                        let in_k = r - g - reach(c, s);
                        if in_k > 0.0 {
                            out.push((PX + c * in_k, PY + s * in_k));
                        }
                    }
                }
                // Too narrow a wedge: beside either end of the arc, or its middle.
                let point = |f: f64| {
                    let a = from + f * delta;
                    (PX + r * a.cos(), PY + r * a.sin())
                };
                let wide = [2.0, 4.0, 7.0, 11.0, 16.0, 22.0, 30.0];
                around(point(0.5), (0.0, 0.0), &wide, &mut out);
                around(point(0.0), (0.0, 0.0), &wide, &mut out);
                around(point(1.0), (0.0, 0.0), &wide, &mut out);
            }
        }
        out
    }

    /// Asks for `text` beside `near` (the directions in `prefer` first).
    fn place(&mut self, id: String, class: &'static str, text: &str, near: Near, prefer: &[f64]) {
        self.specs
            .push((id, class, text.to_owned(), near, prefer.to_vec()));
    }

    /// Lays out the labels asked for: one by one in the order asked; while some label found
    /// no free place beside what it names, again with those first (a few times), keeping the
    /// best layout (fewest such labels, then the least distance in all).
    fn layout(mut self) -> Vec<Label> {
        let specs = std::mem::take(&mut self.specs);
        let n = specs.len();
        let forms: Vec<Vec<Form>> = specs
            .iter()
            .map(|(_, class, text, near, prefer)| Self::forms(class, text, *near, prefer))
            .collect();
        // One layout: the labels placed in `order`; those not beside what they name, and the
        // labels in the order asked (the same output whatever the tries).
        let mut run = |order: &[usize]| {
            self.placed.clear();
            let mut bad = Vec::new();
            for &k in order {
                if !self.put(k, &specs[k].3, &forms[k]) {
                    bad.push(k);
                }
            }
            let mut placed = std::mem::take(&mut self.placed);
            placed.sort_by_key(|p| p.spec);
            (bad, placed)
        };
        let score = |bad: &Vec<usize>, placed: &Vec<Placed>| {
            (
                bad.len(),
                placed.iter().map(|p| p.place.distance).sum::<f64>(),
            )
        };
        let label = |p: &Placed| {
            let (id, class, _, near, _) = &specs[p.spec];
            Label {
                id: id.clone(),
                class,
                at: p.place.at,
                text: forms[p.spec][p.form].text.clone(),
                near: *near,
            }
        };
        let labels = |placed: Vec<Placed>| placed.iter().map(label).collect::<Vec<Label>>();
        let mut order: Vec<usize> = (0..n).collect();
        let (mut bad, mut placed) = run(&order);
        let mut best = (score(&bad, &placed), placed.clone(), bad.clone());
        let mut tries: Vec<Vec<usize>> = Vec::new();
        // The labels that found no place first (a few rounds), ...
        for _ in 0..5 {
            if bad.is_empty() {
                return labels(placed);
            }
            let rest: Vec<usize> = order.iter().copied().filter(|k| !bad.contains(k)).collect();
            order = bad.clone();
            order.extend(rest);
            (bad, placed) = run(&order);
            let s = score(&bad, &placed);
            if s < best.0 {
                best = (s, placed.clone(), bad.clone());
            }
        }
        if best.2.is_empty() {
            return labels(best.1);
        }
        // ... then each label, or each pair, placed last (it takes what the others leave),
        // then orders shuffled by a fixed generator.
        for last in 0..n {
            let mut o: Vec<usize> = (0..n).filter(|&k| k != last).collect();
            o.push(last);
            tries.push(o);
        }
        for &a in &best.2 {
            for b in (0..n).filter(|&b| b != a) {
                for pair in [[a, b], [b, a]] {
                    let mut o: Vec<usize> = (0..n).filter(|k| !pair.contains(k)).collect();
                    o.extend(pair);
                    tries.push(o);
                }
            }
        }
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut shuffled: Vec<usize> = (0..n).collect();
        for _ in 0..8 {
            for i in (1..n).rev() {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                shuffled.swap(i, (seed % (i as u64 + 1)) as usize);
            }
            tries.push(shuffled.clone());
        }
        for o in tries {
            let (bad, placed) = run(&o);
            let s = score(&bad, &placed);
            if s < best.0 {
                best = (s, placed, bad);
                if best.2.is_empty() {
                    break;
                }
            }
        }
        labels(best.1)
    }

    /// The places a label may take, per form of its text (one line, then two or three for a
    /// mark's name), each nearest to what it names first (to 2 px; the preferred directions
    /// first among those as near). They do not depend on the other labels: computed once.
    fn forms(class: &'static str, text: &str, near: Near, prefer: &[f64]) -> Vec<Form> {
        let mut forms = vec![text.to_owned()];
        if class == "mark" && !text.contains('\n') {
            for n in [2, 3] {
                if let Some(lines) = in_lines(text, n) {
                    forms.push(lines);
                }
            }
        }
        let arc = match near {
            Near::Arc(r, from, to) => arc_segments(r, from, to),
            _ => Vec::new(),
        };
        forms
            .into_iter()
            .map(|text| {
                let (hw, hh) = Label::half_size(class, &text);
                let mut places: Vec<(i64, usize, Place)> = Self::candidates(near, hw, hh, prefer)
                    .into_iter()
                    .enumerate()
                    .map(|(k, at)| {
                        let rect = Rect::around(at, (hw, hh));
                        let distance = distance_from(&rect, near, &arc);
                        let place = Place { at, rect, distance };
                        ((distance / 2.0).round() as i64, k, place)
                    })
                    .collect();
                places.sort_unstable_by_key(|&(d, k, _)| (d, k));
                Form {
                    text,
                    places: places.into_iter().map(|(_, _, p)| p).collect(),
                }
            })
            .collect()
    }

    /// Places label `spec` (naming `near`) at the first free of its places beside what it
    /// names; whether it found one (within [`Near::beside`]).
    fn put(&mut self, spec: usize, near: &Near, forms: &[Form]) -> bool {
        let mut fallback: Option<(usize, Place)> = None;
        let mut free_far: Option<(usize, Place)> = None;
        for (f, form) in forms.iter().enumerate() {
            for &p in &form.places {
                if self.free(&p.rect) {
                    if p.distance <= near.beside() {
                        self.push(spec, f, p);
                        return true;
                    }
                    if free_far.is_none_or(|(_, q)| p.distance < q.distance) {
                        free_far = Some((f, p));
                    }
                    break;
                }
                if fallback.is_none() && p.rect.inside_canvas() {
                    fallback = Some((f, p));
                }
            }
        }
        // Free but not beside, or nowhere free (the tests look for both): the nearest free
        // place, else the first inside the drawing, else the first tried.
        if let Some((f, p)) = free_far.or(fallback).or(forms
            .first()
            .and_then(|form| form.places.first())
            .map(|&p| (0, p)))
        {
            self.push(spec, f, p);
        }
        false
    }

    fn push(&mut self, spec: usize, form: usize, place: Place) {
        self.placed.push(Placed {
            spec,
            form,
            place,
            spaced: place.rect.grown(LABEL_GAP),
        });
    }
}

/// `text` on `n` lines of about the same length, broken at spaces; `None` when it has fewer
/// than `n` words.
fn in_lines(text: &str, n: usize) -> Option<String> {
    // A lone capital (the O of "origem O do raio") stays with the word before it.
    let mut words: Vec<String> = Vec::new();
    for w in text.split(' ') {
        match words.last_mut() {
            Some(last) if w.chars().count() == 1 && w.chars().all(char::is_uppercase) => {
                last.push(' ');
                last.push_str(w);
            }
            _ => words.push(w.to_owned()),
        }
    }
    if words.len() < n {
        return None;
    }
    let total = text.chars().count() as f64;
    let mut lines: Vec<String> = vec![String::new()];
    for (k, w) in words.iter().enumerate() {
        let room = n - lines.len();
        let line = lines.last_mut().expect("a line");
        let left = words.len() - k;
        // A new line once this one holds its share, while words remain for the rest.
        if !line.is_empty()
            && room > 0
            && (line.chars().count() as f64 + w.chars().count() as f64 / 2.0 > total / n as f64
                || left == room)
        {
            lines.push(w.clone());
        } else {
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(w);
        }
    }
    // A line does not end with "and" or "e": the word goes down to start the next.
    for k in 0..lines.len().saturating_sub(1) {
        if let Some((head, last)) = lines[k].rsplit_once(' ') {
            if matches!(last, "e" | "and") {
                let head = head.to_owned();
                lines[k + 1] = format!("{last} {}", lines[k + 1]);
                lines[k] = head;
            }
        }
    }
    (lines.len() == n).then(|| lines.join("\n"))
}

/// The screen angle (radians, y down) of the direction (a, b) in the plane.
fn screen_angle(a: f64, b: f64) -> f64 {
    (-b).atan2(a)
}

/// A straight piece of the drawing: its two ends.
type Segment = ((f64, f64), (f64, f64));

/// A mark to draw: its item, centre, half sizes, name and its label's id.
type Mark<'a> = (Item, (f64, f64), (f64, f64), &'a str, String);

/// A vector to name: its id, the names it carries, its two ends, its screen angle from P and
/// the side its label prefers.
type Named<'a> = (&'a str, Vec<&'a str>, (f64, f64), (f64, f64), f64, f64);

/// A diagram's figure in each language, laid out at its first drawing and kept: a document
/// drawn in several formats (SVG in HTML and Markdown, TikZ in LaTeX, the Moodle quiz) lays it
/// out once. The figure is the one of the diagram's fields as they are at that first drawing.
#[derive(Clone, Default)]
pub struct Laid([std::sync::OnceLock<Figure>; 2]);

impl std::fmt::Debug for Laid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Laid")
    }
}

/// A kept layout is a function of the diagram's other fields: it never tells two diagrams apart.
impl PartialEq for Laid {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// The diagram of one light, laid out ([`Laid`]: once per language), its ids starting with
/// `id`.
pub fn figure(d: &Diagram, id: &str, lang: Lang) -> Figure {
    let slot = match lang {
        Lang::En => 0,
        Lang::Pt => 1,
    };
    d.laid.0[slot].get_or_init(|| lay_out(d, lang)).with_id(id)
}

impl Figure {
    /// The figure with `id` before each of its ids (laid out with none: "-N", "-P-label").
    fn with_id(&self, id: &str) -> Figure {
        let mut f = self.clone();
        for item in &mut f.items {
            match item {
                Item::Line { id: i, .. }
                | Item::Dot { id: i, .. }
                | Item::Eye { id: i, .. }
                | Item::Cone { id: i, .. }
                | Item::Arc { id: i, .. } => i.insert_str(0, id),
                Item::Back => {}
            }
        }
        for l in &mut f.labels {
            l.id.insert_str(0, id);
        }
        f
    }
}

/// Lays out the diagram of one light, its ids without their prefix ("-N").
fn lay_out(d: &Diagram, lang: Lang) -> Figure {
    let id = "";
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
    let n_tip = at(0.0, 1.0, 0.8);
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
            // Seen from the viewer's direction (a viewer at the ray's origin, or V taken as
            // the ray's direction), the origin is drawn where the viewer is: one mark, both
            // names.
            let with_viewer = v_dir.is_some_and(|(va, vb)| {
                (-va) * (s * da) + (-vb) * (s * db) > 2f64.to_radians().cos()
            });
            let origin = at(s * da, s * db, if with_viewer { 1.15 } else { 1.35 });
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
    }
    // The marks: the ray's origin, the viewer, the light. Marks that coincide at the
    // drawing's scale (one's centre within the other's size) are drawn once, the first of
    // them, and labelled with every name ("light and viewer").
    let mut marks: Vec<Mark> = Vec::new();
    if let Some((origin, _, _)) = ray_marks {
        marks.push((
            Item::Dot {
                id: format!("{id}-origin"),
                class: "origin",
                at: origin,
                r: 4.5,
                fill: "#8a2be2",
                stroke: "#4b0082",
            },
            origin,
            (4.5, 4.5),
            Phrase::RayOriginMark.get(lang),
            format!("{id}-origin-label"),
        ));
    }
    if let Some((va, vb)) = v_dir {
        let eye = at(-va, -vb, 1.15);
        marks.push((
            Item::Eye {
                id: format!("{id}-viewer"),
                at: eye,
            },
            eye,
            (12.0, 7.0),
            Phrase::ViewerMark.get(lang),
            format!("{id}-viewer-label"),
        ));
    }
    marks.push((
        Item::Dot {
            id: format!("{id}-light"),
            class: "light",
            at: light_at,
            r: 9.0,
            fill: "#ffd633",
            stroke: "#a07800",
        },
        light_at,
        (9.0, 9.0),
        Phrase::LightMark.get(lang),
        format!("{id}-light-label"),
    ));
    // Groups, in the order of the names: the light first, then the viewer, then the origin.
    marks.reverse();
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, m) in marks.iter().enumerate() {
        let coincides = |g: &Vec<usize>| {
            g.iter().any(|&k| {
                let o = &marks[k];
                (o.1 .0 - m.1 .0).hypot(o.1 .1 - m.1 .1) < o.2 .0.max(m.2 .0) + 2.0
            })
        };
        match groups.iter_mut().find(|g| coincides(g)) {
            Some(g) => g.push(i),
            None => groups.push(vec![i]),
        }
    }
    // Drawn under P, the last drawn on top: the origin, the viewer, the light.
    for g in groups.iter().rev() {
        items.push(marks[g[0]].0.clone());
    }
    items.push(Item::Dot {
        id: format!("{id}-P"),
        class: "point",
        at: p,
        r: 3.5,
        fill: "#000000",
        stroke: "#000000",
    });
    // θ between N and −L, φ between R and −V, as arcs at P. A narrow angle gets a wider
    // arc, so that its symbol fits between the two vectors beside the arc (the wedge is
    // about 28 px wide a dozen pixels past the arc); φ's arc stays outside θ's.
    let up = screen_angle(0.0, 1.0);
    let wedge = |from: f64, to: f64| {
        let mut delta = (to - from).abs() % (2.0 * std::f64::consts::PI);
        if delta > std::f64::consts::PI {
            delta = 2.0 * std::f64::consts::PI - delta;
        }
        delta.max(1e-3)
    };
    let mut arcs = Vec::new();
    let mut theta_r = None;
    if lb < 0.0 {
        let to = screen_angle(-la, -lb);
        let r = (28.0 / wedge(up, to) - 12.0).clamp(26.0, 46.0);
        theta_r = Some(r);
        arcs.push(("theta", "l", r, up, to, "θ"));
    }
    if let (Some((ra, rb)), Some((va, vb))) = (r_dir, v_dir) {
        if d.r.is_some() {
            let (from, to) = (screen_angle(ra, rb), screen_angle(-va, -vb));
            // Outside θ's arc, with room for θ's symbol between the two arcs.
            let r = (28.0 / wedge(from, to) - 12.0)
                .clamp(40.0, 85.0)
                .max(theta_r.map_or(0.0, |t| t + 30.0));
            arcs.push(("phi", "r", r, from, to, "φ"));
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

    // What a label may not touch: every line and arc, and every mark.
    let mut segments = Vec::new();
    let mut dots = Vec::new();
    for it in &items {
        match it {
            Item::Line {
                from, to, arrow, ..
            } => {
                segments.push((*from, *to));
                // The arrowhead, wider than the line.
                if *arrow {
                    dots.push(arrowhead(*from, *to, 6.0));
                }
            }
            Item::Arc { r, from, to, .. } => segments.extend(arc_segments(*r, *from, *to)),
            Item::Dot { at, r, .. } => dots.push(Rect {
                x0: at.0 - r,
                y0: at.1 - r,
                x1: at.0 + r,
                y1: at.1 + r,
            }),
            Item::Eye { at, .. } => dots.push(Rect {
                x0: at.0 - 12.0,
                y0: at.1 - 7.0,
                x1: at.0 + 12.0,
                y1: at.1 + 7.0,
            }),
            _ => {}
        }
    }
    let mut placer = Placer {
        segments,
        dots,
        placed: Vec::new(),
        specs: Vec::new(),
    };
    let side = |a: f64, b: f64, s: f64| screen_angle(a, b) + s * std::f64::consts::FRAC_PI_2;
    placer.place(
        format!("{id}-P-label"),
        "sym",
        "P",
        Near::Point(p, (3.5, 3.5)),
        &[0.6, 2.5],
    );
    // The vectors, each named beside its arrow; vectors drawn along one another (within 6°)
    // are named together ("L, V"), beside the longer.
    let mut vectors: Vec<Named> = vec![(
        "N",
        vec!["N"],
        p,
        n_tip,
        screen_angle(0.0, 1.0),
        side(0.0, 1.0, -1.0),
    )];
    vectors.push((
        "L",
        vec!["L"],
        at(-la, -lb, 1.0),
        at(-la, -lb, 0.06),
        screen_angle(-la, -lb),
        side(-la, -lb, 1.0),
    ));
    if let Some((ra, rb)) = r_dir {
        vectors.push((
            "R",
            vec!["R"],
            p,
            at(ra, rb, 1.0),
            screen_angle(ra, rb),
            side(ra, rb, -1.0),
        ));
    }
    if let Some((va, vb)) = v_dir {
        vectors.push((
            "V",
            vec!["V"],
            at(-va, -vb, 1.0),
            at(-va, -vb, 0.06),
            screen_angle(-va, -vb),
            side(-va, -vb, 1.0),
        ));
    }
    let mut merged: Vec<Named> = Vec::new();
    for v in vectors {
        let along = merged.iter_mut().find(|m| {
            let mut delta = (m.4 - v.4).abs() % (2.0 * std::f64::consts::PI);
            if delta > std::f64::consts::PI {
                delta = 2.0 * std::f64::consts::PI - delta;
            }
            delta < 6f64.to_radians()
        });
        match along {
            Some(m) => m.1.extend(v.1),
            None => merged.push(v),
        }
    }
    for (name, _, r, from, to, text) in &arcs {
        let a = (from + to) / 2.0;
        placer.place(
            format!("{id}-{name}-label"),
            "sym",
            text,
            Near::Arc(*r, *from, *to),
            &[a],
        );
    }
    for (name, names, a, b, _, prefer) in &merged {
        placer.place(
            format!("{id}-{name}-label"),
            "sym",
            &names.join(", "),
            Near::Segment(*a, *b),
            &[*prefer],
        );
    }
    for g in &groups {
        let names: Vec<&str> = g.iter().map(|&k| marks[k].3).collect();
        let text = match names.as_slice() {
            [] => String::new(),
            [one] => (*one).to_owned(),
            [init @ .., last] => format!("{}{}{last}", init.join(", "), Phrase::MarksAnd.get(lang)),
        };
        // Away from P first, where the drawing has room, then above.
        let (_, centre, r, _, label_id) = &marks[g[0]];
        let away = (centre.1 - PY).atan2(centre.0 - PX);
        placer.place(
            label_id.clone(),
            "mark",
            &text,
            Near::Point(*centre, *r),
            &[away, -std::f64::consts::FRAC_PI_2],
        );
    }
    if let Some((origin, t, (da, db))) = ray_marks {
        // t names the stretch from the origin to P (the ray for t > 0, its line for t < 0).
        let s = if t > 0.0 { -1.0 } else { 1.0 };
        let text = format!("t = {}", crate::text::number::num(t).replace('-', "−"));
        placer.place(
            format!("{id}-t-label"),
            "note",
            &text,
            Near::Segment(origin, p),
            &[side(s * da, s * db, 1.0)],
        );
    }
    placer.place(
        format!("{id}-back"),
        "note",
        Phrase::BackSide.get(lang),
        Near::Point((50.0, HEIGHT - 14.0), (0.0, 0.0)),
        &[0.0],
    );
    let mut caption = Phrase::DiagramCaption.get(lang).to_owned();
    for note in notes {
        caption.push(' ');
        caption.push_str(note);
    }
    Figure {
        items,
        labels: placer.layout(),
        title: format!("{}{}", Phrase::DiagramOf.get(lang), d.light),
        caption,
    }
}

/// The box of an arrowhead (15 px long and wide, its tip at `to`), `m` each side of its
/// middle.
fn arrowhead(from: (f64, f64), to: (f64, f64), m: f64) -> Rect {
    let len = (to.0 - from.0).hypot(to.1 - from.1).max(1e-9);
    let back = 6.0_f64.min(len / 2.0);
    let c = (
        to.0 - (to.0 - from.0) / len * back,
        to.1 - (to.1 - from.1) / len * back,
    );
    Rect {
        x0: c.0 - m,
        y0: c.1 - m,
        x1: c.0 + m,
        y1: c.1 + m,
    }
}

/// An arc at P as short segments, for what labels must not touch.
fn arc_segments(r: f64, from: f64, to: f64) -> Vec<((f64, f64), (f64, f64))> {
    let mut delta = to - from;
    while delta > std::f64::consts::PI {
        delta -= 2.0 * std::f64::consts::PI;
    }
    while delta < -std::f64::consts::PI {
        delta += 2.0 * std::f64::consts::PI;
    }
    let point = |k: usize| {
        let a = from + delta * k as f64 / 12.0;
        (PX + r * a.cos(), PY + r * a.sin())
    };
    (0..12).map(|k| (point(k), point(k + 1))).collect()
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
        // The label's box is centred on `at`; a line's baseline sits a third of the size
        // below its middle.
        let size = Label::size(l.class);
        let lines: Vec<&str> = l.text.split('\n').collect();
        let first = l.at.1 + size * 0.35 - (lines.len() as f64 - 1.0) * size * LEADING / 2.0;
        let body = match lines.as_slice() {
            [one] => escaped(one),
            _ => lines
                .iter()
                .enumerate()
                .map(|(k, line)| {
                    let dy = if k == 0 { 0.0 } else { size * LEADING };
                    format!(
                        r#"<tspan x="{:.1}" dy="{dy:.1}">{}</tspan>"#,
                        l.at.0,
                        escaped(line)
                    )
                })
                .collect(),
        };
        let _ = writeln!(
            out,
            r#"<text id="{}" class="{}" x="{:.1}" y="{first:.1}" text-anchor="middle">{body}</text>"#,
            l.id, l.class, l.at.0,
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
        // The SVG's size in points (a pixel is 0.02 cm, 0.567 pt), so that the boxes the
        // layout kept apart are the PDF's too (Computer Modern is narrower than DejaVu Sans).
        let size = Label::size(l.class) * 0.567;
        let font = format!(
            "{{\\fontsize{{{size:.1}pt}}{{{:.1}pt}}\\selectfont{}}}",
            size * LEADING,
            if l.class == "sym" {
                "\\bfseries\\itshape"
            } else {
                ""
            }
        );
        let text: Vec<String> = l.text.split('\n').map(escape).collect();
        let _ = writeln!(
            out,
            "\\node[font={font},align=center] at {} {{{}}};",
            pt(l.at),
            text.join("\\\\")
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

    /// Every diagram of an explanation (each part's shading, each light).
    fn diagrams_of(x: &crate::report::explain::Explanation) -> Vec<Diagram> {
        x.parts
            .iter()
            .filter_map(|p| p.shading.as_ref())
            .flat_map(|s| s.diagrams.iter().cloned())
            .collect()
    }

    /// What is wrong with a figure's labels: two that overlap, one that a line, an arc or a
    /// mark crosses, one outside the drawing, one not beside what it names. Boxes are the
    /// layout's own estimate of the text (font size × characters, a little generous).
    fn faults(f: &Figure) -> Vec<String> {
        let mut out = Vec::new();
        let rects: Vec<Rect> = f.labels.iter().map(Label::rect).collect();
        for (i, a) in rects.iter().enumerate() {
            let la = &f.labels[i];
            if !a.inside_canvas() {
                out.push(format!("{} ({:?}) is outside the drawing", la.id, la.text));
            }
            if la.distance() > la.near.beside() {
                out.push(format!(
                    "{} ({:?}) is {:.0} px from what it names",
                    la.id,
                    la.text,
                    la.distance()
                ));
            }
            for (j, b) in rects.iter().enumerate().skip(i + 1) {
                if a.overlaps(b) {
                    out.push(format!("{} overlaps {}", la.id, f.labels[j].id));
                }
            }
            for it in &f.items {
                let hit = match it {
                    Item::Line {
                        id,
                        from,
                        to,
                        arrow,
                        ..
                    } => {
                        let head = arrowhead(*from, *to, 6.0);
                        (a.meets(*from, *to) || (*arrow && head.overlaps(a))).then_some(id)
                    }
                    Item::Arc {
                        id, r, from, to, ..
                    } => arc_segments(*r, *from, *to)
                        .iter()
                        .any(|&(p, q)| a.meets(p, q))
                        .then_some(id),
                    Item::Dot { id, at, r, .. } => Rect {
                        x0: at.0 - r,
                        y0: at.1 - r,
                        x1: at.0 + r,
                        y1: at.1 + r,
                    }
                    .overlaps(a)
                    .then_some(id),
                    Item::Eye { id, at } => Rect {
                        x0: at.0 - 12.0,
                        y0: at.1 - 7.0,
                        x1: at.0 + 12.0,
                        y1: at.1 + 7.0,
                    }
                    .overlaps(a)
                    .then_some(id),
                    _ => None,
                };
                if let Some(id) = hit {
                    out.push(format!("{id} crosses {}", la.id));
                }
            }
        }
        out
    }

    fn check_file(path: &std::path::Path, bad: &mut Vec<String>) -> usize {
        let mut n = 0;
        for lang in [Lang::En, Lang::Pt] {
            let x = crate::report::file::explain_file(path, crate::core::Precision::F64, lang)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            for (k, d) in diagrams_of(&x).iter().enumerate() {
                n += 1;
                for fault in faults(&figure(d, "d", lang)) {
                    bad.push(format!(
                        "{} ({lang:?}) diagram {k}: {fault}",
                        path.display()
                    ));
                }
            }
        }
        n
    }

    #[test]
    fn the_labels_of_400_generated_problems_are_clear_and_beside_what_they_name() {
        use clap::ValueEnum;
        let mut bad = Vec::new();
        let (mut problems, mut n) = (0, 0);
        for &kind in crate::generate::Kind::value_variants() {
            for g in crate::generate::generate(kind, 50, 2026, false) {
                problems += 1;
                let text = g.text();
                let name = std::path::PathBuf::from(&g.file_name);
                let source = crate::problem::Source::Text {
                    name: &name,
                    text: &text,
                };
                let lang = if problems % 2 == 0 {
                    Lang::Pt
                } else {
                    Lang::En
                };
                let x =
                    crate::report::file::explain_source(source, crate::core::Precision::F64, lang)
                        .unwrap_or_else(|e| panic!("{}: {e}", g.file_name));
                for (k, d) in diagrams_of(&x).iter().enumerate() {
                    n += 1;
                    for fault in faults(&figure(d, "d", lang)) {
                        bad.push(format!("{} ({lang:?}) diagram {k}: {fault}", g.file_name));
                    }
                }
            }
        }
        assert!(problems >= 400, "only {problems} problems");
        assert!(n >= 300, "only {n} diagrams");
        assert!(bad.is_empty(), "{} faults:\n{}", bad.len(), bad.join("\n"));
    }

    #[test]
    fn a_long_name_is_set_on_lines_of_about_the_same_length() {
        assert_eq!(in_lines("light", 2), None);
        assert_eq!(
            in_lines("fonte de luz e observador", 2).as_deref(),
            Some("fonte de luz\ne observador")
        );
        assert_eq!(
            in_lines("origem O do raio", 2).as_deref(),
            Some("origem O\ndo raio")
        );
        assert_eq!(
            in_lines("observador e origem O do raio", 3).as_deref(),
            Some("observador\ne origem O\ndo raio")
        );
    }

    #[test]
    fn exercise_4_3_marks_the_light_and_the_viewer_once_with_both_names() {
        // Seen from P = (−64, 4, 60), the light (0, 0, 5) and the viewer (0, 10, 0) lie in
        // almost the same direction, grazing the plane x + y + z = 0: −L and −V differ by
        // about 2°, so at the drawing's scale their marks coincide.
        for (lang, names) in [
            (Lang::En, "light and viewer"),
            (Lang::Pt, "fonte de luz e observador"),
        ] {
            let x = crate::report::file::explain_file(
                std::path::Path::new("exercises/4.3.json"),
                crate::core::Precision::F64,
                lang,
            )
            .unwrap();
            let d = &diagrams_of(&x)[0];
            let f = figure(d, "d", lang);
            let drawn = |id: &str| {
                f.items.iter().any(
                    |it| matches!(it, Item::Dot { id: i, .. } | Item::Eye { id: i, .. } if i == id),
                )
            };
            assert!(drawn("d-light") && !drawn("d-viewer") && drawn("d-origin"));
            let light = f.labels.iter().find(|l| l.id == "d-light-label").unwrap();
            assert_eq!(light.text.replace('\n', " "), names);
            assert!(!f.labels.iter().any(|l| l.id == "d-viewer-label"));
            // L and V are drawn along each other: one label names both.
            let lv = f.labels.iter().find(|l| l.id == "d-L-label").unwrap();
            assert_eq!(lv.text, "L, V");
            assert!(faults(&f).is_empty(), "{:?}", faults(&f));
        }
    }

    #[test]
    fn every_bundled_exercises_labels_are_clear_and_beside_what_they_name() {
        let mut bad = Vec::new();
        let mut n = 0;
        let mut files: Vec<_> = std::fs::read_dir("exercises")
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.push("scenes/4.3.json".into());
        for path in &files {
            n += check_file(path, &mut bad);
        }
        assert!(n >= 30, "only {n} diagrams");
        assert!(bad.is_empty(), "{}", bad.join("\n"));
    }

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
            laid: Laid::default(),
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
