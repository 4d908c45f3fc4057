"""plans: the graphical method of a Theory of Machines and Mechanisms course, exact.

The package follows the method, one room per stage (docs/architecture.md):

- :mod:`plans.scene`: scene files, units, reading (one TOML reader for every file kind).
- :mod:`plans.kinematics`: structure (Assur groups), exact analysis, the construction of
  velocity and acceleration plans, the frozen plan objects.
- :mod:`plans.forces`: loads, Bruevich force polygons, the crank, the Zhukovsky lever.
- :mod:`plans.check`: checking a hand-drawn sheet against the exact analysis.
- :mod:`plans.accuracy`: oracles, reference solutions, the draftsman Monte Carlo, the
  benchmark and the stability suite.

Shared by all rooms: :mod:`plans.errors` (one failure family), :mod:`plans.io` (TOML
reading, atomic writing, JSON), :mod:`plans.units`, :mod:`plans.tolerances`, and
:mod:`plans.results` (the ``solve`` pipeline and its JSON).

``plans`` never imports ``drawings``, svgwrite or cairosvg.  Typical use::

    import plans
    sol = plans.solve("samples/v_engine.toml")       # a Solution: parts computed when read
    sol.value("F_12^τ", 45)                            # N, signed as docs/quantities.md says
"""

from __future__ import annotations

from typing import Any

_LAZY = {
    "load_scene": "plans.kinematics.placing",  # read and placed (positions by travel, extreme)
    "Scene": "plans.scene",
    "solve": "plans.solution",
    "solve_scene": "plans.results",
    "to_json": "plans.results",
    "Solution": "plans.solution",
    "PlansError": "plans.errors",
    "InputError": "plans.errors",
    "ConstructionError": "plans.errors",
}


def __getattr__(name: str) -> Any:  # lazy: importing plans loads nothing heavy
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'plans' has no attribute {name!r}")


__all__ = sorted(_LAZY)
