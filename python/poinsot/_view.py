"""poinsot.view: the 3-D page of a run (view.html, docs/viewer.md), written by the library's own writer (the
one behind ``poinsot view`` and ``poinsot run --html``) and, inside Jupyter, shown inline."""
from __future__ import annotations

import html
import os
from typing import Any

from . import _core


def _in_notebook() -> bool:
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and type(shell).__name__ == "ZMQInteractiveShell"


def view(result_or_out_dir: Any, *, frames: int | None = None, scenario: str | os.PathLike | None = None,
         display: bool | None = None, height: int = 640) -> str:
    """Writes ``view.html`` into a finished run's folder and returns its path.

    ``result_or_out_dir``: the folder of a finished run (``poinsot run ... --out DIR``, or ``poinsot optimize``'s
    folder), or the RunResult of ``poinsot.run(scenario, out_dir)``. ``frames``: the most frames in the page (default
    ``_core.VIEW_FRAMES_DEFAULT``); longer runs are decimated. ``scenario``: the scenario file of the run, for
    the model (default: the path in summary.json, if it still reads). ``display``: show the page inline (an
    iframe); default: when running inside Jupyter. Raises ValueError (the library's one-line message) when the
    folder holds no finished run, and when a result has no folder (run it with an ``out_dir``)."""
    folder = getattr(result_or_out_dir, "out_dir", result_or_out_dir)
    if folder is None:
        raise ValueError("view: the result has no run folder; expected poinsot.run(scenario, out_dir=...) "
                         "or the path of a finished run")
    if not isinstance(folder, (str, os.PathLike)):
        raise TypeError(f"view: expected a run folder or a RunResult, got {type(result_or_out_dir).__name__}")
    path = _core.write_view_page(os.fspath(folder), _core.VIEW_FRAMES_DEFAULT if frames is None else frames,
                                 "" if scenario is None else os.fspath(scenario))
    if display if display is not None else _in_notebook():
        from IPython.display import HTML, display as show

        with open(path, encoding="utf-8") as f:
            page = f.read()
        show(HTML(f'<iframe srcdoc="{html.escape(page, quote=True)}" style="width: 100%; height: {height}px; '
                  f'border: 0"></iframe>'))
    return path
