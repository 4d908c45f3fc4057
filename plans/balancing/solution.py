"""An engine solved once for every reader: its balance (the polygons of inertia forces and
moments, the counterweights, the banks) and, for a connecting rod of finite length, the
check against the exact shaking force of the linkage, each made the first time it is read
and kept by this object.

``plans.solve("engine.toml")`` (or :func:`solve_engine`) gives an :class:`EngineSolution`;
``plans balance`` and the sheets (``drawings.balancing``) read it.
"""

from __future__ import annotations

from functools import cached_property
from pathlib import Path

from .analysis import Balance, balance
from .engine import Engine, load_engine
from .exact import ExactCheck, exact_check


class EngineSolution:
    """An engine's balance and its exact check, each made when first read."""

    def __init__(self, engine: Engine) -> None:
        self.engine = engine

    def __repr__(self) -> str:
        return f"EngineSolution({self.engine.path!r})"

    @cached_property
    def balance(self) -> Balance:
        """Every polygon, resultant and counterweight of the engine."""
        return balance(self.engine)

    @cached_property
    def exact(self) -> ExactCheck | None:
        """The harmonic series against the exact shaking force and moment of the linkage
        (None where λ = 0: the series is then exact)."""
        return exact_check(self.engine) if self.engine.lam > 0 else None


def solve_engine(source: Engine | str | Path) -> EngineSolution:
    """An engine (or the path of its file) solved: parts computed when first read."""
    return EngineSolution(source if isinstance(source, Engine) else load_engine(source))


__all__ = ["EngineSolution", "solve_engine"]
