"""Poinsot's construction as the page draws it, read back from the page's own three.js objects at many frames
and checked against the theory computed here from summary.json alone; the frames against trajectory.csv.

Oracles. The inertia ellipsoid x^T J x = 2T (J about the rotation point, T the kinetic energy) touches the
invariable plane, normal to the fixed L at the distance 2T/|L| from the centre, at x = omega (body frame).
The herpolhode's distance rho from the plane's foot point obeys rho^2 = |omega|^2 - (2T/|L|)^2, and |omega|^2
moves between the ends of the segment {x_i = omega_i^2 >= 0 (principal frame): sum I_i x_i = 2T,
sum I_i^2 x_i = |L|^2}: the theory's annulus. The runs use the exact solution (Jacobi elliptic functions), so
energy and L hold to round-off (1e-13 relative), well inside the 1e-9 asked of the page's geometry; three.js
keeps transforms in doubles."""
import csv
import json
import math

import numpy as np
import pytest

TOL = 1e-9

# An asymmetric body given by a full inertia tensor (principal axes not the body axes), torque-free, exact.
SKEW_BODY = """title = "A body with products of inertia"
[body]
inertia = [[2.0, -0.3, 0.2], [-0.3, 3.0, 0.4], [0.2, 0.4, 4.0]]
[initial]
omega_body = [0.4, 1.5, -0.7]
[integrator]
method = "exact"
[output]
t_end = 12.0
sample_dt = 0.004
"""


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]])


@pytest.fixture(scope="module")
def runs(cli, example_runs, tmp_path_factory):
    root = tmp_path_factory.mktemp("construction")
    (root / "skew.toml").write_text(SKEW_BODY)
    r = cli("run", root / "skew.toml", "--out", root / "skew", "--html", "--quiet")
    assert r.returncode == 0, r.stderr
    tennis = example_runs["tennis_racket.toml"]
    assert json.loads((tennis / "summary.json").read_text())["method"] == "exact"
    return {"tennis_racket.toml": tennis, "skew": root / "skew"}


def theory(summary):
    J = np.array(summary["body"]["inertia"])
    w0 = np.array(summary["initial"]["omega_body"])
    two_T = w0 @ J @ w0
    L = np.array(summary["initial"]["L_space"])
    I = np.linalg.eigvalsh(J)
    d = two_T / np.linalg.norm(L)
    ends = []  # ends of the segment of (omega_i^2) allowed by energy and |L|
    for k in range(3):
        i, j = [m for m in range(3) if m != k]
        A = np.array([[I[i], I[j]], [I[i] ** 2, I[j] ** 2]])
        x = np.linalg.solve(A, [two_T, L @ L])
        if (x >= -1e-12 * np.abs(x).max()).all():
            ends.append(x.sum())
    rho2 = [e - d * d for e in ends]
    return {"two_T": two_T, "L": L, "d": d, "rho_min": math.sqrt(max(min(rho2), 0)), "rho_max": math.sqrt(max(rho2))}


