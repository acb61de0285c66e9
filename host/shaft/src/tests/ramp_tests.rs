//! Speed ramps: the mesh excitation follows the instantaneous speed, and a slow run-up of the
//! hub-motor shaft on linear bearings passes its first lateral resonance where the Campbell
//! diagram puts the crossing of the mesh order with that mode.

use std::path::Path;

use nalgebra::DVector;

use crate::analysis::integrator::{NewtonSettings, Scheme};
use crate::analysis::operating::operating_modes;
use crate::analysis::simulate::{run, RunSettings};
use crate::analysis::system::TimeSystem;
use crate::bearing::{BearingSpec, LinearBearing};
use crate::model::config::load_model;
use crate::model::loads::{Load, SpinAt};
use crate::model::speed_profile::SpeedProfile;
use crate::model::RotorModel;

const TEETH: f64 = 17.0;

fn hub_linear(k: f64, c: f64) -> RotorModel {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/shaft_hub_motor.toml");
    let mut model = load_model(&path).unwrap();
    for b in &mut model.description.bearings {
        b.spec = BearingSpec::Linear(LinearBearing::isotropic(k, c));
    }
    model
}

fn rpm(r: f64) -> f64 {
    r * std::f64::consts::PI / 30.0
}

/// Reference: counting. Along a 1000 → 3000 rpm ramp the y force at the pinion node is sampled
/// finely and its local maxima counted in windows (the mesh fluctuation and the ripple, both at
/// order z = 17, give exactly one maximum per mesh period). The count must equal the number of
/// mesh periods z/(2π)·∫Ω dt = z·(Ω_a + Ω_b)(t_b − t_a)/(4π) of a linear ramp within ±1, so the
/// instantaneous mesh frequency follows the ramp (it triples across the ramp).
#[test]
fn mesh_frequency_follows_the_ramp() {
    let model = hub_linear(3e8, 0.0);
    let system = TimeSystem::new(&model, None).unwrap();
    let node = model
        .description
        .loads
        .loads
        .iter()
        .find_map(|l| match l {
            Load::GearMesh(m) => Some(m.node),
            _ => None,
        })
        .unwrap();
    let profile = SpeedProfile {
        start: rpm(1000.0),
        end: rpm(3000.0),
        ramp_start: 0.0,
        ramp_duration: 0.5,
    };
    let dt = 2e-6;
    let mut f = DVector::zeros(system.n_dof());
    let fy: Vec<f64> = (0..=(0.5 / dt) as usize)
        .map(|k| {
            let t = k as f64 * dt;
            let at = SpinAt {
                angle: profile.angle(t),
                speed: profile.speed(t),
                acceleration: profile.acceleration(t),
            };
            system.load_at(at, &mut f).unwrap();
            f[4 * node + 1]
        })
        .collect();
    let windows = [(0.0, 0.05), (0.2, 0.25), (0.44, 0.49)];
    let mut rates = Vec::new();
    for (ta, tb) in windows {
        let (a, b) = ((ta / dt) as usize, (tb / dt) as usize);
        let maxima = (a.max(1)..b)
            .filter(|&k| fy[k] > fy[k - 1] && fy[k] >= fy[k + 1])
            .count() as f64;
        let expected = TEETH * (profile.speed(ta) + profile.speed(tb)) * (tb - ta)
            / (4.0 * std::f64::consts::PI);
        assert!(
            (maxima - expected).abs() <= 1.0,
            "window {ta}–{tb} s: {maxima} maxima, {expected:.2} mesh periods expected"
        );
        rates.push(maxima / (tb - ta));
    }
    // The local mesh rate rises across the ramp (≈ 299 Hz at the start, ≈ 840 Hz at the end).
    assert!(rates[2] > 2.5 * rates[0], "{rates:?}");
}

/// Reference: Campbell diagram (`operating_modes`, an eigenvalue analysis independent of the
/// time integration). A run-up slow against the mode's damping (sweep parameter
/// η = (dω_exc/dt)/ω_n² well below ζ², the quasi-stationary regime of passage through
/// resonance; Markert & Seidler, Int. J. Solids Struct. 38 (2001) 1975–1992) peaks where the
/// mesh order z·Ω crosses the first lateral natural frequency, within the half-power
/// half-bandwidth: |Ω_peak/Ω_cross − 1| < ζ. Soft damped linear bearings (3·10⁷ N/m,
/// 2 kN·s/m) so the mode has ζ of a few per cent.
#[test]
fn slow_run_up_peaks_at_the_campbell_crossing() {
    let model = hub_linear(3e7, 2e3);
    // Crossing z·Ω = ω₁(Ω) by fixed-point iteration (ω₁ changes little with Ω).
    let mut cross = 2600.0 / TEETH;
    let mut zeta = 0.0;
    for _ in 0..6 {
        let (_, modes) = operating_modes(&model, cross, 2, false).unwrap();
        cross = modes[0].frequency / TEETH;
        zeta = modes[0].damping_ratio;
    }
    assert!(
        zeta > 0.01,
        "too little damping for a short test: ζ = {zeta}"
    );
    let (start, end, ramp) = (0.8 * cross, 1.2 * cross, 1.0);
    let eta = (end - start) * TEETH / ramp / (TEETH * cross).powi(2);
    assert!(
        eta < 0.3 * zeta * zeta,
        "η = {eta:.2e}, ζ² = {:.2e}",
        zeta * zeta
    );
    let mesh_hz = TEETH * end / (2.0 * std::f64::consts::PI);
    let settings = RunSettings {
        spin_speed: start,
        spin_speed_end: Some(end),
        dt: 1.0 / (20.0 * mesh_hz),
        settle_time: 0.05,
        record_time: ramp,
        record_every: 1,
        scheme: Scheme::AverageAcceleration,
        reduction_modes: None,
        newton: NewtonSettings::default(),
    };
    let r = run(&model, &settings, None).unwrap();
    let probe = r.probe_nodes.iter().position(|&n| n == 8).unwrap();
    // Below base speed the mean torque, so the static deflection, is constant: the vibration
    // is the displacement about the record's mean.
    let n = r.samples.len() as f64;
    let mean: [f64; 2] =
        [0, 1].map(|c| r.samples.iter().map(|s| s.probes[probe][0][c]).sum::<f64>() / n);
    let (peak_index, _) = r
        .samples
        .iter()
        .map(|s| {
            let u = s.probes[probe][0];
            (u[0] - mean[0]).hypot(u[1] - mean[1])
        })
        .enumerate()
        .fold(
            (0, 0.0),
            |best, (i, a)| if a > best.1 { (i, a) } else { best },
        );
    let peak_speed = r.samples[peak_index].spin_speed;
    let shift = peak_speed / cross - 1.0;
    println!(
        "crossing {:.1} rpm, peak at {:.1} rpm (shift {:+.4}), ζ = {zeta:.4}, η = {eta:.2e}",
        cross * 30.0 / std::f64::consts::PI,
        peak_speed * 30.0 / std::f64::consts::PI,
        shift
    );
    assert!(shift.abs() < zeta, "shift {shift:+.4} vs ζ = {zeta:.4}");
    // The sampled speed is the ramp's: first and last samples at the ends of the ramp.
    assert!((r.samples.last().unwrap().spin_speed / end - 1.0).abs() < 1e-12);
    assert!(r.samples[0].spin_speed > start && r.samples[0].spin_speed < start * 1.001);
}

