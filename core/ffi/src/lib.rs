//! The C library of the bearing core (`include/bearing.h`, docs/c-api.md).
//!
//! A C program keeps the bearing in storage it provides (static, stack or heap:
//! `BEARING_STORAGE_SIZE` bytes aligned to `BEARING_STORAGE_ALIGN`, or the exact
//! `bearing_storage_size()` / `bearing_storage_align()`), builds it from a `BearingConfig` (the
//! core's `BearingDesign` field by field, and the film model) with `bearing_init`, and steps it
//! with `bearing_advance` (real time), `bearing_evaluate` (a trial) and `bearing_settle`;
//! `bearing_friction` adds the friction of the last step to its output. The Rust layout of the bearing stays behind the opaque `BearingHandle`.
//!
//! Every function checks every pointer (NULL, alignment, an initialised handle) and every
//! value (the core refuses non-finite and out-of-range numbers, naming the field) and returns
//! a `BearingStatus`; none allocates, none can panic (the core's no-panic lints apply to this
//! crate too), so nothing unwinds or aborts across the boundary. The functions keep no state
//! outside the handle: they are re-entrant, and distinct handles may be used from distinct
//! threads at once.
//!
//! `no_std`: on bare metal (`target_os = "none"`) the crate brings its own panic handler, which
//! nothing reaches (docs/c-api.md says how that is checked); on the host the standard library's
//! runtime is linked, as any host `staticlib` or `cdylib` needs.
#![no_std]
#![deny(missing_docs)]
// The core's no-panic rules (`cargo clippy-core`), for this crate's own code.
#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing
)]

#[cfg(not(target_os = "none"))]
extern crate std;

mod refusal;
mod storage;
mod types;

use bearing_core::{BearingDesign, OperatingState, ParamError};
use core::ffi::{c_char, c_void};
use core::mem::{align_of, size_of};
use refusal::{write_refusal, NO_REFUSAL};
use storage::{check_pointer, slot, write_slot, BuildError, Model, PointerError, Slot};

pub use storage::{BEARING_SLICES_PER_ROLLER, BEARING_STORAGE_ALIGN, BEARING_STORAGE_SIZE};
pub use types::{
    BearingAllowed, BearingConfig, BearingContactLaw, BearingFilm, BearingOutput, BearingPreset,
    BearingRefusal, BearingRollerOutput, BearingState, BearingStatus, BEARING_FIELD_NAME_LEN,
    BEARING_MAX_ROLLERS,
};

/// A bearing built by `bearing_init` in the caller's storage. Opaque: C only holds pointers.
pub struct BearingHandle {
    _opaque: [u8; 0],
}

/// Most steps `bearing_settle` takes in one call (the core needs 6 from a cold start).
pub const BEARING_MAX_SETTLE_STEPS: u32 = 1000;

impl From<PointerError> for BearingStatus {
    fn from(error: PointerError) -> Self {
        match error {
            PointerError::Null => BearingStatus::NullPointer,
            PointerError::Misaligned => BearingStatus::Misaligned,
            PointerError::NotInitialised => BearingStatus::NotInitialised,
        }
    }
}

/// Bytes of storage `bearing_init` needs on this target (at most `BEARING_STORAGE_SIZE`).
#[no_mangle]
pub extern "C" fn bearing_storage_size() -> usize {
    size_of::<Slot>()
}

/// Alignment in bytes the storage needs on this target (at most `BEARING_STORAGE_ALIGN`).
#[no_mangle]
pub extern "C" fn bearing_storage_align() -> usize {
    align_of::<Slot>()
}

