//! The friction pass of a lubricated bearing ([`super::Bearing::friction`]): after a step's
//! roller solve, every contact's friction from its own load and film (docs/physics.md §8), at
//! the same cost for every input.

use super::{BearingOutput, BearingParams};
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
    output.friction_torque_nm = bearing.torque_nm;
    output.power_loss_w = bearing.power_loss_w;
    output.power_loss_split_w = bearing.power_loss_split_w;
}
