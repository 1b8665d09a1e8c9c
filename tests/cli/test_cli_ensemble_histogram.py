"""poinsot ensemble: the fixed-edge histograms of summary.json, with edges from [ensemble.histogram] or the
pilot, against a count over samples.csv; their bad input."""
import csv
import json

from test_cli_ensemble import NO_TORQUE, SCENARIO


def count(values, edges):
    """[underflow, overflow, bins...] by comparing every value with the edges (the last bin closed)."""
    c = [0, 0] + [0] * (len(edges) - 1)
    for x in values:
        if x < edges[0]:
            c[0] += 1
        elif x > edges[-1]:
            c[1] += 1
        else:
            i = 0
            while i < len(edges) - 2 and x >= edges[i + 1]:
                i += 1
            c[2 + i] += 1
    return c


def test_histograms_equal_a_count_over_the_rows_and_do_not_need_them(cli, tmp_path):
    text = SCENARIO.format(method="rk4", width="0.02", torque=NO_TORQUE)
    text += "\n[ensemble.histogram]\nbins = 5\nattitude_error = [0.0, 0.02]\n"
    path = tmp_path / "ens.toml"
    path.write_text(text)
    a = cli("ensemble", path, "--threads", "1", "--out", tmp_path / "a")
    b = cli("ensemble", path, "--threads", "2", "--no-per-sample", "--out", tmp_path / "b")
    assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
    sa = json.loads((tmp_path / "a/summary.json").read_text())["outputs"]
    sb = json.loads((tmp_path / "b/summary.json").read_text())["outputs"]
    with open(tmp_path / "a/samples.csv") as f:
        table = list(csv.DictReader(f))
    att = sa["attitude_error"]["histogram"]
    assert att["edges_from"] == "scenario" and len(att["edges"]) == 6
    assert att["edges"][0] == 0.0 and att["edges"][-1] == 0.02
    assert sa["energy_error"]["histogram"]["edges_from"] == "pilot: samples 0 to 63"
    with_histogram = [name for name, o in sa.items() if "histogram" in o]
    assert {"attitude_error", "energy_error", "L_space_error", "flip_interval_theory"} <= set(with_histogram)
    for name in with_histogram:
        h = sa[name]["histogram"]
        values = [float(r[name]) for r in table if r[name] != "nan"]
        assert [h["underflow"], h["overflow"]] + h["counts"] == count(values, h["edges"]), name
        assert sb[name]["histogram"] == h, name  # rows off, two threads: the same counts
    assert sum(att["counts"]) + att["underflow"] + att["overflow"] == 64


def test_bad_histogram_input_is_one_line_exit_2(cli, tmp_path):
    base = SCENARIO.format(method="rk4", width="0.02", torque=NO_TORQUE)
    for extra, word in (("attitude_error = [0.5, 0.1]", "attitude_error"), ("bins = 0", "bins"),
                        ("speed = [0.0, 1.0]", "speed"), ("flip_interval = [1.0]", "flip_interval")):
        path = tmp_path / "bad.toml"
        path.write_text(base + f"\n[ensemble.histogram]\n{extra}\n")
        r = cli("ensemble", path, "--out", tmp_path / "bad")
        assert r.returncode == 2, extra
        assert r.stderr.count("\n") == 1 and word in r.stderr, r.stderr
        assert not (tmp_path / "bad").exists()
