"""The `tether` Python module against closed forms and against the `tether` command line."""

import json
import math
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pyarrow.parquet as pq
import pytest

import tether

SPRING = "scenes/spring_mass.ron"
MOORED = "tests/fixtures/moored_on_seabed.ron"


def closed_form(t, k=100.0, c=1.0, m=1.0, x0=0.01):
    """The damped oscillator's displacement from rest, started at x0 at rest (scenes/spring_mass.ron)."""
    w0 = math.sqrt(k / m)
    zeta = c / (2.0 * math.sqrt(k * m))
    wd = w0 * math.sqrt(1.0 - zeta * zeta)
    return np.exp(-zeta * w0 * t) * (x0 * np.cos(wd * t) + zeta * w0 * x0 / wd * np.sin(wd * t))


def test_spring_mass_follows_its_closed_form(repo):
    sim = tether.load(repo / SPRING)
    run = sim.run(5.0, rate=100)
    x = run.position[:, 0, 0] - 1.0
    # dt = 1 ms, ω0 dt = 0.01: the integrator's phase error over 8 periods is ~1e-4 of the 1 cm
    # amplitude; a wrong stiffness or damping is off by millimetres.
    np.testing.assert_allclose(x, closed_form(run.time), atol=2e-5)
    # The spring's tension is k·stretch + c·stretch rate (positive in tension). The force was
    # evaluated with the leapfrog's velocity half a step behind the sampled one: c·a·dt/2 ≤
    # 1 · 100 · 0.01 · 5e-4 = 5e-4 N apart; a damping 10 % off would be 1e-2 N off.
    v = run.velocity[:, 0, 0]
    np.testing.assert_allclose(run.tension[:, 0], 100.0 * x + 1.0 * v, atol=6e-4)
    # Energy: what the damper took plus what is left is what the spring held at the start.
    e = run.energy
    assert e["elastic"][0] == pytest.approx(0.5 * 100.0 * 0.01**2, rel=1e-12)
    # The leapfrog's energy, from its half-step velocities, wobbles by O((ω0 dt)²) = 1e-4 around
    # the exact balance: 1e-3 of the budget; booking the damper's work twice would be off by 30 %.
    np.testing.assert_allclose(e["kinetic"] + e["elastic"] + e["dissipated"], e["elastic"][0], rtol=1e-3)


def test_a_set_parameter_changes_the_motion_as_its_closed_form_says(repo):
    sim = tether.load(repo / SPRING)
    assert sim["couplings.spring.law.stiffness"] == 100.0
    sim["couplings.spring.law.stiffness"] = 400.0
    sim.set("couplings.spring.damping", 2.0)  # the same damping ratio at 4× the stiffness
    assert sim.get("couplings.spring.law.stiffness") == 400.0
    run = sim.run(2.0, rate=200)
    expected = closed_form(run.time, k=400.0, c=2.0)
    np.testing.assert_allclose(run.position[:, 0, 0] - 1.0, expected, atol=4e-5)


def test_parameters_list_what_can_be_set_with_the_windows_labels(repo):
    sim = tether.load(repo / SPRING)
    found = {p.path: p for p in sim.parameters()}
    stiffness = found["couplings.spring.law.stiffness"]
    assert (stiffness.label, stiffness.unit, stiffness.value) == ("spring: stiffness k", "N/m", 100.0)
    assert found["couplings.spring.damping"].unit == "N·s/m"
    # Every listed path is one get and set reach, with the listed value.
    for parameter in found.values():
        assert sim.get(parameter.path) == parameter.value, parameter.path
    sim.set("couplings.spring.law.stiffness", 250.0)
    assert {p.path: p.value for p in sim.parameters()}["couplings.spring.law.stiffness"] == 250.0