/// A static NUL-terminated English sentence for a status code (any value, known or not).
#[no_mangle]
pub extern "C" fn bearing_error_message(status: u32) -> *const c_char {
    let text: &'static core::ffi::CStr = match status {
        0 => c"ok",
        1 => c"a pointer argument is NULL",
        2 => c"a pointer argument is not aligned for its type (storage: BEARING_STORAGE_ALIGN)",
        3 => c"the storage is smaller than bearing_storage_size()",
        4 => c"the handle does not point at a bearing built by bearing_init",
        5 => c"roller_count is valid but not one this library steps (12 or 17)",
        6 => c"film is not a BearingFilm value (0 int, 1 f32, 2 regression, 3 dry)",
        7 => c"contact_law is not a BearingContactLaw value (0 Palmgren, 1 Lundberg)",
        8 => c"preset is not a BearingPreset value (0 hub motor, 1 NU 205)",
        9 => c"a configuration field is out of its range (see the refusal)",
        10 => c"an operating-state field is out of its range or not finite (see the refusal)",
        11 => c"time_step_s is not finite or outside 0 ... 1 s",
        12 => c"an argument is out of its range (see the refusal)",
        _ => c"unknown status code",
    };
    text.as_ptr()
}

/// Fills `*out` with a bundled bearing (`BearingPreset`) and the integer film network.
///
/// # Safety
/// `out` is NULL or points at memory valid for writing a `BearingConfig`.
#[no_mangle]
pub unsafe extern "C" fn bearing_preset(preset: u32, out: *mut BearingConfig) -> BearingStatus {
    if let Err(e) = check_pointer(out) {
        return e.into();
    }
    let design = match preset {
        0 => BearingDesign::HUB_MOTOR,
        1 => BearingDesign::NU205,
        _ => return BearingStatus::UnknownPreset,
    };
    let config = BearingConfig {
        pitch_diameter_m: design.pitch_diameter_m,
        roller_diameter_m: design.roller_diameter_m,
        roller_length_m: design.roller_length_m,
        roller_count: u32::from(design.roller_count),
        radial_clearance_m: design.radial_clearance_m,
        crown_scale: design.crown_scale,
        elastic_modulus_pa: design.elastic_modulus_pa,
        poisson_ratio: design.poisson_ratio,
        viscosity_pa_s: design.viscosity_pa_s,
        pressure_viscosity_pa_inv: design.pressure_viscosity_pa_inv,
        density_kg_m3: design.density_kg_m3,
        contact_law: types::contact_law_value(design.contact_law),
        damping_factor_s: design.damping_factor_s,
        film: types::film_value(bearing_core::FilmKind::Int),
    };
    // SAFETY: non-NULL and aligned (checked), writable by the caller's contract.
    unsafe { out.write(config) };
    BearingStatus::Ok
}

