//! Friction and power loss of the roller–race line contacts in mixed elastohydrodynamic
//! lubrication (docs/physics.md §8), at a fixed cost per contact.
//!
//! Per contact, from its own load Q and central film h (so that the inner and outer contact
//! may carry different loads and films):
//!
//! 1. λ = h/σ with the composite roughness σ, and the lubrication regime
//!    ([`Lubrication`]: boundary λ < 1, mixed 1 ≤ λ < 3, full film λ ≥ 3);
//! 2. the Greenwood–Tripp asperity load W_a and real area A_a ([`asperity`]); the film carries
//!    the rest, Q − W_a (load sharing, without iterating the film: see [`Prepared::contact`]);
//! 3. boundary friction F_b = τ_b·A_a + ζ·W_a;
//! 4. viscous (sliding) traction of the film at the slide-to-roll ratio s: the lesser of the
//!    isothermal Eyring traction and the thermal-Eyring traction of Evans & Johnson
//!    ([`traction`]);
//! 5. rolling (inlet) resistance F_R of Goksem & Hargreaves ([`traction`]).
//!
//! The bearing sums them ([`FrictionSums`]): the friction torque on the inner ring is the
//! dissipated power over the shaft speed, M = k·Σ(F_R + s·(F_v + F_b)) with k = u_m/|ω| =
//! (d_m/4)(1 − γ²), the power P = M·|ω|. Cage, roller-end and churning losses and roller
//! skid are not modelled.

pub mod asperity;
mod params;
pub mod traction;
// Generated, with the core's other generated files, into `core/src/generated/` (its README).
#[path = "../generated/traction_table.rs"]
pub mod traction_table;

pub use params::{FrictionDesign, FrictionParams};

use crate::film::ContactInput;
use crate::math::{max, min, select, sqrt};
use asperity::Roughness;
use traction::{IsothermalEyring, RollingLaw, Thermal};

/// Lubrication regime of a contact by its film ratio λ = h_c/σ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lubrication {
    /// λ < 1: the asperities carry much of the load.
    Boundary,
    /// 1 ≤ λ < 3: film and asperities share the load.
    Mixed,
    /// λ ≥ 3: the film separates the surfaces.
    FullFilm,
}

impl Lubrication {
    /// The regime of film ratio `lambda` (NaN counts as boundary).
    pub fn of(lambda: f32) -> Self {
        if lambda >= 3.0 {
            Lubrication::FullFilm
        } else if lambda >= 1.0 {
            Lubrication::Mixed
        } else {
            Lubrication::Boundary
        }
    }

    /// Short name for reports and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Lubrication::Boundary => "boundary",
            Lubrication::Mixed => "mixed",
            Lubrication::FullFilm => "full_film",
        }
    }
}

/// Friction of one line contact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactFriction {
    /// Contact load Q (N).
    pub load_n: f32,
    /// Film ratio λ = h_c/σ.
    pub lambda: f32,
    /// Load carried by the asperities W_a (N), at most Q.
    pub asperity_load_n: f32,
    /// Rolling (inlet) resistance F_R (N).
    pub rolling_n: f32,
    /// Viscous traction of the film F_v at the slide-to-roll ratio (N).
    pub viscous_n: f32,
    /// Boundary friction of the asperities F_b (N).
    pub boundary_n: f32,
}

impl ContactFriction {
    /// The traction (sliding friction) coefficient (F_v + F_b)/Q; 0 without load.
    pub fn friction_coefficient(&self) -> f32 {
        let q = self.load_n;
        select(
            q > 0.0,
            (self.viscous_n + self.boundary_n) / max(q, f32::MIN_POSITIVE),
            0.0,
        )
    }

    /// The lubrication regime of λ.
    pub fn lubrication(&self) -> Lubrication {
        Lubrication::of(self.lambda)
    }
}

/// Floor on the film in the friction arithmetic (m): a contact at standstill (zero film) is
/// in boundary lubrication (λ = 0), and the film's viscous traction with u_s → 0 stays finite.
const MIN_FILM_M: f32 = 1.0e-10;
/// Floor on the rolling speed in the thermal and rolling terms (m/s), as the step's.
const MIN_SPEED_M_S: f32 = 1.0e-6;

