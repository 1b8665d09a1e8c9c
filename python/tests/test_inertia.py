"""poinsot.inertia from Python: the lecture's square plate, shapes against their formulas, a mesh against the
box formula, composites, validity and repair, and errors."""
import numpy as np
import pytest

import poinsot
from poinsot import inertia

EPS = np.finfo(float).eps


def test_lecture_square_plate_about_its_corner():
    m, a = 2.0, 0.5
    plate = inertia.plate(m, a, a)
    corner = np.array([-a / 2, -a / 2, 0.0])
    J = plate.inertia_about(corner)
    moments, axes, symmetry = inertia.principal_axes(J)
    # LEC: (1/12, 7/12, 2/3) m a², axes (1,1,0)/√2, (1,−1,0)/√2 and the normal.
    assert np.allclose(moments, np.array([1 / 12, 7 / 12, 2 / 3]) * m * a * a, rtol=1e-15)
    s = 1 / np.sqrt(2)
    assert np.allclose(np.abs(axes[:, 0]), [s, s, 0], atol=4 * EPS)
    assert np.allclose(np.abs(axes[:, 1]), [s, s, 0], atol=4 * EPS)
    assert axes[0, 1] * axes[1, 1] < 0 and np.allclose(np.abs(axes[:, 2]), [0, 0, 1], atol=4 * EPS)
    assert abs(np.linalg.det(axes) - 1) < 8 * EPS and symmetry == "asymmetric"


def test_mass_properties_object():
    box = inertia.box(0.4, [0.3, 0.1, 0.02])
    m, (a, b, c) = 0.4, (0.3, 0.1, 0.02)
    expected = m / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
    assert box.mass == 0.4
    for name, shape in [("center_of_mass", (3,)), ("inertia_com", (3, 3)), ("poinsot_com", (3, 3)),
                        ("principal_moments", (3,)), ("principal_axes", (3, 3))]:
        v = getattr(box, name)
        assert isinstance(v, np.ndarray) and v.dtype == np.float64 and v.shape == shape, name
    assert np.allclose(np.diag(box.inertia_com), expected, rtol=1e-15)
    assert np.allclose(box.principal_moments, np.sort(expected), rtol=1e-15)
    assert box.symmetry == "asymmetric"
    assert inertia.solid_sphere(1.0, 0.1).symmetry == "spherical"
    assert inertia.cylinder(1.0, 0.1, 1.0).symmetry == "prolate"
    assert inertia.cylinder(1.0, 1.0, 0.1).symmetry == "oblate"
    body = box.to_rigid_body()
    assert isinstance(body, poinsot.RigidBody) and np.allclose(body.inertia_com, box.inertia_com, rtol=1e-15)
    # A MassProperties is accepted as simulate's body.
    r = poinsot.simulate(body=box, omega_body=[0.1, 5.0, 0.1], method="rk4", dt=1e-3, t_end=0.1)
    assert r.steps == 100


def test_shape_by_name_with_a_density():
    rho = 7800.0
    s = inertia.shape("sphere", density=rho, radius=0.1)
    m = rho * 4 / 3 * np.pi * 0.1**3
    assert s.mass == pytest.approx(m, rel=1e-14)
    assert np.allclose(s.principal_moments, 0.4 * m * 0.01, rtol=1e-14)
    p = inertia.shape("plate", mass=1.0, size=[0.2, 0.1])
    assert np.allclose(np.diag(p.inertia_com), [0.01 / 12, 0.04 / 12, 0.05 / 12], rtol=1e-14)
    with pytest.raises(ValueError, match="exactly one of mass"):
        inertia.shape("box", size=[1, 1, 1])


def cube_mesh(a, offset):
    v = np.array([[x, y, z] for x in (0, a) for y in (0, a) for z in (0, a)], dtype=float) + offset
    # vertex index = 4x + 2y + z; faces counter-clockwise seen from outside
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return inertia.TriangleMesh(v, np.array(tris, dtype=np.int32))


def test_mesh_mass_properties_equal_the_box_formula_far_from_the_origin():
    a, offset = 0.2, np.array([1000.0, -500.0, 250.0])
    mesh = cube_mesh(a, offset)
    assert mesh.vertices.shape == (8, 3) and mesh.triangles.shape == (12, 3) and mesh.triangles.dtype == np.int32
    props = inertia.mesh(mesh, density=1000.0)
    m = 1000.0 * a**3
    assert props.mass == pytest.approx(m, rel=1e-12)
    assert np.allclose(props.center_of_mass, offset + a / 2, rtol=1e-14)
    # far from the origin: the integral is taken about the bounding-box centre, so 1e-10 survives
    assert np.allclose(props.inertia_com, np.eye(3) * m * a * a / 6, rtol=1e-10, atol=1e-16)
    d = inertia.diagnose(mesh)
    assert d["watertight"] and d["consistent"] and not d["inward"] and d["shells"] == 1


