#!/usr/bin/env python3
"""A stand-in for a tank test's heave decay of the box of heave_box.ron, made without Tether.

The box (20 x 10 x 4 m, 410 t, wall-sided, draft 2 m) is let go 0.5 m above its floating
position in still water (rho = 1025 kg/m^3, g = 9.80665 m/s^2). Its heave z obeys

    m z'' = rho g A (d0 - z) - m g - c z' - w(z) 1/2 rho C_d A |z'| z',   w(z) = (d0 - z) / H,

the buoyancy exact for a wall-sided hull, a linear damper c and a quadratic drag C_d on the
waterplane A = 200 m^2 scaled by the wetted fraction w (docs/PHYSICS.md section 6). This script
solves it by RK4 at 1e-4 s with c = 6.0e4 N s/m and C_d = 2.5 (the "tank's" values, which
heave_box.ron does not have: it says 9.1e4 and 1.0), samples z every 0.05 s for 30 s and adds
Gaussian noise of 2 mm (a wave probe's), seeded, so the file is the same on every run.
Plain Python, no packages:   python3 make_heave_record.py  (writes heave_record.csv here)
"""

import random
from pathlib import Path

RHO, G, AREA, HEIGHT, DRAFT, MASS = 1025.0, 9.80665, 200.0, 4.0, 2.0, 410_000.0
DAMPING, DRAG = 6.0e4, 2.5  # the record's truth
NOISE, SEED = 0.002, 2026  # m, and the noise's seed
STEP, EVERY, UNTIL = 1e-4, 0.05, 30.0


def acceleration(z: float, v: float) -> float:
    wetted = min(max((DRAFT - z) / HEIGHT, 0.0), 1.0)
    force = RHO * G * AREA * (DRAFT - z) - MASS * G - DAMPING * v - wetted * 0.5 * RHO * DRAG * AREA * abs(v) * v
    return force / MASS


def main() -> None:
    z, v = 0.5, 0.0
    per_sample = round(EVERY / STEP)
    rng = random.Random(SEED)
    rows = [(0.0, z + NOISE * rng.gauss(0.0, 1.0))]
    for step in range(1, round(UNTIL / STEP) + 1):
        k1z, k1v = v, acceleration(z, v)
        k2z, k2v = v + 0.5 * STEP * k1v, acceleration(z + 0.5 * STEP * k1z, v + 0.5 * STEP * k1v)
        k3z, k3v = v + 0.5 * STEP * k2v, acceleration(z + 0.5 * STEP * k2z, v + 0.5 * STEP * k2v)
        k4z, k4v = v + STEP * k3v, acceleration(z + STEP * k3z, v + STEP * k3v)
        z += STEP / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z)
        v += STEP / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)
        if step % per_sample == 0:
            rows.append((step * STEP, z + NOISE * rng.gauss(0.0, 1.0)))
    out = Path(__file__).with_name("heave_record.csv")
    with out.open("w") as f:
        f.write("time_s,heave_m\n")
        for t, z in rows:
            f.write(f"{t:.2f},{z:.5f}\n")
    print(f"wrote {out}: {len(rows)} samples, z from {rows[0][1]:.4f} m to {rows[-1][1]:.4f} m")


if __name__ == "__main__":
    main()
