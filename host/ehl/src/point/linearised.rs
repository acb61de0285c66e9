//! The exact Jacobian of the discrete point-contact equations (`level`) applied to a vector
//! without forming it: the Newton operator that GMRES solves with, the windowed sparse
//! Jacobian of `level` serving only as its preconditioner.
//!
//! Unknowns: the interior pressures P_u and the rigid-body separation H₀ (last entry).
//! Rows: the linearised Reynolds residual of every free node, the identity for a node held at
//! P = 0 by the active set, and the load balance ΔX ΔY Σ δP_u. The film change of a pressure
//! change δP is δH = K δP + δH₀ (K the deflection convolution, one FFT pair), and from it
//! δε_q = (∂ε/∂P)_q δP_q + 3ε_q/H_q δH_q and δ(ρ̄H)_q = (dρ̄/dP)_q H_q δP_q + ρ̄_q δH_q, which
//! enter the face-averaged Poiseuille terms and the upwind wedge exactly as in the residual.

use super::deflection::Deflection;

/// The state the Jacobian is taken at (borrowed from the level).
pub(super) struct Linearisation<'a> {
    pub nx: usize,
    pub ny: usize,
    pub dx: f64,
    pub dy: f64,
    /// 1/ΔX² and k⁻²/ΔY².
    pub wx: f64,
    pub wy: f64,
    pub elastic: bool,
    pub p: &'a [f64],
    pub h: &'a [f64],
    pub eps: &'a [f64],
    pub deps: &'a [f64],
    pub rho: &'a [f64],
    pub drho: &'a [f64],
    /// Per unknown: held at P = 0 by the active set.
    pub active: &'a [bool],
}

/// Node-sized buffers of the product.
pub(super) struct ProductBuffers {
    delta: Vec<f64>,
    film: Vec<f64>,
    d_eps: Vec<f64>,
    d_rho_h: Vec<f64>,
}

impl ProductBuffers {
    pub fn new(nodes: usize) -> Self {
        Self {
            delta: vec![0.0; nodes],
            film: vec![0.0; nodes],
            d_eps: vec![0.0; nodes],
            d_rho_h: vec![0.0; nodes],
        }
    }
}

impl Linearisation<'_> {
    /// out = J v for v = (δP_u, δH₀) (length unknowns + 1).
    pub fn apply(
        &self,
        deflection: &mut Deflection,
        buffers: &mut ProductBuffers,
        v: &[f64],
        out: &mut [f64],
    ) {
        let (nx, ny) = (self.nx, self.ny);
        let ix = nx - 2;
        let unknowns = v.len() - 1;
        let delta_h0 = v[unknowns];
        let node = |u: usize| (u / ix + 1) * nx + u % ix + 1;
        for (u, &dv) in v[..unknowns].iter().enumerate() {
            buffers.delta[node(u)] = dv;
        }
        if self.elastic {
            deflection.apply(&buffers.delta, &mut buffers.film);
        } else {
            buffers.film.iter_mut().for_each(|d| *d = 0.0);
        }
        for q in 0..nx * ny {
            let dh = buffers.film[q] + delta_h0;
            let dp = buffers.delta[q];
            let film_term = if self.h[q] > 0.0 {
                3.0 * self.eps[q] / self.h[q] * dh
            } else {
                0.0
            };
            buffers.d_eps[q] = self.deps[q] * dp + film_term;
            buffers.d_rho_h[q] = self.drho[q] * self.h[q] * dp + self.rho[q] * dh;
        }
        let (wx, wy) = (self.wx, self.wy);
        let (dp, de, drh) = (&buffers.delta, &buffers.d_eps, &buffers.d_rho_h);
        for u in 0..unknowns {
            if self.active[u] {
                out[u] = v[u];
                continue;
            }
            let m = node(u);
            let i = u % ix + 1;
            let (e, w, n, s) = (m + 1, m - 1, m + nx, m - nx);
            let (eps, p) = (self.eps, self.p);
            let face = |q: usize| 0.5 * (eps[m] + eps[q]);
            let dface = |q: usize| 0.5 * (de[m] + de[q]);
            // Product rule on ε_face (P_q − P_m).
            let flux = |q: usize, weight: f64| {
                weight * (face(q) * (dp[q] - dp[m]) + dface(q) * (p[q] - p[m]))
            };
            let flow = flux(e, wx) + flux(w, wx) + flux(n, wy) + flux(s, wy);
            let wedge = if i >= 2 {
                (3.0 * drh[m] - 4.0 * drh[w] + drh[w - 1]) / (2.0 * self.dx)
            } else {
                (drh[m] - drh[w]) / self.dx
            };
            out[u] = flow - wedge;
        }
        out[unknowns] = self.dx * self.dy * v[..unknowns].iter().sum::<f64>();
    }
}
