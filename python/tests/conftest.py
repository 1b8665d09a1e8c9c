"""Shared fixtures of the Python module's tests (run by the ctest entry python.pytest, PYTHONPATH set)."""
import math
import os
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EPS = np.finfo(float).eps
G = 9.81  # the tests' gravity, m/s²


def rot_y(angle):
    """The rotation by `angle` (rad) about y."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def tennis_racket():
    """The tennis-racket example scenario (examples/tennis_racket.toml)."""
    path = SOURCE_DIR / "examples" / "tennis_racket.toml"
    if not path.exists():
        pytest.skip("examples/tennis_racket.toml is not in this checkout")
    return path


@pytest.fixture
def cli_exe():
    exe = os.environ.get("POINSOT_CLI")
    if not exe or not Path(exe).exists():
        pytest.skip("POINSOT_CLI is not set or not built: run through ctest after a full build")
    return exe
