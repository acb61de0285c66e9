//! Film network inference cost (goal: ≤ 100 ns per contact for both the f32 and the integer
//! network), beside the regression formulas they replace.
//!
//! - `ann_f32` / `ann_int`: the whole `FilmModel::film` call (logarithms, guard, network, exp).
//! - `ann_f32_network` / `ann_int_network`: the network alone on prepared features.
//! - `regression_powf`: Dowson–Toyoda + Dowson–Higginson with `libm::powf` (the usual way).
//! - `fallback`: an out-of-domain contact through `AnnF32` (guard + regression in logs).

use std::hint::black_box;

use bearing_core::film::ann::{prepare, AnnF32, AnnInt};
use bearing_core::film::{ContactInput, FilmModel};
use criterion::{criterion_group, criterion_main, Criterion};

/// docs/physics.md §6.3: 850 N on 15 mm, 9.83 m/s, R = 3.03 mm, E' = 239.6 GPa, α = 21 GPa⁻¹, η₀ = 0.08 Pa·s.
const CONTACT: ContactInput = ContactInput {
    load_n: 850.0,
    length_m: 15e-3,
    entrainment_speed_m_s: 9.83,
    reduced_radius_m: 3.029e-3,
    reduced_modulus_pa: 239.6e9,
    pressure_viscosity_pa_inv: 2.1e-8,
    viscosity_pa_s: 0.08,
};

fn regression_powf(c: &ContactInput) -> (f32, f32) {
    let er = c.reduced_modulus_pa * c.reduced_radius_m;
    let w = c.load_n / c.length_m / er;
    let u = c.viscosity_pa_s * c.entrainment_speed_m_s / er;
    let g = c.pressure_viscosity_pa_inv * c.reduced_modulus_pa;
    let r = c.reduced_radius_m;
    (
        r * 3.06 * libm::powf(g, 0.56) * libm::powf(u, 0.69) * libm::powf(w, -0.10),
        r * 2.65 * libm::powf(g, 0.54) * libm::powf(u, 0.70) * libm::powf(w, -0.13),
    )
}

fn bench(c: &mut Criterion) {
    let features = prepare(&CONTACT).features;
    let outside = ContactInput {
        load_n: 1e5,
        ..CONTACT
    };
    c.bench_function("ann_f32", |b| b.iter(|| AnnF32.film(black_box(&CONTACT))));
    c.bench_function("ann_int", |b| b.iter(|| AnnInt.film(black_box(&CONTACT))));
    c.bench_function("ann_f32_network", |b| {
        b.iter(|| AnnF32::network(black_box(&features)))
    });
    c.bench_function("ann_int_network", |b| {
        b.iter(|| AnnInt::network(black_box(&features)))
    });
    c.bench_function("regression_powf", |b| {
        b.iter(|| regression_powf(black_box(&CONTACT)))
    });
    c.bench_function("fallback", |b| b.iter(|| AnnF32.film(black_box(&outside))));
}

criterion_group!(benches, bench);
criterion_main!(benches);
