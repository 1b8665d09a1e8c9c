"""examples/multibody/make_chain.py: the generator of the chain scenarios (the benchmark chain)."""
import json
import subprocess
import sys


def make_chain(source_dir, *args):
    return subprocess.run([sys.executable, str(source_dir / "examples/multibody/make_chain.py"), *map(str, args)],
                          capture_output=True, text=True)


def test_it_writes_the_chain16_example(source_dir):
    out = make_chain(source_dir, 16)
    assert out.returncode == 0, out.stderr
    assert out.stdout == (source_dir / "examples/multibody/chain16.toml").read_text()


def test_a_generated_chain_runs_with_its_links_and_joints(cli, source_dir, tmp_path):
    (tmp_path / "chain5.toml").write_text(make_chain(source_dir, 5).stdout)
    r = cli("run", tmp_path / "chain5.toml", "--t-end", "0.05", "--json", "--out", tmp_path / "out")
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["bodies"] == 5
    assert summary["solver"] == "ball_chain"  # five ball joints in a path
    assert summary["joint_gap_max"] < 1e-12


def test_a_bad_count_is_refused_in_one_line(source_dir):
    out = make_chain(source_dir, "x")
    assert out.returncode != 0
    assert "expected one argument: the number of links N >= 1" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
