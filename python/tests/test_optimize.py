"""poinsot.optimize: optimal reorientation from Python (scenario files, dicts, problem objects), checked against
closed forms and published optima, and its handling of bad input and non-converged solutions."""
import json
import math

import numpy as np
import pytest

import poinsot

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "optimal"
BETTS_PUBLISHED = 28.6304077  # s (Betts, Practical Methods for Optimal Control, ex. 6.12; PSOPT)


def axis_angle_dict(axis, angle):
    return {"axis_angle": {"axis": list(axis), "angle": angle}}


@pytest.fixture(scope="module")
def betts():
    return poinsot.optimize(EXAMPLES / "betts.toml")


def test_betts_reaches_the_published_optimum(betts):
    assert betts.optimal and betts.status == "optimal (verified)"
    assert betts.method == "indirect" and betts.objective == "minimum_time"
    # The published value has 9 significant digits; the target is 5e-8 relative.
    assert abs(betts.final_time - BETTS_PUBLISHED) / BETTS_PUBLISHED < 5e-8
    assert betts.cost == pytest.approx(betts.final_time, rel=1e-14)  # T, summed over the arcs
    assert len(betts.switch_times) == 5 and np.all(np.diff(betts.switch_times) > 0)
    assert set(betts.switch_axes) <= {0, 1, 2}
    assert betts.checks["passed"] and betts.checks["failures"] == []
    # DOP853 replay of the bang-bang control with its exact switch times (rtol = atol = 1e-13).
    assert betts.checks["resimulated_attitude_error"] < 1e-9
    # One segment: the open-loop replay is checked; a stable slew amplifies its errors little (measured 3.0).
    assert betts.checks["replay_segments"] == 1 and betts.checks["open_loop_replay_checked"] is True
    assert 1.0 <= betts.checks["replay_amplification"] < 10.0
    assert betts.summary["optimal"] is True
    assert "optimal (verified)" in betts.report


def test_betts_arrays_are_consistent(betts):
    n = len(betts.t)
    assert betts.R.shape == (n, 3, 3) and betts.quaternion.shape == (n, 4)
    for name in ("omega_body", "torque_body", "L_space", "costate_attitude_body", "costate_omega",
                 "switching_function"):
        assert getattr(betts, name).shape == (n, 3), name
    assert np.array_equal(betts.costate_t, betts.t) and betts.hamiltonian.shape == (n,)
    assert betts.t[0] == 0.0 and betts.t[-1] == pytest.approx(betts.final_time, rel=1e-15)
    # The bounds hold at every sample (bang-bang: |u_i| = 50 N·m exactly) and the rate bound is inactive.
    assert np.all(np.abs(betts.torque_body) <= 50.0 * (1 + 1e-15))
    assert np.max(np.abs(betts.omega_body)) < 0.5
    # R stays a rotation (RKF78 at 1e-13 over ~29 s) and the quaternions are the same attitudes.
    I = np.eye(3)
    assert np.max(np.abs(np.einsum("nji,njk->nik", betts.R, betts.R) - I)) < 1e-10
    R_from_q = np.array([poinsot.so3.rotation_from_quaternion(q) for q in betts.quaternion])
    assert np.max(np.abs(R_from_q - betts.R)) < 1e-12
    # L = R J ω, from the independent NumPy product.
    J = np.diag([5621.0, 4547.0, 2364.0])
    assert np.allclose(betts.L_space, np.einsum("nij,nj->ni", betts.R, betts.omega_body @ J), rtol=0,
                       atol=1e-12 * np.max(np.abs(betts.L_space)))
    # Minimum principle: u_i = −u_max sign σ_i wherever σ_i is not negligibly small, and H ≡ 0 (free T).
    sigma = betts.switching_function
    clear = np.abs(sigma) > 1e-6 * np.max(np.abs(sigma))
    assert np.all(np.sign(betts.torque_body[clear]) == -np.sign(sigma[clear]))
    assert np.max(np.abs(betts.hamiltonian)) < 1e-8
    # Starts at rest at the identity, ends at rest at 150° about body x.
    assert np.allclose(betts.R[0], I, atol=1e-15) and np.allclose(betts.omega_body[0], 0, atol=1e-15)
    target = poinsot.so3.rotation_from_quaternion([math.cos(math.radians(75)), math.sin(math.radians(75)), 0, 0])
    assert np.max(np.abs(betts.R[-1] - target)) < 1e-9
    assert np.max(np.abs(betts.omega_body[-1])) < 1e-9


