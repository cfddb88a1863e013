#!/usr/bin/env python3
"""MoorDyn v2 against Tether on the driven chain (issue 24, check 7; docs/dynamic-lines.md).

The chain of scenes/chain_forced_surge.ron (36 mm studless chain, 250 m, anchor at (-237, 0, -50)
on a frictionless seabed in 50 m of still water, fairlead at (0, 0, -1)) is driven at the
fairlead x = A sin(2 pi t / T) (A = 2 m, T = 10 s) for 60 s:

* MoorDyn 2.7.2 (the Python package `moordyn`) at N = 10, 20, 40, 80, 160 segments, RK2 at
  dtM = 0.01 s / ceil(1.25 N) (2e-4 s at N = 40, as in its notes), coupled every 0.01 s with
  the fairlead moved exactly along the prescribed path: Step(x(t), (x(t+dt) - x(t)) / dt, t, dt);
* Tether: `tether record <scene> -o <rrd> --log-hz 100`, the fairlead tension read back from the
  recording with Rerun's dataframe API (`plots/catenary`, series "<line> end2" for today's
  quasi-static catenary; both are options, as is the scene, which may name one file per segment
  count with "{n}").

Like with like: a catenary's fairlead tension is the line's tension at s = L; MoorDyn's end node
force (GetPointForce on the coupled point: the top segment's tension plus the end node's
half-segment of wet weight, no inertia) is the same quantity, while GetLineFairTen is the top
segment's tension, at s = L - l/2. Both are kept; the table compares the end node force.

Prints a table (peak and minimum fairlead tension over the second half, 30-60 s, per N, MoorDyn
against Tether, with MoorDyn's CPU time) and writes into --out: one CSV per MoorDyn run (reused
on the next run unless --rerun), tether.csv, table.md and tension.png (the time series).
Run through validation/moordyn/run, which makes the Python environment.
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

# The driven chain (docs/dynamic-lines.md, "MoorDyn reference"; the notes of issue 24).
AMPLITUDE = 2.0  # m
PERIOD = 10.0  # s
DURATION = 60.0  # s
COUPLING_DT = 0.01  # s
FAIRLEAD = (0.0, 0.0, -1.0)  # m, at t = 0
ANCHOR = (-237.0, 0.0, -50.0)  # m
SECOND_HALF = 30.0  # s: the statistics start here, after the start-up transient

INPUT = """---------------------- LINE TYPES ------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.0648 25.7904 110678400 -0.8 0 2.4 1 1.15 0.5
---------------------- POINTS ----------------------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed {ax} {ay} {az} 0 0 0 0
2 Coupled {fx} {fy} {fz} 0 0 0 0
---------------------- LINES -----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 250 {n} -
---------------------- OPTIONS ---------------------------------------
RK2 tScheme
{dtm:.6e} dtM
9.80665 g
1025 WtrDnsty
50 WtrDpth
3000000 kBot
300000 cBot
0 FrictionCoefficient
0 ICgenDynamic
1 dtIC
300 TmaxIC
5 CdScaleIC
1e-08 threshIC
0 writeLog
1 disableOutput
1 disableOutTime
---------------------- need this line --------------------------------
"""


def quasi_static_tension(x: float) -> float:
    """Fairlead tension [N] of the elastic catenary on a frictionless seabed (PHYSICS.md §3, §7)
    with the fairlead at surge x [m]: Newton on the horizontal and vertical fairlead forces H, V,
    with L_B = L − V/w on the bottom,
    span = L_B + (H/w) asinh(V/H) + H L/EA, height = (H/w)(√(1 + (V/H)²) − 1) + V²/(2 EA w);
    an independent check of Tether's quasi-static line (the chain of the MoorDyn input)."""
    ea, wet = 110678400.0, (25.7904 - 1025.0 * math.pi / 4 * 0.0648**2) * 9.80665
    length, span, height = 250.0, FAIRLEAD[0] + x - ANCHOR[0], FAIRLEAD[2] - ANCHOR[2]

    def residual(h: float, v: float) -> tuple[float, float]:
        grounded = length - v / wet
        return (grounded + h / wet * math.asinh(v / h) + h * length / ea - span,
                h / wet * (math.sqrt(1.0 + (v / h) ** 2) - 1.0) + v * v / (2.0 * ea * wet) - height)

    h, v = 3e4, wet * 100.0
    for _ in range(100):
        r, e = residual(h, v), 1e-3
        a, b = residual(h + e, v), residual(h, v + e)
        j = ((a[0] - r[0]) / e, (b[0] - r[0]) / e, (a[1] - r[1]) / e, (b[1] - r[1]) / e)
        det = j[0] * j[3] - j[1] * j[2]
        dh, dv = (-r[0] * j[3] + r[1] * j[1]) / det, (-j[0] * r[1] + j[2] * r[0]) / det
        h, v = h + dh, v + dv
        if abs(dh) + abs(dv) < 1e-8:
            break
    assert 0.0 < v / wet < length, "the closed form is for a line with part of it on the bottom"
    return math.hypot(h, v)


