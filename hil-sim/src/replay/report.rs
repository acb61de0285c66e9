//! The replay report: the JSON the issue specifies, a markdown summary and the verdicts.
//!
//! JSON keys scripts rely on: `steps`, `step_time_ns{min,median,p99,p999,max}`, `budget_ok`,
//! `budget_judged`,
//! `accuracy_ok`, `film_rel_err_p99`, `film_rel_err_max`, `force_rel_err_p99`,
//! `force_rel_err_max`, `force_rel_err_resultant_p99`, `dry_force_rel_err_p99`,
//! `network_fraction`, `friction` (`friction_torque_nm` and `power_loss_w` as `{min, mean,
//! max}`, `power_loss_split_mean_w{rolling, viscous, boundary}`, `friction_time_ns`), plus
//! `steps_over_budget` and context (trace, film model, limits, pacing,
//! the real-time scheduling of the timed loop, the machine's pauses (`environment`), reasons,
//! notes). Accuracy keys
//! are `null` when no reference ran (`--reference-every 0` or no reference available):
//! nothing was checked, which is not the same as a pass.

use super::engine::{Pacing, ReplayConfig, ReplayRun, SourceCounts};
use super::pauses::PauseSummary;
use super::stats::{
    accuracy_verdict, budget_verdict, percentile, FrictionSummary, Limits, StepTimeStats,
};
use super::FilmKind;
use crate::realtime::Realtime;
use crate::trace::{Trace, TraceMeta};
use bearing_host_common::output::OutputFiles;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::Path;

/// The report of one replay.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ReplayReport {
    /// Steps replayed.
    pub steps: usize,
    /// Step-time distribution (ns).
    pub step_time_ns: StepTimeStats,
    /// p99.9 step time within the budget.
    pub budget_ok: bool,
    /// The budget verdict stands: false when the budget was missed but the machine's measured
    /// pauses alone explain the steps over it (`explained_by_pauses`) and `--strict-timing` was
    /// not given — the model's own steps cannot then be told from the machine's pauses, and the
    /// miss is a note, not a failure.
    pub budget_judged: bool,
    /// Steps longer than the budget (the p99.9 verdict allows one in a thousand).
    pub steps_over_budget: usize,
    /// Film and force errors within the limits; `null` when not checked.
    pub accuracy_ok: Option<bool>,
    /// 99th-percentile relative error of the central film of loaded contacts.
    pub film_rel_err_p99: Option<f64>,
    /// Largest relative error of the central film of loaded contacts.
    pub film_rel_err_max: Option<f64>,
    /// 99th-percentile bearing-force error, relative to the larger of the reference resultant
    /// and its mean roller load (the verdict's measure).
    pub force_rel_err_p99: Option<f64>,
    /// Largest bearing-force error, normalised as `force_rel_err_p99`.
    pub force_rel_err_max: Option<f64>,
    /// 99th-percentile bearing-force error relative to the reference resultant alone (large
    /// where a film-preloaded ring's roller forces nearly cancel; not judged).
    pub force_rel_err_resultant_p99: Option<f64>,
    /// Same for the dry model (what the film buys).
    pub dry_force_rel_err_p99: Option<f64>,
    /// Fraction of film-carrying contacts served by a network rather than the fallback.
    pub network_fraction: Option<f64>,
    /// Contacts per film source over all steps.
    pub film_sources: SourceCounts,
    /// The bearing's friction after every step (the core's `Bearing::friction`): torque and
    /// power loss over the steps, the mean split, and the call's host time. Zeros for the dry
    /// model, which has no film and no friction.
    pub friction: Option<FrictionSummary>,
    /// Bearing identifier of the trace.
    pub bearing: String,
    /// Lubricant identifier of the trace.
    pub lubricant: String,
    /// Film model of the stepper.
    pub film: FilmKind,
    /// Stepper name.
    pub stepper: String,
    /// Step rate (Hz).
    pub rate_hz: f64,
    /// Limits judged against.
    pub limits: Limits,
    /// Every K-th sample was recomputed (0: none).
    pub reference_every: usize,
    /// Reference samples computed.
    pub reference_points: usize,
    /// Loaded contacts compared.
    pub film_contacts_compared: usize,
    /// Deadline statistics, when paced.
    pub pacing: Option<Pacing>,
    /// The real-time scheduling of the timed loop (`--realtime`): CPU and SCHED_FIFO priority;
    /// `null` under the ordinary policy.
    pub realtime: Option<Realtime>,
    /// Why real-time scheduling was asked for and refused (`--realtime auto`); `null` otherwise.
    pub realtime_refused: Option<String>,
    /// The warm-up stepper's first step (ns), with the caches as the harness's setup left them
    /// (`super::engine` module doc); `null` without a warm-up.
    pub cold_step_ns: Option<u64>,
    /// The machine's pauses on the timed loop's CPU and what they alone cost the budget
    /// (`super::pauses`); `null` when the probe did not run. Context for the budget verdict:
    /// a miss it explains is not judged (`budget_judged`).
    pub environment: Option<PauseSummary>,
    /// Why the replay failed (empty when it passed).
    pub reasons: Vec<String>,
    /// What was not judged, and why (a budget miss the machine's pauses explain).
    pub notes: Vec<String>,
}

