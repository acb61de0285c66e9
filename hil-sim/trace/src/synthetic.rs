//! Synthetic traces from closed-form kinematics, for tests and demonstrations.
//!
//! These are not recordings: the inner race follows an exact orbit chosen by the caller, which
//! makes them reproducible without the shaft simulator. The bundled traces the issue asks for
//! are recorded by the shaft simulator instead.

use super::{Sample, Trace, TraceMeta};

/// A steady circular whirl plus a static offset, at a shaft speed that changes linearly
/// (a run-up when `acceleration_rad_s2 > 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Whirl {
    /// Shaft speed at t = 0, ω₀ (rad/s).
    pub speed_rad_s: f64,
    /// Shaft angular acceleration, ω̇ (rad/s²): ω(t) = ω₀ + ω̇·t.
    pub acceleration_rad_s2: f64,
    /// Static displacement of the orbit centre (x, y) (m).
    pub offset_m: [f64; 2],
    /// Orbit radius (m).
    pub radius_m: f64,
    /// Whirl angular frequency, Ω (rad/s).
    pub whirl_rad_s: f64,
    /// Tilt amplitude about x and y (rad); `None` for a trace without tilt.
    pub tilt_amplitude_rad: Option<f64>,
}

impl Whirl {
    /// The trace of `count` samples at `meta.sample_rate_hz`, starting at t = 0.
    ///
    /// x = x₀ + r cos Ωt, y = y₀ + r sin Ωt, so vx = −rΩ sin Ωt and vy = rΩ cos Ωt exactly.
    pub fn trace(&self, meta: TraceMeta, count: usize) -> Trace {
        let period = 1.0 / meta.sample_rate_hz;
        let samples = (0..count)
            .map(|i| {
                let t = i as f64 * period;
                let phase = self.whirl_rad_s * t;
                let (sin, cos) = phase.sin_cos();
                Sample {
                    time_s: t,
                    speed_rad_s: (self.speed_rad_s + self.acceleration_rad_s2 * t) as f32,
                    x_m: (self.offset_m[0] + self.radius_m * cos) as f32,
                    y_m: (self.offset_m[1] + self.radius_m * sin) as f32,
                    vx_m_s: (-self.radius_m * self.whirl_rad_s * sin) as f32,
                    vy_m_s: (self.radius_m * self.whirl_rad_s * cos) as f32,
                    tilt_rad: self
                        .tilt_amplitude_rad
                        .map(|a| [(a * cos) as f32, (a * sin) as f32]),
                }
            })
            .collect();
        Trace { meta, samples }
    }
}
