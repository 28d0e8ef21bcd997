#!/usr/bin/env python3
"""The SHPB study against paper B, in numbers (make shpb; docs/paper-b.md).

Reads each run's series.csv (load_driven = f_i, load_fixed = f_t, load_average = f_a, Eq. 14)
and status.toml, and writes one markdown file: a row per run (how it ended, f_i, f_t, f_a at
10 / 20 / 50 / 100 / 150 us, the energy balance, CPU), then paper B's comparisons where the
runs exist: friction (paper B: mu = 0.05 and 0.35 change the final f_i by < 5 %) on B5 and on
any other mesh given, mesh convergence on G4, grids on B4, and what B6 does (paper B: a
numerical failure from strong localisation, Fig. 13).

usage: paper_table.py --out FILE LABEL=RUN_DIR ...
Labels: the case names of pipelines/shpb/cases-paper.txt (mu0.05-B5G4, B1G4, B4G2, ...);
friction runs on another mesh as <mesh>G4-mu<mu> (e.g. B3G4-mu0.35; B3G4 itself is mu = 0.1).
Standard library only."""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from run_status import read_status  # noqa: E402

TIMES_US = (10, 20, 50, 100, 150)




class Run:
    def __init__(self, label, path):
        self.label, self.path = label, path
        with open(os.path.join(path, "series.csv")) as f:
            self.rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
        if not self.rows:
            raise ValueError("no rows in series.csv")
        self.status = read_status(path)
        self.t_end_us = self.rows[-1]["time[s]"] * 1e6

    def at(self, t_us, column):
        """The column at t (us), from the nearest row; None past the run's end."""
        if t_us > self.t_end_us * (1 + 1e-9):
            return None
        row = min(self.rows, key=lambda r: abs(r["time[s]"] * 1e6 - t_us))
        return row[column]

    def final(self, column="load_driven[N]"):
        return self.rows[-1][column]

    def finished(self):
        return self.status.get("status") == "finished"

    def ended(self):
        s = self.status.get("status", "?")
        if s == "finished":
            return f"finished at {self.t_end_us:.1f} us"
        reason = self.status.get("reason", "")
        return f"{s}{' (' + reason + ')' if reason else ''} at {self.t_end_us:.1f} us"

    def energy(self):
        last = self.rows[-1]
        work = last["external_work[J]"]
        return last["energy_error[J]"] / work if work else float("nan"), work

    def cpu(self):
        cpu = float(self.status.get("cpu_s", "nan"))
        steps = float(self.status.get("steps", "nan"))
        return cpu, 1e3 * cpu / steps if steps else float("nan")


def common_end(done):
    """The time (us) every run of `done` reached."""
    return min(r.t_end_us for r in done.values())


def kn(x):
    return "—" if x is None else f"{x / 1e3:.2f}"


