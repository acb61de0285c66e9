//! The C boundary under hostile arguments, called from Rust exactly as C calls it (the
//! `extern "C"` functions through raw pointers): NULL, misaligned, too small or uninitialised
//! storage, non-finite and out-of-range numbers, unknown enum values. Thousands of random
//! argument sets (proptest) must each give a documented status — the pointer errors before
//! anything is read — leave `*out` untouched and the bearing uncommitted on a refusal, and give
//! finite outputs on success. A panic would abort the test process (an `extern "C"` function
//! cannot unwind), so a run that completes also shows that none occurred.

mod common;

use bearing_ffi::*;
use proptest::prelude::*;
use std::ffi::CStr;
use std::mem::{size_of, MaybeUninit};

/// Storage aligned for the bearing, with room to be offset.
struct Buffer(Vec<u64>);

impl Buffer {
    fn new() -> Self {
        Buffer(vec![0; BEARING_STORAGE_SIZE / 8 + 2])
    }
    fn ptr(&mut self, offset: usize) -> *mut u8 {
        // SAFETY: `offset` < 16 stays inside the buffer, which has 16 bytes to spare.
        unsafe { self.0.as_mut_ptr().cast::<u8>().add(offset) }
    }
}

/// How a pointer argument is passed.
#[derive(Clone, Copy, Debug)]
enum Arg {
    Null,
    /// Offset by 1 … 3 bytes from an aligned address.
    Misaligned(usize),
    Valid,
}

fn arg() -> impl Strategy<Value = Arg> {
    prop_oneof![
        1 => Just(Arg::Null),
        1 => (1usize..4).prop_map(Arg::Misaligned),
        4 => Just(Arg::Valid),
    ]
}

/// A pointer of kind `arg` to a value in `place` (an 8-aligned buffer with room for the offset).
fn pointer<T>(arg: Arg, place: &mut [u64]) -> *mut T {
    assert!(size_of::<T>() + 8 <= place.len() * 8);
    let base = place.as_mut_ptr().cast::<u8>();
    match arg {
        Arg::Null => std::ptr::null_mut(),
        // SAFETY: inside `place`.
        Arg::Misaligned(offset) => unsafe { base.add(offset) }.cast(),
        Arg::Valid => base.cast(),
    }
}

/// Any f32: every bit pattern (NaN payloads, infinities, subnormals) or an edge value.
fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        any::<u32>().prop_map(f32::from_bits),
        prop::sample::select(vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            f32::MIN_POSITIVE,
            f32::MAX,
            -f32::MAX,
            1.0e-3,
            -1.0e-3,
            1.0e5,
            1.0e4,
        ]),
    ]
}

/// A plausible value of one state field, or a hostile one.
fn state_value(typical: f32) -> impl Strategy<Value = f32> {
    prop_oneof![8 => -typical..typical, 1 => any_f32()]
}

fn state() -> impl Strategy<Value = BearingState> {
    (
        [state_value(2.0e-5), state_value(2.0e-5)],
        [state_value(0.05), state_value(0.05)],
        [state_value(1.0e-4), state_value(1.0e-4)],
        state_value(3000.0),
    )
        .prop_map(|(d, v, t, w)| BearingState {
            displacement_m: d,
            velocity_m_s: v,
            tilt_rad: t,
            shaft_speed_rad_s: w,
        })
}

/// A preset with some fields replaced by hostile values.
fn config() -> impl Strategy<Value = BearingConfig> {
    (
        0u32..2,
        prop::collection::vec((0usize..14, any_f32(), any::<u32>()), 0..3),
        prop_oneof![4 => 0u32..4, 1 => any::<u32>()],
    )
        .prop_map(|(preset, changes, film)| {
            let mut c = MaybeUninit::<BearingConfig>::uninit();
            // SAFETY: a valid, aligned pointer to a BearingConfig.
            assert_eq!(
                unsafe { bearing_preset(preset, c.as_mut_ptr()) },
                BearingStatus::Ok
            );
            // SAFETY: bearing_preset returned Ok, so it wrote the whole value.
            let mut c = unsafe { c.assume_init() };
            c.film = film;
            for (field, value, integer) in changes {
                match field {
                    0 => c.pitch_diameter_m = value,
                    1 => c.roller_diameter_m = value,
                    2 => c.roller_length_m = value,
                    3 => c.roller_count = integer % 200,
                    4 => c.radial_clearance_m = value,
                    5 => c.crown_scale = value,
                    6 => c.elastic_modulus_pa = value,
                    7 => c.poisson_ratio = value,
                    8 => c.viscosity_pa_s = value,
                    9 => c.pressure_viscosity_pa_inv = value,
                    10 => c.density_kg_m3 = value,
                    11 => c.contact_law = integer,
                    12 => c.damping_factor_s = value,
                    _ => c.roller_count = integer,
                }
            }
            c
        })
}

