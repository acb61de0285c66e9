//! The static equilibrium beyond small displacements: a soft support that sags by millimetres
//! (closed form), and a rotor with no bearing (refused by name).

use crate::analysis::operating::{build_bearings, operating_modes, OperatingError};
use crate::analysis::statics::{equilibrium, StaticError};
use crate::bearing::{BearingSpec, LinearBearing};
use crate::model::damping::ProportionalDamping;
use crate::model::element::{Material, TimoshenkoElement};
use crate::model::loads::{Load, LoadSet};
use crate::model::{BearingSite, RotorDescription, RotorModel};

const STEEL: Material = Material {
    youngs_modulus: 210e9,
    shear_modulus: 80.8e9,
    density: 7850.0,
};

/// A 0.8 m, Ø30 mm shaft under its own weight on two linear supports of stiffness `k`.
fn shaft_on_springs(k: Option<f64>) -> RotorModel {
    let (l, d, n_el) = (0.8, 0.03, 16);
    let support = |node| BearingSite {
        node,
        spec: BearingSpec::Linear(LinearBearing::isotropic(k.unwrap_or(1.0), 0.0)),
    };
    RotorModel::assemble(RotorDescription {
        node_positions: (0..=n_el).map(|i| l * i as f64 / n_el as f64).collect(),
        element_diameters: vec![(d, 0.0); n_el],
        material: STEEL,
        disks: vec![],
        bearings: if k.is_some() {
            vec![support(0), support(n_el)]
        } else {
            vec![]
        },
        damping: ProportionalDamping::default(),
        loads: LoadSet {
            loads: vec![Load::Gravity { acceleration: 9.81 }],
            motor: None,
        },
    })
}

/// Reference: the supports carry half the weight wL/2 each and sag by wL/(2k) = 1.45 mm, on top
/// of the simply supported Timoshenko beam's 5wL⁴/(384EI) + wL²/(8κGA) at midspan (Timoshenko
/// & Gere, *Mechanics of Materials*; Timoshenko, *Strength of Materials* I §39). A linear
/// problem: Newton lands in one full step, however large the sag.
#[test]
fn millimetre_sag_on_soft_linear_supports() {
    let k = 1.5e4;
    let (l, n_el) = (0.8, 16);
    let model = shaft_on_springs(Some(k));
    let mut b = build_bearings(&model).unwrap();
    let eq = equilibrium(&model, 0.0, &mut b).unwrap();
    let el = TimoshenkoElement {
        length: l,
        outer_diameter: 0.03,
        inner_diameter: 0.0,
        material: STEEL,
    };
    let w = STEEL.density * el.area() * 9.81;
    let support_sag = w * l / (2.0 * k);
    assert!(support_sag > 1.4e-3, "{support_sag}");
    let beam = 5.0 * w * l.powi(4) / (384.0 * STEEL.youngs_modulus * el.second_moment())
        + w * l * l / (8.0 * el.shear_coefficient() * STEEL.shear_modulus * el.area());
    let end = -eq.q[1];
    let mid = -eq.q[4 * (n_el / 2) + 1];
    assert!(
        (end - support_sag).abs() / support_sag < 1e-6,
        "{end} vs {support_sag} m"
    );
    assert!(
        (mid - support_sag - beam).abs() / (support_sag + beam) < 1e-4,
        "{mid} m"
    );
    assert!(eq.iterations <= 2, "{} iterations", eq.iterations);
}

/// A rotor without bearings is a free body: refused by name, not by a residual.
#[test]
fn rotor_without_bearings_is_refused() {
    let model = shaft_on_springs(None);
    let mut b = build_bearings(&model).unwrap();
    let e = equilibrium(&model, 0.0, &mut b).unwrap_err();
    assert_eq!(e, StaticError::NoBearing);
    assert!(
        e.to_string().contains("no bearing supports the rotor"),
        "{e}"
    );
    let e = operating_modes(&model, 0.0, 4, false).unwrap_err();
    assert!(
        matches!(e, OperatingError::Static(StaticError::NoBearing)),
        "{e}"
    );
}
