"""poinsot ensemble: files, determinism across threads, --sample against the single-body run, bad input."""
import csv
import json

SCENARIO = """
[body]
principal_moments = [1.0, 2.0, 2.6]
[initial]
omega_body = [0.05, 2.0, 0.05]
orientation = {{ quaternion = [1.0, 0.0, 0.0, 0.0] }}
[torque]
{torque}
[integrator]
method = "{method}"
dt = 0.01
[output]
t_end = 3.0
sample_dt = 0.1
[ensemble]
samples = 64
seed = 5
moments = {{ law = "normal", width = {width}, relative = true }}
axes = {{ law = "cone", angle = 1.0, degrees = true }}
"""


NO_TORQUE = 'type = "none"'


def write(tmp_path, method="rk4", width="0.02", torque=NO_TORQUE):
    path = tmp_path / "ens.toml"
    path.write_text(SCENARIO.format(method=method, width=width, torque=torque))
    return path


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def test_writes_csv_and_summary_identically_for_one_and_two_threads(cli, tmp_path):
    scenario = write(tmp_path)
    a = cli("ensemble", scenario, "--threads", "1", "--out", tmp_path / "a")
    b = cli("ensemble", scenario, "--threads", "2", "--no-simd", "--quiet", "--out", tmp_path / "b")
    assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
    assert b.stderr == ""  # --quiet (as on `run`): no progress line; through a pipe there is none anyway
    assert (tmp_path / "a/samples.csv").read_text() == (tmp_path / "b/samples.csv").read_text()
    sa = json.loads((tmp_path / "a/summary.json").read_text())
    sb = json.loads((tmp_path / "b/summary.json").read_text())
    assert sa["outputs"] == sb["outputs"]
    assert sa["completed"] == 64 and len(rows(tmp_path / "a/samples.csv")) == 64
    flip = sa["outputs"]["attitude_error"]
    assert set(flip["percentiles"]) == {"P1", "P5", "P50", "P95", "P99", "P99.9"}
    assert flip["min"] <= flip["percentiles"]["P50"] <= flip["max"]


def test_a_torque_in_space_runs_batched_identically_for_threads_and_simd(cli, tmp_path):
    for method in ("rk4", "dlm"):
        scenario = write(tmp_path, method=method, torque='type = "space"\nvalue = [0.01, -0.02, 0.005]')
        a = cli("ensemble", scenario, "--threads", "1", "--json", "--out", tmp_path / f"{method}_a")
        b = cli("ensemble", scenario, "--threads", "2", "--no-simd", "--json",
                "--out", tmp_path / f"{method}_b")
        assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
        sa, sb = json.loads(a.stdout), json.loads(b.stdout)
        assert sa["path"].startswith(f"batched {method}"), sa["path"]
        assert sa["outputs"] == sb["outputs"]
        csv_a, csv_b = (tmp_path / f"{method}_{run}/samples.csv" for run in "ab")
        assert csv_a.read_text() == csv_b.read_text()


def test_exact_sample_equals_the_single_body_run_bit_for_bit(cli, tmp_path):
    scenario = write(tmp_path, method="exact")
    r = cli("ensemble", scenario, "--out", tmp_path / "e")
    assert r.returncode == 0, r.stderr
    row = rows(tmp_path / "e/samples.csv")[12]
    s = cli("ensemble", scenario, "--sample", "12", "--out", tmp_path / "e")
    assert s.returncode == 0, s.stderr
    final = json.loads((tmp_path / "e/sample_12/summary.json").read_text())["final"]
    # Shortest round-trip decimal forms on both sides: equal text means equal bits.
    assert [float(row[k]) for k in ("omega_x", "omega_y", "omega_z")] == final["omega_body"]
    q = [float(row[k]) for k in ("q_w", "q_x", "q_y", "q_z")]
    assert q == final["quaternion"]