def test_betts_direct_solution_and_interpretation(betts):
    d = betts.direct
    # The refinement stops at the first mesh from which the optimum verifies, above the mesh tolerance
    # (docs/optimal_control.md, "Minimum-time problems stop refining once verified").
    assert not d.converged and d.status.endswith("the minimum principle verified from this mesh")
    assert 1e-7 < d.max_mesh_error <= 1e-4
    assert d.quaternion.shape == (len(d.t), 4) and len(d.node_time) == len(d.mesh_error) + 1
    assert d.costate_attitude_body.shape == (len(d.costate_time), 3) and d.max_mesh_error == max(d.mesh_error)
    # The mesh blurs the switches: the direct optimum agrees with the indirect one to the mesh's accuracy.
    assert abs(d.final_time - betts.final_time) / betts.final_time < 1e-3
    m = betts.interpretation
    n = len(betts.t)
    assert m["lambda_body"].shape == (n, 3, 3) and m["stress_space"].shape == (n, 3, 3)
    # vee(Λ − Λᵀ) = u (the paper's Λ carries the torque): computed here from the arrays.
    lam = m["lambda_body"]
    vee = np.stack([lam[:, 2, 1] - lam[:, 1, 2], lam[:, 0, 2] - lam[:, 2, 0], lam[:, 1, 0] - lam[:, 0, 1]], 1)
    assert np.max(np.abs(vee - betts.torque_body)) < 1e-9 * 50
    assert np.allclose(m["momentum_space"], betts.L_space, rtol=0, atol=1e-12 * np.max(np.abs(betts.L_space)))
    assert m["peak_tresca"] > 0 and m["peak_von_mises"] >= m["peak_tresca"] * math.sqrt(3) / 2
    # x is a principal axis: the eigenaxis manoeuvre accelerates at 50/5621 rad/s² for 2√(Θ/α).
    eigenaxis = 2 * math.sqrt(math.radians(150) * 5621 / 50)
    assert m["eigenaxis_cost"] == pytest.approx(eigenaxis, rel=1e-12)
    assert m["saving"] == pytest.approx((eigenaxis - betts.final_time) / eigenaxis, rel=1e-12)


def test_minimum_energy_sphere_from_a_dict_is_the_eigenaxis_cubic():
    j, theta, T = 2.0, 1.2, 3.0
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    scenario = {"body": {"principal_moments": [j, j, j]},
                "optimal_control": {"objective": "minimum_energy", "final_time": T, "torque_max": [10, 10, 10],
                                    "final": {"orientation": axis_angle_dict(axis, theta)}}}
    r = poinsot.optimize(scenario)
    assert r.optimal and r.objective == "minimum_energy" and len(r.switch_times) == 0
    # Closed form: θ(t) = Θ(3s² − 2s³), cost 12 j² Θ² / T³ (the peak torque 6jΘ/T² = 1.6 N·m is inside the bounds).
    assert r.cost == pytest.approx(12 * j**2 * theta**2 / T**3, rel=1e-10)
    s = r.t / T
    angle = np.array([np.linalg.norm(poinsot.so3.log(R)) for R in r.R])
    assert np.max(np.abs(angle - theta * (3 * s**2 - 2 * s**3))) < 1e-10
    # The rotation stays about the fixed axis: ω ∥ n.
    assert np.max(np.linalg.norm(np.cross(r.omega_body, axis), axis=1)) < 1e-10
    # The direct method reaches the same cost to its mesh tolerance.
    assert r.direct.cost == pytest.approx(r.cost, rel=1e-6)


