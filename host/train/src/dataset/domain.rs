//! The training domain of the film network: the input box of docs/physics.md §5.3 (thesis Table 5.1),
//! a Hertz-pressure window and a piezoviscous regime test — widened where the thesis' domain
//! (Q ≥ 150 N, u_m ≤ 30 m/s, 0.3–3.5 GPa, piezoviscous–elastic only) misses loaded rollers of
//! the §6 reference machines: the hub motor's rollers at 11 000–21 000 rpm carry 90–180 N at
//! 0.2–0.3 GPa with u_m up to 34 m/s, in the piezoviscous–rigid transition, and the HIL
//! traces' lightly loaded rollers sit at M ≈ 0.5–1. Hence Q ≥ 50 N, u_m ≤ 40 m/s,
//! 0.15–3.5 GPa, and regime limits that admit the piezoviscous–rigid side
//! (`reference::check_reference_cases` checks it).
//!
//! Scales: an input whose range spans a factor ≥ 3 is sampled uniformly in its logarithm (load,
//! speed, radius, α, η₀, length: the film is close to a power law in each, so equal steps in
//! log space give equal relative changes of the film); the reduced modulus (200–250 GPa, ×1.25)
//! is sampled linearly.
//!
//! Regime test (defined here, used identically by the core's domain guard): with the Moes
//! asymptotes `H_RI, H_EI, H_RP, H_EP` (Moes 1992; docs/physics.md §5.1) a contact is
//! *piezoviscous–elastic* when
//! 1. piezoviscous: `ln(H_EP / max(H_RI, H_EI)) ≥ piezo_min_log_ratio` — the piezoviscous
//!    asymptote is above the isoviscous one, which Moes' formula combines as a near-maximum;
//! 2. elastic: `ln(H_EP / H_RP) ≤ elastic_max_log_ratio` — the elastic asymptote is not far
//!    above the rigid–piezoviscous one, which the formula combines as a near-minimum, i.e.
//!    elastic deformation still shapes the film.
//!
//! The default limits (−0.4 and 1.0) let the isoviscous asymptote exceed the piezoviscous one by
//! up to 50 % and the elastic one exceed the rigid one by up to a factor e: the transitions on
//! both sides, where the reference machines' light rollers run, are inside; the purely
//! iso-viscous and purely rigid corners are not.
//!
//! Both are linear inequalities in `(ln M, ln L)`, so the core evaluates them with a few
//! multiply-adds on the logarithms it already computes for the network input.

use serde::{Deserialize, Serialize};

use super::ContactCase;
use crate::dataset::formulas::{moes_parameters, MoesAsymptotes};

/// One input range, sampled uniformly in the value or in its logarithm.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Interval {
    /// Lower end (SI unit of the input).
    pub min: f64,
    /// Upper end (SI unit of the input).
    pub max: f64,
    /// Sample uniformly in `ln(value)` rather than in the value.
    pub log: bool,
}

impl Interval {
    /// Map `t ∈ [0, 1]` onto the interval.
    pub fn at(&self, t: f64) -> f64 {
        if self.log {
            (self.min.ln() + t * (self.max.ln() - self.min.ln())).exp()
        } else {
            self.min + t * (self.max - self.min)
        }
    }

    /// Whether `value` lies in the closed interval (a relative slack of 1e-9 absorbs the
    /// round trip through the logarithm).
    pub fn contains(&self, value: f64) -> bool {
        value >= self.min * (1.0 - 1e-9) && value <= self.max * (1.0 + 1e-9)
    }
}

/// Regime limits on the Moes asymptotes (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RegimeLimits {
    /// Minimum of `ln(H_EP / max(H_RI, H_EI))`.
    pub piezo_min_log_ratio: f64,
    /// Maximum of `ln(H_EP / H_RP)`.
    pub elastic_max_log_ratio: f64,
}

/// The sampling domain: input box plus Hertz-pressure and regime constraints.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Domain {
    /// Roller load Q (N).
    pub load_n: Interval,
    /// Entrainment speed u_m (m/s).
    pub entrainment_speed_m_s: Interval,
    /// Reduced radius R (m).
    pub reduced_radius_m: Interval,
    /// Reduced modulus E' (Pa).
    pub reduced_modulus_pa: Interval,
    /// Pressure–viscosity coefficient α (1/Pa).
    pub pressure_viscosity_pa_inv: Interval,
    /// Ambient viscosity η₀ (Pa·s).
    pub viscosity_pa_s: Interval,
    /// Effective contact length l (m).
    pub length_m: Interval,
    /// Maximum Hertz pressure window p_h (Pa).
    pub hertz_pressure_pa: Interval,
    /// Piezoviscous–elastic regime test.
    pub regime: RegimeLimits,
}

