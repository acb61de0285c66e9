//! Owned copies of the core's bearing output for host tools.
//!
//! The core's [`DynBearing`](bearing_core::DynBearing) (built by
//! [`bearing_core::bearing::boxed`]) chooses the roller count at run time and lends its output
//! as an [`OutputView`]; a [`StepSnapshot`] keeps it after the bearing steps on.

pub use bearing_core::bearing::{boxed, MAX_ROLLERS, MIN_ROLLERS, SLICES};
use bearing_core::{OutputView, RollerOutput, RollerTotals};

/// The output of one step with per-roller data in a `Vec`: the core's totals
/// ([`RollerTotals`], also read directly: `snapshot.force_n`) and each roller.
#[derive(Clone, Debug, PartialEq)]
pub struct StepSnapshot {
    /// Forces, moments, stiffness, damping and friction summed over the rollers.
    pub totals: RollerTotals,
    /// Film ratios [λ_in, λ_out] per roller.
    pub lambda: Vec<[f32; 2]>,
    /// Per roller.
    pub rollers: Vec<RollerOutput>,
}

impl std::ops::Deref for StepSnapshot {
    type Target = RollerTotals;
    fn deref(&self) -> &RollerTotals {
        &self.totals
    }
}

impl StepSnapshot {
    /// Largest roller load (N).
    pub fn max_roller_load_n(&self) -> f32 {
        self.rollers.iter().fold(0.0, |m, r| m.max(r.load_n))
    }
}

impl From<OutputView<'_>> for StepSnapshot {
    fn from(o: OutputView<'_>) -> Self {
        StepSnapshot {
            totals: o.totals,
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
