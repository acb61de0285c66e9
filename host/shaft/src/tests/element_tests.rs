//! Element matrices against closed forms.

use crate::model::element::{Material, TimoshenkoElement};

const STEEL: Material = Material {
    youngs_modulus: 211e9,
    shear_modulus: 81.2e9,
    density: 7810.0,
};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Reference: Przemieniecki, *Theory of Matrix Structural Analysis* (1968) §5.6, Timoshenko beam
/// stiffness: k_ww = 12EI/((1+Φ)L³), k_wφ = 6EI/((1+Φ)L²), k_φφ = (4+Φ)EI/((1+Φ)L),
/// k_φ1φ2 = (2−Φ)EI/((1+Φ)L). A stubby element makes Φ large so shear matters.
#[test]
fn stiffness_matches_przemieniecki_closed_form() {
    let el = TimoshenkoElement {
        length: 0.05,
        outer_diameter: 0.06,
        inner_diameter: 0.02,
        material: STEEL,
    };
    let phi = el.shear_parameter();
    assert!(phi > 1.0, "test needs a shear-dominated element, Φ = {phi}");
    let (e, i, l) = (STEEL.youngs_modulus, el.second_moment(), el.length);
    let k = el.matrices().stiffness;
    let d = 1.0 + phi;
    // x–z plane: DOFs x1 = 0, θy1 = 3, x2 = 4, θy2 = 7 (θy = +dx/dz).
    assert!(rel(k[(0, 0)], 12.0 * e * i / (d * l.powi(3))) < 1e-12);
    assert!(rel(k[(0, 3)], 6.0 * e * i / (d * l * l)) < 1e-12);
    assert!(rel(k[(3, 3)], (4.0 + phi) * e * i / (d * l)) < 1e-12);
    assert!(rel(k[(3, 7)], (2.0 - phi) * e * i / (d * l)) < 1e-12);
    assert!(rel(k[(0, 4)], -12.0 * e * i / (d * l.powi(3))) < 1e-12);
    // y–z plane: θx = −dy/dz flips the sign of the displacement–rotation coupling.
    assert!(rel(k[(1, 2)], -6.0 * e * i / (d * l * l)) < 1e-12);
    assert!(rel(k[(2, 2)], (4.0 + phi) * e * i / (d * l)) < 1e-12);
    // Planes uncoupled.
    assert_eq!(k[(0, 1)], 0.0);
}

/// Reference: rigid-body kinematics. A rigid translation or rotation strains nothing, and its
/// kinetic energy is that of the rigid cylinder: translation ρAL, rotation about the element's
/// centre ρAL³/12 + ρIL; the gyroscopic coupling of a rigid tilt is ρ·I_p·L = 2ρIL.
#[test]
fn rigid_body_modes_are_strain_free_and_carry_the_rigid_inertia() {
    let el = TimoshenkoElement {
        length: 0.3,
        outer_diameter: 0.05,
        inner_diameter: 0.01,
        material: STEEL,
    };
    let mats = el.matrices();
    let (rho, a, i, l) = (STEEL.density, el.area(), el.second_moment(), el.length);
    // Translation along x.
    let tx = nalgebra::SVector::<f64, 8>::from_column_slice(&[1., 0., 0., 0., 1., 0., 0., 0.]);
    // Rigid tilt about y through the element centre: x = z − L/2, θy = 1.
    let ry = nalgebra::SVector::<f64, 8>::from_column_slice(&[
        -l / 2.0,
        0.,
        0.,
        1.,
        l / 2.0,
        0.,
        0.,
        1.,
    ]);
    // Rigid tilt about x: y = −(z − L/2), θx = 1.
    let rx = nalgebra::SVector::<f64, 8>::from_column_slice(&[
        0.,
        l / 2.0,
        1.,
        0.,
        0.,
        -l / 2.0,
        1.,
        0.,
    ]);
    for v in [&tx, &ry, &rx] {
        assert!((mats.stiffness * v).norm() < 1e-6 * mats.stiffness.norm());
    }
    assert!(rel((tx.transpose() * mats.mass * tx)[0], rho * a * l) < 1e-12);
    let rot = rho * a * l.powi(3) / 12.0 + rho * i * l;
    assert!(rel((ry.transpose() * mats.mass * ry)[0], rot) < 1e-12);
    assert!(rel((rx.transpose() * mats.mass * rx)[0], rot) < 1e-12);
    assert!(
        rel(
            (rx.transpose() * mats.gyroscopic * ry)[0],
            2.0 * rho * i * l
        ) < 1e-12
    );
    assert!((mats.gyroscopic + mats.gyroscopic.transpose()).norm() < 1e-15);
}

/// Reference: Cowper (1966) shear coefficient of a solid circle, 6(1+ν)/(7+6ν).
#[test]
fn solid_shear_coefficient_is_cowpers() {
    let el = TimoshenkoElement {
        length: 1.0,
        outer_diameter: 0.05,
        inner_diameter: 0.0,
        material: STEEL,
    };
    let nu = STEEL.poisson_ratio();
    assert!(rel(el.shear_coefficient(), 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu)) < 1e-14);
}