def test_problem_object_sphere_slew_beats_the_eigenaxis_manoeuvre():
    p = poinsot.optimal.ReorientationProblem(inertia=np.eye(3), torque_max=[1, 1, 1],
                                             attitude_final=[0.0, 1.0, 0.0, 0.0])
    assert p.objective == "minimum_time" and p.torque_bound == "per_axis" and p.rate_max is None
    r = poinsot.optimize(p)
    assert r.optimal and r.problem.torque_bound == "per_axis"
    # Bilimoria & Wie (1993): strictly faster than the eigenaxis 2√π; the optimum is symmetric in time
    # (a rest-to-rest manoeuvre of a sphere reversed is one too), so its switches pair as t_k + t_{6−k} = T.
    eigenaxis = 2 * math.sqrt(math.pi)
    assert r.final_time < eigenaxis * (1 - 0.08)
    assert r.interpretation["eigenaxis_cost"] == pytest.approx(eigenaxis, rel=1e-12)
    ts = r.switch_times
    assert len(ts) == 5
    assert np.max(np.abs(ts + ts[::-1] - r.final_time)) < 1e-8
    assert r.final_time == pytest.approx(3.2430832775, abs=1e-9)


def test_files_are_written_and_agree(tmp_path, betts):
    r = poinsot.optimize(EXAMPLES / "sphere_slew.toml", out_dir=tmp_path / "out")
    out = tmp_path / "out"
    for name in ("report.txt", "trajectory.csv", "control.csv", "costates.csv", "summary.json"):
        assert (out / name).exists(), name
    assert json.loads((out / "summary.json").read_text()) == r.summary
    assert (out / "report.txt").read_text() == r.report
    assert r.out_dir == str(out)


def test_plot_draws_the_figures_from_the_files(tmp_path):
    pytest.importorskip("matplotlib")
    r = poinsot.optimize(EXAMPLES / "sphere_slew.toml", out_dir=tmp_path, plot=True)
    names = sorted(p.name for p in r.figures)
    assert names == ["attitude_error.png", "hamiltonian.png", "omega.png", "switching.png", "torque.png"]
    assert all((tmp_path / n).stat().st_size > 1000 for n in names)
    with pytest.raises(ValueError, match="out_dir"):
        poinsot.optimize(EXAMPLES / "sphere_slew.toml", plot=True)


def test_plot_attitude_error_is_accurate_near_zero():
    """The attitude-error figure's angle: 4 atan2(‖q − q_f‖, ‖q + q_f‖) keeps 1e-10 rad (2 acos would not)."""
    from poinsot.plot_optimal import _quaternion_angle

    a = np.array([1e-10, 0.3, math.pi])
    q = np.column_stack([np.cos(a / 2), np.sin(a / 2) * 0.6, np.zeros(3), np.sin(a / 2) * 0.8])
    assert np.allclose(_quaternion_angle(q, np.array([1.0, 0, 0, 0])), a, rtol=1e-12, atol=0)
    assert _quaternion_angle(-q[:1], np.array([1.0, 0, 0, 0]))[0] == pytest.approx(1e-10, rel=1e-12)


def test_scenario_objects_and_options():
    sc = poinsot.optimal.load_scenario(str(EXAMPLES / "betts.toml"))
    assert sc.name == "betts" and sc.problem.rate_max == 0.5
    coarse = sc.with_options(initial_intervals=4, mesh_tolerance=1e-4)
    assert (coarse.initial_intervals, coarse.mesh_tolerance) == (4, 1e-4)
    assert sc.initial_intervals != 4  # a copy
    with pytest.raises(ValueError, match="initial_intervals"):
        sc.with_options(initial_intervals=1)
    with pytest.raises(ValueError, match="mesh_tolerance"):
        sc.with_options(mesh_tolerance=-1.0)
    with pytest.raises(ValueError, match="max_mesh_iterations"):
        poinsot.optimize(sc, max_mesh_iterations=0)
    assert sc.starts == 4 and sc.with_options(starts=1).starts == 1
    with pytest.raises(ValueError, match="collocation.starts: 0"):
        sc.with_options(starts=0)


