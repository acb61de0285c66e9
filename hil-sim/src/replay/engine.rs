//! The replay loop: one timed step per sample, then the accuracy pass.
//!
//! Timing: each step is bracketed by two `Instant::now()` reads (the monotonic clock, a vDSO
//! call of ≈ 20–30 ns on Linux, so a measured step includes about one clock read). In paced
//! mode, step i is released at start + i/f and due one period later; a step that ends after its
//! deadline is a miss and its lateness is recorded. The sleep before a release ends 100 µs
//! early and the rest is spun, because a thread woken from `sleep` can be a scheduler tick late.
//!
//! Warm-up: the harness's own setup between priming and the first step (allocating and filling
//! the output buffers, megabytes for a long trace) evicts the CPU caches, which no real-time
//! loop does between two steps; the first step then paid 13–18 µs for fetching the step's code
//! and tables, one of the twenty steps a 20 000-step trace may spend over the budget. So a
//! second, identical stepper ([`Parts::warm_up`]) is stepped over the first [`WARM_UP_STEPS`]
//! samples right before the timed loop, on its CPU: the code and the model's tables are then
//! cached, while the timed stepper's own state is untouched (its outputs stay those of a
//! plain replay). The warm-up's first step is reported as the cold-cache step time.
//!
//! Accuracy: after the timed loop, every K-th sample is recomputed by the reference with the
//! rollers where the stepper had them, and the dry stepper (if any) replays every sample (it
//! may integrate state such as the cage angle, so it cannot skip samples). Nothing of this runs
//! inside the timed loop, so the reference cannot pollute the caches the timings see.

use super::pauses::PauseProbe;
use super::stats::Limits;
use super::{AccuracyReference, BearingStepper, FilmSource, StepFault, StepOutputs};
use crate::realtime::{Guard, Realtime};
use crate::trace::{Sample, Trace};
use std::fmt;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// How to replay.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReplayConfig {
    /// Step rate (Hz): the pace of `--paced`, and the rate the budget is judged against.
    pub rate_hz: f64,
    /// Recompute every K-th sample with the reference; 0 disables the accuracy pass.
    pub reference_every: usize,
    /// Run at wall-clock rate with a deadline per period.
    pub paced: bool,
    /// Budget and accuracy limits.
    pub limits: Limits,
    /// Force errors are only taken where the reference force is at least this large (N), because
    /// a relative error of a force crossing zero says nothing about the model.
    pub min_reference_force_n: f64,
    /// Run the timed loop under real-time scheduling (`crate::realtime`).
    pub realtime: Option<Realtime>,
    /// When the system refuses real-time scheduling: run the timed loop under the ordinary
    /// policy and record why (true), or fail the replay (false).
    pub realtime_fallback: bool,
    /// Spin this long (s) after the timed loop, under its scheduling, measuring the machine's
    /// pauses (`super::pauses`); 0 skips the probe.
    pub pause_probe_s: f64,
    /// Fail a missed budget even when the machine's pauses alone explain it (`--strict-timing`);
    /// otherwise such a miss leaves the budget not judged (`ReplayReport::budget_judged`).
    pub strict_timing: bool,
}

/// The models a replay drives.
pub struct Parts<'a> {
    /// The real-time model under test (timed).
    pub stepper: &'a mut dyn BearingStepper,
    /// The full numerical solver, if accuracy is checked.
    pub reference: Option<&'a mut dyn AccuracyReference>,
    /// The dry model (h ≡ 0), whose force error is reported beside the stepper's.
    pub dry: Option<&'a mut dyn BearingStepper>,
    /// A second instance of `stepper`, stepped untimed over the first samples right before the
    /// timed loop so that the step's code and tables are cached (module doc); `None` starts the
    /// timed loop with whatever the caches hold.
    pub warm_up: Option<&'a mut dyn BearingStepper>,
}

/// Samples the warm-up stepper is stepped over before the timed loop.
pub const WARM_UP_STEPS: usize = 16;

