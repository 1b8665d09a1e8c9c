"""poinsot.inertia.check_model and repair_model: the same report as `poinsot inertia check --json`."""
import numpy as np
import pytest

import poinsot
from conftest import SOURCE_DIR

MODELS = SOURCE_DIR / "tests" / "data" / "models"


def test_check_model_reports_each_link():
    r = poinsot.inertia.check_model(str(MODELS / "valid_robot.sdf"))
    assert r["format"] == "sdf"
    assert [l["name"] for l in r["links"]] == ["body", "wheel"]
    # body: a 0.1 x 0.2 x 0.3 m box of 6 kg, written in a frame turned by 90° about z; in the link frame
    # J = m/12 (b² + c², a² + c², a² + b²).
    J = np.array(r["links"][0]["inertia_com"])
    assert J == pytest.approx(np.diag([0.065, 0.05, 0.025]), abs=1e-15)
    assert r["links"][0]["valid"] and r["links"][0]["warnings"] == []


def test_check_model_options_and_errors():
    r = poinsot.inertia.check_model(str(MODELS / "valid_arm.urdf"), density_min=3000.0, density_max=5000.0)
    assert r["warnings"] == 4  # every link's density (1000 to 2984 kg/m³) is now out of range
    with pytest.raises(ValueError, match="ratio limit"):
        poinsot.inertia.check_model(str(MODELS / "valid_arm.urdf"), ratio_limit=0.5)
    with pytest.raises(ValueError, match="cannot read"):
        poinsot.inertia.check_model(str(MODELS / "missing.urdf"))


def test_repair_model_writes_the_nearest_valid_tensors(tmp_path):
    out = tmp_path / "fixed.sdf"
    r = poinsot.inertia.repair_model(str(MODELS / "defects.sdf"), str(out))
    assert [e["link"] for e in r["edits"]] == ["slab"]
    again = poinsot.inertia.check_model(str(out))
    assert again["invalid"] == 0
    J = np.array(again["links"][0]["inertia_com"])
    assert J == pytest.approx(np.array(r["edits"][0]["inertia_after"]), abs=1e-14)
