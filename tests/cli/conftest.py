"""Fixtures for the command-line tests: `cli(*args)` runs the built poinsot binary."""
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))


@pytest.fixture
def cli():
    exe = os.environ.get("POINSOT_CLI")
    if not exe:
        pytest.fail("POINSOT_CLI is not set: run these tests through ctest")

    def run(*args, cwd=None, timeout=120):
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=timeout)

    return run


@pytest.fixture
def source_dir():
    return SOURCE_DIR
