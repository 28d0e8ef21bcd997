#!/usr/bin/env python3
"""Fits paper B's hardening law y(a) = y_inf + (y0 - y_inf) exp(-eta a) + h a (Eq. 10) to a
Johnson-Cook flow curve at fixed temperature and strain rate, y0 = the JC yield stress there.
A grid over eta with the linear least squares for (y_inf, h) at each; plain Python.
    python3 bench/paper_b/fit_hardening.py      (the two sets of docs/paper-b.md)"""
import math


def jc_factor(c, m, rate, temperature, t_ref=298.0, t_melt=1793.0, rate_ref=1.0):
    t_star = (temperature - t_ref) / (t_melt - t_ref)
    return (1 + c * math.log(rate / rate_ref)) * (1 - t_star ** m)


def fit(a, b, n, factor, strain_max, samples=601):
    strains = [strain_max * i / (samples - 1) for i in range(samples)]
    stress = [factor * (a + b * e ** n) for e in strains]
    y0 = factor * a
    best = None
    for k in range(1, 4001):
        eta = 0.05 * k
        u = [1 - math.exp(-eta * e) for e in strains]
        r = [s - y0 * math.exp(-eta * e) for s, e in zip(stress, strains)]
        suu = sum(x * x for x in u)
        suv = sum(x * y for x, y in zip(u, strains))
        svv = sum(y * y for y in strains)
        sur = sum(x * y for x, y in zip(u, r))
        svr = sum(x * y for x, y in zip(strains, r))
        det = suu * svv - suv * suv
        y_inf = (sur * svv - suv * svr) / det
        h = (suu * svr - suv * sur) / det
        res = [y_inf * x + h * y - z for x, y, z in zip(u, strains, r)]
        rms = math.sqrt(sum(x * x for x in res) / len(res))
        if best is None or rms < best[0]:
            best = (rms, eta, y_inf, h, max(abs(x) for x in res))
    rms, eta, y_inf, h, worst = best
    return y0, y_inf, eta, h, rms, worst


if __name__ == "__main__":
    # 42CrMo4 via Johnson & Cook's (1985) AISI 4340 constants at 673 K and 2661.9 1/s.
    f = jc_factor(0.014, 1.03, 2661.9, 673.0)
    print("42CrMo4 400C: JC factor %.4f; y0 %.1f MPa, y_inf %.1f MPa, eta %.2f, h %.1f MPa, rms %.2f, max %.2f MPa"
          % ((f,) + fit(792.0, 510.0, 0.26, f, 0.6)))
    # Ti-6Al-4V via Lesuer's (2000) constants at room temperature and 1 1/s.
    print("Ti-6Al-4V: y0 %.1f MPa, y_inf %.1f MPa, eta %.2f, h %.1f MPa, rms %.2f, max %.2f MPa"
          % fit(1098.0, 1092.0, 0.93, 1.0, 0.3))