def fairlead_x(t: float) -> float:
    """The prescribed surge [m] at time t [s]."""
    return FAIRLEAD[0] + AMPLITUDE * math.sin(2.0 * math.pi * t / PERIOD)


def moordyn_dtm(n: int) -> float:
    """MoorDyn's internal step [s]: 0.01 s / ceil(1.25 N), the notes' 2e-4 s at N = 40 scaled as
    the segment length (the axial wave crosses a segment in l / sqrt(EA / lambda) = 3.0 ms at N = 40)."""
    return COUPLING_DT / math.ceil(1.25 * n)


def run_moordyn(n: int, path: Path) -> dict:
    """Runs MoorDyn at `n` segments; writes (t, end node force, top segment tension) [s, N, N]."""
    import moordyn

    dtm = moordyn_dtm(n)
    with tempfile.TemporaryDirectory() as work:
        case = Path(work) / "chain.txt"
        case.write_text(INPUT.format(n=n, dtm=dtm, ax=ANCHOR[0], ay=ANCHOR[1], az=ANCHOR[2],
                                     fx=FAIRLEAD[0], fy=FAIRLEAD[1], fz=FAIRLEAD[2]))
        cwd = os.getcwd()
        os.chdir(work)  # MoorDyn writes nothing here (outputs disabled), but keep it out of the tree
        try:
            start = time.process_time()
            system = moordyn.Create(str(case))
            moordyn.Init(system, list(FAIRLEAD), [0.0, 0.0, 0.0])
            init_cpu = time.process_time() - start
            line, point = moordyn.GetLine(system, 1), moordyn.GetPoint(system, 2)
            rows = [(0.0, norm(moordyn.GetPointForce(point)), moordyn.GetLineFairTen(line))]
            steps = round(DURATION / COUPLING_DT)
            start = time.process_time()
            for k in range(steps):
                t, t_next = k * COUPLING_DT, (k + 1) * COUPLING_DT
                x, x_next = fairlead_x(t), fairlead_x(t_next)
                moordyn.Step(system, [x, FAIRLEAD[1], FAIRLEAD[2]], [(x_next - x) / COUPLING_DT, 0.0, 0.0], t,
                             COUPLING_DT)
                rows.append((t_next, norm(moordyn.GetPointForce(point)), moordyn.GetLineFairTen(line)))
            step_cpu = time.process_time() - start
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    with path.open("w", newline="") as f:
        out = csv.writer(f)
        out.writerow([f"# moordyn {moordyn_version()} N={n} dtM={dtm:.6e} init_cpu_s={init_cpu:.3f} "
                      f"step_cpu_s={step_cpu:.3f}"])
        out.writerow(["t_s", "end_node_force_N", "fair_ten_N"])
        out.writerows(rows)
    return read_moordyn(path)


def moordyn_version() -> str:
    from importlib.metadata import version

    return version("moordyn")


def read_moordyn(path: Path) -> dict:
    with path.open() as f:
        header = f.readline().strip().lstrip("# ").split()
        meta = dict(item.split("=", 1) for item in header if "=" in item)
        rows = list(csv.reader(f))[1:]
    columns = list(zip(*[[float(v) for v in row] for row in rows]))
    return {"n": int(meta["N"]), "dtm": float(meta["dtM"]), "init_cpu": float(meta["init_cpu_s"]),
            "step_cpu": float(meta["step_cpu_s"]), "t": columns[0], "end": columns[1], "fair": columns[2]}


def norm(v) -> float:
    return math.sqrt(sum(c * c for c in v))


def run_tether(binary: Path, scene: Path, rrd: Path, extra: list[str]) -> None:
    command = [str(binary), "record", str(scene), "-o", str(rrd), "--log-hz", "100", "--duration", str(DURATION),
               *extra]
    print("  $", " ".join(command), file=sys.stderr)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)


