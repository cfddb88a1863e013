#!/usr/bin/env python3
"""Tether's exports read by MoorDyn and MoorPy (issue 32, checks 4 and 5; docs/moordyn-files.md).

For every shipped scene with lines:

1. `tether equilibrium SCENE --json --write EQ.ron`: the static equilibrium (quasi-static lines,
   PHYSICS.md §3/§7), its line end tensions, and the scene placed there — the scene's seabed
   friction set to 0 first, because MoorPy's `Line.staticSolve` sets a line's friction from its
   anchor's height above the seabed (0 for an anchor on it), so that MoorPy's system solve is
   frictionless;
2. `tether export moordyn EQ.ron -o SCENE.dat`: the MoorDyn v2 file (quasi-static lines at the
   export's default 20 segments);
3. MoorDyn 2.7.2 reads it, relaxes it (moordyn.Init) and runs 1 s with its coupled ends held:
   it must do so without error;
4. MoorPy reads it (`moorpy.System(file=...)`), with its bodies held where Tether's equilibrium put
   them (MoorPy knows a body's volume but not its waterplane, so it cannot float Tether's hulls)
   and the file's FrictionCoefficient given to its lines (MoorPy's reader leaves it out), solves
   the free points' equilibrium and its catenaries; each line end's tension must agree with
   Tether's within 0.1 %. A file with a line end above the water (spread_moored_barge's deck
   fairleads) is solved lowered by that height (run_moorpy: MoorPy reweighs such a line between
   wet and dry by its ends' heights), and MoorPy's tensions as read are shown beside.

    python3 validation/moordyn/exports.py [--tether PATH] [--out DIR]

It makes its own virtual environment (validation/moordyn/.venv-exports, or $EXPORTS_VENV) with
MoorPy and MoorDyn 2.7.2 from PyPI the first time and reruns itself in it.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
VENV = Path(os.environ.get("EXPORTS_VENV", HERE / ".venv-exports"))


def in_venv():
    """Reruns this script in its own virtual environment (made the first time)."""
    python = VENV / "bin" / "python"
    if Path(sys.prefix).resolve() == VENV.resolve():
        return
    if not python.exists():
        print(f"making {VENV} with moorpy and moordyn==2.7.2 from PyPI …", flush=True)
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        subprocess.run([str(python), "-m", "pip", "install", "-q", "moorpy==1.3.0", "moordyn==2.7.2"], check=True)
    os.execv(str(python), [str(python), __file__, *sys.argv[1:]])


def scenes_with_lines() -> list[Path]:
    return sorted(p for p in (REPO / "scenes").glob("*.ron") if "Catenary(" in p.read_text())


def run_moordyn(path: Path) -> str:
    """MoorDyn reads the file, relaxes it and runs 1 s with its coupled bodies and points held."""
    import moordyn

    cwd = os.getcwd()
    os.chdir(path.parent)
    try:
        system = moordyn.Create(path.name)
        x = []
        for i in range(moordyn.GetNumberBodies(system)):
            body = moordyn.GetBody(system, i + 1)
            if moordyn.GetBodyType(body) == moordyn.BODY_TYPE_COUPLED:
                x += list(moordyn.GetBodyPos(body)) + list(moordyn.GetBodyAngle(body))
        for i in range(moordyn.GetNumberPoints(system)):
            point = moordyn.GetPoint(system, i + 1)
            if moordyn.GetPointType(point) == moordyn.POINT_TYPE_COUPLED:
                x += list(moordyn.GetPointPos(point))
        moordyn.Init(system, x, [0.0] * len(x))
        for k in range(100):
            moordyn.Step(system, x, [0.0] * len(x), k * 0.01, 0.01)
        moordyn.Close(system)
        return "ran 1 s"
    finally:
        os.chdir(cwd)


def run_moorpy(path: Path, lowered: bool) -> tuple[list[tuple[float, float]], float]:
    """MoorPy's (TA, TB) per line [N], its bodies held, its free points solved; and how far [m]
    the system was lowered.

    `lowered`: when a line end is above the water, MoorPy 1.3's Line.staticSolve weighs the whole
    line between its wet and its dry weight by its ends' heights (w = w_wet + (w_dry − w_wet)
    (−z_bottom)/(z_top − z_bottom): nearly dry for a line from the seabed to a fairlead just above
    the surface), where Tether's catenary (PHYSICS.md §3, §7) weighs it wet all along. Lowering
    the whole system (every point, body and the seabed) by the highest end's height plus 1 m
    keeps each line's geometry, seabed included, and lets MoorPy weigh it as Tether does."""
    import moorpy as mp

    system = mp.System(file=str(path))
    friction = float(system.MDoptions.get("frictioncoefficient", 0.0))
    for line in system.lineList:
        line.cb = friction
    for body in system.bodyList:
        body.type = 1  # held where the file puts it: Tether's equilibrium
    system.initialize()
    highest = max(max(line.rA[2], line.rB[2]) for line in system.lineList)
    drop = highest + 1.0 if lowered and highest > 0.0 else 0.0
    if drop:
        on_bodies = {id(point) for body in system.bodyList for point in system.pointList
                     if point.number in body.attachedP}
        system.depth += drop
        for body in system.bodyList:
            body.r6[2] -= drop
        for point in system.pointList:
            if id(point) not in on_bodies:
                point.r[2] -= drop
        system.initialize()
    system.solveEquilibrium(tol=1e-9)
    return [(line.TA, line.TB) for line in system.lineList], drop


