"""poinsot.optimize: the optimal reorientation of a rigid body from Python (``poinsot optimize`` as a function).

The C++ run (io/run/optimal_run.hpp: direct method, indirect method from its costates, verification,
interpretation) runs with the GIL released; its samples come back as NumPy arrays.

What ``optimize`` accepts is decided by the recognisers in ``_SOLVERS``, tried in order: each is a pair
(recognise, solve), ``recognise(obj)`` returning a prepared input or None, ``solve(prepared, out_dir)`` the
result. A new kind of system (a multibody system, say) is another pair, placed before the single-body one when
its inputs could also look like a single-body scenario (a dict).
"""
from __future__ import annotations

import json
import os
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

import numpy as np

from . import _core
from ._optimize_multibody import MultibodyOptimalSolution, multibody_input, solve_multibody
from ._optimize_multibody import _Prepared as MultibodyPrepared
from ._simulate import scenario_toml


@dataclass(frozen=True)
class DirectSolution:
    """The direct method's (Hermite–Simpson collocation, Ipopt) solution, NumPy float64 arrays.

    Samples at the mesh nodes and midpoints: ``t`` (n,) s, ``quaternion`` (n, 4) (w, x, y, z), body → space,
    ``omega_body`` (n, 3) rad/s, ``torque_body`` (n, 3) N·m. ``node_time`` (m + 1,) s: the final mesh;
    ``mesh_error`` (m,): the relative error between the nodes of each interval, ``max_mesh_error`` its largest.
    Costates from the defect multipliers at the interval centres ``costate_time`` (m,) s:
    ``costate_attitude_body`` p_θ (m, 3), ``costate_omega`` p_ω (m, 3). ``converged`` (every NLP solved and the
    mesh error met), ``status``, ``final_time`` s, ``cost``, ``mesh_iterations``, ``nlp_iterations``.
    With keep-out or keep-in cones: ``pointing_multiplier`` (c, n), the NLP multiplier of each cone's row at
    each sample (≥ 0 on the active set, 0 off it), and ``pointing_widening`` rad, how much the cones imposed
    at the samples were widened so that the re-simulated control meets them between the samples.
    With reaction wheels: ``torque_body`` holds the wheels' motor torques, ``wheel_momentum`` (n, 3) N·m·s their
    angular momenta (None without wheels), and ``wheel_momentum_margin`` the relative tightening of the momentum
    bounds imposed at the samples so that the re-simulated control meets them between the samples.
    """

    converged: bool
    status: str
    final_time: float
    cost: float
    t: np.ndarray
    quaternion: np.ndarray
    omega_body: np.ndarray
    torque_body: np.ndarray
    node_time: np.ndarray
    costate_time: np.ndarray
    costate_attitude_body: np.ndarray
    costate_omega: np.ndarray
    mesh_error: np.ndarray
    max_mesh_error: float
    mesh_iterations: int
    nlp_iterations: int
    pointing_multiplier: np.ndarray
    pointing_widening: float
    wheel_momentum: np.ndarray | None
    wheel_momentum_margin: float


