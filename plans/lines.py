"""Two straight lines intersected in closed form: the force polygons, the hand-drawing model
and the demonstration's mistakes (the plans' own construction writes the same formula).

A line is a point it passes through and a direction, both plane vectors coded as complex
numbers (x + iy), as Python numbers or as numpy arrays over positions alike.  What to do
where the lines are parallel is the caller's: a force polygon notes that its two closing
reactions lie on one line, the demonstration skips the mistake.
"""

from __future__ import annotations

from typing import Any


def cross(a: Any, b: Any) -> Any:
    """a × b (the z component) of two plane vectors coded as complex numbers."""
    return (a.conjugate() * b).imag


def meet(p1: Any, d1: Any, p2: Any, d2: Any, s: Any = None) -> Any:
    """Where the line through ``p1`` along ``d1`` meets the line through ``p2`` along ``d2``:
    ``p1 + t·d1`` with ``t = (p2 − p1) × d2 / (d1 × d2)``.  ``s`` is d1 × d2 when the caller
    has it already (it must not be zero: parallel lines are the caller's)."""
    return p1 + cross(p2 - p1, d2) / (cross(d1, d2) if s is None else s) * d1


def along(p1: Any, d1: Any, p2: Any, d2: Any) -> tuple[Any, Any]:
    """The parameters (t1, t2) of the meeting point on each line, ``p1 + t1·d1 = p2 + t2·d2``
    (in units of each direction's length); parallel lines (d1 × d2 = 0) are the caller's."""
    s = cross(d1, d2)
    w = p2 - p1
    return cross(w, d2) / s, cross(w, d1) / s


__all__ = ["along", "cross", "meet"]
