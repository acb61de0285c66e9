//! The step kernel: what happens to one trace sample, identically on the host and on the
//! Cortex-M4 firmware (which includes this file with `#[path]`).
//!
//! It maps the trace's bearing and lubricant identifiers to the core's [`Bearing`] (the
//! parameters of `configs/<bearing>.toml`, PHYSICS.md §6; a test checks they agree with the
//! config files), keeps the state that carries from one sample to the next (the cage angle and
//! the core's warm start), turns each sample into an [`OperatingState`], runs the core's
//! bearing step with the chosen film model and copies the result into [`StepOutputs`].
//!
//! Determinism (ARCHITECTURE.md, rules for the core): the cage angle advances by the nominal
//! time step 1/rate of the trace (validated to within the gap tolerance), not by the difference
//! of the f64 time stamps, because f64 arithmetic is software-emulated on the M4F and its cost
//! depends on the operands; it is wrapped into [0, 2π) by one float-to-integer conversion, not
//! by `floorf`, whose cost depends on the argument's exponent. The warm start is converged
//! before the loop by [`Kernel::prime`], so every timed step does the same work.

use super::outputs::{StepOutputs, MAX_ROLLERS};
use super::wire::Sample;
use bearing_core::film::ann::{AnnF32, AnnInt};
use bearing_core::{
    Bearing, BearingGeometry, BearingOutput, BearingParams, ContactLaw, Crown, Lubricant, Material,
    OperatingState, Regression, StepStatus,
};

/// Slices per roller: the host tools' choice (`bearing_host_common::rolling::SLICES`), for which the
/// core tests slice-count independence.
pub const SLICES: usize = 10;
/// Steps of [`Kernel::prime`]: the core converges its warm start to |Δh|/h ≤ 10⁻³ from a cold
/// start in `SETTLE_STEPS` (`Bearing::settle`, which also builds every roller's film law).
pub const PRIME_STEPS: usize = bearing_core::bearing::SETTLE_STEPS;

/// Which film model the step uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilmKind {
    /// The integer (quantised) network with its fallback.
    Int,
    /// The f32 network with its fallback.
    F32,
    /// The regression formulas.
    Regression,
    /// No film (h ≡ 0).
    Dry,
}

impl FilmKind {
    /// The name on the command line and in `film.txt` (the firmware's film choice).
    pub fn name(self) -> &'static str {
        match self {
            FilmKind::Int => "int",
            FilmKind::F32 => "f32",
            FilmKind::Regression => "regression",
            FilmKind::Dry => "dry",
        }
    }

    /// The kind of a name (surrounding whitespace ignored).
    pub fn from_name(name: &[u8]) -> Option<FilmKind> {
        let trimmed = name.trim_ascii();
        [
            FilmKind::Int,
            FilmKind::F32,
            FilmKind::Regression,
            FilmKind::Dry,
        ]
        .into_iter()
        .find(|kind| kind.name().as_bytes() == trimmed)
    }
}

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

/// The bearing geometry of an identifier: `configs/<identifier>.toml` (PHYSICS.md §6).
pub fn geometry(bearing_id: &str) -> Result<BearingGeometry, KernelError> {
    let logarithmic = Crown::Logarithmic { scale: 1.0 };
    match bearing_id {
        // §6.2: pitch diameter 60 mm, rollers Ø8.8 mm × 15 mm, 17 rollers, 2 µm interference.
        "hub_motor" => BearingGeometry::new(0.060, 0.0088, 0.015, 17, logarithmic, -2.0e-6),
        // §6.1: raceways Ø31.5 / Ø46.5 mm give d_m = 39 mm; rollers Ø7.5 mm × 9 mm, 12 rollers,
        // zero clearance.
        "nu205" => BearingGeometry::new(0.039, 0.0075, 0.009, 12, logarithmic, 0.0),
        _ => return Err(KernelError::UnknownBearing),
    }
    .map_err(KernelError::Parameter)
}

/// The lubricant of an identifier. `thesis_oil`: η₀ = 0.08 Pa·s, α = 2.1·10⁻⁸ 1/Pa,
/// ρ₀ = 833.8 kg/m³, the oil of both reference machines (PHYSICS.md §6.1, §6.2).
pub fn lubricant(lubricant_id: &str) -> Result<Lubricant, KernelError> {
    match lubricant_id {
        "thesis_oil" => Lubricant::new(0.08, 2.1e-8, 833.8).map_err(KernelError::Parameter),
        _ => Err(KernelError::UnknownLubricant),
    }
}