def read_tether(rrd: Path, entity: str, series: str) -> tuple[list[float], list[float]]:
    """(t [s], the scalar series named `series` of `entity` [N]) from a Tether recording, through
    Rerun's dataframe API (a local server over the one file)."""
    import pyarrow as pa
    import rerun as rr

    entity = "/" + entity.strip("/")
    with rr.server.Server(host="127.0.0.1", datasets={"tether": [str(rrd)]}) as server:
        dataset = server.client().get_dataset("tether").filter_contents([entity])
        static = dataset.reader(index=None).to_arrow_table()
        names_column = f"{entity}:SeriesLines:names"
        if names_column not in static.column_names:
            raise SystemExit(f"{rrd}: no series names at {entity} (columns: {static.column_names})")
        names = [name for row in static.column(names_column).to_pylist() if row for name in row]
        if series not in names:
            raise SystemExit(f"{rrd}: no series {series!r} at {entity} (series: {names})")
        slot = names.index(series)
        table = dataset.reader(index="sim_time").to_arrow_table()
    values_column = f"{entity}:Scalars:scalars"
    times = table.column("sim_time")
    if pa.types.is_duration(times.type) or pa.types.is_timestamp(times.type):
        t = [v.total_seconds() if hasattr(v, "total_seconds") else v / 1e9 for v in times.to_pylist()]
    else:
        t = [float(v) for v in times.to_pylist()]
    pairs = sorted((ti, row[slot]) for ti, row in zip(t, table.column(values_column).to_pylist()) if row)
    return [p[0] for p in pairs], [p[1] for p in pairs]


