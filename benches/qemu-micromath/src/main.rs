//! The core's f32 elementary functions against `micromath`'s (`F32Ext`) on QEMU's Cortex-M4.
//!
//! Run: `cd benches/qemu-micromath && cargo run --release` (needs the thumbv7em-none-eabihf
//! target and qemu-system-arm). It prints a Markdown table (`docs/micromath.md` holds it), one
//! row per function the bearing step calls, over the domain the step calls it on:
//!
//! - instructions per call, fewest and most over 64 arguments spread over the domain (TIM2
//!   under `-icount shift=0`, see `bearing-m4-counter`); the function inlined into the measured closure
//!   as into the step;
//! - the worst error over 20 001 arguments spread over the domain (geometrically for positive
//!   domains spanning decades, evenly otherwise), against the f64 function of the same f32
//!   argument (libm's f64 functions, soft-float here): relative for values of one sign,
//!   absolute for sin/cos (they cross 0) and for logarithms (they cross 0 at 1, and an absolute
//!   error ε of ln x is the relative error e^ε − 1 ≈ ε of the quantity it is later raised to).
//!
//! The errors are those of the M4's own arithmetic; both crates use only IEEE `+ − × ÷`, bit
//! operations and (the core's sqrt) `vsqrt`, so the host computes the same bits.
#![no_std]
#![no_main]

use bearing_core::math;
use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use micromath::F32Ext;

use bearing_m4_counter as counter;

/// Instructions of `f()` (its result kept by `black_box`), less `empty` (the count of an empty
/// measurement, [`empty`]).
fn count<T>(f: impl FnOnce() -> T, empty: u32) -> u32 {
    let start = counter::now();
    let _ = core::hint::black_box(f());
    counter::elapsed(start, counter::now())
        .instructions
        .wrapping_sub(empty)
}

/// The count of an empty measurement, to subtract from [`count`]'s.
fn empty() -> u32 {
    count(|| 0u32, 0)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    debug::exit(debug::EXIT_FAILURE);
    loop {
        core::hint::spin_loop();
    }
}

/// Arguments of the instruction counts per function.
const COST_POINTS: usize = 64;
/// Arguments of the error sweep per function.
const ERROR_POINTS: usize = 20_001;

/// How a domain's arguments are spread.
#[derive(Clone, Copy)]
enum Spacing {
    /// Evenly in x.
    Linear,
    /// Evenly in ln x (lo > 0).
    Geometric,
}

/// The `k`-th of `n` arguments spread over `[lo, hi]`, rounded to f32.
fn argument(lo: f64, hi: f64, spacing: Spacing, k: usize, n: usize) -> f32 {
    let t = k as f64 / (n - 1) as f64;
    match spacing {
        Spacing::Linear => (lo + t * (hi - lo)) as f32,
        Spacing::Geometric => libm::exp(libm::log(lo) + t * (libm::log(hi) - libm::log(lo))) as f32,
    }
}

/// Fewest and most instructions of `f` over [`COST_POINTS`] arguments of the domain. The
/// arguments are computed (in soft-float f64) before any count: computed in the loop, part of
/// that work was scheduled between the counter reads.
fn cost<T>(lo: f64, hi: f64, spacing: Spacing, empty: u32, f: impl Fn(f32) -> T) -> (u32, u32) {
    let mut arguments = [0.0f32; COST_POINTS];
    for (k, x) in arguments.iter_mut().enumerate() {
        *x = argument(lo, hi, spacing, k, COST_POINTS);
    }
    let arguments = black_box(arguments);
    let mut range = (u32::MAX, 0);
    for x in arguments {
        let n = count(|| f(black_box(x)), empty);
        range = (range.0.min(n), range.1.max(n));
    }
    range
}

/// The kind of error reported.
#[derive(Clone, Copy, PartialEq)]
enum Error {
    Relative,
    Absolute,
}

