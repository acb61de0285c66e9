//! The step-time distribution, the error percentiles and the verdicts of a replay.
//!
//! Percentiles use the nearest-rank definition (Hyndman & Fan 1996, definition 1): the p-th
//! percentile of n sorted values is the value of rank ⌈p·n⌉. It always returns a value that was
//! measured, which is what a timing budget must be held to (no interpolation between a fast
//! and a slow step).

use serde::Serialize;

/// Nearest-rank percentile of sorted values; `None` for an empty slice.
pub fn percentile_sorted<T: Copy>(sorted: &[T], p: f64) -> Option<T> {
    if sorted.is_empty() {
        return None;
    }
    let rank = (p.clamp(0.0, 1.0) * sorted.len() as f64).ceil() as usize;
    sorted.get(rank.clamp(1, sorted.len()) - 1).copied()
}

/// Nearest-rank percentile of unsorted f64 values (NaN sorts last and so counts as the worst).
pub fn percentile(values: &[f64], p: f64) -> Option<f64> {
    let mut sorted = values.to_vec();
    sorted.sort_by(|a, b| a.total_cmp(b));
    percentile_sorted(&sorted, p)
}

/// Distribution of step times (ns).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepTimeStats {
    /// Fastest step.
    pub min: u64,
    /// 50th percentile.
    pub median: u64,
    /// 99th percentile.
    pub p99: u64,
    /// 99.9th percentile.
    pub p999: u64,
    /// Slowest step.
    pub max: u64,
    /// Arithmetic mean.
    pub mean: f64,
}

impl StepTimeStats {
    /// The distribution of `times_ns`; `None` when empty.
    pub fn of(times_ns: &[u64]) -> Option<StepTimeStats> {
        let mut sorted = times_ns.to_vec();
        sorted.sort_unstable();
        let sum: f64 = sorted.iter().map(|&t| t as f64).sum();
        Some(StepTimeStats {
            min: *sorted.first()?,
            median: percentile_sorted(&sorted, 0.5)?,
            p99: percentile_sorted(&sorted, 0.99)?,
            p999: percentile_sorted(&sorted, 0.999)?,
            max: *sorted.last()?,
            mean: sum / sorted.len() as f64,
        })
    }
}

/// Limits the replay is judged against (the "what must be true").
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Limits {
    /// Step-time budget for the 99.9th percentile (µs).
    pub budget_us: f64,
    /// Largest 99th-percentile relative error of the central film of loaded contacts.
    pub film_rel_err_p99: f64,
    /// Largest 99th-percentile relative error of the bearing force.
    pub force_rel_err_p99: f64,
}

impl Default for Limits {
    /// The replay's limits: p99.9 step ≤ 10 µs on the host; film within 2 % and force within 1 % at the
    /// 99th percentile against the full numerical solver.
    fn default() -> Self {
        Self {
            budget_us: 10.0,
            film_rel_err_p99: 0.02,
            force_rel_err_p99: 0.01,
        }
    }
}

/// Budget verdict: the 99.9th-percentile step time within the budget. Returns the reason when
/// it is missed.
pub fn budget_verdict(times: &StepTimeStats, limits: &Limits) -> Result<(), String> {
    let budget_ns = limits.budget_us * 1e3;
    if (times.p999 as f64) <= budget_ns {
        Ok(())
    } else {
        Err(format!(
            "timing budget missed: p99.9 step time {:.3} µs > budget {} µs",
            times.p999 as f64 / 1e3,
            limits.budget_us
        ))
    }
}

/// Accuracy verdict from the error percentiles. Returns every limit missed.
pub fn accuracy_verdict(
    film_rel_err_p99: Option<f64>,
    force_rel_err_p99: Option<f64>,
    limits: &Limits,
) -> Result<(), Vec<String>> {
    let mut reasons = Vec::new();
    // A NaN error is a failure, not a pass.
    if let Some(film) = film_rel_err_p99 {
        if film.is_nan() || film > limits.film_rel_err_p99 {
            reasons.push(format!(
                "accuracy missed: central film p99 relative error {:.3} % > {:.3} %",
                film * 100.0,
                limits.film_rel_err_p99 * 100.0
            ));
        }
    }
    if let Some(force) = force_rel_err_p99 {
        if force.is_nan() || force > limits.force_rel_err_p99 {
            reasons.push(format!(
                "accuracy missed: bearing force p99 relative error {:.3} % > {:.3} %",
                force * 100.0,
                limits.force_rel_err_p99 * 100.0
            ));
        }
    }
    if reasons.is_empty() {
        Ok(())
    } else {
        Err(reasons)
    }
}

/// Smallest, mean and largest of a quantity over the steps.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Range {
    /// Smallest value.
    pub min: f64,
    /// Arithmetic mean.
    pub mean: f64,
    /// Largest value.
    pub max: f64,
}

impl Range {
    /// The range of `values`; `None` when empty.
    pub fn of(values: impl Iterator<Item = f64>) -> Option<Range> {
        let (mut min, mut max, mut sum, mut n) = (f64::INFINITY, f64::NEG_INFINITY, 0.0, 0usize);
        for v in values {
            min = min.min(v);
            max = max.max(v);
            sum += v;
            n += 1;
        }
        (n > 0).then(|| Range {
            min,
            mean: sum / n as f64,
            max,
        })
    }
}

/// The mean power loss of every step split by mechanism (W; docs/physics.md §8.4).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PowerLossSplit {
    /// Rolling (hydrodynamic) resistance of the films' inlets.
    pub rolling: f64,
    /// Viscous (Eyring) shear of the films.
    pub viscous: f64,
    /// Boundary friction of the asperities.
    pub boundary: f64,
}

/// The friction the core computed after every step (`Bearing::friction`), and what that call
/// cost on the host.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FrictionSummary {
    /// Friction torque on the inner ring over the steps (N·m).
    pub friction_torque_nm: Range,
    /// Power loss over the steps (W).
    pub power_loss_w: Range,
    /// Mean power loss by mechanism (W).
    pub power_loss_split_mean_w: PowerLossSplit,
    /// Time of the friction call after each step (ns), measured apart from the step.
    pub friction_time_ns: StepTimeStats,
}

impl FrictionSummary {
    /// The summary of every step's outputs and friction times; `None` without steps.
    pub fn of(outputs: &[crate::outputs::StepOutputs], times_ns: &[u64]) -> Option<Self> {
        let mean_of = |k: usize| {
            Range::of(outputs.iter().map(|o| f64::from(o.power_loss_split_w[k]))).map(|r| r.mean)
        };
        Some(FrictionSummary {
            friction_torque_nm: Range::of(outputs.iter().map(|o| f64::from(o.friction_torque_nm)))?,
            power_loss_w: Range::of(outputs.iter().map(|o| f64::from(o.power_loss_w)))?,
            power_loss_split_mean_w: PowerLossSplit {
                rolling: mean_of(0)?,
                viscous: mean_of(1)?,
                boundary: mean_of(2)?,
            },
            friction_time_ns: StepTimeStats::of(times_ns)?,
        })
    }
}
