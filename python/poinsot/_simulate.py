"""poinsot.simulate: a run from Python, from keyword arguments, a scenario file, or a dict shaped like one.

The C++ driver (dynamics::simulate) runs with the GIL released; every sample is written into C++ buffers that
become the NumPy arrays of the result without a copy.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

import numpy as np

from . import _core

DEFAULT_METHOD = _core.DEFAULT_METHOD  # the scenario files' default ([integrator] method), from the registry


@dataclass(frozen=True)
class SimulationResult:
    """The sampled trajectory (NumPy float64 arrays, one row a sample) and the summary of a run.

    Arrays: ``t`` (n,) s; ``R`` (n, 3, 3), body → space; ``quaternion`` (n, 4), (w, x, y, z) with w >= 0;
    ``omega_body`` (n, 3) rad/s; ``energy`` (n,) J, T + V; ``L_space`` (n, 3) kg·m²/s, R J ω. Derived on
    demand: ``omega_space`` (n, 3) and ``L_body`` (n, 3).
    Summary: ``final_state``, ``steps``, ``rejected_steps``, ``errors`` (dict: ``energy_rel_max``,
    ``L_space_rel_max``, ``L_norm_rel_max``, ``orthogonality_max``), ``flip_times`` (s, sign changes of the
    intermediate principal component of L_body), ``flip_interval_theory`` and ``period_theory`` (s, the closed
    forms 2K(k)/ω_p and 4K(k)/ω_p for a torque-free asymmetric body, else None), ``wall_time_s``,
    ``interrupted``, ``method``, ``torque`` (its description), ``body``.
    """

    t: np.ndarray
    R: np.ndarray
    quaternion: np.ndarray
    omega_body: np.ndarray
    energy: np.ndarray
    L_space: np.ndarray
    final_state: Any
    steps: int
    rejected_steps: int
    errors: dict
    flip_times: np.ndarray
    wall_time_s: float
    interrupted: bool
    method: str
    torque: str
    body: Any
    flip_interval_theory: float | None = None
    period_theory: float | None = None
    torque_model: Any = None

    @property
    def omega_space(self) -> np.ndarray:
        """Ω = R ω (n, 3), rad/s, space frame."""
        return np.einsum("nij,nj->ni", self.R, self.omega_body)

    @property
    def L_body(self) -> np.ndarray:
        """J ω (n, 3), kg·m²/s, body frame."""
        return self.omega_body @ np.asarray(self.body.inertia).T

    def lambda_body(self) -> np.ndarray:
        """Λ = (j(ω)² + j(ω̇)) K (n, 3, 3), J, body frame, at every sample (poinsot.analysis.lambda_trajectory
        with this run's body and torque)."""
        return _core.analysis.lambda_trajectory(self.body, self.t, self.R, self.omega_body, self.torque_model)

    def __len__(self) -> int:
        return len(self.t)

    def __repr__(self) -> str:
        return (f"SimulationResult(method={self.method!r}, samples={len(self.t)}, steps={self.steps}, "
                f"t_end={self.final_state.time:g} s, flips={len(self.flip_times)}, "
                f"energy_rel_max={self.errors['energy_rel_max']:.3g})")


def _as_body(body: Any) -> Any:
    if isinstance(body, _core.RigidBody):
        return body
    to_body = getattr(body, "to_rigid_body", None)
    if callable(to_body):  # mass properties of the inertia layer
        return to_body()
    arr = np.asarray(body)
    if arr.shape == (3,):
        return _core.RigidBody.from_principal_moments(arr)
    if arr.shape == (3, 3):
        return _core.RigidBody.from_inertia(arr)
    raise ValueError(f"body: expected a poinsot.RigidBody, mass properties, principal moments of shape (3,) "
                     f"or an inertia tensor of shape (3, 3), got {type(body).__name__} of shape {arr.shape}")


def _toml_value(v: Any, where: str) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        f = float(v)
        if math.isnan(f):
            return "nan"
        if math.isinf(f):
            return "inf" if f > 0 else "-inf"
        return repr(f)
    if isinstance(v, (str, os.PathLike)):
        s = os.fspath(v)
        return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, where) for x in v) + "]"
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x, f'{where}.{k}')}" for k, x in v.items()) + " }"
    raise TypeError(f"scenario {where}: expected a number, string, bool, list or dict, got {type(v).__name__}")


def _toml_key(k: Any) -> str:
    k = str(k)
    return k if k.replace("_", "").replace("-", "").isalnum() else _toml_value(k, "key")


