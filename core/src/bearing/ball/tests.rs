//! The ball bearing against independent references: Hertz by quadrature, Stribeck's constant,
//! the closed-form pure-thrust relation, finite differences, symmetry and the film's fixed
//! point.

extern crate std;

use super::contact::RaceContact;
use super::*;
use std::vec::Vec;

const DEG: f32 = core::f32::consts::PI / 180.0;

fn deep_groove(film: BallFilm) -> BallBearing<9> {
    let p = BallBearingDesign::DEEP_GROOVE_6205.params();
    BallBearing::<9>::new(p.unwrap_or_else(|e| std::panic!("{e}")), film)
        .unwrap_or_else(|e| std::panic!("{e}"))
}

fn angular(film: BallFilm) -> BallBearing<14> {
    let p = BallBearingDesign::ANGULAR_7205.params();
    BallBearing::<14>::new(p.unwrap_or_else(|e| std::panic!("{e}")), film)
        .unwrap_or_else(|e| std::panic!("{e}"))
}

/// Complete elliptic integrals K(m), E(m) by 20 000-interval Simpson quadrature in f64, a
/// method independent of the core's arithmetic-geometric mean.
fn integrals_by_quadrature(m: f64) -> (f64, f64) {
    let n = 20_000;
    let h = core::f64::consts::FRAC_PI_2 / n as f64;
    let (mut k, mut e) = (0.0, 0.0);
    for i in 0..=n {
        let t = i as f64 * h;
        let w = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let s = 1.0 - m * t.sin().powi(2);
        k += w / s.sqrt();
        e += w * s.sqrt();
    }
    (k * h / 3.0, e * h / 3.0)
}

/// The exact ellipticity k of radii R_x, R_y (bisection on Johnson's eq. 4.39, f64).
pub(super) fn ellipticity_reference(rx: f64, ry: f64) -> f64 {
    let ratio = ry / rx;
    let (mut lo, mut hi) = (1.0_f64, 30.0_f64);
    for _ in 0..60 {
        let k = 0.5 * (lo + hi);
        let (kk, ee) = integrals_by_quadrature(1.0 - 1.0 / (k * k));
        if (k * k * ee - kk) / (kk - ee) < ratio {
            lo = k;
        } else {
            hi = k;
        }
    }
    0.5 * (lo + hi)
}

/// Hertz in f64: (compliance c of δ = c Q^⅔, a/Q^⅓, b/Q^⅓) for radii R_x, R_y and E', with
/// k solved by bisection on R_y/R_x = (k²E − K)/(K − E) (Johnson 1985, eq. 4.39).
fn hertz_reference(rx: f64, ry: f64, modulus: f64) -> (f64, f64, f64) {
    let k = ellipticity_reference(rx, ry);
    let (kk, ee) = integrals_by_quadrature(1.0 - 1.0 / (k * k));
    let r = 1.0 / (1.0 / rx + 1.0 / ry);
    let pi = core::f64::consts::PI;
    let c = kk * (9.0 / (2.0 * ee * r) / (pi * k * modulus).powi(2)).cbrt();
    let a = (6.0 * k * k * ee * r / (pi * modulus)).cbrt();
    let b = (6.0 * ee * r / (pi * k * modulus)).cbrt();
    (c, a, b)
}

/// The contacts' Hertz constants within 0.1 % of the exact solution, both races of both
/// bundled bearings, from 0° to 50° (R_y/R_x from 8 to 35).
#[test]
fn hertz_constants_match_the_exact_solution() {
    let mut worst = 0.0_f64;
    for bearing in [
        deep_groove(BallFilm::Dry).params,
        angular(BallFilm::Dry).params,
    ] {
        for angle in [0.0_f32, 15.0, 30.0, 40.0, 50.0] {
            for inner in [true, false] {
                let c = RaceContact::new(&bearing, (angle * DEG).cos(), inner);
                let (c_ref, a_ref, b_ref) = hertz_reference(
                    c.radius_x_m as f64,
                    c.radius_y_m as f64,
                    bearing.reduced_modulus_pa as f64,
                );
                for (got, want) in [
                    (c.compliance, c_ref),
                    (c.semi_axis_per_cbrt_load[0], a_ref),
                    (c.semi_axis_per_cbrt_load[1], b_ref),
                ] {
                    worst = worst.max((got as f64 / want - 1.0).abs());
                }
            }
        }
    }
    std::println!("Hertz constants: worst relative error {worst:.2e}");
    assert!(worst < 1.0e-3, "{worst}");
}

