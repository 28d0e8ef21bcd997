#!/usr/bin/env python3
"""Residual deformation of load-unload runs (make metal-lattice; docs/paper-b.md).

For each run (its series.csv, snapshots and status.toml): the deepest platen travel u_max,
the peak platen force, the travel u_release where the platen's force returns to zero on
unloading (where the rising platen loses the lattice's top), the lattice's own height change
dh at rest (its first snapshot against those at rest: the points that started in the top
layer less those of the bottom layer, lattice_height.py; the residual deformation, whether or
not the platen still touches it, and whatever rigid lift the released lattice has), the
residual strain -dh / H0 and the recovered share (u_max + dh) / u_max, the energies at the
deepest point and at the end, and the cost. dh is the mean over the snapshots taken once the
platen has stopped (the last one always among them): the released lattice rings in its first
mode, and one snapshot's height is that mean plus a phase of the ringing. A run named by
--must-recover (an elastic run without friction) must recover: its height change must lie within `--recover` (a fraction
of u_max) of zero; the table says whether it does, and the script exits 1 when it does not.
u_release is not the check: the platen, rising at the schedule's speed, leaves the top while
the lattice still rises behind it (docs/paper-b.md, "The recovery check").

usage: residual.py --height H0_MM --out DIR [--recover 0.02] [--must-recover LABEL ...] LABEL=RUN_DIR ...
writes DIR/residual.csv and DIR/residual.md (standard library only)."""
import argparse
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_status import read_status  # noqa: E402
from lattice_height import rest_height_change  # noqa: E402


def joules(value):
    """A table's energy: three decimals, or a dash for a column the run's series lacks."""
    return "—" if math.isnan(value) else f"{value:.3f}"


