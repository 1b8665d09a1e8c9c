"""poinsot.multibody from Python: each joint kind (prismatic, universal with and without offset axes, a ball
standing for three hinges) and their springs, and robot files, checked against what NumPy computes here."""
import math

import numpy as np
import pytest

from poinsot import multibody as mb

from conftest import G, SOURCE_DIR, rot_y


def test_prismatic_joint_slides_along_its_line_under_gravity():
    """A tilted body on an inclined line falls along it with g·e (closed form: constant acceleration, which
    RATTLE and RK4 integrate exactly up to round-off); its rotation stays as it was."""
    e = np.array([1.0, 0.5, -0.8]) / np.linalg.norm([1.0, 0.5, -0.8])
    R0 = rot_y(0.7)
    A = np.array([0.1, -0.2, 0.05])  # joint point, body frame, from the centre of mass
    system = mb.System()
    body = system.add_body("slider", 1.5, np.diag([0.02, 0.05, 0.08]))
    system.add_prismatic("slide", body, A, R0.T @ e, mb.WORLD, [0, 0, 0], R0)
    system.gravity = [0, 0, -G]
    x0 = -R0 @ A
    state = mb.State(bodies=[mb.BodyState(x_space=x0, R_space_body=R0, v_space=0.3 * e)])
    mb.check_consistent(system, state)
    a = -G * e[2]  # g·e
    for integrator in (mb.Rattle(system, 1e-2), mb.ProjectedRk4(system, 1e-2)):
        s = mb.State(bodies=[mb.BodyState(x_space=x0, R_space_body=R0, v_space=0.3 * e)])
        integrator.step(s, steps=100)
        t = s.time
        np.testing.assert_allclose(s[0].x_space, x0 + (0.3 * t + 0.5 * a * t * t) * e, rtol=0, atol=1e-12)
        np.testing.assert_allclose(s[0].R_space_body, R0, rtol=0, atol=1e-14)
        v = mb.constraint_violation(system, s)
        assert v.joint_gap < 1e-12 and v.joint_angle < 1e-13
    # The joint carries the weight across the line: force on the body = −m (g − (g·e) e).
    g = np.array([0, 0, -G])
    reaction = mb.exact_multipliers(system, state).joint_force_space[0]
    np.testing.assert_allclose(reaction, -1.5 * (g - g.dot(e) * e), rtol=0, atol=1e-13)


