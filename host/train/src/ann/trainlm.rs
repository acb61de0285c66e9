//! Levenberg–Marquardt on the normal equations, as MATLAB's `trainlm` runs it (Hagan & Menhaj
//! 1994; MathWorks, *trainlm* reference page): each epoch forms `JᵀJ` and `Jᵀe` once, then tries
//! `Δθ = −(JᵀJ + μI)⁻¹ Jᵀe`, multiplying μ by `mu_inc` = 10 until the objective falls, accepts
//! the step and divides μ by 10 (`mu_dec` = 0.1). Training stops after `max_epochs` epochs, after
//! `patience` epochs without a better validation error (`max_fail`), when μ exceeds
//! `mu_max` = 10¹⁰ or when the gradient norm falls below `min_grad` = 10⁻⁷ (the documented
//! defaults, initial μ = 0.001).
//!
//! **Why a second trainer.** The default trainer ([`super::train`], the `levenberg-marquardt`
//! crate, a MINPACK port) factors the whole `(2N + P) × P` Jacobian by Householder QR every
//! epoch, unblocked and on one core: `O(N·P²)` at a few GFLOP/s. For the small nets the core
//! runs that is milliseconds, but for the larger nets of the published architecture study
//! (up to 4×20, P = 1422, on 3500 training samples) it is tens of seconds per epoch, and
//! training the grid to the published stopping rule would take about a day. Here the same
//! `O(N·P²)` work is one symmetric product `JᵀJ` (faer's blocked SIMD kernel, only the lower
//! triangle), and each μ trial is a Cholesky factorisation of a `P × P` matrix: the
//! architecture study runs in under an hour. Both minimise the same objective, so either can
//! produce any row of the study; the committed model stays on the crate's trainer.
//!
//! **Objective** (the same as the crate trainer's): `Σ (y − t)²/(2N) + (λ/P) Σ θ²`, i.e. the
//! residual vector `[(y − t)·d ; r·θ]` with `d = 1/√(2N)`, `r = √(λ/P)`. Its Gauss–Newton
//! matrix is `d²·JᵀJ + r²I` and its half-gradient `d²·Jᵀe + r²θ`; μ is added to that matrix.

use faer::linalg::matmul::triangular::{matmul, BlockStructure};
use faer::linalg::solvers::Solve;
use faer::{Accum, Mat, MatRef, Par, Side};
use rayon::prelude::*;

use super::mlp::Mlp;

/// The `trainlm` parameters (MathWorks defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrainlmParams {
    /// Initial μ.
    pub mu: f64,
    /// Factor applied to μ after an accepted step.
    pub mu_dec: f64,
    /// Factor applied to μ after a rejected trial.
    pub mu_inc: f64,
    /// Training stops when μ exceeds this.
    pub mu_max: f64,
    /// Training stops when the gradient norm falls below this.
    pub min_grad: f64,
}

impl Default for TrainlmParams {
    fn default() -> Self {
        Self {
            mu: 1e-3,
            mu_dec: 0.1,
            mu_inc: 10.0,
            mu_max: 1e10,
            min_grad: 1e-7,
        }
    }
}

/// The data of one training run, already normalised.
pub struct TrainingData<'a> {
    /// Training inputs.
    pub x: &'a [Vec<f64>],
    /// Training targets.
    pub t: &'a [[f64; 2]],
    /// Validation inputs.
    pub val_x: &'a [Vec<f64>],
    /// Validation targets.
    pub val_t: &'a [[f64; 2]],
    /// Weight-decay coefficient λ.
    pub regularisation: f64,
    /// Epoch limit.
    pub max_epochs: usize,
    /// Epochs without validation improvement before stopping.
    pub patience: usize,
}

/// Why a run stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopReason {
    /// `patience` epochs without a better validation error.
    Validation,
    /// The epoch limit.
    MaxEpochs,
    /// μ exceeded `mu_max`: no step lowers the objective.
    MuMax,
    /// The gradient norm fell below `min_grad`.
    MinGradient,
}

/// The result of one run: the weights with the best validation error.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainlmRun {
    /// Parameters at the best validation error.
    pub best_params: Vec<f64>,
    /// Best validation mean squared error (per output, normalised targets).
    pub best_validation_mse: f64,
    /// Epochs run (accepted steps).
    pub epochs: usize,
    /// Why it stopped.
    pub stop: StopReason,
}

/// Mean squared error per output; per-sample terms in parallel, summed in order (deterministic
/// whatever the thread count).
pub(super) fn mse(net: &Mlp, x: &[Vec<f64>], t: &[[f64; 2]]) -> f64 {
    let terms: Vec<f64> = x
        .par_iter()
        .zip(t)
        .map(|(xi, ti)| {
            let y = net.forward(xi);
            (y[0] - ti[0]).powi(2) + (y[1] - ti[1]).powi(2)
        })
        .collect();
    terms.iter().sum::<f64>() / (2 * t.len()).max(1) as f64
}

