//! High-speed corrections of the isothermal, fully flooded film (docs/physics.md §5.4): inlet
//! shear heating (a thermal reduction factor φ_T) and a limited inlet supply (a starvation
//! factor φ_S).
//!
//! Every film model (regression, networks, the host's numerical solver) solves the isothermal,
//! fully flooded problem; the corrections multiply its film afterwards, the same way for every
//! model, so the networks stay trained on the problem they learn best. Martin's rigid
//! iso-viscous film is left as it is: the factors are fitted to EHL solutions, and the film is
//! corrected as √((φ·e)² + h_RI²) with e = √(h² − h_RI²) the model's non-hydrodynamic part
//! (`corrected_film_m`). Both factors are 1 exactly when a correction is off.

use crate::error::{in_range, ParamError};
use crate::film::ContactInput;
use crate::math::{max, min, pow, sqrt};

/// Floor of the non-hydrodynamic part e = √(h² − h_RI²) relative to h: a model film at or below
/// Martin's (a purely hydrodynamic model) leaves e at this fraction, and the blend then returns
/// Martin's film within 10⁻⁶.
const EHL_PART_FLOOR: f32 = 1.0e-3;

/// Thermal conductivity of a mineral oil at ambient pressure, K ≈ 0.14 W/(m·K) (mineral and
/// synthetic oils lie at 0.12 … 0.15 W/(m·K)); the default of `thermal_conductivity_w_per_m_k`.
pub const OIL_THERMAL_CONDUCTIVITY_W_PER_M_K: f32 = 0.14;

/// Temperature–viscosity coefficient β of η = η₀·e^(−β(T − T₀)) for an ISO VG 68 mineral oil,
/// from its catalogue viscosities (68 mm²/s at 40 °C, ≈ 8.6 mm²/s at 100 °C):
/// β ≈ ln(68/8.6)/60 K ≈ 0.034 1/K; the default of `temperature_viscosity_per_k`.
pub const VG68_TEMPERATURE_VISCOSITY_PER_K: f32 = 0.034;

/// Inlet shear heating after Gupta, Cheng, Zhu and Wedeven (1992; for pure rolling, as the
/// bearing's kinematics assume, docs/physics.md §2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalCorrection {
    temperature_viscosity_per_k: f32,
    conductivity_w_per_m_k: f32,
}

impl ThermalCorrection {
    /// The thermal correction of an oil with temperature–viscosity coefficient β
    /// (`temperature_viscosity_per_k`, 0 … 0.2 1/K) and thermal conductivity K
    /// (`thermal_conductivity_w_per_m_k`, 0.01 … 10 W/(m·K)).
    pub fn new(
        temperature_viscosity_per_k: f32,
        thermal_conductivity_w_per_m_k: f32,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            temperature_viscosity_per_k: in_range(
                "temperature_viscosity_per_k",
                temperature_viscosity_per_k,
                0.0,
                0.2,
            )?,
            conductivity_w_per_m_k: in_range(
                "thermal_conductivity_w_per_m_k",
                thermal_conductivity_w_per_m_k,
                0.01,
                10.0,
            )?,
        })
    }

    /// β (1/K).
    pub fn temperature_viscosity_per_k(&self) -> f32 {
        self.temperature_viscosity_per_k
    }

    /// K (W/(m·K)).
    pub fn conductivity_w_per_m_k(&self) -> f32 {
        self.conductivity_w_per_m_k
    }

    /// The thermal loading number L = η₀·β·u²/K of `contact` (u its entrainment speed).
    pub fn loading_number(&self, contact: &ContactInput) -> f32 {
        let u = contact.entrainment_speed_m_s;
        contact.viscosity_pa_s * self.temperature_viscosity_per_k * u * u
            / self.conductivity_w_per_m_k
    }

    /// φ_T of `contact` ([`gupta_thermal_factor`] at its L and p_h/E').
    pub fn factor(&self, contact: &ContactInput) -> f32 {
        let w = contact.load_n / contact.length_m;
        let e = contact.reduced_modulus_pa;
        // p_h/E' = √(w/(2π·R·E')) (Hertz, docs/physics.md §1).
        let ph_over_e = sqrt(max(
            w / (2.0 * core::f32::consts::PI * contact.reduced_radius_m * e),
            0.0,
        ));
        gupta_thermal_factor(self.loading_number(contact), ph_over_e)
    }
}

/// Gupta, Cheng, Zhu and Wedeven (1992) thermal reduction factor of the central film, pure
/// rolling: φ_T = (1 − 13.2·(p_h/E')·L^0.42)/(1 + 0.213·L^0.64), L the thermal loading number
/// and p_h/E' the peak Hertz pressure over the reduced modulus. (With slide-to-roll ratio s the
/// denominator reads 1 + 0.213·(1 + 2.23·s^0.83)·L^0.64.) Held to [0, 1]: the fit is to
/// numerical thermal solutions for moderate L, and its numerator would turn negative only far
/// beyond them.
pub fn gupta_thermal_factor(loading_number: f32, ph_over_e: f32) -> f32 {
    let l = max(loading_number, 0.0);
    let numerator = 1.0 - 13.2 * ph_over_e * pow(l, 0.42);
    let denominator = 1.0 + 0.213 * pow(l, 0.64);
    min(max(numerator / denominator, 0.0), 1.0)
}

