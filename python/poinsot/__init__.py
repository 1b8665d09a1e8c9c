"""poinsot: rotation of rigid bodies.

Inertia from geometry, Euler's equations integrated exactly and with structure-preserving methods, and the
Lagrange multipliers of the rotation-matrix formulation (Vallée & Dumitriu 2002). The compiled core is
``poinsot._core``; its functions are re-exported here. Every ``poinsot::Error`` of the C++ library arrives as
``ValueError`` with the same one-line message.
"""
from . import _core
from ._core import __version__, so3

__all__ = ["__version__", "so3"]
