"""`poinsot optimize` with reaction wheels ([optimal_control.reaction_wheels]): the example ends "converged
(direct; ...)" (exit 3) with the wheel torques within their bounds, the wheel momenta within theirs on the
DOP853 re-simulation and the total angular momentum conserved; the files name the wheel columns; bad wheels are
one line naming the key (exit 2)."""
import csv
import json
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
EXAMPLE = SOURCE / "examples" / "optimal" / "reaction_wheel_slew.toml"

# A spacecraft at rest or spinning about z ({omega}) slewed 30° about z at minimum energy in 20 s by three
# wheels on its body axes; the wheel table's keys are {wheels}.
SLEW = """
[body]
principal_moments = [3.0, 4.0, 2.0]
[optimal_control]
objective = "minimum_energy"
torque_max = [0.1, 0.1, 0.1]
final_time = 20.0
[optimal_control.reaction_wheels]
{wheels}
[optimal_control.initial]
omega_body = {omega}
[optimal_control.final]
orientation = {{ axis_angle = {{ axis = [0.0, 0.0, 1.0], angle = 30.0 }}, degrees = true }}
"""


def write(tmp_path, text):
    p = tmp_path / "s.toml"
    p.write_text(text)
    return p


def rows(path):
    with open(path, encoding="utf-8") as f:
        f.readline()
        return list(csv.DictReader(f))


@pytest.mark.slow_under_sanitizers
def test_example_is_converged_direct_within_the_wheels_bounds(cli, tmp_path):
    out = tmp_path / "out"
    r = cli("optimize", EXAMPLE, "--out", out, "--quiet")
    assert r.returncode == 3, r.stdout + r.stderr
    assert "status: converged (direct; minimum principle not verified: the actuators are reaction wheels" in r.stdout
    assert "wheels on the direct re-simulation" in r.stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["outcome"] == "converged_direct" and summary["optimal"] is False
    wheels = summary["reaction_wheels"]
    assert wheels["momentum_max"] == [0.15, 0.15, 0.15]
    replay = wheels["replay"]
    assert replay["bound_excess"] <= 1e-6       # the bounds hold between the collocation points
    assert max(replay["peak_momentum"]) > 0.15 * (1 - 1e-3)  # and are active
    assert replay["momentum_drift"] < 1e-10     # L = R (J_b ω + A h) conserved by the replay (DOP853, 1e-13)
    assert max(abs(h) for h in replay["final_momentum"]) < 1e-6  # at rest with L = 0: the wheels stop too
    assert abs(summary["direct"]["cost"] / 0.0050589720215 - 1) < 1e-6
    traj = rows(out / "trajectory.csv")
    assert list(traj[0])[:17] == ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz", "u1", "u2", "u3", "Lx", "Ly", "Lz",
                                  "h1", "h2", "h3"]
    for row in traj:
        assert all(abs(float(row[f"u{k}"])) <= 0.05 + 1e-8 for k in (1, 2, 3))
        assert all(abs(float(row[f"h{k}"])) <= 0.15 + 1e-8 for k in (1, 2, 3))
        assert all(abs(float(row[f"L{c}"])) < 1e-12 for c in "xyz")
    with open(out / "control.csv", encoding="utf-8") as f:
        f.readline()
        assert f.readline().strip() == "t,u1,u2,u3"


@pytest.mark.slow_under_sanitizers
def test_plot_draws_the_wheel_momenta(cli, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out"
    r = cli("optimize", write(tmp_path, SLEW.format(wheels="spin_inertia = [0.01, 0.01, 0.01]\nmomentum_max = 0.5",
                                                    omega="[0.0, 0.0, 0.0]")), "--out", out, "--quiet", "--plot")
    assert r.returncode == 3, r.stdout + r.stderr
    assert (out / "wheels.png").stat().st_size > 10000 and (out / "torque.png").exists()


@pytest.mark.parametrize("wheels, omega, key", [
    ("spin_inertia = [0.01, 0.01, 0.01]\naxes = [[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]", "[0.0, 0.0, 0.0]",
     "[optimal_control.reaction_wheels] axes"),
    ("spin_inertia = [0.01, 0.01, 0.01]\naxes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]", "[0.0, 0.0, 0.0]",
     "optimal_control.reaction_wheels.axes: det A"),
    ("spin_inertia = [0.01, 0.01, 0.01]\nmomentum_max = 0.5", "[0.0, 0.0, 0.5]",  # 1 N·m·s must end in wheel 3
     "optimal_control.reaction_wheels.momentum_max"),
    ("spin_inertia = [0.01, 0.01, 2.5]", "[0.0, 0.0, 0.0]", "optimal_control.reaction_wheels.spin_inertia"),
    ("momentum_max = 0.5", "[0.0, 0.0, 0.0]", "spin_inertia"),
    ("spin_inertia = [0.01, 0.01, 0.01]\nspeed_max = 3.0", "[0.0, 0.0, 0.0]", "speed_max"),
])
def test_bad_wheels_are_one_line_naming_the_key(cli, tmp_path, wheels, omega, key):
    out = tmp_path / "out"
    r = cli("optimize", write(tmp_path, SLEW.format(wheels=wheels, omega=omega)), "--out", out)
    assert r.returncode == 2, r.stdout
    assert r.stderr.count("\n") == 1 and key in r.stderr, r.stderr
    assert not out.exists()
