"""`poinsot inertia`: shapes, meshes, tensors and body files; --json keys, --format urdf|mjcf|sdf, bad input.

Oracles: closed forms (box, the lecture's square plate about its corner: 1/12, 7/12, 2/3 m a²), a cube mesh
written here (exact for the divergence theorem), and the worked triangle-inequality message of docs/inertia.md."""
import json
import math
import re

import pytest

BOX_KEYS = {"mass", "center_of_mass", "inertia_com", "poinsot_com", "principal_moments", "principal_axes",
            "symmetry", "valid", "diagnostics"}

# Cube [0, 2]³ with outward triangles (counter-clockwise seen from outside).
CUBE_V = [(0, 0, 0), (2, 0, 0), (0, 2, 0), (2, 2, 0), (0, 0, 2), (2, 0, 2), (0, 2, 2), (2, 2, 2)]
CUBE_T = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
          (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]


def write_stl(path, triangles):
    lines = ["solid cube"]
    for t in triangles:
        lines += ["facet normal 0 0 0", "outer loop"]
        lines += ["vertex %g %g %g" % CUBE_V[i] for i in t]
        lines += ["endloop", "endfacet"]
    lines.append("endsolid cube")
    path.write_text("\n".join(lines) + "\n")
    return path


def run_json(cli, *args):
    r = cli("inertia", *args, "--json")
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    return json.loads(r.stdout)


def close(a, b, tol=1e-14):
    return all(abs(x - y) <= tol * max(1.0, abs(y)) for x, y in zip(a, b))


def test_box_json_matches_the_closed_form(cli):
    j = run_json(cli, "box", "--size", "0.3", "0.1", "0.02", "--mass", "0.4")
    assert BOX_KEYS <= set(j)
    m, (a, b, c) = 0.4, (0.3, 0.1, 0.02)
    expected = [m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12]
    assert close([j["inertia_com"][i][i] for i in range(3)], expected)
    assert close(j["principal_moments"], sorted(expected))
    assert j["symmetry"] == "asymmetric" and j["valid"] is True and j["diagnostics"] == []
    # K = tr(J)/2 I − J
    tr = sum(expected)
    assert close([j["poinsot_com"][i][i] for i in range(3)], [tr / 2 - e for e in expected])


def test_lecture_plate_about_its_corner(cli):
    j = run_json(cli, "plate", "--size", "1", "1", "--mass", "1", "--about", "-0.5", "-0.5", "0")
    assert close(j["inertia_ref"][0], [1 / 3, -0.25, 0]) and close(j["inertia_ref"][2], [0, 0, 2 / 3])
    assert close(j["principal_moments_ref"], [1 / 12, 7 / 12, 2 / 3], 1e-15)
    axes = j["principal_axes_ref"]
    h = 1 / math.sqrt(2)
    assert close([axes[i][0] for i in range(3)], [h, h, 0], 1e-15)
    assert close([axes[i][1] for i in range(3)], [h, -h, 0], 1e-15)
    assert close([axes[i][2] for i in range(3)], [0, 0, -1], 1e-15)  # a3 = a1 × a2 (sign rule)


@pytest.mark.parametrize("args,symmetry", [
    (["sphere", "--radius", "0.1", "--mass", "2"], "spherical"),
    (["sphere", "--radius", "0.1", "--hollow", "--density", "3"], "spherical"),
    (["sphere", "--radius", "0.1", "--inner-radius", "0.05", "--density", "3"], "spherical"),
    (["cylinder", "--radius", "0.1", "--length", "1", "--density", "1000"], "prolate"),
    (["cylinder", "--radius", "0.5", "--length", "0.1", "--inner-radius", "0.2", "--mass", "1"], "oblate"),
    (["cone", "--radius", "0.1", "--height", "0.3", "--mass", "1"], "prolate"),
    (["ellipsoid", "--semi-axes", "0.3", "0.2", "0.1", "--density", "900"], "asymmetric"),
    (["capsule", "--radius", "0.1", "--length", "0.4", "--mass", "1"], "prolate"),
    (["torus", "--major-radius", "0.5", "--minor-radius", "0.1", "--mass", "1"], "oblate"),
    (["rod", "--length", "2", "--density", "0.5"], "prolate"),
    (["point", "--mass", "3"], "spherical"),
])
def test_every_shape(cli, args, symmetry):
    j = run_json(cli, *args)
    assert j["symmetry"] == symmetry and j["valid"] is True
    assert j["principal_moments"] == sorted(j["principal_moments"])


def test_rod_density_gives_mass(cli):
    j = run_json(cli, "rod", "--length", "2", "--density", "0.5")
    assert j["mass"] == 1.0
    assert close([j["inertia_com"][0][0]], [1.0 * 4 / 12])


@pytest.mark.parametrize("fmt", ["urdf", "mjcf", "sdf"])
def test_model_formats(cli, fmt):
    # A tilted tensor so that the order of the products of inertia matters: Ixx..Iyz all different.
    r = cli("inertia", "tensor", "4", "5", "6", "-0.1", "-0.2", "-0.3", "--mass", "2", "--format", fmt)
    assert r.returncode == 0, r.stderr
    out = r.stdout
    if fmt == "urdf":
        assert '<mass value="2"/>' in out
        assert 'ixx="4" ixy="-0.1" ixz="-0.2" iyy="5" iyz="-0.3" izz="6"' in out
    elif fmt == "mjcf":
        assert 'fullinertia="4 5 6 -0.1 -0.2 -0.3"' in out and 'mass="2"' in out
    else:
        tags = re.findall(r"<(i[xyz]{2})>([^<]*)</", out)
        assert tags == [("ixx", "4"), ("ixy", "-0.1"), ("ixz", "-0.2"), ("iyy", "5"), ("iyz", "-0.3"), ("izz", "6")]
        assert "<mass>2</mass>" in out


