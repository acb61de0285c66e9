//! External loads on the shaft: static forces, gravity, mass unbalance and the spur-gear mesh
//! driven by the PMSM ([`crate::model::motor`]).
//!
//! Gear mesh (docs/physics.md §6.2): the pinion of pitch radius r_p = m·z/2 transmits the motor torque
//! T(t), so the tangential tooth force is F_t = T/r_p and the separating (radial) force
//! F_r = F_t·tan α (spur gear, pressure angle α; e.g. Shigley's *Mechanical Engineering Design*,
//! 10th ed., §13-14). The transmission-error excitation is a sinusoid at the mesh frequency
//! z·Ω whose amplitude is a fraction of the transmitted force, so it follows the torque–speed
//! curve. The gear sits in direction β from the pinion centre (angle in the x–y plane from +x):
//! the radial force on the pinion points along −e_β and, for a pinion driving at +Ω, the
//! tangential reaction opposes its rotation at the contact, −F_t·e_θ with e_θ = (−sin β, cos β).
//!
//! Unbalance (Friswell et al. (2010) §3.6.1): m·e·Ω² (cos(Ωt + φ), sin(Ωt + φ)) at constant Ω;
//! during a speed ramp the angular acceleration adds the tangential m·e·Ω̇ term (the inertial
//! force of the eccentric mass, −m d²/dt² [e(cos ψ, sin ψ)]).

use crate::model::motor::Pmsm;

/// One load of the shaft model.
#[derive(Debug, Clone, PartialEq)]
pub enum Load {
    /// Constant force at a node (N).
    Static {
        /// Node index.
        node: usize,
        /// Force [fx, fy] (N).
        force: [f64; 2],
    },
    /// Gravity along −y with acceleration g (m/s²) on every mass of the model.
    Gravity {
        /// Gravitational acceleration (m/s²).
        acceleration: f64,
    },
    /// Rotating mass unbalance at a node.
    Unbalance {
        /// Node index.
        node: usize,
        /// Unbalance m·e (kg·m).
        mass_eccentricity: f64,
        /// Angular position at t = 0 (rad).
        phase: f64,
    },
    /// Spur-gear mesh at a node driven by the motor.
    GearMesh(GearMesh),
}

/// Spur pinion on the shaft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearMesh {
    /// Node index of the pinion.
    pub node: usize,
    /// Number of pinion teeth z.
    pub teeth: u32,
    /// Module m (m).
    pub module: f64,
    /// Pressure angle α (rad).
    pub pressure_angle: f64,
    /// Direction β of the mating gear's centre seen from the pinion (rad from +x towards +y).
    pub mesh_angle: f64,
    /// Relative amplitude of the mesh-frequency force fluctuation (fraction of the mean force).
    pub force_fluctuation: f64,
}

impl GearMesh {
    /// Pitch radius r_p = m z / 2 (m).
    pub fn pitch_radius(&self) -> f64 {
        self.module * f64::from(self.teeth) / 2.0
    }

    /// Mesh frequency z·Ω (rad/s) at spin speed Ω (rad/s).
    pub fn mesh_frequency(&self, spin_speed: f64) -> f64 {
        f64::from(self.teeth) * spin_speed.abs()
    }

    /// Force on the pinion [fx, fy] (N) for the instantaneous torque T (N·m) at spin angle φ.
    pub fn force(&self, torque: f64, spin_angle: f64) -> [f64; 2] {
        let fluct = 1.0 + self.force_fluctuation * (f64::from(self.teeth) * spin_angle).sin();
        let ft = torque / self.pitch_radius() * fluct;
        let fr = ft * self.pressure_angle.tan();
        let (s, c) = self.mesh_angle.sin_cos();
        // −F_r e_β − F_t e_θ, e_β = (c, s), e_θ = (−s, c).
        [-fr * c + ft * s, -fr * s - ft * c]
    }
}

/// The spin state the loads are evaluated at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinAt {
    /// Spin angle φ (rad).
    pub angle: f64,
    /// Spin speed Ω = dφ/dt (rad/s).
    pub speed: f64,
    /// Angular acceleration Ω̇ (rad/s²).
    pub acceleration: f64,
}

