//! The bearing inside the caller's storage: its layout, the size and alignment the header
//! promises, and the checks every handle passes before it is used.

use bearing_core::{Bearing, BearingParams, DynBearing, FilmKind, ParamError};
use core::mem::{align_of, size_of};

/// Slices per roller of every bearing the library builds: the host tools' and the HIL
/// harness's choice, for which the core tests slice-count independence.
pub const BEARING_SLICES_PER_ROLLER: usize = 10;
const SLICES: usize = BEARING_SLICES_PER_ROLLER;

/// Bytes of storage that hold a bearing on every target the library is built for (x86-64,
/// Cortex-M4F): a static buffer of this size works everywhere. The library does not compile
/// when a bearing would need more; `bearing_storage_size()` is the exact need of this build.
pub const BEARING_STORAGE_SIZE: usize = 4096;
/// Alignment (bytes) that suits the storage on every target the library is built for;
/// `bearing_storage_align()` is the exact need of this build.
pub const BEARING_STORAGE_ALIGN: usize = 8;

/// Written by `bearing_init` at the start of the storage, checked by every other function:
/// a handle to zeroed or foreign memory is refused instead of read as a bearing.
const MAGIC: u32 = 0x4252_4731; // "BRG1"

/// The core's bearing at each roller count the library offers (the presets': NU 205 has 12
/// rollers, the hub motor 17). Each count is one monomorphised step in the library's code, so
/// the set is kept to what the bundled bearings need.
#[allow(clippy::large_enum_variant)] // one bearing per storage, never moved after init
pub(crate) enum Model {
    Rollers12(Bearing<12, SLICES>),
    Rollers17(Bearing<17, SLICES>),
}

/// What the storage holds after `bearing_init`.
#[repr(C)]
pub(crate) struct Slot {
    magic: u32,
    /// The last refusal of a step function on this bearing (`bearing_last_refusal`).
    pub(crate) refusal: Option<ParamError>,
    pub(crate) model: Model,
}

const _: () = assert!(size_of::<Slot>() <= BEARING_STORAGE_SIZE);
const _: () = assert!(align_of::<Slot>() <= BEARING_STORAGE_ALIGN);

/// Why a model cannot be built.
pub(crate) enum BuildError {
    Refused(ParamError),
    UnsupportedRollerCount,
}

impl Model {
    pub(crate) fn new(params: BearingParams, film: FilmKind) -> Result<Self, BuildError> {
        match params.geometry().roller_count() {
            12 => Bearing::new(params, film)
                .map(Model::Rollers12)
                .map_err(BuildError::Refused),
            17 => Bearing::new(params, film)
                .map(Model::Rollers17)
                .map_err(BuildError::Refused),
            _ => Err(BuildError::UnsupportedRollerCount),
        }
    }

    pub(crate) fn bearing(&self) -> &dyn DynBearing {
        match self {
            Model::Rollers12(b) => b,
            Model::Rollers17(b) => b,
        }
    }

    pub(crate) fn bearing_mut(&mut self) -> &mut dyn DynBearing {
        match self {
            Model::Rollers12(b) => b,
            Model::Rollers17(b) => b,
        }
    }
}

/// Why a pointer cannot be used as a handle or a buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PointerError {
    Null,
    Misaligned,
    NotInitialised,
}

/// Checks that `ptr` is non-NULL and aligned for `T`.
pub(crate) fn check_pointer<T>(ptr: *const T) -> Result<(), PointerError> {
    if ptr.is_null() {
        Err(PointerError::Null)
    } else if (ptr as usize) % align_of::<T>() != 0 {
        Err(PointerError::Misaligned)
    } else {
        Ok(())
    }
}

/// Writes a new slot into `storage`.
///
/// # Safety
/// `storage` is non-NULL, aligned for `Slot` and valid for writes of `size_of::<Slot>()` bytes.
pub(crate) unsafe fn write_slot(storage: *mut Slot, model: Model) {
    // SAFETY: the caller's contract.
    unsafe {
        storage.write(Slot {
            magic: MAGIC,
            refusal: None,
            model,
        })
    }
}

/// The slot behind a handle.
///
/// # Safety
/// A non-NULL, aligned `handle` points at memory the caller owns and may read for
/// `size_of::<Slot>()` bytes; when its first word is the magic, it is a slot `bearing_init`
/// wrote and nothing else has written since (docs/c-api.md: the caller does not alias it).
pub(crate) unsafe fn slot<'a>(handle: *mut Slot) -> Result<&'a mut Slot, PointerError> {
    check_pointer(handle)?;
    // SAFETY: non-NULL and aligned (checked); readable by the caller's contract. The magic is
    // read as a plain u32 before any other field, so any bytes there are a valid value.
    let magic = unsafe { core::ptr::addr_of!((*handle).magic).read() };
    if magic != MAGIC {
        return Err(PointerError::NotInitialised);
    }
    // SAFETY: the magic says `bearing_init` wrote a slot here (the caller's contract).
    Ok(unsafe { &mut *handle })
}