/// The pointer status of `args` in order, or `None` when every pointer is usable.
fn pointer_status(args: &[Arg]) -> Option<BearingStatus> {
    args.iter().find_map(|a| match a {
        Arg::Null => Some(BearingStatus::NullPointer),
        Arg::Misaligned(_) => Some(BearingStatus::Misaligned),
        Arg::Valid => None,
    })
}

fn bytes_of<T>(value: *const T) -> Vec<u8> {
    // SAFETY: `value` points at an initialised T (the tests fill every out buffer first).
    unsafe { std::slice::from_raw_parts(value.cast::<u8>(), size_of::<T>()).to_vec() }
}

fn all_finite(out: &BearingOutput) -> bool {
    let mut values = vec![out.cage_angle_rad];
    values.extend(out.force_n.iter().chain(&out.moment_nm));
    values.extend(out.stiffness.iter().flatten());
    values.extend(out.damping_n_s_per_m.iter().flatten());
    values.extend([
        out.centrifugal_force_n,
        out.friction_torque_nm,
        out.power_loss_w,
    ]);
    values.extend(out.power_loss_split_w);
    for r in &out.rollers[..out.roller_count as usize] {
        values.extend([
            r.load_n,
            r.central_film_in_m,
            r.central_film_out_m,
            r.approach_m,
            r.contact_stiffness_n_per_m,
            r.roller_stiffness_n_per_m,
            r.damping_force_n,
            r.lambda_in,
            r.lambda_out,
        ]);
    }
    values.iter().all(|v| v.is_finite())
}

/// A bearing built in `buffer` from a preset with `film`.
fn built(buffer: &mut Buffer, preset: u32, film: u32) -> *mut BearingHandle {
    // SAFETY: the buffer holds BEARING_STORAGE_SIZE aligned bytes and outlives the handle.
    unsafe { common::bearing_from_preset(buffer.ptr(0).cast(), preset, film) }
}

/// One call of the step interface with hostile arguments.
#[derive(Clone, Debug)]
enum Call {
    Advance(Arg, BearingState, f32, Arg),
    Evaluate(Arg, BearingState, f32, Arg),
    Settle(Arg, BearingState, u32, Arg),
    Output(Arg),
    Friction(f32, Arg),
    SetCageAngle(f32),
    Reset,
    LastRefusal(Arg),
}

fn call() -> impl Strategy<Value = Call> {
    let dt = || prop_oneof![3 => 0.0f32..1.0e-3, 1 => any_f32()];
    let steps = prop_oneof![3 => 0u32..8, 1 => any::<u32>()];
    prop_oneof![
        4 => (arg(), state(), dt(), arg()).prop_map(|(s, x, d, o)| Call::Advance(s, x, d, o)),
        2 => (arg(), state(), dt(), arg()).prop_map(|(s, x, d, o)| Call::Evaluate(s, x, d, o)),
        1 => (arg(), state(), steps, arg()).prop_map(|(s, x, n, o)| Call::Settle(s, x, n, o)),
        1 => arg().prop_map(Call::Output),
        2 => (state_value(2.0e3), arg()).prop_map(|(w, o)| Call::Friction(w, o)),
        1 => any_f32().prop_map(Call::SetCageAngle),
        1 => Just(Call::Reset),
        1 => arg().prop_map(Call::LastRefusal),
    ]
}

