"""poinsot.multibody: the multibody layer from Python, checked against closed forms computed here in NumPy."""
import io
import math

import numpy as np
import pytest

import poinsot
from poinsot import multibody as mb

from conftest import G, SOURCE_DIR, rot_y


def hat(u):
    return np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])


def rod_poinsot(m, length, radius):
    """K = ∫ρ X⊗X of a solid cylinder along the body z axis, about its centre (kg·m²)."""
    return np.diag([m * radius**2 / 4, m * radius**2 / 4, m * length**2 / 12])


def inertia_from_poinsot(K):
    return np.trace(K) * np.eye(3) - K


def compound_pendulum(m=1.0, length=1.0, radius=0.01):
    """A rod hung from its top end by a hinge about the space y axis; at rest it hangs along −z."""
    system = mb.System()
    rod = system.add_body("rod", m, rod_poinsot(m, length, radius))
    pivot_body = np.array([0.0, 0.0, length / 2])
    system.add_hinge("pivot", rod, pivot_body, [0, 1, 0], mb.WORLD, [0, 0, 0], [0, 1, 0])
    system.gravity = [0, 0, -G]
    return system, pivot_body


def pendulum_state(theta0, pivot_body):
    R = rot_y(theta0)
    return mb.State(bodies=[mb.BodyState(x_space=-R @ pivot_body, R_space_body=R)])


def swing_angle(R):
    """Angle of the rod (body z axis) from the downward vertical, about +y."""
    return math.atan2(R[0, 2], R[2, 2])


def test_compound_pendulum_period_and_constraints():
    m, length, radius = 1.0, 1.0, 0.01
    system, pivot_body = compound_pendulum(m, length, radius)
    J = inertia_from_poinsot(rod_poinsot(m, length, radius))
    d = length / 2
    I_pivot = J[1, 1] + m * d**2  # parallel-axis theorem about the hinge axis
    omega0 = math.sqrt(m * G * d / I_pivot)
    theta0 = 0.02
    # Small-oscillation period with the first amplitude correction (1 + θ0²/16) of the exact pendulum period:
    # the next term, 11θ0⁴/3072 ≈ 6e-10, is below what the test resolves.
    period = 2 * math.pi / omega0 * (1 + theta0**2 / 16)

    h = 1e-3
    state = pendulum_state(theta0, pivot_body)
    mb.check_consistent(system, state)
    rattle = mb.Rattle(system, h)
    assert rattle.dt == h and rattle.uses_tree_solver

    n_steps = int(3.2 * period / h)
    angles = np.empty(n_steps + 1)
    angles[0] = swing_angle(state[0].R_space_body)
    worst_gap = worst_orth = worst_reported = 0.0
    for k in range(1, n_steps + 1):
        rattle.step(state)
        R = state[0].R_space_body
        angles[k] = swing_angle(R)
        # Independent check of the constraints in NumPy: the hinge point stays at the origin, R stays orthogonal.
        worst_gap = max(worst_gap, np.linalg.norm(state[0].x_space + R @ pivot_body))
        worst_orth = max(worst_orth, np.linalg.norm(R.T @ R - np.eye(3)))
        v = mb.constraint_violation(system, state)
        worst_reported = max(worst_reported, v.joint_gap, v.orthogonality, v.joint_angle)
    assert state.time == pytest.approx(n_steps * h, rel=1e-12)
    # RATTLE solves the constraints by Newton to 1e-13 of the length scale (0.5 m): round-off level.
    assert worst_gap < 1e-12
    assert worst_orth < 1e-12
    assert worst_reported < 1e-12

    # Downward zero crossings of θ(t), located by linear interpolation (θ is ≈ sinusoidal, so the
    # interpolation error at a crossing, where θ'' = 0, is O(h³) relative: negligible).
    idx = np.nonzero((angles[:-1] > 0) & (angles[1:] <= 0))[0]
    crossings = (idx + angles[idx] / (angles[idx] - angles[idx + 1])) * h
    assert len(crossings) >= 3
    measured = np.diff(crossings).mean()
    # RATTLE is second order: its phase error on a harmonic oscillator is (ω h)²/24 ≈ 6e-7 relative at
    # ω ≈ 3.8 rad/s, h = 1e-3. Tolerance 3e-6: five times that, and far below the θ0²/16 = 2.5e-5 correction
    # (so the test also sees whether the amplitude dependence is right).
    assert measured == pytest.approx(period, rel=3e-6)
    # Sharper: Störmer–Verlet/RATTLE on a harmonic oscillator has cos(ω̃h) = 1 − (ωh)²/2, i.e. a period
    # shorter by (ωh)²/24 + O(h⁴). With that leading term removed the residual is O(h⁴) and O(θ0²(ωh)²),
    # both ≈ 1e-10 here (measured 2e-10): an error of the wrong order or sign in the integrator fails this.
    assert measured == pytest.approx(period * (1 - (omega0 * h) ** 2 / 24), rel=1e-8)
    # Energy: RATTLE is symplectic, the energy error stays O(h²) bounded (relative to the releasable energy).
    e_release = m * G * d * (1 - math.cos(theta0))
    e_now = mb.total_energy(system, state)
    e_start = mb.total_energy(system, pendulum_state(theta0, pivot_body))
    assert abs(e_now - e_start) < 1e-5 * e_release


