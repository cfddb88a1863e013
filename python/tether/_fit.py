"""Calibration from Python: ``tether.fit``, the same fit as ``tether fit SPEC`` (docs/calibration.md)."""

from __future__ import annotations

import json as _json
import math
import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _tether

PathLike = Union[str, "os.PathLike[str]"]

#: The label of a spec made by :func:`fit_spec`: its errors read ``<tether.fit>:line:col: …``
#: (the line and column in :func:`fit_spec`'s text), and its paths are relative to the current
#: directory, as every other path given to the module is.
LABEL = "<tether.fit>"


@dataclass
class FitSignal:
    """One measured column against the model: ``times`` [s] are the record's in the window,
    ``measured`` the record's values there, ``start`` and ``fitted`` the model's at the record's
    times (shifted by a fitted time shift) with the start and the fitted values; ``rms_start``
    and ``rms_fitted`` the RMS of model - record [unit]; ``weight`` [1/unit] the residual's."""

    column: str
    unit: str
    weight: float
    samples: int
    rms_start: float
    rms_fitted: float
    times: np.ndarray = field(repr=False)
    measured: np.ndarray = field(repr=False)
    start: np.ndarray = field(repr=False)
    fitted: np.ndarray = field(repr=False)


@dataclass
class FitResult:
    """A fit's result (``tether fit --json``'s report, with the signals as numpy arrays).

    - ``values``: name -> fitted value (a parameter's name is its path unless the spec names it;
      a fitted time shift is ``time_shift``);
    - ``intervals``: name -> its 95 % confidence interval ``(lo, hi)``, or None when the data do
      not determine it; ``standard_errors``: name -> standard error or None;
    - ``correlated_intervals``: name -> its 95 % interval if the residual is correlated model
      error rather than white noise (another code's run, a real test: docs/calibration.md), or
      None;
    - ``correlation``: (n, n) numpy array in the parameters' order, NaN where undetermined;
    - ``undetermined``: the combinations the data cannot fix, each a dict with ``reads`` (as
      people read it: ``+0.71 δk1/k1 −0.71 δk2/k2``) and ``direction`` (numpy unit vector over
      the parameters' relative changes);
    - ``iterations``: one dict per solver iteration, the first at the start: ``iteration``,
      ``cost`` (½‖r‖²), ``values`` (name -> value), ``accepted``, ``refused`` (why a trial
      could not run, or None), ``runs`` so far;
    - ``signals``: a :class:`FitSignal` per signal, in the spec's order (``signal(column)``
      picks one);
    - ``runs``: model runs; ``wall_seconds``;
    - ``status``: ``"converged"`` or ``"partial"`` (out of iterations, or stopped by Ctrl-C);
      ``ending``: ``"cost_converged"``, ``"step_converged"``, ``"within_noise"``,
      ``"gradient_converged"``, ``"iteration_limit"`` or ``"cancelled"``; ``interrupted``: True after Ctrl-C;
    - ``spec``: the fit spec's text (what ``tether fit`` would run); ``report``: the table
      ``tether fit`` prints (also ``str(result)``); ``json``: the whole report as a dict,
      including the files written.
    """

    values: Dict[str, float]
    intervals: Dict[str, Optional[Tuple[float, float]]]
    standard_errors: Dict[str, Optional[float]]
    correlated_intervals: Dict[str, Optional[Tuple[float, float]]]
    correlation: np.ndarray = field(repr=False)
    undetermined: List[Dict[str, Any]] = field(repr=False)
    iterations: List[Dict[str, Any]] = field(repr=False)
    signals: List[FitSignal] = field(repr=False)
    runs: int
    wall_seconds: float
    status: str
    ending: str
    interrupted: bool
    spec: str = field(repr=False)
    report: str = field(repr=False)
    json: Dict[str, Any] = field(repr=False)

    @property
    def names(self) -> List[str]:
        """The parameters' names, in the spec's order (the axes of ``correlation``)."""
        return list(self.values)

    def signal(self, column: str) -> FitSignal:
        """The signal of the record's column ``column``."""
        for signal in self.signals:
            if signal.column == column:
                return signal
        raise KeyError(f"no signal {column!r} (signals: {', '.join(s.column for s in self.signals)})")

    def __str__(self) -> str:
        return self.report


