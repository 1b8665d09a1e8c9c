"""Fixtures for the command-line tests: `cli(*args)` runs the built poinsot binary."""
import os
import signal
import subprocess
import time
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


def tty_run(exe, args, stop_after=None, shows=b"\r["):
    """Runs the tool with stderr on a pseudo-terminal; with `stop_after` (s), sends SIGTERM once `shows` (by
    default the start of `poinsot run`'s progress bar) is on the terminal or that time has passed. Returns
    (returncode, stderr text)."""
    import pty
    import select

    master, slave = pty.openpty()
    p = subprocess.Popen([exe, *map(str, args)], stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    chunks, start, signalled = [], time.time(), False
    while True:
        ready, _, _ = select.select([master], [], [], 0.1)
        if ready:
            try:
                data = os.read(master, 4096)
            except OSError:  # the child closed the terminal
                break
            if not data:
                break
            chunks.append(data)
        if stop_after is not None and not signalled and (
                shows in b"".join(chunks) or time.time() - start > stop_after):
            p.send_signal(signal.SIGTERM)
            signalled = True
        if p.poll() is not None and not ready:
            break
    os.close(master)
    return p.wait(timeout=120), b"".join(chunks).decode("utf-8", "replace")
