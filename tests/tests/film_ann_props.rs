//! Property tests of the core film networks' totality: whatever the input — any f32 bit
//! pattern, NaN, ±∞, zero, negative, absurd magnitudes — `AnnF32` and `AnnInt` return a
//! finite, non-negative film, and anything outside the training domain is flagged
//! `Fallback` and served by the regression formulas (checked against an independent
//! evaluation of Dowson–Toyoda / Dowson–Higginson with `powf`, docs/physics.md §5.1).

use bearing_core::film::ann::{AnnF32, AnnInt};
use bearing_core::film::{ContactInput, Film, FilmModel, FilmSource};
use proptest::prelude::*;

fn contact(v: [f32; 7]) -> ContactInput {
    ContactInput {
        load_n: v[0],
        entrainment_speed_m_s: v[1],
        reduced_radius_m: v[2],
        reduced_modulus_pa: v[3],
        pressure_viscosity_pa_inv: v[4],
        viscosity_pa_s: v[5],
        length_m: v[6],
    }
}

fn total(f: &Film) -> bool {
    f.central_m.is_finite() && f.minimum_m.is_finite() && f.central_m >= 0.0 && f.minimum_m >= 0.0
}

/// Dowson–Toyoda and Dowson–Higginson in f64 with powf (the independent reference).
fn regression(c: &ContactInput) -> (f64, f64) {
    let e = f64::from(c.reduced_modulus_pa);
    let r = f64::from(c.reduced_radius_m);
    let w = f64::from(c.load_n) / f64::from(c.length_m) / (e * r);
    let u = f64::from(c.viscosity_pa_s) * f64::from(c.entrainment_speed_m_s) / (e * r);
    let g = f64::from(c.pressure_viscosity_pa_inv) * e;
    // The fallback is the regression model's complete film: Dowson–Toyoda / Dowson–Higginson
    // blended root-sum-square with Martin's h₀/R = 4.896U/W (the central and minimum gap alike).
    (
        r * (3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10)).hypot(4.896 * u / w),
        r * (2.65 * g.powf(0.54) * u.powf(0.70) * w.powf(-0.13)).hypot(4.896 * u / w),
    )
}

fn hostile() -> impl Strategy<Value = f32> {
    prop_oneof![
        any::<u32>().prop_map(f32::from_bits),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0f32),
        Just(-0.0f32),
        Just(-1.0f32),
        Just(f32::MAX),
        Just(f32::MIN_POSITIVE),
        Just(1e-45f32),
    ]
}

/// A physically valid contact anywhere from far below to far above the training box.
fn wide_positive() -> impl Strategy<Value = [f32; 7]> {
    (
        -3.0f32..8.0,   // Q 1e-3 … 1e8 N
        -4.0f32..4.0,   // u_m
        -7.0f32..0.0,   // R
        9.0f32..13.0,   // E'
        -11.0f32..-6.0, // α
        -6.0f32..2.0,   // η₀
        -5.0f32..0.0,   // l
    )
        .prop_map(|(a, b, c, d, e, f, g)| [a, b, c, d, e, f, g].map(|x| 10f32.powf(x)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Any bit patterns: finite, non-negative; non-physical input is flagged Fallback.
    #[test]
    fn hostile_inputs_give_a_finite_non_negative_film(v in prop::array::uniform7(hostile())) {
        let c = contact(v);
        let physical = v.iter().all(|x| x.is_finite() && *x > 0.0);
        for f in [AnnF32.film(&c), AnnInt.film(&c)] {
            prop_assert!(total(&f), "{c:?} → {f:?}");
            if !physical {
                prop_assert_eq!(f.source, FilmSource::Fallback);
            }
        }
    }

    /// Valid contacts anywhere: finite, non-negative; outside the domain the film is the
    /// regression film (to 1e-4, f32 logarithms vs f64 powf), inside it the network's.
    #[test]
    fn valid_contacts_fall_back_to_the_regression_outside_the_domain(v in wide_positive()) {
        let c = contact(v);
        let (dt, dh) = regression(&c);
        for (f, net) in [(AnnF32.film(&c), FilmSource::NetworkF32), (AnnInt.film(&c), FilmSource::NetworkInt)] {
            prop_assert!(total(&f), "{c:?} → {f:?}");
            prop_assert!(f.source == FilmSource::Fallback || f.source == net);
            // Only compare where the reference is a normal f32 (the core clamps its exponent).
            if f.source == FilmSource::Fallback && dt > 1e-30 && dt < 1e30 && dh > 1e-30 && dh < 1e30 {
                prop_assert!((f64::from(f.central_m) / dt - 1.0).abs() < 1e-4, "{c:?}: {} vs {dt}", f.central_m);
                prop_assert!((f64::from(f.minimum_m) / dh - 1.0).abs() < 1e-4, "{c:?}: {} vs {dh}", f.minimum_m);
            }
        }
    }
}

/// Concrete edges of the guard: the §6.3 contact is inside (network), the same contact at
/// 0.1 m/s (below the 0.6 m/s floor) or with a 100 kN load is outside (fallback).
#[test]
fn guard_edges() {
    let inside = ContactInput {
        load_n: 850.0,
        entrainment_speed_m_s: 9.83,
        reduced_radius_m: 3.029e-3,
        reduced_modulus_pa: 239.6e9,
        pressure_viscosity_pa_inv: 2.1e-8,
        viscosity_pa_s: 0.08,
        length_m: 15e-3,
    };
    assert_eq!(AnnF32.film(&inside).source, FilmSource::NetworkF32);
    assert_eq!(AnnInt.film(&inside).source, FilmSource::NetworkInt);
    let slow = ContactInput {
        entrainment_speed_m_s: 0.1,
        ..inside
    };
    let heavy = ContactInput {
        load_n: 1e5,
        ..inside
    };
    for c in [slow, heavy] {
        assert_eq!(AnnF32.film(&c).source, FilmSource::Fallback);
        assert_eq!(AnnInt.film(&c).source, FilmSource::Fallback);
    }
}
