//! The cage angle, which every bearing kind integrates the same way: rolling element j sits at
//! θ_c + 2πj/Z (docs/physics.md §2).

use core::f32::consts::TAU;

/// 1/(2π), by which an angle is divided into turns.
const INV_TAU: f32 = 1.0 / TAU;

/// Wrap an angle by whole turns: one truncation toward zero, exact into [0, 2π) for a
/// non-negative angle, within (−2π, 2π) for a negative one.
pub(crate) fn wrap_turns(angle_rad: f32) -> f32 {
    let turns = (angle_rad * INV_TAU) as i32;
    angle_rad - turns as f32 * TAU
}
