#!/usr/bin/env python3
"""A measured-style fairlead tension record of the driven chain, made by MoorDyn v2, for Tether's
parameter fitting ("calibration") to recover the line's normal drag coefficient from.

The case is the driven chain of validation/moordyn/compare.py (its input, constants and helpers
are imported from there; scenes/chain_forced_surge.ron is the same chain in Tether): 250 m of
36 mm studless chain from an anchor at (-237, 0, -50) on a frictionless seabed in 50 m of still
water to a fairlead at (0, 0, -1) driven x = 2 sin(2 pi t / 10) m, N = 40 segments, RK2 at
dtM = 0.01 s / ceil(1.25 N) = 2e-4 s, coupled every 0.01 s with
Step(x(t), (x(t + dt) - x(t)) / dt, t, dt), for 60 s. The one change is the line type's normal
drag coefficient C_dn (default 1.6 instead of compare.py's 2.4); the normal added mass stays
C_an = 1.0, and C_dt = 1.15, C_at = 0.5, damping ratio 0.8 as there.

The record is the magnitude of the end node force on the coupled point (moordyn.GetPointForce,
the quantity compare.py compares with Tether's end2 tension), sampled every 0.05 s from 0 to
60 s inclusive, written as CSV with the header `time_s,fairlead_tension_N`.

Data source: MoorDyn v2.7.2 (the Python package `moordyn` from PyPI), run on this machine on
2026-11-27 with

    validation/calibration/run                      # writes moordyn_chain_cdn1.6.csv here
    validation/calibration/run --cdn 2.4 --out /tmp/moordyn_chain_cdn2.4.csv

(validation/calibration/run makes the Python environment; it is validation/moordyn/run's.)
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # no __pycache__ in validation/moordyn
sys.path.insert(0, str(HERE.parent / "moordyn"))

from compare import (ANCHOR, COUPLING_DT, DURATION, FAIRLEAD, INPUT, SECOND_HALF,  # noqa: E402
                     extremes, fairlead_x, moordyn_dtm, moordyn_version, norm)

SEGMENTS = 40
SAMPLE_EVERY = 5  # coupling steps: 0.05 s
LINE_TYPE = "chain 0.0648 25.7904 110678400 -0.8 0 {cdn} 1 1.15 0.5"  # compare.py's, C_dn a field


def case_input(cdn: float) -> str:
    """compare.py's MoorDyn input at N = 40 with the line type's C_dn set to `cdn`."""
    original = LINE_TYPE.format(cdn=2.4)
    assert INPUT.count(original) == 1, "compare.py's line type changed; update LINE_TYPE"
    return INPUT.replace(original, LINE_TYPE.format(cdn=repr(float(cdn)))).format(
        n=SEGMENTS, dtm=moordyn_dtm(SEGMENTS), ax=ANCHOR[0], ay=ANCHOR[1], az=ANCHOR[2],
        fx=FAIRLEAD[0], fy=FAIRLEAD[1], fz=FAIRLEAD[2])


def record(cdn: float) -> tuple[list[tuple[float, float]], float, float]:
    """((t [s], end node force [N]) every 0.05 s, MoorDyn's CPU time [s] of Init, of the 60 s)."""
    import moordyn

    with tempfile.TemporaryDirectory() as work:
        case = Path(work) / "chain.txt"
        case.write_text(case_input(cdn))
        cwd = os.getcwd()
        os.chdir(work)  # outputs are disabled, but keep anything MoorDyn writes out of the tree
        try:
            start = time.process_time()
            system = moordyn.Create(str(case))
            moordyn.Init(system, list(FAIRLEAD), [0.0, 0.0, 0.0])
            init_cpu = time.process_time() - start
            point = moordyn.GetPoint(system, 2)
            rows = [(0.0, norm(moordyn.GetPointForce(point)))]
            start = time.process_time()
            for k in range(round(DURATION / COUPLING_DT)):
                t, t_next = k * COUPLING_DT, (k + 1) * COUPLING_DT
                x, x_next = fairlead_x(t), fairlead_x(t_next)
                moordyn.Step(system, [x, FAIRLEAD[1], FAIRLEAD[2]], [(x_next - x) / COUPLING_DT, 0.0, 0.0], t,
                             COUPLING_DT)
                if (k + 1) % SAMPLE_EVERY == 0:
                    rows.append((t_next, norm(moordyn.GetPointForce(point))))
            step_cpu = time.process_time() - start
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return rows, init_cpu, step_cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cdn", type=float, default=1.6, help="the line type's normal drag coefficient C_dn")
    parser.add_argument("--out", default=None,
                        help="the CSV to write (default: validation/calibration/moordyn_chain_cdn<C_dn>.csv)")
    args = parser.parse_args()
    out = Path(args.out) if args.out else HERE / f"moordyn_chain_cdn{args.cdn:g}.csv"

    print(f"MoorDyn {moordyn_version()}, N = {SEGMENTS}, C_dn = {args.cdn:g} ...", file=sys.stderr, flush=True)
    rows, init_cpu, step_cpu = record(args.cdn)
    with out.open("w") as f:
        f.write("time_s,fairlead_tension_N\n")
        f.writelines(f"{t:.6f},{v:.3f}\n" for t, v in rows)
    peak, low = extremes([r[0] for r in rows], [r[1] for r in rows], SECOND_HALF)
    print(f"C_dn = {args.cdn:g}: {len(rows)} rows, over t >= {SECOND_HALF:g} s peak {peak / 1e3:.2f} kN, "
          f"min {low / 1e3:.2f} kN; MoorDyn CPU {init_cpu:.1f} s init + {step_cpu:.1f} s for {DURATION:g} s; wrote {out}")


if __name__ == "__main__":
    main()
