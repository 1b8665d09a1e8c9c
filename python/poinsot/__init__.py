"""poinsot: rotation of rigid bodies.

Inertia from geometry, Euler's equations integrated exactly and with structure-preserving methods, and the
Lagrange multipliers of the rotation-matrix formulation (Vallée & Dumitriu 2002). The compiled core is
``poinsot._core``; its functions are re-exported here. Docstrings are the C++ headers' doc comments (where
they say "throws InvalidInput" or "ComputationFailed", Python raises ``ValueError`` with the same one-line
message). Arrays are NumPy float64; vectors have shape (3,), matrices (3, 3), quaternions (w, x, y, z).
Conventions: ``R`` maps body to space, ``omega_body`` is the body-frame angular velocity, SI units.
"""
from . import _core
from ._core import (
    RigidBody,
    State,
    TorqueModel,
    __version__,
    angular_momentum_body,
    angular_momentum_space,
    kinetic_energy,
    potential_energy,
    so3,
    total_energy,
    validate_state,
)

__all__ = [
    "__version__",
    "so3",
    "RigidBody",
    "State",
    "TorqueModel",
    "kinetic_energy",
    "angular_momentum_body",
    "angular_momentum_space",
    "potential_energy",
    "total_energy",
    "validate_state",
]

from ._simulate import SimulationResult, scenario_toml, simulate  # noqa: E402

__all__ += ["simulate", "SimulationResult", "scenario_toml"]
