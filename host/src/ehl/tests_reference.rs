//! Reference tests of the solver.
use super::*;

#[test]
fn explore() {
    for (m, l) in [(100.0, 10.0), (1000.0, 10.0)] {
        let case = ContactCase::from_moes(m, l).unwrap();
        let opts = SolverOptions {
            viscosity: ViscosityLaw::Barus,
            compressible: false,
            ..Default::default()
        };
        let t = std::time::Instant::now();
        let r = solve(&case, &opts);
        let moes = formulas::moes_central_film_m(&case);
        match r {
            Ok(s) => println!(
                "M={m} L={l}: hc/moes={:.4} hmin/hc={:.3} it={} pmax={:.3} t={:?}",
                s.central_film_m / moes,
                s.min_film_m / s.central_film_m,
                s.iterations,
                s.max_pressure_pa / s.hertz_pressure_pa,
                t.elapsed()
            ),
            Err(e) => println!("M={m} L={l}: {e}"),
        }
    }
}