/// Builds the bearing of `*config` in `storage` (`storage_len` bytes, aligned to
/// `bearing_storage_align()`) and sets `*handle_out` to it. A refused configuration field is
/// described in `*refusal` unless `refusal` is NULL (its `field` is empty when no field was
/// refused).
///
/// # Safety
/// `storage` is NULL or valid for writes of `storage_len` bytes, owned by the caller until
/// the handle is no longer used, and not accessed but through the handle; `config` is NULL or
/// points at a readable `BearingConfig`; `handle_out` and `refusal` are NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn bearing_init(
    storage: *mut c_void,
    storage_len: usize,
    config: *const BearingConfig,
    handle_out: *mut *mut BearingHandle,
    refusal: *mut BearingRefusal,
) -> BearingStatus {
    let storage = storage.cast::<Slot>();
    // A NULL `refusal` asks for no description; a misaligned one is refused like the others.
    let refusal_check = if refusal.is_null() {
        Ok(())
    } else {
        check_pointer(refusal.cast_const())
    };
    for check in [
        check_pointer(storage.cast_const()),
        check_pointer(config),
        check_pointer(handle_out.cast_const()),
        refusal_check,
    ] {
        if let Err(e) = check {
            return e.into();
        }
    }
    let refusal_ok = !refusal.is_null();
    if refusal_ok {
        // SAFETY: non-NULL and aligned (checked), writable by the caller's contract.
        unsafe { refusal.write(NO_REFUSAL) };
    }
    if storage_len < size_of::<Slot>() {
        return BearingStatus::StorageTooSmall;
    }
    // SAFETY: non-NULL and aligned (checked), readable by the caller's contract; every bit
    // pattern is a valid `BearingConfig` (integers and floats only).
    let config = unsafe { config.read() };
    let Some(film) = types::film_kind(config.film) else {
        return BearingStatus::UnknownFilm;
    };
    let Some(contact_law) = types::contact_law(config.contact_law) else {
        return BearingStatus::UnknownContactLaw;
    };
    let refuse = |error: ParamError| {
        if refusal_ok {
            // SAFETY: as above.
            unsafe { write_refusal(refusal, &error) };
        }
        BearingStatus::InvalidConfig
    };
    let Ok(roller_count) = u16::try_from(config.roller_count) else {
        return refuse(ParamError {
            field: "roller_count",
            value: config.roller_count as f32,
            allowed: bearing_core::Allowed::Range {
                min: 3.0,
                max: 128.0,
            },
        });
    };
    let design = BearingDesign {
        pitch_diameter_m: config.pitch_diameter_m,
        roller_diameter_m: config.roller_diameter_m,
        roller_length_m: config.roller_length_m,
        roller_count,
        radial_clearance_m: config.radial_clearance_m,
        crown_scale: config.crown_scale,
        elastic_modulus_pa: config.elastic_modulus_pa,
        poisson_ratio: config.poisson_ratio,
        viscosity_pa_s: config.viscosity_pa_s,
        pressure_viscosity_pa_inv: config.pressure_viscosity_pa_inv,
        density_kg_m3: config.density_kg_m3,
        contact_law,
        damping_factor_s: config.damping_factor_s,
    };
    let params = match design.params() {
        Ok(params) => params,
        Err(error) => return refuse(error),
    };
    let model = match Model::new(params, film) {
        Ok(model) => model,
        Err(BuildError::UnsupportedRollerCount) => return BearingStatus::UnsupportedRollerCount,
        Err(BuildError::Refused(error)) => return refuse(error),
    };
    // SAFETY: `storage` is non-NULL, aligned and at least `size_of::<Slot>()` bytes (checked),
    // writable by the caller's contract; `handle_out` is non-NULL and aligned (checked).
    unsafe {
        write_slot(storage, model);
        handle_out.write(storage.cast::<BearingHandle>());
    }
    BearingStatus::Ok
}

/// The status a result stands for.
fn status(result: Result<(), BearingStatus>) -> BearingStatus {
    match result {
        Ok(()) => BearingStatus::Ok,
        Err(status) => status,
    }
}

/// The slot behind a handle, or the status that refuses the handle.
///
/// # Safety
/// As `bearing_advance` for `handle`.
unsafe fn slot_of<'a>(handle: *mut BearingHandle) -> Result<&'a mut Slot, BearingStatus> {
    // SAFETY: the caller's contract.
    unsafe { slot(handle.cast::<Slot>()) }.map_err(BearingStatus::from)
}

/// Remembers a refused input for `bearing_last_refusal` and returns `status`.
fn refused(slot: &mut Slot, error: ParamError, status: BearingStatus) -> BearingStatus {
    slot.refusal = Some(error);
    status
}

/// Writes the output of the slot's last computing call and its committed cage angle to `out`.
///
/// # Safety
/// `out` is non-NULL, aligned and writable, and does not overlap the slot.
unsafe fn write_output(slot: &Slot, out: *mut BearingOutput) {
    let bearing = slot.model.bearing();
    // SAFETY: the caller's contract.
    unsafe { BearingOutput::write(&bearing.output(), bearing.cage_angle_rad(), out) }
}

/// Which computing call a step function makes.
#[derive(Clone, Copy)]
enum Call {
    Advance(f32),
    Evaluate(f32),
    Settle(u32),
}

