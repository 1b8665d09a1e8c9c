#!/usr/bin/env python3
"""Seeded random families of minimum-time slews for the indirect method of docs/optimal_control_theory.md,
section 3 (figures: docs/measurements/optimal_shooting.md, "Norm bound on any body" and "Active rate bounds"),
each problem solved by `poinsot optimize --json`:

  norm       rest to rest, ‖u‖ ≤ ū: principal moments drawn in [1, 4] kg·m² (triangle inequality, ratio ≤ 4),
             a random axis, Θ in 20° … 180°, ū in [0.2, 2] N·m;
  norm_spin  the same from a spin: ω_0 = J⁻¹L_0 with L_0 along a random axis, ‖L_0‖ drawn in
             [0.1, 0.5] ū √(Θ J_min/ū), to rest at R_f;
  rate_axis  single-axis slews about a principal axis with a rate bound r, |u_i| ≤ ū on the three axes, Θ in
             60° … 180°, r drawn so that the bound is active (θ > r² J/ū): the closed form
             T = Θ/r + r J/ū (accelerate at the bound, coast at the rate limit, brake) is printed beside (an
             extremal with singular transverse torques under per-axis bounds: not handled by the shooting);
  rate       rest to rest about a random axis, per-axis bounds, a rate bound at 0.5 … 0.8 of the unbounded
             optimum's peak |ω_i| estimate √(Θ ū/J) (active in most draws).

Each line: the status, the final time (and the closed form where there is one), the CPU time of the child
process (user + system, s). The summary: the share verified optimal, with the median and the largest CPU time.

Usage: scripts/optimal_indirect_families.py FAMILY [N] [SEED] (POINSOT_CLI: the poinsot binary, default
build/release/apps/poinsot/poinsot; KEEP=DIR: keep each scenario file there). Deterministic for a given binary:
the problems depend on SEED only."""
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXE = os.environ.get("POINSOT_CLI", str(ROOT / "build/release/apps/poinsot/poinsot"))


def moments(rng: random.Random) -> list:
    while True:
        J = [rng.uniform(1.0, 4.0) for _ in range(3)]
        if 2 * max(J) <= sum(J) and max(J) / min(J) <= 4.0:
            return J


def unit(rng: random.Random) -> list:
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-3:
            return [x / n for x in v]


def fmt(v: list) -> str:
    return "[" + ", ".join(f"{x:.12g}" for x in v) + "]"


def problem(family: str, rng: random.Random) -> tuple:
    """(scenario text, closed-form T or None)."""
    J = moments(rng)
    if family in ("norm", "norm_spin"):
        axis, theta, ubar = unit(rng), math.radians(rng.uniform(20.0, 180.0)), rng.uniform(0.2, 2.0)
        spin = ""
        if family == "norm_spin":
            L = rng.uniform(0.1, 0.5) * ubar * math.sqrt(theta * min(J) / ubar)
            w = unit(rng)
            spin = f"[optimal_control.initial]\nomega_body = {fmt([L * w[i] / J[i] for i in range(3)])}\n"
        return (f"""[body]
principal_moments = {fmt(J)}
[optimal_control]
objective = "minimum_time"
torque_bound = "norm"
torque_max = {ubar:.12g}
{spin}[optimal_control.final]
orientation = {{ axis_angle = {{ axis = {fmt(axis)}, angle = {theta:.12g} }} }}
""", None)
    if family == "rate_axis":
        i, theta, ubar = rng.randrange(3), math.radians(rng.uniform(60.0, 180.0)), rng.uniform(0.2, 2.0)
        peak = math.sqrt(theta * ubar / J[i])  # the bang-bang slew's peak rate
        r = rng.uniform(0.3, 0.8) * peak
        axis = [1.0 if k == i else 0.0 for k in range(3)]
        return (f"""[body]
principal_moments = {fmt(J)}
[optimal_control]
objective = "minimum_time"
torque_bound = "per_axis"
torque_max = {fmt([ubar] * 3)}
rate_max = {r:.12g}
[optimal_control.final]
orientation = {{ axis_angle = {{ axis = {fmt(axis)}, angle = {theta:.12g} }} }}
""", theta / r + r * J[i] / ubar)
    if family == "rate":
        axis, theta, ubar = unit(rng), math.radians(rng.uniform(20.0, 180.0)), rng.uniform(0.2, 2.0)
        r = rng.uniform(0.5, 0.8) * math.sqrt(theta * ubar / max(J))
        return (f"""[body]
principal_moments = {fmt(J)}
[optimal_control]
objective = "minimum_time"
torque_bound = "per_axis"
torque_max = {fmt([ubar] * 3)}
rate_max = {r:.12g}
[optimal_control.final]
orientation = {{ axis_angle = {{ axis = {fmt(axis)}, angle = {theta:.12g} }} }}
""", None)
    sys.exit(f"optimal_indirect_families.py: unknown family {family!r}; expected norm, norm_spin, rate_axis "
             "or rate")


def optimize(text: str, folder: Path) -> tuple:
    path = folder / "s.toml"
    path.write_text(text)
    proc = subprocess.Popen([EXE, "optimize", str(path), "--out", str(folder / "out"), "--json"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    out, err = proc.communicate()
    if proc.returncode not in (0, 1, 3):
        sys.exit(f"optimal_indirect_families.py: poinsot optimize failed: {err.strip()}")
    return json.loads(out)


def main() -> None:
    family = sys.argv[1] if len(sys.argv) > 1 else "norm"
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    rng = random.Random(seed)
    verified, cpu = 0, []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for k in range(n):
            text, closed = problem(family, rng)
            before = os.times()
            s = optimize(text, folder)
            after = os.times()
            seconds = (after.children_user - before.children_user) + (after.children_system -
                                                                       before.children_system)
            cpu.append(seconds)
            verified += bool(s["optimal"])
            T = s["indirect"]["final_time"] or s["direct"]["final_time"]
            ref = f", closed form {closed:.12f} ({T / closed - 1:+.1e})" if closed else ""
            print(f"{family} {k:2d}: T = {T:.12f} s{ref}; {seconds:6.2f} s CPU; {s['status']}", flush=True)
            if os.environ.get("KEEP"):
                (Path(os.environ["KEEP"]) / f"{family}_{seed}_{k}.toml").write_text(text)
    cpu.sort()
    print(f"{family}, seed {seed}: {verified} of {n} verified optimal; CPU median {cpu[len(cpu) // 2]:.2f} s, "
          f"largest {cpu[-1]:.2f} s")


if __name__ == "__main__":
    main()