/// All loads of a model plus the motor that drives the gear meshes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadSet {
    /// The loads.
    pub loads: Vec<Load>,
    /// Drive motor (needed by gear meshes).
    pub motor: Option<Pmsm>,
}

impl LoadSet {
    /// Adds the load vector at time t (s) and constant spin speed Ω (rad/s) to `f`
    /// (length n_dof). `gravity_vector` is M·ĝ (the model's mass times a unit field along −y).
    /// `include_dynamic = false` gives the static part (mean gear forces, no ripple,
    /// no fluctuation, no unbalance) used for the equilibrium.
    pub fn add_forces(
        &self,
        time: f64,
        spin_speed: f64,
        gravity_vector: &[f64],
        include_dynamic: bool,
        f: &mut [f64],
    ) -> Result<(), crate::model::motor::SpeedOutOfRange> {
        self.add_forces_mapped(time, spin_speed, gravity_vector, include_dynamic, &|d| d, f)
    }

    /// As [`LoadSet::add_forces`] into a vector whose index of global DOF d is `map(d)` (a
    /// reduced model keeps the loaded nodes' DOFs; `gravity_vector` must already be in the
    /// target coordinates).
    pub fn add_forces_mapped(
        &self,
        time: f64,
        spin_speed: f64,
        gravity_vector: &[f64],
        include_dynamic: bool,
        map: &dyn Fn(usize) -> usize,
        f: &mut [f64],
    ) -> Result<(), crate::model::motor::SpeedOutOfRange> {
        let at = SpinAt {
            angle: spin_speed * time,
            speed: spin_speed,
            acceleration: 0.0,
        };
        self.add_forces_at(at, gravity_vector, include_dynamic, map, f)
    }

    /// As [`LoadSet::add_forces_mapped`] at a spin state that need not be steady (a speed
    /// ramp): the unbalance, mesh and ripple phases follow the spin angle φ, their amplitudes
    /// the instantaneous speed Ω, so the mesh frequency is z·dφ/dt = z·Ω(t).
    pub fn add_forces_at(
        &self,
        at: SpinAt,
        gravity_vector: &[f64],
        include_dynamic: bool,
        map: &dyn Fn(usize) -> usize,
        f: &mut [f64],
    ) -> Result<(), crate::model::motor::SpeedOutOfRange> {
        let (angle, spin_speed) = (at.angle, at.speed);
        for load in &self.loads {
            match *load {
                Load::Static { node, force } => {
                    f[map(4 * node)] += force[0];
                    f[map(4 * node + 1)] += force[1];
                }
                Load::Gravity { acceleration } => {
                    for (fi, gi) in f.iter_mut().zip(gravity_vector) {
                        *fi += acceleration * gi;
                    }
                }
                Load::Unbalance {
                    node,
                    mass_eccentricity,
                    phase,
                } => {
                    if include_dynamic {
                        // −m·(acceleration of the mass at e(cos ψ, sin ψ)), ψ = φ + phase:
                        // m e (Ω² cos ψ + Ω̇ sin ψ, Ω² sin ψ − Ω̇ cos ψ).
                        let amp = mass_eccentricity * spin_speed * spin_speed;
                        let tangential = mass_eccentricity * at.acceleration;
                        let (s, c) = (angle + phase).sin_cos();
                        f[map(4 * node)] += amp * c + tangential * s;
                        f[map(4 * node + 1)] += amp * s - tangential * c;
                    }
                }
                Load::GearMesh(mesh) => {
                    let Some(motor) = self.motor else { continue };
                    let mean = motor.mean_torque(spin_speed)?;
                    let force = if include_dynamic {
                        mesh.force(motor.torque(mean, angle), angle)
                    } else {
                        let steady = GearMesh {
                            force_fluctuation: 0.0,
                            ..mesh
                        };
                        steady.force(mean, 0.0)
                    };
                    f[map(4 * mesh.node)] += force[0];
                    f[map(4 * mesh.node + 1)] += force[1];
                }
            }
        }
        Ok(())
    }
}

impl Load {
    /// The node a point load acts on (None for gravity).
    pub fn node(&self) -> Option<usize> {
        match self {
            Load::Static { node, .. } | Load::Unbalance { node, .. } => Some(*node),
            Load::GearMesh(m) => Some(m.node),
            Load::Gravity { .. } => None,
        }
    }
}