/// The 6205 inner contact: R_y/R_x ≈ 32 and k ≈ 9.3 (the conformity the bundled bearing has).
#[test]
fn deep_groove_inner_contact_is_elongated() {
    let b = deep_groove(BallFilm::Dry);
    let c = RaceContact::new(&b.params, 1.0, true);
    let ratio = c.radius_y_m / c.radius_x_m;
    let k = c.semi_axis_per_cbrt_load[0] / c.semi_axis_per_cbrt_load[1];
    assert!((31.0..34.0).contains(&ratio), "{ratio}");
    assert!((9.0..9.6).contains(&k), "{k}");
}

/// Stribeck: Z Q_max / F_r → 1/J_r(½) = 4.37 for zero clearance and many balls (Harris &
/// Kotzalas 2007, vol. 1, §7.4: J_r = 0.2288 for ε = ½).
#[test]
fn stribeck_constant_for_many_balls() {
    let design = BallBearingDesign {
        ball_count: 60,
        pitch_diameter_m: 160.0e-3,
        diametral_clearance_m: 0.0,
        ..BallBearingDesign::DEEP_GROOVE_6205
    };
    let p = design.params().unwrap_or_else(|e| std::panic!("{e}"));
    let b = BallBearing::<60>::new(p, BallFilm::Dry).unwrap_or_else(|e| std::panic!("{e}"));
    let mut load = BallLoad::translations([0.0, -2000.0, 0.0], 0.0);
    load.free = [true, true, false, false, false];
    let s = b.solve_static(&load).unwrap_or_else(|e| std::panic!("{e}"));
    let ratio = 60.0 * s.output.max_ball_load_n() / 2000.0;
    std::println!("Z Q_max / F_r = {ratio:.4}");
    assert!((ratio / 4.37 - 1.0).abs() < 3.0e-3, "{ratio}");
}

/// Pure thrust on an angular-contact bearing: F_a = Z K (B D)^{3/2} sin α (cos α₀/cos α − 1)^{3/2}
/// (Harris & Kotzalas 2007, vol. 1, eq. 7.55), K from the exact Hertz solution at α, and
/// every ball loaded alike.
#[test]
fn pure_thrust_matches_the_closed_form() {
    let b = angular(BallFilm::Dry);
    let p = b.params;
    for z in [2.0e-6_f32, 5.0e-6, 10.0e-6, 20.0e-6] {
        let out = b
            .evaluate(&BallBearingState::at([0.0, 0.0, z, 0.0, 0.0], 0.0))
            .unwrap_or_else(|e| std::panic!("{e}"));
        let alpha = out.balls[0].contact_angle_rad[0] as f64;
        let a0 = p.centre_distance_m as f64;
        let alpha0 = p.nominal_contact_angle_rad as f64;
        // α itself from the geometry: tan α = (A₀ sin α₀ + z)/(A₀ cos α₀).
        let alpha_geo = (a0 * alpha0.sin() + z as f64).atan2(a0 * alpha0.cos());
        assert!((alpha - alpha_geo).abs() < 2e-5, "{alpha} {alpha_geo}");
        let compliance = |inner| {
            let c = RaceContact::new(&p, alpha_geo.cos() as f32, inner);
            hertz_reference(
                c.radius_x_m as f64,
                c.radius_y_m as f64,
                p.reduced_modulus_pa as f64,
            )
            .0
        };
        let k = (compliance(true) + compliance(false)).powf(-1.5);
        let closed = 14.0
            * k
            * a0.powf(1.5)
            * alpha_geo.sin()
            * (alpha0.cos() / alpha_geo.cos() - 1.0).powf(1.5);
        let fa = -out.force_n[2] as f64;
        std::println!("z = {z:e} m: F_a = {fa:.2} N, closed form {closed:.2} N");
        assert!((fa / closed - 1.0).abs() < 1.0e-3, "{fa} {closed}");
        let loads: Vec<f32> = out.balls.iter().map(|b| b.load_n[0]).collect();
        let (lo, hi) = loads
            .iter()
            .fold((f32::MAX, 0.0_f32), |(l, h), &q| (l.min(q), h.max(q)));
        assert!(hi - lo <= 1e-4 * hi, "{loads:?}");
    }
}