/// The committed state of a bearing as far as C sees it: its last output and cage angle.
fn committed(handle: *mut BearingHandle) -> Vec<u8> {
    let mut out = MaybeUninit::<BearingOutput>::zeroed();
    // SAFETY: a built handle and a valid output pointer.
    assert_eq!(
        unsafe { bearing_output(handle, out.as_mut_ptr()) },
        BearingStatus::Ok
    );
    bytes_of(out.as_ptr())
}

/// Runs `call` on `handle`; checks the status against the pointers and, on a refusal, that
/// `*out` and the committed state are untouched.
fn check_call(handle: *mut BearingHandle, call: &Call) -> BearingStatus {
    let mut state_place = vec![0u64; size_of::<BearingState>() / 8 + 2];
    let mut out_place = vec![0xA5A5_A5A5_A5A5_A5A5u64; size_of::<BearingOutput>() / 8 + 2];
    let before_out = out_place.clone();
    let before = committed(handle);
    let stepped = |s: Arg,
                   x: &BearingState,
                   o: Arg,
                   f: &dyn Fn(*const BearingState, *mut BearingOutput) -> BearingStatus,
                   state_place: &mut Vec<u64>,
                   out_place: &mut Vec<u64>| {
        let sp: *mut BearingState = pointer(s, state_place);
        if !sp.is_null() {
            // SAFETY: inside `state_place`; unaligned write for the misaligned case.
            unsafe { sp.write_unaligned(*x) };
        }
        let op: *mut BearingOutput = pointer(o, out_place);
        let status = f(sp, op);
        if let Some(expected) = pointer_status(&[s, o]) {
            assert_eq!(status, expected, "{call:?}");
        }
        if status == BearingStatus::Ok {
            // SAFETY: Ok means the library wrote a whole output at the valid pointer.
            assert!(all_finite(unsafe { &*op }), "{call:?}");
        }
        status
    };
    // SAFETY: every pointer is NULL, misaligned inside a live buffer, or valid; `handle` is a
    // built bearing.
    let status = unsafe {
        match *call {
            Call::Advance(s, ref x, dt, o) => stepped(
                s,
                x,
                o,
                &|sp, op| bearing_advance(handle, sp, dt, op),
                &mut state_place,
                &mut out_place,
            ),
            Call::Evaluate(s, ref x, dt, o) => stepped(
                s,
                x,
                o,
                &|sp, op| bearing_evaluate(handle, sp, dt, op),
                &mut state_place,
                &mut out_place,
            ),
            Call::Settle(s, ref x, n, o) => stepped(
                s,
                x,
                o,
                &|sp, op| bearing_settle(handle, sp, n, op),
                &mut state_place,
                &mut out_place,
            ),
            Call::Output(o) => {
                let status = bearing_output(handle, pointer(o, &mut out_place));
                assert_eq!(status, pointer_status(&[o]).unwrap_or(BearingStatus::Ok));
                status
            }
            Call::Friction(speed, o) => {
                let op: *mut BearingOutput = pointer(o, &mut out_place);
                let status = bearing_friction(handle, speed, op);
                let allowed = speed.is_finite() && speed.abs() <= 1.0e5;
                let expected = match pointer_status(&[o]) {
                    Some(pointer) => pointer,
                    None if allowed => BearingStatus::Ok,
                    None => BearingStatus::InvalidArgument,
                };
                assert_eq!(status, expected, "{call:?}");
                if status == BearingStatus::Ok {
                    // Ok means the library wrote a whole output at the valid pointer.
                    assert!(all_finite(&*op), "{call:?}");
                }
                status
            }
            Call::SetCageAngle(angle) => {
                let status = bearing_set_cage_angle(handle, angle);
                let allowed = angle.is_finite() && angle.abs() <= 1.0e4;
                let expected = if allowed {
                    BearingStatus::Ok
                } else {
                    BearingStatus::InvalidArgument
                };
                assert_eq!(status, expected, "{call:?}");
                status
            }
            Call::Reset => bearing_reset(handle),
            Call::LastRefusal(o) => {
                let mut place = vec![0u64; size_of::<BearingRefusal>() / 8 + 2];
                let status = bearing_last_refusal(handle, pointer(o, &mut place));
                assert_eq!(status, pointer_status(&[o]).unwrap_or(BearingStatus::Ok));
                status
            }
        }
    };
    let computing = matches!(
        call,
        Call::Advance(..) | Call::Evaluate(..) | Call::Settle(..) | Call::Friction(..)
    );
    if computing && status != BearingStatus::Ok {
        assert_eq!(out_place, before_out, "a refused call wrote *out: {call:?}");
        assert_eq!(
            committed(handle),
            before,
            "a refused call changed the bearing: {call:?}"
        );
        if status != BearingStatus::NullPointer && status != BearingStatus::Misaligned {
            let mut refusal = MaybeUninit::<BearingRefusal>::uninit();
            // SAFETY: a built handle and a valid pointer.
            let refusal = unsafe {
                assert_eq!(
                    bearing_last_refusal(handle, refusal.as_mut_ptr()),
                    BearingStatus::Ok
                );
                refusal.assume_init()
            };
            assert_ne!(
                refusal.field[0], 0,
                "a refusal without a field name: {call:?}"
            );
        }
    }
    status
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    /// bearing_init with hostile storage, configuration and out pointers.
    #[test]
    fn init_refuses_with_a_status(
        storage in arg(),
        storage_len in prop_oneof![Just(BEARING_STORAGE_SIZE), 0usize..BEARING_STORAGE_SIZE, any::<usize>()],
        config_arg in arg(),
        config in config(),
        handle_arg in arg(),
        refusal_arg in arg(),
    ) {
        let mut buffer = Buffer::new();
        let storage_ptr = match storage {
            Arg::Null => std::ptr::null_mut(),
            Arg::Misaligned(offset) => buffer.ptr(offset),
            Arg::Valid => buffer.ptr(0),
        };
        // A pointer past the end of the buffer would be reported as too small only after
        // being written, so lengths beyond the buffer are passed for NULL storage alone.
        let storage_len = if storage_ptr.is_null() { storage_len } else { storage_len.min(BEARING_STORAGE_SIZE) };
        let mut config_place = vec![0u64; size_of::<BearingConfig>() / 8 + 2];
        let config_ptr: *mut BearingConfig = pointer(config_arg, &mut config_place);
        if !config_ptr.is_null() {
            // SAFETY: inside `config_place`.
            unsafe { config_ptr.write_unaligned(config) };
        }
        let mut handle_place = vec![0u64; 2];
        let handle_ptr: *mut *mut BearingHandle = pointer(handle_arg, &mut handle_place);
        let mut refusal_place = vec![0u64; size_of::<BearingRefusal>() / 8 + 2];
        let refusal_ptr: *mut BearingRefusal = pointer(refusal_arg, &mut refusal_place);
        // SAFETY: every pointer is NULL or inside a live buffer.
        let status = unsafe { bearing_init(storage_ptr.cast(), storage_len, config_ptr, handle_ptr, refusal_ptr) };
        // A NULL refusal pointer is allowed (no description wanted); a misaligned one is not.
        let refusal_check = if matches!(refusal_arg, Arg::Null) { Arg::Valid } else { refusal_arg };
        if let Some(expected) = pointer_status(&[storage, config_arg, handle_arg, refusal_check]) {
            prop_assert_eq!(status, expected);
        } else if storage_len < bearing_storage_size() {
            prop_assert_eq!(status, BearingStatus::StorageTooSmall);
        }
        if status == BearingStatus::Ok {
            // SAFETY: Ok wrote the handle.
            prop_assert_eq!(unsafe { handle_ptr.read() }.cast::<u8>(), storage_ptr);
            prop_assert!(config.film < 4 && config.contact_law < 2);
        }
        if status == BearingStatus::InvalidConfig && matches!(refusal_arg, Arg::Valid) {
            // SAFETY: bearing_init wrote the refusal at the valid pointer.
            let refusal = unsafe { refusal_ptr.read() };
            prop_assert_ne!(refusal.field[0], 0);
        }
    }

    /// Random sequences of step calls with hostile arguments on a built bearing.
    #[test]
    fn step_functions_refuse_with_a_status(
        preset in 0u32..2,
        film in 0u32..4,
        calls in prop::collection::vec(call(), 1..6),
    ) {
        let mut buffer = Buffer::new();
        let handle = built(&mut buffer, preset, film);
        for call in &calls {
            check_call(handle, call);
        }
    }

    /// Every status code, known or not, has a static non-empty sentence.
    #[test]
    fn every_status_has_a_message(code in any::<u32>()) {
        // SAFETY: bearing_error_message returns a static NUL-terminated string.
        let text = unsafe { CStr::from_ptr(bearing_error_message(code)) };
        prop_assert!(!text.to_bytes().is_empty());
    }
}