/// The full parameters: steel rings and rollers, Palmgren slices, f_damp = 10⁻⁵ s (the
/// `[model]` of both config files, inside the thesis' 0.25…2.5·10⁻⁵ s, PHYSICS.md §4).
pub fn params(bearing_id: &str, lubricant_id: &str) -> Result<BearingParams, KernelError> {
    BearingParams::new(
        geometry(bearing_id)?,
        Material::STEEL,
        Material::STEEL,
        lubricant(lubricant_id)?,
        ContactLaw::Palmgren,
        1.0e-5,
    )
    .map_err(KernelError::Parameter)
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

/// 2π and its inverse in f32.
const TAU: f32 = core::f32::consts::TAU;
const INV_TAU: f32 = 1.0 / core::f32::consts::TAU;

/// The per-trace stepping state.
#[derive(Clone, Debug)]
pub struct Kernel {
    model: Model,
    film: FilmKind,
    /// Nominal time step 1/rate (s).
    period_s: f32,
    /// Cage angle θ_c in [0, 2π) (rad).
    cage_angle_rad: f32,
    /// 0 before the first step (the first sample defines θ_c = 0), 1 after: the cage advance
    /// is multiplied by it rather than skipped, so that every step runs the same instructions.
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
            "hub_motor" => Model::HubMotor(Bearing::new(params).map_err(KernelError::Parameter)?),
            _ => Model::Nu205(Bearing::new(params).map_err(KernelError::Parameter)?),
        };
        Ok(Kernel {
            model,
            film,
            period_s: (1.0 / sample_rate_hz) as f32,
            cage_angle_rad: 0.0,
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
        self.film
    }

    /// The operating state of `sample` at the current cage angle.
    fn state(&self, sample: &Sample) -> OperatingState {
        OperatingState {
            displacement_m: [sample.x_m, sample.y_m],
            velocity_m_s: [sample.vx_m_s, sample.vy_m_s],
            tilt_rad: sample.tilt_rad.unwrap_or([0.0; 2]),
            shaft_speed_rad_s: sample.speed_rad_s,
            cage_angle_rad: self.cage_angle_rad,
        }
    }

    /// Converges the warm start at the first sample ([`PRIME_STEPS`] untimed steps), so that
    /// the timed steps all do the same work. The cage angle is not advanced.
    // `inline`, like `new`: the caller's crate compiles the settling steps too, so the step's
    // generic code has the same callers there as in a single-crate build.
    #[inline]
    pub fn prime(&mut self, sample: &Sample) {
        let state = self.state(sample);
        match &mut self.model {
            Model::HubMotor(b) => settle(b, self.film, &state),
            Model::Nu205(b) => settle(b, self.film, &state),
        }
    }

    /// Advances to `sample` and writes the outputs.
    // Inlined into the caller's crate (the firmware's replay loop, the host's stepper) and
    // compiled there, as one unit with the loop: measured on the M4 (`hil-sim qemu`, hub motor,
    // int network), 28 177 instructions per step, every step; as a call into this crate
    // 28 222–28 226, varying with the data.
    #[inline(always)]
    pub fn step(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), KernelFault> {
        // Cage speed (ω/2)(1 − D/d_m), PHYSICS.md §2, over one nominal period (none before the
        // first sample).
        let geometry = match &self.model {
            Model::HubMotor(b) => *b.params().geometry(),
            Model::Nu205(b) => *b.params().geometry(),
        };
        let advance = geometry.cage_speed_rad_s(sample.speed_rad_s) * self.period_s;
        let advanced = self.cage_angle_rad + advance * self.advance_scale;
        // A non-finite speed (refused by the core below) must not poison the cage angle of the
        // following samples.
        let advanced = if advanced.is_finite() {
            advanced
        } else {
            self.cage_angle_rad
        };
        self.advance_scale = 1.0;
        // Whole turns by truncation (one instruction): exact wrap into [0, 2π) for the
        // non-negative angles of forward rotation, bounded in (−2π, 2π) otherwise.
        let turns = (advanced * INV_TAU) as i32;
        self.cage_angle_rad = advanced - turns as f32 * TAU;
        let state = self.state(sample);
        let film = self.film;
        out.cage_angle_rad = self.cage_angle_rad;
        match &mut self.model {
            Model::HubMotor(b) => copy_output(run(b, film, &state), out),
            Model::Nu205(b) => copy_output(run(b, film, &state), out),
        }
    }
}

/// One core step with the chosen film model.
fn run<'a, const Z: usize>(
    bearing: &'a mut Bearing<Z, SLICES>,
    film: FilmKind,
    state: &OperatingState,
) -> &'a BearingOutput<Z> {
    match film {
        FilmKind::Dry => bearing.step_dry(state),
        FilmKind::Regression => bearing.step(&Regression, state),
        FilmKind::F32 => bearing.step(&AnnF32, state),
        FilmKind::Int => bearing.step(&AnnInt, state),
    }
}

/// [`PRIME_STEPS`] core steps at one state, every roller's film law rebuilt at each.
fn settle<const Z: usize>(
    bearing: &mut Bearing<Z, SLICES>,
    film: FilmKind,
    state: &OperatingState,
) {
    match film {
        FilmKind::Dry => {
            for _ in 0..PRIME_STEPS {
                bearing.step_dry(state);
            }
        }
        FilmKind::Regression => {
            bearing.settle(&Regression, state, PRIME_STEPS);
        }
        FilmKind::F32 => {
            bearing.settle(&AnnF32, state, PRIME_STEPS);
        }
        FilmKind::Int => {
            bearing.settle(&AnnInt, state, PRIME_STEPS);
        }
    }
}

/// Copies the core's output into the harness's fixed-size record.
fn copy_output<const Z: usize>(
    result: &BearingOutput<Z>,
    out: &mut StepOutputs,
) -> Result<(), KernelFault> {
    if let StepStatus::Rejected(error) = result.status {
        return Err(KernelFault::Rejected(error));
    }
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

// The explicit path keeps the test module findable when the firmware includes this file from
// another crate (rustfmt resolves it there too).
#[cfg(test)]
#[path = "kernel/tests.rs"]
mod tests;
