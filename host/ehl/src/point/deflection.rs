//! Elastic deflection of the point contact: exact influence coefficients of a uniform pressure
//! on a rectangle, applied as a convolution by zero-padded FFT.
//!
//! Two elastic half-spaces of reduced modulus E' (docs/physics.md §1) deflect together by
//! d(x, y) = (2/(πE')) ∬ p(x′, y′)/√((x − x′)² + (y − y′)²) dx′dy′ (Boussinesq; Johnson,
//! *Contact Mechanics*, eq. 3.20 with E* = E'/2). The pressure is taken constant on the cell
//! around each node, and the integral of 1/r over a rectangle is Love's (1929) closed form: with
//! G(u, v) = u asinh(v/|u|) + v asinh(u/|v|), whose mixed derivative ∂²G/∂u∂v is 1/√(u² + v²),
//! the cell of half-widths (ℓ_x, ℓ_y) centred at offset (u, v) from the field point contributes
//! G(u+ℓ_x, v+ℓ_y) − G(u−ℓ_x, v+ℓ_y) − G(u+ℓ_x, v−ℓ_y) + G(u−ℓ_x, v−ℓ_y) (the asinh form
//! differs from Love's logarithms by terms in u or v alone, which cancel in the corner sum, and
//! it loses no digits where the logarithms subtract). The coefficients depend only on the node
//! offset, so the deflection of all nodes is a discrete convolution, done in O(N log N) by a 2D
//! FFT on a grid padded to twice the size (no wrap-around: Hockney's zero padding). The FFT is
//! `rustfft` (maintained, pure Rust, any length; the grid sizes 2(2ⁿ + 1) are not powers of
//! two).

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// ∬ 1/√(u² + v²) du dv antiderivative in the asinh form (0 on the axes).
fn love_antiderivative(u: f64, v: f64) -> f64 {
    let mut g = 0.0;
    if u != 0.0 {
        g += u * (v / u.abs()).asinh();
    }
    if v != 0.0 {
        g += v * (u / v.abs()).asinh();
    }
    g
}

/// ∬ over the rectangle |u′ − u| ≤ ℓ_x, |v′ − v| ≤ ℓ_y of 1/√(u′² + v′²) (Love 1929).
pub fn rectangle_influence(u: f64, v: f64, half_x: f64, half_y: f64) -> f64 {
    love_antiderivative(u + half_x, v + half_y)
        - love_antiderivative(u - half_x, v + half_y)
        - love_antiderivative(u + half_x, v - half_y)
        + love_antiderivative(u - half_x, v - half_y)
}

