//! What several of the C interface's test files need: a bearing built from a preset.

use bearing_ffi::*;
use std::mem::MaybeUninit;

/// A bearing built by the C interface from `preset` with film model `film` in the storage at
/// `place`.
///
/// # Safety
/// `place` must point to `BEARING_STORAGE_SIZE` writable bytes aligned to
/// `bearing_storage_align()`, which outlive the handle.
pub unsafe fn bearing_from_preset(place: *mut u8, preset: u32, film: u32) -> *mut BearingHandle {
    let mut config = MaybeUninit::<BearingConfig>::uninit();
    let mut handle = std::ptr::null_mut();
    // SAFETY: valid pointers; the caller vouches for `place`.
    unsafe {
        assert_eq!(
            bearing_preset(preset, config.as_mut_ptr()),
            BearingStatus::Ok
        );
        let mut config = config.assume_init();
        config.film = film;
        let status = bearing_init(
            place.cast(),
            BEARING_STORAGE_SIZE,
            &config,
            &mut handle,
            std::ptr::null_mut(),
        );
        assert_eq!(status, BearingStatus::Ok);
    }
    handle
}
