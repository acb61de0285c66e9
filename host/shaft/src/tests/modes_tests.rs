//! Natural frequencies against Euler–Bernoulli closed forms and Friswell et al. (2010).

use crate::analysis::modes::{damped_modes, undamped_modes, Whirl};
use crate::bearing::{BearingSpec, LinearBearing};
use crate::model::damping::ProportionalDamping;
use crate::model::disk::RigidDisk;
use crate::model::element::Material;
use crate::model::loads::LoadSet;
use crate::model::{BearingSite, RotorDescription, RotorModel};

const STEEL: Material = Material {
    youngs_modulus: 211e9,
    shear_modulus: 81.2e9,
    density: 7810.0,
};

fn uniform(length: f64, diameter: f64, n_el: usize, bearings: Vec<BearingSite>) -> RotorModel {
    RotorModel::assemble(RotorDescription {
        node_positions: (0..=n_el)
            .map(|i| length * i as f64 / n_el as f64)
            .collect(),
        element_diameters: vec![(diameter, 0.0); n_el],
        material: STEEL,
        disks: vec![],
        bearings,
        damping: ProportionalDamping::default(),
        loads: LoadSet::default(),
    })
}

fn stiff(model: &RotorModel) -> nalgebra::DMatrix<f64> {
    let n = model.description.bearings.len();
    let kb: Vec<_> = model
        .description
        .bearings
        .iter()
        .map(|b| match &b.spec {
            BearingSpec::Linear(l) => l.stiffness,
            BearingSpec::Roller { .. } => panic!("linear bearings only here"),
        })
        .collect();
    model.linearised(0.0, &kb, &vec![[[0.0; 2]; 2]; n]).0
}

/// Euler–Bernoulli bending frequency ω = (βL)² √(EI / (ρ A L⁴)).
fn euler_bernoulli(beta_l: f64, length: f64, diameter: f64) -> f64 {
    let a = std::f64::consts::PI * diameter * diameter / 4.0;
    let i = std::f64::consts::PI * diameter.powi(4) / 64.0;
    beta_l * beta_l * (STEEL.youngs_modulus * i / (STEEL.density * a * length.powi(4))).sqrt()
}

/// Reference: free–free Euler–Bernoulli beam, cos βL cosh βL = 1, βL = 4.730041, 7.853205,
/// 10.995608 (Blevins, *Formulas for Natural Frequency and Mode Shape*, Table 8-1). Slender
/// (L/d = 100) so shear and rotary inertia shift the Timoshenko result by < 0.1 %.
#[test]
fn free_free_shaft_matches_euler_bernoulli() {
    let (l, d) = (2.0, 0.02);
    let model = uniform(l, d, 40, vec![]);
    let (freqs, _) = undamped_modes(&model.mass, &model.stiffness).unwrap();
    // Four rigid-body modes (2 translations, 2 tilts), then pairs of equal x / y bending modes.
    assert!(
        freqs[..4].iter().all(|&w| w < 1e-3 * freqs[4]),
        "{:?}",
        &freqs[..6]
    );
    for (k, beta_l) in [4.730_040_7, 7.853_204_6, 10.995_607_8].iter().enumerate() {
        let exact = euler_bernoulli(*beta_l, l, d);
        for w in &freqs[4 + 2 * k..6 + 2 * k] {
            let err = (w - exact).abs() / exact;
            assert!(err < 0.005, "mode {k}: {w} vs {exact} rad/s ({err:e})");
        }
    }
}

/// Reference: simply supported Euler–Bernoulli beam, βL = nπ (Blevins Table 8-1). The supports
/// are 10¹² N/m springs on x and y (rotations free) at both ends.
#[test]
fn simply_supported_shaft_matches_euler_bernoulli() {
    let (l, d) = (1.0, 0.01);
    let pin = |node| BearingSite {
        node,
        spec: BearingSpec::Linear(LinearBearing::isotropic(1e12, 0.0)),
    };
    let model = uniform(l, d, 30, vec![pin(0), pin(30)]);
    let (freqs, _) = undamped_modes(&model.mass, &stiff(&model)).unwrap();
    for n in 1..=3 {
        let exact = euler_bernoulli(n as f64 * std::f64::consts::PI, l, d);
        for w in &freqs[2 * (n - 1)..2 * n] {
            let err = (w - exact).abs() / exact;
            assert!(err < 0.005, "mode {n}: {w} vs {exact} rad/s ({err:e})");
        }
    }
}

/// The Friswell et al. (2010) Example 5.9.1 rotor: 1.5 m, Ø50 mm shaft in 6 equal elements,
/// disks (Ø0.28 m and Ø0.35 m, 70 mm thick, 50 mm bore) at 0.5 m and 1.0 m (nodes 2 and 4,
/// counting the left end as node 0), isotropic 1 MN/m bearings at both ends, undamped.
pub fn friswell_5_9_1() -> RotorModel {
    let bearing = |node| BearingSite {
        node,
        spec: BearingSpec::Linear(LinearBearing::isotropic(1e6, 0.0)),
    };
    let mut model = uniform(1.5, 0.05, 6, vec![bearing(0), bearing(6)]);
    model.description.disks = vec![
        RigidDisk::annulus(2, STEEL.density, 0.28, 0.05, 0.07),
        RigidDisk::annulus(4, STEEL.density, 0.35, 0.05, 0.07),
    ];
    RotorModel::assemble(model.description)
}

/// Reference: Friswell et al. (2010) Example 5.9.1, published lateral natural frequencies
/// 86.66, 86.66, 274.31, 274.31, 716.78 rad/s at rest and 85.39, 87.80, 251.78, 294.71,
/// 600.18 rad/s at 4000 rpm (backward/forward pairs), each to 0.5 %.
#[test]
fn friswell_example_5_9_1_frequencies() {
    let model = friswell_5_9_1();
    let k = stiff(&model);
    for (rpm, published) in [
        (0.0, [86.66, 86.66, 274.31, 274.31, 716.78]),
        (4000.0, [85.39, 87.80, 251.78, 294.71, 600.18]),
    ] {
        let omega = rpm * std::f64::consts::PI / 30.0;
        let d = &model.gyroscopic * omega;
        let modes = damped_modes(&model.mass, &k, &d, 6, true).unwrap();
        for (m, p) in modes.iter().zip(published) {
            let err = (m.frequency - p).abs() / p;
            eprintln!(
                "{rpm} rpm: {:.3} rad/s vs published {p} ({:+.3} %)",
                m.frequency,
                100.0 * (m.frequency - p) / p
            );
            assert!(
                err < 0.005,
                "{rpm} rpm: {} vs {p} rad/s ({err:e})",
                m.frequency
            );
        }
        if rpm > 0.0 {
            // Gyroscopic stiffening: the upper mode of each split pair whirls forward.
            assert_eq!(modes[0].whirl, Whirl::Backward);
            assert_eq!(modes[1].whirl, Whirl::Forward);
            assert_eq!(modes[2].whirl, Whirl::Backward);
            assert_eq!(modes[3].whirl, Whirl::Forward);
        }
    }
}