/// The common part of the step functions: check the pointers, read the state, call the core,
/// write the output.
///
/// # Safety
/// As `bearing_advance`.
unsafe fn step(
    handle: *mut BearingHandle,
    state: *const BearingState,
    out: *mut BearingOutput,
    call: Call,
) -> Result<(), BearingStatus> {
    check_pointer(state)?;
    check_pointer(out.cast_const())?;
    // SAFETY: the caller's contract for `handle`.
    let slot = unsafe { slot_of(handle) }?;
    // SAFETY: non-NULL and aligned (checked), readable by the caller's contract; any bit
    // pattern is a valid `BearingState`.
    let state = unsafe { state.read() };
    let state = OperatingState::new(
        state.displacement_m,
        state.velocity_m_s,
        state.tilt_rad,
        state.shaft_speed_rad_s,
    )
    .map_err(|error| refused(slot, error, BearingStatus::InvalidState))?;
    let bearing = slot.model.bearing_mut();
    let result = match call {
        Call::Advance(dt_s) => bearing.advance(&state, dt_s).map(|_| ()),
        Call::Evaluate(dt_s) => bearing.evaluate(&state, dt_s).map(|_| ()),
        Call::Settle(steps) if (1..=BEARING_MAX_SETTLE_STEPS).contains(&steps) => {
            bearing.settle(&state, steps as usize).map(|_| ())
        }
        Call::Settle(steps) => {
            let error = ParamError {
                field: "settle_steps",
                value: steps as f32,
                allowed: bearing_core::Allowed::Range {
                    min: 1.0,
                    max: BEARING_MAX_SETTLE_STEPS as f32,
                },
            };
            return Err(refused(slot, error, BearingStatus::InvalidArgument));
        }
    };
    // The core checks the state again and the time step: a refused time step names
    // `time_step_s`.
    result.map_err(|error| {
        let status = if error.field == "time_step_s" {
            BearingStatus::InvalidTimeStep
        } else {
            BearingStatus::InvalidState
        };
        refused(slot, error, status)
    })?;
    // SAFETY: non-NULL and aligned (checked), writable and apart from the storage by the
    // caller's contract.
    unsafe { write_output(slot, out) };
    Ok(())
}

/// The real-time step: time moves on by `dt_s` (s, 0 … 1) to the inner-race motion `*state`;
/// the cage turns, the warm start and one film-table node carry to the next step. The same
/// work at every step. On a refusal nothing is committed and `*out` is left as it was.
///
/// # Safety
/// `handle` is NULL or points into storage the caller owns (initialised by `bearing_init`, or
/// memory whose first four bytes are not the library's tag); `state` is NULL or readable;
/// `out` is NULL or writable and does not overlap the storage.
#[no_mangle]
pub unsafe extern "C" fn bearing_advance(
    handle: *mut BearingHandle,
    state: *const BearingState,
    dt_s: f32,
    out: *mut BearingOutput,
) -> BearingStatus {
    // SAFETY: the caller's contract, as `step` needs it.
    status(unsafe { step(handle, state, out, Call::Advance(dt_s)) })
}

/// A trial for implicit integrators: the output at `*state`, `dt_s` after the committed state,
/// which is left as it was (the result depends on it and the arguments alone, bit for bit).
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_evaluate(
    handle: *mut BearingHandle,
    state: *const BearingState,
    dt_s: f32,
    out: *mut BearingOutput,
) -> BearingStatus {
    // SAFETY: the caller's contract, as `step` needs it.
    status(unsafe { step(handle, state, out, Call::Evaluate(dt_s)) })
}

/// Converges the warm start at `*state` with `steps` (1 … `BEARING_MAX_SETTLE_STEPS`)
/// committing steps and no time passing; 6 reach |Δh|/h ≤ 10⁻³ from a cold start. Call it
/// once before a real-time loop.
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_settle(
    handle: *mut BearingHandle,
    state: *const BearingState,
    steps: u32,
    out: *mut BearingOutput,
) -> BearingStatus {
    // SAFETY: the caller's contract, as `step` needs it.
    status(unsafe { step(handle, state, out, Call::Settle(steps)) })
}

