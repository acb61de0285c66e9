//! Sequences of hostile steps through every film model (integer and f32 networks, regression,
//! dry) of both bundled bearings, with the warm start, the cage angle and the film table carried
//! from step to step: random-bit states and time steps mixed with plausible ones, through
//! [`Bearing::advance`] and [`Bearing::evaluate`]. Nothing panics, every accepted step returns
//! finite outputs and non-negative films and loads, and after a sequence the bearing still
//! settles at a nominal state to finite outputs.
//!
//! The run is sized for CI: [`DEFAULT_STATES`] states in total from a fixed seed. A longer run
//! is one variable away: `HOSTILE_STATES=100000000 cargo test --release -p bearing-core --test
//! hostile_sequences` (and `HOSTILE_SEED=<u64>` for another sequence).

// A test: a panic here fails the test, it is not a path of the core (`clippy.toml` allows
// unwrap and indexing inside `#[test]` functions; these lints would otherwise reach the helpers).
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing
)]

use bearing_core::bearing::SETTLE_STEPS;
use bearing_core::{Bearing, BearingDesign, BearingOutput, FilmKind, OperatingState};
use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};

/// States stepped in total over the 8 models (2 bearings × 4 film models).
const DEFAULT_STATES: u64 = 1_000_000;
/// Steps per sequence (warm start carried) before the settle check.
const SEQUENCE_STEPS: usize = 64;
/// Slices per roller, as the host tools use (`bearing::SLICES` with the `alloc` feature).
const SLICES: usize = 10;

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Uniform in [lo, hi).
fn uniform(rng: &mut TestRng, lo: f32, hi: f32) -> f32 {
    lo + (hi - lo) * (rng.next_u32() >> 8) as f32 / (1u32 << 24) as f32
}

fn random_bits(rng: &mut TestRng) -> f32 {
    f32::from_bits(rng.next_u32())
}

/// A finite value at an edge of the f32 range.
fn extreme(rng: &mut TestRng) -> f32 {
    const EDGES: [f32; 8] = [
        f32::MAX,
        f32::MIN,
        f32::MIN_POSITIVE,
        -f32::MIN_POSITIVE,
        1.0e-45,
        -1.0e-45,
        0.0,
        -0.0,
    ];
    EDGES[(rng.next_u32() % 8) as usize]
}

/// A plausible state: displacements within ±30 µm, velocities ±0.1 m/s, tilts ±1 mrad,
/// 0 … 2500 rad/s (24 000 rpm), dt 10 µs … 1 ms.
fn plausible(rng: &mut TestRng) -> ([f32; 7], f32) {
    let mut v = [0.0f32; 7];
    for x in &mut v[0..2] {
        *x = uniform(rng, -30e-6, 30e-6);
    }
    for x in &mut v[2..4] {
        *x = uniform(rng, -0.1, 0.1);
    }
    for x in &mut v[4..6] {
        *x = uniform(rng, -1e-3, 1e-3);
    }
    v[6] = uniform(rng, 0.0, 2500.0);
    (v, uniform(rng, 1e-5, 1e-3))
}

/// One step's state and time step: half plausible, the rest with one field, every field or
/// the time step replaced by random bits or an f32 edge value.
fn hostile(rng: &mut TestRng) -> (OperatingState, f32) {
    let (mut v, mut dt) = plausible(rng);
    match rng.next_u32() % 8 {
        0..=3 => {}
        4 => v.iter_mut().for_each(|x| *x = random_bits(rng)),
        5 => v[(rng.next_u32() % 7) as usize] = random_bits(rng),
        6 => v[(rng.next_u32() % 7) as usize] = extreme(rng),
        _ => {
            dt = if rng.next_u32() % 2 == 0 {
                random_bits(rng)
            } else {
                extreme(rng)
            }
        }
    }
    let state = OperatingState {
        displacement_m: [v[0], v[1]],
        velocity_m_s: [v[2], v[3]],
        tilt_rad: [v[4], v[5]],
        shaft_speed_rad_s: v[6],
    };
    (state, dt)
}