def scenario_toml(scenario: Mapping[str, Any]) -> str:
    """TOML text of a scenario given as a dict with the file's layout, e.g.
    ``{"body": {"principal_moments": [1, 2, 3]}, "initial": {"omega_body": [0.01, 2, 0.01]}}``."""
    lines = []
    for k, v in scenario.items():
        if not isinstance(v, Mapping):
            lines.append(f"{_toml_key(k)} = {_toml_value(v, k)}")
    for k, v in scenario.items():
        if isinstance(v, Mapping):
            lines.append(f"[{_toml_key(k)}]")
            lines += [f"{_toml_key(kk)} = {_toml_value(vv, f'[{k}] {kk}')}" for kk, vv in v.items()]
    return "\n".join(lines) + "\n"


def _scenario_parts(scenario: Any) -> dict:
    """body, initial, torque, method, integrator and output options of a scenario (a path, a dict with the
    file's layout, or a poinsot.Scenario)."""
    if isinstance(scenario, Mapping):
        scenario = _core.parse_scenario(scenario_toml(scenario), "<dict>", os.getcwd())
    elif isinstance(scenario, (str, os.PathLike)):
        scenario = _core.load_scenario(os.fspath(scenario))
    if not isinstance(scenario, _core.Scenario):
        raise TypeError(f"scenario: expected a path, a dict or a poinsot.Scenario, got {type(scenario).__name__}")
    keys = ("body", "initial", "torque", "method", "dt", "max_step", "rtol", "atol", "newton_tolerance",
            "newton_max_iterations", "t_end", "sample_dt", "locate_flips")
    return {k: getattr(scenario, k) for k in keys}


def simulate(scenario: Any = None, *, body: Any = None, initial: Any = None, omega_body: Any = None,
             R: Any = None, quaternion: Any = None, torque: Any = None, method: str | None = None,
             dt: float | None = None, max_step: float | None = None, rtol: float | None = None,
             atol: float | None = None,
             newton_tolerance: float | None = None, newton_max_iterations: int | None = None,
             t_end: float | None = None, sample_dt: float | None = None, locate_flips: bool | None = None,
             keep_samples: bool = True) -> SimulationResult:
    """Simulates a rotating rigid body and returns its sampled trajectory as NumPy arrays.

    Either a scenario (the path of a TOML scenario file, a dict with the same sections and keys — ``body``,
    ``initial``, ``torque``, ``integrator``, ``output`` — or a ``poinsot.Scenario``), whose values the keyword
    arguments override; or keyword arguments alone:

    - ``body``: a ``poinsot.RigidBody``, principal moments (3,) kg·m², an inertia tensor J (3, 3) about the
      centre of mass, or mass properties from ``poinsot.inertia``;
    - the initial state: ``initial`` (a ``poinsot.State``) or ``omega_body`` (rad/s) with ``R`` or
      ``quaternion`` (w, x, y, z) (default: identity);
    - ``torque``: None, a ``poinsot.TorqueModel``, or a Python callable ``tau(t, R, omega_body) -> (3,)``
      returning the body-frame torque (N·m) (called with the GIL held at every stage of every step);
    - ``method``: a name of ``poinsot.METHODS`` ({methods}; default {default}); ``dt`` (s), ``max_step``
      (s; adaptive methods' largest step, default none), ``rtol``, ``atol``, ``newton_tolerance``,
      ``newton_max_iterations`` as in IntegratorOptions;
    - ``t_end`` (s), ``sample_dt`` (s), ``locate_flips`` as in SimulationOptions. ``keep_samples=False``
      keeps no trajectory (only the summary), for long runs.

    Errors in the input raise ValueError (TypeError for wrong types) with poinsot's one-line message;
    an exception raised by a torque callback propagates as itself.
    """
    defaults = _core._simulation_defaults
    parts: dict = {}
    if scenario is not None:
        parts = _scenario_parts(scenario)
    if body is not None:
        parts["body"] = _as_body(body)
    if "body" not in parts:
        raise ValueError("body: missing; expected body= (poinsot.RigidBody, principal moments or inertia tensor) "
                         "or a scenario")
    if initial is not None and any(x is not None for x in (omega_body, R, quaternion)):
        raise ValueError("initial: give a poinsot.State or omega_body/R/quaternion, not both")
    if initial is not None:
        if not isinstance(initial, _core.State):
            raise TypeError(f"initial: expected a poinsot.State, got {type(initial).__name__}")
        parts["initial"] = initial
    elif any(x is not None for x in (omega_body, R, quaternion)):
        base = parts.get("initial")
        if base is not None and R is None and quaternion is None:
            R = base.R_space_body
        if base is not None and omega_body is None:
            omega_body = base.omega_body
        parts["initial"] = _core.State(R_space_body=R, quaternion=quaternion, omega_body=omega_body)
    if "initial" not in parts:
        raise ValueError("initial: missing; expected initial= (poinsot.State) or omega_body= (rad/s)")
    if torque is not None:
        parts["torque"] = torque
    given = dict(method=method, dt=dt, max_step=max_step, rtol=rtol, atol=atol, newton_tolerance=newton_tolerance,
                 newton_max_iterations=newton_max_iterations, t_end=t_end, sample_dt=sample_dt,
                 locate_flips=locate_flips)
    opts = {k: (v if v is not None else parts.get(k, defaults.get(k))) for k, v in given.items()}
    if opts["method"] is None:
        opts["method"] = DEFAULT_METHOD
    out = _core._simulate(parts["body"], parts["initial"], parts.get("torque"), opts["method"],
                          float(opts["dt"]), float(opts["max_step"]), float(opts["rtol"]), float(opts["atol"]),
                          float(opts["newton_tolerance"]), int(opts["newton_max_iterations"]),
                          float(opts["t_end"]), float(opts["sample_dt"]), bool(opts["locate_flips"]),
                          keep_samples)
    theory = _theory(parts["body"], parts["initial"], out.pop("torque_is_zero"))
    return SimulationResult(body=parts["body"], torque_model=parts.get("torque"), **out, **theory)


