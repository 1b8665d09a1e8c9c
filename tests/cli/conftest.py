"""Fixtures for the command-line tests: `cli(*args)` runs the built poinsot binary."""
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))

# `ctest --preset sanitize` (the CI's sanitizer run) sets ASAN_OPTIONS. A test marked
# `@pytest.mark.slow_under_sanitizers` takes seconds in release and tens of seconds to minutes in the sanitizer
# build; it is skipped there when cheaper tests of the same code paths still run under the sanitizers (each
# marked test says which).
UNDER_SANITIZERS = "ASAN_OPTIONS" in os.environ


def pytest_configure(config):
    config.addinivalue_line("markers", "slow_under_sanitizers: skipped in the sanitizer build (too slow there)")


def pytest_collection_modifyitems(config, items):
    if not UNDER_SANITIZERS:
        return
    skip = pytest.mark.skip(reason="seconds in release, far longer under the sanitizers")
    for item in items:
        if item.get_closest_marker("slow_under_sanitizers"):
            item.add_marker(skip)


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
