"""The multipliers of multibody files as the page draws them: the joint reactions (arrows at the joints) and
each body's principal constraint stresses (the eigen-decomposition of -R Lambda R^T), read back from the drawn
three.js arrows.

Oracles. (1) At the last frame, the run's own reactions.csv and multipliers.csv (written by `poinsot run` at
the final state): the page recomputes them from trajectory.csv's last row and keeps 9 significant digits
(view_multipliers.hpp), so they agree to 1e-8 of the largest value (the 9 digits, 5e-10 relative, and the
quaternion's round trip through the CSV, 1e-16, amplified by the constraint solve). (2) Between, Newton's law
for every body, independent of the multipliers' code: m (a - g) = the sum of the joint forces on it (+F on
body a, -F on body b), a from trajectory.csv's velocities by the five-point central difference over the rows
next to the frame (error h^4/30 |v^(5)| plus the integrator's O(dt^2): 1e-3 of the forces' scale is far above
both and far below the force of a wrong sign, joint or body)."""
import csv

import numpy as np
import pytest

from conftest import SOURCE_DIR

EXAMPLES = ["multibody/double_pendulum.toml", "multibody/l_bracket_hinge.toml", "multibody/chain16.toml",
            "multibody/gyroscope_gimbals.toml"]
SEEN = {"multibody/double_pendulum.toml", "multibody/chain16.toml"}  # joints outside the bodies, in view
# Runs with gravity as their only load, sampled at every step (the examples' rows are too far apart for the
# whip of the chain): 3 s of the 16-link chain at 1 ms, drawn in 60 frames; and the hinged bracket as it is.
DENSE = {"chain16, every step": ("multibody/chain16.toml", "--t-end", "3", "--sample-dt", "0.001", "--frames", "60")}


@pytest.fixture(scope="module")
def newton_runs(cli, example_runs, tmp_path_factory):
    runs = {"multibody/l_bracket_hinge.toml": example_runs["multibody/l_bracket_hinge.toml"]}
    for name, (example, *args) in DENSE.items():
        out = tmp_path_factory.mktemp("dense") / "run"
        r = cli("run", SOURCE_DIR / "examples" / example, "--out", out, "--html", "--quiet", *args)
        assert r.returncode == 0, r.stderr
        runs[name] = out
    return runs