/// The objective `mse + (λ/P)·Σθ²` at `params`.
fn objective(net: &Mlp, data: &TrainingData, params: &[f64]) -> f64 {
    let p = params.len().max(1) as f64;
    mse(net, data.x, data.t) + data.regularisation / p * params.iter().map(|v| v * v).sum::<f64>()
}

/// The Gauss–Newton matrix `d²·JᵀJ` (lower triangle) and the half-gradient `d²·Jᵀe` of the data
/// term at the network's current parameters.
fn normal_equations(net: &Mlp, data: &TrainingData) -> (Mat<f64>, Vec<f64>) {
    let p = net.parameter_count();
    let n = data.x.len();
    let d2 = 1.0 / (2 * n).max(1) as f64;
    // Jᵀ in column-major storage, one column of p per (sample, output). Each sample writes its
    // two columns (and its two residuals) in place, so the Jacobian is held once: 4x20 on 5000
    // samples is 80 MB, not twice that.
    let mut jt = vec![0.0; p * 2 * n];
    let mut residuals = vec![0.0; 2 * n];
    jt.par_chunks_mut(2 * p.max(1))
        .zip(residuals.par_chunks_mut(2))
        .zip(data.x.par_iter().zip(data.t.par_iter()))
        .for_each(|((columns, e), (xi, ti))| {
            let (y, jac) = net.forward_with_jacobian(xi);
            for (o, (column, e)) in columns.chunks_mut(p.max(1)).zip(e.iter_mut()).enumerate() {
                column.copy_from_slice(&jac[o]);
                *e = y[o] - ti[o];
            }
        });
    // The gradient Jᵀe/(2N), summed in sample order (the same order on every run).
    let mut gradient = vec![0.0; p];
    for (column, e) in jt.chunks(p.max(1)).zip(&residuals) {
        for (g, v) in gradient.iter_mut().zip(column) {
            *g += d2 * e * v;
        }
    }
    let jt = MatRef::from_column_major_slice(&jt, p, 2 * n);
    let mut jtj = Mat::<f64>::zeros(p, p);
    matmul(
        jtj.as_mut(),
        BlockStructure::TriangularLower,
        Accum::Replace,
        jt,
        BlockStructure::Rectangular,
        jt.transpose(),
        BlockStructure::Rectangular,
        d2,
        Par::Seq,
    );
    (jtj, gradient)
}

