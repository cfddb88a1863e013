"""The Python module's two speed figures, printed (README and docs/python.md quote them):

(a) a run from Python against the same run by the command line without frames: the thread CPU
    time per step of `Simulation.run` sampling once a simulated second, against the physics'
    CPU time per step that `tether record --timing --log-hz 1` reports (the recorder's calls
    taken out); goal: within 5 %;
(b) the fixed cost of one small step call: `sim.step()` called in a Python loop on the
    spring-mass scene, less the step itself (measured as `sim.step(N)` / N); goal: under 2 µs.

CPU time, not wall time, for (a): the machine may be shared. Each figure is the best of
`--repeat` runs, the two kinds interleaved. The default run, an hour of `moored_buoy` at its
50 ms RK4 step (72,000 steps, about 2 s of CPU), is long enough that the clocks' resolution and
the first steps' cold caches are lost in it; a minute (1,200 steps, 0.04 s of CPU) is not.

    python python/bench.py [--tether PATH] [--scene scenes/moored_buoy.ron] [--duration 3600]
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

# The installed package, not its sources beside this script (which lack the native module).
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != Path(__file__).resolve().parent]
import tether  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def cli_us_per_step(binary: str, scene: Path, duration: float) -> float:
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run(
            [binary, "record", str(scene), "-o", os.path.join(out, "run.rrd"), "--duration", str(duration),
             "--log-hz", "1", "--timing"],
            capture_output=True, text=True, check=True,
        )
    found = re.search(r"physics [0-9.]+ s \([0-9]+%, ([0-9.]+) µs per step\)", done.stderr)
    assert found, done.stderr
    return float(found.group(1))


def python_us_per_step(scene: Path, duration: float) -> float:
    sim = tether.load(scene)
    steps = round(duration / sim.dt)
    start = time.thread_time()
    sim.run(duration, rate=1.0)
    return 1e6 * (time.thread_time() - start) / steps


def step_call_us(scene: Path, calls: int) -> "tuple[float, float]":
    sim = tether.load(scene)
    step = sim.step
    start = time.perf_counter()
    for _ in range(calls):
        step()
    per_call = (time.perf_counter() - start) / calls
    sim.reset()
    start = time.perf_counter()
    sim.step(calls)
    per_step = (time.perf_counter() - start) / calls
    return 1e6 * per_call, 1e6 * per_step


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tether", default=os.environ.get("TETHER_BIN", "tether"), help="the tether binary")
    parser.add_argument("--scene", type=Path, default=REPO / "scenes/moored_buoy.ron")
    parser.add_argument("--duration", type=float, default=3600.0, help="simulated seconds of (a)")
    parser.add_argument("--calls", type=int, default=200_000, help="step() calls of (b)")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()

    # Interleaved, so that a change in the machine's load falls on both alike.
    cli, python = float("inf"), float("inf")
    for _ in range(args.repeat):
        cli = min(cli, cli_us_per_step(args.tether, args.scene, args.duration))
        python = min(python, python_us_per_step(args.scene, args.duration))
    print(f"(a) {args.scene.name}, {args.duration:g} s: Python run {python:.3f} µs/step, "
          f"CLI without frames {cli:.3f} µs/step: Python/CLI = {python / cli:.3f} (goal ≤ 1.05)")

    spring = REPO / "scenes/spring_mass.ron"
    best = min((step_call_us(spring, args.calls) for _ in range(args.repeat)), key=lambda r: r[0] - r[1])
    call, step = best
    print(f"(b) spring_mass: one step() call {call:.3f} µs, of which the step {step:.3f} µs: "
          f"fixed cost {call - step:.3f} µs (goal < 2 µs)")


if __name__ == "__main__":
    main()
