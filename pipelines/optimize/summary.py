#!/usr/bin/env python3
"""summary.md of the optimisation examples from each example's summary.toml (tomllib-free:
the file is flat key = value lines under [method] headers)."""
import sys


def read(path):
    methods, current, head = {}, None, {}
    for line in open(path):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("["):
            current = line.strip("[]")
            methods[current] = {}
        elif "=" in line:
            key, value = (part.strip() for part in line.split("=", 1))
            (methods[current] if current else head)[key] = value.strip("'")
    return head, methods


out, examples = sys.argv[1], sys.argv[2:]
print("# latmpm-optimize: paper C examples\n")
print("Compliance C = elastic potential of the binary design (J); refined: on the grid refined twice "
      "(one refined cell per quadrature point). Seconds per iteration on this machine (2 cores, shared).\n")
print("| example | method | cells | volume % | C (J) | C refined (J) | iterations | s/iteration | components | corrections |")
print("|---|---|---|---|---|---|---|---|---|---|")
for example in examples:
    head, methods = read(f"{out}/{example}/summary.toml")
    for method, m in methods.items():
        print(f"| {example} | {method} | {head['cells']} | {100 * float(m['volume_fraction']):.2f} | "
              f"{float(m['compliance_J']):.4g} | {float(m['compliance_refined_J']):.4g} | {m['iterations']} | "
              f"{float(m['seconds_per_iteration']):.3f} | {m['components']} | {m['connectivity_corrections']} |")
other = [(e, m) for e in examples for m in [read(f"{out}/{e}/summary.toml")[1]] if any("compliance_other_model_J" in v for v in m.values())]
if other:
    print("\nThe same binary designs under the other material model (optimisation grid; paper C Sec. 4.3):\n")
    print("| example | method | C, its own model (J) | C, the other model (J) |")
    print("|---|---|---|---|")
    for example, methods in other:
        for method, m in methods.items():
            print(f"| {example} | {method} | {float(m['compliance_J']):.4g} | {float(m['compliance_other_model_J']):.4g} |")
print("\nPictures: <example>/<method>-design.png; parts: <example>/<method>-part.stl, <method>-points.h5.")
