"""Tether from Python: coupled rigid bodies, springs, catenaries and contact.

Load a scene, read and set its parameters by the sweep's paths, step or run it into numpy arrays,
solve its statics, run sweeps, fit its parameters to a measured record and record runs to Rerun
files::

    import tether
    sim = tether.load("scenes/spring_mass.ron")
    sim["couplings.spring.law.stiffness"] = 2000.0      # checked by the scene loader
    run = sim.run(5.0, rate=100)                    # 5 s sampled at 100 Hz, GIL released
    run.position[:, 0, 2]                           # body 0's height [m], one value per sample

Units are SI throughout (m, s, kg, N, J, rad). Quaternions are ``[w, x, y, z]``. Every error is
a one-line exception: ``ValueError`` for input the loader, a validator or a solver refuses (the
text of the ``tether`` command line), ``TypeError`` for a wrong type, ``RuntimeError`` for a run
that diverges, ``KeyboardInterrupt`` on Ctrl-C.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Union

import numpy as np

from . import _tether
from ._fit import FitResult, FitSignal, fit, fit_spec

__all__ = [
    "Simulation",
    "Trajectory",
    "Equilibrium",
    "Parameter",
    "FitResult",
    "FitSignal",
    "load",
    "from_ron",
    "sweep",
    "fit",
    "fit_spec",
    "__version__",
]
__version__: str = _tether.__version__

PathLike = Union[str, "os.PathLike[str]"]


def _array(raw: Any, shape: List[int], dtype: str = "f8") -> np.ndarray:
    return np.frombuffer(raw, dtype=np.dtype(dtype)).reshape(shape)


@dataclass
class Trajectory:
    """A run's samples (the first is the state at the start of the run).

    ``n`` samples, ``b`` bodies, ``c`` couplings, world axes, SI units:

    - ``time`` (n,) [s];
    - ``position`` (n, b, 3): centre of mass [m]; ``quaternion`` (n, b, 4): orientation of the
      body's frame (the scene file's axes), ``[w, x, y, z]``; ``velocity`` (n, b, 3) [m/s];
      ``angular_velocity`` (n, b, 3) [rad/s];
    - ``point1``/``point2`` (n, c, 3): coupling end points [m]; ``force1``/``force2`` (n, c, 3):
      the force each coupling exerts on its end 1 / end 2 [N]; ``tension`` (n, c): its scalar
      force [N] (a spring's is positive in tension);
    - ``energy``: ``kinetic``, ``gravity``, ``elastic``, ``dissipated``, ``external_work`` and
      ``balance`` (kinetic + gravity + elastic + dissipated - external work, constant for an
      exact integrator; PHYSICS.md section 5), each (n,) [J].
    """

    bodies: List[str]
    couplings: List[str]
    time: np.ndarray
    position: np.ndarray
    quaternion: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    point1: np.ndarray
    point2: np.ndarray
    force1: np.ndarray
    force2: np.ndarray
    tension: np.ndarray
    energy: Dict[str, np.ndarray] = field(default_factory=dict)

    def body(self, name: str) -> Dict[str, np.ndarray]:
        """The columns of body ``name``: position, quaternion, velocity, angular_velocity."""
        i = _index(self.bodies, name, "body")
        return {k: getattr(self, k)[:, i] for k in ("position", "quaternion", "velocity", "angular_velocity")}

    def coupling(self, name: str) -> Dict[str, np.ndarray]:
        """The columns of coupling ``name``: point1, point2, force1, force2, tension."""
        i = _index(self.couplings, name, "coupling")
        return {k: getattr(self, k)[:, i] for k in ("point1", "point2", "force1", "force2", "tension")}


@dataclass
class Equilibrium:
    """A static equilibrium (PHYSICS.md section 7), as ``tether equilibrium --json`` gives it.

    ``bodies``: the bodies that respond to forces; ``position`` (b, 3) [m] of their centres of
    mass, ``moved`` (b, 3) [m] from the scene's start, ``quaternion`` (b, 4) ``[w, x, y, z]``,
    ``stiffness`` (b, 6, 6): rows force x, y, z [N], moment roll, pitch, yaw [N m]; columns move
    x, y, z [m], turn roll, pitch, yaw [rad]. ``couplings``: one dict per coupling (``name``,
    ``kind``, ``tension1``, ``tension2`` [N], a catenary's ``horizontal_tension`` [N] and
    ``grounded_length`` [m], a spring's ``length`` [m], a contact's ``normal`` [N]; None where
    the kind has no such value). ``data``: the JSON as parsed.
    """

    bodies: List[str]
    position: np.ndarray
    moved: np.ndarray
    quaternion: np.ndarray
    stiffness: np.ndarray
    couplings: List[Dict[str, Any]]
    iterations: int
    residual_force: float
    residual_moment: float
    unstable: Optional[str]
    data: Dict[str, Any]

    def tension(self, name: str) -> float:
        """Tension at end 1 of coupling ``name`` [N]."""
        for coupling in self.couplings:
            if coupling["name"] == name:
                return coupling["tension1"]
        raise KeyError(f"no coupling {name!r} (couplings: {', '.join(c['name'] for c in self.couplings)})")


@dataclass
class Parameter:
    """A tunable number of a scene, as the window's knobs and Fit panel offer it.

    ``path``: its sweep parameter path (for :meth:`Simulation.get`/:meth:`Simulation.set`, sweeps
    and fits); ``label``: its name in the window (``"spring: stiffness k"``); ``unit``: its SI
    unit (``"–"`` for a coefficient); ``value``: the scene's value now.
    """

    path: str
    label: str
    unit: str
    value: float


class Simulation:
    """A loaded scene and its world, at simulated time ``time``.

    Build one with :func:`load` or :func:`from_ron`. Parameters are read and set by the sweep's
    paths (``sim["couplings.spring.law.stiffness"]``, ``sim.set("dt", 1e-3)``); setting one builds
    the scene again through the scene loader, which checks it, and starts its world at t = 0.
    """

    __slots__ = ("_native", "step")

    def __init__(self, native: "_tether.Simulation") -> None:
        self._native = native
        # The native method itself: one step costs no Python frame of ours.
        self.step = native.step

    @classmethod
    def load(cls, path: PathLike) -> "Simulation":
        """Loads the scene file at ``path``; ``ValueError("path:line:col: message")`` if it is wrong."""
        return cls(_tether.Simulation.load(os.fspath(path)))

    @classmethod
    def from_ron(cls, text: str, path: PathLike = "<string>") -> "Simulation":
        """Loads a scene from RON text; ``path`` labels its errors and locates its mesh files."""
        if not isinstance(text, str):
            raise TypeError(f"the scene text must be a str, got {type(text).__name__}")
        return cls(_tether.Simulation.from_ron(text, os.fspath(path)))

    # -- what the scene is -------------------------------------------------------------------
    @property
    def path(self) -> str:
        """The scene's path (its label in error messages)."""
        return os.fspath(self._native.path)

    @property
    def bodies(self) -> List[str]:
        """Body names, in the scene's order (the body axis of run arrays)."""
        return self._native.bodies

    @property
    def couplings(self) -> List[str]:
        """Coupling names, in the scene's order (the coupling axis of run arrays)."""
        return self._native.couplings

    @property
    def coupling_kinds(self) -> List[str]:
        """Each coupling's kind: ``spring_damper``, ``catenary`` or ``contact``."""
        return self._native.coupling_kinds

    @property
    def warnings(self) -> List[str]:
        """The loader's warnings."""
        return self._native.warnings

    @property
    def time(self) -> float:
        """Simulated time [s]."""
        return self._native.time

    @property
    def dt(self) -> float:
        """The world step [s]."""
        return self._native.dt

    @property
    def duration(self) -> float:
        """The scene's duration [s] (what :meth:`run` and :meth:`record` run by default)."""
        return self._native.duration

    @property
    def step_count(self) -> int:
        """World steps since t = 0."""
        return self._native.step_count

    # -- parameters ------------------------------------------------------------------------
    def get(self, path: str) -> Union[float, int, str, bool, None]:
        """The value at a sweep parameter path (None: left to the loader's default)."""
        return self._native.get(path)

    def parameters(self) -> List[Parameter]:
        """Every number the window tunes and a fit can move, with its path, label, unit and value.

        The window's own catalogue (its knobs and Fit panel): a couplings' law, damping and line
        constants, the water's waves, current and density, each floating body's coefficients, the
        seabed's line friction, the wind. Counts (a line's segments, a seed) are left out; any
        other value is still reachable by its path with :meth:`get` and :meth:`set`.
        """
        return [Parameter(**entry) for entry in self._native.parameters()]

    def set(self, path: str, value: Union[float, int, str, bool]) -> None:
        """Sets the value at a sweep parameter path: the scene is built again (t = 0).

        ``ValueError`` with the sweep's message for an unknown path, the loader's
        ``path:line:col: message`` for a value it refuses.
        """
        self._native.set(path, value)

    __getitem__ = get
    __setitem__ = set

    def to_ron(self) -> str:
        """The scene, with the values set, as RON text."""
        return self._native.to_ron()

    # -- time ------------------------------------------------------------------------------
    def reset(self) -> None:
        """Back to t = 0 and the scene's initial state."""
        self._native.reset()

    def run(self, duration: Optional[float] = None, rate: Optional[float] = None) -> Trajectory:
        """Runs ``duration`` seconds (None: the scene's) from the current state.

        ``rate``: samples per simulated second (None: every step; above the step rate is
        refused). The GIL is released while the physics runs; Ctrl-C raises
        ``KeyboardInterrupt`` (the world keeps the steps done). ``RuntimeError`` if it diverges.
        """
        raw = self._native._run(self.duration if duration is None else duration, rate)
        columns = {name: _array(*value) for name, value in raw.items()}
        energy = {name[len("energy_"):]: columns.pop(name) for name in list(columns) if name.startswith("energy_")}
        return Trajectory(bodies=self.bodies, couplings=self.couplings, energy=energy, **columns)

    # -- statics ---------------------------------------------------------------------------
    def equilibrium(self) -> Equilibrium:
        """The static equilibrium from the scene's initial poses (``tether equilibrium``'s solver)."""
        import json

        data = json.loads(self._native._equilibrium_json())
        bodies = data["bodies"]

        def stack(key: str, width: Any) -> np.ndarray:
            return np.array([b[key] for b in bodies], dtype=np.float64).reshape((len(bodies),) + width)

        return Equilibrium(
            bodies=[b["name"] for b in bodies],
            position=stack("position", (3,)),
            moved=stack("moved", (3,)),
            quaternion=stack("quaternion", (4,)),
            stiffness=stack("stiffness", (6, 6)),
            couplings=data["couplings"],
            iterations=data["iterations"],
            residual_force=data["residual_force"],
            residual_moment=data["residual_moment"],
            unstable=data["unstable"],
            data=data,
        )

    def offsets(self, body: str, direction: str, to: float, steps: int = 20) -> Dict[str, np.ndarray]:
        """The offset curve of ``body`` (``tether offsets``): held at ``steps + 1`` offsets from 0
        to ``to`` [m or rad] along ``direction`` (x, y, z, roll, pitch, yaw) from its equilibrium,
        the rest settled at each. Columns as ``tether offsets`` writes them (with units):
        the offset, the load, the restoring force, each line's end tensions and grounded length,
        each spring's tension."""
        if isinstance(steps, bool) or not isinstance(steps, int):
            raise TypeError(f"`steps` must be an int, got {type(steps).__name__}")
        if steps < 1:
            raise ValueError(f"`steps` must be 1 to 10000, got {steps}")
        names, values, rows = self._native._offsets(body, direction, to, steps)
        table = np.asarray(values, dtype=np.float64).reshape(rows, len(names))
        return {name: table[:, i].copy() for i, name in enumerate(names)}

    # -- recording -------------------------------------------------------------------------
    def record(self, path: PathLike, duration: Optional[float] = None, log_hz: float = 60.0) -> None:
        """Runs ``duration`` seconds (None: the scene's) and records them to the Rerun file ``path``
        at ``log_hz`` frames per simulated second, as ``tether record`` does (no viewer)."""
        self._native.record(os.fspath(path), duration, log_hz)

    def __repr__(self) -> str:
        return repr(self._native)


def load(path: PathLike) -> Simulation:
    """Loads the scene file at ``path`` (see :meth:`Simulation.load`)."""
    return Simulation.load(path)


def from_ron(text: str, path: PathLike = "<string>") -> Simulation:
    """Loads a scene from RON text (see :meth:`Simulation.from_ron`)."""
    return Simulation.from_ron(text, path)


def sweep(
    spec: PathLike,
    output: Optional[PathLike] = None,
    *,
    jobs: Optional[int] = None,
    max_cases: Optional[int] = None,
    case_timeout: float = 600.0,
    table: str = "auto",
) -> Any:
    """Runs a sweep spec as ``tether sweep SPEC -o OUTPUT`` does; returns its results.parquet.

    ``output``: the sweep's directory (None: a temporary one, removed after reading).
    ``table``: ``"pandas"`` (a DataFrame), ``"arrow"`` (a pyarrow Table), ``"numpy"`` (a dict of
    numpy columns; strings as object arrays, a metric's null as NaN), or ``"auto"``: pandas if
    pandas and pyarrow are installed, else arrow if pyarrow is, else numpy. The GIL is released;
    Ctrl-C stops the sweep (its finished rows are kept) and raises ``KeyboardInterrupt``.
    """
    if table not in ("auto", "pandas", "arrow", "numpy"):
        raise ValueError(f"`table` must be auto, pandas, arrow or numpy, got {table!r}")
    temporary = output is None
    # A new, empty directory is one a sweep accepts.
    directory = tempfile.mkdtemp(prefix="tether-sweep-") if temporary else os.fspath(output)
    try:
        results = _tether.run_sweep(os.fspath(spec), directory, jobs, max_cases, case_timeout)
        return _read_table(os.fspath(results), table)
    finally:
        if temporary:
            shutil.rmtree(directory, ignore_errors=True)


def _read_table(path: str, table: str) -> Any:
    if table == "auto":
        table = "numpy"
        try:
            import pyarrow  # noqa: F401

            table = "arrow"
            import pandas  # noqa: F401

            table = "pandas"
        except ImportError:
            pass
    if table in ("arrow", "pandas"):
        import pyarrow.parquet as pq

        arrow = pq.read_table(path)
        return arrow.to_pandas() if table == "pandas" else arrow
    columns = {}
    for name, (kind, values) in _tether.read_parquet(path).items():
        columns[name] = np.array(values, dtype=object) if kind == "str" else np.frombuffer(values, dtype=kind).copy()
    return columns


def _index(names: List[str], name: str, what: str) -> int:
    try:
        return names.index(name)
    except ValueError:
        raise KeyError(f"no {what} {name!r} ({what} names: {', '.join(names)})") from None