/// Equal ball loads under a pure axial load solved for (z free) on the deep-groove bearing,
/// whose balls take up the clearance and climb the groove to the free contact angle and beyond.
#[test]
fn pure_axial_load_loads_every_ball_alike() {
    let b = deep_groove(BallFilm::NetworkInt);
    let mut load = BallLoad::translations([0.0, 0.0, 1000.0], 1047.0);
    load.free = [false, false, true, false, false];
    let s = b.solve_static(&load).unwrap_or_else(|e| std::panic!("{e}"));
    let q: Vec<f32> = s.output.balls.iter().map(|b| b.load_n[0]).collect();
    let (lo, hi) = q
        .iter()
        .fold((f32::MAX, 0.0_f32), |(l, h), &v| (l.min(v), h.max(v)));
    assert!(hi - lo <= 2e-4 * hi, "{q:?}");
    let angle = s.output.balls[0].contact_angle_rad[0] / DEG;
    assert!(angle > b.params.nominal_contact_angle_rad / DEG, "{angle}");
    // Σ Q sin α balances the load.
    let sum: f32 = s
        .output
        .balls
        .iter()
        .map(|b| b.load_n[0] * b.contact_angle_rad[0].sin())
        .sum();
    assert!((sum / 1000.0 - 1.0).abs() < 2e-4, "{sum}");
}

/// The analytic 5 × 5 stiffness against central differences of the applied load, dry and with
/// Hamrock–Dowson's film, both bearings, at combined radial, axial and tilt displacements.
#[test]
fn stiffness_matches_finite_differences() {
    fn check<const Z: usize>(b: &BallBearing<Z>, u: [f32; 5]) -> f64 {
        let omega = 1500.0;
        let at = |u: [f32; 5]| {
            b.evaluate(&BallBearingState::at(u, omega))
                .unwrap_or_else(|e| std::panic!("{e}"))
        };
        let k = at(u).stiffness;
        let mut worst = 0.0_f64;
        for j in 0..5 {
            let h = if j < 3 { 2.0e-8 } else { 2.0e-6 };
            let (mut up, mut down) = (u, u);
            up[j] += h;
            down[j] -= h;
            let (fu, fd) = (at(up).applied_load(), at(down).applied_load());
            for i in 0..5 {
                let fdiff = (fu[i] as f64 - fd[i] as f64) / (2.0 * h as f64);
                // Relative to the diagonal scale of row i and column j.
                let scale = ((k[i][i] as f64) * (k[j][j] as f64)).sqrt();
                worst = worst.max((k[i][j] as f64 - fdiff).abs() / scale);
            }
        }
        worst
    }
    let u_dg = [3.0e-6, -14.0e-6, 4.0e-6, 2.0e-4, -1.0e-4];
    let u_ac = [2.0e-6, -5.0e-6, 12.0e-6, 1.0e-4, 2.0e-4];
    for film in [BallFilm::Dry, BallFilm::HamrockDowson] {
        let w1 = check(&deep_groove(film), u_dg);
        let w2 = check(&angular(film), u_ac);
        std::println!("{film:?}: worst stiffness error {w1:.2e} (6205), {w2:.2e} (7205)");
        assert!(w1 < 1.0e-2 && w2 < 1.0e-2, "{w1} {w2}");
    }
}

