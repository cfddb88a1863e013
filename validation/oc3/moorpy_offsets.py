#!/usr/bin/env python3
"""The OC3-Hywind surge offset curve: Tether's (`tether offsets`) beside MoorPy's for the same
three lines, the same body (mass, G, displaced volume, waterplane, metacentre) and the same
seabed (C_B = 0), each held at offsets in surge with heave, pitch and the rest settled.

    python3 validation/oc3/moorpy_offsets.py [--tether PATH] [--to 30] [--steps 15] [-o DIR]

It makes its own virtual environment (`validation/oc3/.venv`, or $OC3_VENV) with MoorPy and
matplotlib from PyPI the first time, reruns itself in it, runs Tether (default: the headless
release build `target/release/tether`, else `tether` on PATH), prints the table and writes
`DIR/oc3_offsets.csv` and the chart `DIR/oc3_offsets.png` (default DIR: oc3-offsets).
The line and body numbers are those of scenes/oc3_hywind.ron (Jonkman 2010, NREL/TP-500-47535;
derived ones from validation/oc3/spar.py).
"""

import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
SCENE = ROOT / "scenes" / "oc3_hywind.ron"
VENV = Path(os.environ.get("OC3_VENV", HERE / ".venv"))

# The scene's numbers (SWL coordinates; see its comment).
RHO, G, DEPTH = 1025.0, 9.80665, 320.0
LINE = dict(d=0.09, mass=77.7066, EA=384.243e6, length=902.2)  # volume-equivalent diameter [m]
FAIRLEAD_R, FAIRLEAD_Z, ANCHOR_R = 5.2, -70.0, 853.87
MASS, X_G, Z_G = 8_066_048.0, -0.0119, -78.0007
VOLUME, Z_B = 8029.209, -62.0657
AWP = math.pi * 6.5**2 / 4
Z_M = Z_B + math.pi * 6.5**4 / 64 / VOLUME  # metacentre above the keel's reference: z_B + I_wp/V
YAW_SPRING = 2 * 49.17  # N/m: what the scene's yaw spring pair adds in surge (not a line)


def in_venv():
    """Reruns this script in its own virtual environment (made with MoorPy the first time)."""
    python = VENV / "bin" / "python"
    if Path(sys.prefix).resolve() == VENV.resolve():
        return
    if not python.exists():
        print(f"making {VENV} with moorpy and matplotlib from PyPI …", flush=True)
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        subprocess.run([str(python), "-m", "pip", "install", "-q", "moorpy", "matplotlib"], check=True)
    os.execv(str(python), [str(python), __file__, *sys.argv[1:]])


def tether_curve(binary, to, steps, out):
    """Tether's offset curve: (offset m, restoring N, fairlead tensions N) per row."""
    stem = out / "tether_offsets"
    subprocess.run(
        [binary, "offsets", str(SCENE), "--body", "spar", "--direction", "x", "--to", str(to),
         "--steps", str(steps), "-o", str(stem)],
        check=True, stdout=subprocess.DEVNULL,
    )
    with open(f"{stem}.csv") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], [[float(x) for x in r] for r in rows[1:]]
    t2 = [header.index(f"line{i} T2 [N]") for i in (1, 2, 3)]
    return [(r[0], r[2], [r[i] for i in t2]) for r in body]


def moorpy_system():
    """The OC3 mooring in MoorPy, with the spar as a free body carrying its weight and buoyancy.

    The body's reference point is G, as Tether's offsets hold G: the weight acts there, the
    buoyancy at the metacentre (MoorPy's hydrostatics: `ρ g V` at `rM` gives the pitch and roll
    restoring `ρ g V z_M − m g z_G`), and MoorPy's waterplane term `−ρ g A_wp z_ref`, written
    for a reference point on the waterline, is shifted to G by a constant external force."""
    import numpy as np
    import moorpy as mp

    ms = mp.System(depth=DEPTH, rho=RHO, g=G)
    # The line type by its properties (its weight in water from d_vol, m, ρ and g: 698.094 N/m).
    ms.setLineType(name="main", lineType=dict(d_vol=LINE["d"], m=LINE["mass"], EA=LINE["EA"], w=None))
    f6 = np.zeros(6)
    f6[2] = RHO * G * AWP * Z_G
    body = ms.addBody(0, [X_G, 0, Z_G, 0, 0, 0], m=MASS, v=VOLUME, rCG=[0, 0, 0], AWP=AWP,
                      rM=[-X_G, 0, Z_M - Z_G], f6Ext=f6)
    for k in range(3):
        a = 2 * math.pi * k / 3
        anchor = ms.addPoint(1, [ANCHOR_R * math.cos(a), ANCHOR_R * math.sin(a), -DEPTH])
        fair_rel = [FAIRLEAD_R * math.cos(a) - X_G, FAIRLEAD_R * math.sin(a), FAIRLEAD_Z - Z_G]
        fair = ms.addPoint(1, [fair_rel[0] + X_G, fair_rel[1], FAIRLEAD_Z])
        body.attachPoint(fair.number, fair_rel)
        ms.addLine(LINE["length"], "main", pointA=anchor.number, pointB=fair.number)
    ms.initialize()
    return ms, body


