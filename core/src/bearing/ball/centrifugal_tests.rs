//! The ball bearing with its balls' centrifugal force: force balance, the split of the contact
//! angles with speed (Harris & Kotzalas vol. 2, ch. 3; Jones 1960), the stiffness against
//! finite differences, the films at each contact's own load (Hamrock–Dowson in f64), and the
//! centrifugal-free limit at rest.

extern crate std;

use super::*;
use std::println;

fn bearing<const Z: usize>(
    design: BallBearingDesign,
    film: BallFilm,
    centrifugal: bool,
) -> BallBearing<Z> {
    let d = BallBearingDesign {
        centrifugal,
        ..design
    };
    BallBearing::<Z>::new(d.params().unwrap_or_else(|e| std::panic!("{e}")), film)
        .unwrap_or_else(|e| std::panic!("{e}"))
}

fn eval<const Z: usize>(b: &BallBearing<Z>, u: [f32; 5], rpm: f32) -> BallBearingOutput<Z> {
    b.evaluate(&BallBearingState::at(
        u,
        rpm * core::f32::consts::TAU / 60.0,
    ))
    .unwrap_or_else(|e| std::panic!("{e}"))
}

/// Under axial preload the inner contact angle rises and the outer one falls with speed, the
/// outer load exceeds the inner, and each ball balances F_c = ½ m d_m ω_c².
#[test]
fn contact_angles_split_with_speed() {
    for film in [BallFilm::Dry, BallFilm::HamrockDowson] {
        let b = bearing::<14>(BallBearingDesign::ANGULAR_7205, film, true);
        let p = *b.params();
        let mut last = (0.0_f32, core::f32::consts::FRAC_PI_2);
        for rpm in [0.0_f32, 3_000.0, 10_000.0, 20_000.0, 30_000.0] {
            let out = eval(&b, [0.0, 0.0, 15.0e-6, 0.0, 0.0], rpm);
            let ball = out.balls[3];
            let [ai, ao] = ball.contact_angle_rad;
            let [qi, qo] = ball.load_n;
            let fc = 0.5 * p.ball_mass_kg() * p.pitch_diameter_m() * out.cage_speed_rad_s.powi(2);
            let axial = qi * ai.sin() - qo * ao.sin();
            let radial = qi * ai.cos() - qo * ao.cos() + fc;
            println!(
                "{film:?} {rpm} rpm: α_i {:.3}°, α_o {:.3}°, Q_i {qi:.2} N, Q_o {qo:.2} N, \
                 F_c {fc:.2} N, residual {axial:.1e} {radial:.1e} N",
                ai.to_degrees(),
                ao.to_degrees()
            );
            assert!(axial.abs() < 1e-5 * qo && radial.abs() < 1e-5 * qo);
            if rpm > 0.0 {
                assert!(ai > last.0 && ao < last.1 && qo > qi, "{rpm}: {ai} {ao}");
            }
            last = (ai, ao);
            // Equal ball loads under pure axial load.
            for other in &out.balls {
                assert!((other.load_n[0] / qi - 1.0).abs() < 1e-4);
            }
        }
    }
}

/// At rest the centrifugal solve gives the centrifugal-free solution (its start, kept by the
/// Newton steps), both bearings, combined displacement.
#[test]
fn at_rest_equals_the_model_without_centrifugal_force() {
    fn check<const Z: usize>(design: BallBearingDesign, u: [f32; 5]) {
        let on = eval(&bearing::<Z>(design, BallFilm::Dry, true), u, 0.0);
        let off = eval(&bearing::<Z>(design, BallFilm::Dry, false), u, 0.0);
        let scale = off
            .applied_load()
            .iter()
            .fold(0.0_f32, |m, v| m.max(v.abs()));
        for (a, b) in on.applied_load().iter().zip(off.applied_load()) {
            assert!((a - b).abs() < 1e-4 * scale, "{a} {b}");
        }
        for (a, b) in on.balls.iter().zip(&off.balls) {
            assert!((a.load_n[0] - b.load_n[0]).abs() < 1e-4 * b.load_n[0] + 1e-3);
            assert!((a.load_n[1] - b.load_n[1]).abs() < 1e-4 * b.load_n[1] + 1e-3);
        }
    }
    check::<9>(
        BallBearingDesign::DEEP_GROOVE_6205,
        [3.0e-6, -14.0e-6, 4.0e-6, 2.0e-4, -1.0e-4],
    );
    check::<14>(
        BallBearingDesign::ANGULAR_7205,
        [2.0e-6, -5.0e-6, 12.0e-6, 1.0e-4, 2.0e-4],
    );
}