def test_rattle_steps_many_at_once_like_one_at_a_time():
    system, pivot_body = compound_pendulum()
    a, b = pendulum_state(0.3, pivot_body), pendulum_state(0.3, pivot_body)
    ra, rb = mb.Rattle(system, 2e-3), mb.Rattle(system, 2e-3)
    ra.step(a, steps=50)
    for _ in range(50):
        rb.step(b)
    np.testing.assert_array_equal(a.R_space_body, b.R_space_body)
    np.testing.assert_array_equal(a.x_space, b.x_space)
    assert a.time == b.time


def test_order_four_and_the_solver_in_use():
    system, pivot_body = compound_pendulum()  # a hinge: Baraff's tree solver
    r2, r4 = mb.Rattle(system, 1e-2), mb.Rattle(system, 1e-2, order=4)
    assert (r2.order, r4.order) == (2, 4) and r2.kkt_solver == "tree"
    errors = []
    for rattle in (r2, r4):
        state = pendulum_state(0.5, pivot_body)
        e0 = mb.total_energy(system, state)
        worst = 0.0
        for _ in range(100):
            rattle.step(state)
            worst = max(worst, abs(mb.total_energy(system, state) - e0))
        assert state.time == pytest.approx(1.0, abs=1e-12)
        errors.append(worst / (G * 0.5 * (1 - math.cos(0.5))))
    # O(h²) against O(h⁴) with ωh ≈ 0.05: measured 3.9e-4 and 3.2e-7 of the releasable energy.
    assert errors[1] < errors[0] / 100
    chain = mb.System()
    for i in range(3):
        chain.add_body(f"link{i}", 1.0, rod_poinsot(1.0, 1.0, 0.01))
    chain.add_ball("pivot", 0, [-0.5, 0, 0], mb.WORLD, [0, 0, 0])
    chain.add_ball("j1", 1, [-0.5, 0, 0], 0, [0.5, 0, 0])
    chain.add_ball("j2", 2, [-0.5, 0, 0], 1, [0.5, 0, 0])
    assert mb.Rattle(chain, 1e-3).kkt_solver == "ball_chain"
    with pytest.raises(ValueError, match="order 3"):
        mb.Rattle(chain, 1e-3, order=3)


