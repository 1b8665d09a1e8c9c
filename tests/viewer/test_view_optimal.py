"""`poinsot view` on a `poinsot optimize` folder: the control torque, its bounds, the target attitude and the
chart of the control and the switching functions, read back from the page and checked against the run's files.

Oracles: trajectory.csv (the torque drawn at a frame is R(q) u of that row, to round-off), control.csv (the
chart's control is its columns exactly), summary.json (the switches marked are its switch times), the
scenario (the bounds and the target), and Pontryagin's principle for a per-axis bound in minimum time,
u_i = -u_max,i sign(sigma_i) (docs/optimal_control_theory.md): every marked switch of axis i is a zero of sigma_i in
the chart (its sign changes between the costate samples around it), and between switches the chart's control
has the sign of -sigma_i. The Bilimoria & Wie slew takes 0.3 s to solve."""
import csv
import json
from pathlib import Path

import numpy as np
import pytest



def rows(path):
    with open(path) as f:
        r = [line for line in csv.reader(f) if line and not line[0].startswith("#")]
    return r[0], np.array([[float(x) for x in line] for line in r[1:]])


def rotation(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@pytest.fixture
def slew(slew_run):
    return slew_run


@pytest.mark.parametrize("example", ["optimal/sphere_slew.toml"])
def test_torque_bounds_and_target_as_drawn(example, slew, load):
    page = load(slew / "view.html")
    summary = json.loads((slew / "summary.json").read_text())
    assert summary["optimal"]
    names, traj = rows(slew / "trajectory.csv")
    col = {c: k for k, c in enumerate(names)}
    n = page.js("return window.poinsotView.track.n")
    assert n == len(traj)  # every row is a frame
    idx = sorted(set(np.linspace(0, n - 1, 40).astype(int).tolist()))
    drawn = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.optimal()); });
        return out;""", idx)
    for i, d in zip(idx, drawn):
        i = np.flatnonzero(traj[:, 0] == traj[i, 0])[-1]  # a switch has two rows at one time: the page shows the second
        R = rotation(traj[i, [col[c] for c in ("qw", "qx", "qy", "qz")]])
        u = traj[i, [col["ux"], col["uy"], col["uz"]]]
        assert np.linalg.norm(np.array(d["torque"]) - R @ u) <= 1e-12 * np.sqrt(3), (i, d["torque"], R @ u)
    assert drawn[0]["bounds"] == pytest.approx([1.0, 1.0, 1.0], rel=1e-15)  # torque_max of the file
    assert drawn[0]["boundsFollowBody"]
    target = np.array(drawn[0]["target"])
    assert abs(target @ [0.0, 1.0, 0.0, 0.0]) == pytest.approx(1.0, abs=1e-15)  # the file's final quaternion
    # The body drawn at the end is at the target: the manoeuvre ends where the ghost stands.
    page.js("window.poinsotView.moveTo(window.poinsotView.player.t1);")
    q_end = np.array(page.js("return window.poinsotView.bodyQuaternion()"))
    assert 2 * np.arccos(min(1.0, abs(q_end @ target))) <= 1e-6
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]


@pytest.mark.parametrize("example", ["optimal/sphere_slew.toml"])
def test_chart_of_control_and_switching_functions(example, slew, load):
    page = load(slew / "view.html")
    summary = json.loads((slew / "summary.json").read_text())
    switches = summary["indirect"]["switches"]
    assert len(switches) == 5  # Bilimoria & Wie's five switches
    chart = "var c = window.poinsotView.chart(); return {key: c.key, marks: c.marks, series: c.series.map(" \
            "function (s) { return {t: s.t, values: s.values}; })};"
    control = page.js(chart)
    assert control["key"] == "control"
    assert control["marks"] == [s["t"] for s in switches]
    _, ctrl = rows(slew / "control.csv")
    for k, s in enumerate(control["series"]):
        assert s["t"] == ctrl[:, 0].tolist() and s["values"] == ctrl[:, 1 + k].tolist()

    chart_pixels = "var c = document.getElementById('chart'); return c.toDataURL();"
    before = page.js(chart_pixels)
    page.js("var s = document.getElementById('chart-view'); s.value = 'sigma'; s.dispatchEvent(new Event('change'));")
    assert page.js(chart_pixels) != before  # the chart redrew
    sigma = page.js(chart)
    assert sigma["key"] == "sigma" and sigma["marks"] == control["marks"]
    t = np.array(sigma["series"][0]["t"])
    for s in switches:
        values = np.array(sigma["series"][s["axis"] - 1]["values"])
        before = np.searchsorted(t, s["t"] - 1e-9, "left") - 1  # the samples either side of the switch (some
        after = np.searchsorted(t, s["t"] + 1e-9, "right")      # grids have a sample at it, where sigma is 0)
        assert values[before] * values[after] < 0, s  # sigma_axis changes sign at the switch
    umax = 1.0
    for axis in range(3):  # u_i = -u_max sign(sigma_i), away from the switches
        sig = np.array(sigma["series"][axis]["values"])
        u = np.interp(t, ctrl[:, 0], ctrl[:, 1 + axis])
        away = np.abs(sig) > 1e-6 * np.abs(sig).max()
        assert np.all(np.abs(u[away] + umax * np.sign(sig[away])) <= 1e-9), axis


@pytest.fixture(scope="module")
def sun_run(cli, tmp_path_factory):
    """examples/optimal/sun_avoidance_slew.toml (a keep-out cone, exit 3: converged direct; 2 s) and its page."""
    out = tmp_path_factory.mktemp("optimal") / "sun"
    example = Path(__file__).resolve().parents[2] / "examples" / "optimal" / "sun_avoidance_slew.toml"
    r = cli("optimize", example, "--out", out, "--quiet")
    assert r.returncode == 3, r.stdout + r.stderr
    assert cli("view", out).returncode == 0
    return out


def test_cones_boresights_and_their_chart_as_drawn(sun_run, load):
    """The boresight arrow at each frame is R(q) b of trajectory.csv's row, its angle to the Sun is the row's
    angle_keep_out_1 column, never inside the cone; the chart's pointing view is that column in degrees
    beside the half-angle."""
    page = load(sun_run / "view.html")
    summary = json.loads((sun_run / "summary.json").read_text())
    [sun] = summary["pointing"]
    names, traj = rows(sun_run / "trajectory.csv")
    col = {c: k for k, c in enumerate(names)}
    n = page.js("return window.poinsotView.track.n")
    idx = sorted(set(np.linspace(0, n - 1, 30).astype(int).tolist()))
    drawn = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.optimal().boresights[0]); });
        return out;""", idx)
    for i, d in zip(idx, drawn):
        R = rotation(traj[i, [col[c] for c in ("qw", "qx", "qy", "qz")]])
        assert np.linalg.norm(np.array(d["direction"]) - R @ sun["boresight_body"]) <= 1e-6
        assert d["angle"] == pytest.approx(traj[i, col["angle_keep_out_1"]], abs=1e-6)
        assert d["angle"] >= sun["half_angle"] - 1e-6
    page.js("var s = document.getElementById('chart-view'); s.value = 'pointing'; "
            "s.dispatchEvent(new Event('change'));")
    chart = page.js("var c = window.poinsotView.chart(); return {key: c.key, series: c.series.map("
                    "function (s) { return {label: s.label, values: s.values}; })};")
    assert chart["key"] == "pointing"
    angle, limit = chart["series"]
    assert angle["label"] == "keep-out sun" and limit["label"] == "keep-out sun limit"
    assert np.allclose(angle["values"], np.degrees(traj[:, col["angle_keep_out_1"]]), atol=1e-9)
    assert np.allclose(limit["values"], 50.0, atol=1e-12)
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]


