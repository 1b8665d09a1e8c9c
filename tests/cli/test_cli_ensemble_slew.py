"""poinsot ensemble with [ensemble.slew]: a plan of `poinsot optimize` replayed in closed loop on dispersed
bodies. Zero dispersion reproduces the optimizer's verified replay; threads do not change a bit; bad keys
give one line and exit 2.

The replay is RK4 on steps ≤ dt = 1e-3 s with a node at every switch: its error on this slew (|ω| ≤ 2 rad/s,
T = 3.24 s) is about 1e-13 rad (tests/ensemble/test_slew_tracking.cpp measures the fourth order), and the
optimizer's own DOP853 replay reaches the target to 8e-12 rad, so both final pointing errors are below 1e-10.
"""
import csv
import json

import pytest

SLEW = """
[body]
principal_moments = [1.0, 1.0, 1.0]
[initial]
omega_body = [0.0, 0.0, 0.0]
[integrator]
method = "rk4"
dt = 0.001
[output]
t_end = {t_end}
[ensemble]
samples = {samples}
seed = 3
[ensemble.slew]
control = "{control}"
kp = 4.0
kd = 4.0
torque_bound = "per_axis"
torque_max = 1.2
pointing_requirement = 1.0
degrees = true
[ensemble.slew.target]
orientation = {{ quaternion = [0.0, 1.0, 0.0, 0.0] }}
"""