def test_starts_are_reported_and_one_start_solves_the_first_guess_only(betts):
    # Betts' slew: four first-mesh optima that agree (docs/optimal_control.md, "Several starts"), the first kept;
    # with starts=1 the first mesh is solved once, from the first guess, to the same answer.
    four = betts
    one = poinsot.optimize(EXAMPLES / "betts.toml", starts=1)
    starts = four.summary["direct"]["first_mesh_starts"]
    assert [s["turn_deg"] for s in starts] == [0.0, 90.0, 180.0, 270.0]
    assert all(s["solved"] for s in starts) and four.summary["direct"]["chosen_start"] == 0
    assert max(s["cost"] for s in starts) <= min(s["cost"] for s in starts) * (1 + 1e-6)
    assert one.summary["direct"]["first_mesh_starts"] == []
    assert one.optimal and four.optimal and one.final_time == four.final_time


RATE_BOUNDED = {
    "body": {"principal_moments": [1.0, 1.0, 1.0]},
    "optimal_control": {"objective": "minimum_time", "torque_bound": "norm", "torque_max": 1.0,
                        "rate_max": 0.8, "mesh_tolerance": 1e-6,
                        "final": {"orientation": {"axis_angle": {"axis": [1.0, 0.0, 0.0], "angle": 1.5}}}},
}


def test_a_solution_that_is_not_verified_is_never_presented_as_optimal():
    # Two intervals and one mesh iteration: the shooting method does not take an active rate bound under a
    # norm bound on the torque, and the
    # two-interval control misses the target by about 1e-2 rad: not converged.
    with pytest.warns(RuntimeWarning, match="not converged"):
        r = poinsot.optimize(RATE_BOUNDED, initial_intervals=2, max_mesh_iterations=1)
    assert not r.optimal and r.status.startswith("not converged:") and r.outcome == "not_converged"
    assert r.failed_phase == "indirect method (shooting)" and "mesh_tolerance" in r.advice
    assert r.method == "direct" and len(r.t) == 5
    assert r.summary["optimal"] is False and "not converged" in r.report
    assert "NOT OPTIMAL" in repr(r)


def test_converged_direct_is_its_own_outcome_never_optimal():
    # The same slew refined: the direct solution's control, re-simulated by DOP853, reaches the target to
    # 1e-6, but the minimum principle is not verified (a state-constrained arc under a norm bound): exit 3 of
    # the command.
    with pytest.warns(RuntimeWarning, match="converged \\(direct; minimum principle not verified"):
        r = poinsot.optimize(RATE_BOUNDED)
    assert not r.optimal and r.outcome == "converged_direct" and r.method == "direct"
    assert r.summary["direct_replay"]["scaled_error"] <= 1e-6
    assert np.max(np.abs(r.omega_body)) <= 0.8 * (1 + 1e-6)
    assert "NOT OPTIMAL" in repr(r)