/// Worst error of `f` against the f64 `reference` over [`ERROR_POINTS`] arguments.
fn worst(
    lo: f64,
    hi: f64,
    spacing: Spacing,
    kind: Error,
    f: impl Fn(f32) -> f32,
    reference: impl Fn(f64) -> f64,
) -> f64 {
    let mut worst = 0.0f64;
    for k in 0..ERROR_POINTS {
        let x = argument(lo, hi, spacing, k, ERROR_POINTS);
        let (got, want) = (f(x) as f64, reference(x as f64));
        let error = match kind {
            Error::Relative => libm::fabs(got / want - 1.0),
            Error::Absolute => libm::fabs(got - want),
        };
        // NaN counts as the worst possible.
        worst = if error.is_nan() {
            f64::INFINITY
        } else {
            worst.max(error)
        };
    }
    worst
}

/// One table row: a function of the step, its domain and both implementations.
struct Row<'a> {
    function: &'a str,
    domain: &'a str,
    core_cost: (u32, u32),
    micromath_cost: (u32, u32),
    kind: Error,
    core_error: f64,
    micromath_error: f64,
}

/// "n" for a fixed count, "fewest–most" otherwise.
struct Counts((u32, u32));

impl core::fmt::Display for Counts {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.0 {
            (fewest, most) if fewest == most => write!(f, "{fewest}"),
            (fewest, most) => write!(f, "{fewest}–{most}"),
        }
    }
}

fn print(row: &Row) {
    let kind = if row.kind == Error::Relative {
        "rel."
    } else {
        "abs."
    };
    hprintln!(
        "| {} | {} | {} | {} | {} {:.1e} | {} {:.1e} |",
        row.function,
        row.domain,
        Counts(row.core_cost),
        Counts(row.micromath_cost),
        kind,
        row.core_error,
        kind,
        row.micromath_error
    );
}

/// A row of a one-argument function: the core's `ours`, micromath's `micro`, the f64 `reference`.
#[allow(clippy::too_many_arguments)]
fn row<'a>(
    function: &'a str,
    domain: &'a str,
    (lo, hi, spacing): (f64, f64, Spacing),
    kind: Error,
    empty: u32,
    ours: impl Fn(f32) -> f32 + Copy,
    micro: impl Fn(f32) -> f32 + Copy,
    reference: impl Fn(f64) -> f64 + Copy,
) -> Row<'a> {
    Row {
        function,
        domain,
        core_cost: cost(lo, hi, spacing, empty, ours),
        micromath_cost: cost(lo, hi, spacing, empty, micro),
        kind,
        core_error: worst(lo, hi, spacing, kind, ours, reference),
        micromath_error: worst(lo, hi, spacing, kind, micro, reference),
    }
}