def test_bad_input_is_one_line_exit_2_and_writes_nothing(cli, tmp_path):
    for width in ("-0.1",):
        scenario = write(tmp_path, width=width)
        r = cli("ensemble", scenario, "--out", tmp_path / "bad")
        assert r.returncode == 2
        assert r.stderr.count("\n") == 1 and "width" in r.stderr and "-0.1" in r.stderr
        assert not (tmp_path / "bad").exists()
    scenario = write(tmp_path)
    r = cli("ensemble", scenario, "--samples", "100000000000", "--out", tmp_path / "big")
    assert r.returncode == 2 and "GB" in r.stderr and r.stderr.count("\n") == 1
    assert not (tmp_path / "big/samples.csv").exists()
    text = SCENARIO.format(method="rk4", width="0.0", torque=NO_TORQUE).replace("[1.0, 2.0, 2.6]", "[1.0, 1.0, 5.0]")
    (tmp_path / "tri.toml").write_text(text)
    r = cli("ensemble", tmp_path / "tri.toml", "--out", tmp_path / "tri")
    assert r.returncode == 2 and "triangle" in r.stderr and not (tmp_path / "tri").exists()
    # A reject policy that cannot find valid moments: capped, reported with the sample, nothing written.
    text = SCENARIO.format(method="rk4", width="3.0", torque=NO_TORQUE).replace("[1.0, 2.0, 2.6]", "[1.0, 1.0, 1.999]")
    (tmp_path / "cap.toml").write_text(text.replace("seed = 5", "seed = 5\nmax_tries = 2"))
    r = cli("ensemble", tmp_path / "cap.toml", "--out", tmp_path / "cap")
    assert r.returncode == 2 and "after 2 draws" in r.stderr and r.stderr.count("\n") == 1
    assert not (tmp_path / "cap").exists()


def test_hdf5_table_equals_the_csv(cli, tmp_path):
    h5py = __import__("pytest").importorskip("h5py")
    scenario = write(tmp_path)
    r = cli("ensemble", scenario, "--out", tmp_path / "h")
    assert r.returncode == 0, r.stderr
    if not (tmp_path / "h/samples.h5").exists():
        __import__("pytest").skip("poinsot was built without HDF5")
    table = rows(tmp_path / "h/samples.csv")
    with h5py.File(tmp_path / "h/samples.h5") as f:
        s = f["samples"]
        assert s["moments"].shape == (64, 3) and s["quaternion_final"].shape == (64, 4)
        assert list(s["index"][:]) == [int(t["index"]) for t in table]
        for name in ("attitude_error", "energy_error", "first_flip_time"):
            a = [float(t[name]) for t in table]
            b = list(s[name][:])
            assert all((x == y) or (x != x and y != y) for x, y in zip(a, b)), name


def test_ctrl_c_keeps_complete_rows(cli, tmp_path):
    import os
    import signal
    import subprocess
    import time

    scenario = write(tmp_path)
    proc = subprocess.Popen([os.environ["POINSOT_CLI"], "ensemble", str(scenario), "--samples", "3000000",
                             "--threads", "1", "--out", str(tmp_path / "c")],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # The handler is installed right after the output folder is made: wait for the folder (a loaded machine or
    # the sanitizer build can take seconds to get there), then let some samples run.
    deadline = time.monotonic() + 60
    while not (tmp_path / "c").exists() and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "interrupted" in err
    summary = json.loads((tmp_path / "c/summary.json").read_text())
    assert summary["interrupted"] and 0 < summary["completed"] < 3000000
    table = rows(tmp_path / "c/samples.csv")
    assert len(table) == summary["completed"] and int(table[-1]["index"]) == summary["completed"] - 1
    assert all(t["omega_z"] not in (None, "") for t in table)


def test_the_examples_run(cli, source_dir, tmp_path):
    for path in sorted((source_dir / "examples" / "ensemble").glob("*.toml")):
        r = cli("ensemble", path, "--samples", "40", "--threads", "2", "--json", "--out", tmp_path / path.stem)
        assert r.returncode == 0, f"{path.name}: {r.stderr}"
        summary = json.loads(r.stdout)
        assert summary["completed"] == 40
        assert summary["outputs"]["attitude_error"]["count"] == 40, path.name