/// The friction of the last computing call's output (the core's `Bearing::friction`,
/// docs/physics.md §8): fills every roller's film ratios `lambda_in`, `lambda_out` and the
/// bearing's `friction_torque_nm`, `power_loss_w` and `power_loss_split_w` at the shaft speed
/// `shaft_speed_rad_s` of that step (rad/s, |ω| ≤ 10⁵), and writes the whole output to `*out`.
/// The same work at every call (≈ 35 000 Cortex-M4 instructions for 17 rollers), kept out of
/// the step functions so that a real-time loop pays for it only at the rate it wants the
/// friction. The dry film model has none: its friction fields stay zero. On a refusal
/// (`BEARING_STATUS_INVALID_ARGUMENT`, the refusal names `shaft_speed_rad_s`) nothing is
/// changed and `*out` is left as it was.
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_friction(
    handle: *mut BearingHandle,
    shaft_speed_rad_s: f32,
    out: *mut BearingOutput,
) -> BearingStatus {
    let result = check_pointer(out.cast_const())
        .map_err(BearingStatus::from)
        // SAFETY: the caller's contract for `handle`.
        .and_then(|()| unsafe { slot_of(handle) })
        .and_then(|slot| {
            match slot.model.bearing_mut().friction(shaft_speed_rad_s) {
                Ok(_) => {
                    // SAFETY: non-NULL and aligned (checked), writable and apart from the
                    // storage by the caller's contract.
                    unsafe { write_output(slot, out) };
                    Ok(())
                }
                Err(error) => Err(refused(slot, error, BearingStatus::InvalidArgument)),
            }
        });
    status(result)
}

/// The output of the last computing call (all zero before the first) and the committed cage
/// angle.
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_output(
    handle: *mut BearingHandle,
    out: *mut BearingOutput,
) -> BearingStatus {
    // SAFETY: the caller's contract for `handle` and `out`.
    status(unsafe {
        check_pointer(out.cast_const())
            .map_err(BearingStatus::from)
            .and_then(|()| slot_of(handle))
            .map(|slot| write_output(slot, out))
    })
}

/// Sets the cage angle θ_c (rad, |θ_c| ≤ 10⁴), wrapped by whole turns.
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_set_cage_angle(
    handle: *mut BearingHandle,
    cage_angle_rad: f32,
) -> BearingStatus {
    // SAFETY: the caller's contract for `handle`.
    status(unsafe { slot_of(handle) }.and_then(|slot| {
        slot.model
            .bearing_mut()
            .set_cage_angle(cage_angle_rad)
            .map_err(|error| refused(slot, error, BearingStatus::InvalidArgument))
    }))
}

/// Forgets the warm start and the film table (the next step starts from unloaded rollers);
/// the cage angle is kept.
///
/// # Safety
/// As `bearing_advance`.
#[no_mangle]
pub unsafe extern "C" fn bearing_reset(handle: *mut BearingHandle) -> BearingStatus {
    // SAFETY: the caller's contract for `handle`.
    status(unsafe { slot_of(handle) }.map(|slot| slot.model.bearing_mut().reset()))
}

/// Describes the last input a step function, `bearing_friction` or `bearing_set_cage_angle` refused on this
/// bearing (`field` empty when none was).
///
/// # Safety
/// As `bearing_advance`; `out` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn bearing_last_refusal(
    handle: *mut BearingHandle,
    out: *mut BearingRefusal,
) -> BearingStatus {
    let result = check_pointer(out.cast_const())
        .map_err(BearingStatus::from)
        // SAFETY: the caller's contract for `handle`.
        .and_then(|()| unsafe { slot_of(handle) })
        .map(|slot| match &slot.refusal {
            // SAFETY: non-NULL and aligned (checked), writable by the caller's contract.
            Some(error) => unsafe { write_refusal(out, error) },
            // SAFETY: as above.
            None => unsafe { out.write(NO_REFUSAL) },
        });
    status(result)
}

/// Nothing reaches it: every exported function returns a status for every input and the core
/// never panics (docs/c-api.md, "No panic, no unwind"). With the feature `prove-no-panic` it
/// calls a symbol nothing defines, so a linked program that keeps any path to it does not link.
#[cfg(target_os = "none")]
#[panic_handler]
fn panic(_info: &core::panic::PanicInfo) -> ! {
    #[cfg(feature = "prove-no-panic")]
    {
        extern "C" {
            fn bearing_ffi_panic_is_reachable() -> !;
        }
        // SAFETY: never defined: a program that keeps this call fails to link.
        unsafe { bearing_ffi_panic_is_reachable() }
    }
    #[cfg(not(feature = "prove-no-panic"))]
    loop {
        core::hint::spin_loop();
    }
}
