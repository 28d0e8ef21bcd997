#!/usr/bin/env python3
"""Issue 14's error measures of runs against a reference run (docs/tradeoff.md, "Paper
resolution in minutes"): for each RUN_DIR, the load (series column, default load_fixed) at
every STEP of plate travel, as the mean over the window STEP/2 either side (removes the
explicit solver's step-to-step ripple), its largest difference from the reference's as a
fraction of the reference's peak load; the absorbed energy to the end of the travel, the
trapezoid rule of the load over the displacement, against the reference's; the largest
kinetic over strain energy in the second half of the travel; CPU time and steps from
RUN_DIR/status.toml. Plain Python (no numpy): one CSV row per run on stdout.

  issue14-compare.py REF_DIR RUN_DIR... [--load load_fixed] [--step 0.5mm]
"""
import csv
import sys


def series(run, load):
    with open(f"{run}/series.csv") as f:
        rows = list(csv.reader(f))
    head = [h.split("[")[0] for h in rows[0]]
    col = {h: i for i, h in enumerate(head)}
    data = [[float(x) for x in r] for r in rows[1:] if r]
    d = [r[col["displacement"]] for r in data]
    return d, [r[col[load]] for r in data], [r[col["kinetic_energy"]] for r in data], \
        [r[col["strain_energy"]] for r in data]


def status(run):
    out = {}
    with open(f"{run}/status.toml") as f:
        for line in f:
            if "=" in line:
                k, v = (s.strip() for s in line.split("=", 1))
                out[k] = v.strip('"')
    return out


def window_mean(d, f, centre, half):
    vals = [fi for di, fi in zip(d, f) if centre - half <= di <= centre + half]
    return sum(vals) / len(vals) if vals else float("nan")


def energy(d, f):
    return sum(0.5 * (f[i] + f[i - 1]) * (d[i] - d[i - 1]) for i in range(1, len(d)))


def main(argv):
    load, step, runs = "load_fixed", 0.5e-3, []
    i = 0
    while i < len(argv):
        if argv[i] == "--load":
            load = argv[i + 1]; i += 2
        elif argv[i] == "--step":
            step = float(argv[i + 1].replace("mm", "")) * 1e-3; i += 2
        else:
            runs.append(argv[i]); i += 1
    ref = runs[0]
    rd, rf, _, _ = series(ref, load)
    end = rd[-1]
    stations = [step * k for k in range(1, int(end / step + 1e-9) + 1)]
    ref_loads = [window_mean(rd, rf, s, step / 2) for s in stations]
    peak = max(ref_loads)
    ref_energy = energy(rd, rf)
    ref_cpu = float(status(ref).get("cpu_s", "nan"))
    w = csv.writer(sys.stdout)
    w.writerow(["run", "steps", "cpu_s", "cpu_speedup", "peak_load_N", "max_load_error_of_peak",
                "at_mm", "energy_J", "energy_error", "ke_over_se_max_2nd_half", "status"])
    for run in runs:
        d, f, ke, se = series(run, load)
        st = status(run)
        loads = [window_mean(d, f, s, step / 2) for s in stations]
        errs = [abs(a - b) / peak for a, b in zip(loads, ref_loads)]
        k = max(range(len(errs)), key=lambda j: errs[j])
        e = energy(d, f)
        ratio = max((ke[j] / se[j] for j in range(len(d)) if d[j] >= end / 2 and se[j] > 0), default=float("nan"))
        cpu = float(st.get("cpu_s", "nan"))
        w.writerow([run, st.get("steps"), f"{cpu:.1f}", f"{ref_cpu / cpu:.2f}", f"{max(loads):.4g}",
                    f"{errs[k]:.4f}", f"{stations[k] * 1e3:.2f}", f"{e:.5g}", f"{(e - ref_energy) / ref_energy:+.4f}",
                    f"{ratio:.2g}", st.get("outcome", st.get("status", "?"))])


if __name__ == "__main__":
    main(sys.argv[1:])
