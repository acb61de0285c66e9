//! One FMU instance as plain Rust: the variables, the phase of the FMI 2.0 co-simulation state
//! machine (FMI 2.0.4 §4.2.4) and the core's bearing. The `extern "C"` layer (`ffi`) only
//! converts arguments and reports the errors returned here through the importer's logger.

use bearing_core::bearing::{boxed, SETTLE_STEPS};
use bearing_core::{BearingDesign, DynBearing, FilmKind};

use crate::variables::{
    design_of, operating_state, output_values, parameter_values, Causality, Variability,
    FIRST_OUTPUT, FIRST_PARAMETER, INPUTS, INTEGERS, PARAMETERS, REALS,
};

/// The largest time step the core's `advance` accepts (s; its `time_step_s` range,
/// [`bearing_core::params::MAX_TIME_STEP_S`]). A communication step longer than this is taken in
/// equal sub-steps no longer than it (a test checks the bound against the core's refusal).
pub const CORE_MAX_STEP_S: f64 = bearing_core::params::MAX_TIME_STEP_S as f64;
/// The longest communication step accepted (s): at most this many sub-steps of
/// [`CORE_MAX_STEP_S`], ≈ 4 ms of work on the host.
pub const MAX_COMMUNICATION_STEP_S: f64 = 3600.0;

/// Where the instance is in the co-simulation state machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// After `fmi2Instantiate` or `fmi2Reset`: parameters and inputs may be set.
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    Initialization,
    /// Initialised: `fmi2DoStep` advances the bearing.
    Stepping,
    /// After `fmi2Terminate`: only reading, `fmi2Reset` and `fmi2FreeInstance`.
    Terminated,
}

/// An FMU instance.
pub struct Instance {
    /// Every Real variable, by value reference.
    reals: [f64; REALS.len()],
    /// Every Integer variable, by value reference.
    integers: [i32; INTEGERS.len()],
    /// The parameters of the FMU's bearing file, for `fmi2Reset`.
    defaults: ([f64; PARAMETERS], [i32; INTEGERS.len()]),
    bearing: Option<Box<dyn DynBearing + Send>>,
    phase: Phase,
    /// Communication time reached (s).
    time_s: f64,
    /// A tunable parameter changed since the bearing was built.
    retune: bool,
}

impl Instance {
    /// An instance with the parameters of `design` and `film`, inputs zero.
    pub fn new(design: &BearingDesign, film: FilmKind) -> Self {
        let defaults = parameter_values(design, film);
        let mut instance = Self {
            reals: [0.0; REALS.len()],
            integers: defaults.1,
            defaults,
            bearing: None,
            phase: Phase::Instantiated,
            time_s: 0.0,
            retune: false,
        };
        instance.reset();
        instance
    }

    /// The phase.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// Communication time reached (s).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Back to the state after instantiation: parameters of the bearing file, inputs and
    /// outputs zero, no bearing.
    pub fn reset(&mut self) {
        self.reals = [0.0; REALS.len()];
        self.reals[FIRST_PARAMETER..].copy_from_slice(&self.defaults.0);
        self.integers = self.defaults.1;
        self.bearing = None;
        self.phase = Phase::Instantiated;
        self.time_s = 0.0;
        self.retune = false;
    }

    /// `fmi2SetupExperiment`: the start time.
    pub fn setup_experiment(&mut self, start_time_s: f64) -> Result<(), String> {
        self.expect(Phase::Instantiated)?;
        if !start_time_s.is_finite() {
            return Err(format!(
                "startTime = {start_time_s} is not allowed: it must be finite"
            ));
        }
        self.time_s = start_time_s;
        Ok(())
    }

    /// The calls' own names are added by the FMI layer.
    fn expect(&self, phase: Phase) -> Result<(), String> {
        if self.phase == phase {
            Ok(())
        } else {
            Err(format!(
                "not allowed in phase {:?}: only in {phase:?}",
                self.phase
            ))
        }
    }

    /// The Real of value reference `vr`.
    pub fn real(&self, vr: u32) -> Result<f64, String> {
        self.reals
            .get(vr as usize)
            .copied()
            .ok_or_else(|| unknown("Real", vr, REALS.len()))
    }

    /// The Integer of value reference `vr`.
    pub fn integer(&self, vr: u32) -> Result<i32, String> {
        self.integers
            .get(vr as usize)
            .copied()
            .ok_or_else(|| unknown("Integer", vr, INTEGERS.len()))
    }

