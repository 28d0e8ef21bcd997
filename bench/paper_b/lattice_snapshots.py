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

Standard library only; reads the snapshots with h5dump (hdf5-tools, scripts/install-deps.sh)
through pipelines/metal-lattice/lattice_height.py (the recovery check's measure, residual.py)."""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "pipelines", "metal-lattice"))
from lattice_height import dataset, height_change, layers, snapshot_time, snapshots  # noqa: E402


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
    snaps = snapshots(a.run)
    if not snaps:
        sys.exit(f"lattice_snapshots.py: {a.run}/snapshots: no snap_*.h5")
    chosen = [snaps[int(k)] for k in a.snapshots.split(",")] if a.snapshots else snaps
    x0 = dataset(snaps[0], "/particles/position", 3)
    top, bottom = layers(x0)
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
            up, down, change = (v * 1e3 for v in height_change(x0, x, top, bottom))
            print(f"{os.path.basename(s)} t = {t:.1f} us: top ({len(top)} points) {up:+.3f} mm, bottom "
                  f"({len(bottom)}) {down:+.3f} mm, height change {change:+.3f} mm")


if __name__ == "__main__":
    main()
