"""Shared fixtures of the Python module's tests (run by the ctest entry python.pytest, PYTHONPATH set)."""
import os
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EPS = np.finfo(float).eps


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
