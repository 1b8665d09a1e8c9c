"""Every `poinsot ...` command shown in a shell block of the README or of docs/ runs as written.

Each command runs in a fresh folder where `examples/` and `tests/` point to the source tree, as a reader who
copies it from a clone would run it; it must exit 0, or the status its comment states (`# exit status 3: ...`,
the documented outcome of a run, as `poinsot optimize`'s converged direct solutions). Commands with a
placeholder (an upper-case file name such as SCENARIO.toml, an optional [--flag], a file of the reader's own) are
not runnable as written and are skipped by rule, not by name; so are the long optimisations listed in SLOW,
whose figures the optimal-control script reports instead.
"""
import os
import re
import shlex
import subprocess
from pathlib import Path

import pytest

from conftest import UNDER_SANITIZERS

SOURCE = Path(__file__).resolve().parents[2]
DOCS = [SOURCE / "README.md", *sorted((SOURCE / "docs").glob("**/*.md"))]
# The reader's own files in examples of usage: not in the repository.
READERS_FILES = {"my_body.toml", "part.stl"}
# Run elsewhere: the tumbling racket (minutes of Ipopt) by scripts/optimal_examples.py, the falling cat by
# tests/cli/test_cli_optimize_multibody.py against its stated optimum.
SLOW = ("examples/optimal/falling_cat.toml", "examples/optimal/tennis_racket_stop.toml")


def shell_commands(path):
    """(line number, command) of each `poinsot` command in the ```sh blocks of a Markdown file."""
    text = path.read_text(encoding="utf-8")
    out = []
    for block in re.finditer(r"```(?:sh|bash)\n(.*?)```", text, re.S):
        first_line = text.count("\n", 0, block.start(1)) + 1
        for offset, line in enumerate(block.group(1).splitlines()):
            command = line.split(" #")[0].strip()
            if command.startswith("poinsot "):
                out.append((first_line + offset, line.strip()))
    return out


def runnable(command):
    command = command.split(" #")[0]
    words = shlex.split(command)
    if any(w in READERS_FILES or re.fullmatch(r"[A-Z][A-Z_]*\.\w+", w) or w.startswith("[") for w in words):
        return False
    return not any(slow in command for slow in SLOW)


CASES = [(path, line, command) for path in DOCS for line, command in shell_commands(path)]


def test_the_docs_show_commands():
    assert sum(runnable(c) for _, _, c in CASES) >= 25


@pytest.mark.slow_under_sanitizers
@pytest.mark.parametrize("path, line, command", CASES,
                         ids=[f"{p.relative_to(SOURCE)}:{n}" for p, n, _ in CASES])
def test_command_runs_as_written(tmp_path, path, line, command):
    if not runnable(command):
        pytest.skip("a placeholder or a long optimisation: not runnable as written")
    expected = re.search(r"# exit status (\d+)", command)
    command = command.split(" #")[0].strip()
    for folder in ("examples", "tests"):
        (tmp_path / folder).symlink_to(SOURCE / folder)
    for part in command.split(" && "):
        words = shlex.split(part)
        assert words[0] == "poinsot"
        r = subprocess.run([os.environ["POINSOT_CLI"], *words[1:]], cwd=tmp_path, capture_output=True, text=True,
                           timeout=600, env={**os.environ, "MPLBACKEND": "Agg"})
        status = int(expected.group(1)) if expected else 0
        assert r.returncode == status, f"{path.name}:{line}: {part}\n{r.stderr}"
