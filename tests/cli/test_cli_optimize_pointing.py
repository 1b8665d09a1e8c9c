"""`poinsot optimize` with keep-out and keep-in cones ([[optimal_control.keep_out]], [[optimal_control.keep_in]]):
the example whose cone is active ends "converged (direct; ...)" (exit 3) with the cone holding on the DOP853
re-simulation; a cone the optimum misses leaves it verified; bad cones are one line naming the key (exit 2)."""
import csv
import json
import math
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
EXAMPLE = SOURCE / "examples" / "optimal" / "sun_avoidance_slew.toml"

# The sphere turned 150° about z at minimum energy in 4 s: the boresight x sweeps the xy plane; the cone
# {cone} is written in after [optimal_control].
SPHERE = """
[body]
principal_moments = [2.0, 2.0, 2.0]
[optimal_control]
objective = "minimum_energy"
torque_bound = "norm"
torque_max = 100.0
final_time = 4.0
mesh_tolerance = 1e-8
initial_intervals = 16
[optimal_control.final]
orientation = {{ axis_angle = {{ axis = [0.0, 0.0, 1.0], angle = 150.0 }}, degrees = true }}
{cone}
"""

# 0.3 rad above the boresight's halfway direction (75° from x in the xy plane)
SUN = [math.cos(0.3) * math.cos(math.radians(75)), math.cos(0.3) * math.sin(math.radians(75)), math.sin(0.3)]


def cone(half_angle_deg, direction=SUN, boresight=(1.0, 0.0, 0.0), kind="keep_out", extra=""):
    return (f"[[optimal_control.{kind}]]\nname = \"sun\"\nboresight_body = {list(boresight)}\n"
            f"direction_space = {list(direction)}\nhalf_angle_deg = {half_angle_deg}\n{extra}")


def write(tmp_path, text):
    p = tmp_path / "s.toml"
    p.write_text(text)
    return p


def angles(folder):
    with open(folder / "trajectory.csv", encoding="utf-8") as f:
        f.readline()
        rows = list(csv.DictReader(f))
    return [float(r["angle_keep_out_1"]) for r in rows]


@pytest.mark.slow_under_sanitizers
def test_active_cone_is_converged_direct_and_holds_on_the_replay(cli, tmp_path):
    out = tmp_path / "out"
    r = cli("optimize", EXAMPLE, "--out", out, "--quiet")
    assert r.returncode == 3, r.stdout + r.stderr
    assert "status: converged (direct; minimum principle not verified: the keep_out \"sun\" cone is active" in r.stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["outcome"] == "converged_direct" and summary["optimal"] is False
    [sun] = summary["pointing"]
    assert sun["kind"] == "keep_out" and sun["column"] == "angle_keep_out_1"
    assert abs(sun["half_angle"] - math.radians(50)) < 1e-15
    assert sun["direct_replay"]["margin"] >= -1e-9  # the dense re-simulation stays out of the cone
    assert sun["largest_multiplier"] > 0 and sun["indirect"] is None
    assert summary["direct_replay"]["scaled_error"] <= 1e-6
    # the collocated samples meet the widened cone to Ipopt's constraint tolerance, so the cone itself
    assert min(angles(out)) >= sun["half_angle"]
    assert (out / "trajectory.csv").read_text().startswith("# status: converged (direct;")


def test_cone_the_optimum_misses_leaves_it_verified(cli, tmp_path):
    out = tmp_path / "out"
    r = cli("optimize", write(tmp_path, SPHERE.format(cone=cone(math.degrees(0.25)))), "--out", out, "--quiet")
    assert r.returncode == 0, r.stdout
    summary = json.loads((out / "summary.json").read_text())
    # the free optimum: the eigenaxis turn, cost 12 j² Θ²/T³, passing 0.3 rad from the Sun at T/2
    theta = math.radians(150)
    assert abs(summary["indirect"]["cost"] / (12 * 4.0 * theta**2 / 64.0) - 1) < 1e-10
    [sun] = summary["pointing"]
    assert abs(sun["indirect"]["margin"] - 0.05) < 1e-6 and abs(sun["indirect"]["t"] - 2.0) < 0.1
    assert "cones along the indirect solution (none active)" in r.stdout
    assert 0.3 - 1e-9 <= min(angles(out)) < 0.31  # the samples nearest T/2


@pytest.mark.parametrize("text, key", [
    # the start's boresight x lies inside a 10° cone about x
    (cone(10, direction=(1.0, 0.0, 0.0)), "optimal_control.keep_out[1]: the boresight"),
    (cone(30, boresight=(0.0, 0.0, 0.0)), "boresight_body"),
    (cone(0), "half_angle_deg"),
    (cone(30, extra="half_angle = 0.5\n"), "half_angle"),
    (cone(30, extra="colour = 1\n"), "colour"),
    # keep-in about x with 80°: the final boresight is 150° away
    (cone(80, direction=(1.0, 0.0, 0.0), kind="keep_in"), "optimal_control.keep_in[1]: the boresight"),
])
def test_bad_cones_are_one_line_naming_the_key(cli, tmp_path, text, key):
    out = tmp_path / "out"
    r = cli("optimize", write(tmp_path, SPHERE.format(cone=text)), "--out", out)
    assert r.returncode == 2, r.stdout
    assert r.stderr.count("\n") == 1 and key in r.stderr, r.stderr
    assert not out.exists()