/// Reference: Newton's second law by finite differences. The unbalance force during a ramp must
/// be −m_e·d²/dt² [e(cos ψ, sin ψ)], ψ = φ(t) + phase, evaluated here by a central second
/// difference of the eccentric mass's position along the profile (a different method from the
/// closed form m e (Ω² cos ψ + Ω̇ sin ψ, Ω² sin ψ − Ω̇ cos ψ) in `loads`).
#[test]
fn unbalance_force_during_a_ramp_is_the_inertial_force_of_the_mass() {
    use crate::model::loads::LoadSet;
    let (me, phase) = (2e-4, 0.7);
    let set = LoadSet {
        loads: vec![Load::Unbalance {
            node: 0,
            mass_eccentricity: me,
            phase,
        }],
        motor: None,
    };
    let profile = SpeedProfile {
        start: 200.0,
        end: 1200.0,
        ramp_start: 0.0,
        ramp_duration: 0.05,
    };
    let h = 1e-6;
    for &t in &[0.004, 0.021, 0.037] {
        let mut f = [0.0; 4];
        let at = SpinAt {
            angle: profile.angle(t),
            speed: profile.speed(t),
            acceleration: profile.acceleration(t),
        };
        set.add_forces_at(at, &[0.0; 4], true, &|d| d, &mut f)
            .unwrap();
        let pos = |t: f64| {
            let psi = profile.angle(t) + phase;
            [psi.cos(), psi.sin()]
        };
        let (a, b, c) = (pos(t - h), pos(t), pos(t + h));
        for k in 0..2 {
            let accel = (a[k] - 2.0 * b[k] + c[k]) / (h * h);
            let expected = -me * accel;
            assert!(
                (f[k] - expected).abs() < 1e-4 * expected.abs().max(me * 200.0f64.powi(2)),
                "t = {t}, component {k}: {} vs {expected}",
                f[k]
            );
        }
    }
}

/// Reference: a fresh integrator built at the new speed (the constructor's path). After
/// `set_spin_speed` the integrator must step exactly like one constructed at that speed from
/// the same state — every operator (K*⁻¹, the step operators, the bearing coupling S and the
/// constant-load response) is rebuilt with the new gyroscopic damping. Friswell et al. (2010)
/// Example 5.9.1 rotor, whose disks make the gyroscopic term large.
#[test]
fn speed_change_rebuilds_every_operator() {
    use crate::analysis::operating::build_bearings;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/friswell_5_9_1.toml");
    let model = load_model(&path).unwrap();
    let system = TimeSystem::new(&model, None).unwrap();
    let n = system.n_dof();
    let q0 = DVector::from_fn(n, |i, _| 1e-6 * ((i as f64) * 0.37).sin());
    let (w1, w2, dt) = (rpm(1000.0), rpm(4000.0), 1e-4);
    let make = |w: f64| {
        system
            .integrator(
                Scheme::AverageAcceleration,
                dt,
                w,
                build_bearings(&model).unwrap(),
                NewtonSettings::default(),
                0.0,
                q0.clone(),
                DVector::zeros(n),
            )
            .unwrap()
    };
    let mut changed = make(w1);
    changed.set_spin_speed(w2, &system.damping_at(w2)).unwrap();
    let mut fresh = make(w2);
    let mut slow = make(w1);
    let f = DVector::from_fn(n, |i, _| if i == 9 { 100.0 } else { 0.0 });
    for _ in 0..5 {
        changed.step(&f).unwrap();
        fresh.step(&f).unwrap();
        slow.step(&f).unwrap();
    }
    let diff = (&changed.state.v - &fresh.state.v).amax();
    let gyro = (&slow.state.v - &fresh.state.v).amax();
    assert!(diff <= 1e-12 * fresh.state.v.amax(), "{diff:e}");
    // The comparison can fail: the speed makes a visible difference over these steps.
    assert!(gyro > 1e-6 * fresh.state.v.amax(), "{gyro:e}");
}