@pytest.mark.parametrize("kwargs, match", [
    (dict(inertia=[1, 1, 1], torque_max=[1, -1, 1]), "torque_max"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1]), "torque_max"),
    (dict(inertia=[1, 1, -1], torque_max=[1, 1, 1]), "inertia"),
    (dict(inertia=[1, 2, 10], torque_max=[1, 1, 1]), "inertia"),  # violates the triangle inequality
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], torque_bound="box"), "torque_bound"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], torque_bound="norm"), "torque_max"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], objective="fastest"), "objective"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], objective="minimum_energy"), "final_time"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], final_time=2.0), "final_time"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], objective="minimum_energy", final_time=0.1,
          attitude_final=[0, 1, 0, 0]), "too short"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], rate_max=0.1, omega_initial=[0.2, 0, 0]), "rate_max"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], attitude_final=[1, 1, 0, 0]), "unit quaternion"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], attitude_final=np.ones((3, 3))), "attitude_final"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], free_final_attitude=True, attitude_final=[1, 0, 0, 0]),
     "free_final_attitude"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], energy_weight=1e-3), "energy_weight"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1],
          keep_out=[{"boresight_body": [1, 0, 0], "direction_space": [1, 0, 0], "half_angle": 0.1}]),
     r"keep_out\[1\]: the boresight .* initial attitude"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1],
          keep_in=[{"boresight_body": [0, 0, 0], "direction_space": [1, 0, 0], "half_angle": 0.1}]),
     r"keep_in\[1\]\.boresight_body"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1],
          keep_out=[{"boresight_body": [1, 0, 0], "direction_space": [0, 1, 0], "half_angle": 0.1,
                     "half_angle_deg": 5}]), r"keep_out\[1\]: expected exactly one"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1],
          keep_out=[{"boresight_body": [1, 0, 0], "direction_space": [0, 1, 0], "angle": 0.1}]),
     r"keep_out\[1\]\.angle: unknown key"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], reaction_wheels={"momentum_max": 1.0}),
     r"reaction_wheels\.spin_inertia: missing"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], reaction_wheels={"spin_inertia": [0.1] * 3, "speed": 1}),
     r"reaction_wheels\.speed: unknown key"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1],
          reaction_wheels={"spin_inertia": [0.1] * 3, "axes": [[1, 0, 0], [0, 1, 0], [0, 1, 0]]}),
     r"reaction_wheels\.axes: det A"),
    (dict(inertia=[1, 1, 1], torque_max=[1, 1, 1], omega_initial=[0, 0, 1],
          reaction_wheels={"spin_inertia": [0.1] * 3, "momentum_max": 0.5}),
     r"reaction_wheels\.momentum_max: .* final state"),
])
def test_bad_problems_raise_value_error_naming_the_field(kwargs, match):
    with pytest.raises(ValueError, match=match) as err:
        poinsot.optimal.ReorientationProblem(**kwargs)
    assert "\n" not in str(err.value)


def test_keep_out_cone_the_sphere_misses_leaves_the_verified_optimum():
    """The sphere turned 150° about z at minimum energy: its boresight x passes 0.3 rad from a Sun set above its
    halfway direction; a 0.25 rad cone leaves the eigenaxis optimum (docs/pointing_constraints.md)."""
    j, theta, T = 2.0, math.radians(150.0), 4.0
    sun = [math.cos(0.3) * math.cos(theta / 2), math.cos(0.3) * math.sin(theta / 2), math.sin(0.3)]
    p = poinsot.optimal.ReorientationProblem(
        inertia=[j, j, j], torque_max=100.0, torque_bound="norm", objective="minimum_energy", final_time=T,
        attitude_final=[math.cos(theta / 2), 0.0, 0.0, math.sin(theta / 2)],
        keep_out=[{"name": "sun", "boresight_body": [2, 0, 0], "direction_space": sun, "half_angle": 0.25}])
    [cone] = p.pointing
    assert cone["kind"] == "keep_out" and cone["name"] == "sun" and cone["boresight_body"].tolist() == [1, 0, 0]
    r = poinsot.optimize(p, mesh_tolerance=1e-8)
    assert r.optimal and r.cost == pytest.approx(12 * j**2 * theta**2 / T**3, rel=1e-10)
    [summary] = r.summary["pointing"]
    assert summary["indirect"]["margin"] == pytest.approx(0.05, abs=1e-6)
    assert r.direct.pointing_multiplier.shape == (1, len(r.direct.t))
    assert np.max(np.abs(r.direct.pointing_multiplier)) < 1e-9 and r.direct.pointing_widening == 0.0


