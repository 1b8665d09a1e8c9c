"""poinsot.simulate from Python: round trips against the command line's JSON and the in-process run, the
exact solution, Python torque callbacks (against built-in torques and a closed form), NumPy shapes and dtypes,
zero-copy hand-over, scenario dicts, and errors."""
import json
import subprocess

import numpy as np
import pytest

import poinsot
from poinsot import RigidBody, State, TorqueModel, so3

EPS = np.finfo(float).eps
BODY = [1.0, 2.0, 3.0]
W0 = [0.3, 1.0, 0.2]


def test_result_arrays_have_the_documented_shapes_and_dtypes():
    r = poinsot.simulate(body=BODY, omega_body=W0, method="rk4", dt=1e-3, t_end=1.0, sample_dt=0.1)
    n = 11
    assert len(r) == n
    for name, shape in [("t", (n,)), ("R", (n, 3, 3)), ("quaternion", (n, 4)), ("omega_body", (n, 3)),
                        ("energy", (n,)), ("L_space", (n, 3)), ("omega_space", (n, 3)), ("L_body", (n, 3))]:
        a = getattr(r, name)
        assert a.dtype == np.float64 and a.shape == shape, name
    assert np.allclose(r.t, np.linspace(0, 1, n), rtol=0, atol=1e-12)
    assert r.steps == 1000 and r.method == "rk4" and r.torque == "none"
    assert r.final_state.time == pytest.approx(1.0)
    assert np.array_equal(r.R[-1], r.final_state.R_space_body) and np.array_equal(r.omega_body[-1], r.final_state.omega_body)


def test_trajectory_is_handed_over_without_copying():
    r = poinsot.simulate(body=BODY, omega_body=W0, method="rk4", t_end=0.5, sample_dt=0.1)
    for a in (r.t, r.R, r.quaternion, r.omega_body, r.energy, r.L_space):
        # The memory belongs to the C++ buffer; NumPy holds it through a capsule (the array's base).
        assert not a.flags.owndata and a.base is not None and a.flags.c_contiguous


def test_sampled_invariants_are_those_of_each_sample():
    body = RigidBody.from_principal_moments(BODY)
    r = poinsot.simulate(body=body, omega_body=W0, R=so3.exp([0.2, 0.1, -0.3]), t_end=2.0, sample_dt=0.25)
    J = body.inertia
    assert np.allclose(r.energy, 0.5 * np.einsum("ni,ij,nj->n", r.omega_body, J, r.omega_body), rtol=1e-14)
    assert np.allclose(r.L_space, np.einsum("nij,jk,nk->ni", r.R, J, r.omega_body), rtol=1e-13, atol=1e-15)
    q = r.quaternion
    assert np.all(q[:, 0] >= 0)
    for i in range(len(r)):
        assert np.allclose(so3.rotation_from_quaternion(q[i]), r.R[i], atol=8 * EPS)
    # dop853 at rtol 1e-10 conserves the free body's invariants to round-off-level drift
    assert r.errors["energy_rel_max"] < 1e-11 and r.errors["L_space_rel_max"] < 1e-9


def test_exact_solution_agrees_with_dop853():
    body = RigidBody.from_principal_moments(BODY)
    s0 = State(omega_body=W0)
    r = poinsot.simulate(body=body, initial=s0, method="dop853", rtol=1e-13, atol=1e-15, t_end=10.0, sample_dt=0.5)
    exact = poinsot.ExactFreeBody(body, s0)
    R, w = exact.states_at(r.t)
    assert R.shape == (len(r), 3, 3) and w.shape == (len(r), 3)
    # dop853 at rtol 1e-13 over ~10 rotations: global error ~1e-11 (a few hundred steps × tolerance)
    assert np.abs(R - r.R).max() < 1e-9 and np.abs(w - r.omega_body).max() < 1e-9
    th = poinsot.free_body_theory(body, W0)
    assert th.regime in ("largest axis", "smallest axis")
    assert th.flip_interval == pytest.approx(exact.flip_interval, rel=1e-15)


def test_flips_of_the_tennis_racket_match_the_closed_form(tennis_racket):
    r = poinsot.simulate(tennis_racket, method="dop853")
    assert len(r.flip_times) == 7  # 20 s at 2.7589 s between flips, the first at 1.78 s
    assert r.flip_interval_theory == pytest.approx(np.diff(r.flip_times).mean(), rel=1e-8)
    assert r.period_theory == pytest.approx(2 * r.flip_interval_theory, rel=1e-15)