def test_free_body_lambda_equals_single_body_formula():
    rng = np.random.default_rng(7)
    A = rng.normal(size=(3, 3))
    Q, _ = np.linalg.qr(A)
    Q *= np.sign(np.linalg.det(Q))
    K = Q @ np.diag([0.3, 0.7, 1.1]) @ Q.T  # a general (non-diagonal) Poinsot tensor, kg·m²
    K = (K + K.T) / 2
    system = mb.System()
    system.add_body("free", 2.0, K)
    R = rot_y(0.4) @ Q
    omega = np.array([1.3, -0.4, 2.1])
    state = mb.State(bodies=[mb.BodyState(x_space=[1, 2, 3], R_space_body=R, v_space=[0.1, 0, 0],
                                          omega_body=omega)])
    exact = mb.exact_multipliers(system, state)

    # Oracle in NumPy: Euler's equations J ω̇ = −ω × Jω (no torque), Λ = (j(ω)² + j(ω̇)) K (docs/conventions.md).
    J = inertia_from_poinsot(K)
    omega_dot = np.linalg.solve(J, -np.cross(omega, J @ omega))
    Lam = (hat(omega) @ hat(omega) + hat(omega_dot)) @ K
    scale = np.linalg.norm(omega) ** 2 * np.linalg.norm(K)
    # One dense solve in double precision: error a few ulps of the terms, 1e-13 relative leaves a margin.
    np.testing.assert_allclose(exact.omega_dot_body[0], omega_dot, rtol=0, atol=1e-13 * np.linalg.norm(omega) ** 2)
    np.testing.assert_allclose(exact.Lambda_body[0], Lam, rtol=0, atol=1e-13 * scale)
    # Λ is symmetric (it multiplies the symmetric constraint RᵀR = I), and a free body has no joints.
    np.testing.assert_allclose(Lam, Lam.T, atol=1e-13 * scale)
    assert exact.Lambda_body.shape == (1, 3, 3)
    assert exact.joint_force_space.shape == (0, 3)
    np.testing.assert_allclose(exact.acceleration_space, np.zeros((1, 3)), atol=1e-15)
    # Free motion conserves both momenta, here read from the bindings and compared with NumPy.
    np.testing.assert_allclose(mb.linear_momentum(system, state), 2.0 * np.array([0.1, 0, 0]), rtol=1e-15)
    L = np.cross([1, 2, 3], 2.0 * np.array([0.1, 0, 0])) + R @ J @ omega
    np.testing.assert_allclose(mb.angular_momentum(system, state), L, rtol=1e-14, atol=1e-14)


def test_hanging_pendulum_joint_reaction_is_the_weight():
    """At rest, hanging, the hinge carries the weight: force on the rod = +m g ẑ (Newton's first law)."""
    system, pivot_body = compound_pendulum(m=1.5)
    exact = mb.exact_multipliers(system, pendulum_state(0.0, pivot_body))
    np.testing.assert_allclose(exact.joint_force_space[0], [0, 0, 1.5 * G], atol=1e-12)
    np.testing.assert_allclose(exact.joint_torque_space[0], np.zeros(3), atol=1e-12)


def test_double_pendulum_scenario(tmp_path):
    path = SOURCE_DIR / "examples" / "multibody" / "double_pendulum.toml"
    assert mb.is_multibody_scenario(str(path))
    scenario = mb.load_scenario(str(path))
    assert scenario.system.body_names == ["upper", "lower"]
    assert scenario.system.joint_names == ["pivot", "elbow"]
    np.testing.assert_array_equal(scenario.system.gravity, [0, 0, -G])
    scenario.duration = 2.0  # a shorter run keeps the suite fast; the example runs 10 s
    csv = tmp_path / "trajectory.csv"
    report = io.StringIO()
    summary = mb.run_scenario(scenario, trajectory_csv=str(csv), report=report)
    assert summary.steps == round(scenario.duration / scenario.dt)
    # Joint gaps and orthogonality at round-off (Newton to 1e-13 of the 1 m length scale).
    assert summary.max_joint_gap < 1e-12
    assert summary.max_orthogonality < 1e-12
    # Energy error of a second-order symplectic method, O(h²), relative to the releasable energy m g l ≈ 30 J.
    assert summary.max_energy_error < 1e-4 * 3 * G
    assert summary.tree_solver
    assert report.getvalue().strip()
    rows = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    assert rows.shape[1] == 1 + 13 * 2
    # The initial state the file gives satisfies the joints (velocities projected by the loader).
    mb.check_consistent(scenario.system, scenario.initial)
    v = mb.constraint_violation(scenario.system, scenario.initial)
    assert v.joint_velocity < 1e-12


