#!/usr/bin/env python3
"""Random optimal-control problems for `poinsot optimize`, and how it ends on them
(docs/measurements/optimal_control.md, "The random-problem benchmark").

Each problem is a scenario file generated from (family, seed, index) alone, so any problem can be written
again and run by hand:

    python3 scripts/optimal_benchmark.py --family per_axis --seed 1 --n 8              # run, print the table
    python3 scripts/optimal_benchmark.py --family norm --seed 1 --n 8 --emit DIR       # only write the files
    python3 scripts/optimal_benchmark.py --seed 1 --n 8 --json results.json            # every family

Families (FAMILIES below): per_axis, norm (minimum time under ‖u‖ ≤ ū), energy (minimum energy, norm bound,
T fixed), spin (minimum time from a spin about a random axis to rest), rate (minimum time with an active rate
bound), detumble (minimum time to rest, free final attitude), nonprincipal (minimum time, per-axis bounds, a
full inertia tensor), keep_out (minimum time, per-axis bounds, turns of 60° … 180°, a random boresight kept
15° … 40° from a direction within half that angle of the boresight's position halfway along the eigenaxis
turn, and at least 5° more from it at both ends: a cone across the eigenaxis path), keep_in (the same turns, a
random boresight kept within a cone about the bisector of its start and end directions, 3° … 15° wider than
half their angle), arm (the two-link arm of examples/optimal/two_link_arm.toml to a random target at
minimum energy, minimal coordinates). Rigid bodies: principal moments J1 ≤ J2 ≤ J3 ≤ J1 + J2 with J3/J1 ≤ 4,
scaled by 10^U(−1, 1) kg·m²; rest-to-rest turns of 20° … 180° about a random axis; bounds U(0.5, 2) N·m per
axis (ū U(0.5, 2) N·m for a norm bound).

Each run is `poinsot optimize FILE --json --quiet` with a CPU-time limit (--cpu-limit, RLIMIT_CPU) and a
wall-clock one (--timeout); its exit status is the outcome: 0 verified optimal, 3 converged (direct; minimum
principle not verified), 1 failed (reaching a limit counts as failed; 2, bad input, is a defect of the generator and makes this script exit 1). The CPU time is
the child's user + system time (resource.getrusage). Output: one row per problem (with --verbose), then per
family the shares and the median and 95th percentile of the CPU time. `--expect-verified FAMILY,...` makes
the script exit 1 unless every problem of those families is verified optimal (the CI's smoke run,
tests/cli/test_optimal_benchmark.py). `--starts N` writes `starts = N` into every single-body file (the first mesh's
guesses: docs/optimal_control.md, "Several starts"), so that two settings can be compared on the same problems;
`--json` records each answer's cost (the indirect solution's where it is the answer, else the direct one's) and
the start the refinement continued from.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

FAMILIES = ("per_axis", "norm", "energy", "spin", "rate", "detumble", "nonprincipal", "keep_out", "keep_in",
            "arm")


def _moments(rng: random.Random) -> list[float]:
    """Principal moments with J1 ≤ J2 ≤ J3 ≤ J1 + J2 and J3/J1 ≤ 4, in random order, scaled."""
    j2 = rng.uniform(1.0, 3.0)
    j3 = rng.uniform(j2, min(4.0, 1.0 + j2))
    scale = 10.0 ** rng.uniform(-1.0, 1.0)
    m = [scale, scale * j2, scale * j3]
    rng.shuffle(m)
    return m


def _unit(rng: random.Random) -> list[float]:
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-3:
            return [x / n for x in v]


def _rotation(axis: list[float], angle: float) -> list[list[float]]:
    """Rodrigues' formula."""
    x, y, z = axis
    c, s, t = math.cos(angle), math.sin(angle), 1.0 - math.cos(angle)
    return [[c + t * x * x, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, c + t * y * y, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, c + t * z * z]]


def _fmt(v) -> str:
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    return repr(float(v))


