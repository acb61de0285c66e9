#!/usr/bin/env python3
"""How well a table interpolated over approach and tilt stands in for the slice pass.

The hub-motor roller (l = 15 mm, D = 8.8 mm, ISO logarithmic crown, 10 slices, Palmgren's law
per slice: `core/src/contact/slicing.rs`) is tabulated over u = δ − δ_touch(|ψ|) (the approach
past the first slice's touch) and |ψ| ≤ 0.02 rad (the slice pass's tilt range), both on grids
dense near zero (node i at u_max·(i/(N−1))², likewise in ψ), with Q and K = dQ/dδ at every node:
cubic Hermite in u, linear in ψ, the moment odd in ψ. It is compared with the slice pass, in
f64, on random approaches 0.3–30 µm (Q), and on the bearing force of 17 such rollers (clearance
−2 µm, displacements 0–20 µm in any direction, every roller at tilt ψ):
|ΔF|/max(|F|, mean roller load), the normalisation of `hil-sim replay`'s force verdict.

A grid whose nodes include the untilted roller's touch points (one per slice pair) is shown
too: there the slices' loads start (Q ∝ (δ − δ_k)^(10/9) for each newly touching slice, whose
second derivative is unbounded), which interpolation between nodes cannot follow; with tilt
those points move with ψ and no fixed grid holds them.

    python3 hil-sim/tools/roller_table_error.py
"""

import numpy as np

LENGTH, DIAMETER, SLICES, ROLLERS, CLEARANCE = 0.015, 0.0088, 10, 17, -2.0e-6
X = (np.arange(SLICES) + 0.5) * LENGTH / SLICES - LENGTH / 2
R = 2 * X / LENGTH
CROWN = 2 * 0.00035 * DIAMETER * -np.log(np.maximum(1 - R * R, 1e-6))  # 2P(x_k), m
U_MAX, TILT_MAX = 100e-6, 0.02


def slices(d, psi):
    """Q, K, T, dT/dδ of the slice pass (Palmgren, unit coefficient), of arrays d, psi."""
    a = np.maximum(d[..., None] + X * psi[..., None] - CROWN, 0.0)
    w, k = a ** (10 / 9), (10 / 9) * a ** (1 / 9)
    return w.sum(-1), k.sum(-1), (w * X).sum(-1), (k * X).sum(-1)


def touch(psi):
    return np.min(CROWN[None, :] - X[None, :] * np.abs(psi)[:, None], axis=1)


def hermite(p0, m0, p1, m1, s, h):
    s2, s3 = s * s, s * s * s
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 \
        + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * m1


class Table:
    def __init__(self, u_nodes, tilt_nodes):
        self.u, self.psi = u_nodes, tilt_nodes
        self.touch = touch(tilt_nodes)
        d = u_nodes[None, :] + self.touch[:, None]
        psi = np.repeat(tilt_nodes[:, None], len(u_nodes), 1)
        self.q, self.k, self.t, self.kx = slices(d, psi)

    def load(self, d, psi):
        a = np.abs(psi)
        j = np.clip(np.searchsorted(self.psi, a) - 1, 0, len(self.psi) - 2)
        w = (a - self.psi[j]) / (self.psi[j + 1] - self.psi[j])
        u = np.maximum(d - (self.touch[j] * (1 - w) + self.touch[j + 1] * w), 0)
        i = np.clip(np.searchsorted(self.u, u) - 1, 0, len(self.u) - 2)
        h = self.u[i + 1] - self.u[i]
        s = (u - self.u[i]) / h
        rows = [hermite(self.q[r, i], self.k[r, i], self.q[r, i + 1], self.k[r, i + 1], s, h)
                for r in (j, j + 1)]
        return rows[0] * (1 - w) + rows[1] * w


def squared_grid(n, top):
    return top * (np.arange(n) / (n - 1)) ** 2


def touch_aligned_grid(per_segment, last_segment, top):
    points = np.unique(np.round(CROWN - CROWN.min(), 12))
    ends = list(points) + [top]
    nodes = []
    for s in range(len(ends) - 1):
        m = last_segment if s == len(ends) - 2 else per_segment
        nodes += list(ends[s] + (ends[s + 1] - ends[s]) * (np.arange(m) / m) ** 2)
    return np.array(nodes + [top])


def main():
    rng = np.random.default_rng(3)
    d = rng.uniform(0.3e-6, 30e-6, 200_000)
    e = rng.uniform(0, 20e-6, 20_000)
    phase = rng.uniform(0, 2 * np.pi, 20_000)
    theta = 2 * np.pi * np.arange(ROLLERS) / ROLLERS
    approach = e[:, None] * np.cos(theta[None, :] - phase[:, None]) - CLEARANCE
    tilt_nodes = squared_grid(17, TILT_MAX)
    grids = [(f"squared, {n} nodes", squared_grid(n, U_MAX)) for n in (48, 96)]
    grids.append(("touch points as nodes, 81 nodes", touch_aligned_grid(12, 32, U_MAX)))
    print("| u grid (17 tilt nodes) | tilt ψ (rad) | Q: p99, max of |ΔQ|/Q "
          "| force: p99, max of |ΔF|/max(|F|, mean Q) |")
    print("|---|---|---|---|")
    for name, u_nodes in grids:
        table = Table(u_nodes, tilt_nodes)
        for psi in (0.0, 1e-4, 1e-3):
            tilt = np.full_like(d, psi)
            q_ref = slices(d, tilt)[0]
            dq = np.abs(table.load(d, tilt) - q_ref) / q_ref
            flat = approach.ravel()
            tilt_all = np.full_like(flat, psi)
            q_slices = slices(flat, tilt_all)[0].reshape(approach.shape)
            q_table = table.load(flat, tilt_all).reshape(approach.shape)
            force = lambda q: np.stack([(q * np.cos(theta)).sum(1),
                                        (q * np.sin(theta)).sum(1)], 1)
            f_ref = force(q_slices)
            scale = np.maximum(np.linalg.norm(f_ref, axis=1), q_slices.mean(1))
            df = np.linalg.norm(force(q_table) - f_ref, axis=1) / scale
            print(f"| {name} | {psi:g} | {np.percentile(dq, 99):.1e}, {dq.max():.1e} "
                  f"| {np.percentile(df, 99):.1e}, {df.max():.1e} |")


if __name__ == "__main__":
    main()
