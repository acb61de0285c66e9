//! Where the instructions of a bearing step go: the instruction count (TIM2, see `counter`) of
//! the core's building blocks, each called once on typical hub-motor values, written to
//! `profile.csv` for the report. A measurement's own overhead (an empty call) is subtracted.

use crate::counter;
use crate::host_io::{HostFile, IoError};
use crate::kernel;
use bearing_core::contact::SlicedRoller;
use bearing_core::film::ann::AnnInt;
use bearing_core::{math, Bearing, BearingParams, FilmKind, FilmModel, OperatingState, Regression};
use core::hint::black_box;

/// Instructions of `f`, minus those of measuring nothing.
#[inline(never)]
fn measure<R>(f: impl FnOnce() -> R) -> u32 {
    let start = counter::now();
    black_box(f());
    counter::elapsed(start, counter::now()).instructions
}

/// A typical loaded hub-motor state: 6 µm towards −y, 21 000 rpm.
fn state() -> OperatingState {
    OperatingState {
        displacement_m: [0.0, -6.0e-6],
        velocity_m_s: [1.0e-4, 0.0],
        tilt_rad: [0.0; 2],
        shaft_speed_rad_s: 2199.0,
    }
}

/// Instructions of one real-time step (after a 3-step settle) of the hub-motor bearing with
/// `film` at `state`, cage angle 0.3 rad; `u32::MAX` if the core refuses. One bearing at a
/// time on the stack.
#[inline(never)]
fn step_cost(params: BearingParams, film: FilmKind, state: &OperatingState) -> u32 {
    let Ok(mut bearing) = Bearing::<17, { kernel::SLICES }>::new(params, film) else {
        return u32::MAX;
    };
    if bearing.set_cage_angle(0.3).is_err() || bearing.settle(state, 3).is_err() {
        return u32::MAX;
    }
    measure(|| bearing.advance(black_box(state), 1.0e-4).map(|o| o.force_n))
}

/// Writes `name,instructions` lines into `profile.csv`.
pub fn write_profile() -> Result<(), IoError> {
    let Ok(params) = kernel::params("hub_motor", "thesis_oil") else {
        return Err(IoError);
    };
    let roller = SlicedRoller::<{ kernel::SLICES }>::new(
        params.geometry(),
        params.reduced_modulus_pa(),
        params.law(),
    );
    let state = state();
    let contact = params.contact_input(false, 800.0, 2199.0);
    let empty = measure(|| ());
    let x = black_box(2.0f32);
    let entries: [(&str, u32); 17] = [
        (
            "f32::max(2, 1.5) (fmaxf call)",
            measure(|| black_box(x).max(black_box(1.5))),
        ),
        (
            "f32::max(2, 3) (fmaxf call)",
            measure(|| black_box(x).max(black_box(3.0))),
        ),
        (
            "f32::min(2, 3) (fminf call)",
            measure(|| black_box(x).min(black_box(3.0))),
        ),
        ("libm::sqrtf(2)", measure(|| libm::sqrtf(black_box(2.0)))),
        (
            "libm::sqrtf(1e-12)",
            measure(|| libm::sqrtf(black_box(1.0e-12))),
        ),
        (
            "libm::sqrtf(7.3e5)",
            measure(|| libm::sqrtf(black_box(7.3e5))),
        ),
        ("core math::ln", measure(|| math::ln(black_box(x)))),
        ("core math::exp", measure(|| math::exp(black_box(x)))),
        (
            "AnnInt::film, one contact",
            measure(|| AnnInt.film(black_box(&contact))),
        ),
        (
            "core math::pow",
            measure(|| math::pow(black_box(x), black_box(1.11))),
        ),
        (
            "core math::sin_cos",
            measure(|| math::sin_cos(black_box(x))),
        ),
        (
            "Regression::film, one contact",
            measure(|| Regression.film(black_box(&contact))),
        ),
        (
            "SlicedRoller::evaluate, 10 slices",
            measure(|| roller.evaluate(black_box(4.0e-6), black_box(0.0))),
        ),
        (
            "Bearing::advance dry, 17 rollers",
            step_cost(params, FilmKind::Dry, &state),
        ),
        (
            "Bearing::advance regression, 17 rollers",
            step_cost(params, FilmKind::Regression, &state),
        ),
        (
            "Bearing::advance int network, 17 rollers",
            step_cost(params, FilmKind::Int, &state),
        ),
        ("measurement overhead (subtracted)", empty),
    ];
    let mut file = HostFile::open(
        b"profile.csv\0",
        cortex_m_semihosting::nr::open::W_TRUNC_BINARY,
    )?;
    file.write_all(b"item,instructions\n")?;
    for (name, count) in entries {
        let net = if name.starts_with("measurement") {
            count
        } else {
            count.saturating_sub(empty)
        };
        defmt::info!("profile: {=str}: {=u32} instructions", name, net);
        file.write_all(name.as_bytes())?;
        file.write_all(b",")?;
        write_number(&mut file, net)?;
        file.write_all(b"\n")?;
    }
    Ok(())
}

