"""`poinsot optimize` with the rotation-matrix transcription's options (`stabilisation_step`, `warm_start`,
`no_twist`) and with `objective = "minimum_time"` in a multibody file: a rod on a ball joint against the
closed form of its planar turn, the rod on a hinge against the bang-bang time, the options in report.txt and
summary.json, and bad values (one line, exit 2, nothing written). That the file's keys give the optimum of the
same call in C++: tests/io/run/test_multibody_optimal_options.cpp."""
import json
import math

import pytest

# One rod (1 kg, 1 m, radius 5 cm, along body x) on a ball joint with three motors at its end, no gravity,
# from rest at 0 to rest at 1.2 rad about z in 2 s: a bend without twist about the rod's axis, so the
# no-twist condition holds along the planar optimum, cost 12 I² Θ² / T³ with I = J_zz + m (ℓ/2)².
I_HINGE = 1.0 * (3 * 0.05**2 + 1.0) / 12 + 0.25
BALL = """
[[bodies]]
name = "rod"
mass = 1.0
shape = {{ type = "rod", length = 1.0, radius = 0.05 }}
position = [0.5, 0, 0]
[[joints]]
name = "shoulder"
type = "{joint}"
body_a = "rod"
point_a = [-0.5, 0, 0]
{axis}
[optimal_control]
final_time = 2.0
coordinates = "{coordinates}"
intervals = {intervals}
actuators = [{{ joint = "shoulder", torque_max = {torque} }}]
{extra}
[[optimal_control.final]]
body = "rod"
rotation = {{ axis = [0, 0, 1], angle = {theta} }}
"""
OPTIONS = ('stabilisation_step = 0.3\nwarm_start = [4]\nno_twist = [{ joint = "shoulder", axis_a = [1, 0, 0], '
           'rotation = { axis = [0, 0, 1], angle = 0 } }]')


def ball(tmp_path, extra=OPTIONS, intervals=8):
    p = tmp_path / "ball.toml"
    p.write_text(BALL.format(joint="ball", axis="", coordinates="rotation_matrix", intervals=intervals,
                             torque=50, extra=extra, theta=1.2))
    return p


def hinge(tmp_path, extra):
    p = tmp_path / "hinge.toml"
    p.write_text(BALL.format(joint="hinge", axis="axis_a = [0, 0, 1]", coordinates="minimal", intervals=15,
                             torque=1, extra=extra, theta=1.0))
    return p


def test_ball_joint_with_the_options_meets_the_closed_form(cli, tmp_path):
    out = tmp_path / "out"
    r = cli("optimize", ball(tmp_path), "--out", out)
    assert r.returncode == 0, r.stderr + r.stdout
    assert "no twist: ball joint shoulder" in r.stdout
    assert "stabilising variables bounded by c/h, c = 0.3" in r.stdout
    assert "warm start: 4 intervals, converged" in r.stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["optimal"] is True
    problem = summary["problem"]
    assert problem["stabilisation_step"] == 0.3
    assert problem["no_twist"][0]["joint"] == "shoulder" and problem["no_twist"][0]["axis_a"] == [1, 0, 0]
    assert [m["intervals"] for m in problem["mesh_sequence"]] == [4]
    assert problem["mesh_sequence"][0]["status"] == "converged"
    assert problem["actuators"][0]["kind"] == "ball_torque"
    # R-coordinates' Hermite–Simpson error at N = 8 (2e-5 relative for the hinge): within 1e-4.
    assert summary["solution"]["cost"] == pytest.approx(12 * I_HINGE**2 * 1.2**2 / 2.0**3, rel=1e-4)
    # The stabilising variables' step stays below half its bound (else the run would be "not converged").
    assert 0 < summary["solution"]["stabilisation_step"] < 0.15
    assert summary["replay"]["target_reached"] is True and summary["replay"]["max_joint_gap"] < 1e-12


def test_minimum_time_file_meets_the_bang_bang_time(cli, tmp_path):
    out = tmp_path / "out"
    r = cli("optimize", hinge(tmp_path, 'objective = "minimum_time"\nfinal_time_bounds = [0.5, 5]'), "--out", out)
    assert r.returncode == 0, r.stderr + r.stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["objective"] == "minimum_time"
    assert summary["problem"]["final_time_bounds"] == [0.5, 5]
    # T* = 2 √(Θ I / ū); the odd mesh (15 intervals) blurs the switch by about 0.19/N² s (measured 8.6e-4 s).
    T = summary["solution"]["final_time"]
    T_star = 2 * math.sqrt(I_HINGE)
    assert 0.1 / 15**2 < T - T_star < 0.3 / 15**2
    assert summary["solution"]["cost"] == T
    assert float((out / "control.csv").read_text().splitlines()[-1].split(",")[0]) == T
    assert summary["replay"]["target_reached"] is True


@pytest.mark.parametrize("extra, fragment", [
    ("stabilisation_step = 0.7", "stabilisation_step: got 0.7; expected a number from 0 to 0.6"),
    ("warm_start = [8]", "warm_start: got [8]; expected increasing whole numbers of intervals"),
    ("warm_start = 4", "warm_start: got 4, expected an array of whole numbers"),
    ('no_twist = [{ joint = "shoulder", axis_a = [0, 0, 1] }]', "no_twist[0]: the final state has the twist"),
    ('no_twist = [{ joint = "hip", axis_a = [1, 0, 0] }]', 'joint: got "hip", expected the name of a ball joint'),
    ('objective = "minimum_time"\nfinal_time_bounds = [3, 1]', "final_time: got the bounds [3, 1] s"),
])
def test_bad_values_are_one_line_exit_2_nothing_written(cli, tmp_path, extra, fragment):
    out = tmp_path / "out"
    r = cli("optimize", ball(tmp_path, extra), "--out", out)
    assert r.returncode == 2, r.stdout
    assert fragment in r.stderr
    assert r.stderr.startswith("poinsot: ") and r.stderr.count("\n") == 1
    assert not out.exists()
