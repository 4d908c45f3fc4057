"""Longer plans where the sheet has room: the draftsman's larger round scale.

A1 sheets drawn at the plans' A1 target lengths are often left half empty: twelve velocity
plans of 100 mm on an 800 × 560 mm field.  A draftsman then draws them at a larger round
scale.  The plans, polygons and lever are made again with longer target lengths (``fit`` > 1,
the rest of the solution shared: :meth:`plans.solution.Solution.at_fit`; each plan, polygon
and lever takes the round scale, 1, 2, 2.5, 4 or 5 × 10^k, that draws it within the longer
length), and a sheet takes those panels when they keep as few sheets and cover more of them;
the scales written on the panels are the ones they are drawn at.  The round set has no value
between 1 and 2 (1.5 is not round both ways: 1/1.5 is not), so a plan at K = 1·10^k grows by
two at once, one at 2, 2.5, 4 or 5 by 1.25 or 1.6.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, TypeVar

from plans.solution import MAX_FIT, Solution

T = TypeVar("T")

#: The fits tried above a sheet's own, as factors of it: each moves a plan one or two steps up
#: the round set or leaves it (which, depends on where its longest vector falls between two
#: round values); at most twice the A1 lengths (a known vector of 200 mm), not plans blown up
#: to the sheet.
STEPS = (1.25, 1.6, 2.0)
#: One step further for the course's sheets (the kinematics sheet's few acceleration plans
#: beside the kinematic diagrams, the kinetostatics sheet's polygons and lever of one or two
#: positions), within :data:`plans.solution.MAX_FIT`.
KINEMATIC_STEP = 2.5
#: The fits a sheet of the block layout tries (:func:`drawings.linkage._fuller_blocks`), on to
#: MAX_FIT: a position's block alone on its sheet, its border running round the title block,
#: has room for plans longer than twice the A1 lengths.
BLOCK_STEPS = (*STEPS, 2.2, 2.5)
#: The formats whose sheets are grown (a course's A1, and A2).
FORMATS = ("A1", "A2")
#: A layout whose every sheet is this full is left as it is.
FULL = 2 / 3
#: The ``[scales]`` keys that fix each kind of the engine's scales.
_FIXED = (("velocity", "velocity_known_mm"), ("acceleration", "acceleration_known_mm"), ("force",))


def may_grow(sol: Solution, spec: Any) -> bool:
    """Whether longer plans are worth trying: an A1 or A2 sheet, the solution at the paper's own
    fit, and some plan, polygon or lever scale left to the engine."""
    sc = sol.scene.scales
    return (spec.format in FORMATS and abs(sol.fit - spec.fit) < 1e-12
            and not all(any(k in sc for k in keys) for keys in _FIXED))


def longer(sol: Solution, steps: Sequence[float] | None = None) -> list[Callable[[], Solution]]:
    """Thunks of ``sol`` at each longer fit (``steps`` times its own, default :data:`STEPS`, up
    to MAX_FIT), in order (:meth:`Solution.at_fit`: only the plans, polygons and lever are made
    again, at their longer scales)."""
    from functools import partial

    steps = STEPS if steps is None else steps
    fits = [sol.fit * s for s in steps if sol.fit * s <= MAX_FIT + 1e-12]
    return [partial(sol.at_fit, f) for f in fits]


def longest_of(sol: Solution) -> list[Callable[[], Solution]]:
    """The thunk of ``sol`` at :data:`KINEMATIC_STEP` times its fit (at most ``MAX_FIT``),
    where that is longer than :func:`longer`'s longest."""
    from functools import partial

    fit = min(MAX_FIT, sol.fit * KINEMATIC_STEP)
    return [partial(sol.at_fit, fit)] if fit > sol.fit * STEPS[-1] else []


def once_each(thunks: Sequence[Callable[[], T]]) -> Callable[[int], T]:
    """``i -> thunks[i]()``, each called at most once and only when first asked for: a longer
    solution is solved only when a sheet still has room for it."""
    from functools import cache

    return cache(lambda i: thunks[i]())


def fill(placed: Sequence[tuple[Any, float, float]], size: tuple[float, float]) -> float:
    """The part of a sheet's field (inside the frame, less the title block) under its panels
    (``placed``: (panel, x, y)) on paper of ``size``."""
    import shapely

    from drawings.paper.sheet import title_box, usable

    field = shapely.box(*usable(*size)).difference(shapely.box(*title_box(*size)))
    boxes = [shapely.box(x, y, x + p.width, y + p.height) for p, x, y in placed]
    return float(shapely.union_all(boxes).intersection(field).area / field.area) if boxes else 0.0


def _placed(sheet: Any) -> Sequence[tuple[Any, float, float]]:
    return sheet.placed if hasattr(sheet, "placed") else sheet


def score(sheets: Sequence[Any], size: tuple[float, float]) -> tuple[int, float, float]:
    """A layout's worth (larger is better): fewer sheets, then its least full sheet, then the
    mean (each sheet a Sheet or its placed panels)."""
    fills = [fill(_placed(sh), size) for sh in sheets]
    return (-len(fills), min(fills, default=0.0), sum(fills) / max(len(fills), 1))


def full(sheets: Sequence[Any], size: tuple[float, float]) -> bool:
    """Every sheet at least :data:`FULL`."""
    return score(sheets, size)[1] >= FULL


def better(a: Sequence[Any], b: Sequence[Any], size: tuple[float, float]) -> bool:
    """Whether layout ``b`` beats ``a``: fewer sheets, else a fuller least full sheet (by more
    than half a percent), else, as full, a fuller mean."""
    sa, sb = score(a, size), score(b, size)
    if sa[0] != sb[0]:
        return sb[0] > sa[0]
    if abs(sb[1] - sa[1]) > 0.005:
        return sb[1] > sa[1]
    return sb[2] > sa[2] + 0.005
