#!/usr/bin/env python3
# Section resultants of a buckling-column snapshot (docs/solver.md, "DDMP column", the
# buckled state of DDMP against uGIMP): per horizontal slice one cell thick, the vertical
# force N = sum V sigma_zz / h, the centroid x_c, the moment M = sum V (x - x_c) sigma_zz / h,
# the curvature of x_c(z) over +-2 slices, and the mean sigma_zz of the points within h/2 of
# either side (the outer fibres). V = J (h/2)^3 (2 points per cell per direction). Needs
# only h5dump (hdf5-tools).
#   python3 bench/mpm/column_sections.py RUN/snapshots/snap_012000.h5 CELL_M [BODY]
import math, os, re, subprocess, sys, tempfile
def ds(f, name):
    fd, t = tempfile.mkstemp(); os.close(fd)
    subprocess.run(["h5dump", "-d", name, "-y", "-w", "0", "-o", t, f], capture_output=True, text=True)
    out = open(t).read(); os.remove(t)
    vals = [float(v) for v in re.split(r"[,\s]+", out.strip()) if v]
    return vals
def load(f):
    pos = ds(f, "/particles/position"); s = ds(f, "/particles/stress"); J = ds(f, "/particles/J"); body = ds(f, "/particles/body")
    n = len(J)
    return [(pos[3*i], pos[3*i+1], pos[3*i+2], s[6*i:6*i+6], J[i], int(body[i])) for i in range(n)]
f, h = sys.argv[1], float(sys.argv[2])
P = load(f)
body = int(sys.argv[3]) if len(sys.argv) > 3 else 1  # body index of the column (body_names order)
col = [p for p in P if p[5] == body]
V0 = (h / 2) ** 3
zs = [p[2] for p in col]; z0, z1 = min(zs), max(zs)
nb = int(round((z1 - z0) / h)) + 1
bins = [[] for _ in range(nb)]
for p in col: bins[min(nb - 1, int((p[2] - z0) / h))].append(p)
rows = []
for b in bins:
    if not b: continue
    Vs = [V0 * p[4] for p in b]; Vt = sum(Vs)
    xc = sum(V * p[0] for V, p in zip(Vs, b)) / Vt; yc = sum(V * p[1] for V, p in zip(Vs, b)) / Vt
    zc = sum(V * p[2] for V, p in zip(Vs, b)) / Vt
    N = sum(V * p[3][5] for V, p in zip(Vs, b)) / h
    Mx = sum(V * (p[0] - xc) * p[3][5] for V, p in zip(Vs, b)) / h
    # outer fibres: mean sigma_zz of the points within h/2 of the extreme x (both sides)
    xmax = max(p[0] for p in b); xmin = min(p[0] for p in b)
    out_hi = [p[3][5] for p in b if p[0] > xmax - h / 2]; out_lo = [p[3][5] for p in b if p[0] < xmin + h / 2]
    rows.append((zc, xc, yc, N, Mx, sum(out_hi) / len(out_hi), sum(out_lo) / len(out_lo)))
print("# z(mm) x_c(mm) N(N) M(N mm) kappa(1/mm) EI_eff(N mm2) s_out_hi(kPa) s_out_lo(kPa)")
for i in range(2, len(rows) - 2):
    z, xc = rows[i][0], rows[i][1]
    za, xa = rows[i - 2][0], rows[i - 2][1]; zb, xb = rows[i + 2][0], rows[i + 2][1]
    k = 2 * ((xb - xc) / (zb - z) - (xc - xa) / (z - za)) / (zb - za)
    EI = -rows[i][4] / k if abs(k) > 1e-9 else float("nan")
    print("%.3f %.4f %.4f %.5f %.6f %.2f %.2f %.2f" % (z * 1e3, xc * 1e3, -rows[i][3], rows[i][4] * 1e3, k * 1e-3, EI * 1e6 if EI == EI else EI, rows[i][5] * 1e-3, rows[i][6] * 1e-3))
