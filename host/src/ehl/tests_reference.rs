//! Reference tests of the solver against independent results: the Hertz solution, Martin's
//! rigid iso-viscous load, Moes' formula (Barus, incompressible) and Pan–Hamrock's formulas
//! (Roelands + Dowson–Higginson), plus robustness over Latin-hypercube samples and hostile
//! inputs. The comparison tables are repeated in docs/ehl.md.

use super::*;

fn barus_incompressible() -> SolverOptions {
    SolverOptions {
        viscosity: ViscosityLaw::Barus,
        compressible: false,
        ..Default::default()
    }
}

/// Hertz limit (PHYSICS.md §5.2): at large M with iso-viscous lubricant the pressure tends to
/// √(1 − X²) (within 2 % of p_h inside |X| ≤ 0.9, away from the inlet/outlet edges) and the film
/// is flat in the contact (Hertz closed form; Johnson, *Contact Mechanics* §5.6).
#[test]
fn hertz_limit_at_large_m() {
    let case = ContactCase::from_moes(300.0, 0.0).unwrap();
    let opts = SolverOptions {
        viscosity: ViscosityLaw::Isoviscous,
        compressible: false,
        ..Default::default()
    };
    let s = solve(&case, &opts).unwrap();
    let hc = s.central_film_m / case.film_scale_m();
    for ((x, p), h) in s
        .profile
        .x
        .iter()
        .zip(&s.profile.pressure)
        .zip(&s.profile.film)
    {
        if x.abs() <= 0.9 {
            let hz = (1.0 - x * x).sqrt();
            assert!((p - hz).abs() < 0.02, "X={x}: P={p} vs Hertz {hz}");
        }
        if x.abs() <= 0.7 {
            assert!((h - hc).abs() < 0.15 * hc, "X={x}: H={h} vs Hc={hc}");
        }
    }
}

/// Martin's rigid iso-viscous cylinder with the Reynolds exit condition (PHYSICS.md §5.1):
/// h₀/R = 4.896 U/W. Rigid, iso-viscous, incompressible solver on a long inlet.
#[test]
fn martin_rigid_isoviscous_limit() {
    let (w, u) = (1e-4, 5.0e-10);
    let case = ContactCase::from_dimensionless(w, u, 0.0).unwrap();
    let opts = SolverOptions {
        viscosity: ViscosityLaw::Isoviscous,
        compressible: false,
        elastic: false,
        x_start: -12.0,
        ..Default::default()
    };
    let s = solve(&case, &opts).unwrap();
    let martin = formulas::martin_gap_m(&case);
    let err = s.min_film_m / martin - 1.0;
    assert!(
        err.abs() < 0.01,
        "h0 {} vs Martin {martin}: {err}",
        s.min_film_m
    );
}

/// Moes' formula (Barus, incompressible; Venner & Lubrecht 2000) — h_c within 5 %.
/// Cases: M = 10 × L ∈ {1, 3}, M = 30 × L ∈ {1, 3, 10} and M = 100 × L ∈ {10, 20}. Outside this set the
/// default grid does not reach 5 % (see docs/ehl.md: M = 100, L ≤ 3 and M ≥ 300 come out
/// thinner than Moes, the contact spacing is too coarse for H ≲ 10⁻³; L ≥ 10 at M = 10 and
/// L = 20 at M = 30 are 5.3–6.4 % above Moes).
#[test]
fn moes_formula_agreement() {
    let cases = [
        (10.0, 1.0),
        (10.0, 3.0),
        (30.0, 1.0),
        (30.0, 3.0),
        (30.0, 10.0),
        (100.0, 10.0),
        (100.0, 20.0),
    ];
    let mut solver = Solver::new(barus_incompressible()).unwrap();
    for (m, l) in cases {
        let case = ContactCase::from_moes(m, l).unwrap();
        let s = solver.solve(&case).unwrap();
        let ratio = s.central_film_m / formulas::moes_central_film_m(&case);
        assert!(
            (ratio - 1.0).abs() < 0.05,
            "M={m} L={l}: h_c/Moes = {ratio}"
        );
    }
}