simulate.__doc__ = simulate.__doc__.format(methods=", ".join(_core.METHODS), default=DEFAULT_METHOD)


def _theory(body: Any, initial: Any, torque_free: bool) -> dict:
    """The closed-form flip interval and period of ω for a torque-free body (as `poinsot run` reports them)."""
    if not torque_free or body.has_pivot:
        return {}
    try:
        exact = _core.ExactFreeBody(body, initial)
    except ValueError:
        return {}
    return {"flip_interval_theory": exact.flip_interval or None, "period_theory": exact.omega_period or None}


TorqueCallable = Callable[[float, np.ndarray, np.ndarray], Any]


@dataclass(frozen=True)
class RunResult:
    """What ``poinsot.run`` produced: ``summary`` (the dict of summary.json), ``report`` (the text report of
    ``poinsot run``) and ``out_dir`` (where trajectory.csv and summary.json were written; None: no files)."""

    summary: dict
    report: str
    out_dir: str | None
    figures: list = field(default_factory=list)


def run(scenario: Any, out_dir: str | os.PathLike | None = None, *, method: str | None = None,
        dt: float | None = None, t_end: float | None = None, sample_dt: float | None = None,
        plot: bool = False) -> RunResult:
    """Runs a scenario as ``poinsot run SCENARIO [--out DIR] [--method ...]`` does, through the same engine
    (io/run/run.hpp, io/run/multibody_run.hpp): the same summary (the dict of summary.json) and text report, and with
    ``out_dir`` the same files (for ``poinsot.plot``; ``plot=True`` draws the figures there, as ``--plot`` does,
    and lists them in ``figures``). ``scenario``: a path (a single-body or a multibody file), a dict with the
    single-body file's layout, a poinsot.Scenario or a poinsot.multibody.Scenario."""
    import json

    if isinstance(scenario, Mapping):
        scenario = _core.parse_scenario(scenario_toml(scenario), "<dict>", os.getcwd())
    elif isinstance(scenario, (str, os.PathLike)):
        path = os.fspath(scenario)
        multibody = _core.multibody.is_multibody_scenario(path)
        scenario = (_core.multibody.load_scenario if multibody else _core.load_scenario)(path)
    folder = os.fspath(out_dir) if out_dir is not None else ""
    if plot and not folder:
        raise ValueError("plot: the figures are drawn from the run's files; expected an out_dir")
    if isinstance(scenario, _core.multibody.Scenario):
        text, report = _core._run_multibody_scenario(scenario, folder, method=method or "", dt=dt, t_end=t_end,
                                                     sample_dt=sample_dt)
    elif isinstance(scenario, _core.Scenario):
        scenario = scenario.with_overrides(method=method or "", dt=dt, t_end=t_end, sample_dt=sample_dt)
        text, report = _core._run_scenario(scenario, folder)
    else:
        raise TypeError("scenario: expected a path, a dict, a poinsot.Scenario or a poinsot.multibody.Scenario, "
                        f"got {type(scenario).__name__}")
    figures = []
    if plot:
        from . import plot as plotting

        figures = plotting.plot_run(folder)
    return RunResult(summary=json.loads(text), report=report, out_dir=folder or None, figures=figures)

# The C++ driver's documentation, from its header (one source): appended to simulate's own docstring.
simulate.__doc__ = (simulate.__doc__ or "") + "\n    The C++ driver (dynamics::simulate):\n\n" + "\n".join(
    "    " + line for line in (_core._doc_simulation + "\n\n" + _core._doc_simulate).splitlines())
