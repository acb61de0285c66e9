//! Time response at one constant spin speed, or through a linear speed ramp: start from the
//! static equilibrium at the (start) speed, integrate through a settling time, then record
//! probes (bearing and loaded nodes) and the bearing reactions, and collect the envelopes the
//! speed sweep reports. With a ramp ([`RunSettings::spin_speed_end`]) the speed is held through
//! the settling time and changes linearly over the recorded time ([`SpeedProfile`]); the
//! gyroscopic matrix, the loads and the bearings follow it at every step. A run is judged
//! steady when the displacement envelope of the second half of the record differs from the
//! first half's by less than [`STEADY_TOLERANCE`] (meaningless during a ramp).

use nalgebra::DVector;

use crate::analysis::integrator::{Integrator, NewtonSettings, Scheme, StepError, StepTotals};
use crate::analysis::operating::{build_bearings, OperatingError};
use crate::analysis::statics::equilibrium;
use crate::analysis::system::TimeSystem;
use crate::bearing::{BearingReaction, BearingSpec, RollerState};
use crate::model::loads::SpinAt;
use crate::model::speed_profile::SpeedProfile;
use crate::model::RotorModel;

/// Where the wall time of a run went, per step.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CostBreakdown {
    /// Simulated seconds per wall-clock second of the integration loop.
    pub real_time_factor: f64,
    /// Time step (s).
    pub dt_s: f64,
    /// Integrated coordinates.
    pub n_dof: usize,
    /// Steps.
    pub steps: usize,
    /// Mean bearing evaluations per step (each evaluates every bearing once).
    pub bearing_evaluations_per_step: f64,
    /// Wall time per step in the bearing models (µs).
    pub bearing_us_per_step: f64,
    /// Wall time per step in the shaft's linear algebra: the rest of the integrator step (µs).
    pub linear_algebra_us_per_step: f64,
    /// Wall time per step outside the integrator: loads, envelopes, recording and, during a
    /// speed ramp, the rebuild of the step operators for the new speed (µs).
    pub rest_us_per_step: f64,
    /// Wall time of one evaluation of all bearings (µs).
    pub bearing_us_per_evaluation: f64,
}

impl RunResult {
    /// The cost breakdown of this run at step `dt` (s).
    pub fn cost(&self, dt: f64) -> CostBreakdown {
        let t = &self.totals;
        let per_step = 1e6 / t.steps.max(1) as f64;
        CostBreakdown {
            real_time_factor: t.steps as f64 * dt / self.wall_seconds,
            dt_s: dt,
            n_dof: self.n_dof,
            steps: t.steps,
            bearing_evaluations_per_step: t.evaluations_per_step(),
            bearing_us_per_step: t.bearing_seconds * per_step,
            linear_algebra_us_per_step: (t.step_seconds - t.bearing_seconds) * per_step,
            rest_us_per_step: (self.wall_seconds - t.step_seconds) * per_step,
            bearing_us_per_evaluation: 1e6 * t.bearing_seconds
                / t.bearing_evaluations.max(1) as f64,
        }
    }
}

/// Relative change of the displacement envelope between the two halves of the record below
/// which a run counts as steady.
pub const STEADY_TOLERANCE: f64 = 0.02;

/// Settings of one time response.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSettings {
    /// Spin speed (rad/s): constant, or the start of the ramp.
    pub spin_speed: f64,
    /// End speed of a linear ramp over the recorded time (rad/s); None: constant speed.
    pub spin_speed_end: Option<f64>,
    /// Time step (s).
    pub dt: f64,
    /// Time integrated before recording starts (s).
    pub settle_time: f64,
    /// Recorded time (s).
    pub record_time: f64,
    /// Keep every n-th step in the samples (envelopes use every step).
    pub record_every: usize,
    /// Integration scheme.
    pub scheme: Scheme,
    /// Craig–Bampton modes (None: full model).
    pub reduction_modes: Option<usize>,
    /// Newton settings.
    pub newton: NewtonSettings,
}

