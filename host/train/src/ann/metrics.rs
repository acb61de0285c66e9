//! Accuracy figures of a film model against reference films: the coefficient of determination
//! R² (on h and on ln h) and percentiles of the absolute relative error.

use serde::{Deserialize, Serialize};

/// Errors of one film output.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FilmErrors {
    /// Number of cases.
    pub count: usize,
    /// `R² = 1 − Σ(h − ĥ)² / Σ(h − h̄)²` on the film in metres.
    pub r2: f64,
    /// R² on ln h (the film spans decades; this weighs thin films equally).
    pub r2_log: f64,
    /// Median |ĥ/h − 1| in percent.
    pub median_pct: f64,
    /// 90th percentile of |ĥ/h − 1|, percent.
    pub p90_pct: f64,
    /// 95th percentile, percent (a model file may omit it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub p95_pct: Option<f64>,
    /// 99th percentile, percent.
    pub p99_pct: f64,
    /// Maximum, percent.
    pub max_pct: f64,
}

/// Nearest-rank percentile of sorted values (`q` in [0, 1]).
pub fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (q * sorted.len() as f64).ceil().max(1.0) as usize;
    sorted[rank.min(sorted.len()) - 1]
}

fn r_squared(pred: &[f64], truth: &[f64]) -> f64 {
    let mean = truth.iter().sum::<f64>() / truth.len() as f64;
    let ss_res: f64 = pred.iter().zip(truth).map(|(p, t)| (t - p) * (t - p)).sum();
    let ss_tot: f64 = truth.iter().map(|t| (t - mean) * (t - mean)).sum();
    1.0 - ss_res / ss_tot
}

/// Errors of `pred` against `truth` (same order, films > 0 in truth).
pub fn film_errors(pred: &[f64], truth: &[f64]) -> FilmErrors {
    let mut rel: Vec<f64> = pred
        .iter()
        .zip(truth)
        .map(|(p, t)| ((p / t) - 1.0).abs() * 100.0)
        .collect();
    rel.sort_by(|a, b| a.total_cmp(b));
    let log_pred: Vec<f64> = pred.iter().map(|p| p.max(f64::MIN_POSITIVE).ln()).collect();
    let log_truth: Vec<f64> = truth.iter().map(|t| t.ln()).collect();
    FilmErrors {
        count: truth.len(),
        r2: r_squared(pred, truth),
        r2_log: r_squared(&log_pred, &log_truth),
        median_pct: percentile(&rel, 0.5),
        p90_pct: percentile(&rel, 0.9),
        p95_pct: Some(percentile(&rel, 0.95)),
        p99_pct: percentile(&rel, 0.99),
        max_pct: rel.last().copied().unwrap_or(f64::NAN),
    }
}

/// Errors of both outputs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Metrics {
    /// Central film.
    pub central: FilmErrors,
    /// Minimum film.
    pub minimum: FilmErrors,
}

impl Metrics {
    /// From predicted and true `(h_c, h_min)` pairs.
    pub fn of(pred: &[(f64, f64)], truth: &[(f64, f64)]) -> Self {
        let col = |v: &[(f64, f64)], k: usize| -> Vec<f64> {
            v.iter().map(|p| if k == 0 { p.0 } else { p.1 }).collect()
        };
        Self {
            central: film_errors(&col(pred, 0), &col(truth, 0)),
            minimum: film_errors(&col(pred, 1), &col(truth, 1)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand values: a perfect prediction gives R² = 1 and zero errors; predicting the mean gives
    /// R² = 0; nearest-rank percentiles of 1..=100 are the ranks themselves.
    #[test]
    fn hand_values() {
        let truth = [1.0, 2.0, 3.0, 4.0];
        let e = film_errors(&truth, &truth);
        assert_eq!((e.r2, e.median_pct, e.max_pct), (1.0, 0.0, 0.0));
        assert!(film_errors(&[2.5; 4], &truth).r2.abs() < 1e-15);
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(
            (
                percentile(&v, 0.5),
                percentile(&v, 0.99),
                percentile(&v, 1.0)
            ),
            (50.0, 99.0, 100.0)
        );
        let e = film_errors(&[1.1, 2.0, 3.0, 4.0], &truth);
        assert!((e.max_pct - 10.0).abs() < 1e-9);
    }
}
