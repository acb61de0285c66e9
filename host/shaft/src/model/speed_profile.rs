//! Prescribed spin-speed profile Ω(t) of a time response: constant, or held at a start speed
//! through the settling time and then ramped linearly to an end speed over the recorded time
//! (a run-up or run-down). The spin angle φ(t) = ∫Ω dt is the closed-form integral of the
//! piecewise-linear speed, so the speed-dependent loads (unbalance, gear mesh at z·φ, motor
//! ripple) stay phase-continuous however fast the speed changes.

/// Spin speed as a function of time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedProfile {
    /// Speed from t = 0 until `ramp_start` (rad/s).
    pub start: f64,
    /// Speed reached at `ramp_start + ramp_duration` and held after (rad/s).
    pub end: f64,
    /// Time the ramp begins (s).
    pub ramp_start: f64,
    /// Duration of the ramp (s, > 0 unless `start == end`).
    pub ramp_duration: f64,
}

impl SpeedProfile {
    /// A constant speed Ω (rad/s).
    pub fn constant(speed: f64) -> Self {
        SpeedProfile {
            start: speed,
            end: speed,
            ramp_start: 0.0,
            ramp_duration: 0.0,
        }
    }

    /// True when the speed never changes.
    pub fn is_constant(&self) -> bool {
        self.start == self.end
    }

    /// Angular acceleration of the ramp (rad/s²), 0 when constant.
    fn rate(&self) -> f64 {
        if self.is_constant() || self.ramp_duration <= 0.0 {
            0.0
        } else {
            (self.end - self.start) / self.ramp_duration
        }
    }

    /// Time since the ramp began, clamped to [0, duration] (s).
    fn ramp_time(&self, t: f64) -> f64 {
        (t - self.ramp_start).clamp(0.0, self.ramp_duration.max(0.0))
    }

    /// Spin speed Ω(t) (rad/s).
    pub fn speed(&self, t: f64) -> f64 {
        if self.is_constant() {
            return self.start;
        }
        self.start + self.rate() * self.ramp_time(t)
    }

    /// Angular acceleration Ω̇(t) (rad/s²): the ramp rate inside the ramp, 0 outside.
    pub fn acceleration(&self, t: f64) -> f64 {
        let inside = t > self.ramp_start && t < self.ramp_start + self.ramp_duration;
        if inside {
            self.rate()
        } else {
            0.0
        }
    }

    /// Spin angle φ(t) = ∫₀ᵗ Ω dτ (rad): Ω₀t + ½Ω̇τ² during the ramp (τ = time since its
    /// start), plus Ω_end times the time after it.
    pub fn angle(&self, t: f64) -> f64 {
        if self.is_constant() {
            // The constant-speed case keeps exactly the product Ωt used before ramps existed.
            return self.start * t;
        }
        let tau = self.ramp_time(t);
        let after = (t - self.ramp_start - self.ramp_duration).max(0.0);
        self.start * t.min(self.ramp_start)
            + self.start * tau
            + 0.5 * self.rate() * tau * tau
            + self.end * after
    }

    /// Highest speed of the profile (rad/s, by magnitude).
    pub fn max_speed(&self) -> f64 {
        self.start.abs().max(self.end.abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference: the angle must be the integral of the speed — checked against a composite
    /// Simpson quadrature of `speed` (a different method), across the ramp's kinks.
    #[test]
    fn angle_is_the_integral_of_the_speed() {
        let p = SpeedProfile {
            start: 100.0,
            end: 700.0,
            ramp_start: 0.1,
            ramp_duration: 0.3,
        };
        for &t in &[0.05, 0.1, 0.25, 0.4, 0.55] {
            // Simpson on pieces split at the kinks so each piece is linear (exact there).
            let mut knots = vec![0.0];
            for k in [0.1, 0.4] {
                if k < t {
                    knots.push(k);
                }
            }
            knots.push(t);
            let integral: f64 = knots
                .windows(2)
                .map(|w| {
                    (w[1] - w[0]) / 6.0
                        * (p.speed(w[0]) + 4.0 * p.speed(0.5 * (w[0] + w[1])) + p.speed(w[1]))
                })
                .sum();
            assert!(
                (p.angle(t) - integral).abs() < 1e-9 * integral.max(1.0),
                "t = {t}: {} vs {integral}",
                p.angle(t)
            );
        }
        assert_eq!(p.speed(0.0), 100.0);
        assert!((p.speed(0.25) - 400.0).abs() < 1e-9);
        assert_eq!(p.speed(1.0), 700.0);
        assert_eq!(p.acceleration(0.25), 2000.0);
        assert_eq!(p.acceleration(0.05), 0.0);
    }

    /// Reference: a constant profile is Ω t exactly (the pre-ramp behaviour).
    #[test]
    fn constant_profile_is_omega_t() {
        let p = SpeedProfile::constant(1234.5);
        assert_eq!(p.angle(0.37), 1234.5 * 0.37);
        assert_eq!(p.speed(9.0), 1234.5);
        assert_eq!(p.acceleration(1.0), 0.0);
    }
}
