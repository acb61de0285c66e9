//! Lubricant rheology of the isothermal problem: pressure–viscosity law and density law.
//!
//! Both are written for the solver's dimensionless pressure `P = p / p_h`, and return the
//! *logarithm* of the viscosity ratio η̄ = η/η₀ together with its derivative: at 3.5 GPa with
//! Roelands (or any pressure with Barus and large α p) η̄ spans tens of decades, so the solver
//! never forms η̄ itself — it forms `ε ∝ exp(−ln η̄)`, which underflows gracefully to zero in the
//! contact instead of overflowing.
//!
//! Sources (docs/physics.md §5.2):
//! - Roelands: η = η₀ exp{(ln η₀ + 9.67)[(1 + p/p₀)^Z − 1]}, p₀ = 1.96·10⁸ Pa,
//!   Z = α p₀ / (ln η₀ + 9.67) (Roelands 1966; the form and constants used by Houpert 1985 and
//!   Venner & Lubrecht 2000, η₀ in Pa·s). With this Z the law has d ln η / dp = α at p = 0.
//! - Barus: η = η₀ exp(α p).
//! - Dowson–Higginson: ρ/ρ₀ = 1 + 0.6·10⁻⁹ p / (1 + 1.7·10⁻⁹ p), p in Pa (Dowson & Higginson 1966).

/// Pressure–viscosity law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ViscosityLaw {
    /// Roelands (default, realistic above ~0.5 GPa).
    Roelands,
    /// Barus exponential law (used by Moes' film formula and the Venner–Lubrecht benchmarks).
    Barus,
    /// Constant viscosity η = η₀ (only for limit studies such as Martin's rigid iso-viscous case).
    Isoviscous,
}

/// Roelands reference pressure p₀ in Pa (Roelands 1966).
pub const ROELANDS_P0_PA: f64 = 1.96e8;
/// Roelands constant 9.67 (η₀ in Pa·s; ln(6.31·10⁻⁵ Pa·s) = −9.67).
pub const ROELANDS_LN_ETA_INF: f64 = 9.67;
/// Dowson–Higginson density constants (1/Pa).
const DH_A: f64 = 0.6e-9;
const DH_B: f64 = 1.7e-9;

/// Evaluates ln η̄ and ρ̄ with their derivatives with respect to the dimensionless pressure.
#[derive(Debug, Clone, Copy)]
pub struct Rheology {
    law: ViscosityLaw,
    compressible: bool,
    /// Hertz pressure p_h in Pa: converts P to p.
    hertz_pressure_pa: f64,
    /// Pressure–viscosity coefficient α in 1/Pa.
    alpha_pa_inv: f64,
    /// Roelands: ln η₀ + 9.67 and the exponent Z.
    roelands_lnfactor: f64,
    roelands_z: f64,
}

impl Rheology {
    /// Builds the law for a case. `viscosity_pa_s` is η₀; `hertz_pressure_pa` scales P.
    pub fn new(
        law: ViscosityLaw,
        compressible: bool,
        hertz_pressure_pa: f64,
        alpha_pa_inv: f64,
        viscosity_pa_s: f64,
    ) -> Self {
        let lnfactor = viscosity_pa_s.ln() + ROELANDS_LN_ETA_INF;
        Self {
            law,
            compressible,
            hertz_pressure_pa,
            alpha_pa_inv,
            roelands_lnfactor: lnfactor,
            roelands_z: alpha_pa_inv * ROELANDS_P0_PA / lnfactor,
        }
    }

    /// Returns (ln η̄, d ln η̄ / dP) at dimensionless pressure `p` (negative values are treated
    /// as zero: the film is at ambient pressure there).
    #[inline]
    pub fn ln_viscosity(&self, p: f64) -> (f64, f64) {
        let pa = p.max(0.0) * self.hertz_pressure_pa;
        let active = if p > 0.0 { 1.0 } else { 0.0 };
        match self.law {
            ViscosityLaw::Isoviscous => (0.0, 0.0),
            ViscosityLaw::Barus => (
                self.alpha_pa_inv * pa,
                active * self.alpha_pa_inv * self.hertz_pressure_pa,
            ),
            ViscosityLaw::Roelands => {
                let base = 1.0 + pa / ROELANDS_P0_PA;
                let pow = base.powf(self.roelands_z);
                let ln_eta = self.roelands_lnfactor * (pow - 1.0);
                // d/dp = lnfactor · Z · base^(Z−1) / p0 = α · base^(Z−1)
                let d = active * self.alpha_pa_inv * pow / base * self.hertz_pressure_pa;
                (ln_eta, d)
            }
        }
    }

    /// Returns (ρ̄, dρ̄/dP) at dimensionless pressure `p`.
    #[inline]
    pub fn density(&self, p: f64) -> (f64, f64) {
        if !self.compressible || p <= 0.0 {
            return (1.0, 0.0);
        }
        let pa = p * self.hertz_pressure_pa;
        let den = 1.0 + DH_B * pa;
        (
            1.0 + DH_A * pa / den,
            DH_A / (den * den) * self.hertz_pressure_pa,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Roelands with Z = α p₀/(ln η₀ + 9.67) has initial slope α (Roelands 1966 definition of Z),
    /// and the analytic derivative matches a central difference.
    #[test]
    fn roelands_slope_and_derivative() {
        let r = Rheology::new(ViscosityLaw::Roelands, true, 1.0e9, 2.0e-8, 0.05);
        let (_, d0) = r.ln_viscosity(1e-9);
        assert!((d0 / 1.0e9 / 2.0e-8 - 1.0).abs() < 1e-6);
        for &p in &[0.3, 1.0, 2.5] {
            let h = 1e-6;
            let num = (r.ln_viscosity(p + h).0 - r.ln_viscosity(p - h).0) / (2.0 * h);
            assert!((r.ln_viscosity(p).1 / num - 1.0).abs() < 1e-7);
            let numr = (r.density(p + h).0 - r.density(p - h).0) / (2.0 * h);
            assert!((r.density(p).1 / numr - 1.0).abs() < 1e-7);
        }
    }

    /// Dowson–Higginson tends to ρ̄ = 1 + 0.6/1.7 = 1.353 at infinite pressure; at 1 GPa it
    /// gives 1 + 0.6/2.7 = 1.2222 (closed form of the law).
    #[test]
    fn dowson_higginson_values() {
        let r = Rheology::new(ViscosityLaw::Barus, true, 1.0e9, 2.0e-8, 0.05);
        assert!((r.density(1.0).0 - (1.0 + 0.6 / 2.7)).abs() < 1e-12);
        assert!((r.density(1e6).0 - (1.0 + 0.6 / 1.7)).abs() < 1e-5);
        let inc = Rheology::new(ViscosityLaw::Barus, false, 1.0e9, 2.0e-8, 0.05);
        assert_eq!(inc.density(1.0), (1.0, 0.0));
        // Barus: ln η̄ = α p exactly.
        assert!((r.ln_viscosity(1.5).0 - 30.0).abs() < 1e-12);
    }
}
