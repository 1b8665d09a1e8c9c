"""poinsot.optimize on coupled bodies with the rotation-matrix transcription's options (stabilisation_step,
warm_start, no_twist) and with a free final time (objective="minimum_time"): a rod on a ball joint against the
closed form of its planar turn, the same options from a file giving the same optimum, the rod on a hinge
against the bang-bang time, and bad values as ValueError."""
import math

import numpy as np
import pytest

import poinsot
from poinsot import multibody as mb

I_HINGE = (3 * 0.05**2 + 1) / 12 + 0.25  # the rod (1 kg, 1 m, radius 5 cm) about its end
NO_TWIST = [{"joint": "shoulder", "axis_a": [1.0, 0.0, 0.0], "straight": np.eye(3)}]


def rod_state(theta):
    c, s = math.cos(theta), math.sin(theta)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return mb.State(bodies=[mb.BodyState(x_space=R @ [0.5, 0.0, 0.0], R_space_body=R)])


def rod_system(joint):
    system = mb.System()
    J = np.diag([0.5 * 0.05**2, (3 * 0.05**2 + 1) / 12, (3 * 0.05**2 + 1) / 12])
    rod = system.add_body_from_inertia("rod", 1.0, J)
    if joint == "ball":
        system.add_ball("shoulder", rod, [-0.5, 0, 0], mb.WORLD, [0, 0, 0])
    else:
        system.add_hinge("shoulder", rod, [-0.5, 0, 0], [0, 0, 1], mb.WORLD, [0, 0, 0], [0, 0, 1])
    return system


def ball_problem(**options):
    return poinsot.optimal.MultibodyProblem(
        system=rod_system("ball"), initial_state=rod_state(0.0), final_state=rod_state(1.2), final_time=2.0,
        actuators=[{"joint": "shoulder", "torque_max": 50.0}], intervals=8, **options)


def test_options_meet_the_closed_form_and_equal_the_file(tmp_path):
    # A bend about z without twist about the rod's axis: the planar optimum, cost 12 I² Θ² / T³ to
    # R-coordinates' Hermite–Simpson error at N = 8 (2e-5 relative); the no-twist rows hold along it.
    r = poinsot.optimize(ball_problem(), stabilisation_step=0.3, warm_start=[4], no_twist=NO_TWIST)
    assert r.optimal, r.status
    assert r.control_names == ["shoulder.ux", "shoulder.uy", "shoulder.uz"]
    assert r.cost == pytest.approx(12 * I_HINGE**2 * 1.2**2 / 2.0**3, rel=1e-4)
    assert r.summary["problem"]["stabilisation_step"] == 0.3
    assert [m["intervals"] for m in r.summary["problem"]["mesh_sequence"]] == [4]
    assert r.summary["problem"]["no_twist"][0]["joint"] == "shoulder"
    # The twist s·vee(M − Mᵀ) of R_aᵀ (world b, C = I) about the rod's axis x at every collocation point.
    M = np.transpose(r.R_space_body[:, 0], (0, 2, 1))
    assert np.abs(M[:, 2, 1] - M[:, 1, 2]).max() < 1e-9
    # The same options given to the constructor, and the same problem from a file: the same optimum.
    direct = poinsot.optimize(ball_problem(stabilisation_step=0.3, warm_start=[4], no_twist=NO_TWIST))
    assert direct.cost == r.cost and direct.nlp_iterations == r.nlp_iterations
    path = tmp_path / "ball.toml"
    path.write_text("""
[[bodies]]
name = "rod"
mass = 1.0
shape = { type = "rod", length = 1.0, radius = 0.05 }
position = [0.5, 0, 0]
[[joints]]
name = "shoulder"
type = "ball"
body_a = "rod"
point_a = [-0.5, 0, 0]
[optimal_control]
final_time = 2.0
intervals = 8
stabilisation_step = 0.3
warm_start = [4]
no_twist = [{ joint = "shoulder", axis_a = [1, 0, 0], rotation = { axis = [0, 0, 1], angle = 0 } }]
actuators = [{ joint = "shoulder", torque_max = 50 }]
[[optimal_control.final]]
body = "rod"
rotation = { axis = [0, 0, 1], angle = 1.2 }
""")
    from_file = poinsot.optimize(str(path))
    assert from_file.cost == pytest.approx(r.cost, rel=1e-10)
    assert from_file.problem.warm_start == [4] and from_file.problem.stabilisation_step == 0.3


def test_minimum_time_meets_the_bang_bang_time():
    p = poinsot.optimal.MultibodyProblem(
        system=rod_system("hinge"), initial_state=rod_state(0.0), final_state=rod_state(1.0), final_time=2.0,
        actuators=[{"joint": "shoulder", "torque_max": 1.0}], intervals=15, coordinates="minimal",
        objective="minimum_time", final_time_bounds=[0.5, 5.0])
    r = poinsot.optimize(p)
    assert r.optimal, r.status
    # T* = 2 √(Θ I / ū); the odd mesh blurs the switch by about 0.19/N² s (measured 8.6e-4 s at N = 15).
    T_star = 2 * math.sqrt(I_HINGE)
    assert 0.1 / 15**2 < r.final_time - T_star < 0.3 / 15**2
    assert r.t[-1] == r.final_time and r.cost == r.final_time
    assert r.summary["objective"] == "minimum_time"
    # Bang-bang away from the switch: ±ū at the first and last midpoints.
    assert r.controls[1, 0] == pytest.approx(1.0, abs=1e-6) and r.controls[-2, 0] == pytest.approx(-1.0, abs=1e-6)


def test_bad_values_raise_value_error():
    with pytest.raises(ValueError, match="stabilisation_step: got 0.7; expected a number from 0 to 0.6"):
        ball_problem(stabilisation_step=0.7)
    with pytest.raises(ValueError, match=r"warm_start: got \[8\]; expected increasing"):
        ball_problem(warm_start=[8])
    with pytest.raises(ValueError, match=r"no_twist\[0\]: joint: got \"hip\", expected the name of a ball joint"):
        ball_problem(no_twist=[{"joint": "hip", "axis_a": [1, 0, 0], "straight": np.eye(3)}])
    with pytest.raises(ValueError, match="no_twist\\[0\\]: the final state has the twist"):
        ball_problem(no_twist=[{"joint": "shoulder", "axis_a": [0, 0, 1], "straight": np.eye(3)}])
    with pytest.raises(ValueError, match="no_twist\\[0\\]: expected a dict"):
        ball_problem(no_twist=[{"joint": "shoulder"}])
    with pytest.raises(ValueError, match="final_time_bounds: got None"):
        ball_problem(objective="minimum_time")
    with pytest.raises(ValueError, match="final_time: got the bounds \\[3, 1\\] s"):
        ball_problem(objective="minimum_time", final_time_bounds=[3.0, 1.0])
    with pytest.raises(ValueError, match="objective: got \"fastest\""):
        ball_problem(objective="fastest")
    with pytest.raises(ValueError, match="stabilisation_step: an option of multibody problems"):
        poinsot.optimize(poinsot.optimal.ReorientationProblem(inertia=np.eye(3), torque_max=[1, 1, 1]),
                         stabilisation_step=0.1)
    with pytest.raises(ValueError, match="stabilisation_step: got 0.9"):
        poinsot.optimize(ball_problem(), stabilisation_step=0.9)
