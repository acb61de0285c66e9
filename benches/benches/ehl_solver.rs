//! EHL solver speed over a fixed set of Latin-hypercube samples of the PHYSICS.md §5.3 domain
//! (p_h 0.3–3.5 GPa, seed 5). Besides criterion's timing of one sweep, it prints the per-solution
//! distribution (median, p95, max) of one pass — the figure the issue asks for (goal: median
//! ≤ 20 ms per solution on one core; published solvers: ≈ 5 s finite differences, 19 s FEM).

use bearing_host::ehl::{lhs, Solver, SolverOptions};
use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Instant;

fn distribution(name: &str, opts: SolverOptions, samples: &[lhs::Sample]) {
    let mut solver = Solver::new(opts).expect("options");
    let mut times = Vec::new();
    let mut failures = 0;
    for s in samples {
        let t = Instant::now();
        match solver.solve(&s.case) {
            Ok(_) => times.push(t.elapsed().as_secs_f64()),
            Err(_) => failures += 1,
        }
    }
    times.sort_by(|a, b| a.total_cmp(b));
    let q = |f: f64| times[((times.len() - 1) as f64 * f).round() as usize] * 1e3;
    println!(
        "{name}: {} solutions, {failures} failed; per solution median {:.1} ms, p95 {:.1} ms, max {:.1} ms",
        times.len(),
        q(0.5),
        q(0.95),
        q(1.0)
    );
}

fn bench(c: &mut Criterion) {
    let samples = lhs::sample_domain(24, 5);
    distribution(
        "default grid (801 nodes)",
        SolverOptions::default(),
        &samples,
    );
    distribution("fast grid (401 nodes)", SolverOptions::fast(), &samples);
    let mut group = c.benchmark_group("ehl_solver");
    group.sample_size(10);
    let mut solver = Solver::new(SolverOptions::fast()).expect("options");
    group.bench_function("fast_401_nodes_one_lhs_case", |b| {
        b.iter(|| solver.solve(&samples[1].case).ok())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
