"""`poinsot lambda`: the report of the Λ theorems (Vallée & Dumitriu 2002) and its JSON keys (docs/lambda.md).

Oracles: the docs/conventions.md worked cases b and c (printed eigenvalues), and Λ(0) = (j(ω)² + j(ω̇))K recomputed here
with NumPy from the body and ω0 for the stress integral ∫σ dv = −Λ(0) (R(0) = I).
"""
import json

import numpy as np
import pytest

REQUIRED_KEYS = [
    "eigenvalues_initial", "eigenvalues_final", "eigenvalue_max_variation", "symmetry_error_max",
    "max_eigenvalue_max", "trace_plus_2T_max", "stress_integral_initial", "closed_form",
]


def run_json(cli, *args):
    r = cli("lambda", *map(str, args), "--json")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def hat(u):
    return np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])


def lambda_numpy(J, w):
    K = np.trace(J) / 2 * np.eye(3) - J
    wd = np.linalg.solve(J, np.cross(J @ w, w))
    return (hat(w) @ hat(w) + hat(wd)) @ K


@pytest.mark.parametrize("method", ["rattle", "exact", "dop853"])
def test_case_b_prolate(cli, method):
    d = run_json(cli, "--A", 2, "--C", 1, "--omega0", 0.3, -0.4, 1.2, "--t-end", 5, "--method", method,
                 "--dt", 1e-3 if method == "rattle" else 0.2)
    for key in REQUIRED_KEYS:
        assert key in d
    cf = d["closed_form"]
    # docs/conventions.md: λ1 = −1.0294 < λ3 = −0.845 < λ2 = −0.0656 (sorted ascending)
    assert cf["eigenvalues"] == pytest.approx([-1.0294, -0.845, -0.0656], abs=5e-5)
    assert set(cf) >= {"c1", "c2", "Delta", "eigenvalues", "max_deviation"}
    assert cf["c1"] == pytest.approx(-1.095, abs=1e-14)
    assert cf["Delta"] == pytest.approx(cf["c1"] ** 2 + 4 * cf["c2"], rel=1e-14)
    # rattle conserves these to round-off for an axisymmetric body; exact and dop853 (rtol 1e-10) too
    assert cf["max_deviation"] < 1e-8
    assert d["eigenvalue_max_variation"] < 1e-8
    assert d["max_eigenvalue_max"] <= 1e-15
    assert d["symmetry_error_max"] < 1e-14
    assert d["trace_plus_2T_max"] < 1e-14
    assert d["eigenvalues_initial"] == sorted(d["eigenvalues_initial"])
    J = np.diag([2.0, 2.0, 1.0])
    expected = -lambda_numpy(J, np.array([0.3, -0.4, 1.2]))
    assert np.allclose(np.array(d["stress_integral_initial"]), expected, atol=1e-14)
    if method == "rattle":
        assert d["integrator_multiplier"]["deviation_max"] < 1e-5
    else:
        assert d["integrator_multiplier"] is None


def test_case_c_oblate(cli):
    d = run_json(cli, "--A", 1, "--C", 1.8, "--omega0", 1.0, 0.5, -2.0, "--t-end", 3, "--method", "exact")
    cf = d["closed_form"]
    assert cf["eigenvalues"] == pytest.approx([-4.725, -3.6460, -0.0790], abs=5e-5)
    assert cf["lambda3"] == pytest.approx(-4.725, abs=1e-14)
    assert cf["Delta"] == pytest.approx(12.72, abs=5e-3)
    assert cf["max_deviation"] < 1e-13


def test_asymmetric_body_has_no_closed_form_and_varies(cli):
    d = run_json(cli, "--moments", 2, 3, 4, "--omega0", 1, 0.5, 0.3, "--t-end", 3, "--method", "dop853",
                 "--dt", 0.1)
    assert d["closed_form"] is None
    # docs/conventions.md C3: eig Λ(3 s) = (−2.3779, −0.6791, −0.0530)
    assert d["eigenvalues_final"] == pytest.approx([-2.3779, -0.6791, -0.0530], abs=5e-5)
    assert d["eigenvalue_max_variation"] > 0.1
    assert d["max_eigenvalue_max"] <= 0.0


def test_lamina_and_volume(cli):
    d = run_json(cli, "--moments", 1, 2, 3, "--omega0", 0.4, 1.0, -0.6, "--t-end", 2, "--volume", 0.5)
    assert d["closed_form"] is None
    assert all(np.isfinite(d["eigenvalues_final"]))
    assert d["max_eigenvalue_max"] <= 1e-14
    mean = np.array(d["mean_stress_initial"]["tensor"])
    assert np.allclose(mean, np.array(d["stress_integral_initial"]) / 0.5, rtol=1e-14, atol=1e-15)


