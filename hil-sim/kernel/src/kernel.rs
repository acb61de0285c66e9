//! The step kernel: what happens to one trace sample, identically on the host and on the
//! Cortex-M4 firmware (which depends on this crate, `bearing-hil-kernel`).
//!
//! It maps the trace's bearing and lubricant identifiers to the core's presets
//! ([`BearingDesign::HUB_MOTOR`], [`BearingDesign::NU205`]: the parameters of
//! `configs/<bearing>.toml`, docs/physics.md §6; a test checks they agree with the config files),
//! keeps the core's [`Bearing`] (which carries the cage angle and the warm start from one
//! sample to the next), turns each sample into an [`OperatingState`], advances the bearing by
//! one nominal period and copies the result into [`StepOutputs`]; [`Kernel::friction`] then
//! adds the bearing's friction torque and power loss at that step.
//!
//! Determinism (docs/architecture.md, rules for the core): the cage advances by the nominal time
//! step 1/rate of the trace (validated to within the gap tolerance), not by the difference of
//! the f64 time stamps, because f64 arithmetic is software-emulated on the M4F and its cost
//! depends on the operands; the core wraps it by whole turns at a fixed cost. The warm start
//! is converged before the loop by [`Kernel::prime`], so every timed step does the same work.

use super::outputs::{StepOutputs, MAX_ROLLERS};
use super::wire::Sample;
use bearing_core::bearing::STEEL_DENSITY_KG_M3;
use bearing_core::film::corrections::FilmCorrections;
pub use bearing_core::FilmKind;
use bearing_core::{Bearing, BearingDesign, BearingParams, OperatingState};

/// Slices per roller: the host tools' choice (`bearing_core::bearing::SLICES`), for which the
/// core tests slice-count independence.
pub const SLICES: usize = 10;
/// Steps of [`Kernel::prime`]: the core converges its warm start to |Δh|/h ≤ 10⁻³ from a cold
/// start in `SETTLE_STEPS` (`Bearing::settle`, which also builds every roller's film law).
pub const PRIME_STEPS: usize = bearing_core::bearing::SETTLE_STEPS;

/// Why a kernel cannot be built for a trace.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KernelError {
    /// The trace's bearing identifier names no known bearing.
    UnknownBearing,
    /// The trace's lubricant identifier names no known lubricant.
    UnknownLubricant,
    /// The sample rate is not finite and positive.
    BadSampleRate,
    /// The core refused a parameter (a bug in the tables below).
    Parameter(bearing_core::ParamError),
}

/// Why one step failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KernelFault {
    /// The core refused the operating state; the field is named.
    Rejected(bearing_core::ParamError),
}

/// The design of a bearing identifier in a lubricant identifier: the core's preset of
/// `configs/<bearing>.toml` (docs/physics.md §6); `hub_motor_hs` is the hub motor's.
/// `thesis_oil` (η₀ = 0.08 Pa·s, α = 2.1·10⁻⁸ 1/Pa, ρ₀ = 833.8 kg/m³, the oil of both
/// reference machines, §6.1, §6.2) is the presets' own;
/// `thesis_oil_hs` is the same oil with the film corrections of [`film_corrections`].
pub fn design(bearing_id: &str, lubricant_id: &str) -> Result<BearingDesign, KernelError> {
    let design = match bearing_id {
        "hub_motor" | "hub_motor_hs" => BearingDesign::HUB_MOTOR,
        "nu205" => BearingDesign::NU205,
        _ => return Err(KernelError::UnknownBearing),
    };
    match lubricant_id {
        "thesis_oil" | "thesis_oil_hs" => Ok(design),
        _ => Err(KernelError::UnknownLubricant),
    }
}

