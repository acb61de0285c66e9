//! The implicit integrator: energy conservation, observed order against the exact modal
//! solution, and honest failure reporting.

use nalgebra::{DMatrix, DVector};

use super::modes_tests::friswell_5_9_1;
use crate::analysis::integrator::{Integrator, NewtonSettings, Scheme, StepError};
use crate::analysis::modes::undamped_modes;
use crate::bearing::{
    BearingError, BearingModel, BearingReaction, BearingSpec, BearingState, LinearBearing,
};
use crate::model::RotorModel;

fn linear_bearings(model: &RotorModel) -> Vec<Box<dyn BearingModel>> {
    model
        .description
        .bearings
        .iter()
        .map(|b| b.spec.build().unwrap())
        .collect()
}

fn bearing_k(model: &RotorModel) -> Vec<[[f64; 2]; 2]> {
    model
        .description
        .bearings
        .iter()
        .map(|b| match &b.spec {
            BearingSpec::Linear(l) => l.stiffness,
            BearingSpec::Roller { .. } => unreachable!(),
        })
        .collect()
}

fn integrator(
    model: &RotorModel,
    scheme: Scheme,
    dt: f64,
    rpm: f64,
    q0: DVector<f64>,
    v0: DVector<f64>,
) -> Integrator {
    let omega = rpm * std::f64::consts::PI / 30.0;
    Integrator::new(
        scheme,
        dt,
        omega,
        model.mass.clone(),
        &model.damping + &model.gyroscopic * omega,
        model.stiffness.clone(),
        model.bearing_dofs(),
        linear_bearings(model),
        NewtonSettings::default(),
        (0.0, q0, v0),
        DVector::zeros(model.n_dof()),
        DVector::zeros(model.n_dof()),
    )
    .unwrap()
}

/// Total energy including the linear bearing springs.
fn energy(model: &RotorModel, it: &Integrator) -> f64 {
    let kb = bearing_k(model);
    let mut e = it.shaft_energy();
    for (dofs, k) in model.bearing_dofs().iter().zip(&kb) {
        let u = [it.state.q[dofs[0]], it.state.q[dofs[1]]];
        for r in 0..2 {
            for c in 0..2 {
                e += 0.5 * u[r] * k[r][c] * u[c];
            }
        }
    }
    e
}

/// Reference: the trapezoidal (average-acceleration) rule preserves the quadratic invariant of a
/// linear conservative system exactly (Simo & Tarnow 1992; Géradin & Rixen §7.3), gyroscopic
/// forces doing no work. The undamped Friswell 5.9.1 rotor at 4000 rpm must keep its energy over
/// 4000 steps to round-off and Newton tolerance; HHT-α (α = 0.1) must lose energy.
#[test]
fn average_acceleration_conserves_energy_of_undamped_gyroscopic_rotor() {
    let model = friswell_5_9_1();
    let n = model.n_dof();
    // Start from a bent shape with a velocity kick: all modes excited.
    let q0 = DVector::from_fn(n, |i, _| 1e-3 * ((i as f64) * 0.7).sin());
    let v0 = DVector::from_fn(n, |i, _| 0.1 * ((i as f64) * 1.3).cos());
    let mut it = integrator(
        &model,
        Scheme::AverageAcceleration,
        1e-4,
        4000.0,
        q0.clone(),
        v0.clone(),
    );
    let e0 = energy(&model, &it);
    let mut worst: f64 = 0.0;
    for _ in 0..4000 {
        it.step(&DVector::zeros(n)).unwrap();
        worst = worst.max((energy(&model, &it) - e0).abs() / e0);
    }
    eprintln!("average acceleration: worst relative energy drift {worst:e}");
    assert!(worst < 1e-8, "relative energy drift {worst:e}");

    let mut hht = integrator(&model, Scheme::Hht { alpha: 0.1 }, 1e-4, 4000.0, q0, v0);
    for _ in 0..4000 {
        hht.step(&DVector::zeros(n)).unwrap();
    }
    let loss = 1.0 - energy(&model, &hht) / e0;
    assert!(loss > 1e-3, "HHT-α should dissipate, lost only {loss:e}");
}

