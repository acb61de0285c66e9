//! The hub-motor bearing (`configs/hub_motor.toml`, from the core's preset) with the integer
//! film network, its inner race whirling on a 6 µm circle at the shaft speed of 21 000 rpm,
//! sampled at 10 kHz: one line per step with the bearing force, the radial stiffness and the
//! films of the most loaded roller.
//!
//! `cargo run -p bearing-core --example whirl`

use bearing_core::bearing::SETTLE_STEPS;
use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState, ParamError};

/// Shaft speed (rad/s): 21 000 rpm.
const SHAFT_SPEED_RAD_S: f32 = 2199.1;
/// Radius of the whirl orbit (m).
const WHIRL_RADIUS_M: f32 = 6.0e-6;
/// Sample period (s).
const DT_S: f32 = 1.0e-4;

/// The inner race on the whirl orbit (forward whirl at the shaft speed) at time `t_s`.
fn whirl(t_s: f32) -> Result<OperatingState, ParamError> {
    let (s, c) = (SHAFT_SPEED_RAD_S * t_s).sin_cos();
    let (r, w) = (WHIRL_RADIUS_M, SHAFT_SPEED_RAD_S);
    OperatingState::new([r * c, r * s], [-r * w * s, r * w * c], [0.0; 2], w)
}

fn main() -> Result<(), ParamError> {
    let params = BearingDesign::HUB_MOTOR.params()?;
    let mut bearing = Bearing::<17, 10>::new(params, FilmKind::Int)?;
    // Converge the warm start and fill the film table before the real-time loop.
    bearing.settle(&whirl(0.0)?, SETTLE_STEPS)?;
    println!(
        "  t ms   F_x N     F_y N    k_xx N/µm  k_yy N/µm  cage °  Q_max N  h_in nm  h_out nm"
    );
    for k in 1..=20 {
        let t = k as f32 * DT_S;
        let out = *bearing.advance(&whirl(t)?, DT_S)?;
        let [[kxx, _], [_, kyy]] = out.radial_stiffness_n_per_m();
        let loaded = out
            .rollers
            .iter()
            .max_by(|a, b| a.load_n.total_cmp(&b.load_n))
            .copied()
            .unwrap_or(bearing_core::RollerOutput::ZERO);
        println!(
            "{:6.1} {:9.1} {:9.1} {:10.1} {:10.1} {:7.1} {:8.1} {:8.1} {:9.1}",
            t * 1e3,
            out.force_n[0],
            out.force_n[1],
            kxx * 1e-6,
            kyy * 1e-6,
            bearing.cage_angle_rad().to_degrees(),
            loaded.load_n,
            loaded.central_film_in_m * 1e9,
            loaded.central_film_out_m * 1e9,
        );
    }
    Ok(())
}
