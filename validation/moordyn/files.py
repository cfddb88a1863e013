#!/usr/bin/env python3
"""MoorDyn input files run by both codes (issue 32, checks 1-3; docs/moordyn-files.md).

For each case (a MoorDyn input file under validation/moordyn/inputs/ and a surge of its coupled
points x = x0 + A sin(2 pi t / T)):

* MoorDyn 2.7.2 (the Python package) reads the file, relaxes it to its initial state
  (moordyn.Init: the file's own initial-condition options), then is stepped for 60 s, coupled
  every 0.01 s with the coupled points moved exactly along the prescribed path;
* Tether imports the same file (`tether import`), the coupled points' kinematic bodies are
  given the same motion, and `tether record` runs it; the line end tensions are read back from
  the recording (`plots/catenary`, series "<line> end1" / "<line> end2").

Like with like: Tether's series are the force each line end passes to what it ends on (its end
segment's tension plus the end node's half-segment wet weight, drag and seabed force); MoorDyn's
is the net force on the line's end node, GetLineNodeForce(line, 0 | N) (what it passes to its
point: Line::getEndState), which for a point with one line is GetPointForce.

Static start (check 3): after moordyn.Init against Tether's imported initial state: each line
end's tension (MoorDyn's end node force, Tether's `tether forces --json`), every node of every
line (MoorDyn's GetLineNodePos, the `nodes` of `tether forces --json`: the largest distance, as a
share of the line's unstretched length) and the free points' and bodies' positions (MoorDyn's
GetPointPos/GetBodyPos, the imported scene's).

Prints two tables and writes them, with the CSVs, into --out (table.md). Run through
validation/moordyn/run-files, which makes the Python environment (that of validation/moordyn/run).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from compare import extremes, read_tether  # noqa: E402  (the recording reader of the driven chain)

REPO = Path(__file__).resolve().parents[2]
INPUTS = REPO / "validation" / "moordyn" / "inputs"
DURATION = 60.0  # s
COUPLING_DT = 0.01  # s
SECOND_HALF = 30.0  # s


@dataclass
class Case:
    file: str
    what: str
    amplitude: tuple[float, float, float]  # m, of every coupled point
    period: float  # s
    dtm: float | None = None  # s: MoorDyn's step when the file's CFL choice diverges (ζ = 1 lines)
    moordyn_file: str | None = None  # what MoorDyn reads, when it cannot read `file` (a v1 file)


CASES = [
    Case("WD0050_Chain.txt", "a chain from an anchor to a coupled fairlead, 50 m of water (tests/Mooring)",
         (2.0, 0.0, 0.0), 10.0, 2e-4),
    Case("WD0050_Chain_frictionless.txt", "the same without seabed friction (FrictionCoefficient 0)",
         (2.0, 0.0, 0.0), 10.0, 2e-4),
    Case("WD0050_Chain_coulomb.txt", "the same with FricDamp 3323300 N s/m: Coulomb friction within 1 cm/s of sliding",
         (2.0, 0.0, 0.0), 10.0, 2e-4),
    Case("lines.txt", "OC3-Hywind's three lines, coupled fairleads, 320 m (tests/Mooring)", (5.0, 0.0, 0.0), 20.0),
    Case("local_euler_hanging.txt", "two chains joined by a free point between two coupled points (tests/Mooring/local_euler)",
         (5.0, 0.0, 0.0), 20.0, 1e-4),
    Case("IEA-15-240-RWT-UMaineSemi_MoorDyn_v1.dat", "the IEA 15 MW semi's three chains in OpenFAST's v1 layout "
         "(MoorDyn reads its v2 transcription)", (5.0, 0.0, 0.0), 20.0,
         moordyn_file="IEA-15-240-RWT-UMaineSemi_MoorDyn_v1_as_v2.dat"),
    Case("free_buoy.dat", "a free body on OC3's lines, pulled by a rope from a coupled point (example/body.txt, body made free)",
         (5.0, 0.0, 0.0), 20.0),
]


def norm(v) -> float:
    return math.sqrt(sum(c * c for c in v))


def surge(case: Case, x0, t: float) -> list[float]:
    s = math.sin(2.0 * math.pi * t / case.period)
    return [x0[i] + case.amplitude[i] * s for i in range(3)]


def run_moordyn(case: Case, out: Path) -> dict:
    """MoorDyn on the file: its initial state and each line end's force over time."""
    import moordyn

    with tempfile.TemporaryDirectory() as work:
        read = case.moordyn_file or case.file
        for f in INPUTS.glob(read + "*"):  # the file and its initial-condition file, if any
            shutil.copy(f, work)
        cwd = os.getcwd()
        os.chdir(work)
        try:
            system = moordyn.Create(read)
            if case.dtm:
                moordyn.SetDt(system, case.dtm)
            points = [moordyn.GetPoint(system, i + 1) for i in range(moordyn.GetNumberPoints(system))]
            coupled = [p for p in points if moordyn.GetPointType(p) == moordyn.POINT_TYPE_COUPLED]
            starts = [list(moordyn.GetPointPos(p)) for p in coupled]
            x = [c for s in starts for c in s]
            start = time.process_time()
            moordyn.Init(system, x, [0.0] * len(x))
            init_cpu = time.process_time() - start
            lines = [moordyn.GetLine(system, i + 1) for i in range(moordyn.GetNumberLines(system))]

            def ends() -> list[float]:
                row = []
                for line in lines:
                    n = moordyn.GetLineN(line)
                    row += [norm(moordyn.GetLineNodeForce(line, 0)), norm(moordyn.GetLineNodeForce(line, n))]
                return row

            static = {
                "ends": ends(),
                "nodes": [[list(moordyn.GetLineNodePos(line, i)) for i in range(moordyn.GetLineN(line) + 1)]
                          for line in lines],
                "lengths": [moordyn.GetLineUnstretchedLength(line) for line in lines],
                "free_points": {f"point{i + 1}": list(moordyn.GetPointPos(p)) for i, p in enumerate(points)
                                if moordyn.GetPointType(p) == moordyn.POINT_TYPE_FREE},
                "free_bodies": {f"body{i + 1}": list(moordyn.GetBodyPos(moordyn.GetBody(system, i + 1)))
                                for i in range(moordyn.GetNumberBodies(system))
                                if moordyn.GetBodyType(moordyn.GetBody(system, i + 1)) == moordyn.BODY_TYPE_FREE},
                "single_point_check": [(norm(moordyn.GetPointForce(p)), moordyn.GetPointNAttached(p)) for p in coupled],
            }
            rows = [[0.0] + static["ends"]]
            free_points = [(f"point{i + 1}", p) for i, p in enumerate(points)
                           if moordyn.GetPointType(p) == moordyn.POINT_TYPE_FREE]
            free_bodies = [(f"body{i + 1}", moordyn.GetBody(system, i + 1)) for i in range(moordyn.GetNumberBodies(system))
                           if moordyn.GetBodyType(moordyn.GetBody(system, i + 1)) == moordyn.BODY_TYPE_FREE]
            settled = {name: [0.0, 0.0, 0.0] for name, _ in free_points + free_bodies}
            # On the seabed: below the lowest point (the files' anchors lie on it; a node there sinks
            # into it by its weight over kBot d).
            seabed = min(moordyn.GetPointPos(p)[2] for p in points)
            sliding = 0.0  # the fastest horizontal speed of a node on the seabed over the second half [m/s]
            samples = 0
            steps = round(DURATION / COUPLING_DT)
            start = time.process_time()
            for k in range(steps):
                t, t_next = k * COUPLING_DT, (k + 1) * COUPLING_DT
                here = [c for s in starts for c in surge(case, s, t)]
                there = [c for s in starts for c in surge(case, s, t_next)]
                velocity = [(b - a) / COUPLING_DT for a, b in zip(here, there)]
                moordyn.Step(system, there, velocity, t, COUPLING_DT)
                rows.append([t_next] + ends())
                if t_next > SECOND_HALF:
                    samples += 1
                    for line in lines:
                        for i in range(1, moordyn.GetLineN(line)):
                            if moordyn.GetLineNodePos(line, i)[2] < seabed:
                                vx, vy, _ = moordyn.GetLineNodeVel(line, i)
                                sliding = max(sliding, math.hypot(vx, vy))
                    for name, p in free_points:
                        settled[name] = [a + b for a, b in zip(settled[name], moordyn.GetPointPos(p))]
                    for name, b in free_bodies:
                        settled[name] = [a + c for a, c in zip(settled[name], moordyn.GetBodyPos(b))]
            static["settled"] = {name: [c / samples for c in v] for name, v in settled.items()}
            step_cpu = time.process_time() - start
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return {"static": static, "rows": rows, "lines": len(lines), "init_cpu": init_cpu, "step_cpu": step_cpu,
            "sliding": sliding}


