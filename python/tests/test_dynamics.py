"""poinsot's model and state from Python: RigidBody, State, invariants and torques, against NumPy formulas;
array shapes and dtypes; error translation."""
import numpy as np
import pytest

import poinsot
from poinsot import RigidBody, State, TorqueModel, so3

EPS = np.finfo(float).eps


def random_rotation(rng):
    return so3.exp(rng.normal(size=3))


def test_rigid_body_tensors_match_their_definitions():
    rng = np.random.default_rng(3)
    for _ in range(20):
        m = np.sort(rng.uniform(1, 2, size=3))
        Q = random_rotation(rng)
        J = Q @ np.diag(m) @ Q.T
        J = (J + J.T) / 2
        body = RigidBody.from_inertia(J)
        assert np.allclose(body.inertia_com, J, rtol=0, atol=4 * EPS * m.max())
        # K = tr(J)/2 I - J (docs/conventions.md conventions), computed here independently.
        assert np.allclose(body.poinsot, np.trace(J) / 2 * np.eye(3) - J, rtol=0, atol=8 * EPS * m.max())
        assert np.allclose(body.inertia_inverse @ J, np.eye(3), rtol=0, atol=64 * EPS)
        # principal moments ascending, axes a proper rotation diagonalising J
        assert np.allclose(body.principal_moments, m, rtol=1e-13)
        P = body.principal_axes
        assert abs(np.linalg.det(P) - 1) < 16 * EPS
        assert np.allclose(P.T @ J @ P, np.diag(m), rtol=0, atol=1e-13 * m.max())


def test_properties_are_float64_arrays_of_the_right_shape():
    body = RigidBody.from_principal_moments([1, 2, 3])
    for name, shape in [("inertia", (3, 3)), ("inertia_com", (3, 3)), ("poinsot", (3, 3)),
                        ("principal_moments", (3,)), ("principal_axes", (3, 3)), ("pivot_to_com", (3,))]:
        a = getattr(body, name)
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == shape, name
    assert body.is_diagonal and not body.has_pivot and body.mass == 0.0


def test_pivot_uses_the_parallel_axis_theorem():
    body = RigidBody.from_principal_moments([1, 2, 3]).with_pivot(2.0, [0, 0, 0.5])
    d = np.array([0, 0, 0.5])
    expected = np.diag([1.0, 2, 3]) + 2.0 * (d @ d * np.eye(3) - np.outer(d, d))
    assert np.allclose(body.inertia, expected, rtol=1e-15)
    assert body.has_pivot and body.mass == 2.0


def test_state_and_invariants_against_numpy():
    rng = np.random.default_rng(4)
    body = RigidBody.from_principal_moments([0.5, 1.5, 1.8])
    J = body.inertia
    for _ in range(20):
        R, w = random_rotation(rng), rng.normal(size=3)
        s = State(time=1.5, R_space_body=R, omega_body=w)
        assert s.time == 1.5 and np.array_equal(s.R_space_body, R) and np.array_equal(s.omega_body, w)
        assert np.isclose(poinsot.kinetic_energy(body, s), 0.5 * w @ J @ w, rtol=1e-14)
        assert np.allclose(poinsot.angular_momentum_body(body, s), J @ w, rtol=1e-14)
        assert np.allclose(poinsot.angular_momentum_space(body, s), R @ J @ w, rtol=1e-13, atol=1e-15)
        assert np.allclose(s.omega_space(), R @ w, rtol=1e-13, atol=1e-15)
        q = s.quaternion()
        assert q.shape == (4,) and q[0] >= 0 and np.allclose(so3.rotation_from_quaternion(q), R, atol=8 * EPS)
    # a state from a quaternion
    q = np.array([np.cos(0.3), 0, 0, np.sin(0.3)])
    assert np.allclose(State(quaternion=q).R_space_body, so3.exp([0, 0, 0.6]), atol=4 * EPS)


def test_potential_energy_of_a_pivoted_body():
    body = RigidBody.from_principal_moments([1, 1, 0.5]).with_pivot(3.0, [0, 0, 0.2])
    g = np.array([0, 0, -9.81])
    R = so3.exp([0.4, 0, 0])
    s = State(R_space_body=R, omega_body=[0, 0, 10])
    assert np.isclose(poinsot.potential_energy(body, s, g), -3.0 * g @ R @ [0, 0, 0.2], rtol=1e-14)
    assert np.isclose(poinsot.total_energy(body, s, g),
                      poinsot.kinetic_energy(body, s) + poinsot.potential_energy(body, s, g), rtol=1e-15)


