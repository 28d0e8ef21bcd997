#!/usr/bin/env python3
"""Is the points' strain in their positions? (docs/paper-b.md, "The elastic lattice's permanent set")

  strain_compatibility.py RUN_DIR [--spacing 0.5] [--E 113.8e9] [--nu 0.342]

Reads the run's checkpoint (RUN_DIR/checkpoint.h5: every point's deformation gradient F and
position; a run writes one with `--set checkpoint.every_steps=N`) and its first snapshot (the
points' start X, in their original order; the checkpoint's `id` is that order). For every
point with a full neighbourhood (the 26 points of its 3x3x3 block at the voxelizer's spacing
s: reference distance < 1.8 s), G = the least-squares gradient of its neighbours' positions,
argmin sum |(x_j - x_i) - G (X_j - X_i)|^2 = (sum dx dX^T)(sum dX dX^T)^-1: the deformation
the points' positions show. Prints, over these interior points, the mean Green-strain norms
|E(F)| and |E(G)|, the mean |F - G|, the mean norm of E(F) averaged over each point's block
(what survives smoothing at one point spacing: the rest oscillates from point to point), and
the neo-Hookean energies sum V0 psi(F) and sum V0 psi(G) (the solver's energy, neo_hookean.hpp;
E and nu of the scene). An elastic body unloaded and at rest has E(F) = E(G) = 0; a
strain that F holds and G does not is not in the positions: the grid cannot see it either
(docs/paper-b.md).

Standard library only; reads HDF5 with h5dump through pipelines/metal-lattice/lattice_height.py."""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "pipelines", "metal-lattice"))
from lattice_height import dataset, snapshots  # noqa: E402


def det(a):
    return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))


def inverse(a):
    d = det(a)
    return [[(a[(j + 1) % 3][(i + 1) % 3] * a[(j + 2) % 3][(i + 2) % 3]
              - a[(j + 1) % 3][(i + 2) % 3] * a[(j + 2) % 3][(i + 1) % 3]) / d for j in range(3)] for i in range(3)]


def product(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def green(f):
    """E = (F^T F - I) / 2."""
    return [[0.5 * (sum(f[k][i] * f[k][j] for k in range(3)) - (i == j)) for j in range(3)] for i in range(3)]


def norm(a):
    return math.sqrt(sum(v * v for row in a for v in row))


def neo_hookean_density(f, mu, lam):
    """psi = mu/2 (tr b - 3) - mu ln J + lam/2 (ln J)^2 (neo_hookean.hpp)."""
    j = det(f)
    trace_b = sum(f[i][k] ** 2 for i in range(3) for k in range(3))
    return 0.5 * mu * (trace_b - 3) - mu * math.log(j) + 0.5 * lam * math.log(j) ** 2


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("--spacing", type=float, default=0.5, help="the points' spacing at the start (mm; cell / ppc)")
    p.add_argument("--E", type=float, default=113.8e9, help="Young's modulus (Pa), the scene's")
    p.add_argument("--nu", type=float, default=0.342)
    a = p.parse_args()
    checkpoint = os.path.join(a.run, "checkpoint.h5")
    snaps = snapshots(a.run)
    if not snaps or not os.path.exists(checkpoint):
        sys.exit(f"strain_compatibility.py: {a.run}: needs snapshots/snap_*.h5 and checkpoint.h5")
    mu = a.E / (2 * (1 + a.nu))
    lam = a.E * a.nu / ((1 + a.nu) * (1 - 2 * a.nu))
    x0 = dataset(snaps[0], "/particles/position", 3)
    n = len(x0)
    x, f, v0 = [None] * n, [None] * n, [0.0] * n
    for i, xi, fi, vi in zip(dataset(checkpoint, "/state/particles/id", 1),
                             dataset(checkpoint, "/state/particles/position", 3),
                             dataset(checkpoint, "/state/particles/deformation", 9),
                             dataset(checkpoint, "/state/particles/volume0", 1)):
        i = int(i)
        x[i], v0[i] = xi, vi
        f[i] = [[fi[0], fi[3], fi[6]], [fi[1], fi[4], fi[7]], [fi[2], fi[5], fi[8]]]  # column-major
    radius = 1.8 * a.spacing * 1e-3
    cells = {}
    for i, p0 in enumerate(x0):
        cells.setdefault(tuple(int(math.floor(c / radius)) for c in p0), []).append(i)
    count, ef, eg, fg, smooth, energy_f, energy_g = 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    for i, p0 in enumerate(x0):
        key = tuple(int(math.floor(c / radius)) for c in p0)
        block = [j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                 for j in cells.get((key[0] + dx, key[1] + dy, key[2] + dz), ())
                 if j != i and sum((x0[j][k] - p0[k]) ** 2 for k in range(3)) < radius * radius]
        if len(block) < 26:
            continue  # a surface point: its one-sided gradient is not comparable
        moment = [[0.0] * 3 for _ in range(3)]
        cross = [[0.0] * 3 for _ in range(3)]
        for j in block:
            dX = [x0[j][k] - p0[k] for k in range(3)]
            dx = [x[j][k] - x[i][k] for k in range(3)]
            for r in range(3):
                for c in range(3):
                    moment[r][c] += dX[r] * dX[c]
                    cross[r][c] += dx[r] * dX[c]
        g = product(cross, inverse(moment))
        e_i = green(f[i])
        mean = [[sum(green(f[j])[r][c] for j in block + [i]) / (len(block) + 1) for c in range(3)] for r in range(3)]
        count += 1
        ef += norm(e_i)
        eg += norm(green(g))
        fg += norm([[f[i][r][c] - g[r][c] for c in range(3)] for r in range(3)])
        smooth += norm(mean)
        energy_f += v0[i] * neo_hookean_density(f[i], mu, lam)
        energy_g += v0[i] * neo_hookean_density(g, mu, lam)
    if not count:
        sys.exit(f"strain_compatibility.py: {a.run}: no point has 26 neighbours at spacing {a.spacing} mm")
    t = dataset(checkpoint, "/state/solver/time", 1)[0] * 1e6
    print(f"{a.run}: checkpoint at t = {t:.1f} us, {n} points; {count} interior points (26 neighbours at "
          f"{a.spacing} mm)")
    print(f"  mean |E(F)| {ef / count:.3e}   mean |E(G)| {eg / count:.3e}   mean |F - G| {fg / count:.3e}   "
          f"mean |E(F) averaged over the block| {smooth / count:.3e}")
    print(f"  energy of F {energy_f:.4g} J   energy of G {energy_g:.4g} J (interior points)")


if __name__ == "__main__":
    main()
