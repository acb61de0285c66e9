//! Tests of the replay engine with closed-form test doubles (not the product's model).
//!
//! The doubles implement the slicing-free form of docs/physics.md §4 on a 17-roller bearing: rollers
//! at θ_c + 2πj/Z, approach δ_j = x cos θ_j + y sin θ_j − g_r + 2h, a Palmgren-type load
//! Q = K δ^(10/9), a film depending on speed only (so there is no fixed point), and the force
//! −Σ Q (cos θ, sin θ). The stepper computes in f32, the reference the same formulas in f64, so
//! their difference is f32 rounding (≈ 1e-6 relative): an independent check that the engine
//! pairs each step with the reference of the same state, rollers and contacts.

use super::engine::{replay, Parts, ReplayConfig, ReplayError, ReplayRun, WARM_UP_STEPS};
use super::report::ReplayReport;
use super::stats::{budget_verdict, percentile, Limits, StepTimeStats};
use super::*;
use crate::trace::synthetic::Whirl;
use crate::trace::{Trace, TraceMeta};
use bearing_host_common::output::OutputFiles;

const Z: usize = 17;
/// Load constant K (N/m^(10/9)), of the order of docs/physics.md §3's Palmgren law for l = 15 mm.
const K: f64 = 8.0e9;
/// Radial clearance g_r (m): the hub-motor bearing's 2 µm interference.
const CLEARANCE: f64 = -2.0e-6;
/// Cage speed ratio (1 − γ)/2 for d_m = 60 mm, D = 8.8 mm (docs/physics.md §2).
const CAGE_RATIO: f64 = 0.5 * (1.0 - 8.8 / 60.0);

/// Film of the double (m): 0.2 µm at 1000 rad/s, growing like ω^0.7 (the speed exponent of
/// Dowson–Toyoda, docs/physics.md §5.1).
fn film_m(speed: f64) -> f64 {
    2.0e-7 * (speed.abs() / 1000.0).powf(0.7)
}

struct ClosedFormStepper {
    lubricated: bool,
    cage_angle: f64,
    last_time: Option<f64>,
    fail_at: Option<usize>,
    steps: usize,
    sleep: Option<std::time::Duration>,
}

impl ClosedFormStepper {
    fn new(lubricated: bool) -> Self {
        Self {
            lubricated,
            cage_angle: 0.0,
            last_time: None,
            fail_at: None,
            steps: 0,
            sleep: None,
        }
    }
}

/// Friction torque of the lubricated double (N·m), the same at every speed; its power loss
/// M·|ω| is split 1/2 rolling, 3/10 viscous, 1/5 boundary.
const FRICTION_TORQUE_NM: f32 = 2.0e-3;

impl BearingStepper for ClosedFormStepper {
    fn name(&self) -> String {
        "test double".into()
    }

    fn friction(
        &mut self,
        s: &crate::trace::Sample,
        out: &mut StepOutputs,
    ) -> Result<(), StepFault> {
        if self.lubricated {
            let power = FRICTION_TORQUE_NM * s.speed_rad_s.abs();
            out.friction_torque_nm = FRICTION_TORQUE_NM;
            out.power_loss_w = power;
            out.power_loss_split_w = [0.5 * power, 0.3 * power, 0.2 * power];
        }
        Ok(())
    }

    fn step(&mut self, s: &crate::trace::Sample, out: &mut StepOutputs) -> Result<(), StepFault> {
        if self.fail_at == Some(self.steps) {
            return Err(StepFault {
                reason: "injected".into(),
            });
        }
        self.steps += 1;
        if let Some(d) = self.sleep {
            std::thread::sleep(d);
        }
        if let Some(t) = self.last_time {
            self.cage_angle += CAGE_RATIO * f64::from(s.speed_rad_s) * (s.time_s - t);
        }
        self.last_time = Some(s.time_s);
        let h = if self.lubricated {
            film_m(f64::from(s.speed_rad_s)) as f32
        } else {
            0.0
        };
        out.rollers = Z;
        out.cage_angle_rad = self.cage_angle as f32;
        let mut force = [0f32; 2];
        for j in 0..Z {
            let theta = out.cage_angle_rad + (std::f32::consts::TAU * j as f32) / Z as f32;
            let (sin, cos) = theta.sin_cos();
            let delta = s.x_m * cos + s.y_m * sin - CLEARANCE as f32 + 2.0 * h;
            let q = if delta > 0.0 {
                (K as f32) * delta.powf(10.0 / 9.0)
            } else {
                0.0
            };
            force[0] -= q * cos;
            force[1] -= q * sin;
            out.roller_load_n[j] = q;
            out.film_inner_m[j] = h;
            out.film_outer_m[j] = h;
            let source = match (self.lubricated, j % 2) {
                (false, _) => FilmSource::None,
                (true, 0) => FilmSource::NetworkInt,
                (true, _) => FilmSource::Fallback,
            };
            out.source_inner[j] = source;
            out.source_outer[j] = source;
        }
        out.force_n = force;
        Ok(())
    }
}

