"""The balancing sheet's figures as large as its sheets hold: each group of panels (the
crankshaft, the phase diagrams, each polygon, the banks, the diagrams over a turn) has its
sizes, smallest first, every one at round scales; the search takes the fewest sheets and
leaves the emptiest of them least empty.

First every group at one size together (as the A1 sheet grows), then each group alone on to
its larger sizes, in turn, while that fills more: a polygon's round scale steps by up to
two, so the polygons stop short where the phase diagrams or the turn's diagrams may still
grow.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from drawings.paper.fill import drawn_part
from drawings.paper.panel_frame import Panel
from drawings.paper.sheet import Sheet, SheetSpec, compose, fits_empty

#: Rounds of the groups' one-by-one growth (each round tries every group's larger sizes).
ROUNDS = 2


@dataclass(frozen=True)
class Group:
    """Panels drawn at one of ``options`` (a size, or a tuple of them), the first the A1 one;
    ``joint``: whether the group grows with the others at first (else it keeps its first)."""

    make: Callable[[Any], list[Panel]]
    options: tuple[Any, ...]
    joint: bool = True


def fullest(groups: Sequence[Group], spec: SheetSpec, path: str) -> tuple[list[Panel], list[Sheet]]:
    """The groups' panels at the sizes chosen, and their sheets."""
    made: dict[tuple[int, int], list[Panel]] = {}

    def panels(g: int, i: int) -> list[Panel]:
        if (g, i) not in made:
            made[g, i] = groups[g].make(groups[g].options[i])
        return made[g, i]

    def fits(g: int, i: int) -> bool:
        return all(fits_empty(p, spec.format, spec.orientation) for p in panels(g, i))

    def lay(choice: Sequence[int]) -> tuple[list[Panel], list[Sheet]]:
        ps = [p for g, i in enumerate(choice) for p in panels(g, i)]
        return ps, compose(ps, spec, "", path)

    choice = [0] * len(groups)
    best_panels, best_sheets = lay(choice)
    best = _key(best_sheets)

    def tried(c: list[int]) -> bool:
        nonlocal best_panels, best_sheets, best, choice
        ps, sheets = lay(c)
        part = _key(sheets)
        if part > best:
            best_panels, best_sheets, best, choice = ps, sheets, part, list(c)
            return True
        return False

    common = max(len(g.options) for g in groups if g.joint)
    for j in range(1, common):
        c = [min(j, len(g.options) - 1) if g.joint else 0 for g in groups]
        if not all(fits(g, i) for g, i in enumerate(c)):
            break
        tried(c)
    for _ in range(ROUNDS):
        grew = False
        for g in range(len(groups)):
            shapes = _shapes(panels(g, choice[g]))
            for i in range(choice[g] + 1, len(groups[g].options)):
                if not fits(g, i):
                    break
                if _shapes(panels(g, i)) == shapes:
                    continue  # drawn the same size (a polygon's round scale unchanged): the same sheets
                shapes = _shapes(panels(g, i))
                grew |= tried([i if k == g else choice[k] for k in range(len(groups))])
        if not grew:
            break
    return best_panels, best_sheets


def _shapes(panels: Sequence[Panel]) -> tuple[tuple[float, float], ...]:
    return tuple((round(p.width, 3), round(p.height, 3)) for p in panels)


def _key(sheets: Sequence[Sheet]) -> tuple[int, float]:
    """Fewer sheets first, then the emptiest one's part drawn."""
    return -len(sheets), min(map(drawn_part, sheets))