def _keep_out_cone(rng: random.Random, axis: list[float], angle: float) -> list[str]:
    """A [[optimal_control.keep_out]] table across the eigenaxis turn (family keep_out): redrawn until both ends
    are at least 5° outside the cone."""
    def apply(R, v):
        return [sum(R[i][k] * v[k] for k in range(3)) for i in range(3)]

    def angle_between(a, b):
        return math.acos(max(-1.0, min(1.0, sum(x * y for x, y in zip(a, b)))))

    while True:
        boresight, half = _unit(rng), math.radians(rng.uniform(15.0, 40.0))
        halfway = apply(_rotation(axis, 0.5 * angle), boresight)
        side = _unit(rng)  # tilt `halfway` towards a random direction by at most half the half-angle
        ortho = [x - sum(a * b for a, b in zip(side, halfway)) * h for x, h in zip(side, halfway)]
        n = math.sqrt(sum(x * x for x in ortho))
        if n < 1e-3:
            continue
        tilt = rng.uniform(0.0, 0.5 * half)
        sun = [math.cos(tilt) * h + math.sin(tilt) * o / n for h, o in zip(halfway, ortho)]
        end = apply(_rotation(axis, angle), boresight)
        if min(angle_between(boresight, sun), angle_between(end, sun)) > half + math.radians(5.0):
            return ["[[optimal_control.keep_out]]", 'name = "sun"', f"boresight_body = {_fmt(boresight)}",
                    f"direction_space = {_fmt(sun)}", f"half_angle = {_fmt(half)}"]


def _keep_in_cone(rng: random.Random, axis: list[float], angle: float) -> list[str]:
    """A [[optimal_control.keep_in]] table about the bisector of a random boresight's start and end directions
    (family keep_in), 3° … 15° wider than half their angle: redrawn until they are at least 10° apart."""
    while True:
        boresight = _unit(rng)
        end = [sum(r * b for r, b in zip(row, boresight)) for row in _rotation(axis, angle)]
        between = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(boresight, end)))))
        if between < math.radians(10.0):
            continue
        bisector = [a + b for a, b in zip(boresight, end)]
        n = math.sqrt(sum(x * x for x in bisector))
        half = 0.5 * between + math.radians(rng.uniform(3.0, 15.0))
        return ["[[optimal_control.keep_in]]", 'name = "antenna"', f"boresight_body = {_fmt(boresight)}",
                f"direction_space = {_fmt([x / n for x in bisector])}", f"half_angle = {_fmt(half)}"]


