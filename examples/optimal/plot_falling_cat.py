#!/usr/bin/env python3
"""The falling cat's body shapes at a few instants (PNG, Matplotlib), from the falling_cat.csv that
``example_falling_cat --out DIR`` writes (t, then per half x_space and R_space_body row-major, at every
collocation point; the first line is ``# status: ...``).

Each half (a cylinder of length 1 m along its body x, the waist at its +x end) is drawn as its axis, from its
free end to the waist, with a tick along its body z (the cat's back at the start: pointing down once the cat
has turned over), in the space frame, seen obliquely; one panel per instant, the instants equally spaced
collocation points. Only NumPy and Matplotlib are imported.

Usage: plot_falling_cat.py CSV PNG [--instants K]   (K from 2 to 12, default 6)
"""
from __future__ import annotations

import os
import sys

HALF_LENGTH = 0.5  # m, from a half's centre of mass to either end
TICK = 0.25  # m, the length of the body-z tick
BODIES = ("front", "back")
COLOURS = {"front": "tab:blue", "back": "tab:orange"}


def load(path):
    """(status line, column name -> array) of a falling_cat.csv."""
    import numpy as np

    with open(path, encoding="utf-8") as f:
        status = f.readline().strip().lstrip("#").strip()
        names = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
    if data.shape[1] != len(names):
        raise ValueError(f"{path}: got {data.shape[1]} columns of data and {len(names)} names; expected equal")
    missing = [n for n in ("t", "front.x_x", "back.R22") if n not in names]
    if missing:
        raise ValueError(f"{path}: column {missing[0]!r} is missing; expected the columns of example_falling_cat")
    return status, {name: data[:, i] for i, name in enumerate(names)}


def body_frame(columns, body, k):
    """(centre (3,), R (3, 3)) of `body` at row k."""
    import numpy as np

    x = np.array([columns[f"{body}.x_{c}"][k] for c in "xyz"])
    R = np.array([[columns[f"{body}.R{r}{c}"][k] for c in range(3)] for r in range(3)])
    return x, R


def plot(csv_path, png_path, instants=6):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    status, columns = load(csv_path)
    t = columns["t"]
    rows = np.unique(np.round(np.linspace(0, len(t) - 1, instants)).astype(int))
    fig = plt.figure(figsize=(2.6 * len(rows), 3.2))
    for panel, k in enumerate(rows):
        ax = fig.add_subplot(1, len(rows), panel + 1, projection="3d")
        for body in BODIES:
            x, R = body_frame(columns, body, k)
            axis, up = R[:, 0], R[:, 2]
            free_end, waist = x - HALF_LENGTH * axis, x + HALF_LENGTH * axis
            ax.plot(*np.column_stack([free_end, waist]), color=COLOURS[body], lw=4, solid_capstyle="round",
                    label=body if panel == 0 else None)
            ax.plot(*np.column_stack([x, x + TICK * up]), color="k", lw=1.2)
            ax.scatter(*waist, color="k", s=10)
        ax.set_xlim(-0.6, 0.6)
        ax.set_ylim(-0.6, 0.6)
        ax.set_zlim(-0.6, 0.6)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=20, azim=-60)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_zticks([])
        ax.set_title(f"t = {t[k]:.2f} s", fontsize=9)
    fig.legend(loc="lower center", ncol=2, fontsize=8)
    fig.suptitle(f"falling cat (spine along x, ticks: body z) — {status}"[:150], fontsize=9)
    fig.tight_layout(rect=(0, 0.05, 1, 0.92))
    temp = f"{png_path}.tmp.png"
    fig.savefig(temp, dpi=110)
    plt.close(fig)
    os.replace(temp, png_path)


def main(argv):
    args = list(argv)
    instants = 6
    if "--instants" in args:
        i = args.index("--instants")
        try:
            instants = int(args[i + 1])
        except (IndexError, ValueError):
            instants = -1
        del args[i : i + 2]
        if not 2 <= instants <= 12:
            print("plot_falling_cat.py: --instants: expected an integer from 2 to 12", file=sys.stderr)
            return 2
    if len(args) != 2:
        print("plot_falling_cat.py: expected two arguments: CSV PNG [--instants K]", file=sys.stderr)
        return 2
    try:
        plot(args[0], args[1], instants)
    except (OSError, ValueError) as e:
        print(f"plot_falling_cat.py: {e}".splitlines()[0], file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
