//! Instruction counts of the core film networks on QEMU's Cortex-M4.
//!
//! Run: `cd benches/qemu-film-ann && cargo run --release` (needs the thumbv7em-none-eabihf target
//! and qemu-system-arm). With `-icount shift=0` every guest instruction is 1 ns of virtual time
//! (docs/embedded.md); TIM2 of QEMU's STM32F405 model counts virtual nanoseconds at prescaler 0, so its
//! counter difference is an instruction count (`bearing-m4-counter`, calibrated on 1000 `nop`).
//! Counts are instructions, not Cortex-M4 cycles. For each contact — 20 from the committed pipeline dataset,
//! one out of the domain, one hostile — it prints the counts of `AnnInt::film`, `AnnF32::film` and
//! of the networks alone; they must be the same for every contact. Then the same for the point
//! contact's `PointAnnInt::film`, `PointAnnF32::film` (groups, exact ellipticity, guard,
//! features, network, fallback), their networks alone and `HamrockDowson::film`, on
//! `POINT_CASES`.
#![no_std]
#![no_main]

use bearing_core::film::ann::{point, prepare, AnnF32, AnnInt, PointAnnF32, PointAnnInt};
use bearing_core::film::point::HamrockDowson;
use bearing_core::film::{ContactInput, FilmModel, PointContactInput};
use bearing_m4_counter as counter;
use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    exit(debug::EXIT_FAILURE)
}

/// Ends QEMU through semihosting with `status`. QEMU stops at the call; should a host ignore
/// it, the core sleeps until an interrupt, for ever.
fn exit(status: debug::ExitStatus) -> ! {
    debug::exit(status);
    loop {
        cortex_m::asm::wfi();
    }
}

