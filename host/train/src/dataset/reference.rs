//! Does the training domain contain the reference machines of docs/physics.md §6?
//!
//! Until the bearing model computes roller loads, the most loaded roller is estimated with
//! Stribeck's formula `Q_max = 4.08 F / Z` (zero clearance, line contact; Harris & Kotzalas,
//! *Rolling Bearing Analysis*, 5th ed., §7.2) and the entrainment speed with the pure-rolling
//! kinematics of docs/physics.md §2. Both raceway contacts (inner: convex, outer: concave) are
//! checked at every speed of each case's sweep. The effective length is taken as the roller
//! length (edge radii are not given in §6). Rollers away from the load line carry less than
//! `Q_max` and drop below the 50 N / 0.15 GPa floor near the edge of the loaded zone; those
//! contacts are served by the fallback formula, which is what the domain guard is for.

use super::domain::OutOfDomain;
use super::{ContactCase, Domain};

/// Geometry and lubricant of one reference bearing.
#[derive(Clone, Copy, Debug)]
pub struct ReferenceBearing {
    /// Case name (section of docs/physics.md).
    pub name: &'static str,
    /// Pitch diameter d_m (m).
    pub pitch_diameter_m: f64,
    /// Roller diameter D (m).
    pub roller_diameter_m: f64,
    /// Effective length l (m).
    pub length_m: f64,
    /// Number of rollers Z.
    pub rollers: usize,
    /// Reduced modulus E' (Pa).
    pub reduced_modulus_pa: f64,
    /// α (1/Pa).
    pub pressure_viscosity_pa_inv: f64,
    /// η₀ (Pa·s).
    pub viscosity_pa_s: f64,
}

/// One checked contact.
#[derive(Clone, Debug)]
pub struct ReferenceContact {
    /// Case name.
    pub name: &'static str,
    /// `"inner"` or `"outer"`.
    pub race: &'static str,
    /// Shaft speed (rpm).
    pub speed_rpm: f64,
    /// Radial load on the bearing (N).
    pub radial_load_n: f64,
    /// The most loaded roller's contact.
    pub case: ContactCase,
    /// Inside the domain, or why not.
    pub verdict: Result<(), OutOfDomain>,
}

/// E' of two equal solids, `E/(1−ν²)` (docs/physics.md §1).
const fn reduced_modulus(e: f64, nu: f64) -> f64 {
    e / (1.0 - nu * nu)
}