/// Pan & Hamrock (1989) formulas for Roelands + Dowson–Higginson solutions: h_c and h_min within
/// 10 % at W ∈ {5·10⁻⁵, 10⁻⁴, 2·10⁻⁴}, U = 10⁻¹¹, G ∈ {2500, 5000} and at U = 10⁻¹⁰, G = 2500.
#[test]
fn pan_hamrock_agreement() {
    let mut cases = vec![];
    for w in [5e-5, 1e-4, 2e-4] {
        cases.push((w, 1e-11, 2500.0));
        cases.push((w, 1e-11, 5000.0));
        cases.push((w, 1e-10, 2500.0));
    }
    let mut solver = Solver::new(SolverOptions::default()).unwrap();
    for (w, u, g) in cases {
        let case = ContactCase::from_dimensionless(w, u, g).unwrap();
        let s = solver.solve(&case).unwrap();
        let rc = s.central_film_m / formulas::pan_hamrock_central_film_m(&case);
        let rm = s.min_film_m / formulas::pan_hamrock_min_film_m(&case);
        assert!((rc - 1.0).abs() < 0.10, "W={w} U={u} G={g}: h_c/PH = {rc}");
        assert!(
            (rm - 1.0).abs() < 0.10,
            "W={w} U={u} G={g}: h_min/PH = {rm}"
        );
    }
}

/// Fast robustness check over Latin-hypercube samples of the PHYSICS.md §5.3 domain
/// (p_h 0.3–3.5 GPa) on the 401-node `SolverOptions::fast()` grid: every converged result is physically consistent (film positive,
/// h_min ≤ h_c, load balanced, max pressure ≥ 0.8 p_h) and the converged fraction is reported.
/// The full 2000-sample figure comes from the ignored test below (release mode).
#[test]
fn lhs_robustness_fast() {
    let (ok, failures) = robustness(16, 11);
    for f in &failures {
        println!("failed: {f}");
    }
    println!("converged {ok} of 16");
    assert!(ok >= 12, "only {ok} of 16 converged");
}

/// Full robustness figure: `cargo test --release -p bearing-host ehl::tests_reference::lhs_robustness_2000 -- --ignored --nocapture`.
#[test]
#[ignore]
fn lhs_robustness_2000() {
    let (ok, failures) = robustness(2000, 2024);
    for f in &failures {
        println!("failed: {f}");
    }
    println!("converged {ok} of 2000");
    assert!(ok as f64 >= 0.995 * 2000.0);
}

fn robustness(n: usize, seed: u64) -> (usize, Vec<String>) {
    use rayon::prelude::*;
    let samples = lhs::sample_domain(n, seed);
    let results: Vec<Result<(), String>> = samples
        .par_iter()
        .map_init(
            || Solver::new(SolverOptions::fast()).unwrap(),
            |solver, s| match solver.solve(&s.case) {
                Ok(sol) => {
                    assert!(sol.min_film_m > 0.0 && sol.min_film_m <= sol.central_film_m * 1.0001);
                    assert!(sol.load_error < 1e-3);
                    assert!(sol.max_pressure_pa >= 0.8 * sol.hertz_pressure_pa);
                    Ok(())
                }
                Err(e) => Err(format!("{:?}: {e}", s)),
            },
        )
        .collect();
    let ok = results.iter().filter(|r| r.is_ok()).count();
    (ok, results.into_iter().filter_map(|r| r.err()).collect())
}

/// Hostile options are refused with a typed error naming the field.
#[test]
fn hostile_options_refused() {
    let case = ContactCase::from_moes(30.0, 5.0).unwrap();
    for nodes in [0, 3, 1_000_000] {
        let e = solve(
            &case,
            &SolverOptions {
                nodes,
                ..Default::default()
            },
        )
        .unwrap_err();
        assert!(e.to_string().contains("nodes"), "{e}");
    }
    let e = solve(
        &case,
        &SolverOptions {
            x_start: f64::NAN,
            ..Default::default()
        },
    )
    .unwrap_err();
    assert!(e.to_string().contains("x_start"));
}
