#!/usr/bin/env python3
"""The floating cylinder's RAO three ways, as one chart: Tether's time domain (regular-wave runs)
and frequency domain (the solve of PHYSICS.md §9), both from `tether rao --time-domain --csv`,
beside Capytaine's own `rao()` (`cylinder/cylinder_rao.csv`, written by `cylinder.py`).

    cargo build --release
    target/release/tether rao validation/potential-flow/cylinder.ron --body cylinder \\
        --time-domain --csv rao.csv                     # the file's 100 frequencies, ~1 min on 2 cores
    ~/.cache/tether/capytaine-venv/bin/pip install matplotlib
    ~/.cache/tether/capytaine-venv/bin/python validation/potential-flow/rao_plot.py rao.csv

Writes `screenshots/cylinder_rao.png` (docs/potential-flow.md): surge, heave and pitch, amplitude
per metre of wave and phase in WAMIT's convention, against ω. Capytaine solved with its own
finer mesh's stiffness (0.4 % above the 32-sided mesh's) and the circle's mass, so its heave and
pitch resonances sit slightly apart from Tether's.
"""

import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
OUT = HERE.parent.parent / "screenshots" / "cylinder_rao.png"
# (name, Tether's CSV column stem and unit, Capytaine's column, scale of Capytaine's amplitude)
DOFS = [
    ("surge", "surge", "m_per_m", "surge", 1.0, "m/m"),
    ("heave", "heave", "m_per_m", "heave", 1.0, "m/m"),
    ("pitch", "pitch", "deg_per_m", "pitch", np.degrees(1.0), "deg/m"),
]


def tether_table(path):
    """Tether's CSV as columns of floats (an empty cell, a singular frequency, as NaN)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows or "surge_td_m_per_m" not in rows[0]:
        sys.exit(f"{path}: no time-domain columns: write it with `tether rao ... --time-domain --csv`")
    return {key: np.array([float(r[key]) if r[key] else np.nan for r in rows]) for key in rows[0]}


def capytaine_table():
    """Capytaine's RAO: ω, then amplitude and phase per dof (rad/m for pitch)."""
    lines = [l for l in open(HERE / "cylinder" / "cylinder_rao.csv") if not l.startswith("#")]
    rows = list(csv.DictReader(lines))
    return {key: np.array([float(r[key]) for r in rows]) for key in rows[0]}


def wrap(degrees):
    return (np.asarray(degrees) + 180.0) % 360.0 - 180.0


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    ours, theirs = tether_table(sys.argv[1]), capytaine_table()
    order = np.argsort(ours["omega_rad_s"])
    omega = ours["omega_rad_s"][order]
    figure, axes = plt.subplots(len(DOFS), 2, figsize=(12, 10), sharex=True)
    for row, (name, stem, unit, their, scale, label) in zip(axes, DOFS):
        fd, td = f"{stem}_{unit}", f"{stem}_td_{unit}"
        row[0].plot(omega, ours[fd][order], "-", color="tab:blue", label="Tether, frequency domain")
        row[0].plot(theirs["omega"], theirs[f"{their}_amp"] * scale, "--", color="tab:green", label="Capytaine rao()")
        row[0].plot(omega, ours[td][order], "o", color="tab:orange", markersize=3.5, label="Tether, time domain")
        row[0].set_ylabel(f"{name} [{label}]")
        row[0].set_yscale("log")
        row[1].plot(omega, wrap(ours[f"{stem}_phase_deg"][order]), "-", color="tab:blue")
        row[1].plot(theirs["omega"], wrap(theirs[f"{their}_phase"]), "--", color="tab:green")
        row[1].plot(omega, wrap(ours[f"{stem}_td_phase_deg"][order]), "o", color="tab:orange", markersize=3.5)
        row[1].set_ylabel(f"{name} phase [deg]")
        row[1].set_ylim(-190, 190)
        row[1].set_yticks([-180, -90, 0, 90, 180])
        for axis in row:
            axis.grid(alpha=0.3)
    axes[0][0].legend()
    for axis in axes[-1]:
        axis.set_xlabel("ω [rad/s]")
    figure.suptitle("Floating cylinder (R 3 m, draft 6 m), waves toward 0°: RAO per metre of wave amplitude, WAMIT's phase")
    figure.tight_layout()
    OUT.parent.mkdir(exist_ok=True)
    figure.savefig(OUT, dpi=100)
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
