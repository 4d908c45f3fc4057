"""Engine balancing (seed 002): the inertia forces and moments of a multi-cylinder engine
found as a draftsman finds them, by phase diagrams and vector polygons.

Owns: :mod:`.engine` (the engine file, ``kind = "engine"``), :mod:`.analysis` (phase
diagrams of first and second order, polygons of the rotating and reciprocating inertia
forces and of their moments, closing vectors, analytic tables, counterweights),
:mod:`.banks` (a V engine bank by bank: each bank's polygons along its own axis, and the
banks combined as a circle, line or ellipse),
:mod:`.exact` (the check against exact physics: the shaking force and moment of the same
engine built as planar linkages, one per crank throw, and solved by the kinetostatics of
:mod:`plans.forces`), and
:mod:`.cli` (``plans balance``).

May import :mod:`plans.errors`, :mod:`plans.io`, :mod:`plans.units`, :mod:`plans.kinds` and, in
:mod:`.exact` only, :mod:`plans.scene`, :mod:`plans.kinematics` and :mod:`plans.forces`.
Never imports ``drawings``.  Read first: :func:`plans.balancing.analysis.balance`.

Typical use::

    from plans.balancing import load_engine, balance
    b = balance(load_engine("samples/engines/inline4.toml"))
    b.forces["second_order"].amplitude      # N
"""

from __future__ import annotations

from typing import Any

_LAZY = {
    "load_engine": "plans.balancing.engine",
    "Engine": "plans.balancing.engine",
    "balance": "plans.balancing.analysis",
    "Balance": "plans.balancing.analysis",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'plans.balancing' has no attribute {name!r}")


__all__ = sorted(_LAZY)
