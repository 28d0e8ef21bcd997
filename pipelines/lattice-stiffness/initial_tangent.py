"""The initial stiffness of a compression run as the tangent at zero travel (docs/statics.md,
"T2P30 against the explicit run: the tangent at zero travel").

usage: initial_tangent.py RANGE_MM SERIES_CSV [SERIES_CSV ...]

Per run (a static path or an explicit run's series.csv): the least-squares fit
F(d) = k0 d + a d^2 of the base's reaction `load_fixed` over the rows with d (the platen's
travel) in RANGE_MM ("0:0.3"), and the secant F/d at 0.1 mm (the mean of F/d over the rows
within 0.1 +- 0.025 mm). k0 is the stiffness at d -> 0 on both sides: the secant at a finite travel
also holds the path's first-order softening, which the explicit updated-Lagrangian run and
the static total-Lagrangian solve do not share. Prints one markdown table row per run.
"""
import csv
import sys


def main():
    lo, hi = (float(x) for x in sys.argv[1].split(":"))
    print("| run | rows | k0 (N/mm) | a (N/mm^2) | secant at 0.1 mm (N/mm) |")
    print("|---|---|---|---|---|")
    for path in sys.argv[2:]:
        rows = [r for r in csv.DictReader(line for line in open(path) if not line.startswith("#"))]
        d = [float(r["displacement[m]"]) * 1e3 for r in rows]
        f = [float(r["load_fixed[N]"]) for r in rows]
        pts = [(x, y) for x, y in zip(d, f) if lo <= x <= hi and x > 0]
        if len(pts) < 2:
            raise SystemExit(f"initial_tangent.py: {path}: fewer than 2 rows with travel in {lo}:{hi} mm")
        s11 = sum(x**2 for x, _ in pts)
        s12 = sum(x**3 for x, _ in pts)
        s22 = sum(x**4 for x, _ in pts)
        b1 = sum(x * y for x, y in pts)
        b2 = sum(x * x * y for x, y in pts)
        det = s11 * s22 - s12 * s12
        if det <= 1e-12 * s11 * s22:
            raise SystemExit(f"initial_tangent.py: {path}: the rows in {lo}:{hi} mm do not fix a quadratic (one travel)")
        k0, a = (b1 * s22 - b2 * s12) / det, (s11 * b2 - s12 * b1) / det
        near = [y / x for x, y in zip(d, f) if abs(x - 0.1) <= 0.025 and x > 0]
        secant = f"{sum(near) / len(near):.4f}" if near else "-"
        print(f"| {path} | {len(pts)} | {k0:.4f} | {a:.3f} | {secant} |")


if __name__ == "__main__":
    main()