/// The friction model of one contact kind at one speed: what does not change from roller to
/// roller within a step.
#[derive(Clone, Copy, Debug)]
pub struct Prepared {
    params: FrictionParams,
    roughness: Roughness,
    inv_sigma: f32,
    thermal: Thermal,
    isothermal: IsothermalEyring,
    rolling: RollingLaw,
    rolling_speed_m_s: f32,
}

impl Prepared {
    /// For the contacts of `template` (its speed and lubricant; its load is not used).
    pub fn new(params: &FrictionParams, template: &ContactInput) -> Self {
        let u = max(template.entrainment_speed_m_s, MIN_SPEED_M_S);
        let p = params;
        let thermal_loading =
            template.viscosity_pa_s * p.viscosity_temperature_coefficient_k_inv * u * u
                / p.fluid_conductivity_w_mk;
        Self {
            params: *p,
            roughness: Roughness::new(
                p.composite_roughness_m,
                p.asperity_density_m2,
                p.summit_radius_m,
            ),
            inv_sigma: 1.0 / p.composite_roughness_m,
            thermal: Thermal {
                eyring_stress_pa: p.eyring_stress_pa,
                fluid_conductivity_w_mk: p.fluid_conductivity_w_mk,
                viscosity_temperature_k_inv: p.viscosity_temperature_coefficient_k_inv,
                solid_effusivity_sq: p.solid_conductivity_w_mk
                    * p.solid_density_kg_m3
                    * p.solid_heat_capacity_j_kgk,
            },
            isothermal: IsothermalEyring::new(
                p.eyring_stress_pa,
                template.viscosity_pa_s,
                template.pressure_viscosity_pa_inv,
                u,
                p.slide_to_roll_ratio * u,
                template.reduced_radius_m,
                template.reduced_modulus_pa,
            ),
            rolling: RollingLaw::new(thermal_loading),
            rolling_speed_m_s: u,
        }
    }

    /// The friction of a contact with the geometry and lubricant of `input`, its load
    /// `input.load_n` (N) and central film `central_film_m` (m); the same operations for
    /// every input.
    ///
    /// Load sharing: the asperity load is evaluated at the film the step computed for the
    /// whole load Q, and the film's traction uses the pressure of the rest, Q − W_a. Solving
    /// for the film of Q − W_a instead would raise h by (1 − W_a/Q)^(−0.13) at most (the load
    /// exponent of the line-contact film, Dowson & Higginson): +9 % where the asperities carry
    /// half the load, +3 % where they carry a fifth, and lower W_a further; the fixed-cost
    /// form overestimates the asperity share in mixed lubrication by that much. Near λ = 0
    /// (standstill, boundary lubrication) it underestimates it: there the surfaces would close
    /// further (λ < 0) until the asperities carry the load the film no longer can, and the
    /// separation is not re-solved; W_a stays at its λ = 0 value.
    pub fn contact(&self, input: &ContactInput, central_film_m: f32) -> ContactFriction {
        let p = &self.params;
        let q = max(input.load_n, 0.0);
        let l = input.length_m;
        let r = input.reduced_radius_m;
        let e = input.reduced_modulus_pa;
        // Hertz half-width of a line contact, b = √(8·Q·R/(π·l·E′)) (E′ of docs/physics.md §1).
        let b = sqrt(8.0 * q * r / (core::f32::consts::PI * l * e));
        let area = max(2.0 * b * l, 1.0e-18);
        let lambda = max(central_film_m, 0.0) * self.inv_sigma;
        let h = max(central_film_m, MIN_FILM_M);
        let (asperity, real_area) = self.roughness.contact(lambda, e, area);
        let asperity = min(asperity, q);
        let film_load = q - asperity;
        let mean_pressure = film_load / area;
        let boundary =
            p.boundary_shear_strength_pa * real_area + p.boundary_friction_coefficient * asperity;
        // The film's share Q − W_a on its own Hertz zone (half-width b_f, peak pressure p_f):
        // its isothermal traction is the tabulated numerical solution's at that load.
        let film_half_width = sqrt(8.0 * film_load * r / (core::f32::consts::PI * l * e));
        let film_peak_pressure =
            2.0 * film_load / (core::f32::consts::PI * max(film_half_width, 1.0e-12) * l);
        let isothermal = self.isothermal.traction_n(
            max(film_load, 1.0e-6),
            l,
            film_half_width,
            film_peak_pressure,
            h,
        );
        // The thermal (Evans–Johnson) stress over Hertz's zone, widened at light load
        // (b_eff/b, same load), where its α·p̄/2 is the mean of ln η.
        let peak_pressure = (4.0 / core::f32::consts::PI) * mean_pressure;
        let widening = traction::pressure_zone_widening(
            h,
            r,
            b,
            input.pressure_viscosity_pa_inv * peak_pressure,
        );
        let thermal = area
            * widening
            * traction::evans_johnson_stress_pa(
                &self.thermal,
                input.viscosity_pa_s,
                input.pressure_viscosity_pa_inv,
                mean_pressure / widening,
                h,
                r,
                e,
                self.rolling_speed_m_s,
            );
        let rolling = traction::rolling_n(
            &self.rolling,
            q,
            l,
            r,
            e,
            input.pressure_viscosity_pa_inv,
            input.viscosity_pa_s,
            self.rolling_speed_m_s,
        );
        ContactFriction {
            load_n: q,
            lambda,
            asperity_load_n: asperity,
            rolling_n: rolling,
            viscous_n: min(isothermal, thermal),
            boundary_n: boundary,
        }
    }
}