#[entry]
fn main() -> ! {
    use Error::{Absolute, Relative};
    use Spacing::{Geometric, Linear};
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        debug::exit(debug::EXIT_FAILURE);
        loop {
            core::hint::spin_loop();
        }
    };
    counter::start(&mut peripherals.SYST);
    let calibration = counter::calibrate().instructions;
    hprintln!(
        "calibration: 1000 nop -> {} counts (must be 1000)",
        calibration
    );
    let empty = empty();
    hprintln!("| step function (core) → micromath | domain (the step's call sites) | core instr. | micromath instr. | core worst error | micromath worst error |");
    hprintln!("|---|---|---|---|---|---|");
    let rows = [
        // √(e² + h_RI²) of the film table and the film models' blends: films² in m².
        row(
            "`math::sqrt` → `sqrt`",
            "1e-20 … 1e-4 (film² in m²)",
            (1e-20, 1e-4, Geometric),
            Relative,
            empty,
            math::sqrt,
            F32Ext::sqrt,
            libm::sqrt,
        ),
        // ln(η·u) and ln u per step (u ≥ 1 µm/s), ln Q of the film–load fit (10⁻³ … 10⁷ N).
        row(
            "`math::ln` → `ln`",
            "5e-10 … 1e7 (η·u, u, Q)",
            (5e-10, 1e7, Geometric),
            Absolute,
            empty,
            math::ln,
            F32Ext::ln,
            libm::log,
        ),
        // The same on x ≥ 1 alone: micromath's ln takes 1/x below 1 by its approximate
        // reciprocal (`inv`, ~8 % by its documentation), which dominates the row above.
        row(
            "`math::ln` → `ln`, x ≥ 1 only",
            "1 … 1e7 (Q)",
            (1.0, 1e7, Geometric),
            Absolute,
            empty,
            math::ln,
            F32Ext::ln,
            libm::log,
        ),
        // e^λ of the film table's nodes and the coupling's loads, e^(κ ln u), e^(−λ).
        row(
            "`math::exp` → `exp`",
            "−12 … 16.2 (ln Q, κ ln u)",
            (-12.0, 16.2, Linear),
            Relative,
            empty,
            math::exp,
            F32Ext::exp,
            libm::exp,
        ),
        // The coupling's Newton step: 2^(log₂e·(λ − λ_ref)/n), λ ∈ ln 10⁻⁴ … ln 10⁷,
        // λ_ref ≥ ln 10⁻³, n ≥ 1. micromath has no exp2: e^(y·ln 2).
        row(
            "`math::exp2` → `exp(y·ln 2)`",
            "−37 … 34 (Newton's elastic term)",
            (-37.0, 34.0, Linear),
            Relative,
            empty,
            math::exp2,
            |y: f32| F32Ext::exp(y * core::f32::consts::LN_2),
            libm::exp2,
        ),
        // The Palmgren slice law's δ^(1/9) per slice: the approach over its cap, (0, 1].
        row(
            "`math::ninth_root_in_range` → `powf(x, 1/9)`",
            "1e-13 … 1 (slice approach / cap)",
            (1e-13, 1.0, Geometric),
            Relative,
            empty,
            math::ninth_root_in_range,
            |x: f32| F32Ext::powf(x, 1.0 / 9.0),
            |x: f64| libm::pow(x, 1.0 / 9.0),
        ),
        // The cage angle, once per step (the caller wraps it into a turn).
        row(
            "`math::sin_cos(x).0` → `sin`",
            "0 … 2π (cage angle)",
            (0.0, 2.0 * core::f64::consts::PI, Linear),
            Absolute,
            empty,
            |x| math::sin_cos(x).0,
            F32Ext::sin,
            libm::sin,
        ),
        row(
            "`math::sin_cos(x).1` → `cos`",
            "0 … 2π (cage angle)",
            (0.0, 2.0 * core::f64::consts::PI, Linear),
            Absolute,
            empty,
            |x| math::sin_cos(x).1,
            F32Ext::cos,
            libm::cos,
        ),
        // The film network's seven inputs (DOMAIN of model_weights.rs, and the film table's
        // node loads 1 N … 144 kN): α ≈ 10⁻⁸ 1/Pa up to E' ≈ 2.5·10¹¹ Pa.
        row(
            "`math::series::ln_atanh` → `ln`",
            "1e-9 … 2.6e11 (network inputs)",
            (1e-9, 2.6e11, Geometric),
            Absolute,
            empty,
            math::series::ln_atanh,
            F32Ext::ln,
            libm::log,
        ),
        // The film from its logarithm: ln h in m, 10⁻¹¹ m (standstill floor) … 0.05 m (Martin's
        // film at 1 N).
        row(
            "`math::series::exp_taylor` → `exp`",
            "−25 … −3 (ln film in m)",
            (-25.0, -3.0, Linear),
            Relative,
            empty,
            math::series::exp_taylor,
            F32Ext::exp,
            libm::exp,
        ),
        // The regression film model (Moes' blend): x^y with Moes' exponents; one row at
        // y = −3.5, the largest |y| (errors of ln x are multiplied by y).
        row(
            "`math::pow(x, −3.5)` → `powf` (regression film model)",
            "1e-3 … 1e4 (Moes' H terms)",
            (1e-3, 1e4, Geometric),
            Relative,
            empty,
            |x| math::pow(x, -3.5),
            |x: f32| F32Ext::powf(x, -3.5),
            |x: f64| libm::pow(x, -3.5),
        ),
    ];
    for r in &rows {
        print(r);
    }
    // The sin_cos row counts one of its two outputs; both together, as the step uses them:
    let (lo, hi) = (0.0, 2.0 * core::f64::consts::PI);
    let both_core = cost(lo, hi, Linear, empty, math::sin_cos);
    let both_micro = cost(lo, hi, Linear, empty, F32Ext::sin_cos);
    hprintln!(
        "sin and cos together: core sin_cos {}, micromath sin_cos {} instructions",
        Counts(both_core),
        Counts(both_micro)
    );
    debug::exit(if calibration == 1000 {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {
        core::hint::spin_loop();
    }
}