def table(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def rotation(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def drawn_stress(body):
    """The space-frame tensor sum_k value_k d_k d_k^T of a body's drawn principal arrows."""
    return sum(p["value"] * np.outer(p["direction"], p["direction"]) for p in body)


@pytest.mark.parametrize("example", EXAMPLES)
def test_reactions_and_stresses_at_the_last_frame_are_the_runs(example, example_runs, load):
    run = example_runs[example]
    page = load(run / "view.html")
    data = page.js("var d = window.poinsotView.data; return {joints: d.joints.map(function (j) {"
                   " return {name: j.name, body_a: j.body_a, point_a: j.point_a}; }),"
                   " bodies: d.bodies.map(function (b) { return b.name; })};")
    # Off by default; switched on, they add to the picture (at the frame of the largest joint force).
    page.js("""var v = window.poinsotView, best = 0, at = 0;
        for (var i = 0; i < v.track.n; i++) v.data.joints.forEach(function (j) {
          var f = Math.hypot(j.reaction[6 * i], j.reaction[6 * i + 1], j.reaction[6 * i + 2]);
          if (f > best) { best = f; at = i; } });
        v.player.frame(at);""")
    page.changed_since()
    for overlay in ("reactions", "stress"):
        assert not page.js("return document.getElementById('overlay-' + arguments[0]).checked", overlay)
        page.js("document.getElementById('overlay-' + arguments[0]).click();", overlay)
    if example in SEEN:  # elsewhere the joints sit inside the solid bodies
        assert page.changed_since() > 0.0005, "the reaction and stress arrows draw nothing"
    page.js("window.poinsotView.moveTo(window.poinsotView.player.t1);")
    drawn = page.js("return window.poinsotView.multipliers();")

    rows = table(run / "trajectory.csv")
    last = rows[-1]
    reactions = table(run / "reactions.csv")
    assert [r["joint"] for r in reactions] == [j["name"] for j in data["joints"]]
    assert float(reactions[0]["t"]) == float(last["t"])
    fmax = max(float(r["F_norm"]) for r in reactions)
    cmax = max(float(r["C_norm"]) for r in reactions)
    for r, j, d in zip(reactions, data["joints"], drawn["joints"]):
        name = data["bodies"][j["body_a"]]
        x = np.array([float(last[f"{name}.{c}"]) for c in "xyz"])
        R = rotation([float(last[f"{name}.q{c}"]) for c in "wxyz"])
        assert np.linalg.norm(np.array(d["origin"]) - (x + R @ j["point_a"])) <= 1e-12 * (1 + np.linalg.norm(x))
        F = np.array([float(r[c]) for c in ("Fx", "Fy", "Fz")])
        C = np.array([float(r[c]) for c in ("Cx", "Cy", "Cz")])
        assert np.linalg.norm(np.array(d["force"]) - F) <= 1e-8 * fmax, (j["name"], d["force"], F)
        assert np.linalg.norm(np.array(d["couple"]) - C) <= 1e-8 * max(cmax, fmax * 1e-3), (j["name"], d["couple"], C)

    stresses = table(run / "multipliers.csv")
    assert [s["body"] for s in stresses] == data["bodies"]
    lam_max = 0
    expected = []
    for s in stresses:
        L = np.array([[float(s[f"Lambda_{a}{b}"]) for b in "xyz"] for a in "xyz"])
        R = rotation([float(last[f"{s['body']}.q{c}"]) for c in "wxyz"])
        expected.append(-R @ (0.5 * (L + L.T)) @ R.T)  # the stress integral, space frame (N m)
        lam_max = max(lam_max, np.linalg.norm(L))
    for name, e, body in zip(data["bodies"], expected, drawn["bodies"]):
        assert np.linalg.norm(drawn_stress(body) - e) <= 1e-8 * lam_max, (name, drawn_stress(body), e)


@pytest.mark.parametrize("example", ["multibody/l_bracket_hinge.toml", *DENSE])
def test_reactions_between_satisfy_newtons_law(example, newton_runs, load):
    run = newton_runs[example]
    page = load(run / "view.html")
    stride = page.js("return window.poinsotView.data.stride")
    n = page.js("return window.poinsotView.track.n")
    frames = np.linspace(2, n - 3, 12).astype(int).tolist()
    info = page.js("var d = window.poinsotView.data; return {g: d.gravity, mass: d.bodies.map(function (b) {"
                   " return b.mass; }), names: d.bodies.map(function (b) { return b.name; }), joints:"
                   " d.joints.map(function (j) { return [j.body_a, j.body_b]; })};")
    drawn = page.js("""var v = window.poinsotView, out = [];
        arguments[0].forEach(function (i) { v.moveTo(v.data.t[i]); out.push(v.multipliers().joints); });
        return out;""", frames)
    rows = table(run / "trajectory.csv")
    g = np.array(info["g"])
    scale = max(m for m in info["mass"]) * np.linalg.norm(g)
    worst = 0
    for i, joints in zip(frames, drawn):
        r = i * stride
        h = (float(rows[r + 2]["t"]) - float(rows[r - 2]["t"])) / 4
        for k, (name, m) in enumerate(zip(info["names"], info["mass"])):
            v = [np.array([float(rows[r + s][f"{name}.v{c}"]) for c in "xyz"]) for s in (-2, -1, 1, 2)]
            a = (v[0] - 8 * v[1] + 8 * v[2] - v[3]) / (12 * h)
            F = sum(np.array(j["force"]) * (1 if ab[0] == k else -1) for j, ab in zip(joints, info["joints"])
                    if k in ab)
            worst = max(worst, np.linalg.norm(m * (a - g) - F))
            scale = max(scale, np.linalg.norm(F))
    assert worst <= 1e-3 * scale, (worst, scale)