def test_text_report(cli):
    r = cli("lambda", "--A", 2, "--C", 1, "--omega0", 0.3, -0.4, 1.2, "--t-end", 1)
    assert r.returncode == 0, r.stderr
    assert "closed form" in r.stdout
    assert "stress integral" in r.stdout


@pytest.mark.parametrize("args", [
    ["--omega0", 1, 0, 0],                                     # no body
    ["--moments", 1, 1, 5, "--omega0", 1, 0, 0],               # triangle inequality
    ["--A", 1, "--C", 3, "--omega0", 1, 0, 0],                 # C > 2A
    ["--moments", 1, 2, 3, "--A", 1, "--C", 1, "--omega0", 1, 0, 0],
    ["--moments", 1, 2, 3, "--omega0", 1, 0, 0, "--method", "euler"],
    ["--moments", 1, 2, 3, "--omega0", 1, 0, 0, "--t-end", -1],
])
def test_bad_input_is_one_line_with_status_2(cli, args):
    r = cli("lambda", *map(str, args))
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("poinsot: ")


def test_table_script_reproduces_the_docs_rows(source_dir):
    """scripts/lambda_table.sh runs the CLI for every body; docs/lambda.md holds its output (same rows)."""
    import os
    import subprocess
    exe = os.environ["POINSOT_CLI"]
    r = subprocess.run(["bash", str(source_dir / "scripts" / "lambda_table.sh"), exe], capture_output=True,
                       text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    rows = [l for l in r.stdout.splitlines() if l.startswith("| ") and not l.startswith("| body")]
    assert len(rows) == 12
    doc = (source_dir / "docs" / "lambda.md").read_text()
    block = doc.split("<!-- lambda-table:begin -->")[1].split("<!-- lambda-table:end -->")[0]
    doc_rows = [l for l in block.splitlines() if l.startswith("| ") and not l.startswith("| body")]
    # Same bodies, methods and 4-digit eigenvalues; the round-off columns may differ between builds.
    assert [row.split("|")[1:5] for row in doc_rows] == [row.split("|")[1:5] for row in rows]
    prolate = rows[0].split("|")
    assert prolate[3].strip() == prolate[4].strip() == "(-1.0294, -0.8450, -0.0656)"


def test_scenario_file_form_matches_the_closed_form(cli, source_dir):
    """`poinsot lambda SCENARIO.toml` runs the scenario's body and state; the eigenvalues of Λ(0) must be the
    closed form λ1,2 = (c1 ∓ √Δ)/2, λ3 = −C⟨Ω0,Ω0⟩/2 recomputed here from the file's A, C and ω0."""
    import tomllib

    path = source_dir / "examples" / "axisymmetric_lambda.toml"
    sc = tomllib.loads(path.read_text())
    C = sc["body"]["principal_moments"][2]  # the symmetry axis is body z
    w = np.array(sc["initial"]["omega_body"], dtype=float)
    J = np.diag(sc["body"]["principal_moments"])
    expected = np.sort(np.linalg.eigvalsh(lambda_numpy(J, w)))
    out = run_json(cli, path, "--method", "exact", "--t-end", "5")
    assert out["method"] == "exact"
    assert np.allclose(out["eigenvalues_initial"], expected, rtol=0, atol=1e-13 * np.abs(expected).max())
    eta = w @ w
    assert out["closed_form"] is not None
    assert abs(min(out["closed_form"]["eigenvalues"], key=lambda x: abs(x + C * eta / 2)) + C * eta / 2) < 1e-13
    assert out["closed_form"]["max_deviation"] < 1e-12
    assert out["t_end"] == 5


def test_scenario_file_and_body_flags_together_are_an_error(cli, source_dir):
    r = cli("lambda", source_dir / "examples" / "axisymmetric_lambda.toml", "--moments", "1", "2", "3")
    assert r.returncode == 2
    assert r.stdout == ""
    assert "expected one or the other" in r.stderr


def test_default_method_is_rattle_as_in_the_library_and_python(cli):
    # The default is stated once (dynamics::kDefaultLambdaMethod); analyse_lambda and Python read the same one.
    d = run_json(cli, "--moments", 1, 2, 3, "--omega0", 0.4, 1.0, -0.6, "--t-end", 0.2)
    assert d["method"] == "rattle" and d["integrator_multiplier"] is not None
    r = cli("lambda", "--help")
    assert "exact, rk4, dopri5, dop853, dlm, rattle (default rattle)" in r.stdout
