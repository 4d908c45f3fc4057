"""Longer plans chosen part by part: a sheet's kinds or positions each at its own longer fit.

One fit for a whole sheet often leaves it half empty: on the shaper's kinematics sheet the
twelve velocity plans at the next round scale would take another sheet, so the acceleration
plans stay at the A1 lengths too, though the sheet has room for them at twice those.  A
draftsman draws each kind of plan (and, on the kinetostatics sheet, each position's groups,
polygons and lever) at the largest round scale the sheet has room for, and writes it on the
panel.  :func:`ascend` raises each part's fit in turn (a coordinate ascent over the fits
:mod:`drawings.linkage.larger` solves) while the layout keeps as few sheets and gets fuller.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence
from typing import Any, TypeVar

from drawings.paper.panel_frame import Panel
from plans.tolerances import SAME_ANGLE_DEG

T = TypeVar("T")
K = TypeVar("K", bound=Hashable)

#: The fit of a part left at the sheet's own solution.
OWN = -1


def swapped(panels: Sequence[Panel], parts: Sequence[Callable[[Panel], bool]], keys: Sequence[K],
            panels_at: Callable[[K], dict[str, Panel]]) -> list[Panel]:
    """``panels`` with each panel of part ``j`` (``parts[j](panel)``) taken from the panels
    ``panels_at(keys[j])`` (by id); a panel of no part kept."""
    out = []
    for p in panels:
        j = next((j for j, part in enumerate(parts) if part(p)), None)
        out.append(p if j is None else panels_at(keys[j]).get(p.pid, p))
    return out


def ascend(start: Sequence[int], options: int, lay: Callable[[tuple[int, ...]], T],
           better: Callable[[T, T], bool], done: Callable[[T], bool], more: Callable[[T, T], bool],
           laid: T | None = None) -> tuple[tuple[int, ...], T]:
    """The choice of a fit per part (indices ``OWN``..``options - 1``, larger is longer) found
    by raising each part's in turn from ``start`` while ``better`` (the new layout over the
    best) holds; a part stops rising at the first fit whose layout takes ``more`` sheets or
    that ``lay`` refuses (:class:`drawings.paper.sheet.TooBig`: a panel too long for an empty
    sheet).  ``done``: a layout full enough to stop at.  Returns the choice and its layout."""
    from drawings.paper.sheet import TooBig

    choice = tuple(start)
    best = lay(choice) if laid is None else laid
    for j in range(len(choice)):
        for i in range(choice[j] + 1, options):
            if done(best):
                return choice, best
            trial = choice[:j] + (i,) + choice[j + 1:]
            try:
                got = lay(trial)
            except TooBig:
                break
            if more(best, got):
                break
            if better(best, got):
                choice, best = trial, got
    return choice, best


def memo(make: Callable[[K], T]) -> Callable[[K], T]:
    """``make`` called once per key, when first asked for."""
    from functools import cache

    return cache(make)


def by_phi(phi: float) -> Callable[[Any], bool]:
    """Whether a panel is drawn at the crank angle ``phi``."""
    return lambda p: p.phi is not None and abs(p.phi - phi) < SAME_ANGLE_DEG