def tether_scene(binary: Path, case: Case, out: Path) -> Path:
    """`tether import` of the file, the coupled points' kinematic bodies given the surge."""
    imported = out / (Path(case.file).stem + ".ron")
    subprocess.run([str(binary), "import", str(INPUTS / case.file), "-o", str(imported)], check=True,
                   stdout=subprocess.DEVNULL)
    text = imported.read_text()
    moved = text.replace(
        "velocity: Constant((0.0, 0.0, 0.0))",
        f"velocity: Harmonic(amplitude: ({case.amplitude[0]}, {case.amplitude[1]}, {case.amplitude[2]}), "
        f"period: {case.period})")
    driven = out / (Path(case.file).stem + "_driven.ron")
    driven.write_text(moved)
    return driven


def run_tether(binary: Path, case: Case, out: Path, lines: int) -> dict:
    scene = tether_scene(binary, case, out)
    # The imported scene at rest (the driven one's ends start moving: its damping shows at t = 0).
    imported = out / (Path(case.file).stem + ".ron")
    forces = json.loads(subprocess.run([str(binary), "forces", str(imported), "--json"], check=True,
                                       capture_output=True, text=True).stdout)
    ends = []
    for coupling in forces["couplings"][:lines]:
        ends += [norm(coupling["f1"]), norm(coupling["f2"])]
    nodes = [coupling["nodes"] for coupling in forces["couplings"][:lines]]
    bodies = {}
    for match in re.finditer(r'name: "((?:point|body)\d+)",\s*master: Node\(\s*position: \(([^)]*)\)',
                             imported.read_text()):
        bodies[match.group(1)] = [float(v) for v in match.group(2).split(",")]
    rrd = out / (Path(case.file).stem + ".rrd")
    start = time.perf_counter()
    subprocess.run([str(binary), "record", str(scene), "-o", str(rrd), "--log-hz", "100", "--duration",
                    str(DURATION)], check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    series = {}
    for k in range(lines):
        for end in (1, 2):
            series[(k, end)] = read_tether(rrd, "plots/catenary", f"line{k + 1} end{end}")
    return {"ends": ends, "nodes": nodes, "bodies": bodies, "series": series, "wall": wall}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tether", default=None, help="the tether binary (default: $CARGO_TARGET_DIR or target/)")
    parser.add_argument("--out", default="validation/moordyn/out-files", help="output folder, relative to the repository")
    parser.add_argument("--cases", default=None, help="file names to run (comma-separated; default: all)")
    args = parser.parse_args()
    out = REPO / args.out
    out.mkdir(parents=True, exist_ok=True)
    binary = Path(args.tether) if args.tether else \
        Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target")) / "release" / "tether"
    cases = [c for c in CASES if not args.cases or c.file in args.cases.split(",")]

    dynamic = ["| file | line end | MoorDyn peak | Tether peak | Δ peak | MoorDyn min | Tether min | Δ min |",
               "|---|---|---:|---:|---:|---:|---:|---:|"]
    static = ["| file | what | MoorDyn after Init | Tether at import | Δ |", "|---|---|---:|---:|---:|"]
    sliding = ["| file | fastest slide of a grounded node over the second half, MoorDyn [m/s] |", "|---|---:|"]
    worst = 0.0
    for case in cases:
        print(f"{case.file}: MoorDyn ...", file=sys.stderr, flush=True)
        m = run_moordyn(case, out)
        print(f"{case.file}: Tether ...", file=sys.stderr, flush=True)
        t = run_tether(binary, case, out, m["lines"])
        for force, attached in m["static"]["single_point_check"]:
            print(f"  (coupled point force {force / 1e3:.3f} kN, {attached} line(s) attached)", file=sys.stderr)
        times = [r[0] for r in m["rows"]]
        for k in range(m["lines"]):
            for end in (1, 2):
                column = 1 + 2 * k + (end - 1)
                mpeak, mmin = extremes(times, [r[column] for r in m["rows"]], SECOND_HALF)
                tpeak, tmin = extremes(*t["series"][(k, end)], SECOND_HALF)
                dpeak, dmin = tpeak / mpeak - 1.0, tmin / mmin - 1.0
                worst = max(worst, abs(dpeak), abs(dmin))
                dynamic.append(f"| {case.file} | line{k + 1} end{end} | {mpeak / 1e3:.2f} | {tpeak / 1e3:.2f} | "
                               f"{100 * dpeak:+.2f} % | {mmin / 1e3:.2f} | {tmin / 1e3:.2f} | {100 * dmin:+.2f} % |")
                ms, ts = m["static"]["ends"][column - 1], t["ends"][column - 1]
                static.append(f"| {case.file} | line{k + 1} end{end} tension [kN] | {ms / 1e3:.2f} | {ts / 1e3:.2f} | "
                              f"{100 * (ts / ms - 1):+.2f} % |")
        for k, (theirs, mine, length) in enumerate(zip(m["static"]["nodes"], t["nodes"], m["static"]["lengths"])):
            gaps = [math.dist(a, b) for a, b in zip(theirs, mine)]
            worst_node = max(range(len(gaps)), key=gaps.__getitem__)
            static.append(f"| {case.file} | line{k + 1} nodes: largest distance [m] (node {worst_node} of "
                          f"{len(gaps) - 1}) | | | {gaps[worst_node]:.3f} m = {100 * gaps[worst_node] / length:.3f} % of "
                          f"{length:g} m |")
        for name, where in {**m["static"]["free_points"], **m["static"]["free_bodies"]}.items():
            mine = t["bodies"].get(name)
            if mine is None:
                continue
            gap = math.dist(where, mine)
            static.append(f"| {case.file} | {name} position [m] | ({', '.join(f'{c:.2f}' for c in where)}) | "
                          f"({', '.join(f'{c:.2f}' for c in mine)}) | {gap:.3f} m |")
            mean = m["static"]["settled"][name]
            static.append(f"| {case.file} | {name} position [m], MoorDyn's mean over {SECOND_HALF:g}–{DURATION:g} s "
                          f"(the surge is symmetric) | ({', '.join(f'{c:.2f}' for c in mean)}) | "
                          f"({', '.join(f'{c:.2f}' for c in mine)}) | {math.dist(mean, mine):.3f} m |")
        print(f"  MoorDyn CPU {m['init_cpu']:.1f} s init + {m['step_cpu']:.1f} s; Tether record {t['wall']:.1f} s",
              file=sys.stderr)
        if m["sliding"] > 0.0:
            sliding.append(f"| {case.file} | {m['sliding']:.3f} |")
    text = (f"Line end tensions over {SECOND_HALF:g}–{DURATION:g} s [kN], the coupled points surged as each case "
            "says (files.py CASES):\n\n" + "\n".join(dynamic) + "\n\nStatic start:\n\n" + "\n".join(static)
            + f"\n\nLargest relative difference of a peak or minimum: {100 * worst:.2f} %\n\n"
            + "Seabed sliding (MoorDyn's friction on such a node is μ FricDamp v below its Coulomb limit):\n\n"
            + "\n".join(sliding) + "\n")
    print(text)
    (out / "table.md").write_text(text)


if __name__ == "__main__":
    main()
