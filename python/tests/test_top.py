"""The heavy symmetric top from Python: a simulated gravity run against the closed-form theory (Goldstein
§5.7, dynamics/top_theory.hpp), and the fast-top formula of the notes."""
import numpy as np
import pytest

import poinsot
from poinsot import so3


def test_simulated_top_matches_the_exact_nutation_and_precession():
    g = np.array([0.0, 0.0, -9.81])
    body = poinsot.RigidBody.from_principal_moments([0.6, 0.6, 1.0]).with_pivot(1.0, [0, 0, 0.2])
    top = poinsot.heavy_top_from(body, g)
    assert top.I1 == pytest.approx(0.6 + 1.0 * 0.2**2, rel=1e-15) and top.I3 == 1.0 and top.length == 0.2
    s = poinsot.State(R_space_body=so3.exp([0.5, 0, 0]), omega_body=[0, 0, 30.0])  # tilted 0.5 rad, released without precession
    ic = poinsot.top_initial_conditions(body, s, g)
    assert ic["theta"] == pytest.approx(0.5, rel=1e-15) and ic["omega3"] == 30.0 and ic["phi_dot"] == 0.0
    tm = poinsot.top_motion(top, ic["theta"], ic["theta_dot"], ic["phi_dot"], ic["omega3"])
    T, n, per = tm["nutation_period"], 5, 40
    r = poinsot.simulate(body=body, initial=s, torque=poinsot.TorqueModel.gravity(body, g), method="dop853",
                         rtol=1e-12, atol=1e-14, t_end=n * T, sample_dt=T / per)
    axis = r.R[:, :, 2]  # the symmetry axis in space
    phi = np.unwrap(np.arctan2(axis[:, 1], axis[:, 0]))
    theta = np.arccos(axis[:, 2])
    # After n nutation periods the axis is back at its turning point, having precessed n Δφ.
    assert phi[n * per] - phi[0] == pytest.approx(n * tm["precession_per_nutation"], rel=1e-9)
    assert theta.max() == pytest.approx(tm["theta_max"], abs=1e-9)
    assert theta.min() == pytest.approx(tm["theta_min"], abs=1e-9)
    # a fast top: the notes' M g l/(I3 ω3) within its O(I1 M g l/(I3 ω3)²) error
    fast = poinsot.fast_top_precession_rate(top, 30.0)
    assert fast == pytest.approx(top.mgl / 30.0, rel=1e-15)
    assert abs(tm["mean_precession_rate"] / fast - 1) < 2 * top.I1 * top.mgl / (top.I3 * 30.0) ** 2
    assert poinsot.is_sleeping_top_stable(top, 30.0)
    assert poinsot.sleeping_top_threshold(top) == pytest.approx(np.sqrt(4 * top.I1 * top.mgl) / top.I3, rel=1e-15)


def test_top_errors():
    with pytest.raises(ValueError):
        poinsot.HeavyTop(I1=-1.0, I3=1.0, mass=1.0, length=0.1)
    with pytest.raises(ValueError, match="pivot"):
        poinsot.heavy_top_from(poinsot.RigidBody.from_principal_moments([1, 1, 1.5]), [0, 0, -9.81])