static CASES: [ContactInput; 22] = [
    ContactInput {
        load_n: 4705.284,
        length_m: 0.01252697,
        entrainment_speed_m_s: 23.57517,
        reduced_radius_m: 0.009410606,
        reduced_modulus_pa: 216977700000.0,
        pressure_viscosity_pa_inv: 2.776479e-08,
        viscosity_pa_s: 0.03420908,
    },
    ContactInput {
        load_n: 897.088,
        length_m: 0.03595392,
        entrainment_speed_m_s: 3.895301,
        reduced_radius_m: 0.001592684,
        reduced_modulus_pa: 218796000000.0,
        pressure_viscosity_pa_inv: 1.172581e-08,
        viscosity_pa_s: 0.00438811,
    },
    ContactInput {
        load_n: 204.5222,
        length_m: 0.01661619,
        entrainment_speed_m_s: 0.6639914,
        reduced_radius_m: 0.0006167324,
        reduced_modulus_pa: 240815800000.0,
        pressure_viscosity_pa_inv: 1.292919e-08,
        viscosity_pa_s: 0.0007749371,
    },
    ContactInput {
        load_n: 4010.125,
        length_m: 0.002541737,
        entrainment_speed_m_s: 16.11131,
        reduced_radius_m: 0.005441556,
        reduced_modulus_pa: 219066800000.0,
        pressure_viscosity_pa_inv: 1.398745e-08,
        viscosity_pa_s: 0.0006930171,
    },
    ContactInput {
        load_n: 1192.942,
        length_m: 0.004035643,
        entrainment_speed_m_s: 2.692231,
        reduced_radius_m: 0.008048226,
        reduced_modulus_pa: 233602600000.0,
        pressure_viscosity_pa_inv: 1.66055e-08,
        viscosity_pa_s: 0.04326667,
    },
    ContactInput {
        load_n: 498.2187,
        length_m: 0.003274469,
        entrainment_speed_m_s: 2.212222,
        reduced_radius_m: 0.0005578277,
        reduced_modulus_pa: 213346300000.0,
        pressure_viscosity_pa_inv: 1.492448e-08,
        viscosity_pa_s: 0.001561909,
    },
    ContactInput {
        load_n: 493.8165,
        length_m: 0.01073739,
        entrainment_speed_m_s: 5.614878,
        reduced_radius_m: 0.006718986,
        reduced_modulus_pa: 226707300000.0,
        pressure_viscosity_pa_inv: 1.52431e-08,
        viscosity_pa_s: 0.002742717,
    },
    ContactInput {
        load_n: 343.207,
        length_m: 0.03020922,
        entrainment_speed_m_s: 9.055709,
        reduced_radius_m: 0.0001000691,
        reduced_modulus_pa: 230552000000.0,
        pressure_viscosity_pa_inv: 1.150183e-08,
        viscosity_pa_s: 0.003800693,
    },
    ContactInput {
        load_n: 1456.957,
        length_m: 0.03614268,
        entrainment_speed_m_s: 1.26459,
        reduced_radius_m: 0.003110728,
        reduced_modulus_pa: 233410300000.0,
        pressure_viscosity_pa_inv: 1.229793e-08,
        viscosity_pa_s: 0.000589194,
    },
    ContactInput {
        load_n: 753.9769,
        length_m: 0.02833082,
        entrainment_speed_m_s: 0.6295577,
        reduced_radius_m: 0.0001535393,
        reduced_modulus_pa: 215507900000.0,
        pressure_viscosity_pa_inv: 2.590449e-08,
        viscosity_pa_s: 0.07387788,
    },
    ContactInput {
        load_n: 370.9426,
        length_m: 0.002576111,
        entrainment_speed_m_s: 1.736978,
        reduced_radius_m: 0.006994869,
        reduced_modulus_pa: 233197500000.0,
        pressure_viscosity_pa_inv: 1.03301e-08,
        viscosity_pa_s: 0.001635783,
    },
    ContactInput {
        load_n: 2326.507,
        length_m: 0.01587095,
        entrainment_speed_m_s: 0.8967426,
        reduced_radius_m: 0.001091325,
        reduced_modulus_pa: 248769400000.0,
        pressure_viscosity_pa_inv: 2.110183e-08,
        viscosity_pa_s: 0.002335189,
    },
    ContactInput {
        load_n: 235.3203,
        length_m: 0.003428872,
        entrainment_speed_m_s: 13.59911,
        reduced_radius_m: 0.0004473454,
        reduced_modulus_pa: 223303900000.0,
        pressure_viscosity_pa_inv: 1.886203e-08,
        viscosity_pa_s: 0.004521955,
    },
    ContactInput {
        load_n: 492.3283,
        length_m: 0.002164494,
        entrainment_speed_m_s: 21.08559,
        reduced_radius_m: 0.006125536,
        reduced_modulus_pa: 200118600000.0,
        pressure_viscosity_pa_inv: 2.185048e-08,
        viscosity_pa_s: 0.07275066,
    },
    ContactInput {
        load_n: 164.0271,
        length_m: 0.01795609,
        entrainment_speed_m_s: 1.773821,
        reduced_radius_m: 0.0002077245,
        reduced_modulus_pa: 229335600000.0,
        pressure_viscosity_pa_inv: 1.341836e-08,
        viscosity_pa_s: 0.0008405258,
    },
    ContactInput {
        load_n: 3558.383,
        length_m: 0.01188014,
        entrainment_speed_m_s: 5.352039,
        reduced_radius_m: 0.01676278,
        reduced_modulus_pa: 209803900000.0,
        pressure_viscosity_pa_inv: 2.705093e-08,
        viscosity_pa_s: 0.0009971792,
    },
    ContactInput {
        load_n: 594.9034,
        length_m: 0.002230669,
        entrainment_speed_m_s: 14.40861,
        reduced_radius_m: 0.01484284,
        reduced_modulus_pa: 204524000000.0,
        pressure_viscosity_pa_inv: 1.092654e-08,
        viscosity_pa_s: 0.004059929,
    },
    ContactInput {
        load_n: 2104.736,
        length_m: 0.008438085,
        entrainment_speed_m_s: 0.8027121,
        reduced_radius_m: 0.005537739,
        reduced_modulus_pa: 225686900000.0,
        pressure_viscosity_pa_inv: 2.312157e-08,
        viscosity_pa_s: 0.01219121,
    },
    ContactInput {
        load_n: 801.5942,
        length_m: 0.005179963,
        entrainment_speed_m_s: 28.64209,
        reduced_radius_m: 0.01163476,
        reduced_modulus_pa: 208059000000.0,
        pressure_viscosity_pa_inv: 1.655783e-08,
        viscosity_pa_s: 0.07018368,
    },
    ContactInput {
        load_n: 2957.475,
        length_m: 0.01446754,
        entrainment_speed_m_s: 0.9507556,
        reduced_radius_m: 0.006378948,
        reduced_modulus_pa: 211613300000.0,
        pressure_viscosity_pa_inv: 1.198157e-08,
        viscosity_pa_s: 0.008128658,
    },
    ContactInput {
        load_n: 1e5,
        length_m: 0.01,
        entrainment_speed_m_s: 5.0,
        reduced_radius_m: 0.003,
        reduced_modulus_pa: 2.3e11,
        pressure_viscosity_pa_inv: 2e-8,
        viscosity_pa_s: 0.04,
    },
    ContactInput {
        load_n: f32::NAN,
        length_m: -1.0,
        entrainment_speed_m_s: 0.0,
        reduced_radius_m: f32::INFINITY,
        reduced_modulus_pa: 2.3e11,
        pressure_viscosity_pa_inv: 2e-8,
        viscosity_pa_s: 0.04,
    },
];

