//! The step kernel: what happens to one trace sample, identically on the host and on the
//! Cortex-M4 firmware (which includes this file with `#[path]`).
//!
//! It maps the trace's bearing identifier to a bearing, keeps the state that carries from one
//! sample to the next (the cage angle), and fills [`StepOutputs`]. Today it computes the roller
//! kinematics of PHYSICS.md §2 and the geometric approach of §4, δ_j = x cos θ_j + y sin θ_j − g_r;
//! loads, films and forces stay zero until the core's bearing step (`bearing_core::bearing`)
//! is called here — that call replaces the body of [`Kernel::step`] and nothing else in the
//! harness changes.
//!
//! Determinism (ARCHITECTURE.md, rules for the core): the time step is the nominal 1/rate of the
//! trace (validated to within the gap tolerance), not the difference of the f64 time stamps,
//! because f64 arithmetic is software-emulated on the M4F and its cost depends on the operands.
//! The roller angles are produced by rotating (sin θ_c, cos θ_c) by 2π/Z, so one `sincosf` per
//! step serves all rollers.

use super::outputs::{StepOutputs, MAX_ROLLERS};
use super::wire::Sample;

/// Why a kernel cannot be built for a trace.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KernelError {
    /// The trace's bearing identifier names no known bearing.
    UnknownBearing,
    /// The sample rate is not finite and positive.
    BadSampleRate,
}

/// Why one step failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KernelFault {
    /// A sample value is NaN or infinite (validated traces never have one).
    NonFiniteSample,
}

/// Geometry of a cylindrical roller bearing (PHYSICS.md §2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingGeometry {
    /// Number of rollers, Z.
    pub rollers: usize,
    /// Pitch diameter, d_m (m).
    pub pitch_diameter_m: f32,
    /// Roller diameter, D (m).
    pub roller_diameter_m: f32,
    /// Radial internal clearance per roller, g_r (m); negative for interference.
    pub clearance_m: f32,
}

/// The bearings traces are recorded for, by identifier (PHYSICS.md §6).
pub fn geometry(bearing_id: &str) -> Option<BearingGeometry> {
    match bearing_id {
        // §6.2: pitch diameter 60 mm, rollers Ø8.8 mm, 17 rollers, radial interference 2 µm.
        "hub_motor" => Some(BearingGeometry {
            rollers: 17,
            pitch_diameter_m: 0.060,
            roller_diameter_m: 0.0088,
            clearance_m: -2.0e-6,
        }),
        // §6.1: inner raceway Ø31.5 mm and outer Ø46.5 mm give d_m = 39 mm; rollers Ø7.5 mm,
        // 12 rollers, zero clearance.
        "nu205" => Some(BearingGeometry {
            rollers: 12,
            pitch_diameter_m: 0.039,
            roller_diameter_m: 0.0075,
            clearance_m: 0.0,
        }),
        _ => None,
    }
}

/// 2π in f32.
const TAU: f32 = core::f32::consts::TAU;

/// The per-trace stepping state.
#[derive(Clone, Copy, Debug)]
pub struct Kernel {
    geometry: BearingGeometry,
    /// ω_c / ω = (1 − γ)/2 with γ = D/d_m (PHYSICS.md §2).
    cage_ratio: f32,
    /// Nominal time step 1/rate (s).
    period_s: f32,
    /// sin and cos of the roller pitch 2π/Z.
    pitch_sin_cos: (f32, f32),
    /// Cage angle θ_c in [0, 2π) (rad).
    cage_angle_rad: f32,
    /// No step taken yet (the first sample defines θ_c = 0).
    first: bool,
}

impl Kernel {
    /// The kernel for a trace of `bearing_id` sampled at `sample_rate_hz`.
    pub fn new(bearing_id: &str, sample_rate_hz: f64) -> Result<Kernel, KernelError> {
        let geometry = geometry(bearing_id).ok_or(KernelError::UnknownBearing)?;
        if !(sample_rate_hz.is_finite() && sample_rate_hz > 0.0) {
            return Err(KernelError::BadSampleRate);
        }
        let gamma = geometry.roller_diameter_m / geometry.pitch_diameter_m;
        Ok(Kernel {
            geometry,
            cage_ratio: 0.5 * (1.0 - gamma),
            period_s: (1.0 / sample_rate_hz) as f32,
            pitch_sin_cos: libm::sincosf(TAU / geometry.rollers as f32),
            cage_angle_rad: 0.0,
            first: true,
        })
    }

