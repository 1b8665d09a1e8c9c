"""`poinsot inertia check`: the report, --json, --repair/--from-geometry --out, and one-line refusals that
write nothing."""
import json

import pytest

MODELS = "tests/data/models"


def test_valid_model_reports_no_finding(cli, source_dir):
    r = cli("inertia", "check", source_dir / MODELS / "valid_arm.urdf")
    assert r.returncode == 0, r.stderr
    assert "5 links, 0 invalid, 0 warnings" in r.stdout
    assert r.stderr == ""


def test_json_names_each_defect(cli, source_dir):
    r = cli("inertia", "check", source_dir / MODELS / "defects.urdf", "--json")
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout)
    links = {l["name"]: l for l in report["links"]}
    assert report["invalid"] == 3
    assert links["triangle"]["condition"] == "triangle inequality"
    assert links["triangle"]["amount"] == 50
    assert links["negative_moment"]["condition"] == "negative moment"
    assert any("implied density" in w for w in links["too_dense"]["warnings"])
    assert any("bounding box" in w for w in links["com_outside"]["warnings"])


@pytest.mark.parametrize("name", ["valid_arm.urdf", "valid_arm.xml", "valid_robot.sdf"])
def test_repair_leaves_a_valid_model_byte_for_byte(cli, source_dir, tmp_path, name):
    out = tmp_path / name
    r = cli("inertia", "check", source_dir / MODELS / name, "--repair", "--out", out)
    assert r.returncode == 0, r.stderr
    assert "nothing to repair" in r.stdout
    assert out.read_bytes() == (source_dir / MODELS / name).read_bytes()


@pytest.mark.parametrize("name", ["defects.urdf", "defects.xml", "defects.sdf"])
def test_repaired_copy_checks_valid(cli, source_dir, tmp_path, name):
    out = tmp_path / name
    r = cli("inertia", "check", source_dir / MODELS / name, "--repair", "--out", out, "--json")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout)
    assert result["check"]["invalid"] == len(result["repair"]["edits"]) > 0
    assert all(e["distance"] > 0 for e in result["repair"]["edits"])
    again = json.loads(cli("inertia", "check", out, "--json").stdout)
    assert again["invalid"] == 0


def test_from_geometry(cli, source_dir, tmp_path):
    out = tmp_path / "g.xml"
    r = cli("inertia", "check", source_dir / MODELS / "defects.xml", "--from-geometry", "--out", out)
    assert r.returncode == 0, r.stderr
    assert "repaired link full_bad" in r.stdout
    report = json.loads(cli("inertia", "check", out, "--json").stdout)
    ball = report["links"][1]
    # a 500 kg sphere of radius 0.2 m: 2/5 m r² = 8 kg·m²
    assert ball["principal_moments"] == pytest.approx([8, 8, 8], rel=1e-14)


@pytest.mark.parametrize("args, pieces", [
    (["--repair"], ["--repair needs --out"]),
    (["--out", "x.urdf"], ["--out needs --repair or --from-geometry"]),
    (["--repair", "--from-geometry", "--out", "x.urdf"], ["at most one"]),
    (["--max-file-bytes", "10", "--repair", "--out", "x.urdf"], ["the limit is 10 bytes", "--max-file-bytes"]),
    (["--density-range", "100", "10"], ["density range [100, 10]"]),
])
def test_refusals_are_one_line_and_write_nothing(cli, source_dir, tmp_path, args, pieces):
    r = cli("inertia", "check", source_dir / MODELS / "defects.urdf", *args, cwd=tmp_path)
    assert r.returncode == 2
    assert r.stdout == ""
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("poinsot: ")
    for p in pieces:
        assert p in r.stderr
    assert list(tmp_path.iterdir()) == []


def test_malformed_model_is_refused(cli, tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r"><link name="a"><inertial><mass value="x"/></inertial></link></robot>')
    r = cli("inertia", "check", bad, "--repair", "--out", tmp_path / "out.urdf")
    assert r.returncode == 2
    assert "bad.urdf:1: <mass> value=\"x\": expected 1 finite number" in r.stderr
    assert not (tmp_path / "out.urdf").exists()