/// The same formulas in f64; `film_scale` ≠ 1 makes it disagree with the stepper on purpose.
struct ClosedFormReference {
    film_scale: f64,
}

impl AccuracyReference for ClosedFormReference {
    fn name(&self) -> String {
        "f64 closed form".into()
    }

    fn reference(
        &mut self,
        s: &crate::trace::Sample,
        stepped: &StepOutputs,
    ) -> Result<ReferenceOutputs, StepFault> {
        let h = film_m(f64::from(s.speed_rad_s)) * self.film_scale;
        let mut r = ReferenceOutputs::default();
        for j in 0..stepped.rollers {
            let theta =
                f64::from(stepped.cage_angle_rad) + std::f64::consts::TAU * j as f64 / Z as f64;
            let (sin, cos) = theta.sin_cos();
            let delta = f64::from(s.x_m) * cos + f64::from(s.y_m) * sin - CLEARANCE + 2.0 * h;
            let q = if delta > 0.0 {
                K * delta.powf(10.0 / 9.0)
            } else {
                0.0
            };
            r.force_n[0] -= q * cos;
            r.force_n[1] -= q * sin;
            r.roller_load_n.push(q);
            r.film_inner_m.push(h);
            r.film_outer_m.push(h);
        }
        Ok(r)
    }
}

fn trace(count: usize, rate: f64) -> Trace {
    Whirl {
        speed_rad_s: 1500.0,
        acceleration_rad_s2: 0.0,
        offset_m: [0.0, -6.0e-6],
        radius_m: 1.5e-6,
        whirl_rad_s: 2.0 * std::f64::consts::PI * 120.0,
        tilt_amplitude_rad: None,
    }
    .trace(
        TraceMeta {
            bearing: "hub_motor".into(),
            lubricant: "oil".into(),
            sample_rate_hz: rate,
        },
        count,
    )
}

fn config(reference_every: usize, paced: bool, rate: f64) -> ReplayConfig {
    ReplayConfig {
        rate_hz: rate,
        reference_every,
        paced,
        limits: Limits::default(),
        min_reference_force_n: 1.0,
        realtime: None,
        realtime_fallback: false,
        pause_probe_s: 0.0,
        strict_timing: false,
    }
}

/// Replays `trace` through `stepper` alone (no reference, no dry model, no progress bar).
fn replay_stepper_only(
    trace: &Trace,
    stepper: &mut dyn BearingStepper,
    config: &ReplayConfig,
) -> Result<ReplayRun, ReplayError> {
    replay(
        trace,
        Parts {
            stepper,
            reference: None,
            dry: None,
            warm_up: None,
        },
        config,
        None,
    )
}

/// Reference: the nearest-rank definition worked by hand on 1..=1000.
#[test]
fn nearest_rank_percentiles() {
    let times: Vec<u64> = (1..=1000).rev().collect();
    let s = StepTimeStats::of(&times).unwrap();
    assert_eq!(
        (s.min, s.median, s.p99, s.p999, s.max),
        (1, 500, 990, 999, 1000)
    );
    assert!((s.mean - 500.5).abs() < 1e-12);
    assert_eq!(percentile(&[3.0], 0.99), Some(3.0));
    assert_eq!(percentile(&[], 0.5), None);
    // NaN sorts last: a NaN error can never hide below a limit.
    assert!(percentile(&[0.0, f64::NAN], 0.99).unwrap().is_nan());
}