def _rigid_body(family: str, rng: random.Random) -> str:
    """The scenario text of a single-body family's problem."""
    moments = _moments(rng)
    axis, angle = _unit(rng), math.radians(rng.uniform(20.0, 180.0))
    per_axis = [rng.uniform(0.5, 2.0) for _ in range(3)]
    norm = rng.uniform(0.5, 2.0)
    body = f"principal_moments = {_fmt(moments)}"
    lines = ["[optimal_control]"]
    initial: list[str] = []
    cones: list[str] = []  # [[optimal_control.keep_out]] or keep_in tables, after the final state
    final = [f"orientation = {{ axis_angle = {{ axis = {_fmt(axis)}, angle = {_fmt(angle)} }} }}"]
    if family == "per_axis":
        lines += ['objective = "minimum_time"', 'torque_bound = "per_axis"', f"torque_max = {_fmt(per_axis)}"]
    elif family == "norm":
        lines += ['objective = "minimum_time"', 'torque_bound = "norm"', f"torque_max = {_fmt(norm)}"]
    elif family == "energy":
        # T between 1.5 and 3 times the eigenaxis time 2√(Θ J3/ū) of the largest moment: above the minimum
        # duration, so the problem is feasible, with the bound active or not.
        t_eig = 2.0 * math.sqrt(angle * max(moments) / norm)
        lines += ['objective = "minimum_energy"', 'torque_bound = "norm"', f"torque_max = {_fmt(norm)}",
                  f"final_time = {_fmt(rng.uniform(1.5, 3.0) * t_eig)}"]
    elif family == "spin":
        # a spin whose momentum the bounds remove in about 0.2 … 1 of the rest-to-rest slew's time
        j = max(moments)
        rate = rng.uniform(0.2, 1.0) * math.sqrt(angle * min(per_axis) / j)
        initial = [f"omega_body = {_fmt([rate * x for x in _unit(rng)])}"]
        lines += ['objective = "minimum_time"', 'torque_bound = "per_axis"', f"torque_max = {_fmt(per_axis)}"]
    elif family == "rate":
        # the bang-bang eigenaxis slew's peak rate √(Θ ū/J) about the largest moment, halved or less: active
        peak = math.sqrt(angle * min(per_axis) / max(moments))
        lines += ['objective = "minimum_time"', 'torque_bound = "per_axis"', f"torque_max = {_fmt(per_axis)}",
                  f"rate_max = {_fmt(rng.uniform(0.3, 0.6) * peak)}"]
    elif family == "detumble":
        rate = rng.uniform(0.1, 1.0) * math.sqrt(norm / min(moments))
        initial = [f"omega_body = {_fmt([rate * x for x in _unit(rng)])}"]
        final = ["free_attitude = true"]
        lines += ['objective = "minimum_time"', 'torque_bound = "norm"', f"torque_max = {_fmt(norm)}"]
    elif family in ("keep_out", "keep_in"):
        angle = math.radians(rng.uniform(60.0, 180.0))
        final = [f"orientation = {{ axis_angle = {{ axis = {_fmt(axis)}, angle = {_fmt(angle)} }} }}"]
        lines += ['objective = "minimum_time"', 'torque_bound = "per_axis"', f"torque_max = {_fmt(per_axis)}"]
        cones = (_keep_out_cone if family == "keep_out" else _keep_in_cone)(rng, axis, angle)
    elif family == "nonprincipal":
        R = _rotation(_unit(rng), rng.uniform(0.0, math.pi))
        J = [[sum(R[i][k] * moments[k] * R[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
        J = [[0.5 * (J[i][j] + J[j][i]) for j in range(3)] for i in range(3)]
        body = f"inertia = {_fmt(J)}"
        lines += ['objective = "minimum_time"', 'torque_bound = "per_axis"', f"torque_max = {_fmt(per_axis)}"]
    else:
        raise ValueError(f"--family: {family!r}; expected one of {', '.join(FAMILIES)}")
    text = ["[body]", body, *lines]
    if initial:
        text += ["[optimal_control.initial]", *initial]
    text += ["[optimal_control.final]", *final, *cones]
    return "\n".join(text) + "\n"


def _arm(rng: random.Random, source_dir: Path) -> str:
    """The two-link arm example with a random target (shoulder, elbow) and duration."""
    text = (source_dir / "examples" / "optimal" / "two_link_arm.toml").read_text()
    shoulder, elbow = rng.uniform(0.3, 1.5), rng.uniform(-1.0, 1.0)
    T = rng.uniform(1.2, 2.5)
    upper = -math.pi / 2 + shoulder
    fore = upper + elbow
    text = text.replace("final_time = 1.5 ", f"final_time = {_fmt(T)} ")
    text = text.replace("angle = -0.5707963267948966 }", f"angle = {_fmt(upper)} }}")
    text = text.replace("angle = -0.0707963267948966 }", f"angle = {_fmt(fore)} }}")
    text = text.replace('title = "Two-link arm, hanging to (1, 0.5) rad, minimum energy in 1.5 s"',
                        f'title = "Two-link arm to ({shoulder:.3f}, {elbow:.3f}) rad in {T:.3f} s"')
    # the example's comments describe its own target: dropped
    return "\n".join(line.split("#")[0].rstrip() for line in text.splitlines() if not line.startswith("#")) + "\n"


def scenario(family: str, seed: int, index: int, source_dir: Path) -> str:
    """The scenario text of problem `index` of `family` drawn from `seed` (deterministic)."""
    rng = random.Random(f"{family}/{seed}/{index}")
    header = f"# optimal_benchmark.py: family {family}, seed {seed}, problem {index}\n"
    if family == "arm":
        return header + _arm(rng, source_dir)
    return header + _rigid_body(family, rng)


OUTCOMES = {0: "verified", 3: "converged_direct", 1: "failed"}


def answer_cost(summary: dict):
    """The cost of the answer in a summary.json of `poinsot optimize`: the indirect solution's where it is
    the answer, else the direct one's; None where the summary has neither (a multibody run's)."""
    part = summary.get("indirect") if summary.get("solution_from") == "indirect" else summary.get("direct")
    return part.get("cost") if isinstance(part, dict) else None


def run_one(poinsot: str, path: Path, out: Path, timeout: float, cpu_limit: float) -> dict:
    """Runs `poinsot optimize` on one file: its outcome, CPU and wall time, and its status line. The child's
    CPU time is limited to `cpu_limit` s (RLIMIT_CPU: a loaded machine does not turn slow runs into
    failures), its wall time to `timeout` s."""
    def limit_cpu():
        seconds = max(1, int(math.ceil(cpu_limit)))
        resource.setrlimit(resource.RLIMIT_CPU, (seconds, seconds + 5))

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    try:
        r = subprocess.run([poinsot, "optimize", str(path), "--out", str(out), "--json", "--quiet"],
                           capture_output=True, text=True, timeout=timeout, preexec_fn=limit_cpu)
        code, status, cost, chosen_start = r.returncode, "", None, None
        if code in OUTCOMES:
            try:
                summary = json.loads(r.stdout)
                status = summary["status"]
                direct = summary.get("direct")
                cost = answer_cost(summary)
                chosen_start = direct.get("chosen_start") if isinstance(direct, dict) else None
            except (ValueError, KeyError):
                status = r.stdout.strip().splitlines()[0] if r.stdout.strip() else ""
        elif code in (-24, -9):  # SIGXCPU, SIGKILL: the CPU limit
            status = f"CPU limit of {cpu_limit:g} s reached"
        else:
            status = (r.stderr.strip() or r.stdout.strip()).splitlines()[-1:] or [""]
            status = status[0]
    except subprocess.TimeoutExpired:
        code, status, cost, chosen_start = None, f"timeout after {timeout:g} s", None, None
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    outcome = OUTCOMES.get(code, "failed") if code != 2 else "bad_input"
    return {"outcome": outcome, "exit": code, "cpu_s": cpu, "wall_s": time.monotonic() - start,
            "status": status, "cost": cost, "chosen_start": chosen_start}


def percentile(values: list[float], q: float) -> float:
    """The q-quantile (0 ≤ q ≤ 1) by linear interpolation between order statistics."""
    v = sorted(values)
    if not v:
        return math.nan
    x = q * (len(v) - 1)
    lo = math.floor(x)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (x - lo) * (v[hi] - v[lo])


def table(results: list[dict]) -> str:
    rows = ["| family | problems | verified | converged (direct) | failed | CPU median (s) | CPU 95th pct (s) |",
            "|---|---|---|---|---|---|---|"]
    for family in FAMILIES:
        rs = [r for r in results if r["family"] == family]
        if not rs:
            continue
        n = len(rs)
        count = {k: sum(r["outcome"] == k for r in rs) for k in ("verified", "converged_direct")}
        failed = n - count["verified"] - count["converged_direct"]
        cpu = [r["cpu_s"] for r in rs]
        rows.append(f"| {family} | {n} | {count['verified']} | {count['converged_direct']} | {failed} | "
                    f"{percentile(cpu, 0.5):.2f} | {percentile(cpu, 0.95):.2f} |")
    return "\n".join(rows)


def main(argv: list[str] | None = None) -> int:
    source_dir = Path(__file__).resolve().parents[1]
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--family", default=",".join(FAMILIES),
                    help=f"comma-separated families (default: all): {', '.join(FAMILIES)}")
    ap.add_argument("--seed", type=int, default=1, help="the seed of every family's problems (default 1)")
    ap.add_argument("--n", type=int, default=8, help="problems per family (default 8)")
    ap.add_argument("--first", type=int, default=0, help="index of the first problem (default 0)")
    ap.add_argument("--poinsot", default=os.environ.get("POINSOT_CLI", str(source_dir / "build/release/apps/poinsot/poinsot")),
                    help="the poinsot binary (default: $POINSOT_CLI, else build/release/apps/poinsot/poinsot)")
    ap.add_argument("--cpu-limit", type=float, default=120.0,
                    help="CPU-time limit per problem, s (default 120; reaching it counts as failed)")
    ap.add_argument("--timeout", type=float, default=3600.0,
                    help="wall-clock limit per problem, s (default 3600: a safety net beside --cpu-limit)")
    ap.add_argument("--emit", metavar="DIR", help="write the scenario files into DIR and run nothing")
    ap.add_argument("--keep", metavar="DIR", help="keep the scenario files and the outputs in DIR")
    ap.add_argument("--json", metavar="FILE", help="write every problem's result to FILE")
    ap.add_argument("--verbose", action="store_true", help="one line per problem as it ends")
    ap.add_argument("--starts", type=int, metavar="N",
                    help="write `starts = N` into every single-body problem's [optimal_control] (the first "
                         "mesh's guesses; default: the file's default)")
    ap.add_argument("--expect-verified", default="", metavar="FAMILIES",
                    help="exit 1 unless every problem of these comma-separated families is verified optimal")
    a = ap.parse_args(argv)
    families = [f for f in a.family.split(",") if f]
    for f in families + [f for f in a.expect_verified.split(",") if f]:
        if f not in FAMILIES:
            ap.error(f"--family: {f!r}; expected one of {', '.join(FAMILIES)}")
    if a.n < 1:
        ap.error(f"--n: {a.n}; expected at least 1")
    problems = [(f, i) for f in families for i in range(a.first, a.first + a.n)]

    def text_of(f: str, i: int) -> str:
        text = scenario(f, a.seed, i, source_dir)
        if a.starts is None or f == "arm":
            return text
        return text.replace("[optimal_control]\n", f"[optimal_control]\nstarts = {a.starts}\n", 1)

    if a.emit:
        out = Path(a.emit)
        out.mkdir(parents=True, exist_ok=True)
        for f, i in problems:
            (out / f"{f}_{a.seed}_{i}.toml").write_text(text_of(f, i))
        print(f"{len(problems)} scenario files in {out}")
        return 0
    work = Path(a.keep) if a.keep else Path(tempfile.mkdtemp(prefix="poinsot-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    results = []
    try:
        for f, i in problems:
            path = work / f"{f}_{a.seed}_{i}.toml"
            path.write_text(text_of(f, i))
            r = {"family": f, "seed": a.seed, "index": i,
                 **run_one(a.poinsot, path, work / f"{f}_{a.seed}_{i}-out", a.timeout, a.cpu_limit)}
            results.append(r)
            if a.verbose:
                print(f"{f:12s} {i:3d}  {r['outcome']:16s} {r['cpu_s']:8.2f} s CPU  {r['status'][:110]}",
                      flush=True)
    finally:
        if not a.keep:
            shutil.rmtree(work, ignore_errors=True)
    print(table(results))
    if a.json:
        Path(a.json).write_text(json.dumps(results, indent=1) + "\n")
    bad = [r for r in results if r["outcome"] == "bad_input"]
    for r in bad:
        print(f"generator defect: {r['family']} seed {r['seed']} problem {r['index']}: {r['status']}",
              file=sys.stderr)
    expected = [f for f in a.expect_verified.split(",") if f]
    missed = [r for r in results if r["family"] in expected and r["outcome"] != "verified"]
    for r in missed:
        print(f"not verified: {r['family']} seed {r['seed']} problem {r['index']}: {r['status']}",
              file=sys.stderr)
    return 1 if bad or missed else 0


if __name__ == "__main__":
    sys.exit(main())
