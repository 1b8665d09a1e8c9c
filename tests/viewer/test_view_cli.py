"""`poinsot view` and `poinsot run --html` on bad input: one line on stderr, status 2, nothing written; and
the page is the same bytes whichever command wrote it."""
import json
import shutil

import pytest

from conftest import SOURCE_DIR

TENNIS = SOURCE_DIR / "examples" / "tennis_racket.toml"


def refused(r):
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("poinsot: view: "), r.stderr
    return lines[0]


@pytest.fixture(scope="module")
def tennis(cli, tmp_path_factory):
    out = tmp_path_factory.mktemp("tennis") / "run"
    r = cli("run", TENNIS, "--out", out, "--html", "--quiet", "--t-end", "2")
    assert r.returncode == 0, r.stderr
    return out


def test_view_rewrites_the_same_page(cli, tennis, tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(tennis, copy)
    (copy / "view.html").unlink()
    r = cli("view", copy, "--scenario", TENNIS)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == str(copy / "view.html")
    assert (copy / "view.html").read_bytes() == (tennis / "view.html").read_bytes()
    assert sorted(p.name for p in copy.iterdir()) == ["summary.json", "trajectory.csv", "view.html"]


def test_a_folder_without_a_finished_run_is_refused(cli, tennis, tmp_path):
    assert "is not a folder" in refused(cli("view", tmp_path / "missing"))
    empty = tmp_path / "empty"
    empty.mkdir()
    assert "has no summary.json" in refused(cli("view", empty))
    assert list(empty.iterdir()) == []
    stopped = tmp_path / "stopped"
    shutil.copytree(tennis, stopped)
    (stopped / "view.html").unlink()
    summary = json.loads((stopped / "summary.json").read_text())
    summary["status"] = "interrupted"
    (stopped / "summary.json").write_text(json.dumps(summary))
    assert 'says status "interrupted"' in refused(cli("view", stopped))
    (stopped / "summary.json").write_text("{ not json")
    assert "is not valid JSON" in refused(cli("view", stopped))
    assert not (stopped / "view.html").exists()
    assert [p.name for p in stopped.iterdir() if p.name.startswith(".")] == []  # no temporary file left


@pytest.mark.parametrize("frames", ["1", "100001", "-5"])
def test_frames_out_of_range_are_refused_before_the_run(cli, tennis, tmp_path, frames):
    assert f"--frames {frames} is out of range" in refused(cli("view", tennis, "--frames", frames))
    out = tmp_path / "run"
    assert f"--frames {frames} is out of range" in refused(
        cli("run", TENNIS, "--out", out, "--html", "--frames", frames, "--quiet"))
    assert not out.exists()  # refused before anything was simulated or written


def test_frames_without_html_is_refused(cli, tmp_path):
    r = cli("run", TENNIS, "--out", tmp_path / "run", "--frames", "10", "--quiet")
    assert r.returncode == 2 and r.stderr.strip() == "poinsot: --frames requires --html", r.stderr
    assert not (tmp_path / "run").exists()


def test_a_run_too_large_for_the_frames_is_refused(cli, tmp_path):
    """A multibody run of 200 bodies and 1001 rows holds 1001 x (1 + 10 x 200) numbers, beyond the 2e6 a
    page may hold: refused with the frames that fit, which then work."""
    bodies = 200
    run = tmp_path / "big"
    run.mkdir()
    (run / "summary.json").write_text(json.dumps({"kind": "multibody", "bodies": bodies, "scenario": ""}))
    names = ["t"] + [f"b{k}.{c}" for k in range(bodies)
                     for c in ("x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz")]
    row = ",".join(["1"] * len(names))
    (run / "trajectory.csv").write_text(",".join(names) + "\n" + "\n".join([row] * 1001) + "\n")
    line = refused(cli("view", run))
    assert "more than a page holds (2000000)" in line and "expected --frames ≤ 999" in line, line
    assert not (run / "view.html").exists()
    r = cli("view", run, "--frames", "999")
    assert r.returncode == 0, r.stderr
    assert (run / "view.html").stat().st_size > 999 * bodies * 10


def test_an_optimize_folder_without_its_scenario_is_refused(cli, slew_run, tmp_path):
    """The optimal page takes the body, the bounds and the target from the scenario: without it, one line."""
    copy = tmp_path / "slew"
    shutil.copytree(slew_run, copy)
    (copy / "view.html").unlink()
    summary = json.loads((copy / "summary.json").read_text())
    summary["scenario"] = str(tmp_path / "moved.toml")
    (copy / "summary.json").write_text(json.dumps(summary))
    line = refused(cli("view", copy))
    assert "is a `poinsot optimize` folder whose scenario" in line and "expected --scenario FILE" in line, line
    assert not (copy / "view.html").exists()
    r = cli("view", copy, "--scenario", SOURCE_DIR / "examples" / "optimal" / "sphere_slew.toml")
    assert r.returncode == 0, r.stderr
    pages = [(d / "view.html").read_text(encoding="utf-8") for d in (copy, slew_run)]
    assert pages[0].replace(str(tmp_path / "moved.toml"), summary_path(slew_run)) == pages[1]


def summary_path(run):
    return json.loads((run / "summary.json").read_text())["scenario"]
