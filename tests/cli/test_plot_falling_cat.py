"""examples/optimal/plot_falling_cat.py: the figure of the falling cat's body shapes, drawn from a
falling_cat.csv in the layout example_falling_cat writes (here the bent cat turned rigidly about its spine, so
that the test does not need the minutes-long solve)."""
import math
import subprocess
import sys

import pytest


def cat_csv(path, points=9):
    """The V-shaped cat of examples/optimal/falling_cat.cpp (halves tilted by 0.5 rad, waist at their +x ends)
    turned by π·s about the spine x, s from 0 to 1."""
    a = 0.5

    def rot_x(t):
        c, s = math.cos(t), math.sin(t)
        return [[1, 0, 0], [0, c, -s], [0, s, c]]

    def mul(A, B):
        return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

    def apply(A, v):
        return [sum(A[i][k] * v[k] for k in range(3)) for i in range(3)]

    Ra = [[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]]
    Rb = mul([[-1, 0, 0], [0, -1, 0], [0, 0, 1]], Ra)
    waist = [0.0, 0.0, -0.5 * math.sin(a)]
    names = ["t"]
    for b in ("front", "back"):
        names += [f"{b}.x_{c}" for c in "xyz"] + [f"{b}.R{r}{c}" for r in range(3) for c in range(3)]
    lines = ["# status: converged, effort 0.24 N^2 m^2 s", ",".join(names)]
    for p in range(points):
        Q = rot_x(math.pi * p / (points - 1))
        row = [p / (points - 1)]
        for R in (Ra, Rb):
            x = apply(Q, [waist[i] - 0.5 * R[i][0] for i in range(3)])
            row += x + [v for line in mul(Q, R) for v in line]
        lines.append(",".join(f"{v:.17g}" for v in row))
    path.write_text("\n".join(lines) + "\n")


def plot(source_dir, *args):
    return subprocess.run([sys.executable, str(source_dir / "examples/optimal/plot_falling_cat.py"), *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def test_it_draws_the_shapes_at_a_few_instants(source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    cat_csv(tmp_path / "falling_cat.csv")
    out = plot(source_dir, tmp_path / "falling_cat.csv", tmp_path / "cat.png", "--instants", "5")
    assert out.returncode == 0, out.stderr
    png = (tmp_path / "cat.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cat.png", "falling_cat.csv"]  # no temporary left


def test_bad_input_is_one_line_and_writes_nothing(source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    (tmp_path / "bad.csv").write_text("# status: x\nt,front.x_x\n0,1\n")
    out = plot(source_dir, tmp_path / "bad.csv", tmp_path / "cat.png")
    assert out.returncode == 2
    assert "column 'back.R22' is missing" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "cat.png").exists()
    out = plot(source_dir, tmp_path / "bad.csv", tmp_path / "cat.png", "--instants", "40")
    assert out.returncode == 2 and "--instants" in out.stderr