/// Deadline statistics of a paced replay.
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize)]
pub struct Pacing {
    /// Steps that ended after their deadline.
    pub misses: usize,
    /// Largest lateness past a deadline (ns).
    pub max_lateness_ns: u64,
    /// Sum of the lateness of all misses (ns).
    pub total_lateness_ns: u64,
    /// Wall-clock duration of the paced loop (s).
    pub wall_s: f64,
}

/// The errors at one reference sample.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct AccuracyPoint {
    /// Sample index.
    pub index: usize,
    /// Sample time (s).
    pub time_s: f64,
    /// Largest relative central-film error over the loaded contacts (none loaded: `None`).
    pub film_rel_err_max: Option<f64>,
    /// Bearing-force error |ΔF| relative to the larger of the reference resultant and the
    /// reference's mean roller load (`None` below the force floor; see `force_rel_err`).
    pub force_rel_err: Option<f64>,
    /// Bearing-force error relative to the reference resultant alone.
    pub force_rel_err_resultant: Option<f64>,
    /// Force error of the dry model, normalised as `force_rel_err`.
    pub dry_force_rel_err: Option<f64>,
    /// Magnitude of the reference force (N).
    pub reference_force_n: f64,
    /// Mean roller load of the reference, Σ Q_j / Z (N).
    pub mean_roller_load_n: f64,
}

/// How many contacts each film model served over the whole replay.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize)]
pub struct SourceCounts {
    /// No film (dry model, or no entrainment).
    pub none: u64,
    /// Regression formula by choice.
    pub regression: u64,
    /// f32 network.
    pub network_f32: u64,
    /// Integer network.
    pub network_int: u64,
    /// Regression standing in for a network outside its domain.
    pub fallback: u64,
}

impl SourceCounts {
    fn add(&mut self, source: FilmSource) {
        let slot = match source {
            FilmSource::None => &mut self.none,
            FilmSource::Regression => &mut self.regression,
            FilmSource::NetworkF32 => &mut self.network_f32,
            FilmSource::NetworkInt => &mut self.network_int,
            FilmSource::Fallback => &mut self.fallback,
        };
        *slot += 1;
    }

    /// Fraction of film-carrying contacts served by a network (f32 or integer); `None` when no
    /// contact carried a film (the dry model).
    pub fn network_fraction(&self) -> Option<f64> {
        let network = self.network_f32 + self.network_int;
        let with_film = network + self.regression + self.fallback;
        (with_film > 0).then(|| network as f64 / with_film as f64)
    }
}

/// Everything a replay measured.
#[derive(Clone, Debug, PartialEq)]
pub struct ReplayRun {
    /// Time of every step (ns).
    pub step_times_ns: Vec<u64>,
    /// Time of the friction call after every step (ns), measured apart from the step.
    pub friction_times_ns: Vec<u64>,
    /// Outputs of every step.
    pub outputs: Vec<StepOutputs>,
    /// Deadline statistics when paced.
    pub pacing: Option<Pacing>,
    /// Errors at each reference sample.
    pub points: Vec<AccuracyPoint>,
    /// Relative central-film error of every loaded contact at every reference sample.
    pub film_errors: Vec<f64>,
    /// Force error at every reference sample above the force floor, relative to the larger
    /// of the resultant and the mean roller load (`force_rel_err`).
    pub force_errors: Vec<f64>,
    /// The same errors relative to the resultant alone.
    pub force_errors_resultant: Vec<f64>,
    /// Same for the dry model.
    pub dry_force_errors: Vec<f64>,
    /// Film sources over all steps and contacts.
    pub sources: SourceCounts,
    /// The real-time scheduling the timed loop ran under, if any.
    pub realtime: Option<Realtime>,
    /// Why real-time scheduling was requested but not granted (`realtime_fallback`).
    pub realtime_refused: Option<String>,
    /// The warm-up stepper's first step (ns): the step with the caches as the harness's setup
    /// left them. `None` without a warm-up.
    pub cold_step_ns: Option<u64>,
    /// The machine's pauses, measured right after the timed loop (`super::pauses`).
    pub pauses: Option<PauseProbe>,
}

