"""A gear file solved once for every reader: the pairs, the train's plans and synthesis
(:func:`plans.gears.solve.solve_gears`) and the construction of each pair the meshing sheet
draws, each made the first time it is read and kept by this object.

``plans.solve("gears.toml")`` (or :func:`solve_file`) gives a :class:`GearsSolution`; the
sheets (``drawings.gears``) read it and compute nothing of the gears.
"""

from __future__ import annotations

from functools import cached_property
from pathlib import Path

from .meshing import Meshing, meshing
from .model import GearFile, load_gears
from .solve import GearSolution, solve_gears


class GearsSolution:
    """A gear file's solution and its drawn meshings, each made when first read."""

    def __init__(self, file: GearFile) -> None:
        self.file = file
        self._fields: dict[tuple[int, tuple[float, float]], Meshing] = {}

    def __repr__(self) -> str:
        return f"GearsSolution({self.file.path!r})"

    @cached_property
    def solution(self) -> GearSolution:
        """Shifts, pairs, the speeds by Willis, the velocity plan, the train's synthesis."""
        return solve_gears(self.file)

    @cached_property
    def meshings(self) -> tuple[Meshing, ...]:
        """The construction of each pair the meshing sheet draws (:meth:`GearSolution.drawn_pairs`)."""
        return tuple(meshing(p) for p in self.solution.drawn_pairs())

    def meshing_in(self, index: int, field: tuple[float, float]) -> Meshing:
        """The ``index``-th drawn pair's construction over a field of that half-width and
        half-height about P (paper mm), as many teeth drawn as it shows; kept per field."""
        key = (index, field)
        if key not in self._fields:
            self._fields[key] = meshing(self.solution.drawn_pairs()[index], 3, field)
        return self._fields[key]


def solve_file(source: GearFile | str | Path) -> GearsSolution:
    """A gear file (or its path) solved: parts computed when first read."""
    return GearsSolution(source if isinstance(source, GearFile) else load_gears(source))


__all__ = ["GearsSolution", "solve_file"]