def test_shapes_dtypes_and_sampling(repo):
    sim = tether.load(repo / MOORED)
    run = sim.run(1.0, rate=50)
    n, b, c = 51, 1, 4
    assert run.time.shape == (n,)
    for name, shape in [
        ("position", (n, b, 3)),
        ("quaternion", (n, b, 4)),
        ("velocity", (n, b, 3)),
        ("angular_velocity", (n, b, 3)),
        ("point1", (n, c, 3)),
        ("point2", (n, c, 3)),
        ("force1", (n, c, 3)),
        ("force2", (n, c, 3)),
        ("tension", (n, c)),
    ]:
        array = getattr(run, name)
        assert array.shape == shape, name
        assert array.dtype == np.float64 and array.flags.c_contiguous and array.flags.writeable, name
    assert sorted(run.energy) == sorted(["kinetic", "gravity", "elastic", "dissipated", "external_work", "balance"])
    assert all(v.shape == (n,) and v.dtype == np.float64 for v in run.energy.values())
    np.testing.assert_allclose(np.diff(run.time), 0.02, rtol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(run.quaternion, axis=2), 1.0, atol=1e-12)
    assert run.body("buoy")["position"].shape == (n, 3)
    assert run.coupling("m2")["tension"].shape == (n,)
    assert sim.time == pytest.approx(1.0) and sim.step_count == 500
    # Every step when no rate is given; a second run starts where the first ended.
    again = sim.run(0.01)
    assert again.time.shape == (6,) and again.time[0] == pytest.approx(1.0)


def test_equilibrium_equals_the_clis_json(repo, cli):
    cli_data = json.loads(cli("equilibrium", repo / MOORED, "--json").stdout)
    solved = tether.load(repo / MOORED).equilibrium()
    assert solved.data == cli_data
    assert solved.stiffness.shape == (1, 6, 6) and solved.stiffness.dtype == np.float64
    np.testing.assert_array_equal(solved.stiffness[0], np.array(cli_data["bodies"][0]["stiffness"]))
    np.testing.assert_array_equal(solved.position[0], cli_data["bodies"][0]["position"])
    # At rest the lines, the buoyancy spring and gravity balance: the residual is round-off.
    assert solved.residual_force < 1e-3
    # Symmetric lines around a body on the axis: the stiffness is symmetric in x and y.
    k = solved.stiffness[0]
    assert k[0, 0] == pytest.approx(k[1, 1], rel=1e-3) and k[0, 0] > 0


def test_offset_curve_equals_the_clis_csv(repo, cli, tmp_path):
    out = tmp_path / "curve"
    cli("offsets", repo / MOORED, "--body", "buoy", "--direction", "x", "--to", "10", "--steps", "5", "-o", out)
    lines = (tmp_path / "curve.csv").read_text().splitlines()
    header, rows = lines[0].split(","), np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    curve = tether.load(repo / MOORED).offsets("buoy", "x", 10.0, steps=5)
    assert list(curve) == [h.strip('"') for h in header]
    for i, name in enumerate(curve):
        np.testing.assert_allclose(curve[name], rows[:, i], rtol=1e-9, atol=1e-9, err_msg=name)
    # Nothing to restore at equilibrium; the pull back (restoring = −load) grows with the offset.
    restoring = curve["restoring [N]"]
    assert restoring[0] == pytest.approx(0.0, abs=1e-3) and np.all(np.diff(restoring) > 0)


SPEC = """Sweep(
    name: "spring",
    scene: "{scene}",
    duration: 1.0,
    design: Grid,
    factors: [Factor(path: "couplings.spring.law.stiffness", values: {values})],
    metrics: [Metric(name: "max_x", of: Position("mass", X), take: Max)],
)
"""


