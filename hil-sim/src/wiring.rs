//! Wiring: which bearing model, dry model and accuracy reference the `replay` command drives.
//!
//! This is the one place where the harness meets the product: the core's bearing step, through
//! the shared [`Kernel`] the firmware runs too, as the [`BearingStepper`]; the same kernel with
//! the dry film as the dry model; and the host's numerical EHL solver, with the film–load
//! coupling converged in f64, as the [`AccuracyReference`] ([`crate::reference`]).

use crate::kernel::{FilmKind, Kernel, KernelError, KernelFault};
use crate::outputs::StepOutputs;
use crate::replay::{AccuracyReference, BearingStepper, StepFault};
use crate::trace::{Sample, TraceMeta};
use std::path::PathBuf;

/// The bundled hub-motor run-up trace (recorded by the shaft simulator), the default of
/// `hil-sim replay` and `hil-sim qemu`.
pub fn default_trace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("traces/hub_motor_runup.bin")
}

/// A sentence for a kernel construction error.
pub fn describe(error: &KernelError) -> String {
    match error {
        KernelError::UnknownBearing => {
            "unknown bearing identifier (known: hub_motor, hub_motor_hs, nu205)".to_string()
        }
        KernelError::UnknownLubricant => {
            "unknown lubricant identifier (known: thesis_oil, thesis_oil_hs)".to_string()
        }
        KernelError::BadSampleRate => "the sample rate is not finite and positive".to_string(),
        KernelError::Parameter(e) => format!("the core refused a parameter: {e}"),
    }
}

/// The kernel as a replay stepper.
pub struct KernelStepper {
    kernel: Kernel,
    primed: bool,
}

impl KernelStepper {
    /// A stepper for the trace's bearing and lubricant with `film`.
    pub fn new(meta: &TraceMeta, film: FilmKind) -> Result<Self, String> {
        let kernel = Kernel::new(&meta.bearing, &meta.lubricant, meta.sample_rate_hz, film)
            .map_err(|e| {
                format!(
                    "bearing '{}', lubricant '{}': {}",
                    meta.bearing,
                    meta.lubricant,
                    describe(&e)
                )
            })?;
        Ok(Self {
            kernel,
            primed: false,
        })
    }

    /// Converges the warm start at the first sample (outside the timed loop).
    pub fn prime(&mut self, sample: &Sample) {
        self.kernel.prime(sample);
        self.primed = true;
    }
}

impl BearingStepper for KernelStepper {
    fn name(&self) -> String {
        format!("core/{}", self.kernel.film().name())
    }

    fn step(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), StepFault> {
        self.kernel.step(sample, out).map_err(refused)
    }

    fn friction(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), StepFault> {
        self.kernel.friction(sample, out).map_err(refused)
    }
}

/// The stepper's fault for a sample the core refused.
fn refused(fault: KernelFault) -> StepFault {
    match fault {
        KernelFault::Rejected(e) => StepFault {
            reason: format!("the core refused the sample: {e}"),
        },
    }
}

/// The models a replay drives.
pub struct Product {
    /// The real-time bearing step with the chosen film model.
    pub stepper: Box<dyn BearingStepper>,
    /// The same step with the dry model (h ≡ 0).
    pub dry: Option<Box<dyn BearingStepper>>,
    /// The full numerical solver at the same bearing state.
    pub reference: Option<Box<dyn AccuracyReference>>,
}

/// The trace's bearing stepped with `film`, primed at the trace's first sample.
pub fn primed_stepper(
    meta: &TraceMeta,
    film: FilmKind,
    first: &Sample,
) -> Result<KernelStepper, String> {
    let mut stepper = KernelStepper::new(meta, film)?;
    stepper.prime(first);
    Ok(stepper)
}

/// Builds the product's models for the trace, primed at its first sample.
pub fn product(meta: &TraceMeta, film: FilmKind, first: &Sample) -> Result<Product, String> {
    Ok(Product {
        stepper: Box::new(primed_stepper(meta, film, first)?),
        dry: Some(Box::new(primed_stepper(meta, FilmKind::Dry, first)?)),
        reference: Some(Box::new(crate::reference::NumericalReference::new(meta)?)),
    })
}