def test_tensor_invalid_and_repair(cli):
    r = cli("inertia", "tensor", "1", "1", "5", "0", "0", "0")
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.startswith("poinsot: tensor: principal moments (1, 1, 5) kg·m² violate the triangle "
                               "inequality I1 + I2 >= I3 (short by 3)")
    j = run_json(cli, "tensor", "1", "1", "5", "0", "0", "0", "--repair")
    # Nearest point of the cone I1 + I2 >= I3 to (1, 1, 5): (2, 2, 4), distance √3.
    assert close(j["principal_moments"], [2, 2, 4]) and abs(j["repair_distance"] - math.sqrt(3)) < 1e-14
    assert j["valid"] is True and any("repaired" in d for d in j["diagnostics"])
    # A lamina typed with 6 digits misses I1 + I2 >= I3 by 1e-6: rejected at the default 1e-10 of the trace,
    # accepted with a tolerance the caller sets.
    lamina = ["tensor", "0.083333", "0.083333", "0.166667", "0", "0", "0"]
    assert cli("inertia", *lamina).returncode == 2
    assert run_json(cli, *lamina, "--validity-tolerance", "1e-5")["symmetry"] == "oblate"


def test_mesh_solid_shell_and_diagnostics(cli, tmp_path):
    stl = write_stl(tmp_path / "cube.stl", CUBE_T)
    j = run_json(cli, "mesh", stl, "--density", "1000")
    assert close([j["mass"]], [8000.0]) and close(j["center_of_mass"], [1, 1, 1])
    assert close([j["inertia_com"][0][0]], [8000.0 * 8 / 12])
    assert j["symmetry"] == "spherical"
    # Shell of thickness t: areal density ρ t over 24 m²; J = 5/18 m a² for a cube's surface.
    s = run_json(cli, "mesh", stl, "--density", "1000", "--shell", "0.001")
    assert close([s["mass"]], [24.0]) and close([s["inertia_com"][1][1]], [5 / 18 * 24 * 4])
    # Inward: an error unless --flip-inward, then reported.
    inward = write_stl(tmp_path / "inward.stl", [(a, c, b) for a, b, c in CUBE_T])
    r = cli("inertia", "mesh", inward, "--mass", "1")
    assert r.returncode == 2 and r.stdout == "" and "inward orientation" in r.stderr and "--flip-inward" in r.stderr
    j = run_json(cli, "mesh", inward, "--mass", "1", "--flip-inward")
    assert any(d.startswith("inward orientation") for d in j["diagnostics"])
    # Open: an error naming the count.
    opened = write_stl(tmp_path / "open.stl", CUBE_T[:-1])
    r = cli("inertia", "mesh", opened, "--mass", "1")
    assert r.returncode == 2 and r.stdout == "" and "open edges: 3" in r.stderr


def test_body_file(cli, tmp_path):
    stl = write_stl(tmp_path / "cube.stl", CUBE_T)
    body = tmp_path / "body.toml"
    body.write_text(f"""
[[part]]
mesh = "{stl.name}"
density = 1
[[void]]
shape = "box"
size = [1, 2, 2]
density = 1
position = [1.5, 1, 1]
""")
    j = run_json(cli, "body", body)
    # Cube [0,2]³ minus its half x > 1: the box [0,1]×[0,2]×[0,2].
    assert close([j["mass"]], [4.0]) and close(j["center_of_mass"], [0.5, 1, 1])
    assert close([j["inertia_com"][i][i] for i in range(3)], [4 * 8 / 12, 4 * 5 / 12, 4 * 5 / 12])


@pytest.mark.parametrize("args", [
    ["box", "--size", "0", "1", "1", "--mass", "1"],
    ["box", "--size", "1", "1", "1", "--mass", "-1"],
    ["box", "--size", "1", "1", "1", "--density", "nan"],
    ["box", "--size", "1", "1", "1", "--mass", "inf"],
    ["box", "--size", "1", "1", "1"],
    ["box", "--size", "1", "1", "1", "--mass", "1", "--density", "1"],
    ["sphere", "--radius", "1", "--mass", "1", "--inner-radius", "2"],
    ["torus", "--major-radius", "0.1", "--minor-radius", "0.2", "--mass", "1"],
    ["blob", "--mass", "1"],
    ["box", "--size", "1", "1", "1", "--mass", "1", "--bogus"],
    ["box", "--size", "1", "1", "1", "--mass", "1", "--format", "obj"],
    ["tensor", "1", "1", "1", "0", "0", "x"],
    ["tensor", "1", "2", "3", "0", "0", "0", "--format", "urdf"],
    ["mesh", "/nonexistent/file.stl", "--mass", "1"],
    ["body", "/nonexistent/body.toml"],
    [],
])
def test_bad_input_is_one_line_and_status_2(cli, args):
    r = cli("inertia", *args)
    assert r.returncode == 2
    assert r.stdout == ""
    assert len(r.stderr.strip().splitlines()) == 1 and r.stderr.startswith("poinsot: ")


def test_bad_files(cli, tmp_path):
    empty = tmp_path / "empty.stl"
    empty.write_text("")
    text = tmp_path / "notes.obj"
    text.write_text("hello, this is not a mesh\n")
    for f in (empty, text, tmp_path):
        r = cli("inertia", "mesh", f, "--mass", "1")
        assert r.returncode == 2 and r.stdout == "", (f, r.stdout)
        assert len(r.stderr.strip().splitlines()) == 1