def test_a_sweeps_table_equals_the_clis_parquet(repo, cli, tmp_path):
    spec = tmp_path / "spec.ron"
    spec.write_text(SPEC.format(scene=repo / SPRING, values="List([50.0, 100.0, 200.0])"))
    cli("sweep", spec, "-o", tmp_path / "cli", "--jobs", "1")
    expected = pq.read_table(tmp_path / "cli" / "results.parquet")
    table = tether.sweep(spec, jobs=1, table="arrow")
    assert table.schema == expected.schema
    assert table.num_rows == 3
    # Every column but the measured CPU time is the same, bit for bit.
    for name in expected.column_names:
        if name != "cpu_s":
            assert table.column(name).equals(expected.column(name)), name
    columns = tether.sweep(spec, tmp_path / "py", jobs=1, table="numpy")
    assert (tmp_path / "py" / "results.parquet").exists()
    assert list(columns) == expected.column_names
    for name in expected.column_names:
        if name != "cpu_s":
            assert list(columns[name]) == expected.column(name).to_pylist(), name
    assert columns["case"].dtype == np.uint64 and columns["max_x"].dtype == np.float64
    # Released at rest 1 cm out, the mass never goes farther: the largest x is the start's 1.01 m
    # (within the first step's move, k·x0·dt²/m = 1e-6 m).
    np.testing.assert_allclose(columns["max_x"], 1.01, atol=2e-6)


def first_error_line(done):
    lines = [line for line in done.stderr.splitlines() if line.startswith("error: ")]
    assert lines, done.stderr
    return lines[0][len("error: "):]


def test_a_broken_scene_raises_the_clis_text(repo, cli, tmp_path):
    text = (repo / SPRING).read_text().replace("mass: 1.0,", "mass: -1.0,")
    broken = tmp_path / "broken.ron"
    broken.write_text(text)
    done = cli("check", broken, check=False)
    assert done.returncode != 0
    with pytest.raises(ValueError) as caught:
        tether.load(broken)
    assert str(caught.value) == first_error_line(done)
    assert str(caught.value).startswith(f"{broken}:")
    with pytest.raises(ValueError) as from_text:
        tether.from_ron(text, broken)
    assert str(from_text.value) == str(caught.value)
    with pytest.raises(ValueError, match=r"^<string>:\d+:\d+: "):
        tether.from_ron("Scene(dt: 0.001, bodies: [")


def test_a_refused_parameter_raises_the_sweeps_text(repo, cli, tmp_path):
    spec = tmp_path / "spec.ron"
    spec.write_text(SPEC.format(scene=repo / SPRING, values="List([-5.0])"))
    done = cli("sweep", spec, "-o", tmp_path / "out", check=False)
    assert done.returncode != 0
    sim = tether.load(repo / SPRING)
    with pytest.raises(ValueError) as caught:
        sim["couplings.spring.law.stiffness"] = -5.0
    message = str(caught.value)
    assert message.startswith(f"{repo / SPRING}:") and "\n" not in message
    # The sweep names the factor and its value, then says what the loader says.
    assert first_error_line(done).endswith(f"factor `couplings.spring.law.stiffness` = -5: {message}")
    # Unknown paths: the sweep's path finder's message.
    with pytest.raises(ValueError, match=r"^the scene has no `stiffnes` \(it has: .*\)$"):
        sim.get("stiffnes")
    with pytest.raises(ValueError, match=r"^`couplings` has no item named \"sprung\" \(it has: spring\)$"):
        sim.set("couplings.sprung.stiffness", 1.0)
    assert sim["couplings.spring.law.stiffness"] == 100.0, "a refused value changes nothing"


