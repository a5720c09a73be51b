//! The text report of `phong solve`: every step of the hand calculation, in order, each with
//! the chapter's equation number, then the findings and any other reading.

use std::fmt::Write;

use super::messages;
use super::number::{num, vec3};
use crate::core::real::to_f64_array;
use crate::core::{Falloff, LightKind, LightSet, LightStatus, LightTerm, Real, SpecularStatus, V3};
use crate::problem::format::ColorSpec;
use crate::problem::model::ReflectivitySource;
use crate::problem::Problem;
use crate::solve::{Evaluation, Intersection, Side, Solution, ViewSource};

/// Column at which equation references start.
const EQ_COLUMN: usize = 64;

fn v<R: Real>(x: V3<R>) -> String {
    vec3(to_f64_array::<R>(x))
}

fn n<R: Real>(x: R) -> String {
    num(x.to_f64())
}

/// Writes one step, with its equation reference right-aligned in a column.
fn step(out: &mut String, indent: usize, text: &str, eq: &str) {
    let mut line = format!("{:indent$}{text}", "");
    if !eq.is_empty() {
        let width = line.chars().count();
        let pad = EQ_COLUMN.saturating_sub(width).max(2);
        let _ = write!(line, "{:pad$}{eq}", "");
    }
    out.push_str(line.trim_end());
    out.push('\n');
}

/// The text report of one solved problem.
pub fn render<R: Real>(file: &str, problem: &Problem<R>, s: &Solution<R>) -> String {
    let mut out = String::new();
    let title = s.title.as_deref().unwrap_or("Problem");
    let _ = writeln!(out, "{title}  ({file}, {})", R::NAME);
    if let Some(q) = &s.question {
        for line in wrap(q, 92) {
            let _ = writeln!(out, "  {line}");
        }
    }
    if !s.findings.is_empty() {
        out.push_str("\nFindings\n");
        for f in &s.findings {
            let text = messages::finding(problem, f);
            for (i, line) in wrap(&text, 90).iter().enumerate() {
                let mark = if i == 0 { "! " } else { "  " };
                let _ = writeln!(out, "  {mark}{line}");
            }
        }
    }
    if let Some(x) = &s.intersection {
        out.push_str("\nRay\n");
        intersection(&mut out, x);
    }
    match &s.evaluation {
        Some(e) => {
            out.push_str("\nSolution (the problem as written)\n");
            evaluation(&mut out, problem, e);
        }
        None => out.push_str(
            "\nSolution (the problem as written)\n  no point to shade: the ray hits nothing\n",
        ),
    }
    for r in &s.readings {
        let _ = writeln!(out, "\nReading: {}", messages::reading_label(r.code));
        for line in wrap(messages::reading_explanation(r.code), 90) {
            let _ = writeln!(out, "  {line}");
        }
        if let Some(x) = &r.intersection {
            intersection(&mut out, x);
        }
        evaluation(&mut out, problem, &r.evaluation);
    }
    out
}

fn intersection<R: Real>(out: &mut String, x: &Intersection<R>) {
    step(out, 2, &format!("origin O = {}", v::<R>(x.origin)), "");
    let length = crate::core::vector::length::<R>(x.direction_given);
    if !crate::core::vector::is_unit_length(length) {
        step(
            out,
            2,
            &format!(
                "direction D = {} / ‖·‖ = {}",
                v::<R>(x.direction_given),
                v::<R>(x.direction)
            ),
            "",
        );
    } else {
        step(
            out,
            2,
            &format!("direction D = {}", v::<R>(x.direction)),
            "",
        );
    }
    match (x.t, x.point, x.kind) {
        (Some(t), Some(p), Some(kind)) => {
            let verdict = if x.in_front {
                "hit (t > 0)"
            } else {
                "behind the origin (t ≤ 0): not a hit"
            };
            step(
                out,
                2,
                &format!(
                    "{kind} ({}): t = {}, O + tD = {}  → {verdict}",
                    messages::surface_label(x.source),
                    n::<R>(t),
                    v::<R>(p)
                ),
                "",
            );
        }
        _ => step(out, 2, "the ray's line meets no surface", ""),
    }
}

/// A material colour as given: "O", or "k·O = k × O".
fn color_spec(c: &ColorSpec) -> String {
    match c {
        ColorSpec::Scaled(s) => format!("{} = {} × {}", vec3(c.product()), num(s.k), vec3(s.color)),
        ColorSpec::Rgb(rgb) => vec3(*rgb),
    }
}