/// Errors of a run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    /// Equilibrium, bearing building or reduction failed.
    #[error(transparent)]
    Operating(#[from] OperatingError),
    /// A time step failed.
    #[error(transparent)]
    Step(#[from] StepError),
}

/// One recorded instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub time: f64,
    /// Spin speed at that time (rad/s).
    pub spin_speed: f64,
    /// Per probe node: displacement [x, y] (m), velocity (m/s), acceleration (m/s²).
    pub probes: Vec<[[f64; 2]; 3]>,
    /// Per bearing: its reaction.
    pub bearings: Vec<BearingReaction>,
    /// Per bearing: per-roller states (roller models only) at the last Newton evaluation.
    pub rollers: Vec<Option<Vec<RollerState>>>,
}

/// Max envelopes over the recorded time (None where the bearing model gives no roller data).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct Envelope {
    /// Largest roller contact force (N).
    pub max_contact_force_n: Option<f64>,
    /// Largest roller contact stiffness (N/m).
    pub max_contact_stiffness_n_per_m: Option<f64>,
    /// Largest bearing stiffness: largest eigenvalue of the symmetric part of K_b (N/m).
    pub max_bearing_stiffness_n_per_m: f64,
    /// Largest central film (m).
    pub max_central_film_m: Option<f64>,
    /// Largest inner-race (bearing-node) displacement magnitude (m).
    pub max_displacement_m: f64,
    /// Largest bearing-node acceleration magnitude (m/s²).
    pub max_acceleration_m_s2: f64,
    /// Smallest bearing force magnitude (N).
    pub min_bearing_force_n: f64,
    /// Largest bearing force magnitude (N).
    pub max_bearing_force_n: f64,
}

/// Result of a run.
#[derive(Debug, Clone)]
pub struct RunResult {
    /// Probe node indices.
    pub probe_nodes: Vec<usize>,
    /// Recorded samples.
    pub samples: Vec<Sample>,
    /// Envelopes over the whole record.
    pub envelope: Envelope,
    /// Relative change of the displacement envelope between the record halves.
    pub steadiness: f64,
    /// Steps integrated.
    pub steps: usize,
    /// Integrated coordinates (full DOFs or reduced).
    pub n_dof: usize,
    /// Wall time of the integration loop (s): steps, loads, recording.
    pub wall_seconds: f64,
    /// Part of it in bearing evaluations (s).
    pub bearing_seconds: f64,
    /// The integrator's totals: steps, bearing evaluations, time in steps and in the bearings.
    pub totals: StepTotals,
    /// Largest Newton iteration count of any step.
    pub max_newton_iterations: usize,
    /// Steps whose Newton converged only to the bearing model's resolution
    /// (see `NewtonSettings::model_resolution`).
    pub resolution_limited_steps: usize,
}

fn stiffness_measure(k: &[[f64; 2]; 2]) -> f64 {
    // Largest eigenvalue of the symmetric part.
    let (a, d, b) = (k[0][0], k[1][1], 0.5 * (k[0][1] + k[1][0]));
    0.5 * (a + d) + (0.25 * (a - d).powi(2) + b * b).sqrt()
}

impl Envelope {
    fn empty() -> Self {
        Envelope {
            min_bearing_force_n: f64::INFINITY,
            ..Default::default()
        }
    }

