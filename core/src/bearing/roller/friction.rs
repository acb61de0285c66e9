//! The friction pass of a lubricated bearing ([`super::Bearing::friction`]): after a step's
//! roller solve, every contact's friction from its own load and film (docs/physics.md §8), at
//! the same cost for every input.

use super::{Bearing, BearingOutput, BearingParams, FilmKind};
use crate::error::{in_range, ParamError};
use crate::film::ContactInput;
use crate::friction::{FrictionSums, Prepared};

/// Fill the film ratios of `output`'s rollers and its friction torque and power loss, from
/// the contacts' inputs `templates` (inner, outer: geometry, lubricant and the step's
/// entrainment speed) at shaft speed ω. A roller's inner contact carries its load `load_n`,
/// its outer contact that plus the centrifugal force of the step (0 when the bearing leaves it
/// out; docs/physics.md §4.1).
pub(super) fn friction_pass<const Z: usize>(
    params: &BearingParams,
    templates: &[ContactInput; 2],
    output: &mut BearingOutput<Z>,
    shaft_speed_rad_s: f32,
) {
    let friction = &params.friction;
    let [inner, outer] = templates;
    let prepared = [
        Prepared::new(friction, inner),
        Prepared::new(friction, outer),
    ];
    let [prepared_in, prepared_out] = &prepared;
    let mut sums = FrictionSums::default();
    let centrifugal_force_n = output.centrifugal_force_n;
    for (roller, lambda) in output.rollers.iter().zip(output.lambda.iter_mut()) {
        let c_in = prepared_in.contact(
            &ContactInput {
                load_n: roller.load_n,
                ..*inner
            },
            roller.central_film_in_m,
        );
        let c_out = prepared_out.contact(
            &ContactInput {
                load_n: roller.load_n + centrifugal_force_n,
                ..*outer
            },
            roller.central_film_out_m,
        );
        *lambda = [c_in.lambda, c_out.lambda];
        sums.add(&c_in);
        sums.add(&c_out);
    }
    let bearing = sums.bearing(
        params.geometry.entrainment_speed_m_s(1.0),
        friction.slide_to_roll_ratio(),
        shaft_speed_rad_s,
    );
    output.totals.friction_torque_nm = bearing.torque_nm;
    output.totals.power_loss_w = bearing.power_loss_w;
    output.totals.power_loss_split_w = bearing.power_loss_split_w;
}

impl<const Z: usize, const S: usize> Bearing<Z, S> {
    /// The friction of the last computed output (docs/physics.md §8): fills its rollers' film
    /// ratios λ_in, λ_out and its friction torque, power loss and split at the shaft speed ω
    /// of that step (`shaft_speed_rad_s`, rad/s), and returns the output. The same work for
    /// every input, ≈ 2 k Cortex-M4 instructions per roller: it is kept out of
    /// [`Bearing::advance`] so that the real-time step costs what it did, and runs at the rate
    /// the friction is wanted. The dry model has no film and no friction: its output keeps
    /// zeros there.
    ///
    /// ```
    /// use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
    /// let mut bearing = Bearing::<12, 10>::new(BearingDesign::NU205.params()?, FilmKind::Regression)?;
    /// let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 1000.0)?;
    /// bearing.settle(&state, bearing_core::bearing::SETTLE_STEPS)?;
    /// let out = bearing.friction(state.shaft_speed_rad_s)?;
    /// assert!(out.power_loss_w > 0.0);
    /// assert!((out.power_loss_w / (out.friction_torque_nm * 1000.0) - 1.0).abs() < 1e-5);
    /// # Ok::<(), bearing_core::ParamError>(())
    /// ```
    pub fn friction(&mut self, shaft_speed_rad_s: f32) -> Result<&BearingOutput<Z>, ParamError> {
        in_range(
            "shaft_speed_rad_s",
            shaft_speed_rad_s,
            -crate::params::MAX_SHAFT_SPEED_RAD_S,
            crate::params::MAX_SHAFT_SPEED_RAD_S,
        )?;
        if self.film != FilmKind::Dry {
            let [inner, outer] = self.contact_contexts(shaft_speed_rad_s);
            friction_pass(
                &self.params,
                &[inner.template, outer.template],
                &mut self.output,
                shaft_speed_rad_s,
            );
        }
        Ok(&self.output)
    }
}
