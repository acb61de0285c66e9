//! Reference tests of the solver against independent results: the Hertz solution, Martin's
//! rigid iso-viscous load, Moes' formula (Barus, incompressible) and Pan–Hamrock's formulas
//! (Roelands + Dowson–Higginson), plus robustness over Latin-hypercube samples and hostile
//! inputs. The comparison tables are repeated in docs/ehl.md.

use super::compare::{self, Comparer, Formula};
use super::*;

/// Hertz limit (docs/physics.md §5.2): at large M with iso-viscous lubricant the pressure tends to
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

/// Martin's rigid iso-viscous cylinder with the Reynolds exit condition (docs/physics.md §5.1):
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
    // A rigid cylinder's gap is smallest at the contact centre: the central film is the same
    // gap (the core's hydrodynamic film uses one constant for both).
    let central_err = s.central_film_m / martin - 1.0;
    assert!(
        central_err.abs() < 0.01,
        "h_c {} vs Martin {martin}: {central_err}",
        s.central_film_m
    );
}

/// Moes' formula (Barus, incompressible; Moes 1992 as given by Venner & Lubrecht 2000) over the
/// issue's grid M ∈ {10, 30, 100, 300, 1000} × L ∈ {1, 3, 10, 20} (table in docs/ehl.md): h_c
/// within 5 % at 15 of the 20 points. The other five — M ≤ 30 with L ≥ 10, and M = 100 with
/// L = 20 — come out 5.0–7.5 % above Moes; for them the test asserts instead that the default
/// answer is converged in grid and domain (h_c and h_min within 1 %, the h_c accuracy,
/// of a solve on 1601 nodes with the inlet twice as far, X ∈ [−9, 1.5]; measured 0.00–0.5 %,
/// [`compare::Comparer`]), i.e. that the remaining gap is the formula's, not the discretisation's.
#[test]
fn moes_formula_agreement() {
    let formula_limited = [
        (10.0, 10.0),
        (10.0, 20.0),
        (30.0, 10.0),
        (30.0, 20.0),
        (100.0, 20.0),
    ];
    let mut comparer = Comparer::new(Formula::Moes).unwrap();
    let (ms, ls) = compare::moes_grid();
    let mut within = 0;
    for &m in &ms {
        for &l in &ls {
            let row = comparer
                .compare(&ContactCase::from_moes(m, l).unwrap())
                .unwrap();
            println!(
                "M={m} L={l}: h_c/Moes = {:.4} ({} nodes)",
                row.central_ratio, row.nodes
            );
            match row.refined {
                None => within += 1,
                Some(check) => {
                    println!("   converged check (1601 nodes, X from -9): {check:?}");
                    assert!(
                        formula_limited.contains(&(m, l)),
                        "M={m} L={l}: h_c/Moes = {}",
                        row.central_ratio
                    );
                    assert!(check.converged, "M={m} L={l}: not converged ({check:?})");
                }
            }
        }
    }
    assert_eq!(within, 15);
}