/// A replay that could not finish.
#[derive(Clone, Debug, PartialEq)]
pub struct ReplayError {
    /// Sample index.
    pub index: usize,
    /// What failed: `"configuration"`, `"stepper"`, `"warm-up stepper"`, `"reference"`,
    /// `"stepper friction"`, `"dry stepper"` or `"real-time scheduling"`.
    pub stage: &'static str,
    /// Its reason.
    pub fault: StepFault,
}

impl fmt::Display for ReplayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} failed at sample {}: {}",
            self.stage, self.index, self.fault
        )
    }
}

impl std::error::Error for ReplayError {}

/// Sleeps, then spins, until `release`.
fn wait_until(release: Instant) {
    let now = Instant::now();
    if release > now + Duration::from_micros(200) {
        std::thread::sleep(release - now - Duration::from_micros(100));
    }
    while Instant::now() < release {
        std::hint::spin_loop();
    }
}

/// Error |F − F_ref| of a bearing force relative to max(|F_ref|, `scale_n`).
///
/// The scale is the reference's mean roller load. A film preloads the ring: every roller
/// carries load, and the resultant is the vector sum of Z roller forces that largely cancel.
/// Where it falls below what one roller carries (17 N against ≈ 5.3 kN of roller loads in the
/// bundled hub-motor run-up), the error relative to the resultant alone measures that
/// cancellation more than the model (0.3 N there is 1.9 % of the resultant and 6·10⁻⁵ of the
/// roller loads); the report gives that ratio too (`force_rel_err_resultant_p99`).
fn force_rel_err(force: [f32; 2], reference: [f64; 2], scale_n: f64) -> f64 {
    let dx = f64::from(force[0]) - reference[0];
    let dy = f64::from(force[1]) - reference[1];
    dx.hypot(dy) / reference[0].hypot(reference[1]).max(scale_n)
}

/// Replays `trace` through `parts` (see the module doc). `progress`, if given, is advanced
/// once per reference sample.
pub fn replay(
    trace: &Trace,
    mut parts: Parts<'_>,
    config: &ReplayConfig,
    progress: Option<&indicatif::ProgressBar>,
) -> Result<ReplayRun, ReplayError> {
    // The release times index/rate become `Duration`s, which panic on an infinite or negative
    // number of seconds: refuse a rate outside the traces' own range first.
    let rates = crate::trace::MIN_SAMPLE_RATE_HZ..=crate::trace::MAX_SAMPLE_RATE_HZ;
    if !rates.contains(&config.rate_hz) {
        return Err(ReplayError {
            index: 0,
            stage: "configuration",
            fault: StepFault {
                reason: format!(
                    "step rate {:e} Hz is out of range: allowed {:e} ..= {:e} Hz",
                    config.rate_hz,
                    rates.start(),
                    rates.end()
                ),
            },
        });
    }
    let n = trace.samples.len();
    let mut step_times_ns = vec![0u64; n];
    let mut friction_times_ns = vec![0u64; n];
    let mut outputs = vec![StepOutputs::default(); n];
    let mut pacing = config.paced.then(Pacing::default);
    // Real-time scheduling for the timed loop alone (dropped before the accuracy pass).
    let (realtime, realtime_refused) = match config.realtime.map(Guard::enter) {
        None => (None, None),
        Some(Ok(guard)) => (Some(guard), None),
        Some(Err(reason)) if config.realtime_fallback => (None, Some(reason)),
        Some(Err(reason)) => {
            return Err(ReplayError {
                index: 0,
                stage: "real-time scheduling",
                fault: StepFault { reason },
            })
        }
    };
    let cold_step_ns = match parts.warm_up.as_deref_mut() {
        Some(warm_up) => Some(warm(warm_up, &trace.samples)?),
        None => None,
    };
    let start = Instant::now();
    for (index, (((sample, time), friction_time), out)) in trace
        .samples
        .iter()
        .zip(step_times_ns.iter_mut())
        .zip(friction_times_ns.iter_mut())
        .zip(outputs.iter_mut())
        .enumerate()
    {
        let release = start + Duration::from_secs_f64(index as f64 / config.rate_hz);
        if config.paced {
            wait_until(release);
        }
        let t1;
        (*time, t1) = timed_step(parts.stepper, sample, out, index, "stepper")?;
        *friction_time = timed_friction(parts.stepper, sample, out, index)?;
        if let Some(p) = pacing.as_mut() {
            let deadline = release + Duration::from_secs_f64(1.0 / config.rate_hz);
            if t1 > deadline {
                let late = u64::try_from((t1 - deadline).as_nanos()).unwrap_or(u64::MAX);
                p.misses += 1;
                p.max_lateness_ns = p.max_lateness_ns.max(late);
                p.total_lateness_ns = p.total_lateness_ns.saturating_add(late);
            }
        }
    }
    if let Some(p) = pacing.as_mut() {
        p.wall_s = start.elapsed().as_secs_f64();
    }
    // Still on the timed loop's CPU and policy: the pauses the steps saw.
    let pauses = (config.pause_probe_s > 0.0)
        .then(|| PauseProbe::run(Duration::from_secs_f64(config.pause_probe_s.min(60.0))));
    let realtime_granted = realtime.is_some();
    drop(realtime);

    let mut sources = SourceCounts::default();
    for out in &outputs {
        let rollers = out.rollers.min(super::MAX_ROLLERS);
        for j in 0..rollers {
            sources.add(out.source_inner[j]);
            sources.add(out.source_outer[j]);
        }
    }

    let mut run = ReplayRun {
        step_times_ns,
        friction_times_ns,
        outputs,
        pacing,
        points: Vec::new(),
        film_errors: Vec::new(),
        force_errors: Vec::new(),
        force_errors_resultant: Vec::new(),
        dry_force_errors: Vec::new(),
        sources,
        realtime: config.realtime.filter(|_| realtime_granted),
        realtime_refused,
        cold_step_ns,
        pauses,
    };
    accuracy_pass(trace, parts, config, progress, &mut run)?;
    Ok(run)
}

