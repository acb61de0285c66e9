//! Tests of what a step commits: trial evaluations commit nothing, real-time steps integrate
//! the cage angle for any run length.

use super::*;
use crate::bearing::BearingDesign;
use core::f32::consts::{PI, TAU};

/// The inner race on a 5 µm whirl orbit at ω, `t` seconds in.
fn whirl(t: f32, omega: f32) -> OperatingState {
    let (s, c) = libm::sincosf(omega * t);
    let r = 5.0e-6;
    OperatingState::new(
        [r * c, r * s],
        [-r * omega * s, r * omega * c],
        [0.0; 2],
        omega,
    )
    .unwrap()
}

/// After any number of trial evaluations (other displacements, speeds and time steps) the
/// next trial and the next real-time step give the same output, bit for bit, as without
/// them; the cage angle, warm start and film table are untouched. Every film model, after a
/// converged start and a few real-time steps (film table partly renewed), and on a fresh
/// bearing whose table is not filled yet.
#[test]
fn trial_evaluations_leave_the_next_result_unchanged() {
    let params = BearingDesign::HUB_MOTOR.params().unwrap();
    let (omega, dt) = (2199.0, 1.0e-4);
    for film in FilmKind::ALL {
        let fresh = Bearing::<17, 10>::new(params, film).unwrap();
        let mut stepped = fresh.clone();
        stepped.settle(&whirl(0.0, omega), SETTLE_STEPS).unwrap();
        for k in 1..=7 {
            stepped.advance(&whirl(k as f32 * dt, omega), dt).unwrap();
        }
        for start in [fresh, stepped] {
            let next = whirl(8.0 * dt, omega);
            let mut untouched = start.clone();
            let mut tried = start.clone();
            for n in 0..9 {
                let trial = OperatingState {
                    displacement_m: [n as f32 * 1.0e-6 - 4.0e-6, -3.0e-6],
                    shaft_speed_rad_s: omega * (0.5 + 0.2 * n as f32),
                    ..next
                };
                let out = *tried.evaluate(&trial, n as f32 * 0.3 * dt).unwrap();
                assert!(out.force_n.iter().all(|f| f.is_finite()));
            }
            assert_eq!(tried.cage_angle_rad(), untouched.cage_angle_rad());
            assert_eq!(tried.memory, untouched.memory);
            // (A table not filled yet is filled by every trial at the trial's speed, and by the
            // first committing step again.)
            if !start.table_stale {
                assert_eq!(tried.table, untouched.table);
            }
            let a = *tried.evaluate(&next, dt).unwrap();
            let b = *untouched.evaluate(&next, dt).unwrap();
            assert_eq!(a, b, "{film}: trial after trials");
            let a = *tried.advance(&next, dt).unwrap();
            let b = *untouched.advance(&next, dt).unwrap();
            assert_eq!(a, b, "{film}: step after trials");
            // The trials did run the step: a different displacement gives another force.
            assert_ne!(
                a.force_n,
                start
                    .clone()
                    .evaluate(&whirl(0.0, omega), dt)
                    .unwrap()
                    .force_n
            );
        }
    }
}

/// A trial at the committed state `dt` later sees the cage where the real-time step puts it.
#[test]
fn trial_and_step_turn_the_cage_alike() {
    let params = BearingDesign::NU205.params().unwrap();
    let mut b = Bearing::<12, 10>::new(params, FilmKind::Dry).unwrap();
    let s = whirl(0.0, 1500.0);
    let trial = *b.evaluate(&s, 2.0e-4).unwrap();
    let step = *b.advance(&s, 2.0e-4).unwrap();
    // Dry: no warm start or table, so the outputs agree exactly.
    assert_eq!(trial, step);
    // ω_c = (ω/2)(1 − D/d_m), docs/physics.md §2.
    let expected = 0.5 * 1500.0 * (1.0 - 7.5 / 39.0) * 2.0e-4;
    assert!((b.cage_angle_rad() - expected).abs() < 1e-6);
    let roller_0 = step.rollers[0].angle_rad;
    assert!((roller_0 - expected).abs() < 1e-6);
}

/// 10⁶ s of real-time steps (10⁶ steps of 1 s at 1000 rad/s: the cage turns 4·10⁸ rad) keep
/// the cage angle in [0, 2π) and every step computes; backwards, in (−2π, 2π). A state whose
/// cage angle the caller had integrated would have been refused past 10⁴ rad.
#[test]
fn a_million_second_run_keeps_a_valid_cage_angle() {
    let params = BearingDesign::NU205.params().unwrap();
    for (omega, range) in [(1000.0f32, (0.0, TAU)), (-1000.0, (-TAU, TAU))] {
        let mut b = Bearing::<12, 10>::new(params, FilmKind::Dry).unwrap();
        let s = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], omega).unwrap();
        let (mut low, mut high) = (f32::MAX, f32::MIN);
        for _ in 0..1_000_000 {
            let out = b.advance(&s, 1.0).unwrap();
            assert!(out.force_n[1] > 0.0);
            let angle = b.cage_angle_rad();
            assert!(angle >= range.0 && angle < range.1, "{angle}");
            low = low.min(angle);
            high = high.max(angle);
        }
        // The angle does sweep its range rather than stick.
        assert!(high - low > 5.0, "{omega}: {low} … {high}");
        for r in b.output().rollers.iter() {
            assert!(r.angle_rad > -PI && r.angle_rad <= PI, "{}", r.angle_rad);
        }
    }
}