@pytest.mark.parametrize("example", ["skew", "tennis_racket.toml"])
def test_construction_rolls_on_the_invariable_plane(example, runs, load):
    summary = json.loads((runs[example] / "summary.json").read_text())
    th = theory(summary)
    L_hat = th["L"] / np.linalg.norm(th["L"])
    page = load(runs[example] / "view.html")
    n = page.js("return window.poinsotView.track.n")
    frames = sorted(set(np.linspace(0, n - 1, 60).astype(int).tolist()))
    probes = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.probe()); });
        return out;""", frames)
    for i, p in zip(frames, probes):
        contact, tip = np.array(p["contact"]), np.array(p["omegaTip"])
        size = np.linalg.norm(contact)
        assert np.linalg.norm(contact - tip) <= TOL * size, f"frame {i}: contact {contact} != omega tip {tip}"
        normal = np.array(p["planeNormal"])
        assert np.linalg.norm(np.cross(normal, L_hat)) <= 1e-12 and normal @ L_hat > 0, f"frame {i}: {normal}"
        assert abs((contact - np.array(p["planePoint"])) @ normal) <= TOL * size, f"frame {i}: off the plane"
        M = np.array(p["ellipsoidMatrix"]).reshape(4, 4).T  # three.js stores column-major
        local = np.linalg.solve(M, np.append(contact, 1.0))[:3]
        assert abs(np.linalg.norm(local) - 1) <= TOL, f"frame {i}: off the ellipsoid by {np.linalg.norm(local) - 1}"
        assert np.array(p["planePoint"]) @ normal / p["scale"] == pytest.approx(th["d"], rel=1e-12)
        assert np.linalg.norm(np.cross(np.array(p["LArrow"]), L_hat)) <= TOL

    # The herpolhode of every frame stays in the theory's annulus, and reaches both of its edges.
    her = np.array(page.js("return window.poinsotView.construction.herpolhode")) / probes[0]["scale"]
    rho = np.linalg.norm(her - th["d"] * L_hat, axis=1)
    lo, hi = th["rho_min"], th["rho_max"]
    slack = TOL * math.hypot(th["d"], hi)
    assert rho.min() >= lo - slack and rho.max() <= hi + slack, (rho.min(), rho.max(), lo, hi)
    assert rho.max() >= hi - 0.01 * (hi - lo) and rho.min() <= lo + 0.01 * (hi - lo)


@pytest.mark.parametrize("example", ["tennis_racket.toml"])
def test_frames_equal_the_trajectory_and_slerp_between_them(example, runs, load):
    """At a frame's time the body is drawn with that row of trajectory.csv exactly; between frames (rows the
    decimation left out) the slerp stays within its error bound h^2/8 max|d omega/dt| (the angular velocity's
    change over the frame interval h)."""
    names, rows = read_csv(runs[example] / "trajectory.csv")
    col = {c: k for k, c in enumerate(names)}
    page = load(runs[example] / "view.html")
    data = page.js("var d = window.poinsotView.data; return [d.stride, d.samples, d.frames];")
    stride, samples, frames = data
    assert samples == len(rows) and stride > 1 and frames <= 2000
    q_cols = [col[c] for c in ("qw", "qx", "qy", "qz")]
    idx = list(range(0, frames, 7)) + [frames - 1]
    drawn = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push([v.player.time, v.bodyQuaternion()]); });
        return out;""", idx)
    for i, (t, q) in zip(idx, drawn):
        row = min(i * stride, len(rows) - 1)
        assert t == rows[row, col["t"]]
        assert q == rows[row, q_cols].tolist(), f"frame {i}: {q} != row {row}"

    h = rows[stride, col["t"]] - rows[0, col["t"]]
    w = rows[:, [col["wx"], col["wy"], col["wz"]]]
    wdot = np.linalg.norm(np.diff(w, axis=0), axis=1).max() / (rows[1, col["t"]] - rows[0, col["t"]])
    bound = h * h / 8 * wdot * 1.5  # 1.5: the finite difference underestimates the peak of |d omega/dt|
    between = list(range(1, len(rows) - 1, stride * 5))
    got = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (t) { v.moveTo(t); out.push(v.bodyQuaternion()); });
        return out;""", [rows[r, col["t"]] for r in between])
    worst = 0.0
    for r, q in zip(between, got):
        c = min(1.0, abs(np.dot(q, rows[r, q_cols])))
        worst = max(worst, 2 * math.acos(c))
    assert worst <= bound, (worst, bound)
    assert worst > 0  # the rows between frames are interpolated, not copied


@pytest.mark.parametrize("example", ["multibody/double_pendulum.toml", "multibody/l_bracket_hinge.toml",
                                     "multibody/gyroscope_gimbals.toml", "multibody/chain16.toml"])
def test_multibody_joints_hold_as_drawn(example, example_runs, load):
    """Each joint's point placed from body a (x_a + R_a A) and from body b (x_b + R_b B, or the world's point)
    as the page draws them: apart by no more than the largest joint gap the run measured (summary.json), plus
    round-off. A wrong quaternion convention or body order in the page would open the joints by centimetres."""
    summary = json.loads((example_runs[example] / "summary.json").read_text())
    page = load(example_runs[example] / "view.html")
    n = page.js("return window.poinsotView.track.n")
    frames = sorted(set(np.linspace(0, n - 1, 40).astype(int).tolist()))
    gaps = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.jointGap()); });
        return out;""", frames)
    assert page.js("return window.poinsotView.data.joints.length") > 0
    assert max(gaps) <= summary["joint_gap_max"] + 1e-12, (max(gaps), summary["joint_gap_max"])
