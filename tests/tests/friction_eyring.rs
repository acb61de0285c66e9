//! The core's viscous friction against the host's reference: the isothermal Eyring shear
//! stress integrated over the numerical EHL solver's pressure and film (bearing_ehl::traction),
//! over the film network's training domain (docs/physics.md §8.3, docs/friction.md).
//!
//! Both sides use the Barus viscosity and the numerical central film, so the comparison tests
//! the core's traction model (Hertzian pressure widened at light load, 4-node quadrature), not
//! its film model. The
//! core's viscous friction as the step computes it is the lesser of that and the thermal
//! (Evans–Johnson) traction, compared too, at slide-to-roll ratios 0.3–10 % and Eyring
//! stresses 2–20 MPa.

use bearing_core::film::ann::model_weights::DOMAIN;
use bearing_core::film::ann::AnnF32;
use bearing_core::friction::traction::{isothermal_eyring_n, pressure_zone_widening};
use bearing_core::{ContactInput, FilmModel, FilmSource, FrictionDesign};
use bearing_ehl::traction::eyring_traction_n;
use bearing_ehl::{ContactCase, SolverOptions, ViscosityLaw};

/// The i-th point of the Halton sequence in base `base`, in (0, 1).
fn halton(mut i: u64, base: u64) -> f64 {
    let (mut f, mut r) = (1.0, 0.0);
    while i > 0 {
        f /= base as f64;
        r += f * (i % base) as f64;
        i /= base;
    }
    r
}

/// Contacts spread over the network's training domain (log-uniform in each of its seven
/// inputs by a Halton sequence from index `first`), `count` of those the network's own guard
/// accepts.
fn domain_contacts(first: u64, count: usize) -> Vec<ContactInput> {
    const BASES: [u64; 7] = [2, 3, 5, 7, 11, 13, 17];
    let mut out = Vec::new();
    for i in first..first + 50_000 {
        let v: Vec<f32> = DOMAIN
            .inputs
            .iter()
            .zip(BASES)
            .map(|(&[lo, hi], base)| {
                let (lo, hi) = (f64::from(lo) * 1.0001, f64::from(hi) * 0.9999);
                (lo.ln() + halton(i, base) * (hi / lo).ln()).exp() as f32
            })
            .collect();
        let c = ContactInput {
            load_n: v[0],
            entrainment_speed_m_s: v[1],
            reduced_radius_m: v[2],
            reduced_modulus_pa: v[3],
            pressure_viscosity_pa_inv: v[4],
            viscosity_pa_s: v[5],
            length_m: v[6],
        };
        if AnnF32.film(&c).source == FilmSource::NetworkF32 {
            out.push(c);
        }
        if out.len() == count {
            break;
        }
    }
    out
}

/// (median, 95th percentile) of the values.
fn median_p95(mut v: Vec<f64>) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((v.len() - 1) as f64 * q).round() as usize];
    (at(0.5), at(0.95))
}

/// Moes' M from which a contact counts as elastohydrodynamic here: its pressure is then close
/// to Hertz's (docs/physics.md §8.3). Below, the pressure of the light, nearly rigid contact is
/// lower and wider than Hertz's, which the core's widening of the pressure zone approximates.
const MIN_ELASTIC_MOES_M: f64 = 10.0;

/// Slide-to-roll ratios and Eyring stresses (Pa) the core is checked at besides the bearing's
/// default (s = 1 %, τ₀ = 5 MPa, asserted above).
const SLIDE_TO_ROLL: [f32; 4] = [0.003, 0.01, 0.03, 0.1];
const EYRING_STRESS_PA: [f32; 3] = [2.0e6, 5.0e6, 2.0e7];

#[test]
fn core_viscous_friction_matches_the_integrated_eyring_shear() {
    let contacts = domain_contacts(1, 60);
    assert_eq!(contacts.len(), 60);
    let opts = barus();
    let solutions: Vec<_> = contacts
        .iter()
        .map(|c| {
            let case = case_of(c);
            (bearing_ehl::solve(&case, &opts).unwrap(), case)
        })
        .collect();
    for eyring_stress_pa in EYRING_STRESS_PA {
        for slide_to_roll in SLIDE_TO_ROLL {
            check_at(&contacts, &solutions, eyring_stress_pa, slide_to_roll);
        }
    }
}