fn check_output<const Z: usize>(out: &BearingOutput<Z>, what: &str) {
    let finite = out
        .force_n
        .iter()
        .chain(&out.moment_nm)
        .chain(out.stiffness.iter().flatten())
        .chain(out.damping_n_s_per_m.iter().flatten())
        .all(|x| x.is_finite());
    assert!(finite, "{what}: {out:?}");
    for r in &out.rollers {
        let films = [
            r.central_film_in_m,
            r.central_film_out_m,
            r.min_film_in_m,
            r.min_film_out_m,
            r.load_n,
        ];
        assert!(
            films.iter().all(|x| x.is_finite() && *x >= 0.0),
            "{what}: {r:?}"
        );
        assert!(
            [
                r.approach_m,
                r.damping_force_n,
                r.moment_nm,
                r.roller_stiffness_n_per_m
            ]
            .iter()
            .all(|x| x.is_finite()),
            "{what}: {r:?}"
        );
    }
}

/// Runs `states` hostile states through one model; returns the number of accepted steps.
fn run_model<const Z: usize>(
    design: BearingDesign,
    film: FilmKind,
    states: u64,
    rng: &mut TestRng,
) -> u64 {
    let params = design.params().unwrap();
    let nominal = OperatingState::new([1e-6, -4e-6], [0.0; 2], [0.0; 2], 1500.0).unwrap();
    let mut b = Bearing::<Z, SLICES>::new(params, film).unwrap();
    let fresh = {
        let mut f = b.clone();
        f.set_cage_angle(0.3).unwrap();
        *f.settle(&nominal, SETTLE_STEPS).unwrap()
    };
    let (mut done, mut accepted) = (0u64, 0u64);
    while done < states {
        for _ in 0..SEQUENCE_STEPS {
            let (state, dt) = hostile(rng);
            let what = format!("{film:?} Z={Z} at {state:?}, dt {dt:e}");
            let out = if rng.next_u32() % 4 == 0 {
                b.evaluate(&state, dt).ok().copied()
            } else {
                b.advance(&state, dt).ok().copied()
            };
            if let Some(out) = out {
                check_output(&out, &what);
                accepted += 1;
            }
            done += 1;
        }
        // After any sequence the bearing still settles at a nominal state to finite outputs.
        // (`settle` continues from the warm start the sequence left, so it need not give the
        // fresh bearing's output: see docs/reliability.md §1.)
        b.set_cage_angle(0.3).unwrap();
        check_output(b.settle(&nominal, SETTLE_STEPS).unwrap(), "settle");
        // `reset` leaves nothing of the sequence but the cage angle: settling then gives the
        // fresh bearing's output bit for bit.
        b.reset();
        b.set_cage_angle(0.3).unwrap();
        let settled = *b.settle(&nominal, SETTLE_STEPS).unwrap();
        assert!(
            settled == fresh,
            "{film:?} Z={Z}: reset + settle differs from a fresh bearing"
        );
    }
    accepted
}

#[test]
fn hostile_step_sequences_through_every_film_model() {
    let total = env_u64("HOSTILE_STATES", DEFAULT_STATES);
    let seed = env_u64("HOSTILE_SEED", 0x5eed_0b5e_55ed_u64);
    let mut seed_bytes = [0u8; 32];
    seed_bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &seed_bytes);
    let per_model = total.div_ceil(8);
    let started = std::time::Instant::now();
    let mut accepted = 0;
    for film in FilmKind::ALL {
        accepted += run_model::<17>(BearingDesign::HUB_MOTOR, film, per_model, &mut rng);
        accepted += run_model::<12>(BearingDesign::NU205, film, per_model, &mut rng);
    }
    println!(
        "{} hostile states over 8 models ({accepted} accepted) in {:.2} s",
        8 * per_model,
        started.elapsed().as_secs_f64()
    );
    // Half the states are plausible, so most must have been stepped, not refused.
    assert!(accepted > 8 * per_model / 3, "{accepted} accepted");
}