/// The high-speed film corrections of a lubricant identifier (docs/physics.md §5.4): none for
/// `thesis_oil`; for `thesis_oil_hs` both, with the core's default β and K and a 1 µm
/// inlet oil layer (γ = 2), the case whose step cost `hil-sim qemu` reports for corrections on.
pub fn film_corrections(lubricant_id: &str) -> Result<FilmCorrections, KernelError> {
    use bearing_core::film::corrections::{
        Starvation, ThermalCorrection, OIL_THERMAL_CONDUCTIVITY_W_PER_M_K,
        VG68_TEMPERATURE_VISCOSITY_PER_K,
    };
    if lubricant_id != "thesis_oil_hs" {
        return Ok(FilmCorrections::OFF);
    }
    Ok(FilmCorrections {
        thermal: Some(
            ThermalCorrection::new(
                VG68_TEMPERATURE_VISCOSITY_PER_K,
                OIL_THERMAL_CONDUCTIVITY_W_PER_M_K,
            )
            .map_err(KernelError::Parameter)?,
        ),
        starvation: Some(Starvation::new(1.0e-6, 2.0).map_err(KernelError::Parameter)?),
    })
}

/// The validated parameters of [`design`], with the [`film_corrections`] of the lubricant;
/// `hub_motor_hs` adds the rollers' centrifugal force (docs/physics.md §4.1, steel rollers of
/// [`STEEL_DENSITY_KG_M3`]), as `configs/hub_motor_high_speed.toml` does: the case whose step
/// cost `hil-sim qemu` reports for the centrifugal force on.
pub fn params(bearing_id: &str, lubricant_id: &str) -> Result<BearingParams, KernelError> {
    let params = design(bearing_id, lubricant_id)?
        .params()
        .map_err(KernelError::Parameter)?
        .with_film_corrections(film_corrections(lubricant_id)?);
    if bearing_id == "hub_motor_hs" {
        params
            .with_centrifugal_force(STEEL_DENSITY_KG_M3)
            .map_err(KernelError::Parameter)
    } else {
        Ok(params)
    }
}

/// The core's bearing at the roller count of each known identifier.
// The variants differ by five rollers' state (≈ 400 B); boxing would need a heap, which the
// firmware does not have, and there is one kernel per replay.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Model {
    HubMotor(Bearing<17, SLICES>),
    Nu205(Bearing<12, SLICES>),
}

/// The per-trace stepping state.
#[derive(Clone, Debug)]
pub struct Kernel {
    model: Model,
    /// Nominal time step 1/rate (s).
    period_s: f32,
    /// 0 before the first step (the first sample defines θ_c = 0), 1 after: the time step is
    /// multiplied by it rather than skipped, so that every step runs the same instructions.
    advance_scale: f32,
}

impl Kernel {
    /// The kernel for a trace of `bearing_id` in `lubricant_id` sampled at `sample_rate_hz`,
    /// stepping with `film`.
    #[inline]
    pub fn new(
        bearing_id: &str,
        lubricant_id: &str,
        sample_rate_hz: f64,
        film: FilmKind,
    ) -> Result<Kernel, KernelError> {
        if !(sample_rate_hz.is_finite() && sample_rate_hz > 0.0) {
            return Err(KernelError::BadSampleRate);
        }
        let params = params(bearing_id, lubricant_id)?;
        let model = match bearing_id {
            "hub_motor" | "hub_motor_hs" => {
                Model::HubMotor(Bearing::new(params, film).map_err(KernelError::Parameter)?)
            }
            _ => Model::Nu205(Bearing::new(params, film).map_err(KernelError::Parameter)?),
        };
        Ok(Kernel {
            model,
            period_s: (1.0 / sample_rate_hz) as f32,
            advance_scale: 0.0,
        })
    }

    /// Number of rollers.
    pub fn rollers(&self) -> usize {
        match &self.model {
            Model::HubMotor(_) => 17,
            Model::Nu205(_) => 12,
        }
    }

    /// The film model.
    pub fn film(&self) -> FilmKind {
        match &self.model {
            Model::HubMotor(b) => b.film(),
            Model::Nu205(b) => b.film(),
        }
    }

    /// The operating state of `sample`.
    fn state(sample: &Sample) -> OperatingState {
        OperatingState {
            displacement_m: [sample.x_m, sample.y_m],
            velocity_m_s: [sample.vx_m_s, sample.vy_m_s],
            tilt_rad: sample.tilt_rad.unwrap_or([0.0; 2]),
            shaft_speed_rad_s: sample.speed_rad_s,
        }
    }

