//! Natural frequencies, damping ratios, whirl directions and mode shapes of the linearised rotor.
//!
//! With gyroscopic and bearing damping terms the problem M q̈ + D q̇ + K q = 0 is non-symmetric;
//! it is solved in first-order (state-space) form (Friswell et al. (2010) §2.5 and §5.8):
//!
//!   ż = A z,  z = [q; q̇],  A = [[0, I], [−M⁻¹K, −M⁻¹D]]
//!
//! Eigenvalues come from the real Schur form (nalgebra); each mode's eigenvector from two inverse
//! iterations on (A − σI) with σ next to the eigenvalue. Frequencies are the imaginary parts
//! (rad/s), damping ratio ζ = −Re λ / |λ|. A mode whirls forward when the node orbits turn with
//! the spin (+z): for x = Re(X e^{iωt}), y = Re(Y e^{iωt}) that is Im(X̄ Y) < 0.
//! The undamped non-rotating problem K φ = ω² M φ is also offered (symmetric, Cholesky-reduced).

use nalgebra::{Complex, DMatrix, DVector, Schur, SymmetricEigen};

/// Errors of the eigen-analyses.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModesError {
    /// The mass matrix is not positive definite.
    #[error("the mass matrix is not positive definite (a node without mass or inertia?)")]
    MassNotPositiveDefinite,
    /// The Schur iteration did not converge.
    #[error("the eigenvalue (Schur) iteration did not converge")]
    SchurNotConverged,
    /// The interior stiffness of a reduction is singular (an interior part not held).
    #[error("singular interior stiffness: every free part of the shaft must reach a kept node")]
    SingularInterior,
    /// A bearing DOF is not a kept (boundary) coordinate of the reduced model.
    #[error("bearing DOF {0} is not kept by the reduction")]
    NotKept(usize),
}

/// Direction of the whirl orbit relative to the spin.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Whirl {
    /// Orbit turns with the spin.
    Forward,
    /// Orbit turns against the spin.
    Backward,
    /// Straight-line (planar) or mixed orbit: no clear direction.
    Planar,
}

/// One mode of the linearised rotor.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// Eigenvalue λ (1/s).
    pub eigenvalue: Complex<f64>,
    /// Damped natural frequency Im λ (rad/s).
    pub frequency: f64,
    /// Damping ratio −Re λ / |λ|.
    pub damping_ratio: f64,
    /// Whirl direction.
    pub whirl: Whirl,
    /// Displacement part of the eigenvector (n_dof), largest entry scaled to 1; empty when
    /// shapes were not requested.
    pub shape: Vec<Complex<f64>>,
}

/// M⁻¹ X via Cholesky.
fn mass_solve(m: &DMatrix<f64>, x: &DMatrix<f64>) -> Result<DMatrix<f64>, ModesError> {
    let chol = m
        .clone()
        .cholesky()
        .ok_or(ModesError::MassNotPositiveDefinite)?;
    Ok(chol.solve(x))
}

/// State matrix A = [[0, I], [−M⁻¹K, −M⁻¹D]].
pub fn state_matrix(
    m: &DMatrix<f64>,
    k: &DMatrix<f64>,
    d: &DMatrix<f64>,
) -> Result<DMatrix<f64>, ModesError> {
    let n = m.nrows();
    let mk = mass_solve(m, k)?;
    let md = mass_solve(m, d)?;
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -mk[(i, j)];
            a[(n + i, n + j)] = -md[(i, j)];
        }
    }
    Ok(a)
}