#[test]
fn budget_verdict_is_on_p999() {
    let s = StepTimeStats::of(&(1..=1000).map(|i| i * 10).collect::<Vec<u64>>()).unwrap();
    // p99.9 = 9990 ns.
    let limits = |budget_us| Limits {
        budget_us,
        ..Limits::default()
    };
    assert!(budget_verdict(&s, &limits(9.99)).is_ok());
    let reason = budget_verdict(&s, &limits(9.98)).unwrap_err();
    assert!(
        reason.contains("p99.9 step time 9.990 µs > budget 9.98 µs"),
        "{reason}"
    );
}

/// A budget miss is left not judged only when the measured pauses account for the steps over
/// it (within three Poisson deviations) and the model's own p99 step is inside the budget.
#[test]
fn a_budget_miss_is_explained_by_pauses_only_within_their_poisson_count() {
    use super::pauses::PauseSummary;
    use super::report::explained_by_pauses;
    let pauses = |expected: f64| PauseSummary {
        probe_s: 0.5,
        threshold_ns: 7_200,
        pauses: 641,
        pauses_per_s: 1282.0,
        longest_pause_ns: 90_000,
        expected_steps_over_budget: expected,
    };
    // 1000 steps of 2 µs … 3 µs, then the slow tail the pauses put there.
    let mut times: Vec<u64> = (0..1000).map(|i| 2_000 + i).collect();
    times.extend([30_000; 8]);
    let fast = StepTimeStats::of(&times).unwrap();
    let limits = Limits::default();
    // Expected 73: 73 + 3·√73 + 3 = 101.6 steps allowed.
    assert!(explained_by_pauses(77, &pauses(73.0), &fast, &limits));
    assert!(explained_by_pauses(101, &pauses(73.0), &fast, &limits));
    assert!(!explained_by_pauses(102, &pauses(73.0), &fast, &limits));
    // No pauses measured: 3 steps over are noise, 4 are the model's.
    assert!(explained_by_pauses(3, &pauses(0.0), &fast, &limits));
    assert!(!explained_by_pauses(4, &pauses(0.0), &fast, &limits));
    // A model whose p99 step is over the budget is slow, whatever the machine does.
    let slow = StepTimeStats::of(&(0..1000).map(|_| 12_000).collect::<Vec<u64>>()).unwrap();
    assert!(!explained_by_pauses(1000, &pauses(2000.0), &slow, &limits));
}

