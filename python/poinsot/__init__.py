"""poinsot: rotation of rigid bodies.

Inertia from geometry, Euler's equations integrated exactly and with structure-preserving methods, and the
Lagrange multipliers of the rotation-matrix formulation (Vallée & Dumitriu 2002). The compiled core is
``poinsot._core``; its functions are re-exported here. Docstrings are the C++ headers' doc comments (where
they say "throws InvalidInput" or "ComputationFailed", Python raises ``ValueError`` with the same one-line
message). Arrays are NumPy float64; vectors have shape (3,), matrices (3, 3), quaternions (w, x, y, z).
Conventions: ``R`` maps body to space, ``omega_body`` is the body-frame angular velocity, SI units.

The integration methods: ``METHODS`` (name → ``MethodInfo``: order, what it preserves, whether it takes a
torque, a description), ``DEFAULT_METHOD`` (simulate, scenario files), ``DEFAULT_LAMBDA_METHOD``
(``analysis.lambda_report``); ``multibody.METHODS`` and ``multibody.DEFAULT_METHOD`` for coupled bodies.

Submodules: ``so3`` (rotations), ``inertia`` (mass properties), ``analysis`` (Λ and the constraint stress),
``multibody`` (coupled bodies and joints integrated by RATTLE, their multipliers, scenario files), ``optimal``
(optimal reorientation problems and scenarios; ``poinsot.optimize`` solves them), ``plot``
(the figures of a run folder, Matplotlib: ``poinsot.plot.plot_run(folder)``).
"""
from . import _core
from ._core import (
    DEFAULT_LAMBDA_METHOD,
    DEFAULT_METHOD,
    METHODS,
    ExactFreeBody,
    FreeBodyTheory,
    HeavyTop,
    Integrator,
    MethodInfo,
    RigidBody,
    Scenario,
    State,
    TorqueModel,
    __version__,
    analysis,
    angular_momentum_body,
    angular_momentum_space,
    axisymmetric_free_motion,
    ensemble,
    fast_top_precession_rate,
    free_body_theory,
    heavy_top_from,
    inertia,
    is_sleeping_top_stable,
    kinetic_energy,
    load_scenario,
    make_integrator,
    multibody,
    optimal,
    parse_scenario,
    potential_energy,
    sleeping_top_threshold,
    so3,
    steady_precession_rates,
    top_initial_conditions,
    top_motion,
    total_energy,
    validate_state,
)
from . import plot
from ._simulate import RunResult, SimulationResult, run, scenario_toml, simulate
from ._view import view
from ._optimize import DirectSolution, OptimalSolution, optimize
from ._optimize_multibody import MultibodyOptimalSolution

__all__ = [
    "__version__",
    "so3",
    "inertia",
    "analysis",
    "multibody",
    "RigidBody",
    "State",
    "TorqueModel",
    "kinetic_energy",
    "angular_momentum_body",
    "angular_momentum_space",
    "potential_energy",
    "total_energy",
    "validate_state",
    "Integrator",
    "make_integrator",
    "METHODS",
    "MethodInfo",
    "DEFAULT_METHOD",
    "DEFAULT_LAMBDA_METHOD",
    "ExactFreeBody",
    "FreeBodyTheory",
    "free_body_theory",
    "axisymmetric_free_motion",
    "HeavyTop",
    "heavy_top_from",
    "top_initial_conditions",
    "top_motion",
    "fast_top_precession_rate",
    "steady_precession_rates",
    "sleeping_top_threshold",
    "is_sleeping_top_stable",
    "Scenario",
    "load_scenario",
    "parse_scenario",
    "scenario_toml",
    "simulate",
    "SimulationResult",
    "run",
    "RunResult",
    "ensemble",
    "plot",
    "view",
    "optimal",
    "optimize",
    "OptimalSolution",
    "MultibodyOptimalSolution",
    "DirectSolution",
]

