"""poinsot.optimize on coupled bodies: a multibody scenario file with an ``[optimal_control]`` section, or a
``poinsot.optimal.MultibodyProblem`` built around a ``poinsot.multibody.System`` (io/run/multibody_optimal_run.hpp:
the direct transcription in rotation-matrix or minimal coordinates, and the re-simulation of its control by the
multibody projected RK4). Registered in ``_optimize._SOLVERS`` before the single-body pair.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import _core


@dataclass(frozen=True)
class MultibodyOptimalSolution:
    """The result of ``poinsot.optimize`` on a multibody problem.

    ``optimal`` is True only when Ipopt converged and the control, re-simulated by the multibody projected RK4,
    reaches the target within the scenario's tolerance; ``status`` is then "optimal", else "not converged:
    <what failed>" with the last iterate in the arrays.

    Samples at every collocation point (nodes and midpoints), NumPy float64: ``t`` (n,) s; per body (system
    order) ``x_space`` (n, B, 3) m (centre of mass), ``R_space_body`` (n, B, 3, 3), ``v_space`` (n, B, 3) m/s,
    ``omega_body`` (n, B, 3) rad/s; ``controls`` (n, m) N·m in the columns ``control_names`` (``HINGE.u``,
    ``BODY.ux``, ``BALL.ux``, ...); per joint the reaction on body a ``joint_force_space`` (n, J, 3) N and
    ``joint_torque_space`` (n, J, 3) N·m; per body ``Lambda_body`` (n, B, 3, 3) J. ``cost`` ∫ Σ u² dt
    (N²·m²·s; for minimum time T + ε ∫ Σ u² dt, s), ``final_time`` s (the optimum's, free under minimum
    time), ``nlp_iterations``, ``nlp_restarts`` (Ipopt runs restarted with other settings), ``replay`` (dict: the re-simulation's attitude, position and velocity errors,
    joint gap, ‖RᵀR − I‖, tolerance, ``target_reached``), ``summary`` (the dict of
    summary.json), ``report`` (the text ``poinsot optimize`` prints), ``out_dir``, ``kind`` ("multibody"),
    ``problem`` (the poinsot.optimal.MultibodyProblem solved).
    """

    kind: str
    optimal: bool
    status: str
    objective: str
    coordinates: str
    final_time: float
    cost: float
    nlp_iterations: int
    nlp_restarts: int
    t: np.ndarray
    x_space: np.ndarray
    R_space_body: np.ndarray
    v_space: np.ndarray
    omega_body: np.ndarray
    controls: np.ndarray
    control_names: list
    joint_force_space: np.ndarray
    joint_torque_space: np.ndarray
    Lambda_body: np.ndarray
    replay: dict
    summary: dict
    report: str
    problem: Any
    out_dir: str | None = None
    figures: list = field(default_factory=list)

    def __repr__(self) -> str:
        head = "optimal" if self.optimal else f"NOT OPTIMAL ({self.status})"
        return (f"MultibodyOptimalSolution({head}, coordinates={self.coordinates}, final_time={self.final_time:.12g}"
                f" s, cost={self.cost:.12g}, samples={len(self.t)})")


@dataclass(frozen=True)
class _Prepared:
    """A MultibodyProblem with the option names of ``poinsot.optimize``: ``initial_intervals`` sets the
    (equal) intervals, ``stabilisation_step``, ``warm_start`` (the mesh sequence) and ``no_twist`` replace the
    problem's (MultibodyProblem.with_options); the single body's mesh-refinement options and starts are refused
    (a multibody mesh is refined only where the re-simulation misses the target, from its own warm start)."""

    scenario: Any
    plots: bool = False

    def with_options(self, mesh_tolerance=None, initial_intervals=None, max_mesh_iterations=None, starts=None,
                     stabilisation_step=None, warm_start=None, no_twist=None) -> "_Prepared":
        for name, value in (("mesh_tolerance", mesh_tolerance), ("max_mesh_iterations", max_mesh_iterations),
                            ("starts", starts)):
            if value is not None:
                raise ValueError(f"{name}: multibody problems take no mesh-refinement options; expected None (set "
                                 "initial_intervals, or intervals in the file)")
        return _Prepared(self.scenario.with_options(intervals=initial_intervals,
                                                    stabilisation_step=stabilisation_step,
                                                    warm_start=warm_start, no_twist=no_twist))


def multibody_input(obj: Any) -> _Prepared | None:
    """A prepared multibody problem from a MultibodyProblem or the path of a multibody scenario (a ``bodies``
    array); None for anything else."""
    opt = _core.optimal
    if isinstance(obj, opt.MultibodyProblem):
        return _Prepared(obj)
    if isinstance(obj, (str, os.PathLike)) and _core.multibody.is_multibody_scenario(os.fspath(obj)):
        return _Prepared(opt.load_multibody_scenario(os.fspath(obj)))
    return None


def solve_multibody(prepared: _Prepared, out_dir: str) -> MultibodyOptimalSolution:
    scenario = prepared.scenario
    raw = _core.optimal._run_multibody(scenario, out_dir)
    summary = json.loads(raw["summary"])
    names = []
    for a in summary["problem"]["actuators"]:
        names += [a["name"] + ".u"] if a["kind"] == "hinge_torque" else [a["name"] + c for c in (".ux", ".uy", ".uz")]
    return MultibodyOptimalSolution(
        kind="multibody", optimal=raw["optimal"], status=raw["status"], objective=summary["objective"],
        coordinates=scenario.coordinates, final_time=summary["solution"]["final_time"], cost=raw["cost"],
        nlp_iterations=raw["nlp_iterations"], nlp_restarts=raw["nlp_restarts"], t=raw["t"], x_space=raw["x_space"], R_space_body=raw["R_space_body"],
        v_space=raw["v_space"], omega_body=raw["omega_body"], controls=raw["controls"], control_names=names,
        joint_force_space=raw["joint_force_space"], joint_torque_space=raw["joint_torque_space"],
        Lambda_body=raw["Lambda_body"], replay=summary["replay"], summary=summary, report=raw["report"],
        problem=raw["scenario"], out_dir=out_dir or None)