#[test]
fn exact_reference_passes_and_the_dry_model_is_worse() {
    let trace = trace(500, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    let mut dry = ClosedFormStepper::new(false);
    let mut reference = ClosedFormReference { film_scale: 1.0 };
    let cfg = config(7, false, 10_000.0);
    let run = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: Some(&mut reference),
            dry: Some(&mut dry),
            warm_up: None,
        },
        &cfg,
        None,
    )
    .unwrap();
    assert_eq!(run.step_times_ns.len(), 500);
    assert_eq!(run.points.len(), 500_usize.div_ceil(7));
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, stepper.name(), &cfg, &run).unwrap();
    assert!(report.film_contacts_compared > 0);
    // f32 against f64 of the same formulas: rounding only.
    assert!(report.film_rel_err_p99.unwrap() < 1e-5, "{report:?}");
    assert!(report.force_rel_err_p99.unwrap() < 1e-4, "{report:?}");
    // Without the 2h ≈ 0.5 µm of film in a ≈ 8 µm approach the force is far off.
    assert!(report.dry_force_rel_err_p99.unwrap() > 0.05, "{report:?}");
    assert_eq!(report.accuracy_ok, Some(true));
    // Sources by roller parity: 9 of 17 rollers (even j) are served by the network.
    assert!((report.network_fraction.unwrap() - 9.0 / 17.0).abs() < 1e-12);
    let json = serde_json::to_value(&report).unwrap();
    for key in [
        "steps",
        "budget_ok",
        "accuracy_ok",
        "film_rel_err_p99",
        "force_rel_err_p99",
        "dry_force_rel_err_p99",
        "network_fraction",
        "friction",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    // The friction of every step reaches the report: M·|ω| over the trace's speeds.
    let friction = report.friction.unwrap();
    let power = |s: &crate::trace::Sample| f64::from(FRICTION_TORQUE_NM * s.speed_rad_s.abs());
    let (low, high) = trace
        .samples
        .iter()
        .map(power)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p), h.max(p))
        });
    assert_eq!(friction.power_loss_w.min, low);
    assert_eq!(friction.power_loss_w.max, high);
    assert_eq!(
        friction.friction_torque_nm.mean,
        f64::from(FRICTION_TORQUE_NM)
    );
    let split = friction.power_loss_split_mean_w;
    assert!((split.rolling / friction.power_loss_w.mean - 0.5).abs() < 1e-6);
    assert!((split.boundary / friction.power_loss_w.mean - 0.2).abs() < 1e-6);
    for key in ["min", "median", "p99", "p999", "max"] {
        assert!(
            json["step_time_ns"].get(key).is_some(),
            "missing step_time_ns.{key}"
        );
    }

    let dir = tempfile::tempdir().unwrap();
    if let Ok(keep) = std::env::var("HIL_TEST_KEEP_PLOTS") {
        std::fs::create_dir_all(&keep).unwrap();
        let mut files = OutputFiles::new();
        plots::write_all(&mut files, std::path::Path::new(&keep), &trace, &run, 10.0).unwrap();
        files.commit().unwrap();
    }
    let mut files = OutputFiles::new();
    report.write(&mut files, dir.path(), &trace, &run).unwrap();
    let written =
        plots::write_all(&mut files, dir.path(), &trace, &run, cfg.limits.budget_us).unwrap();
    files.commit().unwrap();
    assert_eq!(written.len(), 3);
    for name in
        written
            .iter()
            .map(String::as_str)
            .chain(["report.json", "report.md", "friction.csv"])
    {
        let len = std::fs::metadata(dir.path().join(name)).unwrap().len();
        assert!(len > 500, "{name} is {len} bytes");
    }
    let csv = std::fs::read_to_string(dir.path().join("friction.csv")).unwrap();
    assert_eq!(csv.lines().count(), 501, "header and one line per step");
}

#[test]
fn a_film_off_by_five_percent_fails_accuracy_with_the_reason() {
    let trace = trace(200, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    // Reference film = stepper film / 1.05: relative error exactly 5 %.
    let mut reference = ClosedFormReference {
        film_scale: 1.0 / 1.05,
    };
    let cfg = config(10, false, 10_000.0);
    let run = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: Some(&mut reference),
            dry: None,
            warm_up: None,
        },
        &cfg,
        None,
    )
    .unwrap();
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run).unwrap();
    assert!(
        (report.film_rel_err_p99.unwrap() - 0.05).abs() < 1e-5,
        "{report:?}"
    );
    assert_eq!(report.accuracy_ok, Some(false));
    assert!(!report.passed());
    assert!(
        report.reasons.iter().any(|r| r.contains("central film")),
        "{:?}",
        report.reasons
    );
    assert_eq!(report.dry_force_rel_err_p99, None);
}

#[test]
fn without_reference_accuracy_is_not_checked() {
    let trace = trace(50, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    let cfg = config(0, false, 10_000.0);
    let run = replay_stepper_only(&trace, &mut stepper, &cfg).unwrap();
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run).unwrap();
    assert_eq!(report.accuracy_ok, None);
    assert_eq!(report.film_rel_err_p99, None);
}

#[test]
fn a_stepper_fault_names_the_sample() {
    let trace = trace(20, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    stepper.fail_at = Some(5);
    let err = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: None,
            dry: None,
            warm_up: None,
        },
        &config(1, false, 10_000.0),
        None,
    )
    .unwrap_err();
    assert_eq!(err.index, 5);
    assert_eq!(err.to_string(), "stepper failed at sample 5: injected");
}

/// A subnormal step rate has an infinite period, which `Duration` cannot hold: refused before
/// the loop (paced or not), never a panic.
#[test]
fn a_step_rate_without_a_finite_period_is_refused() {
    let trace = trace(20, 10_000.0);
    for paced in [false, true] {
        let mut stepper = ClosedFormStepper::new(true);
        let err = replay_stepper_only(&trace, &mut stepper, &config(0, paced, 4e-320)).unwrap_err();
        assert_eq!(err.stage, "configuration");
        assert!(err.to_string().contains("allowed 1e-3 ..= 1e7 Hz"), "{err}");
    }
}

