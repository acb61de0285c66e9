//! Owned copies of the core's bearing output for host tools.
//!
//! The core's [`DynBearing`](bearing_core::DynBearing) (built by
//! [`bearing_core::bearing::boxed`]) chooses the roller count at run time and lends its output
//! as an [`OutputView`]; a [`StepSnapshot`] keeps it after the bearing steps on.

pub use bearing_core::bearing::{boxed, MAX_ROLLERS, MIN_ROLLERS, SLICES};
use bearing_core::{OutputView, RollerOutput};

/// The output of one step with per-roller data in a `Vec`.
#[derive(Clone, Debug, PartialEq)]
pub struct StepSnapshot {
    /// [F_x, F_y] on the inner race (N).
    pub force_n: [f32; 2],
    /// [M_x, M_y] on the inner race (N·m).
    pub moment_nm: [f32; 2],
    /// −∂(F, M)/∂(x, y, tilt_x, tilt_y).
    pub stiffness: [[f32; 4]; 4],
    /// −∂F/∂(ẋ, ẏ) (N·s/m).
    pub damping_n_s_per_m: [[f32; 2]; 2],
    /// Each roller's centrifugal force on the outer race (N; 0 when left out): a roller's
    /// outer contact carries its `load_n` plus this.
    pub centrifugal_force_n: f32,
    /// Friction torque on the inner ring (N·m).
    pub friction_torque_nm: f32,
    /// Power loss (W).
    pub power_loss_w: f32,
    /// Power loss split [rolling, viscous, boundary] (W).
    pub power_loss_split_w: [f32; 3],
    /// Film ratios [λ_in, λ_out] per roller.
    pub lambda: Vec<[f32; 2]>,
    /// Per roller.
    pub rollers: Vec<RollerOutput>,
}

impl StepSnapshot {
    /// Largest roller load (N).
    pub fn max_roller_load_n(&self) -> f32 {
        self.rollers.iter().fold(0.0, |m, r| m.max(r.load_n))
    }
    /// 2×2 radial stiffness (N/m).
    pub fn radial_stiffness_n_per_m(&self) -> [[f32; 2]; 2] {
        let [r0, r1, _, _] = self.stiffness;
        [[r0[0], r0[1]], [r1[0], r1[1]]]
    }
}

impl From<OutputView<'_>> for StepSnapshot {
    fn from(o: OutputView<'_>) -> Self {
        StepSnapshot {
            force_n: o.force_n,
            moment_nm: o.moment_nm,
            stiffness: o.stiffness,
            damping_n_s_per_m: o.damping_n_s_per_m,
            centrifugal_force_n: o.centrifugal_force_n,
            friction_torque_nm: o.friction_torque_nm,
            power_loss_w: o.power_loss_w,
            power_loss_split_w: o.power_loss_split_w,
            lambda: o.lambda.to_vec(),
            rollers: o.rollers.to_vec(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};

    #[test]
    fn dynamic_bearing_equals_the_static_one() {
        let p = BearingDesign {
            crown_scale: 0.0,
            damping_factor_s: 1e-5,
            ..BearingDesign::NU205
        }
        .params()
        .unwrap();
        let mut dynamic = boxed(p, FilmKind::Regression).unwrap();
        let mut fixed = Bearing::<12, SLICES>::new(p, FilmKind::Regression).unwrap();
        dynamic.set_cage_angle(0.2).unwrap();
        fixed.set_cage_angle(0.2).unwrap();
        let s = OperatingState::new([1e-6, -4e-6], [0.0; 2], [0.0; 2], 1000.0).unwrap();
        let a = StepSnapshot::from(dynamic.advance(&s, 1e-4).unwrap());
        let b = *fixed.advance(&s, 1e-4).unwrap();
        assert_eq!(a.force_n, b.force_n);
        assert_eq!(a.rollers.len(), 12);
        assert_eq!(dynamic.cage_angle_rad(), fixed.cage_angle_rad());
    }
}
