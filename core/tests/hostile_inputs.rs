//! Random bit patterns to every public function of the core: nothing panics, constructors
//! refuse what they cannot use, and film models never return a negative, NaN or infinite film.

use bearing_core::contact::{HertzLineContact, SlicedRoller};
use bearing_core::film::{moes_central, Hydrodynamic, LnGroups, Regime};
use bearing_core::math;
use bearing_core::{
    Bearing, BearingGeometry, BearingParams, ContactInput, ContactLaw, Crown, FilmKind, FilmModel,
    Lubricant, Material, OperatingState, Regression,
};
use proptest::prelude::*;

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        any::<u32>().prop_map(f32::from_bits),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0f32),
        Just(-0.0f32),
        Just(f32::MAX),
        Just(f32::MIN_POSITIVE),
        -1.0e3f32..1.0e3,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn constructors_refuse_or_accept_without_panicking(v in proptest::collection::vec(any_f32(), 12), count in any::<u16>()) {
        let material = Material::new(v[0], v[1]);
        if let Ok(m) = material {
            prop_assert!(m.elastic_modulus_pa() > 0.0 && m.elastic_modulus_pa().is_finite());
        }
        let _ = Lubricant::new(v[2], v[3], v[4]);
        let crown = if v[5] > 0.0 { Crown::Logarithmic { scale: v[5] } } else { Crown::None };
        if let Ok(g) = BearingGeometry::new(v[6], v[7], v[8], count, crown, v[9]) {
            prop_assert!(g.roller_diameter_m() < g.pitch_diameter_m());
            prop_assert!(g.crown_drop_m(v[10]).is_finite());
            let f = g.pass_frequencies(v[11]);
            prop_assert!(!f.outer_race_hz.is_nan() || !v[11].is_finite());
        }
        let _ = OperatingState::new([v[0], v[1]], [v[2], v[3]], [v[4], v[5]], v[6]);
    }

    #[test]
    fn film_models_never_return_bad_films(v in proptest::collection::vec(any_f32(), 7)) {
        let c = ContactInput {
            load_n: v[0], length_m: v[1], entrainment_speed_m_s: v[2], reduced_radius_m: v[3],
            reduced_modulus_pa: v[4], pressure_viscosity_pa_inv: v[5], viscosity_pa_s: v[6],
        };
        for f in [Regression.film(&c), Hydrodynamic.film(&c)] {
            prop_assert!(f.central_m.is_finite() && f.central_m >= 0.0, "{f:?} for {c:?}");
            prop_assert!(f.minimum_m.is_finite() && f.minimum_m >= 0.0, "{f:?} for {c:?}");
        }
        let g = LnGroups::new(&c);
        prop_assert!(g.ln_w.is_finite() && g.ln_u.is_finite() && g.ln_g.is_finite());
        let _ = Regime::from_ln_moes(g.ln_m(), g.ln_l());
        let _ = moes_central(v[0], v[1]);
        let h = HertzLineContact::new(v[0], v[1], v[2]);
        prop_assert!(h.half_width_m.is_finite() && h.max_pressure_pa.is_finite());
    }

    #[test]
    fn math_functions_stay_finite(x in any_f32(), y in any_f32()) {
        prop_assert!(math::ln(x).is_finite());
        prop_assert!(math::exp(x).is_finite());
        prop_assert!(math::pow(x, y).is_finite() || !y.is_finite());
        prop_assert!(math::sqrt(x).is_finite());
        let (s, c) = math::sin_cos(x);
        prop_assert!(s.is_finite() && c.is_finite());
    }

    #[test]
    fn slices_and_step_stay_finite(v in proptest::collection::vec(any_f32(), 10)) {
        let g = BearingGeometry::new(0.06, 0.0088, 0.015, 17, Crown::Logarithmic { scale: 1.0 }, -2e-6).unwrap();
        let oil = Lubricant::new(0.08, 2.1e-8, 833.8).unwrap();
        for law in [ContactLaw::Palmgren, ContactLaw::Lundberg] {
            let roller = SlicedRoller::<10>::new(&g, 2.3e11, law);
            let r = roller.evaluate(v[0], v[1]);
            prop_assert!(!r.load_n.is_nan() && !r.moment_nm.is_nan());
            let p = BearingParams::new(g, Material::STEEL, Material::STEEL, oil, law, 1e-5).unwrap();
            let s = OperatingState {
                displacement_m: [v[2], v[3]], velocity_m_s: [v[4], v[5]], tilt_rad: [v[6], v[7]],
                shaft_speed_rad_s: v[8],
            };
            let mut eq = None;
            for film in FilmKind::ALL {
                let mut b = Bearing::<17, 10>::new(p, film).unwrap();
                let _ = b.set_cage_angle(v[9]);
                for out in [b.evaluate(&s, 1e-4).ok().copied(), b.advance(&s, 1e-4).ok().copied()].into_iter().flatten() {
                    prop_assert!(out.force_n.iter().chain(out.moment_nm.iter()).all(|x| x.is_finite()));
                    prop_assert!(out.stiffness.iter().flatten().all(|x| x.is_finite()));
                    prop_assert!(out.damping_n_s_per_m.iter().flatten().all(|x| x.is_finite()));
                }
                if film == FilmKind::Regression {
                    eq = Some(b.static_equilibrium([v[0], v[1]], &s, 1e-6, 5));
                }
            }
            let eq = eq.unwrap();
            prop_assert!(!eq.displacement_m[0].is_nan() || !s.displacement_m[0].is_finite());
        }
    }
}
