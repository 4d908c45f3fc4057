"""The kinetostatics sheet's scales: one standard scale (GOST 2.302) for the mechanism at
every position, one for the free bodies (the groups and the initial link cut free) at every
position, and each position's polygons and lever at the longest round scale the sheet has
room for.

A draftsman draws the positions of one sheet alike: a dead centre's scheme (a thin strip) at
the scale of the other position's, not at twice it, and its free bodies at the scale of the
other's.  The free bodies may be drawn larger than the mechanism (a standard scale or two
above it) when the sheet gets clearly fuller so; the polygons and the lever grow by the
longer solutions (:mod:`drawings.linkage.larger`), position by position, each step raising
the part that makes the sheets fullest (:func:`steepest`).  Of every choice tried, the one
that keeps the fewest sheets and leaves the least of them empty is drawn.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import partial
from typing import Any

from drawings.linkage.larger import better, full, score
from drawings.linkage.mixing import OWN, by_phi

#: Standard scales above the mechanism's tried for the free bodies.
BODIES_RISE = 2
#: The smallest part of the scale the mechanism's size asks for that it is drawn at to keep
#: its positions on fewer sheets (1:4 for 1:2).
SHRINK = 0.5
#: How much fuller (of the field) the least full sheet must get for the free bodies to be
#: drawn at a larger scale than the mechanism.
BODIES_GAIN = 0.02


def lever_apart(phi: float) -> tuple[Callable[[Any], bool], Callable[[Any], bool]]:
    """The two parts of a position's panels on the kinetostatics sheet whose fits rise apart:
    its free bodies with their polygons, and its lever."""
    at = by_phi(phi)
    return (lambda p: at(p) and p.kind != "lever"), (lambda p: at(p) and p.kind == "lever")


def above(mu: float, ratios: Sequence[float]) -> list[float]:
    """The standard length scales (μl, mm per m: 1000 × a GOST 2.302 ratio) larger than
    ``mu``, smallest first."""
    return sorted(1000.0 * r for r in ratios if 1000.0 * r > mu * (1 + 1e-9))


def fewest(lay_at: Callable[[float], list], mu: float, ratios: Sequence[float]) -> float:
    """The largest standard length scale from ``mu`` down to :data:`SHRINK` of it at which the
    kinetostatics take the fewest sheets (``lay_at(μl)``: the sheets with the mechanism and the
    free bodies at μl): two positions that each leave a sheet half empty share one, drawn a
    standard scale or two smaller, as a department would draw them."""
    least = len(lay_at(mu))
    best = mu
    if least <= 1:
        return mu
    for s in sorted((1000.0 * r for r in ratios if mu * SHRINK * (1 - 1e-9) <= 1000.0 * r < mu * (1 - 1e-9)),
                    reverse=True):
        n = len(lay_at(s))
        if n < least:
            best, least = s, n
    return best


def steepest(start: Sequence[int], options: int, lay: Callable[[tuple[int, ...]], list],
             improves: Callable[[list, list], bool], done: Callable[[list], bool],
             rank: Callable[[list], Any]) -> tuple[tuple[int, ...], list]:
    """The choice of a fit per part (indices ``OWN``..``options - 1``, larger is longer) found by
    steepest ascent from ``start``: each round every part's every longer fit is laid out (a part's
    stops at the first that takes more sheets or that ``lay`` refuses as too big) and the best by
    ``rank`` of those that ``improves`` the layout is taken, until none does or it is ``done``.
    Raising the parts in a fixed order instead lets the first take the room a later one would
    fill better (two positions sharing a sheet)."""
    from drawings.paper.sheet import TooBig

    choice = tuple(start)
    best = lay(choice)
    while not done(best):
        top: tuple[tuple[int, ...], list] | None = None
        for j in range(len(choice)):
            for i in range(choice[j] + 1, options):
                trial = choice[:j] + (i,) + choice[j + 1:]
                try:
                    got = lay(trial)
                except TooBig:
                    break
                if len(got) > len(best):
                    break
                if improves(best, got) and (top is None or rank(got) > rank(top[1])):
                    top = (trial, got)
        if top is None:
            break
        choice, best = top
    return choice, best


def kinetic_layout(lay_at: Callable[[tuple[int, ...], float, float], list], positions: int, fits: int,
                   mu: float, ratios: Sequence[float], own: bool, size: tuple[float, float],
                   last: int = 0) -> list:
    """The kinetostatics sheets: ``lay_at(fits, μl, μl of the free bodies)`` lays them out with
    the free bodies and polygons of position ``j`` at the longer solution ``fits[2j]`` and its
    lever at ``fits[2j + 1]`` (:data:`OWN`: the sheet's own), the mechanism at ``mu`` (the
    largest standard scale that keeps the sheets as few) and the free bodies at ``mu`` or a
    standard scale or two above it (with ``own``, the file's length scale, at it).  The fits
    rise position by position, then (while the sheets are not full) part by part: each ascent
    is a steepest one (:func:`steepest`), and either may stop short of the other.  ``fits``:
    the longer solutions; ``last``: longer ones still, tried only when the sheets are not yet
    full without them (the polygons drawn as long as that only where nothing else fills the
    sheet)."""
    laid: dict[tuple[tuple[int, ...], float], list] = {}

    def at(mb: float, together: bool, f: tuple[int, ...]) -> list:
        key = (tuple(x for x in f for _ in (0, 1)) if together else f, mb)
        if key not in laid:
            laid[key] = lay_at(key[0], mu, mb)
        return laid[key]

    first, mb, choice = _search(at, positions, fits, mu, ratios, own, size)
    if not last or full(first, size):
        return first
    # the longest fits from where the search stopped, part by part at its free bodies' scale
    start = choice if len(choice) == 2 * positions else tuple(x for x in choice for _ in (0, 1))
    _, second = steepest(start, fits + last, partial(at, mb, False), partial(better, size=size),
                         partial(full, size=size), lambda s: score(s, size))
    return second if better(first, second, size) else first


def _search(at: Callable[[float, bool, tuple[int, ...]], list], positions: int, fits: int, mu: float,
            ratios: Sequence[float], own: bool, size: tuple[float, float]
            ) -> tuple[list, float, tuple[int, ...]]:
    """The best layout :func:`kinetic_layout` finds with ``fits`` longer solutions (``at(μl of
    the free bodies, together, fits)``: the sheets, a fit per position or per part), with its
    free bodies' scale and its fits."""
    from drawings.paper.sheet import TooBig

    def done(s: list) -> bool:
        return full(s, size)

    def improves(a: list, b: list) -> bool:
        return better(a, b, size)

    best: tuple[list, float, tuple[int, ...]] | None = None
    for mb in [mu] + ([] if own else above(mu, ratios)[:BODIES_RISE]):
        try:
            if best is not None and len(at(mb, True, (OWN,) * positions)) > len(best[0]):
                break  # more sheets at the sheet's own fits: longer ones take no fewer
        except TooBig:
            break
        for together in (True, False):
            n = positions if together else 2 * positions
            try:
                choice, got = steepest((OWN,) * n, fits, partial(at, mb, together), improves, done,
                                       lambda s: score(s, size))
            except TooBig:  # a free body too big for an empty sheet: none larger either
                assert best is not None
                return best
            if best is None or mb == best[1] and improves(best[0], got):
                best = (got, mb, choice)
            elif improves(best[0], got) and (len(got) < len(best[0]) or
                                             score(got, size)[1] >= score(best[0], size)[1] + BODIES_GAIN):
                best = (got, mb, choice)  # free bodies larger than before: for a real gain
            if done(best[0]):
                return best
    assert best is not None
    return best