/// Zeroed, misaligned and NULL handles are refused by every function that takes one.
#[test]
fn handles_not_built_by_init_are_refused() {
    let mut buffer = Buffer::new();
    let state = BearingState {
        displacement_m: [0.0, -5.0e-6],
        velocity_m_s: [0.0; 2],
        tilt_rad: [0.0; 2],
        shaft_speed_rad_s: 1000.0,
    };
    let mut out = MaybeUninit::<BearingOutput>::uninit();
    let mut refusal = MaybeUninit::<BearingRefusal>::uninit();
    for (handle, expected) in [
        (buffer.ptr(0), BearingStatus::NotInitialised),
        (buffer.ptr(4), BearingStatus::Misaligned),
        (std::ptr::null_mut(), BearingStatus::NullPointer),
    ] {
        let handle = handle.cast::<BearingHandle>();
        // SAFETY: the handle points into a live zeroed buffer or is NULL; other pointers valid.
        unsafe {
            assert_eq!(
                bearing_advance(handle, &state, 1e-4, out.as_mut_ptr()),
                expected
            );
            assert_eq!(
                bearing_evaluate(handle, &state, 1e-4, out.as_mut_ptr()),
                expected
            );
            assert_eq!(
                bearing_settle(handle, &state, 6, out.as_mut_ptr()),
                expected
            );
            assert_eq!(bearing_output(handle, out.as_mut_ptr()), expected);
            assert_eq!(bearing_friction(handle, 1000.0, out.as_mut_ptr()), expected);
            assert_eq!(bearing_set_cage_angle(handle, 0.0), expected);
            assert_eq!(bearing_reset(handle), expected);
            assert_eq!(bearing_last_refusal(handle, refusal.as_mut_ptr()), expected);
        }
    }
}