    fn absorb(
        &mut self,
        bearing_disp: &[[f64; 2]],
        bearing_acc: &[[f64; 2]],
        r: &[BearingReaction],
    ) {
        let hyp = |v: &[f64; 2]| v[0].hypot(v[1]);
        for (u, a) in bearing_disp.iter().zip(bearing_acc) {
            self.max_displacement_m = self.max_displacement_m.max(hyp(u));
            self.max_acceleration_m_s2 = self.max_acceleration_m_s2.max(hyp(a));
        }
        let opt_max = |o: Option<f64>, v: f64| Some(o.map_or(v, |x| x.max(v)));
        for b in r {
            self.max_bearing_stiffness_n_per_m = self
                .max_bearing_stiffness_n_per_m
                .max(stiffness_measure(&b.stiffness));
            let f = hyp(&b.force);
            self.max_bearing_force_n = self.max_bearing_force_n.max(f);
            self.min_bearing_force_n = self.min_bearing_force_n.min(f);
            if let Some(d) = b.rollers {
                self.max_contact_force_n = opt_max(self.max_contact_force_n, d.max_contact_force);
                self.max_contact_stiffness_n_per_m =
                    opt_max(self.max_contact_stiffness_n_per_m, d.max_contact_stiffness);
                self.max_central_film_m = opt_max(self.max_central_film_m, d.max_central_film);
            }
        }
    }
}

/// Runs the model at one speed with the bearings built from `bearings` (the model's own specs
/// when None; a sweep passes dry / lubricated variants).
pub fn run(
    model: &RotorModel,
    settings: &RunSettings,
    bearings: Option<&[BearingSpec]>,
) -> Result<RunResult, RunError> {
    let omega = settings.spin_speed;
    let build = || -> Result<Vec<_>, OperatingError> {
        match bearings {
            None => Ok(build_bearings(model)?),
            Some(specs) => Ok(specs.iter().map(|s| s.build()).collect::<Result<_, _>>()?),
        }
    };
    let mut for_static = build()?;
    let eq = equilibrium(model, omega, &mut for_static).map_err(OperatingError::from)?;
    let system = TimeSystem::new(model, settings.reduction_modes).map_err(OperatingError::from)?;
    let n = system.n_dof();
    let z0 = system.from_full(&eq.q);
    let mut it = system.integrator(
        settings.scheme,
        settings.dt,
        omega,
        build()?,
        settings.newton,
        0.0,
        z0,
        DVector::zeros(n),
    )?;
    let probe_nodes = probe_nodes(model);
    let bearing_idx: Vec<[usize; 2]> = model
        .bearing_dofs()
        .iter()
        .map(|d| [system.index(d[0]), system.index(d[1])])
        .collect();
    let settle_steps = (settings.settle_time / settings.dt).ceil() as usize;
    let record_steps = (settings.record_time / settings.dt).ceil().max(2.0) as usize;
    let profile = SpeedProfile {
        start: omega,
        end: settings.spin_speed_end.unwrap_or(omega),
        ramp_start: settle_steps as f64 * settings.dt,
        ramp_duration: record_steps as f64 * settings.dt,
    };
    let mut f = DVector::zeros(n);
    let mut samples = Vec::new();
    let mut halves = [Envelope::empty(), Envelope::empty()];
    let mut max_iter = 0;
    let mut limited = 0;
    let clock = std::time::Instant::now();
    for step in 0..settle_steps + record_steps {
        let t1 = it.state.time + settings.dt;
        let speed = profile.speed(t1);
        if !profile.is_constant() {
            it.set_spin_speed(speed, &system.damping_at(speed))?;
        }
        let at = SpinAt {
            angle: profile.angle(t1),
            speed,
            acceleration: profile.acceleration(t1),
        };
        system
            .load_at(at, &mut f)
            .map_err(|e| StepError::Load(e.to_string()))?;
        it.step(&f)?;
        max_iter = max_iter.max(it.stats.iterations);
        limited += usize::from(it.stats.resolution_limited);
        if step < settle_steps {
            continue;
        }
        let k = step - settle_steps;
        let st = &it.state;
        let disp: Vec<[f64; 2]> = bearing_idx
            .iter()
            .map(|d| [st.q[d[0]], st.q[d[1]]])
            .collect();
        let acc: Vec<[f64; 2]> = bearing_idx
            .iter()
            .map(|d| [st.a[d[0]], st.a[d[1]]])
            .collect();
        halves[usize::from(2 * k >= record_steps)].absorb(&disp, &acc, &it.reactions);
        if k % settings.record_every.max(1) == 0 {
            samples.push(sample(&it, &system, &probe_nodes));
        }
    }
    let wall_seconds = clock.elapsed().as_secs_f64();
    let (envelope, steadiness) = merge_halves(halves);
    Ok(RunResult {
        probe_nodes,
        samples,
        envelope,
        steadiness,
        steps: settle_steps + record_steps,
        n_dof: n,
        wall_seconds,
        bearing_seconds: it.totals.bearing_seconds,
        totals: it.totals,
        max_newton_iterations: max_iter,
        resolution_limited_steps: limited,
    })
}

