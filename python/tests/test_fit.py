"""`tether.fit` against known parameters, the shipped example and the `tether fit` command line."""

import json
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import tether

SPRING = "scenes/spring_mass.ron"
HEAVE = "examples/calibration/heave_decay.ron"
K, C = "couplings.spring.law.stiffness", "couplings.spring.damping"
DAMPING, DRAG = "bodies.box.hydro.linear_damping.2", "bodies.box.hydro.drag.2"


def spring_record(repo, path, seed=0):
    """spring_mass with k = 120 N/m, c = 0.8 N·s/m (the scene has 100 and 1), x at 100 Hz for
    5 s plus seeded Gaussian noise of 1e-4 m (1 % of the amplitude), as a CSV file."""
    sim = tether.load(repo / SPRING)
    sim.set(K, 120.0)
    sim.set(C, 0.8)
    run = sim.run(5.0, rate=100)
    x = run.position[:, 0, 0] + 1e-4 * np.random.default_rng(seed).standard_normal(run.time.shape)
    np.savetxt(path, np.column_stack([run.time, x]), delimiter=",", header="t,x", comments="", fmt="%.12e")
    return path


def spring_fit(repo, record, **more):
    return tether.fit(
        scene=repo / SPRING,
        record=record,
        signals=[("x", 'Position("mass", X)')],
        parameters=[
            dict(path=K, lower=50.0, upper=200.0),
            dict(path=C, lower=0.1, upper=10.0, scale="log"),
        ],
        **more,
    )


def test_spring_mass_parameters_recovered(repo, cli, tmp_path):
    record = spring_record(repo, tmp_path / "decay.csv")
    result = spring_fit(repo, record)
    assert result.status == "converged" and not result.interrupted
    for name, truth in [(K, 120.0), (C, 0.8)]:
        value = result.values[name]
        assert abs(value - truth) < 5e-3 * truth, f"{name} = {value}"
        lo, hi = result.intervals[name]
        assert lo < truth < hi, f"{name}: {truth} outside {lo} … {hi}"
        assert result.standard_errors[name] == pytest.approx((hi - lo) / 2 / result.json["t_quantile_975"])
        # White noise: the interval for a correlated residual is about the textbook one.
        c_lo, c_hi = result.correlated_intervals[name]
        assert c_hi - c_lo == pytest.approx(hi - lo, rel=0.2), f"{name}: {c_lo} … {c_hi} against {lo} … {hi}"
    assert result.correlation.shape == (2, 2) and result.undetermined == []
    x = result.signal("x")
    assert x.samples == 501 and x.times.shape == x.measured.shape == x.start.shape == x.fitted.shape == (501,)
    assert x.rms_fitted < 1.2e-4 < x.rms_start, "the fitted model is within the noise; the start was not"
    np.testing.assert_allclose(np.sqrt(np.mean((x.fitted - x.measured) ** 2)), x.rms_fitted, rtol=1e-12)
    assert result.iterations[0]["values"] == {K: 100.0, C: 1.0}, "started from the scene's values"
    # The spec made from the keywords is one the command line runs to the same numbers.
    spec = tmp_path / "spring.ron"
    spec.write_text(result.spec)
    done = cli("fit", spec, "--json", "-o", tmp_path / "out", "--scene-out", tmp_path / "fitted.ron")
    assert [p["value"] for p in json.loads(done.stdout)["parameters"]] == list(result.values.values())


@pytest.fixture(scope="module")
def heave(repo, tmp_path_factory):
    """The shipped example fitted by its path, its files and fitted scene written."""
    out = tmp_path_factory.mktemp("heave")
    result = tether.fit(repo / HEAVE, output=out / "fit", write_scene=out / "heave_box.fitted.ron")
    return result, out


def test_the_shipped_heave_decay_example(heave):
    result, out = heave
    # examples/calibration/make_heave_record.py made the record with c = 6.0e4, C_d = 2.5 and
    # 2 mm noise; `tether fit` finds about 59,550 and 2.505, each within its interval of ±1.2 %.
    for name, truth in [(DAMPING, 6.0e4), (DRAG, 2.5)]:
        assert abs(result.values[name] - truth) < 0.02 * truth, f"{name} = {result.values[name]}"
        lo, hi = result.intervals[name]
        assert lo < truth < hi
    assert result.status == "converged" and result.ending != "cancelled" and result.ending != "iteration_limit"
    assert result.correlation[0, 1] == result.correlation[1, 0] < -0.5
    assert str(result).startswith("fit converged") and "| bodies.box.hydro.drag.2 | 1 | 2.5" in str(result)
    files = {f["what"]: f["path"] for f in result.json["files"]}
    assert sorted(files) == ["chart of heave_m", "fitted scene", "recording of the fitted run", "report", "report (JSON)"]
    for name in ["report.md", "report.json", "fitted.rrd", "plots/heave_m.png"]:
        assert (out / "fit" / name).stat().st_size > 100, name
    fitted = tether.load(out / "heave_box.fitted.ron")
    assert fitted.get(DRAG) == pytest.approx(result.values[DRAG], rel=1e-5)
    assert (out / "heave_box.fitted.ron").read_text().startswith("// Fitted by `tether fit` (heave_decay.ron)")


def test_the_same_numbers_as_the_command_line(repo, cli, heave, tmp_path):
    result, _ = heave
    done = cli("fit", repo / HEAVE, "--json", "-o", tmp_path / "out", "--scene-out", tmp_path / "fitted.ron")
    expected = json.loads(done.stdout)
    # Bit for bit: the same solver on the same runs (the report's numbers round-trip exactly
    # through JSON); only the wall time and the files written differ.
    assert [p["value"] for p in expected["parameters"]] == list(result.values.values())
    for report in (expected, result.json):
        del report["wall_seconds"], report["files"]
    assert result.json == expected