/// `value` in decimal digits.
fn write_number(file: &mut HostFile, value: u32) -> Result<(), IoError> {
    let mut digits = [0u8; 10];
    let mut at = digits.len();
    let mut value = value;
    loop {
        at -= 1;
        digits[at] = b'0' + (value % 10) as u8;
        value /= 10;
        if value == 0 {
            break;
        }
    }
    file.write_all(&digits[at..])
}

/// The instructions of one real-time step (as [`step_cost`]) of a hub-motor-like bearing with
/// `Z` rollers of `S` slices each: the hub motor's design with 7 mm rollers, so that up to 25
/// fit its 60 mm pitch circle (the step's work does not depend on the geometry: the same
/// operations for every input). `u32::MAX` if the core refuses.
#[cfg(feature = "size-table")]
#[inline(never)]
fn sized_step_cost<const Z: usize, const S: usize>(film: FilmKind) -> u32 {
    let design = bearing_core::BearingDesign {
        roller_count: Z as u16,
        roller_diameter_m: 0.007,
        ..bearing_core::BearingDesign::HUB_MOTOR
    };
    let Ok(params) = design.params() else {
        return u32::MAX;
    };
    let Ok(mut bearing) = Bearing::<Z, S>::new(params, film) else {
        return u32::MAX;
    };
    let state = state();
    if bearing.set_cage_angle(0.3).is_err() || bearing.settle(&state, 3).is_err() {
        return u32::MAX;
    }
    measure(|| {
        bearing
            .advance(black_box(&state), 1.0e-4)
            .map(|o| o.force_n)
    })
}

/// Writes `rollers,slices,film,instructions` lines into `sizes.csv`: the step's instructions
/// for roller counts 8, 12, 17, 21, 25 and 5, 10, 20 slices per roller, integer network and
/// dry (`hil-sim/tools/size_table.py` builds this with the `size-table` feature and fits the
/// counts between them). Each size is a step of its own in the image.
#[cfg(feature = "size-table")]
pub fn write_sizes() -> Result<(), IoError> {
    macro_rules! sizes {
        ($(($z:literal, $s:literal)),*) => {
            [$(
                ($z, $s, "int", sized_step_cost::<$z, $s>(FilmKind::Int)),
                ($z, $s, "dry", sized_step_cost::<$z, $s>(FilmKind::Dry)),
            )*]
        };
    }
    let empty = measure(|| ());
    let rows: [(u32, u32, &str, u32); 30] = sizes!(
        (8, 5),
        (8, 10),
        (8, 20),
        (12, 5),
        (12, 10),
        (12, 20),
        (17, 5),
        (17, 10),
        (17, 20),
        (21, 5),
        (21, 10),
        (21, 20),
        (25, 5),
        (25, 10),
        (25, 20)
    );
    let mut file = HostFile::open(
        b"sizes.csv\0",
        cortex_m_semihosting::nr::open::W_TRUNC_BINARY,
    )?;
    file.write_all(b"rollers,slices,film,instructions\n")?;
    for (rollers, slices, film, count) in rows {
        let net = count.saturating_sub(empty);
        defmt::info!(
            "size table: {=u32} rollers, {=u32} slices, {=str}: {=u32} instructions",
            rollers,
            slices,
            film,
            net
        );
        for value in [rollers, slices] {
            write_number(&mut file, value)?;
            file.write_all(b",")?;
        }
        file.write_all(film.as_bytes())?;
        file.write_all(b",")?;
        write_number(&mut file, net)?;
        file.write_all(b"\n")?;
    }
    Ok(())
}
