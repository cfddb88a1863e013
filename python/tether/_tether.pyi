"""Type stubs of the native module (Rust, PyO3); use it through the `tether` package."""

import os
from typing import Any, Dict, List, Optional, Tuple, Union

__version__: str

_Path = Union[str, "os.PathLike[str]"]
_Column = Tuple[bytearray, List[int]]

class Simulation:
    """A scene and its world (see `tether.Simulation`)."""

    @staticmethod
    def load(path: _Path) -> "Simulation":
        """Loads the scene file at `path`; ValueError("path:line:col: message") if it is wrong."""
    @staticmethod
    def from_ron(text: str, path: _Path = "<string>") -> "Simulation":
        """Loads a scene from RON text; `path` labels its errors and locates its mesh files."""
    @property
    def path(self) -> str: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def bodies(self) -> List[str]: ...
    @property
    def couplings(self) -> List[str]: ...
    @property
    def coupling_kinds(self) -> List[str]: ...
    @property
    def time(self) -> float:
        """Simulated time [s]."""
    @property
    def dt(self) -> float:
        """The world step [s]."""
    @property
    def duration(self) -> float:
        """The scene's duration [s]."""
    @property
    def step_count(self) -> int:
        """World steps since t = 0."""
    def get(self, path: str) -> Union[float, int, str, bool, None]:
        """The value at a sweep parameter path (None: left to the loader's default)."""
    def parameters(self) -> List[Dict[str, Any]]:
        """Every tunable number: path, label, unit and value, one dict each."""
    def set(self, path: str, value: Union[float, int, str, bool]) -> None:
        """Sets the value at a sweep parameter path; the scene is built again (t = 0)."""
    def to_ron(self) -> str:
        """The scene as RON text."""
    def reset(self) -> None:
        """Back to t = 0 and the scene's initial state."""
    def step(self, n: int = 1) -> None:
        """Advances `n` world steps (the GIL released from 256 steps on)."""
    def _run(self, duration: float, rate: Optional[float] = None) -> Dict[str, _Column]:
        """Runs `duration` seconds; float64 columns as (bytearray, shape)."""
    def _equilibrium_json(self) -> str:
        """`tether equilibrium --json`'s text."""
    def _offsets(self, body: str, direction: str, to: float, steps: int) -> Tuple[List[str], List[float], int]:
        """`tether offsets`' table: column names, rows flattened, row count."""
    def record(self, path: _Path, duration: Optional[float] = None, log_hz: float = 60.0) -> None:
        """Runs and records to a Rerun `.rrd` file."""

def run_sweep(
    spec: _Path,
    output: _Path,
    jobs: Optional[int] = None,
    max_cases: Optional[int] = None,
    case_timeout: float = 600.0,
) -> str:
    """Runs a sweep spec into `output`; the path of its results.parquet."""

def read_parquet(path: _Path) -> Dict[str, Tuple[str, Union[bytes, List[Optional[str]]]]]:
    """A Parquet file's columns: (numpy dtype, bytes) or ("str", list)."""

def run_fit(
    spec: _Path,
    text: Optional[str] = None,
    jobs: Optional[int] = None,
    output: Optional[_Path] = None,
    write_scene: Optional[_Path] = None,
) -> Dict[str, Any]:
    """Fits the spec file `spec` (or the spec `text`, labelled `spec`, its paths relative to
    `spec`'s folder) as `tether fit` does; `{"report": JSON text, "table": the printed table,
    "spec": the spec's text, "signals": [{"times", "measured", "start", "fitted": float64
    bytearray}], "interrupted": bool}`."""