/// The deflection operator of one uniform grid: nx × ny nodes, spacings (dx, dy) in units of
/// the rolling semi-axis b, times a scale factor (the film units).
pub struct Deflection {
    nx: usize,
    ny: usize,
    /// Padded sizes (2nx, 2ny).
    mx: usize,
    my: usize,
    /// Coefficient of an offset (di, dj), row-major over dj ∈ [0, ny), di ∈ [0, nx) (symmetric
    /// in the sign of either offset).
    coefficients: Vec<f64>,
    /// FFT of the padded kernel, scaled by 1/(mx·my).
    kernel_spectrum: Vec<Complex<f64>>,
    fft_x: Arc<dyn Fft<f64>>,
    ifft_x: Arc<dyn Fft<f64>>,
    fft_y: Arc<dyn Fft<f64>>,
    ifft_y: Arc<dyn Fft<f64>>,
    buffer: Vec<Complex<f64>>,
    column: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Deflection {
    /// Operator for nx × ny nodes with spacings dx, dy (both in units of b) and the factor
    /// `scale` applied to every coefficient.
    pub fn new(nx: usize, ny: usize, dx: f64, dy: f64, scale: f64) -> Self {
        let (mx, my) = (2 * nx, 2 * ny);
        let mut coefficients = vec![0.0; nx * ny];
        for dj in 0..ny {
            for di in 0..nx {
                coefficients[dj * nx + di] =
                    scale * rectangle_influence(di as f64 * dx, dj as f64 * dy, dx / 2.0, dy / 2.0);
            }
        }
        let mut planner = FftPlanner::new();
        let fft_x = planner.plan_fft_forward(mx);
        let ifft_x = planner.plan_fft_inverse(mx);
        let fft_y = planner.plan_fft_forward(my);
        let ifft_y = planner.plan_fft_inverse(my);
        let scratch_len = [&fft_x, &ifft_x, &fft_y, &ifft_y]
            .iter()
            .map(|f| f.get_inplace_scratch_len())
            .max()
            .unwrap_or(0);
        let mut op = Self {
            nx,
            ny,
            mx,
            my,
            coefficients,
            kernel_spectrum: Vec::new(),
            fft_x,
            ifft_x,
            fft_y,
            ifft_y,
            buffer: vec![Complex::new(0.0, 0.0); mx * my],
            column: vec![Complex::new(0.0, 0.0); my],
            scratch: vec![Complex::new(0.0, 0.0); scratch_len],
        };
        // Wrapped kernel: offset −d sits at index m − d.
        let norm = 1.0 / (mx * my) as f64;
        let mut kernel = vec![Complex::new(0.0, 0.0); mx * my];
        for dj in 0..ny {
            for di in 0..nx {
                let c = Complex::new(op.coefficients[dj * nx + di] * norm, 0.0);
                let cols = [di, (mx - di) % mx];
                let rows = [dj, (my - dj) % my];
                for &r in &rows {
                    for &q in &cols {
                        kernel[r * mx + q] = c;
                    }
                }
            }
        }
        op.transform(&mut kernel, true);
        op.kernel_spectrum = kernel;
        op
    }

    /// Coefficient of the node offset (di, dj).
    #[inline]
    pub fn coefficient(&self, di: isize, dj: isize) -> f64 {
        let (i, j) = (di.unsigned_abs(), dj.unsigned_abs());
        if i >= self.nx || j >= self.ny {
            return 0.0;
        }
        self.coefficients[j * self.nx + i]
    }

    fn transform(&mut self, data: &mut [Complex<f64>], forward: bool) {
        let (fx, fy) = if forward {
            (&self.fft_x, &self.fft_y)
        } else {
            (&self.ifft_x, &self.ifft_y)
        };
        for row in data.chunks_mut(self.mx) {
            fx.process_with_scratch(row, &mut self.scratch);
        }
        for q in 0..self.mx {
            for r in 0..self.my {
                self.column[r] = data[r * self.mx + q];
            }
            fy.process_with_scratch(&mut self.column, &mut self.scratch);
            for r in 0..self.my {
                data[r * self.mx + q] = self.column[r];
            }
        }
    }

    /// deflection[j·nx + i] = Σ_kl K(i − k, j − l) pressure[l·nx + k] for all nodes.
    pub fn apply(&mut self, pressure: &[f64], deflection: &mut [f64]) {
        let (nx, ny, mx) = (self.nx, self.ny, self.mx);
        let mut buffer = std::mem::take(&mut self.buffer);
        buffer.iter_mut().for_each(|c| *c = Complex::new(0.0, 0.0));
        for j in 0..ny {
            for i in 0..nx {
                buffer[j * mx + i] = Complex::new(pressure[j * nx + i], 0.0);
            }
        }
        self.transform(&mut buffer, true);
        for (b, k) in buffer.iter_mut().zip(&self.kernel_spectrum) {
            *b *= *k;
        }
        self.transform(&mut buffer, false);
        for j in 0..ny {
            for i in 0..nx {
                deflection[j * nx + i] = buffer[j * mx + i].re;
            }
        }
        self.buffer = buffer;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The FFT convolution equals the direct sum over all node pairs.
    #[test]
    fn fft_equals_direct_sum() {
        let (nx, ny) = (9, 7);
        let mut op = Deflection::new(nx, ny, 0.3, 0.5, 0.7);
        let p: Vec<f64> = (0..nx * ny).map(|n| ((n * 37 % 11) as f64).sin()).collect();
        let mut d = vec![0.0; nx * ny];
        op.apply(&p, &mut d);
        for j in 0..ny {
            for i in 0..nx {
                let mut direct = 0.0;
                for l in 0..ny {
                    for k in 0..nx {
                        direct += op.coefficient(i as isize - k as isize, j as isize - l as isize)
                            * p[l * nx + k];
                    }
                }
                assert!((d[j * nx + i] - direct).abs() < 1e-12, "{i},{j}");
            }
        }
    }

    /// A uniform pressure on a square of side 2s gives at its centre ∬ 1/r = 8 s asinh(1)
    /// (closed form of the integral over the square), and far away the point-load value
    /// (2s)²/r.
    #[test]
    fn love_coefficient_limits() {
        let s = 0.7;
        let centre = rectangle_influence(0.0, 0.0, s, s);
        assert!((centre - 8.0 * s * 1f64.asinh()).abs() < 1e-14);
        let far = rectangle_influence(300.0, 400.0, s, s);
        assert!((far / (4.0 * s * s / 500.0) - 1.0).abs() < 1e-5);
    }

    /// Hertz: the pressure √(1 − r²) on a unit circle deflects the surface by (π²/4)(2 − r²)
    /// per unit of the 1/r integral inside the circle (Johnson §3.9, eq. 3.41 with
    /// ∬ p/r = π²p₀(2a² − r²)/(4a)), so the film X²/2 + Y²/2 + (2/π²)∬P/r is flat there.
    #[test]
    fn hertz_pressure_gives_flat_film() {
        let n = 161;
        let h = 4.0 / (n - 1) as f64;
        let mut op = Deflection::new(n, n, h, h, 2.0 / (PI * PI));
        let coord = |i: usize| -2.0 + h * i as f64;
        let p: Vec<f64> = (0..n * n)
            .map(|m| {
                let (x, y) = (coord(m % n), coord(m / n));
                (1.0 - x * x - y * y).max(0.0).sqrt()
            })
            .collect();
        let mut d = vec![0.0; n * n];
        op.apply(&p, &mut d);
        let film = |i: usize, j: usize| {
            let (x, y) = (coord(i), coord(j));
            0.5 * (x * x + y * y) + d[j * n + i]
        };
        let centre = film(n / 2, n / 2);
        // Exact centre value: (2/π²)(π²/4)·2 = 1.
        assert!((centre - 1.0).abs() < 5e-3, "{centre}");
        for (i, j) in [
            (n / 2 + 10, n / 2),
            (n / 2 + 20, n / 2 + 20),
            (n / 2, n / 2 - 30),
        ] {
            assert!(
                (film(i, j) - centre).abs() < 5e-3,
                "{i},{j}: {}",
                film(i, j)
            );
        }
    }
}