/// The condensed stiffness against central differences at 15 000 rpm, dry and lubricated.
#[test]
fn stiffness_matches_finite_differences_at_speed() {
    fn check<const Z: usize>(b: &BallBearing<Z>, u: [f32; 5]) -> f32 {
        let k = eval(b, u, 15_000.0).stiffness;
        let steps = [1.6e-7_f32, 1.6e-7, 1.6e-7, 8.0e-6, 8.0e-6];
        let mut worst = 0.0_f32;
        for (j, h) in steps.iter().enumerate() {
            let (mut up, mut down) = (u, u);
            up[j] += h;
            down[j] -= h;
            let (fu, fd) = (
                eval(b, up, 15_000.0).applied_load(),
                eval(b, down, 15_000.0).applied_load(),
            );
            for i in 0..5 {
                let fdiff = (fu[i] - fd[i]) / (2.0 * h);
                let scale = (k[i][i] * k[j][j]).abs().sqrt();
                worst = worst.max((k[i][j] - fdiff).abs() / scale);
            }
        }
        worst
    }
    for film in [BallFilm::Dry, BallFilm::HamrockDowson] {
        let dg = check(
            &bearing::<9>(BallBearingDesign::DEEP_GROOVE_6205, film, true),
            [8.0e-6, -5.0e-6, 30.0e-6, 2.0e-4, -1.0e-4],
        );
        let ac = check(
            &bearing::<14>(BallBearingDesign::ANGULAR_7205, film, true),
            [6.0e-6, 4.0e-6, 25.0e-6, -1.5e-4, 1.0e-4],
        );
        println!("{film:?}, centrifugal, 15 000 rpm: worst scaled stiffness error {dg:.2e} (6205), {ac:.2e} (7205)");
        assert!(dg < 3.0e-3 && ac < 3.0e-3, "{dg} {ac}");
    }
}

/// Each contact's film is Hamrock–Dowson's at that contact's own load, angle and pure-rolling
/// entrainment speed (f64 formula; Hamrock & Dowson 1981), with the exact ellipticity.
#[test]
fn films_at_each_contacts_own_load() {
    let b = bearing::<14>(
        BallBearingDesign::ANGULAR_7205,
        BallFilm::HamrockDowson,
        true,
    );
    let p = *b.params();
    let rpm = 20_000.0_f32;
    let out = eval(&b, [0.0, 0.0, 15.0e-6, 0.0, 0.0], rpm);
    let ball = out.balls[0];
    let omega = rpm as f64 * core::f64::consts::TAU / 60.0;
    let (d, dm) = (p.ball_diameter_m() as f64, p.pitch_diameter_m() as f64);
    let e = 208.0e9_f64 / (1.0 - 0.09);
    let wc = out.cage_speed_rad_s as f64;
    for c in 0..2 {
        let alpha = ball.contact_angle_rad[c] as f64;
        let sign = if c == 0 { -1.0 } else { 1.0 };
        let gamma = d * alpha.cos() / dm;
        let rx = 0.5 * d * (1.0 + sign * gamma);
        let f = if c == 0 { 0.52 } else { 0.53 };
        let ry = f * d / (2.0 * f - 1.0);
        let race = if c == 0 { omega } else { 0.0 };
        let u = (race - wc).abs() * 0.5 * (dm + sign * d * alpha.cos());
        let k = super::tests::ellipticity_reference(rx, ry);
        let w = ball.load_n[c] as f64 / (e * rx * rx);
        let uu = 0.08 * u / (e * rx);
        let hc = rx
            * 2.69
            * uu.powf(0.67)
            * (2.1e-8 * e).powf(0.53)
            * w.powf(-0.067)
            * (1.0 - 0.61 * (-0.73 * k).exp());
        let got = ball.central_film_m[c] as f64;
        println!(
            "contact {c}: Q {:.1} N, α {:.2}°, h_c {:.4} µm (f64 {:.4} µm)",
            ball.load_n[c],
            alpha.to_degrees(),
            got * 1e6,
            hc * 1e6
        );
        assert!((got / hc - 1.0).abs() < 2.0e-3, "{got} {hc}");
    }
    assert!(ball.load_n[1] > ball.load_n[0]);
}