def test_bad_input_raises_the_clis_message(repo, cli, tmp_path):
    record = spring_record(repo, tmp_path / "decay.csv")
    spec = tmp_path / "bad.ron"
    spec.write_text(
        f'Fit(scene: "{repo / SPRING}", record: "decay.csv", signals: [Signal(column: "y", of: Position("mass", X))],\n'
        f'    parameters: [Parameter(path: "{K}", from: 50.0, to: 200.0)])\n'
    )
    done = cli("fit", spec, "-o", tmp_path / "out", check=False)
    assert done.returncode == 1
    with pytest.raises(ValueError) as caught:
        tether.fit(spec)
    assert "error: " + str(caught.value) == done.stderr.strip()
    assert str(caught.value) == f'{spec}:1:{spec.read_text().index(chr(34) + "y") + 1}: {record} has no column "y" (columns: x)'
    cases = [
        (dict(record=tmp_path / "none.csv"), rf"^<tether\.fit>:3:13: no record file {tmp_path}/none\.csv$"),
        (dict(signals=[("y", 'Position("mass", X)')]), r'^<tether\.fit>:5:24: .*decay\.csv has no column "y" \(columns: x\)$'),
        (dict(signals=[("x", 'Position("wheel", X)')]), r'^<tether\.fit>:.*: signal "x": the scene has no body "wheel" \(bodies: mass\)$'),
        (dict(parameters=[dict(path="couplings.spring.stifness", lower=1.0, upper=2.0)]), r"parameter `couplings\.spring\.stifness`"),
        (dict(parameters=[dict(path=K, lower=200.0, upper=50.0)]), r"^<tether\.fit>:8:25: parameter `couplings.spring.law.stiffness`: `from` \(200\) must be below `to` \(50\)$"),
        (dict(parameters=[dict(path=K, lower=float("nan"), upper=50.0)]), r"bounds must be finite, got from NaN to 50$"),
        (dict(parameters=[dict(path=C, lower=0.0, upper=1.0, scale="log")]), r"a Log scale needs bounds > 0, got from 0$"),
        (dict(window=(10.0, 20.0)), r"no time overlap: the record spans 0 to 5 s"),
    ]
    keywords = dict(
        scene=repo / SPRING,
        record=record,
        signals=[("x", 'Position("mass", X)')],
        parameters=[dict(path=K, lower=50.0, upper=200.0)],
    )
    for change, pattern in cases:
        with pytest.raises(ValueError, match=pattern) as caught:
            tether.fit(**{**keywords, **change})
        assert "\n" not in str(caught.value)
    with pytest.raises(ValueError, match=rf"^{tmp_path}/none\.ron: cannot read the fit spec: "):
        tether.fit(tmp_path / "none.ron")
    with pytest.raises(ValueError, match=r"^a parameter's `scale` must be 'linear' or 'log', got 'ln'$"):
        tether.fit(**{**keywords, "parameters": [dict(path=K, lower=50.0, upper=200.0, scale="ln")]})
    with pytest.raises(TypeError, match=r"^a parameter: unknown key\(s\) 'low'"):
        tether.fit(**{**keywords, "parameters": [dict(path=K, low=50.0, upper=200.0)]})
    with pytest.raises(TypeError, match=r"^give a spec file or the spec's parts, not both"):
        tether.fit(spec, jobs=1, **keywords)
    with pytest.raises(ValueError, match=r"^`jobs` must be at least 1$"):
        tether.fit(spec, jobs=0)


# The child takes Ctrl-C as in a terminal's foreground even when the tests run as a background
# job, which passes SIGINT on ignored (Python then installs no KeyboardInterrupt handler). It says
# "early" when Ctrl-C came before the start point was evaluated (KeyboardInterrupt, as documented).
CTRL_C = """
import signal, sys, tether
signal.signal(signal.SIGINT, signal.default_int_handler)
print("fitting", flush=True)
try:
    result = tether.fit(sys.argv[1], jobs=1)
except KeyboardInterrupt:
    print("early", flush=True)
    sys.exit(0)
print(result.status, result.ending, result.interrupted, len(result.iterations), flush=True)
"""


def test_ctrl_c_returns_the_best_point_so_far(repo):
    # The start point is evaluated in about 0.5 s and the whole fit takes about 6 s on one thread
    # here; other machines are faster or slower, so the moment of the Ctrl-C is searched for: later
    # after an "early" one, earlier (halfway back) after one that came when the fit had converged.
    too_early, too_late, delay = 0.0, None, 1.5
    for _ in range(8):
        child = subprocess.Popen(
            [sys.executable, "-c", CTRL_C, str(repo / HEAVE)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        assert child.stdout.readline().strip() == "fitting"
        time.sleep(delay)
        sent = time.perf_counter()
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=60)
        assert time.perf_counter() - sent < 5.0
        assert child.returncode == 0, stderr
        if stdout.strip() == "early":
            too_early = delay
        else:
            status, ending, interrupted, iterations = stdout.split()
            if status == "partial":
                assert (ending, interrupted) == ("cancelled", "True") and 1 <= int(iterations) < 10
                return
            # Ctrl-C came while the converged fit computed its intervals (it finishes, and says it
            # was interrupted), or after the fit had ended (a fast machine): too late either way.
            assert status == "converged" and interrupted in ("True", "False"), stdout
            too_late = delay
        delay = 2 * delay if too_late is None else (too_early + too_late) / 2
    pytest.fail(f"no Ctrl-C stopped the fit between its start point and its end (last tried {delay:.2f} s in)")