fn evaluation<R: Real>(out: &mut String, problem: &Problem<R>, e: &Evaluation<R>) {
    out.push_str("  Given\n");
    if let Some(p) = e.point {
        step(out, 4, &format!("P = {}", v::<R>(p)), "");
    }
    if let Some(nu) = &e.normal {
        let mut line = format!("N = {}", v::<R>(nu.used));
        let unit = crate::core::vector::is_unit_length(nu.length);
        let how = match (unit, nu.reversed) {
            (true, false) => None,
            (true, true) => Some("reversed".to_owned()),
            (false, reversed) => Some(format!(
                "normalised from {} (length {}){}",
                v::<R>(nu.given),
                n(nu.length),
                if reversed { ", then reversed" } else { "" }
            )),
        };
        if let Some(how) = how {
            let _ = write!(line, "  ({how})");
        }
        step(out, 4, &line, "");
    }
    if let Some(vw) = &e.viewer {
        if let Some(p) = vw.position {
            step(out, 4, &format!("viewer E = {}", v::<R>(p)), "");
        }
    }
    let m = &e.material;
    let name = m
        .name
        .as_deref()
        .map_or(String::new(), |n| format!(" \"{n}\""));
    step(out, 4, &format!("material{name}:"), "");
    let colors = [
        ("O_a", &m.spec.ambient, "Eq. 4.5–4.6"),
        ("O_d", &m.spec.diffuse, "Eq. 4.7–4.8"),
        ("O_s", &m.spec.specular, "Eq. 4.9–4.10"),
    ];
    for (symbol, spec, eq) in colors {
        if let Some(c) = spec {
            step(out, 6, &format!("{symbol} = {}", color_spec(c)), eq);
        }
    }
    if m.spec.shininess.is_some() {
        step(out, 6, &format!("n_s = {}", n(m.material.n_s)), "Eq. 4.9");
    }
    if let Some(o_r) = m.material.o_r {
        let src = match m.reflectivity {
            Some(ReflectivitySource::Specular) => " (taken equal to O_s)",
            _ => "",
        };
        step(out, 6, &format!("O_r = {}{src}", v::<R>(o_r)), "Sec. 4.4");
    }

    out.push_str("  Steps\n");
    if let Some(vw) = &e.viewer {
        let how = match vw.source {
            ViewSource::Viewer => "V = (P − E)/‖P − E‖",
            ViewSource::Ray => "V = D (the ray comes from the eye)",
            ViewSource::ReversedRay => "V = −D (the reversed ray)",
        };
        step(out, 4, &format!("{how} = {}", v::<R>(vw.v)), "Eq. 4.10");
        if let (Some(d), Some(side)) = (vw.n_dot_v, vw.side) {
            let side = match side {
                Side::Front => "the viewer is in front of the surface",
                Side::Back => "the viewer is BEHIND the surface",
                Side::InPlane => "the viewer is in the tangent plane",
            };
            step(out, 6, &format!("N·V = {}: {side}", n(d)), "");
        }
    }
    // Ambient.
    if let (Some(i_a), Some(term)) = (e.lights_used(problem).ambient, e.shade.ambient) {
        if problem.ambient_info.len() > 1 {
            let parts: Vec<_> = problem
                .ambient_info
                .iter()
                .map(|a| v::<R>(a.color))
                .collect();
            let sum = format!("I_a = {} = {}", parts.join(" + "), v::<R>(i_a));
            step(out, 4, &sum, "");
        } else {
            step(out, 4, &format!("I_a = {}", v::<R>(i_a)), "");
        }
        step(
            out,
            4,
            &format!("ambient O_a I_a = {}", v::<R>(term)),
            "Eq. 4.6",
        );
    }
    for o in &e.omitted {
        step(out, 4, &messages::omission(o), "");
    }
    for t in &e.lights {
        light(out, problem, e.lights_used(problem), t);
    }
    // The total.
    out.push_str("  Total\n");
    let zero = <V3<R> as crate::core::Vector<R>>::ZERO;
    step(
        out,
        4,
        &format!("ambient   {}", v::<R>(e.shade.ambient.unwrap_or(zero))),
        "",
    );
    step(
        out,
        4,
        &format!("diffuse   {}", v::<R>(e.shade.diffuse)),
        "Σ Eq. 4.8",
    );
    step(
        out,
        4,
        &format!("specular  {}", v::<R>(e.shade.specular)),
        "Σ Eq. 4.10",
    );
    step(
        out,
        4,
        &format!("I = {}", v::<R>(e.shade.color)),
        "Eq. 4.16",
    );
    step(
        out,
        4,
        &format!(
            "colour: {} clamped to [0, 1]; 8-bit ({}, {}, {})",
            v::<R>(e.clamped),
            e.rgb8[0],
            e.rgb8[1],
            e.rgb8[2]
        ),
        "",
    );
    if let Some(l) = e.shade.literal {
        if l != e.shade.color {
            step(
                out,
                4,
                &format!("Eq. 4.16 taken literally (no gating): {}", v::<R>(l)),
                "",
            );
        }
    }
}