@pytest.mark.parametrize(
    "call, error, pattern",
    [
        (lambda s: s.run(float("nan")), ValueError, r"^`duration` must be a finite number, got NaN$"),
        (lambda s: s.run(-1.0), ValueError, r"^`duration` must be a positive number of seconds, got -1$"),
        (lambda s: s.run(float("inf")), ValueError, r"^`duration` must be a finite number, got inf$"),
        (lambda s: s.run(1e20), ValueError, r"more than the 1e12 a run may take$"),
        (lambda s: s.run(1.0, rate=2000.0), ValueError, r"^`rate` 2000 per second is above the step rate 1000\.0+ "),
        (lambda s: s.run(1.0, rate=0.0), ValueError, r"^`rate` must be a positive number"),
        (lambda s: s.run("long"), TypeError, r"duration"),
        (lambda s: s.set("couplings.spring.law.stiffness", float("nan")), ValueError, r"must be a finite number, got NaN$"),
        (lambda s: s.set("couplings.spring.law.stiffness", [1.0]), TypeError, r"^`couplings.spring.law.stiffness`: expected a number, a name or a flag, got list$"),
        (lambda s: s.set("couplings.spring.law.stiffness", "stiff"), ValueError, r"couplings.spring.law.stiffness"),
        (lambda s: s.set("dt", 0.0), ValueError, r"dt"),
        (lambda s: s.offsets("mass", "sideways", 1.0), ValueError, r"sideways"),
        (lambda s: s.offsets("nobody", "x", 1.0), ValueError, r'no body "nobody" \(bodies: mass\)$'),
        (lambda s: s.offsets("mass", "x", 0.0), ValueError, r"^`to` must be a non-zero number of m, got 0$"),
        (lambda s: s.record("/nonexistent-dir/out.rrd", 0.1), ValueError, r"^cannot write /nonexistent-dir/out.rrd"),
        (lambda s: s.step(-1), OverflowError, r"negative"),
    ],
)
def test_bad_input_raises_one_line(repo, call, error, pattern):
    sim = tether.load(repo / SPRING)
    with pytest.raises(error, match=pattern) as caught:
        call(sim)
    assert "\n" not in str(caught.value)


def test_a_divergence_raises_runtime_error(repo):
    sim = tether.load(repo / SPRING)
    sim["dt"] = 0.5  # ω0 dt = 5, far past the leapfrog's limit of 2
    with pytest.raises(RuntimeError) as caught:
        sim.run(100.0)
    assert "\n" not in str(caught.value) and "diverged at t = " in str(caught.value)


def test_a_run_in_a_thread_lets_another_thread_progress(repo):
    sim = tether.load(repo / MOORED)
    ticks = []
    done = threading.Event()

    def run():
        sim.run(1000.0, rate=1.0)  # 5e5 steps: a second or more
        done.set()

    worker = threading.Thread(target=run)
    started = time.perf_counter()
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - started
    assert elapsed > 0.2, f"the run is long enough to tell ({elapsed:.3f} s)"
    # The loop ticks only until the run is done. With the GIL held throughout the run (one
    # call), it would tick once or twice; released, every millisecond or so — fewer on a loaded
    # machine, never as few as 20.
    assert len(ticks) >= 20, f"{len(ticks)} ticks in {elapsed:.3f} s"


# The child takes Ctrl-C as in a terminal's foreground even when the tests run as a background
# job, which passes SIGINT on ignored (Python then installs no KeyboardInterrupt handler).
CTRL_C = """
import signal, sys, tether
signal.signal(signal.SIGINT, signal.default_int_handler)
sim = tether.load(sys.argv[1])
print("running", flush=True)
sim.run(1e6, rate=0.01)
"""


def test_ctrl_c_raises_keyboard_interrupt(repo):
    child = subprocess.Popen(
        [sys.executable, "-c", CTRL_C, str(repo / MOORED)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert child.stdout.readline().strip() == "running"
    time.sleep(0.5)
    sent = time.perf_counter()
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=30)
    assert time.perf_counter() - sent < 5.0
    assert child.returncode != 0
    assert stderr.strip().splitlines()[-1] == "KeyboardInterrupt", stderr


def test_a_recording_verifies(repo, tmp_path):
    out = tmp_path / "run.rrd"
    sim = tether.load(repo / MOORED)
    sim.record(out, duration=1.0, log_hz=30.0)
    assert out.stat().st_size > 1000
    assert sim.time == pytest.approx(1.0)
    rerun = os.environ.get("RERUN_BIN") or "rerun"
    done = subprocess.run([rerun, "rrd", "verify", str(out)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr


def test_one_step_and_reset(repo):
    sim = tether.load(repo / SPRING)
    start = sim.run(0.0005).position  # one step: dt = 1 ms, rounded to 1 step
    assert sim.step_count == 1
    sim.step()
    sim.step(10)
    assert sim.step_count == 12 and sim.time == pytest.approx(0.012)
    sim.reset()
    assert sim.step_count == 0 and sim.time == 0.0
    assert sim.run(0.001).position[0, 0, 0] == start[0, 0, 0]
