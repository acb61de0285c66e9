//! The core's bearing with its roller count chosen at run time.
//!
//! `bearing_core::Bearing<Z, S>` sizes its arrays by const generics, as the firmware needs.
//! Host tools read the roller count from a file, so [`new_bearing`] instantiates the core for
//! every supported count behind one object-safe trait. Slices are fixed at
//! [`SLICES`] (the core's test of slice-count independence covers the choice).

use bearing_core::bearing::Equilibrium;
use bearing_core::{
    Bearing, BearingParams, FilmModel, OperatingState, ParamError, RollerOutput, StepStatus,
};

/// Slices per roller in host tools.
pub const SLICES: usize = 10;
/// Smallest supported roller count.
pub const MIN_ROLLERS: u16 = 6;
/// Largest supported roller count.
pub const MAX_ROLLERS: u16 = 40;

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
    /// Per roller.
    pub rollers: Vec<RollerOutput>,
    /// Whether the step computed.
    pub status: StepStatus,
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

/// A core bearing of any supported roller count.
pub trait DynBearing: Send {
    /// Parameters.
    fn params(&self) -> &BearingParams;
    /// Lubricated step with `film` (see `Bearing::step`).
    fn step(&mut self, film: &dyn FilmModel, state: &OperatingState) -> StepSnapshot;
    /// Dry step.
    fn step_dry(&mut self, state: &OperatingState) -> StepSnapshot;
    /// `steps` lubricated steps at one state (converges the warm start).
    fn settle(
        &mut self,
        film: &dyn FilmModel,
        state: &OperatingState,
        steps: usize,
    ) -> StepSnapshot;
    /// Static equilibrium under `force_n` (dry when `film` is `None`).
    fn static_equilibrium(
        &mut self,
        film: Option<&dyn FilmModel>,
        force_n: [f32; 2],
        state: &OperatingState,
        relative_tolerance: f32,
        max_iterations: usize,
    ) -> Equilibrium;
    /// Forget the warm start.
    fn reset(&mut self);
    /// A boxed copy (same warm start).
    fn boxed_clone(&self) -> Box<dyn DynBearing>;
}

fn snapshot<const Z: usize>(o: &bearing_core::BearingOutput<Z>) -> StepSnapshot {
    StepSnapshot {
        force_n: o.force_n,
        moment_nm: o.moment_nm,
        stiffness: o.stiffness,
        damping_n_s_per_m: o.damping_n_s_per_m,
        rollers: o.rollers.to_vec(),
        status: o.status,
    }
}

impl<const Z: usize> DynBearing for Bearing<Z, SLICES> {
    fn params(&self) -> &BearingParams {
        Bearing::params(self)
    }
    fn step(&mut self, film: &dyn FilmModel, state: &OperatingState) -> StepSnapshot {
        snapshot(Bearing::step(self, film, state))
    }
    fn step_dry(&mut self, state: &OperatingState) -> StepSnapshot {
        snapshot(Bearing::step_dry(self, state))
    }
    fn settle(
        &mut self,
        film: &dyn FilmModel,
        state: &OperatingState,
        steps: usize,
    ) -> StepSnapshot {
        snapshot(Bearing::settle(self, film, state, steps))
    }
    fn static_equilibrium(
        &mut self,
        film: Option<&dyn FilmModel>,
        force_n: [f32; 2],
        state: &OperatingState,
        relative_tolerance: f32,
        max_iterations: usize,
    ) -> Equilibrium {
        Bearing::static_equilibrium(
            self,
            film,
            force_n,
            state,
            relative_tolerance,
            max_iterations,
        )
    }
    fn reset(&mut self) {
        Bearing::reset(self)
    }
    fn boxed_clone(&self) -> Box<dyn DynBearing> {
        Box::new(self.clone())
    }
}

/// The core bearing for `params`, with its roller count as the const generic.
pub fn new_bearing(params: BearingParams) -> Result<Box<dyn DynBearing>, ParamError> {
    macro_rules! counts {
        ($($z:literal)*) => {
            match params.geometry().roller_count() {
                $($z => Ok(Box::new(Bearing::<$z, SLICES>::new(params)?)),)*
                other => Err(ParamError {
                    field: "roller_count",
                    value: f32::from(other),
                    allowed: bearing_core::Allowed::Range { min: MIN_ROLLERS as f32, max: MAX_ROLLERS as f32 },
                }),
            }
        };
    }
    counts!(6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40)
}

#[cfg(test)]
mod tests {
    use super::*;
    use bearing_core::{BearingGeometry, ContactLaw, Crown, Lubricant, Material, Regression};

    #[test]
    fn dynamic_bearing_equals_the_static_one() {
        let g = BearingGeometry::new(0.039, 0.0075, 0.009, 12, Crown::None, 0.0).unwrap();
        let oil = Lubricant::new(0.08, 2.1e-8, 833.8).unwrap();
        let p = BearingParams::new(
            g,
            Material::STEEL,
            Material::STEEL,
            oil,
            ContactLaw::Palmgren,
            1e-5,
        )
        .unwrap();
        let mut dynamic = new_bearing(p).unwrap();
        let mut fixed = Bearing::<12, SLICES>::new(p).unwrap();
        let s = OperatingState::new([1e-6, -4e-6], [0.0; 2], [0.0; 2], 1000.0, 0.2).unwrap();
        let a = dynamic.step(&Regression, &s);
        let b = *fixed.step(&Regression, &s);
        assert_eq!(a.force_n, b.force_n);
        assert_eq!(a.rollers.len(), 12);
    }
}