/// The probed nodes: the bearing nodes, then the loaded nodes, each once, in that order.
fn probe_nodes(model: &RotorModel) -> Vec<usize> {
    let mut probe_nodes: Vec<usize> = model.description.bearings.iter().map(|b| b.node).collect();
    probe_nodes.extend(
        model
            .description
            .loads
            .loads
            .iter()
            .filter_map(|l| l.node()),
    );
    let mut seen = Vec::new();
    probe_nodes.retain(|n| {
        let fresh = !seen.contains(n);
        seen.push(*n);
        fresh
    });
    probe_nodes
}

/// One recorded sample of the integrator's current state: the probes' displacement, velocity
/// and acceleration in physical coordinates, the bearing reactions and the roller states.
fn sample(it: &Integrator, system: &TimeSystem, probe_nodes: &[usize]) -> Sample {
    let st = &it.state;
    let probes = probe_nodes
        .iter()
        .map(|&node| {
            let g = |z: &DVector<f64>, c: usize| system.global(z, 4 * node + c);
            [
                [g(&st.q, 0), g(&st.q, 1)],
                [g(&st.v, 0), g(&st.v, 1)],
                [g(&st.a, 0), g(&st.a, 1)],
            ]
        })
        .collect();
    Sample {
        time: st.time,
        spin_speed: it.spin_speed(),
        probes,
        bearings: it.reactions.clone(),
        rollers: it
            .bearing_models()
            .iter()
            .map(|b| b.roller_states())
            .collect(),
    }
}

/// The envelope of the whole record from those of its two halves, and the steadiness: the
/// relative change of the peak displacement from the first half to the second.
fn merge_halves(halves: [Envelope; 2]) -> (Envelope, f64) {
    let [first, second] = halves;
    let steadiness = (second.max_displacement_m - first.max_displacement_m).abs()
        / first
            .max_displacement_m
            .max(second.max_displacement_m)
            .max(1e-300);
    let mut envelope = first;
    envelope.max_displacement_m = first.max_displacement_m.max(second.max_displacement_m);
    envelope.max_acceleration_m_s2 = first
        .max_acceleration_m_s2
        .max(second.max_acceleration_m_s2);
    envelope.max_bearing_stiffness_n_per_m = first
        .max_bearing_stiffness_n_per_m
        .max(second.max_bearing_stiffness_n_per_m);
    envelope.max_bearing_force_n = first.max_bearing_force_n.max(second.max_bearing_force_n);
    envelope.min_bearing_force_n = first.min_bearing_force_n.min(second.min_bearing_force_n);
    let merge = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(x), Some(y)) => Some(x.max(y)),
        (x, None) => x,
        (None, y) => y,
    };
    envelope.max_contact_force_n = merge(first.max_contact_force_n, second.max_contact_force_n);
    envelope.max_contact_stiffness_n_per_m = merge(
        first.max_contact_stiffness_n_per_m,
        second.max_contact_stiffness_n_per_m,
    );
    envelope.max_central_film_m = merge(first.max_central_film_m, second.max_central_film_m);
    (envelope, steadiness)
}