/// Compares the core with the host over `contacts` (solved: `solutions`) at one Eyring stress
/// and slide-to-roll ratio, prints the errors and, at the bearing's default (τ₀ = 5 MPa,
/// s = 1 %), asserts the goal where the core's Hertzian pressure holds and the level the
/// widened zone reaches over the whole domain.
fn check_at(
    contacts: &[ContactInput],
    solutions: &[(bearing_ehl::EhlSolution, ContactCase)],
    eyring_stress_pa: f32,
    slide_to_roll: f32,
) {
    // Smooth surfaces (σ = 1 nm): no asperity contact, the film carries the whole load.
    let friction = FrictionDesign {
        composite_roughness_m: 1.0e-9,
        eyring_stress_pa,
        slide_to_roll_ratio: slide_to_roll,
        ..FrictionDesign::DEFAULT
    }
    .params()
    .unwrap();
    let (mut isothermal_err, mut step_err) = (Vec::new(), Vec::new());
    // (core/reference − 1, M, L) of the isothermal traction, to list the largest.
    let mut signed = Vec::new();
    for (c, (sol, case)) in contacts.iter().zip(solutions) {
        let sliding = f64::from(slide_to_roll * c.entrainment_speed_m_s);
        let reference = eyring_traction_n(
            sol,
            ViscosityLaw::Barus,
            f64::from(c.length_m),
            sliding,
            f64::from(eyring_stress_pa),
        );
        let film = sol.central_film_m as f32;
        let b = sol.hertz_half_width_m as f32;
        let peak = sol.hertz_pressure_pa as f32;
        let widening = pressure_zone_widening(
            film,
            c.reduced_radius_m,
            b,
            c.pressure_viscosity_pa_inv * peak,
        );
        let core = isothermal_eyring_n(
            eyring_stress_pa,
            c.viscosity_pa_s,
            c.pressure_viscosity_pa_inv,
            sliding as f32,
            film,
            peak / widening,
            b * widening,
            c.length_m,
        );
        let step = friction.contact(c, film).viscous_n;
        let elastic = case.moes_m() >= MIN_ELASTIC_MOES_M;
        isothermal_err.push((elastic, (f64::from(core) / reference - 1.0).abs()));
        signed.push((
            f64::from(core) / reference - 1.0,
            case.moes_m(),
            case.moes_l(),
        ));
        step_err.push((elastic, (f64::from(step) / reference - 1.0).abs()));
    }
    let all = |v: &[(bool, f64)]| v.iter().map(|&(_, e)| e).collect::<Vec<_>>();
    let ehl = |v: &[(bool, f64)]| {
        v.iter()
            .filter(|p| p.0)
            .map(|&(_, e)| e)
            .collect::<Vec<_>>()
    };
    let elastic_count = ehl(&isothermal_err).len();
    let default = eyring_stress_pa == 5.0e6 && slide_to_roll == 0.01;
    if default {
        signed.sort_by(|a, b| b.0.abs().total_cmp(&a.0.abs()));
        let above = signed.iter().filter(|e| e.0.abs() > 0.10).count();
        println!(
            "isothermal Eyring: {above} of {} contacts off by more than 10 %; the largest:",
            signed.len()
        );
        for (error, m, l) in signed.iter().take(above.min(10)) {
            println!("  M {m:7.3}  L {l:6.2}: {:+6.1} %", error * 100.0);
        }
    }
    for (what, errors) in [
        ("isothermal Eyring", &isothermal_err),
        (
            "the step's viscous friction (thermal cap included)",
            &step_err,
        ),
    ] {
        let (median, p95) = median_p95(all(errors));
        let (ehl_median, ehl_p95) = median_p95(ehl(errors));
        println!(
            "{what}, core vs host at τ₀ = {} MPa, s = {slide_to_roll}: all {} domain contacts \
             median {:.2} %, p95 {:.2} %; the {elastic_count} with M ≥ {MIN_ELASTIC_MOES_M} \
             median {:.2} %, p95 {:.2} %",
            eyring_stress_pa * 1e-6,
            contacts.len(),
            median * 100.0,
            p95 * 100.0,
            ehl_median * 100.0,
            ehl_p95 * 100.0
        );
    }
    if default {
        // The goal, where the core's Hertzian pressure holds (elastohydrodynamic contacts)...
        let (median, p95) = median_p95(ehl(&isothermal_err));
        assert!(elastic_count >= 30, "{elastic_count}");
        assert!(median < 0.10 && p95 < 0.10, "median {median}, p95 {p95}");
        // ...and over the whole domain, light-load end included (docs/friction.md: the widened
        // pressure zone brings it within 10 % at the median, not yet at the 95th percentile).
        let (median, p95) = median_p95(all(&isothermal_err));
        assert!(median < 0.10 && p95 < 0.35, "median {median}, p95 {p95}");
    }
}

