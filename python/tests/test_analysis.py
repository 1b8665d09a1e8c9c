"""poinsot.analysis from Python: Λ against the formula of the paper computed in NumPy, its properties along a
simulated trajectory, the axisymmetric closed form, and the constraint stress."""
import numpy as np
import pytest

import poinsot
from poinsot import RigidBody, State, analysis, so3

EPS = np.finfo(float).eps


def lambda_numpy(J, w, tau=np.zeros(3)):
    """Λ = (j(ω)² + j(ω̇)) K with ω̇ = J⁻¹(τ − ω × Jω) and K = tr(J)/2·I − J (docs/conventions.md conventions)."""
    wdot = np.linalg.solve(J, tau - np.cross(w, J @ w))
    K = np.trace(J) / 2 * np.eye(3) - J
    W = so3.hat(w)
    return W @ W @ K + so3.hat(wdot) @ K


def test_lambda_from_state_equals_the_formula():
    rng = np.random.default_rng(5)
    body = RigidBody.from_principal_moments([1.0, 2.0, 2.5])
    for _ in range(10):
        s = State(R_space_body=so3.exp(rng.normal(size=3)), omega_body=rng.normal(size=3))
        L = analysis.lambda_from_state(body, s)
        ref = lambda_numpy(body.inertia, s.omega_body)
        assert np.allclose(L, ref, rtol=0, atol=1e-13 * np.abs(ref).max())
        T = poinsot.kinetic_energy(body, s)
        assert np.trace(L) == pytest.approx(-2 * T, rel=1e-13)  # tr Λ = −2T
        assert analysis.symmetry_error(L) < 1e-13 * np.abs(L).max()
        assert analysis.sorted_eigenvalues(L)[-1] <= 1e-13 * np.abs(L).max()  # −Λ positive semi-definite
    tau = np.array([0.1, -0.2, 0.3])
    s = State(omega_body=[0.3, 1.0, -0.4])
    L = analysis.lambda_from_state(body, s, poinsot.TorqueModel.constant_body(tau))
    assert np.allclose(L, lambda_numpy(body.inertia, s.omega_body, tau), atol=1e-14)
    # a Python callable is accepted as the torque too, with the same result
    L2 = analysis.lambda_from_state(body, s, lambda t, R, w: tau)
    assert np.array_equal(L, L2)


def test_axisymmetric_eigenvalues_are_constant_along_a_run():
    body = RigidBody.from_principal_moments([1.0, 1.0, 1.6])  # oblate: A = 1, C = 1.6
    w0 = [0.4, -0.3, 2.0]
    r = poinsot.simulate(body=body, omega_body=w0, method="dop853", rtol=1e-12, atol=1e-14, t_end=10, sample_dt=0.1)
    lam = analysis.lambda_trajectory(body, r.t, r.R, r.omega_body)
    assert lam.shape == (len(r), 3, 3) and lam.dtype == np.float64
    eig = np.linalg.eigvalsh((lam + lam.transpose(0, 2, 1)) / 2)
    closed = analysis.AxisymmetricLambda(analysis.detect_axisymmetry(body), w0)
    assert np.abs(eig - closed.eigenvalues()).max() < 1e-10
    props = analysis.lambda_properties(body, r.t, r.R, r.omega_body)
    cf = props["closed_form"]
    assert cf is not None and cf["max_deviation"] < 1e-10
    assert np.allclose(cf["eigenvalues"], closed.eigenvalues(), rtol=1e-14)
    assert props["max_eigenvalue_max"] <= 1e-12 and props["samples"] == len(r)
    # λ3 = −C⟨Ω0, Ω0⟩/2 (docs/conventions.md: not η0²)
    assert closed.lambda3 == pytest.approx(-1.6 * np.dot(w0, w0) / 2, rel=1e-15)