/// Murch and Wilson's (1975) thermal reduction factor of pure rolling, φ_T = 3.94/(3.94 +
/// L^0.62): an independent inlet analysis, against which Gupta's fit is checked.
pub fn murch_wilson_thermal_factor(loading_number: f32) -> f32 {
    3.94 / (3.94 + pow(max(loading_number, 0.0), 0.62))
}

/// Starvation by a limited inlet oil layer after Chevalier, Lubrecht, Cann, Colin and Dalmaz
/// (1998): the film a contact builds from a layer of thickness h_oil on the track, with the
/// fully flooded film h_ff, is h_ff·φ_S with φ_S = r/(1 + r^γ)^(1/γ), r = h_oil/h_ff.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Starvation {
    oil_layer_m: f32,
    transition_exponent: f32,
}

impl Starvation {
    /// Starvation by an inlet oil layer `oil_layer_m` thick (1 nm … 1 mm) with the model's
    /// transition exponent γ (`starvation_exponent`, 0.5 … 10: how sharply the film passes from
    /// supply-limited, φ_S ≈ r, to flooded, φ_S ≈ 1).
    pub fn new(oil_layer_m: f32, transition_exponent: f32) -> Result<Self, ParamError> {
        Ok(Self {
            oil_layer_m: in_range("oil_layer_m", oil_layer_m, 1.0e-9, 1.0e-3)?,
            transition_exponent: in_range("starvation_exponent", transition_exponent, 0.5, 10.0)?,
        })
    }

    /// h_oil (m).
    pub fn oil_layer_m(&self) -> f32 {
        self.oil_layer_m
    }

    /// γ.
    pub fn transition_exponent(&self) -> f32 {
        self.transition_exponent
    }

    /// φ_S for a fully flooded central film `flooded_m` (m).
    pub fn factor(&self, flooded_m: f32) -> f32 {
        chevalier_starvation_factor(
            self.oil_layer_m / max(flooded_m, 1.0e-12),
            self.transition_exponent,
        )
    }
}

/// φ_S = r/(1 + r^γ)^(1/γ) (Chevalier et al. 1998) for the supply ratio r = h_oil/h_ff: 1 as
/// r → ∞ (flooded), r as r → 0 (the film is the supplied layer). Computed as
/// (1 + r^(−γ))^(−1/γ), which stays finite for every r > 0.
pub fn chevalier_starvation_factor(supply_ratio: f32, transition_exponent: f32) -> f32 {
    let r = max(supply_ratio, 1.0e-12);
    let g = transition_exponent;
    pow(1.0 + pow(r, -g), -1.0 / g)
}

/// The factors by which a film is multiplied (1 where a correction is off).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CorrectionFactors {
    /// φ_T.
    pub thermal: f32,
    /// φ_S.
    pub starvation: f32,
}

impl CorrectionFactors {
    /// φ_T·φ_S.
    pub fn product(&self) -> f32 {
        self.thermal * self.starvation
    }
}

/// The film corrections of a bearing, each on or off.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilmCorrections {
    /// Inlet shear heating, when on.
    pub thermal: Option<ThermalCorrection>,
    /// Limited inlet supply, when on.
    pub starvation: Option<Starvation>,
}

impl FilmCorrections {
    /// No correction: the isothermal, fully flooded film of the film model.
    pub const OFF: FilmCorrections = FilmCorrections {
        thermal: None,
        starvation: None,
    };

    /// Neither correction is on.
    pub fn is_off(&self) -> bool {
        self.thermal.is_none() & self.starvation.is_none()
    }

    /// The factors of `contact` whose isothermal, fully flooded central film is
    /// `flooded_central_m` (m): φ_T first, then φ_S with the supply ratio taken against the
    /// thermally reduced film (the film the contact would build with a full inlet).
    pub fn factors(&self, contact: &ContactInput, flooded_central_m: f32) -> CorrectionFactors {
        let thermal = self.thermal.map_or(1.0, |t| t.factor(contact));
        let starvation = self
            .starvation
            .map_or(1.0, |s| s.factor(thermal * flooded_central_m));
        CorrectionFactors {
            thermal,
            starvation,
        }
    }
}

/// The part of a film `h` left after removing the hydrodynamic film `hydro` in quadrature,
/// √(h² − hydro²), floored at [`EHL_PART_FLOOR`]·h.
#[inline]
pub(crate) fn ehl_part(h: f32, hydro: f32) -> f32 {
    let floor = EHL_PART_FLOOR * h;
    sqrt(max(h * h - hydro * hydro, floor * floor))
}