/// Paced at 2 kHz (0.5 ms period) with steps that sleep 1 ms: every step misses its deadline
/// (sleep never returns early), and the loop cannot finish before 40 × 1 ms.
#[test]
fn paced_replay_counts_every_missed_deadline() {
    let trace = trace(40, 2000.0);
    let mut stepper = ClosedFormStepper::new(true);
    stepper.sleep = Some(std::time::Duration::from_millis(1));
    let run = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: None,
            dry: None,
            warm_up: None,
        },
        &config(0, true, 2000.0),
        None,
    )
    .unwrap();
    let pacing = run.pacing.unwrap();
    assert_eq!(pacing.misses, 40);
    assert!(pacing.max_lateness_ns >= 500_000);
    assert!(pacing.wall_s >= 0.040);
}

/// Paced at 1 kHz with fast steps: the loop takes at least the trace's duration (39 periods)
/// because each step waits for its release time.
#[test]
fn paced_replay_runs_at_wall_clock_rate() {
    let trace = trace(40, 1000.0);
    let mut stepper = ClosedFormStepper::new(true);
    let run = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: None,
            dry: None,
            warm_up: None,
        },
        &config(0, true, 1000.0),
        None,
    )
    .unwrap();
    assert!(run.pacing.unwrap().wall_s >= 0.039);
}

/// `--realtime`: the timed loop runs under SCHED_FIFO on the requested CPU and the thread is
/// back under its own policy and CPU set afterwards; where the process may not (not root, no
/// CAP_SYS_NICE), the replay refuses with the reason instead of timing under the wrong policy.
#[cfg(target_os = "linux")]
#[test]
fn realtime_scheduling_covers_the_timed_loop_only() {
    use crate::realtime::Realtime;
    let trace = trace(50, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    let request = Realtime {
        cpu: 0,
        priority: 10,
    };
    let cfg = ReplayConfig {
        realtime: Some(request),
        ..config(0, false, 10_000.0)
    };
    // SAFETY: reads of the calling thread's scheduling policy.
    let policy_before = unsafe { libc::sched_getscheduler(0) };
    let result = replay_stepper_only(&trace, &mut stepper, &cfg);
    match result {
        Ok(run) => {
            assert_eq!(run.realtime, Some(request));
            let report =
                ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run)
                    .unwrap();
            assert_eq!(report.realtime, Some(request));
            assert!(report
                .markdown()
                .contains("SCHED_FIFO priority 10 on CPU 0"));
        }
        Err(e) => {
            assert_eq!(e.stage, "real-time scheduling");
            assert!(e.fault.reason.contains("CAP_SYS_NICE"), "{e}");
        }
    }
    // SAFETY: as above.
    assert_eq!(unsafe { libc::sched_getscheduler(0) }, policy_before);
    assert_ne!(policy_before, libc::SCHED_FIFO);
    // A CPU that does not exist is refused before anything changes.
    let cfg = ReplayConfig {
        realtime: Some(Realtime {
            cpu: 1 << 20,
            priority: 10,
        }),
        ..config(0, false, 10_000.0)
    };
    let e = replay_stepper_only(&trace, &mut stepper, &cfg).unwrap_err();
    assert!(e.fault.reason.contains("does not exist"), "{e}");
}

/// `--realtime auto`: where real-time scheduling is refused (here: a CPU that does not exist),
/// the timed loop runs under the ordinary policy and the run and the report say why, instead of
/// the replay failing as it does without the fallback (previous test).
#[cfg(target_os = "linux")]
#[test]
fn refused_realtime_falls_back_when_asked() {
    use crate::realtime::Realtime;
    let trace = trace(50, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    let cfg = ReplayConfig {
        realtime: Some(Realtime {
            cpu: 1 << 20,
            priority: 10,
        }),
        realtime_fallback: true,
        ..config(0, false, 10_000.0)
    };
    let run = replay_stepper_only(&trace, &mut stepper, &cfg).unwrap();
    assert_eq!(run.realtime, None);
    assert_eq!(run.step_times_ns.len(), 50);
    let reason = run.realtime_refused.clone().unwrap();
    assert!(reason.contains("does not exist"), "{reason}");
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run).unwrap();
    assert_eq!(report.realtime_refused.as_deref(), Some(reason.as_str()));
    assert!(report.markdown().contains(&format!(
        "ordinary scheduling policy (real-time scheduling refused: {reason})"
    )));
    let json = serde_json::to_value(&report).unwrap();
    assert_eq!(json["realtime_refused"], serde_json::json!(reason));
    assert!(json["realtime"].is_null());
}

