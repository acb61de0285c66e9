//! Elastic deflection of the line contact: the log kernel integrated exactly over each element.
//!
//! For plane strain of two elastic half-spaces with reduced modulus E' (docs/physics.md §1) the
//! deflection under a line pressure p(x') is −(2/(πE'))∫p ln|x−x'|dx' + const (Johnson,
//! *Contact Mechanics*, eq. 2.25 with E* = E'/2). In the Hertz scaling X = x/b, P = p/p_h,
//! H = hR/b² this becomes the film equation of docs/physics.md §5.2,
//!
//!   H(X) = H₀ + X²/2 − (1/π) ∫ P(X') ln|X − X'| dX',
//!
//! (the additive constant is absorbed in H₀). P is taken piecewise linear between nodes, so the
//! integral is a matrix–vector product with K_ij = ∫ φ_j(X') ln|X_i − X'| dX', φ_j the hat
//! function of node j. Each element integral is done in closed form from the antiderivatives
//! F₀(t) = t ln|t| − t and F₁(t) = t²/2 ln|t| − t²/4 of ln|t| and t ln|t| — exact, including the
//! integrable singularity at X' = X_i, instead of sampling the kernel at nodes.

/// ∫ ln|t| dt antiderivative (0 at t = 0).
#[inline]
fn f0(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * (t.abs().ln() - 1.0)
    }
}

/// ∫ t ln|t| dt antiderivative (0 at t = 0).
#[inline]
fn f1(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        0.5 * t * t * (t.abs().ln() - 0.5)
    }
}

/// Fills `row` (length = nodes.len()) with K(x, j) = ∫ φ_j(X') ln|x − X'| dX' for a field point x.
pub fn kernel_row(nodes: &[f64], x: f64, row: &mut [f64]) {
    row.iter_mut().for_each(|v| *v = 0.0);
    let n = nodes.len();
    if n < 2 {
        return;
    }
    let mut t_prev = nodes[0] - x;
    let mut f0_prev = f0(t_prev);
    let mut f1_prev = f1(t_prev);
    for e in 0..n - 1 {
        let t_next = nodes[e + 1] - x;
        let f0_next = f0(t_next);
        let f1_next = f1(t_next);
        let len = nodes[e + 1] - nodes[e];
        let i0 = f0_next - f0_prev;
        let i1 = f1_next - f1_prev;
        // ∫ φ_right ln = ∫ (t − t_a)/len ln|t| dt
        let w_right = (i1 - t_prev * i0) / len;
        row[e] += i0 - w_right;
        row[e + 1] += w_right;
        t_prev = t_next;
        f0_prev = f0_next;
        f1_prev = f1_next;
    }
}

/// Dense deflection matrix K (row-major, n×n) for field points at the nodes themselves.
pub fn kernel_matrix(nodes: &[f64]) -> Vec<f64> {
    let n = nodes.len();
    let mut k = vec![0.0; n * n];
    for (i, row) in k.chunks_mut(n).enumerate() {
        kernel_row(nodes, nodes[i], row);
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{LN_2, PI};

    /// Hertz check: ∫₋₁¹ √(1−t²) ln|x−t| dt = (π/2)(x² − 1/2 − ln 2) for |x| ≤ 1 (closed form,
    /// e.g. Johnson, *Contact Mechanics* §5.6 / Gradshteyn 4.241); so the Hertz pressure
    /// P = √(1 − X²) makes the film equation exactly flat inside the contact.
    #[test]
    fn hertz_pressure_gives_closed_form_deflection() {
        let n = 2001;
        let nodes: Vec<f64> = (0..n)
            .map(|i| -1.0 + 2.0 * i as f64 / (n - 1) as f64)
            .collect();
        let p: Vec<f64> = nodes
            .iter()
            .map(|x| (1.0 - x * x).max(0.0).sqrt())
            .collect();
        let mut row = vec![0.0; n];
        for &x in &[0.0, 0.3, -0.77, 0.95] {
            kernel_row(&nodes, x, &mut row);
            let val: f64 = row.iter().zip(&p).map(|(k, p)| k * p).sum();
            let exact = 0.5 * PI * (x * x - 0.5 - LN_2);
            // The square-root edge limits piecewise-linear interpolation to O(h^1.5).
            assert!((val - exact).abs() < 2e-4, "x={x}: {val} vs {exact}");
        }
    }

    /// A constant P = 1 on [a, b] must give exactly F₀(b−x) − F₀(a−x) at any x (linear elements
    /// reproduce a constant exactly), also at a node (singular point).
    #[test]
    fn constant_pressure_exact() {
        let nodes = [-1.0, -0.2, 0.1, 0.7, 2.0];
        let mut row = [0.0; 5];
        for &x in &[0.1, 0.33, 5.0] {
            kernel_row(&nodes, x, &mut row);
            let val: f64 = row.iter().sum();
            let exact = f0(2.0 - x) - f0(-1.0 - x);
            assert!((val - exact).abs() < 1e-13);
        }
    }
}