/// A model's complete film `h` (m) corrected by `factor`: √((φ·e)² + h_RI²), e = √(h² − h_RI²)
/// its part beyond Martin's film `martin_m` (m). As the film table serves it (at its nodes).
pub fn corrected_film_m(h: f32, martin_m: f32, factor: f32) -> f32 {
    let e = ehl_part(h, martin_m) * factor;
    sqrt(e * e + martin_m * martin_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// L → 0: no heating, φ_T = 1 for any pressure; Gupta's fit agrees with Murch and Wilson's
    /// independent inlet analysis within 7 % for L ≤ 10 at vanishing p_h/E' (where Gupta's
    /// pressure term drops out): 0.824 against 0.798 at L = 1, 0.518 against 0.486 at L = 10.
    #[test]
    fn thermal_factor_limits_and_murch_wilson() {
        assert_eq!(gupta_thermal_factor(0.0, 0.004), 1.0);
        assert_eq!(murch_wilson_thermal_factor(0.0), 1.0);
        for k in 1..=40 {
            let l = 0.25 * k as f32;
            let gupta = gupta_thermal_factor(l, 0.0);
            let mw = murch_wilson_thermal_factor(l);
            assert!((gupta / mw - 1.0).abs() < 0.07, "L {l}: {gupta} vs {mw}");
        }
        // Closed form at L = 1: 1/1.213 and 3.94/4.94.
        assert!((gupta_thermal_factor(1.0, 0.0) - 1.0 / 1.213).abs() < 1e-6);
        assert!((murch_wilson_thermal_factor(1.0) - 3.94 / 4.94).abs() < 1e-6);
        // The pressure term lowers the factor: (1 − 13.2·0.003)/1.213 at L = 1.
        assert!((gupta_thermal_factor(1.0, 0.003) - (1.0 - 0.0396) / 1.213).abs() < 1e-6);
    }

    /// φ_S → 1 for an ample supply (fully flooded; 1 − φ_S ≈ r^(−γ)/γ on the way), → r for a
    /// thin one, and equals 2^(−1/γ) at r = 1.
    #[test]
    fn starvation_factor_limits() {
        for g in [1.0f32, 2.0, 3.0] {
            assert!((chevalier_starvation_factor(1.0e8, g) - 1.0).abs() < 1e-6);
            let r = 30.0f32;
            let deficit = 1.0 - chevalier_starvation_factor(r, g);
            let asymptote = pow(r, -g) / g;
            assert!(
                (deficit / asymptote - 1.0).abs() < 0.05,
                "γ {g}: {deficit} vs {asymptote}"
            );
            // 1 − φ_S/r ≈ r^γ/γ ≤ 10⁻⁵ here.
            let r = 1.0e-5;
            assert!((chevalier_starvation_factor(r, g) / r - 1.0).abs() < 1e-4);
            let half = chevalier_starvation_factor(1.0, g);
            assert!((half - pow(2.0, -1.0 / g)).abs() < 1e-6, "γ {g}: {half}");
        }
    }

    /// Off is 1 exactly, and a corrected film with factor 1 is the model's film.
    #[test]
    fn off_is_the_identity() {
        let c = ContactInput {
            load_n: 2000.0,
            length_m: 0.015,
            entrainment_speed_m_s: 10.0,
            reduced_radius_m: 3.7e-3,
            reduced_modulus_pa: 2.3e11,
            pressure_viscosity_pa_inv: 2.1e-8,
            viscosity_pa_s: 0.08,
        };
        let f = FilmCorrections::OFF.factors(&c, 1.0e-6);
        assert_eq!((f.thermal, f.starvation), (1.0, 1.0));
        let h = corrected_film_m(1.0e-6, 1.0e-8, 1.0);
        assert!((h / 1.0e-6 - 1.0).abs() < 1e-6);
        let on = FilmCorrections {
            thermal: Some(ThermalCorrection::new(0.034, 0.14).unwrap()),
            starvation: Some(Starvation::new(1.0e-6, 2.0).unwrap()),
        }
        .factors(&c, 1.0e-6);
        assert!(on.thermal < 1.0 && on.starvation < 1.0, "{on:?}");
    }

    #[test]
    fn refusals_name_the_field() {
        assert_eq!(
            ThermalCorrection::new(-0.1, 0.14).unwrap_err().field,
            "temperature_viscosity_per_k"
        );
        assert_eq!(
            ThermalCorrection::new(0.03, 0.0).unwrap_err().field,
            "thermal_conductivity_w_per_m_k"
        );
        assert_eq!(
            Starvation::new(f32::NAN, 2.0).unwrap_err().field,
            "oil_layer_m"
        );
        assert_eq!(
            Starvation::new(1e-6, 0.1).unwrap_err().field,
            "starvation_exponent"
        );
    }
}
