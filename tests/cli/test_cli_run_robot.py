"""`poinsot run` on robot files (URDF, MJCF, SDF) and on scenarios that name one: the run's files and report
(per link, with what is not modelled), and bad files refused with one line and exit status 2."""
import json
from pathlib import Path

import pytest

ROBOTS = Path(__file__).resolve().parents[2] / "tests" / "data" / "models" / "robots"


@pytest.mark.parametrize("name", ["pendulum2.urdf", "pendulum2.xml", "pendulum2.sdf", "joints.xml", "loop.xml"])
def test_a_robot_file_runs_with_the_defaults(cli, tmp_path, name):
    out = tmp_path / "run"
    r = cli("run", ROBOTS / name, "--t-end", "0.05", "--out", out, "--json")
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["kind"] == "multibody" and summary["status"] == "completed"
    assert summary["joint_gap_max"] < 1e-11
    assert summary["not_modelled"], "a robot file always states something the run leaves out (contacts, limits)"
    report = (out / "report.txt").read_text()
    assert "not modelled" in report
    reactions = (out / "reactions.csv").read_text()
    multipliers = (out / "multipliers.csv").read_text()
    if name.startswith("pendulum2"):
        # per link and per joint, by the file's names
        assert ",shoulder," in reactions and ",elbow," in reactions
        assert ",upper," in multipliers and ",lower," in multipliers


def test_a_scenario_names_the_file_and_sets_the_joints(cli, tmp_path):
    out = tmp_path / "run"
    r = cli("run", ROBOTS / "pendulum2_model.toml", "--out", out, "--json")
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["method"] == "rk4" and summary["dt"] == 5e-4 and summary["t_final"] == pytest.approx(0.5)
    assert summary["title"] == "double pendulum from its URDF"


def test_a_bad_file_is_one_line_naming_the_element_and_its_line(cli, tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n<link name="a"/>\n<link name="b"/>\n'
                   '<joint name="j" type="revolute"><parent link="ghost"/><child link="b"/></joint>\n</robot>\n')
    r = cli("run", bad, "--out", tmp_path / "run")
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1
    assert f"{bad}:4: <joint> name=\"j\": <parent link=\"ghost\">: no such link" in r.stderr


def test_a_bad_scenario_key_names_the_key(cli, tmp_path):
    s = tmp_path / "s.toml"
    s.write_text(f'[model]\nfile = "{ROBOTS / "pendulum2.urdf"}"\npositions = {{ knee = 1 }}\n')
    r = cli("run", s, "--out", tmp_path / "run")
    assert r.returncode == 2
    assert "s.toml:3:" in r.stderr and "positions.knee: no moving joint of that name" in r.stderr
