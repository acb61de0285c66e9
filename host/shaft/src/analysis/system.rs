//! The matrices a time simulation integrates: the full finite-element model or its
//! Craig–Bampton reduction, with the load vector and the output DOFs expressed in the chosen
//! coordinates. Boundary (bearing and loaded) nodes are kept physical in the reduction, so the
//! bearings and point loads act on single coordinates either way.

use nalgebra::{DMatrix, DVector};

use crate::analysis::integrator::{Integrator, NewtonSettings, Scheme, StepError};
use crate::analysis::modes::ModesError;
use crate::analysis::reduction::{craig_bampton, ReducedModel};
use crate::bearing::BearingModel;
use crate::model::motor::SpeedOutOfRange;
use crate::model::RotorModel;

/// Full or reduced equations of motion of one rotor.
pub struct TimeSystem<'a> {
    /// The rotor.
    pub model: &'a RotorModel,
    /// The reduction, when used.
    pub reduced: Option<ReducedModel>,
    gravity: DVector<f64>,
    /// Zero vector standing in for gravity when only the time-varying loads are wanted.
    no_gravity: DVector<f64>,
    map: Vec<usize>,
}

impl<'a> TimeSystem<'a> {
    /// The full model (`reduction_modes = None`) or a Craig–Bampton model keeping the bearing
    /// and loaded nodes plus that many fixed-interface modes.
    pub fn new(model: &'a RotorModel, reduction_modes: Option<usize>) -> Result<Self, ModesError> {
        let n = model.n_dof();
        match reduction_modes {
            None => Ok(TimeSystem {
                model,
                reduced: None,
                gravity: model.gravity_vector.clone(),
                no_gravity: DVector::zeros(n),
                map: (0..n).collect(),
            }),
            Some(k) => {
                let mut nodes: Vec<usize> =
                    model.description.bearings.iter().map(|b| b.node).collect();
                nodes.extend(
                    model
                        .description
                        .loads
                        .loads
                        .iter()
                        .filter_map(|l| l.node()),
                );
                let red = craig_bampton(model, &nodes, k)?;
                let gravity = red.transform.transpose() * &model.gravity_vector;
                // Only loaded/bearing DOFs are ever looked up; others map to 0 harmlessly.
                let map = (0..n).map(|d| red.reduced_index(d).unwrap_or(0)).collect();
                let no_gravity = DVector::zeros(gravity.len());
                Ok(TimeSystem {
                    model,
                    reduced: Some(red),
                    gravity,
                    no_gravity,
                    map,
                })
            }
        }
    }

    /// Number of coordinates integrated.
    pub fn n_dof(&self) -> usize {
        self.gravity.len()
    }

    /// Coordinate index of a global DOF of a bearing or loaded node.
    pub fn index(&self, global_dof: usize) -> usize {
        self.map[global_dof]
    }

    /// Value of global DOF `d` from the integrated coordinates `z`.
    pub fn global(&self, z: &DVector<f64>, d: usize) -> f64 {
        match &self.reduced {
            None => z[d],
            Some(r) => match r.reduced_index(d) {
                Some(i) => z[i],
                None => r.transform.row(d).transpose().dot(z),
            },
        }
    }

    /// Integrated coordinates from a full vector (mass-weighted least squares; exact for the
    /// boundary DOFs' static shapes).
    pub fn from_full(&self, q: &DVector<f64>) -> DVector<f64> {
        match &self.reduced {
            None => q.clone(),
            Some(r) => {
                let rhs = r.transform.transpose() * (&self.model.mass * q);
                r.mass
                    .clone()
                    .cholesky()
                    .map(|c| c.solve(&rhs))
                    .unwrap_or(rhs)
            }
        }
    }

    /// Time-varying load vector at time t (s) and spin speed Ω (rad/s) into `f` (overwritten):
    /// everything but gravity, which is [`TimeSystem::constant_load`].
    pub fn load(
        &self,
        t: f64,
        spin_speed: f64,
        f: &mut DVector<f64>,
    ) -> Result<(), SpeedOutOfRange> {
        f.fill(0.0);
        self.model.description.loads.add_forces_mapped(
            t,
            spin_speed,
            self.no_gravity.as_slice(),
            true,
            &|d| self.map[d],
            f.as_mut_slice(),
        )
    }

    /// Time-varying load vector at a spin state (angle, speed, acceleration) into `f`
    /// (overwritten): as [`TimeSystem::load`] for a speed that changes in time.
    pub fn load_at(
        &self,
        at: crate::model::loads::SpinAt,
        f: &mut DVector<f64>,
    ) -> Result<(), SpeedOutOfRange> {
        f.fill(0.0);
        self.model.description.loads.add_forces_at(
            at,
            self.no_gravity.as_slice(),
            true,
            &|d| self.map[d],
            f.as_mut_slice(),
        )
    }

    /// Linear damping D = C + ΩG at spin speed Ω (rad/s) in the integrated coordinates.
    pub fn damping_at(&self, spin_speed: f64) -> DMatrix<f64> {
        let (_, _, g, c) = self.matrices();
        c + g * spin_speed
    }

    /// The constant (gravity) load in the integrated coordinates.
    pub fn constant_load(&self) -> DVector<f64> {
        let g: f64 = self
            .model
            .description
            .loads
            .loads
            .iter()
            .map(|l| match l {
                crate::model::loads::Load::Gravity { acceleration } => *acceleration,
                _ => 0.0,
            })
            .sum();
        &self.gravity * g
    }

    fn matrices(&self) -> (&DMatrix<f64>, &DMatrix<f64>, &DMatrix<f64>, &DMatrix<f64>) {
        match &self.reduced {
            None => (
                &self.model.mass,
                &self.model.stiffness,
                &self.model.gyroscopic,
                &self.model.damping,
            ),
            Some(r) => (&r.mass, &r.stiffness, &r.gyroscopic, &r.damping),
        }
    }

    /// An integrator started from state (q0, v0) in integrated coordinates at time t0.
    #[allow(clippy::too_many_arguments)]
    pub fn integrator(
        &self,
        scheme: Scheme,
        dt: f64,
        spin_speed: f64,
        bearings: Vec<Box<dyn BearingModel>>,
        newton: NewtonSettings,
        t0: f64,
        q0: DVector<f64>,
        v0: DVector<f64>,
    ) -> Result<Integrator, StepError> {
        let (m, k, g, c) = self.matrices();
        let bearing_dofs = self
            .model
            .bearing_dofs()
            .iter()
            .map(|d| [self.index(d[0]), self.index(d[1])])
            .collect();
        let mut f0 = DVector::zeros(self.n_dof());
        self.load(t0, spin_speed, &mut f0)
            .map_err(|e| StepError::Load(e.to_string()))?;
        Integrator::new(
            scheme,
            dt,
            spin_speed,
            m.clone(),
            c + g * spin_speed,
            k.clone(),
            bearing_dofs,
            bearings,
            newton,
            (t0, q0, v0),
            self.constant_load(),
            f0,
        )
    }
}
