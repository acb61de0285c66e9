//! Tests of the high-speed physics in the step: the rollers' centrifugal force (docs/physics.md
//! §4.1) and the film corrections (§5.4).

use super::*;
use crate::bearing::BearingDesign;
use crate::film::corrections::{FilmCorrections, Starvation, ThermalCorrection};

/// Hub-motor shaft speed of the tests: 21 000 rpm (rad/s).
const OMEGA: f32 = 2199.115;

fn straight_hub() -> BearingParams {
    BearingDesign {
        crown_scale: 0.0,
        ..BearingDesign::HUB_MOTOR
    }
    .params()
    .unwrap()
}

fn settled<const Z: usize>(
    params: BearingParams,
    film: FilmKind,
    y_m: f32,
) -> (Bearing<Z, 10>, BearingOutput<Z>) {
    let mut b = Bearing::<Z, 10>::new(params, film).unwrap();
    let state = OperatingState::new([0.0, y_m], [0.0; 2], [0.0; 2], OMEGA).unwrap();
    // Enough committing steps at one speed for the warm start to converge fully.
    let out = *b.settle(&state, 4 * SETTLE_STEPS).unwrap();
    (b, out)
}

/// The approach (m) at which the straight, untilted roller's slices carry `load_n` (both
/// contacts at that load), by bisection on the slices themselves.
fn slice_approach_m<const S: usize>(roller: &SlicedRoller<S>, load_n: f32) -> f32 {
    let (mut lo, mut hi) = (roller.touch_approach_m(), 1.0e-4);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if roller.evaluate(mid, 0.0).load_n < load_n {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// F_c = m·ω_c²·d_m/2 against the closed form in f64: a Ø8.8 × 15 mm steel roller on the
/// hub motor's 30 mm pitch radius at 21 000 rpm, cage at (ω/2)(1 − D/d_m): ≈ 189 N.
#[test]
fn centrifugal_force_is_the_closed_form() {
    let params = BearingDesign::HUB_MOTOR
        .params()
        .unwrap()
        .with_centrifugal_force(STEEL_DENSITY_KG_M3)
        .unwrap();
    let mass = 7850.0 * core::f64::consts::PI / 4.0 * 0.0088f64.powi(2) * 0.015;
    let omega = 21_000.0 * core::f64::consts::PI / 30.0;
    let cage = 0.5 * omega * (1.0 - 0.0088 / 0.060);
    let expected = mass * cage * cage * 0.030;
    let f_c = f64::from(params.centrifugal_force_n(omega as f32).unwrap());
    assert!((f_c / expected - 1.0).abs() < 1.0e-5, "{f_c} vs {expected}");
    assert!((180.0..200.0).contains(&f_c), "{f_c}");
    assert_eq!(
        BearingDesign::HUB_MOTOR
            .params()
            .unwrap()
            .centrifugal_force_n(2000.0),
        None
    );
    assert_eq!(
        params.with_centrifugal_force(0.0).unwrap_err().field,
        "roller_density_kg_m3"
    );
}

/// With the centrifugal force on, every roller's outer contact runs at Q_in + F_c: the step
/// reports F_c, each contact's central film is the film model's at its own load (Regression,
/// the table at one speed: the model at its nodes), and the elastic approach is the two
/// contacts' approaches in series, ½·[δ(Q_in) + δ(Q_out)] with δ the straight roller's slice
/// law found by bisection — loaded rollers and ones the film lifts off the inner race alike.
#[test]
fn outer_contacts_carry_the_centrifugal_force() {
    let params = straight_hub()
        .with_centrifugal_force(STEEL_DENSITY_KG_M3)
        .unwrap();
    let f_c = params.centrifugal_force_n(OMEGA).unwrap();
    let (bearing, out) = settled::<17>(params, FilmKind::Regression, -6.0e-6);
    assert_eq!(out.centrifugal_force_n, f_c);
    let mut checked = 0;
    for r in out.rollers.iter().filter(|r| r.load_n > 1.0) {
        let q_out = out.view().load_out_n(r);
        assert_eq!(q_out, r.load_n + f_c);
        let model = |outer: bool, q: f32| {
            Regression
                .film(&params.contact_input(outer, q, OMEGA))
                .central_m
        };
        let (h_in, h_out) = (model(false, r.load_n), model(true, q_out));
        assert!(
            (r.central_film_in_m / h_in - 1.0).abs() < 2.0e-3,
            "inner {} vs {h_in}",
            r.central_film_in_m
        );
        assert!(
            (r.central_film_out_m / h_out - 1.0).abs() < 2.0e-3,
            "outer {} vs {h_out}",
            r.central_film_out_m
        );
        let series = 0.5
            * (slice_approach_m(&bearing.roller, r.load_n)
                + slice_approach_m(&bearing.roller, q_out));
        assert!(
            (r.approach_m - series).abs() < 1.0e-3 * series.abs() + 1.0e-10,
            "approach {} vs {series}",
            r.approach_m
        );
        checked += 1;
    }
    assert!(checked >= 5, "{checked} loaded rollers");
}

/// The dry roller's centrifugal split: Q_in solves ½·[δ(Q_in) + δ(Q_in + F_c)] = δ_geo on the
/// slices (bisection), and a roller whose geometric approach F_c alone exceeds leaves the inner
/// race (Q_in = 0).
#[test]
fn dry_rollers_split_the_approach_between_their_contacts() {
    let params = straight_hub()
        .with_centrifugal_force(STEEL_DENSITY_KG_M3)
        .unwrap();
    let f_c = params.centrifugal_force_n(OMEGA).unwrap();
    let (bearing, out) = settled::<17>(params, FilmKind::Dry, -6.0e-6);
    let mut checked = 0;
    for r in out.rollers.iter() {
        let series = 0.5
            * (slice_approach_m(&bearing.roller, r.load_n.max(1.0e-3))
                + slice_approach_m(&bearing.roller, r.load_n + f_c));
        if r.load_n > 1.0 {
            assert!(
                (r.geometric_approach_m - series).abs() < 1.0e-3 * series,
                "{} vs {series}",
                r.geometric_approach_m
            );
            checked += 1;
        } else {
            assert!(r.geometric_approach_m < series + 1.0e-9, "{r:?}");
        }
    }
    assert!(checked >= 5, "{checked} loaded rollers");
    // The centrifugal force unloads the inner contacts of the dry bearing.
    let (_, plain) = settled::<17>(straight_hub(), FilmKind::Dry, -6.0e-6);
    assert!(out.max_roller_load_n() < plain.max_roller_load_n());
}

/// Switched off, the corrections and the centrifugal force leave the step as it is, bit for
/// bit: a bearing given `FilmCorrections::OFF` explicitly steps exactly as one built without,
/// and switching either on changes the films (the thermal factor thins them).
#[test]
fn switched_off_the_step_is_unchanged_and_on_it_changes() {
    let plain = BearingDesign::HUB_MOTOR.params().unwrap();
    let off = plain.with_film_corrections(FilmCorrections::OFF);
    for film in [FilmKind::Int, FilmKind::Regression] {
        let (_, a) = settled::<17>(plain, film, -5.0e-6);
        let (_, b) = settled::<17>(off, film, -5.0e-6);
        assert_eq!(a, b, "{film}");
        let thermal = FilmCorrections {
            thermal: Some(ThermalCorrection::new(0.034, 0.14).unwrap()),
            starvation: None,
        };
        let (_, hot) = settled::<17>(plain.with_film_corrections(thermal), film, -5.0e-6);
        let loaded = |o: &BearingOutput<17>| {
            o.rollers
                .iter()
                .max_by(|x, y| x.load_n.total_cmp(&y.load_n))
                .copied()
                .unwrap()
        };
        assert!(loaded(&hot).central_film_in_m < 0.99 * loaded(&a).central_film_in_m);
        let starved = FilmCorrections {
            thermal: None,
            starvation: Some(Starvation::new(0.2e-6, 2.0).unwrap()),
        };
        let (_, dry_inlet) = settled::<17>(plain.with_film_corrections(starved), film, -5.0e-6);
        assert!(loaded(&dry_inlet).central_film_in_m < 0.99 * loaded(&a).central_film_in_m);
    }
}

/// The host's SIMD lanes and the one-roller path agree bit for bit with the centrifugal force on
/// (the M4 takes the one-roller path): every roller solved alone through `prepare_roller`,
/// `iterate_centrifugal` and `finish_roller` from the same memories equals the lockstep step.
#[test]
fn centrifugal_lanes_match_one_roller_at_a_time() {
    let params = BearingDesign::HUB_MOTOR
        .params()
        .unwrap()
        .with_centrifugal_force(STEEL_DENSITY_KG_M3)
        .unwrap();
    let (mut bearing, _) = settled::<17>(params, FilmKind::Regression, -5.0e-6);
    let state = OperatingState::new([1.0e-6, -5.5e-6], [0.0; 2], [0.0; 2], OMEGA).unwrap();
    let memory = bearing.memory;
    let out = *bearing.evaluate(&state, 0.0).unwrap();
    let ctx = bearing.contact_contexts(OMEGA);
    let martin = [ctx[0].martin, ctx[1].martin];
    let templates = [ctx[0].template, ctx[1].template];
    let speed_scale = FilmTable::speed_scale(&templates);
    let films = bearing.table.films_centrifugal(
        speed_scale,
        1.0 / speed_scale,
        martin,
        params.centrifugal_force_n(OMEGA),
    );
    let axes = ctx.map(|c| RegimeAxis::new(c.ln_m_offset, c.ln_l));
    let parts = Parts {
        params: &bearing.params,
        roller: &bearing.roller,
        pitch: &bearing.pitch,
    };
    let places = parts.places(&state, bearing.cage_angle_rad);
    for (j, place) in places.iter().enumerate() {
        let mut m = memory[j];
        let mut p = prepare_roller(&bearing.roller, place.geometric_m, place.tilt_rad, &m);
        for _ in 0..NEWTON_ITERATIONS {
            p.newton.iterate_centrifugal(&films);
        }
        let alone = finish_roller::<true>(&p, &films, &axes, &mut m);
        let stepped = out.rollers[j];
        assert_eq!(
            alone.load.load_n.to_bits(),
            stepped.load_n.to_bits(),
            "roller {j}"
        );
        assert_eq!(
            alone.films[1].0.to_bits(),
            stepped.central_film_out_m.to_bits(),
            "roller {j}"
        );
        assert_eq!(
            alone.films[1].1.to_bits(),
            stepped.min_film_out_m.to_bits(),
            "roller {j}"
        );
    }
}
