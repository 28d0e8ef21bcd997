"""The optimised 3D beam's stiffness in latmpm-solve against the optimiser's compliance
(docs/paper-c.md, "The optimised beam in latmpm-solve").

usage: explicit_stiffness.py RUN_DIR SUMMARY_TOML METHOD FORCE_N OPTIMIZE_LOG POINTS_H5

RUN_DIR: latmpm-solve's run of the whole (mirrored) part, loaded by a driven box;
SUMMARY_TOML: latmpm-optimize's summary.toml; METHOD: leto or simp; FORCE_N: the
optimiser's total load on the modelled part (the half model's, N).
The optimiser's compliance C = 1/2 f.u of the half model under the force F gives the load
point's mean displacement u = 2C/F, so the whole part (twice the force at the same
displacement) has the stiffness k = 2F/u = F^2/C. The explicit stiffness is the slope of the
driven box's load against its travel, least squares over the last 80 % of the travel (the
contact's start left out), and, as a second reading, the secant 2 W / d^2 of the strain
energy W at the end. The volumes: the design's solid points (latmpm-optimize's line, the
whole part) and the run's points (POINTS_H5, read with h5dump).
Prints one markdown table row.
"""
import csv
import re
import subprocess
import sys
import tomllib


def least_squares_slope(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx


def main():
    run, summary, method, force = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    start = 0.2
    design = re.search(rf"optimize: {method} .*points ([0-9.e+]+) mm\^3", open(sys.argv[5]).read()).group(1)
    dump = subprocess.run(["h5dump", "-d", "/points/volume", "-y", "-w", "0", sys.argv[6]], check=True,
                          capture_output=True, text=True).stdout
    points = 1e9 * sum(float(v) for v in dump.split("DATA {", 1)[1].split("}", 1)[0].replace(",", " ").split())
    with open(summary, "rb") as f:
        s = tomllib.load(f)[method]
    rows = list(csv.DictReader(open(f"{run}/series.csv")))
    d = [float(r["displacement[m]"]) for r in rows]
    load = [float(r["load_driven[N]"]) for r in rows]
    fixed = [float(r["load_fixed[N]"]) for r in rows]
    kinetic = [float(r["kinetic_energy[J]"]) for r in rows]
    strain = [float(r["strain_energy[J]"]) for r in rows]
    keep = [i for i in range(len(d)) if d[i] >= start * d[-1]]
    k_driven = least_squares_slope([d[i] for i in keep], [load[i] for i in keep])
    k_fixed = least_squares_slope([d[i] for i in keep], [fixed[i] for i in keep])
    k_energy = 2 * strain[-1] / d[-1] ** 2
    k_opt = force**2 / s["compliance_J"]
    k_ref = force**2 / s["compliance_refined_J"]
    ratio = max(kinetic[i] / strain[i] for i in keep if strain[i] > 0)
    route = "voxelized STL" if "voxelized" in sys.argv[6] else "design's point file"
    route += ", 0.5 mm cells" if "0.5mm" in sys.argv[6] else ""
    print(f"| {method} | {route} | {k_opt:.4g} | {k_ref:.4g} (explicit {100 * (k_driven / k_ref - 1):+.1f} %) "
          f"| {k_driven:.4g} ({100 * (k_driven / k_opt - 1):+.1f} %) "
          f"| {k_fixed:.4g} | {k_energy:.4g} ({100 * (k_energy / k_opt - 1):+.1f} %) | {ratio:.2g} "
          f"| {design} / {points:.1f} |")


if __name__ == "__main__":
    main()
