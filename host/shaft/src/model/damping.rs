//! Material (proportional, Rayleigh) damping of the shaft: C = a·M + b·K.
//!
//! The coefficients are applied to the shaft's own mass and stiffness (bearings and disks add
//! their own terms). This is stationary (non-rotating) damping: the internal-damping circulatory
//! term that destabilises a supercritical rotor (Friswell et al. (2010) §3.7) is not modelled.
//! Modal damping ratio of a mode ω: ζ = a/(2ω) + bω/2 (Rayleigh; Friswell et al. (2010) §5.6).

/// Rayleigh damping coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProportionalDamping {
    /// Mass-proportional coefficient a (1/s).
    pub mass_coefficient: f64,
    /// Stiffness-proportional coefficient b (s).
    pub stiffness_coefficient: f64,
}

impl ProportionalDamping {
    /// Damping ratio this gives at circular frequency ω (rad/s).
    pub fn ratio_at(&self, omega: f64) -> f64 {
        self.mass_coefficient / (2.0 * omega) + self.stiffness_coefficient * omega / 2.0
    }

    /// Coefficients that give damping ratio ζ₁ at ω₁ and ζ₂ at ω₂ (rad/s, ω₁ ≠ ω₂).
    pub fn from_two_modes(omega1: f64, zeta1: f64, omega2: f64, zeta2: f64) -> Self {
        // Solve ζᵢ = a/(2ωᵢ) + bωᵢ/2 for (a, b).
        let det = omega2 / omega1 - omega1 / omega2;
        let b = 2.0 * (zeta2 * omega2 - zeta1 * omega1) / (omega2 * omega2 - omega1 * omega1);
        let a = 2.0 * (zeta1 * omega2 - zeta2 * omega1) / det;
        ProportionalDamping {
            mass_coefficient: a,
            stiffness_coefficient: b,
        }
    }
}