/// True when `steps_over` steps over the budget are what the machine's pauses alone put there:
/// no more than the expected count plus three Poisson standard deviations and three steps (a
/// pause lands in a step at random, so the count the pauses cause is Poisson-distributed), and
/// the model's own step time (the 99th percentile) within the budget.
pub fn explained_by_pauses(
    steps_over: usize,
    pauses: &PauseSummary,
    times: &StepTimeStats,
    limits: &Limits,
) -> bool {
    let expected = pauses.expected_steps_over_budget;
    let fast_enough = times.p99 as f64 <= limits.budget_us * 1e3;
    fast_enough && (steps_over as f64) <= expected + 3.0 * expected.sqrt() + 3.0
}

impl ReplayReport {
    /// Builds the report and its verdicts.
    pub fn build(
        meta: &TraceMeta,
        film: FilmKind,
        stepper: String,
        config: &ReplayConfig,
        run: &ReplayRun,
    ) -> Option<ReplayReport> {
        let step_time_ns = StepTimeStats::of(&run.step_times_ns)?;
        let checked = !run.points.is_empty();
        let film_p99 = percentile(&run.film_errors, 0.99);
        let force_p99 = percentile(&run.force_errors, 0.99);
        let mut reasons = Vec::new();
        let budget_ns = (config.limits.budget_us * 1e3) as u64;
        let steps_over_budget = run
            .step_times_ns
            .iter()
            .filter(|&&t| t as f64 > config.limits.budget_us * 1e3)
            .count();
        let environment = run
            .pauses
            .as_ref()
            .and_then(|p| p.summary(budget_ns, run.step_times_ns.len(), step_time_ns.median));
        let mut notes = Vec::new();
        let mut budget_judged = true;
        let budget_ok = match budget_verdict(&step_time_ns, &config.limits) {
            Ok(()) => true,
            Err(mut reason) => {
                if let Some(e) = &environment {
                    let _ = write!(
                        reason,
                        " (the machine paused this CPU for ≥ {:.1} µs {:.0} times/s while idle-spinning, which alone puts ≈ {:.0} steps over the budget; {} were)",
                        e.threshold_ns as f64 / 1e3,
                        e.pauses_per_s,
                        e.expected_steps_over_budget,
                        steps_over_budget
                    );
                }
                let explained = environment.as_ref().is_some_and(|e| {
                    explained_by_pauses(steps_over_budget, e, &step_time_ns, &config.limits)
                });
                if explained && !config.strict_timing {
                    budget_judged = false;
                    notes.push(format!(
                        "budget not judged: {reason}; the machine's pauses alone explain the \
                         steps over it — judge it on an isolated CPU, or fail such a run with \
                         --strict-timing"
                    ));
                } else {
                    reasons.push(reason);
                }
                false
            }
        };
        let accuracy_ok =
            checked.then(
                || match accuracy_verdict(film_p99, force_p99, &config.limits) {
                    Ok(()) => true,
                    Err(mut missed) => {
                        reasons.append(&mut missed);
                        false
                    }
                },
            );
        Some(ReplayReport {
            steps: run.step_times_ns.len(),
            step_time_ns,
            budget_ok,
            budget_judged,
            steps_over_budget,
            accuracy_ok,
            film_rel_err_p99: film_p99,
            film_rel_err_max: percentile(&run.film_errors, 1.0),
            force_rel_err_p99: force_p99,
            force_rel_err_max: percentile(&run.force_errors, 1.0),
            force_rel_err_resultant_p99: percentile(&run.force_errors_resultant, 0.99),
            dry_force_rel_err_p99: percentile(&run.dry_force_errors, 0.99),
            network_fraction: run.sources.network_fraction(),
            film_sources: run.sources,
            friction: FrictionSummary::of(&run.outputs, &run.friction_times_ns),
            bearing: meta.bearing.clone(),
            lubricant: meta.lubricant.clone(),
            film,
            stepper,
            rate_hz: config.rate_hz,
            limits: config.limits,
            reference_every: config.reference_every,
            reference_points: run.points.len(),
            film_contacts_compared: run.film_errors.len(),
            pacing: run.pacing,
            realtime: run.realtime,
            realtime_refused: run.realtime_refused.clone(),
            cold_step_ns: run.cold_step_ns,
            environment,
            reasons,
            notes,
        })
    }