@dataclass(frozen=True)
class OptimalSolution:
    """The result of ``poinsot.optimize``: the optimal manoeuvre, its checks and its interpretation.

    ``optimal`` is True only when both methods converged and every check passed; ``status`` is then
    "optimal (verified)". ``outcome`` is "optimal", "converged_direct" or "not_converged" (the exit status 0, 3
    or 1 of ``poinsot optimize``): "converged_direct" is a direct solution whose control, re-simulated by
    DOP853, meets the target where the minimum principle could not be verified (``status`` "converged (direct;
    minimum principle not verified: <reason>)"; ``optimal`` False); "not_converged" has ``status`` "not
    converged: <what failed>", and ``failed_phase`` and ``advice`` say which phase failed and what to change.
    The arrays hold the best solution found (the converged indirect one, else the direct one: ``method`` says
    which).

    Samples (NumPy float64, one row a sample; a bang-bang switch appears twice, once per side): ``t`` (n,) s,
    ``R`` (n, 3, 3) body → space, ``quaternion`` (n, 4) (w, x, y, z), ``omega_body`` (n, 3) rad/s,
    ``torque_body`` (n, 3) N·m, ``L_space`` (n, 3) kg·m²/s. Costates at ``costate_t`` (k,) s (= ``t`` for the
    indirect method, the interval centres for the direct one): ``costate_attitude_body`` p_θ (k, 3),
    ``costate_omega`` p_ω (k, 3), ``switching_function`` σ = J⁻¹ p_ω (k, 3), ``hamiltonian`` H (k,) (NaN
    from the direct method). ``switch_times`` (s,) s and ``switch_axes`` (body axes 0, 1, 2) of a bang-bang
    control (the entries into and exits from its arcs included); ``indirect["rate_bound_arcs"]`` and
    ``indirect["singular_arcs"]``: lists of dicts (``axis`` 0, 1, 2, ``t_entry`` s, ``t_exit`` s, and ``side``
    ±1 for a boundary arc ω_axis = side · r).

    ``final_time`` s and ``cost`` (s, N²·m²·s or s per objective) of that solution; ``checks`` (dict: the
    Hamiltonian's mean and deviation, the control gap with ``control_gap_time`` s and ``control_gap_axis`` (0, 1, 2;
    −1 without per-axis bounds) where it is largest and ``control_gap_where_order_two`` (a gap above its tolerance
    there, where both other rates ride their bound about principal axes: a chattering), switching-sign violations,
    the costate drift, ‖RᵀR − I‖, vee(Λ − Λᵀ) − u, the DOP853 re-simulation's attitude and rate errors, its
    amplification ``replay_amplification`` and ``open_loop_replay_checked``, the re-simulation split at the shooting
    nodes ``split_replay_attitude_error`` rad and ``split_replay_rate_error`` rad/s over ``replay_segments``
    segments, the direct–indirect cost difference, ``torque_bound_excess`` and ``rate_bound_excess`` (relative; ≤ 0
    when admissible), ``rate_multiplier_min`` and ``kelley_condition_min`` (the sign conditions of the boundary and
    singular arcs; ≥ 0), ``passed`` and ``failures``); ``interpretation`` (dict: peak Tresca and von Mises stress,
    the eigenaxis manoeuvre's cost and the saving, and the arrays ``lambda_body`` (n, 3, 3) J, ``stress_space`` (n,
    3, 3) N·m, ``momentum_space`` (n, 3)); ``direct`` (DirectSolution) and ``indirect`` (dict of the shooting's
    values and arrays); ``summary`` (the dict of summary.json), ``report`` (the text ``poinsot optimize`` prints),
    ``out_dir`` (where the files went, or None), ``figures`` (paths of the PNGs drawn), ``kind`` ("rigid_body"),
    ``problem`` (the poinsot.optimal.ReorientationProblem solved).
    ``phased`` (dict, summary.json's "phased"): the phase-per-arc re-solve of a minimum-time bang-bang direct
    solution (``enabled``, ``applied``, ``status``, ``converged``, and when applied ``intervals_per_arc``,
    ``final_time`` s, ``cost``, ``switch_times`` s, ``nlp_iterations``); ``direct_optimum_from`` ("phased" or
    "mesh_refinement"): which phase of the direct method gave the direct optimum that the checks compare
    with (``direct`` is always the mesh-refined solution, which seeds the indirect method).
    """

    kind: str
    optimal: bool
    status: str
    method: str
    objective: str
    final_time: float
    cost: float
    t: np.ndarray
    R: np.ndarray
    quaternion: np.ndarray
    omega_body: np.ndarray
    torque_body: np.ndarray
    L_space: np.ndarray
    costate_t: np.ndarray
    costate_attitude_body: np.ndarray
    costate_omega: np.ndarray
    switching_function: np.ndarray
    hamiltonian: np.ndarray
    switch_times: np.ndarray
    switch_axes: list
    checks: dict
    interpretation: dict
    direct: DirectSolution
    indirect: dict
    summary: dict
    report: str
    problem: Any
    phased: dict
    direct_optimum_from: str
    out_dir: str | None = None
    figures: list = field(default_factory=list)
    outcome: str = "not_converged"
    failed_phase: str = ""
    advice: str = ""

    def __repr__(self) -> str:
        head = "optimal (verified)" if self.optimal else f"NOT OPTIMAL ({self.status})"
        return (f"OptimalSolution({head}, objective={self.objective}, method={self.method}, "
                f"final_time={self.final_time:.12g} s, cost={self.cost:.12g}, samples={len(self.t)}, "
                f"switches={len(self.switch_times)})")