def test_builtin_torques():
    R = so3.exp([0.1, -0.4, 0.7])
    w = np.array([1.0, 2.0, 3.0])
    tau = np.array([0.1, 0.2, -0.3])
    assert np.array_equal(TorqueModel.constant_body(tau).torque_body(0.0, R, w), tau)
    assert np.allclose(TorqueModel.constant_space(tau).torque_body(0.0, R, w), R.T @ tau, atol=4 * EPS)
    none = TorqueModel.none()
    assert none.is_zero and np.array_equal(none.torque_body(0.0, R, w), np.zeros(3))
    body = RigidBody.from_principal_moments([1, 1, 0.5]).with_pivot(3.0, [0, 0, 0.2])
    g = np.array([0, 0, -9.81])
    grav = TorqueModel.gravity(body, g)
    assert grav.is_gravity and np.array_equal(grav.gravity_space, g)
    assert np.allclose(grav.torque_body(0.0, R, w), 3.0 * np.cross([0, 0, 0.2], R.T @ g), rtol=1e-14)


def test_python_callable_torque_model():
    seen = []

    def tau(t, R, omega):
        seen.append((t, R.shape, omega.shape, R.dtype))
        return -0.5 * omega

    tm = TorqueModel.callback(tau, depends_on_omega=True, description="damping")
    assert tm.describe() == "damping" and tm.depends_on_omega
    assert np.array_equal(tm.torque_body(2.0, np.eye(3), [2, 4, 6]), [-1, -2, -3])
    assert seen == [(2.0, (3, 3), (3,), np.float64)]


def test_errors_become_value_error_with_the_message():
    with pytest.raises(ValueError, match=r"violate the triangle inequality I1 \+ I2 >= I3 \(short by 3\)"):
        RigidBody.from_principal_moments([1, 1, 5])
    with pytest.raises(ValueError, match="pivot"):
        TorqueModel.gravity(RigidBody.from_principal_moments([1, 2, 3]), [0, 0, -9.81])


def test_wrong_shapes_and_dtypes_say_what_was_expected():
    with pytest.raises(ValueError, match=r"moments: expected an array of shape \(3,\), got shape \(2,\)"):
        RigidBody.from_principal_moments([1, 2])
    with pytest.raises(ValueError, match=r"inertia_com_body: expected an array of shape \(3, 3\), got shape \(3,\)"):
        RigidBody.from_inertia([1, 2, 3])
    with pytest.raises(TypeError, match=r"moments: expected real numbers \(float64\), got dtype complex128"):
        RigidBody.from_principal_moments(np.array([1, 2, 3], dtype=complex))
    with pytest.raises(TypeError, match="expected real numbers"):
        RigidBody.from_principal_moments(["a", "b", "c"])
    with pytest.raises(ValueError, match=r"omega_body: expected an array of shape \(3,\), got shape \(3, 1\)"):
        State(omega_body=np.zeros((3, 1)))
    with pytest.raises(ValueError, match="R_space_body or as quaternion, not both"):
        State(R_space_body=np.eye(3), quaternion=[1, 0, 0, 0])
    # integers, float32 and non-contiguous views are accepted and converted
    assert np.array_equal(RigidBody.from_principal_moments(np.array([1, 2, 3], dtype=np.int32)).principal_moments,
                          [1, 2, 3])
    J = np.diag([1.0, 2, 3]).astype(np.float32)
    assert np.array_equal(RigidBody.from_inertia(J.T).inertia_com, np.diag([1.0, 2, 3]))
    v = (np.arange(6.0) + 2.0)[::2]  # strided view (2, 4, 6)
    assert not v.flags.c_contiguous
    assert np.array_equal(RigidBody.from_principal_moments(v).principal_moments, [2, 4, 6])


def test_so3_errors_name_the_argument():
    with pytest.raises(ValueError, match=r"R: expected an array of shape \(3, 3\), got shape \(2, 2\)"):
        so3.log(np.eye(2))
    with pytest.raises(ValueError, match=r"q: expected an array of shape \(4,\)"):
        so3.rotation_from_quaternion([1, 0, 0])