/// Train `net` from its current weights; `net` ends at the last accepted step, the best
/// validation weights are returned.
pub fn trainlm(net: &mut Mlp, data: &TrainingData, params: TrainlmParams) -> TrainlmRun {
    let p = net.parameter_count();
    let r2 = data.regularisation / p.max(1) as f64;
    let mut theta = net.parameters();
    let mut current = objective(net, data, &theta);
    let mut best_val = mse(net, data.val_x, data.val_t);
    let mut best_params = theta.clone();
    let mut fails = 0;
    let mut mu = params.mu;
    let mut epochs = 0;
    let stop = loop {
        if epochs >= data.max_epochs {
            break StopReason::MaxEpochs;
        }
        let (jtj, data_gradient) = normal_equations(net, data);
        let gradient: Vec<f64> = data_gradient
            .iter()
            .zip(&theta)
            .map(|(g, t)| g + r2 * t)
            .collect();
        // The objective's gradient is twice the half-gradient.
        if 2.0 * gradient.iter().map(|g| g * g).sum::<f64>().sqrt() < params.min_grad {
            break StopReason::MinGradient;
        }
        let mut rhs = Mat::<f64>::zeros(p, 1);
        for (k, g) in gradient.iter().enumerate() {
            rhs[(k, 0)] = -g;
        }
        let accepted = loop {
            if mu > params.mu_max {
                break false;
            }
            let mut system = jtj.clone();
            for k in 0..p {
                system[(k, k)] += r2 + mu;
            }
            let step = match system.llt(Side::Lower) {
                Ok(llt) => llt.solve(&rhs),
                Err(_) => {
                    mu *= params.mu_inc;
                    continue;
                }
            };
            let trial: Vec<f64> = theta
                .iter()
                .enumerate()
                .map(|(k, t)| t + step[(k, 0)])
                .collect();
            net.set_parameters(&trial);
            let value = objective(net, data, &trial);
            if value < current {
                theta = trial;
                current = value;
                mu *= params.mu_dec;
                break true;
            }
            mu *= params.mu_inc;
        };
        if !accepted {
            net.set_parameters(&theta);
            break StopReason::MuMax;
        }
        epochs += 1;
        let val = mse(net, data.val_x, data.val_t);
        if val < best_val {
            best_val = val;
            best_params.clone_from(&theta);
            fails = 0;
        } else {
            fails += 1;
            if fails >= data.patience {
                break StopReason::Validation;
            }
        }
    };
    TrainlmRun {
        best_params,
        best_validation_mse: best_val,
        epochs,
        stop,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::mlp::Activation;

    fn sample_data(n: usize, seed: u64) -> (Vec<Vec<f64>>, Vec<[f64; 2]>) {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        (0..n)
            .map(|_| {
                let x: Vec<f64> = (0..3).map(|_| rng.random_range(-1.0..1.0)).collect();
                // A smooth target pair (closed form), well inside a 1×8 tanh net's reach.
                let t = [
                    (0.7 * x[0] - 0.4 * x[1]).sin() + 0.2 * x[2] * x[2],
                    0.5 * (x[0] * x[1]).tanh() - 0.3 * x[2],
                ];
                (x, t)
            })
            .unzip()
    }

    /// The normal equations against the explicit Jacobian: `JᵀJ` and `Jᵀe` summed by hand from
    /// the backpropagation rows (whose own test is against finite differences).
    #[test]
    fn normal_equations_match_the_explicit_sums() {
        let net = Mlp::new(3, &[4], 2, Activation::Tanh, 7);
        let (x, t) = sample_data(9, 3);
        let data = TrainingData {
            x: &x,
            t: &t,
            val_x: &x,
            val_t: &t,
            regularisation: 0.0,
            max_epochs: 1,
            patience: 1,
        };
        let (jtj, g) = normal_equations(&net, &data);
        let p = net.parameter_count();
        let d2 = 1.0 / 18.0;
        let mut want = vec![vec![0.0; p]; p];
        let mut want_g = vec![0.0; p];
        for (xi, ti) in x.iter().zip(&t) {
            let (y, jac) = net.forward_with_jacobian(xi);
            for o in 0..2 {
                for a in 0..p {
                    want_g[a] += d2 * (y[o] - ti[o]) * jac[o][a];
                    for b in 0..p {
                        want[a][b] += d2 * jac[o][a] * jac[o][b];
                    }
                }
            }
        }
        for a in 0..p {
            assert!((g[a] - want_g[a]).abs() < 1e-13, "gradient {a}");
            for b in 0..=a {
                assert!((jtj[(a, b)] - want[a][b]).abs() < 1e-12, "JᵀJ ({a}, {b})");
            }
        }
    }

    /// Every accepted step lowers the objective (the defining property of the μ schedule), the
    /// fit reaches a small error on a smooth closed form, and two runs give the same weights.
    #[test]
    fn fits_a_closed_form_and_is_deterministic() {
        let (x, t) = sample_data(400, 1);
        let (vx, vt) = sample_data(100, 2);
        let data = TrainingData {
            x: &x,
            t: &t,
            val_x: &vx,
            val_t: &vt,
            regularisation: 1e-7,
            max_epochs: 200,
            patience: 6,
        };
        let start = Mlp::new(3, &[8], 2, Activation::Tanh, 5);
        let initial = mse(&start, &vx, &vt);
        let mut net = start.clone();
        let run = trainlm(&mut net, &data, TrainlmParams::default());
        assert!(run.epochs > 5, "{run:?}");
        // The targets' variance is O(0.1); a converged 1×8 net fits them to ~1e-5.
        assert!(
            run.best_validation_mse < 1e-4 && run.best_validation_mse < 1e-3 * initial,
            "{} from {initial}",
            run.best_validation_mse
        );
        let mut again = start;
        assert_eq!(trainlm(&mut again, &data, TrainlmParams::default()), run);
    }

    /// The objective never rises from one accepted step to the next: run one epoch at a time.
    #[test]
    fn accepted_steps_lower_the_objective() {
        let (x, t) = sample_data(200, 4);
        let mut net = Mlp::new(3, &[6, 6], 2, Activation::Logistic, 9);
        let mut last = f64::INFINITY;
        for _ in 0..15 {
            let data = TrainingData {
                x: &x,
                t: &t,
                val_x: &x,
                val_t: &t,
                regularisation: 1e-4,
                max_epochs: 1,
                patience: 100,
            };
            let run = trainlm(&mut net, &data, TrainlmParams::default());
            assert_eq!(run.epochs, 1);
            let value = objective(&net, &data, &net.parameters());
            assert!(value < last, "{value} after {last}");
            last = value;
        }
    }
}
