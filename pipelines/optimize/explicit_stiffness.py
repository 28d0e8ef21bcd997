"""The optimised 3D beam's stiffness in latmpm-solve against the optimiser's compliance
(docs/paper-c.md, "The optimised beam in latmpm-solve"). Prints one markdown table row.

usage: explicit_stiffness.py POST_DIR SUMMARY_TOML METHOD ROUTE

POST_DIR: latmpm-post over the run of the whole (mirrored) part loaded by a driven box, with
--fit-range 20%:100% (the contact's start left out), label "driven" (--load load_driven) and
"fixed" (--load load_fixed, a second call into POST_DIR/fixed); SUMMARY_TOML:
latmpm-optimize's summary.toml; METHOD: leto or simp; ROUTE: stl or points.
Every number is a tool's: the optimiser's part stiffness (2^mirrors F^2 / (2 C)) and the
exported part's volume from summary.toml; the explicit stiffness (least-squares slope of the
load against the travel) with the largest KE/SE over its fit, the secant 2 W / d^2 of the
strain energy at the end and the run's point volume from latmpm-post's metrics.csv and
checks.csv (docs/post.md). This script
copies them, and sets the explicit ones beside the optimiser's in percent.
"""
import csv
import sys
import tomllib


def row(path, label):
    """The row of LABEL in a latmpm-post CSV, keyed by the header names without units."""
    lines = [line for line in open(path) if not line.startswith("#")]
    for r in csv.DictReader(lines):
        if r["label"] == label:
            return {key.split("[", 1)[0]: value for key, value in r.items()}
    raise SystemExit(f"explicit_stiffness.py: {path}: no row '{label}'")


def main():
    post, summary, method, route = sys.argv[1:5]
    with open(summary, "rb") as f:
        s = tomllib.load(f)[method]
    driven = row(f"{post}/metrics.csv", "driven")
    fixed = row(f"{post}/fixed/metrics.csv", "fixed")
    checks = row(f"{post}/checks.csv", "driven")
    n_per_mm = 1e3  # latmpm-post's N/mm in this table's N/m
    k_opt, k_ref = s["part_stiffness_N_per_m"], s["part_stiffness_refined_N_per_m"]
    k_driven = float(driven["initial_stiffness"]) * n_per_mm
    k_fixed = float(fixed["initial_stiffness"]) * n_per_mm
    k_energy = float(checks["energy_secant_stiffness"]) * n_per_mm
    where = "voxelized STL" if route == "stl" else "design's point file"
    print(f"| {method} | {where} | {k_opt:.4g} | {k_ref:.4g} | {k_driven:.4g} ({100 * (k_driven / k_opt - 1):+.1f} %) "
          f"| {k_fixed:.4g} | {k_energy:.4g} ({100 * (k_energy / k_opt - 1):+.1f} %) | {float(driven['stiffness_fit_ke_over_se']):.2g} "
          f"| {s['part_points_volume_mm3']:.4g} / {float(driven['specimen_volume']):.1f} |")


if __name__ == "__main__":
    main()