impl FrictionParams {
    /// The friction of one contact (see [`Prepared::contact`]).
    pub fn contact(&self, input: &ContactInput, central_film_m: f32) -> ContactFriction {
        Prepared::new(self, input).contact(input, central_film_m)
    }
}

/// The contact forces of a bearing summed over its contacts, and the torque and power they
/// cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrictionSums {
    /// Σ F_R (N).
    pub rolling_n: f32,
    /// Σ F_v (N).
    pub viscous_n: f32,
    /// Σ F_b (N).
    pub boundary_n: f32,
}

/// Friction torque and power loss of a bearing.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BearingFriction {
    /// Friction torque on the inner ring M (N·m).
    pub torque_nm: f32,
    /// Power loss P = M·|ω| (W).
    pub power_loss_w: f32,
    /// P split into [rolling, viscous, boundary] (W).
    pub power_loss_split_w: [f32; 3],
}

impl FrictionSums {
    /// Add one contact.
    #[inline]
    pub fn add(&mut self, c: &ContactFriction) {
        self.rolling_n += c.rolling_n;
        self.viscous_n += c.viscous_n;
        self.boundary_n += c.boundary_n;
    }

    /// Torque and power at shaft speed ω for a bearing whose entrainment speed is
    /// u_m = k·|ω| (k = `entrainment_per_shaft_speed_m`, m) and whose contacts slide at the
    /// slide-to-roll ratio s: the rolling resistance dissipates F_R·u_m, the sliding forces
    /// (F_v + F_b)·s·u_m.
    pub fn bearing(
        &self,
        entrainment_per_shaft_speed_m: f32,
        slide_to_roll_ratio: f32,
        shaft_speed_rad_s: f32,
    ) -> BearingFriction {
        let k = entrainment_per_shaft_speed_m;
        let torque = [
            k * self.rolling_n,
            k * slide_to_roll_ratio * self.viscous_n,
            k * slide_to_roll_ratio * self.boundary_n,
        ];
        let w = shaft_speed_rad_s.abs();
        let split = torque.map(|t| t * w);
        BearingFriction {
            torque_nm: torque[0] + torque[1] + torque[2],
            power_loss_w: split[0] + split[1] + split[2],
            power_loss_split_w: split,
        }
    }
}

#[cfg(test)]
mod tests;
