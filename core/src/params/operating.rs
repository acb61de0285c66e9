//! The operating state of one time step: inner-race motion and shaft speed.

use crate::error::{in_range, ParamError};

/// Largest inner-race displacement accepted (m): far beyond any elastic approach.
pub const MAX_DISPLACEMENT_M: f32 = 1.0e-3;
/// Largest inner-race velocity accepted (m/s).
pub const MAX_VELOCITY_M_S: f32 = 100.0;
/// Largest tilt accepted (rad).
pub const MAX_TILT_RAD: f32 = 0.01;
/// Largest cage angle [`Bearing::set_cage_angle`](crate::Bearing::set_cage_angle) accepts
/// (rad); the bearing wraps it into [0, 2π) and keeps it there as it advances.
pub const MAX_CAGE_ANGLE_RAD: f32 = 1.0e4;
/// Largest time step accepted (s): the cage then turns at most 5·10⁴ rad in one step, which
/// f32 still resolves to 4 mrad before the angle is wrapped.
pub const MAX_TIME_STEP_S: f32 = 1.0;
/// Largest shaft speed accepted (rad/s), ≈ 955 000 rpm.
pub const MAX_SHAFT_SPEED_RAD_S: f32 = 1.0e5;

/// Inner-race kinematics and shaft speed at one instant; the outer race is fixed. The cage
/// angle is not part of it: the bearing integrates it from the shaft speed
/// ([`Bearing::advance`](crate::Bearing::advance)).
///
/// The fields are public so a sample can be filled in place in a real-time loop; the bearing
/// checks them with [`OperatingState::check`] and refuses a bad one (an `Err` naming the
/// field) rather than computing with it. [`OperatingState::new`] checks at construction.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OperatingState {
    /// Inner-race displacement [x, y] in the bearing plane (m).
    pub displacement_m: [f32; 2],
    /// Inner-race velocity [ẋ, ẏ] (m/s).
    pub velocity_m_s: [f32; 2],
    /// Inner-race tilt [about x, about y] (rad).
    pub tilt_rad: [f32; 2],
    /// Shaft (inner-ring) speed ω (rad/s); the sign gives the direction.
    pub shaft_speed_rad_s: f32,
}

impl OperatingState {
    /// A checked operating state; see the `MAX_*` constants for the limits.
    pub fn new(
        displacement_m: [f32; 2],
        velocity_m_s: [f32; 2],
        tilt_rad: [f32; 2],
        shaft_speed_rad_s: f32,
    ) -> Result<Self, ParamError> {
        let state = Self {
            displacement_m,
            velocity_m_s,
            tilt_rad,
            shaft_speed_rad_s,
        };
        state.check()?;
        Ok(state)
    }

    /// Check every field; the first bad one is reported.
    pub fn check(&self) -> Result<(), ParamError> {
        let [x, y] = self.displacement_m;
        in_range(
            "displacement_x_m",
            x,
            -MAX_DISPLACEMENT_M,
            MAX_DISPLACEMENT_M,
        )?;
        in_range(
            "displacement_y_m",
            y,
            -MAX_DISPLACEMENT_M,
            MAX_DISPLACEMENT_M,
        )?;
        let [vx, vy] = self.velocity_m_s;
        in_range("velocity_x_m_s", vx, -MAX_VELOCITY_M_S, MAX_VELOCITY_M_S)?;
        in_range("velocity_y_m_s", vy, -MAX_VELOCITY_M_S, MAX_VELOCITY_M_S)?;
        let [tx, ty] = self.tilt_rad;
        in_range("tilt_x_rad", tx, -MAX_TILT_RAD, MAX_TILT_RAD)?;
        in_range("tilt_y_rad", ty, -MAX_TILT_RAD, MAX_TILT_RAD)?;
        in_range(
            "shaft_speed_rad_s",
            self.shaft_speed_rad_s,
            -MAX_SHAFT_SPEED_RAD_S,
            MAX_SHAFT_SPEED_RAD_S,
        )?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_bad_field() {
        let e = OperatingState::new([0.0, f32::NAN], [0.0; 2], [0.0; 2], 100.0).unwrap_err();
        assert_eq!(e.field, "displacement_y_m");
        let e = OperatingState::new([0.0; 2], [0.0; 2], [0.0; 2], f32::INFINITY).unwrap_err();
        assert_eq!(e.field, "shaft_speed_rad_s");
        assert!(OperatingState::new([1e-5, 0.0], [0.0; 2], [0.0; 2], 2199.0).is_ok());
    }
}
