//! Building the integrator: the effective matrix K*, its inverse and the step operators formed
//! from it (see the parent module), at construction and again after a spin-speed change.

use nalgebra::{DMatrix, DVector};

use super::{
    Integrator, NewtonSettings, RotorState, Scheme, StepError, StepStats, StepTotals, MAX_BEARINGS,
};
use crate::bearing::{BearingModel, BearingReaction};

impl Integrator {
    /// Sets up the integrator. `damping` is D = C + ΩG (linear part), `bearing_dofs` the x, y
    /// DOF indices of each bearing, `constant_load` the load present at all times (gravity),
    /// `f0` the time-varying load at the initial time. The initial acceleration is solved from
    /// the equation of motion.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        scheme: Scheme,
        dt: f64,
        spin_speed: f64,
        mass: DMatrix<f64>,
        damping: DMatrix<f64>,
        stiffness: DMatrix<f64>,
        bearing_dofs: Vec<[usize; 2]>,
        bearings: Vec<Box<dyn BearingModel>>,
        newton: NewtonSettings,
        initial: (f64, DVector<f64>, DVector<f64>),
        constant_load: DVector<f64>,
        f0: DVector<f64>,
    ) -> Result<Integrator, StepError> {
        let nb = bearing_dofs.len();
        if nb > MAX_BEARINGS {
            return Err(StepError::TooManyBearings(nb));
        }
        let (alpha, beta, gamma) = scheme.parameters();
        let n = mass.nrows();
        let empty = || DMatrix::zeros(0, 0);
        let (time, q, v) = initial;
        let mut me = Integrator {
            alpha,
            beta,
            gamma,
            dt,
            spin_speed,
            mass,
            stiffness,
            op_q: empty(),
            op_v: empty(),
            op_hht: None,
            k_eff_inv: empty(),
            const_response: DVector::zeros(n),
            constant_load: constant_load.clone(),
            z: empty(),
            s: empty(),
            bearing_dofs,
            bearings,
            newton,
            state: RotorState {
                time,
                q: q.clone(),
                v: v.clone(),
                a: DVector::zeros(n),
            },
            f_prev: f0.clone(),
            fb_prev: DVector::zeros(2 * nb),
            q_pred: DVector::zeros(n),
            v_pred: DVector::zeros(n),
            q_lin: DVector::zeros(n),
            reactions: vec![BearingReaction::default(); nb],
            stats: StepStats::default(),
            totals: StepTotals::default(),
            eval_u: [0.0; 2 * MAX_BEARINGS],
            eval_w: [0.0; 2 * MAX_BEARINGS],
        };
        me.build_operators(&damping)?;
        let mut u = [0.0; 2 * MAX_BEARINGS];
        let mut w = [0.0; 2 * MAX_BEARINGS];
        for (b, d) in me.bearing_dofs.iter().enumerate() {
            for c in 0..2 {
                u[2 * b + c] = q[d[c]];
                w[2 * b + c] = v[d[c]];
            }
        }
        me.settle_bearings(&u, &w, time)?;
        let mut rhs = constant_load + f0 - &damping * &v - &me.stiffness * &q;
        for (b, d) in me.bearing_dofs.iter().enumerate() {
            for c in 0..2 {
                me.fb_prev[2 * b + c] = me.reactions[b].force[c];
                rhs[d[c]] += me.reactions[b].force[c];
            }
        }
        let chol = me
            .mass
            .clone()
            .cholesky()
            .ok_or(StepError::SingularSystem)?;
        me.state.a = chol.solve(&rhs);
        me.totals = StepTotals::default();
        Ok(me)
    }

    /// Forms K* = M/(βh²) + (1−α)γ/(βh) D + (1−α)K, its inverse and the step operators for the
    /// linear damping D (the constructor's, or a new one after a speed change).
    fn build_operators(&mut self, damping: &DMatrix<f64>) -> Result<(), StepError> {
        let (alpha, beta, gamma, dt) = (self.alpha, self.beta, self.gamma, self.dt);
        let (mass, stiffness) = (&self.mass, &self.stiffness);
        let n = mass.nrows();
        let nb = self.bearing_dofs.len();
        let c1 = gamma / (beta * dt);
        let k_eff =
            mass / (beta * dt * dt) + damping * ((1.0 - alpha) * c1) + stiffness * (1.0 - alpha);
        let k_eff_inv = k_eff.try_inverse().ok_or(StepError::SingularSystem)?;
        self.op_q = &k_eff_inv * (mass / (beta * dt * dt) + damping * ((1.0 - alpha) * c1));
        self.op_v = &k_eff_inv * damping * (-(1.0 - alpha));
        self.op_hht = (alpha != 0.0).then(|| {
            (
                &k_eff_inv * stiffness * (-alpha),
                &k_eff_inv * damping * (-alpha),
            )
        });
        self.const_response = &k_eff_inv * &self.constant_load;
        let mut z = DMatrix::zeros(n, 2 * nb);
        for (b, dofs) in self.bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                z.set_column(2 * b + c, &k_eff_inv.column(dof));
            }
        }
        let mut s = DMatrix::zeros(2 * nb, 2 * nb);
        for (b, dofs) in self.bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                for j in 0..2 * nb {
                    s[(2 * b + c, j)] = z[(dof, j)];
                }
            }
        }
        self.k_eff_inv = k_eff_inv;
        self.z = z;
        self.s = s;
        Ok(())
    }

    /// Changes the spin speed Ω (rad/s) for the following steps: the bearings see the new
    /// speed and the operators are rebuilt with the new linear damping D = C + ΩG (given by the
    /// caller in the integrated coordinates). For a speed ramp this is called before every
    /// step with the speed at the step's end, so the gyroscopic term of the implicit equation
    /// is taken at t₁ like every other term of the average-acceleration rule. (With HHT-α the
    /// α-weighted D v₀ term then also uses the new D: an O(ΔΩ) difference per step.)
    pub fn set_spin_speed(
        &mut self,
        spin_speed: f64,
        damping: &DMatrix<f64>,
    ) -> Result<(), StepError> {
        if spin_speed == self.spin_speed {
            return Ok(());
        }
        self.spin_speed = spin_speed;
        self.build_operators(damping)
    }
}
