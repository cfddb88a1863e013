#!/usr/bin/env python3
"""MoorDyn's step against its seabed friction's damper (docs/moordyn-files.md, "Export").

Exports scenes/spread_moored_barge.ron (seabed friction C_B = 1, FricDamp = w l / v_s with
v_s = 0.01 m/s), makes its barge a Coupled body surged 3 sin(2 pi t / 20) m, and runs MoorDyn
2.7.2 for 30 s at several dtM: the chains' largest anchor tension converges once dtM is under
the time the friction's damper takes to stop a node, lambda0 l / (mu FricDamp), the step
`tether export moordyn` writes. MoorDyn's own initial relaxation (its log: "Remaining error
after …") ends differently at different dtM, which moves the result too.

Run with the Python environment validation/moordyn/run makes (MoorDyn 2.7.2) and the tether
binary built (cargo build --release --no-default-features):
    ~/.cache/tether/moordyn-venv/bin/python validation/moordyn/friction_step.py
"""

import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import moordyn

REPO = Path(__file__).resolve().parents[2]
STEPS = [0.0036, 0.0022, 0.0016, 0.0011, 0.0008, 0.00058, 0.0002]  # s


def anchor_peak(path: Path) -> float:
    """The largest anchor tension [N] over 30 s of surge."""
    system = moordyn.Create(str(path))
    body = moordyn.GetBody(system, 1)
    start = list(moordyn.GetBodyPos(body)) + list(moordyn.GetBodyAngle(body))
    moordyn.Init(system, start, [0.0] * 6)
    lines = [moordyn.GetLine(system, i + 1) for i in range(moordyn.GetNumberLines(system))]
    peak = 0.0
    for k in range(3000):
        t = k * 0.01
        x = list(start)
        x[0] = start[0] + 3.0 * math.sin(2.0 * math.pi * (t + 0.01) / 20.0)
        v = [0.0] * 6
        v[0] = (x[0] - start[0] - 3.0 * math.sin(2.0 * math.pi * t / 20.0)) / 0.01
        moordyn.Step(system, x, v, t, 0.01)
        for line in lines:
            peak = max(peak, math.dist(moordyn.GetLineNodeForce(line, 0), (0.0, 0.0, 0.0)))
    moordyn.Close(system)
    return peak


def main() -> None:
    binary = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target")) / "release" / "tether"
    with tempfile.TemporaryDirectory() as work:
        scene = Path(work) / "barge.ron"
        text = (REPO / "scenes" / "spread_moored_barge.ron").read_text()
        scene.write_text(re.sub(r'file: "(?!/)', f'file: "{REPO}/scenes/', text))
        exported = Path(work) / "barge.dat"
        subprocess.run([str(binary), "export", "moordyn", str(scene), "-o", str(exported)], check=True,
                       stdout=subprocess.DEVNULL)
        text = re.sub(r"^1 Free ", "1 Coupled ", exported.read_text(), flags=re.M)
        text = text.replace("0 writeLog", "0 writeLog\n1 disableOutput\n1 disableOutTime")
        written = re.search(r"^(\S+) dtM", text, flags=re.M).group(1)
        print(f"| dtM [s] | largest anchor tension over 30 s [kN] |\n|---:|---:|")
        for step in STEPS:
            case = Path(work) / f"barge_{step}.dat"
            case.write_text(re.sub(r"^\S+ dtM", f"{step} dtM", text, flags=re.M))
            print(f"| {step}{' (written)' if float(written) == step else ''} | {anchor_peak(case) / 1e3:.2f} |",
                  flush=True)
        print(f"\nthe export writes dtM {written} s", file=sys.stderr)


if __name__ == "__main__":
    main()