/// The EHL case of a contact.
fn case_of(c: &ContactInput) -> ContactCase {
    ContactCase::new(
        f64::from(c.load_n / c.length_m),
        f64::from(c.entrainment_speed_m_s),
        f64::from(c.reduced_radius_m),
        f64::from(c.reduced_modulus_pa),
        f64::from(c.pressure_viscosity_pa_inv),
        f64::from(c.viscosity_pa_s),
    )
    .unwrap()
}

/// The solver options of both the test and the fit: Barus viscosity, as the core's.
fn barus() -> SolverOptions {
    SolverOptions {
        viscosity: ViscosityLaw::Barus,
        ..SolverOptions::default()
    }
}

/// Regenerates the pressure-zone widening of the core (`WIDENING_COEFFICIENT` and the blend
/// exponent of `pressure_zone_widening`): 240 contacts of the network's domain from index
/// 3000 of the Halton sequence (disjoint from the 60 the test above reports), each solved
/// once and its Eyring traction integrated at slide-to-roll ratios 0.3, 1, 3 and 10 %; prints
/// the 95th percentile and median of |core/reference − 1| for each (c, exponent) of a grid,
/// best first. ≈ 1 min.
#[test]
#[ignore = "regenerates fitted constants; run by hand"]
fn fit_pressure_zone_widening() {
    let eyring_stress_pa = 5.0e6_f32;
    let opts = barus();
    // Per (contact, slide-to-roll ratio): film, R, b, p_h, the inputs and the reference.
    let mut samples = Vec::new();
    for c in domain_contacts(3000, 240) {
        let sol = bearing_ehl::solve(&case_of(&c), &opts).unwrap();
        for slide_to_roll in [0.003_f32, 0.01, 0.03, 0.1] {
            let sliding = slide_to_roll * c.entrainment_speed_m_s;
            let reference = eyring_traction_n(
                &sol,
                ViscosityLaw::Barus,
                f64::from(c.length_m),
                f64::from(sliding),
                f64::from(eyring_stress_pa),
            );
            samples.push((
                c,
                sol.central_film_m as f32,
                sol.hertz_half_width_m as f32,
                sol.hertz_pressure_pa as f32,
                sliding,
                reference,
            ));
        }
    }
    let mut results = Vec::new();
    for exponent in [4.0_f32, 8.0] {
        for coefficient in [1.0_f32, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0] {
            let errors: Vec<f64> = samples
                .iter()
                .map(|&(c, film, b, peak, sliding, reference)| {
                    let alpha_peak = (c.pressure_viscosity_pa_inv * peak).max(1.0);
                    let r_sq = coefficient * c.reduced_radius_m * film / (b * b * alpha_peak);
                    let widening = (1.0 + r_sq.powf(exponent / 2.0)).powf(1.0 / exponent);
                    let core = isothermal_eyring_n(
                        eyring_stress_pa,
                        c.viscosity_pa_s,
                        c.pressure_viscosity_pa_inv,
                        sliding,
                        film,
                        peak / widening,
                        b * widening,
                        c.length_m,
                    );
                    (f64::from(core) / reference - 1.0).abs()
                })
                .collect();
            let (median, p95) = median_p95(errors);
            results.push((p95, median, coefficient, exponent));
        }
    }
    results.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (p95, median, coefficient, exponent) in results {
        println!(
            "c {coefficient:5.1}  exponent {exponent}: p95 {:6.2} %, median {:5.2} %",
            p95 * 100.0,
            median * 100.0
        );
    }
}