/// Why a case lies outside the domain (the first reason found).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutOfDomain {
    /// An input outside its box range; the name of the input.
    Input(&'static str),
    /// Hertz pressure outside its window (0.15–3.5 GPa by default).
    HertzPressure,
    /// An isoviscous asymptote dominates.
    NotPiezoviscous,
    /// The rigid–piezoviscous asymptote dominates.
    NotElastic,
}

impl Default for Domain {
    /// docs/physics.md §5.3 (thesis Table 5.1), widened as the module doc says.
    fn default() -> Self {
        Self {
            load_n: Interval {
                min: 50.0,
                max: 5000.0,
                log: true,
            },
            entrainment_speed_m_s: Interval {
                min: 0.6,
                max: 40.0,
                log: true,
            },
            reduced_radius_m: Interval {
                min: 0.1e-3,
                max: 20e-3,
                log: true,
            },
            reduced_modulus_pa: Interval {
                min: 200e9,
                max: 250e9,
                log: false,
            },
            pressure_viscosity_pa_inv: Interval {
                min: 10e-9,
                max: 30e-9,
                log: true,
            },
            viscosity_pa_s: Interval {
                min: 0.0005,
                max: 0.1,
                log: true,
            },
            length_m: Interval {
                min: 1e-3,
                max: 50e-3,
                log: true,
            },
            hertz_pressure_pa: Interval {
                min: 0.15e9,
                max: 3.5e9,
                log: true,
            },
            regime: RegimeLimits {
                piezo_min_log_ratio: -0.4,
                elastic_max_log_ratio: 1.0,
            },
        }
    }
}

impl Domain {
    /// The seven inputs in a fixed order (the order of the unit-cube coordinates).
    pub fn inputs(&self) -> [(&'static str, Interval); 7] {
        [
            ("load_n", self.load_n),
            ("entrainment_speed_m_s", self.entrainment_speed_m_s),
            ("reduced_radius_m", self.reduced_radius_m),
            ("reduced_modulus_pa", self.reduced_modulus_pa),
            ("pressure_viscosity_pa_inv", self.pressure_viscosity_pa_inv),
            ("viscosity_pa_s", self.viscosity_pa_s),
            ("length_m", self.length_m),
        ]
    }

    /// The case at unit-cube point `t` (coordinates in the order of [`Domain::inputs`]).
    pub fn case_at(&self, t: &[f64; 7]) -> ContactCase {
        let [q, u, r, e, a, eta, l] = self.inputs().map(|(_, iv)| iv);
        ContactCase {
            load_n: q.at(t[0]),
            entrainment_speed_m_s: u.at(t[1]),
            reduced_radius_m: r.at(t[2]),
            reduced_modulus_pa: e.at(t[3]),
            pressure_viscosity_pa_inv: a.at(t[4]),
            viscosity_pa_s: eta.at(t[5]),
            length_m: l.at(t[6]),
        }
    }

    /// Check a case against box, Hertz window and regime; `Ok(())` inside.
    pub fn check(&self, case: &ContactCase) -> Result<(), OutOfDomain> {
        let values = [
            case.load_n,
            case.entrainment_speed_m_s,
            case.reduced_radius_m,
            case.reduced_modulus_pa,
            case.pressure_viscosity_pa_inv,
            case.viscosity_pa_s,
            case.length_m,
        ];
        for ((name, iv), v) in self.inputs().iter().zip(values) {
            if !iv.contains(v) {
                return Err(OutOfDomain::Input(name));
            }
        }
        if !self.hertz_pressure_pa.contains(case.hertz_pressure_pa()) {
            return Err(OutOfDomain::HertzPressure);
        }
        let (piezo, elastic) = regime_log_ratios(case);
        if piezo < self.regime.piezo_min_log_ratio {
            return Err(OutOfDomain::NotPiezoviscous);
        }
        if elastic > self.regime.elastic_max_log_ratio {
            return Err(OutOfDomain::NotElastic);
        }
        Ok(())
    }
}

/// `(ln(H_EP / max(H_RI, H_EI)), ln(H_EP / H_RP))` of a case (see the module doc).
pub fn regime_log_ratios(case: &ContactCase) -> (f64, f64) {
    let (w, u, g) = case.dimensionless();
    let (m, l) = moes_parameters(w, u, g);
    let a = MoesAsymptotes::new(m, l);
    let iso = a.rigid_isoviscous.max(a.elastic_isoviscous);
    (
        (a.elastic_piezoviscous / iso).ln(),
        (a.elastic_piezoviscous / a.rigid_piezoviscous).ln(),
    )
}