def fit(
    spec: Optional[PathLike] = None,
    *,
    scene: Optional[PathLike] = None,
    record: Optional[PathLike] = None,
    signals: Optional[Sequence[Any]] = None,
    parameters: Optional[Sequence[Mapping[str, Any]]] = None,
    window: Optional[Sequence[float]] = None,
    time_shift: Optional[Any] = None,
    time_column: Optional[str] = None,
    max_iterations: Optional[int] = None,
    jobs: Optional[int] = None,
    output: Optional[PathLike] = None,
    write_scene: Optional[PathLike] = None,
) -> FitResult:
    """Fits a scene's parameters to a measured record, as ``tether fit`` does; a :class:`FitResult`.

    Either ``spec``, the path of a fit spec file (docs/calibration.md; its paths relative to its
    folder), or the spec's parts as keywords (see :func:`fit_spec`; paths relative to the
    current directory)::

        result = tether.fit(
            scene="scenes/spring_mass.ron",
            record="decay.csv",
            signals=[("x", 'Position("mass", X)')],
            parameters=[
                dict(path="couplings.spring.law.stiffness", lower=50.0, upper=200.0),
                dict(path="couplings.spring.damping", lower=0.1, upper=10.0, scale="log"),
            ],
        )
        result.values, result.intervals

    ``jobs``: model runs at once (None: every core; the result does not depend on it).
    ``output``: a folder (made if absent) for the command line's files: ``report.md``,
    ``report.json``, ``plots/<column>.png``, ``fitted.rrd``. ``write_scene``: a path to write
    the scene with the fitted values in place (its comments kept, a header saying what was
    fitted). Nothing is written by default.

    The GIL is released while the fit runs. Ctrl-C stops it at the best point so far, which is
    returned as the result with ``status == "partial"`` and ``interrupted`` True (its files
    written, as the command line does); a loop of fits that should stop on Ctrl-C checks
    ``result.interrupted``. One that comes after the fit converged (while its intervals are
    computed) lets it finish: its own status, ``interrupted`` True. Only a Ctrl-C before the
    start point was evaluated raises ``KeyboardInterrupt``.

    Errors are one line: ``ValueError`` with the command line's message for a spec, scene or
    record it refuses (a missing file, an unknown column or path, inverted bounds, …; a spec
    made from keywords is labelled ``<tether.fit>``), ``TypeError`` for a wrong type,
    ``RuntimeError`` when the model cannot be run at the start point.
    """
    parts = dict(
        scene=scene,
        record=record,
        signals=signals,
        parameters=parameters,
        window=window,
        time_shift=time_shift,
        time_column=time_column,
        max_iterations=max_iterations,
    )
    if spec is not None:
        given = [name for name, value in parts.items() if value is not None]
        if given:
            raise TypeError(f"give a spec file or the spec's parts, not both (got spec and {', '.join(given)})")
        raw = _tether.run_fit(os.fspath(spec), None, jobs, _path(output), _path(write_scene))
    else:
        text = fit_spec(**parts)
        raw = _tether.run_fit(LABEL, text, jobs, _path(output), _path(write_scene))
    return _result(raw)