# Three reaction wheels on skewed axes (the rows of axes) turn a spacecraft 40° at minimum energy in 30 s.
WHEELS = """
[body]
principal_moments = [3.0, 4.0, 2.0]
[optimal_control]
objective = "minimum_energy"
torque_max = [0.1, 0.1, 0.1]
final_time = 30.0
[optimal_control.reaction_wheels]
axes = [[1.0, 0.2, 0.0], [0.0, 1.0, 0.3], [0.2, 0.0, 1.0]]
spin_inertia = [0.02, 0.02, 0.02]
[optimal_control.final]
orientation = { axis_angle = { axis = [1.0, 1.0, 1.0], angle = 40.0 }, degrees = true }
"""


@pytest.fixture(scope="module")
def wheel_run(cli, tmp_path_factory):
    """A reaction-wheel slew (exit 3: converged direct; about a second) and its page."""
    folder = tmp_path_factory.mktemp("optimal")
    scenario = folder / "wheels.toml"
    scenario.write_text(WHEELS)
    out = folder / "wheels"
    r = cli("optimize", scenario, "--out", out, "--quiet")
    assert r.returncode == 3, r.stdout + r.stderr
    assert cli("view", out).returncode == 0
    return out


def test_wheel_torques_as_drawn(wheel_run, load):
    """With reaction wheels the arrow is the wheels' torque vector A u in the body frame (drawn in space, R A u),
    and the chart's control view holds the wheel torques u_k of control.csv, labelled as such."""
    page = load(wheel_run / "view.html")
    summary = json.loads((wheel_run / "summary.json").read_text())
    A = np.array(summary["reaction_wheels"]["axes_body"]).T  # columns: the unit spin axes
    names, traj = rows(wheel_run / "trajectory.csv")
    col = {c: k for k, c in enumerate(names)}
    n = page.js("return window.poinsotView.track.n")
    idx = sorted(set(np.linspace(0, n - 1, 20).astype(int).tolist()))
    drawn = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.optimal()); });
        return out;""", idx)
    for i, d in zip(idx, drawn):
        R = rotation(traj[i, [col[c] for c in ("qw", "qx", "qy", "qz")]])
        u = traj[i, [col["u1"], col["u2"], col["u3"]]]
        assert np.linalg.norm(np.array(d["torque"]) - R @ A @ u) <= 1e-12, (i, d["torque"], R @ A @ u)
    chart = page.js("var c = window.poinsotView.chart(); return {key: c.key, yLabel: c.yLabel, "
                    "label: document.getElementById('chart-view').selectedOptions[0].textContent, "
                    "series: c.series.map(function (s) { return s.values; }), "
                    "names: c.series.map(function (s) { return s.label; })};")
    assert chart["key"] == "control" and chart["label"] == "wheel torques u\u2096", chart["label"]
    assert chart["yLabel"] == "u wheel (N\u00b7m)" and chart["names"] == ["u1", "u2", "u3"]
    _, control = rows(wheel_run / "control.csv")
    assert np.allclose(chart["series"][0], control[:, 1], atol=1e-15)
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]
