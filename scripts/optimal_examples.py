#!/usr/bin/env python3
"""Runs every optimal-control example (examples/optimal/*.toml) through `poinsot optimize` and checks it
against the optimum it states: verified optimal (exit 0; the keep-out slew, whose cone is active: converged
direct, exit 3) and the figure within the tolerance below. Prints one
line per example (figure, tolerance met, exit status, CPU seconds). Slow (the tumbling racket's direct
phase takes minutes): CI runs the fast ones as tests (tests/cli/test_cli_optimize*.py, python/tests/), not
this script.

    python3 scripts/optimal_examples.py [--poinsot PATH] [--only NAME,...]

Exit status 1 when an example misses its optimum or is not verified.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

# name: (summary.json path of the figure, stated optimum, relative tolerance[, expected exit status, 0 if absent])
EXAMPLES = {
    "betts": (("indirect", "final_time"), 28.6304077, 5e-8),          # published t*, to its digits
    "sphere_slew": (("indirect", "final_time"), 3.2430832775, 1e-10),  # Bilimoria & Wie
    "racket_spin_phase": (("indirect", "cost"), 12 * 0.01638**2 * 0.5**2 / 30.0**3, 1e-10),  # closed form
    "tennis_racket_stop": (("indirect", "final_time"), 10.292254477563144, 1e-12),  # ‖J ω_0‖/ū
    "two_link_arm": (("solution", "cost"), 39.3527635152, 1e-9),       # the 64-interval optimum
    "two_link_arm_urdf": (("solution", "cost"), 39.3527635152, 1e-9),  # the same arm from its URDF
    "falling_cat": (("solution", "cost"), 0.243543547267, 1e-9),       # the 12-interval optimum
    # the active cone: the direct solution (mesh tolerance 1e-7) of the cone widened by 4e-6 rad
    "sun_avoidance_slew": (("direct", "final_time"), 28.0846451, 1e-6, 3),
    # reaction wheels: the direct solution (mesh tolerance 1e-7), momentum bounds tightened by 2.75e-5
    "reaction_wheel_slew": (("direct", "cost"), 0.0050589720215, 1e-6, 3),
}


def main() -> int:
    source = Path(__file__).resolve().parents[1]
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--poinsot", default=os.environ.get("POINSOT_CLI",
                                                        str(source / "build/release/apps/poinsot/poinsot")))
    ap.add_argument("--only", default="", help="comma-separated example names (default: all)")
    a = ap.parse_args()
    names = [n for n in a.only.split(",") if n] or list(EXAMPLES)
    failed = 0
    with tempfile.TemporaryDirectory() as out:
        for name in names:
            keys, stated, rtol, *exit_status = EXAMPLES[name]
            expected_exit = exit_status[0] if exit_status else 0
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            r = subprocess.run([a.poinsot, "optimize", str(source / "examples/optimal" / f"{name}.toml"),
                                "--out", f"{out}/{name}", "--json", "--quiet"], capture_output=True, text=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
            try:
                summary = json.loads(r.stdout)
                figure = summary[keys[0]][keys[1]]
            except (ValueError, KeyError):
                summary, figure = {}, float("nan")
            ok = r.returncode == expected_exit and abs(figure / stated - 1) <= rtol
            failed += not ok
            print(f"{name:20s} {figure:.13g} (stated {stated:.13g}, rtol {rtol:g}) exit {r.returncode} "
                  f"{cpu:7.1f} s CPU  {'ok' if ok else 'MISSED: ' + summary.get('status', r.stderr.strip())}",
                  flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