/// Pan & Hamrock (1989) formulas for Roelands + Dowson–Higginson solutions (ASME J. Tribol. 111,
/// 246–251; constants as in docs/physics.md §5.1 and formulas.rs), checked at every one of the 16 corners
/// of W ∈ {2·10⁻⁵, 5·10⁻⁵, 10⁻⁴, 2·10⁻⁴} × U ∈ {10⁻¹¹, 10⁻¹⁰} × G ∈ {2500, 5000}, η₀ = 0.04 Pa·s
/// (table in docs/ehl.md). The paper's own parameter range and lubricant constants could not be
/// found (search log in docs/ehl.md), so no corner is dropped as "outside PH's range":
/// - h_c and h_min within 10 % at 12 corners;
/// - at the four h_c misses — G = 5000 with (W, U) = (10⁻⁴, 10⁻¹⁰) +12.7 %, (2·10⁻⁴, 10⁻¹¹)
///   +10.6 %, (2·10⁻⁴, 10⁻¹⁰) +16.0 %, and (2·10⁻⁵, 10⁻¹⁰, 2500), M = 1.4, −11.9 % — h_min is still
///   within 10 % except at (2·10⁻⁴, 10⁻¹⁰, 5000) (+10.9 %), and the default answer must be converged
///   in grid and domain: h_c and h_min within 1 % of a solve on 1601 nodes with the inlet twice as
///   far (X ∈ [−9, 1.5]), i.e. the remaining gap is the formula's, not the discretisation's.
#[test]
fn pan_hamrock_agreement() {
    let central_misses = [
        (1e-4, 1e-10, 5000.0),
        (2e-4, 1e-11, 5000.0),
        (2e-4, 1e-10, 5000.0),
        (2e-5, 1e-10, 2500.0),
    ];
    let minimum_misses = [(2e-4, 1e-10, 5000.0)];
    let mut comparer = Comparer::new(Formula::PanHamrock).unwrap();
    let (ws, us, gs) = compare::pan_hamrock_grid();
    let (mut central_within, mut minimum_within) = (0, 0);
    for &w in &ws {
        for &u in &us {
            for &g in &gs {
                let case = ContactCase::from_dimensionless(w, u, g).unwrap();
                let row = comparer.compare(&case).unwrap();
                let rm = row.min_ratio.unwrap();
                println!(
                    "W={w:e} U={u:e} G={g}: h_c/PH = {:.4}, h_min/PH = {rm:.4}",
                    row.central_ratio
                );
                if row.min_within(Formula::PanHamrock) {
                    minimum_within += 1;
                } else {
                    assert!(
                        minimum_misses.contains(&(w, u, g)),
                        "W={w} U={u} G={g}: h_min/PH = {rm}"
                    );
                }
                if row.central_within(Formula::PanHamrock) {
                    central_within += 1;
                } else {
                    assert!(
                        central_misses.contains(&(w, u, g)),
                        "W={w} U={u} G={g}: h_c/PH = {}",
                        row.central_ratio
                    );
                }
                if let Some(check) = row.refined {
                    println!("   converged check (1601 nodes, X from -9): {check:?}");
                    assert!(
                        check.converged,
                        "W={w} U={u} G={g}: not converged ({check:?})"
                    );
                }
            }
        }
    }
    assert_eq!((central_within, minimum_within), (12, 15));
}

/// Fast robustness check over Latin-hypercube samples of the docs/physics.md §5.3 domain
/// (p_h 0.3–3.5 GPa), 100 samples with the default solver: at least 99
/// converge to a consistent result (film positive, load balanced, film exit inside the domain).
/// The full 2000-sample figure comes from the ignored test below (release mode).
#[test]
fn lhs_robustness_fast() {
    let (ok, failures) = robustness(100, 11, SolverOptions::default());
    for f in &failures {
        println!("failed: {f}");
    }
    println!("converged {ok} of 100");
    assert!(ok >= 99, "only {ok} of 100 converged");
}

/// Full robustness figure on the default grid: `cargo test --release -p bearing-ehl tests_reference::lhs_robustness_2000 -- --ignored --nocapture`.
#[test]
#[ignore]
fn lhs_robustness_2000() {
    let (ok, failures) = robustness(2000, 2024, SolverOptions::default());
    for f in &failures {
        println!("failed: {f}");
    }
    println!("converged {ok} of 2000");
    assert!(ok as f64 >= 0.995 * 2000.0);
}

fn robustness(n: usize, seed: u64, opts: SolverOptions) -> (usize, Vec<String>) {
    use rayon::prelude::*;
    let samples = lhs::sample_domain(n, seed);
    let results: Vec<Result<(), String>> = samples
        .par_iter()
        .map_init(
            || Solver::new(opts).unwrap(),
            |solver, s| match solver.solve(&s.case) {
                Ok(sol) => {
                    let last_x = sol.profile.x[sol.profile.x.len() - 1];
                    if !(sol.min_film_m > 0.0 && sol.central_film_m > 0.0) {
                        Err(format!("{s:?}: non-positive film"))
                    } else if sol.load_error >= 1e-3 {
                        Err(format!("{s:?}: load error {}", sol.load_error))
                    } else if sol.exit_x >= last_x {
                        // The exit must lie inside the (possibly stretched) domain.
                        Err(format!("{s:?}: film exit at the domain end"))
                    } else {
                        Ok(())
                    }
                }
                Err(e) => Err(format!(
                    "M = {:.1}, L = {:.1}, p_h = {:.2} GPa, {s:?}: {e}",
                    s.case.moes_m(),
                    s.case.moes_l(),
                    s.case.hertz_pressure_pa() / 1e9
                )),
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