/// The warm-up steps a second stepper over the first `WARM_UP_STEPS` samples before the timed
/// loop and leaves the timed one alone: with the test double's integrated state (cage angle,
/// last time), any extra step of the timed stepper would change its outputs, and they equal a
/// replay's without warm-up sample for sample. The warm-up's first step is reported.
#[test]
fn warm_up_steps_a_second_stepper_only() {
    let trace = trace(100, 10_000.0);
    let cfg = config(0, false, 10_000.0);
    let mut plain = ClosedFormStepper::new(true);
    let without = replay_stepper_only(&trace, &mut plain, &cfg).unwrap();
    let mut stepper = ClosedFormStepper::new(true);
    let mut warm = ClosedFormStepper::new(true);
    let with = replay(
        &trace,
        Parts {
            stepper: &mut stepper,
            reference: None,
            dry: None,
            warm_up: Some(&mut warm),
        },
        &cfg,
        None,
    )
    .unwrap();
    assert_eq!(warm.steps, WARM_UP_STEPS);
    assert_eq!(stepper.steps, 100);
    assert_eq!(with.outputs, without.outputs);
    assert_eq!(without.cold_step_ns, None);
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &with).unwrap();
    assert_eq!(report.cold_step_ns, with.cold_step_ns);
    assert!(report.cold_step_ns.is_some());
    assert!(report.markdown().contains(&format!(
        "Warm-up: a second stepper took {WARM_UP_STEPS} untimed steps"
    )));
    let no_warm_up =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &without).unwrap();
    assert!(!no_warm_up.markdown().contains("Warm-up"));
}

/// The pause probe runs when asked, lands in the report (JSON `environment`, a markdown line)
/// and, when the budget is missed, in its reason; its figures follow `pauses::PauseProbe`'s
/// definition (threshold = budget − median step, floored at 1 µs). Without it the report has
/// no `environment`.
#[test]
fn pause_probe_reaches_the_report() {
    let trace = trace(200, 10_000.0);
    let mut stepper = ClosedFormStepper::new(true);
    // A budget of 1 ns: every step is over it, so the budget verdict fails.
    let cfg = ReplayConfig {
        pause_probe_s: 0.02,
        strict_timing: false,
        limits: Limits {
            budget_us: 1e-3,
            ..Limits::default()
        },
        ..config(0, false, 10_000.0)
    };
    let run = replay_stepper_only(&trace, &mut stepper, &cfg).unwrap();
    let probe = run.pauses.clone().unwrap();
    assert!(probe.duration_ns >= 20_000_000);
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run).unwrap();
    let env = report.environment.unwrap();
    assert_eq!(env.threshold_ns, super::pauses::MIN_PAUSE_NS);
    assert_eq!(env.pauses, probe.gaps_ns.len());
    assert!(!report.budget_ok);
    assert!(
        report
            .reasons
            .iter()
            .any(|r| r.contains("the machine paused")),
        "{:?}",
        report.reasons
    );
    assert!(report.markdown().contains("Machine pauses"));
    let json = serde_json::to_value(&report).unwrap();
    assert!(json["environment"]["pauses_per_s"].is_number());

    let cfg = config(0, false, 10_000.0);
    let run = replay_stepper_only(&trace, &mut stepper, &cfg).unwrap();
    assert_eq!(run.pauses, None);
    let report =
        ReplayReport::build(&trace.meta, FilmKind::Int, "double".into(), &cfg, &run).unwrap();
    assert_eq!(report.environment, None);
    assert!(!report.markdown().contains("Machine pauses"));
}