    /// True when nothing checked failed.
    pub fn passed(&self) -> bool {
        self.reasons.is_empty()
    }

    /// The markdown summary (also what the CLI prints without `--json`).
    pub fn markdown(&self) -> String {
        let pct =
            |v: Option<f64>| v.map_or("not checked".to_string(), |e| format!("{:.3} %", e * 100.0));
        let verdict = |ok: Option<bool>| match ok {
            Some(true) => "pass",
            Some(false) => "FAIL",
            None => "not checked",
        };
        let t = &self.step_time_ns;
        let mut md = String::new();
        let _ = writeln!(md, "# Replay report\n");
        let _ = writeln!(
            md,
            "Bearing `{}`, lubricant `{}`, film model `{}` (stepper `{}`), {} steps at {} Hz.\n",
            self.bearing,
            self.lubricant,
            self.film.name(),
            self.stepper,
            self.steps,
            self.rate_hz
        );
        let _ = writeln!(md, "## Step time\n");
        let _ = writeln!(md, "| min | median | p99 | p99.9 | max | mean |");
        let _ = writeln!(md, "|---:|---:|---:|---:|---:|---:|");
        let us = |ns: u64| format!("{:.3} µs", ns as f64 / 1e3);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {:.3} µs |\n",
            us(t.min),
            us(t.median),
            us(t.p99),
            us(t.p999),
            us(t.max),
            t.mean / 1e3
        );
        let _ = writeln!(
            md,
            "Budget {} µs at p99.9: **{}** ({} of {} steps over it).\n",
            self.limits.budget_us,
            if self.budget_judged {
                verdict(Some(self.budget_ok))
            } else {
                "not judged: the machine's pauses explain the misses"
            },
            self.steps_over_budget,
            self.steps
        );
        match &self.realtime {
            Some(r) => {
                let _ = writeln!(
                    md,
                    "Timed loop under SCHED_FIFO priority {} on CPU {}, memory locked.\n",
                    r.priority, r.cpu
                );
            }
            None => {
                let why = self.realtime_refused.as_ref().map_or(String::new(), |r| {
                    format!(" (real-time scheduling refused: {r})")
                });
                let _ = writeln!(
                    md,
                    "Timed loop under the ordinary scheduling policy{why}; another process can take its CPU for a scheduler slice mid-step (`--realtime` pins it to a CPU under SCHED_FIFO).\n"
                );
            }
        }
        if let Some(cold) = self.cold_step_ns {
            let _ = writeln!(
                md,
                "Warm-up: a second stepper took {} untimed steps right before the timed loop; its first, with the caches as the harness's setup left them, took {:.1} µs.\n",
                super::engine::WARM_UP_STEPS,
                cold as f64 / 1e3
            );
        }
        if let Some(e) = &self.environment {
            let _ = writeln!(
                md,
                "Machine pauses (a {:.2} s probe spinning on the clock right after the timed loop, same CPU and policy): {} pauses of ≥ {:.1} µs (budget − median step), {:.0} per second, longest {:.1} µs. At the median step they alone put ≈ {:.1} of the {} steps over the budget; {} were.\n",
                e.probe_s,
                e.pauses,
                e.threshold_ns as f64 / 1e3,
                e.pauses_per_s,
                e.longest_pause_ns as f64 / 1e3,
                e.expected_steps_over_budget,
                self.steps,
                self.steps_over_budget
            );
        }
        if let Some(p) = &self.pacing {
            let _ = writeln!(
                md,
                "Paced at {} Hz for {:.3} s: {} deadline misses, worst lateness {:.3} µs.\n",
                self.rate_hz,
                p.wall_s,
                p.misses,
                p.max_lateness_ns as f64 / 1e3
            );
        }
        let _ = writeln!(md, "## Accuracy against the full numerical solver\n");
        let _ = writeln!(
            md,
            "{} reference samples (every {}), {} loaded contacts compared.\n",
            self.reference_points, self.reference_every, self.film_contacts_compared
        );
        let _ = writeln!(md, "| quantity | p99 relative error | max | limit (p99) |");
        let _ = writeln!(md, "|---|---:|---:|---:|");
        let _ = writeln!(
            md,
            "| central film, loaded contacts | {} | {} | {:.1} % |",
            pct(self.film_rel_err_p99),
            pct(self.film_rel_err_max),
            self.limits.film_rel_err_p99 * 100.0
        );
        let _ = writeln!(
            md,
            "| bearing force (¹) | {} | {} | {:.1} % |",
            pct(self.force_rel_err_p99),
            pct(self.force_rel_err_max),
            self.limits.force_rel_err_p99 * 100.0
        );
        let _ = writeln!(
            md,
            "| bearing force, relative to the resultant alone | {} | | (not judged) |",
            pct(self.force_rel_err_resultant_p99)
        );
        let _ = writeln!(
            md,
            "| bearing force, dry model (¹) | {} | | (for comparison) |\n",
            pct(self.dry_force_rel_err_p99)
        );
        let _ = writeln!(
            md,
            "(¹) |F − F_ref| relative to the larger of |F_ref| and the reference's mean roller \
             load: where a film preloads every roller, the resultant can be a small difference of \
             large roller forces.\n"
        );
        let _ = writeln!(md, "Accuracy: **{}**.\n", verdict(self.accuracy_ok));
        let s = &self.film_sources;
        let _ = writeln!(
            md,
            "Film sources over all contacts and steps: integer network {}, f32 network {}, regression {}, fallback {}, none {}; network fraction {}.\n",
            s.network_int,
            s.network_f32,
            s.regression,
            s.fallback,
            s.none,
            self.network_fraction.map_or("n/a".into(), |f| format!("{:.4}", f))
        );
        if let Some(f) = &self.friction {
            let _ = writeln!(md, "## Friction after every step\n");
            let _ = writeln!(md, "| quantity | min | mean | max |");
            let _ = writeln!(md, "|---|---:|---:|---:|");
            for (name, r) in [
                ("friction torque (N·m)", &f.friction_torque_nm),
                ("power loss (W)", &f.power_loss_w),
            ] {
                let _ = writeln!(
                    md,
                    "| {name} | {:.4} | {:.4} | {:.4} |",
                    r.min, r.mean, r.max
                );
            }
            let s = &f.power_loss_split_mean_w;
            let _ = writeln!(
                md,
                "\nMean power loss by mechanism: rolling {:.3} W, viscous {:.3} W, boundary {:.3} W. The friction call (`Bearing::friction`, timed apart from the step): median {}, p99 {}. Per step in `friction.csv`.\n",
                s.rolling,
                s.viscous,
                s.boundary,
                us(f.friction_time_ns.median),
                us(f.friction_time_ns.p99)
            );
        }
        if self.reasons.is_empty() {
            let _ = writeln!(md, "Verdict: **pass**.");
            for note in &self.notes {
                let _ = writeln!(md, "- {note}");
            }
        } else {
            let _ = writeln!(md, "Verdict: **FAIL**");
            for reason in &self.reasons {
                let _ = writeln!(md, "- {reason}");
            }
        }
        md
    }

    /// Writes `report.json`, `report.md` and `friction.csv` (every step's friction, from
    /// `run`) into `files`, staged for `dir` (created if missing); they appear there when
    /// `files` is committed.
    pub fn write(
        &self,
        files: &mut OutputFiles,
        dir: &Path,
        trace: &Trace,
        run: &ReplayRun,
    ) -> std::io::Result<()> {
        std::fs::create_dir_all(dir)?;
        std::fs::write(
            files.stage(&dir.join("friction.csv"))?,
            friction_csv(trace, run),
        )?;
        let json = serde_json::to_string_pretty(self).map_err(std::io::Error::other)?;
        std::fs::write(files.stage(&dir.join("report.json"))?, json)?;
        let mut md = self.markdown();
        md.push_str("\n![step time](step_time_histogram.png)\n\n![error along the trace](error_along_trace.png)\n\n![film per roller](film_per_roller.png)\n");
        std::fs::write(files.stage(&dir.join("report.md"))?, md)
    }
}

/// Every step's friction: time and shaft speed of the sample, torque, power loss and its split.
pub fn friction_csv(trace: &Trace, run: &ReplayRun) -> String {
    let mut csv = String::from(
        "step,time_s,shaft_speed_rad_s,friction_torque_nm,power_loss_w,power_loss_rolling_w,power_loss_viscous_w,power_loss_boundary_w\n",
    );
    for (index, (sample, o)) in trace.samples.iter().zip(&run.outputs).enumerate() {
        let [rolling, viscous, boundary] = o.power_loss_split_w;
        let _ = writeln!(
            csv,
            "{index},{},{},{:e},{:e},{:e},{:e},{:e}",
            sample.time_s,
            sample.speed_rad_s,
            o.friction_torque_nm,
            o.power_loss_w,
            rolling,
            viscous,
            boundary
        );
    }
    csv
}