    /// Converges the warm start at the first sample ([`PRIME_STEPS`] untimed steps of the
    /// core's `settle`, which also fills the film table), so that the timed steps all do the
    /// same work. The cage angle is not advanced; a refused sample is refused again by the
    /// first [`Kernel::step`].
    // `inline`, like `new`: the caller's crate compiles the settling steps too, so the step's
    // generic code has the same callers there as in a single-crate build.
    #[inline]
    pub fn prime(&mut self, sample: &Sample) {
        let state = Self::state(sample);
        let _ = match &mut self.model {
            Model::HubMotor(b) => b.settle(&state, PRIME_STEPS).map(|_| ()),
            Model::Nu205(b) => b.settle(&state, PRIME_STEPS).map(|_| ()),
        };
    }

    /// Advances to `sample` by one nominal period (none before the first sample) and writes
    /// the outputs.
    // Inlined into the caller's crate (the firmware's replay loop, the host's stepper) and
    // compiled there, as one unit with the loop: measured on the M4 (`hil-sim qemu`, hub motor,
    // int network), 27 280 instructions per step, every step; as a call into this crate the
    // count was ≈ 45 higher and varied with the data, which `hil-sim qemu` refuses (min = max).
    #[inline(always)]
    pub fn step(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), KernelFault> {
        let dt_s = self.period_s * self.advance_scale;
        self.advance_scale = 1.0;
        let state = Self::state(sample);
        match &mut self.model {
            Model::HubMotor(b) => copy_output(b, &state, dt_s, out),
            Model::Nu205(b) => copy_output(b, &state, dt_s, out),
        }
    }

    /// The friction of the last step at `sample`'s shaft speed (the core's
    /// `Bearing::friction`, docs/physics.md §8): writes the friction torque, power loss and its
    /// split into `out`. A call of its own after [`Kernel::step`], so that the firmware counts
    /// the step's instructions as before and the friction's apart; the same work every call.
    #[inline(always)]
    pub fn friction(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), KernelFault> {
        match &mut self.model {
            Model::HubMotor(b) => copy_friction(b, sample.speed_rad_s, out),
            Model::Nu205(b) => copy_friction(b, sample.speed_rad_s, out),
        }
    }
}

/// Computes `bearing`'s friction at shaft speed ω (rad/s) and copies it into the record.
fn copy_friction<const Z: usize>(
    bearing: &mut Bearing<Z, SLICES>,
    shaft_speed_rad_s: f32,
    out: &mut StepOutputs,
) -> Result<(), KernelFault> {
    let result = bearing
        .friction(shaft_speed_rad_s)
        .map_err(KernelFault::Rejected)?;
    out.friction_torque_nm = result.friction_torque_nm;
    out.power_loss_w = result.power_loss_w;
    out.power_loss_split_w = result.power_loss_split_w;
    Ok(())
}

/// Advances `bearing` to `state` by `dt_s` and copies its output into the harness's
/// fixed-size record (the cage angle also when the core refuses the state). One function per
/// roller count: a second match on the model to read the cage angle cost the M4 11
/// instructions per step.
fn copy_output<const Z: usize>(
    bearing: &mut Bearing<Z, SLICES>,
    state: &OperatingState,
    dt_s: f32,
    out: &mut StepOutputs,
) -> Result<(), KernelFault> {
    let advanced = bearing
        .advance(state, dt_s)
        .map(|_| ())
        .map_err(KernelFault::Rejected);
    out.cage_angle_rad = bearing.cage_angle_rad();
    advanced?;
    let result = bearing.output();
    out.force_n = result.force_n;
    out.rollers = if Z > MAX_ROLLERS { MAX_ROLLERS } else { Z };
    for (j, roller) in result.rollers.iter().enumerate().take(MAX_ROLLERS) {
        out.roller_load_n[j] = roller.load_n;
        out.film_inner_m[j] = roller.central_film_in_m;
        out.film_outer_m[j] = roller.central_film_out_m;
        out.roller_approach_m[j] = roller.geometric_approach_m;
        out.source_inner[j] = roller.film_source_in;
        out.source_outer[j] = roller.film_source_out;
    }
    Ok(())
}

#[cfg(test)]
mod tests;