def test_open_mesh_is_an_error_naming_the_defect():
    mesh = cube_mesh(1.0, np.zeros(3))
    open_mesh = inertia.TriangleMesh(mesh.vertices, mesh.triangles[:-1])
    with pytest.raises(ValueError, match="open edges"):
        inertia.mesh(open_mesh, density=1.0)
    with pytest.raises(TypeError, match="triangles: expected integer vertex indices"):
        inertia.TriangleMesh(mesh.vertices, mesh.triangles.astype(float))
    with pytest.raises(ValueError, match=r"vertices: expected an array of shape \(n, 3\), got shape \(8, 2\)"):
        inertia.TriangleMesh(mesh.vertices[:, :2], mesh.triangles)


def test_composite_and_void():
    whole = inertia.box(8.0, [2, 2, 2])
    hole = inertia.box(1.0, [1, 1, 1]).placed(np.eye(3), [0.5, 0.5, 0.5])
    rest = whole - hole
    assert rest.mass == 7.0
    assert np.allclose(rest.center_of_mass, -np.array([0.5, 0.5, 0.5]) / 7, rtol=1e-14)
    again = rest + hole
    assert np.allclose(again.inertia_com, whole.inertia_com, rtol=1e-13, atol=1e-15)


def test_validity_check_and_repair():
    c = inertia.check_inertia(np.diag([1.0, 1.0, 5.0]))
    assert not c["valid"] and c["condition"] == "triangle inequality" and c["amount"] == pytest.approx(3.0)
    assert c["message"] == ("inertia: principal moments (1, 1, 5) kg·m² violate the triangle inequality "
                            "I1 + I2 >= I3 (short by 3)")
    with pytest.raises(ValueError, match=r"short by 3"):
        inertia.require_valid_inertia(np.diag([1.0, 1.0, 5.0]))
    rep = inertia.repair_inertia(np.diag([1.0, 1.0, 5.0]))
    mu = rep["moments_after"]
    assert mu[0] + mu[1] >= mu[2] - 1e-12 and rep["distance"] > 0
    assert inertia.check_inertia(rep["inertia"])["valid"]
    K = inertia.poinsot_from_inertia(np.diag([1.0, 2.0, 3.0]))
    assert np.allclose(K, np.diag([2.0, 1.0, 0.0]))
    assert np.allclose(inertia.inertia_from_poinsot(K), np.diag([1.0, 2.0, 3.0]))


def test_shape_errors():
    with pytest.raises(ValueError, match="mass"):
        inertia.box(-1.0, [1, 1, 1])
    with pytest.raises(ValueError, match=r"size: expected an array of shape \(3,\)"):
        inertia.box(1.0, [1, 1])


def test_body_file_composite_equals_the_sum_of_its_parts(tmp_path):
    text = """
[[part]]
shape = "box"
size = [2.0, 2.0, 2.0]
mass = 8.0

[[void]]
shape = "box"
size = [1.0, 1.0, 1.0]
mass = 1.0
position = [0.5, 0.5, 0.5]
"""
    (tmp_path / "b.toml").write_text(text)
    res = inertia.load_body_file(str(tmp_path / "b.toml"))
    assert res["parts"] == 1 and res["voids"] == 1
    expected = inertia.box(8.0, [2, 2, 2]) - inertia.box(1.0, [1, 1, 1]).placed(np.eye(3), [0.5, 0.5, 0.5])
    assert res["body"].mass == expected.mass
    assert np.allclose(res["body"].inertia_com, expected.inertia_com, rtol=1e-14, atol=1e-15)
    assert np.allclose(inertia.parse_body(text)["body"].center_of_mass, expected.center_of_mass, rtol=1e-14)


def test_report_and_inertial_elements_are_those_of_the_command_line(cli_exe):
    # One serialiser (io/robot/inertia_report.hpp) behind `poinsot inertia --json / --format` and these functions:
    # the same text for the same body, and the box's closed form m/12 (b² + c², a² + c², a² + b²) in it.
    import json
    import subprocess

    box = inertia.box(0.4, [0.3, 0.1, 0.02])
    args = [cli_exe, "inertia", "box", "--size", "0.3", "0.1", "0.02", "--mass", "0.4"]
    cli = json.loads(subprocess.run(args + ["--json", "--about", "0.1", "0", "0"], capture_output=True, text=True,
                                    check=True).stdout)
    assert inertia.report(box, about=[0.1, 0, 0]) == cli
    m, (a, b, c) = 0.4, (0.3, 0.1, 0.02)
    assert np.allclose(np.diag(cli["inertia_com"]), m / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b]),
                       rtol=1e-15)
    # Parallel axes: J_yy and J_zz about (0.1, 0, 0) gain m·0.1².
    assert np.allclose(np.diag(cli["inertia_ref"]) - np.diag(cli["inertia_com"]), [0, m * 0.01, m * 0.01],
                       rtol=1e-12)
    for fmt in ("urdf", "mjcf", "sdf"):
        text = subprocess.run(args + ["--format", fmt], capture_output=True, text=True, check=True).stdout
        assert inertia.inertial_element(box, fmt) == text
    with pytest.raises(ValueError, match='inertial_element: format "step"; expected urdf, mjcf or sdf'):
        inertia.inertial_element(box, "step")