def test_diagnostics_csv_and_the_multibody_figures(tmp_path):
    """run_scenario(diagnostics_csv=...) writes E, T, V, momenta and constraint violation at the trajectory's rows;
    with a row every step its largest |E − E0| is the summary's max_energy_error and its first energy the
    initial state's total_energy. poinsot.plot draws the multibody figures from such a folder (with the
    summary.json fields `poinsot run` writes)."""
    import json

    pytest.importorskip("matplotlib")
    scenario = mb.load_scenario(str(SOURCE_DIR / "examples" / "multibody" / "double_pendulum.toml"))
    scenario.duration = 0.5
    scenario.output_every = 1
    folder = tmp_path / "run"
    folder.mkdir()
    summary = mb.run_scenario(scenario, trajectory_csv=str(folder / "trajectory.csv"),
                              diagnostics_csv=str(folder / "diagnostics.csv"))
    with open(folder / "diagnostics.csv", encoding="utf-8") as f:
        names = f.readline().strip().split(",")
    d = dict(zip(names, np.loadtxt(folder / "diagnostics.csv", delimiter=",", skiprows=1, ndmin=2).T))
    assert len(d["t"]) == summary.steps + 1
    assert d["energy"][0] == mb.total_energy(scenario.system, scenario.initial)
    assert np.abs(d["energy_error"]).max() == summary.max_energy_error > 0
    np.testing.assert_allclose(d["energy"], d["kinetic"] + d["potential"], rtol=1e-14, atol=1e-14)
    assert d["joint_gap"].max() < 1e-12 and d["orthogonality"].max() < 1e-12
    (folder / "summary.json").write_text(json.dumps(
        {"scenario": "double_pendulum.toml", "kind": "multibody", "dt": scenario.dt, "order": scenario.order}))
    figures = poinsot.plot.plot_run(folder)
    assert sorted(p.name for p in figures) == ["constraints.png", "energy.png", "paths.png"]
    for p in figures:
        assert p.stat().st_size > 1000 and p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_parse_scenario_from_text():
    text = (SOURCE_DIR / "examples" / "multibody" / "compound_pendulum.toml").read_text(encoding="utf-8")
    scenario = mb.parse_scenario(text, "compound_pendulum.toml")
    assert scenario.system.body_count == 1 and scenario.system.joint_count == 1
    assert len(scenario.initial) == 1


def test_mesh_body_from_a_scenario_and_from_mass_properties():
    """A body given by a mesh in a scenario file (relative to base_dir) is the inertia layer's mesh body; the same
    body added from the inertia layer's MassProperties has the same mass and J, and a joint point read off the
    mesh (its frame) is where the mesh says."""
    examples = SOURCE_DIR / "examples"
    text = """
[[bodies]]
name = "bracket"
mesh = { file = "meshes/l_bracket.obj", density = 2700.0 }
[[joints]]
type = "ball"
body_a = "bracket"
point_a = [0.015, 0.065, 0.01]
"""
    scenario = mb.parse_scenario(text, "s.toml", str(examples))
    props = poinsot.inertia.mesh(str(examples / "meshes" / "l_bracket.obj"), density=2700.0)
    system = mb.System()
    system.add_body_from_mass_properties("bracket", props)
    assert system.masses[0] == scenario.system.masses[0] == props.mass
    np.testing.assert_allclose(system.inertia_tensors[0], props.inertia_com, rtol=0, atol=1e-18)
    np.testing.assert_allclose(scenario.system.inertia_tensors[0], props.inertia_com, rtol=0, atol=1e-18)
    assert "l_bracket.obj" in scenario.body_descriptions[0]
    # position = 0 and R = I place the mesh frame on space: the centre of mass starts at c.
    np.testing.assert_allclose(scenario.initial.x_space[0], props.center_of_mass, atol=1e-15)