@pytest.mark.parametrize("h", [0.0, 0.15])
def test_universal_joint_keeps_its_cross_pins_perpendicular_and_its_axes_apart(h):
    """A link on a universal joint (outer pin along space x through the origin, inner pin along body y through
    body point −c), its axes h apart along (R y) × x (h = 0: a Cardan joint, h = 0.15 m: two hinges in series,
    as an ankle): the inner axis stays at that distance, the pins stay perpendicular (checked in NumPy), and
    RATTLE conserves the energy to O(h²)."""
    c = np.array([0.05, 0.02, -0.6])
    system = mb.System()
    link = system.add_body_from_inertia("link", 1.2, np.diag([0.05, 0.07, 0.03]))
    system.add_universal("cardan", link, -c, [0, 1, 0], mb.WORLD, [0, 0, 0], [1, 0, 0], axis_offset=h)
    system.gravity = [0, 0, -G]
    R0 = rot_y(-0.3)
    # 1 rad/s about the outer pin (x, R0ᵀx in the body), 0.5 rad/s about the inner one (body y); the outer turn
    # also moves the inner axis, h from it: x × (−h z) = h y.
    omega = np.array([math.cos(-0.3), 0.0, math.sin(-0.3)]) * 1.0 + np.array([0, 0.5, 0])
    v = R0 @ np.cross(omega, c) + h * np.array([0.0, 1.0, 0.0])
    state = mb.State(bodies=[mb.BodyState(x_space=R0 @ c - h * np.array([0, 0, 1]), R_space_body=R0,
                                          v_space=v, omega_body=omega)])
    mb.check_consistent(system, state)
    E0 = mb.total_energy(system, state)
    rattle = mb.Rattle(system, 2e-3)
    for _ in range(10):
        rattle.step(state, steps=50)
        R, x = state[0].R_space_body, state[0].x_space
        assert np.linalg.norm(x - R @ c - h * np.cross(R @ [0, 1, 0], [1, 0, 0])) < 1e-12
        assert abs((R @ [0, 1, 0]).dot([1, 0, 0])) < 1e-12
    assert abs(mb.total_energy(system, state) - E0) < 1e-4 * abs(E0)
    with pytest.raises(ValueError, match="axis b"):
        system.add_universal("bad", link, [0, 0, 0], [0, 1, 0], mb.WORLD, [0, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="axis offset"):
        system.add_universal("bad", link, [0, 0, 0], [0, 1, 0], mb.WORLD, [0, 0, 0], [1, 0, 0],
                             axis_offset=float("nan"))


def test_ball_joint_springs_act_on_three_hinges_in_series():
    """A ball joint standing for hinges about x, z, y (a hip): at M = Rot(x, q1) Rot(z, q2) Rot(y, q3) the springs'
    energy is that of the three angles, and a coordinate of another joint's kind is refused."""
    system = mb.System()
    body = system.add_body_from_inertia("thigh", 4.0, np.diag([0.3, 0.4, 0.5]))
    hip = system.add_ball("hip", body, [0, 0, 0], mb.WORLD, [0, 0, 0])
    axes = np.array([[1.0, 0, 0], [0, 0, 1], [0, 1, 0]])
    for coordinate, k, rest in (("first", 2.0, 0.1), ("second", 3.0, -0.2), ("third", 5.0, 0.3)):
        system.add_joint_spring(hip, stiffness=k, rest_position=rest, coordinate=coordinate, hinge_axes=axes)
    q = (0.7, -0.8, 0.4)

    def rot(axis, a):
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K

    R = rot(axes[0], q[0]) @ rot(axes[1], q[1]) @ rot(axes[2], q[2])
    state = mb.State(bodies=[mb.BodyState(R_space_body=R)])
    expected = 0.5 * (2.0 * (0.7 - 0.1) ** 2 + 3.0 * (-0.8 + 0.2) ** 2 + 5.0 * (0.4 - 0.3) ** 2)
    assert abs(mb.total_energy(system, state) - expected) < 1e-13
    with pytest.raises(ValueError, match='coordinate "a" does not belong to a ball joint'):
        system.add_joint_spring(hip, stiffness=1.0, coordinate="a", hinge_axes=axes)
    with pytest.raises(ValueError, match="coordinate: got"):
        system.add_joint_spring(hip, stiffness=1.0, coordinate="fourth", hinge_axes=axes)


def test_robot_files_load_as_scenarios_and_systems():
    robots = SOURCE_DIR / "tests" / "data" / "models" / "robots"
    # The URDF double pendulum is the hand-written scenario: same bodies and joints, same initial state.
    robot = mb.load_robot(str(robots / "pendulum2.urdf"))
    toml = mb.load_scenario(str(robots / "pendulum2.toml"))
    assert robot.system.body_names == toml.system.body_names == ["upper", "lower"]
    assert robot.system.joint_names == toml.system.joint_names == ["shoulder", "elbow"]
    for a, b in zip(robot.initial, toml.initial):
        np.testing.assert_array_equal(a.x_space, b.x_space)
    assert any("limits" in line for line in robot.not_modelled)
    assert mb.System.from_file(str(robots / "joints.sdf")).body_names[0] == "tower"
    # Joint coordinates by name: the shoulder at 0.3 rad about y.
    turned = mb.load_robot(str(robots / "pendulum2.urdf"), positions={"shoulder": [0.3]}, gravity=[0, 0, -1.62])
    np.testing.assert_allclose(turned.initial[0].x_space, 0.25 * np.array([math.cos(0.3), 0, -math.sin(0.3)]),
                               atol=1e-16)
    np.testing.assert_array_equal(turned.system.gravity, [0, 0, -1.62])
    with pytest.raises(ValueError, match=r"positions\.knee: no moving joint of that name"):
        mb.load_robot(str(robots / "pendulum2.urdf"), positions={"knee": [1.0]})


def test_a_universal_joint_takes_a_spring_on_either_angle():
    # Two hinges in series, about y of the world then x of the body: R = Rot(y, q_b) Rot(x, q_a); the springs'
    # potential ½ k_a (q_a − 0.1)² + ½ k_b q_b², with the angles of R computed here in NumPy.
    system = mb.System()
    system.add_body("a", 2.0, np.diag([0.3, 0.4, 0.5]))
    u = system.add_universal("u", 0, [0, 0, 0], [1, 0, 0], -1, [0, 0, 0], [0, 1, 0])
    system.add_joint_spring(u, stiffness=2.0, rest_position=0.1)
    system.add_joint_spring(u, stiffness=3.0, coordinate="b")
    q_a, q_b = 0.7, -1.2
    ca, sa, cb, sb = math.cos(q_a), math.sin(q_a), math.cos(q_b), math.sin(q_b)
    R = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]]) @ np.array([[1, 0, 0], [0, ca, -sa], [0, sa, ca]])
    state = mb.State(bodies=[mb.BodyState(R_space_body=R)])
    assert mb.potential_energy(system, state) == pytest.approx(0.5 * 2.0 * 0.6**2 + 0.5 * 3.0 * 1.2**2, abs=1e-13)
    with pytest.raises(ValueError, match='coordinate: got "c"'):
        system.add_joint_spring(u, stiffness=1.0, coordinate="c")