def test_reaction_wheel_slew_is_the_single_axis_closed_form():
    """Three wheels on the axes of a bus J_b = diag(3, 4, 2) (the spacecraft's inertia less the wheels' axial
    parts) turn it 1 rad about z in 10 s at minimum energy: u_z = −6 I Θ/T² (1 − 2t/T), cost 12 I² Θ² / T³,
    h_z = −I θ̇, converged (direct) as the shooting does not model wheels (docs/reaction_wheels.md)."""
    I, theta, T = 2.0, 1.0, 10.0
    p = poinsot.optimal.ReorientationProblem(
        inertia=[3.1, 4.1, I + 0.1], torque_max=[1, 1, 1], objective="minimum_energy", final_time=T,
        attitude_final=[math.cos(theta / 2), 0.0, 0.0, math.sin(theta / 2)],
        reaction_wheels={"spin_inertia": [0.1, 0.1, 0.1], "momentum_max": [1, 1, 1]})
    assert p.reaction_wheels["total_momentum_space"].tolist() == [0, 0, 0]
    r = poinsot.optimize(p, mesh_tolerance=1e-9)
    assert r.outcome == "converged_direct" and not r.optimal and "reaction wheels" in r.status
    assert r.cost == pytest.approx(12 * I**2 * theta**2 / T**3, rel=1e-8)
    t = r.direct.t
    np.testing.assert_allclose(r.direct.torque_body[:, 2], -6 * I * theta / T**2 * (1 - 2 * t / T), atol=1e-6)
    np.testing.assert_allclose(r.direct.wheel_momentum[:, 2], -I * 6 * theta / T**2 * t * (1 - t / T), atol=1e-6)
    assert np.abs(r.L_space).max() < 1e-12  # R (J_b ω + A h): zero total angular momentum throughout
    assert r.summary["reaction_wheels"]["replay"]["momentum_drift"] < 1e-11


def test_bad_scenarios_raise_value_error():
    with pytest.raises(ValueError, match="optimal_control"):
        poinsot.optimize({"body": {"principal_moments": [1, 1, 1]}})
    with pytest.raises(ValueError, match="torque_max"):
        poinsot.optimize({"body": {"principal_moments": [1, 1, 1]},
                          "optimal_control": {"torque_max": [1, 1, 0]}})
    with pytest.raises(ValueError, match="no_such_file"):
        poinsot.optimize("no_such_file.toml")
    with pytest.raises(TypeError, match="problem"):
        poinsot.optimize(42)


def test_the_optimal_reorientation_example_runs_and_verifies():
    """examples/python/optimal_reorientation.py solves Betts and the sphere slew and says all checks passed."""
    import os
    import subprocess
    import sys

    script = SOURCE_DIR / "examples" / "python" / "optimal_reorientation.py"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, env=env, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "all checks passed" in r.stdout
    assert "28.63040" in r.stdout and "3.24308327" in r.stdout


def test_betts_phased_resolve(betts):
    """The phase-per-arc re-solve (64 intervals per arc) gives the direct optimum of Betts' problem: t* within
    5e-8 of the published 28.6304077 s and 1e-10 of the indirect t* (measured 1.1e-11), the phase boundaries
    the indirect switches to 1e-8 s (measured 8.6e-10 s)."""
    p = betts.phased
    assert p["applied"] and p["converged"], p["status"]
    assert betts.direct_optimum_from == "phased"
    assert abs(p["final_time"] - BETTS_PUBLISHED) / BETTS_PUBLISHED < 5e-8
    assert abs(p["final_time"] - betts.final_time) / betts.final_time < 1e-10
    assert np.max(np.abs(np.asarray(p["switch_times"]) - betts.switch_times)) < 1e-8
    assert betts.checks["direct_indirect_difference"] < 1e-10
    # the mesh-refined solution, which seeds the shooting, is kept as `direct`
    assert abs(betts.direct.final_time - betts.final_time) / betts.final_time > 1e-8


def test_phased_resolve_can_be_turned_off():
    problem = {"body": {"principal_moments": [1.0, 1.0, 1.0]},
               "optimal_control": {"objective": "minimum_time", "torque_max": [1.0, 1.0, 1.0],
                                   "mesh_tolerance": 1e-5, "phased": False,
                                   "final": {"orientation": {"quaternion": [0.0, 1.0, 0.0, 0.0]}}}}
    s = poinsot.optimize(problem)
    assert s.optimal, s.status
    assert s.phased == {"enabled": False, "applied": False, "status": "off", "converged": False}
    assert s.direct_optimum_from == "mesh_refinement"
    with pytest.raises(ValueError, match="phased_intervals_per_arc"):
        problem["optimal_control"].update(phased=True, phased_intervals_per_arc=0)
        poinsot.optimize(problem)
