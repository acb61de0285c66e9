//! Kinematics of a cylindrical roller bearing with a fixed outer ring (docs/physics.md §2).
//!
//! Pure rolling is assumed: the cage turns at ω_c = (ω/2)(1 − γ) and both contacts see the
//! same entrainment speed u_m = (d_m/4)(1 − γ²)ω, γ = D/d_m.

use crate::params::BearingGeometry;

/// Characteristic frequencies of the bearing at one shaft speed (Hz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PassFrequencies {
    /// Shaft rotation frequency f_s = ω/2π.
    pub shaft_hz: f32,
    /// Cage rotation frequency f_c = (f_s/2)(1 − γ).
    pub cage_hz: f32,
    /// Outer-race pass (varying compliance) frequency f_bpo = Z f_c.
    pub outer_race_hz: f32,
    /// Inner-race pass frequency f_bpi = (Z f_s/2)(1 + γ).
    pub inner_race_hz: f32,
}

impl BearingGeometry {
    /// γ = D / d_m (–).
    pub fn diameter_ratio(&self) -> f32 {
        self.roller_diameter_m() / self.pitch_diameter_m()
    }

    /// Inner raceway radius r_i = (d_m − D)/2 (m).
    pub fn inner_raceway_radius_m(&self) -> f32 {
        0.5 * (self.pitch_diameter_m() - self.roller_diameter_m())
    }

    /// Outer raceway radius r_o = (d_m + D)/2 (m).
    pub fn outer_raceway_radius_m(&self) -> f32 {
        0.5 * (self.pitch_diameter_m() + self.roller_diameter_m())
    }

    /// Reduced radius of the inner contact, R_in = (D/2)·r_i/(r_i + D/2) (m): two convex
    /// cylinders.
    pub fn inner_reduced_radius_m(&self) -> f32 {
        let r = 0.5 * self.roller_diameter_m();
        let ri = self.inner_raceway_radius_m();
        r * ri / (ri + r)
    }

    /// Reduced radius of the outer contact, R_out = (D/2)·r_o/(r_o − D/2) (m): the concave
    /// raceway enters with a minus sign.
    pub fn outer_reduced_radius_m(&self) -> f32 {
        let r = 0.5 * self.roller_diameter_m();
        let ro = self.outer_raceway_radius_m();
        r * ro / (ro - r)
    }

    /// Cage speed ω_c = (ω/2)(1 − γ) (rad/s) for shaft speed ω (rad/s).
    pub fn cage_speed_rad_s(&self, shaft_speed_rad_s: f32) -> f32 {
        0.5 * shaft_speed_rad_s * (1.0 - self.diameter_ratio())
    }

    /// Entrainment (mean rolling) speed u_m = (d_m/4)(1 − γ²)|ω| (m/s), the same at both
    /// contacts in pure rolling.
    pub fn entrainment_speed_m_s(&self, shaft_speed_rad_s: f32) -> f32 {
        let g = self.diameter_ratio();
        0.25 * self.pitch_diameter_m() * (1.0 - g * g) * shaft_speed_rad_s.abs()
    }

    /// Pass frequencies at shaft speed ω (rad/s).
    pub fn pass_frequencies(&self, shaft_speed_rad_s: f32) -> PassFrequencies {
        let g = self.diameter_ratio();
        let z = f32::from(self.roller_count());
        let shaft_hz = shaft_speed_rad_s.abs() / (2.0 * core::f32::consts::PI);
        let cage_hz = 0.5 * shaft_hz * (1.0 - g);
        PassFrequencies {
            shaft_hz,
            cage_hz,
            outer_race_hz: z * cage_hz,
            inner_race_hz: 0.5 * z * shaft_hz * (1.0 + g),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::params::{BearingGeometry, Crown};

    fn nu205() -> BearingGeometry {
        // docs/physics.md §6.1: raceways Ø31.5 / Ø46.5 mm → d_m = 39 mm, D = 7.5 mm, 12 rollers.
        BearingGeometry::new(0.039, 0.0075, 0.009, 12, Crown::None, 0.0).unwrap()
    }

    #[test]
    fn raceways_and_reduced_radii_follow_section_2() {
        let g = nu205();
        assert!((g.inner_raceway_radius_m() - 0.01575).abs() < 1e-7);
        assert!((g.outer_raceway_radius_m() - 0.02325).abs() < 1e-7);
        // R_in = 3.75·15.75/19.5 mm, R_out = 3.75·23.25/19.5 mm.
        assert!((g.inner_reduced_radius_m() / (3.75e-3 * 15.75 / 19.5) - 1.0).abs() < 1e-6);
        assert!((g.outer_reduced_radius_m() / (3.75e-3 * 23.25 / 19.5) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn pass_frequencies_match_the_closed_forms() {
        // 14 000 rpm: f_s = 233.33 Hz, γ = 7.5/39.
        let g = nu205();
        let omega = 14_000.0 * 2.0 * core::f64::consts::PI / 60.0;
        let f = g.pass_frequencies(omega as f32);
        let fs = 14_000.0 / 60.0;
        let gamma = 7.5 / 39.0;
        let bpo = 12.0 * fs / 2.0 * (1.0 - gamma);
        let bpi = 12.0 * fs / 2.0 * (1.0 + gamma);
        assert!(
            (f.outer_race_hz as f64 / bpo - 1.0).abs() < 1e-5,
            "{} vs {bpo}",
            f.outer_race_hz
        );
        assert!((f.inner_race_hz as f64 / bpi - 1.0).abs() < 1e-5);
        // f_bpo + f_bpi = Z f_s.
        assert!(((f.outer_race_hz + f.inner_race_hz) as f64 / (12.0 * fs) - 1.0).abs() < 1e-5);
        // Cage speed and entrainment: u_m = ω_c·r_i + ... ; check u_m = (d_m/4)(1−γ²)ω.
        let um = 0.039 / 4.0 * (1.0 - gamma * gamma) * omega;
        assert!((g.entrainment_speed_m_s(omega as f32) as f64 / um - 1.0).abs() < 1e-5);
    }

    #[test]
    fn entrainment_equals_the_mean_surface_speed_at_the_inner_contact() {
        // Independent check: inner ring surface speed relative to the cage is (ω − ω_c)·r_i,
        // and the roller surface speed equals it in pure rolling; u_m is their mean.
        let g = nu205();
        let omega = 1000.0f32;
        let rel = (omega - g.cage_speed_rad_s(omega)) * g.inner_raceway_radius_m();
        assert!((g.entrainment_speed_m_s(omega) / rel - 1.0).abs() < 1e-5);
    }
}
