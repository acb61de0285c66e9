//! The machine's pauses: how often the timed loop's CPU is taken away, measured by spinning on
//! the clock.
//!
//! A step's wall time includes whatever interrupted it: the kernel's timer tick, another
//! thread, and on a virtual machine the hypervisor descheduling the virtual CPU — which the
//! guest cannot see (no interrupt is counted, and Firecracker-style VMs report no steal time
//! in `/proc/stat`). The replay cannot remove those pauses, but it can measure them, so that
//! the report tells a slow step of the model from a pause of the machine.
//!
//! After the timed loop, under the same scheduling (CPU, policy), [`PauseProbe::run`] reads the
//! monotonic clock back to back for a fixed time. Consecutive reads are tens of nanoseconds
//! apart; a longer gap is time the thread did not run. A pause of at least
//! `budget − median step` turns the step it lands in into one over the budget, and a pause
//! lands in a step with probability proportional to the time spent stepping, so pauses at a
//! rate `r` (per second) put ≈ `r · n · t_median` of `n` steps over the budget by themselves
//! ([`PauseProbe::summary`]). That is the floor no model speed-up below `t_median` removes
//! on this machine.

use serde::Serialize;
use std::time::{Duration, Instant};

/// Gaps between clock reads shorter than this are the reads themselves, not pauses (ns).
pub const MIN_PAUSE_NS: u64 = 1_000;

/// The pauses seen while spinning on the clock.
#[derive(Clone, Debug, PartialEq)]
pub struct PauseProbe {
    /// Time spent spinning (ns).
    pub duration_ns: u64,
    /// Every gap of at least [`MIN_PAUSE_NS`] between consecutive clock reads (ns).
    pub gaps_ns: Vec<u64>,
}

/// What the probe means for a replay's budget (the report's `environment`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PauseSummary {
    /// Time the probe spun (s).
    pub probe_s: f64,
    /// Pauses counted are at least this long: the budget minus the median step, at least
    /// [`MIN_PAUSE_NS`] (ns).
    pub threshold_ns: u64,
    /// Pauses of at least `threshold_ns`.
    pub pauses: usize,
    /// Their rate (per second).
    pub pauses_per_s: f64,
    /// The longest gap seen (ns).
    pub longest_pause_ns: u64,
    /// Steps the pauses alone are expected to put over the budget: rate × steps × median step.
    pub expected_steps_over_budget: f64,
}

impl PauseProbe {
    /// Spin on the monotonic clock for `duration`, recording the gaps (module doc).
    pub fn run(duration: Duration) -> Self {
        // Room for a pause every 10 µs: no allocation while spinning on any sane machine.
        let capacity = usize::try_from(duration.as_micros() / 10).unwrap_or(usize::MAX);
        let mut gaps_ns = Vec::with_capacity(capacity.min(1 << 20));
        let start = Instant::now();
        let mut last = start;
        loop {
            let now = Instant::now();
            let gap = u64::try_from((now - last).as_nanos()).unwrap_or(u64::MAX);
            if gap >= MIN_PAUSE_NS {
                gaps_ns.push(gap);
            }
            last = now;
            if now - start >= duration {
                break;
            }
        }
        Self {
            duration_ns: u64::try_from((last - start).as_nanos()).unwrap_or(u64::MAX),
            gaps_ns,
        }
    }

    /// The probe's meaning for `steps` steps of median `median_step_ns` against a budget of
    /// `budget_ns` (module doc); `None` for a probe that did not run.
    pub fn summary(
        &self,
        budget_ns: u64,
        steps: usize,
        median_step_ns: u64,
    ) -> Option<PauseSummary> {
        if self.duration_ns == 0 {
            return None;
        }
        let threshold_ns = budget_ns.saturating_sub(median_step_ns).max(MIN_PAUSE_NS);
        let pauses = self.gaps_ns.iter().filter(|&&g| g >= threshold_ns).count();
        let probe_s = self.duration_ns as f64 * 1e-9;
        let pauses_per_s = pauses as f64 / probe_s;
        Some(PauseSummary {
            probe_s,
            threshold_ns,
            pauses,
            pauses_per_s,
            longest_pause_ns: self.gaps_ns.iter().copied().max().unwrap_or(0),
            expected_steps_over_budget: pauses_per_s * steps as f64 * median_step_ns as f64 * 1e-9,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counting by hand: gaps 1.5, 4, 8, 9.5, 30 µs over 0.5 s with a 10 µs budget and a 2 µs
    /// median step count the pauses ≥ 8 µs: 3, i.e. 6/s; 20 000 steps of 2 µs spend 0.04 s
    /// stepping, so 6 × 0.04 = 0.24 steps are expected over the budget.
    #[test]
    fn summary_counts_the_pauses_that_break_the_budget() {
        let probe = PauseProbe {
            duration_ns: 500_000_000,
            gaps_ns: vec![1_500, 4_000, 8_000, 9_500, 30_000],
        };
        let s = probe.summary(10_000, 20_000, 2_000).unwrap();
        assert_eq!(
            (s.threshold_ns, s.pauses, s.longest_pause_ns),
            (8_000, 3, 30_000)
        );
        assert!((s.pauses_per_s - 6.0).abs() < 1e-9);
        assert!((s.expected_steps_over_budget - 0.24).abs() < 1e-9);
        // A median over the budget leaves the 1 µs floor: every recorded gap counts.
        assert_eq!(probe.summary(10_000, 1, 12_000).unwrap().pauses, 5);
        let idle = PauseProbe {
            duration_ns: 0,
            gaps_ns: vec![],
        };
        assert_eq!(idle.summary(10_000, 1, 1), None);
    }

    /// A real probe spins for the time asked (and not much longer), and every gap it records is
    /// at least the pause floor and shorter than the whole probe.
    #[test]
    fn probe_spins_for_its_duration() {
        let probe = PauseProbe::run(Duration::from_millis(20));
        assert!(probe.duration_ns >= 20_000_000, "{}", probe.duration_ns);
        assert!(probe.duration_ns < 2_000_000_000, "{}", probe.duration_ns);
        assert!(probe
            .gaps_ns
            .iter()
            .all(|&g| (MIN_PAUSE_NS..=probe.duration_ns).contains(&g)));
    }
}