def fit_spec(
    *,
    scene: PathLike,
    record: PathLike,
    signals: Sequence[Any],
    parameters: Sequence[Mapping[str, Any]],
    window: Optional[Sequence[float]] = None,
    time_shift: Optional[Any] = None,
    time_column: Optional[str] = None,
    max_iterations: Optional[int] = None,
) -> str:
    """The fit spec's RON text for :func:`fit`'s keywords (save it to run ``tether fit`` on it).

    - ``scene``, ``record``: paths (the record: CSV, Parquet or a Tether ``.rrd``), written as
      given, so relative to the current directory when :func:`fit` runs the text;
    - ``signals``: each ``(column, of)`` or ``(column, of, weight)`` or a dict with those keys:
      ``column`` names the record's column, ``of`` the model quantity as the spec writes it
      (``'Position("mass", X)'``, ``'Tension("spring")'``, ``'EndTension("chain", End2)'``, …),
      ``weight`` [1/unit] (default 1 / the column's standard deviation);
    - ``parameters``: dicts with ``path`` (a sweep value path, or a list of paths set to the same
      value), ``lower`` and ``upper`` (the spec's ``from`` and ``to``, awkward names in Python;
      ``from``/``to`` keys are taken too, and the messages say ``from``/``to``), and optionally
      ``scale`` (``"linear"``, the default, or ``"log"``), ``start`` (default: the scene's value)
      and ``name`` (default: the path);
    - ``window``: ``(from, to)`` [s], the record's times compared (default: all it shares with the
      scene's run);
    - ``time_shift``: ``(lower, upper)``, ``(lower, upper, start)`` or a dict with those keys [s]:
      a time shift fitted with the parameters;
    - ``time_column``: the record's time column (default: its first);
    - ``max_iterations``: default 50.
    """
    lines = ["Fit("]
    lines.append(f"    scene: {_string(os.fspath(_required('scene', scene)), 'scene')},")
    lines.append(f"    record: {_string(os.fspath(_required('record', record)), 'record')},")
    if time_column is not None:
        lines.append(f"    time_column: {_string(time_column, 'time_column')},")
    if window is not None:
        lo, hi = _pair(window, "window")
        lines.append(f"    window: Window(from: {_number(lo, 'window')}, to: {_number(hi, 'window')}),")
    lines.append("    signals: [")
    for signal in _sequence(_required("signals", signals), "signals"):
        lines.append(f"        {_signal(signal)},")
    lines.append("    ],")
    lines.append("    parameters: [")
    for parameter in _sequence(_required("parameters", parameters), "parameters"):
        lines.append(f"        {_parameter(parameter)},")
    lines.append("    ],")
    if time_shift is not None:
        lines.append(f"    time_shift: {_shift(time_shift)},")
    if max_iterations is not None:
        if isinstance(max_iterations, bool) or not isinstance(max_iterations, int):
            raise TypeError(f"`max_iterations` must be an int, got {type(max_iterations).__name__}")
        if not 0 <= max_iterations < 2**32:
            raise ValueError(f"`max_iterations` must be 0 to {2**32 - 1}, got {max_iterations}")
        lines.append(f"    max_iterations: {max_iterations},")
    lines.append(")")
    return "\n".join(lines) + "\n"


# -- the result ----------------------------------------------------------------------------------
def _result(raw: Dict[str, Any]) -> FitResult:
    report = _json.loads(raw["report"])
    names = [p["name"] for p in report["parameters"]]

    def float_array(values: Any) -> np.ndarray:
        return np.array([np.nan if v is None else v for v in values], dtype=np.float64)

    signals = [
        FitSignal(
            column=s["column"],
            unit=s["unit"],
            weight=s["weight"],
            samples=s["samples"],
            rms_start=s["rms_start"],
            rms_fitted=s["rms_fitted"],
            **{k: np.frombuffer(arrays[k], dtype=np.float64) for k in ("times", "measured", "start", "fitted")},
        )
        for s, arrays in zip(report["signals"], raw["signals"])
    ]
    return FitResult(
        values={p["name"]: p["value"] for p in report["parameters"]},
        intervals={p["name"]: None if p["interval_95"] is None else tuple(p["interval_95"]) for p in report["parameters"]},
        standard_errors={p["name"]: p["standard_error"] for p in report["parameters"]},
        correlated_intervals={
            p["name"]: None if p["interval_95_correlated"] is None else tuple(p["interval_95_correlated"])
            for p in report["parameters"]
        },
        correlation=np.array([float_array(row) for row in report["correlation"]], dtype=np.float64).reshape(
            len(names), len(names)
        ),
        undetermined=[
            {"reads": u["reads"], "direction": np.array(u["relative_direction"], dtype=np.float64)}
            for u in report["undetermined"]
        ],
        iterations=[dict(i, values=dict(zip(names, i["values"]))) for i in report["iterations"]],
        signals=signals,
        runs=report["runs"],
        wall_seconds=report["wall_seconds"],
        status=report["status"],
        ending=report["ending"],
        interrupted=raw["interrupted"],
        spec=raw["spec"],
        report=raw["table"],
        json=report,
    )


# -- the spec's text -----------------------------------------------------------------------------
def _path(path: Optional[PathLike]) -> Optional[str]:
    return None if path is None else os.fspath(path)


def _required(name: str, value: Any) -> Any:
    if value is None:
        raise TypeError(f"fit() needs `{name}` (or a spec file)")
    return value


def _sequence(value: Any, name: str) -> Sequence[Any]:
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Sequence):
        raise TypeError(f"`{name}` must be a list, got {type(value).__name__}")
    return value


def _string(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise TypeError(f"`{name}` must be a str, got {type(value).__name__}")
    return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _number(value: Any, name: str) -> str:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"`{name}` must be a number, got {type(value).__name__}")
    x = float(value)
    # Not-finite values go to the spec as RON has them: the spec's checks say what is wrong.
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return repr(x)


