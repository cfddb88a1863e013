"""Shared fixtures: the repository, the `tether` command line the module is compared with."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo() -> Path:
    return REPO


@pytest.fixture(scope="session")
def cli():
    """Runs the `tether` binary ($TETHER_BIN, else `tether` on PATH); returns the finished process.

    The comparisons with the command line are the point of several tests: without the binary
    they fail (they are not skipped)."""
    binary = os.environ.get("TETHER_BIN") or shutil.which("tether")
    assert binary and Path(binary).exists(), "set TETHER_BIN to the `tether` binary (scripts/test does)"

    def run(*args, check=True):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=600)
        if check:
            assert done.returncode == 0, f"tether {' '.join(map(str, args))}: {done.stderr}"
        return done

    return run
