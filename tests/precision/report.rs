//! Per-group summaries of the measurements, and the Markdown tables of README.md.

use super::measure::{CaseResult, Measured};
use super::suite::GROUPS;

/// One precision's errors over a group.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub cases: usize,
    /// Cases phong refused (validation errors), with one message.
    pub refused: usize,
    pub refusal: Option<String>,
    /// Over the refused cases: the core's own colour error (max ulps), and the cases where the
    /// core could not give a finite colour either.
    pub core_when_refused_ulps: f64,
    pub core_also_fails: usize,
    pub non_finite: Vec<String>,
    /// Cases with a gate decided unlike the exact decision, and how many of those are the cone
    /// edge's stated tolerance.
    pub gate_cases: Vec<String>,
    pub edge_tolerance_cases: usize,
    /// Over the cases solved with every gate as the reference decides.
    pub color_ulps: Vec<f64>,
    pub color_scaled_max: f64,
    pub cos_theta_eps_max: f64,
    pub cos_phi_eps_max: f64,
    pub i_l_ulps_max: f64,
    /// Largest absolute colour error where a gate differs.
    pub gate_color_abs_max: f64,
}

impl Stats {
    fn add(&mut self, name: &str, m: &Measured) {
        self.cases += 1;
        if let Some(e) = &m.refused {
            self.refused += 1;
            self.refusal.get_or_insert_with(|| e.clone());
            match &m.core_when_refused {
                Some(Ok(u)) => self.core_when_refused_ulps = self.core_when_refused_ulps.max(*u),
                _ => self.core_also_fails += 1,
            }
            return;
        }
        if m.non_finite {
            self.non_finite.push(name.to_owned());
        }
        if !m.gates.is_empty() {
            let what: Vec<String> = m
                .gates
                .iter()
                .map(|g| {
                    format!(
                        "light {} {}: exact {}, phong {}{}",
                        g.light,
                        g.what,
                        g.reference,
                        g.phong,
                        if g.edge_tolerance {
                            " (within the edge tolerance)"
                        } else {
                            ""
                        }
                    )
                })
                .collect();
            self.gate_cases.push(format!(
                "{name}: {}; |Δcolour| {:.1e}",
                what.join(", "),
                m.color_abs
            ));
            if m.gates.iter().all(|g| g.edge_tolerance) {
                self.edge_tolerance_cases += 1;
            }
            self.gate_color_abs_max = self.gate_color_abs_max.max(m.color_abs);
            return;
        }
        self.color_ulps.push(m.color_ulps);
        self.color_scaled_max = self.color_scaled_max.max(m.color_scaled);
        self.cos_theta_eps_max = self.cos_theta_eps_max.max(m.cos_theta_eps);
        self.cos_phi_eps_max = self.cos_phi_eps_max.max(m.cos_phi_eps);
        self.i_l_ulps_max = self.i_l_ulps_max.max(m.i_l_ulps);
    }

    pub fn max_ulps(&self) -> f64 {
        self.color_ulps.iter().copied().fold(0.0, f64::max)
    }

    pub fn median_ulps(&self) -> f64 {
        median(&self.color_ulps)
    }

    /// Cases solved, with gates as the reference decides.
    pub fn compared(&self) -> usize {
        self.color_ulps.len()
    }
}

pub fn median(xs: &[f64]) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// A group's statistics in each precision.
#[derive(Clone, Debug)]
pub struct Group {
    pub key: &'static str,
    pub title: &'static str,
    pub f64: Stats,
    pub f32: Stats,
    pub f32_own: Stats,
}

pub fn summarize(results: &[CaseResult]) -> Vec<Group> {
    GROUPS
        .iter()
        .map(|&(key, title)| {
            let mut g = Group {
                key,
                title,
                f64: Stats::default(),
                f32: Stats::default(),
                f32_own: Stats::default(),
            };
            for r in results.iter().filter(|r| r.group == key) {
                g.f64.add(&r.name, &r.f64);
                g.f32.add(&r.name, &r.f32);
                g.f32_own.add(&r.name, &r.f32_own);
            }
            g
        })
        .collect()
}

