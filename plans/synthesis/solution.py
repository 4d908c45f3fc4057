"""A synthesis task solved once for every reader: the design (the mechanism sized and
measured back) and where its joints stand at a crank angle, each made the first time it is
read and kept by this object.

``plans.solve("task.toml")`` (or :func:`solve_task`) gives a :class:`DesignSolution`;
``plans design``, the workbench and the sheet (``drawings.synthesis``) read it.
"""

from __future__ import annotations

from functools import cached_property
from pathlib import Path

from .design import Design, design
from .model import Task, load_task
from .numeric import wrap
from .proof import FourBar, Slider


class DesignSolution:
    """A task's design and the positions the sheet draws, each made when first read."""

    def __init__(self, task: Task) -> None:
        self.task = task
        self._joints: dict[float, dict[str, complex]] = {}

    def __repr__(self) -> str:
        return f"DesignSolution({self.task.path!r})"

    @cached_property
    def design(self) -> Design:
        """The mechanism sized from the task and measured back from its motion."""
        return design(self.task)

    def joints(self, phi: float) -> dict[str, complex]:
        """The mechanism's moving joints at the crank angle ``phi`` (rad; world, m): A and B
        (a V-engine's second slider C; a coulisse's D and E)."""
        got = self._joints.get(phi)
        if got is None:
            got = self._joints[phi] = _joints(self.design, phi)
        return dict(got)

    @cached_property
    def rocker_angles(self) -> tuple[float, ...]:
        """Three given positions: the rocker's angle ψ of the designed mechanism at each given
        φ (rad), the nearest turn to the given ψ."""
        d, t = self.design, self.task
        if d.model != "three_positions" or t.positions is None:
            return ()
        fb = d.mechs[0]
        return tuple(psi + wrap(fb.psi(phi) - psi) for phi, psi in t.positions)


def _joints(d: Design, phi: float) -> dict[str, complex]:
    out: dict[str, complex] = {}
    for i, m in enumerate(d.mechs):
        if isinstance(m, Slider):
            A, B = m.place(phi)
            out["A"] = A
            out["B" if i == 0 else "C"] = B
        elif isinstance(m, FourBar):
            out["A"], out["B"] = m.place(phi)
        else:
            out["A"], out["D"], out["E"] = m.place(phi)
    return out


def solve_task(source: Task | str | Path) -> DesignSolution:
    """A synthesis task (or the path of its file) solved: parts computed when first read."""
    return DesignSolution(source if isinstance(source, Task) else load_task(source))


__all__ = ["DesignSolution", "solve_task"]
