//! Non-uniform 1-D grid over the dimensionless coordinate X = x/b.
//!
//! The outlet pressure spike of a heavily loaded contact is a few hundredths of b wide, and
//! docs/physics.md §5.2 asks for ΔX ≲ 0.005 there; a uniform grid that fine over X ∈ [−4.5, 1.5]
//! would need 1200 nodes and a dense Newton solve would cost 64× more. The grid is therefore
//! the image of a uniform parameter s ∈ [0, 1] under X(s), where dX/ds ∝ 1/ψ(X) and the node
//! density ψ is a smooth sum of three plateaus: a coarse inlet/outlet, a finer Hertzian zone and
//! a fine band around the outlet constriction (where the spike and the minimum film sit for every
//! case of the docs/physics.md §5.3 domain). Because the map is fixed, doubling the number of
//! intervals halves every spacing — the grid family needed for Richardson extrapolation.

/// Shape of the node density (all in units of the Hertz half-width b).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GridSpec {
    /// Inlet end of the domain (fully flooded: −4.5 by default, docs/physics.md §5.2).
    pub x_start: f64,
    /// Outlet end of the domain (1.5 by default).
    pub x_end: f64,
    /// Number of intervals (nodes − 1).
    pub intervals: usize,
    /// Relative node density of the Hertzian zone [−1.4, 1.3] over the inlet/outlet density.
    pub contact_density: f64,
    /// Relative node density of the outlet band [0.35, 1.12] over the inlet/outlet density.
    pub outlet_density: f64,
    /// Extra node density added in two bands at the edges of the Hertzian contact,
    /// [−1 − w, −1 + w] (inlet meniscus) and [1 − 2w, 1 + w] (outlet constriction), with
    /// w = `edge_width`; 0 for the standard family. Thin films (large M) need it: the inlet
    /// pressure build-up and the outlet constriction then shrink to a width of order H_c^⅔
    /// (the Hertzian gap opens as (|X| − 1)^{3/2} outside the contact).
    pub edge_density: f64,
    /// Half-width w of the edge bands (units of b).
    pub edge_width: f64,
}

impl GridSpec {
    /// The default family with the given number of intervals.
    pub fn with_intervals(intervals: usize) -> Self {
        Self {
            x_start: -4.5,
            x_end: 1.5,
            intervals,
            contact_density: 4.0,
            outlet_density: 14.0,
            edge_density: 0.0,
            edge_width: 0.05,
        }
    }

    /// The thin-film family (see [`GridSpec::edge_density`]): the standard densities plus
    /// edge bands of density 40 and half-width 0.05 b.
    pub fn thin_film(intervals: usize) -> Self {
        Self {
            edge_density: 40.0,
            ..Self::with_intervals(intervals)
        }
    }
}

/// Smooth indicator of [a, b] with transition width w.
fn smooth_box(x: f64, a: f64, b: f64, w: f64) -> f64 {
    0.5 * (((x - a) / w).tanh() - ((x - b) / w).tanh())
}

fn density(spec: &GridSpec, x: f64) -> f64 {
    let w = spec.edge_width;
    let edges = if spec.edge_density > 0.0 {
        spec.edge_density
            * (smooth_box(x, -1.0 - w, -1.0 + w, 0.25 * w)
                + smooth_box(x, 1.0 - 2.0 * w, 1.0 + w, 0.25 * w))
    } else {
        0.0
    };
    1.0 + (spec.contact_density - 1.0) * smooth_box(x, -1.4, 1.3, 0.15)
        + (spec.outlet_density - spec.contact_density) * smooth_box(x, 0.35, 1.12, 0.05)
        + edges
}

/// Node coordinates X_0 < … < X_n for `spec` (n = intervals).
pub fn build_nodes(spec: &GridSpec) -> Vec<f64> {
    // Cumulative density on a fine uniform sampling, inverted by linear interpolation.
    const SAMPLES: usize = 60_000;
    let (a, b) = (spec.x_start, spec.x_end);
    let dx = (b - a) / SAMPLES as f64;
    let mut cum = Vec::with_capacity(SAMPLES + 1);
    cum.push(0.0);
    let mut acc = 0.0;
    let mut prev = density(spec, a);
    for k in 1..=SAMPLES {
        let d = density(spec, a + dx * k as f64);
        acc += 0.5 * (prev + d) * dx;
        prev = d;
        cum.push(acc);
    }
    let n = spec.intervals;
    let mut nodes = Vec::with_capacity(n + 1);
    let mut k = 0usize;
    for i in 0..=n {
        let target = acc * i as f64 / n as f64;
        while k + 1 < SAMPLES && cum[k + 1] < target {
            k += 1;
        }
        let seg = cum[k + 1] - cum[k];
        let t = if seg > 0.0 {
            ((target - cum[k]) / seg).clamp(0.0, 1.0)
        } else {
            0.0
        };
        nodes.push(a + dx * (k as f64 + t));
    }
    nodes[0] = a;
    nodes[n] = b;
    nodes
}

/// Trapezoid quadrature weights on the nodes (exact for the piecewise-linear pressure the
/// deflection kernel assumes).
pub fn trapezoid_weights(nodes: &[f64]) -> Vec<f64> {
    let n = nodes.len();
    let mut w = vec![0.0; n];
    for e in 0..n.saturating_sub(1) {
        let half = 0.5 * (nodes[e + 1] - nodes[e]);
        w[e] += half;
        w[e + 1] += half;
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Refining the family halves every spacing (the property Richardson extrapolation needs),
    /// and the outlet band meets docs/physics.md §5.2's ΔX ≲ 0.005 at the default 400 intervals.
    #[test]
    fn nested_refinement_and_outlet_spacing() {
        let coarse = build_nodes(&GridSpec::with_intervals(200));
        let fine = build_nodes(&GridSpec::with_intervals(400));
        for (i, x) in coarse.iter().enumerate() {
            assert!((fine[2 * i] - x).abs() < 1e-6, "node {i}");
        }
        let max_outlet = fine
            .windows(2)
            .filter(|w| w[0] > 0.5 && w[1] < 1.05)
            .map(|w| w[1] - w[0])
            .fold(0.0, f64::max);
        assert!(max_outlet < 0.005, "outlet spacing {max_outlet}");
    }

    /// The thin-film family is nested too, and at 800 intervals resolves both contact edges
    /// (|X ± 1| ≤ 0.03) with ΔX ≤ 0.001 — a fifth of the H_c^⅔ ≈ 0.005 width of the inlet
    /// meniscus at M = 1000, L = 1 (H_c ≈ 3.7·10⁻⁴).
    #[test]
    fn thin_film_family_resolves_contact_edges() {
        let coarse = build_nodes(&GridSpec::thin_film(400));
        let fine = build_nodes(&GridSpec::thin_film(800));
        for (i, x) in coarse.iter().enumerate() {
            assert!((fine[2 * i] - x).abs() < 1e-6, "node {i}");
        }
        for edge in [-1.0, 1.0] {
            let max_edge = fine
                .windows(2)
                .filter(|w| (w[0] - edge).abs() <= 0.03 && (w[1] - edge).abs() <= 0.03)
                .map(|w| w[1] - w[0])
                .fold(0.0, f64::max);
            assert!(
                max_edge > 0.0 && max_edge < 0.001,
                "edge {edge}: {max_edge}"
            );
        }
    }
}