/// Exact free response of the undamped non-rotating rotor by modal superposition.
fn exact(
    phi: &DMatrix<f64>,
    w: &[f64],
    m: &DMatrix<f64>,
    q0: &DVector<f64>,
    v0: &DVector<f64>,
    t: f64,
) -> DVector<f64> {
    let mut q = DVector::zeros(q0.len());
    for (i, &wi) in w.iter().enumerate() {
        let col = phi.column(i);
        let a = col.dot(&(m * q0));
        let b = col.dot(&(m * v0));
        q += col * (a * (wi * t).cos() + b * (wi * t).sin() / wi);
    }
    q
}

/// Reference: exact modal solution (Friswell et al. (2010) §2.4) of the undamped rotor at rest.
/// Initial state in the first three modes; the step is halved twice and the observed order
/// log₂(e(h)/e(h/2)) must be 2 (±0.1) for both average acceleration and HHT-α.
#[test]
fn newmark_and_hht_converge_at_second_order() {
    let model = friswell_5_9_1();
    let kb = bearing_k(&model);
    let (k, _) = model.linearised(0.0, &kb, &[[[0.0; 2]; 2]; 2]);
    let (w, phi) = undamped_modes(&model.mass, &k).unwrap();
    let q0 = (phi.column(0) + phi.column(4) * 0.5) * 1e-3;
    let v0 = phi.column(2) * (0.3e-3 * w[2]);
    let t_end = 0.04;
    let reference = exact(&phi, &w, &model.mass, &q0, &v0, t_end);
    for scheme in [Scheme::AverageAcceleration, Scheme::Hht { alpha: 0.05 }] {
        let mut errors = Vec::new();
        for steps in [400usize, 800, 1600] {
            let mut it = integrator(
                &model,
                scheme,
                t_end / steps as f64,
                0.0,
                q0.clone(),
                v0.clone(),
            );
            for _ in 0..steps {
                it.step(&DVector::zeros(model.n_dof())).unwrap();
            }
            errors.push((&it.state.q - &reference).amax());
        }
        for pair in errors.windows(2) {
            let order = (pair[0] / pair[1]).log2();
            eprintln!("{scheme:?}: errors {errors:?}, observed order {order:.4}");
            assert!(
                (order - 2.0).abs() < 0.1,
                "{scheme:?}: errors {errors:?}, order {order}"
            );
        }
    }
}

/// A very stiff bearing that reports a zero tangent: Newton degrades to a fixed-point iteration
/// with contraction factor S·k ≫ 1, diverges, and the step must fail with `NotConverged` rather
/// than return a state.
struct WrongTangent;
impl BearingModel for WrongTangent {
    fn evaluate(&mut self, s: &BearingState) -> Result<BearingReaction, BearingError> {
        let k = 1e9;
        let u = s.displacement;
        Ok(BearingReaction {
            force: [
                -k * u[0] - 1e12 * u[0].powi(3),
                -k * u[1] - 1e12 * u[1].powi(3),
            ],
            stiffness: [[-k, 0.0], [0.0, -k]],
            damping: [[0.0; 2]; 2],
            rollers: None,
        })
    }
    fn commit(&mut self, _: &BearingState, _: f64) {}
}

#[test]
fn newton_failure_is_reported() {
    let model = friswell_5_9_1();
    let n = model.n_dof();
    let mut it = Integrator::new(
        Scheme::AverageAcceleration,
        1e-4,
        0.0,
        model.mass.clone(),
        model.damping.clone(),
        model.stiffness.clone(),
        model.bearing_dofs(),
        vec![
            Box::new(WrongTangent),
            Box::new(LinearBearing::isotropic(1e6, 0.0)),
        ],
        NewtonSettings::default(),
        (0.0, DVector::zeros(n), DVector::zeros(n)),
        DVector::zeros(n),
        DVector::zeros(n),
    )
    .unwrap();
    let mut f = DVector::zeros(n);
    f[0] = 1e4;
    let err = it.step(&f).unwrap_err();
    assert!(matches!(err, StepError::NotConverged { .. }), "{err}");
    assert!(err.to_string().contains("did not converge"), "{err}");
}