/// Step of ln M and ln L of the candidate traction table [`traction_table_interpolation`]
/// measures.
const TABLE_STEP_LN_ML: f64 = 0.25;
/// First node, step and count of z = ln N + α·p_h on that table.
const TABLE_Z: (f64, f64, usize) = (-8.0, 2.0, 57);

/// Catmull–Rom cubic through p₀…p₃ at t ∈ [0, 1] between p₁ and p₂.
fn catmull_rom(p: [f64; 4], t: f64) -> f64 {
    let c1 = 0.5 * (p[2] - p[0]);
    let c2 = p[0] - 2.5 * p[1] + 2.0 * p[2] - 0.5 * p[3];
    let c3 = 0.5 * (p[3] - p[0]) + 1.5 * (p[1] - p[2]);
    p[1] + t * (c1 + t * (c2 + t * c3))
}

/// The mean Eyring stress ratio T = (1/(b·τ₀))∫τ dx of a solution at N = e^`ln_n`,
/// N = η₀·u_s/(h_c·τ₀) (docs/physics.md §8.3).
fn mean_stress_ratio(sol: &bearing_ehl::EhlSolution, ln_n: f64) -> f64 {
    // τ₀ = 1 Pa, l = 1 m: u_s = N·h_c/η₀.
    let sliding = ln_n.exp() * sol.central_film_m / sol.case.viscosity_pa_s;
    eyring_traction_n(sol, ViscosityLaw::Barus, 1.0, sliding, 1.0) / sol.hertz_half_width_m
}