def pct(a, b):
    return 100 * (a - b) / b


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True)
    p.add_argument("runs", nargs="+")
    a = p.parse_args()
    runs, paths = {}, set()
    for item in a.runs:
        label, _, path = item.partition("=")
        if os.path.normpath(path) in paths:  # a run reused under a second name (B5G4 = mu0.1-B5G4)
            continue
        paths.add(os.path.normpath(path))
        try:
            runs[label] = Run(label, path)
        except (OSError, KeyError, ValueError) as e:
            print(f"paper_table.py: {path}: {e} (left out)", file=sys.stderr)
    L = ["# SHPB paper-size study against paper B (paper_table.py)", "",
         "f in kN (f_i, f_t, f_a at each time); energy error = energy_error / work in at the end; "
         "CPU = the solver's user + system seconds over all its parts (resumed runs add up), per step in ms.", "",
         "| case | ended | f_i, f_t, f_a at " + " / ".join(f"{t}" for t in TIMES_US) + " us | energy error | CPU s (ms/step) |",
         "|---|---|---|---|---|"]
    for label, r in runs.items():
        cells = []
        for t in TIMES_US:
            fi, ft, fa = (r.at(t, c) for c in ("load_driven[N]", "load_fixed[N]", "load_average[N]"))
            cells.append("—" if fi is None else f"{kn(fi)}, {kn(ft)}, {kn(fa)}")
        err, work = r.energy()
        cpu, per = r.cpu()
        L.append(f"| {label} | {r.ended()} | {' / '.join(cells)} | {100 * err:+.2f} % of {work:.2f} J | {cpu:.0f} ({per:.2f}) |")

    L += ["", "## Paper B's comparisons, in numbers", ""]

    # Friction: the final f_i of mu = 0.05 against mu = 0.35, per mesh.
    def friction_on(mesh):
        named = {0.1: f"{mesh}G4" if f"{mesh}G4" in runs else None}
        for label in runs:
            if label.endswith(f"-{mesh}G4") and label.startswith("mu"):
                named[float(label[2:label.index("-")])] = label
            if label.startswith(f"{mesh}G4-mu"):
                named[float(label[len(mesh) + 5:])] = label
        if f"mu0.1-{mesh}G4" in runs:
            named[0.1] = f"mu0.1-{mesh}G4"
        return {mu: runs[l] for mu, l in named.items() if l in runs}

    meshes_named = sorted({l.split("-")[-1][:-2] for l in runs if l.startswith("mu")} |
                          {l.split("G4-mu")[0] for l in runs if "G4-mu" in l}, key=lambda m: -int(m[1:]))
    for mesh in meshes_named:
        f = friction_on(mesh)
        done = {mu: r for mu, r in sorted(f.items()) if r.finished()}
        if not done:
            continue
        values = ", ".join(f"{r.final() / 1e3:.2f} kN (mu = {mu:g})" for mu, r in done.items())
        line = (f"- **Friction on {mesh}/G4** (paper B: mu = 0.05 and 0.35 change the final f_i by < 5 %): "
                f"f_i at {common_end(done):.0f} us {values}")
        if 0.05 in done and 0.35 in done:
            lo, hi = done[0.05], done[0.35]
            spread = pct(hi.final(), lo.final())
            line += f"; **{spread:+.1f} % from 0.05 to 0.35**, {'within' if abs(spread) < 5 else 'above'} paper B's 5 %"
            earlier = [f"{pct(hi.at(t, 'load_driven[N]'), lo.at(t, 'load_driven[N]')):+.1f} % at {t} us"
                       for t in (20, 50, 100) if t < lo.t_end_us and t < hi.t_end_us]
            line += " (" + ("f_i: " + ", ".join(earlier) + "; " if earlier else "")
            line += f"f_a at the end: {pct(hi.final('load_average[N]'), lo.final('load_average[N]')):+.1f} %)"
        missing = sorted(set(f) - set(done))
        if missing:
            line += "; not finished: " + ", ".join(f"mu = {m:g} ({f[m].ended()})" for m in missing)
        L.append(line + ".")

    meshes = [(k, runs.get(f"B{k}G4") or (runs.get("mu0.1-B5G4") if k == 5 else None)) for k in range(1, 7)]
    meshes = [(k, r) for k, r in meshes if r is not None and r.finished()]
    if len(meshes) >= 2:
        steps = ", ".join(f"B{a}→B{b} {pct(rb.final(), ra.final()):+.1f} %"
                          for (a, ra), (b, rb) in zip(meshes, meshes[1:]))
        L.append(f"- **Meshes on G4** (paper B Fig. 12a: weak sensitivity, converging): f_i at {meshes[0][1].t_end_us:.0f} us "
                 + ", ".join(f"B{k} {r.final() / 1e3:.2f} kN" for k, r in meshes) + f"; steps {steps}.")

    ref = runs.get("B4G4")
    grids = [(g, runs.get(f"B4G{g}")) for g in (1, 2, 3)]
    grids = [(g, r) for g, r in grids if r is not None]
    if ref and grids:
        parts = []
        for g, r in grids:
            reached = [t for t in TIMES_US if r.at(t, "load_driven[N]") is not None]
            t = reached[-1] if reached else None  # the latest of TIMES_US the run reached
            if t is None:
                parts.append(f"G{g}: {r.ended()}")
                continue
            parts.append(f"G{g} {r.at(t, 'load_driven[N]') / 1e3:.2f} kN at {t} us "
                         f"({pct(r.at(t, 'load_driven[N]'), ref.at(t, 'load_driven[N]')):+.1f} % against G4)")
        L.append("- **Grids on B4** (paper B Fig. 12b: a stronger influence of the grid, converging with finer grids): "
                 + "; ".join(parts) + f"; G4 {ref.final() / 1e3:.2f} kN at 150 us.")

    b6, b5 = runs.get("B6G4"), runs.get("mu0.1-B5G4")
    if b6:
        line = (f"- **B6** (paper B: the finest discretisation fails numerically by strong localisation, Fig. 13): "
                f"{b6.ended()}")
        if b5:
            common = [t for t in TIMES_US if b6.at(t, "load_driven[N]") is not None]
            line += "; f_i against B5: " + ", ".join(
                f"{b6.at(t, 'load_driven[N]') / 1e3:.2f} vs {b5.at(t, 'load_driven[N]') / 1e3:.2f} kN at {t} us"
                for t in common)
        err, _ = b6.energy()
        line += f"; energy error {100 * err:+.2f} %; largest point speed {max(r['max_speed[m/s]'] for r in b6.rows):.1f} m/s."
        L.append(line)

    fi_ft = [abs(pct(r.final("load_fixed[N]"), r.final())) for r in runs.values() if r.finished()]
    if fi_ft:
        L.append(f"- **f_i = f_t** at the end of every finished run within {max(fi_ft):.2f} % (equilibrium).")
    with open(a.out, "w") as f:
        f.write("\n".join(L) + "\n")
    print("\n".join(L))


if __name__ == "__main__":
    main()