@pytest.fixture(scope="module")
def optimum(tmp_path_factory):
    """The sphere's minimum-time slew, solved and verified by poinsot optimize (about a second)."""
    import os
    import subprocess
    from pathlib import Path

    out = tmp_path_factory.mktemp("opt")
    source = Path(os.environ.get("POINSOT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
    r = subprocess.run([os.environ["POINSOT_CLI"], "optimize", str(source / "examples/optimal/sphere_slew.toml"),
                        "--out", str(out / "sphere"), "--json"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    summary = json.loads((out / "sphere/summary.json").read_text())
    assert summary["status"].startswith("optimal")
    return out / "sphere", summary


def scenario(tmp_path, control, t_end, samples=8, edit=None):
    text = SLEW.format(control=control, t_end=repr(t_end), samples=samples)
    if edit:
        text = edit(text)
    path = tmp_path / "slew.toml"
    path.write_text(text)
    return path


def test_zero_dispersion_reproduces_the_verified_replay(cli, tmp_path, optimum):
    opt_dir, summary = optimum
    T = summary["indirect"]["final_time"]
    r = cli("ensemble", scenario(tmp_path, opt_dir / "control.csv", T), "--out", tmp_path / "e", "--json")
    assert r.returncode == 0, r.stderr
    s = json.loads(r.stdout)
    pointing = s["outputs"]["pointing_error"]
    replay = summary["checks"]["resimulated_attitude_error"]
    assert replay < 1e-10  # the optimizer's DOP853 replay against the target
    # Every sample is the nominal one: the same final pointing error as the optimizer's replay, to both
    # integrators' errors (≤ 1e-10 together), and no feedback (the reference is the plan's own motion).
    assert pointing["count"] == 8 and pointing["max"] == pointing["min"]
    assert abs(pointing["nominal"] - replay) < 1e-10
    assert s["outputs"]["rate_error"]["max"] < 1e-10
    assert s["outputs"]["peak_feedback_torque"]["max"] < 1e-9
    assert abs(s["outputs"]["peak_torque"]["nominal"] - 3 ** 0.5) < 1e-9  # |u_i| = 1 on every arc
    assert s["slew"]["share_meeting_requirement"] == 1.0
    assert s["slew"]["kp"] == 4.0 and s["slew"]["torque_bound"] == "per_axis"
    # The target taken from the optimizer's summary.json instead: the same target, the same outputs.
    def from_summary(text):
        head = text[: text.index("[ensemble.slew.target]")]
        return head + f'[ensemble.slew.target]\nsummary = "{opt_dir / "summary.json"}"\n'

    r = cli("ensemble", scenario(tmp_path, opt_dir / "control.csv", T, edit=from_summary), "--out",
            tmp_path / "f", "--json")
    assert r.returncode == 0, r.stderr
    f = json.loads(r.stdout)
    assert f["outputs"] == s["outputs"] and f["slew"]["attitude_final"] == summary["problem"]["attitude_final"]
    # The optimizer's trajectory.csv as the reference: its rows (every 0.007 s, both sides of each switch)
    # interpolated by cubic Hermite, error O(Δt⁴) ≈ 1e-10 rad here (tests/ensemble measures the order): the
    # feedback that error times the gains, the end the same to 1e-10.
    def with_reference(text):
        return text.replace("kp = 4.0", f'reference = "{opt_dir / "trajectory.csv"}"\nkp = 4.0')

    r = cli("ensemble", scenario(tmp_path, opt_dir / "control.csv", T, edit=with_reference), "--out",
            tmp_path / "g", "--json")
    assert r.returncode == 0, r.stderr
    g = json.loads(r.stdout)["outputs"]
    assert 0 < g["peak_feedback_torque"]["nominal"] < 1e-8
    assert abs(g["pointing_error"]["nominal"] - pointing["nominal"]) < 1e-10


def test_the_committed_example_plan_is_the_optimizers(source_dir, optimum):
    """examples/ensemble/sphere_slew_control.csv is what its header's command writes (to 1e-12 s, N·m)."""
    opt_dir, _ = optimum

    def table(path):
        lines = [line for line in open(path) if line.strip() and not line.startswith("#")]
        return [[float(x) for x in row.values()] for row in csv.DictReader(lines)]

    committed = table(source_dir / "examples/ensemble/sphere_slew_control.csv")
    fresh = table(opt_dir / "control.csv")
    assert len(committed) == len(fresh)
    for a, b in zip(committed, fresh):
        assert all(abs(x - y) < 1e-12 for x, y in zip(a, b))


def test_dispersed_slews_are_bit_identical_for_one_and_two_threads(cli, tmp_path, source_dir):
    example = source_dir / "examples/ensemble/sphere_slew_robustness.toml"
    a = cli("ensemble", example, "--samples", "300", "--threads", "1", "--out", tmp_path / "a")
    b = cli("ensemble", example, "--samples", "300", "--threads", "2", "--out", tmp_path / "b")
    assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
    assert (tmp_path / "a/samples.csv").read_text() == (tmp_path / "b/samples.csv").read_text()
    sa = json.loads((tmp_path / "a/summary.json").read_text())
    sb = json.loads((tmp_path / "b/summary.json").read_text())
    assert sa["outputs"] == sb["outputs"] and sa["slew"] == sb["slew"]
    assert sa["path"] == "closed-loop slew, scalar rk4"
    share = sa["slew"]["share_meeting_requirement"]
    assert 0.0 < share < 1.0  # the example's requirement (1°) is met by most samples, not all
    rows = list(csv.DictReader(open(tmp_path / "a/samples.csv")))
    meets = [float(r["meets_requirement"]) for r in rows]
    within = [float(r["pointing_error"]) <= sa["slew"]["pointing_requirement"] for r in rows]
    assert meets == [1.0 if w else 0.0 for w in within]
    assert abs(share - sum(meets) / len(meets)) < 1e-12
    assert "within the pointing requirement" in a.stdout


BAD = [
    ("kp = 4.0", "kp = -1.0", "kp", "-1"),
    ('torque_bound = "per_axis"', 'torque_bound = "box"', "torque_bound", "box"),
    ("torque_max = 1.2", "torque_max = 0.0", "torque_max", "0"),
    ('torque_bound = "per_axis"\ntorque_max = 1.2', 'torque_bound = "norm"\ntorque_max = [1.0, 1.0, 1.0]',
     "torque_max", "array"),
    ("pointing_requirement = 1.0", "pointing_requirement = -2.0", "pointing_requirement", "-2"),
    ('interpolation = "linear"', 'interpolation = "spline"', "interpolation", "spline"),
    ("kd = 4.0", "kd = 4.0\ngain = 1.0", "gain", "gain"),
    ('method = "rk4"', 'method = "dop853"', "method", "dop853"),
    ("[ensemble.slew.target]\norientation", "[ensemble.slew.elsewhere]\norientation", "elsewhere", "elsewhere"),
]


@pytest.mark.parametrize("old,new,key,value", BAD)
def test_bad_keys_give_one_line_naming_key_and_value(cli, tmp_path, source_dir, old, new, key, value):
    control = source_dir / "examples/ensemble/sphere_slew_control.csv"

    def edit(text):
        text = text.replace("control = ", 'interpolation = "linear"\ncontrol = ')
        assert old in text
        return text.replace(old, new)

    r = cli("ensemble", scenario(tmp_path, control, 3.2430832774522544, edit=edit), "--out", tmp_path / "bad")
    assert r.returncode == 2, r.stderr
    assert r.stderr.count("\n") == 1 and key in r.stderr and value in r.stderr, r.stderr
    assert not (tmp_path / "bad").exists()


def test_missing_control_file_and_missing_target(cli, tmp_path, source_dir):
    r = cli("ensemble", scenario(tmp_path, tmp_path / "nowhere.csv", 3.0), "--out", tmp_path / "bad")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "nowhere.csv" in r.stderr, r.stderr
    control = source_dir / "examples/ensemble/sphere_slew_control.csv"

    def no_target(text):
        return text[: text.index("[ensemble.slew.target]")]

    r = cli("ensemble", scenario(tmp_path, control, 3.0, edit=no_target), "--out", tmp_path / "bad")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "target" in r.stderr, r.stderr
    def bad_summary(text):
        return no_target(text) + '[ensemble.slew.target]\nsummary = "nowhere.json"\n'

    r = cli("ensemble", scenario(tmp_path, control, 3.0, edit=bad_summary), "--out", tmp_path / "bad")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "summary" in r.stderr, r.stderr
    assert "nowhere.json" in r.stderr, r.stderr
    def bad_reference(text):
        return text.replace("kp = 4.0", f'reference = "{control}"\nkp = 4.0')

    r = cli("ensemble", scenario(tmp_path, control, 3.0, edit=bad_reference), "--out", tmp_path / "bad")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "reference" in r.stderr, r.stderr
    assert "t,qw,qx,qy,qz,wx,wy,wz,ux,uy,uz" in r.stderr, r.stderr
    r = cli("ensemble", scenario(tmp_path, control, 3.0), "--sample", "2", "--out", tmp_path / "bad")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "--sample" in r.stderr, r.stderr
