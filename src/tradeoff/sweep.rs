//! What `phong tradeoff` sweeps: the tracer's settings to measure, every combination of them in
//! a fixed order, and the reference they are measured against; checked as a file's `render`
//! settings are.

use serde::Serialize;

use crate::core::Precision;
use crate::problem::validate::{check_max_level, check_min_weight, check_samples};
use crate::problem::Invalid;

/// The most renders per setting (`--runs`): 1000, a median steady far beyond need.
pub const MAX_RUNS: u32 = 1000;

/// The most primary rays a whole sweep may trace (the reference, and every setting's samples ×
/// runs, over the image): 2^34, about 1.7e10, several hours on a laptop.
pub const MAX_SWEEP_RAYS: u64 = 1 << 34;

/// One setting of the tracer, as swept.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Setting {
    pub precision: Precision,
    pub max_level: u32,
    pub min_weight: f64,
    pub samples: u32,
}

/// What to sweep: every combination of these, in this order (precision, then level, then
/// minimum weight, then samples), each rendered `runs` times, against the `reference`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub precisions: Vec<Precision>,
    pub levels: Vec<u32>,
    pub min_weights: Vec<f64>,
    pub samples: Vec<u32>,
    pub runs: u32,
    pub reference: ReferenceSettings,
}

impl Sweep {
    /// A sweep of these values, each checked by the rules of a file's `render`: no list empty,
    /// every level (the reference's too, reported as `levels`), weight and sample count valid,
    /// at least one run. A refused value is named by its field in [`Sweep`]. A precision, level
    /// or sample count given twice is swept once; the minimum weights are kept as given.
    pub fn new(
        precisions: &[Precision],
        levels: &[u32],
        min_weights: &[f64],
        samples: &[u32],
        runs: u32,
        reference: ReferenceSettings,
    ) -> Result<Sweep, Invalid> {
        for (field, empty) in [
            ("precisions", precisions.is_empty()),
            ("levels", levels.is_empty()),
            ("min_weights", min_weights.is_empty()),
            ("samples", samples.is_empty()),
        ] {
            if empty {
                return Err(Invalid::of(field, SweepFault::Empty));
            }
        }
        for &l in levels.iter().chain([&reference.max_level]) {
            check_max_level(l).map_err(|e| e.at("levels"))?;
        }
        for &w in min_weights {
            check_min_weight(w).map_err(|e| e.at("min_weights"))?;
        }
        for &n in samples {
            check_samples(n).map_err(|e| e.at("samples"))?;
        }
        check_samples(reference.samples).map_err(|e| e.at("reference_samples"))?;
        if runs == 0 || runs > MAX_RUNS {
            return Err(Invalid::of(
                "runs",
                if runs == 0 {
                    SweepFault::NoRuns { most: MAX_RUNS }
                } else {
                    SweepFault::TooManyRuns {
                        runs,
                        most: MAX_RUNS,
                    }
                },
            ));
        }
        Ok(Sweep {
            precisions: dedup(precisions),
            levels: dedup(levels),
            min_weights: min_weights.to_vec(),
            samples: dedup(samples),
            runs,
            reference,
        })
    }

    /// The primary rays the sweep traces over an image of `pixels`: the reference once, every
    /// setting `runs` times.
    pub fn work(&self, pixels: u64) -> u64 {
        let per_level: u64 = self.samples.iter().map(|&n| u64::from(n)).sum();
        let settings = (self.precisions.len() * self.levels.len() * self.min_weights.len()) as u64;
        let per_pixel = settings
            .saturating_mul(per_level)
            .saturating_mul(u64::from(self.runs))
            .saturating_add(u64::from(self.reference.samples));
        per_pixel.saturating_mul(pixels)
    }

    /// Every combination, in the sweep's order.
    pub fn settings(&self) -> Vec<Setting> {
        let mut all = Vec::new();
        for &precision in &self.precisions {
            for &max_level in &self.levels {
                for &min_weight in &self.min_weights {
                    for &samples in &self.samples {
                        all.push(Setting {
                            precision,
                            max_level,
                            min_weight,
                            samples,
                        });
                    }
                }
            }
        }
        all
    }
}

