//! Right-preconditioned GMRES (Saad & Schultz 1986; Saad, *Iterative Methods for Sparse Linear
//! Systems*, 2nd ed., 2003, Algorithm 9.5) for the Newton systems of the point-contact solver:
//! the operator is the exact Jacobian applied matrix-free (its deflection part by FFT), the
//! preconditioner the sparse LU of the windowed (semi-system) Jacobian.
//!
//! Written here rather than taken from faer's `operator::bicgstab` (the Krylov solver of the
//! linear-algebra crate already used): GMRES minimises the true residual monotonically with one
//! operator and one preconditioner application per iteration, against BiCGStab's two of each
//! and its irregular residual, and the closures below need no `Sync` operator type around the
//! FFT buffers.

/// Solves A x = f for x (started from zero) to ‖f − Ax‖ ≤ `tolerance`·‖f‖ or `max_iterations`
/// Krylov steps, with `apply(v, out)`: out = A v and `precondition(v)`: v ← M⁻¹ v. Returns the
/// iterations taken and the relative residual reached.
pub(super) fn gmres(
    f: &[f64],
    x: &mut [f64],
    tolerance: f64,
    max_iterations: usize,
    mut apply: impl FnMut(&[f64], &mut [f64]),
    mut precondition: impl FnMut(&mut [f64]),
) -> (usize, f64) {
    let n = f.len();
    x.iter_mut().for_each(|v| *v = 0.0);
    let beta = norm(f);
    if beta == 0.0 {
        return (0, 0.0);
    }
    // Krylov basis V, preconditioned directions Z = M⁻¹V, Hessenberg columns after the
    // Givens rotations (c, s), and the rotated right-hand side g.
    let mut basis: Vec<Vec<f64>> = vec![f.iter().map(|v| v / beta).collect()];
    let mut directions: Vec<Vec<f64>> = Vec::new();
    let mut hessenberg: Vec<Vec<f64>> = Vec::new();
    let mut rotations: Vec<(f64, f64)> = Vec::new();
    let mut g = vec![beta];
    let mut w = vec![0.0; n];
    let mut residual = 1.0;
    for j in 0..max_iterations {
        let mut z = basis[j].clone();
        precondition(&mut z);
        apply(&z, &mut w);
        directions.push(z);
        // Modified Gram–Schmidt.
        let mut column = Vec::with_capacity(j + 2);
        for v in &basis {
            let hij = dot(&w, v);
            w.iter_mut().zip(v).for_each(|(a, b)| *a -= hij * b);
            column.push(hij);
        }
        let next = norm(&w);
        column.push(next);
        for (i, &(c, s)) in rotations.iter().enumerate() {
            let (a, b) = (column[i], column[i + 1]);
            column[i] = c * a + s * b;
            column[i + 1] = -s * a + c * b;
        }
        let (a, b) = (column[j], column[j + 1]);
        let r = a.hypot(b);
        let (c, s) = if r == 0.0 { (1.0, 0.0) } else { (a / r, b / r) };
        column[j] = r;
        column[j + 1] = 0.0;
        rotations.push((c, s));
        g.push(-s * g[j]);
        g[j] *= c;
        hessenberg.push(column);
        residual = g[j + 1].abs() / beta;
        if residual <= tolerance || next == 0.0 || j + 1 == max_iterations {
            break;
        }
        basis.push(w.iter().map(|v| v / next).collect());
    }
    // Back substitution of the triangular system, then x = Z y.
    let k = hessenberg.len();
    let mut y = vec![0.0; k];
    for i in (0..k).rev() {
        let mut s = g[i];
        for (l, yl) in y.iter().enumerate().skip(i + 1) {
            s -= hessenberg[l][i] * yl;
        }
        y[i] = s / hessenberg[i][i];
    }
    for (yl, z) in y.iter().zip(&directions) {
        x.iter_mut().zip(z).for_each(|(a, b)| *a += yl * b);
    }
    (k, residual)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-symmetric tridiagonal system, unpreconditioned and with its Jacobi
    /// preconditioner, is solved to the requested residual (checked by applying A).
    #[test]
    fn solves_nonsymmetric_system() {
        let n = 40;
        let apply = |v: &[f64], out: &mut [f64]| {
            for i in 0..n {
                let left = if i > 0 { v[i - 1] } else { 0.0 };
                let right = if i + 1 < n { v[i + 1] } else { 0.0 };
                out[i] = (3.0 + 0.1 * i as f64) * v[i] - 1.3 * left - 0.4 * right;
            }
        };
        let f: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin() + 0.2).collect();
        for jacobi in [false, true] {
            let mut x = vec![0.0; n];
            let (iterations, reached) = gmres(&f, &mut x, 1e-10, n, apply, |v| {
                if jacobi {
                    v.iter_mut()
                        .enumerate()
                        .for_each(|(i, a)| *a /= 3.0 + 0.1 * i as f64);
                }
            });
            let mut ax = vec![0.0; n];
            apply(&x, &mut ax);
            let error = ax.iter().zip(&f).map(|(a, b)| (a - b).powi(2)).sum::<f64>();
            assert!(reached <= 1e-10 && iterations < n, "{iterations} {reached}");
            assert!(error.sqrt() <= 1e-9 * norm(&f), "{error}");
        }
    }
}
