"""poinsot.so3 from Python: round trips against NumPy and error translation."""
import numpy as np
import pytest

import poinsot
from poinsot import so3

EPS = np.finfo(float).eps


def test_version_is_a_string():
    assert isinstance(poinsot.__version__, str) and poinsot.__version__.count(".") == 2


def test_hat_is_cross_product():
    rng = np.random.default_rng(1)
    for _ in range(100):
        u, v = rng.normal(size=3), rng.normal(size=3)
        assert np.allclose(so3.hat(u) @ v, np.cross(u, v), atol=16 * EPS * 10)


def test_exp_log_round_trip():
    rng = np.random.default_rng(2)
    for _ in range(200):
        v = rng.normal(size=3)
        v *= rng.uniform(0, np.pi * 0.999) / np.linalg.norm(v)
        R = so3.exp(v)
        assert np.abs(R.T @ R - np.eye(3)).max() < 8 * EPS
        assert np.abs(so3.log(R) - v).max() < 32 * EPS


def test_quaternion_matches_half_angle_formula():
    angle, axis = 0.7, np.array([1.0, 2.0, 2.0]) / 3.0
    q = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * axis])
    assert np.abs(so3.rotation_from_quaternion(q) - so3.exp(angle * axis)).max() < 8 * EPS
    assert np.abs(so3.quaternion_from_rotation(so3.exp(angle * axis)) - q).max() < 8 * EPS


def test_euler_zxz_round_trip():
    a = np.array([0.3, 1.2, -2.0])
    assert np.abs(so3.euler_from_rotation("ZXZ", so3.rotation_from_euler("ZXZ", a)) - a).max() < 64 * EPS


def test_errors_become_value_error_with_the_message():
    with pytest.raises(ValueError, match=r"quaternion: got \(0, 0, 0, 0\), expected a non-zero quaternion"):
        so3.rotation_from_quaternion(np.zeros(4))
    with pytest.raises(ValueError, match="sequence"):
        so3.rotation_from_euler("ZZX", np.zeros(3))