    /// The bearing this kernel steps.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }

    /// Advances to `sample` and writes the outputs.
    pub fn step(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), KernelFault> {
        let values = [
            sample.speed_rad_s,
            sample.x_m,
            sample.y_m,
            sample.vx_m_s,
            sample.vy_m_s,
        ];
        if !values.iter().all(|v| v.is_finite()) {
            return Err(KernelFault::NonFiniteSample);
        }
        if self.first {
            self.first = false;
        } else {
            let advanced =
                self.cage_angle_rad + self.cage_ratio * sample.speed_rad_s * self.period_s;
            // Wrap into [0, 2π) so that f32 keeps its resolution on long traces.
            self.cage_angle_rad = advanced - TAU * libm::floorf(advanced / TAU);
        }
        let (pitch_sin, pitch_cos) = self.pitch_sin_cos;
        let (mut sin, mut cos) = libm::sincosf(self.cage_angle_rad);
        let rollers = if self.geometry.rollers > MAX_ROLLERS {
            MAX_ROLLERS
        } else {
            self.geometry.rollers
        };
        *out = StepOutputs {
            cage_angle_rad: self.cage_angle_rad,
            rollers,
            ..StepOutputs::default()
        };
        for approach in out.roller_approach_m.iter_mut().take(rollers) {
            *approach = sample.x_m * cos + sample.y_m * sin - self.geometry.clearance_m;
            // Next roller: rotate by 2π/Z (angle addition).
            let next_sin = sin * pitch_cos + cos * pitch_sin;
            cos = cos * pitch_cos - sin * pitch_sin;
            sin = next_sin;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(x: f32, y: f32, speed: f32) -> Sample {
        Sample {
            time_s: 0.0,
            speed_rad_s: speed,
            x_m: x,
            y_m: y,
            vx_m_s: 0.0,
            vy_m_s: 0.0,
            tilt_rad: None,
        }
    }

    /// Reference: PHYSICS.md §2 cage speed (ω/2)(1 − D/d_m) integrated over n steps in f64, and
    /// δ_j = x cos θ_j + y sin θ_j − g_r evaluated directly in f64 at θ_j = θ_c + 2πj/Z.
    #[test]
    fn cage_angle_and_approach_follow_the_closed_form() {
        let rate = 10_000.0;
        let mut kernel = Kernel::new("hub_motor", rate).unwrap();
        let (x, y, speed) = (3.0e-6f32, -7.0e-6f32, 2000.0f32);
        let mut out = StepOutputs::default();
        let steps = 250;
        for _ in 0..steps {
            kernel.step(&sample(x, y, speed), &mut out).unwrap();
        }
        let cage = 0.5 * (1.0 - 8.8 / 60.0) * 2000.0 * (steps - 1) as f64 / rate;
        let cage = cage.rem_euclid(std::f64::consts::TAU);
        assert!(
            (f64::from(out.cage_angle_rad) - cage).abs() < 1e-4,
            "{} vs {cage}",
            out.cage_angle_rad
        );
        assert_eq!(out.rollers, 17);
        for j in 0..17 {
            let theta = f64::from(out.cage_angle_rad) + std::f64::consts::TAU * j as f64 / 17.0;
            let expected = f64::from(x) * theta.cos() + f64::from(y) * theta.sin() + 2.0e-6;
            // 1e-11 m: f32 rounding of a ≈ 1e-5 m value after 17 rotations.
            assert!(
                (f64::from(out.roller_approach_m[j]) - expected).abs() < 1e-11,
                "roller {j}"
            );
        }
    }

    #[test]
    fn refuses_unknown_bearings_and_non_finite_samples() {
        assert_eq!(
            Kernel::new("nu999", 1e4).unwrap_err(),
            KernelError::UnknownBearing
        );
        assert_eq!(
            Kernel::new("nu205", f64::NAN).unwrap_err(),
            KernelError::BadSampleRate
        );
        let mut kernel = Kernel::new("nu205", 1e4).unwrap();
        let mut out = StepOutputs::default();
        assert_eq!(
            kernel.step(&sample(f32::NAN, 0.0, 1.0), &mut out),
            Err(KernelFault::NonFiniteSample)
        );
    }
}