/// The header's storage constants cover this target's bearing (the library also checks this
/// at compile time, for every target it is built for).
#[test]
fn storage_constants_cover_the_bearing() {
    assert!(bearing_storage_size() <= BEARING_STORAGE_SIZE);
    assert!(bearing_storage_align() <= BEARING_STORAGE_ALIGN);
    assert!(BEARING_STORAGE_SIZE % bearing_storage_align() == 0);
}

/// A refused configuration names its field and range; a valid one with an unsupported roller
/// count gives its own status.
#[test]
fn refusals_name_the_field_and_range() {
    let mut buffer = Buffer::new();
    let mut config = MaybeUninit::<BearingConfig>::uninit();
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(bearing_preset(0, config.as_mut_ptr()), BearingStatus::Ok);
        let preset = config.assume_init();
        let mut handle = std::ptr::null_mut();
        let mut refusal = MaybeUninit::<BearingRefusal>::uninit();
        let bad = BearingConfig {
            poisson_ratio: 0.7,
            ..preset
        };
        let status = bearing_init(
            buffer.ptr(0).cast(),
            BEARING_STORAGE_SIZE,
            &bad,
            &mut handle,
            refusal.as_mut_ptr(),
        );
        assert_eq!(status, BearingStatus::InvalidConfig);
        let refusal = refusal.assume_init();
        assert_eq!(
            CStr::from_ptr(refusal.field.as_ptr()).to_str().unwrap(),
            "poisson_ratio"
        );
        assert_eq!(refusal.value, 0.7);
        assert_eq!(refusal.allowed, BearingAllowed::Range as u32);
        assert_eq!((refusal.min, refusal.max), (0.0, 0.5));

        let fourteen = BearingConfig {
            roller_count: 14,
            ..preset
        };
        let status = bearing_init(
            buffer.ptr(0).cast(),
            BEARING_STORAGE_SIZE,
            &fourteen,
            &mut handle,
            std::ptr::null_mut(),
        );
        assert_eq!(status, BearingStatus::UnsupportedRollerCount);
    }
}