def test_same_numbers_as_the_command_line_json(tennis_racket, cli_exe, tmp_path):
    out = subprocess.run([cli_exe, "run", str(tennis_racket), "--method", "dop853", "--json", "--quiet", "--out",
                          str(tmp_path / "run")], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    summary = json.loads(out.stdout)
    r = poinsot.simulate(tennis_racket, method="dop853")
    fin = summary["final"]
    # Same driver, same options: the same doubles (JSON prints them to round-trip exactly).
    assert np.array_equal(r.final_state.omega_body, fin["omega_body"])
    assert np.array_equal(r.final_state.R_space_body, fin["R"])
    assert np.array_equal(r.flip_times, summary["events"]["flip_times"])
    assert r.steps == summary["steps"]
    assert r.errors["energy_rel_max"] == summary["invariants"]["energy_rel_error_max"]
    assert r.flip_interval_theory == summary["events"]["flip_interval_theory"]


def test_run_in_process_gives_the_command_line_summary(tennis_racket, tmp_path):
    res = poinsot.run(tennis_racket, tmp_path / "out", method="dop853", t_end=5.0)
    assert (tmp_path / "out" / "trajectory.csv").exists() and (tmp_path / "out" / "summary.json").exists()
    assert json.loads((tmp_path / "out" / "summary.json").read_text()) == res.summary
    assert "flips of the intermediate axis" in res.report
    r = poinsot.simulate(tennis_racket, method="dop853", t_end=5.0)
    assert np.array_equal(r.final_state.omega_body, res.summary["final"]["omega_body"])


def test_run_of_a_multibody_file_gives_the_command_line_files(cli_exe, source_dir, tmp_path):
    """poinsot.run on a multibody file is `poinsot run`: the same engine (io/run/multibody_run.hpp), the same
    overrides, the same report and summary.json (but for the folder's name and the cpu time), and files."""
    import subprocess

    path = source_dir / "examples" / "multibody" / "double_pendulum.toml"
    res = poinsot.run(path, tmp_path / "py", method="rk4", t_end=0.2, sample_dt=0.01)
    r = subprocess.run([cli_exe, "run", str(path), "--method", "rk4", "--t-end", "0.2", "--sample-dt", "0.01",
                        "--out", str(tmp_path / "cli"), "--json"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)
    assert res.summary == json.loads((tmp_path / "py" / "summary.json").read_text())
    assert res.report == (tmp_path / "py" / "report.txt").read_text()
    for s in (cli, res.summary):
        del s["files"], s["cpu_seconds_per_step"]
    assert res.summary == cli
    assert (res.summary["method"], res.summary["order"], res.summary["steps"]) == ("rk4", 4, 200)
    for name in ("trajectory.csv", "diagnostics.csv", "reactions.csv", "multipliers.csv"):
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text(), name
    assert res.report.startswith("multibody run: double_pendulum (")


def test_a_scenario_dict_equals_the_same_file(tmp_path):
    scenario = {
        "title": "a dict",
        "body": {"principal_moments": [1.0, 2.0, 3.0]},
        "initial": {"omega_body": [0.3, 1.0, 0.2], "orientation": {"axis_angle": {"axis": [0, 0, 1], "angle": 0.5}}},
        "torque": {"type": "body", "value": [0.0, 0.0, 0.1]},
        "integrator": {"method": "dlm", "dt": 1e-3},
        "output": {"t_end": 2.0, "sample_dt": 0.5},
    }
    text = poinsot.scenario_toml(scenario)
    path = tmp_path / "s.toml"
    path.write_text(text)
    a = poinsot.simulate(scenario)
    b = poinsot.simulate(path)
    c = poinsot.simulate(poinsot.load_scenario(str(path)))
    assert a.method == "dlm" and a.steps == 2000
    for x in (b, c):
        assert np.array_equal(a.R, x.R) and np.array_equal(a.omega_body, x.omega_body)
    assert np.allclose(a.R[0], so3.exp([0, 0, 0.5]), atol=4 * EPS)
    # keyword arguments override the scenario's values
    d = poinsot.simulate(scenario, method="rk4", t_end=1.0)
    assert d.method == "rk4" and d.final_state.time == pytest.approx(1.0)


def test_constant_torque_by_callback_equals_the_builtin_torque():
    tau = np.array([0.05, -0.02, 0.1])
    kw = dict(body=BODY, omega_body=W0, t_end=2.0, sample_dt=0.1)
    for method in ("rk4", "dop853", "dlm", "rattle"):
        builtin = poinsot.simulate(torque=TorqueModel.constant_body(tau), method=method, **kw)
        python = poinsot.simulate(torque=lambda t, R, w: tau, method=method, **kw)
        # The callback returns the same doubles at the same calls: the runs are identical.
        assert np.array_equal(builtin.R, python.R), method
        assert np.array_equal(builtin.omega_body, python.omega_body), method
    space = np.array([0.0, 0.1, 0.0])
    builtin = poinsot.simulate(torque=TorqueModel.constant_space(space), method="dop853", **kw)
    python = poinsot.simulate(torque=lambda t, R, w: R.T @ space, method="dop853", **kw)
    # R.T @ tau in NumPy and in Eigen may round differently (1 ulp per call); the adaptive run amplifies it
    # little over 2 s.
    assert np.abs(builtin.R - python.R).max() < 1e-12


def test_omega_dependent_callback_against_the_closed_form():
    # A sphere (J = 2·I) under the damping torque -c ω: ω(t) = ω0 exp(-c t / 2), direction fixed.
    c = 0.3
    r = poinsot.simulate(body=[2.0, 2.0, 2.0], omega_body=[1.0, -0.5, 2.0], torque=lambda t, R, w: -c * w,
                         method="dop853", rtol=1e-12, atol=1e-14, t_end=5.0, sample_dt=0.5)
    expected = np.outer(np.exp(-c * r.t / 2), [1.0, -0.5, 2.0])
    assert np.abs(r.omega_body - expected).max() < 1e-10
    # the energy decays as exp(-c t), checked on the sampled energy
    assert np.allclose(r.energy, r.energy[0] * np.exp(-c * r.t), rtol=1e-10)


class CallbackFailure(Exception):
    pass


def test_an_exception_in_the_callback_propagates_as_itself():
    calls = []

    def tau(t, R, w):
        calls.append(t)
        if t > 0.5:
            raise CallbackFailure(f"stop at {t}")
        return np.zeros(3)

    with pytest.raises(CallbackFailure, match="stop at"):
        poinsot.simulate(body=BODY, omega_body=W0, torque=tau, method="rk4", t_end=2.0)
    assert 0.5 < calls[-1] < 0.51


def test_a_bad_callback_result_says_what_was_expected():
    with pytest.raises(ValueError, match=r"torque callback: .* expected an array of shape \(3,\), got shape \(2,\)"):
        poinsot.simulate(body=BODY, omega_body=W0, torque=lambda t, R, w: [1.0, 2.0], method="rk4", t_end=0.1)
    with pytest.raises(TypeError, match="expected real numbers"):
        poinsot.simulate(body=BODY, omega_body=W0, torque=lambda t, R, w: None, method="rk4", t_end=0.1)
    with pytest.raises(TypeError, match="torque: expected None, a poinsot.TorqueModel or a callable"):
        poinsot.simulate(body=BODY, omega_body=W0, torque=42, t_end=0.1)


def test_errors_are_value_errors_with_poinsots_message():
    with pytest.raises(ValueError, match='method: got "rk5", expected one of ' + ", ".join(poinsot.METHODS)):
        poinsot.simulate(body=BODY, omega_body=W0, method="rk5")
    with pytest.raises(ValueError, match=r'unknown key "t_edn"; valid keys: t_end, sample_dt, dir'):
        poinsot.simulate({"body": {"principal_moments": BODY}, "initial": {"omega_body": W0},
                          "output": {"t_edn": 1.0}})
    with pytest.raises(ValueError, match="triangle inequality"):
        poinsot.simulate(body=[1, 1, 5], omega_body=W0)
    with pytest.raises(ValueError, match="body: missing"):
        poinsot.simulate(omega_body=W0)
    with pytest.raises(ValueError, match="cannot be read|No such file|not found|cannot open"):
        poinsot.simulate("/nonexistent/scenario.toml")


def test_summary_only_run_keeps_no_samples():
    r = poinsot.simulate(body=BODY, omega_body=W0, method="dlm", dt=1e-3, t_end=1.0, keep_samples=False)
    assert len(r) == 0 and r.R.shape == (0, 3, 3) and r.steps == 1000
    assert r.final_state.time == pytest.approx(1.0)


def test_max_step_caps_the_adaptive_steps_from_a_scenario_or_a_keyword():
    # No largest step by default: dop853 at its default tolerances chooses steps far longer than dt = 1e-3;
    # max_step = dt (a keyword, or the scenario's [integrator] max_step) caps every step at dt.
    free = poinsot.simulate(body=BODY, omega_body=W0, method="dop853", t_end=2.0, sample_dt=0.5)
    capped = poinsot.simulate(body=BODY, omega_body=W0, method="dop853", t_end=2.0, sample_dt=0.5, max_step=1e-3)
    assert free.steps < 200 and capped.steps >= 2000
    scenario = {"body": {"principal_moments": list(BODY)}, "initial": {"omega_body": list(W0)},
                "integrator": {"method": "dop853", "max_step": 1e-3}, "output": {"t_end": 2.0, "sample_dt": 0.5}}
    assert poinsot.simulate(scenario).steps == capped.steps
    assert poinsot.parse_scenario(poinsot.scenario_toml(scenario), "<dict>", ".").max_step == 1e-3
    # the two agree to the tolerance (rtol 1e-10 per step over a few hundred steps)
    assert np.abs(free.R - capped.R).max() < 1e-8
    with pytest.raises(ValueError, match="max_step: got 0"):
        poinsot.make_integrator("dopri5", RigidBody.from_principal_moments(BODY), max_step=0.0)


def test_integrator_step_by_step_matches_simulate():
    body = RigidBody.from_principal_moments(BODY)
    integ = poinsot.make_integrator("rk4", body, dt=1e-2)
    s = State(omega_body=W0)
    for _ in range(100):
        integ.step(s, 1e-2)
    r = poinsot.simulate(body=body, omega_body=W0, method="rk4", dt=1e-2, t_end=1.0, sample_dt=1.0)
    assert integ.name == "rk4" and integ.order == 4
    assert np.abs(s.R_space_body - r.final_state.R_space_body).max() < 1e-14


def test_integrator_advance_is_repeated_steps():
    # advance(s, dt, n) leaves bit for bit what n calls of step(s, dt) leave (rk4: one conversion per call).
    body = RigidBody.from_principal_moments(BODY)
    a = poinsot.make_integrator("rk4", body, dt=1e-2)
    b = poinsot.make_integrator("rk4", body, dt=1e-2)
    sa, sb = State(omega_body=W0), State(omega_body=W0)
    for _ in range(37):
        a.step(sa, 1e-2)
    r = b.advance(sb, 1e-2, 37)
    assert r["dt_taken"] == 1e-2 and r["rejected"] == 0
    assert sa.time == sb.time
    assert np.array_equal(sa.R_space_body, sb.R_space_body) and np.array_equal(sa.omega_body, sb.omega_body)
    with pytest.raises(ValueError, match="n = 0 steps; expected at least 1"):
        b.advance(sb, 1e-2, 0)


def test_plot_draws_the_figures_of_a_run_folder(tennis_racket, tmp_path):
    pytest.importorskip("matplotlib")
    res = poinsot.run(tennis_racket, tmp_path / "run", method="dop853", t_end=3.0, plot=True)
    names = sorted(p.name for p in res.figures)
    assert names == ["invariants.png", "omega.png", "polhode.png"]
    for p in res.figures:
        assert p.stat().st_size > 1000 and p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert poinsot.plot.plot_run(tmp_path / "run") == res.figures


def test_ctrl_c_interrupts_a_long_run():
    import _thread
    import threading

    # interrupt_main() raises SIGINT's flag as Ctrl-C would; the C++ loop polls for it between samples.
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            poinsot.simulate(body=BODY, omega_body=W0, method="rk4", dt=1e-6, t_end=1000.0, sample_dt=0.01,
                             keep_samples=False)  # 1e9 steps: minutes, unless interrupted
    finally:
        timer.cancel()


def test_the_registry_of_methods_is_the_one_make_integrator_reads():
    body = poinsot.RigidBody.from_principal_moments([1.0, 2.0, 3.0])
    assert list(poinsot.METHODS) == ["exact", "rk4", "dopri5", "dop853", "dlm", "rattle"]
    for name, info in poinsot.METHODS.items():
        integ = poinsot.make_integrator(name, body)
        assert (info.name, info.order) == (integ.name, integ.order)
        assert set(info.preserves) <= {"energy", "L_space", "L_body_norm", "orthogonality"}
        assert info.description
    assert poinsot.METHODS["dlm"].symplectic and not poinsot.METHODS["exact"].takes_torque
    assert poinsot.DEFAULT_METHOD == "dop853" and poinsot.DEFAULT_LAMBDA_METHOD == "rattle"
    assert poinsot.simulate(body=body, omega_body=W0, t_end=0.1).method == poinsot.DEFAULT_METHOD
    assert ", ".join(poinsot.METHODS) in poinsot.simulate.__doc__
    mb = poinsot.multibody
    assert list(mb.METHODS) == ["rattle", "rk4"] and mb.DEFAULT_METHOD == "rattle"
    assert (mb.METHODS["rattle"].order, mb.METHODS["rattle"].max_order, mb.METHODS["rk4"].order) == (2, 4, 4)
    assert "momentum" in mb.METHODS["rattle"].preserves and "momentum" not in mb.METHODS["rk4"].preserves


def test_lambda_report_defaults_to_the_registrys_lambda_method():
    body = poinsot.RigidBody.from_principal_moments([1.0, 2.0, 3.0])
    rep = poinsot.analysis.lambda_report(body, poinsot.State(omega_body=[0.4, -0.3, 2.0]), t_end=0.2)
    assert rep["method"] == poinsot.DEFAULT_LAMBDA_METHOD