/// The oscillating modes (Im λ > 0) of M q̈ + D q̇ + K q = 0: the `max_modes` of lowest |λ|,
/// returned ascending in Im λ. Rigid-body (λ ≈ 0) and overdamped (real λ) roots are left out.
pub fn damped_modes(
    m: &DMatrix<f64>,
    k: &DMatrix<f64>,
    d: &DMatrix<f64>,
    max_modes: usize,
    with_shapes: bool,
) -> Result<Vec<Mode>, ModesError> {
    let n = m.nrows();
    let a = state_matrix(m, k, d)?;
    let scale = a.amax().max(1.0);
    let schur = Schur::try_new(a.clone(), 1e-14, 100_000).ok_or(ModesError::SchurNotConverged)?;
    let eig = schur.complex_eigenvalues();
    let largest = eig.iter().map(|z| z.norm()).fold(0.0, f64::max);
    // Frequencies below this are rigid-body or numerical zeros.
    let floor = 1e-7 * largest.max(1e-300) + 1e-9 * scale.sqrt();
    let mut roots: Vec<Complex<f64>> = eig.iter().copied().filter(|z| z.im > floor).collect();
    // Keep the modes of lowest undamped frequency |λ| (heavily damped element modes with a
    // small Im λ but a huge |λ| are not what a user asks for), then order by Im λ.
    roots.sort_by(|p, q| p.norm().total_cmp(&q.norm()));
    roots.truncate(max_modes);
    roots.sort_by(|p, q| p.im.total_cmp(&q.im));
    let ac = a.map(|x| Complex::new(x, 0.0));
    let mut modes = Vec::with_capacity(roots.len());
    for lambda in roots {
        // The eigenvector is always computed (the whirl needs it); it is kept on request.
        let v = inverse_iteration(&ac, lambda);
        let q: Vec<Complex<f64>> = v.iter().take(n).copied().collect();
        let whirl = whirl_of(&q);
        let shape = if with_shapes {
            normalised(q)
        } else {
            Vec::new()
        };
        modes.push(Mode {
            eigenvalue: lambda,
            frequency: lambda.im,
            damping_ratio: -lambda.re / lambda.norm(),
            whirl,
            shape,
        });
    }
    Ok(modes)
}

/// Eigenvector of A for the eigenvalue λ: two inverse iterations with a shift next to λ.
fn inverse_iteration(a: &DMatrix<Complex<f64>>, lambda: Complex<f64>) -> DVector<Complex<f64>> {
    let n = a.nrows();
    let shift = lambda * Complex::new(1.0 + 1e-9, 1e-9);
    let mut b = a.clone();
    for i in 0..n {
        b[(i, i)] -= shift;
    }
    let lu = b.lu();
    // Deterministic, generic start vector.
    let mut v = DVector::from_fn(n, |i, _| Complex::new(1.0 + 0.1 * (i as f64).sin(), 0.3));
    for _ in 0..3 {
        if let Some(w) = lu.solve(&v) {
            let norm = w.norm();
            if norm > 0.0 && norm.is_finite() {
                v = w / Complex::new(norm, 0.0);
            }
        }
    }
    v
}

/// Forward / backward whirl from the x and y parts of a shape.
fn whirl_of(q: &[Complex<f64>]) -> Whirl {
    let (mut s, mut total) = (0.0, 0.0);
    for node in q.chunks(4) {
        if let [x, y, ..] = node {
            s += (x.conj() * y).im;
            total += x.norm_sqr() + y.norm_sqr();
        }
    }
    if s < -1e-3 * total {
        Whirl::Forward
    } else if s > 1e-3 * total {
        Whirl::Backward
    } else {
        Whirl::Planar
    }
}

/// Scales a shape so its largest entry is 1 (real, positive).
fn normalised(q: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    let big = q
        .iter()
        .copied()
        .max_by(|p, r| p.norm().total_cmp(&r.norm()))
        .unwrap_or(Complex::new(1.0, 0.0));
    if big.norm() == 0.0 {
        return q;
    }
    q.into_iter().map(|z| z / big).collect()
}

/// Undamped natural frequencies (rad/s, ascending, negative round-off clamped to 0) and mass-
/// normalised mode shapes (columns) of K φ = ω² M φ.
pub fn undamped_modes(
    m: &DMatrix<f64>,
    k: &DMatrix<f64>,
) -> Result<(Vec<f64>, DMatrix<f64>), ModesError> {
    let chol = m
        .clone()
        .cholesky()
        .ok_or(ModesError::MassNotPositiveDefinite)?;
    let l = chol.l();
    let l_inv = l
        .clone()
        .try_inverse()
        .ok_or(ModesError::MassNotPositiveDefinite)?;
    let mut kr = &l_inv * k * l_inv.transpose();
    kr = (&kr + kr.transpose()) * 0.5;
    let eig = SymmetricEigen::new(kr);
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
    let freqs = order
        .iter()
        .map(|&i| eig.eigenvalues[i].max(0.0).sqrt())
        .collect();
    let back = l_inv.transpose() * &eig.eigenvectors;
    let shapes = DMatrix::from_fn(back.nrows(), order.len(), |r, c| back[(r, order[c])]);
    Ok((freqs, shapes))
}
