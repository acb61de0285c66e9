//! EHL solver speed over a fixed set of Latin-hypercube samples of the docs/physics.md §5.3 domain
//! (100 samples, p_h 0.3–3.5 GPa, seed 5). Besides criterion's timing of one case, it prints the
//! per-solution distribution (median, p95, max) of one pass — the figure the issue asks for
//! (goal: median ≤ 20 ms per solution on one core; published solvers: ≈ 5 s finite differences,
//! 19 s FEM). The solver is single-threaded; besides wall time the distribution is given in CPU
//! time of the solving thread (Linux `/proc/thread-self/schedstat`, ns), which is what "on one
//! core" means on a shared machine where other processes inflate the wall time.

use bearing_ehl::{lhs, Solver, SolverOptions};
use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Instant;

/// CPU time of the calling thread in seconds (None where /proc is not available).
fn thread_cpu_s() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = stat.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

fn quantiles(times: &mut [f64]) -> String {
    times.sort_by(|a, b| a.total_cmp(b));
    let q = |f: f64| times[((times.len() - 1) as f64 * f).round() as usize] * 1e3;
    format!(
        "median {:.1} ms, p95 {:.1} ms, max {:.1} ms",
        q(0.5),
        q(0.95),
        q(1.0)
    )
}

fn distribution(name: &str, opts: SolverOptions, samples: &[lhs::Sample]) {
    let mut solver = Solver::new(opts).expect("options");
    let mut wall = Vec::new();
    let mut cpu = Vec::new();
    let mut failures = 0;
    for s in samples {
        let c0 = thread_cpu_s();
        let t = Instant::now();
        let result = solver.solve(&s.case);
        let dt = t.elapsed().as_secs_f64();
        let dc = thread_cpu_s().zip(c0).map(|(c1, c0)| c1 - c0);
        match result {
            Ok(_) => {
                wall.push(dt);
                cpu.extend(dc);
            }
            Err(_) => failures += 1,
        }
    }
    println!(
        "{name}: {} solutions, {failures} failed; per solution wall {}",
        wall.len(),
        quantiles(&mut wall)
    );
    if cpu.len() == wall.len() {
        println!("{name}: per solution CPU {}", quantiles(&mut cpu));
    }
}

fn bench(c: &mut Criterion) {
    let samples = lhs::sample_domain(100, 5);
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