/// One step of `stepper` bracketed by two clock reads: its time (ns) and when it ended.
#[inline(always)]
fn timed_step(
    stepper: &mut dyn BearingStepper,
    sample: &Sample,
    out: &mut StepOutputs,
    index: usize,
    stage: &'static str,
) -> Result<(u64, Instant), ReplayError> {
    let t0 = Instant::now();
    let result = stepper.step(black_box(sample), black_box(out));
    let t1 = Instant::now();
    result.map_err(|fault| ReplayError {
        index,
        stage,
        fault,
    })?;
    Ok((u64::try_from((t1 - t0).as_nanos()).unwrap_or(u64::MAX), t1))
}

/// The friction call of `stepper` after its step, bracketed by two clock reads: its time (ns).
#[inline(always)]
fn timed_friction(
    stepper: &mut dyn BearingStepper,
    sample: &Sample,
    out: &mut StepOutputs,
    index: usize,
) -> Result<u64, ReplayError> {
    let t0 = Instant::now();
    let result = stepper.friction(black_box(sample), black_box(out));
    let t1 = Instant::now();
    result.map_err(|fault| ReplayError {
        index,
        stage: "stepper friction",
        fault,
    })?;
    Ok(u64::try_from((t1 - t0).as_nanos()).unwrap_or(u64::MAX))
}

/// Steps `warm_up` over the first [`WARM_UP_STEPS`] samples and returns the first step's time
/// (ns); the others are not kept.
fn warm(warm_up: &mut dyn BearingStepper, samples: &[Sample]) -> Result<u64, ReplayError> {
    let mut out = StepOutputs::default();
    let mut cold_ns = 0;
    for (index, sample) in samples.iter().take(WARM_UP_STEPS).enumerate() {
        let (ns, _) = timed_step(warm_up, sample, &mut out, index, "warm-up stepper")?;
        if index == 0 {
            cold_ns = ns;
        }
    }
    Ok(cold_ns)
}