def moorpy_curve(offsets):
    """MoorPy's curve at Tether's offsets of G from MoorPy's own equilibrium: the lines'
    restoring force in surge [N] and fairlead tensions [N], every other direction settled."""
    ms, body = moorpy_system()
    ms.solveEquilibrium(tol=1e-6)
    equilibrium = body.r6.copy()
    out = []
    for dx in offsets:
        r6 = equilibrium.copy()
        r6[0] += dx
        body.setPosition(r6)
        body.DOFs, body.nDOF = [1, 2, 3, 4, 5], 5  # surge held
        ms.solveEquilibrium(tol=1e-6)
        body.DOFs, body.nDOF = [0, 1, 2, 3, 4, 5], 6
        surge = body.getForces(lines_only=True)[0]
        out.append((dx, -surge, [line.TB for line in ms.lineList], body.r6.copy()))
    return equilibrium, out


def main():
    in_venv()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tether", default=None, help="the tether binary")
    parser.add_argument("--to", type=float, default=30.0, help="largest surge offset [m]")
    parser.add_argument("--steps", type=int, default=15)
    parser.add_argument("-o", "--out", default="oc3-offsets")
    args = parser.parse_args()
    binary = args.tether or (str(ROOT / "target/release/tether") if (ROOT / "target/release/tether").exists()
                             else shutil.which("tether"))
    if binary is None:
        sys.exit("no tether binary: build it (cargo build --release --no-default-features) or pass --tether")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    tether = tether_curve(binary, args.to, args.steps, out)
    equilibrium, moorpy = moorpy_curve([row[0] for row in tether])
    print(f"MoorPy equilibrium: G at x = {equilibrium[0]:.4f} m, z = {equilibrium[2]:.4f} m, "
          f"pitch {math.degrees(equilibrium[4]):.4f}°")
    print(f"restoring: Tether's less its yaw springs' {YAW_SPRING:.2f} N/m in surge (not a line)\n")
    head = f"{'offset m':>9} {'Tether kN':>11} {'MoorPy kN':>11} {'diff %':>8} | " \
           f"{'1 Tether':>9} {'1 MoorPy':>9} {'2 Tether':>9} {'2 MoorPy':>9}  (fairlead kN; line3 = line2)"
    print(head)
    rows = []
    for (dx, restoring, t_tether), (_, r_moorpy, t_moorpy, _) in zip(tether, moorpy):
        lines_only = restoring - YAW_SPRING * dx
        diff = f"{100 * (lines_only - r_moorpy) / r_moorpy:8.3f}" if abs(r_moorpy) > 1.0 else f"{'—':>8}"
        print(f"{dx:9.2f} {lines_only / 1e3:11.2f} {r_moorpy / 1e3:11.2f} {diff} | "
              f"{t_tether[0] / 1e3:9.2f} {t_moorpy[0] / 1e3:9.2f} {t_tether[1] / 1e3:9.2f} {t_moorpy[1] / 1e3:9.2f}")
        rows.append([dx, lines_only, r_moorpy, *t_tether, *t_moorpy])
    with open(out / "oc3_offsets.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["offset [m]", "Tether restoring, lines [N]", "MoorPy restoring [N]",
                    *[f"Tether line{i} fairlead [N]" for i in (1, 2, 3)],
                    *[f"MoorPy line{i} fairlead [N]" for i in (1, 2, 3)]])
        w.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    x = [r[0] for r in rows]
    top.plot(x, [r[1] / 1e3 for r in rows], "o-", label="Tether")
    top.plot(x, [r[2] / 1e3 for r in rows], "x--", label="MoorPy")
    top.set_ylabel("restoring force of the lines [kN]")
    top.legend()
    top.grid(True)
    for i, style in zip(range(3), ["-", "--", ":"]):
        bottom.plot(x, [r[3 + i] / 1e3 for r in rows], "o" + style, label=f"line{i + 1} Tether")
        bottom.plot(x, [r[6 + i] / 1e3 for r in rows], "x" + style, label=f"line{i + 1} MoorPy")
    bottom.set_xlabel("surge offset from equilibrium [m]")
    bottom.set_ylabel("fairlead tension [kN]")
    bottom.legend(ncol=2)
    bottom.grid(True)
    fig.suptitle("OC3-Hywind: surge offset curve, Tether and MoorPy")
    fig.tight_layout()
    fig.savefig(out / "oc3_offsets.png", dpi=120)
    print(f"\nwrote {out / 'oc3_offsets.csv'} and {out / 'oc3_offsets.png'}")


if __name__ == "__main__":
    main()
