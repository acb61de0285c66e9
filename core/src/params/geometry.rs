//! Cylindrical roller bearing geometry (docs/physics.md §2, §3).

use crate::error::{in_range, positive, Allowed, ParamError};

/// Largest roller count a geometry may have.
pub const MAX_ROLLERS: u16 = 128;

/// Axial profile of the roller (crowning), which relieves the roller ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Crown {
    /// Straight roller: no crown drop.
    None,
    /// Logarithmic profile of ISO/TS 16281, multiplied by `scale` (1.0 = the standard):
    /// drop P(x) = scale · 0.00035 · D · ln[1 / (1 − (2x/l)²)] (docs/physics.md §3; the formula is
    /// dimensionally homogeneous, so it holds in metres as in millimetres).
    Logarithmic {
        /// Multiplier on the ISO/TS 16281 profile (0 … 10).
        scale: f32,
    },
}

/// Geometry of a cylindrical roller bearing with `roller_count` rollers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingGeometry {
    pitch_diameter_m: f32,
    roller_diameter_m: f32,
    roller_length_m: f32,
    roller_count: u16,
    crown: Crown,
    radial_clearance_m: f32,
}

impl BearingGeometry {
    /// A bearing of pitch diameter d_m, roller diameter D < d_m, effective contact length l
    /// (roller length minus edge radii), `roller_count` Z rollers (3 … 128, and they must fit
    /// on the pitch circle: Z·D < π·d_m), a crown profile and the radial internal clearance g_r
    /// per roller (m; negative for an interference preload, −1 mm … 1 mm).
    pub fn new(
        pitch_diameter_m: f32,
        roller_diameter_m: f32,
        roller_length_m: f32,
        roller_count: u16,
        crown: Crown,
        radial_clearance_m: f32,
    ) -> Result<Self, ParamError> {
        let pitch_diameter_m = in_range("pitch_diameter_m", pitch_diameter_m, 1.0e-3, 10.0)?;
        let roller_diameter_m = positive("roller_diameter_m", roller_diameter_m)?;
        if roller_diameter_m >= pitch_diameter_m {
            return Err(ParamError {
                field: "roller_diameter_m",
                value: roller_diameter_m,
                allowed: Allowed::LessThan {
                    field: "pitch_diameter_m",
                    value: pitch_diameter_m,
                },
            });
        }
        let roller_length_m = in_range("roller_length_m", roller_length_m, 1.0e-4, 1.0)?;
        let max_count = (core::f32::consts::PI * pitch_diameter_m / roller_diameter_m) as u16;
        let max_count = max_count.min(MAX_ROLLERS);
        if roller_count < 3 || roller_count > max_count {
            return Err(ParamError {
                field: "roller_count",
                value: f32::from(roller_count),
                allowed: Allowed::Range {
                    min: 3.0,
                    max: f32::from(max_count),
                },
            });
        }
        if let Crown::Logarithmic { scale } = crown {
            in_range("crown_scale", scale, 0.0, 10.0)?;
        }
        let radial_clearance_m =
            in_range("radial_clearance_m", radial_clearance_m, -1.0e-3, 1.0e-3)?;
        Ok(Self {
            pitch_diameter_m,
            roller_diameter_m,
            roller_length_m,
            roller_count,
            crown,
            radial_clearance_m,
        })
    }

    /// Pitch diameter d_m (m).
    pub fn pitch_diameter_m(&self) -> f32 {
        self.pitch_diameter_m
    }
    /// Roller diameter D (m).
    pub fn roller_diameter_m(&self) -> f32 {
        self.roller_diameter_m
    }
    /// Effective contact length l (m).
    pub fn roller_length_m(&self) -> f32 {
        self.roller_length_m
    }
    /// Number of rollers Z.
    pub fn roller_count(&self) -> u16 {
        self.roller_count
    }
    /// Crown profile.
    pub fn crown(&self) -> Crown {
        self.crown
    }
    /// Radial internal clearance g_r per roller (m; negative = interference).
    pub fn radial_clearance_m(&self) -> f32 {
        self.radial_clearance_m
    }

    /// Crown drop P(x) of the roller profile at axial position `x_m` from the roller middle (m).
    /// Zero for a straight roller; the ISO logarithmic profile is finite for |x| < l/2.
    pub fn crown_drop_m(&self, x_m: f32) -> f32 {
        match self.crown {
            Crown::None => 0.0,
            Crown::Logarithmic { scale } => {
                let r = 2.0 * x_m / self.roller_length_m;
                // Clamp so the ends (|x| → l/2) stay finite.
                let inside = crate::math::max(1.0 - r * r, 1.0e-6);
                scale * 0.000_35 * self.roller_diameter_m * -crate::math::ln(inside)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hub() -> Result<BearingGeometry, ParamError> {
        BearingGeometry::new(0.060, 0.0088, 0.015, 17, Crown::None, -2.0e-6)
    }

    #[test]
    fn accepts_the_hub_motor_bearing() {
        assert!(hub().is_ok());
    }

    #[test]
    fn refuses_rollers_larger_than_the_pitch_circle_and_too_many_rollers() {
        let e = BearingGeometry::new(0.06, 0.06, 0.015, 17, Crown::None, 0.0).unwrap_err();
        assert_eq!(e.field, "roller_diameter_m");
        // π·60/8.8 = 21.4: 22 rollers do not fit.
        let e = BearingGeometry::new(0.06, 0.0088, 0.015, 22, Crown::None, 0.0).unwrap_err();
        assert_eq!(e.field, "roller_count");
        let e = BearingGeometry::new(f32::NAN, 0.0088, 0.015, 17, Crown::None, 0.0).unwrap_err();
        assert_eq!(e.field, "pitch_diameter_m");
        let e = BearingGeometry::new(
            0.06,
            0.0088,
            0.015,
            17,
            Crown::Logarithmic { scale: -1.0 },
            0.0,
        )
        .unwrap_err();
        assert_eq!(e.field, "crown_scale");
    }

    #[test]
    fn iso_crown_drop_matches_the_formula() {
        // ISO/TS 16281 log profile at x = 0.4·l: P = 0.00035·D·ln(1/(1 − 0.8²)).
        let g = BearingGeometry::new(
            0.06,
            0.0088,
            0.015,
            17,
            Crown::Logarithmic { scale: 1.0 },
            0.0,
        )
        .unwrap();
        let expected = 0.000_35 * 0.0088 * (1.0f64 / (1.0 - 0.64)).ln();
        let got = g.crown_drop_m(0.4 * 0.015) as f64;
        assert!((got / expected - 1.0).abs() < 1e-5, "{got} vs {expected}");
        assert_eq!(g.crown_drop_m(0.0), 0.0);
    }
}