/// A point contact: w, u_m, R_x, R_y, E', α, η₀.
const fn point(
    w: f32,
    u: f32,
    rx: f32,
    ry: f32,
    e: f32,
    alpha: f32,
    eta: f32,
) -> PointContactInput {
    PointContactInput {
        load_n: w,
        entrainment_speed_m_s: u,
        radius_x_m: rx,
        radius_y_m: ry,
        reduced_modulus_pa: e,
        pressure_viscosity_pa_inv: alpha,
        viscosity_pa_s: eta,
    }
}

/// Point contacts: 8 rows of the committed point dataset, one overloaded (out of the domain,
/// Hamrock–Dowson's fallback), one at R_y/R_x = 100 (the ellipticity's largest ratio), one
/// with R_y < R_x and one hostile.
static POINT_CASES: [PointContactInput; 12] = [
    point(
        8.342113,
        1.725821,
        0.007341554,
        0.03552707,
        227903600000.0,
        1.973398e-08,
        0.05317714,
    ),
    point(
        25.45016,
        4.611199,
        0.009026295,
        0.1002697,
        201414300000.0,
        1.883035e-08,
        0.002696857,
    ),
    point(
        7.529031,
        1.693137,
        0.00245054,
        0.01425212,
        223194400000.0,
        1.013029e-08,
        0.03383287,
    ),
    point(
        8.544655,
        1.673467,
        0.003094429,
        0.004567898,
        230683800000.0,
        1.289382e-08,
        0.061993,
    ),
    point(
        15.06446,
        4.135656,
        0.005561277,
        0.03083627,
        237175800000.0,
        2.22182e-08,
        0.002276116,
    ),
    point(
        32.33185,
        2.335021,
        0.005806274,
        0.03762415,
        245892000000.0,
        1.411048e-08,
        0.02901651,
    ),
    point(
        28.60231,
        5.749712,
        0.00993613,
        0.1079223,
        210335400000.0,
        1.598601e-08,
        0.01732441,
    ),
    point(
        35.96807,
        2.497843,
        0.007479861,
        0.05052713,
        241698900000.0,
        1.72166e-08,
        0.02757344,
    ),
    point(1e5, 5.0, 4e-3, 4e-2, 2.3e11, 2e-8, 0.04),
    point(50.0, 5.0, 4e-3, 0.4, 2.3e11, 2e-8, 0.04),
    point(50.0, 5.0, 4e-3, 2e-3, 2.3e11, 2e-8, 0.04),
    point(f32::NAN, 0.0, -1.0, f32::INFINITY, 2.3e11, 2e-8, 0.04),
];

/// Instructions of `f()`, less `empty` (those of the reads themselves).
fn count<T>(f: impl FnOnce() -> T, empty: u32) -> u32 {
    let s = counter::now();
    let _ = black_box(f());
    counter::elapsed(s, counter::now())
        .instructions
        .wrapping_sub(empty)
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(debug::EXIT_FAILURE)
    };
    counter::start(&mut peripherals.SYST);
    let calibration = counter::calibrate().instructions;
    hprintln!(
        "calibration: 1000 nop -> {} counts (must be 1000)",
        calibration
    );
    let empty = count(|| 0u32, 0);
    for (i, c) in CASES.iter().enumerate() {
        let p = prepare(c);
        let int_film = count(|| AnnInt.film(black_box(c)), empty);
        let f32_film = count(|| AnnF32.film(black_box(c)), empty);
        let int_net = count(|| AnnInt::network(black_box(&p.features)), empty);
        let f32_net = count(|| AnnF32::network(black_box(&p.features)), empty);
        let f = AnnInt.film(c);
        hprintln!(
            "contact {}: AnnInt::film {} AnnF32::film {} int network {} f32 network {} (source {}, h_c {:e} m)",
            i, int_film, f32_film, int_net, f32_net, f.source as u8, f.central_m
        );
    }
    for (i, c) in POINT_CASES.iter().enumerate() {
        let p = point::prepare(c);
        let int_film = count(|| PointAnnInt.film(black_box(c)), empty);
        let f32_film = count(|| PointAnnF32.film(black_box(c)), empty);
        let int_net = count(|| PointAnnInt::network(black_box(&p.features)), empty);
        let f32_net = count(|| PointAnnF32::network(black_box(&p.features)), empty);
        let hd = count(|| HamrockDowson.film(black_box(c)), empty);
        let f = PointAnnInt.film(c);
        hprintln!(
            "point contact {}: PointAnnInt::film {} PointAnnF32::film {} int network {} f32 network {} HamrockDowson::film {} (source {}, h_c {:e} m)",
            i, int_film, f32_film, int_net, f32_net, hd, f.source as u8, f.central_m
        );
    }
    exit(if calibration == 1000 {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    })
}