def _pair(value: Any, name: str) -> Tuple[Any, Any]:
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Sequence) or len(value) != 2:
        raise TypeError(f"`{name}` must be a pair (from, to), got {value!r}")
    return value[0], value[1]


def _keys(given: Mapping[str, Any], allowed: Sequence[str], what: str) -> None:
    unknown = [k for k in given if k not in allowed]
    if unknown:
        raise TypeError(f"{what}: unknown key(s) {', '.join(map(repr, unknown))} (keys: {', '.join(allowed)})")


def _signal(signal: Any) -> str:
    if isinstance(signal, Mapping):
        _keys(signal, ("column", "of", "weight"), "a signal")
        column, of, weight = signal.get("column"), signal.get("of"), signal.get("weight")
    elif isinstance(signal, (tuple, list)) and len(signal) in (2, 3):
        column, of, weight = (*signal, None) if len(signal) == 2 else signal
    else:
        raise TypeError(f"a signal must be (column, of), (column, of, weight) or a dict, got {signal!r}")
    text = f"Signal(column: {_string(column, 'column')}, of: {_quantity(of)}"
    if weight is not None:
        text += f", weight: {_number(weight, 'weight')}"
    return text + ")"


def _quantity(of: Any) -> str:
    if not isinstance(of, str):
        raise TypeError(f"a signal's `of` must be the quantity as the spec writes it (a str), got {type(of).__name__}")
    if not of.strip():
        raise ValueError("a signal's `of` is empty: name a quantity, e.g. 'Position(\"mass\", X)'")
    return of.strip()


_SCALES = {"linear": "Linear", "log": "Log"}


def _parameter(parameter: Any) -> str:
    if not isinstance(parameter, Mapping):
        raise TypeError(f"a parameter must be a dict (path, lower, upper, …), got {type(parameter).__name__}")
    _keys(parameter, ("path", "lower", "upper", "from", "to", "scale", "start", "name"), "a parameter")
    bounds = []
    for python, spec in (("lower", "from"), ("upper", "to")):
        if python in parameter and spec in parameter:
            raise TypeError(f"a parameter: give `{python}` or `{spec}`, not both")
        value = parameter.get(python, parameter.get(spec))
        if value is None:
            raise TypeError(f"a parameter needs `{python}` (the spec's `{spec}`): {dict(parameter)!r}")
        bounds.append(_number(value, python))
    path = parameter.get("path")
    if isinstance(path, str):
        path_text = _string(path, "path")
    elif isinstance(path, (list, tuple)) and path:
        path_text = "[" + ", ".join(_string(p, "path") for p in path) + "]"
    else:
        raise TypeError(f"a parameter's `path` must be a str or a list of str, got {path!r}")
    text = "Parameter("
    if parameter.get("name") is not None:
        text += f"name: {_string(parameter['name'], 'name')}, "
    text += f"path: {path_text}, from: {bounds[0]}, to: {bounds[1]}"
    scale = parameter.get("scale")
    if scale is not None:
        if not isinstance(scale, str) or scale.lower() not in _SCALES:
            raise ValueError(f"a parameter's `scale` must be 'linear' or 'log', got {scale!r}")
        text += f", scale: {_SCALES[scale.lower()]}"
    if parameter.get("start") is not None:
        text += f", start: {_number(parameter['start'], 'start')}"
    return text + ")"


def _shift(shift: Any) -> str:
    if isinstance(shift, Mapping):
        _keys(shift, ("lower", "upper", "from", "to", "start"), "`time_shift`")
        lower = shift.get("lower", shift.get("from"))
        upper = shift.get("upper", shift.get("to"))
        start = shift.get("start")
    elif isinstance(shift, (tuple, list)) and len(shift) in (2, 3):
        lower, upper, start = (*shift, None) if len(shift) == 2 else shift
    else:
        raise TypeError(f"`time_shift` must be (lower, upper), (lower, upper, start) or a dict, got {shift!r}")
    if lower is None or upper is None:
        raise TypeError("`time_shift` needs `lower` and `upper` [s]")
    text = f"Shift(from: {_number(lower, 'time_shift')}, to: {_number(upper, 'time_shift')}"
    if start is not None:
        text += f", start: {_number(start, 'time_shift')}"
    return text + ")"
