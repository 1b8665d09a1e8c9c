"""poinsot ensemble under mpirun: two ranks give the files of one process, bit for bit (skipped unless the
tool was built with MPI: POINSOT_MPIEXEC is set by tests/integration/ensemble_mpi.cmake)."""
import json
import os
import subprocess

import pytest

MPIEXEC = os.environ.get("POINSOT_MPIEXEC")

SCENARIO = """
[body]
principal_moments = [5621.0, 4547.0, 2364.0]
[initial]
omega_body = [0.0, 0.0, 0.01]
orientation = { quaternion = [1.0, 0.0, 0.0, 0.0] }
[torque]
type = "body"
value = [0.001, -0.002, 0.0005]
[integrator]
method = "dlm"
dt = 1.0
[output]
t_end = 50.0
[ensemble]
samples = 2500
seed = 7
moments = { law = "normal", width = 0.05, relative = true }
torque = { law = "normal", width = 0.1, relative = true }
"""


@pytest.mark.skipif(not MPIEXEC, reason="poinsot was built without MPI")
def test_two_ranks_equal_one_process(cli, tmp_path):
    path = tmp_path / "ens.toml"
    path.write_text(SCENARIO)
    one = cli("ensemble", path, "--threads", "1", "--out", tmp_path / "one")
    assert one.returncode == 0, one.stderr
    two = subprocess.run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", "2", os.environ["POINSOT_CLI"],
                          "ensemble", str(path), "--threads", "1", "--out", str(tmp_path / "two")],
                         capture_output=True, text=True, timeout=120)
    assert two.returncode == 0, two.stderr
    assert "2 MPI ranks" in two.stdout
    assert (tmp_path / "one/samples.csv").read_bytes() == (tmp_path / "two/samples.csv").read_bytes()
    a = json.loads((tmp_path / "one/summary.json").read_text())
    b = json.loads((tmp_path / "two/summary.json").read_text())
    assert a["outputs"] == b["outputs"]
    assert a["completed"] == b["completed"] == 2500


@pytest.mark.skipif(not MPIEXEC, reason="poinsot was built without MPI")
def test_two_ranks_without_rows_give_the_percentiles_of_one_process(cli, tmp_path):
    # Per-sample output off: the percentiles come from the quantile sketches, whose integer counts are
    # gathered from the ranks: the same numbers as one process, bit for bit.
    path = tmp_path / "ens.toml"
    path.write_text(SCENARIO)
    one = cli("ensemble", path, "--threads", "1", "--no-per-sample", "--out", tmp_path / "one")
    assert one.returncode == 0, one.stderr
    two = subprocess.run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", "2", os.environ["POINSOT_CLI"],
                          "ensemble", str(path), "--threads", "1", "--no-per-sample", "--out",
                          str(tmp_path / "two")], capture_output=True, text=True, timeout=120)
    assert two.returncode == 0, two.stderr
    a = json.loads((tmp_path / "one/summary.json").read_text())
    b = json.loads((tmp_path / "two/summary.json").read_text())
    assert "sketch" in a["percentile_method"]
    assert set(a["outputs"]["attitude_error"]["percentiles"]) == {"P1", "P5", "P50", "P95", "P99", "P99.9"}
    # The fixed-edge histograms too: rank 1 runs the pilot (block 0) itself to find the same edges.
    hist = a["outputs"]["attitude_error"]["histogram"]
    assert sum(hist["counts"]) + hist["underflow"] + hist["overflow"] == 2500
    assert a["outputs"] == b["outputs"]
    assert not (tmp_path / "two/samples.csv").exists()


@pytest.mark.skipif(not MPIEXEC, reason="poinsot was built without MPI")
def test_per_rank_files_hold_the_rows_of_one_process_in_rank_order(cli, tmp_path):
    path = tmp_path / "ens.toml"
    path.write_text(SCENARIO)
    one = cli("ensemble", path, "--threads", "1", "--out", tmp_path / "one")
    assert one.returncode == 0, one.stderr
    two = subprocess.run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", "2", os.environ["POINSOT_CLI"],
                          "ensemble", str(path), "--threads", "1", "--per-rank-files", "--out",
                          str(tmp_path / "two")], capture_output=True, text=True, timeout=120)
    assert two.returncode == 0, two.stderr
    assert not (tmp_path / "two/samples.csv").exists()
    rank0 = (tmp_path / "two/samples.rank_0.csv").read_text().splitlines(keepends=True)
    rank1 = (tmp_path / "two/samples.rank_1.csv").read_text().splitlines(keepends=True)
    assert rank0[0] == rank1[0]  # the same header
    assert len(rank0) > 1 and len(rank1) > 1  # both ranks wrote rows
    assert "".join(rank0 + rank1[1:]) == (tmp_path / "one/samples.csv").read_text()
    a = json.loads((tmp_path / "one/summary.json").read_text())
    b = json.loads((tmp_path / "two/summary.json").read_text())
    assert "sketch" in b["percentile_method"]
    for name, out in a["outputs"].items():  # the mergeable statistics are those of one process
        for key in ("count", "nan_count", "mean", "std", "min", "max"):
            assert out[key] == b["outputs"][name][key], (name, key)
        if "percentiles" in out:  # exact from the rows against the sketch's bound (alpha = 1e-3)
            for p, exact in out["percentiles"].items():
                assert abs(b["outputs"][name]["percentiles"][p] - exact) <= 1e-3 * max(
                    abs(out["min"]), abs(out["max"])) * (1 + 1e-9), (name, p)


@pytest.mark.slow_under_sanitizers  # 6 300 closed-loop slews: seconds in release, a minute under the sanitizers
@pytest.mark.skipif(not MPIEXEC, reason="poinsot was built without MPI")
def test_two_ranks_equal_one_process_for_a_slew(cli, tmp_path, source_dir):
    """[ensemble.slew] (the sphere slew example, 2 100 samples: three blocks over two ranks)."""
    example = source_dir / "examples/ensemble/sphere_slew_robustness.toml"
    one = cli("ensemble", example, "--samples", "2100", "--threads", "1", "--out", tmp_path / "one")
    assert one.returncode == 0, one.stderr
    two = subprocess.run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", "2", os.environ["POINSOT_CLI"],
                          "ensemble", str(example), "--samples", "2100", "--threads", "1", "--out",
                          str(tmp_path / "two")], capture_output=True, text=True, timeout=120)
    assert two.returncode == 0, two.stderr
    assert (tmp_path / "one/samples.csv").read_bytes() == (tmp_path / "two/samples.csv").read_bytes()
    a = json.loads((tmp_path / "one/summary.json").read_text())
    b = json.loads((tmp_path / "two/summary.json").read_text())
    assert a["outputs"] == b["outputs"] and a["slew"] == b["slew"]
