//! A core refusal (`ParamError`) as the C record `BearingRefusal`: field names as NUL-terminated
//! text in fixed arrays, what is allowed as numbers. No text is formatted here: `core::fmt`'s
//! float formatting keeps panic paths (its internal assertions) that this library must not link.

use crate::types::{BearingAllowed, BearingRefusal, BEARING_FIELD_NAME_LEN};
use bearing_core::{Allowed, ParamError};
use core::ffi::c_char;

/// Nothing refused.
pub(crate) const NO_REFUSAL: BearingRefusal = BearingRefusal {
    field: [0; BEARING_FIELD_NAME_LEN],
    value: 0.0,
    allowed: BearingAllowed::Nothing as u32,
    min: 0.0,
    max: 0.0,
    other_field: [0; BEARING_FIELD_NAME_LEN],
};

/// `name` as NUL-terminated C text, cut to fit (field names are ASCII).
fn c_name(name: &str) -> [c_char; BEARING_FIELD_NAME_LEN] {
    let mut out = [0; BEARING_FIELD_NAME_LEN];
    // The last byte stays NUL.
    for (slot, byte) in out
        .iter_mut()
        .take(BEARING_FIELD_NAME_LEN - 1)
        .zip(name.bytes())
    {
        *slot = byte as c_char;
    }
    out
}

/// The C record of `error`.
fn refusal(error: &ParamError) -> BearingRefusal {
    let mut out = BearingRefusal {
        field: c_name(error.field),
        value: error.value,
        ..NO_REFUSAL
    };
    let allowed = match error.allowed {
        Allowed::Positive => BearingAllowed::Positive,
        Allowed::NonNegative => BearingAllowed::NonNegative,
        Allowed::Finite => BearingAllowed::Finite,
        Allowed::Range { min, max } => {
            (out.min, out.max) = (min, max);
            BearingAllowed::Range
        }
        Allowed::LessThan { field, value } => {
            out.max = value;
            out.other_field = c_name(field);
            BearingAllowed::LessThan
        }
    };
    out.allowed = allowed as u32;
    out
}

/// Writes the C record of `error` to `out`.
///
/// # Safety
/// `out` is non-NULL, aligned and valid for writing a `BearingRefusal`.
pub(crate) unsafe fn write_refusal(out: *mut BearingRefusal, error: &ParamError) {
    // SAFETY: the caller's contract.
    unsafe { out.write(refusal(error)) }
}