def analyse(run):
    with open(os.path.join(run, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{run}/series.csv: no rows")
    col = lambda r, name: float(r[name])
    travel = [col(r, "displacement[m]") * 1e3 for r in rows]  # mm, along the loading axis (down)
    force = [col(r, "load_driven[N]") for r in rows]
    deepest = max(range(len(rows)), key=lambda i: travel[i])
    peak = max(force)
    # Unloading: the first row after the deepest point where the platen carries no force.
    release = next((i for i in range(deepest, len(rows)) if force[i] <= 1e-9 * peak), None)
    end = rows[-1]
    # At rest: from the last row where the platen still moved (its schedule has ended).
    moving = [i for i in range(1, len(rows)) if travel[i] != travel[i - 1]]
    rest_from = col(rows[moving[-1]], "time[s]") if moving else col(end, "time[s]")
    height = rest_height_change(run, rest_from)
    if height is None:
        raise ValueError("fewer than two snapshots: no lattice height")
    # The height is the end's: the solver writes a snapshot at the last step (docs/scene.md).
    if not abs(height["time_s"] - col(end, "time[s]")) <= 2 * col(end, "dt[s]"):  # NaN: unreadable time
        raise ValueError(f"the last snapshot (t = {height['time_s'] * 1e6:.1f} us) is not the series' end")
    # A run still going (no status.toml yet) is read as far as its series goes.
    s = read_status(run) if os.path.exists(os.path.join(run, "status.toml")) else {"status": "running"}
    return {
        "u_max_mm": travel[deepest],
        "peak_force_N": peak,
        "u_release_mm": travel[release] if release is not None else float("nan"),
        "released": release is not None,
        "height_change_mm": height["mean_change_m"] * 1e3,
        "height_change_end_mm": height["change_m"] * 1e3,
        "height_change_min_mm": height["min_change_m"] * 1e3,
        "height_change_max_mm": height["max_change_m"] * 1e3,
        "rest_snapshots": height["rest_snapshots"],
        "rest_from_us": height["rest_from_s"] * 1e6,
        "lift_mm": height["bottom_m"] * 1e3,
        "height_at_us": height["time_s"] * 1e6,
        "strain_energy_at_max_J": col(rows[deepest], "strain_energy[J]"),
        "plastic_at_max_J": col(rows[deepest], "plastic_dissipation[J]"),
        "work_at_max_J": col(rows[deepest], "external_work[J]"),
        "work_end_J": col(end, "external_work[J]"),
        "plastic_end_J": col(end, "plastic_dissipation[J]"),
        "strain_energy_end_J": col(end, "strain_energy[J]"),
        "friction_end_J": col(end, "friction_dissipation[J]"),
        "kinetic_end_J": col(end, "kinetic_energy[J]"),
        "blend_end_J": col(end, "blend_dissipation[J]"),
        # Series written before the column existed (docs/solver.md, "Energy") have none.
        "transfer_end_J": col(end, "transfer_dissipation[J]") if "transfer_dissipation[J]" in end else float("nan"),
        "energy_error_end_J": col(end, "energy_error[J]"),
        "t_end_us": col(end, "time[s]") * 1e6,
        "status": s.get("status", "?"),
        "steps": s.get("steps", "?"),
        "points": s.get("points", "?"),
        "cpu_s": float(s.get("cpu_s", "nan")),
        "wall_s": float(s.get("wall_s", "nan")),
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--height", type=float, required=True, help="the lattice's height H0 (mm)")
    p.add_argument("--out", required=True)
    p.add_argument("--recover", type=float, default=0.02,
                   help="an elastic run recovers when its height change |dh| <= this fraction of u_max (default 0.02)")
    p.add_argument("--must-recover", nargs="*", default=[], metavar="LABEL",
                   help="runs that must recover (elastic, frictionless)")
    p.add_argument("runs", nargs="+", help="LABEL=RUN_DIR")
    a = p.parse_args()
    results = []
    for item in a.runs:
        label, _, run = item.partition("=")
        if not run:
            sys.exit(f"residual.py: {item}: expected LABEL=RUN_DIR")
        try:
            results.append((label, analyse(run)))
        except (OSError, KeyError, ValueError, IndexError, ZeroDivisionError, subprocess.SubprocessError) as e:
            sys.exit(f"residual.py: {run}: {e}")
    os.makedirs(a.out, exist_ok=True)
    keys = list(results[0][1].keys())
    with open(os.path.join(a.out, "residual.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case"] + keys + ["residual_strain"])
        for label, r in results:
            w.writerow([label] + [r[k] for k in keys] + [-r["height_change_mm"] / a.height])
    lines = [
        "# Load-unload: residual deformation (residual.py)", "",
        f"Lattice height H0 = {a.height:g} mm. u_release: the platen's travel where its force returns to "
        "zero on unloading (where the rising platen leaves the lattice's top). dh: the lattice's own height "
        "change at rest (the mean rise of the points that started in its top layer less that of its bottom "
        "layer, averaged over the snapshots taken after the platen stopped, the last one included: the "
        "released lattice rings; their range and count beside it; lift: the bottom layer's rise at the end, "
        "the lattice flying off the base); residual strain -dh / H0; recovered (u_max + dh) / u_max; the recovery check "
        f"(--must-recover): |dh| <= {a.recover:.0%} of u_max. Energies in J at the end unless said: "
        "blend and transfer are the FLIP/PIC blend's and the transfer's numerical dissipation "
        "(docs/solver.md, \"Energy\"), the energy error is `energy_error` against the work in. "
        "CPU = the solver's user + system time.", "",
        "| case | u_max (mm) | peak force (N) | u_release (mm) | dh at rest (mm) [range, snapshots], lift (mm) | residual strain | "
        "recovered | elastic energy at u_max (of the work) | plastic | friction | blend | transfer | "
        "elastic left | kinetic | energy error of the work | status, steps, CPU (s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    failed = []
    for label, r in results:
        dh = r["height_change_mm"]
        rec = (r["u_max_mm"] + dh) / r["u_max_mm"] if r["u_max_mm"] > 0 else float("nan")
        verdict = ""
        if label in a.must_recover:
            ok = r["u_max_mm"] > 0 and abs(dh) <= a.recover * r["u_max_mm"]
            verdict = " (recovers)" if ok else f" (does NOT recover within {a.recover:.0%} of u_max)"
            if not ok:
                failed.append(label)
        share = r["strain_energy_at_max_J"] / r["work_at_max_J"] if r["work_at_max_J"] else float("nan")
        lines.append(
            f"| {label} | {r['u_max_mm']:.3f} | {r['peak_force_N']:.0f} | "
            + (f"{r['u_release_mm']:.3f}" if r["released"] else "never released")
            + f" | {dh:+.3f} [{r['height_change_min_mm']:+.3f} … {r['height_change_max_mm']:+.3f}, "
            f"{r['rest_snapshots']}], {r['lift_mm']:+.3f} | {-dh / a.height:.4f} | {rec:.1%}{verdict} | "
            f"{r['strain_energy_at_max_J']:.3f} ({share:.1%}) | {r['plastic_end_J']:.3f} | {r['friction_end_J']:.3f} | "
            f"{r['blend_end_J']:.3f} | {joules(r['transfer_end_J'])} | "
            f"{r['strain_energy_end_J']:.3f} | {r['kinetic_end_J']:.3f} | "
            f"{r['energy_error_end_J']:.3f} of {r['work_end_J']:.3f} | "
            f"{r['status']}, {r['steps']}, {r['cpu_s']:.0f} |")
    with open(os.path.join(a.out, "residual.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    if failed:
        # Dated back so that make, which keeps the table (it says what failed), still reruns the
        # check the next time instead of taking a failed check for a done one.
        for name in ("residual.md", "residual.csv"):
            os.utime(os.path.join(a.out, name), (0, 0))
        sys.exit(f"residual.py: {', '.join(failed)}: the lattice's height did not recover within "
                 f"{a.recover:.0%} of u_max")


if __name__ == "__main__":
    main()
