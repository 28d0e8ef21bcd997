#!/usr/bin/env python3
"""What a load-unload lattice run's snapshots say (docs/paper-b.md, "make metal-lattice").

  lattice_snapshots.py proximity RUN_DIR [--near 1.2] [--far 2.5] [--snapshots 6,12,-1]
      per snapshot: pairs of points closer than --near (mm) now that were farther than --far
      (mm) apart at the start: distinct struts touching (single-field MPM would share their
      grid nodes). Points are in their original order in every snapshot (docs/formats.md).
  lattice_snapshots.py height RUN_DIR [--snapshots ...]
      per snapshot: the mean vertical displacement of the points within 1 mm of the start's
      top and bottom, and the height change (top - bottom): the lattice's own recovery,
      whether or not the platen still touches it.

Standard library only; reads the snapshots with h5dump (hdf5-tools, scripts/install-deps.sh)."""
import argparse
import glob
import math
import os
import subprocess
import sys
import tempfile


def dataset(path, name, width):
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as out:
        subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", "-o", out.name, path], check=True,
                       capture_output=True)
        values = [float(t) for t in out.read().replace(",", " ").split()]
    return [tuple(values[i:i + width]) for i in range(0, len(values), width)] if width > 1 else values


def snapshot_time(path):
    text = subprocess.run(["h5dump", "-a", "/particles/time", path], capture_output=True, text=True).stdout
    line = next((l for l in text.splitlines() if "(0)" in l), "")
    return float(line.split(":")[-1]) if line else float("nan")


def close_pairs(x, near):
    cells = {}
    for i, p in enumerate(x):
        cells.setdefault(tuple(int(math.floor(c / near)) for c in p), []).append(i)
    pairs = []
    for key, members in cells.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    other = cells.get((key[0] + dx, key[1] + dy, key[2] + dz))
                    for i in members:
                        for j in other or ():
                            if j > i and sum((x[i][a] - x[j][a]) ** 2 for a in range(3)) < near * near:
                                pairs.append((i, j))
    return pairs


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("what", choices=["proximity", "height"])
    p.add_argument("run")
    p.add_argument("--near", type=float, default=1.2, help="mm")
    p.add_argument("--far", type=float, default=2.5, help="mm")
    p.add_argument("--snapshots", default="", help="indices into the sorted snapshots (default: all)")
    a = p.parse_args()
    snaps = sorted(glob.glob(os.path.join(a.run, "snapshots", "snap_*.h5")))
    if not snaps:
        sys.exit(f"lattice_snapshots.py: {a.run}/snapshots: no snap_*.h5")
    chosen = [snaps[int(k)] for k in a.snapshots.split(",")] if a.snapshots else snaps
    x0 = dataset(snaps[0], "/particles/position", 3)
    z0 = [p[2] for p in x0]
    top = [i for i, z in enumerate(z0) if z > max(z0) - 1e-3]
    bottom = [i for i, z in enumerate(z0) if z < min(z0) + 1e-3]
    for s in chosen:
        x = dataset(s, "/particles/position", 3)
        t = snapshot_time(s) * 1e6
        if a.what == "proximity":
            far2 = (a.far * 1e-3) ** 2
            new = [(i, j) for i, j in close_pairs(x, a.near * 1e-3)
                   if sum((x0[i][k] - x0[j][k]) ** 2 for k in range(3)) > far2]
            points = {i for pair in new for i in pair}
            print(f"{os.path.basename(s)} t = {t:.1f} us: {len(new)} pairs closer than {a.near} mm that started "
                  f"farther than {a.far} mm apart ({len(points)} points)")
        else:
            up = sum(x[i][2] - x0[i][2] for i in top) / len(top) * 1e3
            down = sum(x[i][2] - x0[i][2] for i in bottom) / len(bottom) * 1e3
            print(f"{os.path.basename(s)} t = {t:.1f} us: top ({len(top)} points) {up:+.3f} mm, bottom "
                  f"({len(bottom)}) {down:+.3f} mm, height change {up - down:+.3f} mm")


if __name__ == "__main__":
    main()
