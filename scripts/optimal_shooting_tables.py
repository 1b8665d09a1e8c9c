#!/usr/bin/env python3
"""The tables of docs/measurements/optimal_shooting.md, measured with `poinsot optimize --json` on variants of
scenario files (deterministic: the same binary gives the same table):

  spin      examples/optimal/racket_spin_phase.toml (Brody's racket spinning at 1 rad/s about its unstable
            intermediate axis, ending 0.5 rad ahead of the free spin, minimum energy) for T = 10, 20, 30, 40 s
            and M = 1, 2, 4, 8, 16, 32 shooting segments; each cell: verified or the shooting's status, Newton
            iterations and the cost against the closed form 12 J_y²Δ²/T³;
  tilt      the same at T = 30 s with the target turned further by 0.05 rad about body x (no closed form):
            the shooting's status, the cost against the direct one, the open-loop re-simulation's attitude
            error and amplification ‖Φ(T, 0)‖, the largest attitude error of the re-simulation split at the
            nodes, and the verdict;
  reversal  the norm-bound sphere's minimum-time slew (j = 1.5, ‖u‖ ≤ 0.8, Θ = 2.5 rad about body x) for
            M = 1, 2, 3, 4, 5, 6, 8, 16: the shooting's status, residual and T against 2√(Θj/ū).

Usage: scripts/optimal_shooting_tables.py [spin|tilt|reversal ...] (POINSOT_CLI: the poinsot binary, default
build/release/apps/poinsot/poinsot). About 1 s per run on an idle machine."""
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXE = os.environ.get("POINSOT_CLI", str(ROOT / "build/release/apps/poinsot/poinsot"))

REVERSAL = """
[body]
principal_moments = [1.5, 1.5, 1.5]
[optimal_control]
objective = "minimum_time"
torque_bound = "norm"
torque_max = 0.8
initial_intervals = 10
mesh_tolerance = 1e-6
shooting_nodes = {M}
[optimal_control.final]
orientation = {{ axis_angle = {{ axis = [1.0, 0.0, 0.0], angle = 2.5 }} }}
"""


def optimize(text: str, folder: Path) -> dict:
    path = folder / "s.toml"
    path.write_text(text)
    r = subprocess.run([EXE, "optimize", str(path), "--out", str(folder / "out"), "--json"],
                       capture_output=True, text=True, check=False)
    if r.returncode not in (0, 1):
        sys.exit(f"optimal_shooting_tables.py: poinsot optimize failed: {r.stderr.strip()}")
    return json.loads(r.stdout)


def spin_table(folder: Path) -> None:
    example = (ROOT / "examples/optimal/racket_spin_phase.toml").read_text()
    Ms = (1, 2, 4, 8, 16, 32)
    print("| T (λT) | " + " | ".join(f"M = {M}" for M in Ms) + " |")
    print("|---" * (len(Ms) + 1) + "|")
    lam = math.sqrt((0.01638 - 0.00121) * (0.01748 - 0.01638) / (0.00121 * 0.01748))
    for T in (10, 20, 30, 40):
        cells = []
        for M in Ms:
            text = (example.replace("final_time = 30.0", f"final_time = {T:.1f}")
                    .replace("angle = 30.5", f"angle = {T + 0.5:.1f}")
                    .replace("shooting_nodes = 8", f"shooting_nodes = {M}"))
            s = optimize(text, folder)
            ind = s["indirect"]
            closed = 12 * 0.01638**2 * 0.5**2 / T**3
            if s["optimal"]:
                cells.append(f"verified, {ind['iterations']} it., cost {ind['cost'] / closed - 1:+.1e}")
            else:
                cells.append(f"**not converged**: residual {ind['residual']:.1e} after {ind['iterations']} it.")
        direct = s["direct"]["cost"] / closed - 1
        print(f"| {T} s ({lam * T:.1f}; direct {direct:+.1e}) | " + " | ".join(cells) + " |")


def tilt_table(folder: Path) -> None:
    # q = q_y(wT + Δ) ⊗ q_x(0.05), (w, x, y, z)
    a, b = 0.5 * 30.5, 0.5 * 0.05
    q = [math.cos(a) * math.cos(b), math.cos(a) * math.sin(b), math.sin(a) * math.cos(b),
         -math.sin(a) * math.sin(b)]
    example = (ROOT / "examples/optimal/racket_spin_phase.toml").read_text()
    target = "axis_angle = { axis = [0.0, 1.0, 0.0], angle = 30.5 }"
    print("| M | shooting | cost / direct − 1 | open-loop replay (rad) | amplification | split replay (rad) "
          "| verified |")
    print("|---|---|---|---|---|---|---|")
    for M in (1, 2, 4, 8, 16, 32):
        text = (example.replace(target, "quaternion = [" + ", ".join(f"{c!r}" for c in q) + "]")
                .replace("shooting_nodes = 8", f"shooting_nodes = {M}"))
        s = optimize(text, folder)
        ind, checks = s["indirect"], s["checks"]
        checked = "" if checks["open_loop_replay_checked"] else " (not required)"
        print(f"| {M} | {ind['status']} | {ind['cost'] / s['direct']['cost'] - 1:+.1e} | "
              f"{checks['resimulated_attitude_error']:.1e}{checked} | {checks['replay_amplification']:.1e} | "
              f"{checks['split_replay_attitude_error']:.1e} | {s['optimal']} |")


def reversal_table(folder: Path) -> None:
    T_star = 2 * math.sqrt(2.5 * 1.5 / 0.8)
    print("| M | status | residual | T / 2√(Θj/ū) − 1 |")
    print("|---|---|---|---|")
    for M in (1, 2, 3, 4, 5, 6, 8, 16):
        ind = optimize(REVERSAL.format(M=M), folder)["indirect"]
        print(f"| {M} | {ind['status']} | {ind['residual']:.2e} | {ind['final_time'] / T_star - 1:+.1e} |")


def main() -> None:
    which = sys.argv[1:] or ["spin", "tilt", "reversal"]
    with tempfile.TemporaryDirectory() as tmp:
        for name in which:
            {"spin": spin_table, "tilt": tilt_table, "reversal": reversal_table}[name](Path(tmp))
            print()


if __name__ == "__main__":
    main()