def test_lambda_trajectory_checks_its_arrays():
    body = RigidBody.from_principal_moments([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"R: expected an array of shape \(2, 3, 3\), got shape \(3, 3, 3\)"):
        analysis.lambda_trajectory(body, np.zeros(2), np.zeros((3, 3, 3)), np.zeros((2, 3)))


def test_stress_integral_of_a_steady_spin():
    # A box spinning about z: ∫σ dv = ω² diag(m a²/12, m b²/12, 0) (stress.hpp, steady-spin closed form).
    m, (a, b, c), rate = 2.0, (0.3, 0.2, 0.1), 5.0
    box = poinsot.inertia.box(m, [a, b, c])
    body = box.to_rigid_body()
    s = State(omega_body=[0, 0, rate])
    S = analysis.stress_integral_space(body, s)
    assert np.allclose(S, rate**2 * np.diag([m * a * a / 12, m * b * b / 12, 0]), rtol=1e-13, atol=1e-15)
    K = body.poinsot
    assert np.allclose(analysis.steady_spin_stress_integral_body(K, [0, 0, 1], rate), S, rtol=1e-13, atol=1e-15)
    cs = analysis.constraint_stress(analysis.lambda_from_state(body, s), s.R_space_body, volume_m3=a * b * c)
    assert cs["mean"] is not None
    assert cs["integral"]["trace"] == pytest.approx(2 * poinsot.kinetic_energy(body, s), rel=1e-13)


def test_lambda_report_is_the_engine_of_poinsot_lambda():
    body = RigidBody.from_principal_moments([1.0, 1.0, 1.6])
    rep = analysis.lambda_report(body, State(omega_body=[0.4, -0.3, 2.0]), method="dop853", t_end=5.0,
                                 sample_dt=0.1)
    assert rep["method"] == "dop853" and rep["samples"] == 51
    assert rep["closed_form"]["max_deviation"] < 1e-9 and "Λ" in rep["text"]
    # with a Python torque (the GIL is held during the run)
    rep = analysis.lambda_report(body, State(omega_body=[0.4, -0.3, 2.0]), method="rk4", dt=1e-3, t_end=0.5,
                                 torque=lambda t, R, w: np.array([0.0, 0.0, 0.01]))
    assert rep["closed_form"] is None and not rep["torque_free"]


@pytest.mark.parametrize("moments, method", [([1.0, 1.0, 1.6], "rattle"), ([2.0, 3.0, 4.0], "rk4")])
def test_lambda_report_has_the_keys_and_values_of_the_command_line(cli_exe, moments, method):
    """`poinsot lambda --json` and analysis.lambda_report are one serialiser (io/run/lambda_json.hpp): the same
    keys and the same values, bit for bit (the run is deterministic, and JSON round-trips doubles); the
    Python dict adds only `text`, the report the command prints without --json."""
    import json
    import subprocess

    w0 = [0.4, -0.3, 2.0]
    r = subprocess.run([cli_exe, "lambda", "--moments", *map(str, moments), "--omega0", *map(str, w0), "--method",
                        method, "--dt", "1e-3", "--t-end", "0.5", "--sample-dt", "0.05", "--json"],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)
    rep = analysis.lambda_report(RigidBody.from_principal_moments(moments), State(omega_body=w0), method=method,
                                 dt=1e-3, t_end=0.5, sample_dt=0.05)
    text = rep.pop("text")
    assert rep == cli
    assert (cli["closed_form"] is not None) == (moments[0] == moments[1])
    assert (cli["integrator_multiplier"] is not None) == (method == "rattle")
    assert "Λ" in text
    # lambda_properties gives the same keys for the properties of a trajectory.
    props = analysis.lambda_properties(RigidBody.from_principal_moments(moments), [0.0], [np.eye(3)], [w0])
    assert set(props) <= set(cli) and {"samples", "eigenvalues_initial", "closed_form"} <= set(props)


def test_result_lambda_uses_the_runs_torque():
    body = RigidBody.from_principal_moments([1.0, 2.0, 2.5])
    tau = np.array([0.0, 0.1, 0.0])
    r = poinsot.simulate(body=body, omega_body=[0.3, 1.0, 0.2], torque=lambda t, R, w: tau, method="rk4",
                         dt=1e-3, t_end=0.5, sample_dt=0.25)
    lam = r.lambda_body()
    for i in range(len(r)):
        assert np.allclose(lam[i], lambda_numpy(body.inertia, r.omega_body[i], tau), atol=1e-13)
