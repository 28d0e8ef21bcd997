"""A run directory's status.toml (written by latmpm-solve at the end of every run, docs/scene.md
"The run directory") as a dict of strings: status, reason, steps, cpu_s, wall_s, points, ...
Flat key = value lines only, so the standard library suffices (Python 3.11's tomllib is not
on every machine this runs on)."""
import os


def read_status(run_dir):
    out = {}
    with open(os.path.join(run_dir, "status.toml")) as f:
        for line in f:
            if "=" in line and not line.startswith("#"):
                key, value = (part.strip() for part in line.split("=", 1))
                out[key] = value.strip('"')
    return out
