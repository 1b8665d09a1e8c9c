"""The scenario's own shape or mesh as the page draws it, read back from the drawn three.js geometry (single
precision: 1e-6 of the body's size is the tolerance of every coordinate).

Oracles: the mesh file itself, read here (vertices, triangles fanned from the polygons) with its centre of
mass by the divergence theorem (signed tetrahedra from the origin), independent of the inertia layer: the
drawn vertices moved back by that centre are the file's vertices, and the triangles as many. For a shape, the
tessellation's closed form: a cylinder of n segments is the prism on the inscribed n-gon, of volume
(n/2) sin(2 pi/n) R^2 L and bounds +-L/2 along its axis, +-R across."""
import math

import numpy as np
import pytest

from conftest import SOURCE_DIR

# At rest, also: L = 0 has no invariable plane, so the page draws no construction.
CYLINDER = """title = "A cylinder along x, at rest"
[body]
shape = { type = "cylinder", radius = 0.05, length = 0.4, mass = 2.0, axis = "x" }
[initial]
omega_body = [0, 0, 0]
[integrator]
method = "exact"
[output]
t_end = 1.0
"""
SEGMENTS = 48  # inertia::kDrawnSurfaceSegments (inertia/tessellation.hpp)

SHAPES = """var v = window.poinsotView; return v.bodyShapes().map(function (s) {
  return {shown: s.shown, order: s.order, vertices: s.surface ? Array.from(s.surface.geometry.attributes.position.array)
          : null, triangles: s.surface ? Array.from(s.surface.geometry.index.array) : null}; });"""


def read_obj(path):
    vertices, triangles = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == "v":
            vertices.append([float(x) for x in w[1:4]])
        elif w and w[0] == "f":
            idx = [int(x.split("/")[0]) - 1 for x in w[1:]]
            triangles += [[idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1)]
    return np.array(vertices), np.array(triangles)


def volume_and_centroid(vertices, triangles):
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    v6 = np.einsum("ij,ij->i", a, np.cross(b, c))  # six times the signed tetrahedra's volumes
    return v6.sum() / 6, (v6[:, None] * (a + b + c)).sum(axis=0) / (4 * v6.sum())


@pytest.mark.parametrize("example", ["mesh_body.toml"])
def test_mesh_body_draws_its_mesh_and_cycles_the_shapes(example, example_runs, load):
    page = load(example_runs[example] / "view.html")
    vertices, triangles = read_obj(SOURCE_DIR / "examples" / "meshes" / "l_bracket.obj")
    _, com = volume_and_centroid(vertices, triangles)
    (shape,) = page.js(SHAPES)
    assert shape["shown"] == "surface" and shape["order"] == ["surface", "box", "ellipsoid"]
    drawn = np.array(shape["vertices"]).reshape(-1, 3) + com
    size = np.ptp(vertices, axis=0).max()
    assert len(drawn) == len(vertices) and len(shape["triangles"]) == 3 * len(triangles)
    for p in vertices:  # every vertex of the file is drawn (the reader may reorder them)
        assert np.abs(drawn - p).max(axis=1).min() <= 1e-6 * size, p
    assert np.allclose(drawn.min(axis=0), vertices.min(axis=0), atol=1e-6 * size)
    assert np.allclose(drawn.max(axis=0), vertices.max(axis=0), atol=1e-6 * size)
    assert "shape (20 triangles)" in page.js("return document.getElementById('legend').textContent")
    for expected in ("box", "ellipsoid", "surface"):
        page.js("window.poinsotView.player.toggleShape();")
        assert page.js(SHAPES)[0]["shown"] == expected


@pytest.fixture(scope="module")
def cylinder(cli, tmp_path_factory):
    root = tmp_path_factory.mktemp("cylinder")
    (root / "c.toml").write_text(CYLINDER)
    r = cli("run", root / "c.toml", "--out", root / "run", "--html", "--quiet")
    assert r.returncode == 0, r.stderr
    return root / "run" / "view.html"


@pytest.mark.parametrize("example", ["cylinder at rest"])
def test_a_body_at_rest_has_no_construction_and_no_error(example, cylinder, load):
    """L = 0 has no invariable plane: the page draws the body alone, with nothing NaN in the console."""
    page = load(cylinder)
    assert page.js("return window.poinsotView.construction") is None
    assert page.pixels()[0] > 0.001
    assert not [e for e in page.console() if e["level"] in ("SEVERE", "WARNING")]


@pytest.mark.parametrize("example", ["cylinder at rest"])
def test_shape_is_its_tessellation(example, cylinder, load):
    page = load(cylinder)
    (shape,) = page.js(SHAPES)
    v = np.array(shape["vertices"]).reshape(-1, 3)
    t = np.array(shape["triangles"]).reshape(-1, 3)
    R, L = 0.05, 0.4
    assert np.allclose(v.min(axis=0), [-L / 2, -R, -R], atol=1e-6 * L)
    assert np.allclose(v.max(axis=0), [L / 2, R, R], atol=1e-6 * L)
    volume, centroid = volume_and_centroid(v, t)
    prism = SEGMENTS / 2 * math.sin(2 * math.pi / SEGMENTS) * R * R * L
    assert abs(volume) == pytest.approx(prism, rel=1e-6)
    assert np.abs(centroid).max() <= 1e-6 * L


@pytest.mark.parametrize("example", ["multibody/double_pendulum.toml"])
def test_multibody_rods_are_drawn_as_their_cylinders(example, example_runs, load):
    page = load(example_runs[example] / "view.html")
    for shape in page.js(SHAPES):  # rod radius 0.01 m, length 1 m along x
        assert shape["shown"] == "surface"
        v = np.array(shape["vertices"]).reshape(-1, 3)
        assert np.allclose(v.min(axis=0), [-0.5, -0.01, -0.01], atol=1e-6)
        assert np.allclose(v.max(axis=0), [0.5, 0.01, 0.01], atol=1e-6)