/// Measures a candidate for the core's isothermal traction, in f64: a table of ln T over
/// (ln M, ln L, z = ln N + α·p_h), each (M, L) node solved once at α = 1.732·10⁻⁸ 1/Pa (with
/// Dowson–Higginson compressibility T depends on p_h besides M, L and N), ln M from −3.5 and
/// ln L from 0 by [`TABLE_STEP_LN_ML`], z by [`TABLE_Z`] with Catmull–Rom in z; interpolated
/// bilinearly or Catmull–Rom bicubically in (ln M, ln L). Prints the median and 95th
/// percentile of |table/reference − 1| over the 60 contacts of the test above at
/// s = 0.3, 1, 3, 10 % (τ₀ = 5 MPa), and those of T solved at each contact's own (M, L, N) at
/// the table's α (measured median 0.06 %, p95 1.9 %: p_h barely enters). Measured: step 0.5 bilinear median 1.7 %, p95 39 %;
/// bicubic 1.4 %, 21 %; step 0.25 bilinear 0.44 %, 15 %; bicubic 0.41 %, 5.2 %
/// (47 × 21 × 57 nodes: 112 kB as i16). ≈ 2.5 min.
#[test]
#[ignore = "measures a candidate traction table; run by hand"]
fn traction_table_interpolation() {
    let opts = barus();
    let step = TABLE_STEP_LN_ML;
    let (m0, l0) = (-3.5, 0.0);
    let (nm, nl) = ((11.5 / step) as usize + 1, (5.0 / step) as usize + 1);
    let (z0, dz, nz) = TABLE_Z;
    let (alpha, e, r) = (1.732e-8, 2.26e11, 0.01);
    let case_at = |ln_m: f64, ln_l: f64| {
        let two_u = (ln_l.exp() / (alpha * e)).powi(4);
        let eta_u = 0.5 * two_u * e * r;
        let w = ln_m.exp() * two_u.sqrt() * e * r;
        // η₀·u = U·E′R: u = 10 m/s unless η₀ would leave [10⁻⁴, 10³] Pa·s.
        let eta = (eta_u / 10.0).clamp(1.0e-4, 1.0e3);
        ContactCase::new(w, eta_u / eta, r, e, alpha, eta)
    };
    // ln T per node and z; NaN where no solution (α·p_h > 300, far outside the domain).
    let mut table = vec![vec![f64::NAN; nz]; nm * nl];
    for i in 0..nm {
        for j in 0..nl {
            let (ln_m, ln_l) = (m0 + step * i as f64, l0 + step * j as f64);
            let alpha_peak = (ln_l + 0.5 * ln_m).exp() / (2.0 * std::f64::consts::PI).sqrt();
            if alpha_peak > 300.0 {
                continue;
            }
            let Ok(sol) = case_at(ln_m, ln_l).and_then(|c| bearing_ehl::solve(&c, &opts)) else {
                continue;
            };
            let alpha_peak = alpha * sol.hertz_pressure_pa;
            for (k, v) in table[i * nl + j].iter_mut().enumerate() {
                *v = mean_stress_ratio(&sol, z0 + dz * k as f64 - alpha_peak).ln();
            }
        }
    }
    let in_z = |row: &[f64], z: f64| {
        let f = ((z - z0) / dz).clamp(1.0, (nz - 2) as f64);
        let k = (f as usize).clamp(1, nz - 3);
        catmull_rom([row[k - 1], row[k], row[k + 1], row[k + 2]], f - k as f64)
    };
    let (mut bilinear, mut bicubic, mut same_groups) = (Vec::new(), Vec::new(), Vec::new());
    for c in &domain_contacts(1, 60) {
        let case = case_of(c);
        let sol = bearing_ehl::solve(&case, &opts).unwrap();
        let fm = (case.moes_m().ln() - m0) / step;
        let fl = (case.moes_l().ln() - l0) / step;
        let (i, j) = ((fm as usize).min(nm - 2), (fl as usize).min(nl - 2));
        let (tm, tl) = (fm - i as f64, fl - j as f64);
        let alpha_peak = case.pressure_viscosity_pa_inv * sol.hertz_pressure_pa;
        // The contact's (M, L) at the table's α: T at the same N differs only through p_h.
        let twin = case_at(case.moes_m().ln(), case.moes_l().ln())
            .and_then(|c| bearing_ehl::solve(&c, &opts))
            .unwrap();
        for slide_to_roll in [0.003, 0.01, 0.03, 0.1] {
            let ln_n = (case.viscosity_pa_s * slide_to_roll * case.entrainment_speed_m_s
                / (sol.central_film_m * 5.0e6))
                .ln();
            let reference = mean_stress_ratio(&sol, ln_n);
            let at = |a: usize, b: usize| in_z(&table[a * nl + b], ln_n + alpha_peak);
            let linear = (1.0 - tm) * ((1.0 - tl) * at(i, j) + tl * at(i, j + 1))
                + tm * ((1.0 - tl) * at(i + 1, j) + tl * at(i + 1, j + 1));
            let clamp = |x: usize, n: usize| x.clamp(1, n) - 1;
            let rows = [0, 1, 2, 3].map(|a| {
                let ii = clamp(i + a, nm);
                catmull_rom([0, 1, 2, 3].map(|b| at(ii, clamp(j + b, nl))), tl)
            });
            let cubic = catmull_rom(rows, tm);
            bilinear.push((linear.exp() / reference - 1.0).abs());
            bicubic.push((cubic.exp() / reference - 1.0).abs());
            same_groups.push((mean_stress_ratio(&twin, ln_n) / reference - 1.0).abs());
        }
    }
    for (name, errors) in [
        ("the same (M, L, N) at the table's α", same_groups),
        ("bilinear", bilinear),
        ("bicubic", bicubic),
    ] {
        let (median, p95) = median_p95(errors);
        println!(
            "step {step} in ln M, ln L; {name}: median {:.2} %, p95 {:.2} %",
            median * 100.0,
            p95 * 100.0
        );
    }
}