/// Each loaded ball's load is the fixed point Q = ((δ_g + h_i(Q) + h_o(Q))/c)^{3/2} with the
/// films re-evaluated at the returned load, and the film raises the load at a given approach.
#[test]
fn film_coupling_reaches_its_fixed_point() {
    let b = deep_groove(BallFilm::HamrockDowson);
    let dry = deep_groove(BallFilm::Dry);
    let p = b.params;
    for omega in [300.0_f32, 1000.0, 2100.0] {
        let state = BallBearingState::at([0.0, -12.0e-6, 0.0, 0.0, 0.0], omega);
        let out = b.evaluate(&state).unwrap_or_else(|e| std::panic!("{e}"));
        let out_dry = dry.evaluate(&state).unwrap_or_else(|e| std::panic!("{e}"));
        for (ball, ball_dry) in out.balls.iter().zip(out_dry.balls.iter()) {
            let q = ball.load_n[0];
            if q < 1.0 {
                continue;
            }
            let cos_a = ball.contact_angle_rad[0].cos();
            let inner = RaceContact::new(&p, cos_a, true);
            let outer = RaceContact::new(&p, cos_a, false);
            let gamma = p.ball_diameter_m * cos_a / p.pitch_diameter_m;
            let u = 0.25 * p.pitch_diameter_m * omega * (1.0 - gamma * gamma);
            let h = HamrockDowson.film(&inner.film_input(&p, q, u)).central_m
                + HamrockDowson.film(&outer.film_input(&p, q, u)).central_m;
            let fixed =
                ((ball.geometric_approach_m + h) / (inner.compliance + outer.compliance)).powf(1.5);
            assert!((q / fixed - 1.0).abs() < 1.0e-4, "{q} {fixed} at {omega}");
            assert!(q > ball_dry.load_n[0], "film raises the load");
        }
    }
}

/// A NaN or out-of-range state is refused naming the field; the static solve refuses a load
/// the bearing cannot carry with the coordinates given free.
#[test]
fn refusals_name_the_field() {
    let b = deep_groove(BallFilm::NetworkInt);
    let mut state = BallBearingState::at([0.0; 5], 100.0);
    state.displacement[2] = f32::NAN;
    assert_eq!(b.evaluate(&state).err().map(|e| e.field), Some("z_m"));
    state.displacement[2] = 0.0;
    state.shaft_speed_rad_s = f32::INFINITY;
    assert_eq!(
        b.evaluate(&state).err().map(|e| e.field),
        Some("shaft_speed_rad_s")
    );
    // An angular-contact bearing carries thrust in +z only: pulled in −z it has no equilibrium.
    let a = angular(BallFilm::Dry);
    let r = a.solve_static(&BallLoad::translations([0.0, 0.0, -500.0], 0.0));
    assert!(
        matches!(r, Err(StaticSolveError::NotConverged { .. })),
        "{r:?}"
    );
}

/// Under a radial load along −y with the deep-groove clearance, the most loaded ball is the one
/// at −y, loads fall symmetrically about it, and the contact angles stay 0.
#[test]
fn radial_load_distribution_is_symmetric() {
    let b = deep_groove(BallFilm::NetworkInt);
    let mut load = BallLoad::translations([0.0, -1500.0, 0.0], 1047.0);
    load.free = [true, true, true, true, true];
    load.cage_angle_rad = -90.0 * DEG;
    let sol = b.solve_static(&load).unwrap_or_else(|e| std::panic!("{e}"));
    assert!(sol.displacement[2].abs() < 1e-9 && sol.displacement[3].abs() < 1e-7);
    let out = sol.output;
    let q: Vec<f32> = out.balls.iter().map(|b| b.load_n[0]).collect();
    assert!(
        q[0] >= q.iter().cloned().fold(0.0, f32::max) * 0.999,
        "{q:?}"
    );
    assert!((q[1] - q[8]).abs() <= 1e-3 * q[1] + 1e-3, "{q:?}");
    assert!(out
        .balls
        .iter()
        .all(|b| b.contact_angle_rad[0].abs() < 1e-3));
}
