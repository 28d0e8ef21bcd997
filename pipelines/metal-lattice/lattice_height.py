"""The lattice's own height in a load-unload run's snapshots (make metal-lattice; docs/paper-b.md,
"The recovery check"), independent of the platen: the mean vertical displacement of the points
that started in the top layer (within `layer` of the highest point) less that of the points
that started in the bottom layer. A rigid lift (the released lattice flying off the base)
moves both layers alike and leaves the height unchanged.

Standard library only: the snapshots are read with h5dump (hdf5-tools, scripts/install-deps.sh).
Points are in their original order in every snapshot (docs/formats.md), so the first snapshot
gives every point's start."""
import glob
import os
import subprocess
import tempfile


def dataset(path, name, width):
    """The dataset `name` of the HDF5 file `path`: a list of floats, or of `width`-tuples."""
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as out:
        subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", "-o", out.name, path], check=True,
                       capture_output=True)
        values = [float(t) for t in out.read().replace(",", " ").split()]
    return [tuple(values[i:i + width]) for i in range(0, len(values), width)] if width > 1 else values


def snapshot_time(path):
    """The simulated time (s) of a snapshot file."""
    text = subprocess.run(["h5dump", "-a", "/particles/time", path], capture_output=True, text=True).stdout
    line = next((l for l in text.splitlines() if "(0)" in l), "")
    return float(line.split(":")[-1]) if line else float("nan")


def snapshots(run):
    """A run's snapshot files in step order (the first is the start)."""
    return sorted(glob.glob(os.path.join(run, "snapshots", "snap_*.h5")))


def layers(x0, layer=1e-3):
    """Indices of the points that start within `layer` (m) of the top and of the bottom."""
    z0 = [p[2] for p in x0]
    top, bottom = max(z0), min(z0)
    return ([i for i, z in enumerate(z0) if z > top - layer],
            [i for i, z in enumerate(z0) if z < bottom + layer])


def height_change(x0, x, top, bottom):
    """(top layer's mean rise, bottom layer's mean rise, their difference: the height change), m."""
    up = sum(x[i][2] - x0[i][2] for i in top) / len(top)
    down = sum(x[i][2] - x0[i][2] for i in bottom) / len(bottom)
    return up, down, up - down


def final_height_change(run):
    """The lattice's height change between a run's first and last snapshots: a dict with the
    last snapshot's time (s) and the layers' rises and height change (m); None without two
    snapshots."""
    return rest_height_change(run, float("inf"))


def rest_height_change(run, rest_from_s):
    """The lattice's height change at rest: over the snapshots at or after `rest_from_s` (s; the
    last snapshot always counts), the mean of the height change and its range, with the last
    snapshot's values (its time, the layers' rises and height change, m; plus mean_change_m,
    min_change_m, max_change_m, rest_snapshots and rest_from_s); None without two snapshots. A
    released lattice rings in its first mode, so one snapshot's height is the mean plus a phase
    of that ringing."""
    snaps = snapshots(run)
    if len(snaps) < 2:
        return None
    x0 = dataset(snaps[0], "/particles/position", 3)
    top, bottom = layers(x0)
    timed = [(s, snapshot_time(s)) for s in snaps[1:]]
    chosen = [(s, t) for s, t in timed[:-1] if t >= rest_from_s] + [timed[-1]]
    changes = [height_change(x0, dataset(s, "/particles/position", 3), top, bottom) for s, _ in chosen]
    up, down, change = changes[-1]
    values = [c[2] for c in changes]
    return {"time_s": timed[-1][1], "top_m": up, "bottom_m": down, "change_m": change,
            "top_points": len(top), "bottom_points": len(bottom), "mean_change_m": sum(values) / len(values),
            "min_change_m": min(values), "max_change_m": max(values), "rest_snapshots": len(values),
            "rest_from_s": chosen[0][1]}