    /// Set the Real of value reference `vr`: inputs at any time before `fmi2Terminate`, fixed
    /// parameters before `fmi2ExitInitializationMode`, tunable ones also between steps (the
    /// bearing is rebuilt with them at the next step; a value the core refuses is refused
    /// here, naming the field and its allowed range). Outputs cannot be set.
    pub fn set_real(&mut self, vr: u32, value: f64) -> Result<(), String> {
        let variable = REALS
            .get(vr as usize)
            .ok_or_else(|| unknown("Real", vr, REALS.len()))?;
        let settable = match (variable.causality, variable.variability, self.phase) {
            (Causality::Output, _, _) | (_, _, Phase::Terminated) => false,
            (Causality::Input, _, _) => true,
            (_, Variability::Tunable, _) => true,
            (_, _, phase) => phase != Phase::Stepping,
        };
        if !settable {
            return Err(format!(
                "{} ({:?}, {:?}) cannot be set in phase {:?}",
                variable.name, variable.causality, variable.variability, self.phase
            ));
        }
        if self.phase == Phase::Stepping && variable.causality == Causality::Parameter {
            let mut trial = self.parameters();
            if let Some(slot) = trial.get_mut(vr as usize - FIRST_PARAMETER) {
                *slot = value;
            }
            let (design, _) = design_of(&trial, &self.integers)?;
            design.params().map_err(|e| e.to_string())?;
            self.retune = true;
        }
        if let Some(slot) = self.reals.get_mut(vr as usize) {
            *slot = value;
        }
        Ok(())
    }

    /// Set the Integer of value reference `vr` (fixed parameters: before
    /// `fmi2ExitInitializationMode` only; the range is checked there).
    pub fn set_integer(&mut self, vr: u32, value: i32) -> Result<(), String> {
        let variable = INTEGERS
            .get(vr as usize)
            .ok_or_else(|| unknown("Integer", vr, INTEGERS.len()))?;
        if !matches!(self.phase, Phase::Instantiated | Phase::Initialization) {
            return Err(format!(
                "{} (fixed parameter) cannot be set in phase {:?}",
                variable.name, self.phase
            ));
        }
        if let Some(slot) = self.integers.get_mut(vr as usize) {
            *slot = value;
        }
        Ok(())
    }

    fn parameters(&self) -> [f64; PARAMETERS] {
        let mut p = [0.0; PARAMETERS];
        p.copy_from_slice(&self.reals[FIRST_PARAMETER..]);
        p
    }

    /// `fmi2EnterInitializationMode`.
    pub fn enter_initialization(&mut self) -> Result<(), String> {
        self.expect(Phase::Instantiated)?;
        self.phase = Phase::Initialization;
        Ok(())
    }

    /// `fmi2ExitInitializationMode`: build the bearing from the parameters and settle its warm
    /// start at the inputs ([`SETTLE_STEPS`] steps without time passing); the outputs are
    /// those of the settled bearing.
    pub fn exit_initialization(&mut self) -> Result<(), String> {
        self.expect(Phase::Initialization)?;
        self.rebuild(0.0)?;
        self.phase = Phase::Stepping;
        Ok(())
    }

    /// A bearing of the current parameters at cage angle `cage_angle_rad`, settled at the
    /// inputs.
    fn rebuild(&mut self, cage_angle_rad: f32) -> Result<(), String> {
        let (design, film) = design_of(&self.parameters(), &self.integers)?;
        let params = design.params().map_err(|e| e.to_string())?;
        let mut bearing = boxed(params, film).map_err(|e| e.to_string())?;
        bearing
            .set_cage_angle(cage_angle_rad)
            .map_err(|e| e.to_string())?;
        let state = operating_state(&self.inputs());
        let settled = match bearing.settle(&state, SETTLE_STEPS) {
            Ok(_) => bearing.friction(state.shaft_speed_rad_s).map(|_| ()),
            Err(e) => Err(e),
        };
        settled.map_err(|e| format!("inputs at t = {} s: {e}", self.time_s))?;
        self.store_outputs(bearing.as_ref());
        self.bearing = Some(bearing);
        self.retune = false;
        Ok(())
    }

    fn inputs(&self) -> [f64; INPUTS] {
        let mut v = [0.0; INPUTS];
        v.copy_from_slice(&self.reals[..INPUTS]);
        v
    }

    fn store_outputs(&mut self, bearing: &dyn DynBearing) {
        let values = output_values(&bearing.output(), bearing.cage_angle_rad());
        self.reals[FIRST_OUTPUT..FIRST_PARAMETER].copy_from_slice(&values);
    }

