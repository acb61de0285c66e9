//! Permanent-magnet synchronous motor (PMSM) drive torque: the torque–speed curve and the torque
//! ripple that the pinion transmits into the gear mesh.
//!
//! Torque–speed curve of a field-weakened PMSM (docs/physics.md §6.2; e.g. Hendershot & Miller,
//! *Design of Brushless Permanent-Magnet Machines*, 2010, ch. 1): constant torque T_peak up to the
//! base speed Ω_b = P_max / T_peak, constant power P_max above it, nothing above the maximum speed.
//! Ripple: a sinusoid of relative amplitude r at `ripple_order` times the shaft frequency.

/// Motor drive data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pmsm {
    /// Peak (constant-torque region) torque (N·m).
    pub peak_torque: f64,
    /// Maximum power (W).
    pub max_power: f64,
    /// Maximum speed (rad/s).
    pub max_speed: f64,
    /// Fraction of the available torque the operating point uses (0…1).
    pub load_fraction: f64,
    /// Relative torque ripple amplitude (fraction of the mean torque).
    pub ripple_fraction: f64,
    /// Ripple harmonic per shaft revolution (events/rev).
    pub ripple_order: f64,
}

/// A speed outside the motor's range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("speed {speed_rpm:.1} rpm is outside the motor range 0 … {max_rpm:.1} rpm")]
pub struct SpeedOutOfRange {
    /// Requested speed (rpm).
    pub speed_rpm: f64,
    /// Maximum speed (rpm).
    pub max_rpm: f64,
}

impl Pmsm {
    /// Base speed Ω_b = P_max / T_peak (rad/s).
    pub fn base_speed(&self) -> f64 {
        self.max_power / self.peak_torque
    }

    /// Mean drive torque at spin speed Ω (rad/s): load_fraction × min(T_peak, P_max/Ω).
    pub fn mean_torque(&self, speed: f64) -> Result<f64, SpeedOutOfRange> {
        let speed = speed.abs();
        // A small tolerance so the rated maximum itself is accepted after rpm round trips.
        if !speed.is_finite() || speed > self.max_speed * (1.0 + 1e-9) {
            return Err(SpeedOutOfRange {
                speed_rpm: speed * 30.0 / std::f64::consts::PI,
                max_rpm: self.max_speed * 30.0 / std::f64::consts::PI,
            });
        }
        let available = if speed <= self.base_speed() {
            self.peak_torque
        } else {
            self.max_power / speed
        };
        Ok(self.load_fraction * available)
    }

    /// Instantaneous torque at spin angle φ = Ωt (rad): T̄ (1 + r sin(order·φ)).
    pub fn torque(&self, mean_torque: f64, spin_angle: f64) -> f64 {
        mean_torque * (1.0 + self.ripple_fraction * (self.ripple_order * spin_angle).sin())
    }
}