def test_bad_input_raises_value_error_with_the_library_message():
    system = mb.System()
    with pytest.raises(ValueError, match=r"^multibody body 'rod': mass: got -1 kg, expected a finite number > 0$"):
        system.add_body("rod", -1.0, np.eye(3))
    with pytest.raises(ValueError, match=r"multibody body 'plate'.*expected K positive semi-definite"):
        system.add_body("plate", 1.0, np.diag([1.0, 1.0, -0.5]))
    rod = system.add_body("rod", 1.0, rod_poinsot(1.0, 1.0, 0.01))
    with pytest.raises(ValueError, match=r"multibody joint 'j': body b: body index 3 out of range"):
        system.add_ball("j", rod, [0, 0, 0.5], 3, [0, 0, 0])
    with pytest.raises(ValueError, match=r"multibody joint 'h': axis a: axis .* is zero"):
        system.add_hinge("h", "rod", [0, 0, 0.5], [0, 0, 0], "world", [0, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match=r"^multibody: body 'stick' not found; expected 'world' or one of the 1 bodies$"):
        system.add_ball("k", "stick", [0, 0, 0.5])
    with pytest.raises(ValueError, match=r"point_a: expected an array of shape \(3,\), got shape \(2,\)"):
        system.add_ball("k", rod, [0, 0])
    with pytest.raises(TypeError, match=r"body_a: expected a body index \(int\) or a body name \(str\)"):
        system.add_ball("k", 1.5, [0, 0, 0])
    with pytest.raises(ValueError, match=r"^multibody: time step dt: got 0 s, expected a finite number > 0$"):
        mb.Rattle(system, 0.0)
    with pytest.raises(ValueError, match=r"^multibody: state has 0 bodies; expected 1$"):
        mb.Rattle(system, 1e-3).step(mb.State())
    with pytest.raises(ValueError, match=r"^steps: got 0, expected an integer >= 1$"):
        mb.Rattle(system, 1e-3).step(mb.State(bodies=[mb.BodyState()]), steps=0)
    with pytest.raises(ValueError, match=r"^bad\.toml:3:8: \[bodies\[0\]\] mass: got -1 kg, expected a number > 0$"):
        mb.parse_scenario("[[bodies]]\nname = 'a'\nmass = -1\ninertia = [1, 1, 1]\n", "bad.toml")


def test_state_views_and_copies():
    system, pivot_body = compound_pendulum()
    state = pendulum_state(0.1, pivot_body)
    state[0].omega_body = [0, 2.0, 0]  # edits the State through the view
    np.testing.assert_array_equal(state.omega_body, [[0, 2.0, 0]])
    copy = state.bodies
    copy[0].omega_body = [0, 0, 0]  # a copy: the State is unchanged
    np.testing.assert_array_equal(state.omega_body, [[0, 2.0, 0]])
    assert len(state) == 1 and state.x_space.shape == (1, 3) and state.R_space_body.shape == (1, 3, 3)
    assert "multibody" in poinsot.__all__


# ---- ProjectedRk4: the classical RK4 projected onto the joints ---------------------------------------------------


def falling_chain(links=3, length=1.0):
    """Rods (1 kg, 1 m, along body x) joined end to end by ball joints, the first hung from the origin; released
    horizontal along +x with a sideways spin on the last link (velocities projected onto the joints), so the fall
    is three-dimensional. Returns the system and a consistent state."""
    system = mb.System()
    for i in range(links):
        system.add_body(f"link{i}", 1.0, np.diag([length**2 / 12, 1e-4 / 4, 1e-4 / 4]))
    system.add_ball("pivot", 0, [-length / 2, 0, 0], mb.WORLD, [0, 0, 0])
    for i in range(1, links):
        system.add_ball(f"j{i}", i, [-length / 2, 0, 0], i - 1, [length / 2, 0, 0])
    system.gravity = [0, 0, -G]
    bodies = [mb.BodyState(x_space=[(i + 0.5) * length, 0, 0]) for i in range(links)]
    bodies[-1].omega_body = [0.0, 0.5, 2.0]
    bodies[-1].v_space = [0.0, 1.0, 0.0]
    state = mb.State(bodies=bodies)
    mb.project_velocities(system, state)
    mb.check_consistent(system, state)
    return system, state


def joint_gaps(system, state, links):
    """Independent NumPy check of the ball joints: |x_a + R_a p_a − x_b − R_b p_b| per joint (m)."""
    x, R = state.x_space, state.R_space_body
    half = np.array([0.5, 0, 0])
    gaps = [np.linalg.norm(x[0] - R[0] @ half)]
    gaps += [np.linalg.norm(x[i] - R[i] @ half - x[i - 1] - R[i - 1] @ half) for i in range(1, links)]
    return np.array(gaps)


def test_projected_rk4_properties_and_many_steps_at_once():
    system, pivot_body = compound_pendulum()
    rk4 = mb.ProjectedRk4(system, 2e-3)
    assert (rk4.dt, rk4.order, rk4.kkt_solver) == (2e-3, 4, "tree")  # a hinge: Baraff's tree solver
    assert mb.ProjectedRk4(falling_chain()[0], 1e-3).kkt_solver == "ball_chain"
    # No step yet: no multipliers (empty arrays, one row per body / joint once a step is taken).
    assert rk4.multipliers.Lambda_body.shape == (0, 3, 3) and rk4.multipliers.joint_force_space.shape == (0, 3)
    a, b = pendulum_state(0.3, pivot_body), pendulum_state(0.3, pivot_body)
    rk4.step(a, steps=50)
    other = mb.ProjectedRk4(system, 2e-3)
    for _ in range(50):
        other.step(b)
    np.testing.assert_array_equal(a.R_space_body, b.R_space_body)
    np.testing.assert_array_equal(a.x_space, b.x_space)
    assert a.time == b.time == pytest.approx(0.1, abs=1e-15)
    assert rk4.multipliers.Lambda_body.shape == (1, 3, 3)
    # At h = 10 ms the RK4 step leaves an O(h⁵) gap (~1e-10 m) above the 1e-13 tolerance, and each projection
    # iteration gains about (hω)² ≈ 2e-3: one or two iterations a step (measured: always 1). At h = 2 ms the gap
    # is often already below the tolerance (0 or 1 measured), so the count is checked at 10 ms.
    coarse = mb.ProjectedRk4(system, 1e-2)
    c = pendulum_state(0.3, pivot_body)
    for _ in range(50):
        coarse.step(c)
        assert 1 <= coarse.last_iterations <= 2


def test_projected_rk4_multipliers_are_the_exact_multipliers_of_the_state_it_reached():
    system, state = falling_chain()
    h = 1e-3
    rk4 = mb.ProjectedRk4(system, h)
    for _ in range(3):
        rk4.step(state, steps=99)  # 0.1 s of fall per round: the chain swings down and bends
        v_before, w_before = state.v_space, state.omega_body
        rk4.step(state)
        got = rk4.multipliers
        want = mb.exact_multipliers(system, state)  # a fresh KKT factorisation at the same state
        # Both solve the same KKT system at the same state (the integrator from its last factorisation,
        # exact_multipliers from its own): equal to round-off, a few ulps of the largest entry times the chain's
        # condition; 1e-12 of each array's largest entry leaves a margin (measured: bitwise equal).
        for name in ("Lambda_body", "joint_force_space", "joint_torque_space", "acceleration_space",
                     "omega_dot_body"):
            g, w = getattr(got, name), getattr(want, name)
            assert g.shape == w.shape, name
            np.testing.assert_allclose(g, w, rtol=0, atol=1e-12 * max(np.abs(w).max(), 1.0), err_msg=name)
        # Newton on the whole chain (three 1 kg links): the pivot's reaction plus the weight is Σ m a
        # (round-off of the 3 g ≈ 29 N terms, measured 1.2e-16 relative).
        np.testing.assert_allclose(got.joint_force_space[0] + 3.0 * np.array([0, 0, -G]),
                                   got.acceleration_space.sum(axis=0), rtol=0, atol=1e-13 * 3 * G)
        # The accelerations are the trajectory's: central differences of v and ω (body frame) over the steps
        # before and after, exact to O(h²) (h²/6 |d³v/dt³| with ω ≈ 5 rad/s: ~1e-5 relative) plus RK4's O(h⁴)
        # error over two steps; measured ≤ 6e-6 (a) and 1.3e-5 (ω̇) of the largest entry, bound 1e-4.
        state_after = mb.State(time=state.time, bodies=state.bodies)
        mb.ProjectedRk4(system, h).step(state_after)
        a_fd = (state_after.v_space - v_before) / (2 * h)
        w_fd = (state_after.omega_body - w_before) / (2 * h)
        np.testing.assert_allclose(got.acceleration_space, a_fd, rtol=0,
                                   atol=1e-4 * np.abs(a_fd).max())
        np.testing.assert_allclose(got.omega_dot_body, w_fd, rtol=0, atol=1e-4 * np.abs(w_fd).max())


def test_projected_rk4_is_fourth_order():
    """Halving h divides the error at t = 0.5 s by 2⁴ = 16. Reference: RATTLE order 4 at h = 1.25e-4 s (it
    differs from the same at 2.5e-4 s by 1.4e-12, measured), far below RK4's errors at h = 1e-2 and 5e-3."""
    system, state0 = falling_chain()
    t_end = 0.5

    def positions(integrator, h):
        s = mb.State(time=state0.time, bodies=state0.bodies)
        integrator.step(s, steps=round(t_end / h))
        return np.concatenate([s.x_space.ravel(), s.R_space_body.ravel()])

    ref = positions(mb.Rattle(system, 1.25e-4, order=4), 1.25e-4)
    errors = [np.abs(positions(mb.ProjectedRk4(system, h), h) - ref).max() for h in (1e-2, 5e-3)]
    ratio = errors[0] / errors[1]
    # Measured errors 2.7e-7 and 1.7e-8 (m, and entries of R; ratio 15.9; 15.6 from 2e-2 to 1e-2); 16 ± 4 allows
    # the O(h⁵) term at hω ≤ 0.05 (ω ≤ 4.6 rad/s during the fall).
    assert 12 < ratio < 20, (errors, ratio)


def test_projected_rk4_keeps_the_joints_closed_to_round_off():
    system, state = falling_chain()
    rk4 = mb.ProjectedRk4(system, 2e-3)
    scale = system.length_scale()
    for _ in range(5):
        rk4.step(state, steps=40)
        v = mb.constraint_violation(system, state)
        # The projection iterates until every gap is below 1e-13 × the length scale (0.5 m here); the
        # library's measure and the NumPy one (another evaluation order) may differ by a few ulps of the 1.5 m
        # chain, hence 2e-13 (measured 5.6e-16 × scale for both).
        assert v.joint_gap < 2e-13 * scale
        assert joint_gaps(system, state, 3).max() < 2e-13 * scale
        # Newton–Schulz stops at |RᵀR − I| ≤ 1e-15; the joint projection's exact rotations add a few ulps
        # (measured 2.2e-16).
        assert v.orthogonality < 1e-14
        # The velocities are projected exactly onto the joints (one linear solve): round-off of |v| ≤ 5 m/s
        # (measured 5e-16 m/s).
        assert v.joint_velocity < 1e-13 * 5


COMPOUND_PENDULUM_WITH_METHOD = "[simulation]\nmethod = \"{}\"\n"


def test_run_scenario_with_method_rk4():
    text = (SOURCE_DIR / "examples" / "multibody" / "compound_pendulum.toml").read_text(encoding="utf-8")
    rk4 = mb.parse_scenario(text.replace("[simulation]\n", COMPOUND_PENDULUM_WITH_METHOD.format("rk4"), 1), "p.toml")
    rattle = mb.parse_scenario(text, "p.toml")
    assert (rk4.method, rk4.order) == ("rk4", 4) and (rattle.method, rattle.order) == ("rattle", 2)
    summaries = {}
    for name, scenario in (("rk4", rk4), ("rattle", rattle)):
        scenario.duration = 1.0
        summaries[name] = mb.run_scenario(scenario)
    s4, s2 = summaries["rk4"], summaries["rattle"]
    assert s4.steps == s2.steps == 1000
    # RATTLE's O(h²) energy error at ωh ≈ 4e-3 against RK4's O(h⁴) (plus the projections, which never add
    # kinetic energy): measured 8.2e-7 J against 5.8e-13 J (|E| ≈ 4.7 J); 1e4 leaves a margin of 100.
    assert s4.max_energy_error < s2.max_energy_error / 1e4
    # Gaps at the projection tolerance 1e-13 × 0.5 m, as the library measures them (measured 6.1e-14 m; RATTLE's
    # 6.7e-14 m); 2e-13 m allows a few ulps of the 1 m rod more. Orthogonality measured 1e-15.
    assert s4.max_joint_gap < 2e-13 and s4.max_orthogonality < 1e-14
    # The property sets the method as the file does: the same run, bit for bit.
    rattle.method = "rk4"
    assert rattle.order == 4
    again = mb.run_scenario(rattle)
    assert (again.max_energy_error, again.energy_final) == (s4.max_energy_error, s4.energy_final)
    rattle.method = "rattle"
    assert (rattle.method, rattle.order) == ("rattle", 4)  # order is kept: RATTLE's composition from here


def test_projected_rk4_bad_arguments_name_the_field():
    system, pivot_body = compound_pendulum()
    with pytest.raises(ValueError, match=r"^multibody: time step dt: got 0 s, expected a finite number > 0$"):
        mb.ProjectedRk4(system, 0.0)
    with pytest.raises(ValueError, match=r"^multibody: time step dt: got -0\.001 s"):
        mb.ProjectedRk4(system, -1e-3)
    with pytest.raises(ValueError, match=r"^multibody: projection tolerance: got 0"):
        mb.ProjectedRk4(system, 1e-3, tolerance=0.0)
    with pytest.raises(ValueError, match=r"^multibody: max_iterations 0 must be >= 1$"):
        mb.ProjectedRk4(system, 1e-3, max_iterations=0)
    rk4 = mb.ProjectedRk4(system, 1e-3)
    with pytest.raises(ValueError, match=r"^steps: got 0, expected an integer >= 1$"):
        rk4.step(pendulum_state(0.1, pivot_body), steps=0)
    with pytest.raises(ValueError, match=r"^multibody: state has 0 bodies; expected 1$"):
        rk4.step(mb.State())
    scenario = mb.parse_scenario("[[bodies]]\nname = 'a'\nmass = 1\ninertia = [1, 1, 1]\n", "ok.toml")
    with pytest.raises(ValueError, match=r'^Scenario\.method: got "euler", expected "rattle" .* or "rk4" '):
        scenario.method = "euler"
    assert scenario.method == "rattle"  # unchanged by the refused value
    base = "[simulation]\n{}\n[[bodies]]\nname = 'a'\nmass = 1\ninertia = [1, 1, 1]\n"
    with pytest.raises(ValueError, match=r'^bad\.toml:2:10: \[simulation\] method: got "euler", expected "rattle"'):
        mb.parse_scenario(base.format('method = "euler"'), "bad.toml")
    with pytest.raises(ValueError, match=r"^bad\.toml:.*\[simulation\] order: applies to method = \"rattle\" only"):
        mb.parse_scenario(base.format('method = "rk4"\norder = 2'), "bad.toml")