    /// `fmi2DoStep`: advance the bearing by `step_s` to the inputs as set (held over the step),
    /// in ⌈step/[`CORE_MAX_STEP_S`]⌉ equal sub-steps. A refused input or step commits nothing.
    pub fn do_step(&mut self, current_time_s: f64, step_s: f64) -> Result<(), String> {
        self.expect(Phase::Stepping)?;
        if !(step_s.is_finite() && step_s > 0.0 && step_s <= MAX_COMMUNICATION_STEP_S) {
            return Err(format!(
                "communicationStepSize = {step_s} s is not allowed: it must lie in \
                 (0, {MAX_COMMUNICATION_STEP_S}]"
            ));
        }
        if !current_time_s.is_finite() {
            return Err(format!(
                "currentCommunicationPoint = {current_time_s} is not allowed: it \
                 must be finite"
            ));
        }
        if self.retune {
            let angle = self.bearing.as_ref().map_or(0.0, |b| b.cage_angle_rad());
            self.rebuild(angle)?;
        }
        let substeps = (step_s / CORE_MAX_STEP_S).ceil().max(1.0);
        let dt_s = (step_s / substeps) as f32;
        let state = operating_state(&self.inputs());
        let mut bearing = self
            .bearing
            .take()
            .ok_or_else(|| "the bearing was not built".to_owned())?;
        let mut result = Ok(());
        for _ in 0..substeps as u32 {
            if let Err(e) = bearing.advance(&state, dt_s) {
                result = Err(format!("at t = {current_time_s} s: {e}"));
                break;
            }
        }
        // The friction of the step's end state (docs/physics.md §8), at the input speed.
        if result.is_ok() {
            if let Err(e) = bearing.friction(state.shaft_speed_rad_s) {
                result = Err(format!("at t = {current_time_s} s: {e}"));
            }
        }
        if result.is_ok() {
            self.store_outputs(bearing.as_ref());
            self.time_s = current_time_s + step_s;
        }
        self.bearing = Some(bearing);
        result
    }

    /// A copy of the whole state (`fmi2GetFMUstate`): variables, phase, time and the bearing
    /// with its cage angle, warm start and film table (`DynBearing::boxed_clone`).
    pub fn snapshot(&self) -> Instance {
        Instance {
            reals: self.reals,
            integers: self.integers,
            defaults: self.defaults,
            bearing: self.bearing.as_ref().map(|b| b.boxed_clone()),
            phase: self.phase,
            time_s: self.time_s,
            retune: self.retune,
        }
    }

    /// `fmi2Terminate`.
    pub fn terminate(&mut self) -> Result<(), String> {
        if matches!(self.phase, Phase::Stepping | Phase::Initialization) {
            self.phase = Phase::Terminated;
            Ok(())
        } else {
            Err(format!("not allowed in phase {:?}", self.phase))
        }
    }
}

