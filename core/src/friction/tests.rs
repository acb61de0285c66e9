//! The friction model against independent references: numerical quadrature of the Gaussian,
//! the limits of the Eyring traction table, and the regime thresholds.

use super::asperity::{f2, f5_2, LAMBDA_MAX};
use super::*;
use crate::bearing::BearingDesign;

/// F_n(λ) = ∫_λ^∞ (s − λ)ⁿ φ(s) ds by Simpson's rule in f64 on s − λ ∈ [0, 14].
fn gaussian_integral(n: f64, lambda: f64) -> f64 {
    let steps = 20_000;
    let h = 14.0 / steps as f64;
    let f = |t: f64| {
        let s = lambda + t;
        t.powf(n) * (-0.5 * s * s).exp() / (2.0 * core::f64::consts::PI).sqrt()
    };
    let mut sum = f(0.0) + f(14.0);
    for i in 1..steps {
        sum += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

#[test]
fn gt_integrals_match_quadrature() {
    // Closed forms at λ = 0: F₂(0) = 1/2, F₅/₂(0) = 2^{5/4}·Γ(7/4)/(2√π) = 0.616 634.
    assert!((gaussian_integral(2.0, 0.0) - 0.5).abs() < 1e-9);
    assert!((gaussian_integral(2.5, 0.0) - 0.616_634_2).abs() < 1e-6);
    let mut worst = [0.0f64; 2];
    for i in 0..120 {
        let lambda = i as f32 * 0.05;
        let exact = [
            gaussian_integral(2.0, f64::from(lambda)),
            gaussian_integral(2.5, f64::from(lambda)),
        ];
        let fit = [f2(lambda), f5_2(lambda)];
        for k in 0..2 {
            let err = (f64::from(fit[k]) / exact[k] - 1.0).abs();
            worst[k] = worst[k].max(err);
        }
    }
    assert!(
        worst[0] < 0.01 && worst[1] < 0.01,
        "worst relative errors {worst:?}"
    );
    // Beyond the fits' range there is no asperity contact.
    assert_eq!(f2(LAMBDA_MAX + 0.1), 0.0);
    assert_eq!(f5_2(100.0), 0.0);
    assert!(f5_2(LAMBDA_MAX - 0.01) < 1e-9);
}

fn nu205_inner(load_n: f32, shaft_speed_rad_s: f32) -> ContactInput {
    BearingDesign::NU205
        .params()
        .unwrap()
        .contact_input(false, load_n, shaft_speed_rad_s)
}

#[test]
fn lambda_and_regimes_follow_the_film() {
    let p = FrictionParams::DEFAULT;
    let input = nu205_inner(200.0, 1000.0);
    for (film, regime) in [
        (0.0, Lubrication::Boundary),
        (0.1e-6, Lubrication::Boundary),
        (0.2e-6, Lubrication::Mixed),
        (0.6e-6, Lubrication::FullFilm),
    ] {
        let c = p.contact(&input, film);
        assert!((c.lambda / (film / 0.15e-6) - 1.0).abs() < 1e-6 || film == 0.0);
        assert_eq!(c.lubrication(), regime, "h = {film}");
    }
    assert_eq!(Lubrication::of(f32::NAN), Lubrication::Boundary);
    // At λ = 0 the asperity load is Greenwood–Tripp's closed form with F₅/₂(0) = 0.616 634
    // over the Hertz area 2bl, b = √(8QR/(πlE′)).
    let d = FrictionDesign::DEFAULT;
    let (sigma, beta, density) = (
        f64::from(d.composite_roughness_m),
        f64::from(d.summit_radius_m),
        f64::from(d.asperity_density_m2),
    );
    let (q, r, l, e) = (
        f64::from(input.load_n),
        f64::from(input.reduced_radius_m),
        f64::from(input.length_m),
        f64::from(input.reduced_modulus_pa),
    );
    let area = 2.0 * (8.0 * q * r / (core::f64::consts::PI * l * e)).sqrt() * l;
    let nbs = density * beta * sigma;
    let expected = 8.0 * 2f64.sqrt() / 15.0
        * core::f64::consts::PI
        * nbs
        * nbs
        * (sigma / beta).sqrt()
        * e
        * area
        * 0.616_634;
    let dry = p.contact(&input, 0.0);
    assert!(
        (f64::from(dry.asperity_load_n) / expected - 1.0).abs() < 2e-3,
        "{dry:?} vs {expected}"
    );
    let expected_area = core::f64::consts::PI.powi(2) * nbs * nbs * area * 0.5;
    let boundary = f64::from(d.boundary_shear_strength_pa) * expected_area
        + f64::from(d.boundary_friction_coefficient) * expected;
    assert!((f64::from(dry.boundary_n) / boundary - 1.0).abs() < 3e-3);
    // The asperities' share falls as the film grows, to nothing in full film.
    let mixed = p.contact(&input, 0.2e-6);
    let full = p.contact(&input, 1.0e-6);
    assert!(dry.asperity_load_n > mixed.asperity_load_n);
    assert!(
        full.asperity_load_n < 1e-6 * dry.asperity_load_n,
        "{full:?}"
    );
}

/// Beyond the table's z the traction follows its limits: Newtonian below (T ∝ N), linear in
/// z above (the saturated limit asinh y → ln 2y); in between T rises with N, without a jump
/// at the table's ends, at every (ln M, ln L) cell of the table.
#[test]
fn isothermal_traction_table_meets_its_limits() {
    use super::traction_table::{LN_L, LN_M, L_NODES, M_NODES, Z, Z_NODES};
    let z_lo = Z.0 + Z.1;
    let z_hi = Z.0 + (Z_NODES - 2) as f32 * Z.1;
    for i in 1..M_NODES - 2 {
        for j in 1..L_NODES - 2 {
            let ln_m = LN_M.0 + LN_M.1 * (i as f32 + 0.3);
            let ln_l = LN_L.0 + LN_L.1 * (j as f32 + 0.6);
            let t = |z: f32| traction::mean_stress_ratio(ln_m, ln_l, z);
            // Newtonian: one unit of z below the table is a factor e.
            let newtonian = t(z_lo - 3.0) / t(z_lo - 2.0);
            assert!(
                (newtonian / (-1.0f32).exp() - 1.0).abs() < 1e-4,
                "({i}, {j}): {newtonian}"
            );
            // Saturated: equal steps of z above the table add equal stress.
            let (a, b, c) = (t(z_hi + 10.0), t(z_hi + 30.0), t(z_hi + 50.0));
            assert!(
                ((c - b) / (b - a) - 1.0).abs() < 1e-3,
                "({i}, {j}): {a} {b} {c}"
            );
            // Rising in z, by at most 12 % per 0.05 (e^{0.05} where Newtonian), and
            // continuous across both ends of the table.
            let mut previous = t(z_lo - 5.0);
            let steps = ((z_hi - z_lo + 10.0) / 0.05) as usize;
            for k in 1..=steps {
                let value = t(z_lo - 5.0 + 0.05 * k as f32);
                assert!(
                    value > previous && value < 1.12 * previous,
                    "({i}, {j}) step {k}: {value} after {previous}"
                );
                previous = value;
            }
        }
    }
}

/// The traction is l·b·τ₀·T at the contact's own Moes M and L and z = ln N + α·p_h, finite and
/// non-negative for any input.
#[test]
fn isothermal_traction_scales_with_the_contact() {
    let (tau, eta, alpha, u, s) = (5.0e6_f32, 0.01, 2.0e-8, 10.0, 0.02);
    let (q, l, r, e, h) = (2000.0_f32, 0.01, 0.005, 2.3e11, 0.3e-6);
    let w = q / l;
    let b = (8.0 * w * r / (core::f32::consts::PI * e)).sqrt();
    let p_h = (w * e / (2.0 * core::f32::consts::PI * r)).sqrt();
    let two_u = 2.0 * eta * u / (e * r);
    let ln_m = (w / (e * r)).ln() - 0.5 * two_u.ln();
    let ln_l = (alpha * e).ln() + 0.25 * two_u.ln();
    let z = (eta * s * u / (h * tau)).ln() + alpha * p_h;
    let expected = l * b * tau * traction::mean_stress_ratio(ln_m, ln_l, z);
    let eyring = traction::IsothermalEyring::new(tau, eta, alpha, u, s * u, r, e);
    let got = eyring.traction_n(q, l, b, p_h, h);
    assert!((got / expected - 1.0).abs() < 1e-4, "{got} {expected}");
    for bad in [0.0, -1.0, f32::NAN, f32::INFINITY, f32::MIN_POSITIVE, 1e30] {
        for v in [
            eyring.traction_n(bad, l, b, p_h, h),
            eyring.traction_n(q, l, b, p_h, bad),
            eyring.traction_n(q, l, b, bad, h),
            traction::mean_stress_ratio(bad, ln_l, z),
            traction::mean_stress_ratio(ln_m, ln_l, bad),
        ] {
            assert!(v.is_finite() && v >= 0.0, "{bad}: {v}");
        }
    }
}

/// The pressure zone is Hertz's for an elastohydrodynamic contact, the blend's rigid width
/// b_r = √(c·R·h/max(α·p_h, 1)) for a nearly rigid one, and stays finite as the load vanishes.
#[test]
fn pressure_zone_widens_only_at_light_load() {
    let (r, h) = (0.01_f32, 0.5e-6_f32);
    // EHL: b = 200 µm, α·p_h = 30: b_r² = 5·R·h/30 ≪ b², so b_eff = b (to f32).
    let ehl = traction::pressure_zone_widening(h, r, 200.0e-6, 30.0);
    assert!((ehl - 1.0).abs() < 1.0e-6, "{ehl}");
    // Rigid: b = 5 µm, α·p_h = 2: b_r = √(5·R·h/2) = 112 µm, and b_eff = (b⁸ + b_r⁸)^{1/8}.
    let b = 5.0e-6_f32;
    let rigid = traction::pressure_zone_widening(h, r, b, 2.0);
    let b_r = (traction::WIDENING_COEFFICIENT * r * h / 2.0).sqrt();
    let expected = (b.powi(8) + b_r.powi(8)).powf(0.125) / b;
    assert!(
        (rigid / expected - 1.0).abs() < 1.0e-5,
        "{rigid} {expected}"
    );
    // Light load (b = 1 µm, α·p_h → 0): b_eff tends to √(c·R·h), not to infinity.
    let tiny = 1.0e-6_f32;
    let width = tiny * traction::pressure_zone_widening(h, r, tiny, 1.0e-6);
    let limit = (traction::WIDENING_COEFFICIENT * r * h).sqrt();
    assert!((width / limit - 1.0).abs() < 1.0e-4, "{width} {limit}");
}

#[test]
fn thermal_traction_caps_the_isothermal_one_at_high_slide() {
    let input = nu205_inner(250.0, 1500.0);
    let film = 0.8e-6;
    let low = FrictionDesign {
        slide_to_roll_ratio: 0.001,
        ..FrictionDesign::DEFAULT
    }
    .params()
    .unwrap()
    .contact(&input, film);
    let high = FrictionDesign {
        slide_to_roll_ratio: 1.0,
        ..FrictionDesign::DEFAULT
    }
    .params()
    .unwrap()
    .contact(&input, film);
    // Traction rises with sliding but saturates (Eyring and shear heating): 1000× the slide
    // gives far less than 1000× the force, and a coefficient below the limiting ≈ 0.1.
    assert!(high.viscous_n > low.viscous_n);
    assert!(high.viscous_n < 100.0 * low.viscous_n, "{low:?} {high:?}");
    assert!(high.friction_coefficient() < 0.1, "{high:?}");
}

/// Evans & Johnson's bracket ln A in f64 (their large-A form) and A itself, for the thermal
/// stress of `traction::evans_johnson_stress_pa` at film `h` (m).
fn evans_johnson_bracket(
    t: &traction::Thermal,
    eta0: f64,
    alpha: f64,
    p: f64,
    h: f64,
) -> (f64, f64) {
    let (k, r, e, u) = (t.fluid_conductivity_w_mk as f64, 0.01, 2.3e11, 10.0);
    let xi = 4.0 / core::f64::consts::PI * k * r / h
        * (p / (e * r * t.solid_effusivity_sq as f64 * u)).sqrt();
    let root = (2.0 * k * eta0 / (t.viscosity_temperature_k_inv as f64 * (1.0 + 9.6 * xi))).sqrt();
    let a = (0.5 * alpha * p).exp() * 1.2 / (t.eyring_stress_pa as f64 * h) * root;
    (a.ln(), a)
}

#[test]
fn thermal_stress_follows_evans_johnson_and_stays_positive_where_its_logarithm_fails() {
    let t = traction::Thermal {
        eyring_stress_pa: 5.0e6,
        fluid_conductivity_w_mk: 0.14,
        viscosity_temperature_k_inv: 0.034,
        solid_effusivity_sq: 46.6 * 7830.0 * 475.0,
    };
    let stress = |eta0: f64, alpha: f64, p: f64, h: f64| {
        traction::evans_johnson_stress_pa(
            &t,
            eta0 as f32,
            alpha as f32,
            p as f32,
            h as f32,
            0.01,
            2.3e11,
            10.0,
        ) as f64
    };
    // An EHL contact (A ≫ 1): the paper's 1.74·τ₀·ln A, to 1 %.
    let (ln_a, a) = evans_johnson_bracket(&t, 0.05, 2.0e-8, 1.0e9, 0.3e-6);
    assert!(a > 100.0, "{a}");
    let paper = 1.74 * 5.0e6 * ln_a;
    let got = stress(0.05, 2.0e-8, 1.0e9, 0.3e-6);
    assert!((got / paper - 1.0).abs() < 0.01, "{got} vs {paper}");
    // A thick, lightly loaded film (A < 1, where ln A < 0): positive, and the
    // conduction-limited Newtonian stress 0.87·τ₀·A to 1 %.
    let (ln_a, a) = evans_johnson_bracket(&t, 0.01, 2.0e-8, 1.0e6, 20.0e-6);
    assert!(ln_a < 0.0, "{a}");
    let got = stress(0.01, 2.0e-8, 1.0e6, 20.0e-6);
    let limit = 0.87 * 5.0e6 * a;
    assert!(
        got > 0.0 && (got / limit - 1.0).abs() < 0.01,
        "{got} vs {limit}"
    );
}

#[test]
fn rolling_resistance_grows_with_speed_and_hardly_with_load() {
    let p = FrictionParams::DEFAULT;
    let slow = p.contact(&nu205_inner(250.0, 100.0), 0.1e-6).rolling_n;
    let fast = p.contact(&nu205_inner(250.0, 1500.0), 0.8e-6).rolling_n;
    let light = p.contact(&nu205_inner(25.0, 1500.0), 0.9e-6).rolling_n;
    assert!(fast > 3.0 * slow, "{slow} {fast}");
    // f_R ∝ W^0.013 isothermal: a tenth of the load, 3 % less (shear heating alters a(L)).
    assert!((light / fast - 1.0).abs() < 0.05, "{light} {fast}");
}