/// The values in their first order, each once.
fn dedup<T: PartialEq + Copy>(values: &[T]) -> Vec<T> {
    let mut out: Vec<T> = Vec::with_capacity(values.len());
    for &v in values {
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The reference's level and samples; it is always f64 with minimum weight 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct ReferenceSettings {
    pub max_level: u32,
    pub samples: u32,
}

impl ReferenceSettings {
    /// The reference as a [`Setting`].
    pub fn setting(self) -> Setting {
        Setting {
            precision: Precision::F64,
            max_level: self.max_level,
            min_weight: 0.0,
            samples: self.samples,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sweep_is_every_combination_in_order() {
        let s = Sweep {
            precisions: vec![Precision::F32, Precision::F64],
            levels: vec![1, 5],
            min_weights: vec![0.0],
            samples: vec![1, 4],
            runs: 1,
            reference: ReferenceSettings {
                max_level: 5,
                samples: 1,
            },
        };
        let all = s.settings();
        assert_eq!(all.len(), 8);
        assert_eq!(
            (all[0].precision, all[0].max_level, all[0].samples),
            (Precision::F32, 1, 1)
        );
        assert_eq!(
            (all[3].precision, all[3].max_level, all[3].samples),
            (Precision::F32, 5, 4)
        );
        assert_eq!(all[4].precision, Precision::F64);
    }

    fn refused(levels: &[u32], samples: &[u32], runs: u32, reference: (u32, u32)) -> String {
        let reference = ReferenceSettings {
            max_level: reference.0,
            samples: reference.1,
        };
        Sweep::new(&[Precision::F64], levels, &[0.0], samples, runs, reference)
            .expect_err("refused")
            .field
    }

    #[test]
    fn a_refused_value_is_named_by_its_field() {
        assert_eq!(refused(&[], &[1], 1, (5, 1)), "levels");
        assert_eq!(refused(&[0, 3], &[1], 1, (5, 1)), "levels");
        // The reference's level is checked with the levels, and named as them.
        assert_eq!(refused(&[3], &[1], 1, (0, 1)), "levels");
        assert_eq!(refused(&[3], &[5000], 1, (5, 1)), "samples");
        assert_eq!(refused(&[3], &[1], 1, (5, 0)), "reference_samples");
        assert_eq!(refused(&[3], &[1], 0, (5, 1)), "runs");
    }

    #[test]
    fn a_value_given_twice_is_swept_once_but_weights_are_kept_as_given() {
        let reference = ReferenceSettings {
            max_level: 5,
            samples: 1,
        };
        let s = Sweep::new(
            &[Precision::F64, Precision::F64],
            &[2, 1, 2],
            &[0.0, 0.0],
            &[4, 4],
            1,
            reference,
        )
        .expect("a valid sweep");
        assert_eq!(s.precisions, [Precision::F64]);
        assert_eq!(s.levels, [2, 1]);
        assert_eq!(s.min_weights, [0.0, 0.0]);
        assert_eq!(s.samples, [4]);
    }
}

crate::faults! {
    /// A sweep's lists and runs refused ([`Sweep::new`]).
    pub enum SweepFault {
        /// A list with nothing in it.
        Empty =>
            "is empty: there is nothing to sweep", "está vazia: não há nada a varrer";
            fix "give at least one value", "dê pelo menos um valor";
        /// No run.
        NoRuns { most: u32 } =>
            "0 runs measure nothing", "0 execuções não medem nada";
            fix "give --runs from 1 to {most} (3 or 5 for a steadier median)",
                "dê --runs de 1 a {most} (3 ou 5 para uma mediana mais estável)";
        /// More runs than the most.
        TooManyRuns { runs: u32, most: u32 } =>
            "{runs} runs are more than {most}", "{runs} execuções são mais que {most}";
            fix "give --runs from 1 to {most} (3 or 5 for a steadier median)",
                "dê --runs de 1 a {most} (3 ou 5 para uma mediana mais estável)";
    }
}