def extremes(t, values, start: float = SECOND_HALF) -> tuple[float, float]:
    """(peak, minimum) of `values` over t ≥ start."""
    kept = [v for ti, v in zip(t, values) if ti >= start - 1e-9]
    return max(kept), min(kept)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--segments", default="10,20,40,80,160", help="MoorDyn's segment counts N (comma-separated)")
    parser.add_argument("--vary-segments", action="store_true",
                        help="run Tether's scene once per N, its dynamic line's `segments` set to N")
    parser.add_argument("--scene", default="scenes/chain_forced_surge.ron",
                        help="Tether's scene, relative to the repository; with '{n}', one file per N")
    parser.add_argument("--line-model", default="quasi-static",
                        help="what Tether's line is, for the table and the chart (quasi-static, dynamic, ...)")
    parser.add_argument("--entity", default="plots/catenary", help="the recording's entity of the fairlead tension")
    parser.add_argument("--series", default="chain end2", help="the series at --entity that is the fairlead tension")
    parser.add_argument("--tether", default=None,
                        help="the tether binary (default: $CARGO_TARGET_DIR or target/, release/tether)")
    parser.add_argument("--record-arg", action="append", default=[], help="one more argument to `tether record`")
    parser.add_argument("--out", default="validation/moordyn/out", help="output folder, relative to the repository")
    parser.add_argument("--rerun", action="store_true", help="run MoorDyn again even where its CSV exists")
    parser.add_argument("--no-tether", action="store_true", help="MoorDyn only")
    args = parser.parse_args()

    segments = [int(n) for n in args.segments.split(",")]
    out = REPO / args.out
    out.mkdir(parents=True, exist_ok=True)

    moordyn = {}
    for n in segments:
        path = out / f"moordyn_n{n}.csv"
        if path.exists() and not args.rerun:
            moordyn[n] = read_moordyn(path)
        else:
            print(f"MoorDyn N = {n} (dtM = {moordyn_dtm(n):.3e} s) ...", file=sys.stderr, flush=True)
            moordyn[n] = run_moordyn(n, path)

    tether = {}  # N (None: one scene for every N) -> (t, tension)
    if not args.no_tether:
        binary = Path(args.tether) if args.tether else \
            Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target")) / "release" / "tether"
        if not binary.exists():
            raise SystemExit(f"no tether binary at {binary}: `cargo build --release --no-default-features` "
                             "(or pass --tether)")
        for n in segments if ("{n}" in args.scene or args.vary_segments) else [None]:
            scene = REPO / args.scene.replace("{n}", str(n))
            if args.vary_segments:
                # The scene's dynamic line at N segments, written beside the outputs.
                text = scene.read_text()
                if "segments:" not in text:
                    sys.exit(f"--vary-segments: {scene} declares no dynamic line (no `segments:`)")
                varied = out / f"{scene.stem}_n{n}.ron"
                varied.write_text(re.sub(r"segments: *\d+", f"segments: {n}", text))
                scene = varied
            rrd = out / (f"tether_n{n}.rrd" if n else "tether.rrd")
            run_tether(binary, scene, rrd, args.record_arg)
            tether[n] = read_tether(rrd, args.entity, args.series)
        with (out / "tether.csv").open("w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["n", "t_s", "fairlead_tension_N"])
            for n, (t, v) in tether.items():
                w.writerows((n or "", ti, vi) for ti, vi in zip(t, v))

    qs_peak, qs_min, qs_rest = (quasi_static_tension(x) for x in (AMPLITUDE, -AMPLITUDE, 0.0))
    lines = [
        f"Driven chain, x = {AMPLITUDE:g} sin(2πt/{PERIOD:g}) m, {DURATION:g} s; fairlead tension over t ≥ "
        f"{SECOND_HALF:g} s [kN]. MoorDyn: end node force (s = L) and top segment tension (FairTen, "
        f"s = L − l/2); Tether: {args.line_model} ({args.scene}).",
        f"The quasi-static catenary's closed form (frictionless seabed): {qs_peak / 1e3:.2f} kN at x = "
        f"+{AMPLITUDE:g} m, {qs_min / 1e3:.2f} kN at −{AMPLITUDE:g} m, {qs_rest / 1e3:.2f} kN at 0 "
        f"(MoorDyn's end node at rest: " + ", ".join(f"N = {n}: {moordyn[n]['end'][0] / 1e3:.2f}" for n in segments)
        + " kN).",
        "",
        "| N | dtM [s] | MoorDyn peak | MoorDyn min | FairTen peak | FairTen min | Tether peak | Tether min "
        "| MoorDyn peak / Tether peak | MoorDyn CPU: init + 60 s [s] |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for n in segments:
        m = moordyn[n]
        peak, low = extremes(m["t"], m["end"])
        fpeak, flow = extremes(m["t"], m["fair"])
        series = tether.get(n) or tether.get(None)
        if series:
            tpeak, tlow = extremes(*series)
            tcols = f"{tpeak / 1e3:.2f} | {tlow / 1e3:.2f} | {peak / tpeak:.3f}"
        else:
            tcols = "– | – | –"
        lines.append(f"| {n} | {m['dtm']:.2e} | {peak / 1e3:.2f} | {low / 1e3:.2f} | {fpeak / 1e3:.2f} | "
                     f"{flow / 1e3:.2f} | {tcols} | {m['init_cpu']:.1f} + {m['step_cpu']:.1f} |")
    table = "\n".join(lines)
    print(table)
    (out / "table.md").write_text(table + "\n")
    chart(moordyn, tether, args.line_model, out / "tension.png")
    print(f"\nwrote {out / 'table.md'}, {out / 'tension.png'}, the CSVs and recordings in {out}", file=sys.stderr)


def chart(moordyn: dict, tether: dict, line_model: str, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (full, zoom) = plt.subplots(2, 1, figsize=(11, 8), constrained_layout=True)
    for ax, (t0, t1) in ((full, (0.0, DURATION)), (zoom, (DURATION - 2 * PERIOD, DURATION))):
        for n, m in moordyn.items():
            kept = [(t, v) for t, v in zip(m["t"], m["end"]) if t0 <= t <= t1]
            ax.plot([p[0] for p in kept], [p[1] / 1e3 for p in kept], lw=1.0, label=f"MoorDyn N = {n}")
        for n, (t, v) in tether.items():
            kept = [(ti, vi) for ti, vi in zip(t, v) if t0 <= ti <= t1]
            label = f"Tether {line_model}" + (f" N = {n}" if n else "")
            ax.plot([p[0] for p in kept], [p[1] / 1e3 for p in kept], "k--", lw=1.5, label=label)
        ax.set_xlim(t0, t1)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("fairlead tension [kN]")
        ax.grid(alpha=0.3)
    full.set_title(f"Driven chain: fairlead x = {AMPLITUDE:g} sin(2πt/{PERIOD:g}) m (MoorDyn: end node force)")
    full.legend(ncol=3, fontsize=8)
    zoom.set_title("the last two periods")
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