impl ReferenceBearing {
    /// Both raceway contacts of the most loaded roller at a shaft speed and radial load.
    pub fn contacts(&self, speed_rpm: f64, radial_load_n: f64) -> [(&'static str, ContactCase); 2] {
        let d = self.roller_diameter_m;
        let dm = self.pitch_diameter_m;
        let gamma = d / dm;
        let omega = speed_rpm * std::f64::consts::PI / 30.0;
        let u_m = dm / 4.0 * (1.0 - gamma * gamma) * omega; // docs/physics.md §2
        let r_i = (dm - d) / 2.0;
        let r_o = (dm + d) / 2.0;
        let r_in = (d / 2.0) * r_i / (r_i + d / 2.0);
        let r_out = (d / 2.0) * r_o / (r_o - d / 2.0);
        let q_max = 4.08 * radial_load_n / self.rollers as f64; // Stribeck
        let case = |r| ContactCase {
            load_n: q_max,
            entrainment_speed_m_s: u_m,
            reduced_radius_m: r,
            reduced_modulus_pa: self.reduced_modulus_pa,
            pressure_viscosity_pa_inv: self.pressure_viscosity_pa_inv,
            viscosity_pa_s: self.viscosity_pa_s,
            length_m: self.length_m,
        };
        [("inner", case(r_in)), ("outer", case(r_out))]
    }
}

/// §6.1 test-rig NU 205 ECP: d_m = 31.5 + 7.5 = 39 mm, roller 7.5 × 9 mm, 12 rollers, E = 210 GPa,
/// ν = 0.3, α = 2.1·10⁻⁸ Pa⁻¹, η₀ = 0.08 Pa·s.
pub const TEST_RIG: ReferenceBearing = ReferenceBearing {
    name: "6.1 test rig NU 205",
    pitch_diameter_m: 39e-3,
    roller_diameter_m: 7.5e-3,
    length_m: 9e-3,
    rollers: 12,
    reduced_modulus_pa: reduced_modulus(210e9, 0.3),
    pressure_viscosity_pa_inv: 2.1e-8,
    viscosity_pa_s: 0.08,
};

/// §6.2 hub-motor bearing: d_m = 60 mm, roller 8.8 × 15 mm, 17 rollers, same lubricant/steel.
pub const HUB_MOTOR: ReferenceBearing = ReferenceBearing {
    name: "6.2 hub motor",
    pitch_diameter_m: 60e-3,
    roller_diameter_m: 8.8e-3,
    length_m: 15e-3,
    rollers: 17,
    reduced_modulus_pa: reduced_modulus(210e9, 0.3),
    pressure_viscosity_pa_inv: 2.1e-8,
    viscosity_pa_s: 0.08,
};

/// §6.3 static check: d_m = 39 mm, roller 7.5 × 15 mm, 12 rollers, E = 218 GPa; the lubricant is
/// not given in §6.3, so the §6.1 oil is assumed.
pub const STATIC_CHECK: ReferenceBearing = ReferenceBearing {
    name: "6.3 static check",
    pitch_diameter_m: 39e-3,
    roller_diameter_m: 7.5e-3,
    length_m: 15e-3,
    rollers: 12,
    reduced_modulus_pa: reduced_modulus(218e9, 0.3),
    pressure_viscosity_pa_inv: 2.1e-8,
    viscosity_pa_s: 0.08,
};

/// Radial load on one hub-motor bearing at a shaft speed (§6.2): the pinion force
/// `F = (T/r_p)·√(1 + tan²20°)` with `r_p = 17·4/2 mm`, `T = min(68 N·m, 54 kW/ω)`, shared
/// equally by the two bearings (pinion at mid-span).
pub fn hub_motor_bearing_load(speed_rpm: f64) -> f64 {
    let omega = speed_rpm * std::f64::consts::PI / 30.0;
    let torque = if omega > 0.0 {
        68.0f64.min(54e3 / omega)
    } else {
        68.0
    };
    let tangential = torque / 34e-3;
    0.5 * tangential * (1.0 + 20f64.to_radians().tan().powi(2)).sqrt()
}

/// Every checked contact: §6.1 at 750 N over 0–15 000 rpm (250 rpm steps), §6.2 over its
/// sweep (1000–21 000 rpm every 1000, 12 000–14 000 every 250), §6.3 at 2500 N, 10 000 rpm.
pub fn check_reference_cases(domain: &Domain) -> Vec<ReferenceContact> {
    let mut out = Vec::new();
    let mut push = |b: &ReferenceBearing, rpm: f64, load: f64| {
        for (race, case) in b.contacts(rpm, load) {
            out.push(ReferenceContact {
                name: b.name,
                race,
                speed_rpm: rpm,
                radial_load_n: load,
                case,
                verdict: domain.check(&case),
            });
        }
    };
    for k in 0..=60 {
        push(&TEST_RIG, 250.0 * k as f64, 750.0);
    }
    let mut hub: Vec<f64> = (1..=21).map(|k| 1000.0 * k as f64).collect();
    hub.extend((0..=8).map(|k| 12_000.0 + 250.0 * k as f64));
    hub.sort_by(f64::total_cmp);
    hub.dedup();
    for rpm in hub {
        push(&HUB_MOTOR, rpm, hub_motor_bearing_load(rpm));
    }
    push(&STATIC_CHECK, 10_000.0, 2500.0);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand numbers for §6.1 (docs/physics.md §1–2): Q_max = 4.08·750/12 = 255 N; at 15 000 rpm
    /// u_m = (0.039/4)(1 − (7.5/39)²)·1570.8 = 14.75 m/s; R_in = 3.75·15.75/19.5 mm = 3.029 mm;
    /// p_h = √(w E'/(2πR)) = √(28 333 · 230.77e9 / (2π · 3.029e-3)) = 0.586 GPa.
    #[test]
    fn test_rig_hand_numbers() {
        let [(_, inner), _] = TEST_RIG.contacts(15_000.0, 750.0);
        assert!((inner.load_n - 255.0).abs() < 1e-9);
        assert!((inner.entrainment_speed_m_s - 14.75).abs() < 0.01);
        assert!((inner.reduced_radius_m - 3.029e-3).abs() < 1e-6);
        assert!((inner.hertz_pressure_pa() / 0.586e9 - 1.0).abs() < 0.002);
        assert!((reduced_modulus(210e9, 0.3) / 230.8e9 - 1.0).abs() < 1e-3);
    }

    /// The claim of the domain check: every contact of the most loaded roller of the §6.1 rig
    /// from u_m ≥ 0.6 m/s (≥ 750 rpm on the 250 rpm grid) to 15 000 rpm, of the §6.2 hub motor
    /// over its whole sweep (1000–21 000 rpm, down to 92 N and 0.21 GPa at full speed) and of
    /// the §6.3 case lies inside.
    #[test]
    fn reference_cases_inside_the_domain() {
        let contacts = check_reference_cases(&Domain::default());
        for c in &contacts {
            let inside_expected = match c.name {
                n if n == TEST_RIG.name => c.speed_rpm >= 750.0,
                _ => true,
            };
            assert_eq!(
                c.verdict.is_ok(),
                inside_expected,
                "{} {} at {} rpm: {:?}",
                c.name,
                c.race,
                c.speed_rpm,
                c.verdict
            );
        }
    }
}
