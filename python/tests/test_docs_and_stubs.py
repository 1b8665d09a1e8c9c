"""Docstrings come from the C++ headers (one source), and the committed .pyi stubs match the module."""
import importlib.util
import inspect
import sys
from pathlib import Path

import pytest

import poinsot

from conftest import SOURCE_DIR

TOOLS = SOURCE_DIR / "python" / "tools"


def load_tool(name):
    spec = importlib.util.spec_from_file_location(name, TOOLS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def header_docs():
    gen = load_tool("gen_docstrings")
    root = SOURCE_DIR / "include" / "poinsot"
    return gen, gen.extract(list(root.rglob("*.hpp")), root)


def body_of(doc):
    """A pybind11 docstring without its signature line."""
    return doc.split("\n", 2)[2] if doc.count("\n") >= 2 else doc


@pytest.mark.parametrize("obj, key", [
    (lambda: poinsot.RigidBody.from_principal_moments, "dynamics_RigidBody_from_principal_moments"),
    (lambda: poinsot.RigidBody.with_pivot, "dynamics_RigidBody_with_pivot"),
    (lambda: poinsot.kinetic_energy, "dynamics_kinetic_energy"),
    (lambda: poinsot.TorqueModel.gravity, "dynamics_TorqueModel_gravity"),
    (lambda: poinsot.make_integrator, "dynamics_make_integrator"),
    (lambda: poinsot.ExactFreeBody.state_at, "dynamics_ExactFreeBody_state_at"),
    (lambda: poinsot.so3.log, "so3_log"),
    (lambda: poinsot.inertia.combine, "inertia_combine"),
    (lambda: poinsot.analysis.lambda_from_state, "analysis_lambda_from_state"),
    (lambda: poinsot.load_scenario, "io_load_scenario"),
    (lambda: poinsot.multibody.System.add_hinge, "multibody_System_add_hinge"),
    (lambda: poinsot.multibody.System.add_universal, "multibody_System_add_universal"),
    (lambda: poinsot.multibody.System.add_prismatic, "multibody_System_add_prismatic"),
    (lambda: poinsot.multibody.Rattle.step, "multibody_Rattle_step"),
    (lambda: poinsot.multibody.ProjectedRk4.step, "multibody_ProjectedRk4_step"),
    (lambda: poinsot.multibody.run_scenario, "io_run_multibody_scenario"),
    (lambda: poinsot.optimal.load_scenario, "io_load_optimal_scenario"),
    (lambda: poinsot.optimal.ReorientationProblem.torque_norm_limit,
     "optimal_ReorientationProblem_torque_norm_limit"),
])
def test_docstring_is_the_header_doc_comment(header_docs, obj, key):
    _, docs = header_docs
    assert key in docs, f"{key} is no longer documented in the headers"
    assert body_of(obj().__doc__).strip() == docs[key].strip()


def test_class_and_property_docs_come_from_the_headers(header_docs):
    _, docs = header_docs
    assert poinsot.RigidBody.__doc__ == docs["file_dynamics_rigid_body"]
    assert body_of(poinsot.RigidBody.principal_moments.__doc__).strip() == docs[
        "dynamics_RigidBody_principal_moments"]
    assert poinsot.multibody.ProjectedRk4.__doc__ == docs["file_multibody_projected_rk4"]
    assert poinsot.multibody.ProjectedRk4.multipliers.__doc__ == docs["multibody_ProjectedRk4_multipliers"]


def test_generated_header_is_current(header_docs):
    """The docstrings.hpp the module was built from is what the generator makes of today's headers."""
    gen, docs = header_docs
    built = Path(poinsot.__file__).resolve().parent.parent / "generated" / "docstrings.hpp"
    if not built.exists():
        pytest.skip("not run from a build folder")
    assert built.read_text(encoding="utf-8") == gen.render(docs)


def test_stubs_match_the_module():
    gen = load_tool("gen_stubs")
    folder = SOURCE_DIR / "python" / "poinsot"
    for name, text in gen.stubs().items():
        committed = (folder / name).read_text(encoding="utf-8")
        assert committed == text, (f"python/poinsot/{name} is out of date: run PYTHONPATH=build/release/python "
                                   f"/usr/bin/python3 python/tools/gen_stubs.py python/poinsot")


def test_every_public_name_is_exported_and_stubbed():
    core_stub = (SOURCE_DIR / "python" / "poinsot" / "_core.pyi").read_text(encoding="utf-8")
    for name in poinsot.__all__:
        assert hasattr(poinsot, name), name
        obj = getattr(poinsot, name)
        if getattr(obj, "__module__", "") == "poinsot._core" or inspect.isbuiltin(obj):
            assert (f"def {name}(" in core_stub or f"class {name}:" in core_stub), f"{name} missing in _core.pyi"
    assert poinsot.simulate.__doc__ and "scenario" in poinsot.simulate.__doc__
