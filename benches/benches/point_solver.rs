//! Point-contact EHL solver (`bearing_ehl::point`) at default settings on one mid case of the
//! ball-bearing domain: M = 300, L = 10, k = 6 (Roelands + Dowson–Higginson), whose grid chosen
//! from the case is 257 × 129 (M/k = 50; docs/point_contact.md). The per-case table by M and k
//! (time and peak memory) is in docs/point_contact.md; this bench tracks the one case.

use bearing_ehl::point::{grid_for_case, solve_point, PointContactCase, PointSolverOptions};
use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let case = PointContactCase::from_moes(300.0, 10.0, 6.0).expect("case");
    let (nx, ny) = grid_for_case(case.moes_m(), case.hertz().ellipticity);
    let opts = PointSolverOptions::default();
    let mut group = c.benchmark_group("point_solver");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(60));
    group.bench_function(format!("default_m300_l10_k6_{nx}x{ny}"), |b| {
        b.iter(|| solve_point(&case, &opts).expect("a converged, resolved solve"))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