def _quaternions(R: np.ndarray) -> np.ndarray:
    """(w, x, y, z) with w >= 0 of each rotation matrix, through the C++ conversion (so3)."""
    return np.array([_core.so3.quaternion_from_rotation(r) for r in R]).reshape(len(R), 4)


def _rotations(q: np.ndarray) -> np.ndarray:
    return np.array([_core.so3.rotation_from_quaternion(x) for x in q]).reshape(len(q), 3, 3)


def _single_body_input(obj: Any) -> Any:
    """A poinsot.optimal.OptimalScenario from a path, a dict with the file's layout, a scenario or a problem;
    None for anything else."""
    opt = _core.optimal
    if isinstance(obj, opt.OptimalScenario):
        return obj
    if isinstance(obj, opt.ReorientationProblem):
        return opt.OptimalScenario(obj)
    if isinstance(obj, Mapping):
        return opt.parse_scenario(scenario_toml(obj), "<dict>", os.getcwd())
    if isinstance(obj, (str, os.PathLike)):
        return opt.load_scenario(os.fspath(obj))
    return None


def _solve_single_body(scenario: Any, out_dir: str) -> OptimalSolution:
    raw = _core.optimal._run(scenario, out_dir)
    problem = scenario.problem
    J = np.asarray(problem.inertia_body)
    direct = DirectSolution(**raw["direct"])
    ind = raw["indirect"]
    summary = json.loads(raw["summary"])
    if summary["solution_from"] == "indirect":
        method, src = "indirect", ind
        R = ind["R"]
        quaternion = _quaternions(R)
        costate_t, hamiltonian = ind["t"], ind["hamiltonian"]
        sigma = ind["switching_function"]
    else:
        method, src = "direct", raw["direct"]
        quaternion = direct.quaternion
        R = _rotations(quaternion)
        costate_t = direct.costate_time
        hamiltonian = np.full(len(costate_t), np.nan)
        sigma = direct.costate_omega @ np.linalg.inv(J).T
    wheels = problem.reaction_wheels
    if wheels is not None:
        # The bus J_b = J − A diag(I) Aᵀ carries ω; L = R (J_b ω + A h); σ = −Aᵀ J_b⁻¹ p_ω per wheel torque.
        A = np.asarray(wheels["axes"]).T
        J_bus = J - A @ np.diag(wheels["spin_inertia"]) @ A.T
        body_momentum = src["omega_body"] @ J_bus.T + direct.wheel_momentum @ A.T
        sigma = -direct.costate_omega @ np.linalg.inv(J_bus).T @ A
    else:
        body_momentum = src["omega_body"] @ J.T
    interpretation = dict(summary.get("interpretation", {}))
    interpretation.update(raw["interpretation"])
    return OptimalSolution(
        kind="rigid_body", optimal=raw["optimal"], status=raw["status"], method=method,
        objective=problem.objective, final_time=src["final_time"], cost=src["cost"], t=src["t"], R=R,
        quaternion=quaternion, omega_body=src["omega_body"], torque_body=src["torque_body"],
        L_space=np.einsum("nij,nj->ni", R, body_momentum), costate_t=costate_t,
        costate_attitude_body=src["costate_attitude_body"], costate_omega=src["costate_omega"],
        switching_function=sigma, hamiltonian=hamiltonian, switch_times=ind["switch_times"],
        switch_axes=list(ind["switch_axes"]), checks=summary["checks"], interpretation=interpretation,
        direct=direct, indirect=ind, summary=summary, report=raw["report"], problem=problem,
        phased=dict(summary["phased"]), direct_optimum_from=summary["direct"]["optimum_from"],
        out_dir=out_dir or None, outcome=summary["outcome"], failed_phase=summary["failed_phase"],
        advice=summary["advice"])


