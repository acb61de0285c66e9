//! `bearing_friction` gives C what the core's `Bearing::friction` gives Rust, bit for bit: the
//! friction torque, power loss and its split, and every roller's film ratios, for both bundled
//! bearings and every film model, along a short whirl; a step after it leaves those fields as
//! the call left them; the dry model's stay zero.

use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
mod common;

use bearing_ffi::*;
use std::mem::MaybeUninit;

/// Storage for one bearing, aligned to 8 bytes.
fn storage() -> Vec<u64> {
    vec![0; BEARING_STORAGE_SIZE / 8]
}

/// A bearing built by the C interface from `preset` with `film`.
fn c_bearing(place: &mut [u64], preset: u32, film: u32) -> *mut BearingHandle {
    // SAFETY: `place` holds BEARING_STORAGE_SIZE bytes aligned to 8 and outlives the handle.
    unsafe { common::bearing_from_preset(place.as_mut_ptr().cast(), preset, film) }
}

/// The inner race orbiting 1.5 µm around a 5 µm downward offset at ω = 1500 rad/s.
fn state(step: usize) -> OperatingState {
    let phase = step as f32 * 0.4;
    OperatingState::new(
        [1.5e-6 * phase.cos(), -5.0e-6 + 1.5e-6 * phase.sin()],
        [0.0; 2],
        [0.0; 2],
        1500.0,
    )
    .unwrap()
}

fn c_state(s: &OperatingState) -> BearingState {
    BearingState {
        displacement_m: s.displacement_m,
        velocity_m_s: s.velocity_m_s,
        tilt_rad: s.tilt_rad,
        shaft_speed_rad_s: s.shaft_speed_rad_s,
    }
}

/// The friction fields C sees, as bit patterns: torque, power loss, split, then per roller
/// λ_in, λ_out.
fn c_friction(out: &BearingOutput) -> Vec<u32> {
    let mut v = vec![out.friction_torque_nm, out.power_loss_w];
    v.extend(out.power_loss_split_w);
    for r in &out.rollers[..out.roller_count as usize] {
        v.extend([r.lambda_in, r.lambda_out]);
    }
    v.into_iter().map(f32::to_bits).collect()
}

/// The same fields of the core's output.
fn rust_friction<const Z: usize>(out: &bearing_core::BearingOutput<Z>) -> Vec<u32> {
    let mut v = vec![out.friction_torque_nm, out.power_loss_w];
    v.extend(out.power_loss_split_w);
    for lambda in &out.lambda {
        v.extend(lambda);
    }
    v.into_iter().map(f32::to_bits).collect()
}

fn compare<const Z: usize>(design: BearingDesign, preset: u32) {
    for (film, kind) in [
        (BearingFilm::Int, FilmKind::Int),
        (BearingFilm::F32, FilmKind::F32),
        (BearingFilm::Regression, FilmKind::Regression),
        (BearingFilm::Dry, FilmKind::Dry),
    ] {
        let mut place = storage();
        let handle = c_bearing(&mut place, preset, film as u32);
        let mut rust = Bearing::<Z, 10>::new(design.params().unwrap(), kind).unwrap();
        let mut out = MaybeUninit::<BearingOutput>::zeroed();
        let first = state(0);
        // SAFETY: a built handle and valid pointers throughout.
        unsafe {
            assert_eq!(
                bearing_settle(handle, &c_state(&first), 6, out.as_mut_ptr()),
                BearingStatus::Ok
            );
        }
        rust.settle(&first, 6).unwrap();
        for step in 1..12 {
            let s = state(step);
            // SAFETY: as above.
            let out = unsafe {
                assert_eq!(
                    bearing_advance(handle, &c_state(&s), 1.0e-4, out.as_mut_ptr()),
                    BearingStatus::Ok
                );
                assert_eq!(
                    bearing_friction(handle, s.shaft_speed_rad_s, out.as_mut_ptr()),
                    BearingStatus::Ok
                );
                out.assume_init_ref()
            };
            rust.advance(&s, 1.0e-4).unwrap();
            let expected = rust.friction(s.shaft_speed_rad_s).unwrap();
            let label = format!("{kind:?}, {Z} rollers, step {step}");
            assert_eq!(c_friction(out), rust_friction(expected), "{label}");
            assert_eq!(out.force_n, expected.force_n, "{label}");
            if kind == FilmKind::Dry {
                assert!(c_friction(out).iter().all(|&b| b == 0), "{label}");
            } else {
                assert!(out.power_loss_w > 0.0, "{label}: no power loss");
                assert!(out.rollers[0].lambda_in > 0.0, "{label}: no film ratio");
            }
        }
        // A step keeps the friction of the last call: the fields describe that call.
        // SAFETY: written by the calls above.
        let kept = c_friction(unsafe { out.assume_init_ref() });
        // SAFETY: as above.
        unsafe {
            assert_eq!(
                bearing_advance(handle, &c_state(&state(12)), 1.0e-4, out.as_mut_ptr()),
                BearingStatus::Ok
            );
            assert_eq!(c_friction(out.assume_init_ref()), kept);
        }
    }
}

#[test]
fn friction_is_the_cores_bit_for_bit() {
    compare::<17>(BearingDesign::HUB_MOTOR, BearingPreset::HubMotor as u32);
    compare::<12>(BearingDesign::NU205, BearingPreset::Nu205 as u32);
}

/// A shaft speed out of range is refused and named, and nothing is written.
#[test]
fn a_shaft_speed_out_of_range_is_refused_and_named() {
    let mut place = storage();
    let handle = c_bearing(&mut place, 0, BearingFilm::Int as u32);
    let mut out = MaybeUninit::<BearingOutput>::zeroed();
    let untouched = [0xA5u8; std::mem::size_of::<BearingOutput>()];
    // SAFETY: a built handle and valid pointers throughout.
    unsafe {
        out.as_mut_ptr()
            .cast::<u8>()
            .copy_from(untouched.as_ptr(), untouched.len());
        for speed in [f32::NAN, f32::INFINITY, 1.5e5, -1.5e5] {
            assert_eq!(
                bearing_friction(handle, speed, out.as_mut_ptr()),
                BearingStatus::InvalidArgument,
                "{speed}"
            );
            let bytes = std::slice::from_raw_parts(out.as_ptr().cast::<u8>(), untouched.len());
            assert_eq!(bytes, untouched, "{speed}: *out was written");
            let mut refusal = MaybeUninit::<BearingRefusal>::uninit();
            assert_eq!(
                bearing_last_refusal(handle, refusal.as_mut_ptr()),
                BearingStatus::Ok
            );
            let refusal = refusal.assume_init();
            assert_eq!(
                std::ffi::CStr::from_ptr(refusal.field.as_ptr())
                    .to_str()
                    .unwrap(),
                "shaft_speed_rad_s"
            );
            assert_eq!(refusal.allowed, BearingAllowed::Range as u32);
            assert_eq!((refusal.min, refusal.max), (-1.0e5, 1.0e5));
        }
    }
}
