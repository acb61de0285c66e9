//! Statics, loads, reduction and the time-response driver against closed forms and the full
//! model.

use nalgebra::DVector;

use super::modes_tests::friswell_5_9_1;
use crate::analysis::operating::build_bearings;
use crate::analysis::reduction::{craig_bampton, frequency_error};
use crate::analysis::statics::equilibrium;
use crate::bearing::{BearingSpec, LinearBearing};
use crate::model::damping::ProportionalDamping;
use crate::model::element::{Material, TimoshenkoElement};
use crate::model::loads::{GearMesh, Load, LoadSet};
use crate::model::motor::Pmsm;
use crate::model::{BearingSite, RotorDescription, RotorModel};

const STEEL: Material = Material {
    youngs_modulus: 210e9,
    shear_modulus: 80.8e9,
    density: 7850.0,
};

/// Reference: simply supported Timoshenko beam under its own weight w = ρAg, midspan deflection
/// 5wL⁴/(384EI) + wL²/(8κGA) (Timoshenko & Gere, *Mechanics of Materials*; shear term from
/// Timoshenko, *Strength of Materials* I §39), supports 10¹² N/m.
#[test]
fn gravity_sag_of_simply_supported_shaft() {
    let (l, d, n_el) = (0.8, 0.03, 16);
    let pin = |node| BearingSite {
        node,
        spec: BearingSpec::Linear(LinearBearing::isotropic(1e12, 0.0)),
    };
    let model = RotorModel::assemble(RotorDescription {
        node_positions: (0..=n_el).map(|i| l * i as f64 / n_el as f64).collect(),
        element_diameters: vec![(d, 0.0); n_el],
        material: STEEL,
        disks: vec![],
        bearings: vec![pin(0), pin(n_el)],
        damping: ProportionalDamping::default(),
        loads: LoadSet {
            loads: vec![Load::Gravity { acceleration: 9.81 }],
            motor: None,
        },
    });
    let mut b = build_bearings(&model).unwrap();
    let eq = equilibrium(&model, 0.0, &mut b).unwrap();
    let el = TimoshenkoElement {
        length: l,
        outer_diameter: d,
        inner_diameter: 0.0,
        material: STEEL,
    };
    let w = STEEL.density * el.area() * 9.81;
    let exact = 5.0 * w * l.powi(4) / (384.0 * STEEL.youngs_modulus * el.second_moment())
        + w * l * l / (8.0 * el.shear_coefficient() * STEEL.shear_modulus * el.area());
    let mid = -eq.q[4 * (n_el / 2) + 1];
    assert!((mid - exact).abs() / exact < 1e-3, "{mid} vs {exact} m");
    // Reactions carry the weight.
    let total: f64 = eq.reactions.iter().map(|r| r.force[1]).sum();
    assert!((total - w * l).abs() / (w * l) < 1e-9);
}

/// Reference: PMSM field-weakening curve (constant torque to P/T, constant power above) and spur
/// gear forces F_t = T/r_p, F_r = F_t tan α for the docs/physics.md §6.2 drive (68 N·m, 54 kW,
/// 21 000 rpm; 17 teeth, module 4 mm, 20°): base speed 7583.26 rpm, 24.555 N·m at 21 000 rpm.
#[test]
fn motor_curve_and_gear_forces() {
    let motor = Pmsm {
        peak_torque: 68.0,
        max_power: 54_000.0,
        max_speed: 21_000.0 * std::f64::consts::PI / 30.0,
        load_fraction: 1.0,
        ripple_fraction: 0.0,
        ripple_order: 17.0,
    };
    let rpm = |w: f64| w * 30.0 / std::f64::consts::PI;
    assert!((rpm(motor.base_speed()) - 7583.26).abs() < 0.01);
    assert_eq!(motor.mean_torque(500.0).unwrap(), 68.0);
    let t_max = motor.mean_torque(motor.max_speed).unwrap();
    assert!((t_max - 24.555).abs() < 1e-3, "{t_max}");
    assert!(motor.mean_torque(motor.max_speed * 1.01).is_err());
    let mesh = GearMesh {
        node: 0,
        teeth: 17,
        module: 0.004,
        pressure_angle: 20f64.to_radians(),
        mesh_angle: 0.0,
        force_fluctuation: 0.0,
    };
    // Gear at +x: radial force on the pinion along −x, tangential along −y (opposes +Ω).
    let f = mesh.force(68.0, 0.0);
    let ft = 68.0 / 0.034;
    assert!((f[1] + ft).abs() < 1e-9 && (f[0] + ft * 20f64.to_radians().tan()).abs() < 1e-9);
}

/// Reference: the full model. Craig–Bampton keeping the bearing nodes and 8 fixed-interface
/// modes reproduces the first four undamped frequencies of the Friswell rotor within 0.1 %.
#[test]
fn craig_bampton_frequencies_close_to_full_model() {
    let model = friswell_5_9_1();
    let red = craig_bampton(&model, &[0, 6], 8).unwrap();
    assert_eq!(red.mass.nrows(), 16);
    let kb = [[[1e6, 0.0], [0.0, 1e6]]; 2];
    let errors = frequency_error(&model, &red, &kb, 4).unwrap();
    for (w, e) in &errors {
        assert!(e.abs() < 1e-3, "{w} rad/s: {e:e}");
        // Reduction can only stiffen (Rayleigh–Ritz).
        assert!(*e > -1e-12);
    }
    let _ = DVector::<f64>::zeros(1);
}