/// An error in ulps as a short number: 0, 0.73, 12, 3.1e6.
pub fn short(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else if x == 0.0 {
        "0".into()
    } else if x < 10.0 {
        format!("{x:.2}")
    } else if x < 1e4 {
        format!("{x:.0}")
    } else {
        format!("{x:.1e}")
    }
}

fn errors(s: &Stats) -> String {
    if s.compared() == 0 {
        return "–".into();
    }
    format!("{} / {}", short(s.max_ulps()), short(s.median_ulps()))
}

fn scaled(s: &Stats) -> String {
    if s.compared() == 0 {
        return "–".into();
    }
    short(s.color_scaled_max)
}

fn gates(s: &Stats) -> String {
    let n = s.gate_cases.len();
    let mut out = if n == 0 {
        "0".to_string()
    } else if s.edge_tolerance_cases > 0 {
        format!("{n} ({} edge tol.)", s.edge_tolerance_cases)
    } else {
        format!("{n}")
    };
    if s.refused > 0 {
        out += &format!(", {} refused", s.refused);
    }
    if !s.non_finite.is_empty() {
        out += &format!(", {} NOT FINITE", s.non_finite.len());
    }
    out
}

/// The accuracy table: per group, the colour error (max / median, in ulps of the precision),
/// the conditioning-scaled error, and the gates decided unlike the exact decision.
pub fn accuracy_table(groups: &[Group]) -> String {
    let mut t = String::new();
    t += "| case group | n | f64 error, ulps max / median | f64 scaled | f64 gates | \
          f32 error, ulps max / median | f32 scaled | f32 gates | \
          f32 on its own inputs, ulps max / median | f32 own scaled | f32 own gates |\n";
    t += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for g in groups {
        t += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            g.title,
            g.f64.cases,
            errors(&g.f64),
            scaled(&g.f64),
            gates(&g.f64),
            errors(&g.f32),
            scaled(&g.f32),
            gates(&g.f32),
            errors(&g.f32_own),
            scaled(&g.f32_own),
            gates(&g.f32_own),
        );
    }
    t
}

/// The intermediates: cos θ and cos φ (absolute, in ε) and I_l (ulps), max over each group.
pub fn intermediates_table(groups: &[Group]) -> String {
    let mut t = String::new();
    t += "| case group | f64 \\|Δcos θ\\|/ε | f64 \\|Δcos φ\\|/ε | f64 I_l ulps | \
          f32 \\|Δcos θ\\|/ε | f32 \\|Δcos φ\\|/ε | f32 I_l ulps |\n";
    t += "|---|---:|---:|---:|---:|---:|---:|\n";
    for g in groups {
        t += &format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            g.title,
            short(g.f64.cos_theta_eps_max),
            short(g.f64.cos_phi_eps_max),
            short(g.f64.i_l_ulps_max),
            short(g.f32.cos_theta_eps_max),
            short(g.f32.cos_phi_eps_max),
            short(g.f32.i_l_ulps_max),
        );
    }
    t
}

/// Every case whose gates differ, refused or not finite, by group and precision.
pub fn details(groups: &[Group]) -> String {
    let mut t = String::new();
    for g in groups {
        for (p, s) in [
            ("f64", &g.f64),
            ("f32", &g.f32),
            ("f32 (own inputs)", &g.f32_own),
        ] {
            for c in &s.gate_cases {
                t += &format!("- {} [{p}] {c}\n", g.key);
            }
            for c in &s.non_finite {
                t += &format!("- {} [{p}] NOT FINITE: {c}\n", g.key);
            }
            if let Some(e) = &s.refusal {
                t += &format!(
                    "- {} [{p}] {} refused, e.g. \"{e}\"; the core alone (no solver checks) \
                     gives a finite colour for {} of them, max {} ulps\n",
                    g.key,
                    s.refused,
                    s.refused - s.core_also_fails,
                    short(s.core_when_refused_ulps)
                );
            }
        }
    }
    t
}
