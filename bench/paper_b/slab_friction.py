#!/usr/bin/env python3
"""How much should friction raise the SHPB specimen's force? An independent estimate
(docs/paper-b.md, "Friction: how much should it change the force?").

The slab method of cylinder upsetting between flat platens (Siebel; Schroeder & Webster,
J. Appl. Mech. 16, 1949): a thin slab of the cylinder, radius r, in radial equilibrium under
the interface shear tau, with sigma_r = sigma_theta and the yield condition p - sigma_r = y,
gives dp/dr = -2 tau / h with p(R) = y at the rim. Coulomb friction tau = mu p capped at
sticking, tau <= k = y / sqrt(3) (von Mises), integrated from the rim inwards; the mean
pressure p/y over the face is independent of y (so of the steel's constants). Sliding
everywhere it is 2 (e^a - a - 1) / a^2, a = mu d / h; linearised, Siebel's 1 + mu d / (3 h);
sticking everywhere 1 + d / (3 sqrt(3) h).

The specimen of paper B: d0 = l0 = 4 mm, the incident face at 10.6476 m/s, volume kept
(d = d0 sqrt(l0 / h)), no barrelling: the slab method's own assumptions, which overstate
friction's effect on a specimen this thick (it assumes the axial stress uniform through the
height and the friction hill over the whole face). Standard library only."""
import math

L0, D0, SPEED = 4.0, 4.0, 10.6476e-3  # mm, mm, mm/us


def mean_pressure(mu, radius, height, steps=20000):
    """p / y averaged over the face, Coulomb mu (math.inf: sticking) capped at k = y / sqrt(3)."""
    k, p, dr, acc = 1 / math.sqrt(3), 1.0, radius / steps, 0.0
    for i in range(steps):  # from the rim inwards
        r = radius - (i + 0.5) * dr
        tau = k if math.isinf(mu) else min(mu * p, k)
        p += 2 * tau / height * dr
        acc += p * 2 * r * dr
    return acc / (radius * radius)


def main():
    mus = (0.0, 0.05, 0.1, 0.2, 0.35, math.inf)
    print("| t (us) | h (mm) | d (mm) | d/h | p/y for mu = 0, 0.05, 0.1, 0.2, 0.35, stick "
          "| 0.05 -> 0.35 | Siebel, linear | stick against mu = 0 |")
    print("|---|---|---|---|---|---|---|---|")
    for t in (10, 20, 50, 100, 150):
        h = L0 - SPEED * t
        d = D0 * math.sqrt(L0 / h)
        p = [mean_pressure(mu, d / 2, h) if mu > 0 else 1.0 for mu in mus]
        siebel = (1 + 0.35 * d / (3 * h)) / (1 + 0.05 * d / (3 * h))
        print(f"| {t} | {h:.3f} | {d:.3f} | {d / h:.3f} | " + ", ".join(f"{v:.4f}" for v in p)
              + f" | {100 * (p[4] / p[1] - 1):+.1f} % | {100 * (siebel - 1):+.1f} % | {100 * (p[5] - 1):+.1f} % |")


if __name__ == "__main__":
    main()