/// Steps the dry model over every sample and returns its outputs.
fn dry_outputs(
    samples: &[Sample],
    dry: Option<&mut dyn BearingStepper>,
) -> Result<Option<Vec<StepOutputs>>, ReplayError> {
    let Some(dry) = dry else {
        return Ok(None);
    };
    let mut outputs = vec![StepOutputs::default(); samples.len()];
    for (index, (sample, out)) in samples.iter().zip(outputs.iter_mut()).enumerate() {
        dry.step(sample, out).map_err(|fault| ReplayError {
            index,
            stage: "dry stepper",
            fault,
        })?;
    }
    Ok(Some(outputs))
}

fn accuracy_pass(
    trace: &Trace,
    parts: Parts<'_>,
    config: &ReplayConfig,
    progress: Option<&indicatif::ProgressBar>,
    run: &mut ReplayRun,
) -> Result<(), ReplayError> {
    let (Some(reference), true) = (parts.reference, config.reference_every > 0) else {
        return Ok(());
    };
    let dry = dry_outputs(&trace.samples, parts.dry)?;
    for index in (0..trace.samples.len()).step_by(config.reference_every) {
        let (Some(sample), Some(stepped)) = (trace.samples.get(index), run.outputs.get(index))
        else {
            break;
        };
        let fail = |reason: String| ReplayError {
            index,
            stage: "reference",
            fault: StepFault { reason },
        };
        let truth = reference
            .reference(sample, stepped)
            .map_err(|f| fail(f.reason))?;
        let rollers = stepped.rollers;
        if rollers > super::MAX_ROLLERS
            || [
                &truth.roller_load_n,
                &truth.film_inner_m,
                &truth.film_outer_m,
            ]
            .iter()
            .any(|v| v.len() != rollers)
        {
            return Err(fail(format!(
                "the reference returned {} rollers, the stepper {rollers}",
                truth.roller_load_n.len()
            )));
        }
        let mut film_max: Option<f64> = None;
        for j in 0..rollers {
            // A loaded contact: the reference roller load is positive. Both contacts of a
            // roller carry the same load (docs/physics.md §4), each with its own film.
            if truth.roller_load_n[j].is_nan() || truth.roller_load_n[j] <= 0.0 {
                continue;
            }
            for (film, film_ref) in [
                (stepped.film_inner_m[j], truth.film_inner_m[j]),
                (stepped.film_outer_m[j], truth.film_outer_m[j]),
            ] {
                let err = (f64::from(film) - film_ref).abs() / film_ref;
                run.film_errors.push(err);
                film_max = Some(film_max.map_or(err, |m: f64| m.max(err)));
            }
        }
        let reference_force_n = truth.force_n[0].hypot(truth.force_n[1]);
        // The reference's roller loads; a roller outside the EHL reference enters its force
        // with the core's load (`reference`), and so here.
        let mean_roller_load_n = (0..rollers)
            .map(|j| match truth.roller_load_n[j] {
                q if q.is_finite() => q,
                _ => f64::from(stepped.roller_load_n.get(j).copied().unwrap_or(0.0)),
            })
            .sum::<f64>()
            / rollers.max(1) as f64;
        let above_floor = reference_force_n >= config.min_reference_force_n;
        let force_err =
            above_floor.then(|| force_rel_err(stepped.force_n, truth.force_n, mean_roller_load_n));
        let force_err_resultant =
            above_floor.then(|| force_rel_err(stepped.force_n, truth.force_n, 0.0));
        let dry_err = match (&dry, above_floor) {
            (Some(d), true) => d
                .get(index)
                .map(|o| force_rel_err(o.force_n, truth.force_n, mean_roller_load_n)),
            _ => None,
        };
        run.force_errors.extend(force_err);
        run.force_errors_resultant.extend(force_err_resultant);
        run.dry_force_errors.extend(dry_err);
        run.points.push(AccuracyPoint {
            index,
            time_s: sample.time_s,
            film_rel_err_max: film_max,
            force_rel_err: force_err,
            force_rel_err_resultant: force_err_resultant,
            dry_force_rel_err: dry_err,
            reference_force_n,
            mean_roller_load_n,
        });
        if let Some(bar) = progress {
            bar.inc(1);
        }
    }
    Ok(())
}