def main() -> None:
    in_venv()
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tether", default=None, help="the tether binary (default: $CARGO_TARGET_DIR or target/)")
    parser.add_argument("--out", default="validation/moordyn/out-exports", help="output folder, relative to the repository")
    args = parser.parse_args()
    binary = Path(args.tether) if args.tether else \
        Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target")) / "release" / "tether"
    out = REPO / args.out
    out.mkdir(parents=True, exist_ok=True)
    rows = ["| scene | line | Tether end 1 | MoorPy end A | Δ | Tether end 2 | MoorPy end B | Δ | MoorDyn | "
            "MoorPy as read, an end above water: A, B |",
            "|---|---|---:|---:|---:|---:|---:|---:|---|---|"]
    worst = 0.0
    for scene in scenes_with_lines():
        placed, exported = out / f"{scene.stem}_equilibrium.ron", out / f"{scene.stem}.dat"
        frictionless = out / f"{scene.stem}_frictionless.ron"
        text = re.sub(r"line_friction: *[-+0-9.eE]+", "line_friction: 0.0", scene.read_text())
        text = re.sub(r'file: "(?!/)', f'file: "{scene.parent}/', text)  # mesh files from the scene's folder
        frictionless.write_text(text)
        solved = json.loads(subprocess.run([str(binary), "equilibrium", str(frictionless), "--json", "--write", str(placed)],
                                           check=True, capture_output=True, text=True).stdout.split("\nwrote")[0])
        subprocess.run([str(binary), "export", "moordyn", str(placed), "-o", str(exported)], check=True,
                       stdout=subprocess.DEVNULL)
        try:
            moordyn_outcome = run_moordyn(exported)
        except Exception as error:  # noqa: BLE001  (the table says what MoorDyn said)
            moordyn_outcome = f"failed: {error}"
        tensions, drop = run_moorpy(exported, lowered=True)
        as_read = run_moorpy(exported, lowered=False)[0] if drop else [None] * len(tensions)
        lines = [c for c in solved["couplings"] if c["kind"] == "catenary"]
        for coupling, (ta, tb), raw in zip(lines, tensions, as_read):
            t1, t2 = coupling["tension1"], coupling["tension2"]
            d1 = (ta - t1) / max(t1, t2)
            d2 = (tb - t2) / max(t1, t2)
            worst = max(worst, abs(d1), abs(d2))
            rows.append(f"| {scene.stem} | {coupling['name']} | {t1 / 1e3:.3f} | {ta / 1e3:.3f} | {100 * d1:+.3f} % | "
                        f"{t2 / 1e3:.3f} | {tb / 1e3:.3f} | {100 * d2:+.3f} % | {moordyn_outcome} | "
                        + (f"{raw[0] / 1e3:.3f}, {raw[1] / 1e3:.3f} kN ({100 * (raw[1] / t2 - 1):+.1f} %; lowered "
                           f"{drop:.2f} m for the comparison) |" if raw else "|"))
        print(f"{scene.stem}: {moordyn_outcome}", file=sys.stderr, flush=True)
    text = ("Static line end tensions [kN]: `tether equilibrium` against MoorPy on the exported file (Δ relative "
            "to the line's larger end tension):\n\n" + "\n".join(rows)
            + f"\n\nLargest difference: {100 * worst:.3f} %\n")
    print(text)
    (out / "table.md").write_text(text)


if __name__ == "__main__":
    main()