fn unknown(kind: &str, vr: u32, count: usize) -> String {
    format!(
        "{kind} value reference {vr} is not allowed: it must lie in [0, {}]",
        count - 1
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use bearing_core::OperatingState;

    #[test]
    fn core_step_bound_is_the_cores() {
        let params = BearingDesign::NU205.params().unwrap();
        let mut bearing = boxed(params, FilmKind::Dry).unwrap();
        let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 100.0).unwrap();
        assert!(bearing.advance(&state, CORE_MAX_STEP_S as f32).is_ok());
        let refused = bearing
            .advance(&state, (CORE_MAX_STEP_S as f32).next_up())
            .unwrap_err();
        assert_eq!(refused.field, "time_step_s");
    }

    #[test]
    fn a_long_step_is_sub_stepped_like_the_core_stepped_by_hand() {
        let mut fmu = Instance::new(&BearingDesign::NU205, FilmKind::Regression);
        for (vr, v) in [(1, -4.0e-6), (6, 900.0)] {
            fmu.set_real(vr, v).unwrap();
        }
        fmu.enter_initialization().unwrap();
        fmu.exit_initialization().unwrap();
        fmu.do_step(0.0, 2.5).unwrap();
        let params = BearingDesign::NU205.params().unwrap();
        let mut bearing = boxed(params, FilmKind::Regression).unwrap();
        let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 900.0).unwrap();
        bearing.settle(&state, SETTLE_STEPS).unwrap();
        for _ in 0..3 {
            bearing.advance(&state, (2.5_f64 / 3.0) as f32).unwrap();
        }
        bearing.friction(900.0).unwrap();
        assert!(bearing.output().power_loss_w > 0.0);
        let expected = output_values(&bearing.output(), bearing.cage_angle_rad());
        let got: Vec<f64> = (FIRST_OUTPUT..FIRST_PARAMETER)
            .map(|vr| fmu.real(vr as u32).unwrap())
            .collect();
        assert_eq!(got, expected.to_vec());
        assert_eq!(fmu.time_s(), 2.5);
    }

    #[test]
    fn a_tuned_viscosity_rebuilds_the_bearing_at_the_cage_angle_reached() {
        let mut fmu = Instance::new(&BearingDesign::NU205, FilmKind::Regression);
        fmu.set_real(1, -4.0e-6).unwrap();
        fmu.set_real(6, 900.0).unwrap();
        fmu.enter_initialization().unwrap();
        fmu.exit_initialization().unwrap();
        fmu.do_step(0.0, 1.0e-3).unwrap();
        let cage_angle = REALS.iter().position(|v| v.name == "cage_angle_rad");
        let angle = fmu.real(cage_angle.unwrap() as u32).unwrap() as f32;
        let viscosity = FIRST_PARAMETER as u32 + 7;
        fmu.set_real(viscosity, 0.02).unwrap();
        fmu.do_step(1.0e-3, 1.0e-3).unwrap();

        let design = BearingDesign {
            viscosity_pa_s: 0.02,
            ..BearingDesign::NU205
        };
        let mut bearing = boxed(design.params().unwrap(), FilmKind::Regression).unwrap();
        bearing.set_cage_angle(angle).unwrap();
        let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 900.0).unwrap();
        bearing.settle(&state, SETTLE_STEPS).unwrap();
        bearing.advance(&state, 1.0e-3).unwrap();
        bearing.friction(900.0).unwrap();
        let expected = output_values(&bearing.output(), bearing.cage_angle_rad());
        let got: Vec<f64> = (FIRST_OUTPUT..FIRST_PARAMETER)
            .map(|vr| fmu.real(vr as u32).unwrap())
            .collect();
        assert_eq!(got, expected.to_vec());
    }

    #[test]
    fn a_snapshot_restored_repeats_the_steps_bit_for_bit() {
        let mut fmu = Instance::new(&BearingDesign::HUB_MOTOR, FilmKind::Int);
        fmu.set_real(6, 2199.0).unwrap();
        fmu.enter_initialization().unwrap();
        fmu.exit_initialization().unwrap();
        fmu.do_step(0.0, 1.0e-4).unwrap();
        let saved = fmu.snapshot();
        let run = |fmu: &mut Instance| -> Vec<f64> {
            for (k, x) in [3.0e-6, -2.0e-6].into_iter().enumerate() {
                fmu.set_real(0, x).unwrap();
                fmu.do_step((k + 1) as f64 * 1.0e-4, 1.0e-4).unwrap();
            }
            (0..REALS.len() as u32)
                .map(|vr| fmu.real(vr).unwrap())
                .collect()
        };
        let first = run(&mut fmu);
        fmu = saved.snapshot();
        assert_eq!(run(&mut fmu), first);
        assert_eq!(fmu.time_s(), 2.0e-4 + 1.0e-4);
    }

    #[test]
    fn refusals_name_the_field_and_commit_nothing() {
        let mut fmu = Instance::new(&BearingDesign::HUB_MOTOR, FilmKind::Int);
        assert!(fmu.do_step(0.0, 1e-4).unwrap_err().contains("phase"));
        fmu.set_real(6, 2000.0).unwrap();
        fmu.enter_initialization().unwrap();
        fmu.exit_initialization().unwrap();
        let before = fmu.real(FIRST_OUTPUT as u32).unwrap();
        fmu.set_real(0, 2.0e-3).unwrap();
        let e = fmu.do_step(0.0, 1e-4).unwrap_err();
        assert!(e.contains("displacement_x_m"), "{e}");
        assert_eq!(fmu.real(FIRST_OUTPUT as u32).unwrap(), before);
        assert!(fmu
            .do_step(0.0, f64::NAN)
            .unwrap_err()
            .contains("communicationStepSize"));
        assert!(fmu.set_real(FIRST_PARAMETER as u32, 0.07).is_err()); // fixed
        let viscosity = FIRST_PARAMETER as u32 + 7;
        let e = fmu.set_real(viscosity, -1.0).unwrap_err();
        assert!(e.contains("viscosity_pa_s"), "{e}");
        assert!(fmu.set_real(FIRST_OUTPUT as u32, 1.0).is_err());
        assert!(fmu.real(REALS.len() as u32).is_err());
    }
}