# (recognise, solve) pairs, tried in order (see the module's docstring).
_SOLVERS: list[tuple[Callable[[Any], Any], Callable[[Any, str], Any]]] = [
    (multibody_input, solve_multibody),
    (_single_body_input, _solve_single_body),
]


def optimize(problem: Any, *, out_dir: str | os.PathLike | None = None, mesh_tolerance: float | None = None,
             initial_intervals: int | None = None, max_mesh_iterations: int | None = None,
             starts: int | None = None, plot: bool = False, warn: bool = True, stabilisation_step: float | None = None,
             warm_start: list[int] | None = None,
             no_twist: list[dict] | None = None) -> OptimalSolution | MultibodyOptimalSolution:
    """Solves an optimal reorientation as ``poinsot optimize`` does and returns the solution as NumPy arrays.

    ``problem``: the path of a scenario file with an ``[optimal_control]`` section (docs/optimal_control.md), a
    dict with the same layout (``{"body": {...}, "optimal_control": {..., "initial": {...}, "final":
    {...}}}``), a ``poinsot.optimal.OptimalScenario``, or a ``poinsot.optimal.ReorientationProblem``.
    ``mesh_tolerance``, ``initial_intervals``, ``max_mesh_iterations`` and ``starts`` (the guesses the first mesh
    is solved from, 1 … 64) replace the direct method's options (None: the scenario's, else the defaults). ``problem`` may also be a multibody scenario file (a
    ``[[bodies]]`` array and an ``[optimal_control]`` section, docs/optimal_control.md) or a
    ``poinsot.optimal.MultibodyProblem`` built around a ``poinsot.multibody.System``: the result is then a
    ``MultibodyOptimalSolution`` (``initial_intervals`` sets its equal intervals; the mesh options and
    ``plot`` are refused; ``stabilisation_step``, ``warm_start`` and ``no_twist`` replace the problem's, as
    the keys of the same names in the file's ``[optimal_control]`` do: docs/optimal_control.md; they are
    refused for single-body problems). With ``out_dir`` the files of ``poinsot optimize`` (report.txt,
    trajectory.csv, control.csv, costates.csv, summary.json) are written there, and with ``plot=True`` also
    the figures of ``poinsot optimize --plot`` (``poinsot.plot_optimal``; listed in ``figures``).

    Invalid input raises ValueError (TypeError for an object of another type) with poinsot's one-line message.
    A solution that is not verified optimal is returned with ``optimal`` False, its ``status`` saying what
    failed and the best iterate in the arrays, and (unless ``warn=False``) a RuntimeWarning is issued: it is
    never presented as optimal.
    """
    for recognise, solve in _SOLVERS:
        prepared = recognise(problem)
        if prepared is not None:
            break
    else:
        raise TypeError("problem: expected a scenario path, a dict with the scenario's layout, a "
                        "poinsot.optimal.OptimalScenario, a poinsot.optimal.ReorientationProblem or a "
                        f"poinsot.optimal.MultibodyProblem, got {type(problem).__name__}")
    folder = os.fspath(out_dir) if out_dir is not None else ""
    if plot and not getattr(prepared, "plots", True):
        raise ValueError("plot: figures are drawn for single-body problems only; expected plot=False")
    if plot and not folder:
        raise ValueError("plot: the figures are drawn from the solution's files; expected an out_dir")
    options = dict(mesh_tolerance=mesh_tolerance, initial_intervals=initial_intervals,
                   max_mesh_iterations=max_mesh_iterations, starts=starts)
    multibody = dict(stabilisation_step=stabilisation_step, warm_start=warm_start, no_twist=no_twist)
    for name, value in multibody.items():
        if value is not None and not isinstance(prepared, MultibodyPrepared):
            raise ValueError(f"{name}: an option of multibody problems; expected None for a single-body problem")
        if value is not None:
            options[name] = value
    if any(v is not None for v in options.values()):
        prepared = prepared.with_options(**options)
    result = solve(prepared, folder)
    if plot:
        import dataclasses

        from .plot import plot_run

        result = dataclasses.replace(result, figures=plot_run(folder))
    if warn and not result.optimal:
        warnings.warn(f"poinsot.optimize: {result.status}", RuntimeWarning, stacklevel=2)
    return result
