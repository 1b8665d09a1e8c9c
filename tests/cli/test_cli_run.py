"""`poinsot run`: the report, the files, the examples, the overrides, bad input, and interruption."""
import json
import os
import re
import signal
import subprocess
import time
from pathlib import Path

import pytest

from conftest import tty_run

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.toml"))

MINIMAL = """
[body]
principal_moments = [1.0, 2.0, 3.0]
[initial]
omega_body = [0.1, 2.0, 0.1]
[integrator]
method = "exact"
[output]
t_end = 5.0
sample_dt = 0.5
"""


def write(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def csv_rows(path):
    lines = Path(path).read_text().splitlines()
    assert lines[0].startswith("# poinsot trajectory. Units:")
    names = lines[1].split(",")
    return names, [[float(x) for x in line.split(",")] for line in lines[2:]]


def test_tennis_racket_report_puts_the_flips_beside_the_closed_form(cli, source_dir, tmp_path):
    out = tmp_path / "racket"
    r = cli("run", source_dir / "examples/tennis_racket.toml", "--out", out)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""  # not a terminal: no progress bar
    text = r.stdout
    assert "principal moments I1, I2, I3 = (0.00121, 0.01638, 0.01748) kg·m²" in text
    assert "asymmetric" in text
    m = re.search(r"interval between flips: measured ([0-9.]+) s \(mean\), theory 2K\(k\)/ω_p = ([0-9.]+) s", text)
    assert m, text
    measured, theory = float(m.group(1)), float(m.group(2))
    assert abs(measured - theory) <= 1e-8 * theory
    assert "period of omega: theory 4K(k)/ω_p" in text
    assert re.search(r"\d+ steps \(\d+ rejected\), wall time [0-9.]+ s, [0-9.e+]+ steps/s", text)
    summary = json.loads((out / "summary.json").read_text())
    for key in ("t", "omega_body", "R", "quaternion"):
        assert key in summary["final"]
    for key in ("energy_rel_error_max", "L_space_rel_error_max", "orthogonality_error_max"):
        assert summary["invariants"][key] < 1e-12
    ev = summary["events"]
    assert len(ev["flip_times"]) >= 5
    assert abs(ev["period_theory"] - 2 * ev["flip_interval_theory"]) < 1e-12
    assert summary["steps"] > 0 and summary["wall_time_s"] >= 0
    names, rows = csv_rows(out / "trajectory.csv")
    assert names[:12] == ["t", "qw", "qx", "qy", "qz", "wx", "wy", "wz", "energy",
                          "L_space_x", "L_space_y", "L_space_z"]
    assert len(rows) == summary["samples"] == 4001
    assert rows[-1][0] == summary["final"]["t"] == 20.0
    # The quaternion of each row is a unit quaternion (body to space).
    assert all(abs(sum(x * x for x in row[1:5]) - 1.0) < 1e-14 for row in rows)


@pytest.mark.parametrize("example", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_runs_and_says_what_it_shows(cli, example, tmp_path):
    first = example.read_text().splitlines()[0]
    assert first.startswith("# ") and "What it shows" in example.read_text()
    r = cli("run", example, "--out", tmp_path / "run", "--quiet")
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["status"] == "completed"
    assert summary["invariants"]["energy_rel_error_max"] < 1e-6


def test_json_on_stdout_is_the_summary(cli, tmp_path):
    s = write(tmp_path, MINIMAL)
    r = cli("run", s, "--out", tmp_path / "o", "--json")
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert j == json.loads((tmp_path / "o" / "summary.json").read_text())
    assert j["method"] == "exact" and j["final"]["t"] == 5.0


def test_overrides(cli, tmp_path):
    s = write(tmp_path, MINIMAL)
    r = cli("run", s, "--out", tmp_path / "o", "--json", "--method", "rk4", "--dt", "0.01", "--t-end", "2",
            "--sample-dt", "0.25")
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert j["method"] == "rk4" and j["t_end"] == 2.0 and j["steps"] == 200
    assert len(csv_rows(tmp_path / "o" / "trajectory.csv")[1]) == 9  # t = 0, 0.25, ..., 2


def test_default_output_folder_is_named_after_the_scenario(cli, tmp_path):
    s = write(tmp_path, MINIMAL, "spin.toml")
    r = cli("run", s, "--quiet", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "spin-run" / "summary.json").is_file()


def bad(cli, tmp_path, text, *extra):
    s = write(tmp_path, text)
    out = tmp_path / "never"
    r = cli("run", s, "--out", out, *extra)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("poinsot: "), r.stderr
    assert not (out / "trajectory.csv").exists()
    return lines[0]


def test_bad_syntax_gives_line_and_column(cli, tmp_path):
    msg = bad(cli, tmp_path, MINIMAL.replace("t_end = 5.0", "t_end = = 5.0"))
    assert "s.toml:9:9: TOML syntax error" in msg, msg  # line 9 of MINIMAL, the second "="


def test_unknown_key_is_named_with_the_valid_ones(cli, tmp_path):
    msg = bad(cli, tmp_path, MINIMAL.replace("sample_dt", "sampel_dt"))
    assert 'unknown key "sampel_dt"; valid keys: t_end, sample_dt, dir' in msg


def test_a_file_of_another_sub_command_names_the_one_that_reads_it(cli, source_dir):
    for example, reader in (("examples/ensemble/tennis_racket_ensemble.toml", "poinsot ensemble"),
                            ("examples/optimal/betts.toml", "poinsot optimize")):
        path = Path(source_dir) / example
        r = cli("run", path)
        assert r.returncode == 2 and r.stdout == "" and r.stderr.count("\n") == 1, (r.stdout, r.stderr)
        assert f"is read by `{reader}`, not by this sub-command; expected `{reader} {path}`" in r.stderr, r.stderr


def test_the_other_sub_commands_name_the_one_that_reads_a_file(cli, source_dir, tmp_path):
    """A robot file given to a sub-command that reads TOML scenarios, and a scenario of another kind given to
    `poinsot ensemble`: one line naming the sub-command that reads it, exit 2, nothing written."""
    urdf = Path(source_dir) / "tests/data/models/robots/pendulum2.urdf"
    for args in (("optimize", urdf, "--out", tmp_path / "a"), ("ensemble", urdf, "--out", tmp_path / "a"),
                 ("lambda", urdf)):
        r = cli(*args)
        assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
        assert f"a robot file (URDF, MJCF or SDF), which `poinsot run {urdf}` simulates as it is" in r.stderr
    for example, says in (("examples/optimal/betts.toml", "which `poinsot optimize {}` solves"),
                          ("examples/multibody/double_pendulum.toml", "which `poinsot run {}` simulates"),
                          ("examples/tennis_racket.toml", "`poinsot run {}` simulates the file as it is")):
        path = Path(source_dir) / example
        r = cli("ensemble", path, "--out", tmp_path / "a")
        assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
        assert "[ensemble]: missing" in r.stderr and says.format(path) in r.stderr, r.stderr
    assert not (tmp_path / "a").exists()


def test_missing_and_double_keys(cli, tmp_path):
    assert "[output] t_end: missing" in bad(cli, tmp_path, MINIMAL.replace("t_end = 5.0", ""))
    msg = bad(cli, tmp_path, MINIMAL.replace("[initial]", "[initial]\nomega_space = [1, 0, 0]"))
    assert "the angular velocity is given 2 times" in msg
    msg = bad(cli, tmp_path, MINIMAL.replace("[body]", "[body]\nshape = { type = \"sphere\", radius = 1, mass = 1 }"))
    assert "the inertia (one way to give it) is given 2 times (principal_moments and shape)" in msg


def test_wrong_types_and_ranges(cli, tmp_path):
    assert 'got "5", expected a number' in bad(cli, tmp_path, MINIMAL.replace("t_end = 5.0", 't_end = "5"'))
    assert "t_end: got -5 s, expected a number > 0" in bad(cli, tmp_path, MINIMAL.replace("5.0", "-5.0"))
    assert "dt: got 0 s, expected a number > 0" in bad(cli, tmp_path, MINIMAL.replace('"exact"', '"rk4"\ndt = 0'))
    assert "expected finite numbers" in bad(cli, tmp_path, MINIMAL.replace("0.1, 2.0", "nan, 2.0"))
    assert "--dt: got -1 s" in bad(cli, tmp_path, MINIMAL, "--dt", "-1")
    assert "--t-end: got inf s" in bad(cli, tmp_path, MINIMAL, "--t-end", "inf")


def test_invalid_inertia_gives_the_inertia_layers_message(cli, tmp_path):
    msg = bad(cli, tmp_path, MINIMAL.replace("[1.0, 2.0, 3.0]", "[1.0, 1.0, 5.0]"))
    assert "[body] principal_moments:" in msg and "triangle inequality" in msg


def test_exact_with_a_torque_is_refused(cli, tmp_path):
    msg = bad(cli, tmp_path, MINIMAL + '[torque]\ntype = "body"\nvalue = [0, 0, 0.1]\n')
    assert 'method: got "exact"' in msg and "torque-free" in msg
    torqued = MINIMAL.replace('"exact"', '"rk4"') + '[torque]\ntype = "space"\nvalue = [0, 0, 1]\n'
    assert '--method: got "exact"' in bad(cli, tmp_path, torqued, "--method", "exact")


def test_unwritable_output_is_refused_before_simulating(cli, tmp_path):
    s = write(tmp_path, MINIMAL)
    (tmp_path / "a_file").write_text("x")
    r = cli("run", s, "--out", tmp_path / "a_file" / "run")
    assert r.returncode == 2
    assert r.stdout == ""
    assert r.stderr.startswith("poinsot: output: cannot create folder")


def test_sigterm_leaves_complete_files_marked_interrupted(source_dir, tmp_path):
    exe = os.environ["POINSOT_CLI"]
    s = write(tmp_path, MINIMAL.replace('"exact"', '"rk4"\ndt = 1e-5').replace("t_end = 5.0", "t_end = 1e3")
              .replace("sample_dt = 0.5", "sample_dt = 0.001"))
    out = tmp_path / "o"
    p = subprocess.Popen([exe, "run", str(s), "--out", str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    csv = out / "trajectory.csv"
    deadline = time.time() + 60
    while time.time() < deadline and (not csv.exists() or csv.stat().st_size < 20000):
        time.sleep(0.05)
    p.send_signal(signal.SIGTERM)
    stdout, stderr = p.communicate(timeout=60)
    assert p.returncode == 128 + signal.SIGTERM, stderr
    assert "INTERRUPTED at t =" in stdout
    assert "interrupted by signal 15" in stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "interrupted" and summary["interrupted"] is True
    text = csv.read_text()
    assert text.endswith("\n")
    names, rows = csv_rows(csv)
    assert all(len(row) == len(names) for row in rows)
    assert rows[-1][0] == summary["final"]["t"]
    assert summary["samples"] == len(rows)
    assert not list(out.glob(".*tmp"))


def test_plot_writes_the_figures(cli, source_dir, tmp_path):
    out = tmp_path / "top"
    r = cli("run", source_dir / "examples/gyroscope.toml", "--out", out, "--plot", "--quiet", "--t-end", "2")
    assert r.returncode == 0, r.stderr
    for name in ("omega.png", "invariants.png", "polhode.png", "top.png"):
        data = (out / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10000, name
    assert "plot: wrote" in r.stdout


def test_progress_bar_only_on_a_terminal_for_long_runs(tmp_path):
    exe = os.environ["POINSOT_CLI"]
    long_run = write(tmp_path, MINIMAL.replace('"exact"', '"rk4"\ndt = 1e-5').replace("t_end = 5.0", "t_end = 1e3")
                     .replace("sample_dt = 0.5", "sample_dt = 0.01"))
    # The bar appears after the first second (the run is stopped as soon as it shows, or after 30 s).
    rc, err = tty_run(exe, ["run", long_run, "--out", tmp_path / "a"], stop_after=30)
    assert rc == 128 + signal.SIGTERM, err
    assert "\r[" in err and "% " in err and "elapsed" in err, err
    rc, err = tty_run(exe, ["run", long_run, "--out", tmp_path / "b", "--quiet"], stop_after=2.5)
    assert rc == 128 + signal.SIGTERM and "\r[" not in err, err
    fast = write(tmp_path, MINIMAL, "fast.toml")
    rc, err = tty_run(exe, ["run", fast, "--out", tmp_path / "c"])
    assert rc == 0 and err == "", err  # under a second: no bar


def test_multibody_scenario_runs_through_poinsot_run(cli, source_dir, tmp_path):
    """A scenario with [[bodies]] goes to the multibody integrator: report, trajectory and summary.json, with the
    joints closed to round-off (the RATTLE Newton tolerance is 1e-13 relative)."""
    out = tmp_path / "dp"
    r = cli("run", source_dir / "examples" / "multibody" / "double_pendulum.toml", "--t-end", "1", "--out", out,
            "--json")
    assert r.returncode == 0, r.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert json.loads(r.stdout) == summary
    assert summary["kind"] == "multibody" and summary["bodies"] == 2
    assert summary["order"] == 2 and summary["solver"] == "ball_chain"  # two ball joints in a chain
    assert summary["steps"] == round(1 / summary["dt"])
    assert summary["joint_gap_max"] < 1e-12
    assert summary["orthogonality_error_max"] < 1e-12
    # RATTLE is symplectic: the energy error stays at its O(h²) level (here ~1e-3 of E for h = 1 ms).
    assert summary["energy_abs_error_max"] < 1e-2 * abs(summary["energy_initial"])
    rows = (out / "trajectory.csv").read_text().strip().splitlines()
    assert len(rows) > 10
    assert (out / "report.txt").read_text().startswith("multibody run")


def test_multibody_plot_and_diagnostics(cli, source_dir, tmp_path):
    """--plot on a multibody run draws paths.png, energy.png and constraints.png; diagnostics.csv has one row per
    trajectory row (here every step, --sample-dt = dt) and its energy_error column reaches the summary's
    energy_abs_error_max, which the C++ run takes over every step by a separate path (RunSummary): the same
    number to round-off."""
    out = tmp_path / "dp"
    r = cli("run", source_dir / "examples" / "multibody" / "double_pendulum.toml", "--t-end", "1", "--plot",
            "--sample-dt", "0.001", "--out", out)
    assert r.returncode == 0, r.stderr
    assert "plot: wrote" in r.stdout
    for name in ("paths.png", "energy.png", "constraints.png"):
        data = (out / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10000, name
    summary = json.loads((out / "summary.json").read_text())
    lines = (out / "diagnostics.csv").read_text().splitlines()
    names = lines[0].split(",")
    assert names == ["t", "energy", "energy_error", "kinetic", "potential", "linear_momentum", "L_space_x",
                     "L_space_y", "L_space_z", "joint_gap", "joint_angle", "orthogonality"]
    rows = [dict(zip(names, map(float, line.split(",")))) for line in lines[1:]]
    traj = (out / "trajectory.csv").read_text().splitlines()[1:]
    assert len(rows) == len(traj) == summary["steps"] + 1
    assert [row["t"] for row in rows] == [float(line.split(",")[0]) for line in traj]
    assert rows[0]["t"] == 0.0 and rows[0]["energy_error"] == 0.0 and rows[0]["joint_gap"] < 1e-12
    assert rows[0]["energy"] == summary["energy_initial"] and rows[-1]["energy"] == summary["energy_final"]
    worst = max(abs(row["energy_error"]) for row in rows)
    assert summary["energy_abs_error_max"] > 0
    assert worst == pytest.approx(summary["energy_abs_error_max"], rel=1e-14, abs=0)
    for row in rows:
        assert row["energy"] == pytest.approx(row["kinetic"] + row["potential"], rel=1e-14, abs=1e-14)
        assert row["joint_gap"] < 1e-12 and row["orthogonality"] < 1e-12


def test_multibody_order_four_cuts_the_falling_chains_energy_error(cli, source_dir, tmp_path):
    """[simulation] order = 4 runs RATTLE's triple-jump composition: the 16-link chain's energy error over its
    first 2 s of fall is O(h⁴) instead of O(h²): measured 6.0e-5 J against 1.6e-2 J (of 1256 J releasable)."""
    text = (source_dir / "examples" / "multibody" / "chain16.toml").read_text()
    errors = {}
    for order in (2, 4):
        scenario = tmp_path / f"chain_order{order}.toml"
        scenario.write_text(text.replace("[simulation]\n", f"[simulation]\norder = {order}\n", 1))
        r = cli("run", scenario, "--t-end", "2", "--out", tmp_path / f"o{order}", "--json")
        assert r.returncode == 0, r.stderr
        summary = json.loads(r.stdout)
        assert summary["order"] == order and summary["joint_gap_max"] < 1e-12
        errors[order] = summary["energy_abs_error_max"]
    assert errors[4] < errors[2] / 50


def test_multibody_scenario_rejects_other_methods(cli, source_dir, tmp_path):
    r = cli("run", source_dir / "examples" / "multibody" / "double_pendulum.toml", "--method", "euler", "--out",
            tmp_path / "x")
    assert r.returncode == 2 and r.stdout == "" and r.stderr.count("\n") == 1
    assert r.stderr.startswith('poinsot: --method: got "euler"') and 'expected "rattle"' in r.stderr
    assert not (tmp_path / "x").exists()


def test_multibody_method_rk4_closes_the_joints_and_cuts_the_energy_error(cli, source_dir, tmp_path):
    """--method rk4 runs the classical RK4 projected onto the joints: summary.json says so, its joints are closed
    to the projection's tolerance (1e-13 of the 0.5 m length scale; measured 7.4e-14 m, the bound 1e-12 m leaves
    room for the gap's evaluation), and over 1 s of the double pendulum (E0 = 1.5 J) its energy error, O(h⁴)
    plus the velocity projections (which only remove energy), is far below RATTLE's O(h²): measured 7.0e-10 J
    against 1.1e-4 J, so a factor 1e4 leaves a margin of 15."""
    summaries = {}
    for method in ("rk4", "rattle"):
        out = tmp_path / method
        r = cli("run", source_dir / "examples" / "multibody" / "double_pendulum.toml", "--method", method,
                "--t-end", "1", "--out", out, "--json")
        assert r.returncode == 0, r.stderr
        summaries[method] = json.loads(r.stdout)
        assert json.loads((out / "summary.json").read_text()) == summaries[method]
    rk4, rattle = summaries["rk4"], summaries["rattle"]
    assert (rk4["method"], rk4["order"]) == ("rk4", 4) and (rattle["method"], rattle["order"]) == ("rattle", 2)
    assert rk4["steps"] == rattle["steps"] == 1000
    assert rk4["joint_gap_max"] < 1e-12 and rk4["orthogonality_error_max"] < 1e-12
    assert rk4["energy_abs_error_max"] < rattle["energy_abs_error_max"] / 1e4
    assert "RK4 projected onto the joints" in (tmp_path / "rk4" / "report.txt").read_text()


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_multibody_signal_leaves_complete_files_marked_interrupted(source_dir, tmp_path, sig):
    """Ctrl-C (or SIGTERM) during a long multibody run stops it at the next row, as a single-body run: every
    row of trajectory.csv and diagnostics.csv complete, summary.json "interrupted" at the last row's time, the
    report printed with INTERRUPTED, exit status 128 + the signal."""
    exe = os.environ["POINSOT_CLI"]
    out = tmp_path / "o"
    p = subprocess.Popen([exe, "run", str(source_dir / "examples" / "multibody" / "chain16.toml"), "--t-end", "1e3",
                          "--sample-dt", "0.001", "--out", str(out), "--quiet"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    csv = out / "trajectory.csv"
    deadline = time.time() + 60
    while time.time() < deadline and (not csv.exists() or csv.stat().st_size < 100000):
        time.sleep(0.05)
    p.send_signal(sig)
    stdout, stderr = p.communicate(timeout=60)
    assert p.returncode == 128 + sig, stderr
    assert "INTERRUPTED at t =" in stdout
    assert f"interrupted by signal {int(sig)}" in stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "interrupted" and summary["interrupted"] is True
    lines = csv.read_text().splitlines()
    names, rows = lines[0].split(","), [line.split(",") for line in lines[1:]]
    assert len(names) == 1 + 16 * 13 and all(len(row) == len(names) for row in rows)
    assert summary["rows"] == len(rows) > 1 and float(rows[-1][0]) == summary["t_final"]
    diagnostics = (out / "diagnostics.csv").read_text().splitlines()
    assert len(diagnostics) == len(lines) and all(len(d.split(",")) == 12 for d in diagnostics)
    assert summary["steps"] == round(summary["t_final"] / summary["dt"])
    assert (out / "report.txt").read_text() == stdout
    assert (out / "reactions.csv").exists() and not list(out.glob(".*tmp"))


def test_multibody_report_of_a_long_chain_reads_like_the_single_body_one(cli, source_dir, tmp_path):
    """chain16: sections, the 16 identical links said once, short numbers with their units, the 5 largest
    reactions and multipliers with the full tables in reactions.csv and multipliers.csv (one row per joint and
    per body, the same forces)."""
    out = tmp_path / "c"
    r = cli("run", source_dir / "examples" / "multibody" / "chain16.toml", "--t-end", "0.5", "--out", out)
    assert r.returncode == 0, r.stderr
    report = r.stdout
    assert report.startswith("multibody run: chain16 (")
    for section in ("\nsystem\n", "\nrun\n", "\nconserved quantities and constraints", "\njoint reactions at t = 0.5 s",
                    "\nmultipliers Λ at t = 0.5 s", "\ncost\n", "\nfiles\n"):
        assert section in report, section
    assert report.count("bodies 'link0' to 'link15' (16): rod radius 0.01 m") == 1
    assert "the 5 largest of 16 by |F|, all in" in report and "the 5 largest of 16 by ‖Λ‖_F, all in" in report
    assert not re.search(r"\d\.\d{8,}", report), "no 17-digit numbers in the report"
    reactions = (out / "reactions.csv").read_text().splitlines()
    assert reactions[0] == "t,joint,body_a,body_b,Fx,Fy,Fz,F_norm,Cx,Cy,Cz,C_norm" and len(reactions) == 17
    forces = sorted((float(line.split(",")[7]) for line in reactions[1:]), reverse=True)
    table = report.split("joint reactions")[1].split("\n\n")[0].splitlines()[2:]
    assert len(table) == 5
    assert [float(row.split()[2]) for row in table] == pytest.approx(forces[:5], rel=1e-5)  # 6 digits shown
    assert len((out / "multipliers.csv").read_text().splitlines()) == 17


MB_MINIMAL = """[simulation]
{}
[[bodies]]
name = "rod"
mass = 1.0
shape = {{ type = "rod", length = 1.0, radius = 0.01 }}
"""


def test_multibody_method_in_the_file(cli, tmp_path):
    s = write(tmp_path, MB_MINIMAL.format('method = "rk4"'))
    r = cli("run", s, "--t-end", "0.1", "--out", tmp_path / "ok", "--json")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["method"] == "rk4"
    # --method overrides the file's method.
    r = cli("run", s, "--t-end", "0.1", "--out", tmp_path / "ok2", "--json", "--method", "rattle")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["method"] == "rattle"
    msg = bad(cli, tmp_path, MB_MINIMAL.format('method = "rk4"\norder = 2'))
    assert re.search(r"s\.toml:\d+:\d+: \[simulation\] order: applies to method = \"rattle\" only", msg), msg
    msg = bad(cli, tmp_path, MB_MINIMAL.format('method = "euler"'))
    assert re.search(r's\.toml:2:\d+: \[simulation\] method: got "euler", expected "rattle"', msg), msg


MULTIBODY_EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples" / "multibody").glob("*.toml"))


@pytest.mark.parametrize("example", MULTIBODY_EXAMPLES, ids=[p.stem for p in MULTIBODY_EXAMPLES])
def test_every_multibody_example_runs(cli, example, tmp_path):
    """Each multibody example runs through `poinsot run` (a short run: the physics is tested in tests/io and
    tests/multibody), with its joints closed to round-off."""
    r = cli("run", example, "--t-end", "0.2", "--out", tmp_path / "run", "--json")
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["kind"] == "multibody" and summary["steps"] == round(0.2 / summary["dt"])
    assert summary["joint_gap_max"] < 1e-12


def test_mesh_body_swings_with_the_compound_pendulum_period(cli, source_dir, tmp_path):
    """examples/multibody/l_bracket_hinge.toml: the L-bracket mesh hung by its hole. The report says how the
    body was given and where its centre of mass is; the period from the trajectory (centre of mass) is the
    large-amplitude compound-pendulum period T0 (1 + θ0²/16 + 11 θ0⁴/3072) to the series' next term
    (173 θ0⁶/737280 ≈ 3e-5 at θ0 = 0.693 rad) and RATTLE's (ωh)²/24 ≈ 5e-6."""
    out = tmp_path / "lb"
    r = cli("run", source_dir / "examples" / "multibody" / "l_bracket_hinge.toml", "--out", out)
    assert r.returncode == 0, r.stderr
    assert "body 'bracket': mesh" in r.stdout and "centre of mass (0.0467647, 0.02676471, 0.01) m" in r.stdout
    lines = (out / "trajectory.csv").read_text().strip().splitlines()
    assert lines[0].startswith("t,bracket.x,bracket.y,bracket.z")
    rows = [[float(x) for x in line.split(",")[:4]] for line in lines[1:]]
    import math
    angle = [math.atan2(x, -z) for _, x, _, z in rows]
    up = [rows[i - 1][0] + (rows[i][0] - rows[i - 1][0]) * -angle[i - 1] / (angle[i] - angle[i - 1])
          for i in range(1, len(rows)) if angle[i - 1] < 0 <= angle[i]]
    period = (up[-1] - up[0]) / (len(up) - 1)
    # Closed form: two boxes (arm 120 × 30 mm, leg 30 × 50 mm, 20 mm thick, 2700 kg/m³), hole (15, 65) mm.
    parts = [(2700 * 0.12 * 0.03 * 0.02, 0.12, 0.03, 0.06, 0.015), (2700 * 0.03 * 0.05 * 0.02, 0.03, 0.05, 0.015, 0.055)]
    m = sum(p[0] for p in parts)
    cx, cy = (sum(p[0] * p[3] for p in parts) / m, sum(p[0] * p[4] for p in parts) / m)
    px, py = 0.015, 0.065
    inertia = sum(q * (a * a + b * b) / 12 + q * ((x - px) ** 2 + (y - py) ** 2) for q, a, b, x, y in parts)
    d = math.hypot(cx - px, cy - py)
    t0 = 2 * math.pi * math.sqrt(inertia / (m * 9.81 * d))
    theta0 = abs(angle[0])
    assert abs(theta0 - math.atan2(cx - px, py - cy)) < 1e-7  # the mesh has float vertices (6e-8 relative)
    expected = t0 * (1 + theta0 ** 2 / 16 + 11 * theta0 ** 4 / 3072)
    assert abs(period - expected) < 1e-4 * expected, (period, expected)


def test_multibody_bad_mesh_is_one_line_naming_file_entry_and_key(cli, tmp_path):
    p = write(tmp_path, '[[bodies]]\nname = "b"\nmesh = { file = "missing.stl", density = 1000 }\n', "mb.toml")
    r = cli("run", p, "--out", tmp_path / "x")
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1
    assert re.match(r'poinsot: .*mb\.toml:3:17: \[bodies\[0\]\.mesh\] file: .*missing\.stl', r.stderr), r.stderr
    assert not (tmp_path / "x").exists()
