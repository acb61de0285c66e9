//! Typed errors for refused parameters.
//!
//! Bad parameters are refused once, at construction; the error names the field, the value that
//! was given and the range that is allowed, so a message can be shown to a user unchanged.

use core::fmt;

/// What is allowed for a parameter, for the error message.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Allowed {
    /// A finite value strictly above zero.
    Positive,
    /// A finite value at or above zero.
    NonNegative,
    /// A finite value of any sign.
    Finite,
    /// A finite value in the closed interval `[min, max]`.
    Range {
        /// Smallest allowed value.
        min: f32,
        /// Largest allowed value.
        max: f32,
    },
    /// A finite value strictly below the value of another field.
    LessThan {
        /// Name of the other field.
        field: &'static str,
        /// Its value.
        value: f32,
    },
}

/// A parameter was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamError {
    /// Name of the field, as in the configuration file (`roller_diameter_m`).
    pub field: &'static str,
    /// The value that was given.
    pub value: f32,
    /// What would have been accepted.
    pub allowed: Allowed,
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {} is not allowed: ", self.field, self.value)?;
        match self.allowed {
            Allowed::Positive => write!(f, "it must be finite and > 0"),
            Allowed::NonNegative => write!(f, "it must be finite and >= 0"),
            Allowed::Finite => write!(f, "it must be finite"),
            Allowed::Range { min, max } => write!(f, "it must lie in [{min}, {max}]"),
            Allowed::LessThan { field, value } => {
                write!(f, "it must be finite and < {field} = {value}")
            }
        }
    }
}

/// Check that `value` is finite and `> 0`.
pub(crate) fn positive(field: &'static str, value: f32) -> Result<f32, ParamError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(ParamError {
            field,
            value,
            allowed: Allowed::Positive,
        })
    }
}

/// Check that `value` is finite and lies in `[min, max]`.
pub(crate) fn in_range(
    field: &'static str,
    value: f32,
    min: f32,
    max: f32,
) -> Result<f32, ParamError> {
    if value.is_finite() && value >= min && value <= max {
        Ok(value)
    } else {
        Err(ParamError {
            field,
            value,
            allowed: Allowed::Range { min, max },
        })
    }
}

impl core::error::Error for ParamError {}