fn light<R: Real>(out: &mut String, problem: &Problem<R>, set: &LightSet<R>, t: &LightTerm<R>) {
    let l = &set.lights[t.index];
    let info = &problem.light_info[t.index];
    let a = &t.arrival;
    let name = messages::light_name(problem, info.file_index);
    let head = match l.kind {
        LightKind::Point { position, .. } => format!("at {}", v::<R>(position)),
        LightKind::Spot { position, cone, .. } => format!(
            "at {}, axis D_l = {}, γ = {}°, e = {}",
            v::<R>(position),
            v::<R>(cone.axis),
            n(cone.angle_deg),
            n(cone.exponent)
        ),
        LightKind::Directional { direction } => format!("direction D_l = {}", v::<R>(direction)),
    };
    step(
        out,
        4,
        &format!("Light {name} {head}, C_l = {}", v::<R>(l.color)),
        "",
    );
    if t.status == LightStatus::AtLight {
        step(out, 6, messages::light_status(t.status), "");
        return;
    }
    match (a.distance, a.falloff) {
        (Some(d), Some(f)) => {
            step(
                out,
                6,
                &format!("L = (P − P_l)/‖P − P_l‖ = {}", v::<R>(a.l)),
                "Eq. 4.1",
            );
            step(out, 6, &format!("d = ‖P − P_l‖ = {}", n(d)), "");
            let kind = match f {
                Falloff::None => "none",
                Falloff::Linear => "linear",
                Falloff::Quadratic => "quadratic",
            };
            step(
                out,
                6,
                &format!(
                    "falloff f = {} ({kind}): 1/d^f = {}",
                    f.exponent(),
                    n(a.falloff_factor)
                ),
                "Eq. 4.3",
            );
        }
        _ => step(
            out,
            6,
            &format!("L = D_l = {}; no falloff", v::<R>(a.l)),
            "Sec. 4.2",
        ),
    }
    if let Some(c) = &a.cone {
        let verdict = match (c.inside, c.on_edge) {
            (true, true) => "on the edge (ψ = γ): lit",
            (true, false) => "inside the cone (ψ < γ)",
            _ => "OUTSIDE the cone (ψ > γ)",
        };
        let gamma = match l.kind {
            LightKind::Spot { cone, .. } => n(cone.angle_deg),
            _ => String::new(),
        };
        let test = format!(
            "cos ψ = D_l·L = {}, ψ = {}° vs γ = {gamma}°: {verdict}",
            n(c.cos_psi),
            n(c.psi_deg)
        );
        step(out, 6, &test, "Eq. 4.4");
        step(
            out,
            6,
            &format!("spot factor (cos ψ)^e = {}", n(c.factor)),
            "Eq. 4.4",
        );
    }
    let eq_il = match (a.cone.is_some(), a.distance.is_some()) {
        (true, _) => "Eq. 4.4",
        (false, true) => "Eq. 4.2",
        (false, false) => "Sec. 4.2",
    };
    let formula = match (a.cone.is_some(), a.distance.is_some()) {
        (true, _) => "I_l = C_l/d^f · (cos ψ)^e",
        (false, true) => "I_l = C_l/d^f",
        (false, false) => "I_l = C_l",
    };
    step(out, 6, &format!("{formula} = {}", v::<R>(a.i_l)), eq_il);
    if t.status == LightStatus::OutsideCone {
        step(
            out,
            6,
            &format!("status: {}", messages::light_status(t.status)),
            "",
        );
        return;
    }
    step(
        out,
        6,
        &format!("N·L = {};  cos θ = −N·L = {}", n(t.n_dot_l), n(t.cos_theta)),
        "Eq. 4.7",
    );
    step(
        out,
        6,
        &format!("status: {}", messages::light_status(t.status)),
        "",
    );
    if let Some(d) = t.diffuse {
        let mut line = format!("diffuse O_d I_l cos θ = {}", v::<R>(d));
        if let Some(lit) = t.diffuse_literal.filter(|l| *l != d) {
            let _ = write!(line, "   [literally {}]", v::<R>(lit));
        }
        step(out, 6, &line, "Eq. 4.8");
    }
    let s = &t.specular;
    match s.status {
        SpecularStatus::NoViewer | SpecularStatus::NoSpecularColor => step(
            out,
            6,
            &format!("specular: {}", messages::specular_status(s.status)),
            "",
        ),
        _ => {
            if let Some(r) = s.r {
                step(
                    out,
                    6,
                    &format!("R = L − 2(N·L)N = {}", v::<R>(r)),
                    "Eq. 4.15",
                );
            }
            if let Some(c) = s.cos_phi {
                step(out, 6, &format!("cos φ = −R·V = {}", n(c)), "Eq. 4.10");
            }
            if let Some(p) = s.cos_phi_pow {
                step(out, 6, &format!("(cos φ)^n_s = {}", n(p)), "Eq. 4.10");
            }
            let mut line = format!("specular O_s I_l (cos φ)^n_s = {}", v::<R>(s.term));
            match s.literal {
                Some(lit) if lit != s.term => {
                    let _ = write!(line, "   [literally {}]", v::<R>(lit));
                }
                None if s.cos_phi.is_some() => {
                    line.push_str("   [literally undefined: negative cos φ to a non-integer n_s]")
                }
                _ => {}
            }
            step(out, 6, &line, "Eq. 4.10");
            if s.status != SpecularStatus::Lit {
                step(out, 8, messages::specular_status(s.status), "");
            }
        }
    }
}

/// Word-wraps a paragraph to lines of at most `width` characters.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}
